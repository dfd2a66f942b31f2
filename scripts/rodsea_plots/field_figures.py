"""Figures of the beyond-paper observables (docs/analysis.md): coarse-grained field maps, the
polar-rich interface, nematic defects and their tracks, and flocks against +1/2 defects.

Read and checked before anything is drawn, like run_figures; layout: docs/analysis.md.
"""
import os

import numpy as np

from .common import (
    EXIT_IO,
    SIZE_CURVE,
    SIZE_WIDE,
    PlotError,
    finite,
    message_panel,
    missing_module,
    shade_steady,
)

FIGURES = {
    "fields": ["fields_mean.png", "fields_last.png", "interface.png"],
    "defects": ["defects.png"],
    "flock_defects": ["flock_defects.png"],
}


def read_datasets(a, observable, paths):
    """{path: array} of the observable's analysis.h5 datasets, checked to be listed."""
    listed = (a.observable(observable) or {}).get("maps", {})
    try:
        import h5py
    except ImportError:
        raise missing_module("h5py") from None
    out = {}
    path = os.path.join(a.dir, "analysis.h5")
    try:
        with h5py.File(path, "r") as f:
            for p in paths:
                if p not in listed:
                    raise PlotError(f"{a.path}: '{observable}' lists no dataset '{p}'")
                out[p] = np.asarray(f[p][()], dtype=float)
    except KeyError as e:
        raise PlotError(f"{path}: no dataset {e}; run `rodsea analyze` again", EXIT_IO) from None
    except OSError as e:
        raise PlotError(f"{path}: cannot be read ({e})", EXIT_IO) from None
    return out


def field_panels(a):
    """The maps each figure shows: (dataset name under fields/<kind>/, title, kind of map)."""
    panels = []
    for s in a.species:
        panels.append((s["name"], "area_fraction", f"φ, {s['name']}", "phi"))
    for s in a.polar:
        panels.append((s["name"], "px", f"polarisation p, {s['name']}", "polar"))
    for s in a.media:
        if s.get("kind") == "apolar_rod":
            panels.append((s["name"], "qxx", f"S and director, {s['name']}", "nematic"))
    return panels


def draw_maps(plt, a, maps, x, y, panels, heading, defects=None):
    fig, axes = plt.subplots(1, len(panels), figsize=SIZE_WIDE, squeeze=False,
                             constrained_layout=True)
    # Cell centres sit at (i + ½) dx: the cells span 0 to n dx = 2 x[0] n.
    extent = (0.0, 2.0 * x[0] * len(x), 0.0, 2.0 * y[0] * len(y))
    X, Y = np.meshgrid(x, y)
    for ax, (species, field, label, kind) in zip(axes[0], panels):
        if kind == "phi":
            im = ax.imshow(maps[(species, "area_fraction")], origin="lower", extent=extent,
                           cmap="viridis", vmin=0.0)
            fig.colorbar(im, ax=ax, fraction=0.046, pad=0.02, label="φ")
        elif kind == "polar":
            px, py = maps[(species, "px")], maps[(species, "py")]
            im = ax.imshow(np.hypot(px, py), origin="lower", extent=extent, cmap="magma",
                           vmin=0.0, vmax=1.0)
            fig.colorbar(im, ax=ax, fraction=0.046, pad=0.02, label="|p|")
            # An arrow of |p| = 1 spans 0.8 of a cell.
            ax.quiver(X, Y, px, py, color="deepskyblue", scale=1.25 / (2.0 * x[0]),
                      scale_units="xy", width=0.005)
        else:
            qxx, qxy = maps[(species, "qxx")], maps[(species, "qxy")]
            s = np.hypot(qxx, qxy)
            im = ax.imshow(s, origin="lower", extent=extent, cmap="Greys", vmin=0.0, vmax=1.0)
            fig.colorbar(im, ax=ax, fraction=0.046, pad=0.02, label="S")
            angle = 0.5 * np.arctan2(qxy, qxx)
            ax.quiver(X, Y, s * np.cos(angle), s * np.sin(angle), color="navy", headwidth=0,
                      headlength=0, headaxislength=0, pivot="middle", width=0.004)
            if defects is not None:
                for charge, marker, colour, name in ((1, "o", "red", "+1/2"),
                                                     (-1, "^", "blue", "−1/2")):
                    pick = defects["twice_charge"] == charge
                    if pick.any():
                        ax.scatter(defects["x"][pick], defects["y"][pick], marker=marker,
                                   s=40, color=colour, label=f"{name} defects",
                                   edgecolors="white", linewidths=0.5, zorder=3)
                plus = (defects["twice_charge"] == 1) & np.isfinite(defects["orientation"])
                if plus.any():
                    o = defects["orientation"][plus]
                    ax.quiver(defects["x"][plus], defects["y"][plus], np.cos(o), np.sin(o),
                              color="red", width=0.006, zorder=3)
                if (defects["twice_charge"] != 0).any():
                    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.3), ncol=2,
                              fontsize=7)
        ax.set_title(label, fontsize=8)
        ax.set_xlabel("x (mm)")
        ax.set_ylabel("y (mm)")
        ax.set_aspect("equal")
    fig.suptitle(f"{heading}\n{a.describe()}", fontsize=10)
    return fig


