#!/usr/bin/python3
"""Means and block errors of a series table over a time window: the numbers docs/reproduction.md
quotes for runs too short for the automatic steady window.

    scripts/block_means.py SERIES.csv... --from T0 [--to T1] [--block SECONDS]
    scripts/block_means.py SERIES.csv... --from T0 [--to T1] --blocking [--column NAME]
    scripts/block_means.py SEED1.csv SEED2.csv... --from T0 --to T1 [--block S] --replicates
    scripts/block_means.py SEED1.csv [SEED2.csv...] --from T0 --to T1 --correlation [--column NAME]

SERIES.csv is a table of scripts/reproduction_series.py (time bins of P_polar, S_medium, Sigma,
N_m, ...). The window [T0, T1) (s; T1 default: the table's end; bins by their middles) must lie
within the table; it is cut into blocks of --block seconds (default 15; a shorter remainder at
the end is left out); each column's mean is the mean of the block means and its error their
standard deviation over √(blocks − 1), the error of a mean of independent blocks. Prints one
line per table and column.

That holds only when the blocks are longer than P's correlation time, and in the first row's
120 s windows P is correlated beyond 16 s (at the dense end it moves on scales of 30-50 s), so
15 s blocks understate the error. --blocking checks it (Flyvbjerg and Petersen's blocking
analysis): for one column (default P_polar) it prints the error at block lengths doubling from
one bin to a quarter of the window, each with its own uncertainty (error/sqrt(2(blocks - 1))).
The errors have levelled off at the first length that no longer length (at least two of them)
exceeds by more than its own uncertainty; the error quoted is then the largest from that length
on, since the decision is often close. If no length qualifies, the window is too short for an
honest error, and the largest error seen is printed as a lower bound.

--replicates reads the tables as seeds of one state point and checks the errors against their
spread, as `rodsea analyze` does for runs that differ only in their seed: for --column it prints
each seed's block mean and error, their mean, the error from their spread (sd/sqrt(n)), and
chi2/dof = sum (x_i - mean)^2 / error_i^2 / (n - 1), about 1 when the errors are honest. Its 95 %
range is drawn by Monte Carlo, not taken from the chi2 distribution: each error is itself
estimated from a few blocks, which widens the range (with 8 blocks per seed, honest errors give
a mean of about 1.4; with 4 blocks, about 3). --to is required, so that every seed has the same
window.

--correlation says how long blocks must be: C(t) of --column, its bins' deviations from the
mean over every seed's window, multiplied at a lag t and averaged over all pairs in all seeds,
over their variance; printed at lags doubling from one bin to half the window, with the lag at
which it first falls below 1/e (interpolated between bins). Because the deviations are taken
from the common mean, a seed that holds another state than the rest for the whole window counts
as correlation, as it should: its blocks cannot see it. Blocks much shorter than that lag give
errors that are too small; independent blocks need several times it. --to is required.
"""
import argparse
import sys

import numpy as np

BOOKKEEPING = ("t_from", "t_to", "frames", "steady")


def require_window(table, start, end):
    """Refuses a window that reaches past the table: its blocks would average what there is under
    the window's name, and a run not yet at the window's end would be quoted for a span it has
    not reached."""
    first, last = float(np.nanmin(table["t_from"])), float(np.nanmax(table["t_to"]))
    if start < first - 1e-9 or end > last + 1e-9:
        raise ValueError(f"the window {start:g}–{end:g} s is not within the table's "
                         f"{first:g}–{last:g} s")


def block_means(table, start, end, block):
    """{column: (mean of the block means, their error, blocks)} over [start, end), which must lie
    within the table (require_window)."""
    require_window(table, start, end)
    time = 0.5 * (table["t_from"] + table["t_to"])
    edges = np.arange(start, end + 1e-9, block)
    if len(edges) < 3:
        raise ValueError(f"the window {start:g}–{end:g} s holds fewer than two blocks of "
                         f"{block:g} s")
    result = {}
    for column in table.dtype.names:
        if column in BOOKKEEPING:
            continue
        means = []
        for lo, hi in zip(edges[:-1], edges[1:]):
            values = table[column][(time >= lo) & (time < hi)]
            values = values[np.isfinite(values)]
            if len(values):
                means.append(values.mean())
        if len(means) >= 2:
            means = np.array(means)
            result[column] = (means.mean(), means.std(ddof=1) / np.sqrt(len(means)), len(means))
    return result


