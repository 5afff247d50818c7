"""Shared fixtures of the Python tests: the grainlab binary, the tiny config and its CLI run.

Run by ctest (test `python`, cmake/python_module.cmake), which sets PYTHONPATH
to build/python and GRAINLAB to the command line binary; by hand:

    PYTHONPATH=build/python GRAINLAB=build/grainlab /usr/bin/python3 -m pytest tests/python
"""

import os
import subprocess
from pathlib import Path

import pytest

SOURCE = Path(os.environ.get("GRAINLAB_SOURCE", Path(__file__).resolve().parents[2]))


def tiny_config(folder: Path) -> dict:
    """The smallest direct shear that runs every phase (about 50 faceted grains in a 3 mm box,
    sheared to 1 %; any density accepted), as in tests/apps/resume_test.cpp."""
    return {
        "seed": 3,
        "grains": {"shapes": 4, "faces": 120},
        "box": {"length": 0.003, "width": 0.003, "height": 0.002},
        "specimen": {"indices": "lab", "deposition_friction": 0.05, "tolerance": 1.0},
        "shear": {"final_strain": 0.01},
        "numerics": {"threads": 1},
        "output": {"snapshot_interval": 0.004, "folder": str(folder)},
    }


@pytest.fixture(scope="session")
def grainlab_binary() -> str:
    binary = os.environ.get("GRAINLAB", str(SOURCE / "build" / "grainlab"))
    if not Path(binary).is_file():
        pytest.fail(f"no grainlab binary at {binary}: build it (cmake --build build --target grainlab) or set GRAINLAB")
    return binary


def run_cli(binary: str, *args: str, cwd=None) -> subprocess.CompletedProcess:
    return subprocess.run([binary, *args], capture_output=True, text=True, cwd=cwd,
                          env={**os.environ, "OMP_NUM_THREADS": "1"})


@pytest.fixture(scope="session")
def cli_run(tmp_path_factory, grainlab_binary) -> Path:
    """The tiny config run straight through by `grainlab run --no-report`: its folder."""
    import grainlab
    root = tmp_path_factory.mktemp("cli")
    config = root / "tiny.toml"
    config.write_text(grainlab.config.dict_to_toml(tiny_config(root / "run")))
    done = run_cli(grainlab_binary, "run", str(config), "--quiet", "--no-report")
    assert done.returncode == 0, done.stdout + done.stderr
    return root / "run"
