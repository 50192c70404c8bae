"""Write-ups: a solved problem as Markdown or LaTeX for an instructor's solution sheet.

`gyro solve --format markdown|latex [--standalone]`. The solution is walked once
(`document.walk`); `MarkdownWriter` and `LatexWriter` write its parts. Each step
of the worked answer (``work.Step``: symbol, formula, substitution, value, unit,
ref, text) is typeset from the expression tree the kind wrote (`mathprint` sets its
core nodes); a line of prose is
the words and trees the kind wrote (`core.prose`): words are set as text, trees
as maths, and nothing is parsed back from text. A display too wide for the page
is set as aligned rows, one per ``=``, and a long sum is broken at its ``+`` and
``-`` (`document.pack`). A step citing one equation of the chapter is numbered
with it (``\\tag{11.13}``). LaTeX needs amsmath only (``--standalone`` writes a
whole document); Markdown uses ``$...$`` and ``$$...$$`` (GitHub, Pandoc,
Jupyter).

Nothing here is imported by ``gyro solve`` in text or JSON.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from typing import Any

from ..core import expr as E
from ..core import prose as P
from ..core.errors import terminal_text
from ..core.work import num
from ..solving.solve import Result
from .document import (
    NO_KEYS,
    Keys,
    Writer,
    answer_lhs,
    equation_tag,
    file_keys,
    pack,
    step_pieces,
    unbracketed,
    walk,
    width,
)
from .formats import Format
from .mathprint import (
    RELATIONS_TEX,
    LatexPrinter,
    grouped,
    number_tex,
    op_of,
    prose_nodes,
    symbol_node,
    symbol_tex,
    text_escape,
    unit_tex,
)

#: a tree as `mathprint.Lowering` sets it: core nodes
Node = E.Expr

__all__ = ["markdown", "latex", "standalone", "symbol_latex", "words", "text_escape",
           "symbol_tex", "file_keys", "prose_latex", "Keys", "MarkdownWriter", "LatexWriter",
           "steps_lines"]

#: a display wider than this (in characters of maths, about 5.5 pt each) is broken into rows;
#: the page of `standalone` is 17 cm, about 480 pt
WIDTH = 64


# ---- formulas ---------------------------------------------------------------

def symbol_latex(text: str, tree: Any = None) -> str:
    """A symbol as LaTeX maths (no delimiters): its tree, or one name; anything else (a
    symbol no kind writes) as words."""
    node = symbol_node(text, tree)
    if node is not None:
        return LatexPrinter(False).doprint(node)
    return f"\\text{{{text_escape(text)}}}" if text else "\\text{}"


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


def words(text: str, escape: Any = text_escape, keys: Keys = NO_KEYS) -> str:
    """Words as text, escaped; a key of the file (``psi_rate``, in ``keys``) as words
    (``psi rate``). Maths in a sentence is a tree (`core.prose`), never read from its
    words."""
    return keys.words(text, escape)


def prose_latex(prose: Any, markdown: bool = False, keys: Keys = NO_KEYS) -> str:
    """A sentence's words escaped (a key of the file as words) and its trees as inline
    maths."""
    escape = _md_escape if markdown else text_escape
    out = []
    for piece in prose_nodes(prose):
        if isinstance(piece, str):
            out += [escape(part) for _, part in keys.split(piece)]
        else:
            out.append(f"${LatexPrinter(False).doprint(piece)}$")
    return "".join(out)


# ---- breaking a wide display --------------------------------------------------

def _terms(node: Node) -> list[tuple[str, Node]]:
    """A sum as its terms with their signs: a - b + c -> [("", a), ("-", b), ("+", c)]."""
    op = op_of(node)
    if op in ("+", "-"):
        return _terms(node.left) + [(op, node.right)]  # type: ignore[attr-defined]
    return [("", node)]


def _opened(piece: Node, printer: LatexPrinter) -> tuple[str, Node, str]:
    """A piece whose width is in one bracketed sum: the text before the sum, the sum and the
    text after (``a (b + c + d)`` -> ``a \\Bigl(``, b + c + d, ``\\Bigr)``)."""
    node = piece
    if isinstance(node, E.Div) and len(_terms(unbracketed(node.left))) > 1:
        den = printer.doprint(unbracketed(node.right))
        return f"\\frac{{1}}{{{den}}} \\Bigl(", unbracketed(node.left), " \\Bigr)"
    if isinstance(node, E.Mul):
        right = node.right
        body = grouped(right)
        if body is not None and len(_terms(body)) > 1 and width(right) > width(node.left):
            o, c = ("[", "]") if right.open == "[" else ("(", ")")  # type: ignore[attr-defined]
            return f"{printer.doprint(node.left)} \\Bigl{o}", body, f" \\Bigr{c}"
    body = grouped(node)
    if body is not None and len(_terms(body)) > 1:
        o, c = ("[", "]") if node.open == "[" else ("(", ")")  # type: ignore[attr-defined]
        return f"\\Bigl{o}", body, f" \\Bigr{c}"
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
        texts = ((printer.term(sign, term) if sign else printer.doprint(term),
                  width(term) + 3) for sign, term in terms)
        packed = pack(texts, budget, used=width(piece) - width(inner))
        for j, (row, _) in enumerate(packed):
            line = " ".join(([prefix] if j == 0 and prefix else []) + row)
            if j == len(packed) - 1:
                line += suffix
            rows.append((left if j == 0 else "", ("= " if j == 0 else "\\quad ") + line))
    return rows


def _rel_rows(tree: P.Rel) -> list[str]:
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


def _answer_lhs(answer: Any) -> str:
    """``symbol = `` before an answer's values (`document.answer_lhs`), or nothing."""
    tree = answer_lhs(answer)
    return "" if tree is None else LatexPrinter(False).doprint(tree) + " = "


