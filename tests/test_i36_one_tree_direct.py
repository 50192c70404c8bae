"""Issue 36 item 1, one tree: LaTeX and MathML print `core.expr`/`core.prose` nodes
directly. There is no second typesetting tree (`render/mathtree.py`, `render/exprnodes.py`
are gone, no module of ``render/`` defines a node class), every core node prints in both
formats, and the two printers make the same bracket and sign decisions."""

from __future__ import annotations

import importlib
import importlib.util
import math
import pkgutil
import random
import re

from gyro_cli.core import expr as E
from gyro_cli.core import prose as P


def _core_classes() -> set[type]:
    """Every node class of the core tree that a kind may write (not the abstract bases)."""
    out: set[type] = set()
    todo = [E.Expr]
    while todo:
        cls = todo.pop()
        for sub in cls.__subclasses__():
            if sub.__module__ in ("gyro_cli.core.expr", "gyro_cli.core.prose"):
                todo.append(sub)
                out.add(sub)
    return out - {E.BinOp, P.Typeset}


def test_item01_no_second_tree_and_no_node_class_in_render():
    import gyro_cli.render as render

    for gone in ("mathtree", "exprnodes"):
        assert importlib.util.find_spec(f"gyro_cli.render.{gone}") is None, gone
    for info in pkgutil.iter_modules(render.__path__):
        module = importlib.import_module(f"gyro_cli.render.{info.name}")
        for value in vars(module).values():
            if isinstance(value, type) and value.__module__ == module.__name__:
                assert not issubclass(value, E.Expr), (info.name, value)
                assert value.__name__ not in ("Node", "Group", "Tuple", "Abs", "Sum", "Text"), \
                    (info.name, value)


def _every_node() -> list[E.Expr]:
    """One tree of each core node class, with numbers of both signs inside."""
    x, y = E.Sym("x", -1.5, "m"), E.Sym("theta_0", 0.5, "deg")
    a, b = P.names("a b")
    return [x, y, E.PI, E.Num(2), E.Num(-3), E.Num(1.5, "3/2"), E.Let(E.Sym("D", 1.0), x * y),
            -x, -(a * b), x + y, x - y, x * y, x / y, x ** 2, E.sin(y) ** 2, E.sin(y),
            E.absolute(x), E.ellipk(y), E.Chain(x * 1, x), E.SumOf(a * b, (x, y)),
            P.rel(x, "=", y, ">=", 0), P.rel(None, "=", y), P.cross(a, b + a), P.dot(a, b),
            P.fn("f", x), P.fn("d/dt", a * b), P.fn("U''", a), P.fn("Pi", a, b, sep="|"),
            P.total(a + b), P.signed("+-", a * b), P.deriv(E.Sym("H", 1.0)),
            -P.deriv(E.Sym("theta", 1.0)), P.mat((x, y), (a, -b)), P.integral(0, x, a / b),
            P.bracket(x, y), P.paren(a + b), P.tup(a, b, 1), P.pm(a, b), P.pm(None, 1),
            P.words("(slow)", a), P.words("at", a, P.q(math.pi / 6, "deg", exact=True)),
            P.words("drift angle"), P.prime(a, 2), P.q(-0.25, "N*m"),
            P.q(complex(-0.5, -4.25), "1/s"), P.qvec((0, 2.5e5, -1.0), "N m"),
            P.qvec((1, 2)), P.matrix([[1.0, -2.0], [0.0, 3.0]], "kg m^2"),
            P.matrix([[1.0, 2.0], [3.0, 4.0]])]


def _classes_in(tree: E.Expr) -> set[type]:
    out = {type(tree)}
    for child in tree.children():
        out |= _classes_in(child)
    if isinstance(tree, E.Let):
        out |= _classes_in(tree.sym)
    if isinstance(tree, E.SumOf):
        out |= _classes_in(tree.body)
    if isinstance(tree, P.Deriv):
        out.add(E.Sym)
    return out


def test_item01_latex_and_mathml_print_every_core_node():
    """Every core node class, in the formula and in the substitution, set by `Lowering`
    into core nodes only and printed by both printers with no node left unprinted."""
    from gyro_cli.render.mathml import MathMLPrinter
    from gyro_cli.render.mathprint import LatexPrinter, Lowering

    trees = _every_node()
    covered = set().union(*(_classes_in(t) for t in trees))
    assert _core_classes() <= covered, _core_classes() - covered
    for tree in trees:
        for values in (False, True):
            shown = Lowering(values).doprint(tree)
            for node_class in _classes_in(shown):
                assert node_class.__module__.startswith("gyro_cli.core."), node_class
            for display in (False, True):
                tex = LatexPrinter(display).doprint(shown)
                markup = MathMLPrinter(display).doprint(shown)
                assert tex and markup.startswith("<"), (tree, tex, markup)
                assert "object at" not in tex + markup


