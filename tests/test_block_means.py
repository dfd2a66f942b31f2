"""scripts/block_means.py --blocking and --replicates on series whose errors are known.

- An AR(1) series (x_t = a x_{t-1} + noise, unit variance, correlation time tau = 3 bins of
  1 s, 2^14 bins) has the exact error of its mean sqrt((1 + a)/(1 - a) / N) for N >> tau. The
  one-bin blocks must give the naive error, the sample's standard deviation over sqrt(N), to
  0.5 % (the two differ only by ddof and printing). The blocking analysis must find a plateau and
  quote the exact error within 8 %: from 32 bins on, blocks fall short of the asymptote by at
  most 5 % in the error, the plateau's own uncertainty is 2-4 % (256-512 blocks), and the quoted
  error is the largest from the plateau on, a few % high.
- The plateau rule, on many AR(1) windows drawn with a fixed seed (how often it finds a
  plateau is a binomial count over 100 windows, so each rate is known to about 5 %): at least
  90 % of windows 512 correlation times long, and at most 5 % of windows 4 correlation times
  long, where the error still grows as the square root of the block length under the noise of
  few blocks (a rule without the correlation-time test finds one in about a third of them).
- A linear ramp's n block means are evenly spaced, one block length apart, so its error is
  sqrt((n + 1)/12)/n of the ramp's rise: it grows without end, by 2 sqrt((n/2 + 1)/(n + 1)) (about
  sqrt(2)) at each doubling. No plateau, and the lower bound printed is the longest blocks'.
- A constant column has zero error at every block length, a plateau from one bin; its mean is
  the constant. Bins of
  0.5 s start the block lengths at 0.5 s.
- --replicates on three seeds that share one noise pattern, offset by 0 and ±d: each has the
  same block error e, so chi2/dof is exactly (d/e)^2 and the spread's error d/sqrt(3). Its range
  for honest, equal errors: with errors from very many blocks it is the chi2 law's for 2 degrees
  of freedom, -ln(0.975) to -ln(0.025); with 8 blocks per seed its mean is nu/(nu - 2) = 1.4 for
  nu = 7 (the mean of 1/s^2 for an error estimated with nu degrees of freedom).
- --correlation on 8 AR(1) seeds of 4096 one-second bins with tau = 10 s: C(t) = exp(-t/tau),
  so C at 1 s is exp(-0.1) = 0.905 and C falls below 1/e at tau. Their estimates scatter by
  about sqrt((1 + a^2)/(1 - a^2)/32768) = 0.018 in C at tau, where C falls by 0.037 per bin,
  so the crossing scatters by about half a bin: checked to 15 %, C at 1 s to 0.02 (its own
  scatter is below 0.005). Two seeds that hold +1 and -1 for the whole window have C = 1 at
  every lag (the spread between seeds counts as correlation): no crossing.
- A window with --to before --from, one reaching past the table's ends, a column that is not
  there or holds no number, --replicates with one table or without --to, and --replicates with
  --blocking, are refused with a message and exit status 1, printing nothing on stdout.
"""
import math
import os
import re

import pytest

from conftest import run_script

np = pytest.importorskip("numpy")
import block_means  # noqa: E402  (the plateau rule's rates and the honest range, in bulk)

N, TAU = 2**14, 3.0
NUMBER = r"([\d.e+-]+)"


def write_series(directory, name, columns, width=1.0):
    n = len(next(iter(columns.values())))
    path = os.path.join(directory, name)
    with open(path, "w") as f:
        f.write(f"# a test series binned by {width:g} s; units: t_from [s] t_to [s], the rest "
                "[1]\n")
        f.write(",".join(["t_from", "t_to", "frames", "steady", *columns]) + "\n")
        for i in range(n):
            values = [f"{columns[c][i]:.17g}" for c in columns]
            f.write(",".join([f"{i * width:g}", f"{(i + 1) * width:g}", "10", "1", *values])
                    + "\n")
    return path


def run(*args):
    return run_script("block_means.py", *args)


def rows_of(stdout):
    """(block length, error) per printed row."""
    return [(float(m.group(1)), float(m.group(2)))
            for m in re.finditer(r"^\s+([\d.e+]+) s\s+([\d.e+-]+) ±", stdout, re.M)]