def _answer_parts(answer: Any) -> list[tuple[str, str]]:
    parts = []
    for i, value in enumerate(answer.values):
        if isinstance(value, str):
            body = f"\\text{{{text_escape(value)}}}"
        else:
            body = _quantity(value, answer.unit or "")
        label = answer.labels[i] if i < len(answer.labels) else ""
        parts.append((body, label))
    return parts


def _given_text(g: Any) -> str:
    return g.text.replace("_", " ") if isinstance(g.si_value, str) else g.text


def _si(g: Any) -> str:
    if isinstance(g.si_value, str):  # a word of the file (counterclockwise_from_bow)
        return f"\\text{{{text_escape(g.si_value.replace('_', ' '))}}}"
    return _quantity(g.si_value, g.si_unit)


def _squeeze(text: str) -> str:
    return re.sub(r"\n{3,}", "\n\n", text)


class Typeset(str):
    """A line already set (a note written as words and trees)."""


# ---- what Markdown and LaTeX write alike ---------------------------------------------

class _TexWriter(Writer):
    """The parts of a worked answer as lines of Markdown (``markdown``) or LaTeX."""

    markdown = False

    def prose(self, text: str) -> str:
        """Words from a file or a kind, escaped; a key of the file as words."""
        return self.keys.words(text, _md_escape if self.markdown else text_escape)

    def prose_latex(self, prose: Any) -> str:
        return prose_latex(prose, self.markdown, self.keys)

    def title(self, section: Any) -> str:
        prose = getattr(section, "prose", None)
        return self.prose(section.title) if prose is None else self.prose_latex(prose)

    def warning(self, text: str, solution: Any) -> str:
        prose = getattr(solution, "warning_prose", {}).get(text)
        return self.prose(text) if prose is None else self.prose_latex(prose)

    def given_cell(self, g: Any) -> str:
        """The datum as read (a number and its unit, set as maths; words as words), and its
        note (words, or words and trees)."""
        shown = getattr(g, "shown", None)
        if shown is not None:
            number, unit = shown
            cell = f"${number_tex(number)}{unit_latex(unit)}$"
            if g.text.endswith(" (default)"):
                cell += " (default)"
        else:
            cell = self.prose(_given_text(g))
        prose = getattr(g, "note_prose", None)
        if prose is not None:
            return cell + " (" + self.prose_latex(prose) + ")"
        return cell + (" (" + self.prose(g.note) + ")" if g.note else "")

    def step(self, step: Any) -> list[str]:
        markdown = self.markdown
        if step.symbol:
            body, after = self.step_display(step)
            out = _display(body, markdown)
            out += [line if isinstance(line, Typeset) else self.prose(line) for line in after]
            if after:
                out.append("")
            return out
        if getattr(step, "prose", None) is not None:  # words and trees: nothing parsed
            return self.prose_step(step.prose)
        return [self.prose(step.text.strip()), ""]  # words only

    def step_display(self, step: Any) -> tuple[str, list[str]]:
        """The display maths of a step and the prose lines that follow it."""
        markdown = self.markdown
        lhs, pieces = step_pieces(step)
        printer = LatexPrinter(True)
        left = printer.doprint(lhs)
        after: list[str] = []
        tag, rest = equation_tag(step)
        notes = []
        if rest:
            notes.append(f"({rest})")
        if step.text and getattr(step, "prose", None) is None:
            notes.append(step.text)
        note = " ".join(notes)
        lhs_width, piece_widths = width(lhs), [width(p) for p in pieces]  # each walked once
        total = lhs_width + sum(w + 3 for w in piece_widths)
        widest = total if total <= WIDTH else \
            max(lhs_width + 3 + min(w, WIDTH) for w in piece_widths)
        beside = ""  # a short note, set beside the equation

        def short(text: str) -> bool:
            return len(text) <= 48 and widest + len(text) + 4 <= WIDTH + 8

        if getattr(step, "prose", None) is not None:  # a note of words and trees
            maths = [p for p in prose_nodes(step.prose)
                     if not (isinstance(p, str) and not p.strip())]
            if not note and short(step.text) and len(maths) == 1 \
                    and not isinstance(maths[0], str):
                beside = printer.doprint(maths[0])  # a note that is one formula: = 0.03283 deg/h
            elif not note and short(step.text):
                beside = "\\text{" + prose_latex(step.prose, keys=self.keys) + "}"
            else:
                if note:
                    after.append(note)
                after.append(Typeset(self.prose_latex(step.prose)))
            note = ""
        if note and short(note):
            beside = "\\text{" + words(note, keys=self.keys) + "}"
        elif note:
            after.append(note)
        if total <= WIDTH:
            body = " = ".join([left] + [printer.doprint(p) for p in pieces])
        else:
            rows = _rows(left, pieces, WIDTH - min(lhs_width, 12) - 4)
            body = "\\begin{aligned}\n" + " \\\\\n".join(f"{a} &{b}" for a, b in rows) + \
                "\n\\end{aligned}"
        if beside:
            body += f" \\qquad {beside}"
        if tag:
            body += f" \\qquad \\text{{({tag})}}" if markdown else f" \\tag{{{tag}}}"
        return body, after

    def prose_step(self, prose: Any) -> list[str]:
        """A line written as words and trees: one relation displayed (with the chapter's
        equation number it cites), else a paragraph with the maths inline."""
        markdown = self.markdown
        equation = prose.equation()
        if equation is not None:
            rel, tag = equation
            tree = prose_nodes(type(prose)((rel,)))[0]
            number = (f" \\qquad \\text{{({tag})}}" if markdown else f" \\tag{{{tag}}}") \
                if tag else ""
            if isinstance(tree, str):
                raise TypeError("a relation is a tree")
            if width(tree) <= WIDTH or not isinstance(tree, P.Rel):
                return _display(LatexPrinter(True).doprint(tree) + number, markdown)
            return _display("\\begin{aligned}\n" + " \\\\\n".join(_rel_rows(tree)) +
                            "\n\\end{aligned}" + number, markdown)
        return [self.prose_latex(prose), ""]


