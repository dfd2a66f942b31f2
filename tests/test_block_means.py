"""scripts/block_means.py --blocking and --replicates on series whose errors are known.

- An AR(1) series (x_t = a x_{t-1} + noise, unit variance, correlation time tau = 3 bins of
  1 s, 2^14 bins) has the exact error of its mean sqrt((1 + a)/(1 - a) / N) for N >> tau. The
  one-bin blocks must give the naive error, sqrt(1/N) of the sample's spread, that is the exact
  one times sqrt((1 - a)/(1 + a)) = 0.41 (to 3 %: one-bin blocks are 2^14, so their error is
  known to 0.6 %, and the sample's variance to about 2 % at tau = 3). The blocking analysis must
  find a plateau, and its error must be the exact one within 15 %: the plateau's own uncertainty
  is 3-6 % (256-1024 blocks), and blocks of 8-32 bins still fall short of the asymptote by up
  to 2 tau / L in variance, 4-10 % in the error.
- A linear ramp's n block means are evenly spaced, one block length apart, so its error is
  sqrt((n + 1)/12)/n of the ramp's rise: it grows without end, by 2 sqrt((n/2 + 1)/(n + 1)) (about
  sqrt(2)) at each doubling. No plateau, and the lower bound printed is the longest blocks'.
- A constant column has zero error at every block length; its mean is the constant.
- --replicates on three seeds that share one noise pattern, offset by 0 and ±d: each has the
  same block error e, so chi2/dof is exactly (d/e)^2 and the spread's error d/sqrt(3).
- A window with --to before --from, one reaching past the table's ends, a column that is not
  there, or --replicates with one table, is refused with a message and exit status 1, printing
  nothing on stdout.

    /usr/bin/python3 tests/test_block_means.py SOURCE_DIR SCRATCH_DIR
Exit 77 (skipped) without numpy.
"""
import math
import os
import re
import shutil
import subprocess
import sys

try:
    import numpy as np
except ImportError as e:
    print(f"skipped: {e} (install python3-numpy)")
    sys.exit(77)

source, scratch = sys.argv[1], sys.argv[2]
script = os.path.join(source, "scripts", "block_means.py")
shutil.rmtree(scratch, ignore_errors=True)
os.makedirs(scratch)
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)


def write_series(name, columns):
    n = len(next(iter(columns.values())))
    path = os.path.join(scratch, name)
    with open(path, "w") as f:
        f.write("# a test series binned by 1 s; units: t_from [s] t_to [s], the rest [1]\n")
        f.write(",".join(["t_from", "t_to", "frames", "steady", *columns]) + "\n")
        for i in range(n):
            values = [f"{columns[c][i]:.17g}" for c in columns]
            f.write(",".join([str(i), str(i + 1), "10", "1", *values]) + "\n")
    return path


def run(*args):
    return subprocess.run([sys.executable, script, *args], capture_output=True, text=True)


def rows_of(stdout):
    """(block length, error) per printed row."""
    return [(float(m.group(1)), float(m.group(2)))
            for m in re.finditer(r"^\s+([\d.e+]+) s\s+([\d.e+-]+) ±", stdout, re.M)]


N, TAU = 2**14, 3.0
a = math.exp(-1 / TAU)
rng = np.random.default_rng(19)
x = np.empty(N)
x[0] = rng.standard_normal()
kicks = rng.standard_normal(N) * math.sqrt(1 - a * a)
for i in range(1, N):
    x[i] = a * x[i - 1] + kicks[i]
exact = math.sqrt((1 + a) / (1 - a) / N)
ar1 = write_series("ar1.csv", {"P_polar": x, "ramp": np.arange(N) / N, "flat": np.full(N, 0.25)})

result = run(ar1, "--from", "0", "--blocking")
check(result.returncode == 0, f"AR(1) blocking failed: {result.stderr}")
rows = rows_of(result.stdout)
check(rows and rows[0][0] == 1, f"the first block length is not one bin: {rows}")
if rows:
    naive = x.std(ddof=1) / math.sqrt(N)
    check(abs(rows[0][1] / naive - 1) < 0.03, f"one-bin error {rows[0][1]} against {naive}")
    check(abs(rows[0][1] / (exact * math.sqrt((1 - a) / (1 + a))) - 1) < 0.03,
          f"one-bin error {rows[0][1]} is not the exact error times sqrt((1-a)/(1+a))")
    check(rows[-1][0] <= N / 4, f"blocks longer than a quarter of the window: {rows[-1]}")
plateau = re.search(r"^\s+([\d.e+]+) s\s+([\d.e+-]+) ±.*<- plateau", result.stdout, re.M)
check(plateau is not None, f"no plateau found for AR(1) with tau = 3 bins:\n{result.stdout}")
if plateau:
    error = float(plateau.group(2))
    check(abs(error / exact - 1) < 0.15, f"plateau error {error} against the exact {exact:.4g}")
    summary = re.search(r"^  error ([\d.e+-]+) \(blocks of ([\d.e+]+) s\)", result.stdout, re.M)
    check(summary is not None and float(summary.group(2)) == float(plateau.group(1))
          and abs(float(summary.group(1)) / error - 1) < 0.03,  # printed to 2 digits
          f"the summary line does not quote the plateau's error:\n{result.stdout}")

result = run(ar1, "--from", "0", "--blocking", "--column", "ramp")
check(result.returncode == 0, f"ramp blocking failed: {result.stderr}")
rows = rows_of(result.stdout)
check(all(e2 > e1 for (_, e1), (_, e2) in zip(rows, rows[1:])),
      f"a ramp's error does not grow with the block length: {rows}")
