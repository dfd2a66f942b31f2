"""Figures of one run's analysis (RUN_DIR/analysis, written by `rodsea analyze`).

Everything is read and checked by plan() before any figure is drawn; each figure is then a
function of the loaded data. File layout: docs/analysis.md, "Output layout".
"""
import json
import math
import os

import numpy as np

from . import field_figures
from .common import (
    EXIT_IO,
    SIZE_CURVE,
    SIZE_MAP,
    SIZE_WIDE,
    PlotError,
    finite,
    format_value,
    message_panel,
    missing_module,
    read_csv,
    shade_steady,
)

# The figures each observable of `rodsea analyze` gives, in the order they are drawn.
FIGURES = {
    "order": ["order_parameters.png"],
    "autocorrelation": ["autocorrelation.png"],
    "flocks": ["flocks_time.png", "flock_sizes.png"],
    "corotating": ["g_r_theta.png", "G_r_theta.png"],
    "pair": ["pair_correlation.png"],
    "segregation": ["segregation.png"],
    "bands": ["bands.png"],
    "medium_velocity": ["medium_velocity.png"],
}
FIGURES.update(field_figures.FIGURES)

ALL_FIGURES = [name for names in FIGURES.values() for name in names]

ROD_KINDS = ("polar_rod", "apolar_rod")


class Analysis:
    """analysis.json and the files beside it."""

    def __init__(self, directory):
        self.dir = directory
        path = os.path.join(directory, "analysis.json")
        try:
            with open(path, encoding="utf-8") as f:
                self.json = json.load(f)
        except OSError as e:
            raise PlotError(f"{path}: cannot be read ({e.strerror})", EXIT_IO) from None
        except (ValueError, UnicodeDecodeError) as e:
            raise PlotError(f"{path}: not valid JSON ({e}); run `rodsea analyze` again",
                            EXIT_IO) from None
        j = self.json
        if not (isinstance(j, dict) and isinstance(j.get("observables"), dict)
                and isinstance(j.get("steady_state"), dict)
                and isinstance(j.get("parameters", {}).get("species"), list)):
            raise PlotError(f"{path}: not an analysis.json written by `rodsea analyze` "
                            "(no observables, steady_state or parameters.species)")
        self.path = path
        self.species = j["parameters"]["species"]
        self.polar = [s for s in self.species if s.get("kind") == "polar_rod"]
        self.media = [s for s in self.species if s.get("kind") != "polar_rod"]
        self.skipped = {}
        for entry in j.get("skipped", []):
            name, _, reason = str(entry).partition(":")
            self.skipped[name.strip()] = reason.strip()

    def observable(self, name):
        o = self.json["observables"].get(name)
        return o if isinstance(o, dict) else None

    def table(self, observable, name, required=True):
        """The observable's CSV table `name`, or None when the analysis did not write it."""
        entry = (self.observable(observable) or {}).get("tables", {}).get(name)
        if entry is None:
            if required:
                raise PlotError(f"{self.path}: '{observable}' lists no table '{name}'")
            return None
        path = os.path.join(self.dir, entry.get("file", name + ".csv"))
        if not os.path.isfile(path):
            raise PlotError(f"{path}: listed in analysis.json but missing; run `rodsea "
                            "analyze` again", EXIT_IO)
        table = read_csv(path)
        missing = [c for c in entry.get("columns", []) if not table.has(c)]
        if missing:
            raise PlotError(f"{path}: lacks the column(s) {', '.join(missing)} that "
                            "analysis.json lists")
        return table

    def scalar(self, observable, name):
        s = (self.observable(observable) or {}).get("scalars", {}).get(name)
        return s if isinstance(s, dict) else None

    def parameter(self, observable, name):
        p = (self.observable(observable) or {}).get("parameters", {}).get(name)
        return p.get("value") if isinstance(p, dict) else None

    def steady_frames(self):
        return int(self.json["steady_state"].get("frames") or 0)

    def describe(self):
        """Two lines naming the run and its control parameters, under each figure's title."""
        p = self.json["parameters"]
        parts = [str(self.json.get("run", {}).get("directory", self.dir))]
        def number(s, key, spec):
            # JSON writes NaN as null: a present null must not crash the caption.
            v = s.get(key)
            return format(v, spec) if finite(v) else "?"

        for s in self.polar:
            parts.append(f"φ_p = {number(s, 'area_fraction', '.3f')}")
        for s in self.media:
            kind = "ℓ_a" if s.get("kind") == "apolar_rod" else "bead d"
            parts.append(f"φ_a = {number(s, 'area_fraction', '.3f')} "
                         f"({kind} = {number(s, 'length_mm', '.3g')} mm)")
        if finite(p.get("noise_epsilon_per_mm")):
            parts.append(f"ε = {p['noise_epsilon_per_mm']:.3g} 1/mm")
        # The directory on a line of its own: beside the parameters it overflowed the narrow
        # polar maps' titles.
        return parts[0] + "\n" + " · ".join(parts[1:])


