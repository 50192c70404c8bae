"""Issue 35, round four, item 6: the least data, in the books' words.

A wheel by its diameter, an axis's angle from the horizontal or the downward vertical,
a shape with no size where only ratios matter, US data in inches with no mass. Every
number is worked by hand here (or integrated numerically), never by calling gyro's
formula again.
"""

from __future__ import annotations

import math

import pytest

from gyro_cli.solving.problem import build
from gyro_cli.solving.solve import solve

DRIVE = ("id: x\nkind: gyroscopic_torque\n"
         "given: {{J: 180 kg m^2, speed: 95 km/h, {wheel}, precession: 0.1 rad/s}}\n"
         "find: {{moment: N m}}\n")


def _one_line_refusal(result, key: str) -> None:
    assert result.exit_code == 2, result.output
    lines = [line for line in result.stderr.splitlines() if line.strip()]
    assert len(lines) == 1 and key in lines[0], result.stderr
    assert "Traceback" not in result.output


# ---- a. wheel_diameter wherever wheel_radius is ---------------------------------------

def test_item6a_wheel_diameter_gives_the_radius(write, run):
    """Khurmi's locomotive: treads 1.8 m in diameter, 95 km/h; spin = v / (d / 2)."""
    result = run("solve", write(DRIVE.format(wheel="wheel_diameter: 1.8 m")))
    assert result.exit_code == 0, result.output
    v = 95 / 3.6
    spin = v / 0.9
    assert f"{spin:.4g}" in result.stdout  # 29.32 rad/s
    assert f"{180 * spin * 0.1:.4g}" in result.stdout  # 527.8 N m
    assert "r_w = d_w / 2" in result.stdout  # the conversion, shown


def test_item6a_wheel_diameter_on_a_two_wheeler(write, run):
    """The motorcycle of the chapter with wheels 600 mm across: the same answers as
    with wheel_radius 300 mm (a radius of half the diameter)."""
    text = ("id: m\nkind: two_wheeler\ngiven: {{mass: 250 kg, cg_height: 0.6 m, wheel_inertia: "
            "1 kg*m^2, {wheel}, engine_inertia: 0.3 kg*m^2, gear_ratio: 5, speed: 90 km/h, "
            "turn_radius: 50 m}}\nfind: [heel_angle]\n")
    by_d = run("solve", write(text.format(wheel="wheel_diameter: 600 mm"), "d.yaml"))
    by_r = run("solve", write(text.format(wheel="wheel_radius: 300 mm"), "r.yaml"))
    assert by_d.exit_code == 0, by_d.output
    heel = [line for line in by_d.stdout.splitlines() if "heel_angle" in line]
    assert heel and heel == [line for line in by_r.stdout.splitlines() if "heel_angle" in line]


@pytest.mark.parametrize("wheel, words", [
    ("wheel_diameter: 1.8 m, wheel_radius: 0.9 m", "one way"),
    ("wheel_diameter: -1.8 m", "wheel_diameter > 0"),
    ("wheel_diameter: 1.8 kg", "wheel_diameter"),
])
def test_item6a_wheel_diameter_bad_input(write, run, wheel, words):
    result = run("solve", write(DRIVE.format(wheel=wheel)))
    _one_line_refusal(result, "given.wheel_diameter")
    assert words in result.stderr


def test_item6a_did_you_mean_wheel_diameter(write, run):
    """A misspelt diameter is offered the diameter, not the wheel's inertia."""
    result = run("solve", write(DRIVE.format(wheel="wheel_diametre: 1.8 m")))
    _one_line_refusal(result, "given.wheel_diametre")
    assert "did you mean 'wheel_diameter'" in result.stderr