def steps_lines(steps: Sequence[Any], markdown: bool = False, keys: Keys = NO_KEYS) -> list[str]:
    """Steps of a worked answer as lines of LaTeX (or Markdown), as a write-up sets them."""
    writer = MarkdownWriter(keys) if markdown else LatexWriter(keys)
    return [line for step in steps for line in writer.step(step)]


# ---- Markdown ---------------------------------------------------------------

class MarkdownWriter(_TexWriter):
    """The worked answer as Markdown with $-delimited LaTeX maths."""

    markdown = True

    def head(self, result: Any) -> list[str]:
        problem = result.problem
        lines = [f"## {_md_escape(problem.id)}: {_md_escape(problem.title)}".rstrip(": ")
                 if problem.title else f"## {_md_escape(problem.id)}", ""]
        meta = [f"Kind: `{problem.kind.name}`"] + ([f"Source: {_md_escape(problem.source)}"]
                                                  if problem.source else [])
        return lines + ["*" + ". ".join(meta) + ".*", ""]

    def note(self, note: str) -> list[str]:
        return [f"> {self.prose(note)}", ""]

    def given(self, result: Any) -> list[str]:
        solution = result.solution
        lines = ["### Given", "", f"| | as given | {solution.system} |", "|---|---|---|"]
        for g in solution.given:
            lines.append(f"| ${symbol_latex(g.symbol, g.symbol_expr)}$ | "
                         f"{_md_cell(self.given_cell(g))} | ${_si(g)}$ |")
        return lines

    def section(self, section: Any) -> list[str]:
        return ["", f"### {self.title(section)}", ""]

    def checks(self) -> list[str]:
        return ["", "### Check", ""]

    def answers(self, result: Any) -> list[str]:
        lines = ["", "### Answer", ""]
        for name, answer in result.answers.items():
            lhs = _answer_lhs(answer)
            parts = [f"${lhs}{body}$" + (f" ({label})" if label else "")
                     for body, label in _answer_parts(answer)]
            lines.append(f"- **{name}**: " + ", ".join(parts))
        return lines

    def warnings(self, solution: Any) -> list[str]:
        return ["", "### Warnings", ""] + [f"- {self.warning(w, solution)}"
                                           for w in solution.warnings]


