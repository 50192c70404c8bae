"""LaTeX of the formulas a kind wrote, on the design of sympy's printers: one tree.

The printers here print `core.expr`/`core.prose` nodes. `Lowering` first
rewrites a kind's tree into the core nodes it is set as (a substitution's
numbers and units, the brackets `core.expr.needs_brackets` asks for, ...).
Every printer subclasses the one `core.expr.Printer` (``_print_<Node>``
dispatch by class, settings as attributes). `TypesetPrinter` holds what
LaTeX and MathML decide alike: one precedence table and `parenthesize`, the
sign folding of a sum, where a fraction is stacked, when a product's factor is
bracketed, a power's base, a function's argument; its subclasses only spell
the result. `LatexPrinter` typesets (``phidot`` -> ``\\dot{\\phi}``, a/b ->
``\\frac{a}{b}`` in display, ``K x k`` -> ``K \\times k``), `mathml.MathMLPrinter`
writes MathML; plain text is `core.expr.TextPrinter`'s and `core.prose.ProseText`'s.
How names, numbers and units are set is `conventions`.
"""

from __future__ import annotations

import re
from functools import lru_cache
from typing import Any, ClassVar

from ..core import expr as E
from ..core import prose as P
from ..core.expr import Printer as BasePrinter
from .conventions import (
    DEGREES,
    FUNCTIONS,
    LATEX,
    RELATIONS,
    SIGNS,
    NamePart,
    number_parts,
    split_symbol,
    symbol_parts,
    unit_parts,
)

__all__ = [
    "RELATIONS_TEX",
    "LatexPrinter",
    "Lowering",
    "TypesetPrinter",
    "formula_latex",
    "formula_node",
    "latex",
    "number_tex",
    "prose_nodes",
    "split_symbol",
    "substitution_node",
    "symbol_node",
    "symbol_tex",
    "text_escape",
    "unit_tex",
]

#: the levels `parenthesize` asks for, by operator: `core.expr`'s binding strengths
PRECEDENCE = {"Rel": P.Rel.binding, "+": E.ADD, "-": E.ADD, "+-": E.ADD, "-+": E.ADD,
              "*": E.MUL, "/": E.MUL, "x": E.MUL, ".": E.MUL, " ": E.MUL, "Neg": E.NEG,
              "Pow": E.POW, "Atom": E.ATOM}

RELATIONS_TEX = {op: spelt[LATEX] for op, spelt in RELATIONS.items()}
SUM_TEX = {op: spelt[LATEX] for op, spelt in SIGNS.items()}
FUNCTION_TEX = {name: spelt[LATEX] for name, spelt in FUNCTIONS.items()}


# ---- a tree as it is set: the core nodes after `Lowering` ------------------------
#
# The printers below print `core.expr`/`core.prose` nodes. `Lowering` first rewrites a
# kind's tree into the core nodes it is set as (a symbol of a substitution becomes its
# number and unit, a `Let` its symbol or body, brackets a `Bracket`, ...); the
# functions here read such a set tree: a product (`Mul`) is juxtaposition, a `Bracket`
# whose ``open`` ends in "," a list in brackets, a `Quantity`, `Vector` or `Matrix` a
# value with its unit.

#: the operator each binary node is set with
OPS: dict[type, str] = {E.Add: "+", E.Sub: "-", E.Mul: " ", E.Div: "/", P.Cross: "x",
                        P.Dot: "."}
_BUILD: dict[str, Any] = {"+": E.Add, "-": E.Sub, " ": E.Mul, "*": E.Mul, "/": E.Div,
                          "x": P.Cross, ".": P.Dot}


def op_of(node: E.Expr) -> str | None:
    """The operator of a binary node as set (" ": juxtaposition), else None."""
    if node.__class__ is P.Pm:
        return node.op  # type: ignore[attr-defined, no-any-return]
    return OPS.get(node.__class__)


def binop(op: str, left: E.Expr, right: E.Expr) -> E.Expr:
    """The node set as ``left op right``."""
    if op in ("+-", "-+"):
        return P.Pm(left, right, op)
    return _BUILD[op](left, right)  # type: ignore[no-any-return]


def sign_of(node: E.Expr) -> str | None:
    """The sign written before a signed node (``-x``, ``+x``, ``+-x``), else None."""
    if node.__class__ is E.Neg:
        return "-"
    if node.__class__ is P.Sign:
        return node.sign  # type: ignore[attr-defined, no-any-return]
    return None


def operand_of(node: E.Expr) -> E.Expr:
    """What a signed node signs."""
    return node.arg  # type: ignore[attr-defined, no-any-return]