def value_text(scalar, unit=None):
    if scalar is None:
        return "n/a"
    return format_value(scalar.get("value"), scalar.get("error"),
                        scalar.get("unit", "") if unit is None else unit)


def title(ax, analysis, text):
    ax.set_title(f"{text}\n{analysis.describe()}", fontsize=10)


def plan(run_input, log):
    """[(file name, draw(plt) -> figure)] for everything the analysis contains; notes the rest."""
    a = Analysis(run_input.analysis_dir)
    jobs = []
    builders = {
        "order": order_jobs,
        "autocorrelation": autocorrelation_jobs,
        "flocks": flock_jobs,
        "corotating": corotating_jobs,
        "pair": pair_jobs,
        "segregation": segregation_jobs,
        "bands": band_jobs,
        "medium_velocity": medium_velocity_jobs,
        **field_figures.BUILDERS,
    }
    for observable, names in FIGURES.items():
        if not log.wants(*names):
            continue
        if a.observable(observable) is None:
            why = a.skipped.get(observable)
            reason = (f"rodsea analyze skipped '{observable}' ({why})" if why else
                      f"the analysis has no '{observable}' (see rodsea analyze --observables)")
            log.note(f"no {', '.join(names)}: {reason}")
            continue
        jobs += [job for job in builders[observable](a, log) if log.wants(job[0])]
    if not jobs:
        why = ("none of the figures of --only is available" if log.only is not None else
               "no observable with a figure")
        raise PlotError(f"{a.path}: nothing to plot ({why})")
    return jobs


# --- order parameters -------------------------------------------------------------------------

def order_jobs(a, log):
    t = a.table("order", "order_parameters")
    series = []
    for s in a.polar:
        if t.has(f"P_{s['name']}"):
            series.append((f"P_{s['name']}", f"P ({s['name']})"))
    for s in a.species:
        if s.get("kind") in ROD_KINDS and t.has(f"S_{s['name']}"):
            series.append((f"S_{s['name']}", f"S ({s['name']})"))
    time, steady = t.number("time"), t.number("steady")
    data = [(t.number(col), label, a.scalar("order", col)) for col, label in series]

    def draw(plt):
        fig, ax = plt.subplots(figsize=SIZE_CURVE)
        shade_steady(ax, time, steady)
        window = time[steady > 0.5]
        for values, label, scalar in data:
            (line,) = ax.plot(time, values, lw=1.4, label=f"{label}: {value_text(scalar)}")
            if scalar and finite(scalar.get("value")) and window.size:
                ax.hlines(scalar["value"], window[0], window[-1], colors=line.get_color(),
                          linestyles="--", lw=1)
        ax.set_xlabel("t (s)")
        ax.set_ylabel("order parameter P, S")
        ax.set_ylim(0, 1.05)
        title(ax, a, "Polar order P and nematic order S (dashed: steady mean)")
        ax.legend(loc="best")
        return fig

    return [("order_parameters.png", draw)]


# --- orientation autocorrelation --------------------------------------------------------------

