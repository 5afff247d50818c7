"""The table of a sweep: one row per case, its inputs and what its run.json reports.

Columns: case, status, exit_code, error, the case's inputs (variant, dotted config keys,
seed), then every number, string and boolean of run.json flattened to dotted names
(peaks.friction_angle_deg, preparation.void_ratio, final.void_ratio, ...; SI units as
the names say), leaving out the config (the inputs are its varied part) and arrays.
Written as CSV, and as Parquet too when pyarrow imports.
"""

import csv
import json
import os

_SKIPPED_GROUPS = ("config", "specimen_preparation")


def _flat_scalars(d, prefix=""):
    out = {}
    for k, v in d.items():
        if not prefix and k in _SKIPPED_GROUPS:
            continue
        if isinstance(v, dict):
            out.update(_flat_scalars(v, prefix + k + "."))
        elif isinstance(v, (str, int, float, bool)) or v is None:
            out[prefix + k] = v
    return out


def rows(cases, results):
    """One dict per case (in the cases' order) from its result and its run.json."""
    out = []
    for case in cases:
        r = results.get(case.name, {})
        row = {"case": case.name, "status": r.get("status", "not run"), "exit_code": r.get("exit_code"),
               "error": r.get("error", "")}
        row.update(case.inputs)
        try:
            with open(os.path.join(case.folder, "run.json")) as f:
                row.update(_flat_scalars(json.load(f)))
        except (OSError, ValueError):
            pass
        out.append(row)
    return out


def write(table_rows, folder):
    """Writes folder/cases.csv (and cases.parquet with pyarrow); returns the paths written."""
    columns = []
    for row in table_rows:
        columns += [c for c in row if c not in columns]
    path = os.path.join(folder, "cases.csv")
    tmp = path + ".tmp"
    with open(tmp, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=columns, restval="")
        w.writeheader()
        for row in table_rows:
            w.writerow({k: ("" if v is None else v) for k, v in row.items()})
    os.replace(tmp, path)
    written = [path]
    try:
        import pyarrow
        import pyarrow.parquet
    except ImportError:
        return written
    try:
        table = pyarrow.Table.from_pylist([{c: row.get(c) for c in columns} for row in table_rows])
        pyarrow.parquet.write_table(table, os.path.join(folder, "cases.parquet"))
    except (pyarrow.ArrowException, OSError) as e:
        print("grainlab sweep: warning: cases.parquet not written (%s); cases.csv has the same table" % e)
        return written
    written.append(os.path.join(folder, "cases.parquet"))
    return written


def as_frame(table_rows):
    """The rows as a pandas DataFrame, or the list itself when pandas is absent."""
    try:
        import pandas
    except ImportError:
        return table_rows
    return pandas.DataFrame(table_rows)