def is_quantity(node: E.Expr) -> bool:
    """A value set with its unit: ``9.815 m/s^2``, ``(0, 1, 0) N m``."""
    return isinstance(node, (P.Quantity, P.Vector, P.Matrix))


def quantity_value(node: Any) -> E.Expr:
    """The value of a quantity, set before its unit."""
    if isinstance(node, P.Quantity):
        return number(node.label)
    if isinstance(node, P.Vector):
        return _vector_items(node)
    return P.Mat(tuple(tuple(_signed(x.number, "") for x in row) for row in node.entries()))


def quantity_unit(node: Any) -> str:
    """The unit of a quantity as spelt (`Lowering` spells a `Quantity`'s)."""
    if isinstance(node, P.Quantity):
        return node.unit
    return E.UNIT_TEXT.get(node.unit, node.unit)  # type: ignore[no-any-return]


def is_list(node: E.Expr) -> bool:
    """A list in brackets: ``(0, 458.1, 0)``, ``[-1, 1]``."""
    return isinstance(node, P.Bracket) and len(node.open) > 1


def grouped(node: E.Expr) -> E.Expr | None:
    """What brackets hold (one node, not a list), else None."""
    if isinstance(node, P.Bracket) and len(node.open) == 1:
        return node.items[0]
    return None


def number(text: str) -> E.Num:
    """A number as written, ``3.869e-05`` (``label``: the text)."""
    try:
        value = float(text)
    except ValueError:
        value = 0.0
    return E.Num(value if value - value == 0 else 0.0, text)


def symbol(name: str) -> E.Sym:
    return E.Sym(name, E.NAMED)


def quantity_node(text: str, unit: str) -> E.Expr:
    """A number as written with its unit as spelt (none: the number)."""
    return P.Quantity(number(text).si, unit, label=text) if unit else number(text)


def _signed(text: str, unit: str) -> E.Expr:
    """``-0.5``, ``2.0 kg``: a number as written, its sign a unary minus."""
    shown = quantity_node(text.lstrip("-"), unit)
    return E.Neg(shown) if text.startswith("-") else shown


def _vector_items(node: P.Vector) -> P.Bracket:
    return P.Bracket(tuple(_signed(n, "") for n in node.numbers), "(,")


def shown_name(node: E.Expr) -> str | None:
    """The name a function is set with (``K`` for ellipk), or None for anything else
    (a power of a trig function: sin^2)."""
    if isinstance(node, E.Call):
        return E.SHOWN_NAMES.get(node.name, node.name)
    if isinstance(node, P.Fn):
        return node.name
    return None


def sin_power(node: E.Expr) -> str:
    """``"2"`` for ``sin^2(x)`` as `Lowering` sets it (a power of sin, cos or tan by a
    number as written, its label), else ""; ``(sin x)^2`` written through a `Let` is a
    power like any other."""
    if node.__class__ is E.Pow and node.right.__class__ is E.Num \
            and node.right.label:  # type: ignore[attr-defined]
        return E.trig_power(node)  # type: ignore[arg-type]
    return ""


def precedence(node: E.Expr) -> int:
    """How tightly a set node binds: `core.expr.precedence`, the one table, but where a
    typeset formula reads otherwise: a number as written is an atom (its sign is a `Neg`),
    ``sin^2 x`` and an integral bind as a product."""
    if node.__class__ is E.Num:
        return E.ATOM
    if node.__class__ is P.Integral or sin_power(node):
        return E.MUL
    return E.precedence(node, False)


# ---- lowering: a kind's tree as the core nodes it is set as ----------------------

