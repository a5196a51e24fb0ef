#!/usr/bin/env bash
# Shows that a change leaves every scene's outputs byte for byte as they were: builds
# billiards-export at BASE (a commit, default the one named below) in a temporary work tree (or takes
# BASE's programs from a directory, when BASE is one that holds billiards-export), runs it
# and the binary given (default build/bin/billiards-export) with --no-render on every scene in
# scenes/ and the built-in break, each with its own camera and the automatic director's, and compares
# every file they write (events.json, trajectory.csv, camera.csv, each .pov, soundtrack.wav; run.json
# holds times and paths, so it is left out). It also compares the director's script text
# (billiards-preview --write-camera) when both trees build billiards-preview.
#   bash tests/same_outputs.sh [BASE [BILLIARDS_EXPORT]]
#   bash tests/same_outputs.sh OLD_BUILD/bin build/bin/billiards-export
# Exits 0 when everything is identical, 1 naming the first files that differ.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
# The commit before the restructuring of the camera model, the director and the file writing.
base=${1:-dc682d2}
new_export=$(realpath "${2:-build/bin/billiards-export}")
new_preview=$(dirname "$new_export")/billiards-preview
work=$(mktemp -d)
trap 'git -C "$root" worktree remove --force "$work/base" >/dev/null 2>&1 || true; rm -rf "$work"' EXIT

if [ -x "$base/billiards-export" ]; then
  old_export=$(realpath "$base/billiards-export")
  old_preview=$(realpath "$base/billiards-preview")
else
  echo "building billiards-export at $base"
  git worktree add --detach "$work/base" "$base" >/dev/null 2>&1
  launcher=()
  command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
  cmake -S "$work/base" -B "$work/base/build" -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF "${launcher[@]}" >/dev/null
  cmake --build "$work/base/build" -j"$(nproc)" --target billiards-export billiards-preview >/dev/null
  old_export=$work/base/build/bin/billiards-export
  old_preview=$work/base/build/bin/billiards-preview
fi

differ=0
compare() {  # name, then the arguments both programs get
  local name=$1; shift
  "$old_export" "$@" --no-render --quiet -o "$work/old/$name"
  "$new_export" "$@" --no-render --quiet -o "$work/new/$name"
  if ! diff -rq -x run.json "$work/old/$name" "$work/new/$name"; then
    differ=1
  else
    echo "same: $name ($(find "$work/new/$name" -type f ! -name run.json | wc -l) files)"
  fi
}
for scene in scenes/*.scn; do
  name=$(basename "$scene" .scn)
  compare "$name" "$scene"
  compare "$name-auto" "$scene" --camera auto
done
compare builtin
compare builtin-auto --camera auto
compare bank-24fps scenes/bank.scn --fps 24 --size 640x360 --quality draft

if [ -x "$old_preview" ] && [ -x "$new_preview" ]; then
  for scene in scenes/*.scn; do
    "$old_preview" "$scene" --write-camera "$work/old.cam" --quiet
    "$new_preview" "$scene" --write-camera "$work/new.cam" --quiet
    if cmp -s "$work/old.cam" "$work/new.cam"; then
      echo "same: director's script for $scene"
    else
      echo "differ: director's script for $scene"; diff "$work/old.cam" "$work/new.cam" | head -20; differ=1
    fi
  done
fi

if [ "$differ" -ne 0 ]; then
  echo "outputs differ from $base" >&2
  exit 1
fi
echo "every output is byte-identical to $base"
