"""core/record.py: a record behaves as the dataclass of the same fields, before and after
its __init__ is compiled (a class made COMPILE_AFTER times)."""

from __future__ import annotations

import copy
import dataclasses

import pytest

from gyro_cli.core import record as records
from gyro_cli.core.record import field, record


def _pair(frozen: bool):
    def body(decorate):
        @decorate
        class Step:
            name: str
            value: float
            unit: str = ""
            notes: list = field(default_factory=list)
            seen: list = field(default_factory=list)

            def __post_init__(self) -> None:
                self.seen.append(self.name)
        return Step
    return body(dataclasses.dataclass(frozen=False)), body(record(frozen=frozen))


CALLS = [(("a", 1.0), {}), (("a",), {"value": 2.0, "unit": "m"}),
         ((), {"name": "b", "value": 3.0, "notes": [1]}), (("c", 4.0, "s", [2], []), {})]
BAD = [((), {}), (("a",), {}), (("a", 1.0), {"name": "b"}), (("a", 1.0), {"colour": 1}),
       (("a", 1.0, "", [], [], 9), {})]


@pytest.mark.parametrize("rounds", [1, records.COMPILE_AFTER + 5])
def test_a_record_is_made_as_its_dataclass(rounds):
    plain, made = _pair(frozen=False)
    for _ in range(rounds):
        for args, kwargs in CALLS:
            a = plain(*copy.deepcopy(args), **copy.deepcopy(kwargs))
            b = made(*copy.deepcopy(args), **copy.deepcopy(kwargs))
            assert dataclasses.asdict(a) == dataclasses.asdict(b)
            assert [f.name for f in dataclasses.fields(a)] == [f.name for f in dataclasses.fields(b)]
            assert b.seen == [b.name]  # __post_init__ ran once
            assert repr(a) == repr(b)
            assert dataclasses.replace(b, unit="kg", seen=[]) == made(b.name, b.value, "kg",
                                                                      b.notes)
        for args, kwargs in BAD:
            with pytest.raises(TypeError):
                plain(*args, **kwargs)
            with pytest.raises(TypeError):
                made(*args, **kwargs)
    assert made(*CALLS[0][0]).notes is not made(*CALLS[0][0]).notes  # a fresh list each
    assert (made.__init__ is records._init) == (rounds < records.COMPILE_AFTER)


def test_only_a_frozen_record_is_hashable_and_equal_by_its_fields():
    _, thawed = _pair(frozen=False)
    _, frozen = _pair(frozen=True)
    with pytest.raises(TypeError):
        hash(thawed("a", 1.0))
    one, two = frozen("a", 1.0, notes=()), frozen("a", 1.0, notes=())
    other = frozen("a", 2.0, notes=())
    for made in (one, two, other):
        made.seen = tuple(made.seen)
    assert one == two and hash(one) == hash(two) and one != other
    assert dataclasses.is_dataclass(one)
