#!/usr/bin/python3
"""Is the polar rods' pair structure elongated along their motion or across it? g(r,θ) of
`rodsea analyze --observables corotating` averaged over sectors around the reference rod's axis,
shell by shell: the flock shape the paper reads off g(r,θ)'s 70 % contour (σ_f), in a form that
still answers when that contour does not close (flocks of a few rods, whose contact peak is the
maximum of g; docs/reproduction.md, Fig. 4a).

    scripts/pair_sectors.py ANALYSIS... [--shells R0,R1,...] [--half-width DEG]

ANALYSIS is a run's analysis directory (RUN_DIR/analysis, or RUN_DIR) or its analysis.h5. For
each shell [R_i, R_i+1) (mm; default: steps of half the polar rod's length, read from the
analysis, up to the map's range) it prints, as CSV on stdout: the mean g over the bins within
--half-width degrees (default 30) of the axis, ahead (θ = 0, the way the rods move) and behind
(θ = π) together and apart, and across it (θ = ±π/2), each with the standard error of the bins'
scatter (bins of one map are averaged over the same frames, so this error is a lower bound).
g = 1 is no correlation: along > across beyond contact is a longitudinal flock, across > along
a transverse one.

Exit codes: 0 done; 1 h5py missing; 2 bad input (nothing printed).
"""
import argparse
import json
import os
import sys

sys.dont_write_bytecode = True  # keep the source tree clean of __pycache__

import numpy as np

EXIT_BAD_INPUT = 2


def fail(message):
    sys.stderr.write(f"pair_sectors.py: {message}\n")
    sys.exit(EXIT_BAD_INPUT)


def locate(path):
    """(analysis.h5, analysis.json or None) of a run's analysis, however the user names it."""
    if os.path.isdir(path):
        inner = os.path.join(path, "analysis")
        directory = inner if os.path.isfile(os.path.join(inner, "analysis.h5")) else path
        h5 = os.path.join(directory, "analysis.h5")
    else:
        h5, directory = path, os.path.dirname(path) or "."
    if not os.path.isfile(h5):
        fail(f"{path}: no analysis.h5 (run `rodsea analyze RUN_DIR --observables corotating`)")
    js = os.path.join(directory, "analysis.json")
    return h5, js if os.path.isfile(js) else None


def read_map(h5_path):
    try:
        import h5py
    except ImportError:
        sys.stderr.write("pair_sectors.py: needs h5py: install it with ./scripts/install-deps.sh "
                         "(Debian's python3-h5py)\n")
        sys.exit(1)
    with h5py.File(h5_path, "r") as f:
        if "maps/g_r_theta/value" not in f:
            fail(f"{h5_path}: no g(r,θ) map (analyse with --observables corotating)")
        group = f["maps/g_r_theta"]
        g = np.asarray(group["value"], dtype=float)
        r_edges = np.asarray(group["r_edges"], dtype=float)
        theta_edges = np.asarray(group["theta_edges"], dtype=float)
    if g.shape != (len(r_edges) - 1, len(theta_edges) - 1):
        fail(f"{h5_path}: g(r,θ) is {g.shape}, its edges say "
             f"{(len(r_edges) - 1, len(theta_edges) - 1)}")
    return g, r_edges, theta_edges


def polar_length(json_path):
    if json_path is None:
        return None
    with open(json_path) as f:
        species = json.load(f).get("parameters", {}).get("species", [])
    lengths = [s.get("length_mm") for s in species if s.get("kind") == "polar_rod"]
    return float(lengths[0]) if lengths and lengths[0] else None


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


def main(argv):
    args = parse(argv)
    inputs = []
    for path in args.analyses:  # every input is read before anything is printed
        h5, js = locate(path)
        g, r_edges, theta_edges = read_map(h5)
        shells = args.shells
        if shells is None:
            length = polar_length(js)
            if length is None:
                fail(f"{path}: no polar rod length in analysis.json; give --shells")
            shells = list(np.arange(0.0, r_edges[-1] + 1e-9, length / 2))
        if shells[-1] > r_edges[-1] + 1e-9:
            fail(f"{path}: --shells reach {shells[-1]} mm, the map only {r_edges[-1]:g} mm")
        inputs.append((path, shell_means(g, r_edges, theta_edges, shells,
                                         np.radians(args.half_width))))
    names = ("along", "ahead", "behind", "across")
    print("analysis,r_from_mm,r_to_mm," + ",".join(f"g_{n},g_{n}_error" for n in names))
    for path, rows in inputs:
        for r0, r1, cells in rows:
            numbers = ",".join(f"{cells[n][0]:.4g},{cells[n][1]:.2g}" for n in names)
            print(f"{path},{r0:.4g},{r1:.4g},{numbers}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
