#!/usr/bin/env bash
# A rattle in a pocket's jaws beside a cushion's thud, as README's "The sound track" shows them, at the
# calibrated sound level. The rattle: the cue ball at 2.5 m/s sends a ball into the top-right corner
# 36 mm off its middle; it knocks on the jaws five times in 0.7 s (at 0.80, 0.97, 0.62, 0.33 and
# 0.06 m/s) and stays out. The thud: a lone ball into the right-hand cushion at 0.9 m/s. Prints each
# track's integrated loudness and true peak (ffmpeg's ebur128) and the peak level of each knock and
# of the thud (ffmpeg's astats over the 20 ms from each contact), and writes the spectrograms of the
# second and a half from the strike (ffmpeg's showspectrumpic, 50 Hz to 8 kHz on a log scale, the
# rattle above the thud) to PICTURE.
#   bash tests/bench/rattle_sound.sh [BILLIARDS_EXPORT [PICTURE]]
#   bash tests/bench/rattle_sound.sh build/bin/billiards-export tests/bench/rattle_spectrogram.png
set -euo pipefail
cd "$(dirname "$0")/../.."
export_program=$(realpath "${1:-build/bin/billiards-export}")
picture=${2:-tests/bench/rattle_spectrogram.png}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

printf 'cue 0 45\nball 0 0.5176 -0.1683 0.028575  1.7678 1.7678 0  1 0 0 0\nball 1 0.9419 0.2560 0.028575  0 0 0  1 0 0 0\n' \
  >"$work/rattle.scn"
printf 'cue 0 0\nball 0 0.9 0 0.028575  0.9 0 0  1 0 0 0\n' >"$work/thud.scn"

inputs=()
for shot in rattle thud; do
  "$export_program" "$work/$shot.scn" --no-render --quiet --audio-lead 0 -o "$work/$shot"
  wav=$work/$shot/soundtrack.wav
  summary=$(ffmpeg -hide_banner -nostats -i "$wav" -af ebur128=peak=true -f null - 2>&1 | tail -n 12)
  loudness=$(awk '$1 == "I:" {print $2}' <<<"$summary")
  peak=$(awk '$1 == "Peak:" {print $2}' <<<"$summary")
  printf '%-6s %6s LUFS  true peak %5s dBTP\n' "$shot" "$loudness" "$peak"
  # Each contact's peak: the ball-jaw events of the rattle, the ball-rail events of the thud.
  type=$([ "$shot" = rattle ] && echo ball-jaw || echo ball-rail)
  times=$(grep -o "\"time\": [0-9.e-]*, \"type\": \"$type\"" "$work/$shot/events.json" | awk '{print $2}' | tr -d ,)
  for t in $times; do
    level=$(ffmpeg -hide_banner -nostats -ss "$t" -t 0.02 -i "$wav" -af astats=metadata=0 -f null - 2>&1 |
      awk '/Overall/ {overall = 1} overall && /Peak level dB/ {print $NF; exit}')
    printf '         contact at %.3f s: peak %s dBFS\n' "$t" "$level"
  done
  ffmpeg -hide_banner -loglevel error -y -ss 2.4 -t 1.5 -i "$wav" \
    -lavfi "showspectrumpic=s=1000x320:legend=1:scale=log:fscale=log:start=50:stop=8000" "$work/$shot.png"
  inputs+=(-i "$work/$shot.png")
done
ffmpeg -hide_banner -loglevel error -y "${inputs[@]}" -filter_complex vstack=inputs=2 "$picture"
echo "wrote $picture"
