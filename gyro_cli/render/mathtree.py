"""Expression trees for the formulas of a worked answer.

The kinds write their formulas as expression trees (`core.expr`,
`core.prose`); `exprnodes` turns each into these nodes, and `mathprint` and
`mathml` typeset them.
The nodes are small immutable records, compared by value (tests build the
expected trees by hand).
"""

from __future__ import annotations

import re
from dataclasses import dataclass

# ---- names and tokens, shared by the parser and the printers ------------------------

GREEK = {"alpha", "beta", "gamma", "delta", "epsilon", "zeta", "eta", "theta", "iota", "kappa",
         "lambda", "mu", "nu", "xi", "pi", "rho", "sigma", "tau", "phi", "chi", "psi", "omega",
         "Gamma", "Delta", "Theta", "Lambda", "Xi", "Pi", "Sigma", "Phi", "Psi", "Omega"}
_TOKEN = re.compile(r"""
    (?P<num>\d+(?:\.\d+)?(?:[eE][-+]?\d+)?|\.\d+(?:[eE][-+]?\d+)?)
  | (?P<name>[A-Za-z][A-Za-z0-9]*(?:_[A-Za-z0-9]+(?:,[A-Za-z][A-Za-z0-9]*)?)?)
  | (?P<op>>=|<=|->|>>|<<|\+-|-\+|!=|[-+*/=<>^(),;:.!?'|\[\]~])
  | (?P<space>\s+)
  | (?P<other>.)
""", re.X | re.S)


@dataclass(frozen=True)
class Token:
    kind: str   # num, name, op, other, space
    text: str
    space: bool  # whitespace before it


def tokens(text: str, keep_space: bool = False) -> list[Token]:
    out: list[Token] = []
    space = False
    for m in _TOKEN.finditer(text):
        if m.lastgroup == "space":
            space = True
            if keep_space:
                out.append(Token("space", m.group(), False))
            continue
        out.append(Token(m.lastgroup, m.group(), space))
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


def _symbolic(rest: str) -> bool:
    return rest in GREEK or (len(rest) == 1 and rest.isalpha())




class Node:
    """Base of every node."""


@dataclass(frozen=True)
class Num(Node):
    """A number as written: ``3.869e-05``."""
    text: str


@dataclass(frozen=True)
class Sym(Node):
    """A symbol by its plain name: ``phidot``, ``theta_0``, ``F_A,weight``."""
    name: str


@dataclass(frozen=True)
class Quantity(Node):
    """A number with a unit: ``9.815 m/s^2`` (the unit as written)."""
    value: Num
    unit: str


@dataclass(frozen=True)
class Neg(Node):
    """Unary minus (``sign`` "-") or an explicit plus (``sign`` "+")."""
    body: Node
    sign: str = "-"


@dataclass(frozen=True)
class BinOp(Node):
    """``left op right``; op is one of + - +- -+ * / x . and " " (implicit product)."""
    op: str
    left: Node
    right: Node


@dataclass(frozen=True)
class Pow(Node):
    base: Node
    exp: Node


@dataclass(frozen=True)
class Call(Node):
    """``name(args)``: a known function (sin, sqrt, acos) or an applied symbol (``K(m)``);
    ``power`` is the n of ``sin^2(theta)``; ``sep`` joins the arguments (", " or "|")."""
    name: str
    args: tuple
    power: Node | None = None
    parens: bool = True
    sep: str = ","


@dataclass(frozen=True)
class Group(Node):
    """Brackets written by the author: ``(...)`` or ``[...]``."""
    open: str
    body: Node


@dataclass(frozen=True)
class Tuple(Node):
    """A list in brackets: ``(0, 458.1, 0)``, ``[-1, 1]``."""
    items: tuple


@dataclass(frozen=True)
class Abs(Node):
    """``|x|``: magnitude of a vector or absolute value."""
    body: Node


@dataclass(frozen=True)
class Rel(Node):
    """A chain ``a = b >= c``: ``first`` then (op, node) pairs; first may be None (``= x``)."""
    first: Node | None
    rest: tuple


@dataclass(frozen=True)
class Sum(Node):
    """``sum m x^2`` (a sum over the particles of a body)."""
    body: Node


@dataclass(frozen=True)
class Integral(Node):
    """``int_u1^u2 du / sqrt(f(u))``."""
    lower: Node
    upper: Node
    body: Node


@dataclass(frozen=True)
class Prime(Node):
    """``q'`` and ``theta''``: derivatives in Lagrange's notation."""
    body: Node
    count: int


@dataclass(frozen=True)
class Text(Node):
    """Words inside maths (prose that did not parse)."""
    text: str


@dataclass(frozen=True)
class Tex(Node):
    """Maths already typeset (a line that did not parse whole, set piece by piece);
    ``plain`` is the text it came from."""
    latex: str
    plain: str


@dataclass(frozen=True)
class Matrix(Node):
    """``[a b c; d e f]``: rows separated by semicolons, entries by spaces."""
    rows: tuple
