#!/usr/bin/python3
"""Top view of a rodsea run directory, drawn to DIR/snapshot.png.

Reads DIR/trajectory.h5 (H5MD, written by `rodsea run`). Every body of the chosen frame is drawn
as its true outline (the union of its spheres' discs in the plane, periodic images included).
Polar rods are coloured by the direction of their axis (thick -> thin) on a cyclic colour wheel;
the medium is grey. A second panel shows the polar order P(t) of polar rods and the nematic order
S(t) of the other species, from the file's time series.

usage: /usr/bin/python3 scripts/plot_snapshot.py DIR [FRAME]   (FRAME defaults to the last)
Needs Debian's python3-h5py, -numpy and -matplotlib (scripts/install-deps.sh installs them).
"""
import math
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import PatchCollection  # noqa: E402
from matplotlib.patches import Circle  # noqa: E402
import numpy as np  # noqa: E402


def rotate(q, v):
    """Rotates the vectors v (n x 3) by the unit quaternions q (n x 4, w first)."""
    w, u = q[:, :1], q[:, 1:]
    t = 2.0 * np.cross(u, v)
    return v + w * t + np.cross(u, t)


def main(argv):
    if len(argv) not in (2, 3):
        sys.exit(__doc__)
    out = argv[1]
    path = os.path.join(out, "trajectory.h5")
    if not os.path.exists(path):
        sys.exit(f"plot_snapshot: {path} is missing; run `rodsea run CONFIG --out {out}` first")
    f = h5py.File(path, "r")
    bodies = f["particles/bodies"]
    frames = bodies["position/value"].shape[0]
    frame = int(argv[2]) if len(argv) == 3 else frames - 1
    if not -frames <= frame < frames:
        sys.exit(f"plot_snapshot: frame {frame} is outside the {frames} frames of {path}")
    lx, ly, _ = bodies["box/edges/value"][frame]
    x = bodies["position/value"][frame].astype(float)
    q = bodies["orientation/value"][frame].astype(float)
    species = bodies["species"][:]
    kinds, names, shapes = [], [], []
    table = f["parameters/rodsea/species"]
    for s in range(len(table)):
        g = table[str(s)]
        kinds.append(g.attrs["kind"])
        names.append(g.attrs["name"])
        shapes.append((g["sphere_offsets"][:], g["sphere_radii"][:]))
    axis = rotate(q, np.tile([1.0, 0.0, 0.0], (len(x), 1)))
    theta = np.arctan2(axis[:, 1], axis[:, 0])

    fig, (ax, axp) = plt.subplots(1, 2, figsize=(13, 6), gridspec_kw={"width_ratios": [1.15, 1]})
    medium, polar, colours = [], [], []
    for s, (offsets, radii) in enumerate(shapes):
        members = np.flatnonzero(species == s)
        is_polar = kinds[s] == "polar_rod"
        for k, r in enumerate(radii):
            centres = x[members] + rotate(q[members], np.tile(offsets[k], (len(members), 1)))
            for sx in (-lx, 0.0, lx):  # periodic images that reach into the box
                for sy in (-ly, 0.0, ly):
                    cx, cy = centres[:, 0] % lx + sx, centres[:, 1] % ly + sy
                    inside = (cx > -r) & (cx < lx + r) & (cy > -r) & (cy < ly + r)
                    for i in np.flatnonzero(inside):
                        disc = Circle((cx[i], cy[i]), r)
                        if is_polar:
                            polar.append(disc)
                            colours.append((theta[members[i]] % (2 * math.pi)) / (2 * math.pi))
                        else:
                            medium.append(disc)
    ax.add_collection(PatchCollection(medium, facecolor="0.72", edgecolor="none"))
    pc = PatchCollection(polar, cmap=plt.get_cmap("hsv"), edgecolor="none")
    pc.set_array(np.array(colours))
    pc.set_clim(0, 1)
    ax.add_collection(pc)
    ax.set_xlim(0, lx)
    ax.set_ylim(0, ly)
    ax.set_aspect("equal")
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("y (mm)")
    t = f["observables"][f"polar_order_{names[0]}"]["time"][:]
    polar_names = [n for n, k in zip(names, kinds) if k == "polar_rod"]
    title = f"t = {bodies['position/time'][frame]:.3f} s"
    if polar_names:
        p_now = f["observables"][f"polar_order_{polar_names[0]}"]["value"][min(frame % frames, len(t) - 1)]
        title += f", P = {p_now:.2f}"
    ax.set_title(title)
    cbar = fig.colorbar(pc, ax=ax, fraction=0.046, pad=0.04, ticks=[0, 0.25, 0.5, 0.75, 1])
    cbar.ax.set_yticklabels(["0", "90°", "180°", "270°", "360°"])
    cbar.set_label("polar rod axis angle θ (thick → thin)")

    for n, k in zip(names, kinds):
        if k == "polar_rod":
            axp.plot(t, f["observables"][f"polar_order_{n}"]["value"][:], label=f"P ({n})")
        else:
            axp.plot(t, f["observables"][f"nematic_order_{n}"]["value"][:], label=f"S ({n})")
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
