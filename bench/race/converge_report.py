#!/usr/bin/python3
"""Tabulates the runs of bench/race/converge.sh (rodsea) or converge_lammps.sh (LAMMPS): per time
step, the mean and standard error over seeds of each observable the runs report (rodsea: the
collision rates and <v²> in the plane and along z; LAMMPS: the two <v²>), and each step against a
quarter of it."""
import math
import sys
from collections import defaultdict

# What the race judges both codes on (race.sh): the observables that LAMMPS reports too.
RACE_OBSERVABLES = ("in_plane_speed2", "vertical_speed2")

OBSERVABLES = [("body_collision_rate", "body collisions (1/s)", "body"),
               ("plate_collision_rate", "plate collisions (1/s)", "plate"),
               ("in_plane_speed2", "⟨v_xy²⟩ (mm²/s²)", "⟨v_xy²⟩"),
               ("vertical_speed2", "⟨v_z²⟩ (mm²/s²)", "⟨v_z²⟩")]


def parse(path):
    """The runs by dt, and the observables that every run reports."""
    runs = defaultdict(list)
    present = {k for k, _, _ in OBSERVABLES}
    with open(path) as f:
        for line in f:
            fields = dict(item.split("=", 1) for item in line.split() if "=" in item)
            present &= fields.keys()
            runs[float(fields["dt"])].append(fields)
    observables = [o for o in OBSERVABLES if o[0] in present]
    return {dt: [{k: float(r[k]) for k, _, _ in observables} for r in rs]
            for dt, rs in runs.items()}, observables


def mean_error(values):
    n = len(values)
    m = sum(values) / n
    var = sum((v - m) ** 2 for v in values) / (n - 1) if n > 1 else 0.0
    return m, math.sqrt(var / n)


def main():
    runs, observables = parse(sys.argv[1])
    stats = {dt: {k: mean_error([r[k] for r in rs]) for k, _, _ in observables}
             for dt, rs in runs.items()}
    print("| dt (µs) | " + " | ".join(label for _, label, _ in observables) +
          " | " + " | ".join(f"{short} vs dt/4" for _, _, short in observables) + " |")
    print("|---" * (1 + 2 * len(observables)) + "|")
    sigmas = {}  # dt -> observable -> distance from dt/4 in standard errors
    for dt in sorted(stats, reverse=True):
        cells = [f"{m:.4g} ± {e:.2g}" for m, e in (stats[dt][k] for k, _, _ in observables)]
        quarter = min(stats, key=lambda d: abs(d - dt / 4))
        versus = ["–"] * len(observables)
        if abs(quarter - dt / 4) < 1e-12:
            sigmas[dt] = {}
            versus = []
            for k, _, _ in observables:
                (m1, e1), (m2, e2) = stats[dt][k], stats[quarter][k]
                sigmas[dt][k] = abs(m1 - m2) / math.hypot(e1, e2) if e1 or e2 else 0.0
                versus.append(f"{sigmas[dt][k]:.1f} σ ({100 * (m1 - m2) / m2:+.1f} %)")
        print(f"| {dt * 1e6:g} | " + " | ".join(cells) + " | " + " | ".join(versus) + " |")
    print()
    judged = [("every observable", [k for k, _, _ in observables])]
    race = [k for k in RACE_OBSERVABLES if k in stats[next(iter(stats))]]
    if len(race) < len(observables):
        judged.append(("the race's observables (" + ", ".join(race) + ")", race))
    for what, keys in judged:
        passed = [dt for dt, s in sigmas.items() if all(s[k] < 2.0 for k in keys)]
        if passed:
            print(f"Largest dt within 2 σ of dt/4 in {what}: {max(passed) * 1e6:g} µs")
        else:
            print(f"No dt agrees with dt/4 within 2 σ in {what}")


if __name__ == "__main__":
    main()
