"""Sentences that hold formulas: a line of prose written as words and trees.

A kind writes a sentence with maths in it as pieces: a string is words, a
`core.expr` tree is maths, printed by every format from the tree (nothing
parses the sentence back)::

    I_v, alphaddot, H, W, lam, alpha = names("I_v alphaddot H Omega lambda alpha")
    work.text("so ", rel(I_v * alphaddot, "=", -H * W * cos(lam) * sin(alpha)),
              " (terms of order ", I_v * W**2, " neglected)")

The nodes below are the ones only prose needs; nothing evaluates them: a
relation chain (``a = b >= c``), the cross and dot products of vectors, a
tuple, a function known by its name only (``f(u)``, ``R_z(psi)``), the sum
over a body's particles, a sign written out (``+K``, ``+-M / L``), a rate of
change (``dH/dt``) and a quantity written with its value (``0.0001280 N m``),
which ``--units us`` converts.
"""

from __future__ import annotations

import math

from .expr import (
    ADD,
    ATOM,
    MUL,
    NAMED,
    NEG,
    SHOWN,
    SIG,
    UNIT_TEXT,
    Add,
    BinOp,
    Div,
    Expr,
    Mul,
    Neg,
    Sub,
    Sym,
    TextPrinter,
    _node,
    map_tree,
    needs_brackets,
    num,
    precedence,
)

TYPE_CHECKING = False
if TYPE_CHECKING:
    from collections.abc import Callable

RELATIONS = ("=", "<", ">", "<=", ">=", "!=", "~", "->", ">>", "<<")
SIGNS = ("+", "+-", "-+")


def _finite(values) -> None:  # type: ignore[no-untyped-def]
    """A value a sentence states must be a number: an overflow (1e200 rpm squared) or a
    degenerate case is bad input for the kind, refused as a step's would be."""
    for v in values:
        if not math.isfinite(v):
            from .errors import InputError

            raise InputError("a value the worked answer states is not a finite number for "
                             "these data: a degenerate case, or magnitudes beyond double "
                             "precision; check the data and units", key="given")


class Typeset(Expr):
    """A node of a sentence: printed, never evaluated."""

    __slots__ = ()

    @property
    def value(self) -> float:
        raise TypeError(f"{type(self).__name__} is typeset only: it has no value")


class Rel(Typeset):
    """``first op1 rhs1 op2 rhs2 ...``: an equation or inequality chain; with no ``first``
    (None) it continues the line before it, ``= 0.03283 deg`` in a step's note."""

    __slots__ = ("first", "rest")
    binding = 0  # looser than any operator (`expr.precedence`)

    def __init__(self, first: Expr | None, rest: tuple[tuple[str, Expr], ...]) -> None:
        for op, _ in rest:
            if op not in RELATIONS:
                raise ValueError(f"unknown relation {op!r}")
        self.first, self.rest = first, rest

    def children(self) -> tuple[Expr, ...]:
        head = () if self.first is None else (self.first,)
        return head + tuple(rhs for _, rhs in self.rest)

    def map_children(self, change: Callable[[Expr], Expr]) -> Expr:
        return Rel(None if self.first is None else change(self.first),
                   tuple((op, change(rhs)) for op, rhs in self.rest))


class Cross(Typeset, BinOp):
    """The cross product ``a x b`` of two vectors."""

    __slots__ = ()
    op = "x"
    binding = MUL
    bracket_after_sign = True


class Dot(Typeset, BinOp):
    """The dot product ``a . b`` of two vectors."""

    __slots__ = ()
    op = "."
    binding = MUL
    bracket_after_sign = True


class Fn(Typeset):
    """``name(args)`` for a function known by its name only: ``f(u)``, ``R_z(psi)``."""

    __slots__ = ("name", "args", "sep")

    def __init__(self, name: str, args: tuple[Expr, ...], sep: str = ",") -> None:
        self.name, self.args, self.sep = name, args, sep  # sep "|": Pi(n|m)

    def children(self) -> tuple[Expr, ...]:
        return self.args

    def map_children(self, change: Callable[[Expr], Expr]) -> Expr:
        return Fn(self.name, tuple(change(x) for x in self.args), self.sep)


