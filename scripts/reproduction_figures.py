#!/usr/bin/python3
"""The figures of docs/reproduction.md, drawn from the tables in data/reproduction/ alone.

    scripts/reproduction_figures.py [--out DIR] [--only NAME,...] [--dump]

Every figure is listed in FIGURES with the tables it reads (paths relative to the repository);
each is written as DIR/reproduction-<name>.png (default DIR: docs/images). --dump also writes
DIR/reproduction-<name>.json: every curve drawn, as {label: {"x": [...], "y": [...],
"err": [...]}}, so that a test can check the figure against its table. A missing or malformed
table is named and nothing is drawn (exit 2).
"""
import argparse
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from reproduction_rows import DATA, FIG1C_SERIES, ROW38, ROW63  # noqa: E402
from medium_drift import slope_through_origin  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# Fig. 1c / 3a, the reproduction's first row: the campaign tables, each one curve (label, file).
FIG1C_POINTS = [
    ("10 s, 63 mm box", f"{DATA}/fig1c-phi_p0.05-small.points.csv"),
    ("60 s, 63 mm box", f"{DATA}/fig1c-phi_p0.05-long.points.csv"),
]
# Item 3, finite size: the ordered (φ_a = 0.05) and the disordered (0.20) point in up to three
# boxes each, and the dense end (0.65, 0.80) in two: {φ_a: [(label, series table, polar rods)]};
# a box not run yet is left out.
FINITE_SIZE = {
    0.05: [
        ("38 mm box", f"{DATA}/finite-size/fig1c-phi_a0.05-scale0.15.series.csv", 18),
        ("63 mm box", f"{FIG1C_SERIES}/medium.area_fraction=0.05_extended_to_180_s.series.csv", 50),
        ("88 mm box", f"{DATA}/finite-size/fig1c-phi_a0.05-scale0.35_extended_to_360_s.series.csv",
         98),
    ],
    0.20: [
        ("38 mm box", f"{DATA}/finite-size/fig1c-phi_a0.20-scale0.15.series.csv", 18),
        ("63 mm box", f"{FIG1C_SERIES}/medium.area_fraction=0.2_extended_to_180_s.series.csv", 50),
        ("88 mm box", f"{DATA}/finite-size/fig1c-phi_a0.20-scale0.35.series.csv", 98),
    ],
} | {
    phi: [("38 mm box", f"{DATA}/fig1c-dense-38mm/medium.area_fraction={phi:g}.series.csv", 18),
          ("63 mm box", f"{DATA}/fig1c-dense-63mm/medium.area_fraction={phi:g}.series.csv", 50)]
    for phi in (0.65, 0.80)
}

# The first row in the 38 mm box, 180 s per run: ROW38 of reproduction_rows.py. Each run's P, Σ
# and N_m over ROW38_WINDOW, errors from blocks of ROW38_BLOCK seconds. A seed not run yet is left
# out.
ROW38_WINDOW = (60.0, 180.0)
ROW38_BLOCK = 15.0
# The same row in the 63 mm box: ROW63 of reproduction_rows.py. A run not yet at ROW38_WINDOW's
# end is drawn over the part of it that its table covers (row63_window), as an open marker, once
# that holds two blocks; the dashed line joins the means over each φ_a's seeds that have the
# whole window, since a mean over 15 s would weigh as much as one over 120 s.
# The dense end's C(t) is taken over the last 150 s of its 270 s, past the growth of the flocks.
DENSE38_CT_WINDOW = (120.0, 270.0)
# SI S3(a) in the same box: the polar rods' C(t) at each φ_a, from `rodsea analyze --observables
# autocorrelation` over each run's window (φ_a, table, window in s): 0.50's seed 2 over 60–180 s,
# as the 63 mm box's. A φ_a not run yet is left out.
# The 38 mm box's third seed of 0.80, and the 63 mm box's 0.35, 0.65 and 0.80 (two seeds each)
# and 0.50 (five seeds) beside them, over 60–180 s (their whole runs past the first minute).
CT = [(0.50, "38 mm", f"{DATA}/finite-size/replicates38/medium.area_fraction=0.5.seed2"
       ".orientation_autocorrelation.csv", (60.0, 180.0))] + [
    (phi, "38 mm",
     f"{DATA}/fig1c-dense-38mm/medium.area_fraction={phi:g}.orientation_autocorrelation.csv",
     DENSE38_CT_WINDOW) for phi in (0.65, 0.80)] + [
    (0.35, "63 mm",
     f"{DATA}/fig1c-mid-63mm/medium.area_fraction=0.35.orientation_autocorrelation.csv",
     (60.0, 180.0)),
    (0.50, "63 mm",
     f"{DATA}/fig1c-mid-63mm/medium.area_fraction=0.5.orientation_autocorrelation.csv",
     (60.0, 180.0))] + [
    (phi, "63 mm",
     f"{DATA}/fig1c-dense-63mm/medium.area_fraction={phi:g}.orientation_autocorrelation.csv",
     (60.0, 180.0)) for phi in (0.65, 0.80)] + [
    (phi, "63 mm, seed 2",
     f"{DATA}/fig1c-mid-63mm/medium.area_fraction={phi:g}.seed2.orientation_autocorrelation.csv",
     (60.0, 180.0)) for phi in (0.35, 0.50)] + [
    (phi, "63 mm, seed 2",
     f"{DATA}/fig1c-dense-63mm/medium.area_fraction={phi:g}.seed2.orientation_autocorrelation.csv",
     (60.0, 180.0)) for phi in (0.65, 0.80)] + [
    (0.50, "63 mm, seed 3",
     f"{DATA}/fig1c-mid-63mm/medium.area_fraction=0.5.seed3.orientation_autocorrelation.csv",
     (60.0, 180.0)),
    (0.50, "63 mm, seed 4",
     f"{DATA}/fig1c-mid-63mm/medium.area_fraction=0.5.seed4.orientation_autocorrelation.csv",
     (60.0, 180.0)),
    (0.50, "63 mm, seed 5",
     f"{DATA}/fig1c-mid-63mm/medium.area_fraction=0.5.seed5.orientation_autocorrelation.csv",
     (60.0, 180.0)),
    (0.80, "38 mm, seed 3",
     f"{DATA}/fig1c-dense-38mm/medium.area_fraction=0.8.seed3.orientation_autocorrelation.csv",
     (60.0, 180.0))]

# The dense end's whole runs, for the length of their transient: (φ_a, series table, polar rods);
# DENSE38_BIN-second means of each quantity drawn. A φ_a not run yet is left out.
DENSE38 = [(phi, f"{DATA}/fig1c-dense-38mm/medium.area_fraction={phi:g}.series.csv", 18)
           for phi in (0.65, 0.80)]
DENSE38_BIN = 5

# Fig. 1f in the 38 mm box, φ_a = 0.50: (D_r in rad²/s, series table); P over FIG1F_WINDOW from
# blocks of ROW38_BLOCK seconds. D_r = 0 is the first row's run. A D_r not run yet is left out.
FIG1F = [(0.0, f"{DATA}/finite-size/fig1c-phi_a0.50-scale0.15.series.csv")] + [
    (d, f"{DATA}/fig1f-38mm/rotational_diffusion={d}.series.csv")
    for d in (0.026, 0.23, 1.21, 1.87)]
FIG1F_WINDOW = (30.0, 90.0)
# Its second seed (fig1f-38mm-seed2.toml), D_r = 0 included.
FIG1F_SEED2 = [(float(d), f"{DATA}/fig1f-38mm/rotational_diffusion={d}.seed2.series.csv")
               for d in ("0", "0.026", "0.23", "1.21", "1.87")]

# SI S5 (Fig. S7), the bead medium in the 38 mm box: (φ_a, series table); P over BEADS_WINDOW from
# blocks of ROW38_BLOCK seconds. A φ_a not run yet is left out.
BEADS = [(phi, f"{DATA}/beads-38mm/medium.area_fraction={phi:g}.series.csv")
         for phi in (0.50, 0.60, 0.70, 0.75)]
BEADS_WINDOW = (30.0, 90.0)
# The same with beads of 0.033 polar-rod masses (aluminium against brass; docs/reproduction.md),
# 45 s runs: P over BEADS_LIGHT_WINDOW (the last 15 s: at φ_a ≥ 0.70 the rods order only after
# 20–35 s) from blocks of BEADS_LIGHT_BLOCK seconds.
BEADS_LIGHT = [(phi, f"{DATA}/beads-light-38mm/medium.area_fraction={phi:g}.series.csv")
               for phi in (0.50, 0.60, 0.70, 0.75)]
BEADS_LIGHT_WINDOW = (30.0, 45.0)
BEADS_LIGHT_BLOCK = 5.0

# Fig. 4a (inset) in the 38 mm box, φ_a = 0.75, D_r = 0.23 rad²/s: (σ, series table); P and the
# medium's S over FIG4A_WINDOW from blocks of FIG4A_BLOCK seconds. A σ not run yet is left out.
FIG4A = [(sigma, f"{DATA}/fig4a-38mm/medium.area_fraction=0.75,medium.aspect_ratio={sigma:g}"
          ".series.csv") for sigma in (1.25, 3.125, 5.625)]