def autocorrelation_jobs(a, log):
    t = a.table("autocorrelation", "orientation_autocorrelation")
    lag = t.number("t")
    curves = []  # (values, curve label, fit factor k in exp(-k D_r t), D_r scalar, fit label)
    for s in a.species:
        n = s["name"]
        if t.has(f"C_{n}"):
            curves.append((t.number(f"C_{n}"), f"C(t), {n}", 1,
                           a.scalar("autocorrelation", f"D_r_{n}"), "exp(−D_r t)"))
    for s in a.species:
        n = s["name"]
        if t.has(f"C2_{n}"):
            curves.append((t.number(f"C2_{n}"), f"C₂(t), {n}", 4,
                           a.scalar("autocorrelation", f"D_r_C2_{n}"), "exp(−4 D_r t)"))
    floor = a.parameter("autocorrelation", "fit_floor")
    if not curves:
        log.note("no autocorrelation.png: orientation_autocorrelation.csv has no C or C2 column")
        return []

    def draw(plt):
        from matplotlib.ticker import FuncFormatter, NullFormatter

        fig, ax = plt.subplots(figsize=SIZE_CURVE)
        smallest = 1.0
        for k, (values, label, factor, scalar, fit_label) in enumerate(curves):
            shown = np.isfinite(values) & (values > 0)
            if shown.any():
                smallest = min(smallest, values[shown].min())
            (line,) = ax.plot(lag[shown], values[shown], marker="os^vD"[k % 5], ms=4, lw=1,
                              label=label)
            if scalar and finite(scalar.get("value")):
                d_r = scalar["value"]
                tt = np.linspace(0, np.nanmax(lag), 200)
                ax.plot(tt, np.exp(-factor * d_r * tt), ls="--", lw=1.2, color=line.get_color(),
                        label=f"{fit_label}: D_r = {value_text(scalar, 'rad^2/s')}")
        if finite(floor):
            ax.axhline(floor, color="0.45", ls=":", lw=1,
                       label=f"fit floor {floor:g} (fits use lags down to it)")
            smallest = min(smallest, floor)
        ax.set_yscale("log")
        ax.set_ylim(max(smallest / 1.5, 1e-4), 1.15)
        plain = FuncFormatter(lambda v, _: f"{v:g}")
        ax.yaxis.set_major_formatter(plain)
        ax.yaxis.set_minor_formatter(plain if smallest > 0.1 else NullFormatter())
        ax.set_xlim(left=0)
        ax.set_xlabel("t (s)")
        ax.set_ylabel("C(t), C₂(t)")
        title(ax, a, "Orientation autocorrelation and the fits that give D_r")
        ax.legend(loc="lower left")
        return fig

    return [("autocorrelation.png", draw)]


# --- flocks -----------------------------------------------------------------------------------

def flock_jobs(a, log):
    t = a.table("flocks", "flocks")
    hist = a.table("flocks", "largest_flock_histogram")
    dist = a.table("flocks", "flock_size_distribution")
    time, steady = t.number("time"), t.number("steady")
    n_m, count, fraction = t.number("N_m"), t.number("flocks"), t.number("fraction_in_flocks")
    eps, min_samples = a.parameter("flocks", "eps"), a.parameter("flocks", "min_samples")
    how = f"DBSCAN, eps = {eps:g} mm, min_samples = {min_samples:g}" if finite(eps) else "DBSCAN"
    n_polar = sum(int(s.get("count", 0)) for s in a.polar)
    mean_n_m = a.scalar("flocks", "N_m")
    mean_count = a.scalar("flocks", "flock_count")

    def draw_time(plt):
        from matplotlib.ticker import MaxNLocator

        fig, ax = plt.subplots(figsize=SIZE_CURVE)
        shade_steady(ax, time, steady)
        ax.plot(time, n_m, lw=1.4, marker="o", ms=3,
                label=f"N_m, largest flock: ⟨N_m⟩ = {value_text(mean_n_m)}")
        ax.plot(time, count, lw=1.2, marker="s", ms=3,
                label=f"number of flocks: {value_text(mean_count)}")
        top = max(2.0, np.nanmax(np.concatenate([n_m, count, [0.0]])))
        ax.set_ylim(0, 1.5 * top)  # room for the legend above the curves
        ax.yaxis.set_major_locator(MaxNLocator(integer=True))
        ax.set_xlabel("t (s)")
        ax.set_ylabel("N_m (polar rods) / number of flocks")
        right = ax.twinx()
        right.plot(time, fraction, color="0.35", ls=":", lw=1.4, label="fraction in flocks")
        right.set_ylim(0, 1.05)
        right.set_ylabel("fraction of polar rods in flocks")
        right.grid(False)
        handles = ax.get_legend_handles_labels()
        more = right.get_legend_handles_labels()
        ax.legend(handles[0] + more[0], handles[1] + more[1], loc="upper left")
        title(ax, a, f"Flocks of polar rods ({how}; {n_polar} polar rods)")
        return fig

    def draw_sizes(plt):
        from matplotlib.ticker import MaxNLocator

        fig, (left, right) = plt.subplots(1, 2, figsize=SIZE_WIDE)
        if len(hist):
            left.bar(hist.number("N_m"), hist.number("probability"), width=0.8, color="C0")
        else:
            message_panel(left, "no steady frames")
        left.set_xlabel("N_m (polar rods in the largest flock)")
        left.set_ylabel("probability over steady frames")
        left.set_title("Histogram of the largest flock N_m", fontsize=10)
        if len(dist):
            right.bar(dist.number("size"), dist.number("per_frame"), width=0.8, color="C1")
        else:
            message_panel(right, "no flocks in the steady window")
        right.set_xlabel("flock size (polar rods)")
        right.set_ylabel("flocks per steady frame")
        right.set_title("Sizes of all flocks", fontsize=10)
        for ax in (left, right):
            ax.xaxis.set_major_locator(MaxNLocator(integer=True))
        fig.suptitle(f"Flock sizes ({how})\n{a.describe()}", fontsize=10)
        return fig

    return [("flocks_time.png", draw_time), ("flock_sizes.png", draw_sizes)]