def ar1(n, tau, rng):
    a = math.exp(-1 / tau)
    x = np.empty(n)
    x[0] = rng.standard_normal()
    kicks = rng.standard_normal(n) * math.sqrt(1 - a * a)
    for i in range(1, n):
        x[i] = a * x[i - 1] + kicks[i]
    return x


@pytest.fixture(scope="module")
def ar1_table(tmp_path_factory):
    """The AR(1) series (tau = 3 bins) beside a ramp, a constant and an empty column: the
    table's path and the series."""
    x = ar1(N, TAU, np.random.default_rng(19))
    path = write_series(str(tmp_path_factory.mktemp("series")), "ar1.csv",
                        {"P_polar": x, "ramp": np.arange(N) / N, "flat": np.full(N, 0.25),
                         "empty": np.full(N, np.nan)})
    return path, x


def test_ar1_blocking_finds_the_plateau_and_quotes_the_exact_error(ar1_table):
    path, x = ar1_table
    a = math.exp(-1 / TAU)
    exact = math.sqrt((1 + a) / (1 - a) / N)
    result = run(path, "--from", "0", "--blocking")
    assert result.returncode == 0, f"AR(1) blocking failed: {result.stderr}"
    rows = rows_of(result.stdout)
    assert rows and rows[0][0] == 1, f"the first block length is not one bin: {rows}"
    naive = x.std(ddof=1) / math.sqrt(N)
    assert abs(rows[0][1] / naive - 1) < 0.005, f"one-bin error {rows[0][1]} against {naive}"
    assert rows[-1][0] <= N / 4, f"blocks longer than a quarter of the window: {rows[-1]}"
    plateau = re.search(r"^\s+([\d.e+]+) s\s+([\d.e+-]+) ±.*<- levels off", result.stdout, re.M)
    assert plateau is not None, f"no plateau found for AR(1) with tau = 3 bins:\n{result.stdout}"
    summary = re.search(r"^  error ([\d.e+-]+) \(the largest from ([\d.e+]+) s on: blocks of "
                        r"([\d.e+]+) s\)", result.stdout, re.M)
    assert summary is not None, f"no summary line:\n{result.stdout}"
    quoted = float(summary.group(1))
    assert abs(quoted / exact - 1) < 0.08, f"quoted error {quoted} against the exact {exact:.4g}"
    later = [e for length, e in rows if length >= float(plateau.group(1))]
    # The largest from the plateau on, printed to 2 digits.
    assert float(summary.group(2)) == float(plateau.group(1)) \
        and abs(quoted / max(later) - 1) < 0.03, \
        f"the summary does not quote the largest error from the plateau on:\n{result.stdout}"


def test_the_plateau_rules_rates():
    """On the module's own function (100 windows each; fixed seed)."""
    rng = np.random.default_rng(7)
    for tau, n, low, high in ((2.0, 1024, 0.90, 1.0), (32.0, 128, 0.0, 0.05)):
        found = 0
        for _ in range(100):
            table = np.zeros(n, dtype=[("t_from", float), ("t_to", float), ("P_polar", float)])
            table["t_from"], table["t_to"] = np.arange(n), np.arange(n) + 1.0
            table["P_polar"] = ar1(n, tau, rng)
            found += block_means.blocking(table, 0.0, float(n), "P_polar")[1] is not None
        assert low <= found / 100 <= high, f"tau = {tau:g} bins, window {n}: a plateau in " \
            f"{found} of 100 windows, expected {low:.0%}–{high:.0%}"


def test_a_ramps_error_grows_without_end(ar1_table):
    result = run(ar1_table[0], "--from", "0", "--blocking", "--column", "ramp")
    assert result.returncode == 0, f"ramp blocking failed: {result.stderr}"
    rows = rows_of(result.stdout)
    for (length, e1), (_, e2) in zip(rows, rows[1:]):
        n = N / length  # blocks; their means are n evenly spaced values, one block length apart
        growth = 2 * math.sqrt((n / 2 + 1) / (n + 1))
        # Printed to 3 digits, each error is rounded by up to 0.5 %: the ratio by up to 1 %. The
        # last doublings (n = 8, 16: 1.49, 1.45) tell the closed form from sqrt(2).
        assert abs(e2 / e1 / growth - 1) < 0.01, f"a ramp's error grows by {e2 / e1} at " \
            f"{length} s, not 2 sqrt((n/2 + 1)/(n + 1)) = {growth}"
    bound = re.search(r"no plateau: .* at least ([\d.e+-]+) \(blocks of ([\d.e+]+) s\)",
                      result.stdout)
    assert bound is not None, f"a ramp reports a plateau:\n{result.stdout}"
    assert float(bound.group(2)) == rows[-1][0], "the lower bound is not the longest blocks'"