class Lowering(BasePrinter):
    """A kind's tree (`core.expr`, `core.prose`) rewritten into the core nodes it is set
    as, with the brackets `core.expr.needs_brackets` asks for as `Bracket` nodes.
    ``values``: the substitution (each symbol its value and unit), else the formula."""

    def operand(self, parent: E.Expr, child: E.Expr, right: bool = False) -> E.Expr:
        node = self._print(child)
        return P.Bracket((node,), "(") if E.needs_brackets(parent, child, right, self.values) \
            else node

    def _print_Sym(self, node: E.Sym) -> E.Expr:
        if not self.values:
            if node.name.startswith("sum "):  # a total over rotors: ``sum I_w`` is set \sum I_w
                return P.Total(symbol(node.name[4:]))
            return node
        text = E.quantity_text(node.si, node.unit)
        value, _, unit = text.partition(" ")
        return _signed(value, unit)

    def _print_Const(self, node: E.Const) -> E.Expr:
        return symbol(node.name)

    def _print_Num(self, node: E.Num) -> E.Expr:
        # a number as the kind wrote it stays (unlabelled: no power of sin^2, `sin_power`)
        return E.Neg(number(node.text.lstrip("-"))) if node.si < 0 else node

    def _print_Let(self, node: E.Let) -> E.Expr:
        return self._print(node.sym if self.values else node.body)

    def _print_Neg(self, node: E.Neg) -> E.Expr:
        if isinstance(node.arg, P.Deriv):  # -dH_O/dt: the sign on the numerator
            rate = self._print(node.arg)
            assert isinstance(rate, E.Div)
            return E.Div(E.Neg(rate.left), rate.right)
        inner = self.operand(node, node.arg)
        if op_of(inner) == " ":
            # -(a b) is set -a b, as the text reads: the sign on the first factor
            chain = []
            while isinstance(inner, E.Mul):
                chain.append(inner.right)
                inner = inner.left
            out: E.Expr = E.Neg(inner)
            for right in reversed(chain):
                out = E.Mul(out, right)
            return out
        return E.Neg(inner)

    def _print_Add(self, node: E.Add) -> E.Expr:
        return E.Add(self.operand(node, node.left), self.operand(node, node.right, True))

    def _print_Sub(self, node: E.Sub) -> E.Expr:
        return E.Sub(self.operand(node, node.left), self.operand(node, node.right, True))

    def _print_Mul(self, node: E.Mul) -> E.Expr:
        parts = [self.operand(node, f, k > 0) for k, f in enumerate(E.factors(node, self.values))]
        out = parts[0]
        for part in parts[1:]:
            out = E.Mul(out, part)
        return out

    def _print_Div(self, node: E.Div) -> E.Expr:
        return E.Div(self.operand(node, node.left), self.operand(node, node.right, True))

    def _print_Pow(self, node: E.Pow) -> E.Expr:
        n = E.trig_power(node)
        if n:  # sin^2(theta)
            call = node.left
            assert isinstance(call, E.Call)
            return E.Pow(E.Call(call.name, tuple(self._print(a) for a in call.args)), number(n))
        return E.Pow(self.operand(node, node.left), self.operand(node, node.right, True))

    def _print_Call(self, node: E.Call) -> E.Expr:
        return E.Call(node.name, tuple(self._print(a) for a in node.args))

    def _print_SumOf(self, node: E.SumOf) -> E.Expr:
        if self.values:
            return self._print(node.expanded())
        body = self._print(node.body)
        return P.Total(P.Bracket((body,), "(") if E.precedence(node.body, False) <= E.ADD
                       else body)

    def _print_Chain(self, node: E.Chain) -> E.Expr:
        if self.values:
            return self._print(node.forms[-1])
        return P.Rel(self._print(node.forms[0]), tuple(("=", self._print(f))
                                                       for f in node.forms[1:]))

    # ---- the typeset-only nodes of sentences (core/prose.py)

    def _print_Rel(self, node: P.Rel) -> E.Expr:
        first = None if node.first is None else self._print(node.first)
        return P.Rel(first, tuple((op, self._print(rhs)) for op, rhs in node.rest))

    def _vector(self, node: E.BinOp) -> E.Expr:
        sides = []
        for child in (node.left, node.right):
            shown = self._print(child)
            sides.append(P.Bracket((shown,), "(") if P.operand_brackets(node, child) else shown)
        return type(node)(sides[0], sides[1])

    def _print_Cross(self, node: P.Cross) -> E.Expr:
        return self._vector(node)

    def _print_Dot(self, node: P.Dot) -> E.Expr:
        return self._vector(node)

    def _print_Fn(self, node: P.Fn) -> E.Expr:
        if node.name == "d/dt":  # the rate of change of its argument
            arg = self._print(node.args[0])
            return E.Mul(E.Div(symbol("d"), symbol("dt")), P.Bracket((arg,), "("))
        if node.name.endswith("'"):  # U_eff''(theta): the primed name, then its arguments
            name = node.name.rstrip("'")
            return E.Mul(P.Prime(symbol(name), len(node.name) - len(name)),
                         P.Bracket(tuple(self._print(a) for a in node.args), "(,"))
        return P.Fn(node.name, tuple(self._print(a) for a in node.args), node.sep)

    def _print_Total(self, node: P.Total) -> E.Expr:
        body = self._print(node.body)
        return P.Total(P.Bracket((body,), "(") if P.operand_brackets(node, node.body) else body)

    def _print_Sign(self, node: P.Sign) -> E.Expr:
        arg = self._print(node.arg)
        return P.Sign(node.sign, P.Bracket((arg,), "(") if P.operand_brackets(node, node.arg)
                      else arg)

    def _print_Deriv(self, node: P.Deriv) -> E.Expr:
        name = node.sym.name
        top: E.Expr = E.Mul(symbol("d"), symbol(name)) if P.deriv_space(name) \
            else symbol("d" + name)
        return E.Div(top, symbol("d" + node.var))  # d theta/dt, dH/dt

    def _print_Quantity(self, node: P.Quantity) -> E.Expr:
        unit = node.text[len(node.number):].strip()
        value, sign, imag = node.number.partition(" + " if " + " in node.number else " - ")
        if imag:  # a - b i: the imaginary part carries the unit
            return binop(sign.strip(), _signed(value, ""), _signed(imag[:-2] + "i", unit))
        return _signed(value, unit)

    def _print_Matrix(self, node: P.Matrix) -> E.Expr:
        return node if quantity_unit(node) else quantity_value(node)

    def _print_Integral(self, node: P.Integral) -> E.Expr:
        return P.Integral(self._print(node.lower), self._print(node.upper),
                          self._print(node.body))

    def _print_Bracket(self, node: P.Bracket) -> E.Expr:
        items = tuple(self._print(x) for x in node.items)
        return P.Bracket(items, node.open if len(items) == 1 else node.open + ",")

    def _print_Pm(self, node: P.Pm) -> E.Expr:
        right = self._print(node.right)
        if E.precedence(node.right, False) <= E.ADD:
            right = P.Bracket((right,), "(")
        return P.Pm(self._print(node.left), right, node.op)

    def _print_Vector(self, node: P.Vector) -> E.Expr:
        return node if quantity_unit(node) else _vector_items(node)

    def _print_Words(self, node: P.Words) -> E.Expr:
        if node.then is not None:  # phidot_slow at 30 deg: the words spaced from both sides
            words: E.Expr = P.Words(node.words + " ") if node.of is None else \
                E.Mul(self._print(node.of), P.Words(f" {node.words} "))
            return E.Mul(words, self._print(node.then))
        if node.of is None:
            return P.Words(node.words)
        return E.Mul(self._print(node.of), P.Words(" " + node.words))

    def _print_Prime(self, node: P.Prime) -> E.Expr:
        return P.Prime(self._print(node.arg), node.count)

    def _print_Mat(self, node: P.Mat) -> E.Expr:
        return P.Mat(tuple(tuple(self._print(x) for x in row) for row in node.rows))


