"""Issue 36, items 1 and 2: one printer base, shared typesetting decisions, one way to
map a tree, one document walker and a registry of output formats."""

from __future__ import annotations

import inspect
import re
import sys
from collections.abc import Iterator
from contextlib import contextmanager

from gyro_cli.core import expr as E
from gyro_cli.core import prose as P


def test_item01_every_printer_subclasses_the_one_printer_base():
    from gyro_cli.render import mathml, mathprint

    printers = [E.TextPrinter, E.PythonPrinter, P.ProseText, mathprint.Lowering,
                mathprint.LatexPrinter, mathml.MathMLPrinter]
    for printer in printers:
        assert issubclass(printer, E.Printer), printer


def test_item01_latex_and_mathml_share_every_decision():
    """The two typesetting printers only spell: brackets, signs, fractions, products,
    functions, groups and relations are decided once, in their common base."""
    from gyro_cli.render.mathml import MathMLPrinter
    from gyro_cli.render.mathprint import LatexPrinter, TypesetPrinter

    shared = ("_print_Neg", "_print_BinOp", "_print_Call", "_print_Bracket", "_print_Rel",
              "_print_Num", "_print_Sym", "_print_Quantity", "_print_Prime", "_print_Words",
              "_print_Fn", "_print_Sign", "_print_Pm", "_print_Total", "_print_Integral",
              "_print_Mat", "_print_Vector", "_print_Matrix")
    for name in shared:
        assert name in vars(TypesetPrinter), name
        for printer in (LatexPrinter, MathMLPrinter):
            assert name not in vars(printer), (printer.__name__, name)


def test_item01_one_table_per_convention_for_both_formats():
    from gyro_cli.render import conventions, mathml, mathprint

    assert set(mathprint.RELATIONS_TEX) == set(mathml.RELATIONS) == set(conventions.RELATIONS)
    assert set(mathprint.SUM_TEX) == set(mathml.SUMS) == set(conventions.SIGNS)
    assert set(mathprint.FUNCTION_TEX) == set(conventions.FUNCTIONS)
    for name in ("split_symbol", "dotted", "tokens", "GREEK"):
        assert not hasattr(mathprint, name) or getattr(mathprint, name) is \
            getattr(conventions, name), name
        assert not hasattr(mathml, name) or getattr(mathml, name) is \
            getattr(conventions, name), name


def _every_node(x: E.Sym) -> list[E.Expr]:
    """One tree of each class that holds maths, each with ``x`` inside."""
    y = E.Sym("y", 2.0, "m")
    return [x, E.Let(E.Sym("D", 1.0), x * y), -x, x + y, x - y, x * y, x / y, x ** 2,
            E.sin(x), E.Chain(x * 1, x), E.SumOf(x * y, (x, y)),
            P.rel(x, "=", y), P.cross(x, y), P.dot(x, y), P.fn("f", x), P.total(x),
            P.signed("+-", x), P.mat((x, y)), P.integral(0, x, y), P.bracket(x, y),
            P.pm(y, x), P.words("(slow)", x, x), P.prime(x, 2)]


def test_item01_mapping_a_tree_is_one_generic_walk():
    """Every node exposes its children and is rebuilt from them: mapping the symbols
    reaches a symbol inside any node (a `Let`'s own symbol too)."""
    x = E.Sym("zz", 1.0, "m")
    for tree in _every_node(x):
        seen: list[str] = []

        def change(node: E.Expr) -> E.Expr | None:
            if isinstance(node, E.Sym):
                seen.append(node.name)  # noqa: B023 (called in this iteration)
                return E.Sym(node.name + "_new", node.si, node.unit)
            return None

        mapped = E.map_tree(tree, change)
        assert "zz" in seen, type(tree).__name__
        assert type(mapped) is type(tree)
        if isinstance(mapped, E.SumOf):  # its formula names the symbols: the terms change
            mapped = mapped.expanded()
        text = P.text(mapped)
        assert "zz_new" in text and not re.search(r"\bzz\b", text), text


def test_item01_map_values_converts_quantities_inside_any_node():
    q = P.q(1.0, "m")
    for tree in _every_node(E.Sym("x", 1.0, "m")):
        if isinstance(tree, E.Chain):  # a step's whole tree, never inside a sentence
            continue
        mapped = P.map_values(P.rel(tree, "=", q), lambda s: s,
                              lambda v: P.Quantity(v.si * 2, "ft"))
        assert P.text(mapped).endswith("= 2.000 ft"), P.text(mapped)


def test_item01_no_typesetting_node_for_text_already_set():
    import importlib.util

    assert importlib.util.find_spec("gyro_cli.render.mathtree") is None  # no Tex, no tree
    for module in ("mathprint", "mathml"):
        source = inspect.getsource(__import__(f"gyro_cli.render.{module}",
                                              fromlist=["x"]))
        assert "parse" not in source.replace("sparse", ""), module


