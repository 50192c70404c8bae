"""Sentences written as words and trees (core/prose.py, issue 21 item 3): each format
prints the maths of a sentence from its tree, and ``--units us`` converts the
quantities inside; nothing parses the sentence back."""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest
from formula_oracle import spans

from gyro_cli import kinds
from gyro_cli.commands.authoring import template
from gyro_cli.core.expr import PI, SumOf, Sym, cos, formula, python, sin, substitution
from gyro_cli.core.prose import (
    Prose,
    bracket,
    cross,
    deriv,
    dot,
    fn,
    integral,
    mat,
    matrix,
    names,
    plus,
    pm,
    prime,
    q,
    qvec,
    rel,
    signed,
    total,
    tup,
    words,
)
from gyro_cli.core.work import Work
from gyro_cli.render import html, writeup
from gyro_cli.render.us_units import to_us
from gyro_cli.solving.solve import solve_file

#: kinds whose every line of prose that holds maths is written as words and trees: every kind
PROSE_KINDS = set(kinds.names())

#: kinds whose section titles are words and trees where they hold maths (steady_precession
#: joins when its titles are written so)
TITLE_KINDS = PROSE_KINDS
#: titles the parser reads maths in that are words: a year, a problem's number
TITLE_WORDS = {"Conventions (Meijaard, Papadopoulos, Ruina & Schwab 2007)",
               "preset: earth (IERS Conventions 2010, IAU 2009 constants, J2000 elements)",
               "Counterweight on the pivoted arm (problem 11/4)"}

H, U, W, E, lam, alpha, I_v, addot = names("H U Omega E lambda alpha I_v alphaddot")


def test_a_sentence_prints_its_maths_from_the_trees():
    line = Prose(("so  ", rel(I_v * addot, "=", -H * W * cos(lam) * sin(alpha)),
                  "  (terms of order ", I_v * W**2, " dropped)"))
    assert line.text == ("so  I_v alphaddot = -H Omega cos(lambda) sin(alpha)  "
                         "(terms of order I_v Omega^2 dropped)")


def test_vector_products_tuples_functions_and_sums():
    M_U, OmE = names("M_U Omega_E")
    assert Prose((rel(fn("d/dt", dot(H, U)), "=", M_U + dot(H, cross(OmE, U))),)).text == \
        "d/dt (H . U) = M_U + H . (Omega_E x U)"
    assert Prose((2 * cross(H, U),)).text == "2 (H x U)"
    assert Prose((cross(H + U, U),)).text == "(H + U) x U"
    assert Prose((fn("f", names("u")[0]),)).text == "f(u)"
    m, y, z = names("m y z")
    assert Prose((rel(names("I_x")[0], "=", total(m * (y**2 + z**2))),)).text == \
        "I_x = sum m (y^2 + z^2)"
    assert Prose((tup(0, q(458.1, "kg m^2/s"), 0),)).text == "(0, 458.1 kg m^2/s, 0)"


def test_signs_rates_of_change_and_a_product_before_a_cross():
    K, M, L, v, R = names("K M L v R")
    assert Prose((signed("+", K),)).text == "+K"
    line = Prose((rel(signed("+-", M) / L, "=", signed("+-", q(1396.0, "N"))),))
    assert line.text == "+-M / L = +-1396 N"
    assert writeup.prose_latex(line) == r"$\pm M/L = \pm 1396\,\mathrm{N}$"
    assert Prose((signed("+", v + R),)).text == "+(v + R)"
    rate = Prose((rel(deriv(H), "=", cross(W * K, H)),))
    assert rate.text == "dH/dt = Omega K x H"  # a product before x is read first
    assert writeup.prose_latex(rate) == r"$\mathrm{d}H/\mathrm{d}t = \Omega K \times H$"
    assert Prose((cross(H, W * K),)).text == "H x (Omega K)"
    with pytest.raises(ValueError):
        signed("*", K)
    with pytest.raises(TypeError):
        deriv(H + K)


def test_quantities_print_their_value_and_exact_ones_their_digits():
    assert Prose((q(1.28e-4, "N m"),)).text == "0.0001280 N m"
    assert Prose((q(math.pi / 6, "deg"),)).text == "30.00 deg"
    assert Prose((q(math.pi, "deg", exact=True),)).text == "180 deg"
    assert Prose((rel(alpha, "=", q(-2.5, "rad/s")),)).text == "alpha = -2.500 rad/s"