#: a symbol that is one name: ``phidot``, ``theta_0``, ``F_A,weight`` (a part after a comma)
NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]*(,[A-Za-z0-9_]+)?\Z")


def symbol_node(text: str, tree: E.Expr | None = None) -> E.Expr | None:
    """A step's, an answer's or a given's symbol as set: its tree where the kind wrote one,
    one name as that name; None for anything else (not a symbol gyro writes)."""
    if tree is not None:
        return Lowering(values=False).doprint(tree)
    if NAME.match(text):
        return symbol(text)
    return None


def prose_nodes(prose: P.Prose) -> list[str | E.Expr]:
    """A sentence's pieces: words as they are, each tree as it is set."""
    lowering = Lowering(values=False)
    return [p if isinstance(p, str) else lowering.doprint(p) for p in prose.pieces]


def formula_node(expr: E.Expr) -> E.Expr:
    return Lowering(values=False).doprint(expr)  # type: ignore[no-any-return]


def substitution_node(expr: E.Expr) -> E.Expr:
    return Lowering(values=True).doprint(expr)  # type: ignore[no-any-return]


def formula_latex(expr: E.Expr, values: bool = False) -> str:
    """The formula (or its substitution) as LaTeX maths, fractions stacked."""
    return LatexPrinter(True).doprint(Lowering(values).doprint(expr))  # type: ignore[no-any-return]


# ---- text inside LaTeX ------------------------------------------------------

def text_escape(text: str) -> str:
    """Plain text safe in LaTeX text mode: its Unicode maths (``ψ̇``, ``θ₀``, ``√``, ``²``)
    as inline maths, other characters pdflatex cannot set as '?', a line break or tab a
    space and any other control character a '?' (`unicode_tex`)."""
    from .unicode_tex import text_tex

    return text_tex(text)


# ---- symbols ----------------------------------------------------------------

def _spell_tex(part: NamePart) -> str:
    kind = part[0]
    if kind == "greek":
        return "\\" + part[1]
    if kind == "accent":
        return f"\\{part[1]}{{{_spell_tex(part[2])}}}"
    if kind == "differential":
        return r"\mathrm{d}" + _spell_tex(part[1])
    if kind == "word":
        return f"\\mathrm{{{part[1]}}}"
    return str(part[1])  # a letter, digits, one character


