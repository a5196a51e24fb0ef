#!/usr/bin/env bash
# The two programs built from clean, as README's main command builds them, for one or more source
# trees side by side: wall time, compiler CPU and the heaviest translation units.
#   bash tests/bench/build_time.sh [TREE[@GENERATOR] ...]     (default: this tree)
#   bash tests/bench/build_time.sh old@"Unix Makefiles" .        a tree of the code before, and this one
# Each tree is configured afresh in a temporary directory (Release, no compiler cache) with the
# generator given (default: the one its .ci/make-movie picks for a new tree, make before Ninja was
# used) and built with as many jobs as there are cores, as .ci/make-movie does; every compilation is
# timed through a launcher. Run on an idle machine: the figures are times.
set -euo pipefail
trees=("$@")
[ ${#trees[@]} -gt 0 ] || trees=("$(cd "$(dirname "$0")/../.." && pwd)")
[ -x /usr/bin/time ] || { echo "build_time: needs GNU time (apt-get install time)" >&2; exit 1; }
jobs=$(nproc)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat > "$work/timed" <<'LAUNCH'
#!/usr/bin/env bash
# Runs one compilation and appends "user-seconds system-seconds source" to $BSIM_BUILD_LOG.
source_file=""
prev=""
for arg in "$@"; do
  [ "$prev" = "-c" ] && source_file=$arg
  prev=$arg
done
/usr/bin/time -f "%U %S" -o "$BSIM_BUILD_LOG.$$" "$@"
status=$?
read -r user sys < "$BSIM_BUILD_LOG.$$"
rm -f "$BSIM_BUILD_LOG.$$"
echo "$user $sys $source_file" >> "$BSIM_BUILD_LOG"
exit $status
LAUNCH
chmod +x "$work/timed"
printf '%-40s %-15s %8s %10s %6s\n' tree generator wall_s cpu_s units
i=0
resolved=()
for spec in "${trees[@]}"; do
  i=$((i + 1))
  tree=$(cd "${spec%@*}" && pwd)
  resolved+=("$tree")
  generator=${spec#*@}
  if [ "$generator" = "$spec" ]; then
    generator="Unix Makefiles"
    grep -q generator_for "$tree/.ci/make-movie" 2>/dev/null && generator=Ninja
  fi
  dir=$work/build$i
  export BSIM_BUILD_LOG=$work/log$i
  : > "$BSIM_BUILD_LOG"
  cmake -S "$tree" -B "$dir" -G "$generator" -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF \
        -DCMAKE_CXX_COMPILER_LAUNCHER="$work/timed" >/dev/null
  start=$(date +%s.%N)
  cmake --build "$dir" -j"$jobs" --target billiards-export billiards-preview >/dev/null
  end=$(date +%s.%N)
  wall=$(awk -v a="$start" -v b="$end" 'BEGIN {print b - a}')
  cpu=$(awk '{s += $1 + $2} END {printf "%.1f", s}' "$BSIM_BUILD_LOG")
  units=$(wc -l < "$BSIM_BUILD_LOG")
  printf '%-40s %-15s %8.1f %10s %6s\n' "$(basename "$tree")" "$generator" "$wall" "$cpu" "$units"
done
i=0
for tree in "${resolved[@]}"; do
  i=$((i + 1))
  echo
  echo "heaviest translation units of $(basename "$tree") (CPU s):"
  awk '{printf "%7.1f  %s\n", $1 + $2, $3}' "$work/log$i" | sed "s|$work/build$i/||; s|$tree/||" |
    sort -rn | head -12
done