def test_words_stand_as_a_symbol_and_are_set_as_text():
    work = Work()
    work.section("Test")
    work.step(words("body cone"), Sym("beta", 0.5, "deg"), unit="deg", substitute=False)
    step = work.sections[0].steps[0]
    assert step.as_text() == "body cone = beta = 28.65 deg"
    assert r"\text{body cone} = \beta" in "\n".join(writeup.steps_lines([step]))
    assert "<mtext>body cone</mtext>" in html._step_html(step)


def test_a_short_note_of_words_and_trees_sits_beside_its_display():
    work = Work()
    work.section("Test")
    work.step("phidot", Sym("H", 2.0, "kg m^2/s") / Sym("I", 1.0, "kg m^2"), unit="rad/s",
              note=("precession of ", *names("k"), " about ", H))
    latex = "\n".join(writeup.steps_lines(work.sections[0].steps))
    assert r"\qquad \text{precession of $k$ about $H$}" in latex


def _line(*pieces):
    work = Work()
    work.text(*pieces)
    return work.sections[0].steps[0]


def test_primes_and_matrices_print_as_the_chapter_writes_them():
    i, j = names("i j")
    assert Prose((rel(prime(i, 2), "=", cos(alpha) * i - sin(alpha) * j),)).text == \
        "i'' = cos(alpha) i - sin(alpha) j"
    assert Prose((mat((q(1.0), 0), (0, q(-1.0))),)).text == "[1.000 0; 0 -1.000]"
    latex = "\n".join(writeup.steps_lines([_line("so ", rel(prime(i, 2), "=", mat((1, 0), (0, 1))))]))
    assert "i''" in latex and r"\begin{bmatrix} 1 & 0 \\ 0 & 1 \end{bmatrix}" in latex


def test_a_sum_over_particles_prints_the_chapter_form_and_evaluates_its_terms():
    m, y, z = names("m y z")
    parts = [(Sym(f"m_{k}", mk, "kg"), Sym(f"y_{k}", yk, "m"), Sym(f"z_{k}", zk, "m"))
             for k, (mk, yk, zk) in enumerate(((0.5, 0.2, 0.0), (1.0, -0.1, 0.3)))]
    tree = SumOf(m * (y ** 2 + z ** 2), tuple(mk * (yk ** 2 + zk ** 2) for mk, yk, zk in parts))
    assert formula(tree) == "sum m (y^2 + z^2)"
    assert tree.value == pytest.approx(0.5 * 0.04 + 1.0 * (0.01 + 0.09))
    assert substitution(tree).startswith("0.5000 kg ((0.2000 m)^2 + (0 m)^2) + 1.000 kg")
    assert python(tree) == "(m_0*(y_0**2+z_0**2)+m_1*(y_1**2+z_1**2))"
    work = Work()
    work.section("Test")
    work.step("I_x", tree, unit="kg*m^2", substitute=False)
    assert r"I_{x} = \sum m (y^{2} + z^{2})" in "\n".join(
        writeup.steps_lines(work.sections[0].steps))


def test_matrices_primes_integrals_brackets_and_eigenvalues():
    """The nodes of the bicycle's and the released top's sentences, in text and LaTeX."""
    from gyro_cli.render.mathprint import LatexPrinter, Lowering

    def tex(tree):
        return LatexPrinter(False).doprint(Lowering().doprint(tree))

    M, qq, s, u, f = names("M q s u f")
    line = rel(M, "=", matrix([[80.81722, 0.0], [-2.5, 1.0]], "kg m^2", sig=10))
    assert Prose((line,)).text == "M = [[80.81722000, 0], [-2.500000000, 1.000000000]] kg m^2"
    assert r"\begin{bmatrix} 80.81722000 & 0 \\ -2.500000000" in tex(line)
    assert Prose((M * prime(qq, 2),)).text == "M q''" and tex(prime(qq)) == "q'"
    T = integral(names("u1")[0], names("u2")[0], names("du")[0] / fn("f", u))
    assert Prose((2 * T,)).text == "2 int_u1^u2 du / f(u)"
    assert tex(T).startswith(r"\int_{u_{1}}^{u_{2}}")
    assert Prose((bracket(u + 1) / 2,)).text == "[u + 1] / 2"
    assert Prose((fn("Pi", names("n")[0], names("m")[0], sep="|"),)).text == "Pi(n|m)"
    eig = rel(s, "=", q(complex(-0.5, -4.25), "1/s", sig=6))
    assert Prose((eig,)).text == "s = -0.500000 - 4.25000 i 1/s"
    assert tex(eig) == r"s = -0.500000 - 4.25000\,\mathrm{i}\,\mathrm{1/s}"
    assert Prose((q(4.29238253634111, "m/s", sig=12),)).text == "4.29238253634 m/s"


