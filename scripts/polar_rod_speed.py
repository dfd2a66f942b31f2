#!/usr/bin/python3
"""How fast the polar rods of a run move, over a time window: a check that they still self-propel
(in a dense medium they may be caged, and a low P then says little about alignment).

    scripts/polar_rod_speed.py RUN_DIR... --from T0 [--to T1] [--lag SECONDS] [--csv FILE]

For each run: the polar rods' displacement over lags of --lag seconds (default 1; frame-to-frame
steps unwrapped by the minimum image), as the mean speed |Δr|/lag and the mean speed along the
rod's own axis u (body x, thick → thin), Δr·u/lag, both in mm/s over every rod and every lag
start in [T0, T1). A lone rod at this gap moves 2.5 mm/s thick → thin (docs/model.md).
The error is the standard error over rods of each rod's own mean: the spread between rods, not
the (smaller) error of a time average, because a caged rod and a free one differ the most.
--csv FILE also writes one row per run (speeds in mm/s, times in s) for data/reproduction/.
Reads RUN_DIR/trajectory.h5 (H5MD); the polar rods are the species of kind "polar_rod" in the
run's config stored there (species are numbered in the config's order).
"""
import argparse
import csv
import os
import sys

import tomllib

import h5py
import numpy as np


def axis_x(q):
    """The body x axis in the world frame, from quaternions (w, x, y, z)."""
    w, x, y, z = q[..., 0], q[..., 1], q[..., 2], q[..., 3]
    return np.stack([1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)], axis=-1)


def speeds(path, start, end, lag):
    try:
        return read_speeds(path, start, end, lag)
    except (OSError, KeyError, ValueError, UnicodeDecodeError, tomllib.TOMLDecodeError) as e:
        raise SystemExit(f"{path}: not a rodsea trajectory with a config ({e})") from None


def read_speeds(path, start, end, lag):
    if lag <= 0:
        raise SystemExit(f"--lag {lag}: must be > 0 s")
    with h5py.File(path, "r") as f:
        config = tomllib.loads(f["parameters/rodsea/config"][()].decode())
        kinds = [s.get("kind") for s in config.get("species", [])]
        if "polar_rod" not in kinds:
            raise SystemExit(f"{path}: no polar rods in this run")
        bodies = f["particles/bodies"]
        time = bodies["position/time"][:]
        keep = (time >= start) & (time < end)
        if keep.sum() < 2:
            raise SystemExit(f"{path}: fewer than two frames in [{start}, {end}) s")
        species = bodies["species"][:]
        polar = species == kinds.index("polar_rod")
        x = bodies["position/value"][keep][:, polar, :2].astype(float)
        q = bodies["orientation/value"][keep][:, polar, :].astype(float)
        box = bodies["box/edges/value"][0][:2]
    if not np.all(np.isfinite(box)) or np.any(box <= 0):
        raise SystemExit(f"{path}: box edges {box} are not positive lengths")
    t = time[keep]
    step = np.diff(x, axis=0)
    step -= box * np.round(step / box)  # minimum image: no rod crosses half the box per frame
    path_x = np.concatenate([np.zeros_like(x[:1]), np.cumsum(step, axis=0)])
    frames = int(round(lag / np.median(np.diff(t))))
    if frames < 1 or frames >= len(t):
        raise SystemExit(f"{path}: a lag of {lag} s does not fit the window")
    d = path_x[frames:] - path_x[:-frames]
    u = axis_x(q[:-frames])[..., :2]
    u /= np.linalg.norm(u, axis=-1, keepdims=True)  # the rod lies nearly flat
    dt = t[frames:] - t[:-frames]
    speed = (np.linalg.norm(d, axis=-1) / dt[:, None]).mean(axis=0)  # one mean per rod
    along = (np.sum(d * u, axis=-1) / dt[:, None]).mean(axis=0)
    return (*mean_and_error(speed), *mean_and_error(along), polar.sum(), len(t))


def mean_and_error(per_rod):
    if len(per_rod) < 2:
        return per_rod.mean(), float("nan")
    return per_rod.mean(), per_rod.std(ddof=1) / np.sqrt(len(per_rod))


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("runs", nargs="+")
    p.add_argument("--from", dest="start", type=float, required=True)
    p.add_argument("--to", dest="end", type=float, default=np.inf)
    p.add_argument("--lag", type=float, default=1.0)
    p.add_argument("--csv", help="also write one row per run to this file")
    a = p.parse_args()
    rows = []
    for run in a.runs:
        speed, speed_err, along, along_err, rods, frames = speeds(
            f"{run}/trajectory.h5", a.start, a.end, a.lag)
        print(f"{run}: {rods} polar rods, {frames} frames: |Δr|/lag = {speed:.3f} ± "
              f"{speed_err:.3f} mm/s, along the axis {along:+.3f} ± {along_err:.3f} mm/s "
              f"(lag {a.lag:g} s)")
        rows.append([run, a.start, a.end, a.lag, rods, frames, f"{speed:.4f}", f"{speed_err:.4f}",
                     f"{along:.4f}", f"{along_err:.4f}"])
    if a.csv:
        write_table(a.csv, rows)
    return 0


def write_table(path, rows):
    """All or nothing: a table cut short by a failed write would pass for a finished one."""
    try:
        with open(path + ".tmp", "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["run", "from_s", "to_s", "lag_s", "polar_rods", "frames", "speed_mm_s",
                        "speed_err_mm_s", "along_axis_mm_s", "along_axis_err_mm_s"])
            w.writerows(rows)
        os.replace(path + ".tmp", path)
    except OSError as e:
        raise SystemExit(f"--csv {path}: cannot be written ({e.strerror})") from None


if __name__ == "__main__":
    sys.exit(main())
