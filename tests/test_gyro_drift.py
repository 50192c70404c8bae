"""gyro_drift checked against the linearised gimbal equations integrated here.

The equations I_x a'' + H b' = M, I_y b'' - H a' = 0 (a, b: rotations of the
spin axis about the moment's axis x and the drift axis y) are integrated from
rest with scipy's solve_ivp; the drift rate, the nutation frequency and both
amplitudes are read off the numerical solution (a least-squares slope, the
spacing of the peaks of a(t), the extremes) and compared with the kind. Also
the published Earth-precession torque, hand calculations of the bundled
problems, the inverse (budget -> moment -> the same drift) and bad input.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from gyro_cli.physics import gyro_drift as gd

DEG_H = math.pi / 180 / 3600


def nutation_amplitudes(moment: float, H: float, Ix: float, Iy: float) -> tuple[float, float]:
    """Oracle: (about the moment's axis x, about the drift axis y) for M applied at rest,
    M I_y / H^2 and M sqrt(I_x I_y) / H^2 (the closed form of the gimbal equations)."""
    return moment * Iy / (H * H), moment * math.sqrt(Ix * Iy) / (H * H)


def gimbal_angles(t: float, moment: float, H: float, Ix: float, Iy: float) -> tuple[float, float]:
    """Oracle: (a, b) at time t from rest, the closed-form solution of I_x a'' + H b' = M,
    I_y b'' - H a' = 0."""
    wn = H / math.sqrt(Ix * Iy)
    a = moment * Iy / (H * H) * (1 - math.cos(wn * t))
    b = moment / H * t - moment / (H * wn) * math.sin(wn * t)
    return a, b


def integrate(M, H, Ix, Iy, periods=6.0, n=6001):
    """a, b and t from rest, by solve_ivp on the gimbal equations."""
    wn_guess = H / math.sqrt(Ix * Iy)  # only to choose the time span
    t_end = periods * 2 * math.pi / wn_guess

    def rhs(t, s):
        a, b, ad, bd = s
        return [ad, bd, (M - H * bd) / Ix, H * ad / Iy]

    t = np.linspace(0, t_end, n)
    sol = solve_ivp(rhs, (0, t_end), [0, 0, 0, 0], t_eval=t, rtol=1e-11, atol=1e-16,
                    method="DOP853")
    assert sol.success
    return t, sol.y[0], sol.y[1]


def peaks_of(a):
    return [i for i in range(1, len(a) - 1) if abs(a[i]) > abs(a[i - 1]) and
            abs(a[i]) >= abs(a[i + 1])]


def mean_drift(t, a, b):
    """The mean rate of b between the first and last peaks of a (whole nutation cycles)."""
    peaks = peaks_of(a)
    i, j = peaks[0], peaks[-1]
    return (b[j] - b[i]) / (t[j] - t[i])


CASES = [  # M, H, I_x, I_y
    (1e-3, 0.5, 2e-3, 2e-3),
    (2e-3, 0.8, 1e-3, 4e-3),
    (-5e-4, 0.3, 6e-3, 1.5e-3),
    (1e-7, 0.1, 2e-6, 4.5e-6),   # the navigation gyro of drift_navigation_gyro.yaml
]


@pytest.mark.parametrize("M, H, Ix, Iy", CASES)
def test_closed_forms_against_the_integrated_gimbal_equations(M, H, Ix, Iy):
    t, a, b = integrate(M, H, Ix, Iy)
    scale_a = abs(M) * Iy / H ** 2
    assert mean_drift(t, a, b) == pytest.approx(gd.drift_rate(M, H), rel=1e-3)
    # the whole solution against the closed forms
    closed = np.array([gimbal_angles(ti, M, H, Ix, Iy) for ti in t])
    assert np.max(np.abs(closed[:, 0] - a)) < 1e-6 * scale_a
    assert np.max(np.abs(closed[:, 1] - b)) < 1e-6 * abs(M / H) * t[-1]
    # nutation frequency from the spacing of the maxima of |a|
    peaks = peaks_of(a)
    period = (t[peaks[-1]] - t[peaks[0]]) / (len(peaks) - 1)
    assert 2 * math.pi / period == pytest.approx(gd.nutation_frequency(H, Ix, Iy), rel=1e-3)
    # amplitudes: a swings between 0 and 2 M I_y / H^2; the ripple on b is M sqrt(IxIy) / H^2
    ax, ay = nutation_amplitudes(M, H, Ix, Iy)
    assert np.max(np.abs(a)) == pytest.approx(2 * abs(ax), rel=1e-4)
    assert np.min(np.abs(a)) < 1e-6 * scale_a
    ripple = b - gd.drift_rate(M, H) * t
    assert np.max(np.abs(ripple)) == pytest.approx(abs(ay), rel=1e-4)
    if Ix == Iy:  # the M I / H^2
        assert abs(ax) == pytest.approx(abs(M) * Ix / H ** 2)


def test_larger_spin_means_slower_drift_and_faster_smaller_nutation():
    # doubling H halves the drift, doubles w_n and quarters the amplitude
    M, Ix, Iy = 1e-3, 2e-3, 3e-3
    assert gd.drift_rate(M, 2.0) == pytest.approx(gd.drift_rate(M, 1.0) / 2)
    assert gd.nutation_frequency(2.0, Ix, Iy) == pytest.approx(
        2 * gd.nutation_frequency(1.0, Ix, Iy))
    assert nutation_amplitudes(M, 2.0, Ix, Iy)[0] == pytest.approx(
        nutation_amplitudes(M, 1.0, Ix, Iy)[0] / 4)


def solve_json(run, path):
    result = run("solve", "--format", "json", path)
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)


