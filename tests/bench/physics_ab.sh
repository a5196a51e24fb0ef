#!/usr/bin/env bash
# The physics' speed beside a baseline commit's, side by side in one run, and the same events to the bit.
#
#   cmake --build build --target bench
#   tests/bench/physics_ab.sh [--base COMMIT] [--blocks K] [--runs N] [--scenes "break tight-break two-ball"]
#                             [--fastfiz DIR] [--instructions] [--keep DIR]
#
# It builds the baseline's `bench` from `git archive COMMIT` (default 3bf1808, the physics before the
# speed work of issue 40) in a scratch folder, with this tree's tests/bench/bench.cpp (and
# tests/support/physics_fingerprint.h), so both sides are timed and hashed by the same code. First it compares `bench --fingerprint 2000` of both (a hash of every bit of
# every segment, event and drop of the bench's scenes, 2,000 seeded breaks and 101 seeded 100-ball
# tables) and stops if they differ. Then it runs `bench --scene S --runs N` (the median microseconds of
# N shots of the physics alone) for each scene, A (the baseline) and B (this tree) alternately, in K
# blocks (A B, then B A, ...), so both see the same machine load, and prints the median and the least
# over the blocks of each side's figure, and their ratios.
#
# --fastfiz DIR: also FastFiz 0.2, built from DIR (a copy of github.com/ekiefl/FastFiz's FastFiz-0.2/
# FastFiz folder; needs g++ and GSL, Debian's libgsl-dev, which this project does not use) with
# tests/bench/fastfiz_shots.cpp, timed in the same blocks on its own 8-ball break (8 m/s) and on
# bench's two-ball shot scaled to its table, and each side's ratio to it. --instructions: also the
# instructions a shot takes on each side (valgrind's cachegrind, the difference of N and 2N shots),
# which other work on the machine does not change. --keep DIR keeps the baseline's build there (a
# second run with the same DIR does not build it again). Never run by ctest.
set -euo pipefail

root=$(cd "$(dirname "$0")/../.." && pwd)
base=3bf1808
blocks=9
runs=2000
scenes="break tight-break two-ball"
fastfiz=
instructions=
keep=
usage="usage: $0 [--base COMMIT] [--blocks K] [--runs N] [--scenes \"S ...\"] [--fastfiz DIR] [--instructions] [--keep DIR]"
while [ $# -gt 0 ]; do
  case $1 in
    --base) base=$2; shift 2 ;;
    --blocks) blocks=$2; shift 2 ;;
    --runs) runs=$2; shift 2 ;;
    --scenes) scenes=$2; shift 2 ;;
    --fastfiz) fastfiz=$(cd "$2" && pwd); shift 2 ;;
    --instructions) instructions=1; shift ;;
    --keep) keep=$2; shift 2 ;;
    *) echo "$usage" >&2; exit 2 ;;
  esac
done
bench_b=$root/build/bin/bench
[ -x "$bench_b" ] || { echo "physics_ab: build bench first (cmake --build build --target bench)" >&2; exit 1; }
[ -z "$instructions" ] || command -v valgrind >/dev/null || { echo "physics_ab: valgrind is needed" >&2; exit 1; }

work=${keep:-$(mktemp -d)}
mkdir -p "$work"
[ -n "$keep" ] || trap 'rm -rf "$work"' EXIT

# The baseline's bench, its physics built from its own sources (ccache makes a second build quick).
src=$work/base-src
if [ ! -x "$src/build/bin/bench" ] || [ "$(cat "$src/commit" 2>/dev/null)" != "$base" ]; then
  rm -rf "$src" && mkdir -p "$src"
  git -C "$root" archive "$base" | tar -x -C "$src"
  cp "$root/tests/bench/bench.cpp" "$src/tests/bench/bench.cpp"
  cp "$root/tests/support/physics_fingerprint.h" "$src/tests/support/physics_fingerprint.h"
  launcher=()
  command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
  cmake -S "$src" -B "$src/build" -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" >"$work/base-build.log" 2>&1
  cmake --build "$src/build" --target bench -j2 >>"$work/base-build.log" 2>&1 ||
    { echo "physics_ab: the baseline did not build; see $work/base-build.log" >&2; exit 1; }
  echo "$base" >"$src/commit"
fi
bench_a=$src/build/bin/bench

if [ -n "$fastfiz" ]; then
  ff=$work/fastfiz_shots
  g++ -O2 -fpermissive -w -I"$fastfiz" "$root/tests/bench/fastfiz_shots.cpp" \
    "$fastfiz"/{FastFiz,Rules,Noise,Stopwatch}.cpp -lgsl -lgslcblas -o "$ff" 2>"$work/fastfiz-build.log" ||
    { echo "physics_ab: FastFiz did not build; see $work/fastfiz-build.log" >&2; exit 1; }
