"""A question bank as a Blackboard Learn question file (Tests, Surveys and Pools >
Upload Questions): a tab-delimited text file, one question per line.

Blackboard's help page "Upload Questions" (Original Course View) gives each
line as a question type, then its fields, separated by TABs, without a header
row or blank lines; a numeric question is ``NUM TAB question text TAB answer
TAB [optional] tolerance``. The tolerance is read as Blackboard's answer range
for a numeric question: a +/- absolute value around the answer. The file
format has no unit, title or feedback field, so:

- one NUM line per number a variant asks (its `Blank`): a variant asking the
  two roots of a steady precession gives two questions, each with the whole
  statement and a last paragraph saying which number and in which unit
  (``precession (slow), in rpm:``);
- the answer is the solver's value, the tolerance the blank's half-width (the
  problem's tolerance, made absolute around this variant's answer);
- the worked answer is not in the file.

The help page says nothing of the file's encoding, of HTML or of a TAB or a
line break inside a field; what is done here assumes the least:

- a field never holds a TAB or a line break (each is a space here), nor a
  control character: a line is one whole question, whatever the problem file
  says;
- the question text is taken to be shown as HTML (notes of teachers who upload
  such files say it is, and that a line break must be written ``<br />``), so
  every text from a problem file is escaped (`bank.html_text`, as in the other
  banks) and the text is the same HTML the other banks use;
- the file is ASCII: any other character is an HTML character reference
  (``&#969;``), which reads the same whatever encoding Blackboard assumes,
  and there is no byte-order mark to spoil the first field;
- numbers are plain decimals (no exponent), at most 16 significant digits (a
  university's guide to Blackboard's numeric question says its answer takes
  16 digits), so within 1e-15 of the solver's value, far inside any tolerance;
- lines end in CR LF, as the spreadsheet the help page suggests writes them.
"""

from __future__ import annotations

import math
import re
from decimal import Decimal

from .bank import Blank, ProblemBank, Variant, blank_prompt, html_text

#: the question type of a numeric question in an upload file
NUM = "NUM"
#: records per file Blackboard recommends at most (its Ultra help page; the Original
#: one says 500: the smaller is kept)
RECOMMENDED_RECORDS = 250
#: significant digits of a number in the file (Blackboard's numeric answer: 16 digits)
DIGITS = 16

#: what would end a field or a line: TAB, every line break str.splitlines knows, and the
#: other C0 and C1 control characters
_BREAKS = re.compile("[\x00-\x1f\x7f-\x9f\u2028\u2029]")


def number(value: float) -> str:
    """``value`` as a plain decimal of at most 16 significant digits: 45.13 stays 45.13,
    1e-05 is 0.00001, -0.0 is 0."""
    value = float(value)
    if not math.isfinite(value):
        raise ValueError(f"not a finite number: {value!r}")
    text = format(Decimal(f"{value:.{DIGITS}g}"), "f")
    return "0" if float(text) == 0 else text


def field(html: str) -> str:
    """A field of a line: HTML whose TABs, line breaks and control characters are
    spaces and whose characters beyond ASCII are character references."""
    return _BREAKS.sub(" ", html).encode("ascii", "xmlcharrefreplace").decode("ascii")


def question_text(variant: Variant, blank: Blank) -> str:
    """The statement with this variant's numbers, then what this question asks."""
    return variant.statement_html + f"<p>{html_text(blank_prompt(blank))}:</p>"


def line(variant: Variant, blank: Blank) -> str:
    """One NUM question: type, question text, answer, tolerance (absolute)."""
    return "\t".join([NUM, field(question_text(variant, blank)), number(blank.value),
                      number(abs(blank.half_width))])


def lines(banks: list[ProblemBank]) -> list[str]:
    """Every question: each problem's variants in turn, one line per number asked."""
    return [line(variant, blank) for bank in banks for variant in bank.variants
            for blank in variant.blanks]


def text(banks: list[ProblemBank]) -> str:
    """The upload file: one line per question, each ended by CR LF, no header, no blank
    line."""
    return "".join(f"{record}\r\n" for record in lines(banks))
