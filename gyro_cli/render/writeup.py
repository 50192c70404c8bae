"""Write-ups: a solved problem as Markdown or LaTeX for an instructor's solution sheet.

`gyro solve --format markdown|latex [--standalone]`. Each step of the worked
answer (``work.Step``: symbol, formula, substitution, value, unit, ref, text)
is typeset from the expression tree the kind wrote (`exprnodes` makes the
typesetting nodes of `mathtree`, `mathprint` sets them); a line of prose is
the words and trees the kind wrote (`core.prose`): words are set as text, trees
as maths, and nothing is parsed back from text. A display too wide for
the page is set as aligned rows, one per ``=``, and a long sum is broken
at its ``+`` and ``-``. A step citing one equation of the chapter is
numbered with it (``\\tag{11.13}``). LaTeX needs amsmath only (``--standalone``
writes a whole document); Markdown uses ``$...$`` and ``$$...$$`` (GitHub,
Pandoc, Jupyter).

Nothing here is imported by ``gyro solve`` in text or JSON.
"""

from __future__ import annotations

import re
from contextlib import contextmanager
from contextvars import ContextVar
from typing import Any, Iterator, Sequence

from ..core.errors import terminal_text
from ..core.work import num
from ..solving.solve import Result
from .formats import Format
from .exprnodes import formula_node, prose_nodes, substitution_node, symbol_node
from .mathprint import RELATIONS_TEX, LatexPrinter, number_tex, symbol_tex, text_escape, unit_tex
from .mathtree import BinOp, Group, Node, Num, Pow, Quantity, Rel, Sym, Text, Tuple

__all__ = ["markdown", "latex", "standalone", "symbol_latex", "words", "text_escape",
           "symbol_tex"]

#: a display wider than this (in characters of maths, about 5.5 pt each) is broken into rows;
#: the page of `standalone` is 17 cm, about 480 pt
WIDTH = 64

#: a line ending in the chapter's equation number: "udot^2 = f(u) = ...    (Eq. 11.19)"
_EQ = re.compile(r"^Eq\. (\d+\.\d+)(?:, (.+))?$")


# ---- formulas ---------------------------------------------------------------

def symbol_latex(text: str, tree=None) -> str:
    """A symbol as LaTeX maths (no delimiters): its tree, or one name; anything else (a
    symbol no kind writes) as words."""
    node = symbol_node(text, tree)
    if node is not None:
        return LatexPrinter(False).doprint(node)
    return f"\\text{{{text_escape(text)}}}" if text else "\\text{}"


# ---- the file's keys in prose -------------------------------------------------

#: keys of the problem being written that hold an underscore and are not symbols of its
#: kind (psi_rate, bearing_forces, engine_sense): in prose they are words, "psi rate".
#: A context variable, set by `keys_of`: a render in another thread (or task) sees its
#: own problem's keys, never this one's, and no module state changes.
_KEYS: ContextVar[re.Pattern | None] = ContextVar("gyro_file_keys", default=None)


@contextmanager
def keys_of(kind) -> Iterator[None]:
    """Within it, the keys of ``kind`` that are words come out as words in prose."""
    token = _KEYS.set(file_keys(kind))
    try:
        yield
    finally:
        _KEYS.reset(token)


def file_keys(kind) -> re.Pattern | None:
    """A pattern matching the kind's given and answer names that are words, not symbols."""
    from ..core.body import BODY_PARAMS

    params = list(kind.params) + (list(BODY_PARAMS) if kind.uses_body else [])
    names = {p.name for p in params} | {a.name for a in kind.answers}
    symbols = {p.symbol for p in params} | {a.symbol for a in kind.answers}
    words = {p.name for p in params if p.dimension == "word"}  # engine_sense
    keys = sorted((n for n in names if "_" in n and (n not in symbols or n in words)),
                  key=len, reverse=True)
    if not keys:
        return None
    return re.compile(r"(?<![\w.])(" + "|".join(map(re.escape, keys)) + r")(?!\w)")


def _split_keys(text: str) -> list[tuple[bool, str]]:
    """``text`` as (is_key, piece): a key comes out as words, ``psi rate``."""
    pattern = _KEYS.get()
    if pattern is None or not pattern.search(text):
        return [(False, text)]
    out, pos = [], 0
    for m in pattern.finditer(text):
        out += [(False, text[pos:m.start()]), (True, m.group().replace("_", " "))]
        pos = m.end()
    return out + [(False, text[pos:])]


