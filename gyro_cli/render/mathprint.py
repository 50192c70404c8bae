"""Printers for `mathtree` expressions, on the design of sympy's printers.

One base `Printer` dispatches ``_print_<Node>`` by class name and holds one
precedence table and `parenthesize`. `LatexPrinter` typesets (``phidot`` ->
``\\dot{\\phi}``, a/b -> ``\\frac{a}{b}`` in display, ``K x k`` -> ``K \\times
k``); `TextPrinter` writes the plain form back (``phidot sin(theta)``), one
canonical spelling per tree, so ``parse(text(tree)) == tree``.

Symbol names: Greek names become Greek letters; a trailing ``dot``/``ddot``
an accent; trailing digits or what follows ``_`` a subscript (``theta0`` and
``theta_0`` -> theta sub 0, ``u1`` -> u sub 1); a multi-letter subscript
is upright (``psidot_min`` -> psi-dot sub min); ``dH``, ``dtheta`` a
differential (upright d).
"""

from __future__ import annotations

import re

from .mathtree import GREEK, _symbolic, dotted, tokens
from .mathtree import (Abs, BinOp, Call, Group, Neg, Node, Num, Pow, Quantity, Rel, Sym, Text,
                       Tuple)

#: binding strength, loosest first
PRECEDENCE = {"Rel": 0, "+": 10, "-": 10, "+-": 10, "-+": 10, "*": 20, "/": 20, "x": 20,
              ".": 20, " ": 20, "Neg": 25, "Pow": 30, "Prime": 40, "Atom": 50}

RELATIONS_TEX = {"=": "=", ">=": r"\ge", "<=": r"\le", "<": "<", ">": ">", ">>": r"\gg",
                 "<<": r"\ll", "->": r"\to", "~": r"\approx", "!=": r"\ne"}
SUM_TEX = {"+": "+", "-": "-", "+-": r"\pm", "-+": r"\mp"}
FUNCTION_TEX = {"sin": r"\sin", "cos": r"\cos", "tan": r"\tan", "cot": r"\cot", "sec": r"\sec",
                "csc": r"\csc", "exp": r"\exp", "ln": r"\ln", "log": r"\log", "sinh": r"\sinh",
                "cosh": r"\cosh", "tanh": r"\tanh", "det": r"\det", "arcsin": r"\arcsin",
                "arccos": r"\arccos", "arctan": r"\arctan", "asin": r"\arcsin",
                "acos": r"\arccos", "atan": r"\arctan", "max": r"\max", "min": r"\min",
                "atan2": r"\operatorname{atan2}", "Re": r"\operatorname{Re}",
                "Im": r"\operatorname{Im}", "sign": r"\operatorname{sign}"}


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


class Printer:
    """Dispatch on the node's class: ``_print_Sym`` prints a Sym."""

    def doprint(self, node: Node) -> str:
        return self._print(node)

    def _print(self, node: Node) -> str:
        method = getattr(self, f"_print_{type(node).__name__}")
        return method(node)

    def parenthesize(self, node: Node, level: int, strict: bool = False) -> str:
        """The node, in brackets when it binds more loosely than ``level``."""
        p = precedence(node)
        if p < level or (strict and p == level):
            return self.brackets(self._print(node))
        return self._print(node)

    def brackets(self, inner: str) -> str:
        return f"({inner})"


# ---- text inside LaTeX ------------------------------------------------------

def text_escape(text: str) -> str:
    """Plain text safe in LaTeX text mode: its Unicode maths (``ψ̇``, ``θ₀``, ``√``, ``²``)
    as inline maths, other characters pdflatex cannot set as '?', a line break or tab a
    space and any other control character a '?' (`unicode_tex`)."""
    from .unicode_tex import text_tex

    return text_tex(text)


# ---- symbols ----------------------------------------------------------------

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


