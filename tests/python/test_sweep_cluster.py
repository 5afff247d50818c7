"""Sweeps on a real Dask LocalCluster of 2 single-threaded worker processes.

One sweep of 4 tiny cases (2 normal stresses x 2 seeds) during which the worker running a
case is killed with SIGKILL once the case has a checkpoint: the sweep completes, the killed
case continued from its checkpoint, its grainlab child died with the worker, and all four
series.csv are byte for byte those of the same cases run one by one with the CLI. A rerun
of the finished sweep runs nothing and rewrites no file.
"""

import glob
import os
import signal
import threading
import time

import pytest
from distributed import Client, LocalCluster

from grainlab.sweep import sweep
from sweep_helpers import grainlab, grainlab_processes_in, read_bytes, run_with_cli, tiny

STRESSES = [60e3, 100e3]
SEEDS = [3, 4]
STRAIN = 0.08  # well under a second a case unloaded: time to kill one in the middle


def _kill_a_worker_mid_case(client, out, killed, stop):
    """Once a case has a checkpoint and no run.json, kills -9 the worker process running it."""
    while not stop.is_set():
        for ck in glob.glob(os.path.join(out, "*", "checkpoint.bin")):
            folder = os.path.dirname(ck)
            if os.path.exists(os.path.join(folder, "run.json")):
                continue
            name = os.path.basename(folder)
            for address, keys in client.processing().items():
                if any(("grainlab-case-%s-" % name) in str(k) for k in keys):
                    pid = client.run(os.getpid, workers=[address])[address]
                    children = grainlab_processes_in(folder)
                    os.kill(pid, signal.SIGKILL)
                    killed.update(case=name, worker_pid=pid, children=children)
                    return
        time.sleep(0.01)


@pytest.fixture(scope="module")
def killed_sweep(tmp_path_factory):
    tmp = str(tmp_path_factory.mktemp("sweep"))
    out = os.path.join(tmp, "sweep")
    cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None)
    client = Client(cluster)
    killed, stop = {}, threading.Event()
    killer = threading.Thread(target=_kill_a_worker_mid_case, args=(client, out, killed, stop))
    killer.start()
    args = dict(base=tiny(strain=STRAIN), grid={"consolidation.normal_stress": STRESSES}, seeds=SEEDS,
                out=out, grainlab=grainlab(), report=False, log=None)
    try:
        result = sweep(client=client, **args)
    finally:
        stop.set()
        killer.join()
    files = [p for p in glob.glob(os.path.join(out, "**"), recursive=True) if os.path.isfile(p)]
    mtimes = {p: os.stat(p).st_mtime_ns for p in files if os.path.basename(p) != "cases.csv"}
    rerun = sweep(client=client, **args)
    client.close()
    cluster.close()
    return dict(tmp=tmp, out=out, result=result, killed=killed, mtimes=mtimes, rerun=rerun)


def test_four_cases_give_the_series_of_the_cli_run_one_by_one(killed_sweep):
    result = killed_sweep["result"]
    assert result.failed == []
    assert [c.name for c in result.cases] == ["normal_stress-60000_seed-3", "normal_stress-60000_seed-4",
                                              "normal_stress-100000_seed-3", "normal_stress-100000_seed-4"]
    configs = [(tiny(seed=c.inputs["seed"], stress=c.inputs["consolidation.normal_stress"], strain=STRAIN,
                     folder=os.path.join(killed_sweep["tmp"], "cli", c.name)),
                os.path.join(killed_sweep["tmp"], "cli", c.name)) for c in result.cases]
    for case, folder in zip(result.cases, run_with_cli(configs)):
        assert read_bytes(os.path.join(case.folder, "series.csv")) == read_bytes(os.path.join(folder, "series.csv"))


def test_a_killed_worker_s_case_continues_from_its_checkpoint(killed_sweep):
    killed = killed_sweep["killed"]
    assert killed, "no case was caught in the middle with a checkpoint"
    r = killed_sweep["result"].results[killed["case"]]
    assert r["status"] == "finished" and r["resumed"], r
    assert r["worker_pid"] != killed["worker_pid"]
    log = read_bytes(os.path.join(killed_sweep["out"], killed["case"], "sweep.log")).decode()
    assert log.count("# ") == 2 and "--resume" in log.split("# ")[2], log
    # Its grainlab child was running when the worker was killed, and is gone.
    assert killed["children"], "the case's grainlab was not found running"
    for pid in killed["children"]:
        assert not os.path.exists("/proc/%d" % pid) or open("/proc/%d/stat" % pid).read().split()[2] == "Z"


def test_the_table_has_every_case_s_inputs_and_peaks(killed_sweep):
    with open(killed_sweep["result"].table_path) as f:
        lines = f.read().splitlines()
    header = lines[0].split(",")
    for column in ("case", "status", "consolidation.normal_stress", "seed", "peaks.friction_angle_deg",
                   "final.void_ratio"):
        assert column in header
    assert len(lines) == 5
    table = killed_sweep["result"].table
    assert list(table["seed"]) == [3, 4, 3, 4]
    assert (table["peaks.friction_angle_deg"] > 0).all()


def test_a_rerun_of_the_finished_sweep_does_no_work(killed_sweep):
    rerun = killed_sweep["rerun"]
    assert rerun.ran == [] and rerun.failed == []
    assert all(r["status"] == "skipped" for r in rerun.results.values())
    assert len(killed_sweep["mtimes"]) > 4 * 5
    for path, mtime in killed_sweep["mtimes"].items():  # no file but the table rewritten
        assert os.stat(path).st_mtime_ns == mtime, path
