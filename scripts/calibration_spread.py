#!/usr/bin/python3
"""Is the calibration table's D_r error bar honest?

Two independent measurements of the same ε grid (different seeds, disjoint copies), each from
`rodsea calibrate`, are compared point by point: z = (D_a - D_b) / sqrt(err_a² + err_b²) should
be standard normal if the quoted errors hold (|z| < 2 at ~95 % of the points, mean z² ≈ 1). The
two are then pooled (inverse-variance mean, for D_r and the speeds) into one table in the format
of data/calibration.csv.

    calibration_spread.py A/calibration.csv B/calibration.csv --table OUT.csv --report OUT.md
"""
import argparse
import csv
import math


def read(path):
    with open(path) as f:
        lines = [line for line in f if not line.startswith("#")]
    return list(csv.DictReader(lines))


def pooled(a, b, key):
    va, vb = float(a[key]), float(b[key])
    ea, eb = float(a[key + "_err"]), float(b[key + "_err"])
    if ea > 0 and eb > 0:
        wa, wb = 1 / ea**2, 1 / eb**2
        return (wa * va + wb * vb) / (wa + wb), math.sqrt(1 / (wa + wb))
    return 0.5 * (va + vb), 0.5 * math.hypot(ea, eb)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("a")
    parser.add_argument("b")
    parser.add_argument("--table", required=True)
    parser.add_argument("--report", required=True)
    args = parser.parse_args()
    rows_a, rows_b = read(args.a), read(args.b)
    header_comment = open(args.a).readline()
    fields = list(rows_a[0].keys())
    out_rows, lines, z2 = [], [], []
    lines.append("| ε (1/mm) | D_r a (rad²/s) | D_r b (rad²/s) | z = Δ/σ | pooled D_r (rad²/s) |")
    lines.append("|---|---|---|---|---|")
    for a, b in zip(rows_a, rows_b):
        if a["epsilon"] != b["epsilon"]:
            raise SystemExit(f"the two tables differ in ε: {a['epsilon']} vs {b['epsilon']}")
        if a.get("noise_mode", "add") != b.get("noise_mode", "add"):
            raise SystemExit(f"the two tables differ in noise_mode at ε = {a['epsilon']}")
        da, db = float(a["D_r"]), float(b["D_r"])
        ea, eb = float(a["D_r_err"]), float(b["D_r_err"])
        z = (da - db) / math.hypot(ea, eb) if ea > 0 or eb > 0 else float("nan")
        z2.append(z * z)
        row = dict(a)
        for key in ("D_r", "speed", "transverse_speed"):
            row[key], row[key + "_err"] = (f"{v:.8g}" for v in pooled(a, b, key))
        row["copies"] = str(int(a["copies"]) + int(b["copies"]))
        row["unresolved"] = str(int(a["unresolved"]) + int(b["unresolved"]))
        for key in ("forward_fraction", "speed_p10", "speed_p50", "speed_p90"):
            row[key] = f"{0.5 * (float(a[key]) + float(b[key])):.8g}"
        out_rows.append(row)
        lines.append(f"| {a['epsilon']} | {da:.4g} ± {ea:.2g} | {db:.4g} ± {eb:.2g} | "
                     f"{z:+.2f} | {float(row['D_r']):.4g} ± {float(row['D_r_err']):.2g} |")
    inside = sum(1 for v in z2 if v < 4.0)
    mean_z2 = sum(z2) / len(z2)
    lines.append("")
    lines.append(f"{inside} of {len(z2)} points within 2 σ; mean z² = {mean_z2:.2f} "
                 f"(1 if the quoted errors hold; {len(z2)} points give a spread of "
                 f"±{math.sqrt(2 / len(z2)):.2f} on it)")
    with open(args.table, "w", newline="") as f:
        f.write(header_comment)
        w = csv.DictWriter(f, fieldnames=fields, lineterminator="\n")
        w.writeheader()
        w.writerows(out_rows)
    with open(args.report, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
