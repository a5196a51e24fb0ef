#!/usr/bin/env bash
# Tracing only what changed against a baseline commit, side by side in one run: `render_bench --alone`
# of the baseline (A) and of this tree (B) at the same time, so both see the same machine load. Each
# traces every frame of the built-in break whole and, when its code traces it in part, each of its
# rectangles, one POV-Ray at a time (so a frame's two ways see the same load too), and prints
# POV-Ray's CPU (user + system) both ways, their ratio and how many values of the rectangles differ
# from the whole frames'.
#
#   cmake --build build --target render_bench
#   tests/bench/reuse_ab.sh [--base COMMIT] [--size WxH] [--keep DIR]
#
# The baseline's render_bench is built from `git archive COMMIT` (default 09efecf, the code before the
# mirror patches and the dearer start) with this tree's tests/bench/render_bench.cpp laid over it (the
# same measurement of the other code's plan), in DIR/base-src, laid out as a worktree with its build/
# inside and the build's options, so ccache serves what any build of that commit compiled. Two POV-Ray
# processes share the machine while both run; the CPU seconds are each run's own. About 12 minutes of two cores at 320x180, 45 at 640x360. Never run by ctest.
set -euo pipefail

root=$(cd "$(dirname "$0")/../.." && pwd)
base=09efecf
size=320x180
keep=
while [ $# -gt 0 ]; do
  case $1 in
    --base) base=$2; shift 2 ;;
    --size) size=$2; shift 2 ;;
    --keep) keep=$2; shift 2 ;;
    *) echo "usage: $0 [--base COMMIT] [--size WxH] [--keep DIR]" >&2; exit 2 ;;
  esac
done
bench_b=$root/build/bin/render_bench
[ -x "$bench_b" ] || { echo "reuse_ab: build render_bench first (cmake --build build --target render_bench)" >&2; exit 1; }

# shellcheck source=baseline_exporter.sh
. "$root/tests/bench/baseline_exporter.sh"
bench_work "$keep"
src=$work/base-src
if [ ! -x "$src/build/bin/render_bench" ]; then
  rm -rf "$src" && mkdir -p "$src"
  git -C "$root" archive "$base" | tar -x -C "$src"
  cp "$root/tests/bench/render_bench.cpp" "$src/tests/bench/render_bench.cpp"
  launcher=()
  command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
  cmake -S "$src" -B "$src/build" -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" -DCMAKE_COMPILE_WARNING_AS_ERROR=ON \
    >"$work/base-build.log" 2>&1
  cmake --build "$src/build" --target render_bench -j2 >>"$work/base-build.log" 2>&1 ||
    { echo "reuse_ab: the baseline $base did not build; see $work/base-build.log" >&2; exit 1; }
fi

status=0
"$src/build/bin/render_bench" --alone --size "$size" >"$work/A.txt" 2>"$work/A.log" &
pid_a=$!
"$bench_b" --alone --size "$size" >"$work/B.txt" 2>"$work/B.log" || status=1
wait "$pid_a" || status=1
echo "A: the baseline $base"
cat "$work/A.txt"
echo "B: this tree ($(git -C "$root" rev-parse --short HEAD)$(git -C "$root" diff --quiet HEAD -- export || echo ', with changes'))"
cat "$work/B.txt"
exit $status
