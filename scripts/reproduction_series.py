#!/usr/bin/python3
"""Time series of a finished run, binned, small enough to commit beside a campaign's table.

    scripts/reproduction_series.py RUN_DIR... --out DIR [--bin SECONDS]

Reads each run's analysis (RUN_DIR/analysis, written by `rodsea analyze` or `campaign collect`)
and writes DIR/<point>.series.csv: per time bin (default 1 s) the means of P of the polar rods,
S of the medium, Σ (baseline removed), N_m, the fraction of polar rods in flocks and the
transverse and longitudinal band amplitudes |ρ_k| (the `bands` observable), with the number of
frames in the bin and whether the bin lies in the steady window (nan for what the run does not
have: Σ without a medium, bands where the analysis did not compute them). <point> is the run's
campaign point (the name of the directory above seed<k>), or the run directory's name; a
campaign's further replicates (seed<k>, k > 1) write DIR/<point>.seed<k>.series.csv.
Units: time s; the rest are numbers (docs/analysis.md).
"""
import argparse
import os
import sys

import numpy as np

COLUMNS = [  # (analysis file, column, name in the series table)
    ("order_parameters.csv", "P_polar", "P_polar"),
    ("order_parameters.csv", "S_medium", "S_medium"),
    ("segregation.csv", "Sigma", "Sigma"),
    ("flocks.csv", "N_m", "N_m"),
    ("flocks.csv", "fraction_in_flocks", "fraction_in_flocks"),
    ("bands.csv", "transverse", "band_transverse"),
    ("bands.csv", "longitudinal", "band_longitudinal"),
]


def fail(message):
    print(f"reproduction_series.py: {message}", file=sys.stderr)
    sys.exit(2)


def read(path):
    if not os.path.isfile(path):
        fail(f"{path}: missing; analyse the run first (rodsea analyze RUN_DIR)")
    return np.genfromtxt(path, delimiter=",", skip_header=1, names=True)


def point_name(run):
    run = os.path.normpath(run)
    leaf = os.path.basename(run)
    if not (leaf.startswith("seed") and leaf[4:].isdigit()):
        return leaf
    point = os.path.basename(os.path.dirname(run))
    return point if leaf == "seed1" else f"{point}.{leaf}"


def series(run, width):
    analysis = os.path.join(run, "analysis")
    tables = {"order_parameters.csv": read(os.path.join(analysis, "order_parameters.csv"))}
    for file, _, _ in COLUMNS:
        # An observable the run's species do not allow (segregation without a medium) was
        # skipped by the analysis: its columns are nan.
        if file not in tables and os.path.isfile(os.path.join(analysis, file)):
            tables[file] = read(os.path.join(analysis, file))
    time = tables["order_parameters.csv"]["time"]
    steady = tables["order_parameters.csv"]["steady"]
    for file, t in tables.items():
        if len(t) != len(time) or not np.allclose(t["time"], time):
            fail(f"{analysis}/{file}: its frames differ from order_parameters.csv's")
    edges = np.arange(0.0, time[-1] + width, width)
    rows = []
    for lo, hi in zip(edges[:-1], edges[1:]):
        pick = (time >= lo) & (time < hi)
        if not pick.any():
            continue
        row = [lo, hi, int(pick.sum()), int(steady[pick].min() > 0.5)]
        for file, column, _ in COLUMNS:
            t = tables.get(file)
            has = t is not None and column in t.dtype.names
            row.append(float(np.mean(t[column][pick])) if has else np.nan)
        rows.append(row)
    return rows


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("runs", nargs="+")
    p.add_argument("--out", required=True)
    p.add_argument("--bin", type=float, default=1.0, help="bin width, s (default 1)")
    a = p.parse_args(argv)
    if not a.bin > 0:
        fail(f"--bin {a.bin}: must be > 0 s")
    names = [point_name(run) for run in a.runs]
    for name in set(names):
        if names.count(name) > 1:
            fail(f"{name}.series.csv would be written by several runs: give them one at a time "
                 "with different --out")
    os.makedirs(a.out, exist_ok=True)
    for run in a.runs:
        rows = series(run, a.bin)
        path = os.path.join(a.out, point_name(run) + ".series.csv")
        header = ["t_from", "t_to", "frames", "steady"] + [name for _, _, name in COLUMNS]
        with open(path + ".tmp", "w", encoding="utf-8") as f:
            f.write(f"# {os.path.normpath(run)} binned by {a.bin:g} s: means per bin; units: "
                    "t_from [s] t_to [s], the rest [1]; steady = 1 when the whole bin lies in "
                    "the analysis' steady window\n")
            f.write(",".join(header) + "\n")
            for row in rows:
                f.write(",".join(f"{v:.6g}" if isinstance(v, float) else str(v) for v in row)
                        + "\n")
        os.replace(path + ".tmp", path)
        print(path)


if __name__ == "__main__":
    main(sys.argv[1:])
