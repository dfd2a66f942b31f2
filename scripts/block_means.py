#!/usr/bin/python3
"""Means and block errors of a series table over a time window: the numbers docs/reproduction.md
quotes for runs too short for the automatic steady window.

    scripts/block_means.py SERIES.csv... --from T0 [--to T1] [--block SECONDS]

SERIES.csv is a table of scripts/reproduction_series.py (time bins of P_polar, S_medium, Sigma,
N_m, ...). The window [T0, T1) (s; T1 default: the table's end; bins by their middles) is cut
into blocks of --block seconds (default 15; a shorter remainder at the end is left out); each
column's mean is the mean of the block means and its error their standard deviation over
√(blocks − 1), the error of a mean of independent blocks (blocks longer
than the correlation time of P, a few seconds here). Prints one line per table and column.
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


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("tables", nargs="+")
    parser.add_argument("--from", dest="start", type=float, required=True, help="s")
    parser.add_argument("--to", dest="end", type=float, help="s (default: the table's end)")
    parser.add_argument("--block", type=float, default=15.0, help="s (default 15)")
    args = parser.parse_args()
    for path in args.tables:
        try:
            table = np.genfromtxt(path, delimiter=",", names=True, skip_header=1)
        except (OSError, ValueError) as e:
            sys.exit(f"block_means.py: {path}: {e}")
        if not {"t_from", "t_to"} <= set(table.dtype.names or ()):
            sys.exit(f"block_means.py: {path}: no t_from, t_to columns (a reproduction_series.py "
                     "table?)")
        end = args.end if args.end is not None else float(table["t_to"].max())
        try:
            result = block_means(table, args.start, end, args.block)
        except ValueError as e:
            sys.exit(f"block_means.py: {path}: {e}")
        print(f"{path}: {args.start:g}–{end:g} s, blocks of {args.block:g} s")
        for column, (mean, error, blocks) in result.items():
            print(f"  {column:20s} {mean:10.4g} ± {error:.2g}  ({blocks} blocks)")


if __name__ == "__main__":
    main()
