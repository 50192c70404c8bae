"""A step's expression tree (`core.expr`) as the typesetting nodes of `mathtree`.

The LaTeX and MathML printers (`mathprint.LatexPrinter`, `mathml.MathMLPrinter`)
set `mathtree` nodes; this printer, one ``_print_<Class>`` method per node of
`core.expr`, builds those nodes straight from the tree a kind wrote, so a
formula and its substitution are never parsed from text. Brackets are placed by
`core.expr.needs_brackets`, the rule the text printer follows, so every format
brackets the same places (a negative value after a factor or a sign included).
"""

from __future__ import annotations

import re

from ..core import expr as E
from ..core import prose as P
from .mathtree import (
    Abs,
    BinOp,
    Call,
    Group,
    Integral,
    Matrix,
    Neg,
    Node,
    Num,
    Pow,
    Prime,
    Quantity,
    Rel,
    Sum,
    Sym,
    Text,
    Tuple,
)


class NodePrinter(E.Printer):
    """``values``: the substitution (each symbol's value and unit), else the formula."""

    def operand(self, parent: E.Expr, child: E.Expr, right: bool = False) -> Node:
        node = self._print(child)
        return Group("(", node) if E.needs_brackets(parent, child, right, self.values) else node

    def _print_Sym(self, node: E.Sym) -> Node:
        if not self.values:
            if node.name.startswith("sum "):  # a total over rotors: ``sum I_w`` is set \sum I_w
                return Sum(Sym(node.name[4:]))
            return Sym(node.name)
        text = E.quantity_text(node.si, node.unit)
        number, _, unit = text.partition(" ")
        negative = number.startswith("-")
        shown: Node = Num(number.lstrip("-"))
        if unit:
            shown = Quantity(shown, unit)  # type: ignore[arg-type]
        return Neg(shown) if negative else shown

    def _print_Const(self, node: E.Const) -> Node:
        return Sym(node.name)

    def _print_Num(self, node: E.Num) -> Node:
        return Neg(Num(node.text.lstrip("-"))) if node.si < 0 else Num(node.text)  # 3/2 as is

    def _print_Let(self, node: E.Let) -> Node:
        return self._print(node.sym if self.values else node.body)

    def _print_Neg(self, node: E.Neg) -> Node:
        if isinstance(node.arg, P.Deriv):  # -dH_O/dt: the sign on the numerator
            rate = self._print(node.arg)
            assert isinstance(rate, BinOp)
            return BinOp("/", Neg(rate.left), rate.right)
        inner = self.operand(node, node.arg)
        if isinstance(inner, BinOp) and inner.op == " ":
            # -(a b) is set -a b, as the text reads: the sign on the first factor
            chain = []
            while isinstance(inner, BinOp) and inner.op == " ":
                chain.append(inner.right)
                inner = inner.left
            out: Node = Neg(inner)
            for right in reversed(chain):
                out = BinOp(" ", out, right)
            return out
        return Neg(inner)

    def _print_Add(self, node: E.Add) -> Node:
        return BinOp("+", self.operand(node, node.left), self.operand(node, node.right, True))

    def _print_Sub(self, node: E.Sub) -> Node:
        return BinOp("-", self.operand(node, node.left), self.operand(node, node.right, True))

    def _print_Mul(self, node: E.Mul) -> Node:
        parts = [self.operand(node, f, k > 0) for k, f in enumerate(E.factors(node, self.values))]
        out = parts[0]
        for part in parts[1:]:
            out = BinOp(" ", out, part)
        return out

    def _print_Div(self, node: E.Div) -> Node:
        return BinOp("/", self.operand(node, node.left), self.operand(node, node.right, True))

    def _print_Pow(self, node: E.Pow) -> Node:
        n = E.trig_power(node)
        if n:  # sin^2(theta)
            call = node.left
            assert isinstance(call, E.Call)
            return Call(call.name, tuple(self._print(a) for a in call.args), power=Num(n))
        return Pow(self.operand(node, node.left), self.operand(node, node.right, True))

    def _print_Call(self, node: E.Call) -> Node:
        if node.name == "abs":
            return Abs(self._print(node.args[0]))
        return Call(E.SHOWN_NAMES.get(node.name, node.name),
                    tuple(self._print(a) for a in node.args))

    def _print_SumOf(self, node: E.SumOf) -> Node:
        if self.values:
            return self._print(node.expanded())
        body = self._print(node.body)
        return Sum(Group("(", body) if E.precedence(node.body, False) <= E.ADD else body)

    def _print_Chain(self, node: E.Chain) -> Node:
        if self.values:
            return self._print(node.forms[-1])
        return Rel(self._print(node.forms[0]), tuple(("=", self._print(f))
                                                     for f in node.forms[1:]))


    # ---- the typeset-only nodes of sentences (core/prose.py)

    def _print_Rel(self, node: P.Rel) -> Node:
        first = None if node.first is None else self._print(node.first)
        return Rel(first, tuple((op, self._print(rhs))
                                                   for op, rhs in node.rest))

    def _vector(self, node: E.BinOp) -> Node:
        sides = []
        for child in (node.left, node.right):
            shown = self._print(child)
            sides.append(Group("(", shown) if P.operand_brackets(node, child) else shown)
        return BinOp(node.op, sides[0], sides[1])

    def _print_Cross(self, node: P.Cross) -> Node:
        return self._vector(node)

    def _print_Dot(self, node: P.Dot) -> Node:
        return self._vector(node)

    def _print_Fn(self, node: P.Fn) -> Node:
        if node.name == "d/dt":  # the rate of change of its argument
            arg = self._print(node.args[0])
            return BinOp(" ", BinOp("/", Sym("d"), Sym("dt")), Group("(", arg))
        if node.name.endswith("'"):  # U_eff''(theta): the primed name, then its arguments
            name = node.name.rstrip("'")
            return BinOp(" ", Prime(Sym(name), len(node.name) - len(name)),
                         Group("(", Tuple(tuple(self._print(a) for a in node.args))))
        return Call(node.name, tuple(self._print(a) for a in node.args), sep=node.sep)

    def _print_Total(self, node: P.Total) -> Node:
        body = self._print(node.body)
        return Sum(Group("(", body) if P.operand_brackets(node, node.body) else body)

    def _print_Sign(self, node: P.Sign) -> Node:
        arg = self._print(node.arg)
        return Neg(Group("(", arg) if P.operand_brackets(node, node.arg) else arg, node.sign)

    def _print_Deriv(self, node: P.Deriv) -> Node:
        name = node.sym.name
        top: Node = BinOp(" ", Sym("d"), Sym(name)) if P.deriv_space(name) else Sym("d" + name)
        return BinOp("/", top, Sym("d" + node.var))  # d theta/dt, dH/dt

    def _print_Quantity(self, node: P.Quantity) -> Node:
        unit = node.text[len(node.number):].strip()
        number, sign, imag = node.number.partition(" + " if " + " in node.number else " - ")
        if imag:  # a - b i: the imaginary part carries the unit
            return BinOp(sign.strip(), _signed(number, ""), _signed(imag[:-2] + "i", unit))
        return _signed(number, unit)

    def _print_Matrix(self, node: P.Matrix) -> Node:
        rows = tuple(tuple(_signed(x.number, "") for x in row) for row in node.entries())
        unit = P.UNIT_TEXT.get(node.unit, node.unit)
        return Quantity(Matrix(rows), unit) if unit else Matrix(rows)  # type: ignore[arg-type]

    def _print_Integral(self, node: P.Integral) -> Node:
        return Integral(self._print(node.lower), self._print(node.upper), self._print(node.body))

    def _print_Bracket(self, node: P.Bracket) -> Node:
        items = tuple(self._print(x) for x in node.items)
        return Group(node.open, items[0] if len(items) == 1 else Tuple(items))

    def _print_Pm(self, node: P.Pm) -> Node:
        right = self._print(node.right)
        if E.precedence(node.right, False) <= E.ADD:
            right = Group("(", right)
        return BinOp(node.op, self._print(node.left), right)


    def _print_Vector(self, node: P.Vector) -> Node:
        items = tuple(Neg(Num(n[1:])) if n.startswith("-") else Num(n) for n in node.numbers)
        shown: Node = Group("(", Tuple(items))
        unit = E.UNIT_TEXT.get(node.unit, node.unit)
        return Quantity(shown, unit) if unit else shown  # type: ignore[arg-type]

    def _print_Words(self, node: P.Words) -> Node:
        if node.then is not None:  # phidot_slow at 30 deg: the words spaced from both sides
            words: Node = Text(node.words + " ") if node.of is None else \
                BinOp(" ", self._print(node.of), Text(f" {node.words} "))
            return BinOp(" ", words, self._print(node.then))
        if node.of is None:
            return Text(node.words)
        return BinOp(" ", self._print(node.of), Text(" " + node.words))

    def _print_Prime(self, node: P.Prime) -> Node:
        return Prime(self._print(node.arg), node.count)

    def _print_Mat(self, node: P.Mat) -> Node:
        return Matrix(tuple(tuple(self._print(x) for x in row) for row in node.rows))


