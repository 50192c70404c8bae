"""The limits a Param declares (positive, nonnegative, nonzero, whole, range): for every kind and
every declared limit, a value just outside is refused by the loader with exit 2 and one
line naming the key and the limit; a value just inside is accepted by the loader, and a
solve refuses it, if at all, for another reason."""

from __future__ import annotations

import math

import pytest
import yaml

from gyro_cli import kinds
from gyro_cli.core import units
from gyro_cli.core.errors import InputError
from gyro_cli.core.params import Param
from gyro_cli.solving.problem import load, params_of


def _step(x: float) -> float:
    return 1e-6 * max(1.0, abs(x))


# operator -> (a value that breaks it, a value that keeps it), next to the limit x
_SIDES = {
    ">": (lambda x: x, lambda x: x + _step(x)),
    ">=": (lambda x: x - _step(x), lambda x: x),
    "<": (lambda x: x, lambda x: x - _step(x)),
    "<=": (lambda x: x + _step(x), lambda x: x),
    "!=": (lambda x: x, lambda x: x + _step(x)),
    "whole": (lambda x: x / 2, lambda x: x),  # x = 1: half of one, and one
}


def _cases():
    for name in kinds.names():
        kind = kinds.get(name)
        for p in params_of(kind):
            for op, x in p.limits_declared():
                yield pytest.param(name, p, op, x, id=f"{name}-{p.name}{op}{x:.6g}")


CASES = list(_cases())


def _written(p: Param, value: float):
    """The value (SI) as a file writes it: a bare number for a dimensionless key."""
    if p.dimension == "dimensionless":
        return value
    unit = "rad" if p.dimension == "angle" else units.si_text(p.dimension)
    return f"{value!r} {unit}"


def _file(write, kind_name: str, key: str, text) -> str:
    example = kinds.get(kind_name).example
    data = {"id": "limit", "kind": kind_name, "given": dict(example["given"], **{key: text}),
            "find": example["find"]}
    return str(write(yaml.safe_dump(data, sort_keys=False)))


def test_the_migrated_kinds_declare_limits():
    declared = {c.values[0] for c in CASES}
    assert set(kinds.names()) <= declared  # every kind, with the body's keys where it has one


@pytest.mark.parametrize("kind_name, p, op, x", CASES)
def test_just_outside_is_refused_naming_key_and_limit(run, write, kind_name, p, op, x):
    value = _SIDES[op][0](x)
    assert p.limits_broken(value)
    path = _file(write, kind_name, p.name, _written(p, value))
    result = run("solve", path)
    assert result.exit_code == 2, result.output
    err = result.stderr
    assert err.count("\n") == 1 and "Traceback" not in err, err
    unit = units.si_text(p.dimension)
    assert f"given.{p.name} (line" in err, err
    assert f"expected {p.expectation(unit)}, got " in err, err
    assert op == "whole" and "a whole number" in err or \
        f"{op} {p.limit_text(x, unit)}" in err or \
        f"{p.limit_text(x, unit)} {'<' if op == '>' else '<='} {p.name}" in err, err


@pytest.mark.parametrize("kind_name, p, op, x", CASES)
def test_just_inside_is_accepted(run, write, kind_name, p, op, x):
    value = _SIDES[op][1](x)
    assert not p.limits_broken(value)
    path = _file(write, kind_name, p.name, _written(p, value))
    problem = load(path)  # the loader accepts it
    assert problem.given.values[p.name] == pytest.approx(value, rel=1e-12, abs=1e-300)
    result = run("solve", path)
    if result.exit_code != 0:  # e.g. a key that needs another, or the physics of the kind
        assert result.exit_code == 2, result.output
        assert f"expected {p.expectation(units.si_text(p.dimension))}" not in result.stderr


def test_the_message_in_full(write):
    path = write("""
        id: e
        kind: earth_precession
        given:
          preset: earth
          obliquity: 95 deg
        find: [precession_rate]
    """)
    with pytest.raises(InputError) as caught:
        load(str(path))
    assert str(caught.value) == (
        f"{path}: given.obliquity (line 6): expected 0 deg <= obliquity < 90 deg, got "
        "'95 deg'; at 90 deg the bulge lies in the orbit plane and the mean torque vanishes; "
        "for a retrograde rotator give 180 deg minus its obliquity, the axis then moves the "
        "other way")


@pytest.mark.parametrize("declaration, expectation", [
    (dict(positive=True), "x > 0 m"),
    (dict(nonnegative=True), "x >= 0 m"),
    (dict(nonzero=True), "x != 0 m"),
    (dict(range=(-1.0, 2.0)), "-1 m <= x <= 2 m"),
    (dict(range=(0.0, 2 / 3), bounds="(]", limits=("0", "2/3")), "0 < x <= 2/3"),
    (dict(range=(-math.inf, 0.0), bounds="()"), "x < 0 m"),
    (dict(positive=True, range=(-1.0, 2.0), bounds="[)"), "x > 0 m and -1 m <= x < 2 m"),
    (dict(whole=True), "x a whole number"),
    (dict(nonnegative=True, whole=True), "x >= 0 m, a whole number"),
])
def test_the_vocabulary(declaration, expectation):
    p = Param("x", "length", "x", "a length", **declaration)
    assert p.expectation("m" if "limits" not in declaration else "") == expectation


def test_an_angle_limit_is_said_in_degrees():
    p = Param("a", "angle", "a", "an angle", range=(0.0, math.pi / 2), bounds="[)")
    assert p.expectation("rad") == "0 deg <= a < 90 deg"
    assert p.limits_broken(math.pi / 2) == (("<", math.pi / 2),)
    assert p.limits_broken(0.0) == ()


@pytest.mark.parametrize("declaration", [dict(bounds="[["), dict(range=(1.0, 1.0)),
                                         dict(range=(2.0, 1.0))])
def test_a_declaration_that_cannot_hold_is_refused(declaration):
    with pytest.raises(ValueError):
        Param("x", "length", "x", "a length", **declaration)


@pytest.mark.parametrize("value, broken", [(0.0, ()), (3.0, ()), (1e300, ()), (-1.0, ((">=", 0.0),)),
                                           (1.5, (("whole", 1.0),)),
                                           (-0.5, ((">=", 0.0), ("whole", 1.0)))])
def test_a_whole_number(value, broken):
    p = Param("n", "dimensionless", "n", "a count", nonnegative=True, whole=True)
    assert p.limits_broken(value) == broken


def test_a_whole_number_in_the_schema():
    from gyro_cli.commands.authoring import limits_schema

    p = Param("n", "dimensionless", "n", "a count", nonnegative=True, whole=True)
    assert limits_schema(p) == {"minimum": 0.0, "multipleOf": 1.0}
