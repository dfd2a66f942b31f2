#!/usr/bin/python3
"""Top view of a rodsea demo output directory, drawn to DIR/snapshot.png.

Every body is drawn as its true outline (the union of its spheres' discs in the plane). Polar
rods are coloured by the direction of their axis (thick -> thin) on a cyclic colour wheel; the
medium is grey. A second panel shows the polar order P(t) from timeseries.csv.

usage: /usr/bin/python3 scripts/plot_snapshot.py DIR
Needs Debian's python3-numpy and python3-matplotlib (scripts/install-deps.sh installs them).
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import PatchCollection  # noqa: E402
from matplotlib.patches import Circle  # noqa: E402
import numpy as np  # noqa: E402


def read_rows(path):
    with open(path) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def box_size(path):
    with open(path) as f:
        header = f.readline()
    # "# sphere offsets ...; box LX x LY mm"
    words = header.split("box", 1)[1].split()
    return float(words[0]), float(words[2])


def rotate(q, v):
    w, x, y, z = q
    u = np.array([x, y, z])
    t = 2.0 * np.cross(u, v)
    return v + w * t + np.cross(u, t)


def main(argv):
    if len(argv) != 2:
        sys.exit(__doc__)
    out = argv[1]
    for name in ("bodies.csv", "shapes.csv", "timeseries.csv"):
        if not os.path.exists(os.path.join(out, name)):
            sys.exit(f"plot_snapshot: {os.path.join(out, name)} is missing; run `rodsea demo --out {out}` first")
    lx, ly = box_size(os.path.join(out, "shapes.csv"))
    shapes = {}
    for row in read_rows(os.path.join(out, "shapes.csv")):
        shapes.setdefault(row["species"], []).append(
            (np.array([float(row["ox"]), float(row["oy"]), float(row["oz"])]), float(row["radius"])))

    fig, (ax, axp) = plt.subplots(1, 2, figsize=(13, 6), gridspec_kw={"width_ratios": [1.15, 1]})
    wheel = plt.get_cmap("hsv")
    medium, polar, colours = [], [], []
    for body in read_rows(os.path.join(out, "bodies.csv")):
        x = np.array([float(body["x"]), float(body["y"]), float(body["z"])])
        q = tuple(float(body[k]) for k in ("qw", "qx", "qy", "qz"))
        is_polar = body["kind"] == "polar_rod"
        for offset, r in shapes[body["species"]]:
            c = x + rotate(q, offset)
            # Draw the disc and its periodic images that reach into the box.
            for sx in (-lx, 0.0, lx):
                for sy in (-ly, 0.0, ly):
                    cx, cy = (c[0] % lx) + sx, (c[1] % ly) + sy
                    if -r < cx < lx + r and -r < cy < ly + r:
                        disc = Circle((cx, cy), r)
                        if is_polar:
                            polar.append(disc)
                            colours.append((float(body["theta"]) % (2 * math.pi)) / (2 * math.pi))
                        else:
                            medium.append(disc)
    ax.add_collection(PatchCollection(medium, facecolor="0.72", edgecolor="none"))
    pc = PatchCollection(polar, cmap=wheel, edgecolor="none")
    pc.set_array(np.array(colours))
    pc.set_clim(0, 1)
    ax.add_collection(pc)
    ax.set_xlim(0, lx)
    ax.set_ylim(0, ly)
    ax.set_aspect("equal")
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("y (mm)")
    series = read_rows(os.path.join(out, "timeseries.csv"))
    t_end = float(series[-1]["time"])
    ax.set_title(f"t = {t_end:.3f} s, P = {float(series[-1]['P_polar']):.2f}")
    cbar = fig.colorbar(pc, ax=ax, fraction=0.046, pad=0.04, ticks=[0, 0.25, 0.5, 0.75, 1])
    cbar.ax.set_yticklabels(["0", "90°", "180°", "270°", "360°"])
    cbar.set_label("polar rod axis angle θ (thick → thin)")

    t = np.array([float(r["time"]) for r in series])
    axp.plot(t, [float(r["P_polar"]) for r in series], label="P (polar rods)")
    axp.plot(t, [float(r["S_apolar"]) for r in series], label="S (apolar medium)")
    axp.set_xlabel("time (s)")
    axp.set_ylabel("order parameter")
    axp.set_ylim(0, 1.05)
    axp.legend()
    fig.tight_layout()
    target = os.path.join(out, "snapshot.png")
    fig.savefig(target + ".tmp.png", dpi=110)
    os.replace(target + ".tmp.png", target)
    print(f"wrote {target}")


if __name__ == "__main__":
    main(sys.argv)
