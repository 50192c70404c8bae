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

from . import unit_cache
from .errors import InputError
from .record import record

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
    "angular_acceleration": ("1 / [time] ** 2", "rad/s^2", "an angular acceleration like "
                             "'0.01 rad/s^2'"),
    "angular_momentum": ("[mass] * [length] ** 2 / [time]", "kg*m^2/s",
                         "an angular momentum like '2 kg m^2/s'"),
    "speed": ("[length] / [time]", "m/s", "a speed like '10 m/s'"),
    "time": ("[time]", "s", "a time like '2 s'"),
    "dimensionless": ("", "", "a plain number"),
    "inverse_time": ("1 / [time]", "1/s", "an eigenvalue or growth rate like '-0.32 s^-1'"),
    "mass_length": ("[mass] * [length]", "kg*m", "a mass times a length like '2 kg m'"),
    "energy": ("[mass] * [length] ** 2 / [time] ** 2", "J", "an energy like '3 J'"),
    "stiffness": ("[mass] * [length] ** 2 / [time] ** 2", "N*m/rad",
                  "a torsional stiffness like '0.5 N m/rad'"),
    "damping": ("[mass] * [length] ** 2 / [time]", "N*m*s/rad",
                "a rotational damping like '0.002 N m s/rad'"),
    "time_per_angle": ("[time]", "s/rad", "a time per angle like '72 yr/deg'"),
}

# How SI units are written in worked answers.
SI_TEXT = {"kg*m^2": "kg m^2", "N*m": "N m", "kg*m^2/s": "kg m^2/s", "kg*m": "kg m",
           "N*m/rad": "N m/rad", "N*m*s/rad": "N m s/rad"}

ANGLE_UNITS = {"degree", "radian", "arcminute", "arcsecond", "turn", "revolution", "gradian",
               "grade"}
US_MASS_OR_FORCE = {"pound", "ounce", "slug", "pound_force", "ounce_force", "ton", "short_ton",
                    "long_ton", "kip", "grain", "stone", "hundredweight", "short_hundredweight",
                    "long_hundredweight", "force_ounce", "force_pound", "force_ton", "dram"}

# In `weight`, textbooks write lb and oz for pound-force and ounce-force.
WEIGHT_WORDS = {"lb": "lbf", "lbs": "lbf", "pound": "pound_force", "pounds": "pound_force",
                "oz": "ozf", "ounce": "ounce_force", "ounces": "ounce_force"}

MAX_TEXT = 100  # characters in one quantity string
MAX_DEPTH = 8   # brackets nested in one unit

# Regular expressions are compiled on first use (re keeps them): a compile at import is
# up to 0.2 ms of every run, used or not.
# A sign may be U+2212, the minus sign gyro's pages and handouts print (copied from them).
MANTISSA = r"[-+\u2212]?(?:\d+(?:\.\d*)?|\.\d+)"
NUMBER = MANTISSA + r"(?:[eE][-+\u2212]?\d{1,3})?"  # a quantity's number (a sheet's too)
_NUMBER = rf"(?s)\s*({NUMBER})(.*)"
_NAME_START = frozenset("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz_°µΩ")
_NAME_CHARS = _NAME_START | frozenset("0123456789")

