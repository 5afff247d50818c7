"""The cases of a sweep: a base config, crossed with variants, a grid of values and seeds.

cases = variants x (Cartesian product of the grid's value lists) x seeds, in that order
(the last seed varies fastest). Each case is the base config with its values set at
their dotted keys ("consolidation.normal_stress" is [consolidation] normal_stress), the
seed at the top-level key `seed`, and output.folder = "." (a case runs in its own
folder). Its folder name is made of its values ("ottawa_normal_stress-100000_seed-7")
and its identity is the SHA-256 of its config text: a case whose config changed is run
again, one whose config is the same and whose run finished is not.
"""

import copy
import dataclasses
import difflib
import hashlib
import itertools
import os
import re
import tomllib

from . import _toml_write

# Config keys that hold paths; relative ones are made absolute (a case runs in its own folder).
PATH_KEYS = ("grains.folder", "grains.scan", "specimen.from")


class SweepError(ValueError):
    """Bad sweep input: the message says what, where and how to fix it."""


@dataclasses.dataclass
class Case:
    name: str           # folder name under the sweep's output folder
    folder: str         # absolute path of that folder
    inputs: dict        # what this case sets: "variant", dotted keys, "seed"
    config_text: str    # its config.toml
    config_hash: str    # SHA-256 of config_text


def suggest(word, choices):
    close = difflib.get_close_matches(word, list(choices), n=1)
    return " (did you mean '%s'?)" % close[0] if close else ""


def config_from(base, where="base"):
    """The base config as a dict: a TOML path, a TOML string, a dict or an object with .to_toml().

    Paths in it (grains.folder, ...) start at the working directory, as for `grainlab run`.
    """
    if hasattr(base, "to_toml") and callable(base.to_toml):
        base = base.to_toml()
    if isinstance(base, dict):
        return copy.deepcopy(base)
    if isinstance(base, os.PathLike) or (isinstance(base, str) and "\n" not in base and "=" not in base):
        path = os.fspath(base)
        if not os.path.isfile(path):
            raise SweepError("%s: no config file at '%s' (relative paths start at %s); give the path of a "
                             "grainlab config (`grainlab run --print-defaults > base.toml` writes one), or the "
                             "config itself as a TOML string or a dict" % (where, path, os.getcwd()))
        with open(path, "rb") as f:
            try:
                return tomllib.load(f)
            except tomllib.TOMLDecodeError as e:
                raise SweepError("%s: '%s' is not valid TOML: %s; fix the file" % (where, path, e)) from None
    if isinstance(base, str):
        try:
            return tomllib.loads(base)
        except tomllib.TOMLDecodeError as e:
            raise SweepError("%s: the config string is not valid TOML: %s" % (where, e)) from None
    raise SweepError("%s: a config is a TOML file path, a TOML string, a dict or an object with .to_toml(), "
                     "not %s" % (where, type(base).__name__))


def flatten(d, prefix=""):
    """{"a": {"b": 1}} as {"a.b": 1}."""
    out = {}
    for k, v in d.items():
        key = prefix + k
        if isinstance(v, dict):
            out.update(flatten(v, key + "."))
        else:
            out[key] = v
    return out


def set_dotted(config, key, value, where):
    parts = key.split(".")
    if not all(parts):
        raise SweepError("%s: '%s' is not a config key (keys are like consolidation.normal_stress, see "
                         "docs/config.md)" % (where, key))
    node = config
    for i, p in enumerate(parts[:-1]):
        node = node.setdefault(p, {})
        if not isinstance(node, dict):
            raise SweepError("%s: '%s': '%s' is a value in the base config, not a table; check the key "
                             "(docs/config.md)" % (where, key, ".".join(parts[: i + 1])))
    if isinstance(node.get(parts[-1]), dict):
        raise SweepError("%s: '%s' is a table of the config, not a key; name one of its keys (%s)"
                         % (where, key, ", ".join(key + "." + k for k in node[parts[-1]])))
    node[parts[-1]] = value


def value_label(v):
    """A value as a folder-name piece: 100000.0 -> 100000, "sub angular" -> sub_angular."""
    if isinstance(v, bool):
        text = "true" if v else "false"
    elif isinstance(v, float):
        text = "%g" % v if float("%g" % v) == v else repr(v)
    elif isinstance(v, (list, tuple)):
        text = "+".join(value_label(x) for x in v)
    else:
        text = str(v)
    return re.sub(r"[^A-Za-z0-9.+-]+", "_", text).strip("_") or "_"


def _check_grid(grid):
    if grid is None:
        return {}
    if not isinstance(grid, dict):
        raise SweepError("grid: give a dict of dotted config keys to lists of values, e.g. "
                         "{'consolidation.normal_stress': [50e3, 100e3]}, not %s" % type(grid).__name__)
    grid = flatten(grid)
    for key, values in grid.items():
        if not isinstance(values, (list, tuple)) or len(values) == 0:
            raise SweepError("grid.%s: give a non-empty list of the values to run (e.g. %s = [1, 2]), not %r"
                             % (key, key, values))
    return grid