@lru_cache(maxsize=4096)  # a worked answer sets the same few symbols and units again and again
def symbol_tex(name: str) -> str:
    """One symbol name in LaTeX: ``psidot_min`` -> ``\\dot{\\psi}_{\\mathrm{min}}``."""
    base, subs = symbol_parts(name)
    out = _spell_tex(base)
    if subs:
        out += "_{" + ",".join(_spell_tex(p) for p in subs) + "}"
    return out


def number_tex(text: str) -> str:
    """``3.869e-05`` -> ``3.869\\times 10^{-5}``."""
    if text.endswith("i"):
        return number_tex(text[:-1]) + r"\,\mathrm{i}"
    sign, mantissa, power = number_parts(text)
    if power is None:
        return text
    return f"{sign}{mantissa}\\times 10^{{{power}}}"


@lru_cache(maxsize=4096)
def unit_tex(unit: str) -> str:
    """A unit upright: ``kg m^2/s`` -> ``\\mathrm{kg\\,m^{2}/s}``."""
    out: list[str] = []
    for kind, part in unit_parts(unit):
        if kind == "space":
            if out:
                out.append(r"\,")
        elif kind == "power":
            out.append(f"^{{{part}}}")
        else:
            out.append(part if kind in ("name", "num") or part in "/*" else "")
    return "\\mathrm{" + "".join(out).replace("*", r"\,") + "}"


# ---- what LaTeX and MathML decide alike ----------------------------------------

def base_needs_brackets(base: E.Expr) -> bool:
    """A power's base in brackets: anything looser than an atom, a power, a quotient, a
    quantity, a number with an exponent."""
    return precedence(base) < PRECEDENCE["Atom"] or isinstance(base, (E.Pow, E.Div)) \
        or is_quantity(base) or (isinstance(base, E.Num) and "e" in base.text.lower())