def unit_latex(unit: str) -> str:
    if unit in ("deg", "degree"):
        return "^{\\circ}"
    if not unit:
        return ""
    return "\\," + unit_tex(unit.replace("*", " "))


def _quantity(value: float, unit: str) -> str:
    body = number_tex(num(value))
    if unit in ("deg", "degree") and "\\times" in body:
        body = "{" + body + "}"
    return body + unit_latex(unit)


def words(text: str, escape=text_escape) -> str:
    """Words as text, escaped; a key of the file (``psi_rate``) as words (``psi rate``).
    Maths in a sentence is a tree (`core.prose`), never read from its words."""
    return "".join(escape(piece) for _, piece in _split_keys(text))




# ---- width and breaking -----------------------------------------------------

def width(node: Node | None) -> float:
    """Rough width of the typeset node in characters (a stacked fraction is as wide as
    its wider part)."""
    if node is None:
        return 0
    if isinstance(node, BinOp):
        if node.op == "/":
            return max(width(_strip(node.left)), width(_strip(node.right))) + 1
        return width(node.left) + width(node.right) + (3 if node.op in "+-" else 1)
    if isinstance(node, Pow):
        return width(node.base) + 0.7 * width(node.exp)
    if isinstance(node, Quantity):
        return width(node.value) + 0.9 * len(node.unit) + 1
    if isinstance(node, Num):
        return len(node.text) + (4 if "e" in node.text.lower() else 0)
    if isinstance(node, Sym):
        return 1.2 + 0.7 * len(node.name.partition("_")[2])
    if isinstance(node, Rel):
        return width(node.first) + sum(3 + width(rhs) for _, rhs in node.rest)
    if isinstance(node, Text):
        return len(node.text)
    total = 2.0
    for value in vars(node).values():
        if isinstance(value, Node):
            total += width(value)
        elif isinstance(value, tuple):
            total += sum(width(x) + 1 for x in value if isinstance(x, Node))
            total += sum(width(x[1]) + 2 for x in value if isinstance(x, tuple))
        elif isinstance(value, str) and type(node).__name__ == "Call":
            total += len(value) if value not in ("|", ",") else 0
    return total


def _strip(node: Node) -> Node:
    while isinstance(node, Group) and node.open == "(":
        node = node.body
    return node


def _terms(node: Node) -> list[tuple[str, Node]]:
    """A sum as its terms with their signs: a - b + c -> [("", a), ("-", b), ("+", c)]."""
    if isinstance(node, BinOp) and node.op in ("+", "-"):
        return _terms(node.left) + [(node.op, node.right)]
    return [("", node)]


def _opened(piece: Node, printer) -> tuple[str, Node, str]:
    """A piece whose width is in one bracketed sum: the text before the sum, the sum and the
    text after (``a (b + c + d)`` -> ``a \\Bigl(``, b + c + d, ``\\Bigr)``)."""
    node = piece
    if isinstance(node, BinOp) and node.op == "/" and len(_terms(_strip(node.left))) > 1:
        den = printer.doprint(_strip(node.right))
        return f"\\frac{{1}}{{{den}}} \\Bigl(", _strip(node.left), " \\Bigr)"
    if isinstance(node, BinOp) and node.op in (" ", "*"):
        right = node.right
        if isinstance(right, Group) and len(_terms(right.body)) > 1 \
                and width(right) > width(node.left):
            o, c = ("[", "]") if right.open == "[" else ("(", ")")
            return f"{printer.doprint(node.left)} \\Bigl{o}", right.body, f" \\Bigr{c}"
    if isinstance(node, Group) and len(_terms(node.body)) > 1:
        o, c = ("[", "]") if node.open == "[" else ("(", ")")
        return f"\\Bigl{o}", node.body, f" \\Bigr{c}"
    return "", piece, ""


