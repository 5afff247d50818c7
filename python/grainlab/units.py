"""Units of the columns grainlab writes.

SI units throughout (docs/outputs.md): a column's name ends in its unit
(``_s``, ``_m``, ``_N``, ``_Pa``, ``_J``, ``_m3``, ``_m2``, ``_m_per_s``;
``_deg`` for degrees); a name without one is a fraction or a ratio
(dimensionless, "–" in the docs).
"""

from __future__ import annotations

# Longest suffix first: "_m_per_s" before "_s", "_m3" before "_m".
_SUFFIXES = [
    ("_m_per_s", "m/s"),
    ("_m3", "m^3"),
    ("_m2", "m^2"),
    ("_deg", "deg"),
    ("_Pa", "Pa"),
    ("_N", "N"),
    ("_J", "J"),
    ("_m", "m"),
    ("_s", "s"),
]

DIMENSIONLESS = "–"


def column_unit(name: str) -> str:
    """The unit of a column of series.csv (and of the other CSV files): ``"Pa"`` for
    ``normal_stress_Pa``, ``"–"`` (dimensionless) for ``shear_strain``."""
    for suffix, unit in _SUFFIXES:
        if name.endswith(suffix):
            return unit
    return DIMENSIONLESS