class Total(Typeset):
    """``sum body``: a sum over the particles of a body (Eq. 11.3)."""

    __slots__ = ("body",)
    binding = MUL

    def __init__(self, body: Expr) -> None:
        self.body = body

    def children(self) -> tuple[Expr, ...]:
        return (self.body,)

    def map_children(self, change: Callable[[Expr], Expr]) -> Expr:
        return Total(change(self.body))


class Sign(Typeset):
    """``+K``, ``+-M / L``: a sign written before its operand (a minus is `expr.Neg`)."""

    __slots__ = ("sign", "arg")
    binding = NEG

    def __init__(self, sign: str, arg: Expr) -> None:
        if sign not in SIGNS:
            raise ValueError(f"unknown sign {sign!r}")
        self.sign, self.arg = sign, arg

    def children(self) -> tuple[Expr, ...]:
        return (self.arg,)

    def map_children(self, change: Callable[[Expr], Expr]) -> Expr:
        return Sign(self.sign, change(self.arg))


class Deriv(Typeset):
    """``dH/dt``: the rate of change of a quantity known by its name."""

    __slots__ = ("sym", "var")
    binding = MUL

    def __init__(self, sym: Sym, var: str = "t") -> None:
        if not isinstance(sym, Sym):
            raise TypeError("dx/dt takes a symbol; d/dt of a formula is fn(\"d/dt\", ...)")
        self.sym, self.var = sym, var


class Mat(Typeset):
    """``[a b c; d e f]``: a matrix by its rows."""

    __slots__ = ("rows",)

    def __init__(self, rows: tuple[tuple[Expr, ...], ...]) -> None:
        self.rows = rows

    def children(self) -> tuple[Expr, ...]:
        return tuple(x for row in self.rows for x in row)

    def map_children(self, change: Callable[[Expr], Expr]) -> Expr:
        return Mat(tuple(tuple(change(x) for x in row) for row in self.rows))


class Quantity(Typeset):
    """A value with its unit, printed as such in the formula too: ``0.0001280 N m``
    (SI value; ``deg`` shows radians in degrees, as a `Sym` does). ``sig``: the
    significant figures shown (a number the reader compares to many digits); a
    complex value is written ``a - b i`` (an eigenvalue)."""

    __slots__ = ("si", "unit", "exact", "label", "sig")

    def __init__(self, si: float | complex, unit: str = "", exact: bool = False,
                 label: str = "", sig: int = SIG) -> None:
        self.si, self.unit, self.exact, self.label, self.sig = si, unit, exact, label, sig
        _finite((si.real, si.imag) if type(si) is complex else (si,))

    @property
    def number(self) -> str:
        """The value as written, without its unit: ``-0.7753 - 4.465 i``; a label as the
        source gives it (0.003273795, 6.6743e-11)."""
        if self.label:
            return self.label
        if isinstance(self.si, complex):
            re, im = self.si.real, self.si.imag
            return num(re, self.sig) + (f" {'-' if im < 0 else '+'} {num(abs(im), self.sig)} i"
                                        if im else "")
        shown = self.si / SHOWN[self.unit][0] if self.unit in SHOWN else self.si
        return f"{round(shown, 9):g}" if self.exact else num(shown, self.sig)

    @property
    def text(self) -> str:
        """``0.0001280 N m``; an exact quantity as few digits as it needs (``180 deg``)."""
        return f"{self.number} {UNIT_TEXT.get(self.unit, self.unit)}".rstrip()

    @property
    def binding(self) -> int:  # type: ignore[override]
        if isinstance(self.si, complex) and self.si.imag:
            return ADD
        return MUL if self.unit or self.si.real < 0 else ATOM


