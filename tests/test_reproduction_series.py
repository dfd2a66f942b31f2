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
"""
import os

import pytest

from conftest import run_script as run_named

np = pytest.importorskip("numpy")

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
    return run_named("reproduction_series.py", *args)


def table(path):
    return np.genfromtxt(path, delimiter=",", skip_header=1, names=True)


@pytest.fixture
def scratch(tmp_path):
    """The whole run and its two parts, the whole run's and the first part's tables made."""
    scratch = str(tmp_path)
    whole, first, rest = (os.path.join(scratch, n) for n in ("whole", "first", "rest"))
    write_run(whole, slice(0, 100))
    # The first part analysed with a window of its own (from 1 s): the joined table's steady
    # flags are the continuation's analysis', so the whole run's.
    write_run(first, slice(0, 44), steady_from=1.0)
    write_run(rest, slice(44, 100))
    for run, out in ((whole, "w"), (first, "p")):
        r = run_script(run, "--out", os.path.join(scratch, out))
        assert r.returncode == 0, r.stderr
    return scratch


def test_the_joined_table_is_the_whole_runs(scratch):
    r = run_script(os.path.join(scratch, "rest"), "--continues",
                   os.path.join(scratch, "p", "first.series.csv"), "--out",
                   os.path.join(scratch, "joined"))
    assert r.returncode == 0, r.stderr
    expected = table(os.path.join(scratch, "w", "whole.series.csv"))
    joined = table(os.path.join(scratch, "joined", "first.series.csv"))
    assert len(joined) == len(expected) == 10, (len(joined), len(expected))
    for name in ("t_from", "t_to", "frames", "steady"):
        assert np.array_equal(joined[name], expected[name]), (name, joined[name], expected[name])
    for name in ("P_polar", "S_medium"):
        # 6 significant digits in each table, and the joined bin's mean computed from two of them.
        assert np.allclose(joined[name], expected[name], rtol=2e-6, atol=0), \
            (name, joined[name], expected[name])
    for name in ("Sigma", "N_m"):
        assert np.isnan(joined[name]).all(), name


# An earlier table that shares frames with the continuation (to 4.6 s), or stops short of it (to
# 4.1 s), would count frames twice or leave a hole in the shared bin: refused.
@pytest.mark.parametrize("frames, name, why", [(slice(0, 47), "overlap", "share frames"),
                                               (slice(0, 42), "gap", "frames are missing")])
def test_an_earlier_table_that_shares_or_misses_frames_is_refused(scratch, frames, name, why):
    run = os.path.join(scratch, name)
    write_run(run, frames)
    assert run_script(run, "--out", os.path.join(scratch, name + "-table")).returncode == 0
    table_path = os.path.join(scratch, name + "-table", name + ".series.csv")
    r = run_script(os.path.join(scratch, "rest"), "--continues", table_path, "--out",
                   os.path.join(scratch, name + "-joined"))
    assert r.returncode == 2 and why in r.stderr, (name, r.returncode, r.stderr)


def test_the_whole_runs_table_is_no_earlier_part(scratch):
    r = run_script(os.path.join(scratch, "rest"), "--continues",
                   os.path.join(scratch, "w", "whole.series.csv"), "--out",
                   os.path.join(scratch, "refused"))
    assert r.returncode == 2 and "goes past 4 s" in r.stderr, (r.returncode, r.stderr)
    assert not os.path.exists(os.path.join(scratch, "refused", "whole.series.csv"))


def test_a_continuation_of_one_frame_is_refused_not_crashed_on(scratch):
    """It cannot tell its output interval."""
    single = os.path.join(scratch, "single")
    write_run(single, slice(44, 45))
    r = run_script(single, "--continues", os.path.join(scratch, "p", "first.series.csv"),
                   "--out", os.path.join(scratch, "single-joined"))
    assert r.returncode == 2 and "at least two frames" in r.stderr, (r.returncode, r.stderr)


def test_three_sessions_joined_in_two_steps_keep_every_directory_in_the_header(scratch):
    """The continuation split again at 7.0 s and joined in two steps: the table is the whole
    run's, and its header keeps the first two directories, which the second join's input table
    alone no longer shows."""
    first = os.path.join(scratch, "first")
    mid, last = os.path.join(scratch, "mid"), os.path.join(scratch, "last")
    write_run(mid, slice(44, 70))
    write_run(last, slice(70, 100))
    r = run_script(mid, "--continues", os.path.join(scratch, "p", "first.series.csv"), "--out",
                   os.path.join(scratch, "j1"))
    assert r.returncode == 0, r.stderr
    r = run_script(last, "--continues", os.path.join(scratch, "j1", "first.series.csv"),
                   "--out", os.path.join(scratch, "j2"))
    assert r.returncode == 0, r.stderr
    expected = table(os.path.join(scratch, "w", "whole.series.csv"))
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


def test_a_table_whose_header_is_not_the_scripts_is_refused(scratch):
    """It cannot say where its frames came from."""
    foreign = os.path.join(scratch, "foreign.series.csv")
    with open(os.path.join(scratch, "p", "first.series.csv"), encoding="utf-8") as f:
        lines = f.readlines()
    with open(foreign, "w", encoding="utf-8") as f:
        f.writelines(["# made by hand\n"] + lines[1:])
    r = run_script(os.path.join(scratch, "rest"), "--continues", foreign, "--out",
                   os.path.join(scratch, "foreign-joined"))
    assert r.returncode == 2 and "header" in r.stderr, (r.returncode, r.stderr)
