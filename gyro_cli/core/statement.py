"""A problem's `statement`: the text a student reads, with `{key}` placeholders.

The optional top-level key ``statement`` is the problem as the book states it,
written with placeholders such as ``{spin}`` that are filled from ``given`` *as
written in the file* (``spin: 1800 rpm`` -> ``1800 rpm``; a variant's numbers
for a variant). ``{{`` and ``}}`` stand for literal braces. Only the names of
given keys may appear between braces: the text is never evaluated or
formatted with Python's ``str.format`` (no attribute or index lookups).

This module is the one place that fills a statement in; the loader
(solving/problem.py), handouts (commands/handout.py) and anything else that
prints a statement call :func:`fill_statement`.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from typing import Any

PLACEHOLDER = re.compile(r"\{\{|\}\}|\{([^{}]*)\}|[{}]")
KEY_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*\Z")


class StatementError(ValueError):
    """A placeholder that is not a given key, or a lone brace."""


def placeholders(text: str) -> list[str]:
    """The given keys that ``text`` names between braces, in order (repeats kept)."""
    names = []
    for match in PLACEHOLDER.finditer(text):
        token = match.group(0)
        if token in ("{{", "}}"):
            continue
        name = match.group(1)
        if name is None:
            raise StatementError(f"a lone {token!r}; write {token * 2!r} for a brace, or "
                                 "{key} for a given value")
        if not KEY_NAME.match(name.strip()):
            raise StatementError(f"{{{name}}} is not a given key's name; placeholders are "
                                 "{key} with a key of `given`")
        names.append(name.strip())
    return names


def value_text(value: Any) -> str:
    """A given value as the file wrote it (a quantity string as is, a bare number as YAML
    read it, a list of particles as its items)."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float) and value.is_integer() and abs(value) < 1e15:
        return repr(value)
    if isinstance(value, list):
        return ", ".join(value_text(v) for v in value)
    if isinstance(value, dict):
        return ", ".join(f"{k} {value_text(v)}" for k, v in value.items())
    return " ".join(str(value).split())


def fill_statement(text: str, given: Mapping[str, Any]) -> str:
    """``text`` with each ``{key}`` replaced by ``given[key]`` as written.

    ``given`` is the file's raw `given` mapping (strings as written). A name
    that is not among its keys raises :class:`StatementError` naming it and
    the keys there are.
    """
    def one(match: re.Match[str]) -> str:
        token = match.group(0)
        if token == "{{":
            return "{"
        if token == "}}":
            return "}"
        name = (match.group(1) or "").strip()
        if match.group(1) is None or name not in given:
            placeholders(token)  # a lone brace or a bad name: its own message
            keys = ", ".join(str(k) for k in given) or "none"
            raise StatementError(f"{{{name}}} is not a key of `given` (given keys: {keys})")
        return value_text(given[name])

    return PLACEHOLDER.sub(one, text)
