"""The given data of one problem, parsed: SI floats (and words) by key."""

from __future__ import annotations

from typing import TYPE_CHECKING, overload

from .errors import InputError
from .params import MISSING_KEY
from .record import field, record

if TYPE_CHECKING:
    from .body import Body

#: particles as given (``particles:``): (m, x, y, z) in SI each
Particles = tuple[tuple[float, float, float, float], ...]


@record
class Given:
    """SI values by key, plus the body where the kind has one.

    ``given["spin"]`` is psidot in rad/s; ``given.word("arrangement")`` a word.
    Keys absent from the file but with a default in the kind's spec are present.
    """

    values: dict[str, float | str | Particles]
    body: Body | None = None
    defaulted: set[str] = field(default_factory=set)
    #: a key stated another way (a diameter, an angle from the horizontal): the key
    #: written and its SI value, by the key the kind reads
    derived: dict[str, tuple[str, float]] = field(default_factory=dict)

    def __contains__(self, key: str) -> bool:
        return key in self.values

    def __getitem__(self, key: str) -> float:
        if key not in self.values:
            raise InputError(MISSING_KEY, key=f"given.{key}")
        value = self.values[key]
        if isinstance(value, str):
            raise InputError(f"expected a quantity, got the word {value!r}", key=f"given.{key}")
        assert not isinstance(value, tuple), f"{key} holds particles: read given.values"
        return value

    @overload
    def get(self, key: str, default: float) -> float: ...

    @overload
    def get(self, key: str, default: float | None = None) -> float | None: ...

    def get(self, key: str, default: float | None = None) -> float | None:
        return self[key] if key in self.values else default

    @overload
    def word(self, key: str, default: str) -> str: ...

    @overload
    def word(self, key: str, default: str | None = None) -> str | None: ...

    def word(self, key: str, default: str | None = None) -> str | None:
        value = self.values.get(key, default)
        return value if value is None else str(value)

    @property
    def solid_body(self) -> Body:
        """The body of a kind that has one (``Kind.uses_body``: solve.py has built it)."""
        assert self.body is not None, "this kind declares no body"
        return self.body

    def given_explicitly(self, key: str) -> bool:
        return key in self.values and key not in self.defaulted
