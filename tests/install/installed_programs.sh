#!/usr/bin/env bash
# Installs the build into a temporary prefix (cmake --install) and runs the installed programs from a
# directory outside the source and build trees: --help, a snapshot, an --events-only export; checks that
# the manual pages (gzip-compressed, as Debian installs them) and bash completions are installed and name
# every option each program's --help lists, that the completion offers --quality's and --camera's values
# and the scene files, that the change log's entry is this version and that every example scene is there.
#   installed_programs.sh BUILD_DIR VERSION
set -euo pipefail
build=$(cd "$1" && pwd)
version=$2
src_dir=$(cd "$(dirname "$0")/../.." && pwd)
tmp=$(mktemp -d "${TMPDIR:-/tmp}/bsim-install.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

prefix=$tmp/prefix
cmake --install "$build" --prefix "$prefix" > "$tmp/install.log" || { cat "$tmp/install.log"; fail "cmake --install"; }
[ "$(ls "$prefix/bin")" = "$(printf 'billiards-export\nbilliards-preview')" ] || fail "bin holds $(ls "$prefix/bin")"
mkdir "$tmp/elsewhere"
cd "$tmp/elsewhere"
export PATH="$prefix/bin:$PATH"

for program in billiards-export billiards-preview; do
  [ "$(command -v $program)" = "$prefix/bin/$program" ] || fail "$program is not the installed one"
  [ "$($program --version)" = "$program $version" ] || fail "$program --version: $($program --version)"
  $program --help > "$program.help" || fail "$program --help"
  # The manual page compressed as Debian installs one (gzip, no time stamp in its header): read it unpacked.
  [ -s "$prefix/share/man/man1/$program.1.gz" ] || fail "no $prefix/share/man/man1/$program.1.gz"
  [ ! -e "$prefix/share/man/man1/$program.1" ] || fail "$program.1 is installed uncompressed too"
  gzip -t "$prefix/share/man/man1/$program.1.gz" || fail "$program.1.gz is not gzip"
  [ "$(od -An -tu4 -j4 -N4 "$prefix/share/man/man1/$program.1.gz" | tr -d ' ')" = 0 ] ||
    fail "$program.1.gz carries a time stamp"
  man=$tmp/$program.1
  gzip -dc "$prefix/share/man/man1/$program.1.gz" > "$man"
  completion=$prefix/share/bash-completion/completions/$program
  [ -s "$man" ] || fail "$program.1.gz is empty"
  [ -s "$completion" ] || fail "no $completion"
  grep -q "^\.TH \"${program^^}\" \"1\" .*billiards-sim $version" "$man" || fail "$man has no .TH of version $version"
  # Every option --help lists ("  -o, --output DIR   ...", "  --fps N   ..."): in the manual page as
  # \fB\-\-fps\fR, offered by the completion for a word starting with '-'.
  options=$(sed -n 's/^  \(-[a-z]\), \(--[a-z-]*\).*/\1 \2/p; s/^  \(--[a-z-]*\).*/\1/p' "$program.help")
  [ "$(echo $options | wc -w)" -ge 10 ] || fail "$program --help lists only: $options"
  offered=$(bash -c "source '$completion'; COMP_WORDS=($program -); COMP_CWORD=1; _${program//-/_}; echo \" \${COMPREPLY[*]} \"")
  for option in $options; do
    grep -qF "\\fB${option//-/\\-}\\fR" "$man" || fail "$man does not name $option"
    [[ $offered == *" $option "* ]] || fail "the completion of $program does not offer $option"
  done
done

# The change log where Debian keeps a native package's, its latest entry this version.
changelog=$prefix/share/doc/billiards-sim/changelog.gz
[ -s "$changelog" ] || fail "no $changelog"
gzip -dc "$changelog" | head -1 | grep -qxF "billiards-sim ($version) unstable; urgency=medium" ||
  fail "the change log's first entry is not version $version: $(gzip -dc "$changelog" | head -1)"
# Every example scene, and nothing else, in the scenes folder.
[ "$(cd "$prefix/share/billiards-sim/scenes" && ls)" = "$(cd "$src_dir/scenes" && ls -- *.scn)" ] ||
  fail "the installed scenes are $(ls "$prefix/share/billiards-sim/scenes")"

# The completion's values: --quality's presets, --camera's and --overlay's words, the scene files.
complete_words() {  # PROGRAM WORD... : what the completion offers for the last word
  bash -c "source '$prefix/share/bash-completion/completions/$1'; COMP_WORDS=(\"\$@\"); \
           COMP_CWORD=\$((\$# - 1)); _${1//-/_}; echo \"\${COMPREPLY[*]}\"" _ "$@"
}
[ "$(complete_words billiards-export --quality '')" = "draft final" ] || fail "--quality completes to other words"
# bash splits "--camera=a" at the "=" into three words.
[ "$(complete_words billiards-export --camera = a)" = "auto" ] || fail "--camera=a does not complete to auto"
[ "$(complete_words billiards-preview --overlay paths,ev)" = "paths,events" ] || fail "--overlay's list"
cp "$prefix/share/billiards-sim/scenes/bank.scn" .
touch notes.txt
[ "$(complete_words billiards-preview b)" = "bank.scn" ] || fail "the scene does not complete to bank.scn"

# The installed programs at work, with the installed example scene.
billiards-preview "$prefix/share/billiards-sim/scenes/bank.scn" --at 1 --size 320x180 -o shot.png --quiet ||
  fail "billiards-preview snapshot"
[ "$(head -c 8 shot.png | od -An -tx1 | tr -d ' ')" = "89504e470d0a1a0a" ] || fail "shot.png is not a PNG"
billiards-export --events-only -o events --quiet || fail "billiards-export --events-only"
grep -q '"events"' events/events.json || fail "events.json holds no events"
[ -s events/trajectory.csv ] && [ -s events/camera.csv ] || fail "trajectory.csv or camera.csv missing"
echo "installed programs: ok"
