#!/usr/bin/env bash
# The physics' speed beside a baseline commit's, side by side in one run, and the same events to the bit.
#
#   cmake --build build --target bench
#   tests/bench/physics_ab.sh [--base COMMIT] [--blocks K] [--runs N] [--scenes "break tight-break two-ball"]
#                             [--fastfiz DIR] [--instructions] [--keep DIR]
#
# It builds the baseline's `bench` from `git archive COMMIT` (default 3bf1808, the physics before the
# speed work of issue 40) in a scratch folder, with this tree's tests/bench/bench.cpp (and
# tests/support/physics_fingerprint.h), so both sides are timed and hashed by the same code. First it
# compares `bench --fingerprint 2000` of both (a hash of every bit of every segment, event and drop of
# the bench's scenes, 2,000 seeded breaks and 101 seeded 100-ball tables) and stops if they differ.
# Then it runs `bench --scene S --runs N` (the median microseconds of N shots of the physics alone)
# for each scene, A (the baseline) and B (this tree) alternately, in K blocks (A B, then B A, ...), so
# both see the same machine load, and prints the median and the least over the blocks of each side's
# figure, and their ratio. On a shared machine the least is the steadier: other work only ever adds.
#
# --fastfiz DIR: also the ratio to FastFiz 0.2, built from DIR (a copy of github.com/ekiefl/FastFiz's
# FastFiz-0.2/FastFiz folder; needs g++ and GSL, Debian's libgsl-dev, which this project does not use)
# with tests/bench/fastfiz_shots.cpp and `g++ -O2 -fpermissive`, and linked with each side's libraries
# into tests/bench/fastfiz_side_by_side.cpp: one process that shoots ours and FastFiz's in alternating
# blocks (ours, FastFiz's; FastFiz's, ours; ...), FastFiz's own 8-ball break (8 m/s, rack seed 8)
# beside both our breaks and its two-ball shot beside ours. The two processes (A's and B's) run K times
# in turn; it prints the median of each side's ratios and their range. --instructions: also the
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
usage="usage: $0 [--base COMMIT] [--blocks K] [--runs N] [--scenes \"S ...\"] [--fastfiz DIR] [--instructions]"
usage+=" [--keep DIR]"
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

# FastFiz's objects once, and the side-by-side program linked with each side's libraries.
if [ -n "$fastfiz" ]; then
  mkdir -p "$work/fastfiz"
  for name in FastFiz Rules Noise Stopwatch; do
    g++ -O2 -fpermissive -w -I"$fastfiz" -c "$fastfiz/$name.cpp" -o "$work/fastfiz/$name.o"
  done 2>"$work/fastfiz-build.log" ||
    { echo "physics_ab: FastFiz did not build; see $work/fastfiz-build.log" >&2; exit 1; }
  g++ -O2 -fpermissive -w -I"$fastfiz" -c "$root/tests/bench/fastfiz_shots.cpp" -o "$work/fastfiz/shots.o"
  for side in A B; do
    tree=$root
    [ $side = A ] && tree=$src
    includes=()
    for dir in core/physics core/scene core tests/support; do includes+=(-I"$tree/$dir"); done
    mapfile -t libraries < <(find "$tree/build/core" -name '*.a')
    g++ -std=c++20 -O2 "${includes[@]}" -I/usr/include/eigen3 "$root/tests/bench/fastfiz_side_by_side.cpp" \
      "$work"/fastfiz/*.o -Wl,--start-group "${libraries[@]}" -Wl,--end-group -lgsl -lgslcblas \
      -o "$work/side_by_side_$side" 2>>"$work/fastfiz-build.log" ||
      { echo "physics_ab: the side-by-side program did not build; see $work/fastfiz-build.log" >&2; exit 1; }
  done
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
rm -f "$work"/samples_* "$work"/ratios_*
for block in $(seq 1 "$blocks"); do
  order="A B"
  [ $((block % 2)) = 0 ] && order="B A"
  for side in $order; do
    bench=$bench_b
    [ "$side" = A ] && bench=$bench_a
    for scene in $scenes; do
      "$bench" --scene "$scene" --runs "$runs" | awk '{ print $5 }' >>"$work/samples_${side}_$scene"
    done
  done
  echo "block $block of $blocks done" >&2
done

median() { sort -g "$1" | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
least() { sort -g "$1" | head -1; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.3f", b / a }'; }
echo "us per shot: each run's median of $runs shots, over $blocks blocks their median and their least"
printf '%-20s %10s %10s %8s\n' scene "A us" "B us" "B/A"
for scene in $scenes; do
  for statistic in median least; do
    a=$($statistic "$work/samples_A_$scene")
    b=$($statistic "$work/samples_B_$scene")
    printf '%-20s %10s %10s %8s\n' "$scene, $statistic" "$a" "$b" "$(ratio "$a" "$b")"
  done
done

if [ -n "$fastfiz" ]; then
  # Each run prints "NAME us U fastfiz_us F ratio R ..." for the break, the tight break and the two-ball.
  for block in $(seq 1 "$blocks"); do
    order="A B"
    [ $((block % 2)) = 0 ] && order="B A"
    for side in $order; do
      "$work/side_by_side_$side" 2>/dev/null | while read -r name _ us _ ff _ r _; do
        echo "$r" >>"$work/ratios_${side}_$name"
        echo "$us $ff" >>"$work/times_${side}_$name"
      done
    done
    echo "FastFiz block $block of $blocks done" >&2
  done
  echo "FastFiz 0.2 beside ours in one process: the ratio of the medians of a shot, ours over FastFiz's;"
  echo "over $blocks runs of each side their median [least, greatest]"
  printf '%-12s %-24s %-24s %14s\n' scene "A/FastFiz" "B/FastFiz" "FastFiz us (B)"
  for name in break tight-break two-ball; do
    cell() { printf '%s [%s, %s]' "$(median "$1")" "$(least "$1")" "$(sort -g "$1" | tail -1)"; }
    awk '{ print $2 }' "$work/times_B_$name" >"$work/ff_us_$name"
    printf '%-12s %-24s %-24s %14s\n' "$name" "$(cell "$work/ratios_A_$name")" "$(cell "$work/ratios_B_$name")" \
      "$(median "$work/ff_us_$name")"
  done
fi

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
