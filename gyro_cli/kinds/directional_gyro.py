"""The directional gyro on the rotating Earth, as pilot-licence exams ask about it.

Section 11.3 (Fig. 11-13): a gyroscope that feels no moment stays fixed in inertial
space. A directional gyro's horizontal spin axis therefore drifts against north,
which turns about the local vertical at Omega_E sin(lambda) (the Earth) plus
l' sin(lambda) (the craft's own change of longitude): to the right in the northern
hemisphere, to the left in the southern. A latitude nut precesses the axis back
(Eq. 11.29, rate = M / H) at Omega_E sin(lambda_n). The derivation is in
gyro_cli/physics/directional_gyro.py.
"""

from __future__ import annotations

import math

from ..core.errors import InputError
from ..core.expr import Expr, Let, Sym, cos, sin, tan
from ..core.given import Given
from ..core.prose import names, q, rel
from ..core.spec import AnswerSpec, Kind, Param
from ..core.work import Work, num
from ..physics import directional_gyro as dg

DEG_H = math.pi / 180 / 3600  # rad/s per deg/h
KNOT = 1852.0 / 3600  # m/s

#: the symbols the sentences name (values are in the steps' trees)
E0, N0, U0, W0, lam0, R0 = names("E N U Omega_E lambda R")

# The sentences that hold no values are built once, here.
_AXES = (E0, ", ", N0, ", ", U0, ": east, north and up at the craft. A drift is the turn "
         "of the spin axis relative to north about ", U0, ", positive to the right (clockwise "
         "seen from above); latitudes are positive north, speeds positive east.")
_RIGIDITY = ("With no moment about the horizontal (inner) gimbal axis the spin axis keeps its "
             "azimuth in inertial space (section 11.3, Fig. 11-13: a moment about an axis turns "
             "the spin axis about the axis at right angles to both); north turns under it, so "
             "the axis drifts against north the other way.")
_EARTH = ("The Earth turns at ", W0, " about its axis; the part about the local vertical is ",
          W0 * sin(lam0), ", anticlockwise seen from above in the northern hemisphere.")
_NUT = ("The latitude nut is a weight on the inner gimbal: its moment about the horizontal "
        "gimbal axis precesses the spin axis about the vertical at the rate the moment divided "
        "by the spin angular momentum (Eq. 11.29), set to cancel the Earth's drift at its "
        "latitude.")
_HEADING = ("the heading the gyro reads is measured from its spin axis, so the reading moves "
            "opposite to the drift")


def solve(given: Given, find: frozenset[str], work: Work) -> None:
    lat = _latitude(given)
    Omega = given["earth_rate"]
    work.section("Conventions")
    work.text(*_AXES)
    work.text(*_RIGIDITY)
    lam, W = Sym("lambda", lat, "deg"), Sym("Omega_E", Omega, "deg/h")
    work.section("Apparent drift from the Earth's rotation")
    work.text(*_EARTH)
    earth = work.step("D_E", dg.earth_rate_drift(W, lam), unit="deg/h") * DEG_H
    work.answer("earth_rate_drift", "D_E", [earth], "rate")
    parts = [("D_E", earth)]
    transport = _transport(given, find, lat, work)
    if transport is not None:
        parts.append(("D_T", transport))
    nut = _nut(given, find, W, work)
    if nut is not None:
        parts.append(("D_N", nut))
    _total(given, find, parts, work)


def _latitude(given: Given) -> float:
    """The latitude, signed by the hemisphere when that is given as a word."""
    lat = given["latitude"]
    side = given.word("hemisphere")
    if side is not None:
        if lat < 0:
            raise InputError("a negative latitude and a hemisphere together: give the "
                             "latitude's size with the hemisphere, or a signed latitude alone",
                             key="given.hemisphere")
        lat = lat if side == "north" else -lat
    return lat