def test_a_constant_has_no_error_and_half_second_bins_start_at_half_a_second(ar1_table, tmp_path):
    result = run(ar1_table[0], "--from", "100", "--to", "1100", "--blocking", "--column", "flat")
    assert result.returncode == 0, f"flat blocking failed: {result.stderr}"
    assert all(e == 0 for _, e in rows_of(result.stdout)) and "\n  error 0 " in result.stdout, \
        f"a constant has an error, or no plateau:\n{result.stdout}"
    result = run(ar1_table[0], "--from", "100", "--to", "1100", "--block", "100")
    assert re.search(r"^  flat\s+0\.25 ± 0\s+\(10 blocks\)", result.stdout, re.M) is not None, \
        f"a constant's block mean over 10 blocks:\n{result.stdout}"
    half = write_series(str(tmp_path), "half.csv", {"P_polar": ar1_table[1][:512]}, width=0.5)
    rows = rows_of(run(half, "--from", "0", "--blocking").stdout)
    assert [length for length, _ in rows][:3] == [0.5, 1.0, 2.0], f"0.5 s bins: lengths {rows}"


# Three seeds sharing one noise pattern, offset by 0, +d and -d. d = 0.05 is ten block errors
# apart (the errors too small); d = 0.003 less than one (they hold).
@pytest.mark.parametrize("d", [0.05, 0.003])
def test_replicates_give_their_exact_spread_and_verdict(tmp_path, d):
    pattern = np.sin(np.arange(600) * 0.7) + 0.5 * np.cos(np.arange(600) * 0.13)
    seeds = [write_series(str(tmp_path), f"seed{k}.csv", {"P_polar": 0.4 + offset + 0.1 * pattern})
             for k, offset in enumerate((0.0, d, -d))]
    one = run(seeds[0], "--from", "0", "--to", "600", "--block", "30")
    e = float(re.search(r"^  P_polar\s+[\d.]+ ± ([\d.e+-]+)", one.stdout, re.M).group(1))
    result = run(*seeds, "--from", "0", "--to", "600", "--block", "30", "--replicates")
    assert result.returncode == 0, f"--replicates failed: {result.stderr}"
    summary = re.search(rf"mean {NUMBER} ± {NUMBER} \(from the spread\); chi2/dof {NUMBER} "
                        rf"\(95 % range for honest errors {NUMBER}–{NUMBER}\): (.*)$",
                        result.stdout, re.M)
    assert summary is not None, f"--replicates prints no summary:\n{result.stdout}"
    mean = 0.4 + 0.1 * np.mean(pattern[:600])
    assert abs(float(summary.group(1)) - mean) < 1e-3, f"replicates' mean {summary.group(1)}"
    # Printed to 2 digits: 0.0017 for d/sqrt(3) = 0.00173 is 2 % off.
    assert abs(float(summary.group(2)) / (d / math.sqrt(3)) - 1) < 0.03, \
        f"error from the spread {summary.group(2)}, not d/sqrt(3)"
    # e is printed to 2 digits (within 1.2 %), so (d/e)^2 is known to 2.4 %.
    assert abs(float(summary.group(3)) / (d / e) ** 2 - 1) < 0.04, \
        f"chi2/dof {summary.group(3)}, not (d/e)^2 = {(d / e) ** 2:.3g}"
    too_small = (d / e) ** 2 > float(summary.group(5))
    expected = "the errors are too small" if too_small else "the errors hold"
    assert summary.group(6) == expected, f"verdict {summary.group(6)!r}, expected {expected!r}"
    assert too_small == (d == 0.05), f"d = {d}: chi2/dof {summary.group(3)} against the range " \
        f"{summary.group(4)}–{summary.group(5)}"


