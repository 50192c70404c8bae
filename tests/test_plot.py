"""Pictures of the motion (plot.py): the files, and the data behind them.

The data are checked against the chapter's geometry, not against plot.py's own
formulas: cusps (phidot = 0, Eq. 11.26) lie on the theta_min circle, loops turn
back inside the band, waves never stop; the projection by hand at known angles.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from gyro_cli.core.errors import InputError
from gyro_cli.physics.simulate import Params, simulate
from gyro_cli.render import plot

BODY = dict(I=1.776e-4, J=3.869e-5, mgl=0.03178)


def sim_of(theta0_deg: float, spin: float, precession0: float = 0.0, t_end: float = 1.0,
           samples: int = 4001):
    p = Params(theta0=math.radians(theta0_deg), spin=spin, precession0=precession0, **BODY)
    return simulate(p, p, t_end=t_end, samples=samples)


@pytest.fixture(scope="module")
def cusps():
    return sim_of(30, 188.5)


@pytest.fixture(scope="module")
def loops():
    return sim_of(60, 150.0, precession0=-3.0)


@pytest.fixture(scope="module")
def waves():
    return sim_of(45, 150.0, precession0=3.0)


def test_projection_by_hand():
    x, y = plot.path_xy(np.radians([90.0, 30.0, 150.0]), np.radians([0.0, 90.0, 180.0]))
    assert x == pytest.approx([1.0, 0.0, -0.5], abs=1e-15)
    assert y == pytest.approx([0.0, 0.5, 0.0], abs=1e-15)
    cx, cy = plot.circle_xy(math.radians(30))
    assert np.hypot(cx, cy) == pytest.approx(0.5)


def test_cusps_lie_on_the_theta_min_circle(cusps):
    """Released top: phidot = 0 exactly where u = u2, theta = theta_min (Eq. 11.26), once per
    nutation period; the marked points sit on the theta_min circle of the picture."""
    data = plot.from_simulation(cusps)
    marks = plot.stationary_points(data)
    x, y = plot.path_xy(data.theta, data.phi)
    radius = np.hypot(x[marks], y[marks])
    assert radius == pytest.approx(math.sin(data.theta_min), abs=2e-5)
    # the release point (t = 0) and one cusp per nutation period after it
    periods = data.t[-1] / cusps.nutation_period
    assert len(marks) == int(periods) + 1
    # a cusp: phidot touches zero without changing sign
    assert np.all(data.phidot > -1e-9 * np.max(data.phidot))


def test_loops_turn_back_inside_the_band(loops):
    """Loops: phidot changes sign twice per nutation period, near theta_min, never at the
    circles themselves."""
    data = plot.from_simulation(loops)
    marks = plot.stationary_points(data)
    periods = data.t[-1] / loops.nutation_period
    assert abs(len(marks) - 2 * periods) <= 2
    theta = data.theta[marks]
    assert np.all(theta > data.theta_min + 1e-3) and np.all(theta < data.theta_max - 1e-3)
    assert np.any(data.phidot < 0) and np.any(data.phidot > 0)


def test_waves_never_stop(waves):
    data = plot.from_simulation(waves)
    assert len(plot.stationary_points(data)) == 0
    assert np.all(data.phidot > 0)


def test_radial_exaggeration_only_for_narrow_bands():
    wide = plot.PathData(np.zeros(2), np.zeros(2), np.zeros(2), np.zeros(2),
                         math.radians(30), math.radians(60))
    narrow = plot.PathData(np.zeros(2), np.zeros(2), np.zeros(2), np.zeros(2),
                           math.radians(45), math.radians(45.3))
    assert plot.radial_exaggeration(wide) == 1.0
    k = plot.radial_exaggeration(narrow)
    r1, r2 = math.sin(narrow.theta_min), math.sin(narrow.theta_max)
    assert k * (r2 - r1) == pytest.approx(0.3 * (r1 + r2) / 2)


@pytest.mark.parametrize("suffix,magic", [(".png", b"\x89PNG"), (".svg", b"<?xml"),
                                          (".pdf", b"%PDF")])
def test_files_are_written_atomically_and_not_clobbered(tmp_path, cusps, suffix, magic,
                                                       monkeypatch):
    real, drawn = plot.render, []

    def once(data, fmt):  # the figure drawn once, for the first save and the forced one
        if not drawn:
            drawn.append(real(data, fmt))
        return drawn[0]

    monkeypatch.setattr(plot, "render", once)
    data = plot.from_simulation(cusps, title="cusps", motion="cusps")
    target = tmp_path / f"top{suffix}"
    plot.save(data, str(target))
    content = target.read_bytes()
    assert content.startswith(magic) and len(content) > 1000
    with pytest.raises(InputError, match="exists"):
        plot.save(data, str(target))
    assert target.read_bytes() == content
    plot.save(data, str(target), force=True)
    assert [p.name for p in tmp_path.iterdir()] == [target.name]     # no temp file left


def test_item01_a_plot_over_an_existing_file_is_refused_before_it_is_drawn(tmp_path, cusps,
                                                                          monkeypatch):
    """Without --force the refusal comes before matplotlib draws (a second or more), and a
    special file is refused as such, not as existing."""
    def never(data, fmt):
        raise AssertionError("drawn for a file that will not be written")

    monkeypatch.setattr(plot, "render", never)
    data = plot.from_simulation(cusps, title="cusps", motion="cusps")
    target = tmp_path / "top.png"
    target.write_bytes(b"mine")
    with pytest.raises(InputError, match="exists"):
        plot.save(data, str(target))
    assert target.read_bytes() == b"mine"
    (tmp_path / "folder.png").mkdir()
    with pytest.raises(InputError, match="directory"):
        plot.save(data, str(tmp_path / "folder.png"), force=True)


def test_unknown_plot_format_is_refused(tmp_path, cusps):
    with pytest.raises(InputError, match="png"):
        plot.save(plot.from_simulation(cusps), str(tmp_path / "top.jpg"))


def test_gyro_simulate_plot_and_csv(run, problems_dir, tmp_path):
    """Through the CLI: both files written; the CSV holds the steady top's series (theta
    constant, phi growing at the slow root of problem 11/3, 45.13 rpm by hand)."""
    png, csv = tmp_path / "p.png", tmp_path / "p.csv"
    result = run("simulate", problems_dir / "11_3.yaml", "--periods", "2", "--plot", png,
                 "--csv", csv)
    assert result.exit_code == 0, result.output
    assert png.read_bytes().startswith(b"\x89PNG")
    table = np.loadtxt(csv, delimiter=",", skiprows=1)
    header = csv.read_text().splitlines()[0].split(",")
    assert header[:3] == ["t_s", "theta_rad", "phi_rad"] and table.shape[1] == 7
    t, theta, phi = table[:, 0], table[:, 1], table[:, 2]
    assert np.max(np.abs(theta - math.radians(30))) < 1e-9
    slope = np.polyfit(t, phi, 1)[0]
    assert slope * 60 / (2 * math.pi) == pytest.approx(45.13, rel=1e-3)
    again = run("simulate", problems_dir / "11_3.yaml", "--periods", "1", "--plot", png)
    assert again.exit_code == 2 and "exists" in again.stderr
    assert len(again.stderr.strip().splitlines()) == 1


def test_gyro_solve_plot_refuses_other_kinds(run, problems_dir, tmp_path):
    result = run("solve", problems_dir / "11_3.yaml", "--plot", tmp_path / "x.png")
    assert result.exit_code == 2
    assert "released_top and bicycle only" in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1
    assert not (tmp_path / "x.png").exists()


def test_analytic_path_has_its_cusps_on_the_theta_min_circle():
    """gyro solve --plot draws the analytic motion: exact theta(t), phi from Eq. 11.16. Its
    phidot = 0 points lie on the theta_min circle, and the path agrees with the integration."""
    import gyro_cli.physics.nutation as nutation

    top = nutation.Top(I=BODY["I"], J=BODY["J"], mgl=BODY["mgl"])
    start = nutation.Start(theta0=math.radians(30), spin=188.5)
    data = plot.from_analysis(top, start, periods=3, samples_per_period=600)
    assert data.source.startswith("analytic")
    marks = plot.stationary_points(data)
    x, y = plot.path_xy(data.theta, data.phi)
    assert np.hypot(x[marks], y[marks]) == pytest.approx(math.sin(math.radians(30)), abs=2e-5)
    assert len(marks) == 4                               # t = 0 and one per period
    p = Params(theta0=math.radians(30), spin=188.5, **BODY)
    sim = simulate(p, p, t_end=data.t[-1], samples=len(data.t))
    assert np.max(np.abs(sim.theta - data.theta)) < 1e-8
    assert np.max(np.abs(sim.phi - data.phi)) < 1e-6


def test_gyro_solve_plot_takes_one_file(run, problems_dir, tmp_path):
    result = run("solve", problems_dir / "11_3.yaml", problems_dir / "11_1.yaml", "--plot",
                 tmp_path / "x.png")
    assert result.exit_code == 2 and "one FILE" in result.stderr
    assert not (tmp_path / "x.png").exists()
