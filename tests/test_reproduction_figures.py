"""The figures of docs/reproduction.md are drawn from the committed tables alone.
Regenerates Fig. 1c's figure into a scratch directory and checks every curve it drew against
the tables, read here with the csv module (not the script's parser), and the PNG's size; then
the first row's (38 and 63 mm boxes), Fig. 1f's and the bead medium's (heavy and light beads)
points against the block means of their series tables, the 38 mm row's C(t) against its
tables, its dense end's 5 s means against their series, what carries P (P_independent, flock_alignment)
against each run's analysis summary, the dilute end's G(r) and P(t) against their tables, its
medium-mass and time-step points against their summaries, each seed's P(t) either side of
the medium-mass turn against its series, each box's P(t) of the finite-size figure against
its series, Fig. 5b's points at d against their summaries, and the medium's drift against the
rods' order (its blocks and slopes α/Γ_f) against its blocks tables.
"""
import csv
import functools
import math
import json
import os
import struct

import pytest

from conftest import SOURCE, run_script

pytest.importorskip("matplotlib")
pytest.importorskip("numpy")
import reproduction_figures as figures  # noqa: E402  (for the list of tables only)

source = str(SOURCE)


@pytest.fixture(scope="module")
def scratch(tmp_path_factory):
    return str(tmp_path_factory.mktemp("figures"))


def same(a, b):
    """Equal lists of floats, NaN (a run without an error bar) equal to NaN."""
    return len(a) == len(b) and all(x == y or (x != x and y != y) for x, y in zip(a, b))


def read_table(path):
    """A table's column indices by name and its data rows, read with the csv module (not the
    script's parser)."""
    with open(path, encoding="utf-8") as f:
        rows = [r for r in csv.reader(f) if r and not r[0].startswith("#")]
    return {name: i for i, name in enumerate(rows[0])}, rows[1:]


