"""`import rodsea` against the command line: the same numbers on the same run, zero-copy views,
the same error messages, the GIL released while stepping, GSD files gsd.hoomd reads back."""
import json
import re
import threading

import h5py
import numpy as np
import pytest

import rodsea
from conftest import rodsea as cli


def test_the_state_hash_after_a_run_is_the_clis(small_config, small_run):
    _, report = small_run
    cli_hash = re.search(r"state hash ([0-9a-f]+)", report).group(1)
    config = rodsea.load_config(small_config)
    sim = rodsea.Simulation(config)
    assert sim.run(steps=config.total_steps) == config.total_steps
    assert format(sim.state_hash(), "x") == cli_hash


def test_a_checkpoint_continues_bit_for_bit(small_config, tmp_path):
    config = rodsea.load_config(small_config)
    straight = rodsea.Simulation(config)
    straight.run(steps=600)
    stopped = rodsea.Simulation(config)
    stopped.run(steps=300)
    stopped.save_checkpoint(str(tmp_path / "c.h5"))
    resumed = rodsea.Simulation.from_checkpoint(str(tmp_path / "c.h5"))
    resumed.run(steps=300)
    assert resumed.state_hash() == straight.state_hash()
    assert resumed.step == 600


def test_the_runs_own_checkpoint_is_the_clis_final_state(small_run):
    run_dir, report = small_run
    sim = rodsea.Simulation.from_checkpoint(str(run_dir / "checkpoint.h5"))
    assert format(sim.state_hash(), "x") == re.search(r"state hash ([0-9a-f]+)", report).group(1)


def test_state_arrays_are_read_only_views_that_follow_the_steps(small_config):
    sim = rodsea.Simulation(rodsea.load_config(small_config))
    n = sum(s["count"] for s in rodsea.load_config(small_config).species)
    for name, width in (("positions", 3), ("quaternions", 4), ("velocities", 3), ("spins", 3)):
        a = getattr(sim, name)
        assert a.shape == (n, width) and a.dtype == np.float64
        assert not a.flags.writeable and not a.flags.owndata  # a view, not a copy
    assert sim.species.dtype == np.uint32 and sim.species.shape == (n,)
    view = sim.positions
    before = view.copy()
    sim.run(steps=200)
    assert not np.array_equal(view, before)          # the same memory, stepped on
    assert np.array_equal(view, sim.positions)
    with pytest.raises(ValueError):
        view[0, 0] = 1.0
    assert set(sim.timings()) >= {"free_flight", "contact_search", "resolution", "total"}
    assert sim.backend == "cpu"


def test_set_state_is_checked_like_a_resumed_state(small_config):
    sim = rodsea.Simulation(rodsea.load_config(small_config))
    positions = np.array(sim.positions)
    positions[2, 0] = np.nan
    with pytest.raises(rodsea.InvalidParameter, match=r"bodies\[2\]\.position"):
        sim.set_state(positions=positions)
    moved = np.array(sim.positions)
    moved[0, 0] = (moved[0, 0] + 0.001) % 20.0
    sim.set_state(positions=moved)
    assert sim.positions[0, 0] == moved[0, 0]


def test_threads_take_the_command_lines_range(small_config):
    config = rodsea.load_config(small_config)
    for threads in (0, 257, 10**6):
        with pytest.raises(rodsea.InvalidParameter, match=r"threads.*\[1, 256\]"):
            rodsea.Simulation(config, threads=threads)


