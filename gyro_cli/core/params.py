"""The declarations a kind makes of its keys and answers (no imports: the
body, the loader and the kinds all use them)."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Param:
    """A key of `given`: its dimension (a name in units.DIMENSIONS), symbol and meaning."""

    name: str
    dimension: str
    symbol: str
    doc: str
    default: str | None = None  # a quantity string used when the key is absent
    choices: tuple[str, ...] = ()  # for word-valued keys (dimension "word")


@dataclass(frozen=True)
class AnswerSpec:
    """An answer a kind can give; dimension None for a word (``motion``)."""

    name: str
    dimension: str | None
    symbol: str
    doc: str