def markdown(result: Result) -> str:
    """The worked answer as Markdown with $-delimited LaTeX maths."""
    lines = walk(result, MarkdownWriter(Keys.of(result.problem.kind)))
    return _squeeze("\n".join(lines)) + "\n"


def _md_cell(text: str) -> str:
    return text.replace("|", "\\|")


# ---- LaTeX ------------------------------------------------------------------

class LatexWriter(_TexWriter):
    """The worked answer as LaTeX (amsmath); ``level``: the sectioning command of its
    title (``section`` in a whole document)."""

    def __init__(self, keys: Keys = NO_KEYS, level: str = "subsection*") -> None:
        super().__init__(keys)
        self.level = level

    def head(self, result: Any) -> list[str]:
        problem, level = result.problem, self.level
        title = f"{problem.id}: {problem.title}" if problem.title else problem.id
        lines = ["% gyro solve --format latex: paste into a document that loads amsmath"
                 if level == "subsection*" else f"% {text_escape(problem.id)}",
                 f"\\{level}{{{text_escape(title)}}}"]
        meta = text_escape(f"Kind: {problem.kind.name.replace('_', ' ')}.")
        if problem.source:
            meta += " Source: " + _breakable(self.prose(problem.source))
        return lines + ["\\textit{" + meta + "}"]

    def note(self, note: str) -> list[str]:
        return ["", self.prose(note)]

    def given(self, result: Any) -> list[str]:
        solution = result.solution
        # a whole document may break a long table over pages; a fragment needs amsmath only
        table = "longtable" if self.level == "section" else "tabular"
        lines = ["", "\\subsubsection*{Given}", "",
                 f"\\begin{{{table}}}{{@{{}}lp{{0.5\\linewidth}}l@{{}}}}",
                 f"& as given & {solution.system} \\\\ \\hline"]
        for g in solution.given:
            lines.append(f"${symbol_latex(g.symbol, g.symbol_expr)}$ & {self.given_cell(g)} & "
                         f"${_si(g)}$ \\\\")
        return lines + [f"\\end{{{table}}}"]

    def section(self, section: Any) -> list[str]:
        return ["", f"\\subsubsection*{{{self.title(section)}}}", ""]

    def checks(self) -> list[str]:
        return ["", "\\subsubsection*{Check}", ""]

    def answers(self, result: Any) -> list[str]:
        lines = ["", "\\subsubsection*{Answer}", "", "\\begin{itemize}"]
        for name, answer in result.answers.items():
            lhs = _answer_lhs(answer)
            parts = [f"${lhs}{body}$" + (f" ({text_escape(label)})" if label else "")
                     for body, label in _answer_parts(answer)]
            head = "" if lhs and symbol_tex(name) + " = " == lhs else \
                f"\\textbf{{{text_escape(name.replace('_', ' '))}}}: "
            lines.append(f"  \\item {head}" + ", ".join(parts))
        return lines + ["\\end{itemize}"]

    def warnings(self, solution: Any) -> list[str]:
        return ["", "\\subsubsection*{Warnings}", "", "\\begin{itemize}"] + \
            [f"  \\item {self.warning(w, solution)}" for w in solution.warnings] + \
            ["\\end{itemize}"]


def latex(result: Result, level: str = "subsection*") -> str:
    """The worked answer as a LaTeX fragment (needs amsmath) to paste into a solution sheet."""
    lines = walk(result, LatexWriter(Keys.of(result.problem.kind), level))
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
