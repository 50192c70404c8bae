"""Question banks for learning systems: what the four formats share.

`gyro export` (commands/export.py) solves every variant of a problem and hands
the renderers here a `ProblemBank`: per variant the question text (the problem's
`statement`, else a sentence built from its title, data and answers), the
worked answer as HTML (MathML formulas) for the feedback, and one `Blank` per
number the student types, each with the solver's value in the unit the file
asks for and the half-width the problem's tolerance allows around it. The
renderers (`bank_moodle`, `bank_qti`, `bank_blackboard`, `bank_prairielearn`)
only lay these out; none of them computes an answer.

Everything from a problem file is text to escape here: `xml_text` and
`xml_attr` drop the characters XML 1.0 cannot hold and escape the rest,
`cdata` splits a ``]]>``, and `html_text` escapes HTML and the braces that a
Moodle cloze question or a PrairieLearn (mustache) template would read (a
statement's ``{{`` is a brace once filled in, and stays text here).
"""

from __future__ import annotations

import hashlib
import re
import uuid
from dataclasses import dataclass, field
from html import escape

#: the namespace of every UUID gyro writes into a bank (uuid5 of the problem id and
#: variant): the same problem and variant get the same UUID in every export
NAMESPACE = uuid.uuid5(uuid.NAMESPACE_URL, "gyro_cli/question-bank")


@dataclass(frozen=True)
class Blank:
    """One number the student types: the solver's value and how far from it is right
    (the problem's tolerance, widened to the student tolerance where the problem's is
    tighter than ``digits`` significant figures can meet; commands/export.py)."""

    key: str          # unique in its question: precession_slow, min_spin
    label: str        # what is asked, in words: "precession (slow root)"
    value: float      # the solver's answer, in ``unit``
    unit: str         # as the file asks for it ("rpm"); "" for a pure number
    half_width: float  # |typed - value| allowed, in ``unit``
    tolerance: str    # the problem's tolerance as written ("1%", "3 sig", "0.01 rad/s")
    form: str         # the tolerance used: "relative", "sig" or "absolute"
    fraction: float   # relative: the fraction (0.01); sig: the digits; absolute: half_width
    accepts: str = ""  # what is accepted, in words: "within 1%"
    digits: int = 4    # significant figures the question asks for


@dataclass(frozen=True)
class Choice:
    """A word answer asked as a multiple-choice question: the kind's words for it."""

    key: str                  # unique in its question, with the blanks' keys: motion
    label: str                # "motion", "stability (slow)"
    choices: tuple[str, ...]  # the kind's words (AnswerSpec.words), the answer among them
    answer: str               # the solver's word


@dataclass
class Variant:
    """One variant of a problem: its data, text, worked answer and blanks."""

    number: int              # 1, 2, ... (1 alone: the problem as written)
    ident: str               # the variant's problem id ("11/3" or "11/3-v02")
    given: dict[str, str]    # the given values as written
    statement_html: str
    feedback_html: str
    blanks: list[Blank] = field(default_factory=list)
    unasked: list[str] = field(default_factory=list)  # word answers without choices
    choices: list[Choice] = field(default_factory=list)  # word answers asked (multiple choice)
    figure: bytes = b""       # the worked answer's picture as PNG (b"": none)
    figure_alt: str = ""      # what it shows, in words
    #: errors carried forward: a step blank's key -> its values on a grid ("at") and each
    #: later blank's value with it carried ("to"); checking/ecf.py `table`
    carry: dict = field(default_factory=dict)
    figure_tag: str = ""      # a digest of ``figure``, kept where the PNG itself is not

    @property
    def figure_name(self) -> str:
        """The picture's file name in a package: ``figure-1-<16 hex digits>.png`` for
        variant 1, the digits a digest of the picture itself. A platform may serve a
        package's files to whoever can open the question (PrairieLearn's
        clientFilesQuestion), and a bicycle's plot prints its answers: a name no one can
        guess before the answer is shown, the same at every export."""
        tag = self.figure_digest
        return f"figure-{self.number}-{tag}.png" if tag else f"figure-{self.number}.png"

    @property
    def figure_digest(self) -> str:
        """16 hex digits of the picture's SHA-256 ("" without a picture), or the digest kept
        where the PNG is not (``figure_tag``)."""
        return self.figure_tag or (hashlib.sha256(self.figure).hexdigest()[:16]
                                   if self.figure else "")

    def figure_html(self, src: str) -> str:
        """The picture as an ``<img>`` paragraph with ``src`` ("" without a picture)."""
        if not self.figure:
            return ""
        return (f'<p><img src="{escape(src)}" alt="{escape(xml_clean(self.figure_alt))}" '
                'style="max-width: 100%"></p>')

    @property
    def asks(self) -> int:
        """How many answers the variant asks: numbers and choices."""
        return len(self.blanks) + len(self.choices)


