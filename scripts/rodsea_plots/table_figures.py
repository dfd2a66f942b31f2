"""Figures of a table with one row per run (`rodsea analyze RUN... --table T.csv`, or one run's
summary.csv): steady-state scalars with error bars against φ_a and D_r, and the phase diagram.

Column names (docs/analysis.md): run, epsilon_per_mm, phi_<species>, length_mm_<species>, and each
scalar with its error, <scalar> and <scalar>_err. The polar species are those with a P_<species>
column; every other species with a phi_<species> column is a medium. φ_a of a run is the area
fraction of its medium (0 for a run without one).
"""
import os

import numpy as np

from .common import SIZE_CURVE, PlotError, read_csv
from .inputs import TABLE_HINT

ORDERED = 0.5  # the paper's phase boundary: ordered where P > 0.5

ALL_FIGURES = ["P_vs_phi_a.png", "Sigma_vs_phi_a.png", "P_vs_D_r.png", "Sigma_vs_D_r.png",
               "phase_diagram.png", "S_vs_phi_a.png", "sigma_f_vs_phi_a.png", "N_m_vs_phi_a.png",
               "N_avg_vs_phi_a.png", "D_r_vs_phi_a.png"]


class Runs:
    """The rows of a run table, with the control parameters of each run resolved."""

    def __init__(self, path, log):
        t = read_csv(path)
        self.table, self.path = t, path
        species = [c[len("phi_"):] for c in t.columns if c.startswith("phi_")]
        missing = [c for c, ok in (("run", t.has("run")), ("phi_<species>", bool(species)))
                   if not ok]
        if missing:
            hint = ""
            if os.path.isfile(os.path.join(os.path.dirname(path) or ".", "analysis.json")):
                hint = "; to plot a run's analysis, give its directory instead"
            raise PlotError(f"{path} is not a table of runs: it lacks the column(s) "
                            f"{', '.join(missing)} ({TABLE_HINT}){hint}")
        if len(t) == 0:
            raise PlotError(f"{path}: a table of runs without any row")
        self.polar = [s for s in species if t.has(f"P_{s}")]
        self.media = [s for s in species if s not in self.polar]
        if len(self.polar) > 1:
            log.note(f"{path}: several polar species ({', '.join(self.polar)}); "
                     f"plotting {self.polar[0]}")
        self.polar_name = self.polar[0] if self.polar else None
        n = len(t)
        self.names = t.text("run")
        phi = {s: t.number(f"phi_{s}") for s in species}
        present = np.zeros(n, dtype=bool)
        for s in species:
            present |= np.isfinite(phi[s])
        self.phi_a = np.where(present, 0.0, np.nan)
        self.medium = [None] * n  # the (first) medium species of each run
        for s in self.media:
            here = np.isfinite(phi[s]) & (phi[s] > 0)
            self.phi_a = np.where(here, self.phi_a + np.where(here, phi[s], 0.0), self.phi_a)
            for i in np.flatnonzero(here):
                self.medium[i] = self.medium[i] or s
        self.length_a = np.array([t.number(f"length_mm_{m}")[i] if m and t.has(f"length_mm_{m}")
                                  else np.nan for i, m in enumerate(self.medium)])
        self.phi_p = phi[self.polar_name] if self.polar_name else np.full(n, np.nan)
        self.epsilon = t.number("epsilon_per_mm")

    def column(self, name):
        return self.table.number(name)

    def error(self, name):
        e = self.table.number(name + "_err")
        return np.clip(np.nan_to_num(e, nan=0.0), 0.0, None)

    def medium_scalar(self, prefix):
        """Per run, the scalar <prefix><its medium>, e.g. S_medium (NaN where it has none)."""
        values, errors = np.full(len(self.table), np.nan), np.zeros(len(self.table))
        for i, m in enumerate(self.medium):
            if m and self.table.has(prefix + m):
                values[i] = self.column(prefix + m)[i]
                errors[i] = self.error(prefix + m)[i]
        return values, errors

    # Control parameters that can tell runs apart: (key per run, its text for a legend). Keys
    # are rounded so that runs of one series share them, and None where the run has no value.
    def dimension(self, name):
        n = len(self.table)

        def rounded(values, digits):
            return [round(float(v), digits) if np.isfinite(v) else None for v in values]

        if name == "medium":
            keys = [(self.medium[i], rounded(self.length_a[i:i + 1], 3)[0]) if self.medium[i]
                    else None for i in range(n)]
            several = len({k[0] for k in keys if k}) > 1
            return keys, lambda k: ("no medium" if k is None else
                                    (f"{k[0]}: " if several else "") +
                                    (f"ℓ_a = {k[1]:g} mm" if k[1] is not None else ""))
        def text(symbol, form):
            return lambda k: f"{symbol} n/a" if k is None else symbol + form.format(k)

        if name == "phi_p":
            return rounded(self.phi_p, 2), text("φ_p", " ≈ {:.2f}")
        if name == "phi_a":
            return rounded(self.phi_a, 2), text("φ_a", " ≈ {:.2f}")
        if name == "epsilon":
            return rounded(self.epsilon, 9), text("ε", " = {:g} 1/mm")
        raise KeyError(name)


