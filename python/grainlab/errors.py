"""The exceptions of grainlab.

Their messages are the command line's, word for word: what is wrong, where
(file, line, key) and how to fix it.
"""

from __future__ import annotations

import re
from typing import Optional

_WHERE = re.compile(r"^(?P<file>.+?)(?: \(line (?P<line>\d+)(?:, column \d+)?\))?: (?P<rest>.*)$", re.S)
_QUOTED_FILE = re.compile(r"^config file '(?P<file>[^']*)'")
_UNKNOWN_KEY = re.compile(r"unknown key '(?P<key>[^']+)'")
_LEADING_KEY = re.compile(r"^(?P<key>[A-Za-z_][\w-]*(?:\.[\w-]+)*) (?:=|expects|is given)")
_FIRST_SENTENCE = re.compile(r"^.*?[.?](?:\s|$)", re.S)


class ConfigError(ValueError):
    """Bad input: a config value, key or file, or a bad argument of a grainlab function.

    The same message as the command line gives. Attributes, parsed from it
    (None where the message names none):

    - ``file``: the config's file name (or ``<string>``, ``<dict>``)
    - ``line``: the line of the file (int)
    - ``key``: the dotted config key, e.g. ``"shear.final_strain"``
    - ``fix``: what to do, the message after its first sentence
    """

    file: Optional[str]
    line: Optional[int]
    key: Optional[str]
    fix: Optional[str]

    def __init__(self, message: str) -> None:
        super().__init__(message)
        self.message = message
        self.file, self.line, self.key, self.fix = None, None, None, None
        rest = message
        quoted = _QUOTED_FILE.match(message)
        where = None if quoted else _WHERE.match(message)
        if quoted:
            self.file = quoted.group("file")
        elif where and (where.group("line") or not (" " in where.group("file") or where.group("file")[0] == "-")):
            self.file = where.group("file")
            self.line = int(where.group("line")) if where.group("line") else None
            rest = where.group("rest")
        key = _UNKNOWN_KEY.search(rest) or _LEADING_KEY.match(rest)
        if key:
            self.key = key.group("key")
        first = _FIRST_SENTENCE.match(rest)
        if first and first.end() < len(rest):
            self.fix = rest[first.end():].strip()


# The command line's other input errors are the same kind of error.
InputError = ConfigError


class RunError(RuntimeError):
    """A run that failed while it ran (an instability, a file that could not be written).

    The message names what failed and, where one exists, the checkpoint to resume from.
    """