def test_either_sign_a_continued_relation_and_a_bracketed_list():
    from gyro_cli.render.mathprint import LatexPrinter, Lowering

    b, g, f = names("beta gamma f")
    line = rel(fn("f", pm(None, 1)), "=", -pm(b, g, "-+") ** 2, "<=", 0)
    assert Prose((line,)).text == "f(+-1) = -(beta -+ gamma)^2 <= 0"
    assert r"f(\pm 1)" in LatexPrinter(False).doprint(Lowering().doprint(line))
    assert r"\beta \mp \gamma" in LatexPrinter(False).doprint(Lowering().doprint(line))
    assert Prose(("       ", rel(None, "=", b + g))).equation() is not None
    assert Prose((rel(None, ">>", 1),)).text == ">> 1"
    assert Prose((bracket(-1, 1),)).text == "[-1, 1]"
    assert Prose((bracket(q(357.8, "1/s^2"), open="(") * g,)).text == "(357.8 1/s^2) gamma"


def test_us_units_convert_a_matrix_and_keep_the_figures_of_a_unit_both_systems_share():
    from gyro_cli.core.prose import map_values
    from gyro_cli.render.us_units import _us_quantity, _us_symbol

    us = map_values(matrix([[14.593902937206364, 0.0]], "kg", sig=10), _us_symbol, _us_quantity)
    assert Prose((us,)).text == "[[1.000, 0]] slug"
    rate = map_values(q(-0.322866429004087, "1/s", sig=12), _us_symbol, _us_quantity)
    assert Prose((rate,)).text == "-0.322866429004 1/s"


def test_typeset_nodes_have_no_value_and_pieces_are_words_or_trees():
    with pytest.raises(TypeError):
        rel(H, "=", U).value  # noqa: B018 (the access is what raises)
    with pytest.raises(TypeError):
        Prose(("a", 3.0))
    with pytest.raises(ValueError):
        rel(H, "=<", U)
    with pytest.raises(ValueError):
        rel(H, "=")


def test_one_relation_citing_an_equation_is_a_displayed_equation():
    line = Prose((rel(H, "=", I_v * W), "    (Eq. 11.4)"))
    assert line.equation() is not None and line.equation()[1] == "11.4"
    assert Prose(("so ", rel(H, "=", W))).equation() is None


def _work_with_prose() -> Work:
    work = Work()
    work.section("Test")
    work.text("Earth rate: ", rel(names("Omega_E")[0], "=", W * (cos(lam) * names("N")[0] +
                                                                sin(lam) * U)), " & <b>")
    work.text(rel(names("I_v")[0] * (2 * PI / names("T")[0])**2, "=", q(1.0, "N m")),
              "    (Eq. 11.27)")
    work.step("M", Sym("H", 2.0, "kg m^2/s") * Sym("Omega", 3.0, "rad/s"), unit="N m",
              note=("with ", rel(alpha, "=", q(0.0, "deg", True))))
    return work


def test_latex_sets_words_as_text_and_trees_as_maths():
    steps = _work_with_prose().sections[0].steps
    latex = "\n".join(writeup.steps_lines(steps))
    assert r"Earth rate: $\Omega_{E} = \Omega (\cos \lambda N + \sin \lambda U)$ \& \textless{}b\textgreater{}" in latex
    assert r"\tag{11.27}" in latex and r"\frac{2 \pi}{T}" in latex
    assert r"$\alpha = 0^{\circ}$" in latex


def test_html_sets_words_escaped_and_trees_as_mathml():
    steps = _work_with_prose().sections[0].steps
    page = "".join(html._step_html(step) for step in steps)
    assert "&amp; &lt;b&gt;" in page and "<b>" not in page
    assert page.count("<math") >= 3 and "(Eq. 11.27)" in page
    assert '<p class="stepnote">with <math>' in page