class Matrix(Typeset):
    """``[[a, b], [c, d]] unit``: a matrix of values with one unit (SI), ``sig`` figures."""

    __slots__ = ("rows", "unit", "sig")
    binding = MUL

    def __init__(self, rows: tuple[tuple[float, ...], ...], unit: str = "",
                 sig: int = SIG) -> None:
        self.rows, self.unit, self.sig = rows, unit, sig
        _finite(tuple(x for row in rows for x in row))

    def entries(self) -> tuple[tuple[Quantity, ...], ...]:
        """Each entry as a quantity without the unit, as printed."""
        return tuple(tuple(Quantity(x, "", sig=self.sig) for x in row) for row in self.rows)


class Integral(Typeset):
    """``int_a^b body``: a definite integral (the body holds its differential)."""

    __slots__ = ("lower", "upper", "body")
    binding = ATOM  # written last in its product: 2 int_a^b du / sqrt(f(u))

    def __init__(self, lower: Expr, upper: Expr, body: Expr) -> None:
        self.lower, self.upper, self.body = lower, upper, body

    def children(self) -> tuple[Expr, ...]:
        return (self.lower, self.upper, self.body)

    def map_children(self, change: Callable[[Expr], Expr]) -> Expr:
        return Integral(change(self.lower), change(self.upper), change(self.body))


class Bracket(Typeset):
    """Brackets the author writes: ``[x]`` around a long factor, ``(x)`` where precedence
    needs none (``(357.8) u^3``, ``-(omega_p x H)``), ``(a, b, c)`` around a vector's
    components or ``[-1, 1]`` around a list."""

    __slots__ = ("items", "open")
    binding = ATOM

    def __init__(self, items: tuple[Expr, ...], open: str = "[") -> None:
        self.items, self.open = items, open

    def children(self) -> tuple[Expr, ...]:
        return self.items

    def map_children(self, change: Callable[[Expr], Expr]) -> Expr:
        return Bracket(tuple(change(x) for x in self.items), self.open)


class Pm(Typeset):
    """``a +- b``, ``beta -+ gamma``: either sign between two terms (``+-1`` alone is a
    `Sign`)."""

    __slots__ = ("left", "right", "op")
    binding = ADD

    def __init__(self, left: Expr, right: Expr, op: str = "+-") -> None:
        if op not in ("+-", "-+"):
            raise ValueError(f"unknown sign {op!r}")
        self.left, self.right, self.op = left, right, op

    def children(self) -> tuple[Expr, ...]:
        return (self.left, self.right)

    def map_children(self, change: Callable[[Expr], Expr]) -> Expr:
        return Pm(change(self.left), change(self.right), self.op)


class Vector(Typeset):
    """A vector by its components with one unit: ``(0, 458.1, 0) kg m^2/s`` (SI values;
    a zero component is written 0)."""

    __slots__ = ("si", "unit")
    binding = MUL

    def __init__(self, si: tuple[float, ...], unit: str = "") -> None:
        self.si, self.unit = tuple(si), unit
        _finite(self.si)

    @property
    def numbers(self) -> tuple[str, ...]:
        return tuple(num(c) if c else "0" for c in self.si)

    @property
    def text(self) -> str:
        return f"({', '.join(self.numbers)}) {UNIT_TEXT.get(self.unit, self.unit)}".rstrip()


class Words(Typeset):
    """Words standing for a symbol, ``drift angle``, or labelling one: ``phidot (slow)``
    is ``Words("(slow)", of=phidot)``; words may lead to maths, ``phidot_slow at 30 deg``
    is ``Words("at", of=phidot_slow, then=q(...))``."""

    __slots__ = ("words", "of", "then")
    binding = ATOM

    def __init__(self, words: str, of: Expr | None = None, then: Expr | None = None) -> None:
        self.words, self.of, self.then = words, of, then

    def children(self) -> tuple[Expr, ...]:
        return tuple(x for x in (self.of, self.then) if x is not None)

    def map_children(self, change: Callable[[Expr], Expr]) -> Expr:
        return Words(self.words, *(None if x is None else change(x) for x in (self.of, self.then)))


