"""A campaign's collected table (`rodsea campaign collect`: DIR/collected/*.csv)."""
import glob
import os

from . import _rodsea
from .run import read_table


def load_collected(campaign_dir, table=None):
    """{column: array} of the campaign's collected table: `table` names one CSV of
    DIR/collected/ (without .csv); by default the one there is, or points.csv."""
    collected = os.path.join(os.fspath(campaign_dir), "collected")
    if table is None:
        candidates = sorted(glob.glob(os.path.join(collected, "*.csv")))
        preferred = [c for c in candidates if os.path.basename(c) == "points.csv"]
        if preferred:
            candidates = preferred
        if len(candidates) != 1:
            raise _rodsea.FileError(
                f"{collected}: {'no' if not candidates else 'several'} collected tables "
                f"({', '.join(os.path.basename(c) for c in candidates) or 'none'}): run rodsea "
                "campaign collect, or name one with table=")
        path = candidates[0]
    else:
        path = os.path.join(collected, table + ".csv")
    if not os.path.exists(path):
        raise _rodsea.FileError(f"{path}: no such table (rodsea campaign collect writes it)")
    return read_table(path)
