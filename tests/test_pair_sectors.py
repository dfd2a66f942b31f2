"""scripts/pair_sectors.py on g(r,θ) maps whose sector means are known.

A map laid out as `rodsea analyze` writes it (60 shells of 0.375 mm to 22.5 mm, 72 angles from
−π to π) holds g = 1 everywhere except: 3 ahead of the reference rod (|θ| ≤ 20°) and 5 behind it
(|θ − π| ≤ 20°, across the ±π seam) for 4.5 ≤ r < 9 mm, and 2 on both sides (|θ ∓ π/2| ≤ 20°)
for 0 ≤ r < 2.25 mm. Within 30° sectors the fraction of bins that carry the value is fixed by
the bin centres (8 of the 12 bins in each 30° sector lie within 20°), so the script must print
exactly: ahead 1 + 2·8/12, behind 1 + 4·8/12, along their mean, across 1 + 8/12 near contact
and 1 beyond. The default shells (half the polar rod's length, from analysis.json) and explicit
ones must agree; bad input must print nothing and exit 2 (74 for a path that does not exist).
"""
import csv
import io
import json
import math
import os

import pytest

from conftest import run_script

h5py = pytest.importorskip("h5py")
np = pytest.importorskip("numpy")

SHARE = 8 / 12  # of a 30° sector's bin centres, those within 20°


def write_analysis(directory):
    os.makedirs(directory, exist_ok=True)
    r_edges = np.linspace(0.0, 22.5, 61)
    theta_edges = np.linspace(-math.pi, math.pi, 73)
    r = 0.5 * (r_edges[:-1] + r_edges[1:])[:, None]
    theta = 0.5 * (theta_edges[:-1] + theta_edges[1:])[None, :]
    def within(direction, degrees):
        return np.abs(np.angle(np.exp(1j * (theta - direction)))) <= math.radians(degrees)
    g = np.ones((60, 72))
    shell = (r >= 4.5) & (r < 9.0)
    g = np.where(shell & within(0.0, 20), 3.0, g)
    g = np.where(shell & within(math.pi, 20), 5.0, g)
    g = np.where((r < 2.25) & (within(math.pi / 2, 20) | within(-math.pi / 2, 20)), 2.0, g)
    with h5py.File(os.path.join(directory, "analysis.h5"), "w") as f:
        f["maps/g_r_theta/value"] = g
        f["maps/g_r_theta/r_edges"] = r_edges
        f["maps/g_r_theta/theta_edges"] = theta_edges
    with open(os.path.join(directory, "analysis.json"), "w") as f:
        json.dump({"observables": {"corotating": {"maps": {"g_r_theta": {"file": "analysis.h5"}}}},
                   "steady_state": {},
                   "parameters": {"species": [{"kind": "apolar_rod", "length_mm": 2.5},
                                              {"kind": "polar_rod", "length_mm": 4.5}]}}, f)


def run(*args):
    return run_script("pair_sectors.py", *args)


@pytest.fixture
def analysis(tmp_path):
    directory = tmp_path / "run" / "analysis"
    write_analysis(str(directory))
    return directory


def test_the_default_shells_give_each_sectors_known_mean(analysis):
    default = run(analysis.parent)
    assert default.returncode == 0, f"default shells: {default.stderr}"
    rows = list(csv.DictReader(io.StringIO(default.stdout)))
    assert [(float(x["r_from_mm"]), float(x["r_to_mm"])) for x in rows] == \
        [(2.25 * k, 2.25 * (k + 1)) for k in range(10)], \
        f"default shells are not steps of ℓ_p/2 = 2.25 mm to 22.5 mm: {default.stdout}"
    expected = {  # (shell index) -> sector -> mean
        0: {"ahead": 1, "behind": 1, "along": 1, "across": 1 + SHARE},
        2: {"ahead": 1 + 2 * SHARE, "behind": 1 + 4 * SHARE, "along": 1 + 3 * SHARE, "across": 1},
        3: {"ahead": 1 + 2 * SHARE, "behind": 1 + 4 * SHARE, "along": 1 + 3 * SHARE, "across": 1},
        5: {"ahead": 1, "behind": 1, "along": 1, "across": 1},
    }
    for index, sectors in expected.items():
        for sector, value in sectors.items():
            got = float(rows[index][f"g_{sector}"])
            # printed to 4 significant digits
            assert abs(got - value) < 5e-4 * value, \
                f"shell {index}, {sector}: {got}, expected {value:.4f}"
    assert float(rows[5]["g_across_error"]) == 0, "a uniform sector must have no scatter"


def test_explicit_shells_on_the_h5_agree(analysis):
    explicit = run(analysis / "analysis.h5", "--shells", "4.5,9")
    lines = explicit.stdout.splitlines()
    assert explicit.returncode == 0 and len(lines) == 2, \
        f"--shells 4.5,9 on the .h5: {explicit.stdout}{explicit.stderr}"
    row = next(csv.DictReader(io.StringIO(explicit.stdout)))
    assert abs(float(row["g_along"]) - (1 + 3 * SHARE)) < 5e-4 * (1 + 3 * SHARE), \
        f"one shell over 4.5–9 mm: along {row['g_along']}"


# 2: bad input; 74: a file that cannot be read (rodsea plot's codes, whose readers it shares)
@pytest.mark.parametrize("args, code, why", [
    (["--shells", "0,30"], 2, "shells past the map"),
    (["--shells", "5,2"], 2, "decreasing shells"),
    (["--half-width", "60"], 2, "overlapping sectors"),
    (["MISSING"], 74, "one input without an analysis"),
])
def test_bad_input_prints_nothing_and_exits_with_its_code(analysis, args, code, why):
    args = [str(analysis.parent.parent / "missing") if a == "MISSING" else a for a in args]
    out = run(analysis, *args)
    assert out.returncode == code and out.stdout == "" and out.stderr, \
        f"{why}: exit {out.returncode}, stdout {out.stdout!r}, stderr {out.stderr!r}"
