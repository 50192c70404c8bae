"""Units at the edge: one pint registry, guarded parsing, SI floats out.

Every quantity in a problem file is parsed once, here, into a plain SI float.
The physics never sees pint. Parsing is guarded: the text must be a plain
number followed by a unit expression made of names, ``*``, ``/``, brackets and
small integer powers, so that pint is never asked to evaluate arithmetic such
as ``9**9**9**9`` and a megabyte string is refused before it is looked at.
"""

from __future__ import annotations

import math
import re
from typing import Any

from .errors import InputError

# Name -> (pint dimensionality, SI unit used inside gyro, words for messages).
DIMENSIONS: dict[str, tuple[str, str, str]] = {
    "length": ("[length]", "m", "a length like '150 mm'"),
    "mass": ("[mass]", "kg", "a mass like '2 kg'"),
    "force": ("[mass] * [length] / [time] ** 2", "N", "a force like '3 ozf' or '10 N'"),
    "acceleration": ("[length] / [time] ** 2", "m/s^2", "an acceleration like '9.81 m/s^2'"),
    "rate": ("1 / [time]", "rad/s", "an angular rate like '1800 rpm' or '5 rad/s'"),
    "angle": ("", "rad", "an angle like '30 deg' or '0.52 rad'"),
    "inertia": ("[mass] * [length] ** 2", "kg*m^2", "a moment of inertia like '0.01 kg m^2'"),
    "moment": ("[mass] * [length] ** 2 / [time] ** 2", "N*m", "a moment like '2 N m'"),
    "speed": ("[length] / [time]", "m/s", "a speed like '10 m/s'"),
    "time": ("[time]", "s", "a time like '2 s'"),
    "dimensionless": ("", "", "a plain number"),
    "stiffness": ("[mass] * [length] ** 2 / [time] ** 2", "N*m/rad",
                  "a torsional stiffness like '0.5 N m/rad'"),
    "damping": ("[mass] * [length] ** 2 / [time]", "N*m*s/rad",
                "a rotational damping like '0.002 N m s/rad'"),
    "angular_momentum": ("[mass] * [length] ** 2 / [time]", "kg*m^2/s",
                         "an angular momentum like '0.5 kg m^2/s'"),
    "time_per_angle": ("[time]", "s/rad", "a time per angle like '72 yr/deg'"),
}

# How SI units are written in worked answers.
SI_TEXT = {"kg*m^2": "kg m^2", "N*m": "N m", "N*m/rad": "N m/rad",
           "N*m*s/rad": "N m s/rad", "kg*m^2/s": "kg m^2/s"}

ANGLE_UNITS = {"degree", "radian", "arcminute", "arcsecond", "turn", "revolution", "gradian"}
US_MASS_OR_FORCE = {"pound", "ounce", "slug", "pound_force", "ounce_force", "ton", "short_ton",
                    "long_ton", "kip", "grain", "stone", "hundredweight", "short_hundredweight",
                    "long_hundredweight", "force_ounce", "force_pound", "force_ton", "dram"}

# In `weight`, textbooks write lb and oz for pound-force and ounce-force.
WEIGHT_WORDS = {"lb": "lbf", "lbs": "lbf", "pound": "pound_force", "pounds": "pound_force",
                "oz": "ozf", "ounce": "ounce_force", "ounces": "ounce_force"}

MAX_TEXT = 100  # characters in one quantity string

_NUMBER = re.compile(r"\s*([-+]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][-+]?\d{1,3})?)(.*)", re.S)
_NAME = r"[A-Za-z_°µΩ][A-Za-z_0-9°µΩ]*"
_UNIT_EXPR = re.compile(rf"(?:{_NAME}|\s+|[*/()]|(?:\*\*|\^)\s*[-+]?\d{{1,2}})*")
_NAME_RE = re.compile(_NAME)
_CHAINED_POWER = re.compile(r"(?:\*\*|\^)\s*[-+]?\d+\s*(?:\*\*|\^)")

_registry: Any = None
# (unit text, dimension) -> (pint units, SI per unit), for units already checked.
_CHECKED: dict[tuple[str, str], tuple[Any, float]] = {}
# (dimension, unit) -> unit per SI, for answers converted before.
_TO: dict[tuple[str, str], float] = {}


def registry() -> Any:
    """The program's one pint registry, created on first use with pint's cache."""
    global _registry
    if _registry is None:
        import pint

        ureg = pint.UnitRegistry(cache_folder=":auto:", on_redefinition="ignore")
        # A textbook's "Hz" on a rotor is revolutions per second, not 1/s.
        ureg.define("hertz = revolution / second = Hz")
        _registry = ureg
    return _registry


def si_unit(dimension: str) -> str:
    """The SI unit gyro computes in for a dimension name (pint syntax)."""
    return DIMENSIONS[dimension][1]


def si_text(dimension: str) -> str:
    """The SI unit as printed in a worked answer."""
    unit = si_unit(dimension)
    return SI_TEXT.get(unit, unit)


