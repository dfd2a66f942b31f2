#!/usr/bin/python3
"""The validate tier's report: tables (Markdown) and plots from scripts/validate.sh's output.

    /usr/bin/python3 scripts/validation_report.py OUT

reads OUT/{gap,dt,epsilon,apolar-rod,bead}/calibration.csv, OUT/mixture/*/ (rodsea runs) and
OUT/{replicates,medium-drift}/seed*/analysis/analysis.json (rodsea runs, analysed) and writes
OUT/validation.md and OUT/validation-*.png. docs/validation.md quotes them.
"""
import csv
import glob
import json
import math
import os
import re
import sys

import h5py
import matplotlib
import matplotlib.ticker

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from scipy import stats as scipy_stats  # noqa: E402

# docs/model.md §3 and §7: the paper's D_r values and the experiment's single-rod speed.
PAPER_DR = [0.026, 0.23, 1.21, 1.87]  # rad²/s
EXPERIMENT_SPEED = (3.6, 2.5)  # mm/s, thick → thin, Kumar et al. 2014
DEFAULT_DT = 1.25e-6  # s
DEFAULT_GAP = 1.40  # mm


def read_table(path):
    with open(path, newline="") as f:
        lines = [line for line in f if not line.startswith("#")]
    rows = list(csv.DictReader(lines))
    for row in rows:
        for key, value in row.items():
            if key != "species":
                row[key] = float(value)
    return rows


def pm(value, error, digits=2):
    return f"{value:.{digits}f} ± {error:.{digits}f}"


def sig(value, error):
    """value ± error with the error to 2 significant figures and the value to match."""
    if error <= 0 or not math.isfinite(error):
        return f"{value:.3g}"
    if abs(value) < 1e-3 and error < 1e-3:
        return f"{value:.1e} ± {error:.1e}"
    digits = max(0, 1 - int(math.floor(math.log10(error))))
    return f"{value:.{digits}f} ± {error:.{digits}f}"


def direction(row):
    if abs(row["speed"]) < 2 * row["speed_err"]:
        return "none (|v| < 2 errors)"
    return "thick → thin" if row["speed"] > 0 else "thin → thick"


def agreement(a, a_err, b, b_err):
    """|a − b| in units of the combined standard error."""
    combined = math.hypot(a_err, b_err)
    return abs(a - b) / combined if combined > 0 else float("inf")


def speed_axes(ax, experiment_label):
    """Axial-speed axes with the experiment's band and the line between the two directions."""
    low, high = EXPERIMENT_SPEED[0] - EXPERIMENT_SPEED[1], EXPERIMENT_SPEED[0] + EXPERIMENT_SPEED[1]
    ax.axhspan(low, high, color="tab:green", alpha=0.2, label=experiment_label)
    ax.axhline(0, color="k", lw=0.8)
    ax.set_ylabel("axial speed (mm/s), + = thick → thin")


def gap_section(rows, out):
    md = ["## Speed against gap", "",
          "A lone polar rod, ε = 0, dt = 1.25 µs, 16 copies × 2 s (`validate/gap.toml`).", "",
          "| w (mm) | axial speed (mm/s) | direction | copies going that way | transverse (mm/s) |",
          "|---|---|---|---|---|"]
    for r in rows:
        md.append(f"| {r['gap']:.2f} | {sig(r['speed'], r['speed_err'])} | {direction(r)} | "
                  f"{r['forward_fraction'] * 100:.0f} % | "
                  f"{sig(r['transverse_speed'], r['transverse_speed_err'])} |")
    fig, ax = plt.subplots(figsize=(6, 4))
    w = [r["gap"] for r in rows]
    speed_axes(ax, "experiment, thick → thin: 3.6 ± 2.5 mm/s")
    ax.errorbar(w, [r["speed"] for r in rows], [r["speed_err"] for r in rows], fmt="o-",
                color="tab:blue", label="rodsea, ε = 0")
    ax.axvline(DEFAULT_GAP, color="tab:red", ls="--", lw=1, label=f"default w = {DEFAULT_GAP} mm")
    ax.set_xlabel("gap w (mm)")
    ax.legend(fontsize=8)
    save(fig, out, "validation-speed-vs-gap.png")
    return md


