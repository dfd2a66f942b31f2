"""Shared pieces: errors with exit codes, rodsea's CSV files, figure sizes, atomic PNG writing."""
import csv
import math
import os
import re
import sys
import tempfile

import numpy as np

EXIT_OK = 0
EXIT_FAILURE = 1  # a missing Python module, or anything unexpected
EXIT_BAD_INPUT = 2  # nothing was written
EXIT_IO = 74  # a file could not be read or written

INSTALL_HINT = ("install it with ./scripts/install-deps.sh "
                "(Debian's python3-numpy, python3-matplotlib, python3-h5py)")

# Figure sizes in inches. Each is exact in binary, so at D dots per inch a PNG is exactly
# (width × D) × (height × D) pixels: SIZE_CURVE at the default 150 dpi is 975 × 675.
SIZE_CURVE = (6.5, 4.5)  # one panel of curves
SIZE_WIDE = (11.0, 4.5)  # two panels side by side
SIZE_MAP = (6.5, 5.5)  # a polar heat map with its colour bar


class PlotError(Exception):
    """Bad input (exit 2) or a file that could not be read or written (exit 74)."""

    def __init__(self, message, code=EXIT_BAD_INPUT):
        super().__init__(message)
        self.code = code


def missing_module(name):
    return PlotError(
        f"the Python module '{name}' is missing from {sys.executable}; {INSTALL_HINT}",
        EXIT_FAILURE,
    )


def pyplot():
    """matplotlib.pyplot on the Agg backend (files only, no display)."""
    try:
        import matplotlib
    except ImportError:
        raise missing_module("matplotlib") from None
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    plt.rcParams.update(
        {
            "font.size": 11,
            "axes.titlesize": 11,
            "legend.fontsize": 9,
            "axes.grid": True,
            "grid.alpha": 0.3,
            "figure.constrained_layout.use": True,
            "savefig.facecolor": "white",
        }
    )
    return plt


class Log:
    """Notes go to stderr (stdout carries only the PNG paths); --quiet silences them. Also
    carries --only: the figures asked for (None: all)."""

    def __init__(self, quiet, only=None):
        self.quiet = quiet
        self.only = only

    def wants(self, *names):
        return self.only is None or any(n in self.only for n in names)

    def note(self, message):
        if not self.quiet:
            print(f"rodsea plot: note: {message}", file=sys.stderr)


class Table:
    """A CSV file written by rodsea: '#' comment lines (description and units), a header, rows.

    Values stay text until asked for: number(col) gives floats with NaN for empty cells and 'nan'.
    """

    def __init__(self, path, comments, columns, rows):
        self.path = path
        self.comments = comments
        self.columns = columns
        self.rows = rows
        self.units = {}
        for line in comments:
            if "units:" in line:
                for col, unit in re.findall(r"(\S+) \[([^\]]*)\]", line.split("units:", 1)[1]):
                    self.units[col] = unit

    def __len__(self):
        return len(self.rows)

    def has(self, col):
        return col in self.columns

    def text(self, col):
        k = self.columns.index(col)
        return [row[k] for row in self.rows]

    def number(self, col):
        if col not in self.columns:
            return np.full(len(self.rows), np.nan)
        out = np.empty(len(self.rows))
        for i, cell in enumerate(self.text(col)):
            try:
                out[i] = float(cell) if cell.strip() else np.nan
            except ValueError:
                raise PlotError(
                    f"{self.path}: column '{col}', row {i + 1}: '{cell}' is not a number"
                ) from None
        return out


