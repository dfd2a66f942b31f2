"""A campaign's figures (`rodsea campaign collect`): curves of the collected table's scalars
against an axis, one per value of a series axis, with the replicates' error bars; and maps of one
scalar over two axes with its contour at a level (the paper's phase diagrams).

The input is collected/figures.json, written by collect:
  {"rodsea_campaign_figures": 1, "table": "points.csv",
   "figures": [{"name", "kind": "curve"|"map", "x", "y": [...], "series", "serieslabel", "level",
                "xlabel", "ylabel", "title", "logx", "logy", "points": [point names]}]}
x and series are columns of the table (the axes, named as collect names them); y are scalars,
each with its <y>_err column; `points` are the rows (by their `point` column) the figure shows.
"""
import json
import os

import numpy as np

from .common import SIZE_CURVE, PlotError, read_csv
from .table_figures import boundary_triangles

MARKERS = "os^vDP*Xhp"


class CampaignInput:
    """collected/figures.json of a campaign."""

    kind = "campaign"

    def __init__(self, path, spec):
        self.path = path
        self.spec = spec


def read_spec(path):
    """The figures.json of a campaign, or None when the JSON file is something else."""
    try:
        with open(path, encoding="utf-8") as f:
            spec = json.load(f)
    except (OSError, ValueError):
        return None
    if not isinstance(spec, dict) or spec.get("rodsea_campaign_figures") != 1:
        return None
    return spec


def figure_names(spec):
    return [f["name"] + ".png" for f in spec.get("figures", [])]


def numeric(values):
    try:
        return np.array([float(v) for v in values])
    except ValueError:
        return None


def sorted_values(values):
    """The distinct values of a column, numerically when every one is a number."""
    distinct = sorted(set(values))
    as_numbers = numeric(distinct)
    if as_numbers is not None:
        return [v for _, v in sorted(zip(as_numbers, distinct))]
    return distinct


def finish_axes(ax, f, default_ylabel):
    """The figure's labels, log scales and title, as its [[figure]] gives them."""
    ax.set_xlabel(f.get("xlabel") or f["x"])
    ax.set_ylabel(f.get("ylabel") or default_ylabel)
    if f.get("logx"):
        ax.set_xscale("log")
    if f.get("logy"):
        ax.set_yscale("log")
    if f.get("title"):
        ax.set_title(f["title"], fontsize=10)


def curve(table, rows, f, log):
    x_all = numeric(table.text(f["x"]))
    if x_all is None:
        log.note(f"no {f['name']}.png: the axis {f['x']} is not numeric")
        return []
    series = f.get("series") or ""
    series_name = f.get("serieslabel") or series
    groups = []  # (label, y column, rows)
    for y in f["y"]:
        if series:
            text = table.text(series)
            for value in sorted_values([text[i] for i in rows]):
                label = f"{series_name} = {value}" + (f", {y}" if len(f["y"]) > 1 else "")
                groups.append((label, y, [i for i in rows if text[i] == value]))
        else:
            groups.append((y if len(f["y"]) > 1 else "", y, rows))

    def draw(plt):
        fig, ax = plt.subplots(figsize=SIZE_CURVE)
        for k, (label, y, members) in enumerate(groups):
            ys, errs = table.number(y), table.number(y + "_err")
            members = sorted((i for i in members if np.isfinite(ys[i])), key=lambda i: x_all[i])
            if not members:
                continue
            ax.errorbar(x_all[members], ys[members], yerr=errs[members],
                        marker=MARKERS[k % len(MARKERS)], ms=5, capsize=3, lw=1.2,
                        label=label or None)
        finish_axes(ax, f, ", ".join(f["y"]))
        if any(label for label, _, _ in groups):
            ax.legend(loc="best", fontsize=8)
        return fig

    return [(f["name"] + ".png", draw)]


