"""The released_top kind end to end through the CLI: the problem files' answers against
Lagrange's equations integrated in the test, the worked answer's content, warnings, and
bad input (exit 2, one line, no traceback)."""

from __future__ import annotations

import json
import math

import pytest
from lagrange_top import integrate
from test_nutation import TOP

FILES = ["11_2_released_top.yaml", "11_2_released_top_loops.yaml",
         "11_2_released_top_waves.yaml", "11_2_sleeping_top.yaml"]
RPM = math.pi / 30

GIVEN = """\
  weight: 3 oz
  k_axial: 0.84 in
  k_pivot: 1.80 in
  cg_distance: 1.5 in"""


def problem(extra: str, find: str = "theta_max: deg\n  motion: null") -> str:
    return f"id: x\nkind: released_top\ngiven:\n{GIVEN}\n{extra}\nfind:\n  {find}\n"


def one_line_error(result, *fragments: str) -> str:
    assert result.exit_code == 2, result.output
    assert result.stdout == ""
    err = result.stderr
    assert "Traceback" not in err and err.count("\n") == 1 and err.startswith("gyro: "), err
    for fragment in fragments:
        assert fragment in err, (fragment, err)
    return err


@pytest.mark.parametrize("name", FILES)
def test_problem_files_check_clean(run, problems_dir, name):
    result = run("check", problems_dir / name)
    assert result.exit_code == 0, result.output


@pytest.mark.parametrize("name", FILES[:3])
def test_problem_file_answers_against_integration(run, problems_dir, name):
    """gyro solve --format json of each file, against the integrated Eqs. 11.13 from the
    file's initial state (SI values from the JSON given block)."""
    result = run("solve", problems_dir / name, "--format", "json")
    assert result.exit_code == 0, result.output
    report = json.loads(result.stdout)
    given = {g["key"]: g["si_value"] for g in report["given"]}
    answers = {k: v["si_values"] for k, v in report["answers"].items()}
    T = answers["nutation_period"][0]
    ref = integrate(TOP.I, TOP.J, TOP.mgl, given["theta0"], given["spin"],
                    given.get("precession0", 0.0), given.get("theta_rate0", 0.0), t_end=4.3 * T)
    assert answers["theta_min"][0] == pytest.approx(ref.theta_min, rel=1e-7)
    assert answers["theta_max"][0] == pytest.approx(ref.theta_max, rel=1e-7)
    assert T == pytest.approx(ref.nutation_period, rel=1e-7)
    assert answers["mean_precession"][0] == pytest.approx(ref.mean_precession, rel=1e-7)
    u = sorted(math.cos(x) for x in (ref.theta_min, ref.theta_max))
    assert answers["u_roots"][:2] == pytest.approx(u, rel=1e-7)
    assert report["answers"]["motion"]["unit"] is None
    # the problem files' top is TOP: the JSON body agrees with the hand-computed one
    assert report["kind"] == "released_top"


def test_sleeping_file_period_is_the_limit_of_a_tiny_tilt(run, problems_dir):
    result = run("solve", problems_dir / "11_2_sleeping_top.yaml", "--format", "json")
    assert result.exit_code == 0, result.output
    answers = json.loads(result.stdout)["answers"]
    assert answers["motion"]["values"] == ["sleeping"]
    ref = integrate(TOP.I, TOP.J, TOP.mgl, 1e-6, 1800 * RPM, t_end=1.5)
    assert answers["nutation_period"]["si_values"][0] == pytest.approx(ref.nutation_period,
                                                                       rel=1e-6)


def test_worked_answer_shows_the_chapter(run, problems_dir):
    result = run("solve", problems_dir / "11_2_released_top.yaml")
    assert result.exit_code == 0, result.output
    out = result.stdout
    for fragment in ("Eq. 11.14", "Eq. 11.17", "Eq. 11.18", "Eq. 11.19", "Eq. 11.25",
                     "γ²/a", "4 K(m) / sqrt(a (u3 - u1))", "Pi(n1|m)",
                     "Fast-top approximation", "2 pi I / (J omega_z)", "m g l / (J omega_z)",
                     "2 I m g l sin(theta0) / (J omega_z)^2", "error", "motion: cusps",
                     "u1 = 0.7843", "theta_max = 38.34 deg", "T = 0.1887 s"):
        assert fragment in out, fragment
    assert "Warnings" not in out


