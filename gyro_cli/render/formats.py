"""The output formats of a worked answer: one registry, read by ``gyro solve --format``
and by the API (`api.Result.render`, `api.document`).

A format is a `Format` object in a module of ``render/``; adding one is that module
and one line of `REGISTRY`. The module is imported on first use, so ``gyro solve`` in
text loads no write-up.
"""

from __future__ import annotations

from importlib import import_module

TYPE_CHECKING = False
if TYPE_CHECKING:
    from collections.abc import Sequence
    from typing import Any

#: format name -> ("module:object" of its `Format` under gyro_cli.render, what it writes)
REGISTRY = {
    "text": ("report:TEXT", "the worked answer"),
    "json": ("report:JSON", "one JSON object per file, one per line"),
    "markdown": ("writeup:MARKDOWN", "a write-up for a solution sheet"),
    "latex": ("writeup:LATEX", "a write-up for a solution sheet (--standalone: a whole "
                               "document)"),
    "html": ("html:HTML", "one self-contained page of all FILES (MathML formulas, inline "
                          "pictures)"),
}
NAMES = tuple(REGISTRY)
#: the help of ``gyro solve --format``
HELP = "; ".join(f"{name}: {what}" for name, (_, what) in REGISTRY.items()) + "."


class Format:
    """How one format writes worked answers. ``one`` writes one solved problem (an
    `api.Result`: ``result.solved`` is what the renderers read); several files are
    printed one after another, each after ``separator``, unless the format `composes`
    them into one document (`document`)."""

    name = ""
    separator = ""  # printed before every file's output but the first

    def one(self, result: Any, level: int = 2) -> str:
        raise NotImplementedError

    def composes(self, standalone: bool) -> bool:
        """Whether the output is one document of every file, written at the end."""
        return False

    def document(self, results: Sequence[Any], pieces: Sequence[str | None],
                 standalone: bool = False, scripts: Sequence[str] = ()) -> str:
        """Every file's output as one document (``pieces``: each file's `one`, or None)."""
        return "".join((self.separator if i else "") + (piece or "")
                       for i, piece in enumerate(pieces))


def get(name: str) -> Format:
    """The format called ``name`` (a `KeyError` for an unknown one)."""
    module, _, attribute = REGISTRY[name][0].partition(":")
    found: Format = getattr(import_module(f"gyro_cli.render.{module}"), attribute)
    return found
