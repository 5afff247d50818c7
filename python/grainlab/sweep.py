"""Parameter sweeps: many `grainlab run`s, one case per folder, as tasks on Dask.

    from grainlab.sweep import sweep
    result = sweep("base.toml", grid={"consolidation.normal_stress": [50e3, 100e3, 200e3]},
                   seeds=[1, 2, 3], out="runs/stress_sweep")
    result.table        # a pandas DataFrame: one row per case, inputs and run.json results
    result.failed       # the cases that failed, with their error in the table

Each case is the base config with its grid values (dotted config keys, SI units as in
docs/config.md) and seed, written to OUT/CASE/config.toml and run as
`grainlab run config.toml --threads 1` in OUT/CASE, as one task on `dask.distributed`:
a LocalCluster of one single-threaded worker process per core by default, or the cluster
of `client` (a distributed.Client or a scheduler address such as "tcp://head:8786").
Finished cases are skipped (a rerun does no work), a case with a checkpoint continues,
a case whose worker dies is resubmitted by Dask and continues from its checkpoint, a
failing case is reported and the others go on. Before any case runs, every case's config is
checked as `grainlab run` checks it (an unknown key or an impossible value in the grid or a
variant is refused at once, with the command line's message). At the end: OUT/cases.csv (and
cases.parquet with pyarrow) and the comparison report OUT/report/index.html.

`python -m grainlab._sweep_main SWEEP.toml` (what `grainlab sweep` runs) reads a sweep file;
see docs/sweeps.md.
"""

import dataclasses
import os
import shutil
import subprocess
import time
import uuid

from . import _grainlab, _sweep_table, _sweep_task
from ._sweep_cases import Case, SweepError, plan_cases
from .errors import ConfigError

__all__ = ["sweep", "SweepResult", "SweepError", "Case"]


@dataclasses.dataclass
class SweepResult:
    folder: str           # the sweep's output folder
    cases: list           # every Case, in order
    results: dict         # case name -> what its task returned (status, exit_code, error, wall_s, ...)
    table: object         # one row per case: a pandas DataFrame (a list of dicts without pandas)
    table_path: str       # folder/cases.csv
    report: object        # folder/report/index.html, or None when not written
    ran: list             # the cases that ran in this sitting

    @property
    def failed(self):
        """The names of the cases that did not finish (stopped ones included)."""
        return [c.name for c in self.cases if self.results.get(c.name, {}).get("status") not in ("finished", "skipped")]

    @property
    def stopped(self):
        """The names of the cases stopped by a signal (Ctrl-C); the next sweep continues them."""
        return [c.name for c in self.cases if self.results.get(c.name, {}).get("status") == "stopped"]


def check_cases(cases):
    """Checks every case's config as `grainlab run config.toml` does before it starts (the same
    code, in this process; no file is read or written): the first case the command line would
    refuse raises SweepError with its message, before any case runs."""
    for case in cases:
        try:
            _grainlab.config_toml(case.config_text, "config.toml")
        except ConfigError as e:
            raise SweepError("case %s would be refused by `grainlab run`: %s Its values: %s"
                             % (case.name, e, ", ".join("%s = %r" % kv for kv in case.inputs.items()))) from None


def find_grainlab(grainlab=None):
    """The grainlab binary: `grainlab`, else $GRAINLAB, else `grainlab` on PATH."""
    path = grainlab or os.environ.get("GRAINLAB") or shutil.which("grainlab")
    if not path:
        raise SweepError("no grainlab program: give its path (grainlab=\"build/grainlab\", or the GRAINLAB "
                         "environment variable), or put it on PATH")
    if not (os.path.isfile(path) and os.access(path, os.X_OK)):
        raise SweepError("grainlab program '%s' does not exist or is not executable; build it "
                         "(cmake --build build --target grainlab) or give the right path" % path)
    return os.path.abspath(path)


def import_distributed():
    try:
        import distributed
    except ImportError as e:
        raise ImportError("grainlab sweeps run on Dask's distributed scheduler, which does not import here (%s): "
                          "install it with `sudo apt-get install python3-distributed` (Debian's package; "
                          "scripts/setup.sh installs it)" % e) from None
    return distributed