def _base_tex(base: str) -> str:
    if base in GREEK:
        return "\\" + base
    d = dotted(base)
    if d:
        return f"\\{d[1]}{{{_base_tex(d[0])}}}"
    if len(base) == 1:
        return base
    if base[0] == "d" and _symbolic(base[1:]):
        return r"\mathrm{d}" + _base_tex(base[1:])
    return f"\\mathrm{{{base}}}"


def _sub_tex(part: str) -> str:
    if part.isdigit() or len(part) == 1:
        return part
    if part in GREEK or dotted(part):
        return _base_tex(part)
    return f"\\mathrm{{{part}}}"


def symbol_tex(name: str) -> str:
    """One symbol name in LaTeX: ``psidot_min`` -> ``\\dot{\\psi}_{\\mathrm{min}}``."""
    base, subs = split_symbol(name)
    out = _base_tex(base)
    if subs:
        out += "_{" + ",".join(_sub_tex(p) for p in subs) + "}"
    return out


def number_tex(text: str) -> str:
    """``3.869e-05`` -> ``3.869\\times 10^{-5}``."""
    if text.endswith("i"):
        return number_tex(text[:-1]) + r"\,\mathrm{i}"
    mantissa, _, exponent = text.lower().partition("e")
    if not exponent:
        return text
    return f"{mantissa}\\times 10^{{{int(exponent)}}}"


def unit_tex(unit: str) -> str:
    """A unit upright: ``kg m^2/s`` -> ``\\mathrm{kg\\,m^{2}/s}``."""
    out = []
    toks = tokens(unit)
    k = 0
    while k < len(toks):
        t = toks[k]
        if t.space and out:
            out.append(r"\,")
        if t.text == "^":
            exp = ""
            k += 1
            while k < len(toks) and (toks[k].text == "-" or toks[k].kind == "num"):
                exp += toks[k].text
                k += 1
            out.append(f"^{{{exp}}}")
            continue
        out.append(t.text if t.kind in ("name", "num") or t.text in "/*" else "")
        k += 1
    return "\\mathrm{" + "".join(out).replace("*", r"\,") + "}"


# ---- LaTeX ------------------------------------------------------------------