def _split(text: Any, key: str) -> tuple[float, str]:
    """Split a quantity into its number and its (checked) unit expression."""
    if isinstance(text, bool) or text is None:
        raise InputError(f"expected a quantity, got {text!r}", key=key)
    if isinstance(text, (int, float)):
        return float(text), ""
    if not isinstance(text, str):
        raise InputError(f"expected a quantity string such as '150 mm', got a {type(text).__name__}",
                         key=key)
    if len(text) > MAX_TEXT:
        raise InputError(f"quantity text is {len(text)} characters long; at most {MAX_TEXT} "
                         "are accepted", key=key)
    match = _NUMBER.fullmatch(text)
    if not match:
        raise InputError(f"expected a number and a unit such as '150 mm', got {text!r}", key=key)
    number, unit = match.group(1), match.group(2).strip()
    if not _UNIT_EXPR.fullmatch(unit) or _CHAINED_POWER.search(unit):
        raise InputError(f"{text!r} is not a number followed by a unit (only names, *, /, "
                         "brackets and small integer powers are allowed in a unit)", key=key)
    return float(number), unit


def _units(unit: str, key: str, text: Any) -> Any:
    import pint

    ureg = registry()
    try:
        return ureg.parse_units(unit.replace("^", "**")) if unit else ureg.dimensionless
    except pint.errors.UndefinedUnitError as err:
        raise InputError(f"unknown unit {str(err.unit_names)!r} in {text!r}", key=key) from None
    except (pint.errors.DefinitionSyntaxError, SyntaxError, TypeError, ValueError,
            AttributeError, KeyError):
        raise InputError(f"cannot read the unit in {text!r}", key=key) from None


def parse(text: Any, dimension: str, key: str, *, weight: bool = False) -> tuple[float, Any]:
    """Parse a quantity string into (SI float, pint quantity).

    ``dimension`` names an entry of DIMENSIONS. ``weight=True`` reads lb and oz
    as pound-force and ounce-force.
    """
    import math

    number, unit = _split(text, key)
    if not math.isfinite(number):
        raise InputError(f"{text!r} is not a finite number", key=key)
    if weight:
        unit = _NAME_RE.sub(lambda m: WEIGHT_WORDS.get(m.group(0), m.group(0)), unit)
    ureg = registry()
    checked = _CHECKED.get((unit, dimension))
    if checked is not None:  # this unit was parsed and checked for this dimension before
        units, factor = checked
        value = number * factor
        if not math.isfinite(value):
            raise InputError(f"{text!r} is out of range", key=key)
        return value, ureg.Quantity(number, units)
    units = _units(unit, key, text)
    quantity = ureg.Quantity(number, units)
    pint_dim, si, words = DIMENSIONS[dimension]
    if quantity.dimensionality != ureg.get_dimensionality(pint_dim or "[]"):
        got = str(quantity.dimensionality)
        if dimension != "angle" and set(units._units) & ANGLE_UNITS and got == "dimensionless":
            got = "angle"
        raise InputError(f"expected {words}, got {text!r} (dimension {got})", key=key)
    if dimension == "angle" and not (units._units and set(units._units) <= ANGLE_UNITS):
        raise InputError(f"an angle needs a unit, deg or rad: got {text!r}", key=key)
    value = quantity.to(si).magnitude if si else quantity.to("dimensionless").magnitude
    if not math.isfinite(value):
        raise InputError(f"{text!r} is out of range", key=key)
    # Cache the unit's SI factor where the unit is a plain multiple (no offset), so a
    # directory of problems asks pint once per unit, not once per value.
    factor = float(ureg.Quantity(1.0, units).to(si or "dimensionless").magnitude)
    if len(_CHECKED) < 4096 and math.isfinite(factor) and \
            math.isclose(ureg.Quantity(3.0, units).to(si or "dimensionless").magnitude,
                         3 * factor, rel_tol=1e-12):
        _CHECKED[(unit, dimension)] = (units, factor)
        value = number * factor  # the same arithmetic as every later, cached, parse
    return float(value), quantity


def check_unit(text: Any, dimension: str, key: str) -> str:
    """Check a unit an answer is asked in (``find: {precession: rpm}``)."""
    if not isinstance(text, str) or not text.strip():
        raise InputError(f"expected a unit for this answer such as '{si_text(dimension)}', "
                         f"got {text!r}", key=key)
    parse("1 " + text, dimension, key)
    return text.strip()


def convert(si_value: float, dimension: str, unit: str) -> float:
    """An SI value expressed in ``unit`` (already checked with check_unit)."""
    factor = _TO.get((dimension, unit))
    if factor is None:
        ureg = registry()
        si = si_unit(dimension) or "dimensionless"
        target = _units(unit, "", unit)
        factor = float(ureg.Quantity(1.0, si).to(target).magnitude)
        if not math.isclose(ureg.Quantity(3.0, si).to(target).magnitude, 3 * factor,
                            rel_tol=1e-12):  # an offset unit: let pint do it every time
            return ureg.Quantity(si_value, si).to(target).magnitude
        if len(_TO) < 4096:
            _TO[(dimension, unit)] = factor
    return si_value * factor


def is_us_customary(quantity: Any) -> bool:
    """True where a mass or weight was written in US customary units."""
    return bool(set(quantity.units._units) & US_MASS_OR_FORCE)


def unit_text(quantity: Any) -> str:
    """A parsed quantity's unit, abbreviated (``ozf``, ``ft / s ** 2``)."""
    return f"{quantity.units:~}".replace(" ** ", "^").replace("**", "^")
