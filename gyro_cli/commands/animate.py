"""``gyro simulate FILE --animate OUT``: a scene of the motion, built from a simulation.

Tops (``released_top``, ``steady_precession``, ``torque_free``) are integrated
with the full equations of motion (physics.simulate: Euler's equations and a
quaternion attitude), and each frame is the integrator's state at that time,
not a re-drawn analytic curve. The bicycle's lean and steer after a sideways
push come from its linear equations of motion, advanced exactly by the matrix
exponential. A rotor on a turning base (``gyroscopic_torque``) and a disk
rolling on a circle (``rolling_disk``) move steadily by the kind's own
solution: those frames are the steady motion's kinematics, and the scene says so.

The playback speed makes one period of the motion (the nutation period, or a
precession revolution) last PLAYBACK_PERIOD seconds; ``--speed`` multiplies it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..core.errors import InputError
from ..core.work import num

PLAYBACK_PERIOD = 2.0      # playback seconds per period of the motion at --speed 1
DEFAULT_PERIODS = 3.0
MAX_FRAMES = 3600          # two minutes at 30 frames/s
MS_PER_PANEL_FRAME = 10.0  # measured render cost of one panel frame (benchmarks/bench_animate.py)
RPM = 2 * math.pi / 60


@dataclass
class Clock:
    """Which simulated times the frames show."""

    period: float            # simulated seconds of one period of the motion
    meaning: str
    frames: int
    fps: float
    scale: float             # simulated seconds per playback second

    @property
    def times(self) -> np.ndarray:
        return np.arange(self.frames) * (self.scale / self.fps)


def make_clock(period: float, meaning: str, periods: float, speed: float, fps: float,
               panels: int = 1) -> Clock:
    """Frames for ``periods`` periods at ``fps``; refused before any work if too long."""
    if not (math.isfinite(speed) and speed > 0):
        raise InputError("--speed must be a positive number (1 = one period in "
                         f"{PLAYBACK_PERIOD:g} s of playback)")
    if not (math.isfinite(fps) and 1 <= fps <= 60):
        raise InputError("--fps must lie between 1 and 60")
    scale = period * speed / PLAYBACK_PERIOD
    frames = int(round(periods * period / scale * fps)) + 1
    if frames > MAX_FRAMES:
        seconds = frames * panels * MS_PER_PANEL_FRAME / 1000
        raise InputError(f"this animation needs {frames:,} frames ({frames / fps:.0f} s of "
                         f"playback, about {seconds:.0f} s to render); at most {MAX_FRAMES:,}: "
                         "animate fewer --periods or raise --speed")
    if frames < 2:
        raise InputError("--periods is too short for two frames")
    return Clock(period, meaning, frames, fps, scale)


# ---- tops: integrated ------------------------------------------------------------

def _integrate(params, clock: Clock):
    """The integrator's states at the frame times (samples = frames)."""
    from ..physics.simulate import simulate

    t_end = float(clock.times[-1])
    try:
        return simulate(params, params, t_end, samples=clock.frames)
    except (ValueError, RuntimeError) as err:
        raise InputError(f"cannot simulate: {err}") from None


def _pose(sim) -> tuple[np.ndarray, np.ndarray]:
    """Rotation matrices and symmetry axes of the integrated top at its samples."""
    from ..render.animate import zxz

    R = zxz(sim.phi, sim.theta, sim.psi)
    return R, R[:, :, 2].copy()


def _top_solid(body, I_cg: float | None, pivot: bool):
    """The body as a uniform cylinder of its m, J, I_G (a rod to the pivot for a top)."""
    from ..render.animate import Solid, cylinder, equivalent_cylinder

    l = body.l if pivot else 0.0
    r, h = equivalent_cylinder(None if body.per_kg else body.mass, body.J, I_cg,
                               0.6 * l if l else 0.05)
    z0, z1 = l - h / 2, l + h / 2
    disk = cylinder(r, z0, z1)
    if not pivot or z0 <= 0:
        return disk, max(abs(z0), abs(z1), r), r, h
    rod = cylinder(0.06 * r, 0.0, z0, n=8, stripe=False, colour="rod")
    offset = len(disk.vertices)
    faces = disk.faces + [(tuple(i + offset for i in idx), c) for idx, c in rod.faces]
    solid = Solid(np.vstack([disk.vertices, rod.vertices]), faces, convex=False)
    return solid, math.hypot(z1, r), r, h


