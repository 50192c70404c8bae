"""`gyro simulate --animate`: frames from the simulation, GIF timing, HTML, refusals.

Independent checks: the axis drawn in a frame is compared with a separate
integration run to that frame's time, and with the elliptic-function solution
theta(t) (Eq. 11.23); the bicycle's frames with an eigen-decomposition of its
linear equations; the torque-free body's H with the invariant.
"""

from __future__ import annotations

import math
import shutil

import numpy as np
import pytest
from conftest import PROBLEMS
from PIL import Image

from gyro_cli.commands.animate import bicycle_response, build_scene, make_clock
from gyro_cli.core.errors import InputError
from gyro_cli.physics.simulate import simulate
from gyro_cli.render.animate import gif_durations, html_page, zxz


def _gif_timing(path):
    image = Image.open(path)
    durations = []
    for k in range(image.n_frames):
        image.seek(k)
        durations.append(image.info["duration"])
    return image.n_frames, sum(durations)


def test_gif_frame_count_and_duration_match_the_request(run, tmp_path):
    out = tmp_path / "top.gif"
    result = run("simulate", PROBLEMS / "11_2_released_top.yaml", "--animate", out,
                 "--periods", "1", "--fps", "20", "--speed", "1")
    assert result.exit_code == 0, result.output
    frames, total_ms = _gif_timing(out)
    # one nutation period lasts 2 s of playback at --speed 1: 40 intervals + the first frame
    assert frames == 41
    assert abs(total_ms - 1000 * frames / 20) <= 10
    assert "41 frames" in result.stdout
    faster = tmp_path / "fast.gif"
    assert run("simulate", PROBLEMS / "11_2_released_top.yaml", "--animate", faster,
               "--periods", "1", "--fps", "20", "--speed", "2").exit_code == 0
    assert _gif_timing(faster)[0] == 21


def test_gif_durations_keep_the_running_total():
    for fps in (7, 24, 30, 60):
        d = gif_durations(300, fps)
        assert all(x % 10 == 0 for x in d)
        assert abs(sum(d) - 300_000 / fps) <= 10


def test_axis_in_frames_is_the_simulations_axis_at_that_time():
    scene, sims = build_scene(str(PROBLEMS / "11_2_released_top.yaml"), periods=1.0, fps=15)
    panel = scene.panels[0]
    p = sims[0].params
    for i in (1, 7, 18, len(scene.times) - 1):
        t = float(scene.times[i])
        alone = simulate(p, p, t, samples=2)          # a separate run that ends at t
        th, ph = alone.theta[-1], alone.phi[-1]
        k = np.array([math.sin(th) * math.sin(ph), -math.sin(th) * math.cos(ph), math.cos(th)])
        assert np.max(np.abs(panel.axis[i] - k)) < 1e-6, (i, panel.axis[i], k)


def test_theta_in_frames_follows_the_elliptic_solution():
    from gyro_cli.physics.motion import theta_of_t
    from gyro_cli.physics.nutation import Start, Top

    scene, sims = build_scene(str(PROBLEMS / "11_2_released_top.yaml"), periods=1.0, fps=15)
    p = sims[0].params
    theta_drawn = np.arccos(np.clip(scene.panels[0].axis[:, 2], -1, 1))
    exact = theta_of_t(Top(I=p.I, J=p.J, mgl=p.mgl), Start(theta0=p.theta0, spin=p.spin),
                       scene.times)
    assert np.max(np.abs(theta_drawn - exact)) < 1e-6


def test_pose_matrices_are_rotations_with_the_chapters_axis():
    R = zxz([0.3, 1.0], [0.5, 2.0], [0.7, -1.0])
    for M, phi, th in zip(R, (0.3, 1.0), (0.5, 2.0)):
        assert np.allclose(M @ M.T, np.eye(3), atol=1e-14)
        assert math.isclose(np.linalg.det(M), 1.0, rel_tol=1e-14)
        assert np.allclose(M[:, 2], [math.sin(th) * math.sin(phi), -math.sin(th) *
                                     math.cos(phi), math.cos(th)])