FIG4A_WINDOW = (30.0, 60.0)
FIG4A_BLOCK = 5.0
# The same points in the 88 mm box (98 polar rods): (σ, series table, window of its P, seed's
# label suffix): their P(t) and S(t), and P over each one's own window; a run still in its
# transient (window None) is drawn in time only. σ = 1.25 levels only from 60 s (run to 88 s).
# Seed 2 of σ = 5.625 is drawn dash-dotted and as a diamond (FIG4A_88MM_STYLE: P(t), S(t),
# marker).
FIG4A_88MM = [(sigma, f"{DATA}/fig4a-88mm/medium.area_fraction=0.75,medium.aspect_ratio={sigma:g}"
               f"{'.seed2' if seed else ''}.series.csv", window, seed)
              for sigma, window, seed in ((1.25, (60.0, 85.0), ""), (3.125, (30.0, 60.0), ""),
                                          (5.625, (40.0, 60.0), ""),
                                          (5.625, (40.0, 60.0), ", seed 2"))]
FIG4A_88MM_STYLE = {"": ("--", ":", "o"), ", seed 2": ("-.", (0, (1, 3)), "D")}
# More runs of the 38 mm box, each a point over its own window and a P(t) trace: (σ, series
# table, window of its P, label). Second seeds at the text's D_r = 0.23 (σ = 5.625's ran 45 s),
# and σ = 1.25 and 3.125 with the caption's D_r = 0 (two seeds each). FIG4A_MORE_STYLE: label ->
# (marker, colour, filled, P(t) line style, shift along σ so as not to hide the 0.23 points).
FIG4A_MORE = [(sigma, f"{DATA}/fig4a-38mm/medium.area_fraction=0.75,medium.aspect_ratio={sigma:g}"
               f"{suffix}.series.csv", window, label)
              for sigma, suffix, window, label in (
                  (1.25, ".seed2", (30.0, 60.0), "seed 2"),
                  (3.125, ".seed2", (30.0, 60.0), "seed 2"),
                  (5.625, ".seed2", (25.0, 45.0), "seed 2"),
                  (1.25, ".Dr0", (30.0, 60.0), "D_r = 0"),
                  (1.25, ".Dr0.seed2", (30.0, 60.0), "D_r = 0, seed 2"),
                  (3.125, ".Dr0", (30.0, 60.0), "D_r = 0"),
                  (3.125, ".Dr0.seed2", (30.0, 60.0), "D_r = 0, seed 2"))]
FIG4A_MORE_STYLE = {"seed 2": ("D", "0.4", True, (0, (3, 1, 1, 1)), 0.0),
                    "D_r = 0": ("^", "C4", False, (0, (1, 1)), 0.12),
                    "D_r = 0, seed 2": ("v", "C4", False, (0, (1, 2.5)), 0.12)}

# What carries P (the flocks observable's P_independent and flock_alignment): one
# `rodsea analyze --observables order,flocks --from T` summary per run, (x, table), its window
# in its name (from T to the run's end: 180 s for the row's 0.05 and 0.20, 270 s for 0.65 and
# 0.80, 90 s for Fig. 1f's). Against φ_a, the 38 mm box's runs (0.35 and 0.50: their seed 2, the
# 0.50 one Fig. 1f's seed-2 D_r = 0 run on to 180 s); a larger box's, if run, beside them; against
# D_r, Fig. 1f's seed 2.
ALIGNMENT = f"{DATA}/flock-alignment"
ALIGNMENT_ROW = [
    (0.05, f"{ALIGNMENT}/fig1c-38mm-phi_a0.05-seed1-from60.summary.csv"),
    (0.20, f"{ALIGNMENT}/fig1c-38mm-phi_a0.20-seed1-from60.summary.csv"),
    (0.35, f"{ALIGNMENT}/fig1c-38mm-phi_a0.35-seed2-from60.summary.csv"),
    (0.50, f"{ALIGNMENT}/fig1c-38mm-phi_a0.50-seed2-from60.summary.csv"),
    (0.65, f"{ALIGNMENT}/fig1c-38mm-phi_a0.65-seed1-from180.summary.csv"),
    (0.80, f"{ALIGNMENT}/fig1c-38mm-phi_a0.80-seed1-from180.summary.csv"),
]
# The 38 mm box's third seeds of 0.35-0.80 over 60-180 s, drawn beside the line:
# how far one seed's split between flocks and alignment can differ from another's.
ALIGNMENT_ROW_SEED3 = [
    (0.35, f"{ALIGNMENT}/fig1c-38mm-phi_a0.35-seed3-from60.summary.csv"),
    (0.50, f"{ALIGNMENT}/fig1c-38mm-phi_a0.50-seed3-from60.summary.csv"),
    (0.65, f"{ALIGNMENT}/fig1c-38mm-phi_a0.65-seed3-from60.summary.csv"),
    (0.80, f"{ALIGNMENT}/fig1c-38mm-phi_a0.80-seed3-from60.summary.csv"),
]
ALIGNMENT_ROW_88MM = [
    (0.05, f"{ALIGNMENT}/fig1c-88mm-phi_a0.05-seed1-from60.summary.csv"),
]
# The row's middle and dense end in the 63 mm box (50 polar rods), over 60-180 s as the row's
# dilute points; each from all its seeds (five at 0.50, two at 0.35, 0.65 and 0.80).
ALIGNMENT_ROW_63MM = [
    (0.35, f"{ALIGNMENT}/fig1c-63mm-phi_a0.35-seed1-from60.summary.csv"),
    (0.35, f"{ALIGNMENT}/fig1c-63mm-phi_a0.35-seed2-from60.summary.csv"),
    (0.50, f"{ALIGNMENT}/fig1c-63mm-phi_a0.50-seed1-from60.summary.csv"),
    (0.50, f"{ALIGNMENT}/fig1c-63mm-phi_a0.50-seed2-from60.summary.csv"),
    (0.50, f"{ALIGNMENT}/fig1c-63mm-phi_a0.50-seed3-from60.summary.csv"),
    (0.50, f"{ALIGNMENT}/fig1c-63mm-phi_a0.50-seed4-from60.summary.csv"),
    (0.50, f"{ALIGNMENT}/fig1c-63mm-phi_a0.50-seed5-from60.summary.csv"),
    (0.65, f"{ALIGNMENT}/fig1c-63mm-phi_a0.65-seed1-from60.summary.csv"),
    (0.65, f"{ALIGNMENT}/fig1c-63mm-phi_a0.65-seed2-from60.summary.csv"),
    (0.80, f"{ALIGNMENT}/fig1c-63mm-phi_a0.80-seed1-from60.summary.csv"),
    (0.80, f"{ALIGNMENT}/fig1c-63mm-phi_a0.80-seed2-from60.summary.csv"),
]
ALIGNMENT_NOISE = [(float(d), f"{ALIGNMENT}/fig1f-38mm-D_r{d}-seed2-from30.summary.csv")
                   for d in ("0", "0.026", "0.23", "1.21", "1.87")]