class Prime(Typeset):
    """``alpha''``: a derivative written with primes (``count`` of them)."""

    __slots__ = ("arg", "count")
    binding = ATOM

    def __init__(self, arg: Expr, count: int = 1) -> None:
        self.arg, self.count = arg, count

    def children(self) -> tuple[Expr, ...]:
        return (self.arg,)

    def map_children(self, change: Callable[[Expr], Expr]) -> Expr:
        return Prime(change(self.arg), self.count)


# ---- building -----------------------------------------------------------------

def names(text: str, unit: str = "") -> tuple[Sym, ...]:
    """Symbols known by their names only (no value): ``names("I_v H Omega")``.

    The same text gives the same symbols (a tree never changes a node, so they are
    shared): the kinds name the same symbols in every file they solve."""
    made = _NAMED.get((text, unit))
    if made is None:
        made = tuple(Sym(name, NAMED, unit) for name in text.split())
        if len(_NAMED) < 4096:
            _NAMED[(text, unit)] = made
    return made


_NAMED: dict[tuple[str, str], tuple[Sym, ...]] = {}


def rel(first: Expr | float | None, *chain: str | Expr | float) -> Rel:
    """``rel(a, "=", b, ">=", c)``: a relation chain; ``rel(None, "=", b)`` is ``= b``."""
    if not chain or len(chain) % 2:
        raise ValueError("a relation chain alternates a relation and an expression")
    rest = tuple((str(chain[k]), _node(chain[k + 1])) for k in range(0, len(chain), 2))  # type: ignore[arg-type]
    return Rel(None if first is None else _node(first), rest)


def cross(a: Expr, b: Expr) -> Cross:
    return Cross(a, b)


def dot(a: Expr, b: Expr) -> Dot:
    return Dot(a, b)


def tup(*items: Expr | float) -> Bracket:
    """``(a, b, c)``: a vector by its components."""
    return Bracket(tuple(_node(x) for x in items), "(")


def fn(name: str, *args: Expr | float, sep: str = ",") -> Fn:
    """``fn("f", u)``: f(u); ``sep="|"`` for a parameter after a bar, ``Pi(n|m)``."""
    return Fn(name, tuple(_node(a) for a in args), sep)


def total(body: Expr) -> Total:
    return Total(body)


def signed(sign: str, arg: Expr | float) -> Sign:
    """``signed("+", K)`` is ``+K``, ``signed("+-", M) / L`` is ``+-M / L``."""
    return Sign(sign, _node(arg))


def deriv(sym: Sym, var: str = "t") -> Deriv:
    """``deriv(H)`` is ``dH/dt``."""
    return Deriv(sym, var)


def qvec(si, unit: str = "") -> Vector:
    """A vector by its SI components with its unit inside a sentence: ``(0, 1.005e+04, 0) N m``."""
    return Vector(tuple(si), unit)


def plus(x: Expr) -> Sign:
    """``+x``: an explicit plus sign, the positive sense of an axis."""
    return Sign("+", x)


def words(text: str, of: Expr | None = None, then: Expr | None = None) -> Words:
    """A symbol written as words (``words("drift angle")``), or a symbol with a label
    (``words("(slow)", phidot)``, printed ``phidot (slow)``), the label leading to maths
    (``words("at", phidot_slow, q(pi / 6, "deg", True))``, ``phidot_slow at 30 deg``)."""
    return Words(text, of, then)


def paren(x: Expr) -> Bracket:
    """``(x)``: brackets where precedence needs none, ``-(omega_p x H)``."""
    return Bracket((x,), "(")


def prime(x: Expr, count: int = 1) -> Prime:
    """``prime(alpha, 2)``: alpha'' (the second derivative in time)."""
    return Prime(x, count)


def mat(*rows) -> Mat:
    """``mat((a, b), (c, d))``: a matrix by its rows."""
    return Mat(tuple(tuple(_node(x) for x in row) for row in rows))


