#!/usr/bin/python3
"""The demo of the README, from Python: run it, analyse it, plot P(t) and the g(r, θ) map.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/demo.py [--duration S] [--out DIR]

Writes DIR/polar_order.png and DIR/g_r_theta.png (default DIR: out/python-demo). docs/python.md
walks through it.
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import rodsea  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--duration", type=float, default=0.2, help="simulated seconds")
    parser.add_argument("--out", default="out/python-demo", help="where the PNGs go")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)

    # 1. The config: the demo's file, with a duration of our choosing. A dict works too.
    config = rodsea.load_config({
        "box": {"side": 30.0},
        "species": [
            {"name": "polar", "kind": "polar_rod", "area_fraction": 0.05},
            {"name": "medium", "kind": "apolar_rod", "length": 2.5, "area_fraction": 0.30},
        ],
        "time": {"duration": args.duration},
        "output": {"interval": 0.01},
    })
    print(config, f"{config.total_steps} steps of {config.dt * 1e6:g} µs")

    # 2. Run it, sampling P and S of the polar rods every output interval.
    sim = rodsea.Simulation(config)
    polar = sim.species == 0                    # species in config order: 0 is "polar"
    steps = round(config.output_interval / config.dt)
    times, P = [], []
    maps = rodsea.CorotatingMaps(r_max=15.0, r_bins=30, theta_bins=36)
    while sim.step < config.total_steps:
        sim.run(steps=min(steps, config.total_steps - sim.step))  # the GIL is free meanwhile
        angles = rodsea.in_plane_angles(sim.quaternions[polar])
        times.append(sim.time)
        P.append(rodsea.OrderParameters().compute(angles).P)
        maps.compute(config.box, sim.positions[polar], angles)
    print(f"P at the end: {P[-1]:.3f}; wall time per stage: "
          + ", ".join(f"{k} {v:.2f} s" for k, v in sim.timings().items()))

    # 3. P(t).
    fig, ax = plt.subplots(figsize=(5, 3.2))
    ax.plot(times, P)
    ax.set_xlabel("t (s)")
    ax.set_ylabel("P of the polar rods")
    fig.tight_layout()
    fig.savefig(os.path.join(args.out, "polar_order.png"), dpi=120)

    # 4. g(r, θ) in the rods' own frame, as the paper's Fig. 2.
    r, theta = maps.r_edges, maps.theta_edges
    fig, ax = plt.subplots(subplot_kw={"projection": "polar"}, figsize=(4.5, 4.5))
    ax.grid(False)
    mesh = ax.pcolormesh(theta, r, np.nan_to_num(maps.g), shading="flat")
    fig.colorbar(mesh, ax=ax, label="g(r, θ)")
    ax.set_title("polar rods, corotating frame (r in mm)")
    fig.savefig(os.path.join(args.out, "g_r_theta.png"), dpi=120)
    print("wrote", os.path.join(args.out, "polar_order.png"), "and",
          os.path.join(args.out, "g_r_theta.png"))


if __name__ == "__main__":
    main()