class TypesetPrinter(BasePrinter):
    """The decisions of typesetting, shared by LaTeX and MathML; a subclass spells them
    (the hooks below). It prints a tree as `Lowering` sets it, one ``_print_<Node>`` per
    core node. ``display``: fractions stacked (a fraction inside one is written on the
    line); otherwise a/b on the line, as inline maths in a sentence."""

    #: how a product's operator is spelt: "/", "x", "." and "*" (a written dot)
    PRODUCTS: ClassVar[dict[str, str]] = {}

    def __init__(self, display: bool = True) -> None:
        super().__init__()
        self.display = display

    def parenthesize(self, node: E.Expr, level: int, strict: bool = False) -> str:
        """The node, in brackets when it binds more loosely than ``level``."""
        p = precedence(node)
        if p < level or (strict and p == level):
            return self.brackets(self._print(node))
        return self._print(node)  # type: ignore[no-any-return]

    # ---- hooks: how the format spells what was decided
    def number(self, text: str) -> str:
        raise NotImplementedError

    def symbol(self, name: str) -> str:
        raise NotImplementedError

    def words(self, text: str) -> str:
        raise NotImplementedError

    def with_unit(self, value: str, unit: str) -> str:
        raise NotImplementedError

    def signed(self, sign: str, inner: str) -> str:
        raise NotImplementedError

    def sum(self, left: str, op: str, right: str) -> str:
        raise NotImplementedError

    def starts_minus(self, node: E.Expr) -> bool:
        """Whether a term after a sign is written starting with a minus (then it is
        bracketed): the one sign rule of both formats, read from the node as set (a
        stacked fraction, a bracket or a subscripted power's base starts otherwise)."""
        while True:
            sign = sign_of(node)
            if sign is not None:
                return sign == "-"
            if isinstance(node, E.Num):
                return node.text.startswith("-")
            op = op_of(node)
            if is_quantity(node):
                value = quantity_value(node)
                if quantity_unit(node) in DEGREES and isinstance(value, E.Num) \
                        and "e" in value.text.lower():
                    return False  # {-1.5\times 10^{-5}}^{\circ}: braced
                node = value
            elif op is not None:
                if op == "/" and self.display:
                    return False  # a stacked fraction
                level = PRECEDENCE["+"] if op in SIGNS else PRECEDENCE["*"]
                left = node.left  # type: ignore[attr-defined]
                if precedence(left) < level:
                    return False  # bracketed
                node = left
            elif isinstance(node, E.Pow) and not sin_power(node):
                base = node.left
                if isinstance(base, (P.Bracket, E.Sym)) or base_needs_brackets(base):
                    return False  # bracketed, braced, or a name
                node = base
            elif isinstance(node, P.Prime):
                if precedence(node.arg) < PRECEDENCE["Atom"]:
                    return False  # bracketed
                node = node.arg
            else:
                return False

    def frac(self, num: str, den: str) -> str:
        raise NotImplementedError

    def infix(self, left: str, op: str, right: str) -> str:
        raise NotImplementedError

    def beside(self, node: E.BinOp, left: str, right: str) -> str:
        """Words beside maths: ``phidot (slow)``, ``at 30 deg``."""
        raise NotImplementedError

    def number_follows(self, node: E.Expr, text: str) -> bool:
        """Whether a juxtaposed factor starts with a number (then a dot is written)."""
        raise NotImplementedError

    def juxtapose(self, node: E.BinOp, left: str, right: str) -> str:
        raise NotImplementedError

    def root(self, inner: str) -> str:
        raise NotImplementedError

    def function(self, name: str, power: str | None) -> str:
        raise NotImplementedError

    def apply(self, head: str, arg: str, bracketed: bool) -> str:
        raise NotImplementedError

    def separator(self, sep: str) -> str:
        raise NotImplementedError

    def relations(self, first: str | None, rest: list[tuple[str, str]]) -> str:
        raise NotImplementedError

    def primed(self, inner: str, count: int) -> str:
        raise NotImplementedError

    def bracketed(self, text: str) -> bool:
        """Whether a printed bracket (a `Bracket`) shows its brackets (a stacked fraction
        in a display does not)."""
        raise NotImplementedError

    def power(self, base: E.Expr, text: str, exp: str) -> str:
        """A power of ``base`` (printed as ``text``, bracketed where it needs) to ``exp``."""
        raise NotImplementedError

    def items(self, texts: list[str]) -> str:
        """The items of a list, without its brackets: ``a, b, c``."""
        raise NotImplementedError

    def magnitude(self, inner: str) -> str:
        """``|x|``."""
        raise NotImplementedError

    def total(self, body: str) -> str:
        """``sum body``."""
        raise NotImplementedError

    def integral(self, lower: str, upper: str, body: str) -> str:
        raise NotImplementedError

    def matrix(self, rows: list[list[str]]) -> str:
        raise NotImplementedError

    def lead(self, op: str, right: str) -> str:
        """A sign and the term after it, with nothing before the sign."""
        raise NotImplementedError

    # ---- the decisions, one per core node
    def _print_Num(self, node: E.Num) -> str:
        return self.number(node.text)

    def _print_Sym(self, node: E.Sym) -> str:
        return self.symbol(node.name)

    def _print_Words(self, node: P.Words) -> str:
        return self.words(node.words)

    def _print_Quantity(self, node: P.Quantity) -> str:
        return self.with_unit(self._print(quantity_value(node)), quantity_unit(node))

    _print_Vector = _print_Quantity
    _print_Matrix = _print_Quantity

    def _print_Neg(self, node: E.Expr) -> str:
        body = operand_of(node)
        inner = self._print(body) if isinstance(body, E.Num) or is_quantity(body) else \
            self.parenthesize(body, PRECEDENCE["Neg"]) if sign_of(body) is None \
            else self.brackets(self._print(body))
        return self.signed(sign_of(node) or "-", inner)

    _print_Sign = _print_Neg

    def _print_BinOp(self, node: Any) -> str:
        op = op_of(node)
        assert op is not None
        if op in SIGNS:
            left = self.parenthesize(node.left, PRECEDENCE["+"])
            return self.sum(left, *self._after_sign(op, node.right))
        if op == "/" and self.display:
            self.display = False  # a fraction inside a fraction is written on the line
            try:
                num, den = self._print(_strip(node.left)), self._print(_strip(node.right))
            finally:
                self.display = True
            return self.frac(num, den)
        left = self.parenthesize(node.left, PRECEDENCE["*"])
        factor = self.parenthesize(node.right, PRECEDENCE["*"], strict=op == "/")
        if sign_of(node.right) is not None:
            factor = self.brackets(factor)
        if op in self.PRODUCTS:
            return self.infix(left, self.PRODUCTS[op], factor)
        # juxtaposition: words beside maths as they are (phidot_slow at 30 deg), a dot
        # before a number
        if beside_text(node):
            return self.beside(node, left, factor)
        if self.number_follows(node.right, factor):
            return self.infix(left, self.PRODUCTS["*"], factor)
        return self.juxtapose(node, left, factor)

    _print_Pm = _print_BinOp

    def _after_sign(self, op: str, right: E.Expr) -> tuple[str, str]:
        """The sign and the term after it, as a sum writes them: the one sign rule (a
        negative term folded into the sign, a term starting with a minus bracketed)."""
        right, op = _fold(right, op)
        strict = op in ("-", "+-", "-+")
        rtext = self.parenthesize(right, PRECEDENCE["+"], strict=strict)
        bracketed = precedence(right) < PRECEDENCE["+"] or \
            (strict and precedence(right) == PRECEDENCE["+"])
        if not bracketed and self.starts_minus(right) and sign_of(right) is None:
            rtext = self.brackets(rtext)
        return op, rtext

    def term(self, sign: str, node: E.Expr) -> str:
        """A term of a sum with its sign, starting a row of a broken display (``- b``)."""
        return self.lead(*self._after_sign(sign, node))

    def _call(self, name: str, args: tuple[E.Expr, ...], sep: str = ",",
              power: E.Expr | None = None) -> str:
        if name == "sqrt":
            return self.root(self._print(_strip(args[0])))
        if name in FUNCTIONS:
            head = self.function(name, None if power is None else self._print(power))
            arg = args[0] if len(args) == 1 else None
            if arg is not None and isinstance(_strip(arg), E.Sym) or \
                    arg is not None and is_quantity(_strip(arg)):
                return self.apply(head, self._print(_strip(arg)), False)
            inner = self._print(_strip(arg)) if arg is not None else \
                self.separator(sep).join(self._print(a) for a in args)
            return self.apply(head, self.brackets(inner), True)
        args_text = self.separator(sep).join(self._print(a) for a in args)
        return self.apply(self.symbol(name), self.brackets(args_text), True)

    def _print_Call(self, node: E.Call) -> str:
        if node.name == "abs":
            return self.magnitude(self._print(node.args[0]))
        return self._call(E.SHOWN_NAMES.get(node.name, node.name), node.args)

    def _print_Fn(self, node: P.Fn) -> str:
        return self._call(node.name, node.args, node.sep)

    def _print_Bracket(self, node: P.Bracket) -> str:
        body = grouped(node)
        inner = self.items([self._print(x) for x in node.items]) if body is None \
            else self._print(body)
        if self.display and isinstance(body, E.Div):
            return inner  # a stacked fraction needs no brackets
        if node.open[0] == "[":
            return self.brackets(inner, "[", "]")
        return self.brackets(inner)

    def _print_Rel(self, node: P.Rel) -> str:
        first = self._print(node.first) if node.first is not None else None
        return self.relations(first, [(op, self._print(rhs)) for op, rhs in node.rest])

    def _print_Pow(self, node: E.Pow) -> str:
        if sin_power(node):  # sin^2(theta)
            call = node.left
            assert isinstance(call, E.Call)
            return self._call(call.name, call.args, power=node.right)
        base = node.left
        text = self._print(base)
        if (isinstance(base, P.Bracket) and not self.bracketed(text)) or \
                (base_needs_brackets(base) and not isinstance(base, P.Bracket)):
            text = self.brackets(text)
        return self.power(base, text, self._print(_strip(node.right)))

    def _print_Prime(self, node: P.Prime) -> str:
        return self.primed(self.parenthesize(node.arg, PRECEDENCE["Atom"]), node.count)

    def _print_Total(self, node: P.Total) -> str:
        return self.total(self._print(node.body))

    def _print_Integral(self, node: P.Integral) -> str:
        return self.integral(self._print(node.lower), self._print(node.upper),
                             self._print(node.body))

    def _print_Mat(self, node: P.Mat) -> str:
        return self.matrix([[self._print(x) for x in row] for row in node.rows])


