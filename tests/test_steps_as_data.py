"""Worked steps as data (issue 21): every equation step of every bundled problem and
`gyro new` example, re-evaluated from its JSON ``expr`` and ``symbols``; no negative
number juxtaposed in a substitution, in text, Markdown or LaTeX."""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

import pytest
import yaml
from conftest import read_yaml

from gyro_cli.commands.authoring import template
from gyro_cli.core.errors import InputError
from gyro_cli.core.expr import python_names
from gyro_cli.kinds import names as kind_names
from gyro_cli.render import document, report, writeup
from gyro_cli.solving.solve import solve_file

ROOT = Path(__file__).resolve().parents[1]
PROBLEMS = sorted((ROOT / "problems").glob("*.yaml"))


#: text: a minus sign glued to a number right after a factor, a unit, a bracket or a
#: division sign (a subtraction is spaced: ``a - 3``)
TEXT_JUXTAPOSED = re.compile(r"(?:[\w)^]\s+|[/*^]\s*)-\d")
#: LaTeX: a minus sign glued to a number after anything but an opening bracket (``(``,
#: ``\lvert`` of |-3|), a brace, an equals sign or the start (``\cdot -3``, ``\,-3``, ``} -3``)
LATEX_JUXTAPOSED = re.compile(r"(?:\\cdot|\\,|\}|[\w)])(?<!\\lvert)\s*-\d")


def _examples(tmp_path: Path) -> list[Path]:
    out = []
    for name in kind_names():
        path = tmp_path / f"{name}.yaml"
        path.write_text(template(name))
        out.append(path)
    return out


def _eval(expr: str, symbols: dict[str, float]) -> float:
    return eval(expr, {"__builtins__": {}}, python_names() | symbols)  # our own output


def _check_equations(doc: dict, kind: str) -> int:
    count = 0
    for section in doc["steps"]:
        for eq in section["equations"]:
            assert eq["expr"] is not None, (doc["file"], kind, eq)  # every step a tree
            value = _eval(eq["expr"], eq["symbols"])
            assert math.isclose(value, eq["value"], rel_tol=1e-9, abs_tol=1e-300), \
                (doc["file"], eq["symbol"], eq["expr"], value, eq["value"])
            assert (eq["formula"] or eq["substitution"]) and eq["unit"] is not None
            assert bool(eq["formula"]) == bool(eq["formula_latex"])
            count += 1
    return count


def test_every_equation_step_re_evaluates_to_its_value(tmp_path):
    files = PROBLEMS + _examples(tmp_path)
    total = 0
    for path in files:
        result = solve_file(str(path))
        total += _check_equations(report.as_dict(result), result.problem.kind.name)
    assert total > 20


def _negated(path: Path, tmp_path: Path) -> Path | None:
    """The problem with its spin, precession, moment and axial rate negated."""
    data = read_yaml(path.read_text())
    given = data.get("given") or {}
    changed = False
    for key in ("spin", "precession", "moment", "axial_rate", "spin_rate", "turn_rate"):
        value = given.get(key)
        if isinstance(value, str) and value.strip()[:1].isdigit():
            given[key] = "-" + value.strip()
            changed = True
    if not changed:
        return None
    data.pop("expected", None)
    out = tmp_path / f"neg_{path.name}"
    out.write_text(yaml.safe_dump(data))
    return out


def _substitutions(result) -> tuple[list[str], list[str]]:
    texts, latexes = [], []
    for section in result.solution.sections:
        for step in section.steps:
            if step.substitution:
                texts.append(step.substitution)
                if step.expr is not None:
                    lhs, pieces = document.step_pieces(step)
                    latexes.append(writeup.LatexPrinter(True).doprint(pieces[1]))
    return texts, latexes


def test_no_substitution_juxtaposes_a_negative_number(tmp_path):
    files = PROBLEMS + _examples(tmp_path)
    files += [n for n in (_negated(p, tmp_path) for p in files) if n is not None]
    seen = 0
    for path in files:
        try:
            result = solve_file(str(path))
        except InputError:  # a negated rate some kinds refuse (a speed, an engine's rate)
            continue
        texts, latexes = _substitutions(result)
        for line in texts:
            assert not TEXT_JUXTAPOSED.search(line), (path.name, line)
        for line in latexes:
            assert not LATEX_JUXTAPOSED.search(line), (path.name, line)
        seen += len(texts)
    assert seen > 300


def test_top_rev_per_s_divides_by_a_bracketed_negative_product():
    """The slip the issue found: ``(0.0005120 kg m^2 -179.7 rad/s)`` set as a subtraction."""
    doc = json.loads(report.as_json(solve_file(str(ROOT / "problems" / "top_rev_per_s.yaml"))))
    lines = [line for s in doc["steps"] for line in s["lines"]]
    assert not any(TEXT_JUXTAPOSED.search(line) for line in lines), lines


def test_render_reads_no_formula_text():
    """Issue 21's acceptance: a step's formula is a tree or nothing, never text."""
    from gyro_cli.core.work import Work

    work = Work()
    with pytest.raises(TypeError, match="a formula is a tree"):
        work.step("M", "m g l sin(theta)")


def _agm(a: float, b: float) -> float:
    while abs(a - b) > 1e-15 * a:
        a, b = (a + b) / 2, math.sqrt(a * b)
    return a


def test_gyrocompass_trees_agree_with_the_physics_functions(tmp_path):
    """The kind's steps are evaluated from their trees; the formulas of
    physics/gyrocompass.py (Kibble & Berkshire 9.15), written out here on floats, give
    the same, and the swing period the pendulum's exact period by the AGM:
    T0 (2/pi) K(sin(alpha/2)), K(k) = pi / (2 AGM(1, sqrt(1 - k^2)))."""
    result = solve_file(str(ROOT / "problems" / "gyrocompass_ship.yaml"))
    steps = {s.symbol: s for sec in result.solution.sections for s in sec.steps if s.expr}
    syms = {name: s.si for st in steps.values()
            for name, s in __import__("gyro_cli.core.expr", fromlist=["symbols"]).symbols(
                st.expr).items()}
    H, W, lat, alpha, I_v = (syms[k] for k in ("H", "Omega_E", "lambda", "alpha", "I_v"))
    D = H * W * math.cos(lat)
    T0 = 2 * math.pi * math.sqrt(I_v / D)
    k = math.sin(abs(alpha) / 2)
    assert steps["D"].value == pytest.approx(D, rel=1e-12)
    assert steps["M"].value == pytest.approx(D * math.sin(alpha), rel=1e-12)
    assert steps["T"].value == pytest.approx(T0, rel=1e-12)
    assert steps["T(alpha)"].value == pytest.approx(
        T0 * 2 / math.pi * math.pi / (2 * _agm(1.0, math.sqrt(1 - k * k))), rel=1e-12)