def test_cli_answers_match_the_integration(run, write):
    out = solve_json(run, write("""
        id: d
        kind: gyro_drift
        given:
          J: 4e-4 kg m^2
          spin: 2000 rad/s
          moment: 2e-3 N m
          I_x: 1e-3 kg m^2
          I_y: 4e-3 kg m^2
          duration: 10 s
        find: [angular_momentum, drift_rate, drift_angle, nutation_frequency, nutation_period,
               nutation_amplitude, nutation_amplitude_drift, max_deflection]
        """))
    a = {k: v["si_values"][0] for k, v in out["answers"].items()}
    H = 4e-4 * 2000
    t, ang_a, ang_b = integrate(2e-3, H, 1e-3, 4e-3)
    assert a["angular_momentum"] == pytest.approx(0.8)
    assert a["drift_rate"] == pytest.approx(mean_drift(t, ang_a, ang_b), rel=1e-3)
    assert a["drift_angle"] == pytest.approx(2e-3 / 0.8 * 10)
    assert a["max_deflection"] == pytest.approx(np.max(np.abs(ang_a)), rel=1e-4)
    assert a["nutation_amplitude"] == pytest.approx(np.max(np.abs(ang_a)) / 2, rel=1e-4)
    assert a["nutation_period"] == pytest.approx(2 * math.pi / a["nutation_frequency"])
    assert a["nutation_frequency"] == pytest.approx(0.8 / math.sqrt(4e-6))


def test_published_earth_precession_torque(run, problems_dir):
    # Serway & Jewett: I = 2/5 M R^2 = 9.71e37, L = I 2 pi / 86400 s = 7.06e33,
    # w_p = 2 pi / (2.58e4 yr) = 7.72e-12 rad/s, torque = w_p L = 5.45e22 N m.
    out = solve_json(run, problems_dir / "drift_earth_precession.yaml")
    a = {k: v["si_values"][0] for k, v in out["answers"].items()}
    I = 0.4 * 5.98e24 * 6.37e6 ** 2
    L = I * 2 * math.pi / 86400
    wp = 2 * math.pi / (2.58e4 * 365 * 86400)
    assert a["angular_momentum"] == pytest.approx(L, rel=1e-9)
    assert a["moment"] == pytest.approx(wp * L, rel=1e-3)  # Julian year vs 365 d: 0.07 %
    assert round(a["moment"] / 1e22, 2) == 5.45