def _top_panel(title: str, sim, body, I_cg, pivot: bool = True):
    from ..render.animate import Actor, Panel

    R, axis = _pose(sim)
    solid, reach, r, h = _top_solid(body, I_cg, pivot)
    # a top's axis is traced where it leaves the body; a free body's on a sphere around it
    radius = body.l + h / 2 if pivot and body.l + h / 2 > 0 else 1.15 * reach
    actor = Actor(solid, R, np.zeros((len(R), 3)))
    labels = [[f"theta = {math.degrees(th):.2f} deg"] for th in sim.theta]
    return Panel(title, [actor], axis, radius=radius, extent=1.2 * max(reach, radius),
                 labels=labels)


def _released(problem, result, periods, speed, fps):
    from .simulate import prepare

    setup = prepare(problem.file)
    body = problem.given.body
    clock = make_clock(setup.period, setup.period_meaning, periods, speed, fps)
    sim = _integrate(setup.params, clock)
    motion = setup.analytic.get("motion", "")
    panel = _top_panel(f"released top: {motion}", sim, body, body.I_cg)
    notes = [f"Integrated (Euler's equations, quaternion attitude); one {clock.meaning[:-1]} "
             f"of {num(clock.period)} s lasts {PLAYBACK_PERIOD * 1 / speed:g} s of playback.",
             "The red curve is the path of the symmetry axis on the sphere (Figs. 11-7 to "
             "11-10)."]
    return [panel], clock, notes, [sim]


def _steady(problem, result, periods, speed, fps):
    from ..physics.simulate import Params

    given, body = problem.given, problem.given.body
    answers = result.solution.answers
    if "moment" in given or body.I_pivot is None or "precession" not in answers \
            or "spin" not in answers:
        raise InputError("animating a steady precession integrates gravity's torque: give the "
                         "body's transverse inertia, cg_distance and a spin (no applied moment)",
                         file=problem.file)
    pairs = sorted(zip(answers["precession"].si_values, answers["spin"].si_values),
                   key=lambda pair: abs(pair[0]))
    slow = pairs[0][0]
    clock = make_clock(2 * math.pi / abs(slow), "slow precession revolutions", periods, speed,
                       fps, panels=len(pairs))
    panels, sims = [], []
    for (precession, spin), name in zip(pairs, ("slow root", "fast root")):
        params = Params(body.I_pivot, body.J, body.mgl, given["theta"], spin, precession, 0.0)
        sim = _integrate(params, clock)
        sims.append(sim)
        label = name if len(pairs) > 1 else "steady precession"
        panels.append(_top_panel(f"{label}: phidot = {num(precession / RPM)} rpm", sim, body,
                                 body.I_cg))
    notes = ["Both steady precessions of Eq. 11.13, integrated side by side from their "
             "steady starting rates: theta stays constant in each."]
    return panels, clock, notes, sims


def _torque_free(problem, result, periods, speed, fps):
    from ..physics.simulate import Params
    from ..render.animate import Arrow

    body = problem.given.body
    a = {k: v.si_values[0] for k, v in result.solution.answers.items()
         if v.si_values and not isinstance(v.si_values[0], str)}
    I = body.I_cg if body.I_cg is not None else body.I_pivot
    if I is None or body.J is None or not {"precession", "spin", "nutation_angle"} <= set(a):
        raise InputError("animating a torque-free body needs its inertias and the motion: ask "
                         "for precession, spin and nutation_angle", file=problem.file)
    clock = make_clock(2 * math.pi / abs(a["precession"]), "precession revolutions", periods,
                       speed, fps)
    params = Params(I, body.J, 0.0, a["nutation_angle"], a["spin"], a["precession"], 0.0)
    sim = _integrate(params, clock)
    panel = _top_panel("torque-free: H vertical", sim, body, I, pivot=False)
    R = _pose(sim)[0]
    omega = _space_omega(sim)
    size = panel.radius / max(np.max(np.linalg.norm(omega, axis=1)), 1e-300)
    panel.arrows = [Arrow("omega", omega * size, "omega"),
                    Arrow("H", np.tile([0.0, 0.0, 1.1 * panel.radius], (len(R), 1)), "H")]
    panel.lines = [(omega * size, "omega")]
    notes = ["Integrated with no applied moment. The red curve (the axis) and the green one "
             "(omega) are the bases of the body and space cones rolling on each other; H stays "
             "vertical."]
    return [panel], clock, notes, [sim]