def field_jobs(a, log):
    panels = field_panels(a)
    names = sorted({(s, f) for s, f, _, _ in panels} |
                   {(s, "py") for s, f, _, k in panels if k == "polar"} |
                   {(s, "qxy") for s, f, _, k in panels if k == "nematic"})
    wanted = [f"fields/mean/{s}/{f}" for s, f in names] + \
             [f"fields/series/{s}/{f}" for s, f in names] + ["fields/x", "fields/y", "fields/time"]
    d = read_datasets(a, "fields", wanted)
    x, y = d["fields/x"], d["fields/y"]
    mean = {(s, f): d[f"fields/mean/{s}/{f}"] for s, f in names}
    series = {(s, f): d[f"fields/series/{s}/{f}"] for s, f in names}
    times = d["fields/time"]
    jobs = []
    if a.steady_frames() > 0:
        jobs.append(("fields_mean.png",
                     lambda plt: draw_maps(plt, a, mean, x, y, panels,
                                           "Coarse-grained fields, steady-window average")))
    else:
        log.note("no fields_mean.png: the analysis has no steady frame")
    if len(times):
        last = {key: v[-1] for key, v in series.items()}
        defects = None
        if a.observable("defects") is not None:
            dd = read_datasets(a, "defects", ["defects/time", "defects/x", "defects/y",
                                              "defects/twice_charge", "defects/orientation"])
            at = np.isclose(dd["defects/time"], times[-1], rtol=0, atol=1e-9)
            defects = {k.split("/")[1]: v[at] for k, v in dd.items()}
        jobs.append(("fields_last.png",
                     lambda plt: draw_maps(plt, a, last, x, y, panels,
                                           f"Coarse-grained fields at t = {times[-1]:g} s",
                                           defects)))
    t = a.table("fields", "interface", required=False)
    if t is not None:
        time, steady = t.number("time"), t.number("steady")
        length, rich = t.number("length"), t.number("polar_rich_fraction")
        level = a.parameter("fields", "interface_level")

        def draw_interface(plt):
            fig, ax = plt.subplots(figsize=SIZE_CURVE)
            shade_steady(ax, time, steady)
            ax.plot(time, length, lw=1.4, label="interface length")
            ax.set_xlabel("t (s)")
            ax.set_ylabel("interface length (mm)")
            right = ax.twinx()
            right.plot(time, rich, color="0.35", ls=":", lw=1.4, label="polar-rich fraction")
            right.set_ylabel("polar-rich fraction of the box")
            right.grid(False)
            h, l = ax.get_legend_handles_labels()
            h2, l2 = right.get_legend_handles_labels()
            ax.legend(h + h2, l + l2, loc="upper left")
            lvl = f" (polar share > {level:g})" if finite(level) else ""
            ax.set_title(f"Interface of the polar-rich regions{lvl}\n{a.describe()}", fontsize=10)
            return fig

        jobs.append(("interface.png", draw_interface))
    else:
        log.note("no interface.png: the run has no polar rods and medium to separate")
    return jobs