# Names as textbooks write them -> (pint expression, how gyro prints it). The pint
# expressions are gyro's own; a user's text never reaches pint's expression parser.
ALIASES: dict[str, tuple[str, str]] = {
    "RPM": ("revolution / minute", "rpm"), "Rpm": ("revolution / minute", "rpm"),
    "rpm": ("revolution / minute", "rpm"), "RPS": ("revolution / second", "rps"),
    "rps": ("revolution / second", "rps"),
    "rev": ("revolution", "rev"), "revs": ("revolution", "rev"), "r": ("revolution", "rev"),
    "kmph": ("kilometer / hour", "km/h"), "kph": ("kilometer / hour", "km/h"),
    "kmh": ("kilometer / hour", "km/h"), "KPH": ("kilometer / hour", "km/h"),
    "KMPH": ("kilometer / hour", "km/h"), "MPH": ("mile / hour", "mph"),
    "kn": ("knot", "knot"), "kt": ("knot", "knot"), "kts": ("knot", "knot"),
    "Nm": ("newton * meter", "N m"), "kNm": ("kilonewton * meter", "kN m"),
    "t": ("metric_ton", "t"), "tonne": ("metric_ton", "t"), "tonnes": ("metric_ton", "t"),
    # pint's cps is counts per second (1/s); on a rotor it is cycles (revolutions) per
    # second, as Hz is: read with 2 pi, never silently as 1 rad/s.
    "cps": ("revolution / second", "cps"), "CPS": ("revolution / second", "cps"),
    # capitals as a caps-lock or a sentence's start writes them, where no other unit is meant
    "Deg": ("degree", "deg"), "DEG": ("degree", "deg"), "hz": ("hertz", "Hz"),
    "HZ": ("hertz", "Hz"),
}
# Whole units as books print them, with the dots of an abbreviation (the tokenizer would
# read "r.p.m." as r * p * m) or a letter that alone means something else (pint's c is
# the speed of light): the unit text is replaced by gyro's own spelling before reading.
WHOLE_UNITS: dict[str, str] = {
    "r.p.m.": "rpm", "r.p.m": "rpm", "R.P.M.": "rpm", "R.P.M": "rpm",
    "r.p.s.": "rps", "r.p.s": "rps", "R.P.S.": "rps", "R.P.S": "rps",
    "c/s": "cps", "c.p.s.": "cps", "c.p.s": "cps", "%": "percent",
}
# Names refused with the readings they could have had: no wrong number is printed.
REFUSED_NAMES: dict[str, str] = {
    name: "a ton is ambiguous: a short ton (2000 lb = 907.2 kg), a long ton (2240 lb = "
          "1016 kg) or a metric tonne (1000 kg); write short_ton, long_ton or t"
    for name in ("ton", "tons", "Ton", "Tons", "TON")}
# On an angular rate, a bare inverse minute or hour is a rotational frequency (ISO 80000-3:
# n = 1450 min^-1 on a motor's plate is 1450 rev/min); pint would read it as rad/min.
ISO_ROTATION_TIMES = {"minute": "rev/min", "hour": "rev/h"}
# Units whose name already holds a quotient (rpm, mph): a prefix glued to one is refused.
COMPOUND_UNITS = {"revolutions_per_minute", "revolutions_per_second", "mile_per_hour",
                  "kilometer_per_hour", "knot", "number_meter", "foot_per_second",
                  "inch_per_second", "meter_per_second"}
# What a "did you mean" chooses from, beside the aliases.
COMMON_UNITS = ("rad", "deg", "degree", "radian", "s", "sec", "second", "min", "minute", "h",
                "hr", "hour", "Hz", "m", "mm", "cm", "km", "in", "inch", "ft", "foot", "feet",
                "yd", "mile", "kg", "g", "gram", "lb", "lbf", "oz", "ozf", "slug", "N", "kN",
                "kgf", "mph", "knot", "turn", "revolution", "percent")


_registry: Any = None
# (unit text, dimension, weight) -> (SI per unit, printed unit, US customary), checked.
_CHECKED: dict[tuple[str, str, bool], tuple[float, str, bool]] = {}
# (dimension, unit) -> unit per SI, for answers converted before.
_TO: dict[tuple[str, str], float] = {}


def registry() -> Any:
    """The program's one pint registry, created on first use with pint's disk cache.

    pint's cache lives in gyro's cache folder (unit_cache.pint_folder). When it
    cannot be used (no cache, a read-only or missing HOME, a FIFO there) pint
    runs without one; when pint fails on it (a truncated pickle, another gyro
    writing it at the same moment) its files are removed, to be rebuilt by a
    later run, and this run goes on without a cache. A cache never fails a run.
    """
    global _registry
    if _registry is None:
        import pint

        def make(folder: str | None) -> Any:
            ureg: pint.UnitRegistry = pint.UnitRegistry(cache_folder=folder,
                                                        on_redefinition="ignore")
            # A textbook's "Hz" on a rotor is revolutions per second, not 1/s.
            ureg.define("hertz = revolution / second = Hz")
            return ureg

        folder = unit_cache.pint_folder()
        try:
            _registry = make(folder)
        except Exception:  # noqa: BLE001 - any failure of a cache: work without it
            if folder is None:
                raise
            unit_cache.clear_pint_folder(folder)
            _registry = make(None)
    return _registry


