"""MathML for the formulas of an HTML page: core trees as `mathprint.Lowering` sets them.

`MathMLPrinter` spells what `mathprint.TypesetPrinter` decides (the precedence
table, brackets, signs, fractions, the LaTeX printer's decisions) in MathML
Core, which browsers render natively and screen readers speak: ``phidot`` is
phi with a dot accent, ``theta_0`` theta sub 0, ``m g l`` a product joined by
invisible times, ``sin(theta)`` a function application, ``a / b`` a stacked
fraction in a display. Every name and number from a problem file is
HTML-escaped here. Names, numbers and units follow `conventions`.
"""

from __future__ import annotations

import re
from functools import lru_cache
from html import escape
from typing import ClassVar

from ..core import expr as E
from .conventions import (
    DEGREES,
    FUNCTIONS,
    MATHML,
    SIGNS,
    NamePart,
    number_parts,
    symbol_parts,
    unit_parts,
)
from .conventions import RELATIONS as _RELATIONS
from .mathprint import (
    PRECEDENCE,
    TypesetPrinter,
    _rightmost,
    beside_text,
    is_quantity,
    op_of,
    shown_name,
    sign_of,
)

__all__ = ["PRECEDENCE", "MathMLPrinter", "math_element", "symbol_mathml", "tree_mathml"]

GREEK_LETTERS = {
    "alpha": "α", "beta": "β", "gamma": "γ", "delta": "δ", "epsilon": "ε", "zeta": "ζ",
    "eta": "η", "theta": "θ", "iota": "ι", "kappa": "κ", "lambda": "λ", "mu": "μ", "nu": "ν",
    "xi": "ξ", "pi": "π", "rho": "ρ", "sigma": "σ", "tau": "τ", "phi": "ϕ", "chi": "χ",
    "psi": "ψ", "omega": "ω", "Gamma": "Γ", "Delta": "Δ", "Theta": "Θ", "Lambda": "Λ",
    "Xi": "Ξ", "Pi": "Π", "Sigma": "Σ", "Phi": "Φ", "Psi": "Ψ", "Omega": "Ω"}
RELATIONS = {op: spelt[MATHML] for op, spelt in _RELATIONS.items()}
SUMS = {op: spelt[MATHML] for op, spelt in SIGNS.items()}
ACCENTS = {"dot": "˙", "ddot": "¨"}
INVISIBLE_TIMES = "<mo>&#x2062;</mo>"
APPLY = "<mo>&#x2061;</mo>"
THIN = '<mspace width="0.1667em"/>'


def _mi(name: str, upright: bool = False) -> str:
    variant = ' mathvariant="normal"' if upright and len(name) == 1 else ""
    return f"<mi{variant}>{escape(name)}</mi>"


def _mo(op: str) -> str:
    return f"<mo>{op}</mo>"


def _row(*parts: str) -> str:
    parts = tuple(p for p in parts if p)
    if len(parts) == 1 and _one_element(parts[0]):
        return parts[0]
    return "<mrow>" + "".join(parts) + "</mrow>"


def _one_element(markup: str) -> bool:
    """True when ``markup`` is a single element (no need for an <mrow> around it)."""
    if not markup.startswith("<") or markup.startswith("<mspace"):
        return False
    name = markup[1:markup.index(">")].split()[0].rstrip("/")
    if markup.endswith("/>") and markup.count("<") == 1:
        return True
    depth = 0
    for m in re.finditer(r"<(/?)([a-z]+)[^>]*?(/?)>", markup):
        if m.group(3):
            continue
        depth += -1 if m.group(1) else 1
        if depth == 0:
            return m.end() == len(markup) and m.group(2) == name
    return False


# ---- symbols, numbers, units ----------------------------------------------------

def _spell(part: NamePart, sub: bool = False) -> str:
    kind = part[0]
    if kind == "greek":
        return _mi(GREEK_LETTERS[part[1]], upright=part[1][0].isupper())
    if kind == "accent":
        return f'<mover accent="true">{_spell(part[2])}<mo>{ACCENTS[part[1]]}</mo></mover>'
    if kind == "differential":
        return _row(_mi("d", upright=True), _spell(part[1]))
    if kind == "digits":
        return f"<mn>{escape(part[1])}</mn>"
    if kind == "char":  # one character of a subscript: a letter italic, a sign upright
        return _mi(part[1], upright=not part[1].isalpha())
    return _mi(part[1])  # a letter; a multi-letter name is upright