class LatexPrinter(Printer):
    """LaTeX maths (amsmath). ``display``: fractions stacked; otherwise a/b on the line."""

    def __init__(self, display: bool = True) -> None:
        self.display = display

    def brackets(self, inner: str, open_: str = "(", close: str = ")") -> str:
        if self.display and any(tall in inner for tall in (r"\frac", r"\sqrt", r"\int",
                                                           r"\sum")):
            return f"\\left{open_}{inner}\\right{close}"
        return f"{open_}{inner}{close}"

    def _print_Num(self, node: Num) -> str:
        return number_tex(node.text)

    def _print_Sym(self, node: Sym) -> str:
        return symbol_tex(node.name)

    def _print_Text(self, node: Text) -> str:
        return f"\\text{{{text_escape(node.text)}}}"

    def _print_Tex(self, node) -> str:
        return node.latex

    def _print_Quantity(self, node: Quantity) -> str:
        value = self._print(node.value)
        if node.unit in ("deg", "degree", "degrees"):
            if "\\times" in value:
                value = "{" + value + "}"
            return value + "^{\\circ}"
        return f"{value}\\,{unit_tex(node.unit)}"

    def _print_Neg(self, node: Neg) -> str:
        body = node.body
        inner = self._print(body) if isinstance(body, (Num, Quantity)) else \
            self.parenthesize(body, PRECEDENCE["Neg"]) if not isinstance(body, Neg) \
            else self.brackets(self._print(body))
        return SUM_TEX[node.sign].replace("\\pm", "\\pm ").replace("\\mp", "\\mp ") + inner

    def _print_BinOp(self, node: BinOp) -> str:
        op = node.op
        if op in SUM_TEX:
            left = self.parenthesize(node.left, PRECEDENCE["+"])
            right, op = _fold(node.right, op)
            rtext = self.parenthesize(right, PRECEDENCE["+"], strict=True) \
                if op in ("-", "+-", "-+") else self.parenthesize(right, PRECEDENCE["+"])
            if rtext.startswith("-") and not isinstance(right, Neg):
                rtext = self.brackets(rtext)
            return f"{left} {SUM_TEX[op]} {rtext}"
        if op == "/" and self.display:
            # a fraction inside a fraction is written on the line: a/b
            self.display = False
            try:
                num, den = self._print(_strip(node.left)), self._print(_strip(node.right))
            finally:
                self.display = True
            return f"\\frac{{{num}}}{{{den}}}"
        left = self.parenthesize(node.left, PRECEDENCE["*"])
        right = self.parenthesize(node.right, PRECEDENCE["*"], strict=op == "/")
        if isinstance(node.right, Neg):
            right = self.brackets(right)
        if op == "/":
            return f"{left}/{right}"
        if op == "x":
            return f"{left} \\times {right}"
        if op in (".", "*"):
            return f"{left} \\cdot {right}"
        # juxtaposition: words beside maths as they are (phidot_slow at 30 deg), a thin
        # space after a quantity, a dot before a number
        if beside_text(node):
            return f"{left} {right}"
        if right[:1].isdigit() or right.startswith("-"):
            return f"{left} \\cdot {right}"
        if isinstance(_rightmost(node.left), Quantity):
            return f"{left}\\,{right}"
        return f"{left} {right}"

    def _print_Pow(self, node: Pow) -> str:
        base = node.base
        text = self._print(base)
        needs = precedence(base) < PRECEDENCE["Atom"] or isinstance(base, Pow) \
            or (isinstance(base, BinOp) and base.op == "/") or isinstance(base, Quantity) \
            or (isinstance(base, Num) and "e" in base.text.lower())
        if isinstance(base, Group) and not text.startswith(("(", "[", "\\left")):
            text = self.brackets(text)
        elif needs and not isinstance(base, Group):
            text = self.brackets(text)
        elif isinstance(base, Sym) and "_" in text:
            text = "{" + text + "}"
        return f"{text}^{{{self._print(_strip(node.exp))}}}"

    def _print_Call(self, node: Call) -> str:
        args = (r" \mid " if node.sep == "|" else ", ").join(self._print(a) for a in node.args)
        if node.name == "sqrt":
            return f"\\sqrt{{{self._print(_strip(node.args[0]))}}}"
        if node.name in FUNCTION_TEX:
            head = FUNCTION_TEX[node.name]
            if node.power is not None:
                head += f"^{{{self._print(node.power)}}}"
            arg = node.args[0] if len(node.args) == 1 else None
            if arg is not None and (not node.parens or isinstance(_strip(arg), (Sym, Quantity))):
                return f"{head} {self._print(_strip(arg))}"
            inner = self._print(_strip(arg)) if arg is not None else args
            return head + self.brackets(inner)
        return symbol_tex(node.name) + self.brackets(args)

    def _print_Group(self, node: Group) -> str:
        inner = self._print(node.body)
        if self.display and isinstance(node.body, BinOp) and node.body.op == "/":
            return inner  # a stacked fraction needs no brackets
        if node.open == "[":
            return self.brackets(inner, "[", "]")
        return self.brackets(inner)

    def _print_Tuple(self, node: Tuple) -> str:
        return ", ".join(self._print(x) for x in node.items)

    def _print_Abs(self, node: Abs) -> str:
        inner = self._print(node.body)
        if self.display and r"\frac" in inner:
            return f"\\left|{inner}\\right|"
        return f"\\lvert {inner}\\rvert"

    def _print_Rel(self, node: Rel) -> str:
        parts = [self._print(node.first)] if node.first is not None else []
        for op, rhs in node.rest:
            parts.append(f"{RELATIONS_TEX[op]} {self._print(rhs)}")
        return " ".join(parts)

    def _print_Sum(self, node) -> str:
        return r"\sum " + self._print(node.body)

    def _print_Integral(self, node) -> str:
        return (f"\\int_{{{self._print(node.lower)}}}^{{{self._print(node.upper)}}} "
                f"{self._print(node.body)}")

    def _print_Prime(self, node) -> str:
        return self.parenthesize(node.body, PRECEDENCE["Atom"]) + "'" * node.count

    def _print_Matrix(self, node) -> str:
        rows = " \\\\ ".join(" & ".join(self._print(x) for x in row) for row in node.rows)
        return f"\\begin{{bmatrix}} {rows} \\end{{bmatrix}}"