def _east_speed(given: Given) -> float | None:
    """The craft's eastward speed from ground_speed with direction or track; None if still."""
    if "ground_speed" not in given:
        for key in ("direction", "track"):
            if key in given:
                raise InputError(f"{key} needs ground_speed", key="given.ground_speed")
        return None
    if ("direction" in given) == ("track" in given):
        raise InputError("give the way the craft flies: direction (east, west, north or south) "
                         "or track (true, from north), one of them",
                         key="given.track" if "track" in given else "given.direction")
    speed = given["ground_speed"]
    if "track" in given:
        return speed * math.sin(given["track"])
    return speed * {"east": 1.0, "west": -1.0}.get(given.word("direction") or "", 0.0)


_TRANSPORT = ("Moving east along its parallel, of radius ", R0 * cos(lam0),
              ", the craft changes its longitude, which turns north about the polar axis as the "
              "Earth does; only the part about ", U0, " moves the reading. Moving north or "
              "south turns the frame about the east axis and gives no drift.")

_OVER_LONGITUDE = ("A change of longitude turns north about the polar axis as the Earth does; "
                   "only its part about ", U0, " moves the reading. A change of latitude turns "
                   "the frame about the east axis and gives no drift.")


def _transport(given: Given, find: frozenset[str], lat: float, work: Work) -> float | None:
    """Transport wander, right positive, rad/s; None for a craft at rest."""
    v_east = _east_speed(given)
    if "longitude_change" in given:
        if v_east is not None:
            raise InputError("give ground_speed or longitude_change, not both",
                             key="given.longitude_change")
        return _transport_over_longitude(given, find, lat, work)
    if v_east is None:
        if {"transport_wander", "transport_wander_angle"} & find:
            raise InputError("transport wander needs the craft's motion: ground_speed with "
                             "direction or track, or longitude_change", key="given.ground_speed")
        return None
    work.section("Transport wander")
    radius = _radius(given, work)
    work.text(*_TRANSPORT)
    if v_east and math.cos(lat) < 1e-12:
        raise InputError("at a pole there is no east: a craft cannot fly east or west there",
                         key="given.latitude")
    lam, R = Sym("lambda", lat, "deg"), Sym("R", radius, "m")
    V = Sym("V", given["ground_speed"], "m/s")
    if "track" in given:
        work.step("v_E", V * sin(Sym("TR", given["track"], "deg")), unit="m/s",
                  note=("the east component of the ground speed",))
    elif given.word("direction") in ("north", "south"):
        work.text("flying north or south the longitude does not change: no transport wander")
        _transport_answers(given, 0.0, work)
        return 0.0
    else:
        work.step("v_E", V if v_east >= 0 else -V, unit="m/s",
                  note=(f"flying {given.word('direction')}",))
    v = Sym("v_E", v_east, "m/s")
    rate = work.step("l'", dg.longitude_rate(v, R, lam), unit="deg/h",
                     note=("the rate of change of longitude, east positive",))
    wander = work.step("D_T", dg.transport_wander(Let(Sym("l'", rate * DEG_H, "deg/h"),
                                                      dg.longitude_rate(v, R, lam)), lam),
                       unit="deg/h") * DEG_H
    if "earth_radius" not in given:
        kt = v_east / KNOT  # the rule as pilots learn it, with the speed in knots
        V_kt = Sym("V_kt", kt, "")
        work.check("the pilots' rule: ", rel(V_kt / 60 * tan(lam), "=",
                                            q(kt / 60 * math.tan(lat) * DEG_H, "deg/h")),
                   ", with the east speed in knots ", rel(V_kt, "=", round(kt, 4)))
    _transport_answers(given, wander, work)
    return wander


def _radius(given: Given, work: Work) -> float:
    """The Earth's radius: given, or the sphere whose arc minute is a nautical mile."""
    if "earth_radius" in given:
        return given["earth_radius"]
    return work.step("R", value=dg.NAUTICAL_EARTH_RADIUS, unit="m",
                     note=("the sphere whose arc minute is one nautical mile, as pilots' rules "
                           "take it",))