def blocking(table, start, end, column):
    """Rows (block length s, error, its uncertainty, blocks), the plateau's row index (None when
    the errors never stop growing) and the error to quote. Lengths double from the table's bin
    width."""
    if column not in (table.dtype.names or ()) or column in BOOKKEEPING:
        raise ValueError(f"no column {column}")
    width = float(np.median(table["t_to"] - table["t_from"]))
    rows = []
    length = width
    while (end - start) / length >= 4 - 1e-9:
        result = block_means(table, start, end, length)
        if column not in result:
            raise ValueError(f"column {column} has fewer than two finite blocks of {length:g} s")
        _, error, blocks = result[column]
        rows.append((length, error, error / np.sqrt(2 * (blocks - 1)), blocks))
        length *= 2
    if len(rows) < 3:
        raise ValueError(f"the window {start:g}–{end:g} s holds fewer than 16 bins of "
                         f"{width:g} s")
    # One agreeing neighbour is too weak a plateau: the longest blocks are few, their errors
    # uncertain by 30-50 %, so a still-rising curve often agrees with its last point. Falls are
    # not held against a plateau: the error of a mean cannot truly fall with the block length,
    # so a fall is the noise of few blocks.
    # Nor is a flat stretch at blocks shorter than the correlation time: there the error grows as
    # the square root of the length, (e_L / e_1)^2 = L / bin, slowly enough to hide in the noise
    # of a short window. Past the correlation time (e_L / e_1)^2 settles at 2 tau_int (bins), so a
    # plateau must lie at L >= 4 tau_int: (e_L / e_1)^2 <= L / (2 bin).
    plateau = None
    for i in range(len(rows) - 2):
        # A constant column (zero error at one bin) has nothing left to settle.
        settled = rows[0][1] == 0 or (rows[i][1] / rows[0][1]) ** 2 <= rows[i][0] / (2 * rows[0][0])
        if settled and all(e - rows[i][1] <= de for _, e, de, _ in rows[i + 1:]):
            plateau = i
            break
    start_row = plateau if plateau is not None else 0
    quoted = max(rows[start_row:], key=lambda row: row[1])
    return rows, plateau, quoted