def scalar_map(table, rows, f, log):
    name, y = f["name"], f["y"][0]
    x_all, v_all = numeric(table.text(f["x"])), numeric(table.text(f["series"]))
    if x_all is None or v_all is None:
        log.note(f"no {name}.png: the axes {f['x']} and {f['series']} must be numeric")
        return []
    z_all = table.number(y)
    rows = [i for i in rows if np.isfinite(z_all[i])]
    if not rows:
        log.note(f"no {name}.png: no point has {y}")
        return []
    x, v, z = x_all[rows], v_all[rows], z_all[rows]
    level = f.get("level")
    triangles = None
    if level is not None:
        triangles, why_not = boundary_triangles(x, v, z, level, y, "point")
        if triangles is None:
            log.note(f"{name}.png: the contour {y} = {level} is not drawn ({why_not})")

    def draw(plt):
        fig, ax = plt.subplots(figsize=SIZE_CURVE)
        if level is None:
            dots = ax.scatter(x, v, c=z, s=90, cmap="viridis", zorder=3)
        else:
            above = z > level
            dots = ax.scatter(x[~above], v[~above], c=z[~above], s=90, cmap="viridis",
                              vmin=z.min(), vmax=z.max(), zorder=3,
                              label=f"{y} ≤ {level} (filled)")
            ax.scatter(x[above], v[above], s=90, facecolors="none", c=None,
                       edgecolors=plt.get_cmap("viridis")((z[above] - z.min()) /
                                                          max(np.ptp(z), 1e-300)),
                       linewidths=2, zorder=3, label=f"{y} > {level} (hollow)")
            if triangles is not None:
                contour = ax.tricontour(triangles, z, levels=[level], colors="C3",
                                        linestyles="--", linewidths=1.5)
                if contour.allsegs[0]:
                    ax.plot([], [], color="C3", ls="--", label=f"{y} = {level} (interpolated)")
            ax.legend(loc="best", fontsize=8)
        fig.colorbar(dots, ax=ax, label=y)
        for values, set_limits, log_axis in ((x, ax.set_xlim, f.get("logx")),
                                             (v, ax.set_ylim, f.get("logy"))):
            positive = values[values > 0]
            low, high = float(np.min(values)), float(np.max(values))
            if log_axis and positive.size:  # a log axis shows the positive values only
                set_limits(float(positive.min()) / 1.3, float(positive.max()) * 1.3)
            else:
                pad = 0.08 * (high - low) if high > low else max(0.05, 0.1 * abs(low))
                set_limits(low - pad, high + pad)
        for i in range(len(z)):
            ax.annotate(f"{z[i]:.2f}", (x[i], v[i]), textcoords="offset points", xytext=(6, 5),
                        fontsize=7, color="0.3")
        finish_axes(ax, f, f.get("serieslabel") or f["series"])
        return fig

    return [(name + ".png", draw)]


def plan(source, log):
    spec = source.spec
    table_path = os.path.join(os.path.dirname(source.path) or ".", spec.get("table", ""))
    table = read_csv(table_path)
    if not table.has("point"):
        raise PlotError(f"{table_path}: not a campaign's points table (no column 'point')")
    names = table.text("point")
    jobs = []
    for f in spec.get("figures", []):
        if not log.wants(f["name"] + ".png"):
            continue
        columns = [f["x"]] + ([f["series"]] if f.get("series") else []) + list(f["y"])
        missing = [c for c in columns if not table.has(c)]
        if missing:
            scalars = [c for c in table.columns if c.endswith("_err")]
            log.note(f"no {f['name']}.png: {table_path} has no column {', '.join(missing)} "
                     f"(its scalars: {', '.join(c[:-4] for c in scalars) or 'none'})")
            continue
        wanted = set(f.get("points", []))
        rows = [i for i, n in enumerate(names) if n in wanted]
        if not rows:
            log.note(f"no {f['name']}.png: none of its points has finished runs yet")
            continue
        shown = {f["x"], f.get("series") or f["x"]}
        others = [a for a in f.get("axes", []) if a not in shown and table.has(a)]
        if others:
            varying = [a for a in others if len({table.text(a)[i] for i in rows}) > 1]
            if varying:
                log.note(f"{f['name']}.png: its points also differ in {', '.join(varying)}, "
                         "which neither x nor series shows: points of several curves are "
                         "joined (give `when` or `series` for them)")
        jobs += (scalar_map if f["kind"] == "map" else curve)(table, rows, f, log)
    return jobs