# ---- LaTeX ------------------------------------------------------------------

class LatexPrinter(TypesetPrinter):
    """LaTeX maths (amsmath). ``display``: fractions stacked; otherwise a/b on the line."""

    PRODUCTS: ClassVar[dict[str, str]] = {"/": "/", "x": " \\times ", ".": " \\cdot ",
                                          "*": " \\cdot "}

    def brackets(self, inner: str, open_: str = "(", close: str = ")") -> str:
        if self.display and any(tall in inner for tall in (r"\frac", r"\sqrt", r"\int",
                                                           r"\sum")):
            return f"\\left{open_}{inner}\\right{close}"
        return f"{open_}{inner}{close}"

    def number(self, text: str) -> str:
        return number_tex(text)

    def symbol(self, name: str) -> str:
        return symbol_tex(name)

    def words(self, text: str) -> str:
        return f"\\text{{{text_escape(text)}}}"

    def with_unit(self, value: str, unit: str) -> str:
        if unit in DEGREES:
            if "\\times" in value:
                value = "{" + value + "}"
            return value + "^{\\circ}"
        return f"{value}\\,{unit_tex(unit)}"

    def signed(self, sign: str, inner: str) -> str:
        return SUM_TEX[sign].replace("\\pm", "\\pm ").replace("\\mp", "\\mp ") + inner

    def sum(self, left: str, op: str, right: str) -> str:
        return f"{left} {self.lead(op, right)}"

    def lead(self, op: str, right: str) -> str:
        return f"{SUM_TEX[op]} {right}"

    def frac(self, num: str, den: str) -> str:
        return f"\\frac{{{num}}}{{{den}}}"

    def infix(self, left: str, op: str, right: str) -> str:
        return f"{left}{op}{right}"

    def beside(self, node: E.BinOp, left: str, right: str) -> str:
        return f"{left} {right}"

    def number_follows(self, node: E.Expr, text: str) -> bool:
        return text[:1].isdigit() or text.startswith("-")

    def juxtapose(self, node: E.BinOp, left: str, right: str) -> str:
        if is_quantity(_rightmost(node.left)):  # a thin space after a quantity
            return f"{left}\\,{right}"
        return f"{left} {right}"

    def bracketed(self, text: str) -> bool:
        return text.startswith(("(", "[", "\\left"))

    def power(self, base: E.Expr, text: str, exp: str) -> str:
        if isinstance(base, E.Sym) and "_" in text:
            text = "{" + text + "}"
        return f"{text}^{{{exp}}}"

    def root(self, inner: str) -> str:
        return f"\\sqrt{{{inner}}}"

    def function(self, name: str, power: str | None) -> str:
        head = FUNCTION_TEX[name]
        return head if power is None else head + f"^{{{power}}}"

    def apply(self, head: str, arg: str, bracketed: bool) -> str:
        return head + arg if bracketed else f"{head} {arg}"

    def separator(self, sep: str) -> str:
        return r" \mid " if sep == "|" else ", "

    def relations(self, first: str | None, rest: list[tuple[str, str]]) -> str:
        parts = [first] if first is not None else []
        parts += [f"{RELATIONS_TEX[op]} {rhs}" for op, rhs in rest]
        return " ".join(parts)

    def primed(self, inner: str, count: int) -> str:
        return inner + "'" * count

    def items(self, texts: list[str]) -> str:
        return ", ".join(texts)

    def magnitude(self, inner: str) -> str:
        if self.display and r"\frac" in inner:
            return f"\\left|{inner}\\right|"
        return f"\\lvert {inner}\\rvert"

    def total(self, body: str) -> str:
        return r"\sum " + body

    def integral(self, lower: str, upper: str, body: str) -> str:
        return f"\\int_{{{lower}}}^{{{upper}}} {body}"

    def matrix(self, rows: list[list[str]]) -> str:
        body = " \\\\ ".join(" & ".join(row) for row in rows)
        return f"\\begin{{bmatrix}} {body} \\end{{bmatrix}}"


