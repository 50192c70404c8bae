"""The test oracle's parse tree: what `formula_oracle.parse` reads formula text into.

gyro prints `core.expr`/`core.prose` trees only; the oracle, which reads printed
text back, keeps its own small records (compared by value) and hands gyro's
printers the core tree they stand for (`to_core`).
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


# ---- the oracle's own precedence (its text printer's brackets) ----------------------

PRECEDENCE = {"Rel": 0, "+": 10, "-": 10, "+-": 10, "-+": 10, "*": 20, "/": 20, "x": 20,
              ".": 20, " ": 20, "Neg": 25, "Pow": 30, "Prime": 40, "Atom": 50}
SUMS = ("+", "-", "+-", "-+")


def precedence(node: Node) -> int:
    if isinstance(node, Rel):
        return PRECEDENCE["Rel"]
    if isinstance(node, BinOp):
        return PRECEDENCE[node.op]
    if isinstance(node, Neg):
        return PRECEDENCE["Neg"]
    if isinstance(node, Pow):
        return PRECEDENCE["Pow"]
    if isinstance(node, Call) and (not node.parens or node.power is not None):
        return PRECEDENCE["*"]
    if isinstance(node, (Sum, Integral, Quantity)):
        return PRECEDENCE["*"]
    return PRECEDENCE["Atom"]


def fold(right: Node, op: str) -> tuple[Node, str]:
    """``a + (-b) c`` -> ``a - b c``; ``a - (-b)`` -> ``a + b``."""
    flip = {"+": "-", "-": "+"}
    if op not in flip:
        return right, op
    if isinstance(right, Neg) and right.sign == "-":
        return right.body, flip[op]
    if isinstance(right, Group) and isinstance(right.body, Neg) and right.body.sign == "-" \
            and isinstance(right.body.body, (Num, Quantity)):
        return right.body.body, flip[op]
    chain = []
    node = right
    while isinstance(node, BinOp) and node.op in (" ", "*", "/"):
        chain.append(node)
        node = node.left
    if chain and isinstance(node, Neg) and node.sign == "-":
        rebuilt = node.body
        for link in reversed(chain):
            rebuilt = BinOp(link.op, rebuilt, link.right)
        return rebuilt, flip[op]
    return right, op


# ---- the core tree a parse stands for, as gyro's printers print it -------------------

class Unsupported(ValueError):
    """A parse that no tree a kind writes stands for (``1 x 10^6 kg``)."""


def to_core(node: Node):  # type: ignore[no-untyped-def]
    """The core tree (as `mathprint.Lowering` sets a kind's) that prints as ``node``."""
    from gyro_cli.core import expr as E
    from gyro_cli.core import prose as P
    from gyro_cli.render import mathprint as M

    if isinstance(node, Num):
        return M.number(node.text)
    if isinstance(node, Sym):
        return M.symbol(node.name)
    if isinstance(node, Text):
        return P.Words(node.text)
    if isinstance(node, Quantity):
        if not isinstance(node.value, Num):
            raise Unsupported(f"a quantity of {type(node.value).__name__}")
        return M.quantity_node(node.value.text, node.unit)
    if isinstance(node, Neg):
        body = to_core(node.body)
        return E.Neg(body) if node.sign == "-" else P.Sign(node.sign, body)
    if isinstance(node, BinOp):
        if node.op == "*":
            raise Unsupported("a written *")
        return M.binop(node.op, to_core(node.left), to_core(node.right))
    if isinstance(node, Pow):
        return E.Pow(to_core(node.base), to_core(node.exp))
    if isinstance(node, Call):
        args = tuple(to_core(a) for a in node.args)
        if not node.parens and not isinstance(node.args[0], (Sym, Quantity)):
            raise Unsupported("a function's argument without brackets")
        if node.power is not None:
            power = to_core(node.power)
            if node.name not in ("sin", "cos", "tan") or not isinstance(node.power, Num) \
                    or node.power.text not in ("2", "3"):
                raise Unsupported("a power of a function other than sin^2, cos^3")
            return E.Pow(E.Call(node.name, args), power)
        return P.Fn(node.name, args, node.sep)
    if isinstance(node, Group):
        if isinstance(node.body, Tuple):
            return P.Bracket(tuple(to_core(x) for x in node.body.items), node.open + ",")
        return P.Bracket((to_core(node.body),), node.open)
    if isinstance(node, Tuple):
        raise Unsupported("a list without brackets")
    if isinstance(node, Abs):
        return E.Call("abs", (to_core(node.body),))
    if isinstance(node, Rel):
        first = None if node.first is None else to_core(node.first)
        return P.Rel(first, tuple((op, to_core(rhs)) for op, rhs in node.rest))
    if isinstance(node, Sum):
        return P.Total(to_core(node.body))
    if isinstance(node, Integral):
        return P.Integral(to_core(node.lower), to_core(node.upper), to_core(node.body))
    if isinstance(node, Prime):
        return P.Prime(to_core(node.body), node.count)
    if isinstance(node, Matrix):
        return P.Mat(tuple(tuple(to_core(x) for x in row) for row in node.rows))
    raise Unsupported(type(node).__name__)
