"""`grainlab sweep SWEEP.toml`: the C++ command runs the Python sweep with this binary.

A sweep with a case that fails as it starts (a grain folder without meshes) reports that
case with the CLI's message and exit code, finishes the others and writes the table and
their report; bad sweep files, and grid or variant values `grainlab run` would refuse, are
refused with the file, line (or case), what and how to fix, before anything runs;
--dry-run lists the cases; a Python without Dask is told which Debian package to install.
"""

import csv
import os
import re
import subprocess
import time

import pytest

from sweep_helpers import grainlab, tiny


def run_sweep(folder, text, *options, env=None):
    path = os.path.join(folder, "study.sweep.toml")
    with open(path, "w") as f:
        f.write(text)
    return subprocess.run([grainlab(), "sweep", path, *options], cwd=folder, capture_output=True, text=True,
                          env=env)


def inline_base(**kw):
    """tiny() as an inline [base] table of a sweep file."""
    lines = []
    for line in tiny(**kw).splitlines():
        lines.append("[base]\n" + line if not lines else
                     "[base." + line[1:] if line.startswith("[") else line)
    return "\n".join(lines) + "\n"


def test_a_failing_case_is_reported_and_the_others_finish(tmp_path):
    # grains.folder "" generates the grains; an empty folder passes the config's checks (it exists)
    # and fails as the run loads its grains.
    (tmp_path / "empty").mkdir()
    text = ("workers = 2\n" + 'out = "runs/mixed"\n'
            "[grid]\n" + '"grains.folder" = ["", "empty"]\n' + inline_base())
    p = run_sweep(str(tmp_path), text)
    assert p.returncode == 3, p.stdout + p.stderr
    assert "case folder-empty failed: " in p.stderr and "holds no .stl" in p.stderr, p.stderr
    out = tmp_path / "runs" / "mixed"
    with open(out / "cases.csv") as f:
        rows = {r["case"]: r for r in csv.DictReader(f)}
    assert rows["folder-empty"]["status"] == "failed"
    assert rows["folder-empty"]["exit_code"] == "2"
    assert "holds no .stl, .obj, .ply or .dat" in rows["folder-empty"]["error"]
    assert rows["folder-_"]["status"] == "finished" and float(rows["folder-_"]["peaks.friction_angle_deg"]) > 0
    assert (out / "report" / "index.html").exists(), p.stdout


def test_dry_run_lists_the_cases_and_runs_nothing(tmp_path):
    base = tmp_path / "base.toml"
    base.write_text(tiny())
    p = run_sweep(str(tmp_path), 'base = "base.toml"\nseeds = [5, 6]\n'
                  '[[variants]]\nname = "beads"\n"material.preset" = "glass-beads"\n'
                  '[[variants]]\nname = "ottawa"\n"material.preset" = "ottawa"\n"shear.final_strain" = 0.02\n',
                  "--dry-run")
    assert p.returncode == 0, p.stderr
    assert [line.split()[1] for line in p.stdout.splitlines()[:4]] == [
        "beads_seed-5", "beads_seed-6", "ottawa_seed-5", "ottawa_seed-6"]
    assert "4 cases in runs/study: 0 finished before, 4 to run" in p.stdout
    assert not (tmp_path / "runs").exists()


