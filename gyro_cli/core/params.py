"""The declarations a kind makes of its keys and answers (no imports: the
body, the loader and the kinds all use them)."""

from __future__ import annotations

import math
import operator
import re
from typing import TYPE_CHECKING

from .record import record

if TYPE_CHECKING:
    from .expr import Expr

BOUNDS = ("[]", "[)", "(]", "()")


@record(frozen=True)
class Param:
    """A key of `given`: its dimension (a name in units.DIMENSIONS), symbol and meaning,
    and the values it may take.

    The constraints are on the value in SI (an angle in rad) and the loader enforces
    them, one message style for all (``expected 0 deg <= obliquity < 90 deg, got '95 deg'``):
    ``positive`` (> 0), ``nonnegative`` (>= 0), ``nonzero`` (!= 0), ``whole`` (a whole
    number: a count), ``range=(lo, hi)`` with ``bounds`` saying which ends are included ("[]", "[)", "(]", "()"; an end may be
    +-inf, and is then no limit), ``limits`` how to say range's ends where the number
    alone would not ("2/3"), ``reason`` why, added to the refusal. A check that needs two
    keys or the physics (J <= 2 I_G, a spin too low) stays in the kind.
    """

    name: str
    dimension: str
    symbol: str
    doc: str
    default: str | None = None  # a quantity string used when the key is absent
    choices: tuple[str, ...] = ()  # for word-valued keys (dimension "word")
    words: tuple[tuple[str, str], ...] = ()  # other spellings of a choice: (spelling, choice)
    positive: bool = False
    nonnegative: bool = False
    nonzero: bool = False
    whole: bool = False  # a whole number (a count of engines)
    range: tuple[float, float] | None = None  # SI
    bounds: str = "[]"
    limits: tuple[str, str] | None = None
    reason: str = ""
    symbol_tree: Expr | None = None  # a symbol that is not one name, as a tree
    hemisphere: str = ""  # "NS" (a latitude) or "EW" (a longitude): "30 S" is -30 deg
    #: the kind cannot solve without this key: True refuses its absence with the message
    #: every missing key gets; a string is the refusal's own words
    required: bool | str = False

    def __post_init__(self) -> None:
        if self.required and self.default is not None:
            raise ValueError(f"{self.name}: a required key has no default")
        if self.bounds not in BOUNDS:
            raise ValueError(f"{self.name}: bounds is one of {BOUNDS}, not {self.bounds!r}")
        if self.range is not None and not self.range[0] < self.range[1]:
            raise ValueError(f"{self.name}: range {self.range} is empty")

    def limits_declared(self) -> tuple[tuple[str, float], ...]:
        """Each declared limit as (operator, SI value): (">", 0.0), ("<", pi / 2), ("!=", 0.0);
        a whole number as ("whole", 1.0), a multiple of 1."""
        out: list[tuple[str, float]] = []
        if self.positive:
            out.append((">", 0.0))
        if self.nonnegative:
            out.append((">=", 0.0))
        if self.range is not None:
            lo, hi = self.range
            if math.isfinite(lo):
                out.append((">" if self.bounds[0] == "(" else ">=", lo))
            if math.isfinite(hi):
                out.append(("<" if self.bounds[1] == ")" else "<=", hi))
        if self.nonzero:
            out.append(("!=", 0.0))
        if self.whole:
            out.append(("whole", 1.0))
        return tuple(out)

    def limits_broken(self, value: float) -> tuple[tuple[str, float], ...]:
        """The declared limits ``value`` (SI) does not keep; () if it keeps them all."""
        return tuple((op, x) for op, x in self.limits_declared() if not _OPS[op](value, x))

    def limit_text(self, x: float, unit: str = "") -> str:
        """A limit as a message says it: an angle in deg, else in ``unit`` (the SI unit);
        the declared ``limits`` for the ends of ``range``."""
        if self.limits and self.range is not None and x in self.range:
            return self.limits[self.range.index(x)]
        if self.dimension == "angle":
            return f"{math.degrees(x):.6g} deg"
        return f"{x:.6g}" + (f" {unit}" if unit else "")

    def expectation(self, unit: str = "") -> str:
        """The declared limits as one condition on the key: ``0 deg <= obliquity < 90 deg``,
        ``turn_radius > 0 m``, ``engines >= 0, a whole number``; "" if none is declared."""
        def said(op: str, x: float) -> str:
            return f"{self.name} {op} {self.limit_text(x, unit)}"

        parts = [said(op, 0.0) for op, on in ((">", self.positive), (">=", self.nonnegative))
                 if on]
        if self.range is not None:
            (lo, hi), (lo_op, hi_op) = self.range, (_FLIP[self.bounds[0]], _OPS_OF[self.bounds[1]])
            if math.isfinite(lo) and math.isfinite(hi):
                parts.append(f"{self.limit_text(lo, unit)} {lo_op} {self.name} {hi_op} "
                             f"{self.limit_text(hi, unit)}")
            elif math.isfinite(lo):
                parts.append(said({"<": ">", "<=": ">="}[lo_op], lo))
            elif math.isfinite(hi):
                parts.append(said(hi_op, hi))
        if self.nonzero:
            parts.append(said("!=", 0.0))
        said_all = " and ".join(parts)
        if self.whole:
            return f"{said_all}, a whole number" if parts else f"{self.name} a whole number"
        return said_all