#: a symbol that is one name: ``phidot``, ``theta_0``, ``F_A,weight`` (a part after a comma)
NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]*(,[A-Za-z0-9_]+)?\Z")


def symbol_node(text: str, tree: E.Expr | None = None) -> Node | None:
    """A step's, an answer's or a given's symbol: its tree where the kind wrote one, one
    name as that name; None for anything else (not a symbol gyro writes)."""
    if tree is not None:
        return NodePrinter(values=False).doprint(tree)
    if NAME.match(text):
        return Sym(text)
    return None


def prose_nodes(prose: P.Prose) -> list[str | Node]:
    """A sentence's pieces: words as they are, each tree as typesetting nodes."""
    printer = NodePrinter(values=False)
    return [p if isinstance(p, str) else printer.doprint(p) for p in prose.pieces]


def formula_node(expr: E.Expr) -> Node:
    return NodePrinter(values=False).doprint(expr)


def substitution_node(expr: E.Expr) -> Node:
    return NodePrinter(values=True).doprint(expr)


def latex(expr: E.Expr, values: bool = False) -> str:
    """The formula (or its substitution) as LaTeX maths, fractions stacked."""
    from .mathprint import LatexPrinter

    return LatexPrinter(True).doprint(NodePrinter(values).doprint(expr))


def _signed(number: str, unit: str) -> Node:
    """``-0.5``, ``2.0 kg``: a number as written, its sign a unary minus."""
    shown: Node = Num(number.lstrip("-"))
    if unit:
        shown = Quantity(shown, unit)  # type: ignore[arg-type]
    return Neg(shown) if number.startswith("-") else shown