@lru_cache(maxsize=4096)  # a worked answer sets the same few symbols and units again and again
def symbol_mathml(name: str) -> str:
    """One symbol name: ``psidot_min`` -> psi with a dot, sub min."""
    base, subs = symbol_parts(name)
    out = _spell(base)
    if subs:
        sub = _mo(",").join(_spell(p) for p in subs)
        out = f"<msub>{out}{_row(sub) if len(subs) > 1 else sub}</msub>"
    return out


def number_mathml(text: str) -> str:
    """``3.869e-05`` -> 3.869 × 10 to the −5."""
    if text.endswith("i"):
        return _row(number_mathml(text[:-1]), THIN, _mi("i", upright=True))
    sign, mantissa, power = number_parts(text)
    minus = _mo("−") if sign else ""
    if power is None:
        digits = f"<mn>{escape(mantissa)}</mn>"
        return _row(minus, digits) if sign else digits
    exp = _row(_mo("−"), f"<mn>{-power}</mn>") if power < 0 else f"<mn>{power}</mn>"
    body = _row(f"<mn>{escape(mantissa)}</mn>", _mo("×"), f"<msup><mn>10</mn>{exp}</msup>")
    return _row(minus, body) if sign else body


@lru_cache(maxsize=4096)
def unit_mathml(unit: str) -> str:
    """A unit upright: ``kg m^2/s`` -> kg, thin space, m squared, /, s."""
    if unit in DEGREES:
        return _mi("°", upright=True)
    out: list[str] = []
    for kind, part in unit_parts(unit):
        if kind == "space":
            if out:
                out.append(THIN)
        elif kind == "power":
            if not out:  # a power of nothing: its digits as they are
                out += [f"<mn>{escape(d)}</mn>" for d in re.findall(r"[\d.]+", part)]
                continue
            power = f"<mn>{escape(part)}</mn>" if not part.startswith("-") else \
                _row(_mo("−"), f"<mn>{escape(part[1:])}</mn>")
            out[-1] = f"<msup>{out[-1]}{power}</msup>"
        elif kind == "name":
            out.append(_mi(part, upright=True))
        elif kind == "num":
            out.append(f"<mn>{escape(part)}</mn>")
        elif part == "/":
            out.append('<mo lspace="0" rspace="0">/</mo>')
        elif part == "*":
            out.append(THIN)
        elif part in "()":
            out.append(_mo(part))
    return _row(*out)


# ---- the printer ----------------------------------------------------------------