class _Cluster:
    """The client to submit to: the given one, one connected to an address, or a LocalCluster's."""

    def __init__(self, client, workers, allowed_failures):
        self.distributed = import_distributed()
        self.owned = []
        if client is None:
            import dask
            with dask.config.set({"distributed.scheduler.allowed-failures": allowed_failures}):
                cores = len(os.sched_getaffinity(0))  # the cores this process may use (taskset, cgroups)
                cluster = self.distributed.LocalCluster(n_workers=workers or cores,
                                                        threads_per_worker=1, processes=True,
                                                        dashboard_address=":0")
            self.owned.append(cluster)
            client = self.distributed.Client(cluster)
            self.owned.insert(0, client)
        elif isinstance(client, str):  # an address, or the file `dask scheduler --scheduler-file` writes
            client = (self.distributed.Client(scheduler_file=client) if os.path.isfile(client)
                      else self.distributed.Client(client))
            self.owned.append(client)
        self.client = client

    def close(self):
        for thing in self.owned:
            thing.close()


def _job(case, grainlab, threads, case_reports, lock_wait_s):
    return {"name": case.name, "folder": case.folder, "config_text": case.config_text,
            "config_hash": case.config_hash, "inputs": case.inputs, "grainlab": grainlab, "threads": threads,
            "report": case_reports, "lock_wait_s": lock_wait_s}


def _describe(result):
    if result["status"] == "finished":
        return "finished in %.1f s%s" % (result["wall_s"], " (resumed from its checkpoint)" if result["resumed"] else "")
    if result["status"] == "skipped":
        return "finished before"
    if result["status"] == "stopped":
        return "stopped (its checkpoint is saved)"
    first = (result.get("error") or "").strip().splitlines()
    return "FAILED (exit code %s): %s" % (result.get("exit_code"), first[-1] if first else "")


def _run_cases(todo, client, workers, allowed_failures, job_args, log):
    """Runs `todo` on Dask; returns {name: result}."""
    cluster = _Cluster(client, workers, allowed_failures)
    try:
        import cloudpickle
        cloudpickle.register_pickle_by_value(_sweep_task)  # workers need no grainlab package
        c = cluster.client
        if getattr(c, "dashboard_link", None) and cluster.owned:
            log("Dask dashboard: %s" % c.dashboard_link)
        futures = {}
        sitting = uuid.uuid4().hex[:8]
        for case in todo:
            f = c.submit(_sweep_task.run_case, _job(case, *job_args),  # a key of its own each sitting
                         key="grainlab-case-%s-%s-%s" % (case.name, case.config_hash[:12], sitting))
            futures[f] = case
        results = {}
        for f in cluster.distributed.as_completed(list(futures)):
            case = futures[f]
            try:
                r = f.result()
            except cluster.distributed.KilledWorker as e:
                r = {"case": case.name, "status": "failed", "exit_code": None, "resumed": False, "wall_s": 0.0,
                     "error": "the workers running this case died more often than the scheduler allows "
                              "(distributed.scheduler.allowed-failures): %s; look for what kills them (memory?), "
                              "then run the sweep again: it continues from the case's checkpoint" % e}
            except Exception as e:  # the task itself failed (e.g. the folder is not writable there)
                r = {"case": case.name, "status": "failed", "exit_code": None, "resumed": False, "wall_s": 0.0,
                     "error": "%s: %s" % (type(e).__name__, e)}
            results[case.name] = r
            log("[%d/%d] %s: %s" % (len(results), len(futures), case.name, _describe(r)))
        return results
    finally:
        cluster.close()


def _write_report(grainlab, folders, out, log):
    """The comparison report of the finished runs (one run: its report); the path or None."""
    report = os.path.join(out, "report")
    proc = subprocess.run([grainlab, "report", *folders, "--out", report], stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True)
    if proc.returncode != 0:
        log("grainlab sweep: warning: the report was not written (grainlab report exited %d): %s\n"
            "  write it later with `grainlab report %s --out %s`"
            % (proc.returncode, proc.stdout.strip()[-2000:], " ".join(folders), report))
        return None
    return os.path.join(report, "index.html")


