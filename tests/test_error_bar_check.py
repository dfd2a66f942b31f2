"""scripts/error_bar_check.py: the table of docs/reproduction.md's "How far the error bars hold".

- On the committed tables, every line the script prints is in docs/reproduction.md word for
  word: the document quotes what the tables give, and a table that changes without the document
  fails here.
- On a scratch root holding the same file names with series whose answer is known: every seed
  of a point shares one noise pattern, whose 15 s block means over 60-180 s are +b, +b, -b, -b,
  ... (their error b/sqrt(7)), over 30-90 s -b, -b, +b, +b (b/sqrt(3)), and whose 30 s block
  means over 60-180 s alternate +b, -b (b/sqrt(3)). Seed k of n is offset by k d, so every seed
  has the same error e and chi2/dof = sum_k (k d - mean)^2 / e^2 / (n - 1) = n (n + 1) d^2 /
  (12 e^2), exactly. The pooled chi2/dof is sum(chi2_g dof_g) / sum(dof_g). Each printed value
  has two significant digits, so each is checked to 0.5 % of itself plus the last digit's half.
- Errors from 8 blocks scatter as e sqrt(chi2_7 / 7), so honest seeds' chi2/dof has mean
  7/(7 - 2) = 1.4 and the 120 s pool's "errors x" factor is sqrt(chi2/dof / 1.4); 40 000 draws
  put that mean within 1 % (the variance of 7/chi2_7 is finite), so the factor is checked to 2 %
  plus half its last printed digit.
- Seeds offset by nothing give chi2/dof = 0 and p = 1; seeds offset by 3 errors (chi2/dof >= 4.5)
  give p below 0.01 for the 120 s pool.
- A seed whose table ends before the window's end (a run still going) is left out and
  counted; the finished seeds give their own chi2/dof exactly.
- A missing seed's table is refused with a message naming its point, and nothing is printed.
"""
import math
import os
import re

import pytest

from conftest import SOURCE, run_script

pytest.importorskip("numpy")  # the script's own dependency
import error_bar_check  # noqa: E402  (for its list of points and file names only)

source = str(SOURCE)
B = 0.01
OFFSET = 0.5 * B  # d: seed k is offset by k d
ERROR_OF = {("120", 15): B / math.sqrt(7), ("120", 30): B / math.sqrt(3),
            ("60", 15): B / math.sqrt(3)}


def run(root):
    return run_script("error_bar_check.py", "--root", root)


def pattern(t):
    """The shared noise: +-B, constant over each 30 s span counted from 60 s (see above)."""
    return B if math.floor((t - 60.0) / 30.0) % 2 == 0 else -B


def write_point(root, paths, offset):
    for k, relative in enumerate(paths):
        path = os.path.join(root, relative)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w") as f:
            f.write("# a test series binned by 1 s; units: t_from [s] t_to [s], the rest [1]\n")
            f.write("t_from,t_to,frames,steady,P_polar\n")
            for i in range(200):
                f.write(f"{i},{i + 1},10,1,{0.4 + k * offset + pattern(i + 0.5):.17g}\n")


def seeds_of(spec):
    return [os.path.relpath(p, source) for p in error_bar_check.tables_of(source, spec)]


def make_root(scratch, name, offset):
    root = os.path.join(scratch, name)
    for _, _, _, spec in error_bar_check.GROUPS:
        write_point(root, seeds_of(spec), offset)
    return root


def exact_chi2(n, error, offset):
    return n * (n + 1) * offset**2 / (12 * error**2)


def printed(cell):
    """(chi2/dof, p, factor or None) of one printed cell."""
    match = re.match(r"\**([0-9.e+-]+) \(([0-9.e+-]+)–([0-9.e+-]+); p ([=<]) ([0-9.e+-]+)\)"
                     r"(?:, errors × ([0-9.e+-]+))?", cell)
    assert match, cell
    factor = float(match.group(6)) if match.group(6) else None
    return float(match.group(1)), match.group(4), float(match.group(5)), factor


def near(shown, exact):
    """A value printed with two significant digits ("%.2g")."""
    if exact == 0:
        return shown == 0
    last_digit = 10 ** (math.floor(math.log10(abs(exact))) - 1)
    return abs(shown - exact) <= 0.5 * last_digit + 0.005 * abs(exact)


def cells(line):
    return [cell.strip() for cell in line.strip().strip("|").split("|")]


def test_every_line_printed_from_the_committed_tables_is_in_the_document():
    with open(os.path.join(source, "docs", "reproduction.md")) as f:
        document = f.read()
    real = run(source)
    assert real.returncode == 0, f"on the committed tables: {real.stderr}"
    lines = real.stdout.strip().splitlines()
    assert len(lines) == 2 + len(error_bar_check.GROUPS) + 2, \
        f"{len(lines)} lines printed for {len(error_bar_check.GROUPS)} points and two pools"
    for line in lines:
        assert line in document, f"not in docs/reproduction.md: {line}"


