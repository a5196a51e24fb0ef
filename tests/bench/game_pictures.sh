#!/usr/bin/env bash
# README's pictures of a game (scenes/game9.scn), drawn by billiards-preview:
# - game9_timeline.png: the timeline picture, each shot's box naming the player at the table, the
#   planned ball and pocket and the rules' call;
# - game9_sheet.jpg: a contact sheet, one picture per shot at the moment the stick addresses the cue
#   ball, through the automatic director's camera, numbered by shot.
# About half a minute of one core.
#   bash tests/bench/game_pictures.sh [BUILD_BIN [OUTPUT_DIR]]
#   bash tests/bench/game_pictures.sh build/bin tests/bench
set -euo pipefail
cd "$(dirname "$0")/../.."
bin=$(realpath "${1:-build/bin}")
out=${2:-tests/bench}
scene=scenes/game9.scn
work=$(mktemp -d)
mkdir -p "$out"
trap 'rm -rf "$work"' EXIT

"$bin/billiards-preview" "$scene" --timeline -o "$out/game9_timeline.png" --size 1600x520 --quiet
"$bin/billiards-export" "$scene" --events-only --quiet -o "$work/events"
shots=$(grep -c '"type": "cue"' "$work/events/events.json")
at=()
for ((k = 1; k <= shots; k++)); do at+=(--at "shot:$k"); done
"$bin/billiards-preview" "$scene" --camera auto "${at[@]}" -o "$work/shot_%t.png" --size 480x270 --quiet
columns=4
rows=$(((shots + columns - 1) / columns))
font=/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf
ffmpeg -hide_banner -loglevel error -y -start_number 1 -i "$work/shot_shot_%d.png" \
  -vf "drawtext=fontfile=$font:text='shot %{eif\:n+1\:d}':x=10:y=h-th-10:fontsize=22:fontcolor=white:box=1:boxcolor=black@0.5:boxborderw=6,tile=${columns}x${rows}:padding=4:color=black" \
  -frames:v 1 -q:v 3 "$out/game9_sheet.jpg"
echo "wrote $out/game9_timeline.png $out/game9_sheet.jpg ($shots shots)"
