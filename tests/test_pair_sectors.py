"""scripts/pair_sectors.py on g(r,θ) maps whose sector means are known.

A map laid out as `rodsea analyze` writes it (60 shells of 0.375 mm to 22.5 mm, 72 angles from
−π to π) holds g = 1 everywhere except: 3 ahead of the reference rod (|θ| ≤ 20°) and 5 behind it
(|θ − π| ≤ 20°, across the ±π seam) for 4.5 ≤ r < 9 mm, and 2 on both sides (|θ ∓ π/2| ≤ 20°)
for 0 ≤ r < 2.25 mm. Within 30° sectors the fraction of bins that carry the value is fixed by
the bin centres (8 of the 12 bins in each 30° sector lie within 20°), so the script must print
exactly: ahead 1 + 2·8/12, behind 1 + 4·8/12, along their mean, across 1 + 8/12 near contact
and 1 beyond. The default shells (half the polar rod's length, from analysis.json) and explicit
ones must agree; bad input must print nothing and exit 2 (74 for a path that does not exist).

    /usr/bin/python3 tests/test_pair_sectors.py SOURCE_DIR SCRATCH_DIR
Exit 77 (skipped) without numpy or h5py.
"""
import csv
import io
import json
import math
import os
import subprocess
import sys

try:
    import h5py
    import numpy as np
except ImportError as e:
    print(f"skipped: {e} (install python3-numpy python3-h5py)")
    sys.exit(77)

source, scratch = sys.argv[1], sys.argv[2]
script = os.path.join(source, "scripts", "pair_sectors.py")
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)


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
    return subprocess.run([sys.executable, script, *args], capture_output=True, text=True)


analysis = os.path.join(scratch, "run", "analysis")
write_analysis(analysis)
default = run(os.path.join(scratch, "run"))
check(default.returncode == 0, f"default shells: exit {default.returncode}: {default.stderr}")
rows = list(csv.DictReader(io.StringIO(default.stdout)))
check([(float(x["r_from_mm"]), float(x["r_to_mm"])) for x in rows]
      == [(2.25 * k, 2.25 * (k + 1)) for k in range(10)],
      f"default shells are not steps of ℓ_p/2 = 2.25 mm to 22.5 mm: {default.stdout}")
share = 8 / 12  # of a 30° sector's bin centres, those within 20°
expected = {  # (shell index) -> sector -> mean
    0: {"ahead": 1, "behind": 1, "along": 1, "across": 1 + share},
    2: {"ahead": 1 + 2 * share, "behind": 1 + 4 * share, "along": 1 + 3 * share, "across": 1},
    3: {"ahead": 1 + 2 * share, "behind": 1 + 4 * share, "along": 1 + 3 * share, "across": 1},
    5: {"ahead": 1, "behind": 1, "along": 1, "across": 1},
}
for index, sectors in expected.items():
    for sector, value in sectors.items():
        got = float(rows[index][f"g_{sector}"]) if len(rows) > index else math.nan
        # printed to 4 significant digits
        check(abs(got - value) < 5e-4 * value,
              f"shell {index}, {sector}: {got}, expected {value:.4f}")
check(float(rows[5]["g_across_error"]) == 0 if len(rows) > 5 else False,
      "a uniform sector must have no scatter")

explicit = run(os.path.join(analysis, "analysis.h5"), "--shells", "4.5,9")
lines = explicit.stdout.splitlines()
check(explicit.returncode == 0 and len(lines) == 2,
      f"--shells 4.5,9 on the .h5: exit {explicit.returncode}, {explicit.stdout}{explicit.stderr}")
if len(lines) == 2:
    row = next(csv.DictReader(io.StringIO(explicit.stdout)))
    check(abs(float(row["g_along"]) - (1 + 3 * share)) < 5e-4 * (1 + 3 * share),
          f"one shell over 4.5–9 mm: along {row['g_along']}")

# 2: bad input; 74: a file that cannot be read (rodsea plot's codes, whose readers it shares)
for args, code, why in (([analysis, "--shells", "0,30"], 2, "shells past the map"),
                        ([analysis, "--shells", "5,2"], 2, "decreasing shells"),
                        ([analysis, "--half-width", "60"], 2, "overlapping sectors"),
                        ([analysis, os.path.join(scratch, "missing")], 74,
                         "one input without an analysis")):
    out = run(*args)
    check(out.returncode == code and out.stdout == "" and out.stderr,
          f"{why}: exit {out.returncode}, stdout {out.stdout!r}, stderr {out.stderr!r}")

for f in failures:
    print("FAIL:", f)
print("pair_sectors:", "failed" if failures else "passed")
sys.exit(1 if failures else 0)
