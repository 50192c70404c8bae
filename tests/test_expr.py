"""The expression trees of core/expr.py: evaluation, the printers, the brackets."""

from __future__ import annotations

import math
import re

import pytest
from conftest import examples
from hypothesis import given, settings
from hypothesis import strategies as st

from gyro_cli.core import expr as E
from gyro_cli.core.expr import PI, Let, Sym, cos, ellipe, ellipk, sin, sqrt

#: a negative number set right after a factor, a unit or a division sign, with no bracket:
#: ``kg m^2 -179.7 rad/s``, ``/ -3`` (a folded subtraction is `` - 179.7``, spaced)
JUXTAPOSED = re.compile(r"(?:[\w)^]\s+|[/^*]\s*)-\d")


def top() -> dict[str, Sym]:
    """11/3's data in SI: m = 3 oz / g, g = 32.2 ft/s^2, l = 1.5 in, J = m (0.84 in)^2."""
    m = 0.1875 * 4.4482216152605 / 9.81456
    return {"m": Sym("m", m, "kg"), "g": Sym("g", 9.81456, "m/s^2"),
            "l": Sym("l", 1.5 * 0.0254, "m"), "J": Sym("J", m * (0.84 * 0.0254) ** 2, "kg m^2"),
            "theta": Sym("theta", math.pi / 6, "deg"), "psidot": Sym("psidot", -179.7, "rad/s")}


def test_a_tree_evaluates_itself_as_the_hand_calculation():
    s = top()
    moment = s["m"] * s["g"] * s["l"] * sin(s["theta"])
    # by hand: 3 oz = 0.1875 lbf = 0.834 N; l = 0.0381 m; sin 30 deg = 1/2
    assert moment.value == pytest.approx(0.1875 * 4.4482216152605 * 0.0381 * 0.5, rel=1e-12)
    assert (2 * PI * sqrt(s["l"] / s["g"])).value == pytest.approx(
        2 * 3.141592653589793 * (0.0381 / 9.81456) ** 0.5, rel=1e-12)


def test_formula_and_substitution_are_printed_from_the_same_tree():
    s = top()
    e = s["m"] * s["g"] * s["l"] * sin(s["theta"])
    assert E.formula(e) == "m g l sin(theta)"
    assert E.substitution(e) == "0.08498 kg (9.815 m/s^2) (0.03810 m) sin(30.00 deg)"
    assert E.python(e) == "m*g*l*sin(theta)"


def test_a_negative_rate_in_a_product_is_bracketed():
    """The slip of issue 21 (problems/top_rev_per_s.yaml): ``kg m^2 -179.7 rad/s`` read as
    a subtraction."""
    s = top()
    e = s["m"] * s["g"] * s["l"] / (s["J"] * s["psidot"])
    assert E.formula(e) == "m g l / (J psidot)"
    assert E.substitution(e).endswith("/ (3.869e-05 kg m^2 (-179.7 rad/s))")
    assert not JUXTAPOSED.search(E.substitution(e))


def test_a_negative_value_after_a_sign_is_folded_into_it():
    a, b = Sym("a", 2.0, "N m"), Sym("b", -0.5, "N m")
    assert E.substitution(a + b) == "2.000 N m - 0.5000 N m"
    assert E.substitution(a - b) == "2.000 N m + 0.5000 N m"
    assert E.substitution(a - b * Sym("k", 3.0)) == "2.000 N m + 0.5000 N m (3.000)"
    assert (a - b).value == 2.5 and (a + b).value == 1.5
    assert E.substitution(-b) == "-(-0.5000 N m)"
    assert E.substitution(a / b) == "2.000 N m / (-0.5000 N m)"
    assert E.substitution(b ** 2) == "(-0.5000 N m)^2"


def test_precedence_brackets():
    a, b, c = Sym("a", 1.0), Sym("b", 2.0), Sym("c", 3.0)
    assert E.formula((a + b) * c) == "(a + b) c"
    assert E.formula(a - (b - c)) == "a - (b - c)"
    assert E.formula(a - b - c) == "a - b - c"
    assert E.formula((a / b) * c) == "(a / b) c"
    assert E.formula(a / (b * c)) == "a / (b c)"
    assert E.formula((a * b) ** 2) == "(a b)^2"
    assert E.formula(a ** (b / c)) == "a^(b / c)"
    assert E.formula(-(a + b)) == "-(a + b)"


