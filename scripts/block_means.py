#!/usr/bin/python3
"""Means and block errors of a series table over a time window: the numbers docs/reproduction.md
quotes for runs too short for the automatic steady window.

    scripts/block_means.py SERIES.csv... --from T0 [--to T1] [--block SECONDS]
    scripts/block_means.py SERIES.csv... --from T0 [--to T1] --blocking [--column NAME]
    scripts/block_means.py SEED1.csv SEED2.csv... --from T0 [--to T1] [--block S] --replicates

SERIES.csv is a table of scripts/reproduction_series.py (time bins of P_polar, S_medium, Sigma,
N_m, ...). The window [T0, T1) (s; T1 default: the table's end; bins by their middles) is cut
into blocks of --block seconds (default 15; a shorter remainder at the end is left out); each
column's mean is the mean of the block means and its error their standard deviation over
√(blocks − 1), the error of a mean of independent blocks. Prints one line per table and
column.

That holds only when the blocks are longer than P's correlation time, and in the first row's
120 s windows P is correlated beyond 16 s (at the dense end it moves on scales of 30-50 s), so
15 s blocks understate the error. --blocking checks it (Flyvbjerg and Petersen's blocking analysis):
for one column (default P_polar) it prints the error at block lengths doubling from one bin to
a quarter of the window, each with its own uncertainty (error/sqrt(2(blocks - 1))), and says
where the errors stop growing: the first length whose error no longer length (at least two of
them) exceeds by more than that length's uncertainty. If no length qualifies, the window is too
short for an honest error, and the largest error seen is printed as a lower bound.

--replicates reads the tables as seeds of one state point and checks the errors against their
spread, as `rodsea analyze` does for runs that differ only in their seed: for --column it prints
each seed's block mean and error, their mean, the error from their spread (sd/sqrt(n)), and
chi2/dof = sum (x_i - mean)^2 / error_i^2 / (n - 1), about 1 when the errors are honest, with
its 95 % range for n - 1 degrees of freedom.
"""
import argparse
import sys

import numpy as np


def block_means(table, start, end, block):
    time = 0.5 * (table["t_from"] + table["t_to"])
    edges = np.arange(start, end + 1e-9, block)
    if len(edges) < 3:
        raise ValueError(f"the window {start}–{end} s holds fewer than two blocks of {block} s")
    result = {}
    for column in table.dtype.names:
        if column in ("t_from", "t_to", "frames", "steady"):
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
    """Rows (block length s, error, its uncertainty, blocks) and the plateau's row index (None
    when the errors never stop growing). Lengths double from the table's bin width."""
    if column not in (table.dtype.names or ()):
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
    if len(rows) < 2:
        raise ValueError(f"the window {start}–{end} s holds fewer than 8 bins of {width:g} s")
    # One agreeing neighbour is too weak a plateau: the longest blocks are few, their errors
    # uncertain by 30-50 %, so a still-rising curve often agrees with its last point. Falls are
    # not held against a plateau: the error of a mean cannot truly fall with the block length,
    # so a fall is the noise of few blocks.
    plateau = None
    for i in range(len(rows) - 2):
        if all(e - rows[i][1] <= de for _, e, de, _ in rows[i + 1:]):
            plateau = i
            break
    return rows, plateau


def replicates(values, errors):
    """Mean, error from the spread, chi2/dof of the spread against the errors, its 95 % range."""
    values, errors = np.asarray(values), np.asarray(errors)
    n = len(values)
    if n < 2:
        raise ValueError("--replicates needs at least two tables")
    mean = values.mean()
    spread = values.std(ddof=1) / np.sqrt(n)
    chi2 = float(np.sum((values - mean) ** 2 / errors**2) / (n - 1)) if np.all(errors > 0) \
        else float("nan")
    try:
        from scipy.stats import chi2 as distribution
        low, high = (distribution.ppf(q, n - 1) / (n - 1) for q in (0.025, 0.975))
    except ImportError:  # the range is a guide; the numbers above stand without it
        low = high = float("nan")
    return mean, spread, chi2, low, high


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
    parser.add_argument("--column", default="P_polar",
                        help="the column --blocking and --replicates read (default P_polar)")
    args = parser.parse_args()
    if args.blocking and args.replicates:
        sys.exit("block_means.py: --blocking and --replicates are two different readings; "
                 "give one")
    seeds = []
    if args.end is not None and args.end <= args.start:
        sys.exit(f"block_means.py: --to {args.end:g} s must be after --from {args.start:g} s")
    for path in args.tables:
        try:
            table = np.genfromtxt(path, delimiter=",", names=True, skip_header=1)
        except (OSError, ValueError) as e:
            sys.exit(f"block_means.py: {path}: {e}")
        if not {"t_from", "t_to"} <= set(table.dtype.names or ()):
            sys.exit(f"block_means.py: {path}: no t_from, t_to columns (a reproduction_series.py "
                     "table?)")
        first, last = float(table["t_from"].min()), float(table["t_to"].max())
        end = args.end if args.end is not None else last
        # A window past the table would average what there is under the window's name: a run
        # not yet at the window's end would be quoted for a span it has not reached.
        if args.start < first - 1e-9 or end > last + 1e-9:
            sys.exit(f"block_means.py: {path}: the window {args.start:g}–{end:g} s is not within "
                     f"the table's {first:g}–{last:g} s")
        if args.blocking:
            try:
                rows, plateau = blocking(table, args.start, end, args.column)
            except ValueError as e:
                sys.exit(f"block_means.py: {path}: {e}")
            print_blocking(path, args.start, end, args.column, rows, plateau)
            continue
        try:
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
        mean, spread, chi2, low, high = replicates([s[1] for s in seeds], [s[2] for s in seeds])
    except ValueError as e:
        sys.exit(f"block_means.py: {e}")
    window = (f"{args.start:g}–{args.end:g} s" if args.end is not None
              else f"from {args.start:g} s")
    print(f"{args.column}, {window}, blocks of {args.block:g} s, {len(seeds)} replicates")
    for path, value, error, blocks in seeds:
        print(f"  {value:10.4g} ± {error:.2g}  ({blocks} blocks)  {path}")
    verdict = ("no chi2: a seed's error is zero" if not np.isfinite(chi2) else
               "no range without scipy" if not np.isfinite(high) else
               "the errors are too small" if chi2 > high else
               "the errors are too large" if chi2 < low else "the errors hold")
    print(f"  mean {mean:.4g} ± {spread:.2g} (from the spread); chi2/dof {chi2:.3g} "
          f"(95 % range {low:.2g}–{high:.2g}): {verdict}")


def print_blocking(path, start, end, column, rows, plateau):
    print(f"{path}: {column}, {start:g}–{end:g} s, error against block length")
    for i, (length, error, uncertainty, blocks) in enumerate(rows):
        mark = "  <- plateau" if i == plateau else ""
        print(f"  {length:8.4g} s  {error:.3g} ± {uncertainty:.2g}  ({blocks} blocks){mark}")
    if plateau is None:
        largest = max(rows, key=lambda row: row[1])
        print(f"  no plateau: the window is too short for an honest error; it is at least "
              f"{largest[1]:.2g} (blocks of {largest[0]:g} s)")
    else:
        print(f"  error {rows[plateau][1]:.2g} (blocks of {rows[plateau][0]:g} s)")


if __name__ == "__main__":
    main()