def unit_names(units: Any) -> set[str]:
    """The names of the units in a pint Unit (public API: Quantity.unit_items)."""
    return {name for name, _ in registry().Quantity(1, units).unit_items()}


def si_unit(dimension: str) -> str:
    """The SI unit gyro computes in for a dimension name (pint syntax)."""
    return DIMENSIONS[dimension][1]


def si_text(dimension: str) -> str:
    """The SI unit as printed in a worked answer."""
    unit = si_unit(dimension)
    return SI_TEXT.get(unit, unit)



def _fail(message: str, key: str) -> InputError:
    return InputError(message, key=key)


def tokenize(unit: str, text: Any = None, key: str = "") -> list[tuple[str, Any]]:
    """Split a unit expression into tokens in one pass (linear in its length).

    Tokens: ("name", word), ("mul", None) for ``*``, ``-`` or ``.`` between
    names and for a space between two operands, ("div", None), ("pow", int)
    for ``^n`` or ``**n``, ("(", None) and (")", None). Raises InputError with
    one line for anything else: a stray character, unbalanced or empty brackets,
    a trailing or doubled operator, a power without a base or chained powers.
    The unknown names are not looked at here (see ``_resolve_name``).
    """
    shown = text if text is not None else unit
    tokens: list[tuple[str, Any]] = []
    i, n, depth = 0, len(unit), 0

    def operand_before() -> bool:
        return bool(tokens) and tokens[-1][0] in ("name", ")", "pow")

    while i < n:
        ch = unit[i]
        if ch in _NAME_START:
            j = i + 1
            while j < n and unit[j] in _NAME_CHARS:
                j += 1
            if operand_before():
                tokens.append(("mul", None))  # a space (or nothing, after a bracket) multiplies
            tokens.append(("name", unit[i:j]))
            i = j
            continue
        if ch.isspace():
            i += 1
            continue
        if ch == "1" and not operand_before() and unit[i + 1:].lstrip().startswith("/"):
            tokens.append(("name", "1"))  # 1/s
            i += 1
            continue
        if ch == "^" or unit.startswith("**", i):
            i += 1 if ch == "^" else 2
            while i < n and unit[i].isspace():
                i += 1
            j = i + (1 if i < n and unit[i] in "+-" else 0)
            k = j
            while k < n and unit[k].isdigit():
                k += 1
            if k == j:
                raise _fail(f"a power in the unit of {shown!r} needs a whole number after it "
                            "(m^2, s**-1)", key)
            if k - j > 2:
                raise _fail(f"the power {unit[i:k]} in the unit of {shown!r} is too large", key)
            if not tokens or tokens[-1][0] not in ("name", ")"):
                what = "another power (chained powers are refused)" \
                    if tokens and tokens[-1][0] == "pow" else "nothing"
                raise _fail(f"a power in the unit of {shown!r} must follow a unit name or a "
                            f"bracket, not {what}", key)
            tokens.append(("pow", int(unit[i:k])))
            i = k
            continue
        if ch in "*/-.":
            if not operand_before():
                raise _fail(f"{ch!r} in the unit of {shown!r} has no unit before it", key)
            tokens.append(("div" if ch == "/" else "mul", None))
            i += 1
            continue
        if ch == "(":
            depth += 1
            if depth > MAX_DEPTH:
                raise _fail(f"brackets nested more than {MAX_DEPTH} deep in the unit of "
                            f"{shown!r}", key)
            if operand_before():
                tokens.append(("mul", None))
            tokens.append(("(", None))
            i += 1
            continue
        if ch == ")":
            if depth == 0:
                raise _fail(f"unbalanced brackets in the unit of {shown!r}: a ')' closes "
                            "nothing", key)
            if tokens and tokens[-1][0] == "(":
                raise _fail(f"empty brackets '()' in the unit of {shown!r}", key)
            if tokens and tokens[-1][0] in ("mul", "div"):
                raise _fail(f"the unit of {shown!r} has an operator with no unit after it "
                            "before ')'", key)
            depth -= 1
            tokens.append((")", None))
            i += 1
            continue
        raise _fail(f"unexpected {ch!r} in the unit of {shown!r}: a unit is names joined by "
                    "spaces, *, / and ^ powers (a comment needs '#')", key)
    if depth:
        raise _fail(f"unbalanced brackets in the unit of {shown!r}: {depth} '(' not closed", key)
    if tokens and tokens[-1][0] in ("mul", "div"):
        raise _fail(f"the unit of {shown!r} ends with an operator: a unit name must follow it",
                    key)
    for (a, _), (b, _) in zip(tokens, tokens[1:]):
        if a in ("mul", "div") and b in ("mul", "div"):
            raise _fail(f"two operators in a row in the unit of {shown!r}", key)
    return tokens