# ---- plain text -------------------------------------------------------------

class TextPrinter(Printer):
    """The plain form the kinds write, one spelling per tree."""

    def _print_Num(self, node: Num) -> str:
        return node.text

    def _print_Sym(self, node: Sym) -> str:
        return node.name

    def _print_Text(self, node: Text) -> str:
        return node.text

    def _print_Tex(self, node) -> str:
        return node.plain

    def _print_Quantity(self, node: Quantity) -> str:
        return f"{self._print(node.value)} {node.unit}"

    def _print_Neg(self, node: Neg) -> str:
        body = node.body
        inner = self._print(body) if isinstance(body, (Num, Quantity)) else \
            self.parenthesize(body, PRECEDENCE["Neg"]) if not isinstance(body, Neg) \
            else self.brackets(self._print(body))
        return node.sign + inner

    def _print_BinOp(self, node: BinOp) -> str:
        op = node.op
        if op in SUM_TEX:
            right, op = _fold(node.right, op)
            left = self.parenthesize(node.left, PRECEDENCE["+"])
            rtext = self.parenthesize(right, PRECEDENCE["+"], strict=op != "+")
            return f"{left} {op} {rtext}"
        left = self.parenthesize(node.left, PRECEDENCE["*"])
        right = self.parenthesize(node.right, PRECEDENCE["*"], strict=op == "/")
        if isinstance(node.right, Neg):
            right = self.brackets(right)
        sep = {"/": " / ", "x": " x ", ".": " . ", "*": " * ", " ": " "}[op]
        return f"{left}{sep}{right}"

    def _print_Pow(self, node: Pow) -> str:
        base = self.parenthesize(node.base, PRECEDENCE["Atom"])
        if isinstance(node.base, Quantity):
            base = self.brackets(self._print(node.base))
        return f"{base}^{self.parenthesize(node.exp, PRECEDENCE['Pow'])}"

    def _print_Call(self, node: Call) -> str:
        args = (" | " if node.sep == "|" else ", ").join(self._print(a) for a in node.args)
        power = f"^{self._print(node.power)}" if node.power is not None else ""
        if not node.parens:
            return f"{node.name}{power} {self._print(node.args[0])}"
        return f"{node.name}{power}({args})"

    def _print_Group(self, node: Group) -> str:
        inner = self._print(node.body)
        return f"[{inner}]" if node.open == "[" else f"({inner})"

    def _print_Tuple(self, node: Tuple) -> str:
        return ", ".join(self._print(x) for x in node.items)

    def _print_Abs(self, node: Abs) -> str:
        return f"|{self._print(node.body)}|"

    def _print_Rel(self, node: Rel) -> str:
        parts = [self._print(node.first)] if node.first is not None else []
        parts += [f"{op} {self._print(rhs)}" for op, rhs in node.rest]
        return " ".join(parts)

    def _print_Sum(self, node) -> str:
        return "sum " + self._print(node.body)

    def _print_Integral(self, node) -> str:
        return (f"int_{self._print(node.lower)}^{self._print(node.upper)} "
                f"{self._print(node.body)}")

    def _print_Prime(self, node) -> str:
        return self.parenthesize(node.body, PRECEDENCE["Atom"]) + "'" * node.count

    def _print_Matrix(self, node) -> str:
        return "[" + "; ".join(" ".join(self._print(x) for x in row) for row in node.rows) + "]"


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


def text(node: Node) -> str:
    return TextPrinter().doprint(node)