@dataclass
class ProblemBank:
    """A problem and its variants, as one category (Moodle), file (QTI) or question
    directory (PrairieLearn)."""

    id: str
    title: str
    kind: str
    source: str
    slug: str      # a file and directory name: letters, digits, - and _
    topic: str     # the kind in words ("steady precession")
    variants: list[Variant] = field(default_factory=list)
    #: how many variants it asks when they are streamed rather than held (-1: len(variants))
    count: int = -1

    @property
    def size(self) -> int:
        """How many variants the problem has (those held, else ``count``)."""
        return self.count if self.count >= 0 else len(self.variants)

    @property
    def name(self) -> str:
        return f"{self.id}: {self.title}" if self.title else self.id


def stable_uuid(*parts: object) -> uuid.UUID:
    """A UUID that depends only on ``parts`` (the problem id, the variant, the blank)."""
    return uuid.uuid5(NAMESPACE, "\x1f".join(str(p) for p in parts))


_NOT_XML = re.compile("[^\t\n\r\x20-\ud7ff\ue000-\ufffd\U00010000-\U0010ffff]")


def xml_clean(text: str) -> str:
    """``text`` without the characters XML 1.0 cannot hold (control characters, lone
    surrogates, U+FFFE/U+FFFF)."""
    return _NOT_XML.sub("", str(text))


def xml_text(text: str) -> str:
    """Element content: &, < and > escaped."""
    return escape(xml_clean(text), quote=False)


def xml_attr(text: str) -> str:
    """An attribute value in double quotes: &, <, >, " and ' escaped; line breaks as
    character references so a parser keeps them."""
    return escape(xml_clean(text), quote=True).replace("\n", "&#10;").replace(
        "\r", "&#13;").replace("\t", "&#9;")


def cdata(text: str) -> str:
    """``text`` as CDATA: a ``]]>`` inside is split over two sections."""
    return "<![CDATA[" + xml_clean(text).replace("]]>", "]]]]><![CDATA[>") + "]]>"


def html_text(text: str) -> str:
    """Plain text as HTML: escaped, and braces as character references (a Moodle cloze
    question reads ``{1:NUMERICAL:...}`` in its text, a mustache template ``{{...}}``)."""
    return escape(xml_clean(text)).replace("{", "&#123;").replace("}", "&#125;")


def slug(text: str) -> str:
    """A file name from a problem id or file stem: 11/3 -> 11-3."""
    out = re.sub(r"[^A-Za-z0-9_-]+", "-", str(text)).strip("-")
    return out or "problem"


def number_text(value: float) -> str:
    """A number as the bank writes it: every digit the solver gives (repr of the float)."""
    text = repr(float(value))
    return "0.0" if text == "-0.0" else text


def statement_html(statement: str | None, title: str, data_lines: list[tuple[str, str]],
                   asked: list[str]) -> str:
    """The question text as HTML: the statement (filled in already: Problem.statement_text,
    core/statement.py; paragraphs at blank lines), else the title, the data and what is
    asked, in sentences."""
    if statement:
        paragraphs = [p for p in re.split(r"\n\s*\n", statement.strip()) if p.strip()]
        return "".join(f"<p>{html_text(' '.join(p.split()))}</p>" for p in paragraphs)
    title = " ".join(str(title).split())
    out = [f"<p>{html_text(title)}{'' if title.endswith(('.', '?', '!')) else '.'}</p>"] \
        if title else []
    if data_lines:
        out.append("<p>Data:</p><ul>" + "".join(
            f"<li>{html_text(what)}: {html_text(text)}</li>" for what, text in data_lines)
            + "</ul>")
    if asked:
        out.append("<p>Find " + html_text(_join(asked)) + ".</p>")
    return "".join(out)


def _join(items: list[str]) -> str:
    if len(items) <= 1:
        return "".join(items)
    return ", ".join(items[:-1]) + " and " + items[-1]


def precision_text(blanks: list[Blank]) -> str:
    """What the question asks and accepts, as a sentence: ``Give 4 significant figures;
    answers within 1% are accepted.`` (each blank's own where they differ)."""
    if not blanks:
        return ""
    digits = blanks[0].digits
    accepted = list(dict.fromkeys(b.accepts for b in blanks if b.accepts))
    head = f"Give {digits} significant figures"
    if not accepted:
        return head + "."
    if len(accepted) == 1:
        return f"{head}; answers {accepted[0]} are accepted."
    each = "; ".join(f"{b.label} {b.accepts}" for b in blanks)
    return f"{head}; accepted: {each}."


def precision_html(blanks: list[Blank]) -> str:
    """`precision_text` as a paragraph ("" for no blank)."""
    text = precision_text(blanks)
    return f'<p class="gyro-precision">{html_text(text)}</p>' if text else ""


def choice_prompt(choice: Choice) -> str:
    """What a multiple-choice question asks, as plain text: ``motion: choose one``."""
    return f"{choice.label}: choose one"


def blank_prompt(blank: Blank) -> str:
    """What a blank asks, as plain text: ``precession (slow root), in rpm``."""
    return f"{blank.label}, in {blank.unit}" if blank.unit else blank.label