def test_a_known_quantity_shows_its_definition_in_the_formula_and_its_value_after():
    """The gyrocompass's M = H Omega_E cos(lambda) sin(alpha) = D sin(alpha)."""
    H, W, lat = Sym("H", 2.0, "kg m^2/s"), Sym("Omega_E", 7.292e-5, "rad/s"), Sym("lambda", 0.5, "deg")
    D = Sym("D", (H * W * cos(lat)).value, "N m/rad")
    e = Let(D, H * W * cos(lat)) * sin(Sym("alpha", 0.1, "deg"))
    assert E.formula(e) == "H Omega_E cos(lambda) sin(alpha)"
    assert E.substitution(e) == "0.0001280 N m/rad sin(5.730 deg)"
    assert E.python(e) == "D*sin(alpha)"  # what the value is computed from
    assert E.python(H * W * cos(lat)) == "H*Omega_E*cos(lambda_)"
    names = {k: v.si for k, v in E.symbols(e).items()}
    assert eval(E.python(e), {"__builtins__": {}}, E.python_names() | {
        E.python_name(k): v for k, v in names.items()}) == pytest.approx(e.value, rel=1e-12)


def test_the_complete_elliptic_integrals_against_tabulated_values():
    """K(1/2) = 1.8540746773013719, E(1/2) = 1.3506438810476755 (Abramowitz and Stegun,
    table 17.1, m = 0.5); K(0) = E(0) = pi/2, E(1) = 1."""
    assert ellipk(0.5).value == pytest.approx(1.8540746773013719, rel=1e-14)
    assert ellipe(0.5).value == pytest.approx(1.3506438810476755, rel=1e-14)
    assert ellipk(0.0).value == pytest.approx(math.pi / 2, rel=1e-15)
    assert ellipe(0.0).value == pytest.approx(math.pi / 2, rel=1e-15)
    assert ellipe(1.0).value == pytest.approx(1.0, rel=1e-15)


def test_python_names_are_identifiers():
    assert E.python_name("lambda") == "lambda_"
    assert E.python_name("F_A,weight") == "F_A_weight"
    assert E.python_name("omega_z") == "omega_z"


# ---- any tree: expr gives the value, no negative is juxtaposed -----------------

_names = iter(range(10 ** 9))
_units = st.sampled_from(["", "kg", "m/s", "kg m^2", "rad/s", "N m", "deg"])
_leaf = st.one_of(
    st.builds(lambda v, u: Sym(f"x{next(_names)}", v, u),
              st.floats(-1e3, 1e3, allow_nan=False).filter(lambda v: abs(v) > 1e-3), _units),
    st.builds(E.Num, st.sampled_from([2.0, 4.0, 0.5])),
    st.just(PI))


def _extend(children):
    return st.one_of(
        st.builds(lambda a, b: a + b, children, children),
        st.builds(lambda a, b: a - b, children, children),
        st.builds(lambda a, b: a * b, children, children),
        st.builds(lambda a, b: a / b, children, children),
        st.builds(lambda a: -a, children),
        st.builds(lambda a: a ** 2, children),
        st.builds(lambda a: sin(a), children),
        st.builds(lambda a: sqrt(E.absolute(a)), children))


@pytest.mark.property
@settings(max_examples=examples(300), deadline=None)
@given(st.recursive(_leaf, _extend, max_leaves=8))
def test_any_tree_expr_evaluates_to_its_value_and_brackets_negatives(tree):
    try:
        value = tree.value
    except (ZeroDivisionError, ValueError, OverflowError):
        return
    names = {E.python_name(k): s.si for k, s in E.symbols(tree).items()}
    again = eval(E.python(tree), {"__builtins__": {}}, E.python_names() | names)
    assert again == pytest.approx(value, rel=1e-9, abs=1e-300)
    for text in (E.substitution(tree), E.formula(tree)):
        assert not JUXTAPOSED.search(text), text
        assert "--" not in text and "+ -" not in text and "- -" not in text, text


def test_a_negated_product_with_a_negative_first_factor_is_bracketed():
    """-(a sin(x)) with a = -2 rad/s once printed --2.000 rad/s sin(x)."""
    a, x = Sym("a", -2.0, "rad/s"), Sym("x", 0.5, "rad")
    assert E.substitution(-(a * sin(x))) == "-(-2.000 rad/s sin(0.5000 rad))"
    assert E.substitution(-(a / x)) == "-(-2.000 rad/s / (0.5000 rad))"
    assert E.substitution(-(-a * x)) == "-(-(-2.000 rad/s) (0.5000 rad))"
    assert E.formula(-(a * sin(x))) == "-a sin(x)"


