"""Authoring: `gyro new`, `gyro schema`, `gyro vary`.

Independent references: the template and the variants are fed back through
the loader, `gyro solve` and `gyro check`; the schema is applied by a small
validator written here (the draft-07 keywords it uses) to files the loader
accepts and to files it rejects, and the two verdicts must agree; the least
spin that `vary` must respect is worked by hand from the discriminant of the
theta equation, psidot_min = 2 sqrt((I - J) m g l cos(theta)) / J.
"""

from __future__ import annotations

import json
import math
import os
import re
from pathlib import Path

import pytest
import yaml
from conftest import PROBLEMS, read_yaml
from test_check import put

from gyro_cli import kinds
from gyro_cli.core.body import BODY_PARAMS
from gyro_cli.solving.problem import load

G = 9.81


# ---- a small JSON Schema validator (the draft-07 keywords gyro's schema uses) ----

def valid(instance, schema) -> bool:
    if "type" in schema:
        types = schema["type"] if isinstance(schema["type"], list) else [schema["type"]]
        checks = {"object": lambda v: isinstance(v, dict), "array": lambda v: isinstance(v, list),
                  "string": lambda v: isinstance(v, str), "null": lambda v: v is None,
                  "number": lambda v: isinstance(v, (int, float)) and not isinstance(v, bool)}
        if not any(checks[t](instance) for t in types):
            return False
    if "enum" in schema and instance not in schema["enum"]:
        return False
    if "const" in schema and instance != schema["const"]:
        return False
    if isinstance(instance, str):
        if "pattern" in schema and not re.search(schema["pattern"], instance):
            return False
        if len(instance) > schema.get("maxLength", math.inf):
            return False
    if isinstance(instance, list):
        if not schema.get("minItems", 0) <= len(instance) <= schema.get("maxItems", math.inf):
            return False
        if "items" in schema and not all(valid(v, schema["items"]) for v in instance):
            return False
    if isinstance(instance, dict):
        if any(k not in instance for k in schema.get("required", [])):
            return False
        if len(instance) < schema.get("minProperties", 0):
            return False
        props = schema.get("properties", {})
        for key, value in instance.items():
            if key in props:
                if not valid(value, props[key]):
                    return False
            elif schema.get("additionalProperties") is False:
                return False
            elif isinstance(schema.get("additionalProperties"), dict):
                if not valid(value, schema["additionalProperties"]):
                    return False
            if "propertyNames" in schema and not valid(key, schema["propertyNames"]):
                return False
    if isinstance(instance, (int, float)) and not isinstance(instance, bool):
        if not (instance >= schema.get("minimum", -math.inf)
                and instance > schema.get("exclusiveMinimum", -math.inf)
                and instance <= schema.get("maximum", math.inf)
                and instance < schema.get("exclusiveMaximum", math.inf)):
            return False
    if "not" in schema and valid(instance, schema["not"]):
        return False
    if "oneOf" in schema and sum(valid(instance, s) for s in schema["oneOf"]) != 1:
        return False
    if "anyOf" in schema and not any(valid(instance, s) for s in schema["anyOf"]):
        return False
    for sub in schema.get("allOf", []):
        if "if" in sub:
            if valid(instance, sub["if"]) and not valid(instance, sub["then"]):
                return False
        elif not valid(instance, sub):
            return False
    return True


@pytest.fixture
def schema(run):
    result = run("schema")
    assert result.exit_code == 0
    return json.loads(result.stdout)


BASE = {"id": "t", "kind": "steady_precession",
        "given": {"mass": "1 kg", "J": "0.002 kg m^2", "I_pivot": "0.01 kg m^2",
                  "cg_distance": "0.05 m", "spin": "300 rad/s", "theta": "60 deg"},
        "find": {"precession": "rpm"}, "expected": {"precession": ["7.85 rpm", "1425 rpm"]},
        "tolerance": "1%"}