def epsilon_section(rows, out):
    md = ["## The calibration table: ε → D_r and speed", "",
          "A lone polar rod at the default gap (1.40 mm) and dt (1.25 µs), 16 copies × 3 s "
          "(`validate/epsilon.toml`): a quick check of the committed `data/calibration.csv`, "
          "which pools two independent sets of 8 copies × 10 s "
          "(`data/reproduction/noise-calibration/`).", "",
          "| ε (1/mm) | D_r (rad²/s) | speed (mm/s) | speed 10 / 50 / 90 % (mm/s) |",
          "|---|---|---|---|"]
    for r in rows:
        md.append(f"| {r['epsilon']:g} | {sig(r['D_r'], r['D_r_err'])} | "
                  f"{sig(r['speed'], r['speed_err'])} | "
                  f"{r['speed_p10']:.1f} / {r['speed_p50']:.1f} / {r['speed_p90']:.1f} |")
    eps = np.array([r["epsilon"] for r in rows])
    dr = np.array([r["D_r"] for r in rows])
    md += ["", "The paper's D_r values through the table (linear interpolation, as `run` does):",
           "",
           "| D_r (rad²/s) | ε (1/mm) |", "|---|---|"]
    for target in PAPER_DR:
        md.append(f"| {target} | {np.interp(target, dr, eps):.4f} |"
                  if dr[0] <= target <= dr[-1] else f"| {target} | outside the table |")

    fig, ax = plt.subplots(figsize=(6, 4))
    positive = dr > 0
    ax.errorbar(eps[positive], dr[positive], [r["D_r_err"] for r, p in zip(rows, positive) if p],
                fmt="o-", color="tab:blue", label="rodsea")
    for k, target in enumerate(PAPER_DR):
        ax.axhline(target, color="tab:red", ls=":", lw=1,
                   label="paper's D_r values" if k == 0 else None)
        if dr[0] <= target <= dr[-1]:
            ax.plot([np.interp(target, dr, eps)], [target], "x", color="tab:red")
    ax.set_yscale("log")
    ax.set_xlabel("ε (1/mm)")
    ax.set_ylabel("D_r (rad²/s)")
    ax.legend(fontsize=8)
    save(fig, out, "validation-dr-vs-epsilon.png")

    distribution = os.path.join(out, "epsilon", "speed_distribution.csv")
    if os.path.isfile(distribution):
        bins = read_table(distribution)
        fig, ax = plt.subplots(figsize=(6, 4))
        for point in sorted(set(b["point"] for b in bins))[::3]:
            rows_p = [b for b in bins if b["point"] == point]
            centres = [(b["speed_low"] + b["speed_high"]) / 2 for b in rows_p]
            ax.plot(centres, [b["density"] for b in rows_p],
                    label=f"ε = {rows_p[0]['epsilon']:g} /mm")
        ax.set_xlabel("axial speed over one drive period (mm/s), + = thick → thin")
        ax.set_ylabel("probability density (s/mm)")
        ax.legend(fontsize=8)
        save(fig, out, "validation-speed-distribution.png")

    fig, ax = plt.subplots(figsize=(6, 4))
    speed_axes(ax, "experiment (ε unknown)")
    ax.errorbar(eps, [r["speed"] for r in rows], [r["speed_err"] for r in rows], fmt="o-",
                color="tab:blue", label="mean axial speed")
    ax.fill_between(eps, [r["speed_p10"] for r in rows], [r["speed_p90"] for r in rows],
                    color="tab:blue", alpha=0.15, label="per-period speed, 10–90 %")
    ax.set_xlabel("ε (1/mm)")
    ax.legend(fontsize=8)
    save(fig, out, "validation-speed-vs-epsilon.png")
    return md