def test_a_step_that_cannot_be_evaluated_is_bad_input_not_a_crash():
    from gyro_cli.core.errors import InputError
    from gyro_cli.core.work import Work

    work = Work()
    with pytest.raises(InputError, match="the step w = a / b cannot be evaluated"):
        work.step("w", Sym("a", 1.0, "m") / Sym("b", 0.0, "s"), unit="m/s")
    with pytest.raises(InputError, match="cannot be evaluated"):
        work.step("p", Sym("a", 1e200) ** E.Num(3))
    with pytest.raises(TypeError):
        work.step("w", Sym("a", 1.0), "a substitution", 2.0)  # a tree carries its own


def test_a_tree_step_keeps_the_tree_and_prints_the_line():
    from gyro_cli.core.work import Work

    work = Work()
    s = top()
    value = work.step("a", 2 * s["m"] * s["g"] * s["l"] / s["J"], unit="1/s^2", ref="Eq. 11.18")
    step = work.sections[0].steps[0]
    assert value == step.value == step.expr.value
    assert step.as_text().startswith("a = 2 m g l / J = 2 (0.08498 kg) (9.815 m/s^2) (0.03810 m)")
    assert step.as_text().endswith("1/s^2    (Eq. 11.18)")


def test_a_total_over_rotors_is_set_as_a_sum():
    """``sum I_w`` (four_wheeler's total of the wheels' inertias) is set \\sum I_w in LaTeX;
    the text keeps the name and the JSON ``expr`` an identifier."""
    from gyro_cli.render.mathprint import formula_latex as latex

    tree = Sym("sum I_w", 36.0, "kg m^2") - Sym("G", 5.0) * Sym("sum I_E", 24.0, "kg m^2")
    assert latex(tree) == r"\sum I_{w} - G \sum I_{E}"
    assert latex(tree, values=True).startswith(r"36.00\,\mathrm{kg\,m^{2}} - 5.000")
    assert E.formula(tree) == "sum I_w - G sum I_E"
    assert E.python(tree) == "sum_I_w-G*sum_I_E"


def test_a_chain_prints_its_equal_forms_and_substitutes_the_last():
    """A step whose formula is written in two forms, ``A = B`` (swinging_rotor, problem
    11/8): the formula shows both, the substitution, value and ``expr`` are the last's."""
    from gyro_cli.core.work import Work
    from gyro_cli.render import report
    from gyro_cli.render.mathprint import formula_latex as latex

    m, g, L = Sym("m", 2.0, "kg"), Sym("g", 9.81, "m/s^2"), Sym("L", 0.25, "m")
    th, I_O = Sym("theta", math.pi / 3, "deg"), Sym("I_O", 0.13, "kg m^2")
    k = Let(Sym("I_O/m", 0.065, "m^2"), Sym("r", 0.1, "m") ** 2 / 4 + L ** 2)
    chain = E.Chain(m * g * L * sin(th) / I_O, g * L * sin(th) / k)
    assert E.formula(chain) == ("m g L sin(theta) / I_O = g L sin(theta) / (r^2 / 4 + L^2)")
    assert E.substitution(chain) == "9.810 m/s^2 (0.2500 m) sin(60.00 deg) / (0.06500 m^2)"
    assert E.python(chain) == "g*L*sin(theta)/I_O_m"
    assert set(E.symbols(chain)) == {"g", "L", "theta", "I_O/m"}
    assert chain.value == (g * L * sin(th) / k).value
    assert latex(chain).count("=") == 1 and "\\frac{g L" in latex(chain)
    assert latex(chain, values=True) == latex(g * L * sin(th) / k, values=True)
    assert E.substitution(E.map_syms(chain, lambda s: Sym(s.name, 2 * s.si, s.unit))) \
        .startswith("19.62 m/s^2")
    work = Work()
    work.step("thetaddot", chain, unit="rad/s^2")
    step = work.sections[0].steps[0]
    assert step.as_text().startswith("thetaddot = m g L sin(theta) / I_O = g L sin(theta) / (")
    eq = report.equation(step)
    assert eval(eq["expr"], E.python_names() | eq["symbols"]) == eq["value"]


def test_a_chain_refuses_forms_that_disagree_and_being_an_operand():
    from gyro_cli.core.errors import InputError
    from gyro_cli.core.work import Work

    a, b = Sym("a", 2.0, "m"), Sym("b", 3.0, "m")
    with pytest.raises(InputError, match="forms disagree"):
        Work().step("x", E.Chain(a + b, a * b), unit="m")
    assert E.Chain(a + b, b + a, 5.0).value == 5.0
    with pytest.raises(TypeError):
        E.Chain(a, b) * 2
    with pytest.raises(TypeError):
        sin(E.Chain(a, a))
    with pytest.raises(TypeError):
        2 - E.Chain(a, a)
    with pytest.raises(ValueError):
        E.Chain(a)