def _transport_over_longitude(given: Given, find: frozenset[str], lat: float,
                              work: Work) -> float | None:
    """Transport wander over a whole change of longitude (l_2 - l_1) sin(lambda)."""
    work.section("Transport wander over the change of longitude")
    work.text(*_OVER_LONGITUDE)
    lam, dl = Sym("lambda", lat, "deg"), Sym("dl", given["longitude_change"], "deg")
    angle = work.step("A_T", dg.transport_wander(dl, lam), unit="deg") * math.pi / 180
    work.answer("transport_wander_angle", "A_T", [angle], "angle")
    if "duration" not in given:
        if {"transport_wander", "drift_rate", "drift_angle", "reading_change",
                "indicated_heading"} & find:
            raise InputError("a change of longitude needs the flight's duration for a rate",
                             key="given.duration")
        return None
    t = given["duration"]
    if t == 0:
        raise InputError("a change of longitude in no time: give a duration > 0",
                         key="given.duration")
    wander = work.step("D_T", Sym("A_T", angle, "deg") / Sym("t", t, "h"), unit="deg/h") * DEG_H
    work.answer("transport_wander", "D_T", [wander], "rate")
    return wander


def _transport_answers(given: Given, wander: float, work: Work) -> None:
    work.answer("transport_wander", "D_T", [wander], "rate")
    if "duration" in given:
        angle = work.step("A_T", Sym("D_T", wander, "deg/h") * Sym("t", given["duration"], "h"),
                          unit="deg") * math.pi / 180
        work.answer("transport_wander_angle", "A_T", [angle], "angle")


def _nut(given: Given, find: frozenset[str], W: Sym, work: Work) -> float | None:
    """The latitude nut's correction, right positive, rad/s; None without a nut."""
    if "latitude_nut" not in given:
        if {"nut_correction", "nut_moment"} & find:
            raise InputError("no latitude nut is given: give latitude_nut, the latitude it is "
                             "set for", key="given.latitude_nut")
        return None
    work.section("Latitude nut")
    work.text(*_NUT)
    lam_n = Sym("lambda_n", given["latitude_nut"], "deg")
    nut = work.step("D_N", dg.nut_correction(W, lam_n), unit="deg/h") * DEG_H
    work.answer("nut_correction", "D_N", [nut], "rate")
    H = _momentum(given, work)
    if H is not None:
        M = work.step("M_n", dg.nut_moment(Sym("H", H, "kg m^2/s"), Sym("Omega_E", W.si, "rad/s"),
                                           lam_n), unit="N*m", note=("the moment of the nut about the horizontal "
                                                    "gimbal axis",))
        work.answer("nut_moment", "M_n", [M], "moment")
    elif "nut_moment" in find:
        raise InputError("the nut's moment needs the rotor: angular_momentum, or J with spin",
                         key="given.angular_momentum")
    return nut


def _momentum(given: Given, work: Work) -> float | None:
    if "angular_momentum" in given:
        if "J" in given or "spin" in given:
            raise InputError("give angular_momentum, or J with spin, not both",
                             key="given.angular_momentum")
        return given["angular_momentum"]
    if ("J" in given) != ("spin" in given):
        raise InputError("the rotor needs both J and spin", key="given.spin" if "J" in given
                         else "given.J")
    if "J" not in given:
        return None
    return work.step("H", Sym("J", given["J"], "kg m^2") * Sym("psidot", given["spin"], "rad/s"),
                     unit="kg m^2/s")


