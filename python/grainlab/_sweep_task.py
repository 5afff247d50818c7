"""One case of a sweep, run on a Dask worker: `grainlab run config.toml` in the case's folder.

Standard library only: the sweep sends this module to the workers by value, so a worker
needs the grainlab binary and the shared output folder, not this package.

- A case whose run.json says "done" and whose sweep_case.json holds the same config hash
  is finished: nothing runs.
- A case with a checkpoint.bin of the same config continues it (`--resume`); a case
  whose config changed starts again (its old run.json and checkpoint are removed).
- The grainlab child gets SIGTERM when the worker process dies (prctl PR_SET_PDEATHSIG):
  it saves a checkpoint and exits, so the resubmitted task continues from it. The task
  first waits for the folder's lock (.grainlab.lock, a flock that a running grainlab
  holds), so a resubmitted case does not collide with its dying predecessor.
- A run that fails is returned with its exit code and the tail of its error output,
  never raised: the other cases go on. A run stopped by a signal (exit 130: Ctrl-C)
  is "stopped": its checkpoint is saved.
"""

import ctypes
import errno
import fcntl
import json
import os
import signal
import socket
import subprocess
import time

CASE_FILE = "sweep_case.json"  # the sweep's record of a case: its inputs and config hash
LOG_FILE = "sweep.log"         # the output of every sitting of the case's run
LOCK_FILE = ".grainlab.lock"   # grainlab's folder lock (src/core/folder_lock.h)
_PR_SET_PDEATHSIG = 1


def run_json_done(folder):
    """Whether folder/run.json is the record of a finished run."""
    try:
        with open(os.path.join(folder, "run.json")) as f:
            return json.load(f).get("phase") == "done"
    except (OSError, ValueError):
        return False


def recorded_hash(folder):
    try:
        with open(os.path.join(folder, CASE_FILE)) as f:
            return json.load(f).get("config_hash")
    except (OSError, ValueError):
        return None


def is_finished(folder, config_hash):
    return recorded_hash(folder) == config_hash and run_json_done(folder)


def _write_atomically(path, text):
    tmp = path + ".tmp%d" % os.getpid()
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


def _wait_for_lock(folder, timeout_s):
    """Waits until no process holds the folder's grainlab lock; False after timeout_s."""
    path = os.path.join(folder, LOCK_FILE)
    fd = os.open(path, os.O_RDWR | os.O_CREAT, 0o644)
    try:
        deadline = time.monotonic() + timeout_s
        while True:
            try:
                fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
                fcntl.flock(fd, fcntl.LOCK_UN)
                return True
            except OSError as e:
                if e.errno not in (errno.EWOULDBLOCK, errno.EAGAIN) or time.monotonic() > deadline:
                    return False
            time.sleep(0.1)
    finally:
        os.close(fd)


def _die_with_parent(parent_pid):
    """preexec_fn: SIGTERM to the child when the worker process that started it dies.

    libc is loaded here, in the parent: between fork and exec the child only calls it
    (loading a library there could wait forever on a lock another thread held at the fork).
    """
    prctl = ctypes.CDLL(None, use_errno=True).prctl

    def set_death_signal():
        prctl(_PR_SET_PDEATHSIG, signal.SIGTERM, 0, 0, 0)
        if os.getppid() != parent_pid:  # the worker died before prctl took effect
            os._exit(143)
    return set_death_signal


def _tail(text, lines=20):
    return "\n".join(text.strip().splitlines()[-lines:])


def run_case(job):
    """Runs one case; `job` is a dict of name, folder, config_text, config_hash, inputs,
    grainlab (the binary's path), threads, report (bool), lock_wait_s."""
    folder = job["folder"]
    result = {"case": job["name"], "folder": folder, "exit_code": None, "error": "", "resumed": False,
              "wall_s": 0.0, "host": socket.gethostname(), "worker_pid": os.getpid()}
    os.makedirs(folder, exist_ok=True)
    if is_finished(folder, job["config_hash"]):
        return dict(result, status="skipped", exit_code=0)
    if not _wait_for_lock(folder, job.get("lock_wait_s", 120)):
        return dict(result, status="failed",
                    error="another process holds the case folder's lock (%s) for over %g s: is the sweep already "
                          "running elsewhere? Stop it or wait, then run the sweep again"
                          % (os.path.join(folder, LOCK_FILE), job.get("lock_wait_s", 120)))
    if recorded_hash(folder) != job["config_hash"]:
        for stale in ("run.json", "checkpoint.bin"):  # another config's: start again
            try:
                os.remove(os.path.join(folder, stale))
            except FileNotFoundError:
                pass
        _write_atomically(os.path.join(folder, "config.toml"), job["config_text"])
        record = {"case": job["name"], "config_hash": job["config_hash"], "inputs": job["inputs"]}
        _write_atomically(os.path.join(folder, CASE_FILE), json.dumps(record, indent=2) + "\n")
    resume = os.path.exists(os.path.join(folder, "checkpoint.bin"))
    args = [job["grainlab"], "run", "config.toml", "--quiet", "--threads", str(job.get("threads", 1))]
    if not job.get("report", False):
        args.append("--no-report")
    if resume:
        args.append("--resume")
    started = time.monotonic()
    log_path = os.path.join(folder, LOG_FILE)
    with open(log_path, "a") as log:
        log.write("# %s on %s (pid %d): %s\n" % (time.strftime("%Y-%m-%d %H:%M:%S"), result["host"],
                                                 os.getpid(), " ".join(args)))
        log.flush()
        sitting_start = log.tell()
        try:
            child = subprocess.Popen(args, cwd=folder, stdin=subprocess.DEVNULL, stdout=log,
                                     stderr=subprocess.PIPE, text=True, preexec_fn=_die_with_parent(os.getpid()))
        except OSError as e:
            return dict(result, status="failed", error="cannot start '%s': %s; build grainlab or give its path "
                        "(grainlab=... / the GRAINLAB environment variable)" % (job["grainlab"], e.strerror))
        _, err = child.communicate()
        log.write(err)
    result.update(exit_code=child.returncode, resumed=resume, wall_s=time.monotonic() - started)
    if child.returncode == 0 and run_json_done(folder):
        return dict(result, status="finished")
    if child.returncode == 130:  # a stop signal (Ctrl-C, SIGTERM): grainlab saved what it had
        return dict(result, status="stopped", error="stopped by a signal; the next sweep continues it from what "
                    "it saved")
    with open(log_path) as log:  # no message on stderr: the end of what this sitting printed
        log.seek(sitting_start)
        printed = log.read()
    return dict(result, status="failed", error=_tail(err) or _tail(printed, 5) or
                "grainlab exited with code %s and printed nothing (see %s)" % (child.returncode, log_path))
