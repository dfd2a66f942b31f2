#!/usr/bin/python3
"""Is the polar rods' pair structure elongated along their motion or across it? g(r,θ) of
`rodsea analyze --observables corotating` averaged over sectors around the reference rod's axis,
shell by shell: the flock shape the paper reads off g(r,θ)'s 70 % contour (σ_f), in a form that
still answers when that contour does not close (flocks of a few rods, whose contact peak is the
maximum of g; docs/reproduction.md, Fig. 4a).

    scripts/pair_sectors.py ANALYSIS... [--shells R0,R1,...] [--half-width DEG]

ANALYSIS is a run's analysis directory (RUN_DIR/analysis, or RUN_DIR), its analysis.json or
its analysis.h5, read and checked as `rodsea plot` reads them (scripts/rodsea_plots). For
each shell [R_i, R_i+1) (mm; default: steps of half the polar rod's length, read from the
analysis, up to the map's range) it prints, as CSV on stdout: the mean g over the bins within
--half-width degrees (default 30) of the axis, ahead (θ = 0, the way the rods move) and behind
(θ = π) together and apart, and across it (θ = ±π/2), each with the standard error of the bins'
scatter (bins of one map are averaged over the same frames, so this error is a lower bound).
g = 1 is no correlation: along > across beyond contact is a longitudinal flock, across > along
a transverse one.

Exit codes: 0 done; 1 a Python module missing; 2 bad input; 74 a file that cannot be read
(nothing is printed unless every input was read).
"""
import argparse
import os
import sys

sys.dont_write_bytecode = True  # keep the source tree clean of __pycache__

import numpy as np

from rodsea_plots.common import PlotError, finite
from rodsea_plots.inputs import RunInput, classify
from rodsea_plots.run_figures import Analysis, read_map


def load(path):
    """(g, r_edges, theta_edges, polar rod length or None) of one run's analysis."""
    if path.endswith(".h5"):  # an analysis.h5 stands for the analysis.json beside it
        path = os.path.join(os.path.dirname(path) or ".", "analysis.json")
    run = classify(path)
    if not isinstance(run, RunInput):
        raise PlotError(f"{path}: not a run's analysis (a table or campaign has no g(r,θ) map)")
    analysis = Analysis(run.analysis_dir)
    if analysis.observable("corotating") is None:
        raise PlotError(f"{analysis.path}: no g(r,θ) map "
                        "(run `rodsea analyze RUN_DIR --observables corotating`)")
    g, r_edges, theta_edges = read_map(analysis, "g_r_theta")
    lengths = [s.get("length_mm") for s in analysis.polar]
    length = lengths[0] if lengths and finite(lengths[0]) and lengths[0] > 0 else None
    return g, r_edges, theta_edges, length


def sector_masks(theta_edges, half_width):
    """Bins whose centre lies within half_width (rad) of ahead, behind, and either side."""
    centre = 0.5 * (theta_edges[:-1] + theta_edges[1:])
    def near(direction):
        return np.abs(np.angle(np.exp(1j * (centre - direction)))) <= half_width
    return {"ahead": near(0.0), "behind": near(np.pi),
            "along": near(0.0) | near(np.pi), "across": near(np.pi / 2) | near(-np.pi / 2)}


def shell_means(g, r_edges, theta_edges, shells, half_width):
    """[(r0, r1, {sector: (mean, error, bins)})] over each shell's bins (by their centres)."""
    r_centre = 0.5 * (r_edges[:-1] + r_edges[1:])
    masks = sector_masks(theta_edges, half_width)
    rows = []
    for r0, r1 in zip(shells[:-1], shells[1:]):
        in_shell = (r_centre >= r0) & (r_centre < r1)
        cells = {}
        for name, in_sector in masks.items():
            values = g[np.ix_(in_shell, in_sector)].ravel()
            values = values[np.isfinite(values)]
            if len(values) >= 2:
                cells[name] = (values.mean(), values.std(ddof=1) / np.sqrt(len(values)),
                               len(values))
            else:
                cells[name] = (np.nan, np.nan, len(values))
        rows.append((r0, r1, cells))
    return rows


def parse(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("analyses", nargs="+", metavar="ANALYSIS")
    p.add_argument("--shells", help="shell edges in mm, comma-separated and increasing")
    p.add_argument("--half-width", type=float, default=30.0,
                   help="half-width of each sector in degrees, in (0, 45]; default 30")
    a = p.parse_args(argv)
    if not 0 < a.half_width <= 45:
        p.error(f"--half-width = {a.half_width}: allowed (0, 45] degrees (wider sectors overlap)")
    if a.shells is not None:
        try:
            a.shells = [float(x) for x in a.shells.split(",")]
        except ValueError:
            p.error(f"--shells = {a.shells!r}: numbers in mm, comma-separated")
        if len(a.shells) < 2 or any(b <= c for c, b in zip(a.shells, a.shells[1:])) \
                or a.shells[0] < 0:
            p.error(f"--shells = {a.shells}: at least two increasing edges from 0 mm up")
    return a


def measure(path, args):
    g, r_edges, theta_edges, length = load(path)
    shells = args.shells
    if shells is None:
        if length is None:
            raise PlotError(f"{path}: no polar rod length in its analysis.json; give --shells")
        shells = list(np.arange(0.0, r_edges[-1] + 1e-9, length / 2))
    if shells[-1] > r_edges[-1] + 1e-9:
        raise PlotError(f"{path}: --shells reach {shells[-1]} mm, the map only {r_edges[-1]:g} mm")
    return shell_means(g, r_edges, theta_edges, shells, np.radians(args.half_width))


def main(argv):
    args = parse(argv)
    inputs = []
    for path in args.analyses:  # every input is read before anything is printed
        try:
            inputs.append((path, measure(path, args)))
        except PlotError as e:
            sys.stderr.write(f"pair_sectors.py: {e}\n")
            return e.code
    names = ("along", "ahead", "behind", "across")
    print("analysis,r_from_mm,r_to_mm," + ",".join(f"g_{n},g_{n}_error" for n in names))
    for path, rows in inputs:
        for r0, r1, cells in rows:
            numbers = ",".join(f"{cells[n][0]:.4g},{cells[n][1]:.2g}" for n in names)
            print(f"{path},{r0:.4g},{r1:.4g},{numbers}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
