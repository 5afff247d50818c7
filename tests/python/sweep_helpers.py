"""What the sweep tests share: the grainlab binary, a tiny config, runs of it with the CLI."""

import glob
import os
import subprocess

import pytest

# About 50 glass beads in a 3 x 3 x 2 mm box (the apps tests' tiny box), whatever density
# the first trial reaches, sheared to `strain`; a checkpoint every 0.05 s of wall time.
TINY = """seed = {seed}
[material]
preset = "glass-beads"
[grains]
shapes = 4
faces = 120
[box]
length = 0.003
width = 0.003
height = 0.002
[specimen]
indices = "lab"
deposition_friction = 0.05
tolerance = 1.0
[consolidation]
normal_stress = {stress!r}
[shear]
final_strain = {strain!r}
[output]
snapshot_interval = 0
checkpoint_interval = 0.05
folder = "{folder}"
"""


def grainlab():
    path = os.environ.get("GRAINLAB")
    if not path or not os.access(path, os.X_OK):
        pytest.fail("set GRAINLAB to the grainlab binary (ctest does: build/grainlab)")
    return path


def tiny(seed=1, stress=100e3, strain=0.01, folder="."):
    return TINY.format(seed=seed, stress=stress, strain=strain, folder=folder)


def run_with_cli(configs):
    """Runs each (config text, folder) with `grainlab run --threads 1`, two at a time; returns the folders."""
    procs = []
    for text, folder in configs:
        os.makedirs(folder, exist_ok=True)
        path = folder + ".toml"
        with open(path, "w") as f:
            f.write(text)
        if len(procs) >= 2:
            procs.pop(0).wait()
        procs.append(subprocess.Popen([grainlab(), "run", path, "--quiet", "--no-report", "--threads", "1"],
                                      stdout=subprocess.DEVNULL))
    for p in procs:
        assert p.wait() == 0
    return [folder for _, folder in configs]


def read_bytes(path):
    with open(path, "rb") as f:
        return f.read()


def grainlab_processes_in(folder):
    """Pids of grainlab processes whose working directory is `folder`."""
    pids = []
    for proc in glob.glob("/proc/[0-9]*"):
        try:
            if os.readlink(proc + "/cwd") == folder and os.readlink(proc + "/exe").endswith("grainlab"):
                pids.append(int(os.path.basename(proc)))
        except OSError:
            pass
    return pids
