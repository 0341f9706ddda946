#!/usr/bin/env bash
# `cmake --install` into a fresh prefix, then the installed l2wall run on the default wall for
# 2 frames from a folder outside the working tree: it must find its pipeserver, the bunny, the
# golden images and the image codec module in the prefix, not in the build tree.
# Arguments: the build folder.
set -uo pipefail
build=$1
prefix=$(mktemp -d)
trap 'rm -rf "$prefix"' EXIT
fail() {
  echo "FAIL $*"
  exit 1
}
cmake --install "$build" --prefix "$prefix" >"$prefix/install.log" 2>&1 ||
  fail "cmake --install: $(tail -5 "$prefix/install.log")"
for program in l2wall pipeserver vizserver lightning2_emu tilelayout strip_headers \
  sync_backchannel show_wall; do
  [[ -x $prefix/bin/$program ]] || fail "no $prefix/bin/$program"
done
for file in share/lightning2/walls/kd-2x2.toml share/lightning2/data/bunny.ply \
  share/lightning2/tests/golden_images/manifest.toml share/doc/lightning2/README.md \
  share/doc/lightning2/strip-header.md share/doc/lightning2/wall-file.md; do
  [[ -f $prefix/$file ]] || fail "no $prefix/$file"
done
# The defaults in the prefix, as --help shows them.
help=$("$prefix/bin/l2wall" run --help)
[[ $help == *"--pipeserver-program TEXT=$prefix/bin/pipeserver"* ]] ||
  fail "l2wall run's default --pipeserver-program is not $prefix/bin/pipeserver: $(grep -A1 -- --pipeserver-program <<<"$help")"
help=$("$prefix/bin/l2wall" golden check --help)
[[ $help == *"--goldens DIR=$prefix/share/lightning2/tests/golden_images"* ]] ||
  fail "the default --goldens is not in the prefix: $(grep -- --goldens <<<"$help")"

codec=$prefix/lib/lightning2/libl2_png_oiio.so
[[ -f $codec ]] || fail "no $codec"

mkdir "$prefix/elsewhere"
cd "$prefix/elsewhere" || exit 1
# The dynamic loader's log of every process of the run: the image codec they load on their first
# picture of another format than PNG (PNG they read and write themselves), here a PPM the
# pipeservers show, must be the prefix's, not the build tree's.
printf 'P6\n2 2\n255\n\377\0\0\0\377\0\0\0\377\377\377\377' >picture.ppm
LD_DEBUG=libs LD_DEBUG_OUTPUT="$prefix/loader" \
  "$prefix/bin/l2wall" run --scene picture --content picture.ppm --frames 2 --no-progress \
  --out run >run.log 2>&1
status=$?
[[ $status -eq 0 ]] || fail "installed l2wall run: exit $status: $(tail -5 run.log)"
# (found through the run path $ORIGIN/../lib/lightning2: PREFIX/bin/../lib/lightning2/...)
installed="calling init: $prefix/\(bin/\.\./\)\?lib/lightning2/libl2_png_oiio\.so$"
grep -qs "$installed" "$prefix"/loader.* ||
  fail "the installed programs did not load $codec: $(grep -hs 'calling init: .*png_oiio' "$prefix"/loader.* | head -3)"
if grep -hs 'calling init: .*png_oiio' "$prefix"/loader.* | grep -v "$installed"; then
  fail "an installed program loaded another image codec than $codec (above)"
fi
grep -q '^l2wall run: 2 frames on 4 displays from 4 pipeservers' run/summary.txt ||
  fail "summary: $(head -1 run/summary.txt)"
for d in 0 1 2 3; do
  [[ -s run/frame-1/display-$d.png ]] || fail "no run/frame-1/display-$d.png"
done
echo "ok   installed into $prefix; l2wall run from there: $(head -1 run/summary.txt)"