def defect_jobs(a, log):
    t = a.table("defects", "defect_counts")
    time, steady = t.number("time"), t.number("steady")
    plus, minus = t.number("plus_half"), t.number("minus_half")
    tracks = a.table("defects", "defect_tracks")
    charge, lifetime, ended = (tracks.number("charge"), tracks.number("lifetime"),
                               tracks.number("ended"))
    interval = a.json.get("run", {}).get("frame_interval_s")

    def draw(plt):
        fig, (left, right) = plt.subplots(1, 2, figsize=SIZE_WIDE)
        shade_steady(left, time, steady)
        left.plot(time, plus, lw=1.3, color="red", label="+1/2")
        left.plot(time, minus, lw=1.3, ls="--", color="blue", label="−1/2")
        left.set_xlabel("t (s)")
        left.set_ylabel("defects in the box")
        left.set_title("Nematic defects of the medium", fontsize=10)
        left.legend(loc="best")
        done = (ended > 0.5) & (np.abs(charge) == 0.5)
        if done.any():
            # Lifetimes are whole numbers of frame intervals: one bar per interval.
            step = interval if finite(interval) and interval > 0 else 1.0
            top = np.nanmax(lifetime[done])
            edges = (np.arange(int(round(top / step)) + 2) - 0.5) * step
            right.hist(lifetime[done], bins=edges, color="C2")
            right.set_yscale("log")
        else:
            message_panel(right, "no ±1/2 track ended inside the run")
        right.set_xlabel("lifetime of a ±1/2 track (s; 0: seen in one frame)")
        right.set_ylabel("tracks")
        right.set_title("Defect lifetimes", fontsize=10)
        fig.suptitle(a.describe(), fontsize=9)
        return fig

    return [("defects.png", draw)]


def flock_defect_jobs(a, log):
    h = a.table("flock_defects", "flock_defect_distance_histogram")
    pairs = a.table("flock_defects", "flock_defect_pairs")
    low, high = h.number("r_low"), h.number("r_high")
    flocks, random = h.number("flocks"), h.number("random")
    alignment = pairs.number("alignment")

    def draw(plt):
        fig, (left, right) = plt.subplots(1, 2, figsize=SIZE_WIDE)
        if flocks.sum() > 0:
            centres = 0.5 * (low + high)
            width = (high - low)[0] if len(high) else 1.0
            left.bar(centres, flocks / flocks.sum(), width=width, alpha=0.6, label="flocks")
            left.step(centres, random / max(random.sum(), 1e-300), where="mid", color="k",
                      label="random points")
            left.legend(loc="best")
        else:
            message_panel(left, "no steady frame with flocks and +1/2 defects")
        left.set_xlabel("distance to the nearest +1/2 defect (mm)")
        left.set_ylabel("fraction")
        if len(alignment):
            right.hist(alignment, bins=20, range=(-1, 1), color="C3")
        else:
            message_panel(right, "no flock next to a +1/2 defect")
        right.set_xlabel("cos(flock heading − defect orientation)")
        right.set_ylabel("flock-frames")
        fig.suptitle(f"Flocks and +1/2 defects of the medium\n{a.describe()}", fontsize=10)
        return fig

    return [("flock_defects.png", draw)]


BUILDERS = {"fields": field_jobs, "defects": defect_jobs, "flock_defects": flock_defect_jobs}