def q(si: float | complex, unit: str = "", exact: bool = False, label: str = "",
      sig: int = SIG) -> Quantity:
    """A value with its unit inside a sentence (SI value); ``exact``: a number of the
    text such as 180 deg, printed with the digits it needs, not to 4 figures; ``label``:
    the number as its source writes it (``"0.003273795"``), all its digits; ``sig``: the
    figures shown where the text compares many (an eigenvalue to 12)."""
    return Quantity(si, unit, exact, label, sig)


def matrix(rows, unit: str = "", sig: int = SIG) -> Matrix:
    """A matrix of SI values with its unit: ``matrix(M, "kg m^2", sig=10)``."""
    return Matrix(tuple(tuple(float(x) + 0.0 for x in row) for row in rows), unit, sig)


def integral(lower: Expr | float, upper: Expr | float, body: Expr) -> Integral:
    return Integral(_node(lower), _node(upper), body)


def bracket(*items: Expr | float, open: str = "[") -> Bracket:
    """``[x]`` (``open="("``: ``(x)``); several items: a list, ``[-1, 1]``."""
    return Bracket(tuple(_node(x) for x in items), open)


def pm(left: Expr | float | None, right: Expr | float, op: str = "+-") -> Pm | Sign:
    """``pm(a, b)``: a +- b; ``pm(None, 1)``: +-1; ``op="-+"``: the other sign first."""
    if left is None:
        return Sign(op, _node(right))
    return Pm(_node(left), _node(right), op)


# ---- a line of prose --------------------------------------------------------------

Piece = "str | Expr"


class Prose:
    """A sentence as pieces: strings are words, trees are maths."""

    __slots__ = ("pieces",)

    def __init__(self, pieces: tuple) -> None:
        for piece in pieces:
            if not isinstance(piece, (str, Expr)):
                raise TypeError(f"a piece of prose is words or a tree, not {piece!r}")
        self.pieces = pieces

    @property
    def text(self) -> str:
        printer = ProseText()
        return "".join(p if isinstance(p, str) else printer.doprint(p) for p in self.pieces)

    def equation(self) -> tuple[Rel, str] | None:
        """The line as one displayed relation and the chapter equation it cites
        (``rel(...)``, optionally followed by ``"  (Eq. 11.19)"``), else None."""
        pieces = [p for p in self.pieces if not (isinstance(p, str) and not p.strip())]
        tag = ""
        if len(pieces) == 2 and isinstance(pieces[1], str):
            words = pieces[1].strip()
            if not (words.startswith("(Eq. ") and words.endswith(")")):
                return None
            tag = words[5:-1]
            pieces = pieces[:1]
        if len(pieces) == 1 and isinstance(pieces[0], Rel):
            return pieces[0], tag
        return None

    def map(self, change: Callable[[Expr], Expr]) -> Prose:
        return Prose(tuple(p if isinstance(p, str) else change(p) for p in self.pieces))


def map_values(expr: Expr, sym: Callable[[Sym], Sym],
               quantity: Callable[[Quantity], Quantity]) -> Expr:
    """The tree with each symbol and each quantity changed (``--units us``): a vector's
    and a matrix's entries each as a quantity of their unit; one walk, `map_tree`."""
    def change(node: Expr) -> Expr | None:
        if isinstance(node, Sym):
            return sym(node)
        if isinstance(node, Quantity):
            return quantity(node)
        if isinstance(node, Vector):
            parts = [quantity(Quantity(c, node.unit)) for c in node.si]
            return Vector(tuple(p.si for p in parts),  # type: ignore[misc]
                          parts[0].unit if parts else node.unit)
        if isinstance(node, Matrix):
            shown = [[quantity(Quantity(x, node.unit, sig=node.sig)) for x in row]
                     for row in node.rows]
            unit = shown[0][0].unit if shown and shown[0] else node.unit
            return Matrix(tuple(tuple(x.si for x in row)  # type: ignore[misc]
                                for row in shown), unit,
                          shown[0][0].sig if shown and shown[0] else node.sig)
        return None

    return map_tree(expr, change)


def deriv_space(name: str) -> str:
    """``d theta/dt`` but ``dH/dt``, ``dH_O/dt``: a space after d before a longer name."""
    return " " if len(name) > 1 and name[:2].isalpha() else ""