fi

echo "A: $base   B: $(git -C "$root" rev-parse --short HEAD)$(git -C "$root" diff --quiet HEAD -- core/physics || echo ' + changes')"
"$bench_a" --fingerprint 2000 >"$work/fingerprint_A"
"$bench_b" --fingerprint 2000 >"$work/fingerprint_B"
if ! cmp -s "$work/fingerprint_A" "$work/fingerprint_B"; then
  echo "physics_ab: the events differ:" >&2
  diff "$work/fingerprint_A" "$work/fingerprint_B" >&2 || true
  exit 1
fi
echo "same events to the bit: $(tail -2 "$work/fingerprint_B" | head -1 | cut -d' ' -f2-) and the bench's scenes"

# Each timed run appends its median us per shot to samples_SIDE_SCENE.
rm -f "$work"/samples_*
time_scene() {  # side scene
  local line
  if [ "$1" = FF ]; then
    if [ "$2" = two-ball ]; then line=$("$ff" two-ball "$runs"); else line=$("$ff" break $((runs / 20 + 5))); fi
  else
    line=$("$([ "$1" = A ] && echo "$bench_a" || echo "$bench_b")" --scene "$2" --runs "$runs")
  fi
  echo "$line" | awk '{ for (i = 1; i < NF; ++i) if ($i == "us") print $(i + 1) }' >>"$work/samples_$1_$2"
}
sides="A B"
[ -z "$fastfiz" ] || sides="A B FF"
for block in $(seq 1 "$blocks"); do
  order=$sides
  [ $((block % 2)) = 0 ] && order=$(echo "$sides" | tr ' ' '\n' | tac | tr '\n' ' ')
  for side in $order; do
    if [ "$side" = FF ]; then
      time_scene FF break
      time_scene FF two-ball
    else
      for scene in $scenes; do time_scene "$side" "$scene"; done
    fi
  done
  echo "block $block of $blocks done" >&2
done

median() { sort -g "$1" | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
least() { sort -g "$1" | head -1; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.3f", b / a }'; }
row() {  # label statistic scene
  local a b f
  a=$($2 "$work/samples_A_$3")
  b=$($2 "$work/samples_B_$3")
  if [ -z "$fastfiz" ]; then
    printf '%-20s %10s %10s %8s\n' "$1" "$a" "$b" "$(ratio "$a" "$b")"
    return
  fi
  # FastFiz's own break stands beside both breaks (its rack is neither), its two-ball beside the two-ball.
  f=$($2 "$work/samples_FF_$([ "$3" = two-ball ] && echo two-ball || echo break)")
  printf '%-20s %10s %10s %8s %12s %8s %8s\n' "$1" "$a" "$b" "$(ratio "$a" "$b")" "$f" "$(ratio "$f" "$a")" "$(ratio "$f" "$b")"
}
echo "us per shot: each run's median of $runs shots (FastFiz's break: of $((runs / 20 + 5))), over $blocks blocks their median"
echo "and their least (on a shared machine the least is the steadier: other work only ever adds time)"
if [ -z "$fastfiz" ]; then
  printf '%-20s %10s %10s %8s\n' scene "A us" "B us" "B/A"
else
  printf '%-20s %10s %10s %8s %12s %8s %8s\n' scene "A us" "B us" "B/A" "FastFiz us" "A/FF" "B/FF"
fi
for scene in $scenes; do
  row "$scene, median" median "$scene"
  row "$scene, least" least "$scene"
done

if [ -n "$instructions" ]; then
  count() {  # bench scene runs: instructions of the whole process
    valgrind --tool=cachegrind --cache-sim=no --cachegrind-out-file=/dev/null "$1" --scene "$2" --runs "$3" 2>&1 |
      awk '/I *refs/ { gsub(",", "", $4); print $4 }'
  }
  n=$((runs / 20 + 10))
  echo "instructions per shot (valgrind, $n shots against $((2 * n)))"
  printf '%-12s %12s %12s %8s\n' scene A B B/A
  for scene in $scenes; do
    ia=$(($(count "$bench_a" "$scene" $((2 * n))) - $(count "$bench_a" "$scene" "$n")))
    ib=$(($(count "$bench_b" "$scene" $((2 * n))) - $(count "$bench_b" "$scene" "$n")))
    printf '%-12s %12d %12d %8s\n' "$scene" $((ia / n)) $((ib / n)) "$(ratio "$ia" "$ib")"
  done
fi