def _mutations():
    yield "as is", BASE
    yield "unknown top key", dict(BASE, colour="red")
    yield "typo in given", dict(BASE, given=dict(BASE["given"], spinn="1 rad/s"))
    yield "unknown kind", dict(BASE, kind="nope")
    yield "missing find", {k: v for k, v in BASE.items() if k != "find"}
    yield "unknown answer in find", dict(BASE, find={"precesion": "rpm"})
    yield "unknown answer in expected", dict(BASE, expected={"spinn": "1 rpm"})
    yield "number without unit in given", dict(BASE, given=dict(BASE["given"], spin=300))
    yield "find as a list", dict(BASE, find=["precession"])
    yield "word shape", dict(BASE, given=dict(BASE["given"], shape="cube"))
    yield "per-answer tolerance", dict(BASE, tolerance={"precession": "3 sig"})
    # a dimensionless key's declared limits, which the schema states as minimum/maximum
    earth = {"id": "e", "kind": "earth_precession", "given": {"preset": "earth"},
             "find": {"precession_rate": "arcsec/yr"}}
    yield "eccentricity inside", dict(earth, given={"preset": "earth", "moon_eccentricity": 0.9})
    yield "eccentricity 1", dict(earth, given={"preset": "earth", "moon_eccentricity": 1})
    yield "eccentricity below 0", dict(earth, given={"preset": "earth", "sun_eccentricity": -0.1})
    yield "polar factor 2/3", dict(earth, given={"preset": "earth", "J2": 1e-3,
                                                 "polar_moment_factor": 0.6666})
    yield "polar factor above 2/3", dict(earth, given={"preset": "earth", "J2": 1e-3,
                                                       "polar_moment_factor": 0.67})
    yield "ellipticity 0", dict(earth, given={"preset": "earth", "dynamical_ellipticity": 0})


def _loader_accepts(tmp_path: Path, data: dict) -> bool:
    path = put(tmp_path, "m.yaml", yaml.safe_dump(data))
    try:
        load(str(path))
    except Exception:  # noqa: BLE001 - InputError is the only expected one
        return False
    return True


def test_schema_agrees_with_the_loader(schema, tmp_path):
    for name, data in _mutations():
        assert valid(data, schema) == _loader_accepts(tmp_path, data), name


def test_bundled_problems_are_valid_under_the_schema(schema, problems_dir):
    for path in sorted(problems_dir.glob("*.yaml")):
        data = read_yaml(path.read_text())
        if data.get("kind") in kinds.REGISTRY:
            assert valid(data, schema), path


def test_schema_lists_every_key_of_every_kind(schema):
    assert schema["$schema"].startswith("http://json-schema.org/draft-07")
    rules = {r["if"]["properties"]["kind"]["const"]: r["then"]["properties"]
             for r in schema["allOf"]}
    assert sorted(rules) == kinds.names()
    for name in kinds.names():
        kind = kinds.get(name)
        given = set(rules[name]["given"]["properties"])
        assert {p.name for p in kind.params} <= given
        if kind.uses_body:
            assert {p.name for p in BODY_PARAMS} <= given
        assert set(rules[name]["expected"]["properties"]) == {a.name for a in kind.answers} | {"steps"}


# ---- gyro new -----------------------------------------------------------------

def test_new_template_solves_and_checks(run, tmp_path, schema):
    out = tmp_path / "new.yaml"
    result = run("new", "steady_precession", "-o", out)
    assert result.exit_code == 0, result.output
    text = out.read_text()
    kind = kinds.get("steady_precession")
    for key in [p.name for p in kind.params + BODY_PARAMS] + [a.name for a in kind.answers] + \
            ["id", "title", "kind", "source", "notes", "given", "find", "expected", "tolerance",
             "vary"]:
        assert re.search(rf"^\s*#?\s*{key}:", text, re.M), key
    assert valid(yaml.safe_load(text), schema)
    assert run("solve", out).exit_code == 0
    assert run("check", out).exit_code == 0
    # the template's example answer, checked by hand: the 11/3 top, whose slow
    # precession must satisfy the theta equation with thetaddot = 0
    data = yaml.safe_load(text)
    slow = float(data["expected"]["precession"][0].split()[0]) * 2 * math.pi / 60
    weight = 3 * 0.27801385  # 3 ozf in N
    m = weight / (32.2 * 0.3048)
    J, I = m * (0.84 * 0.0254) ** 2, m * (1.80 * 0.0254) ** 2
    mgl, spin, th = weight * 1.5 * 0.0254, 1800 * 2 * math.pi / 60, math.radians(30)
    residual = I * slow ** 2 * math.cos(th) - J * (spin + slow * math.cos(th)) * slow + mgl
    assert abs(residual) < 1e-3 * mgl  # 4 significant figures
    again = run("new", "steady_precession", "-o", out)
    assert again.exit_code == 2 and "--force" in again.stderr