def groups(runs, rows, dims):
    """Splits `rows` by the control parameters in `dims` that vary among them: a list of
    (legend label, row indices) in increasing order of those parameters, and the text of the
    parameters that do not vary."""
    keyed, constant = [], []
    for d in dims:
        keys, text = runs.dimension(d)
        values = {keys[i] for i in rows}
        if len(values) > 1:
            keyed.append((keys, text))
        else:
            constant.append(text(values.pop()))
    buckets = {}
    for i in rows:
        buckets.setdefault(tuple(keys[i] for keys, _ in keyed), []).append(i)
    ordered = sorted(buckets.items(), key=lambda kv: sort_key(kv[0]))
    labelled = [(", ".join(text(k) for (_, text), k in zip(keyed, key)) or None, members)
                for key, members in ordered]
    return labelled, constant


def sort_key(key):
    """Orders keys of mixed parts: numbers, then text, then None."""
    if key is None:
        return [(2, 0.0, "")]
    if isinstance(key, tuple):
        return [part for k in key for part in sort_key(k)]
    if isinstance(key, (int, float)):
        return [(0, float(key), "")]
    return [(1, 0.0, str(key))]


def subtitle(runs, constant, shown):
    parts = constant + [f"{len(shown)} of {len(runs.table)} runs, {runs.path}"]
    return " · ".join(parts)


def versus(runs, log, name, x, x_err, x_label, y, y_err, y_label, heading, dims, hline=None):
    """One figure of y ± y_err against x (± x_err), a line and colour per group of runs."""
    if not log.wants(name):
        return []
    rows = [i for i in range(len(runs.table)) if np.isfinite(x[i]) and np.isfinite(y[i])]
    if not rows:
        log.note(f"no {name}: no run has both {x_label} and {y_label}")
        return []
    labelled, constant = groups(runs, rows, dims)

    def draw(plt):
        fig, ax = plt.subplots(figsize=SIZE_CURVE)
        for k, (label, members) in enumerate(labelled):
            members = sorted(members, key=lambda i: x[i])
            xs, ys = x[members], y[members]
            ax.errorbar(xs, ys, yerr=y_err[members],
                        xerr=None if x_err is None else x_err[members],
                        marker="os^vDP*Xhp"[k % 10], ms=5, capsize=3, lw=1.2, label=label)
        if hline is not None:
            ax.axhline(hline, color="0.5", lw=0.8, ls=":")
        ax.set_xlabel(x_label)
        ax.set_ylabel(y_label)
        ax.set_title(f"{heading}\n{subtitle(runs, constant, rows)}", fontsize=10)
        if any(label for label, _ in labelled):
            ax.legend(loc="best")
        return fig

    return [(name, draw)]


