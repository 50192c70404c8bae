"""How gyro writes maths, stated once for every format: symbol names, numbers, units
and the tables of relations, signs and functions (LaTeX and MathML columns side by side).

A symbol's plain name says how it is set: Greek names become Greek letters; a
trailing ``dot``/``ddot`` an accent; trailing digits or what follows ``_`` a
subscript (``theta0`` and ``theta_0`` -> theta sub 0, ``u1`` -> u sub 1); a
multi-letter subscript is upright (``psidot_min`` -> psi-dot sub min); ``dH``,
``dtheta`` a differential (upright d). The printers (`mathprint`, `mathml`) read
these rules and tables; nothing here prints.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from ..core.expr import UNIT_TEXT

__all__ = [
    "DEGREES",
    "FUNCTIONS",
    "GREEK",
    "RELATIONS",
    "SIGNS",
    "UNIT_TEXT",
    "Token",
    "dotted",
    "number_parts",
    "split_symbol",
    "symbolic",
    "tokens",
    "unit_spelling",
]

GREEK = {"alpha", "beta", "gamma", "delta", "epsilon", "zeta", "eta", "theta", "iota", "kappa",
         "lambda", "mu", "nu", "xi", "pi", "rho", "sigma", "tau", "phi", "chi", "psi", "omega",
         "Gamma", "Delta", "Theta", "Lambda", "Xi", "Pi", "Sigma", "Phi", "Psi", "Omega"}

#: a relation of a chain: plain spelling -> (LaTeX, MathML operator)
RELATIONS = {"=": ("=", "="), ">=": (r"\ge", "≥"), "<=": (r"\le", "≤"), "<": ("<", "&lt;"),
             ">": (">", "&gt;"), ">>": (r"\gg", "≫"), "<<": (r"\ll", "≪"), "->": (r"\to", "→"),
             "~": (r"\approx", "≈"), "!=": (r"\ne", "≠")}
#: a sign between terms or before one: plain -> (LaTeX, MathML operator)
SIGNS = {"+": ("+", "+"), "-": ("-", "−"), "+-": (r"\pm", "±"), "-+": (r"\mp", "∓")}
#: functions set upright by name: plain -> (LaTeX, MathML name); atan2 and the like have
#: no LaTeX command and are set as operator names
FUNCTIONS = {
    "sin": (r"\sin", "sin"), "cos": (r"\cos", "cos"), "tan": (r"\tan", "tan"),
    "cot": (r"\cot", "cot"), "sec": (r"\sec", "sec"), "csc": (r"\csc", "csc"),
    "exp": (r"\exp", "exp"), "ln": (r"\ln", "ln"), "log": (r"\log", "log"),
    "sinh": (r"\sinh", "sinh"), "cosh": (r"\cosh", "cosh"), "tanh": (r"\tanh", "tanh"),
    "det": (r"\det", "det"), "arcsin": (r"\arcsin", "arcsin"),
    "arccos": (r"\arccos", "arccos"), "arctan": (r"\arctan", "arctan"),
    "asin": (r"\arcsin", "arcsin"), "acos": (r"\arccos", "arccos"),
    "atan": (r"\arctan", "arctan"), "max": (r"\max", "max"), "min": (r"\min", "min"),
    "atan2": (r"\operatorname{atan2}", "atan2"), "Re": (r"\operatorname{Re}", "Re"),
    "Im": (r"\operatorname{Im}", "Im"), "sign": (r"\operatorname{sign}", "sign")}
#: the units set as a degree sign after the number
DEGREES = ("deg", "degree", "degrees")

LATEX, MATHML = 0, 1  # the columns of the tables above


def unit_spelling(unit: str) -> str:
    """A kind's spelling of a unit as printed: ``kg*m^2`` -> ``kg m^2``."""
    return UNIT_TEXT.get(unit, unit)


# ---- names and tokens -------------------------------------------------------------------

_TOKEN = re.compile(r"""
    (?P<num>\d+(?:\.\d+)?(?:[eE][-+]?\d+)?|\.\d+(?:[eE][-+]?\d+)?)
  | (?P<name>[A-Za-z][A-Za-z0-9]*(?:_[A-Za-z0-9]+(?:,[A-Za-z][A-Za-z0-9]*)?)?)
  | (?P<op>>=|<=|->|>>|<<|\+-|-\+|!=|[-+*/=<>^(),;:.!?'|\[\]~])
  | (?P<space>\s+)
  | (?P<other>.)
""", re.VERBOSE | re.DOTALL)


@dataclass(frozen=True)
class Token:
    kind: str   # num, name, op, other, space
    text: str
    space: bool  # whitespace before it


