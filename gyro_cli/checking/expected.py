"""Expected values of a problem file (`expected:`), read and checked into SI."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from ..core import units
from ..core.errors import InputError, shown
from ..solving.problem import guarded as _guarded

# ---- expected values --------------------------------------------------------

@dataclass(frozen=True)
class Expected:
    """One expected value: as written, in SI, and the written number and unit."""

    text: str
    si: float | str  # a word for word answers
    number: float = 0.0
    unit: str = ""
    factor: float = 1.0  # SI per written unit (linear units only)


# (unit, dimension) -> (SI per unit, the unit as printed): pint asked once per unit
_UNITS: dict[tuple[str, str], tuple[float, str]] = {}


def parse_value(raw: Any, dimension: str | None, key: str) -> Expected:
    """One expected value in the answer's dimension; a word for word answers.

    The SI factor and printed form of each unit are cached, so checking many files asks
    pint once per unit, not once per value.
    """
    if dimension is None:
        if not isinstance(raw, str) or not raw.strip():
            raise InputError(f"expected a word, got {shown(raw)}", key=key)
        return Expected(str(raw).strip(), str(raw).strip())
    if isinstance(raw, (dict, list)):
        raise InputError(f"expected a quantity such as '45.1 rpm', got a "
                         f"{'mapping' if isinstance(raw, dict) else 'nested list'}", key=key)
    number, unit = _guarded(_split, raw, dimension, key)
    known = _UNITS.get((unit, dimension))
    if known is None:
        _guarded(units.parse, raw, dimension, key)  # every check, with the text as written
        factor, _ = _guarded(units.parse, f"1 {unit}" if unit else 1, dimension, key)
        known = factor, units.display(unit, dimension, key)
        if len(_UNITS) < 4096:
            _UNITS[(unit, dimension)] = known
    factor, printed = known
    si = number * factor
    if not math.isfinite(si):
        raise InputError(f"{shown(raw)} is not a finite number", key=key)
    text = " ".join(raw.split()) if isinstance(raw, str) else f"{raw:g}"
    return Expected(text, si, number, printed, factor)


def _split(text: Any, dimension: str, key: str) -> tuple[float, str]:
    return units._split(text, key, (dimension, False))


def parse_expected(raw: Any, dimension: str | None, key: str) -> list[Expected]:
    """`expected.<name>`: one value or a non-empty list of them (roots in any order)."""
    values = raw if isinstance(raw, list) else [raw]
    if not values:
        raise InputError("expected at least one value, got an empty list", key=key)
    return [parse_value(v, dimension, key) for v in values]
