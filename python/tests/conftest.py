"""Shared fixtures: a small run made by the rodsea executable, as users make one."""
import os
import subprocess

import pytest

EXECUTABLE = os.environ.get("RODSEA_EXECUTABLE", "rodsea")

SMALL = """[box]
side = 20.0
[[species]]
name = "polar"
kind = "polar_rod"
count = 6
[[species]]
name = "medium"
kind = "apolar_rod"
length = 2.5
area_fraction = 0.15
[time]
duration = 0.01
[output]
interval = 0.002
[run]
seed = 5
"""


def rodsea(*args, check=True):
    r = subprocess.run([EXECUTABLE, *map(str, args)], capture_output=True, text=True)
    if check and r.returncode != 0:
        raise AssertionError(f"rodsea {' '.join(map(str, args))}: exit {r.returncode}\n{r.stderr}")
    return r


@pytest.fixture(scope="session")
def small_config(tmp_path_factory):
    path = tmp_path_factory.mktemp("config") / "small.toml"
    path.write_text(SMALL)
    return path


@pytest.fixture(scope="session")
def small_run(tmp_path_factory, small_config):
    """The run directory and the CLI's report of it (its stdout, with the state hash)."""
    out = tmp_path_factory.mktemp("runs") / "small"
    report = rodsea("run", small_config, "--out", out).stdout
    rodsea("analyze", out, "--from", "0", "--quiet")
    return out, report