def _tree_steps(path: Path) -> tuple[dict, dict]:
    result = solve_file(str(path))
    steps = {s.symbol: s for sec in result.solution.sections for s in sec.steps if s.expr}
    return steps, _symbol_values(result)


@pytest.mark.parametrize("name", ["11_3_equinoxes.yaml", "mars_precession.yaml"])
def test_earth_precession_trees_agree_with_the_oracle(name):
    """Each body's rate from its tree against the oracle's precession_rate (tests/oracles.py,
    MacCullagh's torque averaged over the orbit), and the tidal terms against Kepler III."""
    import oracles as P

    steps, syms = _tree_steps(ROOT / "problems" / name)
    H, omega, eps = syms["H"], syms["omega"], syms["epsilon"]
    for b in ("sun", "moon"):
        if f"Omega_{b}" not in steps:
            continue
        tidal = steps[f"G M_{b} / a_{b}^3"]
        if f"P_{b}" in syms:
            assert tidal.value == pytest.approx(
                P.tidal_from_period(syms[f"P_{b}"], syms[f"q_{b}"]), rel=1e-12)
        e, i = syms.get(f"e_{b}", 0.0), syms.get(f"i_{b}", 0.0)
        assert steps[f"(1 - e_{b}^2)^(-3/2)"].value == pytest.approx(
            P.eccentricity_factor(e), rel=1e-12)
        expected = P.precession_rate(tidal.value, e, H, eps, omega, i)
        assert steps[f"Omega_{b}"].value == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize("name", ["11_2_released_top.yaml", "11_2_released_top_loops.yaml"])
def test_released_top_trees_agree_with_the_physics(name):
    """The constants of the motion and the fast-top estimates, evaluated from the step
    trees, against physics/nutation.py (which computes them its own way)."""
    from gyro_cli.physics import nutation as N

    result = solve_file(str(ROOT / "problems" / name))
    steps = {s.symbol: s for sec in result.solution.sections for s in sec.steps if s.expr}
    v = _symbol_values(result)
    top = N.Top(I=v["I"], J=v["J"], mgl=v["mgl"])
    start = N.Start(theta0=v["theta0"], spin=v["psidot"], precession0=v["phidot0"],
                    theta_rate0=v["thetadot0"])
    nut = N.analyse(top, start)
    omega_z = steps["omega_z"].value
    for symbol, expected in (("P2", nut.P2), ("P1", nut.P1), ("h", nut.energy), ("a", nut.a),
                             ("alpha", nut.alpha), ("beta", nut.beta), ("gamma", nut.gamma),
                             ("T_fast", 2 * math.pi * top.I / (top.J * omega_z)),
                             ("phidot_fast", top.mgl / (top.J * omega_z))):
        assert steps[symbol].value == pytest.approx(expected, rel=1e-12), symbol
    if "dtheta_fast" in steps:
        # the fast top's cone: 2 I m g l sin(theta0) / (J omega_z)^2
        assert steps["dtheta_fast"].si[0] == pytest.approx(
            2 * top.I * top.mgl * math.sin(start.theta0) / (top.J * omega_z) ** 2, rel=1e-12)


def _symbol_values(result):
    """The data of the problem as the steps' symbols hold them (SI): each symbol of each
    tree step, a later step's value of a name over an earlier one's."""
    from gyro_cli.core.expr import symbols

    syms = {}
    for sec in result.solution.sections:
        for s in sec.steps:
            if s.expr is not None:
                syms |= {k: v.si for k, v in symbols(s.expr).items()}
    return syms


@pytest.mark.parametrize("gyroscopic", [True, False])
def test_bicycle_trees_agree_with_the_paper_totals(gyroscopic, tmp_path):
    """Eqs. A 1-A 17 evaluated from the step trees against physics/bicycle.py's totals."""
    from gyro_cli.physics import bicycle as B

    path = tmp_path / "bike.yaml"
    path.write_text("id: b\nkind: bicycle\ngiven:\n  preset: benchmark\n  speed: 5 m/s\n"
                    f"  gyroscopic: {'true' if gyroscopic else 'false'}\nfind: [motion]\n")
    result = solve_file(str(path))
    steps = {s.symbol: s for sec in result.solution.sections for s in sec.steps}
    t = B.totals(dict(B.BENCHMARK), gyroscopic)
    names = {"m_T": t.mT, "x_T": t.xT, "z_T": t.zT, "I_Txx": t.ITxx, "I_Txz": t.ITxz,
             "I_Tzz": t.ITzz, "m_A": t.mA, "x_A": t.xA, "z_A": t.zA, "I_Axx": t.IAxx,
             "I_Axz": t.IAxz, "I_Azz": t.IAzz, "u_A": t.uA, "I_All": t.IAll, "I_Alx": t.IAlx,
             "I_Alz": t.IAlz, "mu": t.mu, "S_R": t.SR, "S_F": t.SF, "S_T": t.ST, "S_A": t.SA}
    for symbol, expected in names.items():
        assert steps[symbol].value == pytest.approx(expected, rel=1e-12, abs=1e-15), symbol


STEADY_TOP = """\
id: t
kind: steady_precession
given: {{mass: 2 kg, shape: disk, diameter: 150 mm, cg_distance: 600 mm, theta: {theta},
        {rates}}}
find: [{find}]
"""


@pytest.mark.parametrize("theta, rates, find", [
    ("120 deg", "precession: 36 rpm", "spin, min_spin, precession_period, cg_speed, "
                                      "pivot_force"),
    ("60 deg", "spin: -3000 rpm, precession: -12 rpm", "moment"),
    ("60 deg", "axial_rate: 9000 rpm", "precession, spin, precession_approx"),
    ("90 deg", "spin: 3000 rpm", "precession")])
