"""The edge-runner (muller) mill: the gyroscopic couple of a roller rolling round a pan adds
to its pressure on the pan.

Each roller turns on a horizontal axle hinged to the vertical shaft and rolls without
slipping on the pan at the path radius R; its spin omega = Omega R / r turns with the
shaft at Omega, so the roller needs the couple C = J omega Omega (Eq. 11.29), which only
the pan's force can give (moments about the hinge): N = m g + C / R. The derivation is in
gyro_cli/physics/edge_runner.py.

Reference: R.S. Khurmi and J.K. Gupta, "Theory of Machines", ch. 14 (applications of the
gyroscopic couple); S.S. Rattan, "Theory of Machines", ch. 14.
"""

from __future__ import annotations

import math

from ..core.errors import InputError, refuse_overflow
from ..core.expr import Sym
from ..core.given import Given
from ..core.prose import names, q, rel
from ..core.spec import AnswerSpec, Kind, Param
from ..core.work import Work
from ..physics import edge_runner as P

#: the symbols the sentences name (values are in the steps' trees)
O0, R0, r0, W0, N0, C0, P0, H0, Om0, J0 = names("O R r W N C P H Omega J")

_SETUP = ("Each roller turns freely on a horizontal axle hinged to the vertical shaft at ", O0,
          ", on the shaft's axis, so that it can rise and fall; it rolls without slipping on "
          "the pan at the path radius ", R0, " from the shaft's axis (its own radius is ", r0,
          "). The hinge pin carries the roller's centripetal force; the pan pushes only "
          "upward, with ", N0, ".")
_SPIN = ("rolling without slipping: the contact point is at rest, so the roller's spin ",
         names("omega")[0], " makes its rim speed equal to the speed of its centre, ",
         rel(names("omega")[0] * r0, "=", Om0 * R0))
_TURNS = (H0, ", the roller's spin angular momentum, lies along the axle and turns with the "
          "shaft at ", Om0, " about the vertical: it changes at the rate of the couple below, "
          "about the horizontal axis across the axle")
_MOMENTS = ("moments about the hinge ", O0, " (the pin gives none about the axis across the "
            "axle), with ", W0, " the roller's weight: ", rel((N0 - W0) * R0, "=", C0), ". The couple presses the roller down on "
            "the pan whichever way the shaft turns.")


def solve(given: Given, find: frozenset[str], work: Work) -> None:
    body = given.body
    assert body is not None  # the kind has body keys: the loader builds it
    body.require("J", "radius")
    J, r = body.J, body.radius
    assert J is not None and r is not None  # required above
    for key in ("shaft_speed", "path_radius"):
        if key not in given:
            raise InputError("the mill needs shaft_speed (the vertical shaft's speed) and "
                             "path_radius (shaft axis to the roller's line of contact)",
                             key=f"given.{key}")
    Omega, R = given["shaft_speed"], given["path_radius"]
    n = given["rollers"] if "rollers" in given else 1
    omega = P.roller_spin(Omega, R, r)
    C = P.couple(J, omega, Omega)
    extra = P.extra_pressure(C, R)
    refuse_overflow(C, extra)

    work.section("The mill")
    work.text(*_SETUP)
    work.section("Roller")
    work.step("J", value=J, unit="kg*m^2", note="the roller's moment of inertia about its axle")
    work.step("Omega", value=Omega, unit="rad/s", note="speed of the vertical shaft: the "
              "precession")
    work.text(*_SPIN)
    Om_, R_, r_ = Sym("Omega", Omega, "rad/s"), Sym("R", R, "m"), Sym("r", r, "m")
    work.step("omega", P.roller_spin(Om_, R_, r_), unit="rad/s", note="the roller's spin")
    work.answer("roller_spin", "omega", [omega], "rate")

    work.section("Gyroscopic couple")
    work.text(*_TURNS)
    work.step("C", P.couple(Sym("J", J, "kg m^2"), Sym("omega", omega, "rad/s"), Om_), unit="N*m",
              ref="Eq. 11.29")
    work.answer("couple", "C", [C], "moment")

    work.section("Pressure on the pan")
    work.text(*_MOMENTS)
    work.step("P", P.extra_pressure(Sym("C", C, "N m"), R_), unit="N",
              note="the couple's share of the pressure on the pan")
    work.answer("extra_pressure", "P", [extra], "force")
    work.check(rel(P0, "=", q(extra, "N"), "=", J0 * Om0 ** 2 / r0, "=",
                   q(J * Omega * Omega / r, "N")))
    if {"pan_force", "total_pan_force"} & find:
        W = body.weight
        N = P.pan_force(W, extra)
        work.step("W", Sym("m", body.m, "kg") * Sym("g", body.g, "m/s^2"), unit="N",
                  note="the roller's weight")
        work.step("N", P.pan_force(Sym("W", W, "N"), Sym("P", extra, "N")), unit="N",
                  note="the pan's force on each roller, and the roller's on the pan")
        work.answer("pan_force", "N", [N], "force")
        total = n * N
        if n != 1:
            work.step("N_total", Sym("n", n) * Sym("N", N, "N"), unit="N",
                      note=f"the {num_word(n)} rollers together")
        work.answer("total_pan_force", "N_total", [total], "force")


