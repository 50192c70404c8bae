"""Pictures that never mislead: steady tops drawn steady, true angles on widened
bands, hemispheres told apart, rates in the file's unit, no empty frames.

Each expectation is geometry worked by hand (sin and theta/90 deg radii, the
chapter's steady-precession root of 11/3), not plot.py's own formulas.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from gyro_cli.physics.simulate import Params, simulate
from gyro_cli.render import plot

BODY = dict(I=1.776e-4, J=3.869e-5, mgl=0.03178)   # the 11/3 top, SI
RPM = 2 * math.pi / 60


def _sim(theta0_deg, spin, precession0=0.0, t_end=0.5, samples=3001):
    p = Params(theta0=math.radians(theta0_deg), spin=spin, precession0=precession0, **BODY)
    return simulate(p, p, t_end=t_end, samples=samples)


def _slow_root(theta, spin):
    # (J - I) cos(theta) x^2 + J spin x - m g l = 0, the slow root worked by hand
    a = (BODY["J"] - BODY["I"]) * math.cos(theta)
    b = BODY["J"] * spin
    c = -BODY["mgl"]
    return (-b + math.sqrt(b * b - 4 * a * c)) / (2 * a)


def _lines(fig, gid):
    return [ln for ln in fig.axes[0].get_lines() if ln.get_gid() == gid]


def test_steady_precession_is_one_circle_not_exaggerated_noise():
    theta = math.radians(30)
    rate = _slow_root(theta, 188.5)
    sim = _sim(30, 188.5, precession0=rate)
    data = plot.from_simulation(sim)
    assert data.theta_max - data.theta_min < 1e-8           # only integration noise
    assert plot.is_steady(data) and plot.radial_exaggeration(data) == 1.0
    fig = plot.figure(data)
    circles = _lines(fig, "theta circle")
    assert len(circles) == 1 and "steady" in circles[0].get_label()
    assert "30 deg" in circles[0].get_label()
    assert "widened" not in fig.axes[0].get_title()


def test_narrow_band_is_widened_with_true_angles_and_no_false_ticks():
    sim = _sim(30, 188.5 * 6, t_end=0.05)        # a fast top: a narrow nutation band
    data = plot.from_simulation(sim)
    k = plot.radial_exaggeration(data)
    assert k > 1.0
    fig = plot.figure(data)
    ax = fig.axes[0]
    assert list(ax.get_xticks()) == [] and list(ax.get_yticks()) == []
    labels = [t.get_text() for t in ax.texts if t.get_gid() == "true theta"]
    assert labels == [f"{math.degrees(data.theta_min):.6g} deg",
                      f"{math.degrees(data.theta_max):.6g} deg"]


def test_path_below_the_horizontal_has_its_own_colour_and_circles_keep_order():
    sim = _sim(80, 60.0, t_end=0.6)               # slow spin: the axis falls past 90 deg
    data = plot.from_simulation(sim)
    assert data.theta_max > math.pi / 2 > data.theta_min
    assert plot.crosses_horizontal(data)
    fig = plot.figure(data)
    upper, = _lines(fig, "upper hemisphere")
    lower, = _lines(fig, "lower hemisphere")
    assert upper.get_color() != lower.get_color()
    assert np.ma.count(lower.get_xdata()) > 0 and np.ma.count(upper.get_xdata()) > 0
    # radius theta / 90 deg: theta_min inside the horizontal circle, theta_max outside
    r = {ln.get_label().split(" =")[0]: float(np.hypot(ln.get_xdata()[0], ln.get_ydata()[0]))
         for ln in _lines(fig, "theta circle")}
    horizontal, = _lines(fig, "horizontal")
    r90 = float(np.hypot(horizontal.get_xdata()[0], horizontal.get_ydata()[0]))
    assert r90 == pytest.approx(1.0)
    assert r["theta_min"] < r90 < r["theta_max"]
    assert r["theta_max"] == pytest.approx(math.degrees(data.theta_max) / 90)


def test_rates_are_drawn_in_the_unit_the_file_asks(tmp_path, run, problems_dir):
    pytest.importorskip("matplotlib")
    from gyro_cli.solving.solve import solve_file

    result = solve_file(str(problems_dir / "11_2_released_top.yaml"))
    unit = next(u for n, u in result.problem.find.items()
                if result.problem.kind.answer(n).dimension == "rate")
    data = plot.with_rate_unit(plot.from_simulation(_sim(30, 188.5, t_end=0.1)), result.problem)
    assert data.rate_unit == unit
    per_si = {"rpm": 60 / (2 * math.pi), "rad/s": 1.0, "deg/s": 180 / math.pi}[unit]
    assert data.rate_per_si == pytest.approx(per_si)
    fig = plot.figure(data)
    assert fig.axes[2].get_ylabel() == f"phidot ({unit})"
    drawn = fig.axes[2].get_lines()[0].get_ydata()
    assert drawn == pytest.approx(np.asarray(data.phidot) * per_si)


def test_sleeping_top_plot_is_refused_with_the_reason_after_the_answer(run, problems_dir,
                                                                       tmp_path):
    out = tmp_path / "sleep.png"
    result = run("solve", problems_dir / "11_2_sleeping_top.yaml", "--plot", out)
    assert result.exit_code == 2
    assert "sleeping" in result.stdout and "Answer" in result.stdout   # the worked answer
    assert result.stderr.count("\n") == 1 and "one point" in result.stderr
    assert not out.exists()


def test_solve_plot_onto_existing_file_prints_answer_then_refuses(run, problems_dir, tmp_path):
    out = tmp_path / "top.png"
    out.write_bytes(b"mine")
    result = run("solve", problems_dir / "11_2_released_top.yaml", "--plot", out)
    assert result.exit_code == 2
    assert "Answer" in result.stdout
    assert "exists" in result.stderr and result.stderr.count("\n") == 1
    assert out.read_bytes() == b"mine"
    forced = run("solve", problems_dir / "11_2_released_top.yaml", "--plot", out, "--force")
    assert forced.exit_code == 0 and out.read_bytes()[:4] == b"\x89PNG"


def test_gyro_kinds_columns_never_run_together(run):
    """Every key and answer row: name, two spaces at least, dimension, two spaces, text."""
    import re

    from gyro_cli import kinds

    out = run("kinds").stdout
    rows = [ln for ln in out.splitlines() if ln.startswith("    ") and "body keys" not in ln]
    from gyro_cli.core.alternatives import alternatives_of

    names = {p.name for k in kinds.names() for p in kinds.get(k).params} | \
            {a.name for k in kinds.names() for a in kinds.get(k).answers} | \
            {key for k in kinds.names()  # keys as books state them (wheel_diameter, ...)
             for key in alternatives_of({p.name: p for p in kinds.get(k).params})}
    assert len(rows) >= len(names)
    for ln in rows:
        assert re.match(r"^    \S+ {2,}\S+ {2,}\S", ln), ln
        assert ln.split()[0] in names
