"""grainlab from Python: the virtual soil laboratory's runs, results, grains and CT scans.

The same code as the ``grainlab`` command line, in this process:

>>> import grainlab
>>> cfg = grainlab.default_config(test="direct-shear")          # or Config.from_toml("test.toml")
>>> run = grainlab.run(cfg.replace({"shear.final_strain": 0.02}), out="runs/a", progress=True)
>>> run.series[["shear_strain", "stress_ratio"]]                  # pandas DataFrame, SI units
>>> run.peaks["friction_angle_deg"], run.report()                 # run.json's peaks, the HTML report

- :class:`Config`, :func:`default_config`, :func:`lab_tests`: configs (keys: docs/config.md)
- :func:`run`: a lab test; Ctrl-C checkpoints, ``resume=True`` goes on
- :class:`Run`: a run folder's series, summary, peaks, snapshots and report
- :mod:`grainlab.grains`, :mod:`grainlab.ct`: ``grainlab grains ...`` and ``grainlab ct ...``
- :func:`sweep`: many runs (a grid of keys x seeds) on Dask, resumable (docs/sweeps.md)
- :class:`ConfigError`, :class:`RunError`: the command line's messages as exceptions

SI units throughout (m, kg, s, N, Pa). Reference: docs/python.md.
"""

import os as _os

# Idle OpenMP threads sleep, as the command line's (core/wait_policy.h): libgomp
# reads the policy once, when the compiled module loads it, so it is set before.
if "OMP_WAIT_POLICY" not in _os.environ and "GOMP_SPINCOUNT" not in _os.environ:
    _os.environ["OMP_WAIT_POLICY"] = "PASSIVE"

from . import ct, grains, units  # noqa: E402
from .config import Config, default_config, lab_tests  # noqa: E402
from .errors import ConfigError, InputError, RunError  # noqa: E402
from .run_folder import Run, report as _report_runs  # noqa: E402
from . import report  # noqa: E402  (the subpackage grainlab.report, callable: below)
from .running import run  # noqa: E402
from .sweep import sweep  # noqa: E402  (dask.distributed is imported only when a sweep runs)


class _CallableReport(type(report)):
    """grainlab.report is the report's subpackage (python -m grainlab.report, one module per figure kind) and,
    called, grainlab.report(runs, out=None): the report of one run or the comparison of several
    (grainlab.run_folder.report)."""

    def __call__(self, runs, out=None):
        return _report_runs(runs, out)


report.__class__ = _CallableReport

__version__ = "0.1.0"

__all__ = ["Config", "ConfigError", "InputError", "Run", "RunError", "ct", "default_config", "grains",
           "lab_tests", "report", "run", "sweep", "units"]
