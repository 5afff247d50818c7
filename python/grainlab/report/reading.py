"""Reading a run folder for the report: series.csv as columns, run.json, the optional files'
paths, and the engine's peaks (what the report draws; it derives none)."""

import csv
import json
import math
from pathlib import Path

import numpy as np


REQUIRED_COLUMNS = ["time_s", "shear_strain", "horizontal_displacement_m", "vertical_displacement_m",
                    "shear_force_N", "normal_force_N", "normal_stress_Pa", "stress_ratio",
                    "friction_angle_deg", "void_ratio"]


# The column each known test's series progresses along; a test not named here gets the generic report
# (generic_report), which draws every column against its first column after time_s.
PROGRESS_COLUMNS = {"direct-shear": "shear_strain", "oedometer": "stage", "triaxial": "axial_strain"}


class ReportError(Exception):
    """A fatal problem with the inputs; its message is printed as one line."""


# ---------------------------------------------------------------------------
# Reading a run folder.

def read_csv_columns(path):
    """Named float columns of a CSV file (header row, then numbers); bad or empty cells are nan."""
    with open(path, newline="") as fh:
        rows = [r for r in csv.reader(fh) if r and any(c.strip() for c in r)]
    if not rows:
        raise ValueError("empty file")
    header = [h.strip() for h in rows[0]]
    values = np.full((len(rows) - 1, len(header)), np.nan)
    for i, r in enumerate(rows[1:]):
        for j in range(min(len(r), len(header))):
            try:
                values[i, j] = float(r[j])
            except ValueError:
                pass
    return {name: values[:, j] for j, name in enumerate(header) if name}


def get(d, *keys, default=None):
    """d[k0][k1]... or default when any level is missing."""
    for k in keys:
        if not isinstance(d, dict) or k not in d or d[k] is None:
            return default
        d = d[k]
    return d


def num(x):
    """x as a float, or None when it is not a finite number."""
    try:
        v = float(x)
    except (TypeError, ValueError):
        return None
    return v if math.isfinite(v) else None


class Run:
    """One run folder: its series columns, run.json and the paths of its optional files."""

    def __init__(self, folder):
        self.dir = Path(folder)
        if not self.dir.is_dir():
            raise ReportError(f"'{folder}' is not a folder: give a grainlab run folder (with series.csv and run.json)")
        for name in ("series.csv", "run.json"):
            if not (self.dir / name).is_file():
                raise ReportError(f"'{folder}' has no {name}: not a grainlab run folder "
                                  "(a run writes series.csv and run.json; run it first or check the path)")
        try:
            self.series = read_csv_columns(self.dir / "series.csv")
        except (OSError, ValueError, csv.Error) as e:
            raise ReportError(f"cannot read '{self.dir / 'series.csv'}': {e}")
        try:
            self.info = json.loads((self.dir / "run.json").read_text())
        except (OSError, ValueError) as e:
            raise ReportError(f"cannot read '{self.dir / 'run.json'}': {e}")
        if not isinstance(self.info, dict):
            raise ReportError(f"'{self.dir / 'run.json'}' is not a JSON object")
        self.test = get(self.info, "config", "test", default="direct-shear")
        first = PROGRESS_COLUMNS.get(self.test) or self.progress_column
        if first is None or first not in self.series:
            raise ReportError(f"'{self.dir / 'series.csv'}' has no {first or 'column besides time_s'}"
                              + (" column" if first else "") + f": not a grainlab {self.test} series")
        if len(self.series[first]) == 0:
            raise ReportError(f"'{self.dir / 'series.csv'}' has a header but no rows: the run has not "
                              + ("loaded" if self.test == "oedometer" else "sheared") + " yet")
        self.name = self.dir.resolve().name
        self.label = self.preset or self.name

    @property
    def progress_column(self):
        """The column a test's series progresses along: the known tests' own (PROGRESS_COLUMNS), else the first
        column that is not time_s (the engine writes the time, then the test's progress); None without one."""
        known = PROGRESS_COLUMNS.get(self.test)
        if known is not None:
            return known
        return next((c for c in self.series if c != "time_s"), None)

    @property
    def preset(self):
        return get(self.info, "config", "grains", "preset", default="")

    @property
    def sand(self):
        return get(self.info, "config", "material", "preset", default="")

    def col(self, name):
        """The named series column, or None when it is missing or all nan."""
        c = self.series.get(name)
        return None if c is None or not np.any(np.isfinite(c)) else c

    @property
    def strain_pct(self):
        return 100.0 * self.series["shear_strain"]

    def path(self, rel):
        return self.dir / rel

    @property
    def shear_plane_z(self):
        """World z of the shear plane (middle of the gap) = box height / 2, or None if unknown."""
        h = num(get(self.info, "config", "box", "height"))
        return None if h is None else 0.5 * h

    # Peak values, as the engine found and judged them (run.json "peaks"; src/analysis/peak.h).
    def peak(self, what):
        """(largest value, strain at it, whether it is a peak) of run.json's peaks for what = "friction" or
        "dilation"; (None, None, True) without them. A run written before the engine judged its peaks (no
        peaks.<what>_is_peak) has each largest value shown as its peak."""
        v = num(get(self.info, "peaks", f"{what}_angle_deg"))
        e = num(get(self.info, "peaks", f"strain_at_peak_{what}"))
        return v, e, get(self.info, "peaks", f"{what}_is_peak", default=True) is not False

    def peak_friction(self):
        return self.peak("friction")

    def peak_dilation(self):
        return self.peak("dilation")

    def peak_psi(self, band=False):
        return num(get(self.info, "peaks", "fabric_psi_band" if band else "fabric_psi"))

    def derived(self):
        """analysis/derived.csv (the engine's per-sample derived series) as columns, or None."""
        p = self.path("analysis/derived.csv")
        if not p.is_file():
            return None
        try:
            return read_csv_columns(p)
        except (OSError, ValueError, csv.Error):
            return None

    def band(self):
        """(low_m, high_m, method, source) of the final shear band, or None."""
        p = self.path("analysis/band.json")
        if p.is_file():
            try:
                b = json.loads(p.read_text())
                lo, hi = num(b.get("low_m")), num(b.get("high_m"))
                if lo is not None and hi is not None:
                    return lo, hi, str(b.get("method", "")), "analysis/band.json"
            except (OSError, ValueError, AttributeError):
                pass
        lo, hi = self.col("band_low_m"), self.col("band_high_m")
        if lo is not None and hi is not None:
            ok = np.isfinite(lo) & np.isfinite(hi)
            if np.any(ok):
                k = np.nonzero(ok)[0][-1]
                return float(lo[k]), float(hi[k]), "last sample of series.csv", "series.csv"
        return None


# The engine calls no largest value in the last 5 % of the test's strain a peak (run.json peaks.*_is_peak).
NO_PEAK = ("no peak: {what} is largest at the end of the test and may still be rising; shear further "
           "(shear.final_strain) to find its peak")