def _check_seeds(seeds):
    if seeds is None:
        return None
    if not isinstance(seeds, (list, tuple)) or not seeds:
        raise SweepError("seeds: give a non-empty list of integer seeds (e.g. [1, 2, 3]), not %r" % (seeds,))
    for s in seeds:
        if isinstance(s, bool) or not isinstance(s, int) or s < 0:
            raise SweepError("seeds: %r is not a seed; seeds are integers >= 0 (e.g. [1, 2, 3])" % (s,))
    if len(set(seeds)) != len(seeds):
        raise SweepError("seeds: %r repeats a seed; each seed once" % (list(seeds),))
    return list(seeds)


def _check_variants(variants):
    if variants is None:
        return [{}]
    if not isinstance(variants, (list, tuple)) or not variants:
        raise SweepError("variants: give a non-empty list of tables, each a 'name' and the config keys it "
                         "sets together (e.g. {'name': 'angular', 'material.preset': 'crushed-limestone'})")
    out, names = [], set()
    for i, v in enumerate(variants):
        where = "variants[%d]" % i
        if not isinstance(v, dict):
            raise SweepError("%s: a variant is a table of 'name' and config keys, not %r" % (where, v))
        v = dict(v)
        name = v.pop("name", None)
        if not isinstance(name, str) or not name.strip():
            raise SweepError("%s: give it a name (name = \"...\"): it starts the folder names of its cases" % where)
        if name in names:
            raise SweepError("%s: the name '%s' is taken by another variant; give each its own" % (where, name))
        names.add(name)
        values = flatten(v)
        if not values:
            raise SweepError("%s ('%s'): it sets no config key; add the keys it changes" % (where, name))
        out.append(dict(values, name=name))
    return out


def _absolute_paths(config, cwd):
    flat = flatten(config)
    for key in PATH_KEYS:
        p = flat.get(key)
        if isinstance(p, str) and p and not os.path.isabs(p):
            set_dotted(config, key, os.path.normpath(os.path.join(cwd, p)), key)


def plan_cases(base, out, grid=None, seeds=None, variants=None):
    """The cases of a sweep (see the module's docstring); raises SweepError for bad input."""
    config = config_from(base)
    grid = _check_grid(grid)
    seeds = _check_seeds(seeds)
    variants = _check_variants(variants)
    if seeds is not None and "seed" in grid:
        raise SweepError("grid.seed and seeds both set the seed; give the seeds in one of them")
    varied = list(grid)
    for v in variants:
        for key in v:
            if key != "name" and key in grid:
                raise SweepError("variant '%s' and grid both set '%s'; set it in one of them" % (v["name"], key))
    # A grid key's folder label: its last part, or the whole key where two keys share it.
    last = [k.split(".")[-1] for k in varied]
    labels = {k: (k.split(".")[-1] if last.count(k.split(".")[-1]) == 1 else k) for k in varied}
    # Every key a variant sets is an input of every case (the base's value where its variant leaves it).
    variant_keys = list(dict.fromkeys(k for v in variants for k in v if k != "name"))
    cwd = os.getcwd()
    out = os.path.abspath(out)
    cases, seen = [], {}
    for variant in variants:
        for combo in itertools.product(*(grid[k] for k in varied)):
            for seed in (seeds if seeds is not None else [None]):
                case_config = copy.deepcopy(config)
                inputs = {}
                parts = []
                if variant:
                    inputs["variant"] = variant["name"]
                    parts.append(value_label(variant["name"]))
                    for key, value in variant.items():
                        if key != "name":
                            set_dotted(case_config, key, value, "variant '%s'" % variant["name"])
                for key, value in zip(varied, combo):
                    set_dotted(case_config, key, value, "grid." + key)
                    inputs[key] = value
                    parts.append("%s-%s" % (value_label(labels[key]), value_label(value)))
                if seed is not None:
                    case_config["seed"] = seed
                    parts.append("seed-%d" % seed)
                flat = flatten(case_config)
                for key in variant_keys:
                    inputs[key] = flat.get(key)
                inputs.setdefault("seed", case_config.get("seed", 1))
                case_config.setdefault("output", {})
                if not isinstance(case_config["output"], dict):
                    raise SweepError("base: 'output' must be a table ([output])")
                case_config["output"]["folder"] = "."
                _absolute_paths(case_config, cwd)
                name = "_".join(parts) or "case"
                if name in seen:
                    raise SweepError("two cases get the folder name '%s' (%s and %s); make their values differ "
                                     "in more than punctuation" % (name, seen[name], inputs))
                seen[name] = inputs
                try:
                    text = _toml_write.dumps(case_config)
                except TypeError as e:
                    raise SweepError("case %s: %s" % (name, e)) from None
                cases.append(Case(name=name, folder=os.path.join(out, name), inputs=inputs, config_text=text,
                                  config_hash=hashlib.sha256(text.encode()).hexdigest()))
    return cases
