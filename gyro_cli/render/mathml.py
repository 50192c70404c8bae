"""MathML for `mathtree` expressions: the formulas of an HTML page.

`MathMLPrinter` follows `mathprint.LatexPrinter` node by node (the same
precedence table and brackets), writing MathML Core, which browsers render
natively and screen readers speak: ``phidot`` is phi with a dot accent,
``theta_0`` theta sub 0, ``m g l`` a product joined by invisible times,
``sin(theta)`` a function application, ``a / b`` a stacked fraction in a
display. Every name and number from a problem file is HTML-escaped here.

The nodes come from the expression trees the kinds write (`exprnodes`);
nothing here reads formula text.
"""

from __future__ import annotations

import re
from html import escape

from .mathprint import (PRECEDENCE, Printer, _fold, _rightmost, _strip, beside_text,
                        precedence, split_symbol)
from .mathtree import (GREEK, Abs, BinOp, Call, Group, Neg, Node, Num, Pow, Quantity, Sym, Tuple,
                       _symbolic, dotted, tokens)

__all__ = ["MathMLPrinter", "math_element", "symbol_mathml", "tree_mathml"]

GREEK_LETTERS = {
    "alpha": "α", "beta": "β", "gamma": "γ", "delta": "δ", "epsilon": "ε", "zeta": "ζ",
    "eta": "η", "theta": "θ", "iota": "ι", "kappa": "κ", "lambda": "λ", "mu": "μ", "nu": "ν",
    "xi": "ξ", "pi": "π", "rho": "ρ", "sigma": "σ", "tau": "τ", "phi": "ϕ", "chi": "χ",
    "psi": "ψ", "omega": "ω", "Gamma": "Γ", "Delta": "Δ", "Theta": "Θ", "Lambda": "Λ",
    "Xi": "Ξ", "Pi": "Π", "Sigma": "Σ", "Phi": "Φ", "Psi": "Ψ", "Omega": "Ω"}
RELATIONS = {"=": "=", ">=": "≥", "<=": "≤", "<": "&lt;", ">": "&gt;", ">>": "≫",
             "<<": "≪", "->": "→", "~": "≈", "!=": "≠"}
SUMS = {"+": "+", "-": "−", "+-": "±", "-+": "∓"}
FUNCTIONS = {"sin", "cos", "tan", "cot", "sec", "csc", "exp", "ln", "log", "sinh", "cosh",
             "tanh", "det", "arcsin", "arccos", "arctan", "max", "min", "atan2", "Re", "Im",
             "sign"}
FUNCTION_NAMES = {"asin": "arcsin", "acos": "arccos", "atan": "arctan"}
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

def _base(base: str) -> str:
    if base in GREEK:
        return _mi(GREEK_LETTERS[base], upright=base[0].isupper())
    d = dotted(base)
    if d:
        return f'<mover accent="true">{_base(d[0])}<mo>{ACCENTS[d[1]]}</mo></mover>'
    if len(base) == 1:
        return _mi(base)
    if base[0] == "d" and _symbolic(base[1:]):
        return _row(_mi("d", upright=True), _base(base[1:]))
    return _mi(base)  # a multi-letter name is upright


def _sub(part: str) -> str:
    if part.isdigit():
        return f"<mn>{escape(part)}</mn>"
    if part in GREEK or dotted(part):
        return _base(part)
    return _mi(part, upright=len(part) == 1 and not part.isalpha())


def symbol_mathml(name: str) -> str:
    """One symbol name: ``psidot_min`` -> psi with a dot, sub min."""
    base, subs = split_symbol(name)
    out = _base(base)
    if subs:
        sub = _mo(",").join(_sub(p) for p in subs)
        out = f"<msub>{out}{_row(sub) if len(subs) > 1 else sub}</msub>"
    return out


def number_mathml(text: str) -> str:
    """``3.869e-05`` -> 3.869 × 10 to the −5."""
    if text.endswith("i"):
        return _row(number_mathml(text[:-1]), THIN, _mi("i", upright=True))
    sign = ""
    if text.startswith("-"):
        sign, text = _mo("−"), text[1:]
    mantissa, _, exponent = text.lower().partition("e")
    if not exponent:
        digits = f"<mn>{escape(text)}</mn>"
        return _row(sign, digits) if sign else digits
    power = int(exponent)
    exp = _row(_mo("−"), f"<mn>{-power}</mn>") if power < 0 else f"<mn>{power}</mn>"
    body = _row(f"<mn>{escape(mantissa)}</mn>", _mo("×"), f"<msup><mn>10</mn>{exp}</msup>")
    return _row(sign, body) if sign else body


