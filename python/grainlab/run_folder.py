"""grainlab.Run: the files of a run folder (docs/outputs.md) as Python objects."""

from __future__ import annotations

import json
import os
from pathlib import Path
from typing import Any, Optional, Union

from . import _grainlab
from .errors import ConfigError, RunError
from .units import column_unit

PathLike = Union[str, "os.PathLike[str]"]


class Run:
    """A run folder written by ``grainlab run`` or :func:`grainlab.run` (``output.folder``).

    - :attr:`series`: series.csv, one row per sample of the loading phase
    - :attr:`summary`: run.json (inputs, preparation, peaks, final state, timings)
    - :attr:`peaks`: run.json's ``peaks`` (direct shear) or the test's own group
    - :attr:`snapshots`: the ParaView collections (grains, contacts, walls)
    - :meth:`report`: writes the HTML report and returns its path

    SI units throughout; a column's unit is in its name and in
    ``run.series.attrs["units"]`` (see :func:`grainlab.units.column_unit`).
    """

    def __init__(self, folder: PathLike) -> None:
        """Opens a run folder. Raises ConfigError if it holds no series.csv nor run.json."""
        self.folder = Path(folder)
        if not (self.folder / "series.csv").is_file() and not (self.folder / "run.json").is_file():
            raise ConfigError(f"'{self.folder}' is not a run folder: it holds neither series.csv nor run.json; "
                              "give the output.folder of a run")

    @property
    def finished(self) -> bool:
        """True once the run ended (run.json is written at the end)."""
        return (self.folder / "run.json").is_file()

    @property
    def series(self) -> Any:
        """series.csv as a pandas DataFrame (a numpy structured array where pandas is absent).

        One row per sample of the loading phase; the columns are those of docs/outputs.md,
        their units in ``.attrs["units"]`` (DataFrame) and in each name's suffix: ``time_s``
        (s), ``shear_strain`` (–), ``normal_stress_Pa`` (Pa), ``friction_angle_deg`` (deg), ...
        ``nan`` where a value is not defined yet."""
        path = self.folder / "series.csv"
        if not path.is_file():
            raise RunError(f"'{path}' does not exist yet: the run has not reached its loading phase")
        try:
            import pandas
        except ImportError:
            import numpy
            return numpy.genfromtxt(path, delimiter=",", names=True, dtype=float, deletechars="")
        frame = pandas.read_csv(path)
        frame.attrs["units"] = {name: column_unit(name) for name in frame.columns}
        return frame

    @property
    def units(self) -> dict:
        """The unit of each column of :attr:`series` ("–": dimensionless)."""
        with open(self.folder / "series.csv", encoding="utf-8") as f:
            header = f.readline().strip()
        return {name: column_unit(name) for name in header.split(",")}

    @property
    def summary(self) -> dict:
        """run.json as a dict (docs/outputs.md lists its keys and groups); written when the run ends."""
        path = self.folder / "run.json"
        if not path.is_file():
            raise RunError(f"'{path}' does not exist: the run has not finished (resume it to finish it)")
        with open(path, encoding="utf-8") as f:
            return json.load(f)

    @property
    def config(self):
        """The run's config (its config.toml) as a :class:`grainlab.Config`."""
        from .config import Config
        return Config.from_toml(self.folder / "config.toml")

    @property
    def peaks(self) -> dict:
        """The run's peaks: run.json's ``peaks`` (direct shear: friction_angle_deg,
        strain_at_peak_friction, dilation_angle_deg, friction_is_peak, ...), or the test's own
        result group (``triaxial``, ``oedometer``) for the other tests."""
        summary = self.summary
        for group in ("peaks", summary.get("config", {}).get("test", "")):
            if isinstance(summary.get(group), dict):
                return summary[group]
        return {}

    @property
    def snapshots(self) -> dict:
        """Paths of the ParaView collections, ``{"grains": Path, "contacts": Path, "walls": Path}``
        (open them in ParaView), for those the run has written."""
        folder = self.folder / "paraview"
        return {kind: folder / f"{kind}.pvd" for kind in ("grains", "contacts", "walls")
                if (folder / f"{kind}.pvd").is_file()}

    def report(self, out: Optional[PathLike] = None) -> Path:
        """Writes the HTML report (as ``grainlab report FOLDER``, in this process by
        :mod:`grainlab.report`; needs matplotlib) and returns the path of its index.html:
        ``FOLDER/report/index.html``, or ``out/index.html``."""
        return report([self], out)

    def __repr__(self) -> str:
        return f"<grainlab.Run {self.folder}{'' if self.finished else ' (not finished)'}>"


def report(runs: list, out: Optional[PathLike] = None) -> Path:
    """The HTML report of one run, or the comparison of several (as ``grainlab report A B ...``,
    in this process by :mod:`grainlab.report`); returns the path of its index.html. ``runs``:
    Run objects or folders. A comparison goes to ``A/../comparison/report/`` unless ``out`` is
    given. Prints what the command line prints (the page, the figures, their notes). Raises
    ConfigError for a folder that is not a run folder or runs that cannot be compared, RunError
    when matplotlib is missing."""
    folders = [os.fspath(r.folder if isinstance(r, Run) else r) for r in runs]
    if not folders:
        raise ConfigError("grainlab.report needs at least one run folder: grainlab.report([run_a, run_b, ...])")
    try:
        from .report import ReportError, write_report
        from .report.reports import summary_lines
        # The engine's part first (several triaxial runs: their Mohr-Coulomb fit, mohr_coulomb.json).
        out_dir = _grainlab.prepare_report_folder(folders, "" if out is None else os.fspath(out))
        page, figs = write_report(folders, out_dir or None)
    except ImportError as e:
        raise RunError(f"the report was not written: it needs matplotlib and numpy ({e}). Install them with "
                       "`sudo apt-get install python3-matplotlib` (scripts/setup.sh does)") from None
    except ReportError as e:
        raise ConfigError(f"the report was not written: {e}") from None
    print("\n".join(summary_lines(page, figs)))
    return page