# --- corotating maps --------------------------------------------------------------------------

def read_map(a, name):
    entry = (a.observable("corotating") or {}).get("maps", {}).get(name)
    if entry is None:
        raise PlotError(f"{a.path}: 'corotating' lists no map '{name}'")
    try:
        import h5py
    except ImportError:
        raise missing_module("h5py") from None
    path = os.path.join(a.dir, entry.get("file", "analysis.h5"))
    try:
        with h5py.File(path, "r") as f:
            group = f[f"maps/{name}"]
            value = np.asarray(group["value"][()], dtype=float)
            r_edges = np.asarray(group["r_edges"][()], dtype=float)
            theta_edges = np.asarray(group["theta_edges"][()], dtype=float)
    except KeyError:
        raise PlotError(f"{path}: no /maps/{name}/{{value, r_edges, theta_edges}}",
                        EXIT_IO) from None
    except OSError as e:
        raise PlotError(f"{path}: cannot be read ({e})", EXIT_IO) from None
    if value.shape != (len(r_edges) - 1, len(theta_edges) - 1):
        raise PlotError(f"{path}: /maps/{name}/value is {value.shape}, its bin edges "
                        f"{len(r_edges)} × {len(theta_edges)}", EXIT_IO)
    return value, r_edges, theta_edges


def trajectory_path(a):
    """The run's trajectory.h5: beside RUN_DIR/analysis, or where analysis.json says."""
    candidates = [os.path.join(os.path.dirname(os.path.abspath(a.dir)), "trajectory.h5")]
    recorded = a.json.get("run", {}).get("trajectory")
    if isinstance(recorded, str):
        candidates.append(recorded)
    return next((p for p in candidates if os.path.isfile(p)), None)


def motion_along_axis(a, log, max_pairs=20):
    """The polar rods' mean displacement along their axis (thick → thin) per unit time in the
    steady window, from up to `max_pairs` consecutive frame pairs of the trajectory: (mean, error)
    in mm/s, the error from the spread over frame pairs. None when the trajectory is not there."""
    path = trajectory_path(a)
    if path is None:
        log.note("trajectory.h5 not found beside the analysis: 'ahead' marks the rod axis, "
                 "the direction of motion is not measured")
        return None
    try:
        import h5py

        with h5py.File(path, "r") as f:
            bodies = f["particles/bodies"]
            table = f["parameters/rodsea/species"]
            polar = [int(k) for k in table
                     if str(np.asarray(table[k].attrs.get("kind", "")).astype(str)) == "polar_rod"]
            rods = np.flatnonzero(np.isin(bodies["species"][()], polar))
            positions, orientations = bodies["position/value"], bodies["orientation/value"]
            times = bodies["position/time"][()]
            edges = bodies["box/edges/value"]
            # By time, not by frame index: the analysis of a run joined from several directories
            # counts frames over all of them, and this file holds the latest part's.
            from_s = a.json["steady_state"].get("from_s")
            first = (int(np.searchsorted(times, float(from_s) - 1e-9)) if from_s is not None
                     else int(a.json["steady_state"].get("first_frame", 0)))
            frames = positions.shape[0]
            if rods.size == 0 or frames - first < 2:
                return None
            starts = np.unique(np.linspace(first, frames - 2,
                                           min(max_pairs, frames - 1 - first)).astype(int))
            speeds = []
            for k in starts:
                x0, x1 = positions[k][rods, :2], positions[k + 1][rods, :2]
                box = np.asarray(edges[k][:2], dtype=float)
                d = (x1 - x0).astype(float)
                d -= box * np.round(d / box)
                axis = (in_plane_axis(orientations[k][rods])
                        + in_plane_axis(orientations[k + 1][rods]))
                axis /= np.maximum(np.linalg.norm(axis, axis=1, keepdims=True), 1e-12)
                speeds.append(np.mean(np.sum(d * axis, axis=1)) / (times[k + 1] - times[k]))
    except (OSError, KeyError, ValueError) as e:
        log.note(f"{path}: direction of motion not measured ({e})")
        return None
    speeds = np.asarray(speeds)
    error = speeds.std(ddof=1) / math.sqrt(len(speeds)) if len(speeds) > 1 else float("nan")
    return float(speeds.mean()), float(error)


