#!/usr/bin/python3
"""Are the block errors of P honest? The table of docs/reproduction.md's "How far the error bars
hold": for every state point run from several seeds, chi2/dof of the seeds' spread against each
seed's own block error (scripts/block_means.py --replicates), with 15 s and 30 s blocks, the
95 % range that honest errors give, and the points pooled by window length.

    scripts/error_bar_check.py [--root REPOSITORY]

Prints a Markdown table: chi2/dof, its 95 % range for honest errors and p, the chance that
honest errors give at least the chi2/dof seen; for a pool, also the factor by which the errors
would have to grow for its chi2/dof to be honest errors' mean. A pooled chi2/dof is
sum(chi2_g dof_g) / sum(dof_g) over its groups; its range is drawn the same way from honest
seeds (block_means.honest_chi2). A window cut into fewer than 4 blocks gets a dash: its errors
would rest on one to three degrees of freedom each. A seed whose table ends before the
window's end (a run still going) is left out of its point and counted beside its seeds.
"""
import argparse
import glob
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from block_means import block_means, chi2_per_dof, honest_chi2, read_table  # noqa: E402
from reproduction_rows import DATA, ROW38, ROW63  # noqa: E402

ROW = (60.0, 180.0)
FIG1F = (30.0, 90.0)


# (label, pool, window, [series tables of the seeds]). The first row's seeds are
# reproduction_rows.py's, which the figures draw; a φ_a with one seed has no spread to check.
# The medium masses 0.1 and 0.15 are shown but pooled with nothing: their seeds end in different
# states (ordered or not), so their spread is a bimodality, not noise.
GROUPS = [
    (f"Fig. 1c, 38 mm, φ_a = {phi}", "120 s", ROW, seeds)
    for phi, seeds in ROW38.items() if len(seeds) > 1
] + [
    # 0.50 is not pooled: its seeds 1-3 each hold one state over the whole window (flocks and lone
    # rods heading together, apart, or partly), seed 4 moves between those states for 50 s at a
    # time and seed 5 holds one for 100 s: a spread between states that no block error of one seed
    # can see.
    # 0.05 is pooled although its seeds disagree as much (chi2/dof 23 from six): none holds one
    # state over the whole window (they order and disorder in spells of 40-100 s), and the point
    # was pooled before its third seed came.
    (f"Fig. 1c, 63 mm, φ_a = {phi:.2f}" + (" (not pooled)" if phi == 0.50 else ""),
     None if phi == 0.50 else "120 s", ROW, seeds)
    for phi, seeds in ROW63.items() if len(seeds) > 1
] + [
    ("38 mm, φ_a = 0.05 at dt 2.5 µs, seeds 3–7", "120 s", ROW,
     "dilute-order/medium-mass-seeds/medium.mass=0.2.seed*.series.csv"),
    ("the same with medium mass 0.15, seeds 1–8", None, ROW,
     "dilute-order/medium-mass-38mm-0.15*.series.csv "
     "dilute-order/medium-mass-seeds/medium.mass=0.15.seed*.series.csv"),
    ("the same with medium mass 0.1, seeds 1–5", None, ROW,
     "dilute-order/medium-mass-38mm-0.1.series.csv "
     "dilute-order/medium-mass-38mm-0.1.seed2.series.csv "
     "dilute-order/medium-mass-seeds/medium.mass=0.1.seed*.series.csv"),
] + [
    (f"Fig. 1f, 38 mm, φ_a = 0.50, D_r = {d}", "60 s", FIG1F,
     [f"{DATA}/finite-size/fig1c-phi_a0.50-scale0.15.series.csv" if d == "0" else
      f"{DATA}/fig1f-38mm/rotational_diffusion={d}.series.csv",
      f"{DATA}/fig1f-38mm/rotational_diffusion={d}.seed2.series.csv"])
    for d in ("0", "0.026", "0.23", "1.21", "1.87")
]
BLOCKS = (15.0, 30.0)


def tables_of(root, spec):
    if isinstance(spec, list):
        return [os.path.join(root, path) for path in spec]
    return sorted(path for pattern in spec.split()
                  for path in glob.glob(os.path.join(root, DATA, pattern)))