def phase_diagram(runs, log, p, d_r, d_r_name):
    if not log.wants("phase_diagram.png"):
        return []
    rows_all = [i for i in range(len(runs.table))
                if np.isfinite(p[i]) and np.isfinite(runs.phi_a[i])]
    if not rows_all:
        log.note("no phase_diagram.png: no run has both P and φ_a")
        return []
    if all(np.isfinite(d_r[i]) for i in rows_all):
        y, y_label, y_name = d_r, "D_r of polar rods, from C(t) (rad²/s)", "D_r"
    elif all(np.isfinite(runs.epsilon[i]) for i in rows_all):
        log.note(f"phase_diagram.png: {d_r_name} is missing for some runs; plotting "
                 "against the noise ε instead")
        y, y_label, y_name = runs.epsilon, "noise ε (1/mm)", "ε"
    else:
        log.note(f"no phase_diagram.png: neither {d_r_name} nor epsilon_per_mm for every run")
        return []
    rows = rows_all
    x = runs.phi_a
    _, constant = groups(runs, rows, ["medium", "phi_p"])
    ordered = [i for i in rows if p[i] > ORDERED]
    disordered = [i for i in rows if p[i] <= ORDERED]
    boundary, why_not = boundary_triangles(x[rows], y[rows], p[rows])
    if boundary is None:
        log.note(f"phase_diagram.png: P = {ORDERED} boundary not drawn ({why_not}); "
                 "marker style alone tells the phases apart")

    def draw(plt):
        fig, ax = plt.subplots(figsize=SIZE_CURVE)
        if disordered:
            ax.scatter(x[disordered], y[disordered], s=55, color="C0", zorder=3,
                       label=f"disordered (P ≤ {ORDERED})")
        if ordered:
            ax.scatter(x[ordered], y[ordered], s=55, facecolors="none", edgecolors="C0",
                       linewidths=1.6, zorder=3, label=f"ordered (P > {ORDERED})")
        for i in rows:
            digits = 3 if abs(p[i] - ORDERED) < 0.005 else 2  # 0.502 is not "0.50"
            ax.annotate(f"{p[i]:.{digits}f}", (x[i], y[i]), textcoords="offset points",
                        xytext=(6, 5), fontsize=7, color="0.3")
        if boundary is not None:
            contour = ax.tricontour(boundary, p[rows], levels=[ORDERED], colors="C3",
                                    linestyles="--", linewidths=1.5)
            if contour.allsegs[0]:
                ax.plot([], [], color="C3", ls="--", label=f"P = {ORDERED} (interpolated)")
        for values, set_limits in ((x[rows], ax.set_xlim), (y[rows], ax.set_ylim)):
            low, high = float(np.min(values)), float(np.max(values))
            pad = 0.08 * (high - low) if high > low else max(0.05, 0.1 * abs(low))
            set_limits(low - pad, high + pad)
        ax.set_xlabel("φ_a (medium area fraction)")
        ax.set_ylabel(y_label)
        ax.set_title(f"Phase diagram in the (φ_a, {y_name}) plane (numbers: P)\n"
                     f"{subtitle(runs, constant, rows)}", fontsize=10)
        ax.legend(loc="best")
        return fig

    return [("phase_diagram.png", draw)]


def boundary_triangles(x, y, p, level=ORDERED, name="P", noun="run"):
    """A triangulation of the points for the contour p = level, or (None, why not)."""
    from matplotlib.tri import Triangulation

    points = {(a, b) for a, b in zip(x, y)}
    if len(points) < 3:
        return None, "needs at least 3 distinct points"
    if not (np.any(p > level) and np.any(p <= level)):
        return None, f"every {noun} is on one side of {name} = {level}"
    span_x, span_y = np.ptp(x), np.ptp(y)
    if span_x == 0 or span_y == 0:
        return None, "the runs lie on one line"
    try:
        # Delaunay on coordinates scaled to the unit square: φ_a and D_r have different units.
        scaled = Triangulation((x - x.min()) / span_x, (y - y.min()) / span_y)
        return Triangulation(x, y, triangles=scaled.triangles), None
    except (RuntimeError, ValueError):
        return None, "the runs lie on one line"