def _names(unit: str) -> list[str]:
    """The words of a unit text, in order, in one pass (no checking)."""
    words: list[str] = []
    word: list[str] = []
    for ch in unit:
        if ch in _NAME_CHARS and (word or ch in _NAME_START):
            word.append(ch)
        elif word:
            words.append("".join(word))
            word = []
    if word:
        words.append("".join(word))
    return words


# SI's own ways of writing a unit (N·m, kg·m², s⁻¹) and the degree signs of other
# keyboards (º, ˚), as the tokenizer reads them: a product as a space, a power as ^n.
_DOTS = str.maketrans({"\u00b7": " ", "\u22c5": " ", "\u2022": " ", "\u00ba": "\u00b0",
                       "\u02da": "\u00b0"})
SUPERSCRIPT = "\u207b\u207a\u2070\u00b9\u00b2\u00b3\u2074\u2075\u2076\u2077\u2078\u2079"
SUPERSCRIPTS = str.maketrans(SUPERSCRIPT, "-+0123456789")  # ⁻¹² as -12


def _plain_unit(unit: str) -> str:
    """``N·m`` as ``N m``, ``kg·m²`` as ``kg m^2``, ``s⁻¹`` as ``s^-1``, ``19.47º``'s unit
    as ``°``; any other text as it is."""
    import re

    unit = unit.translate(_DOTS)
    return re.sub("[\u207b\u207a]?[\u2070\u00b9\u00b2\u00b3\u2074-\u2079]+",
                  lambda m: "^" + m.group().translate(SUPERSCRIPTS), unit)


def _split(text: Any, key: str, known: tuple[str, bool] | None = None) -> tuple[float, str]:
    """Split a quantity into its number and its (checked) unit expression.

    ``known``: (dimension, weight) of a parse; a unit the disk table holds for them
    passed these checks in an earlier run, so its names need no pint now."""
    if isinstance(text, str):  # the usual case first (text is never a bool, None or number)
        if len(text) > MAX_TEXT:
            raise InputError(f"quantity text is {len(text)} characters long; at most {MAX_TEXT} "
                             "are accepted", key=key)
        match = re.fullmatch(_NUMBER, text)
        if not match:
            raise InputError(f"expected a number and a unit such as '150 mm', got {text!r}",
                             key=key)
        number, unit = match.groups()
        number = number.replace("\u2212", "-")
        unit = unit.strip()
        if not unit.isascii():
            unit = _plain_unit(unit)
        unit = WHOLE_UNITS.get(unit, unit)
        if unit in _VALID:
            return float(number), unit
        if known and unit_cache.get("parse", unit, known[0], int(known[1])):
            if len(_VALID) < 4096:  # these checks passed for it: met again, no disk look-up
                _VALID.add(unit)
            return float(number), unit
        words = _names(unit)
        if len(words) >= 3 or (words and any(ch in unit for ch in ",;:!?")):
            # Prose after the number ("1800 rpm relative to the frame"): name the first word
            # that is no unit, before any complaint about the punctuation around it.
            for word in words:
                if _lookup(word, None) is None:
                    raise InputError(f"unknown unit {word!r} in {text!r}; a comment needs '#'",
                                     key=key)
        tokenize(unit, text, key)
        if len(_VALID) < 4096:
            _VALID.add(unit)
        return float(number), unit
    if isinstance(text, bool) or text is None:
        raise InputError(f"expected a quantity, got {text!r}", key=key)
    if isinstance(text, (int, float)):
        return float(text), ""
    raise InputError(f"expected a quantity string such as '150 mm', got a {type(text).__name__}",
                     key=key)


