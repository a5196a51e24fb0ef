#!/usr/bin/env bash
# Makes the Debian package (cpack -G DEB) into a temporary directory and checks its control fields
# (dpkg-deb -f: Package, Version, Depends naming povray, ffmpeg and the libraries), its file list
# (dpkg-deb -c: the manual pages gzip-compressed, the change log), that the packaged program runs and,
# where lintian is installed (.ci/test installs it), that lintian finds no error and no warning.
#   debian_package.sh BUILD_DIR VERSION
set -euo pipefail
build=$(cd "$1" && pwd)
version=$2
tmp=$(mktemp -d "${TMPDIR:-/tmp}/bsim-deb.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

cd "$build"
cpack -G DEB -B "$tmp" > "$tmp/cpack.log" 2>&1 || { cat "$tmp/cpack.log"; fail "cpack -G DEB"; }
deb=$tmp/billiards-sim_${version}_$(dpkg --print-architecture).deb
[ -f "$deb" ] || fail "no $(basename "$deb"); made: $(ls "$tmp")"

[ "$(dpkg-deb -f "$deb" Package)" = billiards-sim ] || fail "Package: $(dpkg-deb -f "$deb" Package)"
[ "$(dpkg-deb -f "$deb" Version)" = "$version" ] || fail "Version: $(dpkg-deb -f "$deb" Version)"
[ -n "$(dpkg-deb -f "$deb" Maintainer)" ] && [ -n "$(dpkg-deb -f "$deb" Section)" ] || fail "no Maintainer or Section"
depends=$(dpkg-deb -f "$deb" Depends)
# Each needed package as a whole name in the comma-separated list (a version may follow).
for package in povray povray-includes ffmpeg libosmesa6 libgl1 libglfw3 libsndfile1 zlib1g fonts-dejavu-core libc6; do
  [[ ", $depends," =~ ,\ $package(\ \([^\)]*\))?, ]] || fail "Depends lacks $package: $depends"
done

dpkg-deb -c "$deb" | awk '{print $NF}' > "$tmp/files"
for file in ./usr/bin/billiards-export ./usr/bin/billiards-preview ./usr/share/man/man1/billiards-export.1.gz \
            ./usr/share/man/man1/billiards-preview.1.gz ./usr/share/bash-completion/completions/billiards-export \
            ./usr/share/bash-completion/completions/billiards-preview ./usr/share/billiards-sim/scenes/break.scn \
            ./usr/share/doc/billiards-sim/copyright ./usr/share/doc/billiards-sim/changelog.gz; do
  grep -qxF "$file" "$tmp/files" || fail "the package lacks $file"
done
# Nothing else in usr/bin (no test or generator program), nothing outside usr/.
[ "$(grep -c '^\./usr/bin/.' "$tmp/files")" = 2 ] || fail "usr/bin holds: $(grep '^\./usr/bin/.' "$tmp/files")"
grep -v '^\./usr/\|^\./$' "$tmp/files" && fail "files outside usr/"

# No manual page left uncompressed.
grep '^\./usr/share/man/.*\.[0-9]$' "$tmp/files" && fail "manual pages installed uncompressed"

dpkg-deb -x "$deb" "$tmp/root"
[ "$("$tmp/root/usr/bin/billiards-export" --version)" = "billiards-export $version" ] || fail "packaged program"

# lintian's errors and warnings (the informational tags README lists are not shown by default).
if command -v lintian > /dev/null; then
  lintian --fail-on error,warning "$deb" > "$tmp/lintian.log" 2>&1 || { cat "$tmp/lintian.log"; fail "lintian"; }
  if grep -q '^[EW]: ' "$tmp/lintian.log"; then cat "$tmp/lintian.log"; fail "lintian reports tags"; fi
else
  echo "lintian is not installed: the package's lintian check is skipped"
fi
echo "package $(basename "$deb"): ok"