def num_word(n: float) -> str:
    return {2: "two", 3: "three", 4: "four"}.get(int(n), f"{n:g}")


KIND = Kind(
    name="edge_runner",
    summary="an edge-runner (muller) mill: the gyroscopic couple of each roller rolling round "
            "the pan and the extra pressure it gives on the pan",
    chapter="Eq. 11.29, C = omega_p x H; Khurmi, Theory of Machines, ch. 14",
    params=(
        Param("shaft_speed", "rate", "Omega", "speed of the vertical shaft that carries the "
              "rollers round (the precession)", positive=True),
        Param("path_radius", "length", "R", "radius of the roller's path: the vertical shaft's "
              "axis to the roller's line of contact on the pan (its mid-plane)", positive=True),
        Param("rollers", "dimensionless", "n", "number of rollers, for total_pan_force (one if "
              "absent)", range=(1.0, math.inf), bounds="[)", whole=True,
              reason="rollers is a count (1, 2, ...)"),
    ),
    answers=(
        AnswerSpec("roller_spin", "rate", "omega", "the roller's spin about its axle, "
                   "Omega R / r (rolling)"),
        AnswerSpec("couple", "moment", "C", "gyroscopic couple on each roller, J omega Omega"),
        AnswerSpec("extra_pressure", "force", "P", "the couple's addition to each roller's "
                   "pressure on the pan, C / R = J Omega^2 / r"),
        AnswerSpec("pan_force", "force", "N", "each roller's whole pressure on the pan, its "
                   "weight plus C / R"),
        AnswerSpec("total_pan_force", "force", "N_total", "all the rollers' pressure on the "
                   "pan, n (m g + C / R)"),
    ),
    solve=solve,
    gravity=True, body_keys=("mass", "weight", "g", "J", "k_axial", "shape", "radius",
                             "diameter", "length"),
    example={
        "statement": ("Each of the {rollers} rollers of an edge-runner mill has a mass of "
                      "{mass}, a diameter of {diameter} and a radius of gyration of {k_axial} "
                      "about its axle. The rollers run on a path of mean radius {path_radius} "
                      "and the vertical shaft turns at {shaft_speed}. Find the gyroscopic "
                      "couple on each roller and the total pressure on the pan."),
        "given": {"mass": "600 kg", "diameter": "1.2 m", "k_axial": "0.45 m",
                  "path_radius": "0.6 m", "shaft_speed": "30 rpm", "rollers": 2},
        "find": {"couple": "N*m", "extra_pressure": "N", "total_pan_force": "kN"},
        "vary": {"shaft_speed": "[0.8, 1.2]"}},
)
