#!/usr/bin/env bash
# A renderer of your own built outside this tree (examples/README.md): `cmake --install` into a
# fresh prefix, then examples/ configured and built alone against it with plain cmake
# (find_package(Lightning2), Lightning2::renderer) and none of this project's flags, and the
# program it builds run: --help; one frame alone, which must be the very picture this build's
# spinning_cubes writes, written with libpng and no image codec module (install_run.sh shows the
# installed programs load the prefix's module when they need it); and 2 frames live under the
# installed l2wall, from a folder outside the working tree.
# Arguments: the build folder, its C++ compiler, this build's spinning_cubes.
set -uo pipefail
build=$1
cxx=$2
in_tree=$3
source=$(cd "$(dirname "$0")/.." && pwd)
prefix=$(mktemp -d)
trap 'rm -rf "$prefix"' EXIT
fail() {
  echo "FAIL $*"
  exit 1
}
# The user's environment, not ours, decides a user's flags: none here.
unset CXXFLAGS CPPFLAGS LDFLAGS CMAKE_PREFIX_PATH

cmake --install "$build" --prefix "$prefix" >"$prefix/install.log" 2>&1 ||
  fail "cmake --install: $(tail -5 "$prefix/install.log")"
package=$prefix/lib/cmake/Lightning2
for file in "$package/Lightning2Config.cmake" "$package/Lightning2ConfigVersion.cmake" \
  "$package/Lightning2Targets.cmake" "$prefix/include/lightning2/pipeserver/renderer.hpp"; do
  [[ -f $file ]] || fail "no $file"
done
# The project's warnings and -Werror are its own (cmake/Warnings.cmake): not in what it exports.
if grep -n 'INTERFACE_COMPILE_OPTIONS.*-W' "$package"/Lightning2Targets*.cmake; then
  fail "the package's targets carry warning options (above)"
fi

outside=$prefix/outside
cmake -S "$source/examples" -B "$outside" -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_EXPORT_COMPILE_COMMANDS=ON >"$prefix/configure.log" 2>&1 ||
  fail "configuring examples/ alone: $(tail -20 "$prefix/configure.log")"
cmake --build "$outside" -j 2 >"$prefix/build.log" 2>&1 ||
  fail "building examples/ alone: $(tail -30 "$prefix/build.log")"
program=$outside/spinning_cubes
[[ -x $program ]] || fail "no $program"
# Compiled with no -W option and no include folder of the working tree or the build.
command=$(grep '"command"' "$outside/compile_commands.json" | grep spinning_cubes.cpp)
[[ -n $command ]] || fail "no compile command for spinning_cubes.cpp in $outside/compile_commands.json"
[[ $command != *" -W"* ]] || fail "spinning_cubes.cpp compiled with warning options: $command"
[[ $command != *"$source/"*"/include"* ]] ||
  fail "spinning_cubes.cpp compiled with the working tree's headers: $command"

"$program" --help >"$prefix/help.log" 2>&1 || fail "$program --help: $(tail -5 "$prefix/help.log")"

mkdir "$prefix/elsewhere"
cd "$prefix/elsewhere" || exit 1
for which in outside in-tree; do
  binary=$program
  [[ $which == in-tree ]] && binary=$in_tree
  # The dynamic loader's log: the image codec (OpenImageIO's module) is not needed to write a PNG.
  LD_DEBUG=libs LD_DEBUG_OUTPUT="$prefix/loader-$which" \
    "$binary" --pipeserver 1 --frame 3 --out "alone-$which" >"alone-$which.log" 2>&1 ||
    fail "$binary --pipeserver 1 --frame 3: $(tail -5 "alone-$which.log")"
done
cmp -s alone-outside/scanout-1.png alone-in-tree/scanout-1.png ||
  fail "the program built outside draws another frame than $in_tree"
if grep -hs 'calling init: .*png_oiio' "$prefix"/loader-outside.*; then
  fail "the program built outside loaded an image codec (above) to write a PNG"
fi
grep -qs 'calling init: .*libpng16' "$prefix"/loader-outside.* ||
  fail "the program built outside did not load libpng: its log holds no PNG writer"

"$prefix/bin/l2wall" run --pipeserver-program "$program" --frames 2 --no-progress --out run \
  >run.log 2>&1
status=$?
[[ $status -eq 0 ]] || fail "installed l2wall run --pipeserver-program $program: exit $status: $(tail -5 run.log)"
grep -q '^l2wall run: 2 frames on 4 displays from 4 pipeservers' run/summary.txt ||
  fail "summary: $(head -1 run/summary.txt)"
for d in 0 1 2 3; do
  [[ -s run/frame-1/display-$d.png ]] || fail "no run/frame-1/display-$d.png"
done
echo "ok   examples/ built alone against $prefix; l2wall run: $(head -1 run/summary.txt)"
