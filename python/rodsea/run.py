"""A run directory as numpy arrays: frames with random access and slicing, the time series, the
config and the analysis (what `rodsea analyze` wrote), all checked as the CLI checks them."""
import csv
import json
import os

import numpy as np

from . import _rodsea


class _FrameArray:
    """run.positions[k], run.positions[2:10:2], run.positions[-1]: one field of the frames."""

    def __init__(self, run, field):
        self._run, self._field = run, field

    def __len__(self):
        return self._run.frames

    def __getitem__(self, index):
        if isinstance(index, slice):
            return np.stack([self._run.frame(k)[self._field]
                             for k in range(*index.indices(self._run.frames))])
        k = int(index)
        if k < 0:
            k += self._run.frames
        return self._run.frame(k)[self._field]


class Run:
    def __init__(self, path):
        self._stored = _rodsea._StoredRun(os.fspath(path))
        self.path = self._stored.run_dir
        self.frames = self._stored.frames
        self.times = self._stored.times          # s
        self.steps = self._stored.steps
        self.box = self._stored.box              # (L_x, L_y), mm
        self.config = self._stored.config        # the resolved TOML text
        self.species_names = self._stored.species_names
        for field in ("positions", "quaternions", "angles", "velocities", "spins"):
            setattr(self, field, _FrameArray(self, field))

    def frame(self, k):
        """Frame k as a dict: positions (N, 3) mm, quaternions (N, 4), angles (N,) rad,
        velocities (N, 3) mm/s, spins (N, 3) rad/s, species (N,)."""
        if k < 0:
            k += self.frames
        return self._stored.frame(k)

    @property
    def species(self):
        return self._stored.frame(0)["species"]

    @property
    def series_names(self):
        return self._stored.series_names

    def series(self, name=None):
        """One time-series column (one value per frame), or all of them as a dict."""
        if name is not None:
            return self._stored.series(name)
        return {n: self._stored.series(n) for n in self._stored.series_names}

    def analysis(self, directory=None):
        """What `rodsea analyze` wrote (RUN/analysis/ unless given): {"json": the parsed
        analysis.json, "scalars": {name: (value, error)}, "tables": {csv name: {column: array}},
        "maps": {name: {"value", "r_edges", "theta_edges"}}, "datasets": {path: array} for the
        other arrays of analysis.h5 (defects/..., flock_tracks/..., fields/mean/...; the time
        series of maps, fields/series/..., are left to fields())}."""
        directory = directory or os.path.join(self.path, "analysis")
        summary_path = os.path.join(directory, "analysis.json")
        if not os.path.exists(summary_path):
            raise _rodsea.FileError(f"{summary_path}: no analysis here: run rodsea analyze "
                                    f"{self.path} first")
        with open(summary_path) as f:
            summary = json.load(f)
        scalars = {}
        for observable in summary.get("observables", {}).values():
            for name, s in observable.get("scalars", {}).items():
                scalars[name] = (s.get("value"), s.get("error"))
        tables = {}
        for name in sorted(os.listdir(directory)):
            if name.endswith(".csv"):
                tables[name[:-4]] = read_table(os.path.join(directory, name))
        maps, datasets = {}, {}
        h5 = os.path.join(directory, "analysis.h5")
        if os.path.exists(h5):
            import h5py
            with h5py.File(h5, "r") as f:
                for name, group in f.get("maps", {}).items():
                    maps[name] = {k: group[k][()] for k in group}

                def keep(path, item):
                    if (isinstance(item, h5py.Dataset) and not path.startswith(("maps/", "labels/"))
                            and not path.startswith("fields/series/")):
                        datasets[path] = item[()]

                f.visititems(keep)
        return {"json": summary, "scalars": scalars, "tables": tables, "maps": maps,
                "datasets": datasets}

    def fields(self, directory=None):
        """The coarse-grained fields of `rodsea analyze` (observable 'fields'): {"x", "y": cell
        centres (mm), "time" (s) and "steady" of each kept map, "mean": {species: {field: map}},
        "series": {species: {field: array [frame, y, x]}}}. Maps are indexed [y, x], so
        imshow(map, origin="lower") draws them the right way up. Fields: area_fraction, vx, vy
        (mm/s), and px, py (polar rods), qxx, qxy (rods); NaN where a cell holds no body."""
        directory = directory or os.path.join(self.path, "analysis")
        h5 = os.path.join(directory, "analysis.h5")
        import h5py
        try:
            f = h5py.File(h5, "r")
        except OSError as e:
            raise _rodsea.FileError(f"{h5}: cannot be read ({e}); run rodsea analyze "
                                    f"{self.path} first") from None
        with f:
            if "fields" not in f:
                raise _rodsea.FileError(f"{h5}: no fields; run rodsea analyze {self.path} "
                                        "--observables fields")
            g = f["fields"]
            out = {k: g[k][()] for k in ("x", "y", "time", "steady")}
            for part in ("mean", "series"):
                out[part] = {species: {name: values[()] for name, values in group.items()}
                             for species, group in g[part].items()}
        return out


def read_table(path):
    """A rodsea CSV (a '#' comment line, a header, rows) as {column: numpy array}; columns that
    are not numbers stay lists of strings."""
    with open(path, newline="") as f:
        rows = [r for r in csv.reader(line for line in f if not line.startswith("#"))]
    if not rows:
        return {}
    header, body = rows[0], rows[1:]
    table = {}
    for i, name in enumerate(header):
        column = [r[i] if i < len(r) else "" for r in body]
        try:
            table[name] = np.array([float(v) if v != "" else np.nan for v in column])
        except ValueError:
            table[name] = column
    return table


def open_run(path):
    """A run directory written by `rodsea run` (or its trajectory.h5), checked as `rodsea
    analyze` checks it: rodsea.FileError names the file, dataset, frame and value."""
    return Run(path)
