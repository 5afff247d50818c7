"""A sweep file (SWEEP.toml, docs/sweeps.md) read and checked into the arguments of sweep().

    base = "base.toml"              # or an inline [base] table: the config every case starts from
    out = "runs/my_sweep"           # default runs/<file name without .sweep.toml>
    seeds = [1, 2, 3]
    threads = 1                     # each run's --threads
    workers = 0                     # LocalCluster processes, 0 = one per core
    scheduler = ""                  # "tcp://head:8786": an existing Dask cluster
    report = true                   # the comparison report of all cases
    case_reports = false            # each run's own report/ too
    [grid]
    "consolidation.normal_stress" = [50e3, 100e3]
    [[variants]]
    name = "angular"
    "material.preset" = "crushed-limestone"

`base` as a path starts at this file's folder; `out` and paths inside the config start at
the working directory (as for `grainlab run`). Every error names the file, the line
where it can, what is wrong and how to fix it.
"""

import os
import re
import tomllib

from ._sweep_cases import SweepError, config_from, flatten, suggest

KEYS = {
    "base": "the config every case starts from: a path (from this file's folder) or an inline [base] table",
    "out": "the sweep's output folder (from the working directory)",
    "seeds": "list of integer seeds; each case runs once per seed",
    "grid": "table of dotted config keys to lists of values; every combination is a case",
    "variants": "array of tables [[variants]]: a name and config keys that go together",
    "threads": "each run's --threads (integer >= 0; 1 by default)",
    "workers": "worker processes of the local Dask cluster (0: one per core)",
    "scheduler": "an existing Dask scheduler: tcp://HOST:8786 or a scheduler file; \"\" = a local cluster",
    "report": "write the comparison report of the finished cases (true/false)",
    "case_reports": "each run also writes its own report/ (true/false)",
}


def _line_of(text, key):
    """The first line (1-based) that sets or opens `key`, or None."""
    pattern = re.compile(r'^\s*(\[\[?\s*)?"?%s"?\s*(=|\]|\.)' % re.escape(key))
    for n, line in enumerate(text.splitlines(), 1):
        if pattern.match(line):
            return n
    return None


def _where(path, text, key):
    line = _line_of(text, key)
    return "%s:%d" % (path, line) if line else path


def _default_out(path):
    name = os.path.basename(path)
    for suffix in (".sweep.toml", ".toml"):
        if name.endswith(suffix):
            name = name[: -len(suffix)]
            break
    return os.path.join("runs", name or "sweep")


def read(path):
    """The keyword arguments of sweep() (plus "scheduler") that the sweep file at `path` asks for."""
    try:
        with open(path, "rb") as f:
            raw = f.read()
    except OSError as e:
        raise SweepError("cannot read the sweep file '%s': %s; check the path (relative paths start at %s)"
                         % (path, e.strerror, os.getcwd())) from None
    text = raw.decode("utf-8", errors="replace")
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as e:
        raise SweepError("%s: not valid TOML: %s; fix the syntax (docs/sweeps.md shows a sweep file)"
                         % (path, e)) from None
    for key in data:
        if key not in KEYS:
            raise SweepError("%s: unknown key '%s'%s; a sweep file has %s (docs/sweeps.md). Config keys go "
                             "into [base] (or the base file) and the values to vary into [grid]"
                             % (_where(path, text, key), key, suggest(key, KEYS), ", ".join(KEYS)))

    def fail(key, what, fix):
        raise SweepError("%s: %s %s; %s" % (_where(path, text, key), key, what, fix))

    if "base" not in data:
        raise SweepError("%s: no base config: add base = \"base.toml\" (a grainlab config, from this file's "
                         "folder) or an inline [base] table of config keys" % path)
    base = data["base"]
    if isinstance(base, str):
        base_path = base if os.path.isabs(base) else os.path.join(os.path.dirname(os.path.abspath(path)), base)
        if not os.path.isfile(base_path):
            fail("base", "= \"%s\": no such file (looked at %s)" % (base, base_path),
                 "give the path of a grainlab config from the sweep file's folder")
        base = base_path
    elif not isinstance(base, dict):
        fail("base", "must be a path or a table", "write base = \"base.toml\" or an inline [base] table")
    kwargs = {"base": config_from(base, where=_where(path, text, "base") + ": base")}
    kwargs["out"] = data.get("out", _default_out(path))
    if not isinstance(kwargs["out"], str) or not kwargs["out"]:
        fail("out", "must be a folder path (a string)", "e.g. out = \"runs/my_sweep\"")
    if "seeds" in data:
        kwargs["seeds"] = data["seeds"]
    if "grid" in data:
        if not isinstance(data["grid"], dict):
            fail("grid", "must be a table", "write [grid] and under it \"dotted.key\" = [values]")
        for key, values in flatten(data["grid"]).items():
            if not isinstance(values, list) or not values:
                raise SweepError("%s: grid key '%s' = %r: give a non-empty list of the values to run, e.g. "
                                 "\"%s\" = [1, 2]" % (_where(path, text, '"' + key) if _line_of(text, '"' + key)
                                                      else _where(path, text, key), key, values, key))
        kwargs["grid"] = data["grid"]
    if "variants" in data:
        if not isinstance(data["variants"], list):
            fail("variants", "must be an array of tables", "write each variant as a [[variants]] table")
        kwargs["variants"] = data["variants"]
    if "grid" not in data and "variants" not in data and "seeds" not in data:
        raise SweepError("%s: nothing varies: add a [grid] table (\"dotted.key\" = [values]), [[variants]] or "
                         "seeds = [...]" % path)
    for key, default in (("threads", 1), ("workers", 0)):
        v = data.get(key, default)
        if isinstance(v, bool) or not isinstance(v, int) or v < 0:
            fail(key, "= %r must be an integer >= 0" % (v,), KEYS[key])
        kwargs[key] = v
    kwargs["workers"] = kwargs["workers"] or None
    for key, default in (("report", True), ("case_reports", False)):
        v = data.get(key, default)
        if not isinstance(v, bool):
            fail(key, "= %r must be true or false" % (v,), KEYS[key])
        kwargs[key] = v
    scheduler = data.get("scheduler", "")
    if not isinstance(scheduler, str):
        fail("scheduler", "= %r must be a string" % (scheduler,), "e.g. scheduler = \"tcp://head:8786\"")
    kwargs["client"] = scheduler or None
    return kwargs