def test_us_units_convert_the_quantities_in_a_sentence(tmp_path):
    path = tmp_path / "gc.yaml"
    path.write_text(template("gyrocompass"))
    result = solve_file(str(path))
    checks = [s for s in result.solution.checks if s.prose is not None]
    assert checks, "the gyrocompass check is a sentence of trees"
    us = to_us(result)
    before, after = checks[0].text, [s for s in us.solution.checks if s.prose][0].text
    assert "N m/rad" in before and "N m/rad" in after  # a unit with no US form stays
    work = Work()
    work.text("a moment of ", q(1.3558179483314004, "N m"))
    sol = dataclass_result(result, work)
    assert to_us(sol).solution.sections[-1].steps[-1].text == "a moment of 1.000 lbf ft"


def dataclass_result(result, work):
    import dataclasses

    sections = result.solution.sections + work.sections
    return dataclasses.replace(result, solution=dataclasses.replace(result.solution,
                                                                    sections=sections))


@pytest.mark.parametrize("kind", sorted(PROSE_KINDS))
def test_prose_kinds_write_every_formula_in_a_sentence_as_a_tree(kind, tmp_path):
    """In a kind written as trees, a line of plain words holds no maths (the parser is
    the oracle here: it would find a formula left in the words)."""
    files = [f for f in sorted(Path(__file__).resolve().parents[1].glob("problems/*.yaml"))
             if re.search(rf"^kind: *{kind} *$", f.read_text(), re.M)]


    files = sorted(path for path in Path(__file__).resolve().parents[1].glob("problems/*.yaml")
                   if f"\nkind: {kind}\n" in path.read_text())  # 11_2_released_top*.yaml too
    path = tmp_path / f"{kind}.yaml"
    path.write_text(template(kind))
    for file in files + [path]:
        result = solve_file(str(file))
        keys = writeup.file_keys(result.problem.kind)  # the file's keys are words, as rendered
        lines = [s for sec in result.solution.sections for s in sec.steps] + \
            list(result.solution.checks)
        titles = [sec.title for sec in result.solution.sections
                  if sec.prose is None and sec.title not in TITLE_WORDS] \
            if kind in TITLE_KINDS else []
        for text in [s.text for s in lines if s.prose is None and s.text] + titles + \
                [w for w in result.solution.warnings if w not in result.solution.warning_prose]:
            words = keys.sub("key", text) if keys else text
            maths = [str(p) for is_math, p in spans(words) if is_math]
            assert not maths, (file.name, text, maths)


def test_a_warning_of_words_and_trees_is_printed_from_them(tmp_path):
    import dataclasses

    path = tmp_path / "gc.yaml"
    path.write_text(template("gyrocompass"))
    result = solve_file(str(path))
    work = Work()
    work.warn("the moment ", rel(names("M")[0], "=", q(1.3558179483314004, "N m")),
              " is small")
    work.warn("the moment ", rel(names("M")[0], "=", q(1.3558179483314004, "N m")),
              " is small")  # said once
    solution = dataclasses.replace(result.solution, warnings=work.warnings,
                                   warning_prose=work.warning_prose)
    result = dataclasses.replace(result, solution=solution)
    assert result.solution.warnings == ["the moment M = 1.356 N m is small"]
    assert "$M = 1.356\\,\\mathrm{N\\,m}$" in writeup.latex(result)
    us = to_us(result)
    assert us.solution.warnings == ["the moment M = 1.000 lbf ft is small"]
    assert "<li>the moment <math>" in html.worked_answer(us)


def test_a_section_title_of_words_and_trees():
    work = Work()
    work.section("Steady precession, Eq. 11.13 with ", rel(names("thetaddot")[0], "=", 0))
    work.text("x")
    section = work.sections[0]
    assert section.title == "Steady precession, Eq. 11.13 with thetaddot = 0"
    result = _result_with(work)
    assert r"with $\ddot{\theta} = 0$" in writeup.latex(result)
    assert "with <math>" in html.worked_answer(result)


def test_us_units_convert_the_quantities_in_a_section_title():
    work = Work()
    work.section("At ", rel(names("v")[0], "=", q(5.0, "m/s", label="5")), ": the eigenvalues")
    work.text("x")
    result = _result_with(work)
    assert result.solution.sections[0].title == "At v = 5 m/s: the eigenvalues"
    us = to_us(result)
    assert us.solution.sections[0].title == "At v = 16.40 ft/s: the eigenvalues"
    assert r"$v = 16.40\,\mathrm{ft/s}$" in writeup.latex(us)