def read_csv(path):
    """Reads a rodsea CSV file; PlotError 74 when it cannot be read, 2 when it is malformed."""
    try:
        with open(path, newline="", encoding="utf-8") as f:
            lines = f.read().splitlines()
    except UnicodeDecodeError:
        raise PlotError(f"{path}: not a text CSV file") from None
    except OSError as e:
        raise PlotError(f"{path}: cannot be read ({e.strerror})", EXIT_IO) from None
    comments = [line for line in lines if line.startswith("#")]
    body = [line for line in lines if line.strip() and not line.startswith("#")]
    if not body:
        raise PlotError(f"{path}: no header line (an empty CSV file)")
    parsed = list(csv.reader(body))
    columns = [c.strip() for c in parsed[0]]
    rows = []
    for k, row in enumerate(parsed[1:], start=2):
        if len(row) != len(columns):
            raise PlotError(
                f"{path}: data line {k} has {len(row)} fields, the header {len(columns)}"
            )
        rows.append(row)
    return Table(path, comments, columns, rows)


def finite(x):
    return x is not None and isinstance(x, (int, float)) and math.isfinite(x)


def pretty_unit(unit):
    return {"rad^2/s": "rad²/s", "1/mm": "1/mm", "": ""}.get(unit, unit.replace("^2", "²"))


def format_value(value, error=None, unit=""):
    """'0.2815 ± 0.0082 rad²/s': the error to two significant digits, the value to match."""
    if not finite(value):
        return "n/a"
    suffix = f" {pretty_unit(unit)}" if unit else ""
    if not finite(error) or error <= 0:
        return f"{value:.3g}{suffix}" + ("" if finite(error) else " (no error bar)")
    digits = min(8, max(0, 1 - math.floor(math.log10(error))))
    return f"{value:.{digits}f} ± {error:.{digits}f}{suffix}"


def shade_steady(ax, time, steady):
    """Shades the steady window (the frames the averages use) of a time-series axes."""
    inside = np.flatnonzero(steady > 0.5)
    if inside.size:
        ax.axvspan(time[inside[0]], time[inside[-1]], color="0.88", zorder=0,
                   label="steady window")


def message_panel(ax, text):
    """An axes that says why it is empty instead of showing nothing."""
    ax.text(0.5, 0.5, text, ha="center", va="center", transform=ax.transAxes, color="0.3",
            wrap=True)


def blocker(path):
    """' (X is a file)' when an ancestor X of `path` exists and is not a directory, else ''."""
    parent = os.path.dirname(os.path.abspath(path))
    while parent and not os.path.exists(parent):
        parent = os.path.dirname(parent)
    return f" ({parent} is a file)" if parent and not os.path.isdir(parent) else ""


class FigureWriter:
    """Writes each figure to a temporary name in the output directory, then renames it: a reader
    (or a crash) never sees half a PNG. Prints each PNG's path once it is complete."""

    def __init__(self, directory, dpi, plt):
        self.directory = directory
        self.dpi = dpi
        self.plt = plt
        self.written = []
        mask = os.umask(0)
        os.umask(mask)
        self.mode = 0o666 & ~mask

    def prepare(self):
        d = self.directory
        if os.path.exists(d) and not os.path.isdir(d):
            raise PlotError(f"output {d}: exists and is not a directory", EXIT_IO)
        try:
            os.makedirs(d, exist_ok=True)
        except OSError as e:
            raise PlotError(
                f"output directory {d} cannot be created: {e.strerror}{blocker(d)}", EXIT_IO
            ) from None
        if not os.access(d, os.W_OK | os.X_OK):
            raise PlotError(f"output directory {d} is not writable", EXIT_IO)

    def save(self, fig, name):
        final = os.path.join(self.directory, name)
        tmp = None
        try:
            fd, tmp = tempfile.mkstemp(prefix=f".{name}.", suffix=".tmp", dir=self.directory)
            with os.fdopen(fd, "wb") as f:
                fig.savefig(f, format="png", dpi=self.dpi)
            os.chmod(tmp, self.mode)
            os.replace(tmp, final)
            tmp = None
        except OSError as e:
            raise PlotError(f"{final}: could not be written ({e.strerror})", EXIT_IO) from None
        finally:
            if tmp is not None:
                try:
                    os.unlink(tmp)
                except OSError:
                    pass
            self.plt.close(fig)
        self.written.append(final)
        print(final, flush=True)
