"""A seeded fuzz of the module's entry points: random shapes, dtypes, NaN, infinities, huge and
tiny values, wrong types, and calls from two threads at once. Every call must either return or
raise one of the module's errors (rodsea.InvalidParameter is a ValueError) or Python's TypeError;
a crash, a MemoryError or any other exception fails. The seeds are fixed, so a failure repeats."""
import math
import threading

import numpy as np
import pytest

import rodsea

ALLOWED = (ValueError, TypeError, RuntimeError, OverflowError, rodsea.FileError,
           rodsea.BlowUpError)

HOSTILE = [0, 1, -1, 0.5, 1e-12, -1e-9, 1e9, 1e300, -1e300, math.inf, -math.inf, math.nan,
           2**62, -(2**62), 10**30, True, "1", None, [1.0, 2.0], np.float32(2.0), np.int64(3)]
BOX = (20.0, 20.0)


def plausible(rng, name):
    """Arguments a user would pass: n bodies (0 to 60) in a 20 mm box."""
    n = int(rng.integers(0, 61))
    positions, angles = rng.uniform(0.0, 20.0, (n, 3)), rng.uniform(-np.pi, np.pi, n)
    velocities = rng.normal(0.0, 10.0, (n, 3))
    q = rng.normal(size=(n, 4))
    q /= np.maximum(np.linalg.norm(q, axis=1, keepdims=True), 1e-9)
    frames = int(rng.integers(1, 30))
    return {
        "order_parameter": [angles, int(rng.integers(1, 3))],
        "in_plane_angles": [q],
        "PairCorrelation": [9.0, 0.5, BOX, positions, angles],
        "CorotatingMaps": [9.0, 10, 12, BOX, positions, angles],
        "bands": [BOX, positions, angles],
        "MediumVelocity": [5.0, 9.0, 1.0, BOX, positions, velocities, positions[: n // 3],
                           angles[: n // 3], velocities[: n // 3]],
        "coarse_grain": [BOX, 2.0, positions, angles, velocities, 1.0],
        "orientation_autocorrelation": [np.cumsum(rng.normal(0, 0.1, (frames, n)), axis=0), 1,
                                        int(rng.integers(0, frames + 3))],
        "rotational_diffusion": [np.exp(-0.1 * np.arange(frames)), 0.01, 1, 0.2],
    }[name]


def hostile(rng, value):
    """`value` made hostile: another value or type, NaN or infinity inside it, another dtype,
    one row more or less, or its axes swapped."""
    r = rng.random()
    if not isinstance(value, np.ndarray) or value.size == 0 or r < 0.3:
        return HOSTILE[int(rng.integers(0, len(HOSTILE)))]
    a = value.copy()
    if r < 0.5 and np.issubdtype(a.dtype, np.floating):
        a.reshape(-1)[int(rng.integers(0, a.size))] = rng.choice([np.nan, np.inf, -np.inf, 1e300])
        return a
    if r < 0.65:
        return a.astype(rng.choice([np.float32, np.int64, np.bool_, np.complex128]))
    if r < 0.85:
        return a[1:] if rng.random() < 0.5 else np.concatenate([a, a[:1]])
    return a.T


def call(name, args):
    if name == "PairCorrelation":
        return rodsea.PairCorrelation(*args[:2]).compute(*args[2:])
    if name == "CorotatingMaps":
        return rodsea.CorotatingMaps(*args[:3]).compute(*args[3:])
    if name == "MediumVelocity":
        return rodsea.MediumVelocity(*args[:3]).compute(*args[3:])
    return getattr(rodsea, name)(*args)


NAMES = ["order_parameter", "in_plane_angles", "PairCorrelation", "CorotatingMaps", "bands",
         "MediumVelocity", "coarse_grain", "orientation_autocorrelation", "rotational_diffusion"]


@pytest.mark.parametrize("name", NAMES)
@pytest.mark.filterwarnings("ignore::RuntimeWarning", "ignore::numpy.ComplexWarning")
def test_no_entry_point_crashes_on_hostile_input(name):
    rng = np.random.default_rng(sum(map(ord, name)))
    outcomes = {"returned": 0, "refused": 0}
    for _ in range(300):
        args = plausible(rng, name)
        for _ in range(int(rng.integers(0, 3))):  # none, one or two arguments made hostile
            i = int(rng.integers(0, len(args)))
            args[i] = hostile(rng, args[i])
        try:
            call(name, args)
            outcomes["returned"] += 1
        except ALLOWED:
            outcomes["refused"] += 1
    # Both happen: the fuzz reaches the computations, not only the argument checks.
    assert min(outcomes.values()) > 20, outcomes


# Plausible arguments with one value made hostile: the checks, not numpy's conversion, must
# refuse it.
def test_observables_refuse_mismatched_lengths_and_bins_by_name():
    rng = np.random.default_rng(7)
    p50, p40 = rng.uniform(0, 20, (50, 3)), rng.uniform(0, 20, (40, 3))
    with pytest.raises(rodsea.InvalidParameter, match="medium_velocities"):
        rodsea.MediumVelocity(d=5.0, r_max=9.0, bin=1.0).compute(
            (20.0, 20.0), p50, p40, p50[:5], np.zeros(5), p50[:5])
    with pytest.raises(rodsea.InvalidParameter, match="medium_velocities"):
        rodsea.MediumVelocity(d=5.0, r_max=9.0, bin=1.0).compute(
            (20.0, 20.0), p50, np.zeros((0, 3)), p50[:5], np.zeros(5), p50[:5])
    with pytest.raises(rodsea.InvalidParameter, match="rod_velocities"):
        rodsea.MediumVelocity(d=5.0, r_max=9.0, bin=1.0).compute(
            (20.0, 20.0), p50, p50, p50[:5], np.zeros(5), p50[:4])
    with pytest.raises(rodsea.InvalidParameter, match=r"cell.*at most 1e\+07 bins"):
        rodsea.coarse_grain((20.0, 20.0), 1e-9, p50, np.zeros(50))
    for make in (lambda: rodsea.PairCorrelation(r_max=10.0, bin=1e-9),
                 lambda: rodsea.MediumVelocity(d=5.0, r_max=10.0, bin=1e-12),
                 lambda: rodsea.CorotatingMaps(r_max=10.0, r_bins=100000, theta_bins=100000)):
        with pytest.raises(rodsea.InvalidParameter, match="bins"):
            make()


def test_run_refuses_a_length_it_cannot_count(small_config):
    sim = rodsea.Simulation(rodsea.load_config(small_config))
    for kwargs in ({"seconds": 1e300}, {"seconds": math.nan}, {"steps": 2**62},
                   {"seconds": -1.0}):
        with pytest.raises(rodsea.InvalidParameter):
            sim.run(**kwargs)
    assert sim.step == 0


def test_dict_configs_take_numpy_numbers_and_refuse_keys_that_are_not_keys():
    base = {"box": {"side": np.float32(30.0)},
            "species": [{"name": "polar", "kind": "polar_rod", "count": np.int64(3)}]}
    assert rodsea.load_config(base).box == (30.0, 30.0)
    for bad in ({"box": {"side = 1\n[evil]\nx": 1.0}},
                {"box]\n[time": {"duration": 1.0}},
                {"box": {1: 2.0}},
                {"species": [{"name": "p", "kind": "polar_rod", "count": 3, "x y": 1}]}):
        with pytest.raises(rodsea.InvalidParameter, match="key"):
            rodsea.load_config({**base, **bad})


def test_a_simulation_takes_one_call_at_a_time(small_config):
    """run() frees the GIL; another thread's call meanwhile is refused, not raced: the state
    after the run is the one a run alone reaches, bit for bit."""
    config = rodsea.load_config(small_config)
    alone = rodsea.Simulation(config)
    alone.run(steps=30000)
    sim = rodsea.Simulation(config)
    same_state = sim.positions.copy()
    stepping = threading.Thread(target=sim.run, kwargs={"steps": 30000})
    stepping.start()
    refused = set()
    calls = {
        "positions": lambda: sim.positions,
        "state_hash": sim.state_hash,
        "set_state": lambda: sim.set_state(positions=same_state),
        "run": lambda: sim.run(steps=10),
        "save_checkpoint": lambda: sim.save_checkpoint("/nonexistent/c.h5"),
    }
    while stepping.is_alive() and len(refused) < len(calls):
        for what, call in calls.items():
            if what in refused or what in ("set_state", "run") and not refused:
                continue  # the mutating calls only once the run has surely begun
            try:
                call()
            except RuntimeError as e:
                assert "running in another thread" in str(e)
                refused.add(what)
            except rodsea.FileError:
                pass  # save_checkpoint before the run began: its path is refused
    stepping.join()
    assert refused == set(calls), f"not refused while running: {set(calls) - refused}"
    assert sim.step == 30000
    assert sim.state_hash() == alone.state_hash()