def test_new_for_every_kind_is_yaml_with_every_key(run):
    for name in kinds.names():
        result = run("new", name)
        assert result.exit_code == 0
        yaml.safe_load(result.stdout)  # valid YAML
        kind = kinds.get(name)
        for key in [p.name for p in kind.params] + [a.name for a in kind.answers]:
            assert re.search(rf"^\s*#?\s*{key}:", result.stdout, re.M), (name, key)
    bad = run("new", "nope")
    assert bad.exit_code == 2 and "unknown kind" in bad.stderr


@pytest.mark.parametrize("name", kinds.names())
def test_new_template_of_every_kind_is_a_working_problem(run, tmp_path, name):
    """A newcomer's `gyro new KIND` then `gyro solve` must work, for every kind."""
    out = tmp_path / f"{name}.yaml"
    assert run("new", name, "-o", out).exit_code == 0
    assert run("solve", out).exit_code == 0
    assert run("check", out).exit_code == 0


# ---- gyro vary ----------------------------------------------------------------

TOP = """\
id: top
kind: steady_precession
given:
  mass: 1 kg
  J: 0.002 kg m^2
  I_pivot: 0.01 kg m^2
  cg_distance: 0.05 m
  spin: 300 rad/s
  theta: 60 deg
find:
  precession: rpm
  min_spin: rad/s
expected:
  precession: [7.85 rpm, 1425 rpm]
tolerance: 1%
vary:
  spin: [0.05, 1.5]
  theta: [20 deg, 70 deg]
"""


def _least_spin(theta: float) -> float:
    """Hand-worked: real roots of I p^2 cos th - J (s + p cos th) p + m g l = 0 need
    J^2 s^2 >= 4 (I - J) m g l cos th."""
    I, J, mgl = 0.01, 0.002, 1 * G * 0.05
    return 2 * math.sqrt((I - J) * mgl * math.cos(theta)) / J


def test_vary_is_reproducible_and_every_variant_checks_clean(run, tmp_path):
    source = put(tmp_path, "top.yaml", TOP)
    a, b, c = tmp_path / "a", tmp_path / "b", tmp_path / "c"
    assert run("vary", source, "--count", "12", "--seed", "5", "-o", a).exit_code == 0
    assert run("vary", source, "--count", "12", "--seed", "5", "-o", b).exit_code == 0
    assert run("vary", source, "--count", "12", "--seed", "6", "-o", c).exit_code == 0
    names = sorted(os.listdir(a))
    assert len(names) == 12 and names == sorted(os.listdir(b))
    assert all((a / n).read_bytes() == (b / n).read_bytes() for n in names)
    assert any((a / n).read_bytes() != (c / n).read_bytes() for n in names)
    result = run("check", a)
    assert result.exit_code == 0, result.output
    assert "12 problems" in result.stdout.splitlines()[-1]
    for n in names:
        data = yaml.safe_load((a / n).read_text())
        spin = float(data["given"]["spin"].split()[0])
        theta = math.radians(float(data["given"]["theta"].split()[0]))
        assert 0.05 * 300 * 0.995 <= spin <= 1.5 * 300 * 1.005
        assert 19.9 <= math.degrees(theta) <= 70.1
        # spins below the least spin have no steady precession: they were rejected
        assert spin >= _least_spin(theta)
        assert len(data["expected"]["precession"]) == 2
        assert "vary" not in data