def operand_brackets(parent: Expr, child: Expr) -> bool:
    """Brackets around an operand of a prose node: a sum or difference in a product
    of vectors or under a sum sign, a quotient or product beside a cross or dot (a
    product before it is read first: ``Omega K x H``), a sum or a product after a sign."""
    if isinstance(parent, (Cross, Dot)):
        if child is parent.left and isinstance(child, Mul):
            return False
        return precedence(child, False) <= MUL and not isinstance(child, (Fn, Bracket))
    if isinstance(parent, Sign):
        return needs_brackets(Neg(child), child, False, False)
    if isinstance(parent, Total):
        return isinstance(child, (Add, Sub, Div, Rel))
    return False


# ---- printing -----------------------------------------------------------------

class ProseText(TextPrinter):
    """The plain text of a sentence's maths: symbols by name, quantities by value."""

    def _print_Rel(self, node: Rel) -> str:
        head = [] if node.first is None else [self._print(node.first)]
        return " ".join(head + [f"{op} {self._print(rhs)}" for op, rhs in node.rest])

    def _vector(self, node: BinOp) -> str:
        parts = []
        for child in (node.left, node.right):
            text = self._print(child)
            parts.append(f"({text})" if operand_brackets(node, child) else text)
        return f" {node.op} ".join(parts)

    def _print_Cross(self, node: Cross) -> str:
        return self._vector(node)

    def _print_Dot(self, node: Dot) -> str:
        return self._vector(node)

    def _print_Fn(self, node: Fn) -> str:
        space = "" if node.name.rstrip("'").isidentifier() else " "  # d/dt (H . U), U''(x)
        sep = ", " if node.sep == "," else node.sep
        return f"{node.name}{space}({sep.join(self._print(a) for a in node.args)})"

    def _print_Total(self, node: Total) -> str:
        body = self._print(node.body)
        return "sum " + (f"({body})" if operand_brackets(node, node.body) else body)

    def _print_Sign(self, node: Sign) -> str:
        arg = self._print(node.arg)
        return node.sign + (f"({arg})" if operand_brackets(node, node.arg) else arg)

    def _print_Deriv(self, node: Deriv) -> str:
        return f"d{deriv_space(node.sym.name)}{node.sym.name}/d{node.var}"

    def _print_Quantity(self, node: Quantity) -> str:
        return node.text

    def _print_Vector(self, node: Vector) -> str:
        return node.text

    def _print_Words(self, node: Words) -> str:
        text = node.words if node.of is None else f"{self._print(node.of)} {node.words}"
        return text if node.then is None else f"{text} {self._print(node.then)}"

    def _print_Prime(self, node: Prime) -> str:
        inner = self._print(node.arg)
        return (f"({inner})" if precedence(node.arg, False) < ATOM else inner) + "'" * node.count

    def _print_Mat(self, node: Mat) -> str:
        return "[" + "; ".join(" ".join(self._print(x) for x in row) for row in node.rows) + "]"

    def _print_Matrix(self, node: Matrix) -> str:
        rows = ", ".join("[" + ", ".join(x.number for x in row) + "]" for row in node.entries())
        return f"[{rows}] {UNIT_TEXT.get(node.unit, node.unit)}".rstrip()

    def _print_Integral(self, node: Integral) -> str:
        return (f"int_{self._print(node.lower)}^{self._print(node.upper)} "
                f"{self._print(node.body)}")

    def _print_Bracket(self, node: Bracket) -> str:
        inner = ", ".join(self._print(x) for x in node.items)
        return f"[{inner}]" if node.open == "[" else f"({inner})"

    def _print_Pm(self, node: Pm) -> str:
        right = self._print(node.right)
        if precedence(node.right, False) <= ADD:
            right = f"({right})"
        return f"{self._print(node.left)} {node.op} {right}"


def text(expr: Expr) -> str:
    """The plain text of one piece of maths in a sentence."""
    return ProseText().doprint(expr)