_HEMISPHERE_WORDS = {"n": "N", "north": "N", "s": "S", "south": "S", "e": "E", "east": "E",
                     "w": "W", "west": "W"}
_WORD = r"(?<![A-Za-z])(north|south|east|west|[NSEWnsew])"
_NUMBER = r"[-+]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][-+]?\d+)?"
_PATTERNS: list[re.Pattern[str]] = []  # compiled when a hemisphere is first read (ms at start-up)


def _hemisphere_patterns() -> list[re.Pattern[str]]:
    """The number before the hemisphere (``30 deg S``), then after it (``S 30``)."""
    if not _PATTERNS:
        _PATTERNS.extend([
            re.compile(rf"^\s*(?P<number>{_NUMBER})\s*(?P<unit>.*?)\s*{_WORD}\.?\s*$", re.I),
            re.compile(rf"^\s*{_WORD}\.?\s*(?P<number>{_NUMBER})\s*(?P<unit>.*?)\s*$", re.I)])
    return _PATTERNS


def split_hemisphere(text: str, letters: str) -> tuple[str, int] | None:
    """``30 S``, ``30 deg S``, ``30°S``, ``S 30`` -> ("30 deg", -1) for letters "NS"
    (N and E are +1; a bare number is in degrees); None when no hemisphere is written.

    Raises ValueError, in words, for a letter of the other pair (``30 E`` as a latitude)
    or a sign written with a hemisphere (``-30 S``).
    """
    after, before = _hemisphere_patterns()
    match = after.match(text) or before.match(text)
    if match is None:
        return None
    word = next(g for g in match.groups() if g and g.lower() in _HEMISPHERE_WORDS)
    letter = _HEMISPHERE_WORDS[word.lower()]
    number, unit = match.group("number"), match.group("unit").strip() or "deg"
    if letter not in letters:
        raise ValueError(f"{word!r} is not a hemisphere of this key: write {letters[0]} or "
                         f"{letters[1]}")
    if number[0] in "+-":
        raise ValueError(f"a sign and a hemisphere together: write {number.lstrip('+-')} "
                         f"{letter} or {number} deg, not both")
    return f"{number} {unit}", (1 if letter in "NE" else -1)


_OPS = {">": operator.gt, ">=": operator.ge, "<": operator.lt, "<=": operator.le,
        "!=": operator.ne, "whole": lambda v, x: math.isfinite(v) and (v / x).is_integer()}
_FLIP = {"(": "<", "[": "<="}  # a range's lower end, read left to right
_OPS_OF = {")": "<", "]": "<="}


MISSING_KEY = "this problem needs this key in `given`"


@record(frozen=True)
class OneOf:
    """Keys of which a problem gives exactly one (``optional``: at most one).

    ``missing`` refuses none (at the first key); ``many`` two or more (at the second
    given), with ``{keys}`` the keys and ``{present}`` those given, joined by "and".
    """

    keys: tuple[str, ...]
    missing: str = ""
    many: str = "give one of {keys}, not {present}: they say the same thing"
    optional: bool = False

    def refusal(self, present: list[str]) -> tuple[str, str] | None:
        """(message, key) refusing the keys ``present``, or None if they are one of."""
        if not present and not self.optional:
            return self.missing, self.keys[0]
        if len(present) > 1:
            return (self.many.format(keys=", ".join(self.keys), present=" and ".join(present)),
                    present[1])
        return None


