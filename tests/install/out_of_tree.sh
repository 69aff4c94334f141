#!/bin/bash
# A tutorial copied out of the tree builds against an installed
# fsgmpm. Installs the build into a temporary prefix (cmake --install),
# copies doc/tutorials/step-1 to a temporary directory, configures and builds
# it with its own CMakeLists.txt against the installed package only, runs it at
# 10 cells across, and runs the installed fsgmpm program on its default
# scene for a few steps.
# Usage: out_of_tree.sh <build dir> <source dir>
set -euo pipefail
build=$(cd "$1" && pwd)
source=$(cd "$2" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
config=$(find "$work/prefix" -name fsgmpmConfig.cmake)
test -n "$config" || { echo "FAIL: no fsgmpmConfig.cmake installed"; exit 1; }
for f in include/fsgmpm/simulator.h include/fsgmpm/step/mpm_step.h bin/fsgmpm; do
  test -e "$work/prefix/$f" || { echo "FAIL: $f not installed"; exit 1; }
done

# Out of the tree: only the installed headers and library can be found.
cp -r "$source/doc/tutorials/step-1" "$work/step-1"
launcher=()
command -v ccache > /dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S "$work/step-1" -B "$work/step-1/build" "${launcher[@]}" \
  -Dfsgmpm_DIR="$(dirname "$config")" > "$work/configure.log" \
  || { cat "$work/configure.log"; echo "FAIL: configure"; exit 1; }
cmake --build "$work/step-1/build" > "$work/build.log" 2>&1 \
  || { cat "$work/build.log"; echo "FAIL: build"; exit 1; }
if grep -q "$source/include" "$work/step-1/build/CMakeFiles/step-1.dir/flags.make"; then
  echo "FAIL: the out-of-tree build used the source tree's headers"; exit 1
fi
(cd "$work/step-1/build" && ./step-1 10) > "$work/run.log"
grep "from the experiment" "$work/run.log"
echo "ok: step-1 built out of tree against the installed fsgmpm and ran"

(cd "$work" && "$work/prefix/bin/fsgmpm" \
  --set "Simulation/Maximum number of steps=5" \
  --set "Output/Directory=$work/default" > "$work/fsgmpm.log") \
  || { cat "$work/fsgmpm.log"; echo "FAIL: installed fsgmpm"; exit 1; }
echo "ok: the installed fsgmpm ran the default scene"
