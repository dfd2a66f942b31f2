"""scripts/polar_rod_speed.py on a trajectory whose answer is known: two polar rods gliding along
their own axis, at 2 and 4 mm/s (one heading +x across the periodic edge of a 10 mm box, one at
120°), and a bead drifting sideways that must be left out. The script must unwrap the edge
crossing and report 3 ± 1 mm/s both as the speed and along the axis (the standard error over
two rods of 2 and 4 is 1); rods sliding sideways at the same speeds must give 3 ± 1 mm/s and
0 ± 0 along the axis. The --csv table must hold the same numbers.

    /usr/bin/python3 tests/test_polar_rod_speed.py SOURCE_DIR SCRATCH_DIR
Exit 77 (skipped) without numpy or h5py.
"""
import csv
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
script = os.path.join(source, "scripts", "polar_rod_speed.py")
CONFIG = ('[[species]]\nname = "medium"\nkind = "bead"\ncount = 1\n'
          '[[species]]\nname = "polar"\nkind = "polar_rod"\ncount = 2\n')


def write_run(run, sideways):
    """Frames every 0.1 s for 5 s; rod k heads along angle a_k and moves along a_k (or
    perpendicular to it when `sideways`), at 2 and 4 mm/s; positions wrapped into the box."""
    os.makedirs(run, exist_ok=True)
    t = np.arange(51) * 0.1
    headings = [0.0, 2 * math.pi / 3]
    x = np.zeros((len(t), 3, 3))
    q = np.zeros((len(t), 3, 4))
    q[:, 0] = [1, 0, 0, 0]
    x[:, 0, 0] = 5.0 + 0.7 * t  # the bead, species 0
    for k, (a, v) in enumerate(zip(headings, (2.0, 4.0)), start=1):
        move = a + (math.pi / 2 if sideways else 0.0)
        x[:, k, 0] = 8.0 + v * t * math.cos(move)
        x[:, k, 1] = 5.0 + v * t * math.sin(move)
        q[:, k] = [math.cos(a / 2), 0, 0, math.sin(a / 2)]  # a turn by a about z
    x[..., :2] %= 10.0
    with h5py.File(os.path.join(run, "trajectory.h5"), "w") as f:
        f["parameters/rodsea/config"] = np.bytes_(CONFIG)
        b = f.create_group("particles/bodies")
        b["species"] = np.array([0, 1, 1], dtype=np.int32)
        for name, value in (("position", x), ("orientation", q)):
            b[f"{name}/value"] = value.astype(np.float32)
            b[f"{name}/time"] = t
        b["box/edges/value"] = np.tile([10.0, 10.0, 1.4], (len(t), 1))


def measured(run):
    """(speed, its error, along the axis, its error) as printed and as written by --csv."""
    table = os.path.join(scratch, "speeds.csv")
    out = subprocess.run([sys.executable, script, run, "--from", "0", "--csv", table],
                         capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    words = out.stdout.split()
    printed = [float(words[words.index("|Δr|/lag") + k]) for k in (2, 4)]
    printed += [float(words[words.index("axis") + k]) for k in (1, 3)]
    with open(table) as f:
        row = list(csv.DictReader(f))[0]
    written = [float(row[k]) for k in ("speed_mm_s", "speed_err_mm_s", "along_axis_mm_s",
                                       "along_axis_err_mm_s")]
    assert row["run"] == run and int(row["polar_rods"]) == 2, row
    # the csv keeps 4 decimals, the printout 3
    assert all(abs(p - w) < 6e-4 for p, w in zip(printed, written)), (printed, written)
    return written


# float32 positions (~1e-6 mm) over 1 s lags: the answers hold to far better than 2e-3 mm/s.
forward = os.path.join(scratch, "forward")
write_run(forward, sideways=False)
got = measured(forward)
assert all(abs(g - e) < 2e-3 for g, e in zip(got, (3.0, 1.0, 3.0, 1.0))), got
sideways = os.path.join(scratch, "sideways")
write_run(sideways, sideways=True)
got = measured(sideways)
assert all(abs(g - e) < 2e-3 for g, e in zip(got, (3.0, 1.0, 0.0, 0.0))), got
print("polar_rod_speed.py: 3 ± 1 mm/s forward and sideways, the edge crossing unwrapped, the "
      "bead left out, the csv equal to the printout")