def finished_seeds(paths, window):
    """The tables that reach the window's end, and how many do not: a run still going (its
    checkpoint kept, to be run on) is drawn by the figures over what it has, but its spread
    against finished seeds would compare different windows."""
    finished = [path for path in paths
                if float(np.nanmax(read_table(path)["t_to"])) >= window[1] - 1e-9]
    return finished, len(paths) - len(finished)


def group_seeds(paths, window, block):
    """(values, errors, blocks) of P over `window` in each seed, or None when a seed's window
    holds fewer than 4 blocks."""
    values, errors, counts = [], [], []
    for path in paths:
        mean, error, count = block_means(read_table(path), *window, block)["P_polar"]
        if count < 4:
            return None
        values.append(mean)
        errors.append(error)
        counts.append(count)
    return np.array(values), np.array(errors), counts


def cell(chi2, honest, factor=False):
    """chi2/dof, the range of honest errors, and the chance p that honest errors give at least
    this much; with `factor`, also by how much the errors would have to grow for chi2/dof to
    be honest errors' mean."""
    low, high = np.percentile(honest, [2.5, 97.5])
    p = np.mean(honest >= chi2)
    p = f"p = {p:.2g}" if p > 0 else f"p < {1 / len(honest):.2g}"
    text = f"{chi2:.2g} ({low:.2g}–{high:.2g}; {p})"
    if factor:
        text += f", errors × {np.sqrt(chi2 / honest.mean()):.2g}"
    return text


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", default=os.path.dirname(os.path.dirname(
        os.path.abspath(__file__))))
    args = parser.parse_args()
    pools = {}
    # Printed only once every table has been read, so that a bad one leaves no half table.
    out = ["| point (P, window) | seeds | " + " | ".join(
        f"chi2/dof, {b:g} s blocks (95 % range if honest; p)" for b in BLOCKS) + " |",
        "|---|---|" + "---|" * len(BLOCKS)]
    for index, (label, pool, window, spec) in enumerate(GROUPS):
        try:
            paths, running = finished_seeds(tables_of(args.root, spec), window)
        except ValueError as e:
            sys.exit(f"error_bar_check.py: {label}: {e}")
        if len(paths) < 2:
            sys.exit(f"error_bar_check.py: {label}: fewer than two seeds' tables past "
                     f"{window[1]:g} s ({spec})")
        cells = []
        for block in BLOCKS:
            try:
                seeds = group_seeds(paths, window, block)
            except (KeyError, ValueError) as e:
                sys.exit(f"error_bar_check.py: {label}: {e}")
            if seeds is None:
                cells.append("— (under 4 blocks)")
                continue
            values, errors, counts = seeds
            # Each group draws its own honest seeds, so that a pool sums independent draws.
            honest = honest_chi2(errors, counts, seed=1000 + 10 * index + int(block))
            chi2 = float(chi2_per_dof(values, errors))
            cells.append(cell(chi2, honest))
            if pool:
                dof = len(values) - 1
                total = pools.setdefault((pool, block), [0.0, 0, 0.0])
                total[0] += chi2 * dof
                total[1] += dof
                total[2] = total[2] + honest * dof
        seeds_cell = f"{len(paths)}" + (f" (+{running} not yet at {window[1]:g} s)"
                                         if running else "")
        out.append(f"| {label}, {window[0]:g}–{window[1]:g} s | {seeds_cell} | "
                   + " | ".join(cells) + " |")
    for pool in dict.fromkeys(p for p, _ in pools):
        cells = []
        for block in BLOCKS:
            if (pool, block) not in pools:
                cells.append("—")
                continue
            chi2, dof, honest = pools[(pool, block)]
            cells.append("**" + cell(chi2 / dof, honest / dof, factor=True) + "**")
        dofs = {pools[k][1] for k in pools if k[0] == pool}
        out.append(f"| **{pool} windows, pooled** | {'/'.join(map(str, sorted(dofs)))} dof | "
                   + " | ".join(cells) + " |")
    print("\n".join(out))


if __name__ == "__main__":
    main()
