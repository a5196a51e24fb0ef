#!/usr/bin/env bash
# The look before and after: the same instants rendered by a baseline commit's billiards-export and by
# this tree's, at final quality, side by side in one contact sheet (the README's look gallery).
#
#   cmake --build build --target billiards-export look_bench develop_bench
#   tests/bench/look_gallery.sh [--base COMMIT] [--size WxH] [--sheet FILE] [--keep DIR [--again]]
#
# The instants: the built-in break's frames 0 (the still before the break, close behind the cue
# ball), 76 (the break), 90 (the spread from above), 150 and 297 (the wide shots of the room),
# scenes/runout.scn's frames 360 (behind the cue ball, a step to its left) and 660 (from high over the
# near side as a ball runs to its pocket), and scenes/follow.scn's frame 40 (0.65 m behind the cue
# ball, the focus's close-up). Each commit writes its frames with `--no-render` (final quality,
# --size, default 1280x720) from its own scenes/ file (the language has grown since, and the scenes
# with it), and each instant is rendered by one POV-Ray process with the exporter's own options. Both
# render this tree's frame files (the camera, the balls and the stick where this tree puts them),
# each with its own commit's billiards.inc (the table, the balls' look, the lights, the room), so
# the two differ in the look alone. The baseline's (default 172eaef, the look before the cloth, the hall's light, the
# pockets' fill and the lens) is developed as the develop stage does without a lens (`look_bench
# develop`), this tree's with each frame's lens (`develop_bench --out`: depth of field, aberration,
# vignetting, grain). The sheet (default tests/bench/look_gallery.jpg) has a row an instant, the
# baseline on the left and this tree on the right, each at half size, and a last row with the focus's
# close-up at full size (the middle of its top half). --again makes the sheet again from the pictures
# a run with the same --keep DIR left there, rendering nothing. About 16 renders of 8 to 20 s
# of one core at 1280x720. Never run by ctest.
set -euo pipefail

root=$(cd "$(dirname "$0")/../.." && pwd)
base=172eaef
size=1280x720
sheet=$root/tests/bench/look_gallery.jpg
keep=
again=
while [ $# -gt 0 ]; do
  case $1 in
    --base) base=$2; shift 2 ;;
    --size) size=$2; shift 2 ;;
    --sheet) sheet=$2; shift 2 ;;
    --keep) keep=$2; shift 2 ;;
    --again) again=1; shift ;;
    *) echo "usage: $0 [--base COMMIT] [--size WxH] [--sheet FILE] [--keep DIR [--again]]" >&2; exit 2 ;;
  esac
done
bin=$root/build/bin
for tool in billiards-export look_bench develop_bench; do
  [ -x "$bin/$tool" ] || { echo "look_gallery: build $tool first (cmake --build build --target $tool)" >&2; exit 1; }
done
for program in povray ffmpeg; do
  command -v $program >/dev/null || { echo "look_gallery: $program is needed" >&2; exit 1; }
done
font=/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf
[ -f "$font" ] || { echo "look_gallery: $font is needed (fonts-dejavu-core)" >&2; exit 1; }
width=${size%x*}
height=${size#*x}

# shellcheck source=baseline_exporter.sh
. "$root/tests/bench/baseline_exporter.sh"
bench_work "$keep"
export_a=$(baseline_exporter "$root" "$base" "$work") || { echo "look_gallery: giving up" >&2; exit 1; }

# scene (empty: the built-in break), its name, its frames.
instants=("break 0" "break 76" "break 90" "break 150" "break 297" "runout 360" "runout 660" "follow 40")
scene_file() {  # tree name
  case $2 in break) ;; *) echo "$1/scenes/$2.scn" ;; esac
}
frames_of() {  # name
  local i
  for i in "${instants[@]}"; do [ "${i% *}" = "$1" ] && printf '%s ' "${i#* }"; done
}

[ -z "$again" ] || [ -n "$keep" ] || { echo "look_gallery: --again needs --keep DIR" >&2; exit 2; }
for name in break runout follow; do
  [ -z "$again" ] || break
  for side in A B; do
    exporter=$export_a file=$(scene_file "$work/base-src" $name)
    [ $side = B ] && exporter=$bin/billiards-export file=$(scene_file "$root" $name)
    rm -rf "${work:?}/$side/$name"
    # shellcheck disable=SC2086 # an empty $file is the built-in break
    "$exporter" $file --no-render --quiet --quality final --size "$size" -o "$work/$side/$name" >/dev/null
  done
  # The baseline: this tree's frame with the baseline's include, one POV-Ray run with the exporter's
  # options, developed without a lens.
  for f in $(frames_of $name); do
    n=$(printf 'frame_%05d' "$f")
    cp "$work/B/$name/frames/$n.pov" "$work/A/$name/frames/$n.pov"
    echo "look_gallery: $base's $name frame $f" >&2
    (cd "$work/A/$name/frames" &&
      povray -D +FH +WT1 "+I$n.pov" "+O$n.hdr" "+W$width" "+H$height" +Q9 +A0.3 +AM2 +R2 >/dev/null 2>"$work/log") ||
      { tail -3 "$work/log" >&2; exit 1; }
    "$bin/look_bench" develop "$work/A/$name/frames/$n.hdr" "$work/A/$name/$n.png"
  done
  # This tree: rendered and developed with each frame's lens.
  echo "look_gallery: this tree's $name frames $(frames_of $name)" >&2
  # shellcheck disable=SC2046 # one argument a frame
  "$bin/develop_bench" "$work/B/$name/frames" $(frames_of $name) --size "$size" --quality final --runs 1 \
    --out "$work/B/$name" >"$work/B/$name/develop.txt"
done

# The sheet: a row an instant, the baseline left and this tree right, each at half size, labelled;
# then the focus's close-up again at full size: the middle of its top half, where the far rail and
# the ball beyond lie.
cell_w=$((width / 2)) cell_h=$((height / 2)) text=$((height / 36))
head=$(git -C "$root" rev-parse --short HEAD)
inputs=() filters='' k=0
add_cell() {  # picture label filter
  inputs+=(-i "$1")
  filters+="[$k:v]$3,drawtext=fontfile=$font:text='$2':x=8:y=8:fontsize=$text:fontcolor=white:box=1:boxcolor=black@0.5:boxborderw=4[c$k];"
  k=$((k + 1))
}
close=${instants[-1]}
for i in "${instants[@]}" "$close full"; do
  read -r name f whole <<<"$i"
  n=$(printf 'frame_%05d' "$f")
  filter=scale=$cell_w:$cell_h what="$name frame $f"
  [ -z "$whole" ] || filter=crop=$cell_w:$cell_h:$((width / 4)):0 what="$name frame $f at full size"
  add_cell "$work/A/$name/$n.png" "$what, $base" "$filter"
  add_cell "$work/B/$name/$n.png" "$what, $head" "$filter"
done
rows=
for ((r = 0; r < k / 2; ++r)); do
  filters+="[c$((2 * r))][c$((2 * r + 1))]hstack[r$r];"
  rows+="[r$r]"
done
filters+="${rows}vstack=inputs=$((k / 2))"
ffmpeg -loglevel error -y "${inputs[@]}" -filter_complex "$filters" -frames:v 1 -q:v 3 "$sheet"
echo "look_gallery: wrote $sheet" >&2
for name in break runout follow; do
  [ -z "$again" ] || break
  echo "develop stage, $name:"
  cat "$work/B/$name/develop.txt"
done