def in_plane_axis(q):
    """The body x axis (thick → thin for polar rods) of unit quaternions q (w first), in plane."""
    q = np.asarray(q, dtype=float)
    w, x, y, z = q[:, 0], q[:, 1], q[:, 2], q[:, 3]
    return np.stack([1 - 2 * (y * y + z * z), 2 * (x * y + w * z)], axis=1)


def corotating_jobs(a, log):
    g, r_edges, theta_edges = read_map(a, "g_r_theta")
    big_g, big_r, big_theta = read_map(a, "G_r_theta")
    contour = a.table("corotating", "flock_contour")
    level = a.parameter("corotating", "contour_level")
    sigma_f, n_avg = a.scalar("corotating", "sigma_f"), a.scalar("corotating", "N_avg")
    rod_length = a.polar[0].get("length_mm", float("nan")) if a.polar else float("nan")
    motion = motion_along_axis(a, log)
    c_theta, c_r = contour.number("theta"), contour.number("r")
    level_text = f"{100 * level:g} %" if finite(level) else "the flock"
    contour_label = (f"contour at {level_text} of max g: σ_f = {value_text(sigma_f)}, "
                     f"N_avg = {value_text(n_avg)}")
    if motion is not None and finite(motion[1]) and abs(motion[0]) > 2 * motion[1]:
        ahead = 0.0 if motion[0] > 0 else math.pi
        ahead_text = (f"ahead: rods move {'thin' if motion[0] > 0 else 'thick'} end first, "
                      f"{format_value(abs(motion[0]), motion[1], 'mm/s')}")
    elif motion is not None:
        ahead = 0.0
        ahead_text = (f"ahead = rod axis, θ = 0 (direction of motion not resolved: "
                      f"{format_value(motion[0], motion[1], 'mm/s')} along it)")
    else:
        ahead, ahead_text = 0.0, "ahead = rod axis (θ = 0; motion not measured)"

    finite_g = g[np.isfinite(g)]
    g_max = float(finite_g.max()) if finite_g.size else 1.0
    g_top = float(np.percentile(finite_g, 99)) if finite_g.size else 1.0
    clipped = g_max > 3 * g_top > 0  # a few nearly empty inner bins would wash out the map

    def draw_map(plt, value, edges_r, edges_theta, label, cmap, vmin, vmax, extend, heading):
        import matplotlib.patheffects as effects

        fig = plt.figure(figsize=SIZE_MAP)
        ax = fig.add_subplot(projection="polar")
        ax.set_facecolor("0.85")  # bins without pairs
        mesh = ax.pcolormesh(edges_theta, edges_r, np.ma.masked_invalid(value), cmap=cmap,
                             vmin=vmin, vmax=vmax, shading="flat")
        r_max = edges_r[-1]
        closed_theta, closed_r = np.append(c_theta, c_theta[:1]), np.append(c_r, c_r[:1])
        ax.plot(closed_theta, closed_r, color="k", lw=1.6, label=contour_label,
                path_effects=[effects.withStroke(linewidth=3.2, foreground="w")])
        if finite(rod_length):
            half = min(rod_length / 2, r_max)
            ax.annotate("", xy=(0.0, half), xytext=(math.pi, half),
                        arrowprops=dict(arrowstyle="-|>", lw=2.4, color="w", shrinkA=0,
                                        shrinkB=0, mutation_scale=14,
                                        path_effects=[effects.withStroke(linewidth=4,
                                                                         foreground="k")]))
            ax.plot([], [], color="w", lw=2.4, marker=">", markeredgecolor="k",
                    label="reference polar rod, thick → thin (θ = 0)")
        # θ tick labels in rad; the one in the direction of motion also says "ahead".
        ticks = np.arange(8) * math.pi / 4
        labels = ["0", "π/4", "π/2", "3π/4", "π", "−3π/4", "−π/2", "−π/4"]
        k_ahead = int(round(ahead / (math.pi / 4))) % 8
        labels[k_ahead] = f"ahead ({labels[k_ahead]})"
        ax.set_xticks(ticks)
        ax.set_xticklabels(labels)
        ax.get_xticklabels()[k_ahead].set_fontweight("bold")
        ax.set_ylim(0, r_max)
        ax.set_rlabel_position(112.5)
        ax.text(math.radians(112.5), 1.13 * r_max, "r (mm)", ha="center", va="center")
        ax.grid(True, color="w", alpha=0.35)
        fig.colorbar(mesh, ax=ax, pad=0.1, shrink=0.8, label=label, extend=extend)
        ax.set_title(f"{heading}\n{a.describe()}\n{ahead_text}", fontsize=9)
        ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.1), fontsize=8, frameon=False)
        return fig

    def draw_g(plt):
        return draw_map(plt, g, r_edges, theta_edges, "g(r, θ)", "viridis", 0.0,
                        g_top if clipped else max(g_max, 1e-12), "max" if clipped else "neither",
                        "Pair distribution g(r, θ) of polar rods, corotating frame")

    def draw_big_g(plt):
        label = r"$G(r,\theta) = \langle\cos(\theta_j - \theta_i)\rangle$"
        return draw_map(plt, big_g, big_r, big_theta, label, "RdBu_r",
                        -1.0, 1.0, "neither",
                        "Polar order correlation G(r, θ), corotating frame")

    return [("g_r_theta.png", draw_g), ("G_r_theta.png", draw_big_g)]