def tokens(text: str, keep_space: bool = False) -> list[Token]:
    """A unit's (or a name's) tokens: numbers, names, operators."""
    out: list[Token] = []
    space = False
    for m in _TOKEN.finditer(text):
        if m.lastgroup == "space":
            space = True
            if keep_space:
                out.append(Token("space", m.group(), False))
            continue
        out.append(Token(m.lastgroup or "other", m.group(), space))
        space = False
    return out


def dotted(name: str) -> tuple[str, str] | None:
    """``phidot`` -> ("phi", "dot"), ``thetaddot`` -> ("theta", "ddot")."""
    for suffix in ("ddot", "dot"):
        base = name[: -len(suffix)]
        if name.endswith(suffix) and base and (base in GREEK or len(base) == 1
                                               or base in ("roll", "pitch", "yaw")):
            return base, suffix
    return None


def symbolic(rest: str) -> bool:
    """A name a differential's d may stand before: ``dtheta``, ``dH``."""
    return rest in GREEK or (len(rest) == 1 and rest.isalpha())


_DIGITS = re.compile(r"([A-Za-z]+?)(\d+)$")


def split_symbol(name: str) -> tuple[str, list[str]]:
    """``theta_0`` -> ("theta", ["0"]); ``u1`` -> ("u", ["1"]); ``F_A,weight`` ->
    ("F", ["A", "weight"]); ``K0_pp`` -> ("K", ["0", "pp"])."""
    base, _, sub = name.partition("_")
    subs = sub.split(",") if sub else []
    if len(base) == 2 and base[0].isupper() and base[1] in "xyz":
        return base[0], [base[1]] + subs  # Rz: the rotation about z
    m = _DIGITS.match(base)
    if m and (m.group(1) in GREEK or len(m.group(1)) <= 2 or dotted(m.group(1))
              or m.group(1) in ("phidot", "thetadot", "psidot")):
        base, subs = m.group(1), [m.group(2)] + subs
    return base, subs


#: a piece of a symbol's name as set: ("greek", "theta"), ("accent", "dot", piece),
#: ("letter", "m"), ("differential", piece), ("word", "min"), ("digits", "0"), ("char", "'")
NamePart = tuple


def base_part(base: str) -> NamePart:
    """How a symbol's base is set: a Greek letter, an accented base, one letter (italic), a
    differential (upright d), else a word (upright)."""
    if base in GREEK:
        return ("greek", base)
    d = dotted(base)
    if d:
        return ("accent", d[1], base_part(d[0]))
    if len(base) == 1:
        return ("letter", base)
    if base[0] == "d" and symbolic(base[1:]):
        return ("differential", base_part(base[1:]))
    return ("word", base)


def sub_part(part: str) -> NamePart:
    """How one subscript is set: digits, one character, a Greek or accented name, or an
    upright word (``min``)."""
    if part.isdigit():
        return ("digits", part)
    if len(part) == 1:
        return ("char", part)
    if part in GREEK or dotted(part):
        return base_part(part)
    return ("word", part)


def symbol_parts(name: str) -> tuple[NamePart, list[NamePart]]:
    """A symbol's name as its base and subscripts, each as set (`base_part`, `sub_part`):
    ``psidot_min`` -> (("accent", "dot", ("greek", "psi")), [("word", "min")])."""
    base, subs = split_symbol(name)
    return base_part(base), [sub_part(p) for p in subs]


def number_parts(text: str) -> tuple[str, str, int | None]:
    """A number as written, as (sign, mantissa, power of ten or None): ``-3.869e-05`` ->
    ("-", "3.869", -5)."""
    sign = "-" if text.startswith("-") else ""
    mantissa, _, exponent = text[len(sign):].lower().partition("e")
    if not exponent:
        return sign, text[len(sign):], None
    return sign, mantissa, int(exponent)


def unit_parts(unit: str) -> list[tuple[str, str]]:
    """A unit as (kind, text) parts: ("space", ""), ("name", "kg"), ("num", "2"),
    ("power", "-2"), ("op", "/")."""
    out: list[tuple[str, str]] = []
    toks = tokens(unit)
    k = 0
    while k < len(toks):
        t = toks[k]
        if t.space:
            out.append(("space", ""))
        if t.text == "^":
            exp = ""
            k += 1
            while k < len(toks) and (toks[k].text == "-" or toks[k].kind == "num"):
                exp += toks[k].text
                k += 1
            out.append(("power", exp))
            continue
        out.append((t.kind if t.kind in ("name", "num") else "op", t.text))
        k += 1
    return out
