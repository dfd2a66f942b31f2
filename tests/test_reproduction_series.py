"""scripts/reproduction_series.py --continues on a run cut in two: a run's 100 frames (0-9.9 s,
P and S known functions of time, steady from 5 s) analysed whole, and the same frames split at
4.4 s into the run's first directory and its continuation (`rodsea run --continue`). The first
part's table joined with the continuation must be the whole run's table: the same bins, frame
counts, steady flags (the continuation's, whatever window the first part was analysed with), and
means to the tables' 6 digits (the bin that both parts hold in part, 4-5 s, is the frame-weighted
mean of the two partial means, which is the mean over its frames).
A table that runs past the continuation's start, shares frames with it or stops short of it is
refused, and so is a continuation of one frame (its output interval is unknown). A run in three
directories, joined twice, gives the whole run's table too, and its header names all three with
the times the continuations start.

    /usr/bin/python3 tests/test_reproduction_series.py SOURCE_DIR SCRATCH_DIR
Exit 77 (skipped) without numpy.
"""
import os
import shutil
import subprocess
import sys

try:
    import numpy as np
except ImportError as e:
    print(f"skipped: {e} (install python3-numpy)")
    sys.exit(77)

source, scratch = sys.argv[1], sys.argv[2]
script = os.path.join(source, "scripts", "reproduction_series.py")
shutil.rmtree(scratch, ignore_errors=True)
TIMES = np.round(np.arange(100) * 0.1, 10)


def write_run(run, frames, steady_from=5.0):
    """A run directory whose analysis holds `frames` of the run, steady from `steady_from` s."""
    os.makedirs(os.path.join(run, "analysis"))
    with open(os.path.join(run, "analysis", "order_parameters.csv"), "w") as f:
        f.write("# order_parameters; units: time [s] steady [1] P_polar [1] S_medium [1]\n")
        f.write("time,steady,P_polar,S_medium\n")
        for t in TIMES[frames]:
            p, s = 0.5 + 0.4 * np.sin(t), 0.1 + 0.01 * t * t
            f.write(f"{t!r},{int(t >= steady_from)},{p!r},{s!r}\n")


def run_script(*args):
    return subprocess.run(["/usr/bin/python3", script, *args], capture_output=True, text=True)


def table(path):
    return np.genfromtxt(path, delimiter=",", skip_header=1, names=True)


whole, first, rest = (os.path.join(scratch, n) for n in ("whole", "first", "rest"))
write_run(whole, slice(0, 100))
# The first part analysed with a window of its own (from 1 s): the joined table's steady flags
# are the continuation's analysis', so the whole run's.
write_run(first, slice(0, 44), steady_from=1.0)
write_run(rest, slice(44, 100))
for run, out in ((whole, "w"), (first, "p")):
    r = run_script(run, "--out", os.path.join(scratch, out))
    assert r.returncode == 0, r.stderr
r = run_script(rest, "--continues", os.path.join(scratch, "p", "first.series.csv"), "--out",
               os.path.join(scratch, "joined"))
assert r.returncode == 0, r.stderr
expected = table(os.path.join(scratch, "w", "whole.series.csv"))
joined = table(os.path.join(scratch, "joined", "first.series.csv"))
assert len(joined) == len(expected) == 10, (len(joined), len(expected))
for name in ("t_from", "t_to", "frames", "steady"):
    assert np.array_equal(joined[name], expected[name]), (name, joined[name], expected[name])
for name in ("P_polar", "S_medium"):
    # 6 significant digits in each table, and the joined bin's mean computed from two of them.
    assert np.allclose(joined[name], expected[name], rtol=2e-6, atol=0), (name, joined[name],
                                                                         expected[name])
for name in ("Sigma", "N_m"):
    assert np.isnan(joined[name]).all(), name

# An earlier table that shares frames with the continuation (to 4.6 s), or stops short of it (to
# 4.1 s), would count frames twice or leave a hole in the shared bin: refused.
for frames, name, why in ((slice(0, 47), "overlap", "share frames"),
                          (slice(0, 42), "gap", "frames are missing")):
    run = os.path.join(scratch, name)
    write_run(run, frames)
    assert run_script(run, "--out", os.path.join(scratch, name + "-table")).returncode == 0
    table_path = os.path.join(scratch, name + "-table", name + ".series.csv")
    r = run_script(rest, "--continues", table_path, "--out",
                   os.path.join(scratch, name + "-joined"))
    assert r.returncode == 2 and why in r.stderr, (name, r.returncode, r.stderr)

# The whole run's table is no earlier part of the continuation: refused, nothing written.
r = run_script(rest, "--continues", os.path.join(scratch, "w", "whole.series.csv"), "--out",
               os.path.join(scratch, "refused"))
assert r.returncode == 2 and "goes past 4 s" in r.stderr, (r.returncode, r.stderr)
assert not os.path.exists(os.path.join(scratch, "refused", "whole.series.csv"))

# A continuation of one frame cannot tell its output interval: refused with that reason, not a
# crash on the one-row table.
single = os.path.join(scratch, "single")
write_run(single, slice(44, 45))
r = run_script(single, "--continues", os.path.join(scratch, "p", "first.series.csv"), "--out",
               os.path.join(scratch, "single-joined"))
assert r.returncode == 2 and "at least two frames" in r.stderr, (r.returncode, r.stderr)

# Three sessions: the continuation split again at 7.0 s and joined in two steps. The table is
# the whole run's, and its header keeps the first two directories, which the second join's
# input table alone no longer shows.
mid, last = os.path.join(scratch, "mid"), os.path.join(scratch, "last")
write_run(mid, slice(44, 70))
write_run(last, slice(70, 100))
r = run_script(mid, "--continues", os.path.join(scratch, "p", "first.series.csv"), "--out",
               os.path.join(scratch, "j1"))
assert r.returncode == 0, r.stderr
r = run_script(last, "--continues", os.path.join(scratch, "j1", "first.series.csv"), "--out",
               os.path.join(scratch, "j2"))
assert r.returncode == 0, r.stderr
twice = os.path.join(scratch, "j2", "first.series.csv")
for name in ("t_from", "t_to", "frames"):
    assert np.array_equal(table(twice)[name], expected[name]), (name, table(twice)[name])
# Steady is the last analysis' (from 7 s, where its frames start), not the whole run's (5 s).
assert np.array_equal(table(twice)["steady"], expected["t_from"] >= 7), table(twice)["steady"]
assert np.allclose(table(twice)["P_polar"], expected["P_polar"], rtol=4e-6, atol=0)
with open(twice, encoding="utf-8") as f:
    header = f.readline()
chain = f"# {first} to 4.4 s, then {mid} to 7 s, then {last} binned by 1 s"
assert header.startswith(chain), (header, chain)

# A table whose header is not this script's cannot say where its frames came from: refused.
foreign = os.path.join(scratch, "foreign.series.csv")
with open(os.path.join(scratch, "p", "first.series.csv"), encoding="utf-8") as f:
    lines = f.readlines()
with open(foreign, "w", encoding="utf-8") as f:
    f.writelines(["# made by hand\n"] + lines[1:])
r = run_script(rest, "--continues", foreign, "--out", os.path.join(scratch, "foreign-joined"))
assert r.returncode == 2 and "header" in r.stderr, (r.returncode, r.stderr)
print("reproduction_series --continues: the joined table is the whole run's (10 bins), also "
      "joined in two steps, with every directory named in its header")
