#!/usr/bin/python3
"""rodsea plot: the paper's figure types from `rodsea analyze` output (docs/plots.md).

usage: /usr/bin/python3 scripts/rodsea_plot.py INPUT -o DIR [--dpi D] [--only F,..] [--quiet]

INPUT is one run's analysis (RUN_DIR/analysis, RUN_DIR itself, or its analysis.json), a table
with one row per run (`rodsea analyze RUN1 RUN2 ... --table T.csv`, or a run's summary.csv), or a
campaign's collected/figures.json (written by `rodsea campaign collect`).
Writes PNG files into DIR (created if needed) and prints each one's path on stdout, one per
line; notes on what was skipped go to stderr (--quiet silences them). Every input is read and
checked before the first figure is drawn; each PNG is written under a temporary name and
renamed, so no half-written PNG is ever left.

Exit codes: 0 done; 1 a Python module is missing (or an unexpected error); 2 bad input (nothing
written); 74 a file could not be read or written.

Run by `rodsea plot`; needs Debian's python3-numpy, -matplotlib and -h5py
(./scripts/install-deps.sh installs them).
"""
import argparse
import os
import signal
import sys

sys.dont_write_bytecode = True  # keep the source tree clean of __pycache__

EXIT_FAILURE, EXIT_BAD_INPUT = 1, 2
INSTALL_HINT = ("install it with ./scripts/install-deps.sh "
                "(Debian's python3-numpy, python3-matplotlib, python3-h5py)")


class Parser(argparse.ArgumentParser):
    def error(self, message):
        sys.stderr.write(f"rodsea plot: {message} (usage: rodsea plot INPUT -o DIR "
                         "[--dpi D] [--only F,..] [--quiet])\n")
        sys.exit(EXIT_BAD_INPUT)


def parse(argv):
    p = Parser(prog="rodsea plot", description=__doc__,
               formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("input", metavar="INPUT")
    p.add_argument("-o", "--output", metavar="DIR", required=True)
    p.add_argument("--dpi", type=int, default=150,
                   help="pixels per inch of the PNG files (20 to 600; default 150)")
    p.add_argument("--only", metavar="F,..",
                   help="draw only these figures (file names, .png optional, comma-separated)")
    p.add_argument("--quiet", action="store_true", help="no notes on stderr")
    args = p.parse_args(argv)
    if not 20 <= args.dpi <= 600:
        p.error(f"invalid --dpi = {args.dpi}: allowed a whole number in [20, 600]")
    return args


def only(text, known, kind):
    """The figure names of --only, each checked against those the input kind can give."""
    from rodsea_plots.common import PlotError

    names = {n.strip() if n.strip().endswith(".png") else n.strip() + ".png"
             for n in text.split(",") if n.strip()}
    unknown = sorted(names - set(known))
    if unknown or not names:
        what = {"run": "a run's analysis", "table": "a table of runs",
                "campaign": "the campaign"}[kind]
        raise PlotError(f"invalid --only = '{text}': allowed figures of {what}: "
                        + ", ".join(n[:-len(".png")] for n in known))
    return names


def main(argv):
    args = parse(argv)
    # SIGTERM unwinds like Ctrl-C, so that a PNG being written loses only its temporary file.
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(143))
    for module in ("numpy", "matplotlib"):
        try:
            __import__(module)
        except ImportError:
            other = ("" if os.path.realpath(sys.executable) == os.path.realpath("/usr/bin/python3")
                     else "; or leave RODSEA_PYTHON unset to use Debian's /usr/bin/python3")
            sys.stderr.write(f"rodsea plot: the Python module '{module}' is missing from "
                             f"{sys.executable}; {INSTALL_HINT}{other}\n")
            return EXIT_FAILURE
    from rodsea_plots import campaign_figures, common, inputs, run_figures, table_figures

    log = common.Log(args.quiet)
    try:
        source = inputs.classify(args.input)
        figures = {"run": run_figures, "table": table_figures,
                   "campaign": campaign_figures}[source.kind]
        if args.only is not None:
            known = (campaign_figures.figure_names(source.spec) if source.kind == "campaign"
                     else figures.ALL_FIGURES)
            log.only = only(args.only, known, source.kind)
        jobs = figures.plan(source, log)  # reads and checks everything; writes nothing
        plt = common.pyplot()
        writer = common.FigureWriter(args.output, args.dpi, plt)
        writer.prepare()
        failed = []
        for name, draw in jobs:
            try:
                writer.save(draw(plt), name)
            except common.PlotError:
                raise
            except Exception as e:  # one figure's failure does not cost the others
                failed.append(f"{name}: {type(e).__name__}: {e}")
        if failed:
            raise common.PlotError("could not draw " + "; ".join(failed), common.EXIT_FAILURE)
    except common.PlotError as e:
        sys.stderr.write(f"rodsea plot: {e}\n")
        return e.code
    except KeyboardInterrupt:
        sys.stderr.write("rodsea plot: interrupted\n")
        return 130
    return common.EXIT_OK


if __name__ == "__main__":
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    sys.exit(main(sys.argv[1:]))
