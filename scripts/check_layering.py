#!/usr/bin/env python3
"""Fails when a module of src/rodsea includes a module above it, or another module's private
(detail/) headers, or a library other than its own (the engine builds with OpenMP only), or
when production code includes the scenario library of tests.

The modules in layers, lowest first: a module may include its own headers and those of strictly
lower layers only, so dependencies run one way (docs/architecture.md has the picture). The
files at the top of src/rodsea (error, random, number_text) are the layer "core".

    scripts/check_layering.py [SOURCE_ROOT]      exit 0: clean; 1: each offending include listed
    scripts/check_layering.py --self-test        plants each kind of bad include in a scratch
                                                 tree and checks that every one is reported
"""
import pathlib
import re
import sys
import tempfile

LAYERS = [
    ["math"],
    ["core"],
    ["shape", "neighbors", "cli"],
    ["engine"],
    ["analysis", "builder"],
    ["scenes", "config"],
    ["io"],
    ["calibration", "analyze", "meanfield"],
    ["run"],
    ["view"],
    ["campaign"],
]
LAYER = {module: level for level, modules in enumerate(LAYERS) for module in modules}
INCLUDE = re.compile(r'^\s*#\s*include\s+"rodsea/([^"]+)"', re.MULTILINE)
# The libraries that are not the standard library, and the modules that may include them: the
# engine and the builder build with none but OpenMP (RODSEA_ENGINE_ONLY).
EXTERNAL = {
    "omp.h": {"engine"},
    "fftw3.h": {"analysis"},
    "toml++/": {"config", "calibration"},
    "hdf5.h": {"io"},
    "nlohmann/": {"analyze", "campaign"},
    "CLI/": {"cli"},
    "cairo": {"view"},
    "png.h": {"view"},
}
SYSTEM_INCLUDE = re.compile(r"^\s*#\s*include\s+<([^>]+)>", re.MULTILINE)


def module_of(path_in_rodsea: str) -> str:
    parts = path_in_rodsea.split("/")
    return parts[0] if len(parts) > 1 else "core"


def check(root: pathlib.Path) -> list[str]:
    problems = []
    src = root / "src" / "rodsea"
    for file in sorted(src.rglob("*.[ch]pp")):
        here = module_of(file.relative_to(src).as_posix())
        if here not in LAYER:
            problems.append(f"{file}: module '{here}' has no layer in scripts/check_layering.py")
            continue
        text = file.read_text(encoding="utf-8")
        for header in SYSTEM_INCLUDE.findall(text):
            for prefix, modules in EXTERNAL.items():
                if header.startswith(prefix) and here not in modules:
                    problems.append(f"{file.relative_to(root)}: '{here}' includes <{header}>, "
                                    f"which only {', '.join(sorted(modules))} may")
        for target in INCLUDE.findall(text):
            there = module_of(target)
            line = text[: text.find(target)].count("\n") + 1
            where = f"{file.relative_to(root)}:{line}: includes rodsea/{target}"
            if there not in LAYER:
                problems.append(f"{where}: unknown module '{there}'")
            elif "/detail/" in target and there != here:
                problems.append(f"{where}: a private header of '{there}'")
            elif there == "scenes" and here != "scenes":
                problems.append(f"{where}: the scenario library is for tests and benchmarks")
            elif there != here and LAYER[there] >= LAYER[here]:
                problems.append(
                    f"{where}: '{here}' (layer {LAYER[here]}) may not include '{there}' "
                    f"(layer {LAYER[there]})")
    for file in sorted((root / "app").rglob("*.[ch]pp")):
        text = file.read_text(encoding="utf-8")
        for target in INCLUDE.findall(text):
            if "/detail/" in target or module_of(target) == "scenes":
                problems.append(f"{file.relative_to(root)}: includes rodsea/{target}, not public")
    return problems


def self_test() -> int:
    planted = {
        "src/rodsea/engine/a.hpp": '#include "rodsea/config/run_plan.hpp"\n',  # upward
        "src/rodsea/analysis/b.hpp": '#include "rodsea/builder/lattice.hpp"\n',  # same layer
        "src/rodsea/analyze/c.cpp": '#include "rodsea/io/detail/hdf5.hpp"\n',  # private
        "src/rodsea/run/d.cpp": '#include "rodsea/scenes/scenes.hpp"\n',  # test support
        "src/rodsea/widgets/e.hpp": "",  # a module without a layer
        "src/rodsea/io/f.cpp": '#include "rodsea/engine/simulation.hpp"\n',  # fine
        "src/rodsea/builder/g.cpp": "#include <hdf5.h>\n",  # a library the engine builds without
    }
    with tempfile.TemporaryDirectory() as scratch:
        root = pathlib.Path(scratch)
        (root / "app").mkdir()
        for name, text in planted.items():
            path = root / name
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(text, encoding="utf-8")
        problems = check(root)
    reported = {p.split(":")[0].split("/")[-1] for p in problems}
    expected = {"a.hpp", "b.hpp", "c.cpp", "d.cpp", "e.hpp", "g.cpp"}
    if reported != expected or len(problems) != len(expected):
        print(f"check_layering --self-test: reported {sorted(reported)}, expected {sorted(expected)}")
        return 1
    print("check_layering --self-test: all 6 planted includes reported, the good one not")
    return 0


def main() -> int:
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).parent.parent)
    problems = check(root.resolve())
    for p in problems:
        print(p)
    if problems:
        print(f"check_layering: {len(problems)} include(s) against the module layers")
        return 1
    print("check_layering: every include runs downward")
    return 0


if __name__ == "__main__":
    sys.exit(main())