# Unit texts that passed the checks of _split (their names may still be unknown).
_VALID: set[str] = set()
# (unit, dimension) -> the unit as gyro prints it.
_SHOWN: dict[tuple[str, str], str] = {}
# (name, weight reading) -> (pint units, printed name) or None when unknown.
_NAMES: dict[tuple[str, bool], Any] = {}


def _lookup(name: str, weight: bool | None) -> tuple[Any, str] | None:
    """A unit name as pint units and as printed; None if unknown. Refuses glued prefixes."""
    weight = bool(weight)
    cache_key = (name, weight)
    if cache_key in _NAMES:
        return _NAMES[cache_key]
    ureg = registry()
    found: tuple[Any, str] | None
    if name == "1":
        found = (ureg.dimensionless, "1")
    elif name in REFUSED_NAMES:
        found = ("refused", REFUSED_NAMES[name])
    elif weight and name in WEIGHT_WORDS:
        target = WEIGHT_WORDS[name]
        found = (ureg.parse_units(target), "lbf" if target in ("lbf", "pound_force") else "ozf")
    elif name in ALIASES:
        target, shown = ALIASES[name]
        found = (ureg.parse_units(target), shown)
    else:
        import pint

        try:
            candidates = ureg.parse_unit_name(name)
        except (pint.errors.PintError, ValueError, KeyError, AttributeError):
            candidates = ()
        power = re.fullmatch(_POWER_SUFFIX, name)
        base = _lookup(power.group(1), weight) if power and not candidates else None
        if base is not None:
            # kg.m2, kg m2: a power written without its ^ (books print m2 for m^2)
            assert power is not None, "a base is looked up for a power suffix only"
            found = base if base[0] == "refused" else \
                (base[0] ** int(power.group(2)), f"{base[1]}^{power.group(2)}")
        elif not candidates and name not in ("°",):
            found = None
        elif candidates and all(prefix for prefix, _, _ in candidates) and \
                any(unit in COMPOUND_UNITS for _, unit, _ in candidates):
            prefix, unit, _ = candidates[0]
            found = ("refused", f"{name!r} would be read as {prefix}-{unit.replace('_', ' ')}, "
                                "which no textbook means; write the unit out (rpm, km/h)")
        else:
            try:
                found = (ureg.parse_units(name), name)
            except (pint.errors.PintError, ValueError, KeyError, AttributeError, SyntaxError):
                found = None
    if len(_NAMES) < 4096:
        _NAMES[cache_key] = found
    return found


_POWER_SUFFIX = r"([A-Za-z_]*[A-Za-z_])([2-4])"


def _did_you_mean(name: str) -> str:
    import difflib

    options = list(ALIASES) + list(COMMON_UNITS)
    lower = {o.lower(): o for o in options}
    if name.lower() in lower:
        return f"; did you mean {lower[name.lower()]!r}?"
    for option in sorted(options, key=lambda o: o != o.lower()):  # swapped: rmp -> rpm
        if len(name) > 2 and sorted(option.lower()) == sorted(name.lower()):
            return f"; did you mean {option!r}?"
    close = difflib.get_close_matches(name, options, n=1, cutoff=0.6)
    return f"; did you mean {close[0]!r}?" if close else ""