# ---- shared ---------------------------------------------------------------

def _strip(node: E.Expr) -> E.Expr:
    """Round brackets that a fraction, a root or an exponent makes redundant."""
    while isinstance(node, P.Bracket) and node.open == "(":
        node = node.items[0]
    return node


def _rightmost(node: E.Expr) -> E.Expr:
    while isinstance(node, E.Mul):
        node = node.right
    return node


def beside_text(node: E.Expr) -> bool:
    """True for words juxtaposed with maths (``phidot (slow)``, ``at 30 deg``): no product."""
    if not isinstance(node, E.Mul):
        return False
    first = node.right
    while isinstance(first, E.Mul):
        first = first.left
    return isinstance(_rightmost(node.left), P.Words) or isinstance(first, P.Words)


def _fold(right: E.Expr, op: str) -> tuple[E.Expr, str]:
    """``a + (-b) c`` -> ``a - b c``; ``a - (-b)`` -> ``a + b``: no ``+ -`` in print."""
    flip = {"+": "-", "-": "+"}
    if op not in flip:
        return right, op
    body = grouped(right)
    inner = body if isinstance(body, E.Neg) and \
        (isinstance(body.arg, E.Num) or is_quantity(body.arg)) else None
    if isinstance(right, E.Neg):
        return right.arg, flip[op]
    if inner is not None:
        return inner.arg, flip[op]
    # a product whose first factor is negative
    chain = []
    node = right
    while isinstance(node, (E.Mul, E.Div)):
        chain.append(node)
        node = node.left
    if chain and isinstance(node, E.Neg):
        rebuilt = node.arg
        for link in reversed(chain):
            rebuilt = type(link)(rebuilt, link.right)
        return rebuilt, flip[op]
    return right, op


def latex(node: E.Expr, display: bool = True) -> str:
    """A tree as `Lowering` sets it, in LaTeX."""
    return LatexPrinter(display).doprint(node)  # type: ignore[no-any-return]