def test_steady_precession_shows_both_roots_with_theta_constant():
    scene, sims = build_scene(str(PROBLEMS / "11_3.yaml"), periods=0.5, fps=10)
    assert len(scene.panels) == 2
    assert "slow" in scene.panels[0].title and "fast" in scene.panels[1].title
    for panel in scene.panels:
        theta = np.arccos(np.clip(panel.axis[:, 2], -1, 1))
        assert np.ptp(theta) < 1e-8
        assert math.isclose(theta[0], math.radians(30), rel_tol=1e-12)


def test_torque_free_keeps_theta_and_the_momentum_vertical():
    scene, sims = build_scene(str(PROBLEMS / "torque_free_football.yaml"), periods=1, fps=10)
    sim = sims[0]
    p = sim.params
    assert p.mgl == 0.0
    theta = np.arccos(np.clip(scene.panels[0].axis[:, 2], -1, 1))
    assert np.ptp(theta) < 1e-8
    # H = I omega_perp + J omega_z k stays vertical: its horizontal part is zero
    k = scene.panels[0].axis
    omega = scene.panels[0].arrows[0].tips
    omega_z = np.sum(omega * k, axis=1)[:, None] * k
    H = p.I * (omega - omega_z) + p.J * omega_z
    assert np.max(np.hypot(H[:, 0], H[:, 1])) < 1e-9 * np.max(np.abs(H[:, 2]))


def test_bicycle_frames_follow_the_eigenvector_solution():
    from gyro_cli.physics import bicycle as bike

    m = bike.matrices(bike.BENCHMARK)
    g, v = 9.81, 5.0
    t = np.linspace(0, 15, 301)
    x = bicycle_response(m, v, g, t, lean_rate0=0.5)
    M = np.array(m.M)
    K = g * np.array(m.K0) + v * v * np.array(m.K2)
    C = v * np.array(m.C1)
    A = np.block([[np.zeros((2, 2)), np.eye(2)], [-np.linalg.solve(M, K), -np.linalg.solve(M, C)]])
    w, V = np.linalg.eig(A)
    c = np.linalg.solve(V, np.array([0, 0, 0.5, 0]))
    exact = np.real((V[None, :, :] * np.exp(np.outer(t, w))[:, None, :]) @ c)
    assert np.max(np.abs(x - exact)) < 1e-9
    # 5 m/s lies in the benchmark's self-stable range (4.29-6.02 m/s): the lean dies away
    assert abs(x[-1, 0]) < 0.1 * np.max(np.abs(x[:, 0]))


def test_bicycle_inside_and_outside_the_self_stable_range():
    scene, _ = build_scene(str(PROBLEMS / "bicycle_benchmark.yaml"), periods=1, fps=10)
    titles = [p.title for p in scene.panels]
    assert "self-stable" in titles[0] and "not self-stable" in titles[1]


@pytest.mark.parametrize("name", ["11_5.yaml", "11_6.yaml", "rolling_hoop_stable.yaml",
                                  "11_2_released_top_loops.yaml", "torque_free_plate.yaml"])
def test_every_moving_kind_draws(name, tmp_path, run):
    out = tmp_path / "a.gif"
    result = run("simulate", PROBLEMS / name, "--animate", out, "--periods", "0.5",
                 "--fps", "8")
    assert result.exit_code == 0, result.output
    assert Image.open(out).n_frames >= 2


def test_html_is_one_page_with_no_outside_request(tmp_path, run):
    out = tmp_path / "a.html"
    assert run("simulate", PROBLEMS / "11_2_released_top.yaml", "--animate", out,
               "--periods", "0.5", "--fps", "10").exit_code == 0
    page = out.read_text()
    assert page.startswith("<!DOCTYPE html>") and "<canvas" in page
    for outside in ("http://", "https://", "src=\"//", "@import"):
        assert outside not in page


def test_title_cannot_break_out_of_the_page(tmp_path):
    scene, _ = build_scene(str(PROBLEMS / "11_2_released_top.yaml"), periods=0.2, fps=5)
    scene.title = "</script><script>alert(1)</script>"
    page = html_page(scene)
    assert "<script>alert(1)" not in page