def _resolve(unit: str, key: str, text: Any, weight: bool = False) -> tuple[Any, str]:
    """A checked unit text as (pint units, the unit as gyro prints it).

    A small recursive-descent reading of the tokens: products and quotients
    left to right, powers binding tightest, brackets at most MAX_DEPTH deep.
    """
    ureg = registry()
    if not unit:
        return ureg.dimensionless, ""
    unit = WHOLE_UNITS.get(unit, unit)
    tokens = tokenize(unit, text, key)
    single = len(tokens) == 1
    pos = 0

    def atom() -> tuple[Any, str]:
        nonlocal pos
        kind, value = tokens[pos]
        pos += 1
        if kind == "(":
            units, shown = expr()
            pos += 1  # the ')' (tokenize checked the brackets balance)
            return units, f"({shown})"
        found = _lookup(value, weight)
        if found is None:
            raise InputError(f"unknown unit {value!r} in {text!r}{_did_you_mean(value)}",
                             key=key)
        if found[0] == "refused":
            what = "ambiguous" if value in REFUSED_NAMES else "unknown"
            raise InputError(f"{what} unit {value!r} in {text!r}: {found[1]}", key=key)
        units, shown = found
        if not single and "/" in shown:  # km/h inside a product prints as kph
            shown = f"({shown})"
        return units, shown

    def power() -> tuple[Any, str]:
        nonlocal pos
        units, shown = atom()
        if pos < len(tokens) and tokens[pos][0] == "pow":
            exponent = tokens[pos][1]
            pos += 1
            units, shown = units ** exponent, f"{shown}^{exponent}"
        return units, shown

    def expr() -> tuple[Any, str]:
        nonlocal pos
        units, shown = power()
        while pos < len(tokens) and tokens[pos][0] in ("mul", "div"):
            op = tokens[pos][0]
            pos += 1
            right, right_shown = power()
            if op == "mul":
                units, shown = units * right, f"{shown} {right_shown}"
            else:
                units, shown = units / right, f"{shown}/{right_shown}"
        return units, shown

    return expr()


def _units(unit: str, key: str, text: Any) -> Any:
    return _resolve(unit, key, text)[0]


def _reading(unit: str, dimension: str, key: str, text: Any,
             weight: bool = False) -> tuple[Any, str]:
    """The pint units of ``unit`` for ``dimension``, with its printed form.

    Where a force or a moment is asked for, lb and oz written for the force
    (``20 lb``, ``50 lb ft``, ``oz in``) are read as lbf and ozf when the mass
    reading has the wrong dimension: the only reading that fits, never a
    silent change of meaning.
    """
    ureg = registry()
    units, shown = _resolve(unit, key, text, weight)
    pint_dim = DIMENSIONS[dimension][0]
    items = list(ureg.Quantity(1, units).unit_items())
    if dimension == "rate" and len(items) == 1:
        (name, exponent), = items
        if exponent == -1 and name in ISO_ROTATION_TIMES:  # min^-1 on a rate: rev/min
            return units * ureg.revolution, ISO_ROTATION_TIMES[name]
    if not weight and dimension in ("force", "moment") and \
            units.dimensionality != ureg.get_dimensionality(pint_dim) and \
            set(_names(unit)) & set(WEIGHT_WORDS):
        as_force, shown_force = _resolve(unit, key, text, True)
        if as_force.dimensionality == ureg.get_dimensionality(pint_dim):
            return as_force, shown_force
    return units, shown


def display(unit: str, dimension: str, key: str = "") -> str:
    """How gyro prints a (checked) unit: ``N*m`` -> ``N m``, ``lb-ft`` -> ``lbf ft``."""
    if not unit:
        return unit
    shown = _SHOWN.get((unit, dimension))
    if shown is None:
        shown = unit_cache.get("shown", unit, dimension)
        if shown is None:
            shown = _reading(unit, dimension, key, unit)[1]
            unit_cache.put("shown", shown, unit, dimension)
        if len(_SHOWN) < 4096:
            _SHOWN[(unit, dimension)] = shown
    return shown


@record(frozen=True)
class Parsed:
    """A quantity as written: its number, its unit as gyro prints it, and whether
    that unit is US customary (for the default g)."""

    magnitude: float
    unit_text: str
    us_customary: bool