def _result_with(work):
    import dataclasses
    import tempfile

    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "gc.yaml"
        path.write_text(template("gyrocompass"))
        result = solve_file(str(path))
    return dataclasses.replace(result, solution=dataclasses.replace(
        result.solution, sections=work.sections))


def test_vectors_with_a_unit_explicit_signs_brackets_and_primes():
    from gyro_cli.core.prose import map_values, paren, plus, prime, qvec

    x, wp, a = names("x omega_p alpha")
    line = Prose((plus(x), "; ", rel(-paren(cross(wp, H)), "=", qvec((0, -1.005e4, 0), "N m")),
                  ", ", rel(I_v * prime(a, 2), "=", 0)))
    assert line.text == "+x; -(omega_p x H) = (0, -1.005e+04, 0) N m, I_v alpha'' = 0"
    work = Work()
    work.section("T")
    work.text(*line.pieces)
    tex = "\n".join(writeup.steps_lines(work.sections[0].steps))
    assert r"$+x$" in tex and r"-(\omega_{p} \times H)" in tex and r"\alpha''" in tex
    assert r"(0, -1.005\times 10^{4}, 0)\,\mathrm{N\,m}" in tex
    us = line.map(lambda t: map_values(t, lambda s: s,
                                       lambda v: q(v.si / 1.3558179483314004, "lbf ft")))
    assert "(0, -7412, 0) lbf ft" in us.text


def test_signs_derivatives_primes_vectors_and_a_relation_that_continues():
    """The nodes the vehicles and the rolling disk write: +z, d theta/dt, betadot'',
    (0, 2.011e+05, 0) N m, ``= 0.1047 rad`` (a note continuing its step)."""
    from gyro_cli.render.mathprint import LatexPrinter, prose_nodes

    x, z, theta, H_O, bd, k, wp = names("x z theta H_O betadot k omega_p")
    line = Prose((plus(z), " ", -cross(wp, H), " ", rel(names("omega_p")[0], "=", deriv(theta)),
                  " ", deriv(H_O), " ", rel(prime(bd, 2) + k * bd, "=", 0), " ",
                  rel(cross(wp, H), "=", qvec((0, 2.011e5, -0.0), "N m")), " ",
                  rel(None, "=", q(0.1047, "rad"))))
    assert line.text == ("+z -(omega_p x H) omega_p = d theta/dt dH_O/dt betadot'' + k betadot = 0 "
                         "omega_p x H = (0, 2.011e+05, 0) N m = 0.1047 rad")
    tex = [LatexPrinter(False).doprint(n) for n in prose_nodes(line) if not isinstance(n, str)]
    assert tex[:2] == ["+z", r"-(\omega_{p} \times H)"]
    assert tex[3] == r"\mathrm{d}H_{O}/\mathrm{d}t"
    assert tex[5].endswith(r"= (0, 2.011\times 10^{5}, 0)\,\mathrm{N\,m}")
    assert tex[6] == r"= 0.1047\,\mathrm{rad}"
    with pytest.raises(ValueError):
        rel(None)


def test_us_units_convert_each_component_of_a_vector(tmp_path):
    work = Work()
    work.text("couple ", qvec((0, 1.3558179483314004, 0), "N m"), " at ", qvec((1, 0, 0), "rad/s"))
    path = tmp_path / "gc.yaml"
    path.write_text(template("gyrocompass"))
    sol = dataclass_result(solve_file(str(path)), work)
    assert to_us(sol).solution.sections[-1].steps[-1].text == \
        "couple (0, 1.000, 0) lbf ft at (1.000, 0, 0) rad/s"


