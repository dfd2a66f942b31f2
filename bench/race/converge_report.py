#!/usr/bin/python3
"""Tabulates bench/race/converge.sh's runs: per time step, the mean and standard error over seeds
of the collision rates and the in-plane <v²>, and each step against a quarter of it."""
import math
import sys
from collections import defaultdict

OBSERVABLES = [("body_collision_rate", "body collisions (1/s)", "body"),
               ("plate_collision_rate", "plate collisions (1/s)", "plate"),
               ("in_plane_speed2", "⟨v_xy²⟩ (mm²/s²)", "⟨v_xy²⟩"),
               ("vertical_speed2", "⟨v_z²⟩ (mm²/s²)", "⟨v_z²⟩")]


def parse(path):
    runs = defaultdict(list)
    with open(path) as f:
        for line in f:
            fields = dict(item.split("=", 1) for item in line.split() if "=" in item)
            runs[float(fields["dt"])].append({k: float(fields[k]) for k, _, _ in OBSERVABLES})
    return runs


def mean_error(values):
    n = len(values)
    m = sum(values) / n
    var = sum((v - m) ** 2 for v in values) / (n - 1) if n > 1 else 0.0
    return m, math.sqrt(var / n)


def main():
    runs = parse(sys.argv[1])
    stats = {dt: {k: mean_error([r[k] for r in rs]) for k, _, _ in OBSERVABLES}
             for dt, rs in runs.items()}
    print("| dt (µs) | " + " | ".join(label for _, label, _ in OBSERVABLES) +
          " | " + " | ".join(f"{short} vs dt/4" for _, _, short in OBSERVABLES) + " |")
    print("|---" * (1 + 2 * len(OBSERVABLES)) + "|")
    converged = []
    for dt in sorted(stats, reverse=True):
        cells = [f"{m:.4g} ± {e:.2g}" for m, e in (stats[dt][k] for k, _, _ in OBSERVABLES)]
        quarter = min(stats, key=lambda d: abs(d - dt / 4))
        versus = []
        ok = True
        if abs(quarter - dt / 4) < 1e-12:
            for k, _, _ in OBSERVABLES:
                (m1, e1), (m2, e2) = stats[dt][k], stats[quarter][k]
                sigma = abs(m1 - m2) / math.hypot(e1, e2) if e1 or e2 else 0.0
                versus.append(f"{sigma:.1f} σ ({100 * (m1 - m2) / m2:+.1f} %)")
                ok = ok and sigma < 2.0
            if ok:
                converged.append(dt)
        else:
            versus = ["–"] * len(OBSERVABLES)
        print(f"| {dt * 1e6:g} | " + " | ".join(cells) + " | " + " | ".join(versus) + " |")
    print()
    if converged:
        print(f"Largest dt within 2 σ of dt/4 in every observable: {max(converged) * 1e6:g} µs")
    else:
        print("No dt agrees with dt/4 within 2 σ in every observable")


if __name__ == "__main__":
    main()