def _total(given: Given, find: frozenset[str], parts: list[tuple[str, float]],
           work: Work) -> None:
    work.section("Drift of the spin axis")
    total_tree: Expr = Sym(parts[0][0], parts[0][1], "deg/h")
    for name, value in parts[1:]:
        total_tree = total_tree + Sym(name, value, "deg/h")
    D = work.step("D", total_tree, unit="deg/h", substitute=len(parts) > 1) * DEG_H
    sense = "right" if D > 0 else "left" if D < 0 else "none"
    reading = {"right": "decreases", "left": "increases", "none": "stays"}[sense]
    work.text(_said(sense, D), "; ", _HEADING, f": it {reading}.")
    work.answer("drift_rate", "D", [D], "rate")
    work.answer("drift_sense", "sense", [sense], None)
    work.answer("reading", "reading", [reading], None)
    if "duration" not in given:
        asked = sorted({"drift_angle", "reading_change", "indicated_heading"} & find)
        if asked:
            raise InputError(f"{asked[0]} needs the time: give duration", key="given.duration")
        return
    t = given["duration"]
    angle = work.step("A", Sym("D", D, "deg/h") * Sym("t", t, "h"), unit="deg") * math.pi / 180
    work.answer("drift_angle", "A", [angle], "angle")
    work.answer("reading_change", "-A", [-angle], "angle")
    if "initial_heading" in given:
        _heading(given, angle, work)
    elif "indicated_heading" in find:
        raise InputError("indicated_heading needs the reading at the start: give "
                         "initial_heading", key="given.initial_heading")


def _heading(given: Given, angle: float, work: Work) -> None:
    start, turn = given["initial_heading"], given.get("heading_change", 0.0) or 0.0
    psi_0, A = Sym("psi_0", start, "deg"), Sym("A", angle, "deg")
    if "heading_change" in given:
        h = work.step("psi_DI", psi_0 + Sym("dpsi", turn, "deg") - A, unit="deg",
                      note=("the reading at the start, plus the turn of the craft's true "
                            "heading, less the drift",)) * math.pi / 180
    else:
        h = work.step("psi_DI", psi_0 - A, unit="deg",
                      note=("the reading at the start less the drift (the true heading held)",)
                      ) * math.pi / 180
    wrapped = dg.heading_after(start, turn, angle)
    if abs(wrapped - h) > 1e-12:
        work.step("psi_DI", value=math.degrees(wrapped), unit="deg",
                  note=("on the dial, between 0 and 360 deg",))
    work.answer("indicated_heading", "psi_DI", [wrapped], "angle")


def _said(sense: str, D: float) -> str:
    if sense == "none":
        return "No drift"
    way = "clockwise" if sense == "right" else "anticlockwise"
    return f"The spin axis drifts {num(abs(D) / DEG_H)} deg/h to the {sense} ({way} seen from above)"


_HEMISPHERES = (("n", "north"), ("s", "south"), ("northern", "north"), ("southern", "south"),
                ("nh", "north"), ("sh", "south"), ("northern_hemisphere", "north"),
                ("southern_hemisphere", "south"))
_DIRECTIONS = tuple((f"{way}{end}", way) for way in ("east", "west", "north", "south")
                    for end in ("bound", "erly", "ward", "wards")) + \
    (("e", "east"), ("w", "west"), ("n", "north"), ("s", "south"))

