"""What a problem kind declares: its given keys, its answers and its solver.

A kind is one module in ``gyro_cli/kinds`` exposing ``KIND = Kind(...)`` and one
line in the registry ``gyro_cli/kinds/__init__.py``.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from .params import AnswerSpec, OneOf, Param
from .record import field, record

if TYPE_CHECKING:
    from .given import Given
    from .work import Work

__all__ = ["AnswerSpec", "Kind", "OneOf", "Param"]


@record(frozen=True)
class Kind:
    """A problem kind: the keys it reads, the answers it gives, its solver.

    ``solve(given, find, work)`` reads SI floats from ``given``, writes the
    worked answer and every answer named in ``find`` into ``work``, and raises
    InputError (with ``key``) for input it cannot solve.
    """

    name: str
    summary: str
    params: tuple[Param, ...]
    answers: tuple[AnswerSpec, ...]
    solve: Callable[[Given, frozenset[str], Work], None]
    uses_body: bool = True
    chapter: str = ""
    #: a complete, solvable example for ``gyro new``: its ``given``, ``find``, ``vary`` and
    #: a ``statement`` with ``{key}`` placeholders
    example: dict[str, Any] = field(default_factory=dict)
    gravity: bool = True  # gravity acts on the body (False: no g key, no default g line)
    #: the body keys the kind reads (None: every key of the body, BODY_PARAMS)
    body_keys: tuple[str, ...] | None = None
    size_free: bool = False  # the body may be given by its moments alone, without a size
    #: groups of keys of which a problem gives one (checked before ``solve``, as are the
    #: params that are ``required``)
    one_of: tuple[OneOf, ...] = ()
    # What the layers above offer a kind, by what the kind says it is (never by its name):
    #: the picture of a solved problem (render/picture.py, `gyro solve --plot`):
    #: "axis_path" (the axis seen from above, theta(t), phidot(t)) or "eigenvalues"
    picture: str = ""
    #: the scene `--animate` draws (commands/animate.py): "nutating_top", "steady_top",
    #: "free_body", "turning_rotor", "rolling" or "lean_and_steer"
    animation: str = ""
    #: what `gyro simulate` integrates beside the answer: "released" or "steady" (a top)
    simulation: str = ""
    #: the physics modules the solver imports on first use (preloaded before forking)
    physics: tuple[str, ...] = ()
    #: the model the pictures and scenes draw, from the given data: ``model(given, work)``
    #: (the bicycle's parameters in SI)
    model: Callable[[Given, Work], Any] | None = None

    def __repr__(self) -> str:  # short: gyro_cli.kinds() lists sixteen of them
        return f"<Kind {self.name}: {self.summary}>"

    def param(self, name: str) -> Param | None:
        return next((p for p in self.params if p.name == name), None)

    def answer(self, name: str) -> AnswerSpec | None:
        by_name = self.__dict__.get("_answers_by_name")  # made on first use, per instance
        if by_name is None:
            by_name = self.__dict__["_answers_by_name"] = {}
            for a in reversed(self.answers):  # the first of a name, as a search finds it
                by_name[a.name] = a
        return by_name.get(name) if isinstance(name, str) else None
