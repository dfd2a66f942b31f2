#!/usr/bin/python3
"""rodsea export --format gsd: a run's frames as a HOOMD GSD file (docs/export.md).

One particle per body, at its centre of mass, with its orientation quaternion (body frame ->
lab, as HOOMD's); each species a particle type whose shape is a SphereUnion of its spheres
(offsets in the body frame and diameters, mm), so OVITO draws the rods as they are; the box;
and per frame `log` entries: rodsea/time (s) and each species' polar and nematic order.

HOOMD's box is centred on the origin: x and y are shifted by -L/2, z by -w/2 (w the gap), and
L_z is the plates' whole travel (w + 2A). Units stay mm and s.

Called by rodsea (which has checked every frame first) as
    rodsea_gsd.py TRAJECTORY OUTPUT FRAMES_FILE HEIGHT
with FRAMES_FILE holding the frame indices, one per line, and HEIGHT the box's L_z (mm).
"""
import sys


def main(trajectory, output, frames_file, height):
    try:
        import gsd.hoomd
        import h5py
        import numpy as np
    except ImportError as e:
        sys.stderr.write(f"rodsea export: {e.name} is missing: install Debian's python3-gsd, "
                         "python3-h5py and python3-numpy (./scripts/install-deps.sh)\n")
        return 1
    frames = [int(line) for line in open(frames_file) if line.strip()]
    with h5py.File(trajectory, "r") as f:
        bodies = f["particles/bodies"]
        species = bodies["species"][()].astype(np.uint32)
        params = f["parameters/rodsea/species"]
        names, shapes = [], []
        for i in range(len(params)):
            g = params[str(i)]
            name = g.attrs["name"]
            names.append(name.decode() if isinstance(name, bytes) else str(name))
            shapes.append({"type": "SphereUnion",
                           "centers": g["sphere_offsets"][()].astype(float).tolist(),
                           "diameters": (2.0 * g["sphere_radii"][()]).astype(float).tolist()})
        lx, ly, gap = bodies["box/edges/value"][0]
        steps = bodies["position/step"][()]
        times = bodies["position/time"][()]
        logged = {}
        for name in names:
            for kind in ("polar_order_", "nematic_order_"):
                column = kind + name
                if "observables/" + column in f:
                    logged[column] = f["observables/" + column + "/value"][()]
        # gsd 3 names a frame Frame and opens with "w"; Debian 12's gsd 2.7 says Snapshot, "wb".
        make_frame = getattr(gsd.hoomd, "Frame", None) or gsd.hoomd.Snapshot
        mode = "w" if hasattr(gsd.hoomd, "Frame") else "wb"
        with gsd.hoomd.open(output, mode) as out:
            for k in frames:
                frame = make_frame()
                frame.configuration.step = int(steps[k])
                frame.configuration.box = [float(lx), float(ly), float(height), 0.0, 0.0, 0.0]
                p = bodies["position/value"][k].astype(np.float32)
                p[:, 0] -= np.float32(0.5 * lx)
                p[:, 1] -= np.float32(0.5 * ly)
                p[:, 2] -= np.float32(0.5 * gap)
                frame.particles.N = len(species)
                frame.particles.position = p
                frame.particles.orientation = bodies["orientation/value"][k].astype(np.float32)
                frame.particles.velocity = bodies["velocity/value"][k].astype(np.float32)
                frame.particles.typeid = species
                frame.particles.types = names
                frame.particles.type_shapes = shapes
                frame.log["rodsea/time"] = np.array([times[k]])
                for column, values in logged.items():
                    frame.log["rodsea/" + column] = np.array([values[k]])
                out.append(frame)
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 5:
        sys.stderr.write("usage: rodsea_gsd.py TRAJECTORY OUTPUT FRAMES_FILE HEIGHT\n")
        sys.exit(2)
    sys.exit(main(*sys.argv[1:]))