def test_long_requests_are_refused_before_they_start(run, tmp_path):
    out = tmp_path / "a.gif"
    result = run("simulate", PROBLEMS / "11_2_released_top.yaml", "--animate", out,
                 "--periods", "10000")
    assert result.exit_code == 2
    assert "frames" in result.stderr and "to render" in result.stderr
    assert not out.exists()
    with pytest.raises(InputError, match="--speed"):
        make_clock(1.0, "periods", 1.0, 0.0, 30)


def test_bad_outputs_and_kinds_are_one_line(run, tmp_path, write):
    bad = run("simulate", PROBLEMS / "11_2_released_top.yaml", "--animate", tmp_path / "a.avi")
    assert bad.exit_code == 2 and ".gif, .mp4 or .html" in bad.stderr
    still = run("simulate", PROBLEMS / "11_8.yaml", "--animate", tmp_path / "b.gif")
    assert still.exit_code == 2 and "kinds that move" in still.stderr
    existing = tmp_path / "c.gif"
    existing.write_bytes(b"mine")
    again = run("simulate", PROBLEMS / "11_2_released_top.yaml", "--animate", existing)
    assert again.exit_code == 2 and existing.read_bytes() == b"mine"
    if not shutil.which("ffmpeg"):
        mp4 = run("simulate", PROBLEMS / "11_2_released_top.yaml", "--animate",
                  tmp_path / "d.mp4")
        assert mp4.exit_code == 2 and "ffmpeg" in mp4.stderr
    for result in (bad, still, again):
        assert "Traceback" not in result.output and len(result.stderr.splitlines()) == 1


@pytest.mark.skipif(not shutil.which("ffmpeg"), reason="ffmpeg is not installed")
def test_mp4_through_ffmpeg(run, tmp_path):
    out = tmp_path / "a.mp4"
    assert run("simulate", PROBLEMS / "11_2_released_top.yaml", "--animate", out,
               "--periods", "0.3", "--fps", "10").exit_code == 0
    assert out.read_bytes()[4:8] == b"ftyp"


@pytest.mark.slow
def test_html_animation_plays_in_chromium_without_console_errors(run, tmp_path, browser):
    """(`browser`, conftest.py: the test process's Chromium; skips, saying why, without.)"""
    out = tmp_path / "a.html"
    assert run("simulate", PROBLEMS / "11_3.yaml", "--animate", out, "--periods", "0.3",
               "--fps", "10").exit_code == 0
    errors: list[str] = []
    page = browser.new_page()
    try:
        page.on("console", lambda m: errors.append(m.text) if m.type == "error" else None)
        page.on("pageerror", lambda e: errors.append(str(e)))
        page.goto(out.as_uri())
        page.wait_for_timeout(400)
        drawn = page.evaluate("""() => { const c = document.querySelector('canvas');
            const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
            let ink = 0; for (let i = 0; i < d.length; i += 4) if (d[i] < 200) ink++;
            return ink; }""")
    finally:
        page.close()
    assert errors == []
    assert drawn > 1000


# ---- the rolling disk's integration (physics/rolling_motion.py) ----------------------

def _hoop():
    """problems/rolling_hoop_stable.yaml: a 0.35 m hoop at 3 m/s on a 20 m contact circle,
    tilt 5.2523 deg (worked by hand in the file's notes); per unit mass J = r^2, I_G = r^2/2."""
    from gyro_cli.physics import rolling_motion as rm

    r = 0.35
    d = rm.Disk(r, r * r, r * r / 2, 9.81)
    tilt = math.radians(5.2523)
    rho = 20.0 - r * math.sin(tilt)
    return d, tilt, rho, 3.0 / rho


def test_steady_rolling_stays_steady_when_undisturbed():
    from gyro_cli.physics import rolling_motion as rm

    d, tilt, rho, Om = _hoop()
    t = np.linspace(0, 2 * math.pi / Om / 4, 50)      # a quarter lap
    ys, drift = rm.integrate(d, rm.steady_start(d, tilt, rho, Om), t)
    # the hand-worked tilt (5 significant figures) is steady to that precision
    assert np.max(np.abs(rm.tilt_of(ys) - tilt)) < 2e-5
    assert np.max(np.abs(np.hypot(ys[:, 9], ys[:, 10]) - rho)) < 1e-3
    assert drift < 1e-9