# --- radial pair correlations -----------------------------------------------------------------

def pair_jobs(a, log):
    polar = a.table("pair", "pair_correlation_polar", required=False)
    medium = a.table("pair", "pair_correlation_medium", required=False)
    if polar is None and medium is None:
        log.note("no pair_correlation.png: the analysis has no g(r) table")
        return []
    polar_name = a.polar[0]["name"] if a.polar else "polar"
    medium_name = next((s["name"] for s in a.media if s.get("kind") == "apolar_rod"), "medium")

    def draw(plt):
        fig, (left, right) = plt.subplots(1, 2, figsize=SIZE_WIDE)
        for table, who in ((polar, f"polar rods ({polar_name})"),
                           (medium, f"medium rods ({medium_name})")):
            if table is None:
                continue
            r = table.number("r")
            for ax, col, label, ls in ((left, "g", f"g(r), {who}", "-"),
                                       (right, "G", f"G(r), {who}", "-"),
                                       (right, "G2", f"G₂(r), {who}", "--")):
                if not table.has(col):
                    continue
                y = table.number(col)
                line, = ax.plot(r, y, lw=1.3, ls=ls, label=label)
                # The time blocks' standard error, where the analysis wrote it.
                if table.has(col + "_err"):
                    e = table.number(col + "_err")
                    ax.fill_between(r, y - e, y + e, color=line.get_color(), alpha=0.2, lw=0)
        left.axhline(1.0, color="0.4", lw=0.8, ls=":")
        right.axhline(0.0, color="0.4", lw=0.8, ls=":")
        left.set_xlabel("r (mm)")
        left.set_ylabel("g(r)")
        left.set_title("Radial distribution (1: uncorrelated)", fontsize=10)
        right.set_xlabel("r (mm)")
        right.set_ylabel("G(r) = ⟨cos(θ_i − θ_j)⟩, G₂(r) = ⟨cos 2(θ_i − θ_j)⟩")
        right.set_ylim(-1.05, 1.05)
        right.set_title("Orientational correlation", fontsize=10)
        left.legend()
        right.legend()
        fig.suptitle(f"Radial pair correlations (steady window)\n{a.describe()}", fontsize=10)
        return fig

    return [("pair_correlation.png", draw)]


# --- segregation ------------------------------------------------------------------------------

