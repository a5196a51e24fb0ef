#!/usr/bin/env bash
# README's render-time table: POV-Ray's CPU (user + system) a frame on five frames of the built-in
# break (60 the still before the break, 76 the break, 90 the spread, 150 the balls rolling seen wide,
# 297 the closing shot), at draft and final, 640x360 and 1280x720, each frame traced whole with the
# exporter's own POV-Ray options, one process at a time; and the default movie (300 frames) reckoned
# from the mean at one POV-Ray process per core on two cores.
#
#   cmake --build build --target billiards-export
#   tests/bench/render_times.sh [--frames "60 76 90 150 297"] [--runs N]
#
# With --runs N each frame is rendered N times and the least CPU kept (other work on a shared
# machine only ever adds to a run's CPU). About 2 minutes of one core a run. Never run by ctest.
set -euo pipefail

root=$(cd "$(dirname "$0")/../.." && pwd)
frames="60 76 90 150 297"
runs=1
while [ $# -gt 0 ]; do
  case $1 in
    --frames) frames=$2; shift 2 ;;
    --runs) runs=$2; shift 2 ;;
    *) echo "usage: $0 [--frames \"60 76 90 150 297\"] [--runs N]" >&2; exit 2 ;;
  esac
done
exporter=$root/build/bin/billiards-export
[ -x "$exporter" ] || { echo "render_times: build billiards-export first (cmake --build build)" >&2; exit 1; }
command -v povray >/dev/null || { echo "render_times: povray is needed" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# One frame's least CPU seconds over the runs.
render() {  # dir frame width height quality
  local name least=
  name=$(printf 'frame_%05d' "$2")
  local options=(+Q9 +A0.3 +AM2 +R2)
  [ "$5" = draft ] && options=(+Q9 -A)
  for _ in $(seq 1 "$runs"); do
    (cd "$1/frames" && /usr/bin/time -f '%U %S' -o "$work/time" \
      povray -D +FH +WT1 "+I$name.pov" "+O$work/out.hdr" "+W$3" "+H$4" "${options[@]}" >/dev/null 2>"$work/log") ||
      { tail -3 "$work/log" >&2; exit 1; }
    least=$(awk -v l="$least" '{ t = $1 + $2; if (l == "" || t < l) l = t; printf "%.2f", l }' "$work/time")
  done
  echo "$least"
}

printf '%-7s %-10s' quality size
for f in $frames; do printf ' %7s' "f$f"; done
printf ' %7s %s\n' mean "the movie (300 frames, 2 cores)"
for quality in draft final; do
  for size in 640x360 1280x720; do
    dir=$work/$quality-$size
    "$exporter" --no-render --quiet --quality $quality --size $size -o "$dir" >/dev/null
    printf '%-7s %-10s' $quality $size
    sum=0 n=0
    for f in $frames; do
      t=$(render "$dir" "$f" "${size%x*}" "${size#*x}" $quality)
      printf ' %7s' "$t"
      sum=$(awk -v s="$sum" -v t="$t" 'BEGIN { print s + t }') n=$((n + 1))
    done
    awk -v s="$sum" -v n="$n" 'BEGIN { m = s / n; printf " %7.2f about %.0f min\n", m, m * 300 / 2 / 60 }'
  done
done
