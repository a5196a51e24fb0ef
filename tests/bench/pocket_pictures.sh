#!/usr/bin/env bash
# README's pictures of the pockets, rendered by billiards-export at final quality:
# - pockets_from_above.jpg: the top-right corner (the 9 resting on its shelf, behind the mouth) and the
#   top side pocket (the cue ball, rolled in, lying in its cup), each seen straight down from above;
# - rattle_strip.jpg: tests/bench/rattle.scn, the cue ball rattling out of the top-right corner, at
#   2.70, 2.83, 2.92, 3.04, 3.20, 3.33, 3.60 and 4.50 s (its four contacts with the jaws are at 2.83,
#   2.92, 3.04 and 3.33 s), left to right and top to bottom.
# About 2.5 minutes of two cores.
#   bash tests/bench/pocket_pictures.sh [BILLIARDS_EXPORT [OUTPUT_DIR]]
#   bash tests/bench/pocket_pictures.sh build/bin/billiards-export tests/bench
set -euo pipefail
cd "$(dirname "$0")/../.."
export_program=$(realpath "${1:-build/bin/billiards-export}")
out=${2:-tests/bench}
work=$(mktemp -d)
mkdir -p "$out"
trap 'rm -rf "$work"' EXIT

# The pockets from above: one scene, two cameras. The cue ball is struck at 2.5 s (after the stick's
# approach) and lies in the side pocket's cup by 3 s; at 2 frames a second the last frame (3.5 s) shows
# every ball at rest.
views=("corner 1.25 0.615 0.42  1.25 0.615 0" "side 0 0.67 0.36  0 0.67 0")
for view in "${views[@]}"; do
  read -r name camera <<<"$view"
  printf '%s\n' "cue 0 73.79" "stroke 1.4 0 0 0" "ball 0 -0.15 0.2" "ball 9 1.2394 0.6044" \
    "camera" "event start 0 0 hover  $camera" "endcamera" >"$work/$name.scn"
  "$export_program" "$work/$name.scn" --fps 2 --size 640x480 --quality final --quiet -o "$work/$name"
done
ffmpeg -hide_banner -loglevel error -y -i "$work/corner/frames/frame_00007.png" -i "$work/side/frames/frame_00007.png" \
  -filter_complex "hstack=inputs=2,scale=960:-2" -q:v 3 "$out/pockets_from_above.jpg"
echo "wrote $out/pockets_from_above.jpg"

# The rattle: every frame at 30 fps (a fixed camera: each traced only where the ball changed it), then
# eight of them tiled.
"$export_program" tests/bench/rattle.scn --fps 30 --size 480x270 --quality final --quiet -o "$work/rattle"
inputs=()
for t in 2.70 2.83 2.92 3.04 3.20 3.33 3.60 4.50; do
  frame=$(awk -v t="$t" 'BEGIN { printf "%05d", t * 30 + 0.5 }')
  inputs+=(-i "$work/rattle/frames/frame_$frame.png")
done
ffmpeg -hide_banner -loglevel error -y "${inputs[@]}" \
  -filter_complex "concat=n=8:v=1:a=0,scale=320:-2,tile=4x2" -q:v 3 "$out/rattle_strip.jpg"
echo "wrote $out/rattle_strip.jpg"