def _rows(lhs: str, pieces: list[Node], budget: float) -> list[tuple[str, str]]:
    """(left, right) rows of an aligned display: ``lhs = p1 = p2`` one ``=`` a row, a piece
    too wide broken at the + and - of its sum."""
    printer = LatexPrinter(True)
    rows: list[tuple[str, str]] = []
    for k, piece in enumerate(pieces):
        left = lhs if k == 0 else ""
        if width(piece) <= budget:
            rows.append((left, "= " + printer.doprint(piece)))
            continue
        prefix, inner, suffix = _opened(piece, printer)
        terms = _terms(inner)
        if len(terms) == 1:
            rows.append((left, "= " + printer.doprint(piece)))
            continue
        line, first = prefix, True
        used = width(piece) - width(inner)
        for sign, term in terms:
            text = printer.doprint(BinOp(sign, Num("0"), term))[2:] if sign else \
                printer.doprint(term)
            w = width(term) + 3
            if line.strip() and line != prefix and used + w > budget:
                rows.append((left if first else "", ("= " if first else "\\quad ") + line))
                first, line, used = False, "", 0.0
            line = f"{line} {text}".strip() if line else text
            used += w
        rows.append((left if first else "", ("= " if first else "\\quad ") + line + suffix))
    return rows


# ---- steps ------------------------------------------------------------------

def _step_pieces(step) -> tuple[Node | None, list[Node]]:
    lhs = symbol_node(step.symbol, getattr(step, "symbol_expr", None)) or Text(step.symbol)
    pieces: list[Node] = []
    tree = getattr(step, "shown", None)
    if tree is not None:  # built from an expression tree: typeset from it, nothing parsed
        if step.formula:
            pieces.append(formula_node(tree))
        if step.substitution:
            pieces.append(substitution_node(tree))
    elif step.formula or step.substitution:  # Work.step takes a formula as a tree only
        raise TypeError(f"the step {step.symbol} has a formula but no tree")
    if step.value is not None:
        unit = {"kg*m^2": "kg m^2", "N*m": "N m", "kg*m^2/s": "kg m^2/s"}.get(step.unit,
                                                                              step.unit)
        pieces.append(Quantity(Num(num(step.value)), unit) if unit else Num(num(step.value)))
    return lhs, pieces


def _tag(step) -> tuple[str, str]:
    """The chapter's equation number a step cites, and the rest of its reference."""
    m = _EQ.match(step.ref or "")
    return (m.group(1), m.group(2) or "") if m else ("", step.ref or "")


def _step_display(step, markdown: bool) -> tuple[str, list[str]]:
    """The display maths of a step and the prose lines that follow it."""
    lhs, pieces = _step_pieces(step)
    printer = LatexPrinter(True)
    left = printer.doprint(lhs)
    after = []
    tag, rest = _tag(step)
    notes = []
    if rest:
        notes.append(f"({rest})")
    if step.text and getattr(step, "prose", None) is None:
        notes.append(step.text)
    note = " ".join(notes)
    total = width(lhs) + sum(width(p) + 3 for p in pieces)
    widest = total if total <= WIDTH else \
        max(width(lhs) + 3 + min(width(p), WIDTH) for p in pieces)
    beside = ""  # a short note, set beside the equation

    def short(text: str) -> bool:
        return len(text) <= 48 and widest + len(text) + 4 <= WIDTH + 8

    if getattr(step, "prose", None) is not None:  # a note of words and trees
        maths = [p for p in prose_nodes(step.prose) if not (isinstance(p, str) and not p.strip())]
        if not note and short(step.text) and len(maths) == 1 and not isinstance(maths[0], str):
            beside = printer.doprint(maths[0])  # a note that is one formula: = 0.03283 deg/h
        elif not note and short(step.text):
            beside = "\\text{" + prose_latex(step.prose) + "}"
        else:
            if note:
                after.append(note)
            after.append(Typeset(prose_latex(step.prose, markdown)))
        note = ""
    if note and short(note):
        beside = _note_math(note)
    elif note:
        after.append(note)
    if total <= WIDTH:
        body = " = ".join([left] + [printer.doprint(p) for p in pieces])
    else:
        rows = _rows(left, pieces, WIDTH - min(width(lhs), 12) - 4)
        body = "\\begin{aligned}\n" + " \\\\\n".join(f"{a} &{b}" for a, b in rows) + \
            "\n\\end{aligned}"
    if beside:
        body += f" \\qquad {beside}"
    if tag:
        body += f" \\qquad \\text{{({tag})}}" if markdown else f" \\tag{{{tag}}}"
    return body, after