def test_vary_leaves_out_an_answer_a_variant_does_not_have(run, tmp_path):
    """A bicycle without its wheels' spin is never self-stable: it has no weave speed
    (gyro solve gives none, with a warning), so a variant keys none rather than writing
    `weave_speed: []`, which gyro check refuses as an expected value; the variants
    check clean and still ask for it in `find`."""
    text = (PROBLEMS / "bicycle_no_spin.yaml").read_text()
    text = text.replace("find:\n  motion: null\n", "find:\n  motion: null\n  weave_speed: m/s\n")
    text = re.sub(r"expected:\n(  .*\n)+", "", text) + "vary:\n  speed: [0.9, 1.1]\n"
    source = put(tmp_path, "no_spin.yaml", text)
    out = tmp_path / "out"
    assert run("vary", source, "--count", "3", "--seed", "2", "-o", out).exit_code == 0
    for name in sorted(os.listdir(out)):
        data = yaml.safe_load((out / name).read_text())
        assert "weave_speed" in data["find"] and "weave_speed" not in data["expected"]
        assert data["expected"]["motion"] == "weave"
    result = run("check", out)
    assert result.exit_code == 0, result.output


def test_vary_writes_the_digits_a_tight_tolerance_needs(run, tmp_path):
    """With `tolerance: 14 sig` an expected value needs more than 12 significant digits
    to be within half a unit of its 14th digit of the computed value: every variant
    keys such values and checks clean against its own key."""
    source = put(tmp_path, "top.yaml", TOP.replace("tolerance: 1%", "tolerance: 14 sig"))
    out = tmp_path / "out"
    assert run("vary", source, "--count", "12", "--seed", "3", "-o", out).exit_code == 0
    digits = []
    for name in sorted(os.listdir(out)):
        data = yaml.safe_load((out / name).read_text())
        digits += [len(re.sub(r"[^0-9]", "", v.split()[0].split("e")[0]).lstrip("0"))
                   for v in data["expected"]["precession"]]
    assert max(digits) > 12  # the old 12-digit text could not meet 14 sig
    result = run("check", out)
    assert result.exit_code == 0, result.output


def test_vary_refuses_overwrite_and_impossible_ranges(run, tmp_path):
    source = put(tmp_path, "top.yaml", TOP)
    out = tmp_path / "out"
    assert run("vary", source, "--count", "2", "--seed", "1", "-o", out).exit_code == 0
    again = run("vary", source, "--count", "2", "--seed", "1", "-o", out)
    assert again.exit_code == 2 and "--force" in again.stderr
    assert run("vary", source, "--count", "2", "--seed", "1", "-o", out, "--force").exit_code == 0
    # 3..6 rad/s: below the least spin at every theta in 20..70 deg (35..61 rad/s)
    low = put(tmp_path, "low.yaml", TOP.replace("[0.05, 1.5]", "[0.01, 0.02]"))
    result = run("vary", low, "--count", "3", "-o", tmp_path / "low")
    assert result.exit_code == 2 and "real solution" in result.stderr


@pytest.mark.parametrize("block, message", [
    ("vary: {spinn: [0.8, 1.2]}", "not a numeric given key"),
    ("vary: {spin: [1.2]}", "expected [low, high]"),
    ("vary: {spin: [1.2, 0.8]}", "0 < low <= high"),
    ("vary: {theta: [40 deg, 20 deg]}", "low must not exceed high"),
    ("vary: {theta: [20 m, 40 m]}", "an angle"),
    ("", "no `vary` block"),
])
def test_vary_block_errors(run, tmp_path, block, message):
    text = TOP.split("vary:")[0] + block + "\n"
    source = put(tmp_path, "top.yaml", text)
    result = run("vary", source, "--count", "2", "-o", tmp_path / "out")
    assert result.exit_code == 2
    assert message in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1


def test_vary_through_the_installed_command(tmp_path):
    import subprocess

    from test_check import gyro_exe

    source = put(tmp_path, "top.yaml", TOP)
    outs = []
    for name in ("x", "y"):
        done = subprocess.run([gyro_exe(), "vary", str(source), "--count", "3", "--seed", "9",
                               "-o", str(tmp_path / name)], capture_output=True, text=True)
        assert done.returncode == 0, done.stderr
        outs.append({n: (tmp_path / name / n).read_bytes()
                     for n in os.listdir(tmp_path / name)})
    assert outs[0] == outs[1] and len(outs[0]) == 3
    checked = subprocess.run([gyro_exe(), "check", str(tmp_path / "x")], capture_output=True,
                             text=True)
    assert checked.returncode == 0, checked.stdout
