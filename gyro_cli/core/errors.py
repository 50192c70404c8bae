"""The one exception users see: bad input, reported as one line and exit code 2."""

from __future__ import annotations


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
                line: int | None = None) -> "InputError":
        """Fill in where the error is, keeping what is already known."""
        self.file = self.file or file
        self.key = self.key or key
        self.line = self.line or line
        return self

    def __str__(self) -> str:
        where = []
        if self.file:
            where.append(self.file)
        if self.key:
            key = self.key + (f" (line {self.line})" if self.line else "")
            where.append(key)
        elif self.line:
            where.append(f"line {self.line}")
        text = " ".join(self.message.split())  # always one line
        return ": ".join(where + [text])