def test_disturbed_stable_rolling_wobbles_at_the_linearised_frequency():
    from gyro_cli.physics import rolling_motion as rm
    from gyro_cli.physics.stability import disk_rolling

    d, tilt, rho, Om = _hoop()
    v = disk_rolling(1.0, d.g, d.r, d.i, d.j, tilt, Om, -Om * rho / d.r)
    assert v.word == "stable"
    T = 2 * math.pi / v.frequency
    t = np.linspace(0, 6 * T, 1201)
    ys, drift = rm.integrate(d, rm.steady_start(d, tilt, rho, Om, kick=1e-4), t)
    beta = rm.tilt_of(ys) - np.mean(rm.tilt_of(ys))
    crossings = t[1:][np.sign(beta[1:]) != np.sign(beta[:-1])]
    measured = 2 * np.mean(np.diff(crossings))
    assert abs(measured - T) < 0.01 * T
    assert drift < 1e-9


def test_disturbed_unstable_rolling_grows_at_the_linearised_rate():
    # problems/rolling_coin_upright.yaml: a quarter (r = 12.13 mm, thin disk) at 10 cm/s on a
    # 1 m circle leans 0.08761 deg; Routh's upright speed is sqrt(g r / 3) = 0.199 m/s
    from gyro_cli.kinds.rolling_disk import free_from_speed_and_path
    from gyro_cli.physics import rolling_motion as rm
    from gyro_cli.physics.stability import disk_rolling

    r = 0.01213
    d = rm.Disk(r, r * r / 2, r * r / 4, 9.81)
    (state,) = free_from_speed_and_path(1.0, d.g, r, d.j, d.i, 0.1, 1.0)
    assert abs(math.degrees(state.tilt) - 0.08761) < 1e-5
    tilt, rho, Om = state.tilt, state.centre_radius, state.precession
    v = disk_rolling(1.0, d.g, r, d.i, d.j, tilt, Om, -Om * rho / r)
    assert v.word == "unstable" and abs(v.growth_rate - 22.0) < 0.1
    t = np.linspace(0, 0.4, 401)
    ys, _ = rm.integrate(d, rm.steady_start(d, tilt, rho, Om, kick=1e-7), t)
    dev = np.abs(rm.tilt_of(ys) - tilt)
    window = (t > 0.1) & (t < 0.35)
    rate = np.polyfit(t[window], np.log(dev[window]), 1)[0]
    assert abs(rate - v.growth_rate) < 0.02 * v.growth_rate


def test_rolling_disk_animation_is_integrated():
    scene, runs = build_scene(str(PROBLEMS / "rolling_hoop_stable.yaml"), periods=1, fps=10)
    assert any("Integrated" in n for n in scene.notes)
    assert len(scene.panels) == 2      # the whole circle, and a close view of the hoop


def test_solve_html_embeds_the_animation_only_where_the_kind_moves(run, tmp_path):
    """--animate with --format html: a canvas in the released top's article, none in a
    kind that does not move, and the page allows exactly the embedded players' scripts."""
    import base64
    import hashlib
    import re

    out = run("solve", "--format", "html", "--animate", PROBLEMS / "11_2_released_top.yaml",
              PROBLEMS / "gyrocompass_disc.yaml")
    assert out.exit_code == 0, out.output
    page = out.output
    assert page.count("<canvas") == 1
    scripts = [s for s in re.findall(r"<script>(.*?)</script>", page, re.S)]
    assert len(scripts) == 1
    digest = base64.b64encode(hashlib.sha256(scripts[0].encode()).digest()).decode()
    assert f"script-src 'sha256-{digest}'" in page
    refused = run("solve", "--format", "text", "--animate", PROBLEMS / "11_3.yaml")
    assert refused.exit_code == 2 and "--format html" in refused.output
