"""Typesetting nodes: a formula of a worked answer as the LaTeX and MathML printers set it.

The kinds write their formulas as expression trees (`core.expr`,
`core.prose`); `exprnodes` turns each into these nodes, and `mathprint` and
`mathml` typeset them. The nodes are small immutable records, compared by value.
"""

from __future__ import annotations

from dataclasses import dataclass


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
    """Words inside maths: ``phidot (slow)``, ``at 30 deg``."""
    text: str


@dataclass(frozen=True)
class Matrix(Node):
    """``[a b c; d e f]``: rows separated by semicolons, entries by spaces."""
    rows: tuple
