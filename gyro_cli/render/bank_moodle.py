"""A question bank as Moodle XML (Question bank > Import > Moodle XML format).

One category per problem (``$course$/top/gyro/<id>: <title>``) holding its
variants, so a quiz's "random question from this category" gives each student
one variant. A variant that asks one number is a ``numerical`` question (the
answer, its tolerance as Moodle's absolute +/- error, the unit); one that asks
several (the two roots of a steady precession, a rotor's two bearing forces) is
a ``cloze`` question with a ``{1:NUMERICAL:=value:error}`` blank for each, since
a numerical question holds one number. The statement is the question text, the
worked answer (MathML) the general feedback; both are HTML in CDATA.

The elements and their meaning are those Moodle's importer reads
(question/format/xml/format.php: ``import_numerical``, ``import_multianswer``,
categories as ``<question type="category">``).
"""

from __future__ import annotations

import base64

from .bank import (
    Blank,
    Choice,
    ProblemBank,
    Variant,
    blank_prompt,
    cdata,
    choice_prompt,
    html_text,
    number_text,
    xml_text,
)

#: the category every problem's category sits in
TOP = "$course$/top/gyro"


def category_path(bank: ProblemBank) -> str:
    """The problem's category path; a slash inside a name is doubled (Moodle reads a
    single ``/`` as a sub-category)."""
    name = " ".join(bank.name.split()).replace("/", "//")
    return f"{TOP}/{name}"


#: what the file starts and ends with, around the problems' categories and questions
HEAD = '<?xml version="1.0" encoding="UTF-8"?>\n<quiz>\n'
TAIL = "</quiz>\n"


def xml(banks: list[ProblemBank]) -> str:
    """The Moodle XML file of ``banks``."""
    return HEAD + "".join(piece for bank in banks for variant in bank.variants
                          for piece in pieces(bank, variant, variant is bank.variants[0])) + TAIL


def pieces(bank: ProblemBank, variant: Variant, first: bool) -> list[str]:
    """What one variant adds to the file (``first``: the problem's category before it);
    ``bank.size`` must be known, the variants need not be held (commands/export.py
    streams them)."""
    return ([_category(bank) + "\n"] if first else []) + [_question(bank, variant) + "\n"]


def _category(bank: ProblemBank) -> str:
    info = f"<p>{html_text(bank.name)}</p>" + (
        f"<p>Source: {html_text(bank.source)}</p>" if bank.source else "")
    return ('  <question type="category">\n'
            f"    <category><text>{xml_text(category_path(bank))}</text></category>\n"
            f'    <info format="html"><text>{cdata(info)}</text></info>\n'
            "  </question>")


def _name(bank: ProblemBank, variant: Variant) -> str:
    return f"{bank.id} variant {variant.number}" if bank.size > 1 else bank.id


def _common(bank: ProblemBank, variant: Variant, text: str) -> list[str]:
    # No <idnumber>: Moodle wants it unique in a category, and a second import of the
    # same bank into the same category must not fail on it.
    return [f"    <name><text>{xml_text(_name(bank, variant))}</text></name>",
            f'    <questiontext format="html"><text>{cdata(text)}</text></questiontext>',
            _feedback(variant)]


def _feedback(variant: Variant) -> str:
    """The general feedback: the worked answer, and its picture as a file of the question
    (``@@PLUGINFILE@@``, the file inline in base64, as Moodle's importer reads it)."""
    html = variant.feedback_html + variant.figure_html(f"@@PLUGINFILE@@/{variant.figure_name}")
    file = (f'<file name="{variant.figure_name}" path="/" encoding="base64">'
            f"{base64.b64encode(variant.figure).decode('ascii')}</file>"
            if variant.figure else "")
    return f'    <generalfeedback format="html"><text>{cdata(html)}</text>{file}</generalfeedback>'


def _question(bank: ProblemBank, variant: Variant) -> str:
    if len(variant.blanks) == 1 and not variant.choices:
        return _numerical(bank, variant, variant.blanks[0])
    if len(variant.choices) == 1 and not variant.blanks:
        return _multichoice(bank, variant, variant.choices[0])
    return _cloze(bank, variant)


#: one mark, a third of it lost for each wrong try where the quiz allows tries, not hidden
_GRADED = ("    <defaultgrade>1</defaultgrade>", "    <penalty>0.3333333</penalty>",
           "    <hidden>0</hidden>")