def block_mean(path, column, start, end, block=15.0):
    """The mean of the block means of `column` over [start, end), bins by their middles, read
    with the csv module."""
    col, rows = read_table(path)
    blocks = {}
    for r in rows:
        middle = 0.5 * (float(r[col["t_from"]]) + float(r[col["t_to"]]))
        if start <= middle < end:
            blocks.setdefault(int((middle - start) // block), []).append(float(r[col[column]]))
    means = [sum(v) / len(v) for _, v in sorted(blocks.items())]
    return sum(means) / len(means)


def covered_window(path, start=60.0, stop=180.0, block=15.0):
    """The whole blocks of [start, stop) that a series covers, read with the csv module: up to
    the end of its last 1 s bin, or its start where that bin lacks frames (a run stopped within
    it); None below two blocks."""
    col, rows = read_table(path)
    frames = [int(r[col["frames"]]) for r in rows]
    last = rows[-1]
    end = float(last[col["t_to"]] if frames[-1] >= max(frames) else last[col["t_from"]])
    blocks = int((min(end, stop) - start) // block)
    return (start, start + blocks * block) if blocks >= 2 else None


def are_bin_means(curve, values, width):
    """Whether `curve` is the means of consecutive groups of `width` of `values` (a shorter
    remainder left out)."""
    groups = [values[i:i + width] for i in range(0, len(values) - width + 1, width)]
    return len(curve) == len(groups) and all(
        abs(y - sum(g) / width) < 1e-12 for y, g in zip(curve, groups))


def check_points(name, drawn_points, expected, at_least):
    assert len(drawn_points) == len(expected) >= at_least, (drawn_points, expected)
    for (x, y), (ex, ey) in zip(drawn_points, expected):
        assert x == ex and abs(y - ey) < 1e-12, ((x, y), (ex, ey))
    print(f"checked the {len(drawn_points)} runs of reproduction-{name}.png against their "
          "series tables")


@functools.cache
def drawn_in(scratch, name):
    """What the script drew of figure `name` (its --dump), drawn once per scratch directory."""
    run = run_script("reproduction_figures.py", "--only", name, "--out", scratch, "--dump")
    assert run.returncode == 0, run.stderr
    with open(os.path.join(scratch, f"reproduction-{name}.json")) as f:
        return json.load(f)


def test_fig1c_is_drawn_from_its_tables(scratch):
    drawn = drawn_in(scratch, "fig1c")
    checked = 0
    for label, relative in figures.FIG1C_POINTS:
        path = os.path.join(source, relative)
        if not os.path.isfile(path):
            assert not any(k.endswith(": " + label) for k in drawn), f"{label} drawn without a table"
            continue
        col, rows = read_table(path)
        rows.sort(key=lambda r: float(r[col["medium.area_fraction"]]))
        for name in ("P_polar", "Sigma", "N_m"):
            curve = drawn[f"{name}: {label}"]
            assert same(curve["x"], [float(r[col["medium.area_fraction"]]) for r in rows]), name
            assert same(curve["y"], [float(r[col[name]]) for r in rows]), (name, label)
            assert same(curve["err"], [float(r[col[name + "_err"]]) for r in rows]), (name, label)
            checked += 1
    assert checked >= 3, "no table of Fig. 1c was checked"

    # 12 × 4 inches at 110 dpi.
    with open(os.path.join(scratch, "reproduction-fig1c.png"), "rb") as f:
        head = f.read(24)
    assert head[:8] == b"\x89PNG\r\n\x1a\n"
    assert struct.unpack(">II", head[16:24]) == (1320, 440), struct.unpack(">II", head[16:24])
    print(f"checked {checked} curves of reproduction-fig1c.png against their tables")


def test_the_first_rows_points_and_s3a_are_their_block_means(scratch):
    # The first row: each 38 mm seed's point is the mean of its 15 s block means over 60–180 s, and
    # so is each 63 mm point, over its own window where the run has not reached 180 s.
    row = drawn_in(scratch, "row")
    expected = [(float(phi), block_mean(os.path.join(source, relative), "P_polar", 60.0, 180.0))
                for phi, tables in figures.ROW38.items() for relative in tables
                if os.path.isfile(os.path.join(source, relative))]
    check_points("row", list(zip(row["P_polar: seeds"]["x"], row["P_polar: seeds"]["y"])),
                 expected, 8)
    present = [(phi, relative, covered_window(os.path.join(source, relative)))
               for phi, seeds in figures.ROW63.items() for relative in seeds
               if os.path.isfile(os.path.join(source, relative))]
    present = [entry for entry in present if entry[2] is not None]
    expected = [(phi, block_mean(os.path.join(source, relative), "P_polar", *window))
                for phi, relative, window in present]
    check_points("row", list(zip(row["P_polar: 63 mm"]["x"], row["P_polar: 63 mm"]["y"])),
                 expected, 5)
    assert [tuple(w) for w in row["P_polar: 63 mm"]["window"]] == [w for _, _, w in present], \
        (row["P_polar: 63 mm"]["window"], present)
    # The dashed line joins, at each φ_a, the mean of the seeds' points just checked that cover the
    # whole 60–180 s (a run still under way is drawn, but kept out of the mean).
    means = {}
    for (phi, y), (_, _, window) in zip(expected, present):
        if window == (60.0, 180.0):
            means.setdefault(phi, []).append(y)
    check_points("row", list(zip(row["P_polar: 63 mm mean"]["x"], row["P_polar: 63 mm mean"]["y"])),
                 [(phi, sum(ys) / len(ys)) for phi, ys in means.items()], 4)
    # SI S3(a): each run's C(t) as drawn is its table's, every positive value of it (a log axis).
    ct = drawn_in(scratch, "ct")
    checked = 0
    for phi, box, relative, _ in figures.CT:
        path = os.path.join(source, relative)
        key = f"C: φ_a = {phi:g}, {box}"
        if not os.path.isfile(path):
            assert key not in ct, f"{key} drawn without a table"
            continue
        col, rows = read_table(path)
        table = [(float(r[col["t"]]), float(r[col["C_polar"]])) for r in rows]
        table = [(t, c) for t, c in table if c > 0]
        curve = ct[key]
        assert same(curve["x"], [t for t, _ in table]) and same(curve["y"], [c for _, c in table]), key
        checked += 1
    assert checked >= 5, f"only {checked} C(t) tables were checked"
    print(f"checked the C(t) of {checked} runs of reproduction-ct.png against their tables")


def test_the_dense_end_over_whole_runs(scratch):
    # The dense end over whole runs: each curve's points are the means of consecutive groups of the
    # table's 1 s bins, the bins read here with the csv module.
    dense = drawn_in(scratch, "dense38")
    checked = 0
    for phi, relative, _ in figures.DENSE38:
        path = os.path.join(source, relative)
        if not os.path.isfile(path):
            continue
        col, rows = read_table(path)
        for name in ("P_polar", "S_medium", "Sigma", "fraction_in_flocks"):
            assert are_bin_means(dense[f"{name}: φ_a = {phi:g}"]["y"],
                                 [float(r[col[name]]) for r in rows], figures.DENSE38_BIN), (phi, name)
        checked += 1
    assert checked >= 1, "no dense-end series was checked"
    print(f"checked the series of {checked} dense-end runs of reproduction-dense38.png")


def test_finite_size_series_are_their_tables(scratch):
    # Finite size: each box's P(t) is its series table's 1 s bins in 5 s means, and its dashed line
    # √(π/4N) for the box's N polar rods (the mean |Σ of N random unit vectors| / N, large N).
    sizes = drawn_in(scratch, "finite-size")
    checked = 0
    for phi, boxes in figures.FINITE_SIZE.items():
        for label, relative, rods in boxes:
            path = os.path.join(source, relative)
            key = f"φ_a = {phi:.2f}, {label}"
            if not os.path.isfile(path):
                assert f"P_polar: {key}" not in sizes, f"{key} drawn without a table"
                continue
            col, rows = read_table(path)
            assert are_bin_means(sizes[f"P_polar: {key}"]["y"],
                                 [float(r[col["P_polar"]]) for r in rows], 5), key
            assert abs(sizes[f"random headings: {key}"]["y"][0] - math.sqrt(math.pi / (4 * rods))) \
                < 1e-12, key
            checked += 1
    assert checked >= 8, f"only {checked} finite-size series were checked"
    print(f"checked the P(t) of {checked} boxes of reproduction-finite-size.png against their series")


def test_fig1f_points_are_their_block_means(scratch):
    # Fig. 1f: each D_r's point is the mean of its 15 s block means over 30–90 s.
    fig1f = drawn_in(scratch, "fig1f")
    expected = [(d_r, block_mean(os.path.join(source, relative), "P_polar", 30.0, 90.0))
                for d_r, relative in figures.FIG1F if os.path.isfile(os.path.join(source, relative))]
    check_points("fig1f", list(zip(fig1f["P"]["x"], fig1f["P"]["y"])), expected, 3)
    expected = [(d_r, block_mean(os.path.join(source, relative), "P_polar", 30.0, 90.0))
                for d_r, relative in figures.FIG1F_SEED2
                if os.path.isfile(os.path.join(source, relative))]
    if expected:
        check_points("fig1f seed 2",
                     list(zip(fig1f["P, seed 2"]["x"], fig1f["P, seed 2"]["y"])), expected, 1)
        # The mean of the seeds, at each D_r both have run.
        first = dict(zip(fig1f["P"]["x"], fig1f["P"]["y"]))
        expected = [(d_r, 0.5 * (first[d_r] + p)) for d_r, p in expected if d_r in first]
        check_points("fig1f mean of the seeds",
                     list(zip(fig1f["P, mean of the seeds"]["x"],
                              fig1f["P, mean of the seeds"]["y"])), expected, 1)


def test_the_bead_mediums_points_are_their_block_means(scratch):
    # The bead medium: each φ_a's point is the mean of its 15 s block means over 30–90 s.
    beads = drawn_in(scratch, "beads")
    expected = [(phi, block_mean(os.path.join(source, relative), "P_polar", 30.0, 90.0))
                for phi, relative in figures.BEADS if os.path.isfile(os.path.join(source, relative))]
    check_points("beads", list(zip(beads["P"]["x"], beads["P"]["y"])), expected, 2)


def test_light_beads_beside_the_default_mass(scratch):
    # Light beads: each φ_a's point is the mean of its 5 s block means over 30–45 s, and the
    # default mass's points beside them are the "beads" figure's.
    light = drawn_in(scratch, "beads-light")
    beads = drawn_in(scratch, "beads")
    expected = [(phi, block_mean(os.path.join(source, relative), "P_polar", 30.0, 45.0, block=5.0))
                for phi, relative in figures.BEADS_LIGHT
                if os.path.isfile(os.path.join(source, relative))]
    check_points("beads-light", list(zip(light["P"]["x"], light["P"]["y"])), expected, 3)
    assert light["P, mass 0.2"] == beads["P"], (light["P, mass 0.2"], beads["P"])


def test_fig4a_points_are_their_block_means(scratch):
    # Fig. 4a: each σ's P and the medium's S are the means of their 5 s block means over 30–60 s.
    fig4a = drawn_in(scratch, "fig4a")
    for drawn, name in (("P", "P_polar"), ("S_medium", "S_medium")):
        expected = [(sigma, block_mean(os.path.join(source, relative), name, 30.0, 60.0, block=5.0))
                    for sigma, relative in figures.FIG4A
                    if os.path.isfile(os.path.join(source, relative))]
        check_points("fig4a", list(zip(fig4a[drawn]["x"], fig4a[drawn]["y"])), expected, 3)


def test_fig4a_further_38mm_runs(scratch):
    fig4a = drawn_in(scratch, "fig4a")
    # Fig. 4a's further runs in the 38 mm box (second seeds, the caption's D_r = 0): each label's
    # points are the means of their 5 s block means, each over its own window, and each P(t) its
    # table's.
    for label in dict.fromkeys(label for *_, label in figures.FIG4A_MORE):
        expected = [(sigma, block_mean(os.path.join(source, relative), "P_polar", *window, block=5.0))
                    for sigma, relative, window, named in figures.FIG4A_MORE
                    if named == label and os.path.isfile(os.path.join(source, relative))]
        if expected:
            drawn = fig4a[f"P, {label}"]
            check_points(f"fig4a, {label}", list(zip(drawn["x"], drawn["y"])), expected, 1)
    for sigma, relative, _, label in figures.FIG4A_MORE:
        path = os.path.join(source, relative)
        if os.path.isfile(path):
            col, rows = read_table(path)
            assert same(fig4a[f"P(t): σ = {sigma:g}, {label}"]["y"],
                        [float(r[col["P_polar"]]) for r in rows]), (sigma, label)
        else:
            assert f"P(t): σ = {sigma:g}, {label}" not in fig4a, f"{label} drawn without a table"


def test_fig4a_88mm_runs(scratch):
    fig4a = drawn_in(scratch, "fig4a")
    # Fig. 4a's 88 mm runs (seed 2 of σ = 5.625 among them, under its own keys): each one's P(t)
    # and S(t) as drawn are its table's, and its P point the mean of its 5 s block means over its
    # own window.
    expected_88mm = {}
    for sigma, relative, window, seed in figures.FIG4A_88MM:
        path = os.path.join(source, relative)
        if not os.path.isfile(path):
            continue
        col, rows = read_table(path)
        for drawn, name in ((f"P(t): σ = {sigma:g}, 88 mm{seed}", "P_polar"),
                            (f"S(t): σ = {sigma:g}, 88 mm{seed}", "S_medium")):
            assert same(fig4a[drawn]["y"], [float(r[col[name]]) for r in rows]), drawn
        if window is not None:  # None: drawn in time only, still in its transient
            expected_88mm.setdefault(seed, []).append(
                (sigma, block_mean(path, "P_polar", *window, block=5.0)))
        print(f"checked the 88 mm run at σ = {sigma:g}{seed}: P(t) and S(t) ({len(rows)} bins)")
    for seed, expected in expected_88mm.items():
        key = f"P, 88 mm{seed}"
        check_points(f"fig4a 88 mm{seed}", list(zip(fig4a[key]["x"], fig4a[key]["y"])), expected, 1)


def test_fig4a_third_panel_bands(scratch):
    fig4a = drawn_in(scratch, "fig4a")
    # Fig. 4a's third panel: every longitudinal band drawn is its table's column, read here with the
    # csv module, and a run whose table has the column is drawn.
    bands_checked = 0
    band_runs = [(f"σ = {sigma:g}, 38 mm", relative) for sigma, relative in figures.FIG4A]
    band_runs += [(f"σ = {sigma:g}, 88 mm{seed}", relative)
                  for sigma, relative, _, seed in figures.FIG4A_88MM]
    for label, relative in band_runs:
        path = os.path.join(source, relative)
        if not os.path.isfile(path):
            continue
        col, rows = read_table(path)
        if "band_longitudinal" not in col:
            continue
        table = [float(r[col["band_longitudinal"]]) for r in rows]
        if all(math.isnan(v) for v in table):
            continue
        drawn = fig4a[f"longitudinal band: {label}"]["y"]
        assert same(drawn, table), label
        bands_checked += 1
    print(f"checked {bands_checked} longitudinal band series of fig4a against their tables")


def test_what_carries_p_is_each_runs_summary(scratch):
    # What carries P: every point of the alignment figure is its run's summary value (mean and
    # error), read here with the csv module; the runs of the 38 mm row (its third seeds too) and of
    # Fig. 1f are all drawn.
    alignment = drawn_in(scratch, "alignment")
    alignment_checked = 0
    for box, runs, axis in (("38 mm box", figures.ALIGNMENT_ROW, "φ_a"),
                            ("38 mm box, seed 3", figures.ALIGNMENT_ROW_SEED3, "φ_a"),
                            ("63 mm box", figures.ALIGNMENT_ROW_63MM, "φ_a"),
                            ("88 mm box", figures.ALIGNMENT_ROW_88MM, "φ_a"),
                            ("38 mm box, seed 2", figures.ALIGNMENT_NOISE, "D_r")):
        present = [(x, os.path.join(source, relative)) for x, relative in runs
                   if os.path.isfile(os.path.join(source, relative))]
        if box.startswith("38 mm"):
            assert len(present) == len(runs), f"{box}: a summary is missing"
        if not present:
            continue
        for name in ("P_polar", "P_independent", "flock_alignment"):
            curve = alignment[f"{name}: {box}, against {axis}"]
            expected_x, expected_y, expected_err = [], [], []
            for x, path in present:
                col, rows = read_table(path)
                expected_x.append(x)
                expected_y.append(float(rows[0][col[name]]))
                expected_err.append(float(rows[0][col[name + "_err"]]))
            assert same(curve["x"], expected_x) and same(curve["y"], expected_y), (box, name)
            assert same(curve["err"], expected_err), (box, name)
            alignment_checked += len(present)
    print(f"checked {alignment_checked} points of reproduction-alignment.png against their summaries")


def test_the_dilute_end_is_its_tables(scratch):
    # The dilute end: every G(r) drawn is its table's G and G_err wherever G has a value, and every
    # P(t) its series' 5 s means, the tables read here with the csv module; every run is drawn.
    dilute = drawn_in(scratch, "dilute")
    dilute_checked = 0
    for label, relative, _, _ in figures.DILUTE_CORRELATIONS:
        col, rows = read_table(os.path.join(source, relative))
        kept = [r for r in rows if not math.isnan(float(r[col["G"]]))]
        curve = dilute[f"G: {label}"]
        assert same(curve["x"], [float(r[col["r"]]) for r in kept]), label
        assert same(curve["y"], [float(r[col["G"]]) for r in kept]), label
        assert same(curve["err"], [float(r[col["G_err"]]) for r in kept]), label
        dilute_checked += 1
    for label, relative, _, _ in figures.DILUTE_SERIES:
        col, rows = read_table(os.path.join(source, relative))
        assert are_bin_means(dilute[f"P: {label}"]["y"], [float(r[col["P_polar"]]) for r in rows],
                             figures.DILUTE_BIN), label
        dilute_checked += 1
    print(f"checked {dilute_checked} curves of reproduction-dilute.png against their tables")


def test_what_sets_the_mediums_kicks(scratch):
    # What sets the medium's kicks: every run of each summary is drawn once, in the table's order,
    # at the mass its directory names (no medium at 0, the default run at the paper's 0.2), with its
    # own D_r, P and errors; the time-step panel has every run of its table, in order of dt.
    choices = drawn_in(scratch, "dilute-choices")
    choices_checked = 0
    for label, relative, _, _, _ in figures.DILUTE_MASS_TABLES:
        col, rows = read_table(os.path.join(source, relative))
        rows = [r for r in rows if not r[col["replicates"]]]
        named = {"polar-only": 0.0, "dt=": 0.2}
        mass = []
        for r in rows:
            run_name = r[col["run"]]
            if "medium.mass=" in run_name:
                mass.append(float(run_name.split("medium.mass=")[1].split("/")[0]))
            else:
                mass.append(next(m for key, m in named.items() if key in run_name))
        for name in ("D_r_C2_polar", "P_polar"):
            curve = choices[f"{name}: {label}"]
            assert same(curve["x"], mass), (label, name)
            assert same(curve["y"], [float(r[col[name]]) for r in rows]), (label, name)
            assert same(curve["err"], [float(r[col[name + "_err"]]) for r in rows]), (label, name)
            choices_checked += len(rows)
    col, rows = read_table(os.path.join(source, figures.DILUTE_DT_TABLE))
    rows.sort(key=lambda r: float(r[col["dt_s"]]))
    curve = choices["D_r_C2_polar: dt"]
    assert same(curve["x"], [float(r[col["dt_s"]]) * 1e6 for r in rows])
    assert same(curve["y"], [float(r[col["D_r_C2_polar"]]) * 10.0 for r in rows])  # drawn in 0.1 rad²/s
    choices_checked += len(rows)
    print(f"checked {choices_checked} points of reproduction-dilute-choices.png against their summaries")


def test_the_same_turn_seed_by_seed(scratch):
    # The same turn seed by seed: every run listed is drawn in its mass's panel as its series' 5 s
    # means, and its table is the run of that mass (its file names the mass; seed 1 at the paper's
    # 0.2 is the time-step scan's 2.5 µs run).
    seeds = drawn_in(scratch, "dilute-seeds")
    seeds_checked = 0
    for mass, runs in figures.DILUTE_SEED_SERIES.items():
        for label, relative in runs:
            # "0.1.s" is in 0.1.series and 0.1.seed3, not in 0.15.series.
            names_its_mass = f"{mass:g}.s" in os.path.basename(relative)
            assert names_its_mass or "dt-38mm-2.5e-06" in relative, relative
            col, rows = read_table(os.path.join(source, relative))
            assert are_bin_means(seeds[f"P: {mass}: {label}"]["y"],
                                 [float(r[col["P_polar"]]) for r in rows], figures.DILUTE_BIN), relative
            seeds_checked += 1
    assert len(seeds) == seeds_checked, sorted(seeds)
    print(f"checked {seeds_checked} curves of reproduction-dilute-seeds.png against their series")


def test_fig5b_at_the_papers_d(scratch):
    # Fig. 5b at the paper's d: each point is its summary's comoving-frame speed at d with its error,
    # one curve per time base of the velocities, and each profile is its table's v_along wherever the
    # shell holds enough pairs.
    fig5b = drawn_in(scratch, "fig5b-gpu")
    fig5b_checked = 0
    for label, infix in figures.FIG5B_GPU_LAGS:
        means, errors = [], []
        for phi in figures.FIG5B_GPU_PHI:
            col, rows = read_table(os.path.join(
                source, f"{figures.FIG5B_GPU}/medium_velocity_{infix}phi_a{phi}.summary.csv"))
            assert len(rows) == 1, (label, phi)
            means.append(float(rows[0][col["medium_speed_at_d"]]))
            errors.append(float(rows[0][col["medium_speed_at_d_err"]]))
        curve = fig5b[f"speed at d: {label}"]
        assert same(curve["x"], [float(phi) for phi in figures.FIG5B_GPU_PHI]), label
        assert same(curve["y"], means) and same(curve["err"], errors), label
        fig5b_checked += len(means)
    for phi in figures.FIG5B_GPU_PHI:
        col, rows = read_table(os.path.join(
            source, f"{figures.FIG5B_GPU}/medium_velocity_lag1s_phi_a{phi}.csv"))
        kept = [r for r in rows if float(r[col["pairs"]]) >= figures.FIG5B_GPU_MIN_PAIRS]
        curve = fig5b[f"v_along over 1 s: φ_a = {phi}"]
        assert same(curve["x"], [float(r[col["r"]]) for r in kept]), phi
        assert same(curve["y"], [float(r[col["v_along"]]) for r in kept]), phi
        # The profile reaches the paper's d = 100 mm: the box was chosen for it.
        assert curve["x"][-1] >= 100.0, curve["x"][-1]
        fig5b_checked += 1
    print(f"checked {fig5b_checked} points and profiles of reproduction-fig5b-gpu.png against their "
          "tables")


def test_fig5b_in_the_end_matters_reading(scratch):
    # Fig. 5b in the End Matter's reading: each φ_a's points are its blocks table's (|P|, v_par), and
    # its α/Γ_f is their slope through the origin, Σ v P / Σ P², computed here from the table.
    drift = drawn_in(scratch, "fig5b-drift")
    drift_checked = []
    for phi, relative in figures.FIG5B_DRIFT:
        path = os.path.join(source, relative)
        if not os.path.isfile(path):
            continue  # a φ_a not analysed yet, left out of the figure too
        col, rows = read_table(path)
        p = [float(r[col["P_polar"]]) for r in rows]
        v = [float(r[col["v_medium_along_polar"]]) for r in rows]
        assert same(drift[f"blocks: φ_a = {phi}"]["x"], p) and \
            same(drift[f"blocks: φ_a = {phi}"]["y"], v), phi
        slope = sum(a * b for a, b in zip(p, v)) / sum(a * a for a in p)
        at = drift["alpha/Gamma_f"]["x"].index(float(phi))
        assert abs(drift["alpha/Gamma_f"]["y"][at] - slope) < 1e-9, (phi, slope)
        drift_checked.append(phi)
    assert len(drift_checked) == len(drift["alpha/Gamma_f"]["x"]) >= 2, drift_checked
    print(f"checked α/Γ_f and the blocks of reproduction-fig5b-drift.png at φ_a = "
          f"{', '.join(drift_checked)} against their tables")
