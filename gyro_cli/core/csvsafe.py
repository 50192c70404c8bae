"""CSV cells that a spreadsheet opens as text, never runs (CSV injection).

OWASP's CSV-injection rules: a cell that begins with ``=``, ``+``, ``-``,
``@``, a tab or a carriage return is run as a formula by Excel, LibreOffice
and Google Sheets, and so is a part of a cell after a field separator (``,``
``;``, tab, a line break), which a spreadsheet set to split on it starts as a
new cell. Such a cell gets a leading ``'`` (and such a part a ``'`` before it),
which makes the spreadsheet read it as text. The full-width forms of the four
signs are treated alike. A cell that is a plain number (``-0.0013``, ``45``,
``1e-5``) is left as it is, so numbers stay numbers.

Every CSV gyro writes from user text (grades, rosters, assignments, key files,
gradebooks) passes its cells through :func:`safe_cell`.
"""

from __future__ import annotations

import re
from typing import Any

TRIGGERS = ("=", "+", "-", "@", "\t", "\r", "\n", "\uff1d", "\uff0b", "\uff0d", "\uff20")
PLAIN_NUMBER = re.compile(r"[-+]?(\d+(\.\d*)?|\.\d+)([eE][-+]?\d+)?%?\Z")
SEPARATED = re.compile(r"([,;\t\r\n|])(\s*)(?='*[=+\-@\uff1d\uff0b\uff0d\uff20])")
QUOTED_TRIGGER = re.compile("'+[=+\\-@\t\r\n\uff1d\uff0b\uff0d\uff20]")


def _part_is_number(text: str, start: int) -> bool:
    end = len(text)
    for sep in ",;\t\r\n|":
        k = text.find(sep, start)
        if k != -1:
            end = min(end, k)
    return bool(PLAIN_NUMBER.match(text[start:end].strip()))


def safe_cell(value: Any) -> str:
    """``value`` as a CSV cell a spreadsheet will read as text or a plain number.

    Text that already has quotes where a guard would go (``'=1+1``) gets one more
    (``''=1+1``), so that :func:`plain_cell` gives back exactly the text written.
    """
    text = "" if value is None else str(value)
    if not text:
        return text

    def guard(match: re.Match[str]) -> str:
        if _part_is_number(text, match.end()):
            return match.group(0)
        return match.group(1) + match.group(2) + "'"

    if any(sep in text for sep in ",;\t\r\n|"):
        text = SEPARATED.sub(guard, text)
    if (text.startswith(TRIGGERS) and not PLAIN_NUMBER.match(text)) \
            or QUOTED_TRIGGER.match(text):
        return "'" + text
    return text


UNGUARD = re.compile(r"(^)'(?='*[=+\-@\t\r\n\uff1d\uff0b\uff0d\uff20])"
                     r"|([,;\t\r\n|]\s*)'(?='*[=+\-@\uff1d\uff0b\uff0d\uff20])")


def plain_cell(text: str) -> str:
    """Undo :func:`safe_cell` on a cell gyro wrote (reading its own assignment back):
    exactly, ``plain_cell(safe_cell(t)) == t`` for every text. A cell safe_cell would not
    have written (edited by hand) is taken as it stands."""
    if "'" not in text:
        return text
    plain = UNGUARD.sub(lambda m: m.group(1) or m.group(2) or "", text)
    return plain if safe_cell(plain) == text else text


class CellRunsOn(ValueError):
    """A CSV cell holding a line break, at ``line`` (where its row starts)."""

    def __init__(self, line: int) -> None:
        super().__init__("a cell runs over a line break: a quote left open (\") takes in the "
                         "lines after it as one cell; close it (a cell here is one line)")
        self.line = line


def one_line_rows(text: str, delimiter: str = ",") -> list[tuple[int, list[str]]]:
    """The rows of a CSV text, each with the line it starts on. A cell that holds a line
    break is refused (`CellRunsOn`): in a roster or an answer sheet none is meant, and a
    stray quote would otherwise fold the rows after it, silently, into one cell.
    ``csv.Error`` is the caller's to report."""
    import csv
    import io

    reader = csv.reader(io.StringIO(text, newline=""), delimiter=delimiter)
    rows = []
    line = 1
    for row in reader:
        if any("\n" in cell or "\r" in cell for cell in row):
            raise CellRunsOn(line)
        rows.append((line, row))
        line = reader.line_num + 1
    return rows
