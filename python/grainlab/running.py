"""grainlab.run: a lab test run in this Python process, by the command line's own run function."""

from __future__ import annotations

import os
import sys
from typing import Any, Callable, Mapping, Optional, Union

from . import _grainlab
from .config import Config
from .errors import RunError
from .run_folder import Run

PathLike = Union[str, "os.PathLike[str]"]
Progress = Callable[[dict], Any]


def run(config: Union[Config, PathLike, Mapping[str, Any]], out: Optional[PathLike] = None,
        progress: Union[bool, Progress, None] = False, threads: Optional[int] = None,
        resume: bool = False, report: bool = False,
        log: Optional[Callable[[str], Any]] = None) -> Run:
    """Runs a lab test (direct shear, oedometer, triaxial) as ``grainlab run`` does, and returns its :class:`Run`.

    The same code as the command line, in this process: the same files (series.csv, run.json,
    checkpoint.bin, analysis/, paraview/; docs/outputs.md), the same bits.

    - ``config``: a :class:`Config`, the path of a config file, or a dict of its keys.
    - ``out``: the run folder (default: the config's ``output.folder``).
    - ``progress``: ``True`` for a progress bar (tqdm, in notebooks too, where python3-tqdm is
      installed; else progress lines on standard output), or a callable called about four times
      a second with a dict: ``phase``, ``step``, ``time_s`` (s, simulated), ``loading`` (bool),
      ``progress`` and ``final_progress`` (direct shear: shear strain, –), ``progress_label``,
      ``status`` (one line of measurements). An exception it raises stops the run as Ctrl-C does.
    - ``threads``: worker threads (overrides ``numerics.threads``; 0 = automatic); the results
      are the same bits on any count.
    - ``resume``: go on from the folder's checkpoint (a run stopped by Ctrl-C, a signal or a
      crash); the series then equals that of a run never stopped, byte for byte.
    - ``report``: also write the HTML report at the end (``Run.report()`` writes it later).
    - ``log``: a callable given each line the command line would print (e.g. ``print``).

    The engine runs with the GIL released. Ctrl-C (KeyboardInterrupt) stops the run at the
    next step with a checkpoint, as SIGTERM does for ``grainlab run``, then is raised: call
    ``run(..., resume=True)`` to go on. Bad config: :class:`grainlab.ConfigError` before
    anything is written; a failure while running: :class:`grainlab.RunError`.
    """
    if not isinstance(config, Config):
        config = Config.from_dict(config) if isinstance(config, Mapping) else Config.from_toml(config)
    folder = os.fspath(out) if out is not None else config["output.folder"]
    callback, bar = _progress_callback(progress)
    say = log
    if progress is True and bar is None and say is None:  # no tqdm: the command line's lines
        say = print
    hint = f"`grainlab.run(config, out={folder!r}, resume=True)`"
    sys.stdout.flush()
    try:
        rc = _grainlab.run(config.to_toml(), config.source, folder, resume,
                           -1 if threads is None else int(threads), callback, say, report, hint)
    finally:
        if bar is not None:
            bar.close()
    if rc != 0:
        raise RunError(f"the run in '{folder}' stopped (exit code {rc}); go on with {hint}")
    return Run(folder)


def _progress_callback(progress: Union[bool, Progress, None]):
    """(callback or None, the tqdm bar to close or None)."""
    if callable(progress):
        return progress, None
    if not progress:
        return None, None
    try:
        from tqdm.auto import tqdm
    except ImportError:
        return None, None
    bar = tqdm(total=1.0, bar_format="{desc} {percentage:3.0f}%|{bar}| {postfix}")

    def update(p: dict) -> None:
        if p["loading"] and p["final_progress"] > 0:
            bar.total = p["final_progress"]
            bar.n = min(p["progress"], p["final_progress"])
        bar.set_description(p["phase"], refresh=False)
        bar.set_postfix_str(f"step {p['step']}  {p['status']}", refresh=False)
        bar.refresh()

    return update, bar