# The dilute end's order (φ_a = 0.05, φ_p = 0.05, D_r = 0): how far it reaches and what carries
# it. G(r) of the polar rods over 60-180 s unless the label names a window, from `rodsea analyze
# --observables pair --from T --param pair.r_max=L/2 --param pair.bin=1` (label, table, colour,
# line style), and P(t) in 5 s means of 1 s series tables (label, table, colour, line style):
# the row's runs with the medium from the random start; the same rods without the medium
# (dilute-order/polar-only-*.toml, seed 2 to 360 s); the 88 mm box with medium rods of a quarter
# of the mass (light-medium-88mm.toml), of half (half-mass-medium-88mm.toml; seed 2,
# medium-mass-88mm-seed2.toml) and of 0.15
# polar-rod masses (medium-mass-88mm.toml) and, P(t) only (stopped at 70 s), from an aligned
# start (aligned-88mm.toml).
DILUTE = f"{DATA}/dilute-order"
DILUTE_CORRELATIONS = [
    ("38 mm, with medium", f"{DILUTE}/fig1c-38mm-phi_a0.05-seed1-from60.pair_correlation_polar.csv",
     "C0", "-"),
    ("38 mm, no medium", f"{DILUTE}/polar-only-38mm-from60.pair_correlation_polar.csv", "C0", "--"),
    ("88 mm, with medium", f"{DILUTE}/fig1c-88mm-phi_a0.05-seed1-from60.pair_correlation_polar.csv",
     "C3", "-"),
    ("88 mm, with medium, seed 2, 60–360 s",
     f"{DILUTE}/with-medium-88mm-seed2-from60.pair_correlation_polar.csv", "C4", "-"),
    ("88 mm, no medium", f"{DILUTE}/polar-only-88mm-from60.pair_correlation_polar.csv", "C3", "--"),
    ("88 mm, no medium, seed 2, 60–180 s (before it orders)",
     f"{DILUTE}/polar-only-88mm-seed2-from60-to180.pair_correlation_polar.csv", "C3", "-."),
    ("88 mm, no medium, seed 2, 240–360 s",
     f"{DILUTE}/polar-only-88mm-seed2-from240.pair_correlation_polar.csv", "C3", ":"),
    ("88 mm, light medium", f"{DILUTE}/light-medium-88mm-from60.pair_correlation_polar.csv", "C1",
     "-"),
    ("88 mm, half-mass medium",
     f"{DILUTE}/half-mass-medium-88mm-from60.pair_correlation_polar.csv", "C1", "--"),
    ("88 mm, half-mass medium, seed 2",
     f"{DILUTE}/medium-mass-88mm-0.1-seed2-from60.pair_correlation_polar.csv", "C5", "--"),
    ("88 mm, medium of 0.15 masses",
     f"{DILUTE}/medium-mass-88mm-0.15-from60.pair_correlation_polar.csv", "C1", ":"),
]
DILUTE_SERIES = [
    ("38 mm, with medium", f"{DATA}/finite-size/fig1c-phi_a0.05-scale0.15.series.csv", "C0", "-"),
    ("38 mm, no medium", f"{DILUTE}/polar-only-38mm.series.csv", "C0", "--"),
    ("88 mm, with medium",
     f"{DATA}/finite-size/fig1c-phi_a0.05-scale0.35_extended_to_360_s.series.csv", "C3", "-"),
    ("88 mm, with medium, seed 2", f"{DILUTE}/with-medium-88mm-seed2.series.csv", "C4", "-"),
    ("88 mm, no medium", f"{DILUTE}/polar-only-88mm.series.csv", "C3", "--"),
    ("88 mm, no medium, seed 2", f"{DILUTE}/polar-only-88mm-seed2.series.csv", "C3", ":"),
    ("88 mm, with medium, aligned start", f"{DILUTE}/aligned-88mm.series.csv", "C2", "-"),
    ("88 mm, light medium", f"{DILUTE}/light-medium-88mm.series.csv", "C1", "-"),
    ("88 mm, half-mass medium", f"{DILUTE}/half-mass-medium-88mm.series.csv", "C1", "--"),
    ("88 mm, half-mass medium, seed 2", f"{DILUTE}/medium-mass-88mm-0.1.seed2.series.csv", "C5",
     "--"),
    ("88 mm, medium of 0.15 masses", f"{DILUTE}/medium-mass-88mm-0.15.series.csv", "C1", ":"),
]
DILUTE_BIN = 5
# What sets how hard the medium kicks (docs/reproduction.md, the dilute end): the φ_a = 0.05
# point in the 38 mm box at several medium masses (seed 1; seed 2 at the two masses either side
# of the turn; seeds 3-5 at those two and the paper's; seeds 6-8 at the turn and 6-7 at the
# paper's) and at several time steps. Each run row of a summary is one run (the rows of seed
# groups that `analyze` appends are skipped); the masses, in polar-rod masses (0: no medium),
# are those of its run rows in order (the toml headers' commands). A table with several seeds
# at one mass is drawn as points, not joined.
DILUTE_MASS_TABLES = [
    ("seed 1", f"{DILUTE}/medium-mass-38mm-from60.summary.csv", [0.0, 0.05, 0.1, 0.15, 0.2, 0.4],
     "C0", "o"),
    ("seed 2", f"{DILUTE}/medium-mass-38mm-seed2-from60.summary.csv", [0.1, 0.15], "C3", "s"),
    ("seeds 3–5", f"{DILUTE}/medium-mass-38mm-seeds3-5-from60.summary.csv",
     [0.1] * 3 + [0.15] * 3 + [0.2] * 3, "C2", "^"),
    ("seeds 6–8", f"{DILUTE}/medium-mass-38mm-seeds6-8-from60.summary.csv", [0.15] * 3, "C4",
     "v"),
    ("seeds 6–7", f"{DILUTE}/medium-mass-38mm-paper-seeds6-7-from60.summary.csv", [0.2] * 2,
     "C5", "D"),
]
DILUTE_DT_TABLE = f"{DILUTE}/dt-38mm-from60.summary.csv"
# The same turn run by run: P(t) of every seed at the masses either side of it and the paper's
# (mass: [(label, 1 s series table)]), in 5 s means. Seeds 1 and 2 are the tables above's runs
# (seed 1 at 0.2 is dt-38mm's 2.5 µs run); seeds 3-8 are those of medium-mass-38mm-seeds3-5,
# -seeds6-8 and -paper-seeds6-7.toml, named by `scripts/reproduction_series.py` after their
# campaign point.
DILUTE_SEEDS = f"{DILUTE}/medium-mass-seeds"
DILUTE_SEED_SERIES = {
    0.1: [("seed 1", f"{DILUTE}/medium-mass-38mm-0.1.series.csv"),
          ("seed 2", f"{DILUTE}/medium-mass-38mm-0.1.seed2.series.csv")]
    + [(f"seed {k}", f"{DILUTE_SEEDS}/medium.mass=0.1.seed{k}.series.csv") for k in (3, 4, 5)],
    0.15: [("seed 1", f"{DILUTE}/medium-mass-38mm-0.15.series.csv"),
           ("seed 2", f"{DILUTE}/medium-mass-38mm-0.15.seed2.series.csv")]
    + [(f"seed {k}", f"{DILUTE_SEEDS}/medium.mass=0.15.seed{k}.series.csv") for k in range(3, 9)],
    0.2: [("seed 1", f"{DILUTE}/dt-38mm-2.5e-06.series.csv")]
    + [(f"seed {k}", f"{DILUTE_SEEDS}/medium.mass=0.2.seed{k}.series.csv") for k in range(3, 8)],
}
PAPER_MEDIUM_MASS = 0.2  # docs/model.md §2, the paper's m_apolar / m_polar

# Fig. 5b, first look: the medium's velocity around polar rods against distance in the 63 mm box
# (label, profile table) from `rodsea analyze --observables medium_velocity`.
FIG5B_PROFILES = [
    (f"φ_a = {phi}", f"{DATA}/fig5b-63mm/medium_velocity_phi_a{phi}.csv")
    for phi in ("0.05", "0.20", "0.50")
]

# Fig. 5b in the End Matter's reading, v = (α/Γ_f) P: the medium's mean velocity along the polar
# rods' mean heading against their |P|, as block means of the 63 mm box's runs past their first
# minute (`scripts/medium_drift.py --blocks-out`), one table per φ_a holding all its seeds.
FIG5B_DRIFT = [(phi, f"{DATA}/fig5b-63mm/drift-against-order/phi_a{phi}.blocks.csv")
               for phi in ("0.05", "0.20", "0.35", "0.50", "0.65", "0.80")]

# Fig. 5b at the paper's d = 100 mm: the 214 mm box on an H100, t = 1-11.6 s (fig5b-gpu/). Each
# time base of the velocities (`medium_velocity.lag`): (label, file infix).
FIG5B_GPU = f"{DATA}/fig5b-gpu"
FIG5B_GPU_PHI = ("0.05", "0.20", "0.50")
FIG5B_GPU_LAGS = [("instantaneous", ""), ("over 0.1 s", "lag0.1s_"), ("over 1 s", "lag1s_")]
# A profile's bins of fewer pairs are not drawn: only the innermost, where a medium rod's centre
# is within 1 mm of a polar rod's, can be so sparse (23 and 255 pairs at φ_a = 0.05 and 0.20 in
# the 1 s tables; the next bin holds thousands).
FIG5B_GPU_MIN_PAIRS = 1000


class TableError(Exception):
    pass


def read_csv(relative):
    path = os.path.join(ROOT, relative)
    if not os.path.isfile(path):
        raise TableError(f"{relative}: missing")
    try:
        # deletechars="": keep the dots of config keys in column names (medium.area_fraction).
        t = np.genfromtxt(path, delimiter=",", skip_header=1, names=True, dtype=float,
                          encoding="utf-8", deletechars="")
    except ValueError as e:
        raise TableError(f"{relative}: not a table ({e})") from None
    return np.atleast_1d(t)


def column(t, name, relative):
    if name not in (t.dtype.names or ()):
        raise TableError(f"{relative}: no column '{name}'")
    return np.asarray(t[name], dtype=float)


def fig1c_curves():
    """{panel: [(label, x, y, err)]} of P, Σ and N_m against φ_a."""
    panels = {"P_polar": [], "Sigma": [], "N_m": []}
    for label, relative in FIG1C_POINTS:
        if not os.path.isfile(os.path.join(ROOT, relative)):
            continue  # a campaign not run yet: its curve is left out, and said so in the doc
        t = read_csv(relative)
        x = column(t, "medium.area_fraction", relative)
        order = np.argsort(x)
        for name in panels:
            panels[name].append((label, x[order], column(t, name, relative)[order],
                                 column(t, name + "_err", relative)[order]))
    if not panels["P_polar"]:
        raise TableError(f"none of {', '.join(r for _, r in FIG1C_POINTS)} exists")
    return panels


def draw_fig1c(plt):
    panels = fig1c_curves()
    fig, axes = plt.subplots(1, 3, figsize=(12.0, 4.0))
    ylabels = {"P_polar": "P (polar rods)", "Sigma": "Σ (baseline removed)",
               "N_m": "⟨N_m⟩ (rods in the largest flock)"}
    for ax, (name, curves) in zip(axes, panels.items()):
        for label, x, y, err in curves:
            ax.errorbar(x, y, yerr=err, marker="o", ms=4, capsize=3, label=label)
        ax.set_xlabel("φ_a")
        ax.set_ylabel(ylabels[name])
        if name == "Sigma":
            ax.axhline(0.0, color="0.6", lw=0.8)
    axes[0].legend(loc="best", fontsize=8)
    fig.suptitle("Fig. 1c / 3a at φ_p = 0.05, σ = 3.125, D_r = 0: rodsea, one run per point "
                 "(errors: each run's own)", fontsize=10)
    fig.tight_layout()
    dump = {f"{name}: {label}": {"x": x.tolist(), "y": y.tolist(), "err": e.tolist()}
            for name, curves in panels.items() for label, x, y, e in curves}
    return fig, dump


