"""`gyro check` grades intermediate values: `expected: {steps: {symbol: value}}`."""

from __future__ import annotations

import json

AEROPLANE = """\
id: s1
kind: aeroplane
given: {{mass: 400 kg, k_axial: 0.3 m, spin: 2400 rpm, rotor_sense: clockwise_from_rear,
        speed: 200 km/h, turn_radius: 50 m}}
find: {{couple: N*m}}
expected:
  steps: {{{steps}}}
"""
# by hand: J = 400 kg (0.3 m)^2 = 36 kg m^2; omega = 2400 rpm = 251.33 rad/s;
# H = J omega = 9047.8 kg m^2/s; omega_p = v / R = (200 / 3.6 m/s) / 50 m = 1.1111 rad/s
# = 10.610 rpm; C = H omega_p = 10053 N m


def test_a_right_intermediate_value_passes(run, write):
    path = write(AEROPLANE.format(steps="H: 9048 kg m^2/s, omega_p: 10.61 rpm, C: 10.05 kN m"))
    out = run("check", "--format", "json", path)
    assert out.exit_code == 0, out.output
    answers = json.loads(out.stdout)["problems"][0]["answers"]
    assert [a["name"] for a in answers] == ["steps.H", "steps.omega_p", "steps.C"]
    assert all(a["passed"] for a in answers)


def test_a_wrong_intermediate_value_fails(run, write):
    path = write(AEROPLANE.format(steps="omega_p: 12 rpm"))  # 13% off
    out = run("check", path)
    assert out.exit_code == 1, out.output
    assert "FAIL  steps.omega_p" in out.stdout


def test_an_unknown_step_or_dimension_is_a_bad_file(run, write):
    out = run("check", write(AEROPLANE.format(steps="omega_q: 10 rpm")))
    assert out.exit_code == 2
    assert "expected.steps.omega_q: no step of the worked answer gives 'omega_q'" in out.output
    assert "did you mean 'omega_p'" in out.output and "Traceback" not in out.output
    out = run("check", write(AEROPLANE.format(steps="omega_p: 3 m")))
    assert out.exit_code == 2 and "expected.steps.omega_p" in out.output
    out = run("check", write(AEROPLANE.format(steps="").replace("steps: {}", "steps: [1]")))
    assert out.exit_code == 2 and "expected.steps" in out.output


def test_the_schema_accepts_graded_steps():
    import jsonschema
    import yaml

    from gyro_cli.commands.authoring import schema

    doc = yaml.safe_load(AEROPLANE.format(steps="omega_p: 10.61 rpm"))
    jsonschema.validate(doc, schema())
    doc["expected"]["steps"] = {}
    try:
        jsonschema.validate(doc, schema())
    except jsonschema.ValidationError:
        pass
    else:
        raise AssertionError("an empty steps mapping should not validate")