def _note_math(note: str) -> str:
    return "\\text{" + words(note) + "}"


def _steps(steps, markdown: bool) -> list[str]:
    out = []
    for step in steps:
        if step.symbol:
            body, after = _step_display(step, markdown)
            out += _display(body, markdown)
            out += [line if isinstance(line, Typeset) else _prose(line, markdown)
                    for line in after]
            if after:
                out.append("")
            continue
        if getattr(step, "prose", None) is not None:  # words and trees: nothing parsed
            out += _prose_step(step.prose, markdown)
            continue
        out += [_prose(step.text.strip(), markdown), ""]  # words only
    return out


class Typeset(str):
    """A line already set (a note written as words and trees)."""


def _prose_step(prose, markdown: bool) -> list[str]:
    """A line written as words and trees: one relation displayed (with the chapter's
    equation number it cites), else a paragraph with the maths inline."""
    equation = prose.equation()
    if equation is not None:
        rel, tag = equation
        tree = prose_nodes(type(prose)((rel,)))[0]
        number = (f" \\qquad \\text{{({tag})}}" if markdown else f" \\tag{{{tag}}}") if tag else ""
        if width(tree) <= WIDTH or not isinstance(tree, Rel):
            return _display(LatexPrinter(True).doprint(tree) + number, markdown)
        return _display("\\begin{aligned}\n" + " \\\\\n".join(_rel_rows(tree)) +
                        "\n\\end{aligned}" + number, markdown)
    return [prose_latex(prose, markdown), ""]


def prose_latex(prose, markdown: bool = False) -> str:
    """A sentence's words escaped (a key of the file as words) and its trees as inline
    maths."""
    escape = _md_escape if markdown else text_escape
    out = []
    for piece in prose_nodes(prose):
        if isinstance(piece, str):
            out += [escape(part) for _, part in _split_keys(piece)]
        else:
            out.append(f"${LatexPrinter(False).doprint(piece)}$")
    return "".join(out)


def _given_cell(g, markdown: bool) -> str:
    """The datum as read (a number and its unit, set as maths; words as words), and its
    note (words, or words and trees)."""
    shown = getattr(g, "shown", None)
    if shown is not None:
        number, unit = shown
        cell = f"${number_tex(number)}{unit_latex(unit)}$"
        if g.text.endswith(" (default)"):
            cell += " (default)"
    else:
        cell = _prose(_given_text(g), markdown)
    prose = getattr(g, "note_prose", None)
    if prose is not None:
        return cell + " (" + prose_latex(prose, markdown) + ")"
    return cell + (" (" + _prose(g.note, markdown) + ")" if g.note else "")


def _title(section, markdown: bool) -> str:
    prose = getattr(section, "prose", None)
    return _prose(section.title, markdown) if prose is None else prose_latex(prose, markdown)


def _warning(text: str, solution, markdown: bool) -> str:
    prose = getattr(solution, "warning_prose", {}).get(text)
    return _prose(text, markdown) if prose is None else prose_latex(prose, markdown)


def _rel_rows(tree: Rel) -> list[str]:
    printer = LatexPrinter(True)
    first = printer.doprint(tree.first) if tree.first is not None else ""
    rows = []
    for k, (op, rhs) in enumerate(tree.rest):
        sub = _rows("", [rhs], WIDTH - 8)
        for j, (_, right) in enumerate(sub):
            if j == 0:
                right = f"{RELATIONS_TEX[op]} {right[2:]}"
            rows.append(f"{first if k == 0 and j == 0 else ''} &{right}")
    return rows


def _display(body: str, markdown: bool) -> list[str]:
    if markdown:
        return [f"$$ {body} $$", ""]
    if "\\tag" in body:
        return ["\\begin{equation*}", body, "\\end{equation*}"]
    return [f"\\[ {body} \\]"]


def _prose(text: str, markdown: bool) -> str:
    return words(text, _md_escape if markdown else text_escape)


def _breakable(tex: str) -> str:
    """Long addresses may break after a slash (outside the maths)."""
    parts = re.split(r"(\$[^$]*\$)", tex)
    return "".join(p if p.startswith("$") else p.replace("/", "/\\allowbreak{}")
                   for p in parts)