def dt_section(rows, out):
    md = ["## Time-step convergence of a single rod", "",
          "A lone polar rod at w = 1.40 mm, 32 copies × 4 s (`validate/dt.toml`, "
          "`validate/dt-fine.toml`). The last columns compare each dt with dt/4: the difference "
          "in combined standard errors (and in per cent).", "",
          "| ε (1/mm) | dt (µs) | speed (mm/s) | D_r (rad²/s) | speed vs dt/4 | D_r vs dt/4 |",
          "|---|---|---|---|---|---|"]
    by_eps = {}
    for r in rows:
        by_eps.setdefault(r["epsilon"], []).append(r)
    for e, group in sorted(by_eps.items()):
        group.sort(key=lambda r: -r["dt"])
        for r in group:
            quarter = [q for q in group if math.isclose(q["dt"], r["dt"] / 4, rel_tol=1e-6)]
            if quarter:
                q = quarter[0]
                dv = (f"{agreement(r['speed'], r['speed_err'], q['speed'], q['speed_err']):.1f} σ "
                      f"({100 * (r['speed'] - q['speed']) / q['speed']:+.1f} %)")
                # Without noise D_r is zero up to the rod's slow start-up turning: no comparison.
                dd = (f"{agreement(r['D_r'], r['D_r_err'], q['D_r'], q['D_r_err']):.1f} σ "
                      f"({100 * (r['D_r'] - q['D_r']) / q['D_r']:+.0f} %)" if e > 0 else "–")
            else:
                dv = dd = "–"
            md.append(f"| {e:g} | {r['dt'] * 1e6:g} | {sig(r['speed'], r['speed_err'])} | "
                      f"{sig(r['D_r'], r['D_r_err'])} | {dv} | {dd} |")
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for e, group in sorted(by_eps.items()):
        dts = np.array([r["dt"] for r in group]) * 1e6
        axes[0].errorbar(dts, [r["speed"] for r in group], [r["speed_err"] for r in group],
                         fmt="o-", label=f"ε = {e:g} /mm")
        if e > 0:
            axes[1].errorbar(dts, [r["D_r"] for r in group], [r["D_r_err"] for r in group],
                             fmt="o-", color="tab:orange", label=f"ε = {e:g} /mm")
    for ax in axes:
        log_dt_axis(ax, sorted(set(r["dt"] * 1e6 for r in rows)))
    axes[0].set_ylabel("axial speed (mm/s)")
    axes[1].set_ylabel("D_r (rad²/s)")
    save(fig, out, "validation-dt-single-rod.png")
    return md


def drift_section(tables):
    md = ["## Bodies that must not drift", "",
          "Lone apolar rods (ℓ_a = 2.5 mm) and beads, ε = 0, dt = 1.25 µs, 16 copies × 2 s "
          "(`validate/apolar-rod.toml`, `validate/bead.toml`). |v|/error below 2 is no drift.", "",
          "| body | w (mm) | axial speed (mm/s) | \\|v\\| / error | transverse (mm/s) |",
          "|---|---|---|---|---|"]
    for name, rows in tables:
        for r in rows:
            if r["speed"] == 0 and r["speed_err"] == 0 and r["transverse_speed"] == 0:
                # A symmetric start that nothing can break, e.g. a sphere bouncing straight up.
                md.append(f"| {name} | {r['gap']:.2f} | 0 exactly | – | 0 exactly |")
                continue
            ratio = abs(r["speed"]) / r["speed_err"]
            md.append(f"| {name} | {r['gap']:.2f} | {sig(r['speed'], r['speed_err'])} | "
                      f"{ratio:.1f} | {sig(r['transverse_speed'], r['transverse_speed_err'])} |")
    return md


def read_run(run_dir):
    with open(os.path.join(run_dir, "timeseries.csv"), newline="") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    with h5py.File(os.path.join(run_dir, "trajectory.h5"), "r") as f:
        bodies = f["particles/bodies/position/value"].shape[1]
    with open(os.path.join(run_dir, "config.toml")) as f:
        config = f.read()
    dt = float(re.search(r"^dt = ([0-9.eE+-]+)", config, re.M).group(1))
    box = float(re.search(r"^side = ([0-9.eE+-]+)", config, re.M).group(1))
    rows = rows[1:]  # the row at t = 0 covers no steps
    return {
        "dt": dt,
        # collisions (approach > 1 mm/s) per body per simulated second, with bodies and plates
        "body_rate": np.mean([float(r["body_collision_rate"]) for r in rows]),
        "plate_rate": np.mean([float(r["plate_collision_rate"]) for r in rows]),
        "impulse_rate": np.mean([float(r["impulses_per_step"]) for r in rows]) / dt / bodies,
        "P": float(rows[-1]["polar_order_polar"]),
        "max_overlap": max(float(r["max_overlap_fraction"]) for r in rows),
        "unresolved": sum(float(r["unresolved_contacts"]) for r in rows),
        "duration": float(rows[-1]["time"]),
        "bodies": bodies,
        "box": box,
    }