def test_steady_precession_trees_agree_with_the_physics(theta, rates, find, tmp_path):
    """Each step from its tree against the kind's and physics/steady.py's functions, with
    negative rates among them."""
    from gyro_cli.kinds import steady_precession as K
    from gyro_cli.physics import steady

    path = tmp_path / "t.yaml"
    path.write_text(STEADY_TOP.format(theta=theta, rates=rates, find=find))
    result = solve_file(str(path))
    steps = [s for sec in result.solution.sections for s in sec.steps if s.expr is not None]
    v = _symbol_values(result)
    m = 2.0
    J, I = m * 0.075 ** 2 / 2, m * 0.075 ** 2 / 4 + m * 0.6 ** 2  # disk, parallel axes
    th = v["theta"]
    for s in steps:
        if s.formula.startswith("phidot sin(theta) (J omega_z"):
            assert s.value == pytest.approx(K.moment_required(I, J, th, v["psidot"],
                                                              v["phidot"]), rel=1e-12)
        if s.symbol == "psidot" and "D" in v and "phidot" in v:
            assert s.value == pytest.approx(K.spin_for_precession(I, J, th, v["phidot"], v["D"]),
                                            rel=1e-12)
        if s.symbol == "psidot_min":
            assert s.value == pytest.approx(K.min_spin(I, J, th, v["D"]), rel=1e-12)
        if s.symbol == "phidot_approx":
            omega = v.get("omega_z", v.get("psidot"))
            assert s.value == pytest.approx(steady.precession_approx(v["D"], J, omega), rel=1e-12)
        if s.symbol.startswith("T"):
            assert s.value == pytest.approx(steady.precession_period(v["phidot"]), rel=1e-12)
        if s.symbol.startswith("v_G"):
            assert s.value == pytest.approx(steady.cg_speed(0.6, th, v["phidot"]), rel=1e-12)
        if s.symbol == "phidot" and "M" in v:  # theta = 90 deg: M / (J psidot), exact
            assert s.value == pytest.approx(v["M"] / (J * v["psidot"]), rel=1e-12)
    assert steps


def _si(step) -> float:
    """A step's value in SI (an angle shown in deg, in rad)."""
    return step.si[0] if step.si is not None else step.value


@pytest.mark.parametrize("name", sorted(p.name for p in PROBLEMS
                                        if p.name.startswith("torque_free")))
def test_torque_free_trees_agree_with_the_physics(name):
    """Each step from its tree against physics/torque_free.py's solve_motion, which finds
    the motion its own way (atan2, hypot) from the two given quantities."""
    from gyro_cli.physics import torque_free as P

    result = solve_file(str(ROOT / "problems" / name))
    steps, syms = _tree_steps(ROOT / "problems" / name)
    given = {g.key: g.si_value for g in result.solution.given}
    known = {k: given[k] for k in P.MOTION_KEYS if k in given}
    if given.get("precession_sense") is not None and "spin" in known:
        known["spin"] = abs(known["spin"]) * (1 if given["precession_sense"] == "direct" else -1)
    s = P.solve_motion(syms["J"], syms["I"], known)
    expected = {"beta": s.omega_angle, "theta": s.nutation_angle, "omega_z": s.axial_rate,
                "omega_e": s.transverse_rate, "omega": s.omega, "H": s.angular_momentum,
                "phidot": s.precession, "psidot": s.spin, "T_p": s.precession_period,
                "T_w": s.body_wobble_period, "body cone": s.body_cone_angle,
                "space cone": s.space_cone_angle, "n": s.spin / s.precession,
                "T": s.kinetic_energy, "I_max": s.major_moment, "omega_f": s.final_rate,
                "T_f": s.final_kinetic_energy, "T - T_f": s.energy_lost}
    if given.get("precession_sense") is not None:
        expected["n"] = abs(expected["n"])
    for symbol, step in steps.items():
        if symbol in expected:  # not the body's J, I_G
            assert _si(step) == pytest.approx(expected[symbol], rel=1e-12), symbol
    if s.omega_angle > 0:  # a steady spin about the axis (angle 0) has no wobble to state
        assert {"omega_e", "H", "phidot", "psidot", "T_p", "n"} <= set(steps)
    else:
        assert "H" in steps and not {"phidot", "psidot", "T_p", "n"} & set(steps)


@pytest.mark.parametrize("name", ["rate_gyro_reading.yaml", "rate_gyro_turn.yaml",
                                  "rate_integrating_gyro.yaml", "11_3_bearing_moment.yaml",
                                  "template"])
def test_rate_gyro_trees_agree_with_the_physics(name, tmp_path):
    """Each step from its tree against the rate gyro's formulas written out here on floats
    (Thomson ch. 5; the kind builds its trees from physics/rate_gyro.py); f_n (Hz) is
    omega_n (rad/s) over 2 pi."""
    path = ROOT / "problems" / name
    if name == "template":
        path = tmp_path / "rate_gyro.yaml"
        path.write_text(template("rate_gyro"))
    steps, v = _tree_steps(path)
    H = v["H"]
    if "Omega" in steps:  # from the measurement
        O = steps["Omega"].value
        if "M" in v and "k" not in v:
            assert O == pytest.approx(v["M"] / H, rel=1e-12)
    O = v["Omega"] if "Omega" in v else None
    checks = {"M": lambda: H * O,
              "theta": lambda: (H * O / v["k"] if "k" in v else H / v["c"] * v["phi"]),
              "S": lambda: H / v["k"],
              "omega_n": lambda: math.sqrt(v["k"] / v["I_g"]),
              "f_n": lambda: math.sqrt(v["k"] / v["I_g"]) / (2 * math.pi),
              "zeta": lambda: v["c"] / (2 * math.sqrt(v["k"] * v["I_g"])),
              "thetadot": lambda: H * O / v["c"],
              "H / c": lambda: H / v["c"], "tau": lambda: v["I_g"] / v["c"]}
    for symbol, step in steps.items():
        if symbol in checks:
            assert _si(step) == pytest.approx(checks[symbol](), rel=1e-12), symbol
    if name == "template":
        assert steps["f_n"].unit == "Hz" and steps["omega_n"].unit == "rad/s"
        assert {"theta", "S", "omega_n", "f_n", "zeta"} <= set(steps)


@pytest.mark.parametrize("name", sorted(p.name for p in PROBLEMS if p.name.startswith("euler"))
                         + ["template"])
