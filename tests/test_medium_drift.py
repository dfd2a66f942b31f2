"""scripts/medium_drift.py on analysis tables whose answer is known.

- A slaved medium: |P| an AR(1) series about 0.35 (correlation time 10 s, frames every 0.1 s,
  2000 s) and v_par = k |P| + white noise (σ = 0.6 mm/s per frame, about a dense medium's
  agitation over its ~1000 rods), k = 1.2 mm/s. The slope through the origin of 10 s block
  means has the exact error σ_b / √(Σ P_b²), σ_b = σ/√100 the block mean's noise: the jackknife
  error must match it within 15 % (200 blocks estimate it to about 5 %), the slope must lie
  within 4 of those errors of k, and blocks of 1 s must give the same error within 15 %, since
  the residual has no memory (the docstring's argument for short blocks).
- Two seeds that share P and the noise and differ only in k (k and k + d): their slopes differ
  by d exactly, their jackknife errors e are equal, the pooled slope is their mean, and
  chi2/dof is (d/2)^2 · 2 / e^2 = d^2 / (2 e^2) (within what e's three printed decimals allow).
- --blocks-out holds one row per block whose means are the frames' means over the block, and
  whose slope through the origin is the printed one.
- A missing column, tables whose frames differ, a window outside the frames, fewer than three
  blocks, --to before --from, and a non-number in a column are refused with exit status 1 and
  nothing on stdout; nothing is written to --blocks-out then.
"""
import csv
import math
import os
import re

import pytest

from conftest import run_script

np = pytest.importorskip("numpy")

FRAME_S = 0.1
N, K, SIGMA = 20000, 1.2, 0.6


def write_run(scratch, name, time, order, velocity, drift_time=None, order_column="P_polar"):
    """An analysis directory as `rodsea analyze --observables order,drift` writes it (the columns
    the script reads, among others)."""
    directory = os.path.join(scratch, name)
    os.makedirs(directory, exist_ok=True)
    with open(os.path.join(directory, "order_parameters.csv"), "w") as f:
        f.write("# test order_parameters; units: time [s] steady [1] P_polar [1] S_polar [1]\n")
        f.write(f"time,steady,{order_column},S_polar\n")
        for t, p in zip(time, order):
            f.write(f"{t:.10g},1,{p!r},0.1\n")
    with open(os.path.join(directory, "drift.csv"), "w") as f:
        f.write("# test drift; units: time [s] steady [1] v_rms_medium [mm/s] "
                "v_medium_along_polar [mm/s]\n")
        f.write("time,steady,v_rms_medium,v_medium_along_polar\n")
        for t, v in zip(drift_time if drift_time is not None else time, velocity):
            f.write(f"{t:.10g},1,20.0,{v!r}\n")
    return directory


def run(*args):
    return run_script("medium_drift.py", *args)


LINE = re.compile(r"^(.+?): (\d+) frames, (\d+) blocks; \|P\| = ([\d.]+) ± ([\d.]+); v_par = "
                  r"(-?[\d.]+) ± ([\d.]+) mm/s; alpha/Gamma_f = (-?[\d.]+) ± ([\d.]+) mm/s; "
                  r"r\(blocks\) = (-?[\d.na]+)(?:; chi2/dof of the tables' slopes ([\d.]+))?$",
                  re.M)


def lines_of(stdout):
    return {m.group(1): {"frames": int(m.group(2)), "blocks": int(m.group(3)),
                         "slope": float(m.group(8)), "slope_err": float(m.group(9)),
                         "chi2": float(m.group(11)) if m.group(11) else None}
            for m in LINE.finditer(stdout)}


def ar1(n, tau_frames, rng):
    a = math.exp(-1 / tau_frames)
    x = np.empty(n)
    x[0] = rng.standard_normal()
    kicks = rng.standard_normal(n) * math.sqrt(1 - a * a)
    for i in range(1, n):
        x[i] = a * x[i - 1] + kicks[i]
    return x


@pytest.fixture(scope="module")
def medium():
    """|P|, and the noise of the slaved medium's velocity, on N frames."""
    rng = np.random.default_rng(5)
    time = np.arange(N) * FRAME_S
    order = np.clip(0.35 + 0.15 * ar1(N, 100.0, rng), 0.01, 1.0)
    noise = SIGMA * rng.standard_normal(N)
    return time, order, noise