def test_seeds_of_known_errors_give_their_exact_chi2_and_pools(tmp_path):
    result = run(make_root(str(tmp_path), "known", OFFSET))
    assert result.returncode == 0, f"on known seeds: {result.stderr}"
    rows = [cells(line) for line in result.stdout.strip().splitlines()[2:]]
    pools = {}
    for (label, pool, window, spec), row in zip(error_bar_check.GROUPS, rows):
        n = len(seeds_of(spec))
        span = f"{window[1] - window[0]:g}"
        assert row[0] == f"{label}, {window[0]:g}–{window[1]:g} s" and row[1] == str(n), row[:2]
        for column, block in ((2, 15), (3, 30)):
            if (span, block) not in ERROR_OF:
                assert row[column].startswith("— (under 4 blocks)"), (label, block, row[column])
                continue
            exact = exact_chi2(n, ERROR_OF[(span, block)], OFFSET)
            chi2, _, _, _ = printed(row[column])
            assert near(chi2, exact), \
                f"{label}, {block} s blocks: {chi2} printed, {exact:.4g} exact"
            if pool:
                total = pools.setdefault((pool, block), [0.0, 0])
                total[0] += exact * (n - 1)
                total[1] += n - 1
    pooled = {row[0].strip("*"): row for row in rows[len(error_bar_check.GROUPS):]}
    for (pool, block), (sum_chi2, dof) in pools.items():
        row = pooled[f"{pool} windows, pooled"]
        assert row[1] == f"{dof} dof", (pool, row[1])
        chi2, _, _, factor = printed(row[2 if block == 15 else 3])
        assert near(chi2, sum_chi2 / dof), \
            f"{pool} pool, {block} s: {chi2}, exact {sum_chi2 / dof:.4g}"
        if (pool, block) == ("120 s", 15):
            expected = math.sqrt(sum_chi2 / dof / 1.4)
            # The factor is printed with two significant digits too, so its rounding adds half a
            # last digit (0.05 near 1) to the Monte Carlo's 2 %.
            last_digit = 10 ** (math.floor(math.log10(expected)) - 1)
            assert abs(factor - expected) <= 0.02 * expected + 0.5 * last_digit, \
                f"errors x {factor} printed, sqrt(chi2/dof / 1.4) = {expected:.3f}"
    assert len(pools) == 3, f"pools {sorted(pools)}"


# Seeds alike: chi2/dof = 0, p = 1. Seeds 3 errors apart: p < 0.01 in the 120 s pool.
@pytest.mark.parametrize("name, offset, test", [
    ("alike", 0.0, lambda p: p == ("=", 1.0)),
    ("apart", 3 * B / math.sqrt(7), lambda p: p[0] == "<" or p[1] < 0.01)])
def test_p_at_the_extremes(tmp_path, name, offset, test):
    result = run(make_root(str(tmp_path), name, offset))
    assert result.returncode == 0, f"{name}: {result.stderr}"
    pool = [line for line in result.stdout.splitlines()
            if line.startswith("| **120 s windows, pooled**")]
    assert pool, f"{name}: no 120 s pool printed"
    chi2, relation, p, _ = printed(cells(pool[0])[2])
    assert test((relation, p)), f"{name}: 120 s pool chi2/dof {chi2}, p {relation} {p}"


def test_a_seed_still_running_is_left_out_and_counted(tmp_path):
    """Its table ends at 150 s, before the window's end: the two finished seeds, offset by 0
    and d, give the two-seed chi2/dof exactly."""
    root = make_root(str(tmp_path), "running", OFFSET)
    label, _, window, spec = error_bar_check.GROUPS[0]
    last = os.path.join(root, seeds_of(spec)[-1])
    with open(last) as f:
        kept = f.readlines()[:2 + 150]
    with open(last, "w") as f:
        f.writelines(kept)
    result = run(root)
    row = next((cells(line) for line in result.stdout.splitlines()
                if line.startswith(f"| {label},")), None)
    n = len(seeds_of(spec)) - 1
    assert result.returncode == 0 and row is not None \
        and row[1] == f"{n} (+1 not yet at {window[1]:g} s)" \
        and near(printed(row[2])[0], exact_chi2(n, ERROR_OF[("120", 15)], OFFSET)), \
        f"a seed still running: rc {result.returncode}, {row}, {result.stderr!r}"


def test_a_missing_table_is_refused_naming_its_point(tmp_path):
    root = make_root(str(tmp_path), "known", OFFSET)
    os.remove(os.path.join(root, seeds_of(error_bar_check.GROUPS[0][3])[1]))
    result = run(root)
    assert result.returncode != 0 and error_bar_check.GROUPS[0][0] in result.stderr \
        and result.stdout == "", f"a missing seed: rc {result.returncode}, {result.stderr!r}"
