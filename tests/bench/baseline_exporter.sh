# shellcheck shell=bash
# Sourced by the look's scripts (look_cost.sh, look_gallery.sh): their scratch folder, and an earlier
# commit's billiards-export built from its own sources.
#
#   bench_work KEEP                     # sets $work: KEEP, or a temporary folder removed at exit
#   baseline_exporter ROOT COMMIT DIR   # prints the exporter's path
#
# `git archive COMMIT` of the repository at ROOT is unpacked into DIR/base-src and built there
# (Release, with ccache when there is one, so a second build is quick); a build already there is
# reused. The build's log is DIR/base-build.log.
baseline_exporter() {
  local root=$1 commit=$2 dir=$3
  local src=$dir/base-src
  if [ ! -x "$src/build/bin/billiards-export" ]; then
    rm -rf "$src" && mkdir -p "$src"
    git -C "$root" archive "$commit" | tar -x -C "$src"
    local launcher=()
    command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
    cmake -S "$src" -B "$src/build" -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" >"$dir/base-build.log" 2>&1
    cmake --build "$src/build" --target billiards-export -j2 >>"$dir/base-build.log" 2>&1 ||
      { echo "the baseline $commit did not build; see $dir/base-build.log" >&2; return 1; }
  fi
  echo "$src/build/bin/billiards-export"
}

bench_work() {
  work=${1:-$(mktemp -d)}
  mkdir -p "$work"
  # shellcheck disable=SC2064 # the folder is known now
  [ -n "$1" ] || trap "rm -rf '$work'" EXIT
}
