#!/usr/bin/python3
"""The medium's drift against the polar rods' order: the End Matter's reading of Fig. 5b.

    scripts/medium_drift.py DIR... --from T0 [--to T1] [--block SECONDS] [--blocks-out FILE]

Each DIR is the output of `rodsea analyze RUN --observables order,drift --out DIR`: its
drift.csv (the medium's mean in-plane velocity along the polar rods' mean heading every frame,
v_medium_along_polar, mm/s) and order_parameters.csv (the polar rods' |P| every frame). The
paper's mean field (docs/meanfield.md) slaves the medium's mean velocity to the rods' order,
v = (α/Γ_f)(P − (ρ/Γ_f) dP/dt); along P's own direction that is v_par = (α/Γ_f)|P| once the
medium follows within a frame. So, over the window [T0, T1) (s; frames by their times), cut into
blocks of --block seconds (default 10; a shorter remainder at the end is left out), it prints
per table:
- the means of |P| and v_par (mm/s) with block errors (the blocks' standard deviation over
  √(blocks − 1));
- α/Γ_f (mm/s per unit P), the slope through the origin of the block means,
  Σ v_b P_b / Σ P_b², with its jackknife error over the blocks; and the block means' correlation.
With several tables (seeds of one state point) it adds one line for all their blocks together,
and chi2/dof of the tables' slopes about it. --blocks-out writes the block means behind those
lines (one row per block: the directory, t_from, t_to in s, |P|, v_par in mm/s) as a CSV table,
the small table a figure is drawn from once the trajectories are gone.

The slope's error is a block error of the residuals v_par − (α/Γ_f)|P|, not of P itself: P is
correlated over tens of seconds, but the residual is the medium's agitation averaged over its
rods, which forgets itself within the medium's own relaxation time. So blocks much shorter than
P's correlation time still give the slope an honest error where that time is short (blocks of 1
and 10 s then give the same error), and chi2/dof over seeds checks it.

A table without the columns, tables whose frames do not share their times, or a window outside
them or with fewer than three blocks are refused with a message and exit status 1, printing
nothing on stdout.
"""
import argparse
import csv
import math
import os
import sys

import numpy as np


def read_table(path, columns):
    """Reads a rodsea analysis CSV (comment lines first) into float arrays, refusing one that
    lacks a needed column or holds a non-number in it."""
    try:
        with open(path, newline="") as f:
            rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    except OSError as error:
        raise ValueError(f"{path}: {error.strerror}") from None
    if not rows:
        raise ValueError(f"{path}: no rows")
    table = {}
    for name in columns:
        if name not in rows[0]:
            raise ValueError(f"{path}: no column '{name}' (it has {', '.join(rows[0])})")
        try:
            table[name] = np.array([float(r[name]) for r in rows])
        except ValueError:
            raise ValueError(f"{path}: column '{name}' holds something that is not a number") \
                from None
        if not np.all(np.isfinite(table[name])):
            raise ValueError(f"{path}: column '{name}' holds a value that is not finite")
    return table


def read_run(directory, start, end):
    """The window's frames of one analysis directory: (time, |P|, v_par, the frames' interval in
    s); end None is the last frame's end."""
    order = read_table(os.path.join(directory, "order_parameters.csv"), ("time", "P_polar"))
    drift = read_table(os.path.join(directory, "drift.csv"), ("time", "v_medium_along_polar"))
    if len(order["time"]) != len(drift["time"]) or \
            not np.allclose(order["time"], drift["time"], rtol=0, atol=1e-6):
        raise ValueError(f"{directory}: order_parameters.csv and drift.csv do not share their "
                         "frames' times (made by different analyses?)")
    time = order["time"]
    interval = frame_interval(time, directory)
    last = time[-1] + interval
    end = last if end is None else end
    # A run continued from a checkpoint starts its frames one interval after the time it was
    # continued from, which a window may name.
    if start < time[0] - interval - 1e-9 or end > last + 1e-9:
        raise ValueError(f"{directory}: the window {start:g}–{end:g} s is not within its frames' "
                         f"{time[0]:g}–{time[-1]:g} s")
    keep = (time >= start - 1e-9) & (time < end - 1e-9)
    return time[keep], order["P_polar"][keep], drift["v_medium_along_polar"][keep], interval


def frame_interval(time, where):
    if len(time) < 2:
        raise ValueError(f"{where}: fewer than two frames")
    steps = np.diff(time)
    if np.any(steps <= 0) or not np.allclose(steps, steps[0], rtol=1e-3, atol=1e-9):
        raise ValueError(f"{where}: frames not evenly spaced in time")
    return float(steps[0])


def block_means(values, per_block):
    blocks = len(values) // per_block
    return values[:blocks * per_block].reshape(blocks, per_block).mean(axis=1)


def mean_and_error(blocks):
    return float(blocks.mean()), float(blocks.std(ddof=0) / math.sqrt(len(blocks) - 1))


