"""`gyro simulate` on runs shorter than, about and longer than a nutation period.

The reference is tests/lagrange_top.py (Lagrange's equations 11.13 in Euler angles,
integrated here with solve_ivp, theta's turning points as events), and a hand
reading of the released top: let go from rest (thetadot = phidot = 0 at theta0), the
axis first falls, so t = 0 is a theta minimum with phidot = 0 there: cusps (Fig. 11-9).
"""

from __future__ import annotations

import json
import math

import pytest
from lagrange_top import integrate

INCH = 0.0254
# problem 11/3's top (problems/11_2_released_top.yaml), SI, by hand
WEIGHT = 3 * 0.27801385                  # 3 ozf in N
M = WEIGHT / (32.2 * 0.3048)            # kg: US customary data take the textbook g
I = M * (1.80 * INCH) ** 2              # about the fixed point
J = M * (0.84 * INCH) ** 2
MGL = WEIGHT * 1.5 * INCH               # weight times cg_distance
THETA0, SPIN = math.radians(30), 1800 * 2 * math.pi / 60


@pytest.fixture(scope="module")
def reference():
    """Ten periods of the Lagrange integration: theta_max, the period, the mean precession."""
    return integrate(I, J, MGL, THETA0, SPIN, t_end=2.0)


def simulated(run, problems_dir, periods):
    result = run("simulate", problems_dir / "11_2_released_top.yaml", "--periods", periods,
                 "--format", "json")
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)


def test_reference_is_the_released_top(reference):
    """The hand-built top is the file's: its theta_max and period as the file expects."""
    assert math.degrees(reference.theta_max) == pytest.approx(38.342, rel=5e-4)
    assert reference.nutation_period == pytest.approx(0.18865, rel=5e-4)


def test_a_third_of_a_period_is_too_short_to_classify(run, problems_dir, reference):
    """0.3 periods: theta only falls, from its minimum at the release toward a maximum it has
    not reached. One extremum, of one kind, says nothing about loops, cusps or waves; no whole
    period holds a mean; the largest theta seen is no maximum."""
    report = simulated(run, problems_dir, "0.3")
    sim = report["simulated"]
    assert sim["motion"] == "too short to classify"
    assert report["difference"]["motion"] is None           # not flagged DIFFERENT
    assert sim["mean_precession"] is None
    assert sim["nutation_period"] is None
    assert sim["theta_max"] is None
    assert report["theta_range"] < reference.theta_max - THETA0 - math.radians(1)
    assert sim["theta_min"] == pytest.approx(THETA0, abs=1e-12)   # the release is a minimum
    notes = " ".join(report["notes"])
    assert "whole periods only" in notes and "theta_max is not measured" in notes


def test_text_report_says_too_short(run, problems_dir):
    result = run("simulate", problems_dir / "11_2_released_top.yaml", "--periods", "0.3")
    assert result.exit_code == 0, result.output
    line = next(l for l in result.stdout.splitlines() if l.strip().startswith("motion"))
    assert "too short to classify" in line and "not compared" in line
    assert "DIFFERENT" not in result.stdout


def test_a_period_and_a_fifth_reports_the_motion(run, problems_dir, reference):
    """1.2 periods: the release (a minimum), one maximum and the next minimum: the nutation
    period is measured between the two minima and the mean precession over that one whole
    period, both as the Lagrange reference has them; cusps, as read by hand."""
    report = simulated(run, problems_dir, "1.2")
    sim = report["simulated"]
    assert sim["motion"] == "cusps"
    assert report["difference"]["motion"] is True
    assert sim["theta_max"] == pytest.approx(reference.theta_max, rel=1e-9)
    assert sim["nutation_period"] == pytest.approx(reference.nutation_period, rel=1e-9)
    assert sim["mean_precession"] == pytest.approx(reference.mean_precession, rel=1e-8)
    assert any("over 1 whole nutation period" in note for note in report["notes"])


def test_seven_tenths_of_a_period_classifies_from_the_two_extrema(run, problems_dir):
    """0.7 periods: a minimum (the release) and a maximum are seen, enough for the motion;
    no whole period: no period and no mean precession."""
    report = simulated(run, problems_dir, "0.7")
    assert report["simulated"]["motion"] == "cusps"
    assert report["simulated"]["nutation_period"] is None
    assert report["simulated"]["mean_precession"] is None


def test_five_periods(run, problems_dir, reference):
    report = simulated(run, problems_dir, "5")
    sim = report["simulated"]
    assert sim["motion"] == "cusps" and report["difference"]["motion"] is True
    assert sim["nutation_period"] == pytest.approx(reference.nutation_period, rel=1e-9)
    assert sim["mean_precession"] == pytest.approx(reference.mean_precession, rel=1e-8)
    assert any("over 4 whole nutation periods" in note for note in report["notes"])


def test_energy_drift_beside_its_varying_part(run, problems_dir, reference):
    """The spin energy J omega_z^2 / 2 is constant; the energy that varies is the transverse
    kinetic energy, which by energy conservation peaks at theta_max at
    m g l (cos theta0 - cos theta_max) (released from rest), plus m g l. The two drift
    figures are the same error over the two scales."""
    report = simulated(run, problems_dir, "5")
    T0 = 0.5 * J * SPIN ** 2
    transverse_max = MGL * (math.cos(THETA0) - math.cos(reference.theta_max))
    ratio = (T0 + MGL) / (transverse_max + MGL)
    assert ratio > 15                                       # the spin energy dominates T0
    drift = report["drift"]
    assert drift["energy_varying"] == pytest.approx(drift["energy"] * ratio, rel=1e-6)
    assert drift["energy_varying"] < 1e-10


@pytest.mark.parametrize("name, motion", [("loops", "loops"),
                                          ("waves", "too short to classify")])
def test_a_third_of_a_period_pushed_tops(run, problems_dir, name, motion):
    """Pushed at 30 deg with phidot0 = -20 rpm (against the mean precession, which is
    forward, +46 rpm): phidot takes both signs within the first third of a period, and a
    phidot that changes sign is a loop whatever theta's range. Pushed with +20 rpm, phidot
    keeps its sign so far: waves and cusps cannot be told apart yet."""
    result = run("simulate", problems_dir / f"11_2_released_top_{name}.yaml", "--periods",
                 "0.3", "--format", "json")
    assert result.exit_code == 0, result.output
    report = json.loads(result.stdout)
    assert report["simulated"]["motion"] == motion
    assert report["difference"]["motion"] is (True if motion == "loops" else None)
