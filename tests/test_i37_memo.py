"""The HTML page remembers printed formulas by their shape, so the variants of a bank
share the formulas they have in common (issue 37: export --variants had become a fifth
slower when core nodes, compared by identity, replaced the typesetting tree)."""

from __future__ import annotations

from gyro_cli.core.expr import Sym, sin
from gyro_cli.render import html, mathml
from gyro_cli.render.mathprint import formula_node, substitution_node


def _tree(m: float, theta: float):
    return Sym("m", m, "kg") * Sym("g", 9.81, "m/s^2") * sin(Sym("theta", theta, "deg"))


def test_item03_a_formula_has_one_shape_whatever_its_values():
    assert html.shape(formula_node(_tree(1.0, 0.5))) == html.shape(formula_node(_tree(2.0, 0.7)))


def test_item03_substitutions_with_other_values_are_other_shapes():
    one, two = substitution_node(_tree(1.0, 0.5)), substitution_node(_tree(2.0, 0.5))
    assert html.shape(one) != html.shape(two)
    assert html.formula_mathml(one) != html.formula_mathml(two)
    assert html.formula_mathml(two) == mathml.tree_mathml(two, True)


def test_item03_names_and_structure_tell_formulas_apart():
    a = formula_node(Sym("m", 1.0, "kg") * Sym("g", 9.81, "m/s^2"))
    b = formula_node(Sym("m", 1.0, "kg") / Sym("g", 9.81, "m/s^2"))
    c = formula_node(Sym("M", 1.0, "kg") * Sym("g", 9.81, "m/s^2"))
    assert len({html.shape(a), html.shape(b), html.shape(c)}) == 3
    for node in (a, b, c):
        for display in (True, False):
            assert html.formula_mathml(node, display) == mathml.tree_mathml(node, display)


def test_item03_the_second_variant_prints_its_shared_formulas_from_memory(monkeypatch):
    calls = []
    real = mathml.tree_mathml
    monkeypatch.setattr(mathml, "tree_mathml",
                        lambda node, display: calls.append(1) or real(node, display))
    html.formula_mathml(formula_node(_tree(1.25, 0.3)))
    first = len(calls)
    html.formula_mathml(formula_node(_tree(3.5, 0.9)))
    assert first == 1 and len(calls) == first


def test_item03_a_tree_met_again_is_walked_once_for_its_shape(monkeypatch):
    """A step's sides reach several memos (printed, width, rows): the tree's shape is
    walked for the first, and kept by identity for the others."""
    node = formula_node(_tree(1.5, 0.4))
    walked = []
    real = html.shape
    monkeypatch.setattr(html, "shape", lambda n: walked.append(n is node) or real(n))
    html.formula_mathml(node, True)
    html.formula_mathml(node, False)
    assert walked.count(True) == 1


def test_item03_a_tree_gone_never_lends_its_shape_to_one_in_its_place():
    """Python gives a freed object's id to the next one made: the shape kept for a tree
    is never served to another tree that came to have its id."""
    names = ("m", "M", "g", "theta", "x", "r")
    for k in range(3000):
        node = formula_node(Sym(names[k % 6], 1.0, "kg") * Sym(names[k % 5], 2.0, "m")
                            if k % 2 else Sym(names[k % 6], 1.0, "kg") / Sym("g", 2.0, "m"))
        assert html._shape_of(node) == html.shape(node), k
