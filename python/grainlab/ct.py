"""grainlab.ct: X-ray CT volumes to grain meshes (``grainlab ct``; docs/ct.md)."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any, Union

from .grains import _command, _options

PathLike = Union[str, "os.PathLike[str]"]


def segment(image: PathLike, out: PathLike, **options: Any) -> Path:
    """Segments a CT volume into one closed mesh per grain: ``grainlab ct segment IMAGE --out OUT``.

    ``image``: a 3D image (TIFF, NRRD, MetaImage, raw) or a folder of 2D slices. Options as
    keywords, as on the command line: ``voxel_size`` (m), ``size`` and ``type`` (raw files),
    ``crop``, ``bin``, ``labels``, ``threshold``, ``h``, ``merge_ratio``, ``threads``,
    ``min_voxels``, ``faces``, ``smooth``, ``format`` (stl | obj), ``force``, ``quiet``.
    Returns ``out``, which holds the meshes, grains.csv and grain_quality.csv (docs/outputs.md);
    ``grains.scan = OUT`` in a config runs a test on those grains where they were scanned."""
    _command(["ct", "segment", os.fspath(image), *_options(out=out, **options)])
    return Path(out)


def synth(out: PathLike, **options: Any) -> Path:
    """Writes a synthetic CT scan of touching grains (``grainlab ct synth --out OUT``) to try
    :func:`segment` on. Options: ``truth`` (a folder for the true meshes), ``size``, ``grains``,
    ``touching``, ``grain_size`` (voxels), ``voxel_size`` (m), ``blur``, ``noise``, ``seed``, ``type``."""
    _command(["ct", "synth", *_options(out=out, **options)])
    return Path(out)