def test_euler_angles_trees_agree_with_the_physics(name, tmp_path):
    """Eq. 11.8 both ways, the fixed-frame rates (R omega), T and H from the step trees
    against physics/euler_kinematics.py, which works with exact zeros, matrices and dot
    products; every equation step is a tree: the particle sums of Eq. 11.3 over each
    particle's m, x, y, z, the angle between omega and H as atan2 of the components."""
    from gyro_cli.physics import euler_kinematics as ek

    path = ROOT / "problems" / name
    if name == "template":
        path = tmp_path / "euler_angles.yaml"
        path.write_text(template("euler_angles"))
    result = solve_file(str(path))
    for section in report.as_dict(result)["steps"]:
        for eq in section["equations"]:
            assert eq["expr"] is not None, eq
    steps, v = _tree_steps(path)
    answers = {k: a.si_values for k, a in result.answers.items()}
    zyx = "yaw" in v or "pitch" in v
    a2, a3 = (v.get("pitch"), v.get("roll")) if zyx else (v.get("theta"), v.get("psi"))
    if a2 is None:  # omega given in body axes, no angle
        omega = tuple(v[k] for k in ("omega_x", "omega_y", "omega_z"))
        rates = None
    elif any(k in steps for k in ("omega_x", "p")):  # forward
        rates = [v.get(k, 0.0) for k in (("yawdot", "pitchdot", "rolldot") if zyx
                                         else ("phidot", "thetadot", "psidot"))]
        omega = (ek.body_rates_zyx if zyx else ek.body_rates_zxz)(a2, a3, *rates)
        for sym, value in zip(("p", "q", "r") if zyx else ("omega_x", "omega_y", "omega_z"),
                              omega):
            assert steps[sym].value == pytest.approx(value, rel=1e-12, abs=1e-15), sym
    else:  # inverse
        omega = tuple(v[k] for k in (("p", "q", "r") if zyx else ("omega_x", "omega_y",
                                                                   "omega_z")))
        rates = (ek.euler_rates_zyx if zyx else ek.euler_rates_zxz)(a2, a3, *omega)
        for sym, value in zip(("yawdot", "pitchdot", "rolldot") if zyx
                              else ("phidot", "thetadot", "psidot"), rates):
            assert steps[sym].value == pytest.approx(value, rel=1e-12, abs=1e-15), sym
    if "omega_X" in steps and "phi" in v:
        fixed = ek.matvec(ek.attitude("zxz", v["phi"], a2, a3), omega)
        for sym, value in zip(("omega_X", "omega_Y", "omega_Z"), fixed):
            assert steps[sym].value == pytest.approx(value, rel=1e-12, abs=1e-15), sym
    assert steps["|omega|"].value == pytest.approx(ek.norm(omega), rel=1e-12)
    if "T" in steps:
        matrix = ek.inertia_matrix(v["I_x"], v["I_y"], v["I_z"], v.get("I_xy", 0.0),
                                   v.get("I_yz", 0.0), v.get("I_zx", 0.0))
        assert steps["T"].value == pytest.approx(ek.kinetic_energy(matrix, omega), rel=1e-12)
        H = ek.angular_momentum(matrix, omega)
        for sym, value in zip(("H_x", "H_y", "H_z"), H):
            assert steps[sym].value == pytest.approx(value, rel=1e-12, abs=1e-15), sym
        assert steps["|H|"].value == pytest.approx(ek.norm(H), rel=1e-12)
        if "kinetic_energy" in answers:
            assert answers["kinetic_energy"][0] == pytest.approx(steps["T"].value, rel=1e-12)
        if "alpha_x" in steps:  # Eq. 11.8 differentiated, or as given; Euler's equations
            dots = ("yawddot", "pitchddot", "rollddot") if zyx else ("phiddot", "thetaddot",
                                                                     "psiddot")
            if any(d in v for d in dots) or (rates is not None and "phidot" in v):
                accel = (ek.body_accel_zyx if zyx else ek.body_accel_zxz)(
                    a2, a3, rates, [v.get(d, 0.0) for d in dots])
            else:
                accel = tuple(v.get(k, 0.0) for k in ("alpha_x", "alpha_y", "alpha_z"))
            for sym, value in zip(("alpha_x", "alpha_y", "alpha_z"), accel):
                assert steps[sym].value == pytest.approx(value, rel=1e-12, abs=1e-15), sym
            M = ek.euler_moment(matrix, omega, accel)
            for sym, value in zip(("M_x", "M_y", "M_z"), M):
                assert steps[sym].value == pytest.approx(value, rel=1e-12, abs=1e-12), sym
        if "angle(omega, H)" in steps:
            assert steps["angle(omega, H)"].si[0] == pytest.approx(
                ek.angle_between(omega, H), rel=1e-12, abs=1e-15)
    if "m_0" in v:  # particles: the sums of Eq. 11.3 against physics' own
        particles = [(v[f"m_{i}"], v[f"x_{i}"], v[f"y_{i}"], v[f"z_{i}"])
                     for i in range(len([k for k in v if k.startswith("m_")]))]
        for sym, value in zip(("I_x", "I_y", "I_z", "I_xy", "I_yz", "I_zx"),
                              ek.inertia_from_particles(particles)):
            assert steps[sym].value == pytest.approx(value, rel=1e-12, abs=1e-15), sym


SHIP = """\
id: s
kind: ship
given: {{mass: 6000 kg, k_axial: 450 mm, spin: 2400 rpm, rotor_sense: clockwise_from_stern,
        {motion}}}
find: [couple]
"""


@pytest.mark.parametrize("motion", [
    "motion: steering, speed: 20 knot, turn_radius: 250 m, turn: right",
    "motion: pitching, amplitude: 7.5 deg, period: 18 s, bow: rising",
    "motion: pitching, between_extremes: 12 deg, frequency: 0.025 Hz, bow: falling",
    "motion: rolling, roll_rate: 0.035 rad/s",
    "motion: rolling"])
def test_ship_trees_agree_with_a_hand_calculation(motion, tmp_path):
    """H, omega_p, the pitching's omega_1, omega_p,max and alpha_max (theta = phi sin(omega_1 t)
    differentiated by hand) and the couple, from the step trees, against the vector rule
    omega_p x H of physics/vehicles.py."""
    from gyro_cli.physics import vehicles as V

    path = tmp_path / "s.yaml"
    path.write_text(SHIP.format(motion=motion))
    steps, syms = _tree_steps(path)
    J, omega = syms["J"], syms["omega"]
    H = V.spin_vector(J, omega, V.spin_direction("clockwise_from_stern"))
    assert steps["H"].value == pytest.approx(V.norm(H), rel=1e-12)
    if "steering" in motion:
        wp = V.steering_precession(syms["v"], syms["R"], "right")
        assert steps["omega_p"].value == pytest.approx(syms["v"] / syms["R"], rel=1e-12)
    elif "pitching" in motion:
        phi = syms["phi"]
        if "phi_total" in syms:
            assert steps["phi"].si[0] == pytest.approx(syms["phi_total"] / 2, rel=1e-12)
            assert steps["T"].value == pytest.approx(2 * math.pi / syms["omega_1"], rel=1e-12)
        w1 = 2 * math.pi / (steps["T"].value if "T" in steps else syms["T"])
        if "omega_1" in steps:  # from the period (from a frequency it is given)
            assert steps["omega_1"].value == pytest.approx(w1, rel=1e-12)
        # theta = phi sin(w1 t): theta' peaks at phi w1, theta'' at phi w1^2
        assert steps["omega_p,max"].value == pytest.approx(phi * w1, rel=1e-12)
        assert steps["alpha_max"].value == pytest.approx(phi * w1 * w1, rel=1e-12)
        wp = V.pitching_precession(phi * w1, "rising")
    else:
        wp = V.rolling_precession(syms["omega_p"])
    assert steps["C"].value == pytest.approx(V.norm(V.couple_on_rotor(wp, H)), rel=1e-12,
                                             abs=1e-9)


