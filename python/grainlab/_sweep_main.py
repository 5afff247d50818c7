"""`python -m grainlab._sweep_main SWEEP.toml` (what `grainlab sweep` runs): a sweep file's cases on Dask.

Exit status: 0 every case finished; 2 bad input (the sweep file, a missing grainlab
binary); 3 a case failed (the others ran; the table has its error), Dask is missing, or
the cluster failed; 130 stopped (Ctrl-C): the running cases saved their checkpoints, and
the same command continues.
"""

import argparse
import sys

from . import _sweep_file, _sweep_task
from ._sweep_cases import SweepError, plan_cases
from .sweep import check_cases, find_grainlab, import_distributed, sweep

EPILOG = """\
The sweep file names a base config and what to vary (docs/sweeps.md):

    base = "base.toml"                 # a grainlab config, from this file's folder
    seeds = [1, 2, 3]
    [grid]
    "consolidation.normal_stress" = [50e3, 100e3, 200e3]   # Pa

Each case runs `grainlab run config.toml` in OUT/CASE; finished cases are skipped, so the
same command continues a stopped sweep. Results: OUT/cases.csv and OUT/report/index.html.
On a cluster: start `dask scheduler` on one node and `dask worker tcp://HOST:8786
--nthreads 1 --nworkers N` on the others (same grainlab path and OUT on a shared file
system), then pass --scheduler tcp://HOST:8786.
"""


def _parser():
    p = argparse.ArgumentParser(
        prog="grainlab sweep", description="Run every case of a parameter sweep (a base config x grid values x "
        "seeds) as `grainlab run` tasks on Dask: a local cluster, or an existing one (--scheduler).",
        epilog=EPILOG, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("sweep_file", metavar="SWEEP.toml", help="the sweep file")
    p.add_argument("--scheduler", metavar="ADDRESS", help="an existing Dask scheduler: its address (e.g. "
                   "tcp://head:8786) or its scheduler file (dask scheduler --scheduler-file); overrides the file's")
    p.add_argument("--workers", type=int, metavar="N", help="worker processes of the local cluster (default: the "
                   "file's workers, else one per core)")
    p.add_argument("--out", metavar="DIR", help="the sweep's folder (overrides the file's out)")
    p.add_argument("--dry-run", action="store_true", help="list the cases and which finished before; run nothing")
    p.add_argument("--grainlab", metavar="PATH", help="the grainlab binary (default $GRAINLAB, then PATH)")
    return p


def _dry_run(kwargs, log):
    cases = plan_cases(kwargs["base"], kwargs["out"], grid=kwargs.get("grid"), seeds=kwargs.get("seeds"),
                       variants=kwargs.get("variants"))
    check_cases(cases)
    done = 0
    for c in cases:
        finished = _sweep_task.is_finished(c.folder, c.config_hash)
        done += finished
        values = ", ".join("%s = %r" % kv for kv in c.inputs.items())
        log("%s  %s  (%s)" % ("done" if finished else "todo", c.name, values))
    log("%d cases in %s: %d finished before, %d to run" % (len(cases), kwargs["out"], done, len(cases) - done))
    return 0


def main(argv=None):
    args = _parser().parse_args(argv)
    log = lambda line: print(line, flush=True)  # noqa: E731
    try:
        kwargs = _sweep_file.read(args.sweep_file)
        if args.out:
            kwargs["out"] = args.out
        if args.workers is not None:
            if args.workers < 1:
                raise SweepError("--workers %d: give at least 1 worker process" % args.workers)
            kwargs["workers"] = args.workers
        if args.scheduler:
            kwargs["client"] = args.scheduler
        if args.dry_run:
            return _dry_run(kwargs, log)
        find_grainlab(args.grainlab)
        import_distributed()
        result = sweep(grainlab=args.grainlab, log=log, **kwargs)
    except SweepError as e:
        print("grainlab sweep: error: %s" % e, file=sys.stderr)
        return 2
    except ImportError as e:
        print("grainlab sweep: error: %s" % e, file=sys.stderr)
        return 3
    except KeyboardInterrupt:
        print("grainlab sweep: stopped; run the same command again to continue (finished cases are kept, "
              "the others continue from their checkpoints)", file=sys.stderr)
        return 130
    except OSError as e:  # a folder that cannot be written, a scheduler that cannot be reached
        print("grainlab sweep: error: %s; check the path or the scheduler's address" % e, file=sys.stderr)
        return 3
    for name in result.failed:
        if name not in result.stopped:
            print("grainlab sweep: case %s failed: %s" % (name, result.results[name].get("error", "")),
                  file=sys.stderr)
    if result.stopped and len(result.stopped) == len(result.failed):
        print("grainlab sweep: %d case(s) stopped by a signal; run the same command again to continue them"
              % len(result.stopped), file=sys.stderr)
        return 130
    return 3 if result.failed else 0


if __name__ == "__main__":
    sys.exit(main())
