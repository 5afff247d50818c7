"""`python -m grainlab.report RUN_DIR [RUN_DIR ...] [--out DIR]`: the command line of the report
(`grainlab report` runs it, after writing a triaxial comparison's Mohr-Coulomb fit)."""

import argparse
import sys

from .reading import ReportError
from .reports import summary_lines, write_report

PROG = "python3 -m grainlab.report"


def main(argv=None):
    ap = argparse.ArgumentParser(
        prog=PROG,
        description="Write an HTML report with PNG figures for one grainlab run (direct shear: paper Figs. 10-17; "
                    "oedometer; triaxial), or a comparison report for several direct shear runs or several "
                    "triaxial runs (Mohr circles and a c', phi' fit).")
    ap.add_argument("runs", nargs="+", metavar="RUN_DIR", help="run folder(s) holding series.csv and run.json")
    ap.add_argument("--out", metavar="DIR", help="where to write index.html and the PNGs (default: RUN_DIR/report "
                    "for one run, RUN_DIR/../comparison/report for several, after the first run)")
    a = ap.parse_args(argv)
    try:
        page, figs = write_report(a.runs, a.out)
    except ReportError as e:
        print(f"grainlab report: error: {e}", file=sys.stderr)
        return 1
    print("\n".join(summary_lines(page, figs)))
    return 0