def test_the_honest_range_of_equal_errors():
    """With unequal errors the unweighted mean makes the statistic no longer chi2-distributed,
    which the Monte Carlo follows and the law does not. With 10^4 blocks per seed the errors are
    as good as known: the chi2 law's 2.5 % and 97.5 % points for 2 dof, to the Monte Carlo's
    accuracy (40 000 draws: 3 % at the low end, 1 % at the high end; 10 % allowed). With 8
    blocks: mean 7/5 (its draws' spread puts the mean within 2 %; 5 % allowed)."""
    honest = block_means.honest_chi2([0.02] * 3, [10001] * 3)
    low, high = np.percentile(honest, [2.5, 97.5])
    assert abs(low / -math.log(0.975) - 1) < 0.1 and abs(high / -math.log(0.025) - 1) < 0.1, \
        f"honest range with known errors {low:.4g}–{high:.4g}, not the chi2 law's"
    honest = block_means.honest_chi2([0.02] * 3, [8] * 3)
    assert abs(honest.mean() / 1.4 - 1) < 0.05, f"honest mean with 8 blocks {honest.mean():.3g}"


def test_the_correlation_time_of_ar1_seeds_and_of_two_held_states(tmp_path):
    rng = np.random.default_rng(23)
    seeds = [write_series(str(tmp_path), f"ar1-tau10-seed{k}.csv",
                          {"P_polar": ar1(4096, 10.0, rng)}) for k in range(8)]
    result = run(*seeds, "--from", "0", "--to", "4096", "--correlation")
    crossing = re.search(r"C falls below 1/e at ([\d.e+-]+) s", result.stdout)
    first = re.search(r"^\s+1 s  C = ([\d.-]+)", result.stdout, re.M)
    assert result.returncode == 0 and crossing and abs(float(crossing.group(1)) / 10 - 1) < 0.15 \
        and first and abs(float(first.group(1)) - math.exp(-0.1)) < 0.02, \
        f"AR(1) tau = 10 s correlation: {result.stdout!r} {result.stderr!r}"
    held = [write_series(str(tmp_path), f"held{k}.csv", {"P_polar": np.full(64, sign)})
            for k, sign in enumerate((1.0, -1.0))]
    result = run(*held, "--from", "0", "--to", "64", "--correlation")
    assert result.returncode == 0 \
        and "C stays above 1/e to half the window (32 s)" in result.stdout \
        and result.stdout.count("C = 1.000") == 6, \
        f"two seeds in two states: {result.stdout!r} {result.stderr!r}"
    half_bins = write_series(str(tmp_path), "half-bins.csv", {"P_polar": ar1(64, 3.0, rng)},
                             width=0.5)
    for bad, says in ((["--from", "0", "--correlation"], "--correlation needs --to"),
                      (["--from", "0", "--to", "64", "--correlation", "--replicates"], "give one"),
                      (["--from", "0", "--to", "64", "--correlation", "--column", "nope"],
                       "no column nope")):
        result = run(held[0], *bad)
        assert result.returncode == 1 and says in result.stderr and not result.stdout, \
            f"{bad}: exit {result.returncode}, stderr {result.stderr!r}, stdout {result.stdout!r}"
    result = run(held[0], half_bins, "--from", "0", "--to", "32", "--correlation")
    assert result.returncode == 1 and "bins differ" in result.stderr and not result.stdout, \
        f"tables of different bins: {result.returncode}, {result.stderr!r}"


@pytest.mark.parametrize("bad, says", [
    (["--from", "50", "--to", "40", "--blocking"], "--to 40 s must be after"),
    (["--from", "0", "--blocking", "--column", "nope"], "no column nope"),
    (["--from", "0", "--blocking", "--column", "empty"],
     "column empty has fewer than two finite blocks"),
    (["--from", "100", "--to", f"{N + 1}"], "is not within the table's 0–16384 s"),
    (["--from", "-1", "--blocking"], "is not within"),
    (["--from", "0", "--to", "600", "--replicates"], "at least two tables"),
    (["--from", "0", "--replicates"], "--replicates needs --to"),
    (["--from", "0", "--replicates", "--blocking"], "give one")])
def test_bad_input_is_refused_printing_nothing(ar1_table, bad, says):
    result = run(ar1_table[0], *bad)
    assert result.returncode == 1 and says in result.stderr and not result.stdout, \
        f"{bad}: exit {result.returncode}, stderr {result.stderr!r}, stdout {result.stdout!r}"
