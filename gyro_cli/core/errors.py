"""The one exception users see: bad input, reported as one line and exit code 2."""

from __future__ import annotations

import math


class InputError(Exception):
    """Bad or physically impossible input.

    Rendered as ``FILE: KEY (line N): MESSAGE``; the CLI prints it on one line
    and exits with code 2.
    """

    def __init__(self, message: str, *, key: str | None = None,
                 file: str | None = None, line: int | None = None) -> None:
        super().__init__(message)
        self.message = message
        self.key = key
        self.file = file
        self.line = line

    def located(self, file: str | None = None, key: str | None = None,
                line: int | None = None) -> InputError:
        """Fill in where the error is, keeping what is already known."""
        self.file = self.file or file
        self.key = self.key or key
        self.line = self.line or line
        return self

    def __str__(self) -> str:
        where = []
        if self.file:
            where.append(_one_line(self.file))
        if self.key:
            key = _one_line(self.key) + (f" (line {self.line})" if self.line else "")
            where.append(key)
        elif self.line:
            where.append(f"line {self.line}")
        text = _one_line(" ".join(self.message.split()))  # always one line, no escapes
        return ": ".join(where + [text])


def refuse_overflow(*values: float) -> None:
    """Refuse data whose products overflow double precision (any of ``values`` not finite)."""
    if not all(map(math.isfinite, values)):
        raise InputError("these data are outside what gyro can compute reliably in double "
                         "precision (a product overflows); check the magnitudes and units",
                         key="given")


def shown(value: object) -> str:
    """A value from the file for a message, as YAML writes it (``.nan``, ``[1, .inf]``),
    so a message never prints a bare nan or inf of its own."""
    if isinstance(value, str):
        return repr(value)
    try:
        import yaml

        text = yaml.safe_dump(value, default_flow_style=True, width=200).strip()
        text = text.removesuffix("...").strip()
    except Exception:  # noqa: BLE001 - an odd type: its name is enough
        return f"a {type(value).__name__}"
    return text if len(text) <= 80 else text[:77] + "..."


def terminal_text(text: object) -> str:
    """Text from a file, a sheet or a file name, safe to print on a terminal: on one line,
    with line breaks, tabs, escape sequences (ESC), other control characters and bidi
    overrides shown as escapes (``\\n``, ``\\x1b``, ``\\u202e``), never sent raw; a
    no-break or other wide space is a plain space.

    The one place every terminal output (reports, tables, messages) passes user strings
    through; JSON, HTML, Markdown and LaTeX have their own escaping."""
    text = str(text)
    if text.isprintable():
        return text
    import unicodedata

    return "".join(c if c.isprintable() else " " if unicodedata.category(c) == "Zs"
                   else c.encode("unicode_escape").decode("ascii") for c in text)


_one_line = terminal_text


def internal_message(file: str | None, error: BaseException) -> str:
    """One line for a bug in gyro: ``FILE: internal error: TYPE: message (please report)``.

    The command goes on with the next file and exits 3 at the end. Set
    GYRO_DEBUG=1 to have the traceback printed as well.
    """
    text = " ".join(str(error).split())
    if len(text) > 300:
        text = text[:297] + "..."
    where = f"{_one_line(file)}: " if file else ""
    return f"{where}internal error: {type(error).__name__}: {text} (please report)"