def slope_through_origin(order, velocity):
    """α/Γ_f from block means and its jackknife error (leave one block out)."""
    cross, square = float(np.dot(order, velocity)), float(np.dot(order, order))
    slope = cross / square
    n = len(order)
    left_out = (cross - order * velocity) / (square - order ** 2)
    error = math.sqrt((n - 1) / n * float(np.sum((left_out - left_out.mean()) ** 2)))
    return slope, error


def describe(name, time, order, velocity, interval, block_s):
    per_block = int(round(block_s / interval))
    if per_block < 1 or len(time) // per_block < 3:
        raise ValueError(f"{name}: fewer than three blocks of {block_s:g} s in the window")
    p_blocks, v_blocks = block_means(order, per_block), block_means(velocity, per_block)
    starts = time[:len(p_blocks) * per_block:per_block]
    return {"name": name, "frames": len(time), "blocks": len(p_blocks), "t_from": starts,
            "t_to": starts + per_block * interval, "p_blocks": p_blocks, "v_blocks": v_blocks}


def write_blocks(path, rows, args):
    """The block means, written whole or not at all."""
    with open(path + ".tmp", "w", newline="") as f:
        f.write(f"# scripts/medium_drift.py --from {args.start:g}"
                + (f" --to {args.end:g}" if args.end is not None else "")
                + f" --block {args.block:g}: block means of the polar rods' |P| and the medium's "
                "mean velocity along their mean heading; units: t_from [s] t_to [s] P_polar [1] "
                "v_medium_along_polar [mm/s]\n")
        writer = csv.writer(f, lineterminator="\n")
        writer.writerow(["run", "t_from", "t_to", "P_polar", "v_medium_along_polar"])
        for row in rows:
            for values in zip(row["t_from"], row["t_to"], row["p_blocks"], row["v_blocks"]):
                writer.writerow([row["name"], *(f"{x:.10g}" for x in values)])
    os.replace(path + ".tmp", path)


def line(row):
    p, p_err = mean_and_error(row["p_blocks"])
    v, v_err = mean_and_error(row["v_blocks"])
    slope, slope_err = slope_through_origin(row["p_blocks"], row["v_blocks"])
    r = float(np.corrcoef(row["p_blocks"], row["v_blocks"])[0, 1]) \
        if np.std(row["p_blocks"]) > 0 and np.std(row["v_blocks"]) > 0 else float("nan")
    text = (f"{row['name']}: {row['frames']} frames, {row['blocks']} blocks; |P| = {p:.3f} ± "
            f"{p_err:.3f}; v_par = {v:.3f} ± {v_err:.3f} mm/s; alpha/Gamma_f = {slope:.3f} ± "
            f"{slope_err:.3f} mm/s; r(blocks) = {r:.2f}")
    return text, slope, slope_err


def main(argv):
    parser = argparse.ArgumentParser(
        description="The medium's drift along the polar rods' heading against their order "
                    "(alpha/Gamma_f, mm/s) from `rodsea analyze --observables order,drift` "
                    "directories.")
    parser.add_argument("directories", nargs="+", metavar="DIR")
    parser.add_argument("--from", dest="start", type=float, required=True, help="window start, s")
    parser.add_argument("--to", dest="end", type=float, default=None,
                        help="window end, s (default: each table's last frame)")
    parser.add_argument("--block", type=float, default=10.0, help="block length, s (default 10)")
    parser.add_argument("--blocks-out", metavar="FILE", default=None,
                        help="write the block means to this CSV table")
    args = parser.parse_args(argv)
    try:
        if args.block <= 0:
            raise ValueError(f"--block must be positive (got {args.block:g} s)")
        if args.end is not None and args.end <= args.start:
            raise ValueError(f"--to ({args.end:g} s) must come after --from ({args.start:g} s)")
        rows = []
        for directory in args.directories:
            rows.append(describe(directory, *read_run(directory, args.start, args.end),
                                 args.block))
    except ValueError as error:
        print(f"medium_drift: {error}", file=sys.stderr)
        return 1
    out = []
    slopes = []
    for row in rows:
        text, slope, slope_err = line(row)
        out.append(text)
        slopes.append((slope, slope_err))
    if len(rows) > 1:
        pooled = {"name": f"all {len(rows)}", "frames": sum(r["frames"] for r in rows),
                  "blocks": sum(r["blocks"] for r in rows),
                  "p_blocks": np.concatenate([r["p_blocks"] for r in rows]),
                  "v_blocks": np.concatenate([r["v_blocks"] for r in rows])}
        text, slope, _ = line(pooled)
        chi2 = sum((s - slope) ** 2 / e ** 2 for s, e in slopes if e > 0) / (len(slopes) - 1)
        out.append(f"{text}; chi2/dof of the tables' slopes {chi2:.2f}")
    if args.blocks_out is not None:
        try:
            write_blocks(args.blocks_out, rows, args)
        except OSError as error:
            print(f"medium_drift: {args.blocks_out}: {error.strerror}", file=sys.stderr)
            return 1
    print("# window from {:g} s{}; blocks of {:g} s; v_par: the medium's mean velocity along the "
          "polar rods' mean heading".format(
              args.start, f" to {args.end:g} s" if args.end is not None else "", args.block))
    print("\n".join(out))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
