"""Issue 36 item 1, one tree and one printer: one text printer in the package (HTML measures
inline maths with it) and one sign rule for a sum's terms, a broken row's included."""

from __future__ import annotations

from gyro_cli.core import expr as E
from gyro_cli.core import prose as P


def test_item01_one_text_printer_in_the_package():
    """The typesetting printers' module has no text printer of its own: plain text is
    `core.expr.TextPrinter`'s (and `core.prose.ProseText`'s), so two cannot disagree."""
    from gyro_cli.render import html, mathprint

    assert not hasattr(mathprint, "TextPrinter") and not hasattr(mathprint, "text")
    assert not hasattr(html, "plain_text")


def test_item01_inline_width_measured_by_the_one_text_printer():
    """A sentence's maths longer than `INLINE_WIDTH` in the text report's characters
    scrolls sideways on its own; as long or shorter, it does not."""
    from gyro_cli.render import html

    def sentence(count: int) -> tuple[P.Prose, str]:
        terms = P.names(" ".join(f"a{k}" for k in range(count)))
        tree: E.Expr = terms[0]
        for term in terms[1:]:
            tree = tree + term
        return P.Prose(("so ", tree)), P.text(tree)

    for count in range(2, 12):
        prose, text = sentence(count)
        scrolls = 'aria-label="formula (scrolls sideways)"' in html.prose_pieces_html(prose)
        assert scrolls == (len(text) > html.INLINE_WIDTH), (count, text)


def test_item01_a_rows_term_printed_by_the_sum_sign_rule():
    """A term starting a row of a broken display is printed by the rule a sum follows (its
    negative folded into the sign), not by printing ``0 + term`` and cutting the 0 off."""
    import inspect

    from gyro_cli.render import html, writeup
    from gyro_cli.render.mathml import MathMLPrinter
    from gyro_cli.render.mathprint import LatexPrinter, formula_node

    a, b, c = P.names("a b c")
    for sign, term, tex in (("+", -b, "- b"), ("-", -b, "+ b"), ("-", b * c, "- b c"),
                            ("+", b, "+ b")):
        node = formula_node(term)
        whole = formula_node(a + term if sign == "+" else a - term)
        assert LatexPrinter(True).term(sign, node) == tex
        assert LatexPrinter(True).doprint(whole) == "a " + tex  # the same rule as the sum
        mathml = MathMLPrinter(True)
        assert mathml.doprint(whole) == \
            mathml.doprint(formula_node(a)).join(("<mrow>", mathml.term(sign, node)[6:]))
    for module in (html, writeup):
        assert 'Num("0")' not in inspect.getsource(module), module


def test_item01_a_powers_base_bracketed_by_one_rule():
    """Whether a power's base is bracketed is decided once, in the shared base; LaTeX and
    MathML only spell the power (a brace, an <msubsup>)."""
    from gyro_cli.render.mathml import MathMLPrinter
    from gyro_cli.render.mathprint import LatexPrinter, TypesetPrinter, formula_node

    for printer in (LatexPrinter, MathMLPrinter):
        for name in ("_print_Pow", "_after_sign", "term"):
            assert name in vars(TypesetPrinter) and name not in vars(printer), (printer, name)
    a, b, theta_0 = P.names("a b theta_0")
    cases = (((a + b) ** 2, "(a + b)^{2}"), ((a / b) ** 2, r"\left(\frac{a}{b}\right)^{2}"),
             (theta_0 ** 2, r"{\theta_{0}}^{2}"), (a ** 2, "a^{2}"))
    for tree, tex in cases:
        assert LatexPrinter(True).doprint(formula_node(tree)) == tex
    mathml = MathMLPrinter(True).doprint(formula_node((a + b) ** 2))
    assert mathml.startswith("<msup><mrow><mo>(</mo>"), mathml
    assert MathMLPrinter(True).doprint(formula_node(theta_0 ** 2)).startswith("<msubsup>")
