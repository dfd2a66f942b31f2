#!/usr/bin/python3
"""Turns rodsea_bench's JSON output (--benchmark_out=FILE --benchmark_out_format=json) into the
scaling table of docs/performance.md and a plot of the cost per step against the number of
spheres, which a linear-cost engine draws as a line of slope 1 on log-log axes.

    /usr/bin/python3 bench/scaling_report.py bench.json [PLOT.png]
"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def rows(path):
    with open(path) as f:
        data = json.load(f)
    out = []
    for b in data["benchmarks"]:
        if b.get("run_type") == "aggregate" or not b["name"].startswith("BM_Step"):
            continue
        out.append({
            "name": b["name"].split("/")[0],
            "bodies": b["bodies"], "spheres": b["spheres"], "threads": int(b["threads"]),
            "ms": b["real_time"] if b["time_unit"] == "ms" else b["real_time"] / 1e6,
            "steps/s": b["steps/s"], "sphere-steps/s": b["sphere-steps/s"],
            "bytes/sphere": b.get("bytes/sphere", 0.0),
            "steps/rebuild": b.get("steps/rebuild", 0.0),
            "search": b["%search"], "free": b["%free_flight"], "resolve": b["%resolve"],
            "spheres%": b["%spheres"],
        })
    return out


def main():
    data = rows(sys.argv[1])
    print("| system | bodies | spheres | threads | ms / step | steps/s | sphere-steps/s | "
          "free flight / spheres / search / resolve (%) | steps per rebuild |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in sorted(data, key=lambda r: (r["spheres"], r["threads"])):
        print(f"| {r['name'].removeprefix('BM_Step')} | {r['bodies']:.0f} | {r['spheres']:.0f} | "
              f"{r['threads']} | {r['ms']:.3g} | {r['steps/s']:.4g} | "
              f"{r['sphere-steps/s'] / 1e6:.3g} M | {r['free']:.0f} / {r['spheres%']:.0f} / "
              f"{r['search']:.0f} / {r['resolve']:.0f} | {r['steps/rebuild']:.0f} |")
    if len(sys.argv) < 3:
        return
    fig, ax = plt.subplots(figsize=(6, 4.2))
    for threads, marker in ((1, "o"), (2, "s")):
        pts = sorted((r["spheres"], r["ms"]) for r in data if r["threads"] == threads)
        if not pts:
            continue
        x, y = zip(*pts)
        ax.loglog(x, y, marker=marker, label=f"{threads} thread{'s' if threads > 1 else ''}")
    ref = sorted((r["spheres"], r["ms"]) for r in data if r["threads"] == 1)
    if ref:
        x0, y0 = ref[0]
        xs = [x0, ref[-1][0]]
        ax.loglog(xs, [y0 * x / x0 for x in xs], "k:", label="linear in N")
    ax.set_xlabel("spheres")
    ax.set_ylabel("wall time per step (ms)")
    ax.set_title("rodsea step cost against system size")
    ax.legend()
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=120)


if __name__ == "__main__":
    main()
