#!/usr/bin/python3
"""How the builder starts the paper's systems, and how random the start is.

For each medium and area fraction (polar rods at phi_p = 0.05, the full 252 mm box by default) it
writes a config, runs `rodsea run` for one step and reads the start line it prints: the start
kind, the build time, and P and S per species. Prints a Markdown table (docs/builder.md).

    /usr/bin/python3 scripts/start_table.py [--rodsea build/rodsea] [--side 252] [--seed 1]
"""
import argparse
import re
import subprocess
import sys
import tempfile
from pathlib import Path

POINTS = [  # (medium label, kind, length mm or None, area fractions)
    ("beads", "bead", None, [0.50, 0.60, 0.70, 0.75, 0.80]),
    ("1.0 mm", "apolar_rod", 1.0, [0.50, 0.60, 0.70, 0.75]),
    ("2.0 mm", "apolar_rod", 2.0, [0.50]),
    ("2.5 mm", "apolar_rod", 2.5, [0.50, 0.60, 0.70, 0.75, 0.80]),
    ("4.5 mm", "apolar_rod", 4.5, [0.50, 0.60, 0.70, 0.75]),
]

START = re.compile(r"initial state built in (?P<seconds>[0-9.e+-]+) s: (?P<start>[a-z]+)(?P<how>.*?), "
                   r"then (?P<sweeps>\d+) Monte Carlo sweeps; order at the start:(?P<order>.*)$")
ORDER = re.compile(r"(\w+) P = ([0-9.e+-]+), S = ([0-9.e+-]+);")
DOMAINS = re.compile(r"in (\d+) domains|as one domain")


def config(kind, length, phi, side, seed):
    medium = f'name = "medium"\nkind = "{kind}"\narea_fraction = {phi}\n'
    if length is not None:
        medium += f"length = {length}\n"
    return (f"[box]\nside = {side}\n\n[[species]]\nname = \"polar\"\nkind = \"polar_rod\"\n"
            f"area_fraction = 0.05\n\n[[species]]\n{medium}\n[time]\nduration = 1.25e-6\n\n"
            f"[output]\ninterval = 1.25e-6\n\n[run]\nseed = {seed}\n")


def measure(rodsea, kind, length, phi, side, seed, work):
    path = Path(work) / "start.toml"
    path.write_text(config(kind, length, phi, side, seed))
    out = subprocess.run([rodsea, "run", str(path), "--out", str(Path(work) / "run"), "--overwrite"],
                         capture_output=True, text=True)
    if out.returncode != 0:
        return None  # refused: the counts do not fit this box (the message is rodsea's)
    for line in out.stdout.splitlines():
        m = START.search(line)
        if m:
            order = {name: (float(p), float(s)) for name, p, s in ORDER.findall(m["order"])}
            d = DOMAINS.search(m["how"])
            domains = "" if not d else (d[1] or "1")
            return m["start"], domains, float(m["seconds"]), order
    raise RuntimeError("no start line in:\n" + out.stdout)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rodsea", default="build/rodsea")
    parser.add_argument("--side", type=float, default=252.0)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    print("| medium | φ_a | start | domains | build s | P polar | S polar | S medium |")
    print("|---|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as work:
        for label, kind, length, fractions in POINTS:
            for phi in fractions:
                measured = measure(args.rodsea, kind, length, phi, args.side, args.seed, work)
                if measured is None:
                    print(f"| {label} | {phi:.2f} | does not fit | | | | | |", flush=True)
                    continue
                start, domains, seconds, order = measured
                medium = "–" if kind == "bead" else f"{order['medium'][1]:.3f}"
                print(f"| {label} | {phi:.2f} | {start} | {domains} | {seconds:.1f} | "
                      f"{order['polar'][0]:.3f} | {order['polar'][1]:.3f} | {medium} |", flush=True)


if __name__ == "__main__":
    sys.exit(main())