def mean_and_error(values):
    values = np.asarray(values, dtype=float)
    return values.mean(), values.std(ddof=1) / len(values) ** 0.5


def mixture_section(mixture_dir, out):
    runs = [read_run(d) for d in sorted(glob.glob(os.path.join(mixture_dir, "dt*_seed*")))
            if os.path.isfile(os.path.join(d, "timeseries.csv"))]
    if not runs:
        return []
    by_dt = {}
    for r in runs:
        by_dt.setdefault(r["dt"], []).append(r)
    keys = ("body_rate", "plate_rate", "impulse_rate", "P")
    stats = []
    for dt, group in sorted(by_dt.items(), reverse=True):
        entry = {"dt": dt, "n": len(group),
                 "overlap": max(r["max_overlap"] for r in group),
                 "unresolved": sum(r["unresolved"] for r in group)}
        for key in keys:
            entry[key] = mean_and_error([r[key] for r in group])
        stats.append(entry)
    finest = stats[-1]

    def versus_finest(entry, key):
        (a, a_err), (b, b_err) = entry[key], finest[key]
        return f"{agreement(a, a_err, b, b_err):.1f} σ" if entry is not finest else "–"

    md = ["## Time-step convergence of a dense mixture", "",
          f"Polar rods at φ_p = 0.05 in apolar rods of ℓ_a = 2.5 mm at φ_a = 0.50, "
          f"{runs[0]['box']:g} mm box ({runs[0]['bodies']} bodies, `validate/mixture.toml`), "
          f"{runs[0]['duration']:g} s from the builder's isotropic start, {stats[0]['n']} seeds per "
          "dt. Collision rates: collisions (impulses at approach speeds above 1 mm/s) per body per "
          "simulated second over the whole run, with other bodies and with the plates. Impulses: "
          "all impulses per body per second, resting contacts included. P: the polar order at the "
          "end. Errors: standard error over seeds; the last columns compare with the finest dt.",
          "",
          "| dt (µs) | body collisions (1/s) | plate collisions (1/s) | impulses (1/s) | "
          "P at the end | largest overlap / radius | unresolved | body vs finest | "
          "plate vs finest | P vs finest |",
          "|---|---|---|---|---|---|---|---|---|---|"]
    for e in stats:
        md.append(f"| {e['dt'] * 1e6:g} | {sig(*e['body_rate'])} | {sig(*e['plate_rate'])} | "
                  f"{sig(*e['impulse_rate'])} | {sig(*e['P'])} | {e['overlap']:.4f} | "
                  f"{e['unresolved']:.0f} | {versus_finest(e, 'body_rate')} | "
                  f"{versus_finest(e, 'plate_rate')} | {versus_finest(e, 'P')} |")
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    dts = [e["dt"] * 1e6 for e in stats]
    for key, label in (("body_rate", "with bodies"), ("plate_rate", "with plates")):
        axes[0].errorbar(dts, [e[key][0] for e in stats], [e[key][1] for e in stats], fmt="o-",
                         label=label)
    axes[0].set_ylabel("collisions per body per second (1/s)")
    axes[1].errorbar(dts, [e["P"][0] for e in stats], [e["P"][1] for e in stats], fmt="o-")
    axes[1].set_ylabel(f"P at t = {runs[0]['duration']:g} s")
    for ax in axes:
        log_dt_axis(ax, dts)
    save(fig, out, "validation-dt-mixture.png")
    return md


def analysed_seeds(part_dir):
    """(seed, analysis.json) of every analysed run of a validate part, by seed."""
    runs = []
    for path in glob.glob(os.path.join(part_dir, "seed*", "analysis", "analysis.json")):
        seed = int(re.search(r"seed(\d+)", path).group(1))
        with open(path) as f:
            runs.append((seed, json.load(f)))
    return sorted(runs)


