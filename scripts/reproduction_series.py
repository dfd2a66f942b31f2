#!/usr/bin/python3
"""Time series of a finished run, binned, small enough to commit beside a campaign's table.

    scripts/reproduction_series.py RUN_DIR... --out DIR [--bin SECONDS]
    scripts/reproduction_series.py RUN_DIR --continues SERIES_CSV --out DIR [--bin SECONDS]

Reads each run's analysis (RUN_DIR/analysis, written by `rodsea analyze` or `campaign collect`)
and writes DIR/<point>.series.csv: per time bin (default 1 s) the means of P of the polar rods,
S of the medium, Σ (baseline removed), N_m, the fraction of polar rods in flocks and the
transverse and longitudinal band amplitudes |ρ_k| (the `bands` observable), with the number of
frames in the bin and whether the bin lies in the steady window (nan for what the run does not
have: Σ without a medium, bands where the analysis did not compute them). <point> is the run's
campaign point (the name of the directory above seed<k>), or the run directory's name; a
campaign's further replicates (seed<k>, k > 1) write DIR/<point>.seed<k>.series.csv.
With --continues, RUN_DIR is a continuation (`rodsea run --continue`: its trajectory holds the
run's frames from a checkpoint on) and SERIES_CSV the table of the run's earlier frames, written
by this script with the same --bin: the two are joined into DIR/<SERIES_CSV's name>, the earlier
table's bins before the continuation's first frame, then the continuation's; a bin that both hold
in part gets the frame-weighted mean of the two, and steady is the continuation's analysis' (0
for the earlier table's bins and the shared one, which that analysis did not see whole). The
header line names every directory the table's frames came from, in order, with the time each
continuation starts: `# RUN1 to T1 s, then RUN2 to T2 s, then RUN3 binned by ...`.
Every frame must be in exactly one of them (the earlier table made from the first directory's
frames up to the checkpoint, as a run stopped by a signal leaves them): frames in both, or in
neither, are refused. Where the first directory holds frames past the checkpoint (a run killed
or crashed after it), give all the run's directories to one `rodsea analyze` and this script
the latest (without --continues): that analysis keeps each frame from the part that continues it.
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
    # A table of one frame reads as a 0-d record; every caller indexes frames.
    return np.atleast_1d(np.genfromtxt(path, delimiter=",", skip_header=1, names=True))


def point_name(run):
    run = os.path.normpath(run)
    leaf = os.path.basename(run)
    if not (leaf.startswith("seed") and leaf[4:].isdigit()):
        return leaf
    point = os.path.basename(os.path.dirname(run))
    return point if leaf == "seed1" else f"{point}.{leaf}"


def series(run, width):
    """The run's rows of the series table, binned by `width` s, and its frame times, s."""
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
    return rows, time


HEADER = ["t_from", "t_to", "frames", "steady"] + [name for _, _, name in COLUMNS]


BINNED = " binned by "


def read_series(path, width):
    """The directories a series table this script wrote came from (its header line up to
    BINNED) and its rows, checked against --bin."""
    if not os.path.isfile(path):
        fail(f"--continues {path}: missing")
    with open(path, encoding="utf-8") as f:
        comment = f.readline()
        if not comment.startswith("# ") or BINNED not in comment:
            fail(f"--continues {path}: its first line is not this script's header "
                 f"('# RUN_DIR{BINNED}...')")
        sources = comment[2:comment.index(BINNED)]
        header = f.readline().strip().split(",")
        if header != HEADER:
            fail(f"--continues {path}: not a series table of this script (columns {header})")
        rows = [[float(v) for v in line.split(",")] for line in f if line.strip()]
    for row in rows:
        off_grid = abs(row[0] / width - round(row[0] / width)) > 1e-6
        if abs(row[1] - row[0] - width) > 1e-9 * width or off_grid:
            fail(f"--continues {path}: its bin {row[0]:g}-{row[1]:g} s is not on the --bin "
                 f"{width:g} s grid")
    return sources, rows


def frames_per_bin(run, time, width):
    """How many frames a full bin holds: the bin width over the run's output interval (`time`:
    the run's frame times)."""
    if len(time) < 2:
        fail(f"{run}: --continues needs at least two frames to know the output interval")
    return int(round(width / float(np.median(np.diff(time)))))