def _space_omega(sim) -> np.ndarray:
    """omega = phidot K + thetadot n + psidot k in fixed axes (Eqs. 11.5-11.8)."""
    n = np.column_stack([np.cos(sim.phi), np.sin(sim.phi), np.zeros_like(sim.phi)])
    k = np.column_stack([np.sin(sim.theta) * np.sin(sim.phi),
                         -np.sin(sim.theta) * np.cos(sim.phi), np.cos(sim.theta)])
    K = np.array([0.0, 0.0, 1.0])
    return sim.phidot[:, None] * K + sim.theta_rate[:, None] * n + sim.psidot[:, None] * k


# ---- steady kinematics: rotor on a turning base, rolling disk ----------------------

def _turning_rotor(problem, result, periods, speed, fps):
    from ..render.animate import Actor, Arrow, Panel, Solid, cylinder, equivalent_cylinder, zxz

    given, body = problem.given, problem.given.body
    answers = result.solution.answers
    precession = answers["precession"].si_values[0] if "precession" in answers else \
        given.get("precession")
    spin = given.get("spin")
    if not precession or not spin or body.J is None:
        raise InputError("animating a rotor on a turning base needs spin, precession (or a "
                         "turn) and the rotor's axial inertia", file=problem.file)
    theta = given.get("theta", math.pi / 2)
    clock = make_clock(2 * math.pi / abs(precession), "turns of the base", periods, speed, fps)
    t = clock.times
    R = zxz(precession * t, np.full_like(t, theta), spin * t)
    r, h = equivalent_cylinder(body.mass, body.J, body.I_cg, 0.05)
    rotor = cylinder(r, -h / 2, h / 2)
    axle = cylinder(0.05 * r, -1.6 * r, 1.6 * r, n=8, stripe=False, colour="rod")
    off = len(rotor.vertices)
    solid = Solid(np.vstack([rotor.vertices, axle.vertices]),
                  rotor.faces + [(tuple(i + off for i in idx), c) for idx, c in axle.faces],
                  convex=False)
    axis = R[:, :, 2].copy()
    H = axis * (1.5 * r * math.copysign(1.0, spin))
    M = np.cross(np.array([0.0, 0.0, precession]), axis * spin)
    M *= 1.5 * r / max(float(np.linalg.norm(M[0])), 1e-300)
    panel = Panel("rotor on a turning base", [Actor(solid, R, np.zeros((len(t), 3)))], axis,
                  radius=1.6 * r, extent=2.0 * r,
                  arrows=[Arrow("H", H, "H"), Arrow("M", M, "omega")])
    notes = ["Steady motion as solved (spin about the axle, the base turning about the "
             "vertical): kinematics of the answer, not an integration. M = Omega x H is the "
             "moment the frame must apply (Eq. 11.29)."]
    return [panel], clock, notes, []


def _rolling(problem, result, periods, speed, fps):
    from ..render.animate import Actor, Panel, cylinder, zxz

    given, body = problem.given, problem.given.body
    a = result.solution.answers
    r = body.radius
    if r is None or "precession" not in a and "precession" not in given:
        raise InputError("animating a rolling disk needs its radius and the steady motion",
                         file=problem.file)
    disk = cylinder(r, -0.04 * r, 0.04 * r)     # the body's own radius (disk or hoop)
    if given.word("arrangement", "free") != "axle_pivot":
        return _rolling_free(problem, result, periods, speed, fps, disk)
    precession, centre = given["precession"], given["path_radius"]
    spin = a["spin"].si_values[0] if "spin" in a else -precession * centre / r
    clock = make_clock(2 * math.pi / abs(precession), "laps", periods, speed, fps)
    t = clock.times
    phi = precession * t
    R = zxz(phi, np.full_like(t, math.pi / 2), spin * t)
    position = np.column_stack([centre * np.sin(phi), -centre * np.cos(phi),
                                np.full_like(t, r)])
    panel = Panel("disk on an axle pinned to the shaft", [Actor(disk, R, position)], None,
                  radius=centre + r, extent=1.1 * (centre + 2 * r), sphere=False,
                  lines=[(_circle(centre), "frame")])
    notes = ["The axle pinned to the shaft allows one motion, turning with the shaft: drawn "
             "from the answer's rates (kinematics, not an integration)."]
    return [panel], clock, notes, []


def _circle(radius: float, z: float = 0.0) -> np.ndarray:
    a = np.linspace(0, 2 * math.pi, 121)
    return np.column_stack([radius * np.cos(a), radius * np.sin(a), np.full_like(a, z)])


KICK = 0.02                # the disturbance: a tilt rate of KICK sqrt(g / r)