def _random_tree(rng: random.Random, depth: int) -> E.Expr:
    leaves = [lambda: E.Sym(rng.choice(["a", "b", "theta_0", "phidot"]),
                            rng.choice([2.0, -0.5, 3.25e-6, -4.0e7]),
                            rng.choice(["", "kg", "m/s", "deg"])),
              lambda: E.Num(rng.choice([2, 3, -1, 0.5])),
              lambda: P.q(rng.choice([1.5, -2.25, -1.5e-5]), rng.choice(["", "N m", "deg"])),
              lambda: E.Num(1.5, "3/2")]
    if depth == 0 or rng.random() < 0.25:
        return rng.choice(leaves)()
    left, right = _random_tree(rng, depth - 1), _random_tree(rng, depth - 1)
    build = rng.choice([
        lambda: left + right, lambda: left - right, lambda: left * right,
        lambda: left / right, lambda: left ** E.Num(2), lambda: -left,
        lambda: E.sin(left), lambda: E.sqrt(left), lambda: E.cos(left) ** 2,
        lambda: P.signed("+-", left), lambda: P.pm(left, right), lambda: P.cross(left, right),
        lambda: P.paren(left) * right, lambda: E.absolute(left)])
    return build()  # type: ignore[no-any-return]


def _brackets_and_signs(tex: str, markup: str) -> tuple[tuple[int, ...], tuple[int, ...]]:
    """The brackets and the signs each printer wrote: (, ), [, ], -, +, +- and -+."""
    tex = tex.replace(r"\left", "").replace(r"\right", "")
    tex_counts = (tex.count("("), tex.count(")"), tex.count("["), tex.count("]"),
                  tex.count("-"), tex.count("+"), tex.count(r"\pm"), tex.count(r"\mp"))
    mo = re.findall(r"<mo>([^<]*)</mo>", markup)
    ml_counts = (mo.count("("), mo.count(")"), mo.count("["), mo.count("]"), mo.count("−"),
                 mo.count("+"), mo.count("±"), mo.count("∓"))
    return tex_counts, ml_counts


def test_item01_latex_and_mathml_share_bracket_and_sign_decisions_on_random_trees():
    """For random formulas and their substitutions, LaTeX and MathML write the same
    brackets and the same signs (the decisions are the shared base's; they only spell):
    every bracket inline, every sign in a display too."""
    from gyro_cli.render.mathml import MathMLPrinter
    from gyro_cli.render.mathprint import LatexPrinter, Lowering

    rng = random.Random(3601)
    checked = 0
    for _ in range(600):
        tree = _random_tree(rng, 4)
        for values in (False, True):
            shown = Lowering(values).doprint(tree)
            for display in (False, True):
                tex = LatexPrinter(display).doprint(shown)
                markup = MathMLPrinter(display).doprint(shown)
                ours, theirs = _brackets_and_signs(tex, markup)
                if display:  # a stacked fraction as a power's base: LaTeX brackets it,
                    ours, theirs = ours[4:], theirs[4:]  # MathML's <mfrac> needs none
                assert ours == theirs, (P.text(tree), tex, markup)
                checked += 1
    assert checked == 2400


def test_item01_sin_squared_and_a_power_of_a_named_sine_stay_apart():
    """``sin(x)^2`` is set ``sin^2 x``; a power of a quantity defined as a sine (a `Let`)
    is a power like any other, as before the one tree, in both formats."""
    from gyro_cli.render.mathml import MathMLPrinter
    from gyro_cli.render.mathprint import formula_latex, formula_node

    x = E.Sym("theta", 0.5, "deg")
    named = E.Let(E.Sym("s", 0.4), E.sin(x)) ** 2
    assert formula_latex(E.sin(x) ** 2) == r"\sin^{2} \theta"
    assert formula_latex(named) == r"\sin \theta^{2}"
    assert formula_latex(named, values=True) == "0.4000^{2}"
    assert MathMLPrinter(True).doprint(formula_node(E.sin(x) ** 2)).startswith(
        "<mrow><msup><mi>sin</mi>")
    assert MathMLPrinter(True).doprint(formula_node(named)).startswith("<msup><mrow><mi>sin")