TWO_WHEELER = """\
id: t
kind: two_wheeler
given: {{mass: 250 kg, cg_height: 0.6 m, wheel_inertia: 1 kg*m^2, wheel_radius: 300 mm,
        engine_inertia: 0.3 kg*m^2, gear_ratio: 5, engine_sense: {sense}, speed: 90 km/h,
        turn_radius: 50 m}}
find: [heel_angle]
"""


@pytest.mark.parametrize("sense", ["same", "opposite"])
def test_two_wheeler_trees_agree_with_a_hand_calculation(sense, tmp_path):
    """The rates, the couples and the heel from the step trees against the book's working
    (H = (2 I_w +- G I_E) v / r_w, C_g = H v / R) and the heeled machine's moment balance
    m g h sin(theta) = (C_g + C_c) cos(theta)."""
    path = tmp_path / "t.yaml"
    path.write_text(TWO_WHEELER.format(sense=sense))
    steps, v = _tree_steps(path)
    w, wp = v["v"] / v["r_w"], v["v"] / v["R"]
    H = (2 * v["I_w"] + (1 if sense == "same" else -1) * v["G"] * v["I_E"]) * w
    C_g, C_c = H * wp, v["m"] * v["v"] * v["v"] * v["h"] / v["R"]
    assert steps["omega_w"].value == pytest.approx(w, rel=1e-12)
    assert steps["omega_E"].value == pytest.approx(v["G"] * w, rel=1e-12)
    assert steps["omega_p"].value == pytest.approx(wp, rel=1e-12)
    assert steps["H"].value == pytest.approx(H, rel=1e-12)
    assert steps["C_g"].value == pytest.approx(C_g, rel=1e-12)
    assert steps["C_c"].value == pytest.approx(C_c, rel=1e-12)
    theta = steps["theta"].si[0]
    weight = v["m"] * v["g"] * v["h"]
    assert 0 < theta < math.pi / 2
    assert weight * math.sin(theta) == pytest.approx((C_g + C_c) * math.cos(theta), rel=1e-12)


@pytest.mark.parametrize("name", ["four_wheeler_trolley_2500kg.yaml",
                                  "four_wheeler_trolley_2700kg.yaml",
                                  "four_wheeler_railcar_limit.yaml"])
def test_four_wheeler_trees_agree_with_a_hand_calculation(name):
    """The rotors' totals, the couples and each wheel's share from the step trees against
    the book's working by hand (C_g = H omega_p); at the limiting speed the inner wheels'
    reaction, worked by hand, is zero."""
    steps, v = _tree_steps(ROOT / "problems" / name)
    data = read_yaml((ROOT / "problems" / name).read_text())["given"]
    sense = data.get("engine_sense", "same")
    wheels = 4 * v["I_w"] if "I_w" in v else 2 * v["I_axle"]
    engines = v["n_E"] * v["I_E"]
    assert steps["sum I_w"].value == pytest.approx(wheels, rel=1e-12)
    assert steps["sum I_E"].value == pytest.approx(engines, rel=1e-12)
    I_eq = wheels + (1 if sense == "same" else -1) * v["G"] * engines
    assert steps["I_eq"].value == pytest.approx(I_eq, rel=1e-12)
    if "speed" in data:
        w, wp = v["v"] / v["r_w"], v["v"] / v["R"]
        C_g, C_c = I_eq * w * wp, v["m"] * v["v"] ** 2 * v["h"] / v["R"]
        P_w, P_g, P_c = v["m"] * v["g"] / 4, C_g / (2 * v["x"]), C_c / (2 * v["x"])
        for symbol, expected in (("omega_w", w), ("omega_p", wp), ("H", I_eq * w),
                                 ("C_g", C_g), ("C_c", C_c), ("P_w", P_w), ("P_g", P_g),
                                 ("P_c", P_c), ("R_outer", P_w + P_g + P_c),
                                 ("R_inner", P_w - P_g - P_c)):
            assert steps[symbol].value == pytest.approx(expected, rel=1e-12), symbol
    if "v_lim" in steps:
        u = steps["v_lim"].value
        couples = I_eq * u * u / (v["r_w"] * v["R"]) + v["m"] * u * u * v["h"] / v["R"]
        inner = v["m"] * v["g"] / 4 - couples / (2 * v["x"])
        assert inner == pytest.approx(0, abs=1e-9 * v["m"] * v["g"])


ROLLING = """\
id: d
kind: rolling_disk
given: {{mass: 1.2 kg, shape: {shape}, radius: 0.35 m, {given}}}
find: [{find}]
"""


@pytest.mark.parametrize("shape, given, find", [
    ("disk", "path_radius: 0.6 m, precession: 48 rpm", "normal_force, moment, precession_period"),
    ("disk", "path_radius: 0.6 m, precession: -48 rpm", "normal_force, moment"),
    ("ring", "arrangement: free, tilt: 5 deg, path_radius: 20 m", "speed, precession_period"),
    ("ring", "arrangement: free, tilt: 5 deg, speed: 3 m/s", "path_radius"),
    ("disk", "arrangement: free, speed: 3 m/s, path_radius: 20 m", "tilt, upright_speed")])
def test_rolling_disk_trees_agree_with_the_physics(shape, given, find, tmp_path):
    """Each step from its tree against the kind's float functions (axle_pivot_spin,
    axle_pivot_normal_force, free_from_tilt_and_path, free_from_speed_and_tilt) and
    physics/stability.py's disk_critical_axial_rate."""
    from gyro_cli.kinds import rolling_disk as K
    from gyro_cli.physics.stability import disk_critical_axial_rate

    path = tmp_path / "d.yaml"
    path.write_text(ROLLING.format(shape=shape, given=given, find=find))
    result = solve_file(str(path))
    steps = [s for sec in result.solution.sections for s in sec.steps if s.expr is not None]
    v = _symbol_values(result)
    by = {s.symbol: s for s in steps}
    m, g, r, J = v["m"], v["g"], v["r"], v["J"]
    if "precession:" in given:
        Omega, R = v["Omega"], v["R"]
        assert by["psidot"].value == pytest.approx(K.axle_pivot_spin(Omega, R, r), rel=1e-12)
        assert by["dH_O/dt"].value == pytest.approx(J * K.axle_pivot_spin(Omega, R, r) * Omega,
                                                    rel=1e-12)
        N = K.axle_pivot_normal_force(m, g, J, Omega, r)
        assert by["N"].value == pytest.approx(N, rel=1e-12)
        assert by["M"].value == pytest.approx(J * Omega ** 2 * R / r, rel=1e-9)
        if "T" in by:
            assert by["T"].value == pytest.approx(2 * math.pi / abs(Omega), rel=1e-12)
        return
    I = v["I_G"]
    if "path_radius:" in given and "tilt:" in given:
        s = K.free_from_tilt_and_path(m, g, r, J, I, v["beta"], v["R"])
        assert by["rho"].value == pytest.approx(s.centre_radius, rel=1e-12)
        assert by["Omega"].value == pytest.approx(s.precession, rel=1e-12)
        assert by["v"].value == pytest.approx(s.speed, rel=1e-12)
    elif "tilt:" in given:
        s = K.free_from_speed_and_tilt(m, g, r, J, I, v["beta"], v["v"])
        assert by["rho"].value == pytest.approx(s.centre_radius, rel=1e-12)
        assert by["R"].value == pytest.approx(s.path_radius, rel=1e-12)
    else:
        [s] = K.free_from_speed_and_path(m, g, r, J, I, 3.0, 20.0)  # as given
    assert by["omega_z"].value == pytest.approx(s.axial_rate, rel=1e-12)
    assert by["psidot"].value == pytest.approx(s.spin, rel=1e-12)
    assert by["v_upright"].value == pytest.approx(disk_critical_axial_rate(m, g, r, I, J) * r,
                                                  rel=1e-12)


