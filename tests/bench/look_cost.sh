#!/usr/bin/env bash
# The look's cost: POV-Ray's CPU (user + system) on final 1280x720 frames of the built-in break, this
# tree's frames beside a baseline commit's, side by side in one run.
#
#   cmake --build build --target billiards-export look_bench
#   tests/bench/look_cost.sh [--base COMMIT] [--frames "0 150 297"] [--runs N] [--size WxH]
#                            [--instructions] [--keep DIR]
#
# It builds the baseline's billiards-export from `git archive COMMIT` (default 172eaef, the commit
# the look's cost rule is measured against) in a scratch folder, writes both trees' frames with
# `billiards-export --no-render` (final, 1280x720) and renders each frame with one POV-Ray process at
# a time, alternately A (the baseline), B (this tree), A, B, ..., with the exporter's own POV-Ray
# options (export/render_jobs.cpp: +FH +WT1 +Q9 +A0.3 +AM2 +R2), so both see the same machine load.
# It prints each frame's mean and least CPU seconds over the runs and the ratios B/A of both, per
# frame and of the sums (on a shared machine the least is the steadier figure: other work only ever
# adds to a run's CPU, by taking the core's caches and its other hyperthread), and (with look_bench
# built) how many stops the walls and the floor lie under the lit cloth in each frame (look_bench
# stops). --instructions counts the instructions POV-Ray executes instead (valgrind's cachegrind,
# about 50 times slower: use --size 640x360 and --runs 1), which other work on the machine does not
# change at all. --keep DIR keeps both trees' frames, .hdr and developed PNGs there. Takes about
# 16 s of one core a frame and run at 1280x720. Never run by ctest.
set -euo pipefail

root=$(cd "$(dirname "$0")/../.." && pwd)
base=172eaef
frames="0 150 297"
runs=2
keep=
size=1280x720
instructions=
while [ $# -gt 0 ]; do
  case $1 in
    --base) base=$2; shift 2 ;;
    --frames) frames=$2; shift 2 ;;
    --runs) runs=$2; shift 2 ;;
    --keep) keep=$2; shift 2 ;;
    --size) size=$2; shift 2 ;;
    --instructions) instructions=1; shift ;;
    *) echo "usage: $0 [--base COMMIT] [--frames \"0 150 297\"] [--runs N] [--size WxH] [--instructions] [--keep DIR]" >&2
       exit 2 ;;
  esac
done
export_b=$root/build/bin/billiards-export
look_bench=$root/build/bin/look_bench
[ -x "$export_b" ] || { echo "look_cost: build billiards-export first (cmake --build build)" >&2; exit 1; }
command -v povray >/dev/null || { echo "look_cost: povray is needed" >&2; exit 1; }
[ -z "$instructions" ] || command -v valgrind >/dev/null || { echo "look_cost: valgrind is needed" >&2; exit 1; }
width=${size%x*}
height=${size#*x}

# shellcheck source=baseline_exporter.sh
. "$root/tests/bench/baseline_exporter.sh"
bench_work "$keep"
export_a=$(baseline_exporter "$root" "$base" "$work") || { echo "look_cost: giving up" >&2; exit 1; }

for side in A B; do
  exporter=$export_a
  [ $side = B ] && exporter=$export_b
  rm -rf "${work:?}/$side"
  "$exporter" --no-render --quiet --quality final --size "$size" -o "$work/$side" >/dev/null
done

# One POV-Ray run: its user + system CPU seconds, or the millions of instructions it executed.
render() {  # side frame
  local name
  name=$(printf 'frame_%05d' "$2")
  cd "$work/$1/frames"
  local povray=(povray -D +FH +WT1 "+I$name.pov" "+O$name.hdr" "+W$width" "+H$height" +Q9 +A0.3 +AM2 +R2)
  # A run that fails (POV-Ray gives up waiting for its render thread to start on a busy machine, under
  # valgrind) is run again, twice at most.
  for attempt in 1 2 3; do
    rm -f "$name.hdr"
    if [ -n "$instructions" ]; then
      valgrind --tool=cachegrind --cache-sim=no --cachegrind-out-file=/dev/null "${povray[@]}" >/dev/null 2>"$work/log" &&
        [ -s "$name.hdr" ] && { awk '/I *refs/ { gsub(",", "", $4); printf "%.0f", $4 / 1e6 }' "$work/log"; return; }
    else
      /usr/bin/time -f '%U %S' -o "$work/time" "${povray[@]}" >/dev/null 2>"$work/log" &&
        [ -s "$name.hdr" ] && { awk '{ printf "%.3f", $1 + $2 }' "$work/time"; return; }
    fi
    echo "look_cost: POV-Ray failed on $1's $name (attempt $attempt): $(grep -v '^==' "$work/log" | tail -1)" >&2
  done
  exit 1
}

rm -f "$work"/samples_*
for run in $(seq 1 "$runs"); do
  for f in $frames; do
    for side in A B; do
      t=$(render $side "$f") || { echo "look_cost: giving up" >&2; exit 1; }
      echo "$t" >>"$work/samples_${side}_$f"
      echo "run $run frame $f ${side}: $t" >&2
    done
  done
done

unit="s of CPU (user + system)"
[ -z "$instructions" ] || unit="millions of instructions"
echo "POV-Ray, final $size, one process at a time, $runs runs alternating A and B: $unit a frame"
echo "A: $base   B: $(git -C "$root" rev-parse --short HEAD)$(git -C "$root" diff --quiet HEAD -- export || echo ' + changes')"
printf '%-7s %10s %10s %8s %10s %10s %8s\n' frame "A mean" "B mean" "B/A" "A least" "B least" "B/A"
stat() {  # file: mean least
  awk 'NR == 1 || $1 < least { least = $1 } { sum += $1 } END { printf "%.2f %.2f", sum / NR, least }' "$1"
}
sa=0 sb=0 la=0 lb=0
for f in $frames; do
  read -r ma mina <<<"$(stat "$work/samples_A_$f")"
  read -r mb minb <<<"$(stat "$work/samples_B_$f")"
  printf '%-7s %10s %10s %8.3f %10s %10s %8.3f\n' "$f" "$ma" "$mb" "$(awk -v a="$ma" -v b="$mb" 'BEGIN { print b / a }')" \
    "$mina" "$minb" "$(awk -v a="$mina" -v b="$minb" 'BEGIN { print b / a }')"
  read -r sa sb la lb <<<"$(awk -v sa="$sa" -v sb="$sb" -v la="$la" -v lb="$lb" -v a="$ma" -v b="$mb" -v c="$mina" -v d="$minb" \
    'BEGIN { print sa + a, sb + b, la + c, lb + d }')"
done
printf '%-7s %10.2f %10.2f %8.3f %10.2f %10.2f %8.3f\n' all "$sa" "$sb" "$(awk -v a="$sa" -v b="$sb" 'BEGIN { print b / a }')" \
  "$la" "$lb" "$(awk -v a="$la" -v b="$lb" 'BEGIN { print b / a }')"

if [ -x "$look_bench" ]; then
  for side in A B; do
    echo "the room against the lit cloth, $side (median linear luma; EV under the cloth):"
    args=()
    for f in $frames; do
      n=$work/$side/frames/$(printf 'frame_%05d' "$f")
      args+=("$n.pov" "$n.hdr")
    done
    "$look_bench" stops "${args[@]}"
    if [ -n "$keep" ]; then
      for f in $frames; do
        n=$(printf 'frame_%05d' "$f")
        "$look_bench" develop "$work/$side/frames/$n.hdr" "$work/$side/frames/$n.png"
      done
    fi
  done
fi