def unit_mathml(unit: str) -> str:
    """A unit upright: ``kg m^2/s`` -> kg, thin space, m squared, /, s."""
    if unit in ("deg", "degree", "degrees"):
        return _mi("°", upright=True)
    out: list[str] = []
    toks = tokens(unit)
    k = 0
    while k < len(toks):
        t = toks[k]
        if t.space and out:
            out.append(THIN)
        if t.text == "^" and out:
            exp = ""
            k += 1
            while k < len(toks) and (toks[k].text == "-" or toks[k].kind == "num"):
                exp += toks[k].text
                k += 1
            power = f"<mn>{escape(exp)}</mn>" if not exp.startswith("-") else \
                _row(_mo("−"), f"<mn>{escape(exp[1:])}</mn>")
            out[-1] = f"<msup>{out[-1]}{power}</msup>"
            continue
        if t.kind == "name":
            out.append(_mi(t.text, upright=True))
        elif t.kind == "num":
            out.append(f"<mn>{escape(t.text)}</mn>")
        elif t.text == "/":
            out.append('<mo lspace="0" rspace="0">/</mo>')
        elif t.text == "*":
            out.append(THIN)
        elif t.text in "()":
            out.append(_mo(t.text))
        k += 1
    return _row(*out)


# ---- the printer ----------------------------------------------------------------

class MathMLPrinter(Printer):
    """MathML Core presentation markup (the content of a ``<math>`` element).

    ``display``: fractions stacked (a fraction inside one is written on the line);
    otherwise a/b on the line, as inline maths in a sentence.
    """

    def __init__(self, display: bool = True) -> None:
        self.display = display

    def brackets(self, inner: str, open_: str = "(", close: str = ")") -> str:
        return _row(_mo(open_), inner, _mo(close))

    def _print_Num(self, node: Num) -> str:
        return number_mathml(node.text)

    def _print_Sym(self, node: Sym) -> str:
        return symbol_mathml(node.name)

    def _print_Text(self, node) -> str:
        return f"<mtext>{escape(node.text)}</mtext>"

    def _print_Quantity(self, node: Quantity) -> str:
        value = self._print(node.value)
        if node.unit in ("deg", "degree", "degrees"):
            return _row(value, unit_mathml(node.unit))
        return _row(value, THIN, unit_mathml(node.unit))

    def _print_Neg(self, node: Neg) -> str:
        body = node.body
        inner = self._print(body) if isinstance(body, (Num, Quantity)) else \
            self.parenthesize(body, PRECEDENCE["Neg"]) if not isinstance(body, Neg) \
            else self.brackets(self._print(body))
        return _row(_mo(SUMS[node.sign]), inner)

    def _print_BinOp(self, node: BinOp) -> str:
        op = node.op
        if op in SUMS:
            left = self.parenthesize(node.left, PRECEDENCE["+"])
            right, op = _fold(node.right, op)
            rtext = self.parenthesize(right, PRECEDENCE["+"], strict=True) \
                if op in ("-", "+-", "-+") else self.parenthesize(right, PRECEDENCE["+"])
            if _starts_negative(right) and not isinstance(right, Neg):
                rtext = self.brackets(rtext)
            return _row(left, _mo(SUMS[op]), rtext)
        if op == "/" and self.display:
            self.display = False  # a fraction inside a fraction is written on the line
            try:
                num, den = self._print(_strip(node.left)), self._print(_strip(node.right))
            finally:
                self.display = True
            return f"<mfrac>{_row(num)}{_row(den)}</mfrac>"
        left = self.parenthesize(node.left, PRECEDENCE["*"])
        factor = self.parenthesize(node.right, PRECEDENCE["*"], strict=op == "/")
        if isinstance(node.right, Neg):
            factor = self.brackets(factor)
        if op == "/":
            return _row(left, _mo("/"), factor)
        if op == "x":
            return _row(left, _mo("×"), factor)
        if op in (".", "*"):
            return _row(left, _mo("⋅"), factor)
        if beside_text(node):  # words beside maths, one row: phidot_slow at 30 deg
            return _row(*(text[6:-7] if beside_text(side) and text.startswith("<mrow>") else text
                          for text, side in ((left, node.left), (factor, node.right))))
        if _starts_number(node.right):
            return _row(left, _mo("⋅"), factor)
        if isinstance(_rightmost(node.left), Quantity) or _starts_function(node.right):
            return _row(left, THIN, INVISIBLE_TIMES, factor)
        return _row(left, INVISIBLE_TIMES, factor)

    def _print_Pow(self, node: Pow) -> str:
        base = node.base
        text = self._print(base)
        needs = precedence(base) < PRECEDENCE["Atom"] or isinstance(base, Pow) \
            or (isinstance(base, BinOp) and base.op == "/") or isinstance(base, Quantity) \
            or (isinstance(base, Num) and "e" in base.text.lower())
        if needs and not isinstance(base, Group):
            text = self.brackets(text)
        exp = _row(self._print(_strip(node.exp)))
        if isinstance(base, Sym) and text.startswith("<msub>") and text.endswith("</msub>"):
            return "<msubsup>" + text[len("<msub>"):-len("</msub>")] + exp + "</msubsup>"
        return f"<msup>{text}{exp}</msup>"

    def _print_Call(self, node: Call) -> str:
        sep = _mo("∣") if node.sep == "|" else _mo(",")
        args = sep.join(self._print(a) for a in node.args)
        if node.name == "sqrt":
            return f"<msqrt>{self._print(_strip(node.args[0]))}</msqrt>"
        name = FUNCTION_NAMES.get(node.name, node.name)
        if name in FUNCTIONS:
            head = _mi(name)
            if node.power is not None:
                head = f"<msup>{head}{_row(self._print(node.power))}</msup>"
            arg = node.args[0] if len(node.args) == 1 else None
            if arg is not None and (not node.parens or isinstance(_strip(arg), (Sym, Quantity))):
                return _row(head, APPLY, self._print(_strip(arg)))
            inner = self._print(_strip(arg)) if arg is not None else args
            return _row(head, APPLY, self.brackets(inner))
        return _row(symbol_mathml(node.name), APPLY, self.brackets(args))

    def _print_Group(self, node: Group) -> str:
        inner = self._print(node.body)
        if self.display and isinstance(node.body, BinOp) and node.body.op == "/":
            return inner  # a stacked fraction needs no brackets
        if node.open == "[":
            return self.brackets(inner, "[", "]")
        return self.brackets(inner)

    def _print_Tuple(self, node: Tuple) -> str:
        return _row(*_joined([self._print(x) for x in node.items], _mo(",")))

    def _print_Abs(self, node: Abs) -> str:
        return _row(_mo("|"), self._print(node.body), _mo("|"))

    def _print_Rel(self, node) -> str:
        parts = [self._print(node.first)] if node.first is not None else []
        for op, rhs in node.rest:
            parts += [_mo(RELATIONS[op]), self._print(rhs)]
        return _row(*parts)

    def _print_Sum(self, node) -> str:
        return _row('<mo largeop="true">∑</mo>', self._print(node.body))

    def _print_Integral(self, node) -> str:
        return _row(f"<msubsup><mo>∫</mo>{_row(self._print(node.lower))}"
                    f"{_row(self._print(node.upper))}</msubsup>", self._print(node.body))

    def _print_Prime(self, node) -> str:
        primes = {1: "′", 2: "″", 3: "‴"}.get(node.count, "′" * node.count)
        return _row(self.parenthesize(node.body, PRECEDENCE["Atom"]), _mo(primes))

    def _print_Matrix(self, node) -> str:
        rows = "".join("<mtr>" + "".join(f"<mtd>{self._print(x)}</mtd>" for x in row) + "</mtr>"
                       for row in node.rows)
        return self.brackets(f"<mtable>{rows}</mtable>", "[", "]")