#: released tops near the sleeping limit and other hard cases: a tilt of 1e-6 deg, spins
#: just above and below the least spin of the sleeping top (2 sqrt(I m g l) / J, about
#: 1173 rpm here: m -> 1), hanging near the bottom, a fast top, a nearly steady one
NEAR_LIMITS = [
    "theta0: 0.000001 deg\n  spin: 1800 rpm",
    "theta0: 0.01 deg\n  spin: 1180 rpm",
    "theta0: 0.01 deg\n  spin: 1170 rpm",
    "theta0: 0.5 deg\n  spin: 1174 rpm",
    "theta0: 179.999 deg\n  spin: 1800 rpm",
    "theta0: 30 deg\n  spin: 100000 rpm",
    "theta0: 60 deg\n  spin: 1800 rpm\n  precession0: 4.6 rad/s",
    "theta0: 60 deg\n  spin: 1800 rpm\n  precession0: 4.552618042746112 rad/s",
    "theta0: 0 deg\n  spin: 1800 rpm\n  theta_rate0: 1 rad/s",
    "theta0: 180 deg\n  spin: 1800 rpm\n  theta_rate0: 1 rad/s",
]
RELEASED_TOP = ("id: x\nkind: released_top\ngiven:\n  mass: 0.08498 kg\n  J: 3.869e-5 kg m^2\n"
                "  I_pivot: 1.776e-4 kg m^2\n  cg_distance: 0.0381 m\n  {}\nfind: [theta_max]\n")


def _released_top_files(tmp_path: Path) -> list[Path]:
    out = sorted((ROOT / "problems").glob("11_2_*.yaml"))
    example = tmp_path / "example.yaml"
    example.write_text(template("released_top"))
    out.append(example)
    for k, given in enumerate(NEAR_LIMITS):
        path = tmp_path / f"near_{k}.yaml"
        path.write_text(RELEASED_TOP.format(given))
        out.append(path)
    return out


def test_released_top_limits_period_and_precession_trees_agree_with_the_physics(tmp_path):
    """The nutation limits, m, T and phidot at the limits, evaluated from their trees (the
    JSON ``expr`` too), within 1e-9 of physics/nutation.py's answers for every bundled
    released top, the `gyro new` example and tops near the sleeping limit; K(m) by the
    tree's AGM against physics' R_F where m is not near 1, and phidot against Eq. 11.16
    evaluated at the roots where u is not near a pole."""
    import oracles

    from gyro_cli.core.expr import _ellipk
    from gyro_cli.physics import nutation as N

    seen = set()
    for path in _released_top_files(tmp_path):
        result = solve_file(str(path))
        _check_equations(report.as_dict(result), "released_top")
        steps = {s.symbol: s for sec in result.solution.sections for s in sec.steps}
        v = _symbol_values(result)
        top = N.Top(I=v["I"], J=v["J"], mgl=v["mgl"])
        start = N.Start(theta0=v["theta0"], spin=v["psidot"], precession0=v["phidot0"],
                        theta_rate0=v["thetadot0"])
        nut = N.analyse(top, start)
        close = dict(rel=1e-9, abs=1e-300)
        if nut.motion == "sleeping":
            assert "theta_max" not in steps
            continue
        seen.add(nut.motion)
        assert steps["theta_max"].si[0] == pytest.approx(nut.theta_max, **close), path.name
        assert steps["theta_min"].si[0] == pytest.approx(nut.theta_min, **close), path.name
        assert steps["T"].value == pytest.approx(nut.nutation_period, **close), path.name
        m = steps["m"].value
        if m < 0.9:
            assert _ellipk(m) == pytest.approx(steps["K(m)"].value, rel=1e-12), path.name
        for k, u in enumerate(("u1", "u2")):
            rate = steps[f"phidot({u})"].value
            assert rate == pytest.approx(nut.limit_precession[k], **close), path.name
            root = nut.u_roots[k]
            if 1 - abs(root) > 1e-3:  # Eq. 11.16 as written, well conditioned there
                scale = abs(nut.beta) + abs(nut.gamma)
                assert rate == pytest.approx(N.phidot(nut, root), abs=1e-9 * scale), path.name
        if "theta_1" in steps:  # released from rest: Eq. 11.25 as printed
            u1 = steps["u1"].value
            assert u1 == pytest.approx(oracles.released_u1(top.I, top.J, top.mgl,
                                                           start.theta0, v["omega_z"]),
                                       rel=1e-9), path.name
            assert u1 == pytest.approx(nut.u_roots[0], rel=1e-9), path.name
            if 1 - abs(u1) > 1e-6:
                assert steps["theta_1"].si[0] == pytest.approx(nut.theta_max, rel=1e-9)
    assert {"cusps", "loops", "waves"} <= seen, seen


def _moments(region, n: int = 48) -> tuple[float, float]:
    """(J, I_G) per unit mass of a uniform body, by Gauss-Legendre quadrature over
    ``region``: (coordinates, weights) of its points as arrays, the axis along z."""
    (x, y, z), weight = region(n)
    mass = weight.sum()
    zc = (weight * z).sum() / mass
    J = (weight * (x * x + y * y)).sum() / mass
    I_G = (weight * (y * y + (z - zc) ** 2)).sum() / mass
    return J, I_G


def _gauss(a, b, n):
    import numpy as np

    t, w = np.polynomial.legendre.leggauss(n)
    return (a + b) / 2 + (b - a) / 2 * t, (b - a) / 2 * w


def _revolution(z0, z1, s_lo, s_hi):
    """A body of revolution: s_lo(z) <= s <= s_hi(z), z0 <= z <= z1 (dm ~ s ds dz, taken in
    the plane y = 0 with <x^2> = <y^2> = s^2 / 2 by symmetry)."""
    import numpy as np

    def region(n):
        zs, wz = _gauss(z0, z1, n)
        pts, ws = [], []
        for zk, wk in zip(zs, wz):
            s, w = _gauss(s_lo(zk), s_hi(zk), n)
            pts.append(np.stack([s / np.sqrt(2), s / np.sqrt(2), np.full_like(s, zk)]))
            ws.append(wk * w * s)
        return np.concatenate(pts, axis=1), np.concatenate(ws)
    return region