def scalar_of(analysis, observable, name):
    """The scalar's JSON entry (value, error, tau_int_samples, n_eff, ...), None if absent."""
    return analysis["observables"].get(observable, {}).get("scalars", {}).get(name)


def replicate_consistency(values, errors):
    """The replicates' spread against their quoted errors: the standard deviation of the values,
    the rms quoted error, and chi² = Σ (x − x̄)² / σ² over its n − 1 degrees of freedom with the
    central 95 % range of that ratio for honest (Gaussian) errors."""
    x, e = np.asarray(values, float), np.asarray(errors, float)
    n = len(x)
    chi2 = float(np.sum((x - x.mean()) ** 2 / e ** 2)) / (n - 1)
    low, high = (scipy_stats.chi2.ppf(q, n - 1) / (n - 1) for q in (0.025, 0.975))
    return {"n": n, "mean": x.mean(), "sd": x.std(ddof=1), "rms_error": float(np.sqrt(np.mean(e ** 2))),
            "chi2": chi2, "low": low, "high": high}


def replicates_section(part_dir, out):
    runs = analysed_seeds(part_dir)
    if len(runs) < 2:
        return []
    md = ["## Error bars against replicates", "",
          f"{len(runs)} seeds of the dilute point of `validate/replicates.toml` (45 polar rods at "
          "φ_p = 0.05 among apolar rods of ℓ_a = 2.5 mm at φ_a = 0.05, 60 mm box, D_r = 0), each "
          f"{runs[0][1]['run']['last_time_s']:g} s, analysed by `rodsea analyze` with its automatic "
          "window. Each seed quotes a steady mean ± error; honest errors make the spread of the "
          "seeds' means match them: χ²/dof = Σ (x − x̄)² / σ² / (n − 1) lies in the given 95 % range.",
          "",
          "| seed | window from (s) | decided by | P polar | τ_int (frames) | n_eff | short | "
          "S medium | N_m | medium along p̂ (mm/s) |",
          "|---|---|---|---|---|---|---|---|---|---|"]
    columns = {"P_polar": ("order", "P_polar"), "S_medium": ("order", "S_medium"),
               "N_m": ("flocks", "N_m"), "v_along": ("drift", "v_medium_along_polar")}
    values = {k: [] for k in columns}
    for seed, a in runs:
        entries = {k: scalar_of(a, *where) for k, where in columns.items()}
        for k, e in entries.items():
            if e and e.get("value") is not None and e.get("error"):
                values[k].append((e["value"], e["error"]))
        p = entries["P_polar"]
        cell = lambda e: sig(e["value"], e["error"]) if e and e.get("error") else "–"  # noqa: E731
        md.append(f"| {seed} | {a['steady_state']['from_s']:g} | "
                  f"{a['steady_state'].get('decided_by', '')} | {cell(p)} | "
                  f"{p['tau_int_samples']:.1f} | {p['n_eff']:.1f} | "
                  f"{'yes' if p.get('short_series') else 'no'} | {cell(entries['S_medium'])} | "
                  f"{cell(entries['N_m'])} | {cell(entries['v_along'])} |")
    md += ["", "| quantity | mean of seeds | sd of the seeds | rms quoted error | sd / error | "
           "χ²/dof | 95 % range |", "|---|---|---|---|---|---|---|"]
    fig, axes = plt.subplots(1, len(columns), figsize=(4 * len(columns), 3.6))
    for ax, (k, pairs) in zip(axes, values.items()):
        if len(pairs) < 2:
            continue
        c = replicate_consistency(*zip(*pairs))
        md.append(f"| {k} | {c['mean']:.4g} | {c['sd']:.3g} | {c['rms_error']:.3g} | "
                  f"{c['sd'] / c['rms_error']:.2f} | {c['chi2']:.2f} | {c['low']:.2f}–{c['high']:.2f} |")
        seeds = range(1, len(pairs) + 1)
        ax.errorbar(seeds, [v for v, _ in pairs], [e for _, e in pairs], fmt="o", capsize=3)
        ax.axhspan(c["mean"] - c["sd"], c["mean"] + c["sd"], color="tab:grey", alpha=0.3,
                   label="mean ± sd of the seeds")
        ax.set_xlabel("seed")
        ax.set_title(k, fontsize=10)
        ax.legend(fontsize=7)
    save(fig, out, "validation-replicates.png")
    return md