def _md_escape(text: str) -> str:
    """Prose in Markdown: characters that Markdown would read as markup (or HTML: a
    title's <script>) escaped, on one line, control characters shown as escapes (the one
    place user strings meet Markdown)."""
    text = terminal_text(" ".join(text.splitlines()))
    return re.sub(r"([*_`|<>\[\]\\$&])", r"\\\1", text)


def _answer_lhs(answer) -> str:
    """``symbol = `` before an answer's values; nothing when the symbol is the name in words
    (``motion: retrograde``)."""
    tree = answer_symbol(answer)
    if tree is None or answer.symbol == answer.name \
            and not (answer.values and not isinstance(answer.values[0], str)) \
            and answer.symbol.isalpha() and len(answer.symbol) > 2:
        return ""
    if isinstance(tree, Group) and isinstance(tree.body, Tuple) and len(answer.values) > 1:
        return ""  # (I_1, I_2, I_3): one symbol per value, not the triple before each
    return LatexPrinter(False).doprint(tree) + " = "


def answer_symbol(answer) -> Node | None:
    """An answer's symbol as typesetting nodes (its tree, or its one name)."""
    return symbol_node(answer.symbol, getattr(answer, "symbol_expr", None))


def _answer_parts(answer) -> list[tuple[str, str]]:
    parts = []
    for i, value in enumerate(answer.values):
        if isinstance(value, str):
            body = f"\\text{{{text_escape(value)}}}"
        else:
            body = _quantity(value, answer.unit or "")
        label = answer.labels[i] if i < len(answer.labels) else ""
        parts.append((body, label))
    return parts


def _given_text(g) -> str:
    return g.text.replace("_", " ") if isinstance(g.si_value, str) else g.text


def _si(g) -> str:
    if isinstance(g.si_value, str):  # a word of the file (counterclockwise_from_bow)
        return f"\\text{{{text_escape(g.si_value.replace('_', ' '))}}}"
    return _quantity(g.si_value, g.si_unit)


# ---- Markdown ---------------------------------------------------------------

def markdown(result: Result) -> str:
    """The worked answer as Markdown with $-delimited LaTeX maths."""
    with keys_of(result.problem.kind):
        return _markdown(result)


def _markdown(result: Result) -> str:
    problem, solution = result.problem, result.solution
    lines = [f"## {_md_escape(problem.id)}: {_md_escape(problem.title)}".rstrip(": ")
             if problem.title else f"## {_md_escape(problem.id)}", ""]
    meta = [f"Kind: `{problem.kind.name}`"] + ([f"Source: {_md_escape(problem.source)}"]
                                              if problem.source else [])
    lines += ["*" + ". ".join(meta) + ".*", ""]
    for note in problem.notes:
        lines += [f"> {_prose(note, True)}", ""]
    lines += ["### Given", "", f"| | as given | {solution.system} |", "|---|---|---|"]
    for g in solution.given:
        lines.append(f"| ${symbol_latex(g.symbol, g.symbol_expr)}$ | "
                     f"{_md_cell(_given_cell(g, True))} | ${_si(g)}$ |")
    for section in solution.sections:
        lines += ["", f"### {_title(section, True)}", ""]
        lines += _steps(section.steps, True)
    if solution.checks:
        lines += ["", "### Check", ""]
        lines += _steps(solution.checks, True)
    lines += ["", "### Answer", ""]
    for name, answer in result.answers.items():
        lhs = _answer_lhs(answer)
        parts = [f"${lhs}{body}$" + (f" ({label})" if label else "")
                 for body, label in _answer_parts(answer)]
        lines.append(f"- **{name}**: " + ", ".join(parts))
    if solution.warnings:
        lines += ["", "### Warnings", ""]
        lines += [f"- {_warning(w, solution, True)}" for w in solution.warnings]
    return _squeeze("\n".join(lines)) + "\n"


def _md_cell(text: str) -> str:
    return text.replace("|", "\\|")


def _squeeze(text: str) -> str:
    return re.sub(r"\n{3,}", "\n\n", text)


# ---- LaTeX ------------------------------------------------------------------

def latex(result: Result, level: str = "subsection*") -> str:
    """The worked answer as a LaTeX fragment (needs amsmath) to paste into a solution sheet."""
    with keys_of(result.problem.kind):
        return _latex(result, level)