def sweep(base, grid=None, seeds=None, client=None, out="runs/sweep", workers=None, variants=None, threads=1,
          grainlab=None, report=True, case_reports=False, allowed_failures=3, lock_wait_s=120, log=print):
    """Runs every case of a sweep (see the module's docstring) and returns a SweepResult.

    base: the config every case starts from: a TOML file path, a TOML string, a dict of the same
        keys, or an object with .to_toml() (grainlab.Config). Relative paths in it start at the
        working directory, as for `grainlab run`.
    grid: {dotted config key: [values]}: every combination is a case (SI units, docs/config.md).
    seeds: [integers]: each combination runs once per seed (top-level key `seed`); None: the base's.
    variants: [{"name": ..., key: value, ...}]: sets of values that go together (a sand preset and
        its final strain), crossed with the grid; their name starts the folder names.
    client: None (a LocalCluster of `workers` single-threaded processes, default one per core),
        a distributed.Client, a scheduler address ("tcp://head:8786") or a scheduler file (the
        JSON file of `dask scheduler --scheduler-file PATH`).
    out: the sweep's folder: one folder per case, cases.csv, report/.
    threads: each run's --threads (1: one core per case, the cluster runs the cases side by side).
    grainlab: the binary (default $GRAINLAB, then PATH); workers on other machines must see the
        same path and the same `out` (a shared file system).
    report: write the comparison report of the finished cases to out/report (needs matplotlib).
    case_reports: let each run write its own report/ too (else `grainlab run --no-report`).
    allowed_failures: how often a case may lose its worker before it counts as failed (only for the
        LocalCluster made here; an existing scheduler has its distributed.scheduler.allowed-failures).
    lock_wait_s: how long a case waits for a previous grainlab in its folder to let go of it.
    log: where progress lines go (print; None for silence).
    """
    log = log or (lambda *a: None)
    cases = plan_cases(base, out, grid=grid, seeds=seeds, variants=variants)
    check_cases(cases)
    if not isinstance(threads, int) or isinstance(threads, bool) or threads < 0:
        raise SweepError("threads = %r: give each run's thread count, an integer >= 0 (0: automatic)" % (threads,))
    if workers is not None and (not isinstance(workers, int) or isinstance(workers, bool) or workers < 1):
        raise SweepError("workers = %r: give the number of worker processes, an integer >= 1" % (workers,))
    binary = find_grainlab(grainlab)
    out = os.path.abspath(out)
    os.makedirs(out, exist_ok=True)
    todo = [c for c in cases if not _sweep_task.is_finished(c.folder, c.config_hash)]
    results = {c.name: {"case": c.name, "status": "skipped", "exit_code": 0, "error": ""}
               for c in cases if c not in todo}
    log("grainlab sweep: %d cases in %s, %d finished before, %d to run" % (len(cases), out, len(results), len(todo)))
    started = time.monotonic()
    if todo:
        results.update(_run_cases(todo, client, workers, allowed_failures,
                                  (binary, threads, case_reports, lock_wait_s), log))
    ran = [c.name for c in todo if results[c.name]["status"] != "skipped"]
    rows = _sweep_table.rows(cases, results)
    table_path = _sweep_table.write(rows, out)[0]
    done = [c.folder for c in cases if results[c.name]["status"] in ("finished", "skipped")]
    index = os.path.join(out, "report", "index.html")
    report_path = index if os.path.exists(index) and not ran else None
    if report and done and (ran or report_path is None):
        report_path = _write_report(binary, done, out, log)
    failed = sum(results[c.name]["status"] == "failed" for c in cases)
    stopped = sum(results[c.name]["status"] == "stopped" for c in cases)
    log("grainlab sweep: %d of %d cases finished%s%s in %.0f s; table %s%s"
        % (len(cases) - failed - stopped, len(cases),
           ", %d FAILED (see the table's error column)" % failed if failed else "",
           ", %d stopped" % stopped if stopped else "", time.monotonic() - started, table_path,
           ", report %s" % report_path if report_path else ""))
    return SweepResult(folder=out, cases=cases, results=results, table=_sweep_table.as_frame(rows),
                       table_path=table_path, report=report_path, ran=ran)