def join(earlier, later, full):
    """`earlier`'s rows before `later`'s first bin, a shared bin merged, then `later`'s. Each
    frame of the run must be in exactly one of the two: `full` frames make a whole bin."""
    start = later[0][0]
    if any(row[0] > start + 1e-9 for row in earlier):
        fail(f"the earlier table goes past {start:g} s, where the continuation's first bin "
             "starts: is it the table of the run this directory continues? (if the first "
             "directory holds frames past the checkpoint, analyse all the run's directories "
             "with one `rodsea analyze` and give this script the latest, without --continues)")
    # The earlier table's steady flags are its own analysis' window, not the continuation's.
    kept = [list(row[:3]) + [0] + list(row[4:]) for row in earlier if row[0] < start - 1e-9]
    shared = [row for row in earlier if abs(row[0] - start) <= 1e-9]
    first = list(later[0])
    if shared:
        old = shared[0]
        n_old, n_new = old[2], first[2]
        if n_old + n_new != full:
            fail(f"the bin {start:g}-{first[1]:g} s holds {n_old:g} frames in the earlier table "
                 f"and {n_new:g} in the continuation, where it has {full}: "
                 + ("the two share frames (was the earlier table made from frames past the "
                    "checkpoint?)" if n_old + n_new > full else "frames are missing between "
                    "them (the earlier table stops before the checkpoint?)"))
        for c in range(4, len(HEADER)):
            a, b = old[c], first[c]
            if np.isnan(a) or np.isnan(b):
                first[c] = b if np.isnan(a) else a
            else:
                first[c] = (n_old * a + n_new * b) / (n_old + n_new)
        first[2] = int(n_old + n_new)
        first[3] = 0
    elif not kept or abs(kept[-1][1] - start) > 1e-9 or kept[-1][2] != full or first[2] != full:
        fail(f"frames are missing between the earlier table (to {kept[-1][1] if kept else 0:g} "
             f"s) and the continuation (from {start:g} s)")
    return kept + [first] + later[1:]


def write_series(path, rows, comment):
    with open(path + ".tmp", "w", encoding="utf-8") as f:
        f.write(comment + "\n")
        f.write(",".join(HEADER) + "\n")
        for row in rows:
            f.write(",".join(str(int(v)) if c in (2, 3) else f"{v:.6g}" for c, v in enumerate(row))
                    + "\n")
    os.replace(path + ".tmp", path)
    print(path)


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("runs", nargs="+")
    p.add_argument("--out", required=True)
    p.add_argument("--bin", type=float, default=1.0, help="bin width, s (default 1)")
    p.add_argument("--continues", metavar="SERIES_CSV",
                   help="the series table of the run's earlier frames, which RUN_DIR continues")
    a = p.parse_args(argv)
    if not a.bin > 0:
        fail(f"--bin {a.bin}: must be > 0 s")
    names = [point_name(run) for run in a.runs]
    for name in set(names):
        if names.count(name) > 1:
            fail(f"{name}.series.csv would be written by several runs: give them one at a time "
                 "with different --out")
    if a.continues and len(a.runs) != 1:
        fail("--continues joins one continuation to its run's earlier table: give one RUN_DIR")
    sources, earlier = read_series(a.continues, a.bin) if a.continues else (None, None)
    os.makedirs(a.out, exist_ok=True)
    for run in a.runs:
        rows, time = series(run, a.bin)
        # The earlier table's own directories stay named: the header is the table's provenance,
        # however many sessions the run took; the continuation starts at its first frame.
        origin = os.path.normpath(run)
        if earlier is not None:
            origin = f"{sources} to {time[0]:.10g} s, then {origin}"
        comment = (f"# {origin}{BINNED}{a.bin:g} s: means per bin; units: t_from [s] t_to [s], "
                   "the rest [1]; steady = 1 when the whole bin lies in the analysis' steady "
                   "window")
        if earlier is None:
            write_series(os.path.join(a.out, point_name(run) + ".series.csv"), rows, comment)
            continue
        comment += (f"; before {rows[0][0]:g} s from {os.path.normpath(a.continues)}, the run's "
                    "earlier frames, which this directory continues")
        joined = join(earlier, rows, frames_per_bin(run, time, a.bin))
        write_series(os.path.join(a.out, os.path.basename(a.continues)), joined, comment)


if __name__ == "__main__":
    main(sys.argv[1:])
