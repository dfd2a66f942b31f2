"""What INPUT is: one run's analysis (a directory or its analysis.json) or a table of runs (CSV)."""
import os

from .common import EXIT_IO, PlotError

TABLE_HINT = ("`rodsea analyze RUN1 RUN2 ... --table T.csv` writes one, "
              "as does each run's summary.csv")


class RunInput:
    """The analysis of one run: the directory holding analysis.json."""

    kind = "run"

    def __init__(self, analysis_dir):
        self.analysis_dir = analysis_dir
        self.json_path = os.path.join(analysis_dir, "analysis.json")


class TableInput:
    """A CSV table with one row per run."""

    kind = "table"

    def __init__(self, path):
        self.path = path


def classify(path):
    """RunInput or TableInput for the path given on the command line, or PlotError."""
    if not os.path.exists(path):
        raise PlotError(f"{path}: no such file or directory", EXIT_IO)
    if os.path.isdir(path):
        if os.path.isfile(os.path.join(path, "analysis.json")):
            return RunInput(path)
        nested = os.path.join(path, "analysis")
        if os.path.isfile(os.path.join(nested, "analysis.json")):
            return RunInput(nested)
        if os.path.isfile(os.path.join(path, "trajectory.h5")):
            raise PlotError(
                f"{path} is a run without an analysis; run `rodsea analyze {path}` first"
            )
        raise PlotError(
            f"{path} is a directory without analysis.json; expected a run's analysis "
            "directory (RUN_DIR/analysis), a run directory that has one, or a table CSV"
        )
    if not os.access(path, os.R_OK):
        raise PlotError(f"{path}: cannot be read (permission denied)", EXIT_IO)
    name = os.path.basename(path)
    if name.endswith(".json"):
        if name != "analysis.json":
            from .campaign_figures import CampaignInput, read_spec

            spec = read_spec(path)
            if spec is not None:
                return CampaignInput(path, spec)
            raise PlotError(
                f"{path}: a JSON file other than a run's analysis.json "
                "(written by `rodsea analyze`)"
            )
        return RunInput(os.path.dirname(path) or ".")
    if name.endswith(".csv"):
        return TableInput(path)
    raise PlotError(
        f"{path}: unknown kind of input; expected a run's analysis directory, its analysis.json, "
        f"or a table CSV with one row per run ({TABLE_HINT})"
    )

