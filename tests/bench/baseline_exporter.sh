# Sourced by the look's scripts: builds an earlier commit's billiards-export from its own sources.
#
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