def _rolling_free(problem, result, periods, speed, fps, disk):
    """The free disk integrated (physics.rolling_motion) from its steady rolling, disturbed."""
    from ..physics import rolling_motion as rm
    from ..physics.stability import disk_rolling
    from ..render.animate import Actor, Panel

    body, a = problem.given.body, result.solution.answers
    m, g, r, J, I = body.mass_for_rates, body.g, body.radius, body.J, body.I_cg
    tilt, precession = a["tilt"].si_values[0], a["precession"].si_values[0]
    rho = a["path_radius"].si_values[0] - r * math.sin(tilt)
    lap = 2 * math.pi / abs(precession)
    verdict = disk_rolling(m, g, r, I, J, tilt, precession, -precession * rho / r)
    if verdict.growth_rate > 0:
        period, meaning = min(lap, 3 / verdict.growth_rate), "growth times (x 3)"
    elif verdict.frequency > 0:
        period, meaning = min(lap, 2 * math.pi / verdict.frequency), "wobble periods"
    else:
        period, meaning = lap, "laps"
    clock = make_clock(period, meaning, periods, speed, fps)
    d = rm.Disk(r, J / m, I / m, g)
    kick = KICK * math.sqrt(g / r)
    try:
        ys, drift = rm.integrate(d, rm.steady_start(d, tilt, rho, precession, kick),
                                 clock.times)
    except RuntimeError as err:
        raise InputError(f"cannot simulate the rolling disk: {err}") from None
    k, e = ys[:, 0:3], ys[:, 3:6]
    k = k / np.linalg.norm(k, axis=1)[:, None]
    e = e - np.sum(e * k, axis=1)[:, None] * k
    e = e / np.linalg.norm(e, axis=1)[:, None]
    R = np.stack([e, np.cross(k, e), k], axis=2)
    beta = rm.tilt_of(ys)
    position = np.column_stack([ys[:, 9], ys[:, 10], r * np.cos(beta)])
    labels = [[f"tilt {math.degrees(b):.2f} deg"] for b in beta]
    contact = rho + r * math.sin(tilt)
    panels = [Panel("disk rolling on a circle", [Actor(disk, R, position)], None,
                    radius=contact, extent=1.1 * (contact + 2 * r), sphere=False,
                    vertical=False, lines=[(_circle(contact), "frame")], labels=labels)]
    if rho > 4 * r:      # the disk is small beside its circle: follow it too
        here = np.column_stack([np.zeros_like(beta), np.zeros_like(beta), position[:, 2] - r])
        panels.append(Panel("close up, following the disk", [Actor(disk, R, here)], None,
                            radius=r, extent=1.6 * r, sphere=False, vertical=False,
                            labels=labels))
    stopped = np.flatnonzero(np.all(ys[1:] == ys[:-1], axis=1))
    fell = stopped[:1] + 1 if len(stopped) else stopped
    notes = [f"Integrated (Newton-Euler equations of the rolling disk) from the steady rolling "
             f"solved, disturbed by a tilt rate of {num(kick)} rad/s: {verdict.word} "
             f"(energy drift {drift:.1e})."]
    if len(fell):
        notes.append(f"Rolling contact ends at t = {num(float(clock.times[fell[0]]))} s (the "
                     f"tilt passes {math.degrees(rm.FLAT):.0f} deg, or the plane would have to "
                     "pull): the picture stops there.")
    return panels, clock, notes, [ys]


# ---- the bicycle: linear equations, exact steps ------------------------------------

PUSH = 0.5                 # rad/s of lean rate: the sideways push
FALLEN = math.radians(45)  # beyond this the linear model no longer describes the bicycle


def bicycle_response(m, v: float, g: float, t: np.ndarray, lean_rate0: float = PUSH):
    """Lean phi and steer delta at times t (evenly spaced) after a push giving lean_rate0.

    M q'' + v C1 q' + (g K0 + v^2 K2) q = 0 (Meijaard et al. 2007, Eq. A 1 without
    applied torques), q = (phi, delta), as x' = A x with x = (q, q'); each frame
    is the previous one times expm(A dt), the exact flow of the linear equations.
    """
    from scipy.linalg import expm

    M = np.array(m.M, float)
    K = g * np.array(m.K0, float) + v * v * np.array(m.K2, float)
    C = v * np.array(m.C1, float)
    Minv = np.linalg.inv(M)
    A = np.block([[np.zeros((2, 2)), np.eye(2)], [-Minv @ K, -Minv @ C]])
    step = expm(A * (t[1] - t[0])) if len(t) > 1 else np.eye(4)
    x = np.array([0.0, 0.0, lean_rate0, 0.0])
    out = np.empty((len(t), 4))
    for i in range(len(t)):
        out[i] = x
        x = step @ x
    return out


