#!/usr/bin/env bash
# The installed tree on its own (docs/running.md, "Installing"): installs the build into a fresh
# prefix and then, from outside the source tree, with nothing but that prefix on the paths, runs
# the installed `rodsea` on the demo (run, analyze, render, plot, export to GSD), imports the
# installed Python package and steps a small system, builds the installed examples/cpp project
# with find_package(rodsea), and compiles every installed header on its own include path.
#
#   installed_tree.sh BUILD_DIR WORK_DIR CMAKE CXX GENERATOR PYTHON_MODULE(0|1)
set -euo pipefail
build=$(realpath "$1"); work=$2; cmake=$3; cxx=$4; generator=$5; python_module=$6
rm -rf "$work"; mkdir -p "$work"; work=$(realpath "$work")
prefix=$work/prefix
fail() { echo "FAIL: $*" >&2; exit 1; }

# `cmake --install` rewrites the build's install_manifest.txt: the user's own (for uninstalling
# a real install) is put back.
manifest=$build/install_manifest.txt
[ -f "$manifest" ] && cp -p "$manifest" "$work/manifest.saved"
restore() { if [ -f "$work/manifest.saved" ]; then mv -f "$work/manifest.saved" "$manifest";
            else rm -f "$manifest"; fi; }
trap restore EXIT
"$cmake" --install "$build" --prefix "$prefix" >"$work/install.log" || fail "cmake --install"
grep -q "^$prefix/bin/rodsea\$" "$manifest" || fail "the manifest does not list bin/rodsea"

cd "$work"
unset RODSEA_SCRIPTS_DIR RODSEA_EXECUTABLE RODSEA_SOURCE_DIR PYTHONPATH
export PATH="$prefix/bin:/usr/bin:/bin"
[ "$(command -v rodsea)" = "$prefix/bin/rodsea" ] || fail "rodsea is not the installed one"
share=$prefix/share/rodsea

# Nothing a user should not include: no backend internals, no detail/ folders.
internal=$(cd "$prefix/include" && find rodsea \( -path 'rodsea/engine/cpu/*' \
           -o -path 'rodsea/engine/cuda/*' -o -path 'rodsea/engine/parallel/*' -o -path '*/detail/*' \
           -o -path 'rodsea/view/*' -o -path 'rodsea/campaign/*' \) -print)
[ -z "$internal" ] || fail "internal headers installed: $internal"
# ... and every installed header stands on the installed ones alone.
(cd "$prefix/include" && find rodsea -name '*.hpp' | sort | sed 's/.*/#include "&"/') >all_headers.cpp
"$cxx" -std=c++20 -fsyntax-only -I"$prefix/include" all_headers.cpp || fail "installed headers"

# The command line, on the installed demo and with the installed scripts.
rodsea run "$share/examples/demo.toml" --out demo --overwrite --quiet >run.log 2>&1 ||
    fail "rodsea run: $(tail -3 run.log)"
rodsea analyze demo >analyze.log 2>&1 || fail "rodsea analyze: $(tail -3 analyze.log)"
[ -s demo/analysis/analysis.json ] || fail "no analysis.json"
rodsea render demo -o snapshot.png >/dev/null 2>&1 || fail "rodsea render"
[ -s snapshot.png ] || fail "no snapshot"
rodsea plot demo -o plots --quiet >plot.log 2>&1 || fail "rodsea plot: $(tail -3 plot.log)"
[ -s plots/order_parameters.png ] || fail "no plots/order_parameters.png"
if /usr/bin/python3 -c "import gsd" 2>/dev/null; then
    rodsea export demo --format gsd -o demo.gsd --quiet || fail "rodsea export --format gsd"
    /usr/bin/python3 -c "import gsd.hoomd, sys; sys.exit(0 if len(gsd.hoomd.open('demo.gsd')) == 21 else 1)" ||
        fail "demo.gsd does not hold the run's 21 frames"
else
    echo "skipped: the GSD export (no python3-gsd)"
fi
# The installed scripts drew them, not the source tree's: with the installed folder moved away,
# plot must name the installed script that it misses.
mv "$share/scripts" "$share/scripts.away"
if rodsea plot demo -o plots-again --quiet >plot-again.log 2>&1; then
    fail "rodsea plot ran without the installed scripts (the source tree's instead?)"
fi
grep -q "$share/scripts/rodsea_plot.py" plot-again.log || fail "plot did not name its script"
mv "$share/scripts.away" "$share/scripts"

# A CMake project of one's own: the installed examples/cpp.
"$cmake" -S "$share/examples/cpp" -B one_rod -G "$generator" -DCMAKE_CXX_COMPILER="$cxx" \
    -DCMAKE_PREFIX_PATH="$prefix" >one_rod.log 2>&1 || fail "configure examples/cpp: $(tail -5 one_rod.log)"
"$cmake" --build one_rod >>one_rod.log 2>&1 || fail "build examples/cpp: $(tail -5 one_rod.log)"
cpp_hash=$(./one_rod/one_rod "$share/examples/cpp/one_rod.toml") || fail "one_rod"
[[ "$cpp_hash" =~ ^[0-9a-f]{16}$ ]] || fail "one_rod printed '$cpp_hash'"

# The Python package, where the install said it is; the same engine as the C++ program's.
if [ "$python_module" = 1 ]; then
    site=$(sed -n 's/.*the Python package is in \([^:]*\):.*/\1/p' install.log)
    [ -d "$site/rodsea" ] || fail "the install did not say where the Python package is"
    py_hash=$(PYTHONPATH="$site" /usr/bin/python3 -c "
import sys, rodsea
assert rodsea.__file__.startswith('$prefix/'), rodsea.__file__
sim = rodsea.Simulation(rodsea.load_config(sys.argv[1]))
sim.run(steps=1000)
print('%016x' % sim.state_hash())" "$share/examples/cpp/one_rod.toml") || fail "import rodsea"
    [ "$py_hash" = "$cpp_hash" ] || fail "Python's hash $py_hash is not the C++ program's $cpp_hash"
else
    echo "skipped: the Python package (the build has no Python module)"
fi
echo "the installed tree works on its own: one rod's hash $cpp_hash from C++ and Python"