for (length, e1), (_, e2) in zip(rows, rows[1:]):
    n = N / length  # blocks; their means are n evenly spaced values, one block length apart
    growth = 2 * math.sqrt((n / 2 + 1) / (n + 1))
    # Printed to 3 digits, each error is rounded by up to 0.25 %: the ratio by up to 0.5 %.
    # The last doublings (n = 8, 16: 1.49, 1.45) tell the closed form from sqrt(2).
    check(abs(e2 / e1 / growth - 1) < 6e-3, f"a ramp's error grows by {e2 / e1} at {length} s, "
          f"not 2 sqrt((n/2 + 1)/(n + 1)) = {growth}")
bound = re.search(r"no plateau: .* at least ([\d.e+-]+) \(blocks of ([\d.e+]+) s\)", result.stdout)
check(bound is not None, f"a ramp reports a plateau:\n{result.stdout}")
if bound and rows:
    check(float(bound.group(2)) == rows[-1][0], "the lower bound is not the longest blocks'")

result = run(ar1, "--from", "100", "--to", "1100", "--blocking", "--column", "flat")
check(result.returncode == 0, f"flat blocking failed: {result.stderr}")
check(all(e == 0 for _, e in rows_of(result.stdout)), f"a constant has an error:\n{result.stdout}")
result = run(ar1, "--from", "100", "--to", "1100", "--block", "100")
check(re.search(r"^  flat\s+0\.25 ± 0\s+\(10 blocks\)", result.stdout, re.M) is not None,
      f"a constant's block mean over 10 blocks:\n{result.stdout}")

# Three seeds that share one noise pattern and differ by a constant offset (0, +d, -d) have the
# same block error e, so their chi2/dof is exactly (d^2 + d^2) / e^2 / 2 = (d / e)^2, and their
# mean's error from the spread is d / sqrt(3).
pattern = np.sin(np.arange(600) * 0.7) + 0.5 * np.cos(np.arange(600) * 0.13)
# d = 0.05 is ten block errors apart (the errors too small); d = 0.003 less than one (they hold).
for d in (0.05, 0.003):
    seeds = [write_series(f"seed{k}-{d}.csv", {"P_polar": 0.4 + offset + 0.1 * pattern})
             for k, offset in enumerate((0.0, d, -d))]
    one = run(seeds[0], "--from", "0", "--to", "600", "--block", "30")
    e = float(re.search(r"^  P_polar\s+[\d.]+ ± ([\d.e+-]+)", one.stdout, re.M).group(1))
    result = run(*seeds, "--from", "0", "--to", "600", "--block", "30", "--replicates")
    check(result.returncode == 0, f"--replicates failed: {result.stderr}")
    summary = re.search(r"mean ([\d.]+) ± ([\d.e+-]+) \(from the spread\); chi2/dof ([\d.e+-]+) "
                        r"\(95 % range ([\d.e+-]+)–([\d.e+-]+)\): (.*)$", result.stdout, re.M)
    check(summary is not None, f"--replicates prints no summary:\n{result.stdout}")
    if summary:
        mean = 0.4 + 0.1 * np.mean(pattern[:600])
        check(abs(float(summary.group(1)) - mean) < 1e-3, f"replicates' mean {summary.group(1)}")
        # Printed to 2 digits: 0.0017 for d/sqrt(3) = 0.00173 is 2 % off.
        check(abs(float(summary.group(2)) / (d / math.sqrt(3)) - 1) < 0.03,
              f"error from the spread {summary.group(2)}, not d/sqrt(3)")
        # e is printed to 2 digits (within 1.2 %), so (d/e)^2 is known to 2.4 %.
        check(abs(float(summary.group(3)) / (d / e) ** 2 - 1) < 0.04,
              f"chi2/dof {summary.group(3)}, not (d/e)^2 = {(d / e) ** 2:.3g}")
        # chi2/dof's 95 % range for 2 degrees of freedom is -ln(0.975) to -ln(0.025).
        check(abs(float(summary.group(4)) / -math.log(0.975) - 1) < 0.03
              and abs(float(summary.group(5)) / -math.log(0.025) - 1) < 0.03,
              f"95 % range {summary.group(4)}–{summary.group(5)} for 2 dof")
        too_small = (d / e) ** 2 > -math.log(0.025)
        expected = "the errors are too small" if too_small else "the errors hold"
        check(summary.group(6) == expected, f"verdict {summary.group(6)!r}, expected {expected!r}")
for bad, says in ((["--from", "50", "--to", "40", "--blocking"], "--to 40 s must be after"),
                  (["--from", "0", "--blocking", "--column", "nope"], "no column nope"),
                  (["--from", "100", "--to", f"{N + 1}"], "is not within the table's 0–16384 s"),
                  (["--from", "-1", "--blocking"], "is not within"),
                  (["--from", "0", "--replicates"], "at least two tables"),
                  (["--from", "0", "--replicates", "--blocking"], "give one")):
    result = run(ar1, *bad)
    check(result.returncode == 1 and says in result.stderr and not result.stdout,
          f"{bad}: exit {result.returncode}, stderr {result.stderr!r}, stdout {result.stdout!r}")

if failures:
    print("\n".join(failures))
    sys.exit(1)
print("block_means: AR(1) plateau, ramp, constant and bad input as expected")
