"""examples/direct_shear.ipynb executes, offline, with Debian's nbconvert and ipykernel."""

import os
import shutil
import subprocess
import sys

from pathlib import Path

import nbformat

import grainlab
from conftest import SOURCE


def test_the_example_notebook_executes(tmp_path):
    notebook = tmp_path / "direct_shear.ipynb"
    shutil.copy(SOURCE / "examples" / "direct_shear.ipynb", notebook)  # its runs/ go to tmp_path
    env = {**os.environ, "PYTHONPATH": str(Path(grainlab.__file__).resolve().parents[1]), "OMP_NUM_THREADS": "1"}
    env.pop("MPLBACKEND", None)  # the kernel's inline backend draws the figures into the notebook
    done = subprocess.run([sys.executable, "-m", "nbconvert", "--to", "notebook", "--execute",
                           "--ExecutePreprocessor.timeout=300", "--output", "executed.ipynb", str(notebook)],
                          capture_output=True, text=True, cwd=tmp_path,
                          env=env)
    assert done.returncode == 0, done.stderr[-3000:]
    executed = nbformat.read(tmp_path / "executed.ipynb", as_version=4)
    outputs = [o for cell in executed.cells if cell.cell_type == "code" for o in cell.outputs]
    assert not [o for o in outputs if o.output_type == "error"]
    assert any("image/png" in o.get("data", {}) for o in outputs)  # the curves were drawn
    for run in ("ottawa", "griffin"):
        assert (tmp_path / "runs" / run / "run.json").is_file(), run
