"""A nested dict written as TOML text (the reverse of the standard library's tomllib).

Only what a grainlab config holds: tables of strings, booleans, integers, floats and
lists of them. Top-level values come first, then one [table] per nested dict, in the
dict's order, so the same dict always gives the same text (a sweep hashes it).
"""

import math
import os
import re
from collections.abc import Mapping

_BARE_KEY = re.compile(r"^[A-Za-z0-9_-]+$")


def _key(k):
    return k if _BARE_KEY.match(k) else _string(k)


def _string(s):
    out = ['"']
    for ch in s:
        if ch in '"\\':
            out.append("\\" + ch)
        elif ch == "\n":
            out.append("\\n")
        elif ch == "\t":
            out.append("\\t")
        elif ord(ch) < 0x20 or ord(ch) == 0x7F:
            out.append("\\u%04x" % ord(ch))
        else:
            out.append(ch)
    out.append('"')
    return "".join(out)


def value_text(v, where="value"):
    """One value as TOML; `where` (its dotted key) names it in the TypeError raised
    for what a config cannot hold."""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        return repr(float(v))  # a numpy float64 too
    if isinstance(v, str):
        return _string(v)
    if isinstance(v, os.PathLike):
        return _string(os.fspath(v))
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(value_text(x, where) for x in v) + "]"
    if hasattr(v, "item") and callable(v.item):  # a numpy scalar
        return value_text(v.item(), where)
    raise TypeError("%s = %r: a config value is a string, boolean, number or a list of them, not %s"
                    % (where, v, type(v).__name__))


def dumps(data):
    """The TOML text of `data` (a dict of top-level values and tables as nested dicts)."""
    lines = []

    def table(d, path):
        scalars = [(str(k), v) for k, v in d.items() if not isinstance(v, Mapping)]
        tables = [(str(k), v) for k, v in d.items() if isinstance(v, Mapping)]
        if path and (scalars or not tables):
            if lines:
                lines.append("")
            lines.append("[" + ".".join(_key(p) for p in path) + "]")
        for k, v in scalars:
            lines.append("%s = %s" % (_key(k), value_text(v, ".".join(path + [k]))))
        for k, v in tables:
            table(v, path + [k])

    table(data, [])
    return "\n".join(lines) + "\n"