def series_files():
    directory = os.path.join(ROOT, FIG1C_SERIES)
    if not os.path.isdir(directory):
        raise TableError(f"{FIG1C_SERIES}/: missing")
    files = sorted(f for f in os.listdir(directory) if f.endswith(".series.csv"))
    if not files:
        raise TableError(f"{FIG1C_SERIES}/: no *.series.csv")
    # A run continued further ("<point>_extended_to_180_s") holds the shorter run's series as
    # its beginning, bit for bit: draw only the longer one.
    stems = [f[:-len(".series.csv")] for f in files]
    files = [f for f, stem in zip(files, stems)
             if not any(other.startswith(stem + "_extended_to_") for other in stems)]
    return [os.path.join(FIG1C_SERIES, f) for f in files]


def draw_fig1c_series(plt):
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7.0, 6.0), sharex=True)
    dump = {}
    for relative in series_files():
        t = read_csv(relative)
        mid = 0.5 * (column(t, "t_from", relative) + column(t, "t_to", relative))
        # "medium.area_fraction=0.05_extended_to_180_s" → "φ_a = 0.05 extended to 180 s"
        name = os.path.basename(relative)[:-len(".series.csv")]
        label = "φ_a = " + name.replace("medium.area_fraction=", "", 1).replace("_", " ")
        p, n_m = column(t, "P_polar", relative), column(t, "N_m", relative)
        top.plot(mid, p, lw=1.3, label=label)
        bottom.plot(mid, n_m, lw=1.3, label=label)
        dump[f"P_polar: {label}"] = {"x": mid.tolist(), "y": p.tolist()}
        dump[f"N_m: {label}"] = {"x": mid.tolist(), "y": n_m.tolist()}
    top.set_ylabel("P (1 s means)")
    bottom.set_ylabel("N_m (1 s means)")
    bottom.set_xlabel("t (s)")
    top.legend(loc="best", fontsize=8)
    top.set_title("Transients of the long runs (63 mm box, φ_p = 0.05, D_r = 0)", fontsize=10)
    fig.tight_layout()
    return fig, dump


def draw_finite_size(plt):
    """P against time for each FINITE_SIZE point in each box, 5 s means, beside the order of N
    random headings, √(π/4N), which a disordered state of N polar rods shows."""
    fig, axes = plt.subplots(2, 2, figsize=(10.0, 6.6), sharey=True)
    dump = {}
    for ax, (phi, boxes) in zip(axes.flat, FINITE_SIZE.items()):
        for (label, relative, rods), colour in zip(boxes, ("C0", "C1", "C2")):
            if not os.path.isfile(os.path.join(ROOT, relative)):
                continue  # a box not run yet
            mid, mean = bin_means(read_csv(relative), "P_polar", relative, 5)
            floor = float(np.sqrt(np.pi / (4 * rods)))
            ax.plot(mid, mean, color=colour, lw=1.4, label=f"{label}, {rods} polar rods")
            ax.axhline(floor, color=colour, lw=0.9, ls="--")
            dump[f"P_polar: φ_a = {phi:.2f}, {label}"] = {"x": mid.tolist(), "y": mean.tolist()}
            dump[f"random headings: φ_a = {phi:.2f}, {label}"] = {"x": [], "y": [floor]}
        ax.set_title(f"φ_a = {phi:.2f}", fontsize=10)
        ax.legend(loc="best", fontsize=8)
    for ax in axes[1]:
        ax.set_xlabel("t (s)")
    for ax in axes[:, 0]:
        ax.set_ylabel("P (5 s means)")
    fig.suptitle("φ_p = 0.05, σ = 3.125, D_r = 0 in boxes of up to three sizes (dashed: N random "
                 "headings)", fontsize=10)
    fig.tight_layout()
    return fig, dump


def window_mean(relative, name, window, block):
    """`name`'s block mean and error over `window` in one series table, and the table. A window
    the table does not cover, or one with fewer than two finite blocks of `name`, is refused."""
    from block_means import block_means
    t = read_csv(relative)
    for needed in ("t_from", "t_to", name):
        column(t, needed, relative)
    try:
        result = block_means(t, *window, block)
    except ValueError as e:
        raise TableError(f"{relative}: {e}") from None
    if name not in result:
        raise TableError(f"{relative}: {name} has fewer than two finite blocks of {block:g} s "
                         f"over {window[0]:g}–{window[1]:g} s")
    mean, err, _ = result[name]
    return mean, err, t