KIND = Kind(
    name="directional_gyro",
    summary="directional gyro on the rotating Earth: apparent drift 15.04 deg/h sin(latitude), "
            "latitude nut, transport wander, the reading after a flight",
    chapter="section 11.3, the gyroscope as an inertial reference (Fig. 11-13); the nut by "
            "Eq. 11.29",
    uses_body=False,
    params=(
        Param("latitude", "angle", "lambda", "latitude of the craft (the mean latitude of a "
              "flight): '30 S', '45 deg N' or signed, north positive",
              range=(-math.pi / 2, math.pi / 2), hemisphere="NS", required=True),
        Param("hemisphere", "word", "hemisphere", "north or south, with a latitude written "
              "without one", choices=("north", "south"), words=_HEMISPHERES),
        Param("latitude_nut", "angle", "lambda_n", "latitude the nut is set for: '50 N'; no "
              "nut if absent", range=(-math.pi / 2, math.pi / 2), hemisphere="NS"),
        Param("ground_speed", "speed", "V", "the craft's ground speed, e.g. '400 kt'",
              nonnegative=True),
        Param("direction", "word", "direction", "east, west, north or south: the way the craft "
              "flies", choices=("east", "west", "north", "south"), words=_DIRECTIONS),
        Param("track", "angle", "TR", "instead of direction: the true track, clockwise from "
              "north", range=(0.0, 2 * math.pi), bounds="[)"),
        Param("longitude_change", "angle", "dl", "instead of ground_speed: the change of "
              "longitude over the flight, '20 deg E' or east positive", hemisphere="EW"),
        Param("duration", "time", "t", "time of the flight or the wait, for the drift angle",
              nonnegative=True),
        Param("initial_heading", "angle", "psi_0", "the gyro's reading at the start",
              range=(0.0, 2 * math.pi), bounds="[]"),
        Param("heading_change", "angle", "dpsi", "change of the craft's true heading over the "
              "flight (0 if absent)"),
        Param("angular_momentum", "angular_momentum", "H", "the rotor's spin angular momentum, "
              "for the nut's moment"),
        Param("J", "inertia", "J", "the rotor's moment of inertia about its axis (with spin)",
              positive=True),
        Param("spin", "rate", "psidot", "the rotor's spin (with J)"),
        Param("earth_rate", "rate", "Omega_E", "the Earth's rate of rotation (sidereal, 15.041 "
              "deg/h; books often round it to 15 deg/h)", default="7.292115e-5 rad/s",
              positive=True),
        Param("earth_radius", "length", "R", "radius of the Earth; if absent, the sphere "
              "whose arc minute is one nautical mile, 6366.7 km", positive=True),
    ),
    answers=(
        AnswerSpec("drift_rate", "rate", "D", "the drift of the spin axis against north, "
                   "right (clockwise seen from above) positive: the sum of the parts"),
        AnswerSpec("drift_sense", None, "sense", "right, left or none"),
        AnswerSpec("reading", None, "reading", "what the heading reading does: decreases, "
                   "increases or stays"),
        AnswerSpec("earth_rate_drift", "rate", "D_E", "apparent drift, Omega_E sin(lambda)"),
        AnswerSpec("transport_wander", "rate", "D_T", "drift from the change of longitude, "
                   "v_E tan(lambda) / R"),
        AnswerSpec("transport_wander_angle", "angle", "A_T", "transport wander over the flight, "
                   "(l_2 - l_1) sin(lambda)"),
        AnswerSpec("nut_correction", "rate", "D_N", "the latitude nut's drift, "
                   "-Omega_E sin(lambda_n)"),
        AnswerSpec("nut_moment", "moment", "M_n", "the nut's moment, H Omega_E sin(lambda_n)"),
        AnswerSpec("drift_angle", "angle", "A", "drift over duration, right positive"),
        AnswerSpec("reading_change", "angle", "-A", "change of the heading reading over "
                   "duration"),
        AnswerSpec("indicated_heading", "angle", "psi_DI", "the reading at the end, 0 to "
                   "360 deg"),
    ),
    solve=solve,
    example={
        "statement": ("A directional gyro has its latitude nut set for {latitude_nut}. The "
                      "aircraft flies {direction} at a ground speed of {ground_speed} along "
                      "the parallel of {latitude} for {duration}; the gyro read "
                      "{initial_heading} at the start. Find the rate and the sense of the "
                      "drift, the transport wander, and what the gyro reads at the end."),
        "given": {"latitude": "45 N", "latitude_nut": "45 N", "ground_speed": "400 kt",
                  "direction": "east", "duration": "2 h", "initial_heading": "90 deg"},
        "find": {"drift_rate": "deg/h", "drift_sense": None, "transport_wander": "deg/h",
                 "indicated_heading": "deg"},
        "vary": {"ground_speed": "[0.8, 1.2]"}},
)
