"""grainlab.Config: a run's configuration, read and checked by the command line's code.

A Config is the TOML that ``grainlab run`` reads (every key, its unit and
meaning: ``docs/config.md``, or ``grainlab run --print-defaults``). It is made
from a file, a TOML string or a dict with the same keys, and checked the same
way: a bad key or value raises :class:`grainlab.ConfigError` with the
command line's message. SI units throughout (m, kg, s, N, Pa).
"""

from __future__ import annotations

import os
import tomllib
from typing import Any, Mapping, Union

from . import _grainlab, _toml_write

PathLike = Union[str, "os.PathLike[str]"]


class Config:
    """A checked run configuration (the keys of ``grainlab run``'s TOML file).

    Make one with :meth:`from_toml` (a file), :meth:`from_string`,
    :meth:`from_dict` or :func:`grainlab.default_config`. It holds every key
    (defaults filled in), exactly as the run's ``config.toml`` will.

    >>> cfg = grainlab.Config.from_dict({"shear": {"final_strain": 0.05}})
    >>> cfg["shear.final_strain"]
    0.05
    """

    def __init__(self, toml_text: str, source: str = "<string>") -> None:
        """Parses and checks ``toml_text``; ``source`` names it in error messages."""
        self._toml = _grainlab.config_toml(toml_text, source)
        self.source = source

    @classmethod
    def from_toml(cls, path: PathLike) -> "Config":
        """Reads a config file, as ``grainlab run FILE`` does (ConfigError names the file and line)."""
        path = os.fspath(path)
        config = cls.__new__(cls)
        config._toml = _grainlab.load_config_toml(path)
        config.source = path
        return config

    @classmethod
    def from_string(cls, text: str) -> "Config":
        """Parses config text (TOML); messages name it ``<string>``."""
        return cls(text, "<string>")

    @classmethod
    def from_dict(cls, values: Mapping[str, Any]) -> "Config":
        """A config from a dict with the file's layout: top-level keys (``test``, ``seed``) and
        tables as nested dicts, e.g. ``{"seed": 3, "box": {"length": 0.003}}``. Keys left out keep
        their defaults; ``material.preset`` applies a sand preset before the other keys. Messages
        name it ``<dict>`` with the line of the TOML it was written as (see :meth:`dict_to_toml`)."""
        return cls(dict_to_toml(values), "<dict>")

    def to_toml(self) -> str:
        """Every key as TOML, exact (``Config.from_string(c.to_toml())`` equals ``c``)."""
        return self._toml

    def to_dict(self) -> dict:
        """Every key as nested dicts (tables) of values."""
        return tomllib.loads(self._toml)

    def __getitem__(self, dotted_key: str) -> Any:
        """The value of a dotted key, e.g. ``config["consolidation.normal_stress"]`` (Pa)."""
        node: Any = self.to_dict()
        for part in _split_key(dotted_key):
            if not isinstance(node, dict) or part not in node:
                raise KeyError(f"{dotted_key!r} is not a key of this config; see docs/config.md for the keys")
            node = node[part]
        return node

    def replace(self, changes: Mapping[str, Any]) -> "Config":
        """A new config with some keys changed, given dotted: ``cfg.replace({"seed": 2,
        "shear.final_strain": 0.02})``. Checked like any config. (A changed ``material.preset``
        does not reset keys this config sets already: build the config with
        :meth:`from_dict` from the preset instead.)"""
        values = self.to_dict()
        for dotted_key, value in changes.items():
            *tables, last = _split_key(dotted_key)
            node = values
            for table in tables:
                node = node.setdefault(table, {})
            node[last] = value
        return Config.from_dict(values)

    @property
    def test(self) -> str:
        """The lab test: ``direct-shear``, ``oedometer``, ``triaxial``."""
        return self["test"]

    def differences(self, other: "Config") -> list[str]:
        """Dotted keys whose values differ between this config and ``other``."""
        return list(_grainlab.config_differences(self._toml, other._toml))

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Config) and self._toml == other._toml

    def __hash__(self) -> int:
        return hash(self._toml)

    def __repr__(self) -> str:
        return f"<grainlab.Config {self.test} seed={self['seed']} from {self.source}>"


def default_config(test: str = "direct-shear", law: str = "") -> Config:
    """The embedded default config of a lab test (``grainlab run --print-defaults --test TEST``),
    for contact law ``law`` ("" = the default, hertz-material). ``test``: one of
    ``grainlab.lab_tests()``."""
    return Config(_grainlab.default_config_toml(test, law), "<embedded default>")


def lab_tests() -> list[str]:
    """The names of the lab tests a config's ``test`` key can name."""
    return list(_grainlab.lab_test_names())


def _split_key(dotted_key: str) -> list[str]:
    # A law's table holds a dash: material.hertz-material.youngs_modulus.
    return dotted_key.split(".")


def dict_to_toml(values: Mapping[str, Any]) -> str:
    """TOML text of a dict of top-level values and tables (nested dicts): what
    :meth:`Config.from_dict` parses. Values: str, bool, int, float, lists of them."""
    return _toml_write.dumps(values)
