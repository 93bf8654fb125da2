#!/usr/bin/env bash
# Installs kdpm into a temporary prefix, builds examples/trace-and-gather against the installed
# CMake package (find_package(kdpm)), and runs it on a Cornell box made by the installed tools.
#   installed_package_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$1 source=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix

cmake --install "$build" --prefix "$prefix" >/dev/null
for f in bin/kdpm-render bin/kdpm-build-geometry include/kdpm/formats/container_reader.h \
         include/kdpm/runtime/geometry/scene_traversal.h lib/cmake/kdpm/kdpm-config.cmake; do
  [ -e "$prefix/$f" ] || { echo "not installed: $f"; exit 1; }
done
[ ! -e "$prefix/include/kdpm/runtime/view" ] || { echo "the viewer's headers should not be installed"; exit 1; }

cmake -S "$source/examples/trace-and-gather" -B "$work/example" -DCMAKE_PREFIX_PATH="$prefix" \
      -DCMAKE_BUILD_TYPE=Release >"$work/configure.log" 2>&1 || { cat "$work/configure.log"; exit 1; }
cmake --build "$work/example" -j 2 >"$work/build.log" 2>&1 || { cat "$work/build.log"; exit 1; }

"$prefix/bin/kdpm-build-geometry" "$source/scenes/cornell-box/cornell-box.json" -o "$work/scene.kdg" --quiet
"$prefix/bin/kdpm-shoot-photons" "$work/scene.kdg" -n 20000 -o "$work/scene.kdph" --quiet
"$prefix/bin/kdpm-build-photons" "$work/scene.kdph" -o "$work/scene.kdp" --quiet
out=$("$work/example/trace-and-gather" "$work/scene.kdg" "$work/scene.kdp" 7)
echo "$out"
# The Cornell camera sits at (0, 1, 3.9) and looks along -z: the hit lies on that line at 3.9 - t.
awk '/^hit triangle/ { split($0, a, /[=(), ]+/); t = a[6]; x = a[8]; y = a[9]; z = a[10]
       ok = (x + 0 == 0 && y == 1 && (z - (3.9 - t))^2 < 1e-6) } END { exit !ok }' <<<"$out"
grep -q '^7 nearest of [0-9]* photons:$' <<<"$out"
[ "$(grep -c '^  photon ' <<<"$out")" -eq 7 ]
# Each photon's printed distance is its distance to the hit.
awk '/^hit triangle/ { split($0, a, /[=(), ]+/); hx = a[8]; hy = a[9]; hz = a[10] }
     /^  photon/ { split($0, b, /[(), ]+/); d = sqrt((b[5]-hx)^2 + (b[6]-hy)^2 + (b[7]-hz)^2)
       if ((d - b[9])^2 > 1e-6) bad = 1; n++ }
     END { exit bad || n != 7 }' <<<"$out"
# The Python package, where the build has it: importable from the prefix, tracing the same hit.
if [ -d "$build/python/kdpm" ]; then
  init=$(find "$prefix/lib" -path '*-packages/kdpm/__init__.py' | head -1)
  [ -n "$init" ] || { echo "not installed: the kdpm Python package"; exit 1; }
  PYTHONPATH=$(dirname "$(dirname "$init")") "${KDPM_PYTHON:-python3}" -B -c "
import numpy, kdpm
g = kdpm.GeometryFile('$work/scene.kdg')
hits = g.intersect(numpy.array([[0, 1, 3.9]], 'f4'), numpy.array([[0, 0, -1]], 'f4'))
assert hits['triangle'][0] >= 0 and abs(hits['t'][0] - 3.9) < 0.5, hits
print('installed Python package:', kdpm.__file__)"
fi
echo "installed package: ok"
