"""Expected values of a problem file (`expected:`), read and checked into SI."""

from __future__ import annotations

import math
import re
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
    side: int | None = None  # the value's place in the answer, named by words ("at A")
    sign: int = 0  # +1 or -1 where words give the sign of a size ("down", "relieved")


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


def parse_expected(raw: Any, dimension: str | None, key: str, sides: tuple[str, ...] = (),
                   signs: tuple[tuple[str, int], ...] = ()) -> list[Expected]:
    """`expected.<name>`: one value or a non-empty list of them (roots in any order).

    ``sides`` and ``signs``: the answer's places (``A``, ``B``; ``outer``, ``inner``) and
    the words that sign a size (``up`` +1, ``down`` -1), so that a value may be written as
    books print it, a size with words: ``1.4 kN down at B``, ``2869 N inner``."""
    values = raw if isinstance(raw, list) else [raw]
    if not values:
        raise InputError("expected at least one value, got an empty list", key=key)
    out = [_parse_worded(v, dimension, key, sides, signs) if (sides or signs) else
           parse_value(v, dimension, key) for v in values]
    placed = [v.side for v in out if v.side is not None]
    if placed and len(placed) != len(out):
        raise InputError(f"name the place of every value ({', '.join(sides)}) or of none",
                         key=key)
    if len(set(placed)) != len(placed):
        twice = next(sides[p] for p in placed if placed.count(p) > 1)
        raise InputError(f"two values are both at {twice}", key=key)
    return out


def answer_signs(spec: Any, reported: Any) -> tuple[tuple[str, int], ...]:
    """The words that sign an answer's sizes in this problem: the solver's own for it
    where the kind's do not hold (a wheel drop's couple forces lie along the track, so
    ``up`` and ``pressed`` sign nothing), else the kind's (``spec.signs``)."""
    own = getattr(reported, "signs", None)
    return spec.signs if own is None else tuple((str(w), int(n)) for w, n in own)


# words that only join the others: "1.4 kN, outer rail pressed", "116.5 N upwards at A"
_FILLERS = frozenset(("a", "an", "at", "on", "of", "the", "is", "and", "bearing", "bearings",
                      "rail", "rails", "wheel", "wheels", "each", "side", "end", "force",
                      "reaction", "load", "axle", "pair"))
_TOKENS = re.compile(r"[^\s,;:()]+")


def _parse_worded(raw: Any, dimension: str | None, key: str, sides: tuple[str, ...],
                  signs: tuple[tuple[str, int], ...]) -> Expected:
    """A value with words around its number and unit: the quantity, its place among
    ``sides`` and the sign its words give. Plain values are read as before."""
    if not isinstance(raw, str) or dimension is None:
        return parse_value(raw, dimension, key)
    sign_of = dict(signs)
    place_words = {w for side in sides for w in _side_words(side)}

    def known(word: str) -> bool:
        return _word(word) in sign_of or _word(word) in _FILLERS or word in place_words or \
            (len(word) > 1 and word.lower() in place_words)

    tokens = _TOKENS.findall(raw)
    lead = 0
    while lead < len(tokens) and known(tokens[lead]):
        lead += 1
    end = len(tokens)
    while end > lead and known(tokens[end - 1]):
        end -= 1
    words = tokens[:lead] + tokens[end:]
    readable = [*(f"{s} (place)" for s in sides), *(f"{w} ({'+' if n > 0 else '-'})"
                                                   for w, n in signs)]
    if not words:
        try:
            return parse_value(raw, dimension, key)
        except InputError as err:
            raise InputError(f"{err.message}; a size may carry words this answer reads: "
                             f"{', '.join(readable)}", key=key) from None
    start = raw.index(tokens[lead]) if lead < len(tokens) else 0
    stop = raw.rindex(tokens[end - 1]) + len(tokens[end - 1]) if end > lead else start
    try:
        value = parse_value(raw[start:stop].strip(" ,;:"), dimension, key)
    except InputError as err:
        raise InputError(f"{raw!r}: not a quantity with words this answer reads: "
                         f"{', '.join(readable)} ({err.message})", key=key) from None
    side = _side_named(words, sides, raw, key)
    named = {sign_of[_word(w)] for w in words if _word(w) in sign_of}
    if len(named) > 1:
        raise InputError(f"{raw!r}: its words give both signs", key=key)
    sign = named.pop() if named else 0
    if sign and value.number < 0:
        raise InputError(f"{raw!r}: give a size with its word, or a signed value, not both",
                         key=key)
    si = float(value.si) * (sign or 1)
    return Expected(" ".join(raw.split()), si, value.number * (sign or 1), value.unit,
                    value.factor, side, sign)


def _word(token: str) -> str:
    return token.lower()


def _side_words(side: str) -> list[str]:
    """The words of a place's label: a one-letter label (A, B) is matched in capitals
    only, so that the article "a" is not a bearing."""
    return [w if len(w) == 1 else w.lower() for w in side.split()]


def _side_named(words: list[str], sides: tuple[str, ...], raw: str, key: str) -> int | None:
    """The index of the one place whose label's words are all among ``words``; None if
    the words name no place; InputError if they name a place only in part."""
    present = {w if len(w) == 1 else w.lower() for w in words}
    full = [i for i, side in enumerate(sides) if set(_side_words(side)) <= present]
    # "front outer" names front outer, not also "outer" where both are labels
    full = [i for i in full if not any(j != i and set(_side_words(sides[i])) <
                                       set(_side_words(sides[j])) for j in full)]
    if len(full) == 1:
        return full[0]
    partial = [s for s in sides if set(_side_words(s)) & present]
    if len(full) > 1 or partial:
        raise InputError(f"{raw!r}: its words name {' or '.join(partial or [sides[i] for i in full])}"
                         f"; say which one of {', '.join(sides)}", key=key)
    return None