def _bicycle(problem, result, periods, speed, fps):
    from ..core.work import Work
    from ..physics import bicycle as bike

    given = problem.given
    p = problem.kind.model(given, Work())
    gyroscopic = given.word("gyroscopic", "true") == "true"
    m = bike.matrices(p, gyroscopic)
    stab = bike.stability(m, p["g"])
    stable = [(lo, hi) for lo, hi in stab.stable if hi > lo]
    speeds = []
    file_speed = given.get("speed")
    if stable:
        lo, hi = stable[0]
        inside = file_speed if file_speed and lo < file_speed < hi else \
            (0.5 * (lo + hi) if math.isfinite(hi) else 1.2 * lo)
        outside = file_speed if file_speed and not any(a < file_speed < b for a, b in stable) \
            else 0.6 * lo
        speeds = [(inside, "self-stable"), (outside, "not self-stable")]
    else:
        speeds = [(file_speed or 5.0, "not self-stable (no self-stable speed)")]
    # period = PLAYBACK_PERIOD: one simulated second per playback second at --speed 1
    clock = make_clock(PLAYBACK_PERIOD, "seconds", periods, speed, fps, panels=len(speeds))
    panels = []
    for v, words in speeds:
        x = bicycle_response(m, v, p["g"], clock.times)
        panels.append(_bicycle_panel(p, v, words, x, clock.times))
    notes = [f"Lean and steer after a sideways push (lean rate {PUSH} rad/s) from the linear "
             "equations of motion (Meijaard et al. 2007), stepped exactly by the matrix "
             "exponential; beyond 45 deg of lean the linear model no longer holds and the "
             "picture stops there."]
    return panels, clock, notes, []


def _bicycle_panel(p: dict, v: float, words: str, x: np.ndarray, t: np.ndarray):
    from ..render.animate import Actor, Panel, Solid, cylinder

    w, rR, rF, lam, c = p["w"], p["rR"], p["rF"], p["lambda"], p["c"]
    fallen = np.flatnonzero(np.abs(x[:, 0]) > FALLEN)
    if len(fallen):
        x = x.copy()
        x[fallen[0]:] = x[fallen[0]]
    lean, steer = x[:, 0], x[:, 1]
    n = len(t)

    def lean_matrix(angle):
        c_, s_ = math.cos(angle), math.sin(angle)
        return np.array([[1, 0, 0], [0, c_, -s_], [0, s_, c_]])

    def wheel(r):
        return cylinder(r, -0.02, 0.02, n=24, colour="tyre")

    def axis_y(solid, spin):
        c_, s_ = math.cos(spin), math.sin(spin)
        to_y = np.array([[1, 0, 0], [0, 0, 1], [0, -1, 0]])     # body z -> fixed y
        return to_y @ np.array([[c_, -s_, 0], [s_, c_, 0], [0, 0, 1]])

    def about(axis, angle):
        axis = axis / np.linalg.norm(axis)
        K = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
        return np.eye(3) + math.sin(angle) * K + (1 - math.cos(angle)) * K @ K

    steer_axis = np.array([-math.sin(lam), 0.0, math.cos(lam)])
    pivot = np.array([w + c, 0.0, 0.0])           # where the steer axis meets the ground
    R_rear, R_front, R_frame = np.empty((n, 3, 3)), np.empty((n, 3, 3)), np.empty((n, 3, 3))
    P_rear, P_front, P_frame = np.empty((n, 3)), np.empty((n, 3)), np.empty((n, 3))
    frame_dir = np.array([w, 0.0, rF - rR])
    length = float(np.linalg.norm(frame_dir))
    frame_rot = _align_z(frame_dir / length)
    for i in range(n):
        L = lean_matrix(lean[i])
        spin = v * t[i]
        R_rear[i] = L @ axis_y(None, -spin / rR)
        P_rear[i] = L @ np.array([0.0, 0.0, rR])
        S = about(steer_axis, steer[i])
        hub = pivot + S @ (np.array([w, 0.0, rF]) - pivot)
        R_front[i] = L @ S @ axis_y(None, -spin / rF)
        P_front[i] = L @ hub
        R_frame[i] = L @ frame_rot
        P_frame[i] = L @ np.array([0.0, 0.0, rR])
    frame = cylinder(0.02, 0.0, length, n=8, stripe=False, colour="frame")
    actors = [Actor(wheel(rR), R_rear, P_rear), Actor(wheel(rF), R_front, P_front),
              Actor(Solid(frame.vertices, frame.faces), R_frame, P_frame)]
    centre = np.array([0.5 * w, 0.0, 0.0])         # the view is centred on the bicycle
    for P in (P_rear, P_front, P_frame):
        P -= centre
    ground = np.array([[-0.5, 0.0, 0.0], [w + 0.5, 0.0, 0.0]]) - centre
    labels = [[f"lean {math.degrees(a):+.1f} deg, steer {math.degrees(b):+.1f} deg"]
              for a, b in zip(lean, steer)]
    return Panel(f"v = {num(v)} m/s: {words}", actors, None, radius=w, extent=0.5 * w + rF + 0.1,
                 lines=[(ground, "frame")], labels=labels, sphere=False, vertical=False)


