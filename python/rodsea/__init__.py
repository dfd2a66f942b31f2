"""rodsea from Python: build, run, read and analyse vibrated-rod simulations (docs/python.md).

    import rodsea
    config = rodsea.load_config("examples/demo.toml")        # or a dict, as the TOML's tables
    sim = rodsea.Simulation(config)                          # the initial state `rodsea run` builds
    sim.run(seconds=0.01)                                    # releases the GIL while it steps
    sim.positions                                            # (N, 3) mm, a read-only view
    run = rodsea.open_run("out/demo")                        # a run directory written by `rodsea run`
    run.positions[-1], run.series("polar_order_polar"), run.analysis()["scalars"]

Units: mm, s, rad (mm/s, rad/s); masses in the config's unit. Errors arrive as
rodsea.InvalidParameter (a ValueError), rodsea.FileError (an OSError) and rodsea.BlowUpError,
with the command line's messages.
"""
import os

# rodsea opens its HDF5 files without HDF5's file locks (a running simulation's trajectory stays
# readable); h5py in the same process must do the same, or HDF5 refuses a file opened both ways
# ("file locking flag values don't match").
os.environ.setdefault("HDF5_USE_FILE_LOCKING", "FALSE")

from ._rodsea import (  # noqa: E402,F401  (the C++ core, re-exported)
    BlowUpError,
    Config,
    CorotatingMaps,
    DefectTracker,
    FileError,
    FlockTracker,
    InvalidParameter,
    MediumVelocity,
    PairCorrelation,
    Simulation,
    __version__,
    bands,
    coarse_grain,
    dbscan,
    in_plane_angles,
    level_set,
    nematic_defects,
    order_parameter,
    orientation_autocorrelation,
    random_mixing_segregation,
    rotational_diffusion,
    segregation,
)
from .campaign import load_collected  # noqa: E402,F401
from .config import load_config  # noqa: E402,F401
from .observables import Flocks, OrderParameters, TimeCorrelation  # noqa: E402,F401
from .run import Run, open_run  # noqa: E402,F401
