#!/usr/bin/python3
"""Per-kernel times from bench/gpu/run.sh's ncu output (kernels.csv): each kernel's mean duration
over the steps profiled, its share of the step, and the launches per step.

    /usr/bin/python3 bench/gpu/kernel_table.py OUT/kernels.csv [--steps 10]
"""
import argparse
import csv
import re
from collections import OrderedDict


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("csv")
    parser.add_argument("--steps", type=int, default=10, help="steps the launches cover")
    args = parser.parse_args()
    lines = open(args.csv).read().splitlines()
    header = next(i for i, line in enumerate(lines) if line.startswith('"ID"'))
    rows = list(csv.reader(lines[header:]))
    name_at = rows[0].index("Kernel Name")
    value_at = rows[0].index("Metric Value")
    unit_at = rows[0].index("Metric Unit")
    scale = {"ns": 1e-3, "nsecond": 1e-3, "us": 1.0, "usecond": 1.0, "ms": 1e3, "msecond": 1e3}
    times = OrderedDict()
    for row in rows[1:]:
        # A step kernel by its element kernels (run_kernel_then's tail after a +), whether ncu
        # writes them with their namespace or without.
        kernels = re.findall(r"parallel::(\w+)", row[name_at])
        if not kernels:
            template = re.match(r"(?:void )?run_\w+<([^>(]*)>", row[name_at])
            kernels = [k.strip() for k in template.group(1).split(",")] if template else []
        name = " + ".join(kernels) if kernels else re.sub(r"<.*", "", row[name_at]).split("::")[-1]
        times.setdefault(name, []).append(float(row[value_at].replace(",", "")) * scale[row[unit_at]])
    total = sum(sum(v) for v in times.values())
    print("| kernel | launches per step | µs per launch | µs per step | share |")
    print("|---|---|---|---|---|")
    for name, v in times.items():
        per_step = sum(v) / args.steps
        print(f"| {name} | {len(v) / args.steps:g} | {sum(v) / len(v):.2f} | {per_step:.2f} | "
              f"{100 * sum(v) / total:.0f} % |")
    print(f"| all | {sum(len(v) for v in times.values()) / args.steps:g} | | "
          f"{total / args.steps:.1f} | |")


if __name__ == "__main__":
    main()