@record(frozen=True)
class AnswerSpec:
    """An answer a kind can give; dimension None for a word (``motion``)."""

    name: str
    dimension: str | None
    symbol: str
    doc: str
    words: tuple[str, ...] = ()  # a word answer's possible values (a bank's choices)
    # a signed pair as books print it, a size with words: its places in order (A, B) and
    # the words that sign a size (("up", 1), ("down", -1)); `gyro check` reads both
    sides: tuple[str, ...] = ()
    signs: tuple[tuple[str, int], ...] = ()


# ---- words as books write them ------------------------------------------------

# Spellings of a rotation's sense and of a viewpoint, in every word-valued key.
_PHRASES = (
    ("anti_clockwise", "counterclockwise"), ("anticlockwise", "counterclockwise"),
    ("counter_clockwise", "counterclockwise"), ("ccw", "counterclockwise"),
    ("_when_seen_from_", "_from_"), ("_when_viewed_from_", "_from_"),
    ("_as_seen_from_", "_from_"), ("_as_viewed_from_", "_from_"), ("_seen_from_", "_from_"),
    ("_viewed_from_", "_from_"),
    ("_looking_from_", "_from_"), ("_from_the_", "_from_"),
)

# Opposite meanings: a suggestion never swaps one pole of these for the other.
_POLES = (
    (("anti", "counter", "ccw"), ("clockwise",)),
    (("left", "port"), ("right", "starboard")),
    (("ris", "ascend", "up"), ("fall", "descend", "down")),
    (("stern", "aft", "rear", "back", "behind", "tail"), ("bow", "front", "fore", "nose")),
    (("same",), ("opposite",)),
)


def normal_word(text: str) -> str:
    """A word as a key's choices are written: lower case, ``_`` between words, the
    rotation written ``counterclockwise`` (``anti-clockwise``, ``counter-clockwise``),
    ``seen from the stern`` as ``from_stern``."""
    word = "_".join(text.strip().lower().replace("-", " ").replace(".", " ").split())
    word = f"_{word}_"
    for spelling, choice in _PHRASES:
        word = word.replace(spelling, choice)
    return word.strip("_")


def read_word(param: Param, text: str) -> str | None:
    """The choice ``text`` names (a choice, or one of the param's other spellings), or None."""
    word = normal_word(text)
    if word in param.choices:
        return word
    return dict(param.words).get(word)


def _pole(word: str, axis: tuple[tuple[str, ...], tuple[str, ...]]) -> int:
    first, second = axis
    if axis is _POLES[0]:  # counterclockwise contains clockwise: look at the prefix
        if any(m in word for m in first):
            return 0
        token = next((t for t in word.split("_") if "clock" in t), None)
        if token is None:
            return -1
        # "clockwise" alone is clockwise; anything before it ("couter", "ani") is a slip
        # of counter- or anti-, never read as clockwise
        return 1 if token.startswith("clock") else 0
    has = [any(m in word for m in first), any(m in word for m in second)]
    return -1 if has[0] == has[1] else (0 if has[0] else 1)


def flips(text: str, choice: str) -> bool:
    """Whether reading ``text`` as ``choice`` would turn a meaning into its opposite
    (``anticlockwise_from_stern`` as ``clockwise_from_stern``, ``port`` as ``right``)."""
    word = normal_word(text)
    for axis in _POLES:
        a, b = _pole(word, axis), _pole(choice, axis)
        if a >= 0 and b >= 0 and a != b:
            return True
    return False


def safe_choices(text: str, choices: tuple[str, ...]) -> list[str]:
    """The choices a "did you mean" may offer for ``text``: none that flips its meaning, and
    none that guesses a pole the text does not state where the choices differ on it
    (``clockwise`` alone: from the stern or from the bow are opposite senses)."""
    word = normal_word(text)
    safe = [c for c in choices if not flips(text, c)]
    for axis in _POLES:
        poles = {_pole(c, axis) for c in safe}
        if _pole(word, axis) < 0 and {0, 1} <= poles:
            safe = [c for c in safe if _pole(c, axis) < 0]
    return safe