def _spherical(r_in, r_out):
    """A spherical shell r_in <= rho <= r_out (dm ~ rho^2 sin(phi) drho dphi)."""
    import numpy as np

    def region(n):
        rho, wr = _gauss(r_in, r_out, n)
        phi, wp = _gauss(0.0, np.pi, 2 * n)
        R, P = np.meshgrid(rho, phi)
        W = np.outer(wp, wr) * R ** 2 * np.sin(P)
        s = R * np.sin(P)
        return np.stack([s / np.sqrt(2), s / np.sqrt(2), R * np.cos(P)]).reshape(3, -1), W.ravel()
    return region


def _box(w, L):
    import numpy as np

    def region(n):
        a, wa = _gauss(-w / 2, w / 2, n)
        c, wc = _gauss(0.0, L, n)
        X, Y, Z = np.meshgrid(a, a, c, indexing="ij")
        W = np.einsum("i,j,k->ijk", wa, wa, wc)
        return np.stack([X, Y, Z]).reshape(3, -1), W.ravel()
    return region


THIN = 1e-10  # the thickness of a thin shape (ring, tube, spherical shell, disk), relative


@pytest.mark.parametrize("shape", ["disk", "ring", "cylinder", "sphere", "cone", "shell", "rod",
                                   "hollow_sphere", "box", "annulus"])
def test_body_shape_trees_agree_with_integrals_over_the_body(shape):
    """core/body.py's J and I_G of each shape, evaluated from their trees, against the
    moments integrated over the uniform solid by quadrature (a thin shape as a solid of
    relative thickness 1e-10)."""
    from gyro_cli.core.body import build_body
    from gyro_cli.core.work import Work

    m, r, ri, L, h, w = 2.0, 0.1, 0.06, 0.3, 0.2, 0.08
    values = {"mass": m, "shape": shape}
    region = {
        "disk": ({"radius": r}, _revolution(0.0, THIN * r, lambda z: 0.0, lambda z: r)),
        "ring": ({"radius": r}, _revolution(0.0, THIN * r, lambda z: r * (1 - THIN),
                                           lambda z: r)),
        "cylinder": ({"radius": r, "length": L}, _revolution(0.0, L, lambda z: 0.0,
                                                             lambda z: r)),
        "rod": ({"radius": r, "length": L}, _revolution(0.0, L, lambda z: 0.0, lambda z: r)),
        "sphere": ({"radius": r}, _spherical(0.0, r)),
        "hollow_sphere": ({"radius": r}, _spherical(r * (1 - THIN), r)),
        "cone": ({"radius": r, "height": h}, _revolution(0.0, h, lambda z: 0.0,
                                                         lambda z: r * z / h)),
        "shell": ({"radius": r, "length": L}, _revolution(0.0, L, lambda z: r * (1 - THIN),
                                                          lambda z: r)),
        "box": ({"width": w, "length": L}, _box(w, L)),
        "annulus": ({"radius": r, "inner_radius": ri, "length": L},
                    _revolution(0.0, L, lambda z: ri, lambda z: r)),
    }[shape]
    values |= region[0]
    work = Work()
    body = build_body(values, False, work)
    J, I_G = _moments(region[1])
    assert body.J == pytest.approx(m * J, rel=1e-9)
    assert body.I_cg == pytest.approx(m * I_G, rel=1e-9)
    steps = {s.symbol: s for s in work.sections[0].steps}
    assert steps["J"].expr is not None and steps["I_G"].expr is not None
    if shape == "cone":  # the apex at the fixed point: the centre of mass at 3 h / 4
        assert body.l == pytest.approx(0.75 * h, rel=1e-12)


TORQUE = """\
id: t
kind: gyroscopic_torque
given: {{{given}}}
find: [{find}]
"""