def parse(text: Any, dimension: str, key: str, *, weight: bool = False) -> tuple[float, Parsed]:
    """Parse a quantity string into (SI float, Parsed).

    ``dimension`` names an entry of DIMENSIONS. ``weight=True`` reads lb and oz
    as pound-force and ounce-force (as does any force or moment where the mass
    reading would have the wrong dimension). A unit met before, in this process
    or (through unit_cache) an earlier one, is not asked of pint again.
    """
    if text.__class__ is str:
        known = _PARSED.get((text, dimension, weight))
        if known is not None and _CHECKED.get(known[0]) is known[1]:
            return known[2]
    number, unit = _split(text, key, (dimension, weight))
    if not math.isfinite(number):
        raise InputError(f"{text!r} is not a finite number", key=key)
    reading = (unit, dimension, weight)
    checked = _CHECKED.get(reading)
    if checked is None:
        stored = unit_cache.get("parse", unit, dimension, int(weight))
        if stored is not None:
            checked = _CHECKED[reading] = tuple(stored)
    if checked is not None:  # this unit was parsed and checked for this dimension before
        factor, shown, us = checked
        value = number * factor
        if not math.isfinite(value):
            raise InputError(f"{text!r} is out of range", key=key)
        parsed = value, Parsed(number, shown, us)
        if text.__class__ is str:
            if len(_PARSED) >= _PARSED_MAX:  # emptied, not frozen: a kind's defaults and
                _PARSED.clear()              # the texts a bank repeats come back at once
            _PARSED[(text, dimension, weight)] = (reading, checked, parsed)
        return parsed
    return _parse_with_pint(text, number, unit, dimension, key, weight)


# (text, dimension, weight) -> (its _CHECKED key, that entry, what parse returned): a bank
# writes the same quantities ("9.81 m/s^2", "2 kg", a kind's defaults) in file after file,
# and each is read once. An entry counts only while _CHECKED holds the very entry it was
# computed from (a table replaced or cleared drops it), and the text's checks (_split) and
# arithmetic depend on nothing else, so it is the answer parse would compute again.
_PARSED: dict[tuple[str, str, bool], tuple[tuple[str, str, bool], tuple[float, str, bool],
                                            tuple[float, Parsed]]] = {}
_PARSED_MAX = 1024  # entries (about 0.45 MB at most)


def _parse_with_pint(text: Any, number: float, unit: str, dimension: str, key: str,
                     weight: bool) -> tuple[float, Parsed]:
    ureg = registry()
    units, _ = _reading(unit, dimension, key, text, weight)
    quantity = ureg.Quantity(number, units)
    pint_dim, si, words = DIMENSIONS[dimension]
    if quantity.dimensionality != ureg.get_dimensionality(pint_dim or "[]"):
        got = str(quantity.dimensionality)
        if dimension != "angle" and _angles(units) and got == "dimensionless":
            got = "angle"
        raise InputError(f"expected {words}, got {text!r} (dimension {got})", key=key)
    if dimension == "angle" and not (unit_names(units) and _angles(units) == unit_names(units)):
        raise InputError(f"an angle needs a unit, deg or rad: got {text!r}", key=key)
    if dimension == "dimensionless" and _angles(units):
        # pint counts an angle as a plain number: `gear_ratio: 5 deg` would be 0.0873
        would = quantity.to("dimensionless").magnitude
        raise InputError(f"expected a plain number (a ratio or a count), got {text!r}: its "
                         f"unit holds an angle ({', '.join(sorted(_angles(units)))}), which "
                         f"would be read as {would:.4g}; write the number alone", key=key)
    if dimension == "time_per_angle" and not _angles(units):
        # pint counts angles as plain numbers: `yr` alone would silently mean years per radian
        raise InputError(f"a time per angle needs an angle in its unit, such as 'yr/deg': got "
                         f"{text!r}", key=key)
    value = quantity.to(si).magnitude if si else quantity.to("dimensionless").magnitude
    if not math.isfinite(value):
        raise InputError(f"{text!r} is out of range", key=key)
    parsed = Parsed(number, f"{units:~}".replace(" ** ", "^").replace("**", "^"),
                    bool(unit_names(units) & US_MASS_OR_FORCE))
    # Cache the unit's SI factor where the unit is a plain multiple (no offset), so a
    # directory of problems asks pint once per unit, not once per value.
    factor = float(ureg.Quantity(1.0, units).to(si or "dimensionless").magnitude)
    if len(_CHECKED) < 4096 and math.isfinite(factor) and factor != 0 and \
            math.isclose(ureg.Quantity(3.0, units).to(si or "dimensionless").magnitude,
                         3 * factor, rel_tol=1e-12):
        _CHECKED[(unit, dimension, weight)] = (factor, parsed.unit_text, parsed.us_customary)
        unit_cache.put("parse", [factor, parsed.unit_text, parsed.us_customary],
                       unit, dimension, int(weight))
        value = number * factor  # the same arithmetic as every later, cached, parse
    return float(value), parsed


