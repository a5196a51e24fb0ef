#!/usr/bin/env bash
# Spectrograms and loudness of three shots at the calibrated sound level, as README's "The sound
# track" shows them: the built-in break, a soft two-ball tap (the cue ball at 0.8 m/s from
# (-0.6, 0) into a ball at (0.2, 0.01)) and scenes/bank.scn. Prints each track's integrated
# loudness, loudness range and true peak (ffmpeg's ebur128) and writes their spectrograms (ffmpeg's
# showspectrumpic, 0-12 kHz, one above the other in that order) to PICTURE.
#   bash tests/bench/shot_spectrograms.sh [BILLIARDS_EXPORT [PICTURE]]
#   bash tests/bench/shot_spectrograms.sh build/bin/billiards-export tests/bench/shot_spectrograms.png
set -euo pipefail
cd "$(dirname "$0")/../.."
export_program=$(realpath "${1:-build/bin/billiards-export}")
picture=${2:-tests/bench/shot_spectrograms.png}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

printf 'cue 0 0\nball 0 -0.6 0 0.028575  0.8 0 0  1 0 0 0\nball 1 0.2 0.01 0.028575  0 0 0  1 0 0 0\n' >"$work/tap.scn"
"$export_program" --no-render --quiet -o "$work/break"
"$export_program" "$work/tap.scn" --no-render --quiet -o "$work/tap"
"$export_program" scenes/bank.scn --no-render --quiet -o "$work/bank"

inputs=()
for shot in break tap bank; do
  wav=$work/$shot/soundtrack.wav
  summary=$(ffmpeg -hide_banner -nostats -i "$wav" -af ebur128=peak=true -f null - 2>&1 | tail -n 12)
  loudness=$(awk '$1 == "I:" {print $2}' <<<"$summary")
  range=$(awk '$1 == "LRA:" {print $2}' <<<"$summary")
  peak=$(awk '$1 == "Peak:" {print $2}' <<<"$summary")
  printf '%-6s %6s LUFS  range %5s LU  true peak %5s dBTP\n' "$shot" "$loudness" "$range" "$peak"
  ffmpeg -hide_banner -loglevel error -y -i "$wav" \
    -lavfi "showspectrumpic=s=640x160:legend=1:scale=log:fscale=lin:stop=12000" "$work/$shot.png"
  inputs+=(-i "$work/$shot.png")
done
ffmpeg -hide_banner -loglevel error -y "${inputs[@]}" -filter_complex vstack=inputs=3 "$picture"
echo "wrote $picture"
