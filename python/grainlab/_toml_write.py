"""A nested dict written as TOML text (the reverse of the standard library's tomllib).

Only what a grainlab config holds: tables of strings, booleans, integers, floats and
lists of them. Top-level values come first, then one [table] per nested dict, in the
dict's order, so the same dict always gives the same text (a sweep hashes it).
"""

import math
import re

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


def value_text(v):
    """One value as TOML (raises TypeError for what a config cannot hold)."""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        return repr(v)
    if isinstance(v, str):
        return _string(v)
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(value_text(x) for x in v) + "]"
    if hasattr(v, "item") and callable(v.item):  # a numpy scalar
        return value_text(v.item())
    raise TypeError("a TOML config value must be a string, boolean, number or list, not %s (%r)"
                    % (type(v).__name__, v))


def dumps(data):
    """The TOML text of `data` (a dict of values and nested dicts)."""
    lines = []

    def table(d, path):
        scalars = [(k, v) for k, v in d.items() if not isinstance(v, dict)]
        tables = [(k, v) for k, v in d.items() if isinstance(v, dict)]
        if path and (scalars or not tables):
            if lines:
                lines.append("")
            lines.append("[" + ".".join(_key(p) for p in path) + "]")
        for k, v in scalars:
            lines.append("%s = %s" % (_key(k), value_text(v)))
        for k, v in tables:
            table(v, path + [k])

    table(data, [])
    return "\n".join(lines) + "\n"