def row63_window(relative):
    """The part of ROW38_WINDOW that a run's series table covers, in whole ROW38_BLOCK blocks, or
    None below two blocks. A last 1 s bin with fewer frames than the others (a run stopped
    within it) does not count as covered."""
    t = read_csv(relative)
    for needed in ("t_from", "t_to", "frames"):
        column(t, needed, relative)
    if t.size == 0:
        raise TableError(f"{relative}: no bins")
    end = t["t_to"][-1] if t["frames"][-1] >= t["frames"].max() else t["t_from"][-1]
    start, stop = ROW38_WINDOW
    blocks = int((min(end, stop) - start) // ROW38_BLOCK)
    return (start, start + blocks * ROW38_BLOCK) if blocks >= 2 else None


def draw_row(plt):
    """P, Σ and N_m against φ_a: in the 38 mm box each seed's 60–180 s mean (error from 15 s
    blocks) and the mean over the seeds; in the 63 mm box the same, each seed over 60–180 s
    where the run has it."""
    fig, axes = plt.subplots(1, 3, figsize=(12.0, 3.8))
    dump = {}
    panels = (("P_polar", "P (polar rods)"), ("Sigma", "Σ (segregation)"),
              ("N_m", "⟨N_m⟩ (rods per flock)"))
    # Each 63 mm run's window, once for all three panels; a seed not run yet has none.
    windows63 = {relative: row63_window(relative) for seeds in ROW63.values()
                 for relative in seeds if os.path.isfile(os.path.join(ROOT, relative))}
    for ax, (name, title) in zip(axes, panels):
        xs, means = [], []
        seeds_x, seeds_y, seeds_err = [], [], []
        for phi, tables in ROW38.items():
            values = []
            for relative in tables:
                if not os.path.isfile(os.path.join(ROOT, relative)):
                    continue  # a seed not run yet
                mean, err, _ = window_mean(relative, name, ROW38_WINDOW, ROW38_BLOCK)
                values.append(mean)
                seeds_x.append(float(phi))
                seeds_y.append(mean)
                seeds_err.append(err)
            if values:
                xs.append(float(phi))
                means.append(float(np.mean(values)))
        ax.errorbar(seeds_x, seeds_y, yerr=seeds_err, fmt="o", ms=4, color="C0", alpha=0.7,
                    capsize=2, label="38 mm, one seed (15 s blocks)")
        ax.plot(xs, means, "-", color="C3", lw=1.4, label="38 mm, mean over seeds")
        dump[f"{name}: seeds"] = {"x": seeds_x, "y": seeds_y, "err": seeds_err}
        dump[f"{name}: mean"] = {"x": xs, "y": means}
        big = {"x": [], "y": [], "err": [], "window": []}
        big_mean = {"x": [], "y": []}
        whole_labelled = False
        for phi, seeds in ROW63.items():
            values = []
            for relative in seeds:
                window = windows63.get(relative)
                if window is None:
                    continue  # not run yet, or not yet two blocks past the window's start
                mean, err, _ = window_mean(relative, name, window, ROW38_BLOCK)
                whole = window == ROW38_WINDOW
                if not whole:
                    label = f"63 mm, {window[0]:g}–{window[1]:g} s so far"
                else:
                    label = None if whole_labelled else "63 mm, one seed (15 s blocks)"
                    whole_labelled = True
                ax.errorbar([phi], [mean], yerr=[err], fmt="s", ms=5, capsize=2, color="C2",
                            mfc="C2" if whole else "none", label=label)
                if whole:
                    values.append(mean)
                for key, value in zip(big, (phi, mean, err, list(window))):
                    big[key].append(value)
            if values:
                big_mean["x"].append(phi)
                big_mean["y"].append(float(np.mean(values)))
        if big_mean["x"]:
            ax.plot(big_mean["x"], big_mean["y"], "--", color="C2", lw=1.0,
                    label="63 mm, mean over seeds")
        dump[f"{name}: 63 mm"] = big
        dump[f"{name}: 63 mm mean"] = big_mean
        ax.set_xlabel("φ_a")
        ax.set_title(title, fontsize=10)
    # Below the panels: inside, with the open markers added, it hid a point wherever it went.
    handles, labels = axes[0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=4, fontsize=7, frameon=False)
    fig.suptitle("φ_p = 0.05, σ = 3.125, D_r = 0 in the 38 mm box (18 polar rods) and the 63 mm "
                 f"box (50): means over {ROW38_WINDOW[0]:g}–{ROW38_WINDOW[1]:g} s", fontsize=10)
    fig.tight_layout(rect=(0.0, 0.09, 1.0, 1.0))
    return fig, dump


def window_points(runs, window, block, name="P_polar"):
    """`name` (default P) over `window` (the mean of blocks of `block` seconds, and its error) of
    each run: [(value, mean, error, series table)]; a table not there yet is left out."""
    points = []
    for value, relative in runs:
        if not os.path.isfile(os.path.join(ROOT, relative)):
            continue  # a point not run yet
        points.append((value, *window_mean(relative, name, window, block)))
    return points


def draw_points_and_series(plt, runs, window, x_label, x_name, unit, title, block=ROW38_BLOCK,
                           panels=2, columns=None):
    """P over `window` (errors from blocks) against a parameter, one run per value, beside each
    run's P(t), and `panels` − 2 empty panels after them for the caller (fig.axes[2:]), in rows
    of `columns` (default: one row). runs: [(value, series table)]; a table not there yet is
    left out."""
    columns = columns or panels
    rows = -(-panels // columns)
    fig, axes = plt.subplots(rows, columns, figsize=(5.0 * columns, 3.6 * rows), squeeze=False)
    points, series = axes.flat[0], axes.flat[1]
    measured = window_points(runs, window, block)
    if not measured:
        raise TableError(f"none of {', '.join(r for _, r in runs)} exists")
    dump = {}
    values = [value for value, _ in runs]
    for value, _, _, t in measured:
        k = values.index(value)  # a colour per value, whichever points have run
        middle = 0.5 * (t["t_from"] + t["t_to"])
        keep = middle <= window[1]
        series.plot(middle[keep], t["P_polar"][keep], color=f"C{k}", lw=0.9,
                    label=f"{x_name} = {value:g}{unit}")
        dump[f"P(t): {x_name} = {value:g}"] = {"x": middle[keep].tolist(),
                                               "y": t["P_polar"][keep].tolist()}
    xs, ys, errs = ([m[i] for m in measured] for i in range(3))
    points.errorbar(xs, ys, yerr=errs, fmt="o-", ms=5, capsize=3, color="C3")
    dump["P"] = {"x": xs, "y": ys, "err": errs}
    points.set_xlabel(x_label)
    points.set_ylabel(f"P, {window[0]:g}–{window[1]:g} s")
    series.axvspan(*window, color="0.93", zorder=0)
    series.set_xlabel("t (s)")
    series.set_ylabel("P (1 s bins)")
    series.legend(loc="best", fontsize=7)
    fig.suptitle(title + " (grey: the window)", fontsize=10)
    fig.tight_layout(rect=(0, 0, 1, 1 - 0.06 / rows))
    return fig, points, dump


def draw_fig1f(plt):
    """P against the polar rods' intrinsic noise D_r at φ_a = 0.50 in the 38 mm box (over
    FIG1F_WINDOW, errors from blocks), and P(t) of each run."""
    fig, points, dump = draw_points_and_series(
        plt, FIG1F, FIG1F_WINDOW, "D_r (rad²/s; linear below 0.01)", "D_r", " rad²/s",
        "Fig. 1f, 38 mm box (18 polar rods), φ_p = 0.05, φ_a = 0.50, σ = 3.125 (P(t): seed 1)")
    second = window_points(FIG1F_SEED2, FIG1F_WINDOW, ROW38_BLOCK)
    if second:
        xs, ys, errs = ([m[i] for m in second] for i in range(3))
        points.errorbar(xs, ys, yerr=errs, fmt="s--", ms=4, capsize=3, color="C0",
                        label="seed 2")
        dump["P, seed 2"] = {"x": xs, "y": ys, "err": errs}
        first = {x: y for x, y in zip(dump["P"]["x"], dump["P"]["y"])}
        both = [(x, 0.5 * (first[x] + y)) for x, y in zip(xs, ys) if x in first]
        if both:
            mx, my = zip(*both)
            points.plot(mx, my, "-", color="k", lw=2.0, alpha=0.6, label="mean of the seeds")
            dump["P, mean of the seeds"] = {"x": list(mx), "y": list(my)}
        points.containers[0].set_label("seed 1")
        points.legend(loc="best", fontsize=7)
    points.set_xscale("symlog", linthresh=0.01)
    points.set_xlim(-0.002, 3.0)
    points.set_title("P against the polar rods' noise", fontsize=10)
    return fig, dump


def draw_beads(plt):
    """P against the bead medium's φ_a in the 38 mm box (over BEADS_WINDOW), and P(t)."""
    fig, points, dump = draw_points_and_series(
        plt, BEADS, BEADS_WINDOW, "φ_a (0.8 mm beads)", "φ_a", "",
        "SI S5, bead medium, 38 mm box (18 polar rods), φ_p = 0.05, D_r = 0")
    points.set_xlim(0.45, 0.80)
    points.set_title("P against the beads' area fraction", fontsize=10)
    return fig, dump


def draw_beads_light(plt):
    """The same with light beads (BEADS_LIGHT, over BEADS_LIGHT_WINDOW), the default mass's
    points beside them in grey."""
    fig, points, dump = draw_points_and_series(
        plt, BEADS_LIGHT, BEADS_LIGHT_WINDOW, "φ_a (0.8 mm beads)", "φ_a", "",
        "SI S5, beads of 0.033 polar-rod masses, 38 mm box (18 polar rods), φ_p = 0.05, D_r = 0",
        block=BEADS_LIGHT_BLOCK)
    heavy = window_points(BEADS, BEADS_WINDOW, ROW38_BLOCK)
    if heavy:
        xs, ys, errs = ([m[i] for m in heavy] for i in range(3))
        points.errorbar(xs, ys, yerr=errs, fmt="s--", ms=4, capsize=3, color="0.55",
                        label=f"mass 0.2 ({BEADS_WINDOW[0]:g}–{BEADS_WINDOW[1]:g} s)")
        dump["P, mass 0.2"] = {"x": xs, "y": ys, "err": errs}
    points.containers[0].set_label(  # the light beads' errorbar, drawn first
        f"mass 0.033 ({BEADS_LIGHT_WINDOW[0]:g}–{BEADS_LIGHT_WINDOW[1]:g} s)")
    points.legend(loc="best", fontsize=7)
    points.set_ylabel("P over the window")
    points.set_xlim(0.45, 0.80)
    points.set_ylim(0.0, 1.0)
    points.set_title("P against φ_a: light and heavy beads", fontsize=10)
    return fig, dump


def draw_fig4a(plt):
    """P and the medium's S against the medium rods' aspect ratio σ at φ_a = 0.75 (over
    FIG4A_WINDOW, errors from blocks), P(t) of each run in the 38 mm box and P(t) and S(t) of
    each run in the 88 mm box, and the longitudinal band of each."""
    fig, points, dump = draw_points_and_series(
        plt, FIG4A, FIG4A_WINDOW, "σ (medium rods' aspect ratio)", "σ", "",
        "Fig. 4a inset, φ_p = 0.05, φ_a = 0.75, D_r = 0.23 rad²/s unless named:\n38 mm box "
        "(18 polar rods) and 88 mm box (98 polar rods; dashed, open circles and diamonds)",
        block=FIG4A_BLOCK, panels=4, columns=2)
    nematic = window_points(FIG4A, FIG4A_WINDOW, FIG4A_BLOCK, "S_medium")
    xs, ys, errs = ([m[i] for m in nematic] for i in range(3))
    points.errorbar(xs, ys, yerr=errs, fmt="s--", ms=4, capsize=3, color="C0",
                    label="S of the medium")
    dump["S_medium"] = {"x": xs, "y": ys, "err": errs}
    points.containers[0].set_label("P of the polar rods")  # drawn first
    k_of = {sigma: k for k, (sigma, _) in enumerate(FIG4A)}
    series, series_88mm = fig.axes[1], fig.axes[2]
    series.set_title("38 mm box", fontsize=10)
    for sigma, relative, window, label in FIG4A_MORE:
        more = window_points([(sigma, relative)], window, FIG4A_BLOCK)
        if not more:
            continue  # not run yet
        marker, colour, filled, p_style, shift = FIG4A_MORE_STYLE[label]
        x, y, err, t = more[0]
        key = f"P, {label}"
        points.errorbar([x + shift], [y], yerr=[err], fmt=marker, ms=5, capsize=3, color=colour,
                        mfc=colour if filled else "none",
                        label=f"P, 38 mm box, {label}" if key not in dump else None)
        if window != FIG4A_WINDOW:  # the axis names FIG4A_WINDOW
            points.annotate(f"{window[0]:g}–{window[1]:g} s", (x + shift, y), xytext=(-6, -10),
                            textcoords="offset points", ha="right", fontsize=7, color=colour)
        dump.setdefault(key, {"x": [], "y": [], "err": []})
        for name, value in (("x", x), ("y", y), ("err", err)):
            dump[key][name].append(value)
        middle = 0.5 * (t["t_from"] + t["t_to"])
        series.plot(middle, t["P_polar"], color=f"C{k_of[sigma]}", lw=0.8, ls=p_style,
                    label=f"σ = {sigma:g}, {label}")
        dump[f"P(t): σ = {sigma:g}, {label}"] = {"x": middle.tolist(),
                                                 "y": t["P_polar"].tolist()}
    points.set_ylabel(f"over {FIG4A_WINDOW[0]:g}–{FIG4A_WINDOW[1]:g} s unless named")
    points.set_xlim(0.8, 6.0)
    points.set_ylim(0.0, 1.0)
    points.set_title("P and the medium's S against σ", fontsize=10)
    t_end = FIG4A_WINDOW[1]
    for sigma, relative, window, seed in FIG4A_88MM:
        if not os.path.isfile(os.path.join(ROOT, relative)):
            continue  # not run yet
        p_style, s_style, marker = FIG4A_88MM_STYLE[seed]
        t = read_csv(relative)
        middle = 0.5 * (column(t, "t_from", relative) + column(t, "t_to", relative))
        t_end = max(t_end, float(column(t, "t_to", relative)[-1]))
        p, nematic = column(t, "P_polar", relative), column(t, "S_medium", relative)
        series_88mm.plot(middle, p, color=f"C{k_of[sigma]}", lw=1.2, ls=p_style,
                         label=f"P, σ = {sigma:g}{seed}")
        series_88mm.plot(middle, nematic, color=f"C{k_of[sigma]}", lw=1.0, ls=s_style,
                         label=f"S of the medium, σ = {sigma:g}{seed}")
        dump[f"P(t): σ = {sigma:g}, 88 mm{seed}"] = {"x": middle.tolist(), "y": p.tolist()}
        dump[f"S(t): σ = {sigma:g}, 88 mm{seed}"] = {"x": middle.tolist(), "y": nematic.tolist()}
        if window is None:
            continue  # not steady yet: no point against σ
        _, y, err, _ = window_points([(sigma, relative)], window, FIG4A_BLOCK)[0]
        key = f"P, 88 mm{seed}"
        points.errorbar([sigma], [y], yerr=[err], fmt=marker, ms=7, mfc="none", capsize=3,
                        color="C3", label=f"P, 88 mm box{seed}" if key not in dump else None)
        if window != FIG4A_WINDOW:
            points.annotate(f"{window[0]:g}–{window[1]:g} s", (sigma, y), xytext=(-8, 6),
                            textcoords="offset points", ha="right", fontsize=7, color="C3")
        dump.setdefault(key, {"x": [], "y": [], "err": []})
        for name, value in (("x", sigma), ("y", y), ("err", err)):
            dump[key][name].append(value)
    series_88mm.set_xlabel("t (s)")
    series_88mm.set_ylabel("P, S (1 s bins)")
    series_88mm.set_xlim(0.0, t_end)
    series_88mm.set_ylim(0.0, 1.0)
    series_88mm.set_title("88 mm box: P (dashed) and the medium's S (dotted)", fontsize=10)
    points.legend(loc="upper center", bbox_to_anchor=(0.42, 1.0), fontsize=7)  # clear of σ = 1.25
    series.legend(loc="upper left", fontsize=7, ncol=2)
    series.set_ylim(0.0, 1.0)
    series_88mm.legend(loc="upper left", fontsize=7, ncol=2)
    draw_fig4a_bands(fig.axes[3], dump, t_end)
    fig.tight_layout(rect=(0, 0, 1, 0.95))
    return fig, dump


def draw_fig4a_bands(ax, dump, t_end):
    """The longitudinal band, |ρ_k| of the polar rods' longest density mode across their axis of
    motion (the `bands` observable), against time to `t_end` in every run whose table has it,
    beside the mean for rods at random positions, √(π/4N)."""
    k_of = {sigma: k for k, (sigma, _) in enumerate(FIG4A)}
    runs = [(f"σ = {sigma:g}, 38 mm", relative, f"C{k_of[sigma]}", "-", 18)
            for sigma, relative in FIG4A]
    runs += [(f"σ = {sigma:g}, 88 mm{seed}", relative, f"C{k_of[sigma]}",
              FIG4A_88MM_STYLE[seed][0], 98) for sigma, relative, _, seed in FIG4A_88MM]
    floors = set()
    for label, relative, colour, style, rods in runs:
        if not os.path.isfile(os.path.join(ROOT, relative)):
            continue
        t = read_csv(relative)
        if "band_longitudinal" not in t.dtype.names or np.isnan(t["band_longitudinal"]).all():
            continue  # analysed before the bands observable
        middle = 0.5 * (column(t, "t_from", relative) + column(t, "t_to", relative))
        ax.plot(middle, t["band_longitudinal"], color=colour, lw=1.0, ls=style, label=label)
        dump[f"longitudinal band: {label}"] = {"x": middle.tolist(),
                                               "y": t["band_longitudinal"].tolist()}
        floors.add(rods)
    for rods in sorted(floors):
        ax.axhline(np.sqrt(np.pi / (4 * rods)), color="0.5", lw=0.8, ls=":")
    ax.set_xlabel("t (s)")
    ax.set_ylabel("longitudinal band |ρ_k| (1 s bins)")
    ax.set_xlim(0.0, t_end)  # as the 88 mm P(t) above it (38 mm σ = 3.125 runs on to 120 s)
    ax.set_ylim(0.0, 1.0)
    ax.set_title("band along the motion (dotted: random, √(π/4N))", fontsize=10)
    if floors:
        ax.legend(loc="best", fontsize=7)


def draw_fig5b(plt):
    """The medium's mean velocity along the rod's axis (lab frame) and its mean speed against
    the distance from a polar rod, for each φ_a: the drag near the rod and the far field."""
    fig, (along, speed) = plt.subplots(1, 2, figsize=(10.0, 3.6))
    dump = {}
    for (label, relative), colour in zip(FIG5B_PROFILES, ("C0", "C1", "C2")):
        if not os.path.isfile(os.path.join(ROOT, relative)):
            continue
        t = read_csv(relative)
        r = column(t, "r", relative)
        v = column(t, "v_along", relative)
        u = column(t, "speed", relative)
        keep = column(t, "pairs", relative) > 0
        along.plot(r[keep], v[keep], color=colour, lw=1.4, label=label)
        speed.plot(r[keep], u[keep], color=colour, lw=1.4, label=label)
        dump[f"v_along: {label}"] = {"x": r[keep].tolist(), "y": v[keep].tolist()}
        dump[f"speed: {label}"] = {"x": r[keep].tolist(), "y": u[keep].tolist()}
    along.axhline(0.0, color="0.6", lw=0.8)
    along.set_xlabel("distance from a polar rod, r (mm)")
    along.set_ylabel("medium velocity along the rod's axis (mm/s)")
    speed.set_xlabel("distance from a polar rod, r (mm)")
    speed.set_ylabel("medium speed |v| (mm/s, instantaneous)")
    along.legend(loc="best", fontsize=8)
    fig.suptitle("Medium around polar rods, 63 mm box, φ_p = 0.05, D_r = 0, from t = 30 s",
                 fontsize=10)
    fig.tight_layout()
    return fig, dump


def draw_fig5b_gpu(plt):
    """At the paper's d in a 214 mm box: the medium's mean velocity along the rods' axis against r
    (the flow the rods drive, from 1 s displacements), and the comoving-frame speed at d against
    φ_a for each time base of the velocities (what docs/model.md reads as the paper's |v|)."""
    fig, (along, at_d) = plt.subplots(1, 2, figsize=(10.0, 3.8))
    dump = {}
    for phi, colour in zip(FIG5B_GPU_PHI, ("C0", "C1", "C2")):
        relative = f"{FIG5B_GPU}/medium_velocity_lag1s_phi_a{phi}.csv"
        t = read_csv(relative)
        keep = column(t, "pairs", relative) >= FIG5B_GPU_MIN_PAIRS
        r = column(t, "r", relative)[keep]
        v = column(t, "v_along", relative)[keep]
        along.plot(r, v, color=colour, lw=1.4, label=f"φ_a = {phi}")
        dump[f"v_along over 1 s: φ_a = {phi}"] = {"x": r.tolist(), "y": v.tolist()}
    along.axhline(0.0, color="0.6", lw=0.8)
    along.axvline(100.0, color="0.6", lw=0.8, ls=":")
    along.set_xscale("log")
    along.set_xlabel("distance from a polar rod, r (mm)")
    along.set_ylabel("medium velocity along the rod's axis,\nfrom 1 s displacements (mm/s)")
    along.legend(loc="upper right", fontsize=8)
    phis = [float(phi) for phi in FIG5B_GPU_PHI]
    for (label, infix), marker in zip(FIG5B_GPU_LAGS, ("o", "s", "^")):
        means, errors = [], []
        for phi in FIG5B_GPU_PHI:
            relative = f"{FIG5B_GPU}/medium_velocity_{infix}phi_a{phi}.summary.csv"
            t = read_csv(relative)
            means.append(float(column(t, "medium_speed_at_d", relative)[0]))
            errors.append(float(column(t, "medium_speed_at_d_err", relative)[0]))
        at_d.errorbar(phis, means, yerr=errors, marker=marker, capsize=3, lw=1.2, label=label)
        dump[f"speed at d: {label}"] = {"x": phis, "y": means, "err": errors}
    at_d.set_ylim(bottom=0.0)
    at_d.set_xlabel("medium area fraction φ_a")
    at_d.set_ylabel("|v_j − v_i| at d = 100 mm (mm/s)")
    at_d.legend(loc="upper left", fontsize=8, title="velocities", title_fontsize=8)
    fig.suptitle("Medium around polar rods at the paper's d: 214 mm box (H100), φ_p = 0.05, "
                 "D_r = 0, t = 1–11.6 s", fontsize=10)
    fig.tight_layout()
    return fig, dump


def draw_fig5b_drift(plt):
    """The End Matter's reading of Fig. 5b at steady state: the medium's drift along the polar
    rods' mean heading against their order, one point per block, with the slope through the
    origin (α/Γ_f) of each φ_a; and α/Γ_f against φ_a with its jackknife error over the blocks."""
    fig, (scatter, slopes) = plt.subplots(1, 2, figsize=(10.0, 3.8))
    dump = {}
    phis, values, errors = [], [], []
    for (phi, relative), colour in zip(FIG5B_DRIFT, [f"C{i}" for i in range(10)]):
        if not os.path.isfile(os.path.join(ROOT, relative)):
            continue  # a φ_a not analysed yet
        t = read_csv(relative)
        p = column(t, "P_polar", relative)
        v = column(t, "v_medium_along_polar", relative)
        if len(p) < 3:
            raise TableError(f"{relative}: fewer than three blocks")
        slope, error = slope_through_origin(p, v)
        scatter.plot(p, v, "o", ms=3, color=colour, alpha=0.7,
                     label=f"φ_a = {phi}: {slope:.2f} ± {error:.2f} mm/s")
        line = np.array([0.0, float(p.max())])
        scatter.plot(line, slope * line, color=colour, lw=1.0)
        dump[f"blocks: φ_a = {phi}"] = {"x": p.tolist(), "y": v.tolist()}
        phis.append(float(phi))
        values.append(slope)
        errors.append(error)
    scatter.axhline(0.0, color="0.6", lw=0.8)
    scatter.set_xlim(left=0.0)
    scatter.set_xlabel("polar order |P| (block mean)")
    scatter.set_ylabel("medium's mean velocity along the\npolar rods' heading (mm/s)")
    scatter.legend(loc="upper left", fontsize=7, title="α/Γ_f (slope)", title_fontsize=7)
    slopes.errorbar(phis, values, yerr=errors, marker="o", capsize=3, lw=1.2, color="k")
    dump["alpha/Gamma_f"] = {"x": phis, "y": values, "err": errors}
    slopes.set_ylim(bottom=0.0)
    slopes.set_xlabel("medium area fraction φ_a")
    slopes.set_ylabel("α/Γ_f = v/P (mm/s)")
    fig.suptitle("The medium's drift against the polar rods' order, 63 mm box, φ_p = 0.05, "
                 "D_r = 0, past 60 s", fontsize=10)
    fig.tight_layout()
    return fig, dump


def bin_means(t, name, relative, width):
    """`name` in means of `width` consecutive 1 s bins of a series table, at the bins' middles
    (a shorter remainder at the end is left out)."""
    start, values = column(t, "t_from", relative), column(t, name, relative)
    count = len(values) // width
    middles = start[:width * count].reshape(count, width).min(axis=1) + 0.5 * width
    return middles, values[:width * count].reshape(count, width).mean(axis=1)


def draw_dense38(plt):
    """The dense end of the 38 mm row over the whole run: P (beside N random headings), the
    medium's S, Σ and the share of polar rods in flocks, in 5 s means."""
    fig, axes = plt.subplots(2, 2, figsize=(10.0, 6.0), sharex=True)
    panels = (("P_polar", "P (polar rods)"), ("S_medium", "S (medium)"),
              ("Sigma", "Σ (segregation)"), ("fraction_in_flocks", "polar rods in flocks"))
    dump = {}
    drawn = 0
    for k, (phi, relative, rods) in enumerate(DENSE38):
        if not os.path.isfile(os.path.join(ROOT, relative)):
            continue  # a φ_a not run yet
        t = read_csv(relative)
        for ax, (name, title) in zip(axes.flat, panels):
            x, y = bin_means(t, name, relative, DENSE38_BIN)
            ax.plot(x, y, color=f"C{k}", lw=1.3, label=f"φ_a = {phi:.2f}")
            ax.set_title(title, fontsize=10)
            dump[f"{name}: φ_a = {phi:g}"] = {"x": x.tolist(), "y": y.tolist()}
        floor = float(np.sqrt(np.pi / (4 * rods)))
        axes[0, 0].axhline(floor, color="grey", lw=0.9, ls="--")
        drawn += 1
    if not drawn:
        raise TableError(f"none of {', '.join(r for _, r, _ in DENSE38)} exists")
    axes[0, 0].legend(loc="best", fontsize=8)
    for ax in axes[1]:
        ax.set_xlabel("t (s)")
    fig.suptitle(f"The 38 mm row's dense end (18 polar rods), {DENSE38_BIN} s means; dashed: "
                 "18 random headings", fontsize=10)
    fig.tight_layout()
    return fig, dump


def draw_ct(plt):
    """SI S3(a): the polar rods' orientation autocorrelation C(t) against the lag, semilog, one
    curve per φ_a of the 38 mm box (solid; its third seed of 0.80 dash-dotted) and of the 63 mm
    box (dashed; the second seeds dotted, the third dash-dotted, the fourth dash-dot-dotted,
    the fifth long-dashed),
    and the medium's C₂(t)."""
    fig, (polar, medium) = plt.subplots(1, 2, figsize=(10.0, 4.6))
    dump = {}
    drawn = 0
    colours = {0.35: "C4", 0.50: "C0", 0.65: "C1", 0.80: "C2"}
    for phi, box, relative, window in CT:
        if not os.path.isfile(os.path.join(ROOT, relative)):
            continue  # a φ_a not run yet
        t = read_csv(relative)
        for needed in ("t", "C_polar", "C2_medium"):
            column(t, needed, relative)
        label = f"φ_a = {phi:g}, {box} ({window[0]:g}–{window[1]:g} s)"
        style = {"color": colours.get(phi, "k"),
                 "ls": {"38 mm": "-", "63 mm": "--", "63 mm, seed 2": ":",
                        "63 mm, seed 4": (0, (4, 1, 1, 1, 1, 1)),
                        "63 mm, seed 5": (0, (8, 3))}.get(box, "-."),
                 "label": label}
        keep = t["C_polar"] > 0  # a log axis: the noise floor's negative values are not drawn
        polar.semilogy(t["t"][keep], t["C_polar"][keep], **style)
        medium.plot(t["t"], t["C2_medium"], **style)
        dump[f"C: φ_a = {phi:g}, {box}"] = {"x": t["t"][keep].tolist(),
                                            "y": t["C_polar"][keep].tolist()}
        drawn += 1
    if not drawn:
        raise TableError(f"none of {', '.join(r for _, _, r, _ in CT)} exists")
    polar.set_yticks([0.1, 0.2, 0.3, 0.5, 0.7, 1.0], ["0.1", "0.2", "0.3", "0.5", "0.7", "1"])
    # 18 rods over a window of ~20 decorrelation times leave C(t) uncertain by ~0.05: lower values
    # are noise, and a log axis would stretch them over most of the panel. (The 63 mm box's 50
    # rods, over ~6 decorrelation times, are uncertain by about as much.)
    polar.set_ylim(0.03, 1.1)
    polar.minorticks_off()
    polar.set_xlabel("lag t (s)")
    polar.set_ylabel("C(t), polar rods")
    medium.set_xlim(0, 5)
    medium.set_xlabel("lag t (s)")
    medium.set_ylabel("C₂(t), medium rods")
    fig.suptitle("SI S3(a, b): 38 mm box (18 polar rods, solid) and 63 mm box (50, dashed), "
                 "φ_p = 0.05, σ = 3.125, D_r = 0", fontsize=10)
    # Below the panels: with a curve per run, inside the polar panel it hid some wherever it went.
    handles, labels = polar.get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=4, fontsize=7, frameon=False)
    fig.tight_layout(rect=(0.0, 0.17, 1.0, 1.0))
    return fig, dump


def alignment_points(runs, required=True):
    """[(x, {scalar: (mean, error)})] of P, P_independent and flock_alignment from each run's
    summary; a run not made yet is left out unless `required`."""
    points = []
    for x, relative in runs:
        if not required and not os.path.isfile(os.path.join(ROOT, relative)):
            continue
        t = read_csv(relative)
        points.append((x, {name: (float(column(t, name, relative)[0]),
                                  float(column(t, name + "_err", relative)[0]))
                           for name in ("P_polar", "P_independent", "flock_alignment")}))
    return points


def draw_alignment(plt):
    """What carries the polar rods' order: P beside P_independent, the P that the same flocks and
    lone rods would give heading independently (top), and their ratio ⟨P²⟩/⟨P_independent²⟩
    (bottom), against φ_a (Fig. 1c's row) and against D_r (Fig. 1f)."""
    fig, axes = plt.subplots(2, 2, figsize=(10.0, 6.0), sharex="col")
    dump = {}
    curves = ((0, "38 mm box", ALIGNMENT_ROW, True, "o-"),
              (0, "38 mm box, seed 3", ALIGNMENT_ROW_SEED3, False, "^"),
              (0, "63 mm box", ALIGNMENT_ROW_63MM, False, "s"),
              (0, "88 mm box", ALIGNMENT_ROW_88MM, False, "D"),
              (1, "38 mm box, seed 2", ALIGNMENT_NOISE, True, "o-"))
    for col, box, runs, required, fmt in curves:
        points = alignment_points(runs, required)
        if not points:
            continue
        xs = [x for x, _ in points]
        colour = {"38": "C0", "63": "C1"}.get(box[:2], "C3")
        for row, names in ((0, ("P_polar", "P_independent")), (1, ("flock_alignment",))):
            for name in names:
                ys = [v[name][0] for _, v in points]
                errs = [v[name][1] for _, v in points]
                label = {"P_polar": f"P, {box}", "P_independent": f"P_independent, {box}",
                         "flock_alignment": box}[name]
                dashed = name == "P_independent" and fmt.endswith("-")
                axes[row, col].errorbar(
                    xs, ys, yerr=errs, fmt=fmt.replace("-", "--") if dashed else fmt, ms=5,
                    capsize=3, color=colour, mfc="white" if name == "P_independent" else colour,
                    label=label)
                dump[f"{name}: {box}, against {'φ_a' if col == 0 else 'D_r'}"] = {
                    "x": xs, "y": ys, "err": errs}
    for col in (0, 1):
        axes[1, col].axhline(1.0, color="grey", lw=0.9, ls="--")
        axes[0, col].set_ylim(0, 1)
        axes[0, col].legend(loc="best", fontsize=7)
        axes[1, col].legend(loc="best", fontsize=7)
    axes[0, 0].set_ylabel("P; P of independent flocks")
    axes[1, 0].set_ylabel("⟨P²⟩ / ⟨P_independent²⟩")
    axes[0, 0].set_title("Fig. 1c's row (D_r = 0)", fontsize=10)
    axes[0, 1].set_title("Fig. 1f (φ_a = 0.50)", fontsize=10)
    axes[1, 0].set_xlabel("φ_a")
    axes[1, 1].set_xlabel("D_r (rad²/s; linear below 0.01)")
    axes[1, 1].set_xscale("symlog", linthresh=0.01)
    axes[1, 1].set_xlim(-0.002, 3.0)
    fig.suptitle("What carries P: flocks (P_independent) or alignment between flocks and lone rods "
                 "(the ratio; 1 = independent)", fontsize=10)
    fig.tight_layout()
    return fig, dump


def draw_dilute(plt):
    """The dilute end's order: G(r) of the polar rods against distance in two boxes, with and
    without the medium and from an aligned start (left), and P(t) of the same runs (right)."""
    fig, (left, right) = plt.subplots(1, 2, figsize=(11.0, 5.6))
    dump = {}
    for label, relative, colour, style in DILUTE_CORRELATIONS:
        t = read_csv(relative)
        r, g, err = (column(t, n, relative) for n in ("r", "G", "G_err"))
        keep = np.isfinite(g)
        left.plot(r[keep], g[keep], color=colour, ls=style, lw=1.3, label=label)
        left.fill_between(r[keep], (g - err)[keep], (g + err)[keep], color=colour, alpha=0.15,
                          lw=0)
        dump[f"G: {label}"] = {"x": r[keep].tolist(), "y": g[keep].tolist(),
                               "err": err[keep].tolist()}
    for label, relative, colour, style in DILUTE_SERIES:
        t = read_csv(relative)
        x, y = bin_means(t, "P_polar", relative, DILUTE_BIN)
        right.plot(x, y, color=colour, ls=style, lw=1.3, label=label)
        dump[f"P: {label}"] = {"x": x.tolist(), "y": y.tolist()}
    left.axhline(0.0, color="grey", lw=0.8, ls=":")
    left.set_xlabel("r (mm)")
    left.set_ylabel("G(r) = ⟨cos(θ_i − θ_j)⟩, polar rods")
    left.set_title("Polar correlation, 60–180 s unless named (shaded: ± 1 s.e.)", fontsize=10)
    # Below the axes: the curves fill the panels.
    left.legend(loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=2, fontsize=7)
    right.set_xlabel("t (s)")
    right.set_ylabel(f"P ({DILUTE_BIN} s means)")
    right.set_ylim(0, 1)
    right.set_title("Global polar order", fontsize=10)
    right.legend(loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=2, fontsize=7)
    fig.suptitle("The dilute end (φ_a = 0.05, φ_p = 0.05, σ = 3.125, D_r = 0): how far the "
                 "polar order reaches, and whether it is the medium's", fontsize=10)
    fig.tight_layout()
    return fig, dump


def draw_dilute_choices(plt):
    """What sets the medium's kicks at the dilute point: the polar rods' D_r and P against the
    medium rods' mass (left, middle) and D_r with the medium's agitation against dt (right)."""
    fig, (left, middle, right) = plt.subplots(1, 3, figsize=(13.0, 4.4))
    dump = {}
    for label, relative, mass, colour, marker in DILUTE_MASS_TABLES:
        t = read_csv(relative)
        t = t[np.isnan(column(t, "replicates", relative))]  # runs, not their seed groups
        if len(t) != len(mass):
            raise TableError(f"{relative}: {len(t)} runs for the {len(mass)} masses {mass}")
        joined = len(set(mass)) == len(mass)
        for ax, name in ((left, "D_r_C2_polar"), (middle, "P_polar")):
            y = column(t, name, relative).tolist()
            err = column(t, name + "_err", relative).tolist()
            ax.errorbar(mass, y, err, color=colour, marker=marker, ls="-" if joined else "none",
                        lw=1, capsize=3, mfc=colour if joined else "none", label=label)
            dump[f"{name}: {label}"] = {"x": mass, "y": y, "err": err}
    for ax in (left, middle):
        ax.axvline(PAPER_MEDIUM_MASS, color="grey", lw=0.8, ls=":")
        ax.set_xlabel("medium rod's mass (polar-rod masses; 0: no medium)")
        ax.legend(loc="best", fontsize=8)
    left.set_ylabel("polar rods' D_r from C₂(t) (rad²/s)")
    left.set_title("How fast the polar rods turn (dotted: the paper's 0.2)", fontsize=10)
    middle.set_ylabel("P")
    middle.set_ylim(0, 1)
    middle.set_title("Global polar order", fontsize=10)
    t = read_csv(DILUTE_DT_TABLE)
    order = np.argsort(column(t, "dt_s", DILUTE_DT_TABLE))
    dt = (column(t, "dt_s", DILUTE_DT_TABLE)[order] * 1e6).tolist()
    # Scaled to share one axis: D_r ~0.05 rad²/s, the medium's agitation ~10 mm/s and rad/s.
    for name, scale, colour, label in (
            ("D_r_C2_polar", 10.0, "C0", "polar rods' D_r (0.1 rad²/s)"),
            ("v_rms_medium", 0.1, "C1", "medium's rms in-plane speed (10 mm/s)"),
            ("spin_rms_medium", 0.1, "C2", "medium's rms spin (10 rad/s)")):
        y = (column(t, name, DILUTE_DT_TABLE)[order] * scale).tolist()
        err = (column(t, name + "_err", DILUTE_DT_TABLE)[order] * scale).tolist()
        right.errorbar(dt, y, err, color=colour, marker="o", ls="-", lw=1, capsize=3, label=label)
        dump[f"{name}: dt"] = {"x": dt, "y": y, "err": err}
    right.set_xscale("log", base=2)
    right.set_xticks(dt, [f"{x:g}" for x in dt])
    right.set_xlabel("dt (µs; the default 1.25)")
    right.set_ylim(0, None)
    right.set_title("The time step, at the paper's mass", fontsize=10)
    right.legend(loc="best", fontsize=8)
    fig.suptitle("The dilute point (φ_a = φ_p = 0.05, σ = 3.125, D_r = 0, 38 mm box, 60–180 s): "
                 "the medium's mass decides, the time step does not", fontsize=10)
    fig.tight_layout()
    return fig, dump


def draw_dilute_seeds(plt):
    """The medium-mass turn run by run: P(t) of every seed, one panel per mass."""
    fig, axes = plt.subplots(1, len(DILUTE_SEED_SERIES), figsize=(13.0, 4.2), sharey=True)
    dump = {}
    for ax, (mass, runs) in zip(axes, DILUTE_SEED_SERIES.items()):
        for k, (label, relative) in enumerate(runs):
            x, y = bin_means(read_csv(relative), "P_polar", relative, DILUTE_BIN)
            ax.plot(x, y, color=f"C{k}", lw=1.1, label=label)
            dump[f"P: {mass}: {label}"] = {"x": x.tolist(), "y": y.tolist()}
        ax.axvspan(60, 180, color="grey", alpha=0.08, lw=0)
        paper = " (the paper's)" if mass == PAPER_MEDIUM_MASS else ""
        ax.set_title(f"medium rods of {mass:g} polar-rod masses{paper}", fontsize=10)
        ax.set_xlabel("t (s; shaded: the 60–180 s window)")
        ax.set_ylim(0, 1)
        ax.legend(loc="lower right", ncol=3, fontsize=7)
    axes[0].set_ylabel(f"P ({DILUTE_BIN} s means)")
    fig.suptitle("The dilute point (φ_a = φ_p = 0.05, σ = 3.125, D_r = 0, 38 mm box, dt = 2.5 µs): "
                 "each seed's global polar order either side of the turn", fontsize=10)
    fig.tight_layout()
    return fig, dump


FIGURES = {"fig1c": draw_fig1c, "fig1c-series": draw_fig1c_series,
           "finite-size": draw_finite_size, "row": draw_row, "ct": draw_ct,
           "dense38": draw_dense38, "alignment": draw_alignment, "dilute": draw_dilute,
           "dilute-choices": draw_dilute_choices, "dilute-seeds": draw_dilute_seeds,
           "fig1f": draw_fig1f,
           "beads": draw_beads, "beads-light": draw_beads_light, "fig4a": draw_fig4a,
           "fig5b": draw_fig5b, "fig5b-gpu": draw_fig5b_gpu, "fig5b-drift": draw_fig5b_drift}


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--out", default=os.path.join(ROOT, "docs/images"))
    p.add_argument("--only", default=",".join(FIGURES))
    p.add_argument("--dump", action="store_true")
    a = p.parse_args(argv)
    names = [n for n in a.only.split(",") if n]
    unknown = [n for n in names if n not in FIGURES]
    if unknown:
        print(f"reproduction_figures.py: unknown figure {', '.join(unknown)} (figures: "
              f"{', '.join(FIGURES)})", file=sys.stderr)
        return 2
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    drawn = []
    try:
        for name in names:
            drawn.append((name, *FIGURES[name](plt)))
    except TableError as e:
        print(f"reproduction_figures.py: {e}; nothing drawn", file=sys.stderr)
        return 2
    os.makedirs(a.out, exist_ok=True)
    for name, fig, dump in drawn:
        path = os.path.join(a.out, f"reproduction-{name}.png")
        fig.savefig(path + ".tmp.png", dpi=110)
        os.replace(path + ".tmp.png", path)
        if a.dump:
            with open(os.path.join(a.out, f"reproduction-{name}.json"), "w") as f:
                json.dump(dump, f)
        print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