def test_labelled_symbols_and_a_primed_function_are_words_beside_maths():
    """``phidot (slow)``, ``phidot_slow at 30 deg``: words beside maths are no product (no
    dot, no invisible times); ``U_eff''(theta)`` is the primed name applied."""
    from gyro_cli.core.prose import map_values, words
    from gyro_cli.render.mathml import MathMLPrinter
    from gyro_cli.render.mathprint import LatexPrinter, symbol_node

    phidot, slow, theta, U = names("phidot phidot_slow theta U_eff")
    at = words("at", slow, q(math.pi / 6, "deg", exact=True))
    assert Prose((at,)).text == "phidot_slow at 30 deg"
    assert LatexPrinter(False).doprint(symbol_node("", at)) == \
        r"\dot{\phi}_{\mathrm{slow}} \text{ at } 30^{\circ}"
    mathml = MathMLPrinter().doprint(symbol_node("", at))
    assert "<mtext> at </mtext><mrow><mn>30</mn>" in mathml and "&#x2062;" not in mathml
    assert "&#x2062;" not in MathMLPrinter().doprint(symbol_node("", words("(slow)", phidot)))
    us = map_values(words("at", slow, q(1.3558179483314004, "N m")), lambda s: s,
                    lambda v: q(v.si / 1.3558179483314004, "lbf ft"))
    assert Prose((us,)).text == "phidot_slow at 1.000 lbf ft"
    primed = fn("U_eff''", theta) / names("I")[0]
    assert Prose((primed,)).text == "U_eff''(theta) / I"
    assert writeup.prose_latex(Prose((primed,))) == r"$U_{\mathrm{eff}}'' (\theta)/I$"


BODY_PROBLEMS = {  # the body's own sentences: a rate per kilogram, l = 0, impossible inertias
    "per_kg": "k_axial: 0.84 in\n  k_pivot: 1.80 in\n  cg_distance: 1.5 in",
    "no_mass_at_centre": "J: 0.004 kg m^2\n  I_cg: 0.003 kg m^2\n  cg_distance: 0 m",
    "pivot_inertia_too_small": "mass: 2 kg\n  k_axial: 5 cm\n  k_pivot: 5 cm\n  cg_distance: 10 cm",
    "J_too_large": "mass: 2 kg\n  J: 0.01 kg m^2\n  I_cg: 0.002 kg m^2\n  cg_distance: 0.1 m",
}


@pytest.mark.parametrize("name", sorted(BODY_PROBLEMS))
def test_the_body_writes_its_sentences_and_warnings_as_trees(name, tmp_path):
    path = tmp_path / f"{name}.yaml"
    path.write_text(f"id: {name}\nkind: steady_precession\ngiven:\n  {BODY_PROBLEMS[name]}\n"
                    "  spin: 3000 rpm\n  theta: 60 deg\nfind:\n  precession: rpm\n")
    result = solve_file(str(path))
    body = [s for sec in result.solution.sections if sec.title == "Body" for s in sec.steps]
    texts = [s.text for s in body if s.prose is None and s.text] + \
        [w for w in result.solution.warnings if w not in result.solution.warning_prose]
    for text in texts:
        assert not [p for is_math, p in spans(text) if is_math], (name, text)
    assert any(s.prose is not None for s in body) or result.solution.warning_prose, name


def test_a_sentence_is_printed_when_read_and_its_overflow_is_bad_input(run, write):
    """A line of words and trees is printed only when something reads it (gyro check
    never does), and a quantity in it that overflows is refused as a step's would be."""
    import math as _math

    from gyro_cli.core.work import _PRINT

    work = Work()
    work.section("S")
    work.text("a moment of ", q(2.0, "N m"))
    step = work.sections[0].steps[0]
    assert step.__dict__["_text"] is _PRINT
    assert step.text == "a moment of 2.000 N m" and step.__dict__["_text"] == step.text
    from gyro_cli.core.errors import InputError

    for bad in (lambda: q(_math.inf, "N m"), lambda: qvec((0, _math.nan, 0), "N m"),
                lambda: q(complex(1.0, _math.inf)), lambda: matrix([[1.0, _math.inf]])):
        with pytest.raises(InputError, match="not a finite number"):
            bad()
    assert Prose(("x ", rel(H, "=", q(1.0, "N m")))).text == "x H = 1.000 N m"  # names: no value


def test_a_check_whose_quantity_overflows_is_one_line(run, write, monkeypatch):
    import dataclasses
    import importlib

    module = importlib.import_module("gyro_cli.kinds.gyrocompass")
    real = module.KIND.solve

    def overflowing(given, find, work):
        real(given, find, work)
        work.check("the moment ", q(float("inf"), "N m"))

    monkeypatch.setattr(module, "KIND", dataclasses.replace(module.KIND, solve=overflowing))
    path = write(template("gyrocompass"))
    result = run("solve", path)
    assert result.exit_code == 2 and "not a finite number" in result.output, result.output
    assert "Traceback" not in result.output