def _align_z(direction: np.ndarray) -> np.ndarray:
    """A rotation taking body z to ``direction`` (unit)."""
    z = np.array([0.0, 0.0, 1.0])
    v = np.cross(z, direction)
    s, c = float(np.linalg.norm(v)), float(z @ direction)
    if s < 1e-12:
        return np.eye(3) if c > 0 else np.diag([1.0, -1.0, -1.0])
    K = np.array([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]]) / s
    angle = math.atan2(s, c)
    return np.eye(3) + math.sin(angle) * K + (1 - math.cos(angle)) * K @ K


#: the scene of each motion a kind may declare (Kind.animation), in the order messages list them
BUILDERS = {"nutating_top": _released, "steady_top": _steady, "free_body": _torque_free,
            "turning_rotor": _turning_rotor, "rolling": _rolling, "lean_and_steer": _bicycle}


def build_scene(path: str, periods: float | None = None, speed: float = 1.0,
                fps: float = 30.0):
    """(Scene, simulations) for a problem file; InputError if its kind does not move."""
    from ..solving.problem import load
    from ..solving.solve import solve

    problem = load(path)
    if problem.kind.animation not in BUILDERS:
        from ..kinds import offering

        raise InputError(f"--animate draws the kinds that move: "
                         f"{', '.join(offering('animation', BUILDERS))}; this file "
                         f"is kind {problem.kind.name!r}", file=path, key="kind")
    if periods is not None and not (math.isfinite(periods) and periods > 0):
        raise InputError("--periods must be a positive number")
    return scene_of(problem, solve(problem), periods, speed, fps, path)


def scene_of(problem, result, periods: float | None = None, speed: float = 1.0,
             fps: float = 30.0, path: str | None = None):
    """(Scene, simulations) for a problem already solved (its kind one that moves)."""
    from ..render.animate import Scene

    try:
        panels, clock, notes, sims = BUILDERS[problem.kind.animation](
            problem, result, periods or DEFAULT_PERIODS, speed, fps)
    except InputError as err:
        raise err.located(file=path or problem.file) from None
    title = f"{problem.id}  {problem.title}".strip()
    return Scene(title, panels, clock.times, fps, notes), sims


def check_output(path: str, force: bool) -> None:
    """Refuse a bad name or an existing file before any work."""
    from pathlib import Path

    from ..core.files import refuse_special
    from ..render.animate import FORMATS

    suffix = Path(path).suffix.lower()
    if suffix not in FORMATS:
        raise InputError("animation format not supported; name the file .gif, .mp4 or .html",
                         file=str(path))
    refuse_special(path)
    target = Path(path)
    if target.exists() and not force:
        raise InputError("exists; not overwritten (use --force to replace it)", file=str(path))
    if suffix == ".mp4":
        import shutil

        if not shutil.which("ffmpeg"):
            raise InputError("MP4 needs ffmpeg, which is not installed (apt-get install "
                             "ffmpeg); write .gif or .html instead", file=str(path))


def animate_file(path: str, out: str, periods: float | None = None, speed: float = 1.0,
                 fps: float = 30.0, force: bool = False) -> str:
    """The whole --animate request: returns the lines to print."""
    from ..render import animate as render

    check_output(out, force)
    scene, _ = build_scene(path, periods, speed, fps)
    render.write(scene, out, force=force)
    lines = [f"Wrote animation: {out} ({scene.frames} frames, {scene.duration:.2f} s at "
             f"{scene.fps:g} frames/s)"]
    lines += [f"Note: {n}" for n in scene.notes]
    return "\n".join(lines) + "\n"