def _multichoice(bank: ProblemBank, variant: Variant, choice: Choice) -> str:
    """A word answer alone: a multiple-choice question (one right answer, shuffled)."""
    text = variant.statement_html + f"<p>{html_text(choice_prompt(choice))}:</p>"
    lines = ['  <question type="multichoice">', *_common(bank, variant, text),
             *_GRADED,
             "    <single>true</single>",
             "    <shuffleanswers>true</shuffleanswers>",
             "    <answernumbering>abc</answernumbering>"]
    for word in choice.choices:
        lines += [f'    <answer fraction="{100 if word == choice.answer else 0}" format="html">',
                  f"      <text>{cdata(html_text(word))}</text>",
                  '      <feedback format="html"><text></text></feedback>',
                  "    </answer>"]
    lines.append("  </question>")
    return "\n".join(lines)


#: what a cloze answer must escape with a backslash (Moodle's multianswer help: } # ~ / " \\)
_CLOZE_SPECIAL = str.maketrans({c: "\\" + c for c in '}#~/"\\'})


def cloze_choice(choice: Choice) -> str:
    """One cloze multiple choice: ``{1:MULTICHOICE:=cusps~loops~waves}`` (a drop-down)."""
    return "{1:MULTICHOICE:" + "~".join(
        ("=" if word == choice.answer else "") + xml_text(word.translate(_CLOZE_SPECIAL))
        for word in choice.choices) + "}"


def unit_spellings(unit: str) -> list[str]:
    """The unit names a numerical question lists for ``unit`` (multiplier 1 each): Moodle
    deletes every space of a response before it reads the unit, so ``12 kN m`` arrives as
    ``12kNm``: the unit without its spaces first (the default unit), then with ``*`` and
    ``·`` between its factors."""
    parts = unit.split()
    return list(dict.fromkeys(["".join(parts), "*".join(parts), "\u00b7".join(parts)]))


def _numerical(bank: ProblemBank, variant: Variant, blank: Blank) -> str:
    prompt = blank_prompt(blank) + (f" (type the number and its unit: {_example(blank)})"
                                    if blank.unit else "")
    text = variant.statement_html + f"<p>{html_text(prompt)}:</p>"
    lines = ['  <question type="numerical">', *_common(bank, variant, text),
             *_GRADED,
             '    <answer fraction="100" format="plain_text">',
             f"      <text>{number_text(blank.value)}</text>",
             f"      <tolerance>{number_text(blank.half_width)}</tolerance>",
             '      <feedback format="html"><text></text></feedback>',
             "    </answer>"]
    if blank.unit:
        # The unit typed after the number (showunits 0) must be one listed: Moodle cannot
        # tell a missing unit from a wrong one, and with unitgradingtype 0 it takes either
        # at full marks; graded (1) with a penalty of the whole mark, the number counts
        # only with the unit asked.
        units = "".join("      <unit>\n        <multiplier>1</multiplier>\n"
                        f"        <unit_name>{xml_text(name)}</unit_name>\n      </unit>\n"
                        for name in unit_spellings(blank.unit))
        lines += ["    <units>\n" + units + "    </units>",
                  "    <unitgradingtype>1</unitgradingtype>",
                  "    <unitpenalty>1</unitpenalty>",
                  "    <showunits>0</showunits>",
                  "    <unitsleft>0</unitsleft>"]
    else:
        lines.append("    <showunits>3</showunits>")
    lines.append("  </question>")
    return "\n".join(lines)


def _example(blank: Blank) -> str:
    """How an answer is typed, with a made-up number: ``1.234 kN m``."""
    return f"{'1.234567'[:blank.digits + 1]} {blank.unit}"


def cloze_blank(blank: Blank) -> str:
    """One cloze blank: ``{1:NUMERICAL:=45.13:0.45}`` (value and absolute error)."""
    return f"{{1:NUMERICAL:={number_text(blank.value)}:{number_text(blank.half_width)}}}"


def _cloze(bank: ProblemBank, variant: Variant) -> str:
    rows = "".join(f"<li>{html_text(blank.label)}: {cloze_blank(blank)}"
                   + (f" {html_text(blank.unit)}" if blank.unit else "") + "</li>"
                   for blank in variant.blanks)
    rows += "".join(f"<li>{html_text(choice.label)}: {cloze_choice(choice)}</li>"
                    for choice in variant.choices)
    text = variant.statement_html + f"<ul>{rows}</ul>"
    lines = ['  <question type="cloze">', *_common(bank, variant, text),
             "    <penalty>0.3333333</penalty>",
             "    <hidden>0</hidden>",
             "  </question>"]
    return "\n".join(lines)
