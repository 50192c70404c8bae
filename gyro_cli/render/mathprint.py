"""Printers for `mathtree` expressions, on the design of sympy's printers.

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

from typing import Any, ClassVar

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
from .mathtree import (
    Abs,
    BinOp,
    Call,
    Group,
    Neg,
    Node,
    Num,
    Pow,
    Prime,
    Quantity,
    Rel,
    Sym,
    Text,
    Tuple,
)

__all__ = [
    "RELATIONS_TEX",
    "LatexPrinter",
    "TypesetPrinter",
    "latex",
    "number_tex",
    "split_symbol",
    "symbol_tex",
    "text_escape",
    "unit_tex",
]

#: binding strength, loosest first
PRECEDENCE = {"Rel": 0, "+": 10, "-": 10, "+-": 10, "-+": 10, "*": 20, "/": 20, "x": 20,
              ".": 20, " ": 20, "Neg": 25, "Pow": 30, "Prime": 40, "Atom": 50}

RELATIONS_TEX = {op: spelt[LATEX] for op, spelt in RELATIONS.items()}
SUM_TEX = {op: spelt[LATEX] for op, spelt in SIGNS.items()}
FUNCTION_TEX = {name: spelt[LATEX] for name, spelt in FUNCTIONS.items()}


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
    if type(node).__name__ in ("Sum", "Integral"):
        return PRECEDENCE["*"]
    if isinstance(node, Quantity):
        return PRECEDENCE["*"]
    return PRECEDENCE["Atom"]


class Printer(BasePrinter):
    """A printer of typesetting nodes: `parenthesize` by the precedence table."""

    def parenthesize(self, node: Node, level: int, strict: bool = False) -> str:
        """The node, in brackets when it binds more loosely than ``level``."""
        p = precedence(node)
        if p < level or (strict and p == level):
            return self.brackets(self._print(node))
        return self._print(node)


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

def base_needs_brackets(base: Node) -> bool:
    """A power's base in brackets: anything looser than an atom, a power, a quotient, a
    quantity, a number with an exponent."""
    return precedence(base) < PRECEDENCE["Atom"] or isinstance(base, Pow) \
        or (isinstance(base, BinOp) and base.op == "/") or isinstance(base, Quantity) \
        or (isinstance(base, Num) and "e" in base.text.lower())


class TypesetPrinter(Printer):
    """The decisions of typesetting, shared by LaTeX and MathML; a subclass spells them
    (the hooks below). ``display``: fractions stacked (a fraction inside one is written on
    the line); otherwise a/b on the line, as inline maths in a sentence."""

    #: how a product's operator is spelt: "/", "x", "." and "*" (a written dot)
    PRODUCTS: ClassVar[dict[str, str]] = {}

    def __init__(self, display: bool = True) -> None:
        super().__init__()
        self.display = display

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

    def starts_minus(self, node: Node) -> bool:
        """Whether a term after a sign is written starting with a minus (then it is
        bracketed): the one sign rule of both formats, read from the node as printed (a
        stacked fraction, a bracket or a subscripted power's base starts otherwise)."""
        while True:
            if isinstance(node, Neg):
                return node.sign == "-"
            if isinstance(node, Num):
                return node.text.startswith("-")
            if isinstance(node, Quantity):
                if node.unit in DEGREES and isinstance(node.value, Num) \
                        and "e" in node.value.text.lower():
                    return False  # {-1.5\times 10^{-5}}^{\circ}: braced
                node = node.value
            elif isinstance(node, BinOp):
                if node.op == "/" and self.display:
                    return False  # a stacked fraction
                level = PRECEDENCE["+"] if node.op in SIGNS else PRECEDENCE["*"]
                if precedence(node.left) < level:
                    return False  # bracketed
                node = node.left
            elif isinstance(node, Pow):
                base = node.base
                if isinstance(base, Group) or base_needs_brackets(base) or isinstance(base, Sym):
                    return False  # bracketed, braced, or a name
                node = base
            elif isinstance(node, Tuple) and node.items:
                node = node.items[0]
            elif isinstance(node, Prime):
                if precedence(node.body) < PRECEDENCE["Atom"]:
                    return False  # bracketed
                node = node.body
            else:
                return False

    def frac(self, num: str, den: str) -> str:
        raise NotImplementedError

    def infix(self, left: str, op: str, right: str) -> str:
        raise NotImplementedError

    def beside(self, node: BinOp, left: str, right: str) -> str:
        """Words beside maths: ``phidot (slow)``, ``at 30 deg``."""
        raise NotImplementedError

    def number_follows(self, node: Node, text: str) -> bool:
        """Whether a juxtaposed factor starts with a number (then a dot is written)."""
        raise NotImplementedError

    def juxtapose(self, node: BinOp, left: str, right: str) -> str:
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
        """Whether a printed bracket (a `Group`) shows its brackets (a stacked fraction
        in a display does not)."""
        raise NotImplementedError

    def power(self, base: Node, text: str, exp: str) -> str:
        """A power of ``base`` (printed as ``text``, bracketed where it needs) to ``exp``."""
        raise NotImplementedError

    # ---- the decisions
    def _print_Num(self, node: Num) -> str:
        return self.number(node.text)

    def _print_Sym(self, node: Sym) -> str:
        return self.symbol(node.name)

    def _print_Text(self, node: Text) -> str:
        return self.words(node.text)

    def _print_Quantity(self, node: Quantity) -> str:
        return self.with_unit(self._print(node.value), node.unit)

    def _print_Neg(self, node: Neg) -> str:
        body = node.body
        inner = self._print(body) if isinstance(body, (Num, Quantity)) else \
            self.parenthesize(body, PRECEDENCE["Neg"]) if not isinstance(body, Neg) \
            else self.brackets(self._print(body))
        return self.signed(node.sign, inner)

    def _print_BinOp(self, node: BinOp) -> str:
        op = node.op
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
        if isinstance(node.right, Neg):
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

    def _after_sign(self, op: str, right: Node) -> tuple[str, str]:
        """The sign and the term after it, as a sum writes them: the one sign rule (a
        negative term folded into the sign, a term starting with a minus bracketed)."""
        right, op = _fold(right, op)
        strict = op in ("-", "+-", "-+")
        rtext = self.parenthesize(right, PRECEDENCE["+"], strict=strict)
        bracketed = precedence(right) < PRECEDENCE["+"] or \
            (strict and precedence(right) == PRECEDENCE["+"])
        if not bracketed and self.starts_minus(right) and not isinstance(right, Neg):
            rtext = self.brackets(rtext)
        return op, rtext

    def term(self, sign: str, node: Node) -> str:
        """A term of a sum with its sign, starting a row of a broken display (``- b``)."""
        return self.lead(*self._after_sign(sign, node))

    def lead(self, op: str, right: str) -> str:
        """A sign and the term after it, with nothing before the sign."""
        raise NotImplementedError

    def _print_Call(self, node: Call) -> str:
        args = self.separator(node.sep).join(self._print(a) for a in node.args)
        if node.name == "sqrt":
            return self.root(self._print(_strip(node.args[0])))
        if node.name in FUNCTIONS:
            head = self.function(node.name, None if node.power is None
                                 else self._print(node.power))
            arg = node.args[0] if len(node.args) == 1 else None
            if arg is not None and (not node.parens or isinstance(_strip(arg), (Sym, Quantity))):
                return self.apply(head, self._print(_strip(arg)), False)
            inner = self._print(_strip(arg)) if arg is not None else args
            return self.apply(head, self.brackets(inner), True)
        return self.apply(self.symbol(node.name), self.brackets(args), True)

    def _print_Group(self, node: Group) -> str:
        inner = self._print(node.body)
        if self.display and isinstance(node.body, BinOp) and node.body.op == "/":
            return inner  # a stacked fraction needs no brackets
        if node.open == "[":
            return self.brackets(inner, "[", "]")
        return self.brackets(inner)

    def _print_Rel(self, node: Rel) -> str:
        first = self._print(node.first) if node.first is not None else None
        return self.relations(first, [(op, self._print(rhs)) for op, rhs in node.rest])

    def _print_Pow(self, node: Pow) -> str:
        base = node.base
        text = self._print(base)
        if (isinstance(base, Group) and not self.bracketed(text)) or \
                (base_needs_brackets(base) and not isinstance(base, Group)):
            text = self.brackets(text)
        return self.power(base, text, self._print(_strip(node.exp)))

    def _print_Prime(self, node: Any) -> str:
        return self.primed(self.parenthesize(node.body, PRECEDENCE["Atom"]), node.count)


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

    def beside(self, node: BinOp, left: str, right: str) -> str:
        return f"{left} {right}"

    def number_follows(self, node: Node, text: str) -> bool:
        return text[:1].isdigit() or text.startswith("-")

    def juxtapose(self, node: BinOp, left: str, right: str) -> str:
        if isinstance(_rightmost(node.left), Quantity):  # a thin space after a quantity
            return f"{left}\\,{right}"
        return f"{left} {right}"

    def bracketed(self, text: str) -> bool:
        return text.startswith(("(", "[", "\\left"))

    def power(self, base: Node, text: str, exp: str) -> str:
        if isinstance(base, Sym) and "_" in text:
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

    def _print_Tuple(self, node: Tuple) -> str:
        return ", ".join(self._print(x) for x in node.items)

    def _print_Abs(self, node: Abs) -> str:
        inner = self._print(node.body)
        if self.display and r"\frac" in inner:
            return f"\\left|{inner}\\right|"
        return f"\\lvert {inner}\\rvert"

    def _print_Sum(self, node: Any) -> str:
        return r"\sum " + self._print(node.body)

    def _print_Integral(self, node: Any) -> str:
        return (f"\\int_{{{self._print(node.lower)}}}^{{{self._print(node.upper)}}} "
                f"{self._print(node.body)}")

    def _print_Matrix(self, node: Any) -> str:
        rows = " \\\\ ".join(" & ".join(self._print(x) for x in row) for row in node.rows)
        return f"\\begin{{bmatrix}} {rows} \\end{{bmatrix}}"


# ---- shared ---------------------------------------------------------------

def _strip(node: Node) -> Node:
    """Round brackets that a fraction, a root or an exponent makes redundant."""
    while isinstance(node, Group) and node.open == "(" and not isinstance(node.body, Tuple):
        node = node.body
    return node


def _rightmost(node: Node) -> Node:
    while isinstance(node, BinOp) and node.op == " ":
        node = node.right
    return node


def beside_text(node: Node) -> bool:
    """True for words juxtaposed with maths (``phidot (slow)``, ``at 30 deg``): no product."""
    if not (isinstance(node, BinOp) and node.op == " "):
        return False
    first = node.right
    while isinstance(first, BinOp) and first.op == " ":
        first = first.left
    return isinstance(_rightmost(node.left), Text) or isinstance(first, Text)


def _fold(right: Node, op: str) -> tuple[Node, str]:
    """``a + (-b) c`` -> ``a - b c``; ``a - (-b)`` -> ``a + b``: no ``+ -`` in print."""
    flip = {"+": "-", "-": "+"}
    if op not in flip:
        return right, op
    inner = right.body if isinstance(right, Group) and isinstance(right.body, Neg) \
        and right.body.sign == "-" and isinstance(right.body.body, (Num, Quantity)) else None
    if isinstance(right, Neg) and right.sign == "-":
        return right.body, flip[op]
    if inner is not None:
        return inner.body, flip[op]
    # a product whose first factor is negative
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


def latex(node: Node, display: bool = True) -> str:
    return LatexPrinter(display).doprint(node)

