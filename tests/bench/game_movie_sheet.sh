#!/usr/bin/env bash
# README's contact sheet of a game's movie (scenes/game9.scn), captions and replay included: the movie
# rendered small and at a few frames a second by billiards-export, then 20 of its frames spread evenly
# over the game and 4 over the replay, tiled in movie order, each labelled with its movie time.
# A minute and a half on two cores.
#   bash tests/bench/game_movie_sheet.sh [BUILD_BIN [OUTPUT_DIR]]
#   bash tests/bench/game_movie_sheet.sh build/bin tests/bench
set -euo pipefail
cd "$(dirname "$0")/../.."
bin=$(realpath "${1:-build/bin}")
out=${2:-tests/bench}
scene=scenes/game9.scn
fps=2
work=$(mktemp -d)
mkdir -p "$out"
trap 'rm -rf "$work"' EXIT

"$bin/billiards-export" "$scene" -o "$work/movie" --size 480x270 --quality draft --fps "$fps" --quiet
# camera.csv: frame,time,...,replay (the last column).
pick() {  # $1: 0 the game, 1 the replay; $2: how many
  awk -F, -v want="$1" -v n="$2" 'NR > 1 && $NF == want { f[c++] = $1 }
    END { for (i = 0; i < n; i++) print f[int((i + 0.5) * c / n)] }' "$work/movie/camera.csv"
}
k=0
for frame in $(pick 0 20) $(pick 1 4); do
  seconds=$(awk -v f="$frame" -v fps="$fps" 'BEGIN { printf "%dm%02ds", int(f / fps / 60), int(f / fps) % 60 }')
  cp "$work/movie/frames/$(printf 'frame_%05d.png' "$frame")" "$work/tile_$(printf '%02d' "$k").png"
  echo "$seconds" > "$work/label_$(printf '%02d' "$k").txt"
  k=$((k + 1))
done
font=/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf
inputs=()
for ((i = 0; i < k; i++)); do
  label=$(cat "$work/label_$(printf '%02d' "$i").txt")
  ffmpeg -hide_banner -loglevel error -y -i "$work/tile_$(printf '%02d' "$i").png" \
    -vf "drawtext=fontfile=$font:text='$label':x=8:y=8:fontsize=18:fontcolor=white:box=1:boxcolor=black@0.5:boxborderw=4" \
    "$work/labelled_$(printf '%02d' "$i").png"
done
ffmpeg -hide_banner -loglevel error -y -start_number 0 -i "$work/labelled_%02d.png" \
  -vf "tile=4x6:padding=4:color=black" -frames:v 1 -q:v 3 "$out/game9_movie_sheet.jpg"
echo "wrote $out/game9_movie_sheet.jpg ($k frames of the movie)"