def test_the_slope_and_its_jackknife_error_of_a_slaved_medium(tmp_path, medium):
    time, order, noise = medium
    slaved = write_run(str(tmp_path), "slaved", time, order, K * order + noise)
    result = run(slaved, "--from", "0")
    assert result.returncode == 0, f"the slaved medium failed: {result.stderr}"
    got = lines_of(result.stdout).get(slaved)
    assert got is not None, f"no line for the slaved medium:\n{result.stdout}"
    blocks = order.reshape(-1, 100).mean(axis=1)
    exact = (SIGMA / math.sqrt(100)) / math.sqrt(float(np.dot(blocks, blocks)))
    assert got["blocks"] == 200 and got["frames"] == N, f"blocks and frames: {got}"
    assert abs(got["slope_err"] / exact - 1) < 0.15, \
        f"jackknife error {got['slope_err']} against the exact {exact:.4g}"
    assert abs(got["slope"] - K) < 4 * exact, f"slope {got['slope']} against k = {K}"
    short = lines_of(run(slaved, "--from", "0", "--block", "1").stdout).get(slaved)
    assert short is not None and abs(short["slope_err"] / got["slope_err"] - 1) < 0.15, \
        f"1 s blocks give {short} against 10 s blocks' {got['slope_err']}"


def test_two_seeds_differing_in_k_pool_and_their_block_table(tmp_path, medium):
    time, order, noise = medium
    D = 0.1
    first = write_run(str(tmp_path), "seed1", time, order, K * order + noise)
    second = write_run(str(tmp_path), "seed2", time, order, (K + D) * order + noise)
    table = str(tmp_path / "blocks.csv")
    result = run(first, second, "--from", "100", "--to", "1100", "--blocks-out", table)
    assert result.returncode == 0, f"two seeds failed: {result.stderr}"
    got = lines_of(result.stdout)
    one, two, pooled = got.get(first), got.get(second), got.get("all 2")
    assert None not in (one, two, pooled), f"missing lines:\n{result.stdout}"
    assert abs(two["slope"] - one["slope"] - D) < 2e-3, f"slopes {one} and {two} differ by not {D}"
    assert abs(one["slope_err"] - two["slope_err"]) < 2e-3, f"errors differ: {one}, {two}"
    assert abs(pooled["slope"] - (one["slope"] + two["slope"]) / 2) < 2e-3, \
        f"pooled slope {pooled['slope']} is not the seeds' mean"
    # The error is printed to 3 decimals, so the expected chi2/dof is known to a range.
    high = D ** 2 / (2 * (one["slope_err"] - 5e-4) ** 2) + 0.005
    low = D ** 2 / (2 * (one["slope_err"] + 5e-4) ** 2) - 0.005
    assert low <= pooled["chi2"] <= high, f"chi2/dof {pooled['chi2']} outside {low:.3g}–{high:.3g}"
    assert one["frames"] == 10000 and one["blocks"] == 100, f"the window 100-1100 s: {one}"
    with open(table) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    assert len(rows) == 200, f"{len(rows)} block rows, not 200"
    mine = [r for r in rows if r["run"] == first]
    p = np.array([float(r["P_polar"]) for r in mine])
    v = np.array([float(r["v_medium_along_polar"]) for r in mine])
    frames = slice(1000, 1100)  # the first block, 100-110 s
    assert abs(p[0] - order[frames].mean()) < 1e-9 and float(mine[0]["t_from"]) == 100.0 \
        and float(mine[0]["t_to"]) == 110.0, f"first block row {mine[0]}"
    assert abs(float(np.dot(p, v) / np.dot(p, p)) - one["slope"]) < 1e-3, \
        "the table's slope is not the printed one"


def refusals(scratch, medium):
    time, order, noise = medium
    short_time, order, noise = time[:300], order[:300], noise[:300]
    bad = {
        "no column": write_run(scratch, "nocolumn", short_time, order, noise,
                               order_column="P_apolar"),
        "frames differ": write_run(scratch, "shifted", short_time, order, noise,
                                   drift_time=short_time + 0.05),
    }
    not_number = write_run(scratch, "nan", short_time, order, noise)
    with open(os.path.join(not_number, "drift.csv")) as f:
        text = f.read().replace(f"{noise[7]!r}", "oops", 1)
    with open(os.path.join(not_number, "drift.csv"), "w") as f:
        f.write(text)
    bad["not a number"] = not_number
    good_short = write_run(scratch, "short", short_time, order, noise)
    return [(label, [d, "--from", "0"]) for label, d in bad.items()] + [
        ("window outside", [good_short, "--from", "0", "--to", "60"]),
        ("fewer than three blocks", [good_short, "--from", "0", "--block", "15"]),
        ("--to before --from", [good_short, "--from", "20", "--to", "10"]),
    ]


def test_bad_tables_and_windows_are_refused_and_write_nothing(tmp_path, medium):
    for label, args in refusals(str(tmp_path), medium):
        out = str(tmp_path / f"refused-{label.replace(' ', '_')}.csv")
        result = run(*args, "--blocks-out", out)
        assert result.returncode == 1 and result.stdout == "" \
            and "medium_drift:" in result.stderr and not os.path.exists(out), \
            f"{label}: rc {result.returncode}, stdout {result.stdout!r}, stderr {result.stderr!r}"