def _joined(items: list[str], sep: str) -> list[str]:
    out: list[str] = []
    for i, item in enumerate(items):
        if i:
            out.append(sep)
        out.append(item)
    return out


def _starts_number(node: Node) -> bool:
    """Juxtaposition before a number (``2 (3)``) is written with a dot."""
    while isinstance(node, (BinOp, Pow)):
        node = node.left if isinstance(node, BinOp) else node.base
    return isinstance(node, (Num, Quantity)) or isinstance(node, Neg)


def _starts_function(node: Node) -> bool:
    """``m g l sin(theta)``: a thin space before the function's name, as LaTeX sets it."""
    while isinstance(node, (BinOp, Pow)):
        node = node.left if isinstance(node, BinOp) else node.base
    return isinstance(node, Call) and node.name in FUNCTIONS | set(FUNCTION_NAMES)


def _starts_negative(node: Node) -> bool:
    while isinstance(node, (BinOp, Pow)):
        node = node.left if isinstance(node, BinOp) else node.base
    if isinstance(node, Quantity):
        node = node.value
    return isinstance(node, Num) and node.text.startswith("-")


# ---- the switch: formula text -> MathML ---------------------------------------

def math_element(inner: str, display: bool = False, label: str | None = None) -> str:
    """A ``<math>`` element around presentation markup."""
    attrs = ' display="block"' if display else ""
    if label:
        attrs += f' alttext="{escape(label)}"'
    return f"<math{attrs}>{inner}</math>"


def tree_mathml(node: Node, display: bool = False) -> str:
    """The content of a ``<math>`` element for one tree."""
    return MathMLPrinter(display).doprint(node)