def test_bundled_navigation_and_gpb_by_hand(run, problems_dir):
    out = solve_json(run, problems_dir / "drift_navigation_gyro.yaml")
    a = {k: v["values"][0] for k, v in out["answers"].items()}
    # 1 dyn cm = 1e-7 N m; 1e6 g cm^2/s = 0.1 kg m^2/s; drift 1e-6 rad/s
    assert a["drift_rate"] == pytest.approx(1e-6 / DEG_H)          # deg/h
    assert a["drift_angle"] == pytest.approx(math.degrees(1e-6 * 8 * 3600))
    assert a["nutation_frequency"] == pytest.approx(0.1 / math.sqrt(2e-6 * 4.5e-6) / (2 * math.pi))
    assert a["nutation_amplitude"] == pytest.approx(1e-7 * 4.5e-6 / 0.01)
    out = solve_json(run, problems_dir / "drift_gpb_budget.yaml")
    a = {k: v["si_values"][0] for k, v in out["answers"].items()}
    J = 0.4 * 0.0632 * 0.019 ** 2
    assert a["moment"] == pytest.approx(J * 2 * math.pi * 170 * 1e-11 * DEG_H)


def test_budget_gives_the_moment_that_drifts_at_the_budget(run, write):
    base = """
        id: b
        kind: gyro_drift
        given:
          J: 1e-3 kg m^2
          spin: 12000 rpm
          {what}
        find: [moment, drift_rate]
        """
    out = solve_json(run, write(base.format(what="drift_rate: 0.1 deg/h")))
    M = out["answers"]["moment"]["si_values"][0]
    assert M == pytest.approx(1e-3 * 12000 * 2 * math.pi / 60 * 0.1 * DEG_H)
    back = solve_json(run, write(base.format(what=f"moment: {M!r} N m"), "c.yaml"))
    assert back["answers"]["drift_rate"]["si_values"][0] == pytest.approx(0.1 * DEG_H)


def one_line(result, *fragments):
    assert result.exit_code == 2, result.output
    err = result.stderr
    assert err.count("\n") == 1 and "Traceback" not in err, err
    for f in fragments:
        assert f in err, (f, err)


@pytest.mark.parametrize("given, find, fragments", [
    ("J: 1e-3 kg m^2\n  spin: 100 rad/s\n  moment: 1e-4 N m\n  I: -1e-3 kg m^2",
     "nutation_frequency", ["given.I", "expected I > 0 kg m^2"]),
    ("J: -1e-3 kg m^2\n  spin: 100 rad/s\n  moment: 1e-4 N m", "drift_rate",
     ["given.J", "expected J > 0 kg m^2"]),
    ("J: 1e-3 kg m^2\n  spin: 0 rad/s\n  moment: 1e-4 N m", "drift_rate",
     ["given.spin", "must spin"]),
    ("J: 1e-3 kg m^2\n  spin: 100 rad/s\n  moment: 1e-4 N m\n  drift_rate: 1 deg/h",
     "drift_rate", ["given.drift_rate", "not moment and drift_rate"]),
    ("J: 1e-3 kg m^2\n  spin: 100 rad/s\n  drift_rate: -1 deg/h", "moment",
     ["given.drift_rate", "expected drift_rate >= 0 rad/s", "magnitude"]),
    ("J: 1e-3 kg m^2\n  spin: 100 rad/s\n  moment: 1e-4 N m", "nutation_frequency",
     ["given.I", "transverse inertia"]),
    ("J: 1e-3 kg m^2\n  spin: 100 rad/s\n  moment: 1e-4 N m", "drift_angle",
     ["given.duration"]),
    ("J: 1e-3 kg m^2\n  spin: 100 rad/s\n  moment: 1e-4 N m\n  I_x: 1e-3 kg m^2",
     "nutation_frequency", ["given.I_y", "both"]),
    ("spin: 100 rad/s\n  moment: 1e-4 N m", "drift_rate", ["given.J"]),
    ("angular_momentum: 1 kg m^2/s\n  spin: 100 rad/s\n  moment: 1e-4 N m", "drift_rate",
     ["given.spin", "not both"]),
    ("J: 1e-3 kg m^2\n  spin: 100 rad/s\n  moment: 3 m", "drift_rate",
     ["given.moment", "a moment"]),
])
def test_bad_input(run, write, given, find, fragments):
    path = write(f"id: x\nkind: gyro_drift\ngiven:\n  {given}\nfind: [{find}]\n")
    one_line(run("solve", path), str(path), *fragments)


def test_large_nutation_warns(run, write):
    out = solve_json(run, write("""
        id: w
        kind: gyro_drift
        given: {angular_momentum: 0.01 kg m^2/s, moment: 0.01 N m, I: 0.01 kg m^2}
        find: [nutation_amplitude]
        """))
    assert any("small angles" in w for w in out["warnings"])