def test_errors_carry_the_command_lines_messages(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text("[box]\nside = -3.0\n")
    r = cli("info", bad, check=False)
    assert r.returncode == 2
    with pytest.raises(rodsea.InvalidParameter) as e:
        rodsea.load_config(bad)
    assert str(e.value) in r.stderr
    assert isinstance(e.value, ValueError)
    with pytest.raises(rodsea.InvalidParameter, match="box.side"):
        rodsea.load_config({"box": {"side": -3.0}})
    with pytest.raises(rodsea.FileError, match="no such file"):
        rodsea.load_config(tmp_path / "missing.toml")
    with pytest.raises(rodsea.FileError):
        rodsea.open_run(tmp_path)


def test_a_config_reports_the_noise_rule_and_both_readings_of_the_mass():
    config = rodsea.load_config(
        {
            "noise": {"mode": "set", "epsilon": 1.0},
            "species": [
                {"name": "polar", "kind": "polar_rod", "count": 1},
                {"name": "medium", "kind": "apolar_rod", "length": 2.5, "count": 1, "density": 0.2},
            ],
        }
    )
    assert config.noise_mode == "set"
    assert config.noise_epsilon == 1.0
    polar, medium = config.species
    assert polar["mass"] == 1.0 and polar["density"] == pytest.approx(1.0, rel=1e-12)
    # 0.2 of the polar rod's density in 0.636 of its 3.119 mm³: 0.041 of its mass.
    assert medium["density"] == pytest.approx(0.2, rel=1e-12)
    assert medium["mass"] == pytest.approx(0.0408, abs=2e-4)


def test_stepping_releases_the_gil(small_config):
    sim = rodsea.Simulation(rodsea.load_config(small_config))
    counted, stop = [0], threading.Event()

    def count():
        while not stop.is_set():
            counted[0] += 1

    other = threading.Thread(target=count)
    other.start()
    sim.run(steps=4000)
    during = counted[0]
    stop.set()
    other.join()
    # With the GIL held the other thread would get at most a switch interval's worth.
    assert during > 10000


def test_open_run_gives_frames_series_and_analysis(small_run):
    run_dir, _ = small_run
    run = rodsea.open_run(run_dir)
    assert run.frames == 6 and len(run.times) == 6
    n = len(run.species)
    assert run.positions[-1].shape == (n, 3)
    assert run.positions[1:4].shape == (3, n, 3)
    assert np.array_equal(run.positions[-1], run.frame(5)["positions"])
    with h5py.File(run_dir / "trajectory.h5") as f:
        stored = f["particles/bodies/position/value"][3]
    assert np.array_equal(run.positions[3], stored.astype(np.float64))
    p = run.series("polar_order_polar")
    assert p.shape == (6,) and "nematic_order_medium" in run.series_names
    analysis = run.analysis()
    assert "P_polar" in analysis["scalars"] and "g_r_theta" in analysis["maps"]
    # The coarse-grained fields conserve the area: the mean polar map averages to φ_p.
    fields = run.fields()
    phi = fields["mean"]["polar"]["area_fraction"]
    assert phi.shape == (len(fields["y"]), len(fields["x"]))
    phi_p = next(s["area_fraction"] for s in analysis["json"]["parameters"]["species"]
                 if s["name"] == "polar")
    assert abs(phi.mean() - phi_p) < 1e-9 * max(phi_p, 1.0)
    assert fields["series"]["polar"]["area_fraction"].shape[1:] == phi.shape
    assert "defects/x" in analysis["datasets"]


def test_order_parameters_equal_the_recorded_series(small_run):
    run = rodsea.open_run(small_run[0])
    recorded = run.series("polar_order_polar")
    for k in range(run.frames):
        frame = run.frame(k)
        polar = frame["species"] == 0
        p = rodsea.OrderParameters().compute(frame["angles"][polar]).P
        # The series is computed from the doubles in the run; frames are stored in float32.
        assert p == pytest.approx(recorded[k], abs=1e-6)


def test_corotating_maps_equal_rodsea_analyze(small_run):
    run_dir, _ = small_run
    run = rodsea.open_run(run_dir)
    summary = json.load(open(run_dir / "analysis" / "analysis.json"))
    p = {k: v["value"] for k, v in summary["observables"]["corotating"]["parameters"].items()}
    maps = rodsea.CorotatingMaps(r_max=p["r_max"], r_bins=int(p["r_bins"]),
                                 theta_bins=int(p["theta_bins"]))
    pair = rodsea.PairCorrelation(r_max=5.0, bin=0.5)
    for k in range(run.frames):
        frame = run.frame(k)
        polar = frame["species"] == 0
        maps.compute(run.box, frame["positions"][polar], frame["angles"][polar])
        pair.compute(run.box, frame["positions"][polar], frame["angles"][polar])
    assert maps.frames == run.frames
    with h5py.File(run_dir / "analysis" / "analysis.h5") as f:
        g = f["maps/g_r_theta/value"][()]
        r_edges = f["maps/g_r_theta/r_edges"][()]
    np.testing.assert_allclose(maps.r_edges, r_edges)
    np.testing.assert_allclose(maps.g, g, rtol=1e-12, equal_nan=True)
    assert pair.g.shape == pair.bin_centers.shape


def test_flocks_time_correlation_segregation_and_medium_velocity_compute(small_run):
    run = rodsea.open_run(small_run[0])
    frame = run.frame(-1)
    polar = frame["species"] == 0
    flocks = rodsea.Flocks(eps=2.25, min_samples=2).compute(run.box, frame["positions"][polar])
    assert flocks.labels.shape == (polar.sum(),)
    assert flocks.largest == (flocks.sizes.max() if flocks.sizes.size else 0)
    # Two points 1 mm apart across the periodic edge form one flock.
    edge = rodsea.Flocks(eps=1.5, min_samples=2).compute((10.0, 10.0), [[0.2, 5.0], [9.7, 5.0]])
    assert list(edge.labels) == [0, 0]
    angles = np.array([run.frame(k)["angles"][polar] for k in range(run.frames)])
    c = rodsea.TimeCorrelation(m=1, max_lag=3).compute(np.unwrap(angles, axis=0), 0.002)
    assert c.C[0] == pytest.approx(1.0) and len(c.C) == 4
    sigma = rodsea.segregation(run.box, frame["positions"], polar, cell=5.0)
    assert 0.0 <= sigma <= 1.0
    # Rods along x in a stripe along x, a quarter of the box wide: a longitudinal band whose
    # mode (0, 1) is the stripe's transform, |sin(n k δ/2) / (n sin(k δ/2))| for n rows δ apart.
    side, n, w = 40.0, 5, 10.0
    ys = 15.0 + w * (np.arange(n) + 0.5) / n
    xs = side * (np.arange(8) + 0.5) / 8
    stripe = np.array([[x, y] for y in ys for x in xs])
    b = rodsea.bands((side, side), stripe, np.zeros(len(stripe)))
    k, d = 2 * np.pi / side, w / n
    expected = abs(np.sin(n * k * d / 2) / (n * np.sin(k * d / 2)))
    assert b["longitudinal"] == pytest.approx(expected, abs=1e-12)
    assert b["modes"][(0, 1)] == pytest.approx(expected, abs=1e-12)
    assert b["transverse"] == pytest.approx(0.0, abs=1e-12) and b["axis"] == pytest.approx(0.0)
    assert b["longitudinal_at"] == pytest.approx(15.0 + w / 2, abs=1e-9)  # the stripe's centre
    medium = ~polar
    mv = rodsea.MediumVelocity(d=3.0, r_max=5.0, bin=1.0).compute(
        run.box, frame["positions"][medium], frame["velocities"][medium],
        frame["positions"][polar], frame["angles"][polar], frame["velocities"][polar])
    assert mv.pairs.sum() > 0


def test_gsd_export_reads_back_with_its_shapes_orientations_and_log(small_run, tmp_path):
    gsd_hoomd = pytest.importorskip("gsd.hoomd")
    run_dir, _ = small_run
    out = tmp_path / "run.gsd"
    cli("export", run_dir, "--format", "gsd", "-o", out, "--quiet")
    run = rodsea.open_run(run_dir)
    with gsd_hoomd.open(str(out), "rb") as t:
        assert len(t) == run.frames
        frame = t[2]
        assert frame.particles.types == ["polar", "medium"]
        np.testing.assert_array_equal(frame.particles.typeid, run.species)
        np.testing.assert_allclose(frame.particles.orientation, run.quaternions[2], atol=1e-7)
        with h5py.File(run_dir / "trajectory.h5") as f:
            radii = f["parameters/rodsea/species/0/sphere_radii"][()]
            offsets = f["parameters/rodsea/species/0/sphere_offsets"][()]
        shape = frame.particles.type_shapes[0]
        assert shape["type"] == "SphereUnion"
        np.testing.assert_allclose(shape["diameters"], 2 * radii, rtol=1e-6)
        np.testing.assert_allclose(shape["centers"], offsets, rtol=1e-6)
        # Centred box: x and y shifted by -L/2.
        np.testing.assert_allclose(frame.particles.position[:, 0] + 10.0,
                                   run.positions[2][:, 0], atol=1e-5)
        assert frame.log["rodsea/time"][0] == pytest.approx(run.times[2])
        assert frame.log["rodsea/polar_order_polar"][0] == pytest.approx(
            run.series("polar_order_polar")[2])


def test_a_campaigns_collected_table_loads_as_columns(tmp_path):
    collected = tmp_path / "campaign" / "collected"
    collected.mkdir(parents=True)
    (collected / "points.csv").write_text(
        "# rodsea collected points; units: phi_medium [1] P_polar [1]\n"
        "point,phi_medium,P_polar,P_polar_err\nphi=0.2,0.2,0.31,0.02\nphi=0.5,0.5,0.12,nan\n")
    t = rodsea.load_collected(tmp_path / "campaign")
    np.testing.assert_allclose(t["phi_medium"], [0.2, 0.5])
    assert t["point"] == ["phi=0.2", "phi=0.5"] and np.isnan(t["P_polar_err"][1])
    with pytest.raises(rodsea.FileError, match="no such table"):
        rodsea.load_collected(tmp_path / "campaign", table="runs")


def test_the_tutorial_script_runs_and_draws(tmp_path):
    import os
    import subprocess
    import sys
    script = os.path.join(os.environ.get("RODSEA_SOURCE_DIR", "."), "examples", "python",
                          "demo.py")
    r = subprocess.run([sys.executable, script, "--duration", "0.02", "--out", str(tmp_path)],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    for name in ("polar_order.png", "g_r_theta.png"):
        assert (tmp_path / name).stat().st_size > 10000


def test_a_view_taken_before_set_state_stays_valid(small_config):
    sim = rodsea.Simulation(rodsea.load_config(small_config))
    old = sim.positions
    kept = old.copy()
    moved = np.array(sim.positions)
    moved[0, 0] = (moved[0, 0] + 0.001) % 20.0
    sim.set_state(positions=moved)
    sim.run(steps=100)
    del sim
    # The old engine lives on in the view: the state as it was, not freed memory.
    np.testing.assert_array_equal(old, kept)


def test_observables_refuse_nonsense_by_name():
    with pytest.raises(rodsea.InvalidParameter, match="segregation.cell"):
        rodsea.segregation((10.0, 10.0), np.zeros((3, 2)), np.array([1, 0, 0], bool), cell=0.0)
    with pytest.raises(rodsea.InvalidParameter, match=r"positions\[1\]"):
        rodsea.dbscan((10.0, 10.0), np.array([[1.0, 1.0], [np.nan, 2.0]]))
    with pytest.raises(rodsea.InvalidParameter, match="pair.bin"):
        rodsea.PairCorrelation(r_max=5.0, bin=0.0)
    with pytest.raises(rodsea.InvalidParameter, match="angles"):
        rodsea.CorotatingMaps().compute((10.0, 10.0), np.zeros((3, 2)), np.zeros(2))


def pair_field(x, y, xp, xm, y0, side, images=8):
    """Director angle of a +1/2 at (xp, y0) and a -1/2 at (xm, y0), periodic in the box."""
    t = np.zeros_like(x)
    for a in range(-images, images + 1):
        for b in range(-images, images + 1):
            t += 0.5 * np.arctan2(y - y0 - b * side, x - xp - a * side)
            t -= 0.5 * np.arctan2(y - y0 - b * side, x - xm - a * side)
    return t


def test_fields_defects_and_level_sets_from_python():
    # Rods at the cell centres of a 2 mm grid whose axes follow a planted ± pair: the fields
    # conserve the count, and exactly the pair is found (periodic field, zero net charge).
    side = 32.0
    c = np.arange(1.0, side, 2.0)
    x, y = [a.ravel() for a in np.meshgrid(c, c)]
    theta = pair_field(x, y, 10.0, 22.0, 16.0, side)
    f = rodsea.coarse_grain((side, side), 2.0, np.column_stack([x, y]), theta, body_area=2.0)
    assert f["qxx"].shape == (16, 16)
    assert abs(f["weight"].sum() - len(x)) < 1e-9
    assert abs(f["area_fraction"].mean() - len(x) * 2.0 / side**2) < 1e-12
    d = rodsea.nematic_defects((side, side), 2.0, f["qxx"], f["qxy"])
    assert sorted(d["charge"]) == [-0.5, 0.5]
    plus = d["charge"] == 0.5
    assert abs(d["x"][plus][0] - 10.0) < 2.0 and abs(d["x"][~plus][0] - 22.0) < 2.0
    # A stripe's edges: two straight lines the box's height long.
    stripe = ((f["x"] > 10) & (f["x"] < 20)).astype(float)[None, :].repeat(16, axis=0)
    length, above = rodsea.level_set((side, side), 2.0, stripe, 0.5)
    assert abs(length - 2 * side) < 1e-9 and abs(above - 5 / 16) < 1e-12
    # The pair followed over two frames 0.5 mm apart: two tracks, two frames each.
    tracker = rodsea.DefectTracker((side, side), link=2.0, pair=4.0)
    tracker.add_frame(0.0, d["x"], d["y"], d["charge"], d["orientation"])
    tracker.add_frame(0.1, d["x"] + 0.5, d["y"], d["charge"], d["orientation"])
    assert [len(t["time"]) for t in tracker.tracks] == [2, 2]
    assert [e[0] for e in tracker.events] == ["birth", "birth"]
    with pytest.raises(rodsea.InvalidParameter, match="qxx"):
        rodsea.nematic_defects((side, side), 2.0, f["qxx"][:5], f["qxy"])


def test_flocks_followed_in_time_from_python():
    # Two flocks of five rods heading +x; the first catches the second in the third frame.
    box = (60.0, 60.0)
    tracker = rodsea.FlockTracker(box)
    for k in range(4):
        xs = np.r_[10.0 + k + 0.8 * np.arange(5), 18.0 + 0.8 * np.arange(5)]
        positions = np.column_stack([xs, np.full(10, 30.0)])
        labels = rodsea.dbscan(box, positions, eps=2.25, min_samples=3)
        tracker.add_frame(0.01 * k, labels, positions, np.zeros(10))
    kinds = [e[0] for e in tracker.events]
    assert kinds.count("merge") == 1
    first = tracker.tracks[0]
    assert abs(first["vx"][1] - 100.0) < 1e-9  # 1 mm per 0.01 s
    assert first["leader"][1] == 4  # the rod furthest ahead along +x


def test_from_checkpoint_and_set_state_check_what_resume_checks(small_config, tmp_path):
    """A checkpoint `rodsea run --continue` refuses is refused here too, and set_state refuses
    bodies on top of each other (the next step used to blame time.dt instead)."""
    sim = rodsea.Simulation(rodsea.load_config(small_config))
    sim.run(steps=200)
    sim.save_checkpoint(str(tmp_path / "c.h5"))
    with h5py.File(tmp_path / "c.h5", "r+") as f:
        species = f["rodsea_checkpoint/species"]
        edited = species[:]
        edited[0] = 1  # a polar rod made an apolar one
        species[...] = edited
    with pytest.raises(rodsea.FileError, match="dataset species holds 5 bodies of species 0"):
        rodsea.Simulation.from_checkpoint(str(tmp_path / "c.h5"))
    hash_before = sim.state_hash()
    positions = sim.positions.copy()
    positions[1] = positions[0]
    with pytest.raises(rodsea.InvalidParameter, match=r"bodies\[\d+\]\.position.*overlapping body"):
        sim.set_state(positions=positions)
    assert sim.state_hash() == hash_before
