"""scripts/polar_rod_speed.py on a trajectory whose answer is known: two polar rods gliding along
their own axis, at 2 and 4 mm/s (one heading +x across the periodic edge of a 10 mm box, one at
120°), and a bead drifting sideways that must be left out. The script must unwrap the edge
crossing and report 3 ± 1 mm/s both as the speed and along the axis (the standard error over
two rods of 2 and 4 is 1); rods sliding sideways at the same speeds must give 3 ± 1 mm/s and
0 ± 0 along the axis. The --csv table must hold the same numbers.
"""
import csv
import math
import os

import pytest

from conftest import run_script

h5py = pytest.importorskip("h5py")
np = pytest.importorskip("numpy")

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


def measured(run, scratch):
    """(speed, its error, along the axis, its error) as printed and as written by --csv."""
    table = os.path.join(scratch, "speeds.csv")
    out = run_script("polar_rod_speed.py", run, "--from", "0", "--csv", table)
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
@pytest.mark.parametrize("sideways, along", [(False, (3.0, 1.0)), (True, (0.0, 0.0))])
def test_speed_and_speed_along_the_axis(tmp_path, sideways, along):
    run = str(tmp_path / ("sideways" if sideways else "forward"))
    write_run(run, sideways)
    got = measured(run, str(tmp_path))
    assert all(abs(g - e) < 2e-3 for g, e in zip(got, (3.0, 1.0) + along)), got
