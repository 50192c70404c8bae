"""Worked answers as HTML: a self-contained, accessible page, and fragments for Jupyter.

`gyro solve --format html` writes `page`; `gyro check --html` writes
`check_page`; a `Result` in Jupyter shows `worked_answer`. Other tools that
want the worked answer as HTML (quiz feedback, handouts) call
`worked_answer(result)`: an ``<article>`` that needs no stylesheet to read.

The page asks nothing of the network (no script, no web font, no stylesheet
or image from elsewhere; a Content-Security-Policy says so to the browser).
Formulas are MathML, which browsers render natively and screen readers speak;
pictures are inline SVG with a title that says what they show. Headings,
tables (with header cells) and lists are marked up as such, the language is
declared, colours meet WCAG 2.1 AA contrast in light and dark schemes
(``prefers-color-scheme``), the page reads at 360 px wide (long equations
break into rows at their ``=`` and their sums' signs, and scroll in their own
box where a single term is still wider), and it prints without its colours.
Every string from a problem file is HTML-escaped.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence
from html import escape as _escape
from typing import Any, TypeVar

from ..core import prose as P
from ..core.expr import Chain, Expr, Sym
from ..core.prose import text as prose_text
from ..core.work import num
from ..solving.solve import Result
from . import mathml
from .conventions import unit_spelling
from .document import (
    NO_KEYS,
    Keys,
    Writer,
    answer_lhs,
    equation_tag,
    pack,
    step_pieces,
    walk,
    width,
)
from .formats import Format
from .mathml import MathMLPrinter, math_element
from .mathprint import formula_node, op_of, prose_nodes, quantity_node, symbol_node

#: a tree as `mathprint.Lowering` sets it: core nodes
Node = Expr

_T = TypeVar("_T")


def _memo(function: Callable[[Node], _T]) -> Callable[[Node], _T]:
    """``function`` of a set tree, remembered for the last trees met by their shape
    (`shape`), so the variants of a bank share the formulas they have in common. A tree
    whose shape cannot be told is computed afresh."""
    remembered: dict[tuple, object] = {}

    def call(node: Node) -> _T:
        try:
            key = _shape_of(node)
        except TypeError:
            return function(node)
        value = remembered.get(key, _MISSING)  # one lookup: another thread may clear
        if value is _MISSING:
            value = function(node)
            if len(remembered) >= 256:
                remembered.clear()
            remembered[key] = value
        return value  # type: ignore[return-value]
    return call


_MISSING = object()

#: the shapes of the last trees met, by identity: a step's sides reach four of the memos
#: above (printed, width, rows), and walking a tree for its shape cost as much as printing
#: it. Each entry holds its tree, so that no other tree can take its id while it is here;
#: the trees are not changed once made.
_SHAPED: dict[int, tuple[object, tuple]] = {}


def _shape_of(node: object) -> tuple:
    """`shape`, walked once for a tree met again soon after (see _SHAPED)."""
    held = _SHAPED.get(id(node))  # one lookup: another thread may clear
    if held is not None and held[0] is node:
        return held[1]
    key = shape(node)
    if len(_SHAPED) >= 256:
        _SHAPED.clear()
    _SHAPED[id(node)] = (node, key)
    return key


def _slots(cls: type) -> tuple[str, ...]:
    return tuple(name for klass in reversed(cls.__mro__)
                 for name in getattr(klass, "__slots__", ()))


_SLOTS: dict[type, tuple[str, ...]] = {}


def shape(node: object) -> tuple:
    """A set tree as a key equal for trees the printers print alike: each node's class and
    every field it holds, but a symbol's SI value (a set tree shows a symbol by its name;
    `mathprint.Lowering` has already put a substitution's values in as quantities).
    TypeError for a field that is neither a node, a tuple, nor a plain value."""
    cls = node.__class__
    names = _SLOTS.get(cls)
    if names is None:
        names = _SLOTS[cls] = _slots(cls)
    key: list = [cls]
    for name in names:
        if cls is Sym and name == "si":
            continue
        key.append(_field(getattr(node, name, None)))
    return tuple(key)


def _field(value: object) -> object:
    if isinstance(value, Expr):
        return shape(value)
    if isinstance(value, (tuple, list)):
        return tuple(_field(item) for item in value)
    if value is None or isinstance(value, (str, int, float, bool)):
        return value
    raise TypeError(f"no shape for {type(value).__name__}")


def escape(text: str, quote: bool = True) -> str:
    """A string from a file in HTML (the one place they meet it): markup escaped, and a
    control character or bidi override shown as an escape (\\x1b), so a page printed to a
    terminal sends none raw. Line breaks and tabs stay."""
    text = _escape(text, quote)
    if text.isprintable():
        return text
    return "".join(c if c.isprintable() or c in "\n\t" else
                   c.encode("unicode_escape").decode("ascii") for c in text)


__all__ = ["worked_answer", "page", "document", "check_page", "check_body", "STYLE", "PAGE_STYLE",
           "formula_mathml", "prose_html"]

#: a step wider than this (characters of maths) is set as rows, one ``=`` a row
ROW_WIDTH = 30
#: inline maths wider than this may not fit a phone's line: it scrolls in its own box
INLINE_WIDTH = 30

#: the page: colours for both schemes, body, skip link, print (variables on :root)
PAGE_STYLE = """
:root { color-scheme: light dark; --fg: #1b1b1b; --bg: #ffffff; --muted: #4a4a4a;
  --rule: #c8c8c8; --link: #0645ad; --note-bg: #fff4e0; --note-fg: #3d2600;
  --fail: #a3001b; --pass: #1d5e20; }
@media (prefers-color-scheme: dark) {
  :root { --fg: #e8e8e8; --bg: #161616; --muted: #c4c4c4; --rule: #5a5a5a;
    --link: #9cc3ff; --note-bg: #3b2a0a; --note-fg: #ffe4b0; --fail: #ff9a9a;
    --pass: #8fdc8f; }
}
html { -webkit-text-size-adjust: 100%; }
body { margin: 0; background: var(--bg); color: var(--fg);
  font: 1rem/1.5 system-ui, -apple-system, "Segoe UI", Roboto, "Noto Sans", sans-serif; }
main { max-width: 52rem; margin: 0 auto; padding: 1rem; }
a { color: var(--link); }
h1 { font-size: 1.5rem; line-height: 1.25; }
h2 { font-size: 1.3rem; line-height: 1.3; margin-top: 2rem; }
.skip { position: absolute; left: -10000px; }
.skip:focus { position: static; }
@media print {
  :root { --fg: #000; --bg: #fff; --muted: #333; --rule: #999; --link: #000;
    --note-bg: #fff; --note-fg: #000; --fail: #000; --pass: #000; }
  body { font-size: 10.5pt; }
  main { max-width: none; padding: 0; }
  .skip { display: none; }
}
"""

#: the worked answer and the check table, scoped under .gyro; without the page's
#: variables (in Jupyter) the text keeps the notebook's own colours
STYLE = """
.gyro h3 { font-size: 1.1rem; margin: 1.4rem 0 0.4rem; }
.gyro h4 { font-size: 1rem; margin: 1.2rem 0 0.3rem; }
.gyro .meta, .gyro .eqno, .gyro .stepnote, .gyro figcaption { color: var(--muted, inherit); }
.gyro .eq { display: flex; flex-wrap: wrap; align-items: baseline; column-gap: 1rem;
  margin: 0.3rem 0; }
.gyro .eq > .m { max-width: 100%; overflow-x: auto; overflow-y: hidden; }
.gyro .eq math[display="block"] { display: block math; text-align: left; margin: 0.15rem 0; }
.gyro .eq mtd { text-align: left; padding: 0.1em 0; }
.gyro .mi { display: inline-block; max-width: 100%; overflow-x: auto; overflow-y: hidden;
  vertical-align: middle; }
.gyro .stepnote { margin: 0 0 0.4rem 1rem; }
.gyro p { margin: 0.4rem 0; overflow-wrap: anywhere; }
.gyro math { font-size: 1.15em; }
.gyro h2 math, .gyro h3 math, .gyro h4 math { font-size: 1em; }  /* a heading's formula fits 360 px */
.gyro .table { max-width: 100%; overflow-x: auto; }
.gyro table { border-collapse: collapse; margin: 0.4rem 0; }
.gyro th, .gyro td { border-bottom: 1px solid var(--rule, #c8c8c8);
  padding: 0.25rem 0.6rem 0.25rem 0; text-align: left; vertical-align: baseline; }
.gyro td { overflow-wrap: anywhere; }
.gyro thead th { border-bottom: 2px solid var(--rule, #c8c8c8); }
.gyro .warnings { background: var(--note-bg, #fff4e0); color: var(--note-fg, #3d2600);
  padding: 0.3rem 1rem; border-radius: 0.3rem; }
.gyro .warnings a { color: inherit; }
.gyro figure { margin: 1rem 0; }
.gyro svg.picture { display: block; max-width: 100%; height: auto; background: #ffffff; }
.gyro figcaption { font-size: 0.95rem; }
.gyro .fail { color: var(--fail, #a3001b); font-weight: 600; }
.gyro .pass { color: var(--pass, #1d5e20); }
.gyro .error { color: var(--fail, #a3001b); font-weight: 600; }
.gyro blockquote { margin: 0.4rem 0 0.4rem 1rem; }
.gyro table.check td { overflow-wrap: break-word; min-width: 5.5rem; }
.gyro table.check td:first-child { min-width: 0; }
.gyro table.check td:last-child { min-width: 14rem; }
.gyro table.check caption { text-align: left; }
.gyro .file, .gyro .small { font-size: 0.9rem; }
.gyro .file { color: var(--muted, inherit); overflow-wrap: anywhere; }
@media print {
  .gyro .eq > .m, .gyro .table, .gyro .mi { overflow: visible; }
  .gyro article.problem { break-before: page; }
  .gyro article.problem:first-of-type { break-before: auto; }
  .gyro h2, .gyro h3, .gyro h4 { break-after: avoid; }
  .gyro .eq, .gyro figure, .gyro tr { break-inside: avoid; }
  .gyro .warnings { border: 1px solid #000; }
}
"""

# No request may leave the page: nothing loads from anywhere, styles are inline.
CSP = "default-src 'none'; style-src 'unsafe-inline'; img-src data:"


# ---- the switch: formulas -----------------------------------------------------

def formula_mathml(node: Node, display: bool = True) -> str:
    """The one place a formula becomes MathML (content of a <math> element); the last
    trees met are remembered by their shape (`_memo`)."""
    return (_display_mathml if display else _inline_mathml)(node)


@_memo
def _display_mathml(node: Node) -> str:
    return mathml.tree_mathml(node, True)


@_memo
def _inline_mathml(node: Node) -> str:
    return mathml.tree_mathml(node, False)


def _math(node: Node, display: bool = False) -> str:
    return math_element(formula_mathml(node, display), display=display)


def prose_html(text: str, keys: Keys = NO_KEYS) -> str:
    """Words, escaped; the file's keys (psi_rate, in ``keys``) as words. Maths in a sentence
    is a tree (`core.prose`, `prose_pieces_html`), never read from its words."""
    return keys.words(text, escape)


def _inline(tree: Expr) -> str:
    """Inline maths; a long chain ``a = b = c`` as one <math> per link, so that the line
    may wrap between them on a narrow screen. Its length in characters is the one text
    printer's (`core.prose.ProseText`), as the text report writes it."""
    node = formula_node(tree)
    links = _links(tree)
    if links is not None and width(node) > 16:
        first, rest = links
        return " ".join([_inline(first)] + [_inline(P.Rel(None, ((op, rhs),)))
                                            for op, rhs in rest])
    if len(prose_text(tree)) > INLINE_WIDTH:  # may be wider than a phone: its own sideways scroll
        return (f'<span class="mi" tabindex="0" role="group" aria-label="formula (scrolls '
                f'sideways)">{_math(node)}</span>')
    return _math(node)


def _links(tree: Expr) -> tuple[Expr, tuple[tuple[str, Expr], ...]] | None:
    """A chain's first side and its (relation, side) links; None for anything else or a
    chain continuing the line before it (``= x``)."""
    if isinstance(tree, P.Rel) and tree.first is not None:
        return tree.first, tree.rest
    if isinstance(tree, Chain):
        return tree.forms[0], tuple(("=", form) for form in tree.forms[1:])
    return None


# ---- steps ----------------------------------------------------------------------

def _terms(node: Node) -> list[tuple[str, Node]]:
    """A sum as its signed terms, a product as its factors (the places a row may break)."""
    op = op_of(node)
    pair: Any = node  # a binary node: its left and right
    if op in ("+", "-"):
        return _terms(pair.left) + [(op, pair.right)]
    if op in (" ", "*", ".", "x"):
        left = _terms(pair.left) if not _is_sum(pair.left) else [("", pair.left)]
        if len(left) > 1 and any(sign in ("+", "-") for sign, _ in left[1:]):
            return [("", node)]
        return left + [(str(op), pair.right)]
    return [("", node)]


def _is_sum(node: Node) -> bool:
    return op_of(node) in ("+", "-")


def _piece_rows(piece: Node, budget: float) -> list[tuple[str, float]]:
    """One right-hand side as MathML rows with their widths: whole, or broken at the signs
    of its sum or between the factors of its product."""
    printer = MathMLPrinter(True)
    terms = _terms(piece)
    whole = width(piece)
    if whole <= budget or len(terms) == 1:
        return [(printer.doprint(piece), whole)]
    items = []
    for sign, term in terms:
        if sign in ("+", "-"):
            text = printer.term(sign, term)
        elif sign:
            op = {" ": mathml.INVISIBLE_TIMES, "*": "<mo>⋅</mo>", ".": "<mo>⋅</mo>",
                  "x": "<mo>×</mo>"}[sign]
            factor = printer.parenthesize(term, mathml.PRECEDENCE["*"])
            if sign == " ":  # never the first: that has no sign
                op = mathml.THIN + op
            text = f"<mrow>{op}{factor}</mrow>"
        else:
            text = printer.doprint(term) if _is_sum(piece) else \
                printer.parenthesize(term, mathml.PRECEDENCE["*"])
        items.append((text, width(term) + (3 if sign in ("+", "-") else 1)))
    return [("".join(row), used) for row, used in pack(items, budget)]


@_memo
def _printed(node: Node) -> str:
    return MathMLPrinter(True).doprint(node)


@_memo
def _node_width(node: Node) -> float:
    return width(node)


@_memo
def _rows(piece: Node) -> tuple[tuple[str, float], ...]:
    return tuple(_piece_rows(piece, ROW_WIDTH))


def _equation(lhs: Node | None, pieces: list[Node], relation: str = "=") -> tuple[str, bool]:
    """``lhs = p1 = p2 ...`` as one <math> element (rows in an <mtable> when wide);
    also whether it may still be wider than a phone (then its box scrolls)."""
    left = _printed(lhs) if lhs is not None else ""
    rel = f"<mo>{mathml.RELATIONS[relation]}</mo>"
    total = (_node_width(lhs) if lhs is not None else 0) + sum(_node_width(p) + 3
                                                                for p in pieces)
    if total <= ROW_WIDTH:
        body = left + "".join(rel + _printed(p) for p in pieces)
        return math_element(f"<mrow>{body}</mrow>", display=True), False
    rows, wide = [], False
    for k, piece in enumerate(pieces):
        for j, (row, w) in enumerate(_rows(piece)):
            head = left if k == 0 and j == 0 else ""
            op = rel if j == 0 else "<mspace width=\"1em\"/>"
            wide = wide or w > ROW_WIDTH - 2
            rows.append(f"<mtr><mtd><mrow>{head}</mrow></mtd><mtd><mrow>{op}{row}</mrow></mtd></mtr>")
    wide = wide or width(lhs) > 12
    return math_element(f'<mtable displaystyle="true">{"".join(rows)}</mtable>',
                        display=True), wide


def _eq_div(math: str, wide: bool, tag: str = "", note: str = "", keys: Keys = NO_KEYS) -> str:
    """An equation's box: the maths (focusable when it may scroll), its chapter number."""
    focus = ' tabindex="0" role="group" aria-label="equation (scrolls sideways)"' if wide else ""
    out = f'<div class="eq"><div class="m"{focus}>{math}</div>'
    if tag:
        out += f'<span class="eqno">(Eq. {escape(tag)})</span>'
    out += "</div>"
    if note:
        out += f'<p class="stepnote">{prose_html(note, keys)}</p>'
    return out


def _step_html(step: Any, keys: Keys = NO_KEYS) -> str:
    if step.symbol:
        lhs, pieces = step_pieces(step)
        tag, rest = equation_tag(step)
        prose = getattr(step, "prose", None)
        notes = ([f"({rest})"] if rest else []) + ([step.text] if step.text and prose is None
                                                   else [])
        math, wide = _equation(lhs, pieces)
        out = _eq_div(math, wide, tag, " ".join(notes), keys)
        if prose is not None:  # a note of words and trees
            out += f'<p class="stepnote">{prose_pieces_html(prose, keys)}</p>'
        return out
    if getattr(step, "prose", None) is not None:  # words and trees: nothing parsed
        return _prose_step_html(step.prose, keys)
    return f"<p>{prose_html(step.text.strip(), keys)}</p>"  # words only


def _relation_html(tree: Node, tag: str = "") -> str:
    """A displayed relation: one chain of one kind of relation in rows, else as it is."""
    if isinstance(tree, P.Rel) and tree.rest and tree.first is not None \
            and len({op for op, _ in tree.rest}) == 1:
        math, wide = _equation(tree.first, [rhs for _, rhs in tree.rest], tree.rest[0][0])
    else:
        math = _math(tree, display=True)
        wide = width(tree) > ROW_WIDTH + 8
    return _eq_div(math, wide, tag)


def _prose_step_html(prose: Any, keys: Keys = NO_KEYS) -> str:
    """A line written as words and trees: a relation displayed, else a paragraph."""
    equation = prose.equation()
    if equation is not None:
        rel, tag = equation
        tree = prose_nodes(type(prose)((rel,)))[0]
        assert not isinstance(tree, str)
        return _relation_html(tree, tag)
    return f"<p>{prose_pieces_html(prose, keys)}</p>"


def _warning_html(text: str, solution: Any, keys: Keys = NO_KEYS) -> str:
    prose = solution.warning_prose.get(text)
    return prose_html(text, keys) if prose is None else prose_pieces_html(prose, keys)


def prose_pieces_html(prose: Any, keys: Keys = NO_KEYS) -> str:
    """A sentence's words escaped (a key of the file as words), its trees inline MathML."""
    out = []
    for piece in prose.pieces:
        if isinstance(piece, str):
            out += [escape(part) for _, part in keys.split(piece)]
        else:
            out.append(_inline(piece))
    return "".join(out)


# ---- a worked answer --------------------------------------------------------------

def _heading(level: int, text: str, ident: str | None = None) -> str:
    level = min(max(level, 1), 6)
    attr = f' id="{escape(ident)}"' if ident else ""
    return f"<h{level}{attr}>{text}</h{level}>"


def _quantity(value: float | str, unit: str | None) -> str:
    if isinstance(value, str):
        return escape(value.replace("_", " "))
    unit = unit_spelling(unit or "")
    return _math(quantity_node(num(value), unit))


def _given_table(result: Result, level: int, keys: Keys = NO_KEYS) -> str:
    solution = result.solution
    rows = []
    for g in solution.given:
        symbol = symbol_node(g.symbol, g.symbol_expr)
        sym = _math(symbol) if symbol is not None else escape(g.symbol)
        text = g.text.replace("_", " ") if isinstance(g.si_value, str) else g.text
        note = f" ({escape(g.note)})" if g.note else ""
        if g.note_prose is not None:
            note = f" ({prose_pieces_html(g.note_prose, keys)})"
        cell = escape(text)
        if g.shown is not None:  # the quantity as read, as maths
            cell = _math(quantity_node(g.shown[0], g.shown[1]))
            cell += " (default)" if g.text.endswith(" (default)") else ""
        rows.append(f"<tr><th scope=\"row\">{sym}</th><td>{cell}{note}</td>"
                    f"<td>{_quantity(g.si_value, g.si_unit)}</td></tr>")
    return (_heading(level, "Given") + _table_box("Given") + '<table><thead><tr><th scope="col">symbol</th>'
            f'<th scope="col">as given</th><th scope="col">{escape(solution.system)}</th>'
            "</tr></thead><tbody>" + "".join(rows) + "</tbody></table></div>")


def _answers_table(result: Result, level: int) -> str:
    rows = []
    for name, answer in result.answers.items():
        parts = []
        for i, value in enumerate(answer.values):
            label = answer.labels[i] if i < len(answer.labels) else ""
            parts.append(_quantity(value, answer.unit if not isinstance(value, str) else None)
                         + (f" ({escape(label)})" if label else ""))
        tree = answer_lhs(answer)
        lhs = _math(tree) if tree is not None else ""
        values = ", ".join(parts) if parts else "none"
        rows.append(f'<tr id="{escape(_answer_id(result, name))}"><th scope="row">'
                    f"{escape(name.replace('_', ' '))}</th><td>{lhs}</td><td>{values}</td></tr>")
    return (_heading(level, "Answer") + _table_box("Answers") + '<table class="answers"><thead><tr><th scope="col">answer</th>'
            '<th scope="col">symbol</th><th scope="col">value</th></tr></thead><tbody>'
            + "".join(rows) + "</tbody></table></div>")


def _table_box(label: str) -> str:
    """A table's box: it scrolls sideways where the screen is narrower than the table, so it
    can take the keyboard's focus (WCAG 2.1.1) and is named for screen readers."""
    return f'<div class="table" role="region" tabindex="0" aria-label="{escape(label)} table">'


def anchor(result_or_file) -> str:
    """The id of a problem's worked answer on a page (from its file, else its id)."""
    if isinstance(result_or_file, str):
        key = result_or_file
    else:
        problem = result_or_file.problem
        key = problem.file or str(problem.id)
    return "p-" + re.sub(r"[^A-Za-z0-9_-]+", "-", key).strip("-")


def _answer_id(result: Result, name: str) -> str:
    return f"{anchor(result)}-{name}"


def worked_answer(result: Result, level: int = 2, picture: bool = True,
                  ident: str | None = None, animation: str = "") -> str:
    """One solved problem as an ``<article>``: title, source, notes, picture, Given table,
    the steps with MathML formulas, the checks, the answers and the warnings.

    ``level``: the heading level of the title (sections one below); ``animation``: a
    figure of the motion (render.animate.html_fragment) placed after the picture. Needs no
    stylesheet to read; `STYLE` lays it out (rows, tables, dark mode).
    """
    writer = HtmlWriter(Keys.of(result.problem.kind), level, picture, ident or anchor(result),
                        animation)
    return "\n".join(x for x in walk(result, writer) + ["</article>"] if x)


class HtmlWriter(Writer):
    """The parts of a worked answer as HTML: an <article> (closed by the caller), headings
    from ``level``, the picture and an animation before the Given table."""

    def __init__(self, keys: Keys = NO_KEYS, level: int = 2, picture: bool = True,
                 ident: str = "", animation: str = "") -> None:
        super().__init__(keys)
        self.level, self.picture, self.ident, self.animation = level, picture, ident, animation

    def head(self, result: Any) -> list[str]:
        problem, ident = result.problem, self.ident
        title = f"{problem.id}: {problem.title}" if problem.title else str(problem.id)
        meta = f"Kind: {escape(problem.kind.name.replace('_', ' '))}."
        if problem.source:
            meta += f" Source: {escape(problem.source)}."
        return [f'<article class="problem" aria-labelledby="{escape(ident)}">',
                _heading(self.level, escape(title), ident), f'<p class="meta">{meta}</p>']

    def note(self, note: str) -> list[str]:
        return [f"<blockquote><p>{prose_html(note, self.keys)}</p></blockquote>"]

    def given(self, result: Any) -> list[str]:
        out = [_figure(result, self.ident)] if self.picture else []
        return out + [self.animation, _given_table(result, self.level + 1, self.keys)]

    def section(self, section: Any) -> list[str]:
        return [_heading(self.level + 1, prose_html(section.title, self.keys)
                         if section.prose is None else prose_pieces_html(section.prose, self.keys))]

    def checks(self) -> list[str]:
        return [_heading(self.level + 1, "Check")]

    def step(self, step: Any) -> list[str]:
        return [_step_html(step, self.keys)]

    def answers(self, result: Any) -> list[str]:
        return [_answers_table(result, self.level + 1)]

    def warnings(self, solution: Any) -> list[str]:
        return [f'<section class="warnings" aria-label="warnings">'
                f"{_heading(self.level + 1, 'Warnings')}<ul>"
                + "".join(f"<li>{_warning_html(w, solution, self.keys)}</li>"
                          for w in solution.warnings)
                + "</ul></section>"]


def _figure(result: Result, ident: str) -> str:
    from .picture import picture

    if not result.problem.kind.picture:
        return ""
    pic = picture(result, prefix=f"{ident}-fig")
    if pic is None:
        return ""
    return f"<figure>{pic.svg}<figcaption>{escape(pic.alt)}</figcaption></figure>"


# ---- pages ------------------------------------------------------------------------

def csp(scripts: Sequence[str] = ()) -> str:
    """The page's Content-Security-Policy: nothing leaves the page, and the only scripts
    that run are ``scripts`` (the embedded animations' players), allowed by their hash."""
    if not scripts:
        return CSP
    import base64
    import hashlib

    hashes = " ".join("'sha256-" + base64.b64encode(hashlib.sha256(s.encode()).digest())
                      .decode() + "'" for s in scripts)
    return f"{CSP}; script-src {hashes}"


def document(title: str, body: str, scripts: Sequence[str] = ()) -> str:
    """A whole HTML document around ``body`` (inside <main>); ``scripts``: the inline
    scripts of ``body`` the page may run."""
    return ("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
            f"<meta http-equiv=\"Content-Security-Policy\" content=\"{csp(scripts)}\">\n"
            "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
            "<meta name=\"color-scheme\" content=\"light dark\">\n"
            "<meta name=\"generator\" content=\"gyro\">\n"
            f"<title>{escape(title)}</title>\n<style>{PAGE_STYLE}{STYLE}</style>\n</head>\n"
            "<body>\n<a class=\"skip\" href=\"#main\">Skip to the content</a>\n"
            f"<main id=\"main\" class=\"gyro\">\n{body}\n</main>\n</body>\n</html>\n")


def page(results: list[Result], title: str | None = None,
         articles: list[str] | None = None, scripts: Sequence[str] = ()) -> str:
    """One self-contained page: a single problem, or several with a contents list.
    ``articles``: their `worked_answer`, already rendered (at level 1 for one problem, 2
    for several: the command renders each file on its own, so that a failure is that
    file's alone)."""
    if len(results) == 1:
        r = results[0]
        title = title or (f"{r.problem.id}: {r.problem.title}" if r.problem.title
                          else str(r.problem.id))
        return document(title, worked_answer(r, level=1) if articles is None else articles[0],
                        scripts)
    title = title or "Worked solutions"
    items = "".join(f'<li><a href="#{escape(anchor(r))}">{escape(str(r.problem.id))}'
                    + (f": {escape(r.problem.title)}" if r.problem.title else "") + "</a></li>"
                    for r in results)
    body = [f"<h1>{escape(title)}</h1>",
            f'<nav aria-label="problems"><h2>Problems</h2><ol>{items}</ol></nav>']
    body += articles if articles is not None else [worked_answer(r, level=2) for r in results]
    return document(title, "\n".join(body), scripts)


def check_page(run, results: dict[str, Result] | None = None,
               title: str = "gyro check") -> str:
    """`gyro check --html`: the check table as a page, failing answers (and bad files) first,
    each linking to its worked answer further down the page."""
    return document(title, f"<h1>{escape(title)}</h1>\n" + check_body(run, results, level=2))


def check_body(run, results: dict[str, Result] | None = None, level: int = 2) -> str:
    """The check report without its page: summary, table, worked answers (headings from
    ``level``)."""
    from .check_report import summary_line

    results = results or {}
    rows = []
    order = {"error": 0, "fail": 1, "no expected answers": 3, "pass": 2}
    for p in sorted(run.problems, key=lambda p: order.get(p.status, 9)):
        where = escape(p.file) if p.file not in results else \
            f'<a href="#{escape(anchor(results[p.file]))}">{escape(p.file)}</a>'
        problem = f'<span class="file">{where}</span>'
        if p.status == "error":
            rows.append((0, f'<tr><td class="error">ERROR</td><td>{problem}</td>'
                            f'<td colspan="3">{escape(p.error or "")}</td></tr>'))
            continue
        if p.status == "no expected answers":
            rows.append((3, f"<tr><td>----</td><td>{problem}</td>"
                            '<td colspan="3">no expected answers (not checked)</td></tr>'))
            continue
        for a in p.answers:
            status = "PASS" if a.passed and a.keyed else "----" if a.passed else "FAIL"
            cls = {"PASS": "pass", "FAIL": "fail"}.get(status, "")
            target = results.get(p.file)
            label = escape(a.label)
            if target is not None and a.name in target.answers:
                label = f'<a href="#{escape(_answer_id(target, a.name))}">{label}</a>'
            note = a.message if not a.passed or not a.keyed else ""
            if a.slip:
                note += f"; likely slip: {a.slip}"
            error = "" if a.relative_error is None else f"{a.relative_error * 100:+.2f}%"
            got = escape(a.got or "-") + (f'<br><span class="small">{escape(error)}, '
                                          f'tolerance {escape(a.tolerance)}</span>'
                                          if error else "")
            rows.append((0 if status == "FAIL" else 2 if status == "PASS" else 1,
                         f'<tr><td class="{cls}">{status}</td><td>{label}<br>{problem}</td>'
                         f"<td>{escape(a.expected or '-')}</td><td>{got}</td>"
                         f"<td>{escape(note)}</td></tr>"))
    rows.sort(key=lambda r: r[0])
    table = (_table_box("Checked answers") + '<table class="check"><caption>Every checked '
             'answer, failing ones first</caption><thead><tr><th scope="col">status</th>'
             '<th scope="col">answer and file</th><th scope="col">expected</th>'
             '<th scope="col">got (error, tolerance)</th><th scope="col">note</th>'
             "</tr></thead><tbody>" + "".join(r[1] for r in rows) + "</tbody></table></div>")
    body = [f"<p><strong>{escape(summary_line(run))}</strong></p>",
            _heading(level, "Answers"), table]
    if results:
        body.append(_heading(level, "Worked answers"))
        body += [worked_answer(r, level=level + 1) for r in results.values()]
    return "\n".join(body)


class _Html(Format):
    """Every file's worked answer on one self-contained page."""

    name = "html"

    def one(self, result: Any, level: int = 2) -> str:
        return worked_answer(result.solved, level=level)

    def composes(self, standalone: bool) -> bool:
        return True

    def document(self, results: Sequence[Any], pieces: Sequence[str | None],
                 standalone: bool = False, scripts: Sequence[str] = ()) -> str:
        articles = None if any(p is None for p in pieces) else [str(p) for p in pieces]
        return page([r.solved for r in results], articles=articles, scripts=list(scripts))


HTML = _Html()