def medium_drift_section(part_dir, replicates_dir):
    runs = analysed_seeds(part_dir)
    if not runs:
        return []
    md = ["## The medium alone does not drift", "",
          f"Apolar rods of ℓ_a = 2.5 mm at φ_a = 0.50 alone in a 30 mm box "
          f"(`validate/medium-drift.toml`), {len(runs)} seeds of "
          f"{runs[0][1]['run']['last_time_s']:g} s: the steady mean of the medium's mean in-plane "
          "velocity (`rodsea analyze`, observable `drift`) with its τ_int error. |v| / error below "
          "2 is no drift.", "",
          "| seed | frames | v_x (mm/s) | \|v_x\| / error | v_y (mm/s) | \|v_y\| / error |",
          "|---|---|---|---|---|---|"]
    for seed, a in runs:
        vx, vy = scalar_of(a, "drift", "vx_medium"), scalar_of(a, "drift", "vy_medium")
        md.append(f"| {seed} | {vx['samples']} | {sig(vx['value'], vx['error'])} | "
                  f"{abs(vx['value']) / vx['error']:.1f} | {sig(vy['value'], vy['error'])} | "
                  f"{abs(vy['value']) / vy['error']:.1f} |")
    along = [scalar_of(a, "drift", "v_medium_along_polar") for _, a in analysed_seeds(replicates_dir)]
    along = [e for e in along if e and e.get("error")]
    if along:
        mean, err = mean_and_error([e["value"] for e in along])
        md += ["", f"With polar rods (the replicate runs above), the medium's mean velocity along the "
               f"polar rods' mean heading is {sig(mean, err)} mm/s over {len(along)} seeds "
               f"({abs(mean) / err:.1f} standard errors from zero)."]
    return md


def log_dt_axis(ax, dts_us):
    """A log dt axis ticked at the measured steps, with the default marked."""
    ax.set_xscale("log")
    ax.xaxis.set_major_locator(matplotlib.ticker.FixedLocator(dts_us))
    ax.xaxis.set_major_formatter(matplotlib.ticker.FixedFormatter([f"{d:g}" for d in dts_us]))
    ax.xaxis.set_minor_locator(matplotlib.ticker.NullLocator())
    ax.axvline(DEFAULT_DT * 1e6, color="tab:red", ls="--", lw=1, label="default dt")
    ax.set_xlabel("dt (µs)")
    ax.legend(fontsize=8)


def save(fig, out, name):
    fig.tight_layout()
    path = os.path.join(out, name)
    fig.savefig(path + ".tmp.png", dpi=110)
    os.replace(path + ".tmp.png", path)
    plt.close(fig)


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    out = sys.argv[1]
    md = ["# Validation report", "", "Written by scripts/validation_report.py; "
          "numbers are value ± standard error.", ""]
    def table(part):
        path = os.path.join(out, part, "calibration.csv")
        return read_table(path) if os.path.isfile(path) else None

    if table("gap"):
        md += gap_section(table("gap"), out) + [""]
    if table("epsilon"):
        md += epsilon_section(table("epsilon"), out) + [""]
    if table("dt"):
        md += dt_section(table("dt") + (table("dt-fine") or []), out) + [""]
    drift = [(name, table(part)) for name, part in (("apolar rod", "apolar-rod"), ("bead", "bead"))
             if table(part)]
    if drift:
        md += drift_section(drift) + [""]
    md += mixture_section(os.path.join(out, "mixture"), out) + [""]
    md += replicates_section(os.path.join(out, "replicates"), out) + [""]
    md += medium_drift_section(os.path.join(out, "medium-drift"), os.path.join(out, "replicates"))
    path = os.path.join(out, "validation.md")
    with open(path + ".tmp", "w") as f:
        f.write("\n".join(md) + "\n")
    os.replace(path + ".tmp", path)
    print(path)


if __name__ == "__main__":
    main()