def _latex(result: Result, level: str) -> str:
    problem, solution = result.problem, result.solution
    title = f"{problem.id}: {problem.title}" if problem.title else problem.id
    lines = ["% gyro solve --format latex: paste into a document that loads amsmath"
             if level == "subsection*" else f"% {text_escape(problem.id)}",
             f"\\{level}{{{text_escape(title)}}}"]
    meta = text_escape(f"Kind: {problem.kind.name.replace('_', ' ')}.")
    if problem.source:
        meta += " Source: " + _breakable(_prose(problem.source, False))
    lines.append("\\textit{" + meta + "}")
    for note in problem.notes:
        lines += ["", _prose(note, False)]
    # a whole document may break a long table over pages; a fragment needs amsmath only
    table = "longtable" if level == "section" else "tabular"
    lines += ["", "\\subsubsection*{Given}", "", f"\\begin{{{table}}}{{@{{}}lp{{0.5\\linewidth}}l@{{}}}}",
              f"& as given & {solution.system} \\\\ \\hline"]
    for g in solution.given:
        lines.append(f"${symbol_latex(g.symbol, g.symbol_expr)}$ & {_given_cell(g, False)} & ${_si(g)}$ \\\\")
    lines.append(f"\\end{{{table}}}")
    for section in solution.sections:
        lines += ["", f"\\subsubsection*{{{_title(section, False)}}}", ""]
        lines += _steps(section.steps, False)
    if solution.checks:
        lines += ["", "\\subsubsection*{Check}", ""]
        lines += _steps(solution.checks, False)
    lines += ["", "\\subsubsection*{Answer}", "", "\\begin{itemize}"]
    for name, answer in result.answers.items():
        lhs = _answer_lhs(answer)
        parts = [f"${lhs}{body}$" + (f" ({text_escape(label)})" if label else "")
                 for body, label in _answer_parts(answer)]
        head = "" if lhs and symbol_tex(name) + " = " == lhs else \
            f"\\textbf{{{text_escape(name.replace('_', ' '))}}}: "
        lines.append(f"  \\item {head}" + ", ".join(parts))
    lines.append("\\end{itemize}")
    if solution.warnings:
        lines += ["", "\\subsubsection*{Warnings}", "", "\\begin{itemize}"]
        lines += [f"  \\item {_warning(w, solution, False)}" for w in solution.warnings]
        lines.append("\\end{itemize}")
    return _squeeze("\n".join(lines)) + "\n"


PREAMBLE = r"""\documentclass[10pt]{article}
\usepackage[a4paper,margin=2cm]{geometry}
\usepackage{amsmath}
\usepackage{longtable}
\setlength{\parindent}{0pt}
\setlength{\parskip}{0.5ex}
\emergencystretch=3em
\allowdisplaybreaks
"""


def standalone(results: list[Result], title: str = "Worked solutions") -> str:
    """A complete LaTeX document (pdflatex compiles it as it is): preamble, title, one
    section per problem."""
    if len(results) == 1 and results[0].problem.title:
        title = results[0].problem.title
    body = [PREAMBLE, f"\\title{{{text_escape(title)}}}", "\\date{}", "\\begin{document}",
            "\\maketitle", ""]
    for result in results:
        body.append(latex(result, level="section"))
    body.append("\\end{document}")
    return "\n".join(body) + "\n"


standalone_document = standalone  # a name the format's ``standalone`` flag does not hide


class _Markdown(Format):
    name = "markdown"
    separator = "\n"

    def one(self, result: Any, level: int = 2) -> str:
        return markdown(result.solved)


class _Latex(Format):
    """A fragment per file, or with ``standalone`` one document of every file."""

    name = "latex"
    separator = "\n"

    def one(self, result: Any, level: int = 2) -> str:
        return latex(result.solved)

    def composes(self, standalone: bool) -> bool:
        return standalone

    def document(self, results: Sequence[Any], pieces: Sequence[str | None],
                 standalone: bool = False, scripts: Sequence[str] = ()) -> str:
        if standalone:
            return standalone_document([r.solved for r in results])
        return super().document(results, pieces)


MARKDOWN, LATEX = _Markdown(), _Latex()