def segregation_jobs(a, log):
    t = a.table("segregation", "segregation")
    time, steady = t.number("time"), t.number("steady")
    sigma, raw = t.number("Sigma"), t.number("Sigma_raw")
    mean = a.scalar("segregation", "Sigma")
    baseline = (a.scalar("segregation", "Sigma_baseline") or {}).get("value")
    cell = a.parameter("segregation", "cell_used_x")

    def draw(plt):
        fig, ax = plt.subplots(figsize=SIZE_CURVE)
        shade_steady(ax, time, steady)
        ax.plot(time, sigma, lw=1.4, marker="o", ms=3,
                label=f"Σ − random-mixing baseline: ⟨Σ⟩ = {value_text(mean)}")
        ax.plot(time, raw, lw=1.0, ls="--", label="Σ as measured")
        if finite(baseline):
            ax.axhline(baseline, color="0.4", ls=":", lw=1,
                       label=f"random-mixing baseline {baseline:.3f}")
        ax.axhline(0.0, color="0.6", lw=0.8)
        ax.set_xlabel("t (s)")
        ax.set_ylabel("segregation Σ")
        cells = f" ({cell:g} mm cells)" if finite(cell) else ""
        title(ax, a, f"Segregation of polar rods from the medium{cells}")
        ax.legend(loc="best")
        return fig

    return [("segregation.png", draw)]


# --- bands ------------------------------------------------------------------------------------

def band_jobs(a, log):
    t = a.table("bands", "bands")
    time, steady = t.number("time"), t.number("steady")
    transverse, longitudinal = t.number("transverse"), t.number("longitudinal")
    mean_t = a.scalar("bands", "band_transverse")
    mean_l = a.scalar("bands", "band_longitudinal")
    random = (a.scalar("bands", "band_random") or {}).get("value")
    threshold = a.parameter("bands", "band_threshold")
    floors = a.parameter("bands", "threshold")

    def draw(plt):
        fig, ax = plt.subplots(figsize=SIZE_CURVE)
        shade_steady(ax, time, steady)
        ax.plot(time, longitudinal, lw=1.4, marker="o", ms=3,
                label=f"longitudinal band (mode across the motion): {value_text(mean_l)}")
        ax.plot(time, transverse, lw=1.2, marker="s", ms=3,
                label=f"transverse band (mode along the motion): {value_text(mean_t)}")
        if finite(random):
            ax.axhline(random, color="0.4", ls=":", lw=1,
                       label=f"random positions √(π/4N) = {random:.3f}")
        if finite(threshold):
            ax.axhline(threshold, color="0.4", ls="--", lw=0.8,
                       label=f"a band above {threshold:.3f} ({floors:g} × random)")
        ax.set_ylim(bottom=0.0)
        ax.set_xlabel("t (s)")
        ax.set_ylabel("|ρ_k| of the polar rods (longest modes)")
        title(ax, a, "Bands of polar rods: longest density modes")
        ax.legend(loc="best")
        return fig

    return [("bands.png", draw)]


# --- medium velocity --------------------------------------------------------------------------

def medium_velocity_jobs(a, log):
    t = a.table("medium_velocity", "medium_velocity")
    r = t.number("r")
    some = t.number("pairs") > 0
    curves = [
        ("v_along", "along the rod's axis (lab frame)", "-"),
        ("v_across", "across the axis (lab frame)", "-"),
        ("speed", "speed |v| (lab frame)", "-"),
        ("relative_v_along", "along the axis, relative to the rod", "--"),
        ("relative_speed", "|v − v_rod| (comoving frame)", "--"),
    ]
    data = [(np.where(some, t.number(col), np.nan), label, ls) for col, label, ls in curves]
    at_d = a.scalar("medium_velocity", "medium_speed_at_d")
    d = a.parameter("medium_velocity", "d")

    def draw(plt):
        fig, ax = plt.subplots(figsize=SIZE_CURVE)
        for values, label, ls in data:
            ax.plot(r, values, ls=ls, lw=1.3, marker="o", ms=2.5, label=label)
        ax.axhline(0.0, color="0.5", lw=0.8)
        ax.set_xlabel("r (mm), distance from a polar rod")
        ax.set_ylabel("medium velocity (mm/s)")
        extra = (f"; comoving speed at d = {d:g} mm: {value_text(at_d, 'mm/s')}"
                 if at_d and finite(at_d.get("value")) else "")
        title(ax, a, f"Medium velocity around polar rods{extra}")
        ax.legend(loc="best")
        return fig

    return [("medium_velocity.png", draw)]