def correlation(tables, start, end, column):
    """Lags (in bins), C at each lag from 0 to half the window, the bin width (s) and the first
    lag (s) where C < 1/e, or None: see the module's --correlation."""
    series, widths = [], set()
    for table in tables:
        if column not in (table.dtype.names or ()) or column in BOOKKEEPING:
            raise ValueError(f"no column {column}")
        require_window(table, start, end)
        widths.add(round(float(np.median(table["t_to"] - table["t_from"])), 9))
        middle = 0.5 * (table["t_from"] + table["t_to"])
        series.append(table[column][(middle >= start) & (middle < end)])
    if len(widths) != 1:
        raise ValueError(f"the tables' bins differ ({sorted(widths)} s): lags would not match")
    width = widths.pop()
    bins = min(len(x) for x in series)
    if bins < 8:
        raise ValueError(f"the window {start:g}–{end:g} s holds fewer than 8 bins")
    values = np.array([x[:bins] for x in series], dtype=float)
    if not np.isfinite(values).any():
        raise ValueError(f"column {column} holds no number in the window")
    deviation = values - np.nanmean(values)
    variance = np.nanmean(deviation**2)
    if variance == 0:
        raise ValueError(f"column {column} is constant: no correlation to measure")
    lags = np.arange(bins // 2 + 1)
    c = np.array([np.nanmean(deviation[:, :bins - lag] * deviation[:, lag:]) for lag in lags])
    c /= variance
    below = np.nonzero(c < np.exp(-1))[0]
    crossing = None
    if len(below):
        k = below[0]  # c[k - 1] >= 1/e > c[k], with c[0] = 1
        crossing = width * (k - 1 + (c[k - 1] - np.exp(-1)) / (c[k - 1] - c[k]))
    return lags, c, width, crossing


def chi2_per_dof(values, errors):
    """sum (x_i - mean)^2 / error_i^2 / (n - 1) along the last axis, the mean unweighted as in
    `rodsea analyze`'s replicate rows."""
    mean = values.mean(axis=-1, keepdims=True)
    return ((values - mean) ** 2 / errors**2).sum(axis=-1) / (values.shape[-1] - 1)


def honest_chi2(errors, blocks, draws=40000, seed=19):
    """chi2/dof of `draws` sets of seeds whose block errors are honest: seed i's mean is normal
    with standard deviation errors[i], and its error is estimated from blocks[i] blocks, so it
    scatters as errors[i] sqrt(chi2_k / k), k = blocks[i] - 1. The seed fixes the draws, so the
    printed range is the same on every run."""
    rng = np.random.default_rng(seed)
    errors = np.asarray(errors, dtype=float)
    dof = np.asarray(blocks) - 1
    values = rng.standard_normal((draws, len(errors))) * errors
    estimated = errors * np.sqrt(rng.chisquare(dof, (draws, len(errors))) / dof)
    return chi2_per_dof(values, estimated)


def replicates(values, errors, blocks):
    """Mean, error from the spread, chi2/dof of the spread against the errors, and the 2.5 % and
    97.5 % points of chi2/dof for honest errors estimated from `blocks` blocks each."""
    values, errors = np.asarray(values, dtype=float), np.asarray(errors, dtype=float)
    n = len(values)
    if n < 2:
        raise ValueError("--replicates needs at least two tables")
    if not np.all(errors > 0):
        raise ValueError("a seed's error is zero: chi2 is undefined")
    chi2 = float(chi2_per_dof(values, errors))
    low, high = np.percentile(honest_chi2(errors, blocks), [2.5, 97.5])
    return values.mean(), values.std(ddof=1) / np.sqrt(n), chi2, float(low), float(high)


def read_table(path):
    try:
        table = np.genfromtxt(path, delimiter=",", names=True, skip_header=1)
    except (OSError, ValueError) as e:
        raise ValueError(e) from None
    if not {"t_from", "t_to"} <= set(table.dtype.names or ()):
        raise ValueError("no t_from, t_to columns (a reproduction_series.py table?)")
    return table


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("tables", nargs="+")
    parser.add_argument("--from", dest="start", type=float, required=True, help="s")
    parser.add_argument("--to", dest="end", type=float, help="s (default: the table's end)")
    parser.add_argument("--block", type=float, default=15.0, help="s (default 15)")
    parser.add_argument("--blocking", action="store_true",
                        help="print the error against block length for --column instead")
    parser.add_argument("--replicates", action="store_true",
                        help="read the tables as seeds of one point: their spread against "
                             "their errors, for --column")
    parser.add_argument("--correlation", action="store_true",
                        help="read the tables as seeds of one point: the time correlation of "
                             "--column about their common mean")
    parser.add_argument("--column", default="P_polar",
                        help="the column --blocking, --replicates and --correlation read "
                             "(default P_polar)")
    args = parser.parse_args()
    if args.blocking + args.replicates + args.correlation > 1:
        sys.exit("block_means.py: --blocking, --replicates and --correlation are different "
                 "readings; give one")
    for flag, given in (("--replicates", args.replicates), ("--correlation", args.correlation)):
        if given and args.end is None:
            sys.exit(f"block_means.py: {flag} needs --to, so that every seed has the same "
                     "window")
    if args.end is not None and args.end <= args.start:
        sys.exit(f"block_means.py: --to {args.end:g} s must be after --from {args.start:g} s")
    if args.correlation:
        print_correlation(args)
        return
    seeds = []
    for path in args.tables:
        try:
            table = read_table(path)
            end = args.end if args.end is not None else float(np.nanmax(table["t_to"]))
            if args.blocking:
                print_blocking(path, args.start, end, args.column,
                               *blocking(table, args.start, end, args.column))
                continue
            result = block_means(table, args.start, end, args.block)
        except ValueError as e:
            sys.exit(f"block_means.py: {path}: {e}")
        if args.replicates:
            if args.column not in result:
                sys.exit(f"block_means.py: {path}: no column {args.column} with two finite "
                         "blocks")
            seeds.append((path, *result[args.column]))
            continue
        print(f"{path}: {args.start:g}–{end:g} s, blocks of {args.block:g} s")
        for column, (mean, error, blocks) in result.items():
            print(f"  {column:20s} {mean:10.4g} ± {error:.2g}  ({blocks} blocks)")
    if args.replicates:
        print_replicates(seeds, args)


def print_replicates(seeds, args):
    try:
        mean, spread, chi2, low, high = replicates(*zip(*[s[1:] for s in seeds]))
    except ValueError as e:
        sys.exit(f"block_means.py: {e}")
    print(f"{args.column}, {args.start:g}–{args.end:g} s, blocks of {args.block:g} s, "
          f"{len(seeds)} replicates")
    for path, value, error, blocks in seeds:
        print(f"  {value:10.4g} ± {error:.2g}  ({blocks} blocks)  {path}")
    verdict = ("the errors are too small" if chi2 > high else
               "the errors are too large" if chi2 < low else "the errors hold")
    print(f"  mean {mean:.4g} ± {spread:.2g} (from the spread); chi2/dof {chi2:.3g} "
          f"(95 % range for honest errors {low:.2g}–{high:.2g}): {verdict}")


def print_correlation(args):
    try:
        lags, c, width, crossing = correlation([read_table(path) for path in args.tables],
                                               args.start, args.end, args.column)
    except ValueError as e:
        sys.exit(f"block_means.py: {e}")
    print(f"{args.column}, {args.start:g}–{args.end:g} s, {len(args.tables)} table(s): its "
          "time correlation about their common mean")
    lag = 1
    while lag < len(lags):
        print(f"  {lag * width:8.4g} s  C = {c[lag]:.3f}")
        lag *= 2
    if crossing is None:
        print(f"  C stays above 1/e to half the window ({lags[-1] * width:g} s): the correlation "
              "time is longer than that, and no block in this window is independent")
    else:
        print(f"  C falls below 1/e at {crossing:.3g} s")


def print_blocking(path, start, end, column, rows, plateau, quoted):
    print(f"{path}: {column}, {start:g}–{end:g} s, error against block length")
    for i, (length, error, uncertainty, blocks) in enumerate(rows):
        mark = "  <- levels off" if i == plateau else ""
        print(f"  {length:8.4g} s  {error:.3g} ± {uncertainty:.2g}  ({blocks} blocks){mark}")
    if plateau is None:
        print(f"  no plateau: the window is too short for an honest error; it is at least "
              f"{quoted[1]:.2g} (blocks of {quoted[0]:g} s)")
    else:
        print(f"  error {quoted[1]:.2g} (the largest from {rows[plateau][0]:g} s on: blocks of "
              f"{quoted[0]:g} s)")


if __name__ == "__main__":
    main()
