#!/usr/bin/python3
"""The cost table of docs/campaigns.md: every campaign of examples/paper/ planned at its full size
with its throughput measured on this machine (`rodsea campaign plan`, 0.3 s of stepping per
point; a few minutes in all) and its time on one H200 GPU (the plan's model of the measured GPU
step), printed as a Markdown table.

    /usr/bin/python3 scripts/paper_campaign_costs.py [RODSEA]    (default build/rodsea)
"""
import pathlib
import re
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
CORES = 64  # the "on a cluster" column: one node of a typical cluster


def plan(rodsea, campaign, out):
    text = subprocess.run([rodsea, "campaign", "plan", str(campaign), "--out", out],
                          check=True, capture_output=True, text=True).stdout
    points, replicates, runs = re.search(
        r"(\d+) points? x (\d+) replicates? .*= (\d+) runs", text).groups()
    steps = float(re.search(r"total ([0-9.e+]+) sphere-steps", text).group(1))
    hours = re.search(r"about ([0-9.e+]+) core-hours", text)
    gpu = re.search(r"about ([0-9.e+]+) GPU-hours run by run, about ([0-9.e+]+) as one", text)
    return (int(points), int(replicates), int(runs), steps,
            float(hours.group(1)) if hours else None, float(gpu.group(1)), float(gpu.group(2)))


def main():
    rodsea = sys.argv[1] if len(sys.argv) > 1 else str(ROOT / "build" / "rodsea")
    print("| campaign | points × replicates = runs | sphere-steps | core-hours here "
          f"| on {CORES} cores | one H200: run by run / one ensemble |")
    print("|---|---|---|---|---|---|")
    total = [0, 0.0, 0.0, 0.0, 0.0]
    unmeasured = 0
    with tempfile.TemporaryDirectory() as scratch:
        for campaign in sorted((ROOT / "examples" / "paper").glob("*.toml")):
            if campaign.stem.startswith("base-"):
                continue
            points, replicates, runs, steps, hours, alone, together = plan(
                rodsea, campaign, f"{scratch}/{campaign.stem}")
            days = "—" if hours is None else f"{hours / CORES / 24:.1f} days"
            print(f"| `{campaign.stem}` | {points} × {replicates} = {runs} | {steps:.2g} "
                  f"| {'not measured' if hours is None else f'{hours:,.0f}'} | {days} "
                  f"| {alone / 24:.1f} days / {together / 24:.1f} days |")
            total[0] += runs
            total[1] += steps
            total[2] += hours or 0.0
            total[3] += alone
            total[4] += together
            unmeasured += hours is None
    bound = "at least " if unmeasured else ""  # a campaign without a cost is left out of it
    print(f"| **all** | {total[0]} runs | {total[1]:.2g} | {bound}{total[2]:,.0f} "
          f"| {bound}{total[2] / CORES / 24:.0f} days "
          f"| {total[3] / 24:.0f} days / {total[4] / 24:.0f} days |")


if __name__ == "__main__":
    main()