def _angles(units: Any) -> set[str]:
    """The names in ``units`` that are angles, prefixed or not (mrad, mdeg, grad)."""
    ureg = registry()
    found = set()
    for name in unit_names(units):
        if name in ANGLE_UNITS:
            found.add(name)
            continue
        try:
            bases = {base for _, base, _ in ureg.parse_unit_name(name)}
        except Exception:  # noqa: BLE001 - pint's own name lookup; no angle then
            bases = set()
        if bases & ANGLE_UNITS:
            found.add(name)
    return found


def check_unit(text: Any, dimension: str, key: str) -> str:
    """Check a unit an answer is asked in (``find: {precession: rpm}``).

    Returns the unit as gyro prints it (``N*m`` -> ``N m``, ``lb ft`` -> ``lbf ft``),
    which ``convert`` reads back to the same units.
    """
    if not isinstance(text, str) or not text.strip():
        raise InputError(f"expected a unit for this answer such as '{si_text(dimension)}', "
                         f"got {text!r}", key=key)
    value = re.fullmatch(_NUMBER, text)
    if value and not value.group(2).lstrip().startswith("/"):  # 1/s is a unit
        raise InputError(f"expected a unit for this answer such as '{si_text(dimension)}', not "
                         f"a value: got {text!r} (an expected value goes under `expected`)",
                         key=key)
    parse("1 " + text, dimension, key)
    return display(text.strip(), dimension, key)


def convert(si_value: float, dimension: str, unit: str) -> float:
    """An SI value expressed in ``unit`` (already checked with check_unit)."""
    factor = _TO.get((dimension, unit)) or unit_cache.get("to", dimension, unit)
    if factor is None:
        ureg = registry()
        si = si_unit(dimension) or "dimensionless"
        target = _reading(unit, dimension, "", unit)[0] if unit else ureg.dimensionless
        factor = float(ureg.Quantity(1.0, si).to(target).magnitude)
        if not math.isclose(ureg.Quantity(3.0, si).to(target).magnitude, 3 * factor,
                            rel_tol=1e-12):  # an offset unit: let pint do it every time
            return ureg.Quantity(si_value, si).to(target).magnitude
        unit_cache.put("to", factor, dimension, unit)
    if len(_TO) < 4096:
        _TO[(dimension, unit)] = factor
    return si_value * factor


def is_us_customary(quantity: Parsed) -> bool:
    """True where a mass or weight was written in US customary units."""
    return quantity.us_customary


#: a unit written as plain names, powers, products and quotients (``rpm``, ``m/s^2``,
#: ``kg m^2``), which the write-ups set as a unit; anything else stays the words written
_PLAIN_UNIT = r"[A-Za-z]+(\^-?\d+)?([ */]+[A-Za-z]+(\^-?\d+)?)*"


def written(text: str) -> tuple[str, str] | None:
    """A quantity string as written: its number and its unit (``"1800 rpm"`` ->
    ``("1800", "rpm")``), or None where the unit is not plain names (``r.p.m.``)."""
    match = re.fullmatch(_NUMBER, text)
    if match is None:
        return None
    number, unit = match.group(1), " ".join(match.group(2).split())
    # one name (rpm, oz, deg) needs no pattern: compiling it is a tenth of a millisecond
    if unit and not (unit.isascii() and unit.isalpha()) and not re.fullmatch(_PLAIN_UNIT, unit):
        return None
    return number, unit


def unit_text(quantity: Parsed) -> str:
    """A parsed quantity's unit, abbreviated (``ozf``, ``ft/s^2``)."""
    return quantity.unit_text
