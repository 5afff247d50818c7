"""grainlab.grains: synthetic grains, grain shape metrics and the grains' own index densities.

Each function runs the ``grainlab grains`` subcommand of the same name in this
process, with the arguments a shell would give (``grainlab grains SUBCOMMAND
--help`` documents each). Sizes in metres.
"""

from __future__ import annotations

import io
import os
from pathlib import Path
from typing import Any, Optional, Sequence, Union

from . import _grainlab
from .errors import RunError

PathLike = Union[str, "os.PathLike[str]"]


def _options(**options: Any) -> list[str]:
    """Command-line options of keyword arguments: d_min=1e-3 -> ["--d-min", "0.001"]; None left out."""
    args: list[str] = []
    for name, value in options.items():
        if value is None or value is False:
            continue
        flag = "--" + name.replace("_", "-")
        if value is True:
            args.append(flag)
        elif isinstance(value, (list, tuple)):
            args += [flag, *(str(v) for v in value)]
        else:
            args += [flag, os.fspath(value) if isinstance(value, os.PathLike) else repr(value)
                     if isinstance(value, float) else str(value)]
    return args


def _command(args: list[str], capture: bool = False) -> str:
    rc, output = _grainlab.command(args, capture)
    if rc == 130:  # stopped by Ctrl-C, as the command line is: what could be kept was kept
        raise KeyboardInterrupt(f"`grainlab {' '.join(args)}` stopped")
    if rc != 0:
        raise RunError(f"`grainlab {' '.join(args)}` failed with exit code {rc} (see its message above)")
    return output


def generate(out: PathLike, preset: Optional[str] = "rounded", count: int = 10, seed: int = 1,
             spectrum: Optional[PathLike] = None, **options: Any) -> list[Path]:
    """Writes ``count`` synthetic grains as STL files (metres) to ``out`` and returns their paths:
    ``grainlab grains generate --preset PRESET --count N --seed S --out OUT``.

    ``preset``: glass-beads | rounded | sub-angular | angular; or ``spectrum``: a sand's
    spherical-harmonic spectrum file (then ``preset`` is ignored). More options as keywords, as
    on the command line: ``faces``, ``roundness``, ``elongation``, ``flatness``, ``convexity``,
    ``d_min`` and ``d_max`` (m, the sieve sizes)."""
    before = set(Path(out).glob("*.stl")) if Path(out).is_dir() else set()
    source = {"spectrum": spectrum} if spectrum is not None else {"preset": preset}
    _command(["grains", "generate", *_options(**source, count=count, seed=seed, out=out, **options)])
    return sorted(set(Path(out).glob("*.stl")) - before) or sorted(Path(out).glob("*.stl"))


def metrics(mesh_or_path: Union[PathLike, Sequence[PathLike]], representation: str = "auto") -> Any:
    """Shape metrics of grain meshes (STL, OBJ, PLY in metres; .dat spherical-harmonic grains):
    ``grainlab grains stats PATHS``. ``mesh_or_path``: a file, a folder of them, or a list.

    Returns a pandas DataFrame (a list of dicts where pandas is absent), one row per grain:
    ``file``, ``volume_m3``, ``surface_area_m2``, ``equivalent_diameter_m``, ``long_axis_m``,
    ``intermediate_axis_m``, ``short_axis_m``, ``elongation`` (I/L), ``flatness`` (S/I),
    ``sphericity``, ``convexity``, ``roundness`` (Wadell), ``simulated_as`` (hull | pieces),
    ``pieces``, ``collision_excess``."""
    paths = [mesh_or_path] if isinstance(mesh_or_path, (str, os.PathLike)) else list(mesh_or_path)
    text = _command(["grains", "stats", *(os.fspath(p) for p in paths),
                     *_options(representation=representation)], capture=True)
    try:
        import pandas
    except ImportError:
        import csv
        return list(csv.DictReader(io.StringIO(text)))
    return pandas.read_csv(io.StringIO(text))


def index_densities(config: Optional[Any] = None, json: Optional[PathLike] = None, **options: Any) -> dict:
    """The grains' own index void ratios e_min and e_max (``grainlab grains index``), measured
    by loose and dense preparations of the grains in a small box.

    ``config``: a :class:`grainlab.Config` (or a config file) whose grains, material,
    consolidation stress, numerics and seed are used; more options as keywords, as on the
    command line: ``preset``, ``folder``, ``shapes``, ``faces``, ``d_min``, ``d_max`` (m),
    ``stress`` (Pa), ``seed``, ``seeds``, ``box_diameters``, ``height_diameters``,
    ``loose_friction``, ``max_steps``, ``threads``, ``keep``.
    Returns the JSON record of the figures and every preparation (written to ``json`` too)."""
    import json as json_module
    import tempfile

    from .config import Config
    with tempfile.TemporaryDirectory(prefix="grainlab-index-") as tmp:
        args = ["grains", "index"]
        if config is not None:
            path = config
            if isinstance(config, Config):
                path = Path(tmp) / "config.toml"
                path.write_text(config.to_toml(), encoding="utf-8")
            args += ["--config", os.fspath(path)]
        target = Path(json) if json is not None else Path(tmp) / "index_densities.json"
        _command(args + _options(json=target, **options))
        with open(target, encoding="utf-8") as f:
            return json_module.load(f)