class MathMLPrinter(TypesetPrinter):
    """MathML Core presentation markup (the content of a ``<math>`` element).

    ``display``: fractions stacked (a fraction inside one is written on the line);
    otherwise a/b on the line, as inline maths in a sentence.
    """

    PRODUCTS: ClassVar[dict[str, str]] = {"/": "<mo>/</mo>", "x": "<mo>×</mo>",
                                          ".": "<mo>⋅</mo>", "*": "<mo>⋅</mo>"}

    def brackets(self, inner: str, open_: str = "(", close: str = ")") -> str:
        return _row(_mo(open_), inner, _mo(close))

    def number(self, text: str) -> str:
        return number_mathml(text)

    def symbol(self, name: str) -> str:
        return symbol_mathml(name)

    def words(self, text: str) -> str:
        return f"<mtext>{escape(text)}</mtext>"

    def with_unit(self, value: str, unit: str) -> str:
        if unit in DEGREES:
            return _row(value, unit_mathml(unit))
        return _row(value, THIN, unit_mathml(unit))

    def signed(self, sign: str, inner: str) -> str:
        return _row(_mo(SUMS[sign]), inner)

    def sum(self, left: str, op: str, right: str) -> str:
        return _row(left, _mo(SUMS[op]), right)

    def lead(self, op: str, right: str) -> str:
        return _row(_mo(SUMS[op]), right)

    def frac(self, num: str, den: str) -> str:
        return f"<mfrac>{_row(num)}{_row(den)}</mfrac>"

    def infix(self, left: str, op: str, right: str) -> str:
        return _row(left, op, right)

    def beside(self, node: E.BinOp, left: str, right: str) -> str:
        # words beside maths, one row: phidot_slow at 30 deg
        return _row(*(text[6:-7] if beside_text(side) and text.startswith("<mrow>") else text
                      for text, side in ((left, node.left), (right, node.right))))

    def number_follows(self, node: E.Expr, text: str) -> bool:
        return _starts_number(node)

    def juxtapose(self, node: E.BinOp, left: str, right: str) -> str:
        if is_quantity(_rightmost(node.left)) or _starts_function(node.right):
            return _row(left, THIN, INVISIBLE_TIMES, right)
        return _row(left, INVISIBLE_TIMES, right)

    def bracketed(self, text: str) -> bool:
        return True  # a Group's own brackets, or a stacked fraction that needs none

    def power(self, base: E.Expr, text: str, exp: str) -> str:
        exp = _row(exp)
        if isinstance(base, E.Sym) and text.startswith("<msub>") and text.endswith("</msub>"):
            return "<msubsup>" + text[len("<msub>"):-len("</msub>")] + exp + "</msubsup>"
        return f"<msup>{text}{exp}</msup>"

    def root(self, inner: str) -> str:
        return f"<msqrt>{inner}</msqrt>"

    def function(self, name: str, power: str | None) -> str:
        head = _mi(FUNCTIONS[name][MATHML])
        return head if power is None else f"<msup>{head}{_row(power)}</msup>"

    def apply(self, head: str, arg: str, bracketed: bool) -> str:
        return _row(head, APPLY, arg)

    def separator(self, sep: str) -> str:
        return _mo("∣") if sep == "|" else _mo(",")

    def relations(self, first: str | None, rest: list[tuple[str, str]]) -> str:
        parts = [first] if first is not None else []
        for op, rhs in rest:
            parts += [_mo(RELATIONS[op]), rhs]
        return _row(*parts)

    def primed(self, inner: str, count: int) -> str:
        primes = {1: "′", 2: "″", 3: "‴"}.get(count, "′" * count)
        return _row(inner, _mo(primes))

    def items(self, texts: list[str]) -> str:
        return _row(*_joined(texts, _mo(",")))

    def magnitude(self, inner: str) -> str:
        return _row(_mo("|"), inner, _mo("|"))

    def total(self, body: str) -> str:
        return _row('<mo largeop="true">∑</mo>', body)

    def integral(self, lower: str, upper: str, body: str) -> str:
        return _row(f"<msubsup><mo>∫</mo>{_row(lower)}{_row(upper)}</msubsup>", body)

    def matrix(self, rows: list[list[str]]) -> str:
        body = "".join("<mtr>" + "".join(f"<mtd>{x}</mtd>" for x in row) + "</mtr>"
                       for row in rows)
        return self.brackets(f"<mtable>{body}</mtable>", "[", "]")


def _joined(items: list[str], sep: str) -> list[str]:
    out: list[str] = []
    for i, item in enumerate(items):
        if i:
            out.append(sep)
        out.append(item)
    return out


def _first(node: E.Expr) -> E.Expr:
    """The node a product, quotient, sum or power is written starting with."""
    while op_of(node) is not None or isinstance(node, E.Pow):
        node = node.left  # type: ignore[attr-defined]
    return node


def _starts_number(node: E.Expr) -> bool:
    """Juxtaposition before a number (``2 (3)``) is written with a dot."""
    first = _first(node)
    return isinstance(first, E.Num) or is_quantity(first) or sign_of(first) is not None


def _starts_function(node: E.Expr) -> bool:
    """``m g l sin(theta)``: a thin space before the function's name, as LaTeX sets it."""
    return shown_name(_first(node)) in FUNCTIONS



# ---- elements -----------------------------------------------------------------

def math_element(inner: str, display: bool = False, label: str | None = None) -> str:
    """A ``<math>`` element around presentation markup."""
    attrs = ' display="block"' if display else ""
    if label:
        attrs += f' alttext="{escape(label)}"'
    return f"<math{attrs}>{inner}</math>"


def tree_mathml(node: E.Expr, display: bool = False) -> str:
    """The content of a ``<math>`` element for one tree."""
    return MathMLPrinter(display).doprint(node)