BAD_FILES = [
    ('base = "base.toml"\nseed = [1, 2]\n', "study.sweep.toml:2: unknown key 'seed' (did you mean 'seeds'?)"),
    ('base = "nope.toml"\nseeds = [1]\n', "study.sweep.toml:1: base = \"nope.toml\": no such file"),
    ('base = "base.toml"\n[grid]\n"consolidation.normal_stress" = 1e5\n',
     "study.sweep.toml:3: grid key 'consolidation.normal_stress' = 100000.0: give a non-empty list"),
    ('base = "base.toml"\n[grid\n', "study.sweep.toml: not valid TOML"),
    ('base = "base.toml"\n', "nothing varies"),
    ('base = "base.toml"\nseeds = [1]\nthreads = -1\n', "study.sweep.toml:3: threads = -1 must be an integer >= 0"),
    ('base = "base.toml"\nseeds = [1, 1]\n', "seeds: [1, 1] repeats a seed"),
    ('base = "base.toml"\nseeds = [1.5]\n', "seeds: 1.5 is not a seed"),
    ('base = "base.toml"\n[[variants]]\n"material.preset" = "ottawa"\n', "variants[0]: give it a name"),
    ('base = "base.toml"\n[[variants]]\nname = "a"\n"shear.final_strain" = 0.1\n'
     '[grid]\n"shear.final_strain" = [0.1]\n', "variant 'a' and grid both set 'shear.final_strain'"),
    ('base = "base.toml"\n[grid]\n"seed.value" = [1]\n', "'seed' is a value in the base config, not a table"),
    ('base = "base.toml"\n[grid]\n"shear" = [1]\n', "'shear' is a table of the config, not a key"),
    ('[base]\nseed = 1\nbox = 3\n[grid]\n"box.length" = [0.003]\n', "'box' is a value in the base config"),
    # Every case's config is checked as `grainlab run` checks it, before any case runs.
    ('base = "base.toml"\n[grid]\n"consolidation.normal_stress" = [60e3, -5.0]\n',
     "consolidation.normal_stress = -5 is impossible: it must be > 0"),
    ('base = "base.toml"\n[grid]\n"consolidation.normal_stres" = [1e5]\n',
     "unknown key 'consolidation.normal_stres'. Did you mean 'normal_stress'?"),
    ('base = "base.toml"\n[[variants]]\nname = "a"\n"material.preset" = "nope"\n',
     'material.preset = "nope" is not a sand preset'),
]


@pytest.mark.parametrize("text,message", BAD_FILES)
def test_bad_sweep_files_are_refused_with_where_and_how(tmp_path, text, message):
    (tmp_path / "base.toml").write_text(tiny())
    p = run_sweep(str(tmp_path), text)
    assert p.returncode == 2, p.stdout + p.stderr
    assert message in p.stderr, p.stderr
    assert p.stderr.startswith("grainlab sweep: error: ") and p.stderr.count("\n") == 1, p.stderr
    assert not (tmp_path / "runs").exists()


def test_a_python_without_dask_names_the_debian_package(tmp_path):
    fake = tmp_path / "fake" / "distributed"
    fake.mkdir(parents=True)
    (fake / "__init__.py").write_text("raise ImportError('No module named distributed (a test stand-in)')\n")
    env = dict(os.environ, PYTHONPATH=str(tmp_path / "fake"))
    p = run_sweep(str(tmp_path), "seeds = [1]\n" + inline_base(), env=env)
    assert p.returncode == 3, p.stdout + p.stderr
    assert "sudo apt-get install python3-distributed" in p.stderr, p.stderr
    assert not (tmp_path / "runs").exists()


def test_an_existing_cluster_runs_the_cases_its_workers_need_no_grainlab_package(tmp_path):
    # A scheduler and a worker as a user starts them (dask scheduler / dask worker), the worker
    # without the grainlab package on its PYTHONPATH; the sweep given the scheduler file.
    bare = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    scheduler_file = str(tmp_path / "scheduler.json")
    daemons = [subprocess.Popen(["dask", "scheduler", "--scheduler-file", scheduler_file, "--port", "0",
                                 "--no-dashboard"], env=bare, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)]
    try:
        daemons.append(subprocess.Popen(["dask", "worker", "--scheduler-file", scheduler_file, "--nthreads", "1",
                                         "--no-dashboard", "--local-directory", str(tmp_path / "dask")], env=bare,
                                        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL))
        for _ in range(600):
            if os.path.exists(scheduler_file):
                break
            time.sleep(0.05)
        p = run_sweep(str(tmp_path), "report = false\nseeds = [1, 2]\n" + inline_base(), "--scheduler", scheduler_file)
        assert p.returncode == 0, p.stdout + p.stderr
        assert "2 of 2 cases finished" in p.stdout
        # Ran by the worker process of that `dask worker` (a child of its nanny).
        log = (tmp_path / "runs" / "study" / "seed-2" / "sweep.log").read_text()
        pid = int(re.search(r"\(pid (\d+)\)", log).group(1))
        with open("/proc/%d/stat" % pid) as f:
            assert int(f.read().rsplit(")", 1)[1].split()[1]) == daemons[1].pid
    finally:
        for d in daemons:
            d.terminate()
            d.wait(timeout=30)