def plan(table_input, log):
    runs = Runs(table_input.path, log)
    jobs = []
    phi_a, zero = runs.phi_a, np.zeros(len(runs.table))
    phi_label = "φ_a (medium area fraction)"
    by_phi = ["medium", "phi_p", "epsilon"]
    by_d_r = ["medium", "phi_p", "phi_a"]
    pn = runs.polar_name
    if pn is None:
        log.note("no P, D_r or phase-diagram figures: the table has no polar species "
                 "(no P_<species> column)")
        p = d_r = np.full(len(runs.table), np.nan)
        p_err = d_r_err = zero
    else:
        p, p_err = runs.column(f"P_{pn}"), runs.error(f"P_{pn}")
        d_r, d_r_err = runs.column(f"D_r_{pn}"), runs.error(f"D_r_{pn}")
    d_r_label = "D_r of polar rods, from C(t) (rad²/s)"
    sigma, sigma_err = runs.column("Sigma"), runs.error("Sigma")
    s_medium, s_medium_err = runs.medium_scalar("S_")
    if pn is not None:
        jobs += versus(runs, log, "P_vs_phi_a.png", phi_a, None, phi_label, p, p_err,
                       "polar order P", "Polar order of the polar rods vs medium density",
                       by_phi, hline=ORDERED)
    jobs += versus(runs, log, "Sigma_vs_phi_a.png", phi_a, None, phi_label, sigma, sigma_err,
                   "segregation Σ (random-mixing baseline removed)",
                   "Segregation vs medium density", by_phi, hline=0.0)
    if pn is not None:
        jobs += versus(runs, log, "P_vs_D_r.png", d_r, d_r_err, d_r_label, p, p_err,
                       "polar order P", "Polar order vs rotational diffusion", by_d_r,
                       hline=ORDERED)
        jobs += versus(runs, log, "Sigma_vs_D_r.png", d_r, d_r_err, d_r_label, sigma, sigma_err,
                       "segregation Σ (random-mixing baseline removed)",
                       "Segregation vs rotational diffusion", by_d_r, hline=0.0)
        jobs += phase_diagram(runs, log, p, d_r, f"D_r_{pn}")
    extra = [
        ("S_vs_phi_a.png", s_medium, s_medium_err, "nematic order S of the medium",
         "Nematic order of the medium vs its density"),
        ("sigma_f_vs_phi_a.png", runs.column("sigma_f"), runs.error("sigma_f"),
         "flock aspect ratio σ_f",
         "Flock aspect ratio (70 % contour of g(r, θ)) vs medium density"),
        ("N_m_vs_phi_a.png", runs.column("N_m"), runs.error("N_m"),
         "⟨N_m⟩ (polar rods in the largest flock)", "Largest flock vs medium density"),
        ("N_avg_vs_phi_a.png", runs.column("N_avg"), runs.error("N_avg"),
         "N_avg (polar rods in the flock contour)", "Average flock size vs medium density"),
        ("D_r_vs_phi_a.png", d_r, d_r_err, d_r_label,
         "Rotational diffusion of polar rods vs medium density"),
    ]
    for name, y, y_err, y_label, heading in extra:
        if np.isfinite(y).any():
            jobs += versus(runs, log, name, phi_a, None, phi_label, y, y_err, y_label, heading,
                           by_phi)
        elif log.wants(name):
            log.note(f"no {name}: the table has no value of it")
    if not jobs:
        raise PlotError(f"{runs.path}: nothing to plot: no run has a steady-state scalar "
                        "(P, Σ, S, D_r, N_m) together with φ_a")
    return jobs