ROOT = __import__("pathlib").Path(__file__).resolve().parents[1]
TWO = [str(ROOT / "problems" / "11_3.yaml"), str(ROOT / "problems" / "11_1.yaml")]


def test_item02_cli_and_api_read_one_registry_of_formats():
    """`gyro solve --format` offers exactly the registry's formats, and prints what the API
    composes from the same registry (a page, a standalone document, files one after
    another)."""
    from click.testing import CliRunner

    from gyro_cli import api
    from gyro_cli.cli import main, solve
    from gyro_cli.render import formats

    option = next(p for p in solve.params if p.name == "fmt")
    assert tuple(option.type.choices) == formats.NAMES == api.FORMATS
    results = [api.solve_file(path) for path in TWO]
    for fmt in formats.NAMES:
        out = CliRunner().invoke(main, ["solve", *TWO, "--format", fmt])
        assert out.exit_code == 0, out.output
        assert out.stdout == api.document(results, fmt), fmt
        assert results[0].render(fmt) == formats.get(fmt).one(results[0], 2)
    out = CliRunner().invoke(main, ["solve", *TWO, "--format", "latex", "--standalone"])
    assert out.stdout == api.document(results, "latex", standalone=True)
    assert api.document(results[:1], "html") == results[0].html(page=True)


@contextmanager
def switching_often() -> Iterator[None]:
    """Threads that hand over the interpreter every millisecond, not every 5 ms: one round
    of renders then meets a state the threads share as surely as two rounds did at the
    usual interval (a writer's keys shared: 8 of 9 one-round runs failed at 5 ms, 8 of 8
    at 1 ms), for a seventh more time instead of twice the time."""
    before = sys.getswitchinterval()
    sys.setswitchinterval(1e-3)
    try:
        yield
    finally:
        sys.setswitchinterval(before)


# Item 2's renders by 8 threads at once, in SI and US units, are test_i34_robust's
# test_item25_threads_render_what_one_thread_renders (every problem in SI, every sixth in
# US units too): the same threads' check of the same renders, made once.


def test_item02_one_walker_and_no_state_between_renders():
    """The write-ups walk a solution with `document.walk` and carry the file's keys in
    their writer: no module state is swapped around a render, and the HTML page uses no
    private helper of the LaTeX write-up."""
    from gyro_cli.render import document, html, writeup

    assert not hasattr(writeup, "_KEYS") and not hasattr(writeup, "keys_of")
    for writer in (writeup.MarkdownWriter, writeup.LatexWriter, html.HtmlWriter):
        assert issubclass(writer, document.Writer)
    source = inspect.getsource(html)
    assert "from .writeup import" not in source and "writeup." not in source
    calls = []
    original = document.walk

    def counted(result, writer):
        calls.append(type(writer).__name__)
        return original(result, writer)

    from gyro_cli import api

    r = api.solve_file(TWO[0])
    try:
        document.walk = counted
        writeup.walk = html.walk = counted  # the name each module calls
        r.render("markdown"), r.render("latex"), r.render("html")
    finally:
        document.walk = writeup.walk = html.walk = original
    assert calls == ["MarkdownWriter", "LatexWriter", "HtmlWriter"]


def test_item02_one_line_breaking_routine():
    from gyro_cli.render.document import pack

    items = [("a", 3.0), ("b", 3.0), ("c", 3.0), ("d", 9.0)]
    assert pack(items, 7) == [(["a", "b"], 6.0), (["c"], 3.0), (["d"], 9.0)]
    assert pack(items, 7, used=5) == [(["a"], 8.0), (["b", "c"], 6.0), (["d"], 9.0)]
    assert pack([("wide", 20.0)], 7) == [(["wide"], 20.0)]


def test_item01_one_sign_rule_reads_the_node_as_latex_writes_it():
    """Whether a term after a sign starts with a minus is decided from the node, once for
    LaTeX and MathML: for random formulas it agrees with the LaTeX as written."""
    import random

    from formula_oracle import ParseError, parse
    from oracle_tree import Unsupported, to_core

    from gyro_cli.render.mathprint import LatexPrinter

    vocab = ["-2.5", "3", "-1.5e-05", " kg", " deg", "x", "theta_0", "phidot", "^2", "(", ")",
             " / ", " ", " + ", " - ", "sin(", "'", ", "]
    rng = random.Random(36)
    checked = 0
    for _ in range(4000):
        text = "".join(rng.choice(vocab) for _ in range(rng.randint(1, 8)))
        try:
            node = to_core(parse(text))
        except (ParseError, RecursionError, ValueError, Unsupported):
            continue
        for display in (True, False):
            printer = LatexPrinter(display)
            assert printer.starts_minus(node) == printer.doprint(node).startswith("-"), text
        checked += 1
    assert checked > 300