@pytest.mark.parametrize("given, find", [
    ("mass: 2.5 kg, k_axial: 35 mm, supported_mass: 10 kg, spin: -1725 rpm, precession: 48 rpm, "
     "bearing_spacing: 200 mm", "bearing_forces, moment"),
    ("mass: 3 kg, shape: disk, radius: 80 mm, spin: -3000 rpm, precession: 40 rpm, "
     "theta: 60 deg, bearing_spacing: 150 mm, cg_position: 50 mm, cg_radius: 120 mm, "
     "cg_offset: along", "moment, bearing_forces, axial_thrust"),
    ("mass: 3 kg, shape: disk, radius: 80 mm, spin: 3000 rpm, precession: -40 rpm, "
     "theta: 120 deg, bearing_spacing: 150 mm, cg_radius: 120 mm", "bearing_side_forces"),
    ("mass: 400 kg, k_axial: 0.3 m, spin: -2400 rpm, speed: 200 km/h, turn_radius: 50 m, "
     "turn: right, bearing_spacing: 1 m, cg_position: 0.3 m", "bearing_loads, axial_thrust"),
    ("J: 0.02 kg m^2, I_cg: 0.012 kg m^2, spin: 2000 rpm, moment: 3 N m, theta: 60 deg",
     "precession"),
    ("J: 0.02 kg m^2, I_cg: 0.012 kg m^2, spin: -2000 rpm, moment: 3 N m, theta: 130 deg",
     "precession"),
    ("J: 0.02 kg m^2, spin: 2000 rpm, moment: -3 N m", "precession"),
    ("J: 180 kg m^2, speed: 95 km/h, wheel_radius: 0.9 m, drop: 6 mm, drop_time: 0.1 s, "
     "bearing_spacing: 1.5 m", "couple_forces"),
    ("J: 180 kg m^2, speed: 95 km/h, wheel_radius: 0.9 m, drop: 6 mm, drop_length: 2 m, "
     "bearing_spacing: 1.5 m", "couple_forces"),
    ("mass: 2.2 kg, k_axial: 60 mm, spin: 1725 rpm, precession: 0.2 rad/s, counterweight: 0.5 kg, "
     "balance_position: 180 mm", "counterweight_position"),
])
def test_gyroscopic_torque_trees_agree_with_the_physics(given, find, tmp_path):
    """Each step from its tree against gyroscopic_torque's physics functions (Eq. 11.29
    generalised, the slow root, the free body of the rotor, the wheel's drop), with
    negative rates and angles past 90 deg among them."""
    import oracles

    from gyro_cli.kinds import gyroscopic_torque as K

    path = tmp_path / "t.yaml"
    path.write_text(TORQUE.format(given=given, find=find))
    result = solve_file(str(path))
    steps = [s for sec in result.solution.sections for s in sec.steps if s.expr is not None]
    by = {s.symbol: s.value for s in steps}
    v = _symbol_values(result)
    th = v.get("theta", math.pi / 2)
    J, I = v["J"], v.get("I", 0.0)
    if "psidot" in by and "v" in v and "r_w" in v:
        assert by["psidot"] == pytest.approx(v["v"] / v["r_w"], rel=1e-12)
    if "t" in by:
        assert by["Omega"] == pytest.approx(oracles.tilt_rate_uniform(v["h"], v["v"], v["s"], v["L"]),
                                            rel=1e-12)
    if "ydot_max" in by:
        assert by["Omega"] == pytest.approx(oracles.tilt_rate_harmonic(v["h"], v["T_d"], v["L"]),
                                            rel=1e-12)
    if "R" in v and "Omega" in by:
        sign = -1 if "right" in given else 1
        assert by["Omega"] == pytest.approx(sign * v["v"] / v["R"], rel=1e-12)
    if "moment:" in given:
        roots = K.precession_for_moment(J, I, v["psidot"], th, v["M"])
        assert by["Omega"] == pytest.approx(min(roots, key=abs), rel=1e-12)
    Omega = by.get("Omega", v.get("Omega"))
    M = oracles.gyroscopic_moment(J, I, v["psidot"], Omega, th)
    assert by["M"] == pytest.approx(M, rel=1e-12)
    if "F_A,weight" in by:
        m = v.get("m_s", v.get("m"))
        forces = K.bearing_forces(m, v["g"], M, v["L"], v["a"], Omega, th, v.get("R", 0.0),
                                  "along" if "along" in given else "across")
        assert (by["F_A,weight"], by["F_B,weight"]) == pytest.approx(forces.weight, rel=1e-12)
        assert (by["F_A"], by["F_B"]) == pytest.approx(forces.up, rel=1e-12)
        assert by["T"] == pytest.approx(forces.thrust, rel=1e-12, abs=1e-12)
        if "F_A,accel" in by:
            assert (by["F_A,accel"], by["F_B,accel"]) == pytest.approx(forces.inertial, rel=1e-12)
        if "F_A,side" in by:
            assert (by["F_A,side"], by["F_B,side"]) == pytest.approx(forces.side, rel=1e-12)
    if "F_A,couple" in by:
        assert (by["F_A,couple"], by["F_B,couple"]) == pytest.approx(
            K.couple_forces(M, v["L"]), rel=1e-12)
    if "db" in by:
        assert by["db"] == pytest.approx(oracles.counterweight_offset(M, v["m_c"], v["g"]), rel=1e-12)
    assert steps


SWING = """\
id: s
kind: swinging_rotor
given: {{{given}}}
find: [bearing_forces, angular_rate]
"""


def _lets(node):
    """Every `Let` of a tree (a quantity shown by its definition in the formula)."""
    from gyro_cli.core import expr as E

    if isinstance(node, E.Let):
        yield node
    for child in node.children():
        yield from _lets(child)


@pytest.mark.parametrize("given", [
    "mass: 2 kg, shape: disk, radius: 100 mm, spin: 300 rad/s, arm_length: 250 mm, "
    "bearing_spacing: 200 mm, theta: 90 deg",
    "mass: 3 kg, shape: ring, radius: 120 mm, spin: -200 rad/s, arm_length: 300 mm, "
    "bearing_spacing: 250 mm, arm_position: 60 mm, theta: 135 deg, theta0: 30 deg",
    "mass: 3 kg, k_axial: 50 mm, k_cg: 40 mm, spin: 200 rad/s, arm_length: 300 mm, "
    "bearing_spacing: 250 mm, theta: 200 deg, theta0: 10 deg",
])
def test_swinging_rotor_trees_agree_with_the_physics(given, tmp_path):
    """Each step from its tree (both forms of the two-form steps) against swing_forces,
    and every part shown by its definition (the expanded formulas of 11/8) evaluated from
    that definition against the value it stands for."""
    from gyro_cli.core import expr as E
    from gyro_cli.kinds import swinging_rotor as K

    path = tmp_path / "s.yaml"
    path.write_text(SWING.format(given=given))
    result = solve_file(str(path))
    steps = [s for sec in result.solution.sections for s in sec.steps if s.expr is not None]
    by = {s.symbol: s for s in steps}
    v = _symbol_values(result)
    m, g, L, d, p = v["m"], v["g"], v["L"], v["d"], v["p"]
    th0, th = v["theta0"], v["theta"]
    J, I_G = v["J"], by["I_G"].value
    a = v["a/d"] * d
    f = K.swing_forces(m, g, J, I_G, p, L, d, a, th0, th)
    I_O = I_G + m * L * L
    assert by["I_O"].value == pytest.approx(I_O, rel=1e-12)
    for symbol, expected in (("I_O", I_O), ("thetadot^2", K.swing_rate_sq(m, g, L, I_O, th0, th)),
                             ("thetaddot", K.swing_acceleration(m, g, L, I_O, th))):
        chain = by[symbol].expr
        assert isinstance(chain, E.Chain) and len(chain.forms) == 2
        for form in chain.forms:
            assert form.value == pytest.approx(expected, rel=1e-12, abs=1e-12), symbol
    assert by["J p thetadot / d"].value == pytest.approx(f.couple, rel=1e-12, abs=1e-12)
    for k, end in enumerate("AB"):
        assert by[f"F_{end},arm"].value == pytest.approx(f.arm[k], rel=1e-12)
        assert by[f"F_{end},normal"].value == pytest.approx(f.normal[k], rel=1e-12, abs=1e-12)
        assert by[f"|F_{end}|"].value == pytest.approx(f.magnitudes[k], rel=1e-12)
    lets = [let for s in steps for let in _lets(s.expr)]
    assert {let.sym.name for let in lets} >= {"I_O/m", "S_arm", "S_normal", "F_couple", "b/d"}
    for let in lets:
        assert let.body.value == pytest.approx(let.sym.si, rel=1e-9, abs=1e-12), let.sym.name


def test_a_steps_init_takes_every_field_of_the_dataclass():
    """Step's __init__ is written out (core/work.py, _step_init) to store the printed
    fields directly: it must take exactly the dataclass's fields, in order, with their
    defaults, or a field added later would be left unset."""
    import dataclasses
    import inspect

    from gyro_cli.core.work import Step

    params = list(inspect.signature(Step.__init__).parameters.values())[1:]
    fields = dataclasses.fields(Step)
    assert [p.name for p in params] == [f.name for f in fields]
    assert [p.default for p in params] == [f.default for f in fields]
    step = Step()
    assert all(getattr(step, f.name) == f.default for f in fields)