def test_fast_top_section_errors_are_the_relative_errors(run, write):
    """At 100000 rpm the fast-top forms are within 0.05% of the exact values (a / gamma^2 is
    about 6e-5)."""
    result = run("solve", write(problem("  theta0: 30 deg\n  spin: 100000 rpm")), "--format",
                 "json")
    assert result.exit_code == 0, result.output
    lines = [line for s in json.loads(result.stdout)["steps"] for line in s["lines"]]
    fast = [line for line in lines if line.startswith(("T_fast", "phidot_fast", "dtheta_fast"))]
    assert len(fast) == 3
    for line in fast:
        error = float(line.rsplit("error ", 1)[1].rstrip("%"))
        assert abs(error) < 0.05, line


def test_warning_when_theta_max_passes_90_deg(run, write):
    result = run("solve", write(problem("  theta0: 80 deg\n  spin: 600 rpm")))
    assert result.exit_code == 0, result.output
    assert "passes 90 deg" in result.stdout and "floor" in result.stdout


def test_unstable_sleeping_top_warns(run, write):
    result = run("solve", write(problem("  theta0: 0 deg\n  spin: 600 rpm")))
    assert result.exit_code == 0, result.output
    least = 2 * math.sqrt(TOP.I * TOP.mgl) / TOP.J / RPM      # J^2 omega^2 = 4 I m g l
    assert "unstable" in result.stdout and f"{least:.4g} rpm" in result.stdout


BAD = {
    "negative spin": ("  theta0: 30 deg\n  spin: -1800 rpm", ["given.spin", "reverse the sense"]),
    "zero spin": ("  theta0: 30 deg\n  spin: 0 rpm", ["given.spin", "pendulum"]),
    "upright, no spin": ("  theta0: 0 deg\n  spin: 0 rpm", ["given.spin"]),
    "theta0 past 180 deg": ("  theta0: 200 deg\n  spin: 1800 rpm", ["given.theta0", "180"]),
    "negative theta0": ("  theta0: -10 deg\n  spin: 1800 rpm", ["given.theta0"]),
    "bare angle": ("  theta0: 30\n  spin: 1800 rpm", ["given.theta0"]),
}


@pytest.mark.parametrize("name", list(BAD))
def test_bad_input_exits_2(run, write, name):
    extra, fragments = BAD[name]
    one_line_error(run("solve", write(problem(extra))), *fragments)


def test_top_that_cannot_stand_exits_2(run, write):
    no_l = problem("  theta0: 30 deg\n  spin: 1800 rpm").replace("  cg_distance: 1.5 in\n", "")
    one_line_error(run("solve", write(no_l)), "given.cg_distance")
    zero_l = problem("  theta0: 30 deg\n  spin: 1800 rpm").replace("1.5 in", "0 in")
    one_line_error(run("solve", write(zero_l)), "given.cg_distance")
    no_I = problem("  theta0: 30 deg\n  spin: 1800 rpm").replace("  k_pivot: 1.80 in\n", "")
    one_line_error(run("solve", write(no_I)), "given.I_pivot")


def test_sleeping_top_has_no_precession(run, write):
    text = problem("  theta0: 0 deg\n  spin: 1800 rpm", find="mean_precession: rpm")
    one_line_error(run("solve", write(text)), "find.mean_precession", "sleeping")


def test_thrown_top_defaults_and_units(run, write):
    """precession0 and theta_rate0 in any rate unit; the defaults are shown as defaults."""
    text = problem("  theta0: 45 deg\n  spin: 1500 rpm\n  precession0: 30 deg/s\n"
                   "  theta_rate0: -0.5 rad/s", find="theta_min: deg\n  mean_precession: rpm")
    result = run("solve", write(text), "--format", "json")
    assert result.exit_code == 0, result.output
    answers = json.loads(result.stdout)["answers"]
    ref = integrate(TOP.I, TOP.J, TOP.mgl, math.radians(45), 1500 * RPM, math.radians(30),
                    -0.5, t_end=1.0)
    assert answers["theta_min"]["si_values"][0] == pytest.approx(ref.theta_min, rel=1e-7)
    released = run("solve", write(problem("  theta0: 45 deg\n  spin: 1500 rpm"), "r.yaml"))
    assert "(default)" in released.stdout


@pytest.mark.parametrize("theta0", ["0 deg", "180 deg"])
def test_thrown_through_the_vertical_warns_about_phi(run, write, theta0):
    text = problem(f"  theta0: {theta0}\n  spin: 1800 rpm\n  theta_rate0: 1 rad/s",
                   find="theta_max: deg\n  mean_precession: rpm\n  max_precession: rpm")
    result = run("solve", write(text), "--format", "json")
    assert result.exit_code == 0, result.output
    report = json.loads(result.stdout)
    assert any("passes through the vertical" in w for w in report["warnings"])
    assert all(math.isfinite(v) for a in report["answers"].values() for v in a["si_values"])
