"""The precession of the equinoxes: an oblate planet as a top (section 11.3).

The Sun and the Moon pull on the Earth's equatorial bulge; the orbit-averaged
torque, from the planet's quadrupole (MacCullagh's formula), turns the spin
angular momentum C omega about the normal of each body's orbit, a steady
precession in the chapter's sense (dH/dt = T, Eqs. 11.27-11.29 with the torque
given). For each torquing body

    Omega_p = (3/2) (G M_b / a^3) (1 - e^2)^(-3/2) H cos(epsilon) (1 - (3/2) sin^2(i)) / omega,

H = (C - A) / C the dynamical ellipticity, eps the obliquity, i the
inclination of the body's orbit to the reference plane (averaged over its
turning node), and G M_b / a^3 = n_b^2 q / (1 + q) by Kepler's third law.
The derivation is in gyro_cli/physics/earth_precession.py and docs/applications.md.
"""

from __future__ import annotations

import math
import operator
from functools import cache, reduce

from ..core.errors import InputError
from ..core.expr import NAMED, PI, Const, Expr, Let, Num, Sym, absolute, cos, sin
from ..core.given import Given
from ..core.prose import cross, dot, names, paren, q, rel
from ..core.spec import AnswerSpec, Kind, Param
from ..core.work import Work, num
from ..physics.earth_precession import ARCSEC, JULIAN_YEAR, G

DAY = 86400.0
BODIES = ("sun", "moon")
BODY_NAMES = {"sun": "the Sun", "moon": "the Moon"}

# preset: earth. IERS Conventions (2010), Table 1.1 (H, eps0, G M_E, the Moon/Earth
# mass ratio), the IAU 2009 system of astronomical constants (Sun/Earth mass ratio),
# and mean orbital elements at J2000 (Simon et al. 1994; the Astronomical Almanac).
EARTH = {
    "dynamical_ellipticity": 0.003273795,
    "obliquity": math.radians(84381.406 / 3600),   # 23.4392794 deg
    "rotation_period": 86164.0905,                   # sidereal day, s
    "planet_mass": 3.986004418e14 / G,               # G M_E / G
    "sun_mass_ratio": 332946.0487,
    "sun_orbital_period": 365.256363004 * DAY,       # sidereal year
    "sun_eccentricity": 0.0167086,
    "sun_inclination": 0.0,                          # the ecliptic is the reference plane
    "moon_mass_ratio": 0.0123000371,
    "moon_orbital_period": 27.321661 * DAY,          # sidereal month
    "moon_eccentricity": 0.0549,
    "moon_inclination": math.radians(5.145),
}
def _preset_text() -> dict[str, tuple]:
    """How the preset's values are written (each number as its source gives it)."""
    G_, M_E = names("G M")

    def given(label: str, unit: str = "", note: str = "") -> tuple:
        value = float(label) * (math.pi / 180 if unit == "deg" else DAY if unit == "d" else 1)
        return (q(value, unit, label=label),) + ((note,) if note else ())

    obliquity = EARTH["obliquity"]
    return {
        "dynamical_ellipticity": given("0.003273795", "", " (IERS 2010)"),
        "obliquity": (q(obliquity, "arcsec", label="84381.406"), "=",
                      q(obliquity, "deg", label="23.43928"), " (IERS 2010, J2000)"),
        "rotation_period": given("86164.0905", "s", " (sidereal day)"),
        "planet_mass": (q(3.986004418e14, "m^3/s^2", label="3.986004418e14") / G_,
                        " (the Earth's ", G_ * M_E, ", IERS 2010; ", G_,
                        ": the constant of gravitation)"),
        "sun_mass_ratio": given("332946.0487", "", " (IAU 2009)"),
        "sun_orbital_period": given("365.256363", "d", " (sidereal year)"),
        "sun_eccentricity": given("0.0167086", "", " (J2000)"),
        "sun_inclination": given("0", "deg", " (the ecliptic)"),
        "moon_mass_ratio": given("0.0123000371", "", " (IERS 2010)"),
        "moon_orbital_period": given("27.321661", "d", " (sidereal month)"),
        "moon_eccentricity": given("0.0549", "", " (mean)"),
        "moon_inclination": given("5.145", "deg", " (mean, to the ecliptic)"),
    }

# Keys that say the same thing: the preset fills a group only if the file gives none of it.
GROUPS = [("dynamical_ellipticity", "J2", "polar_moment_factor"),
          ("rotation_period", "rotation_rate"), ("obliquity",), ("planet_mass",)]
for _b in BODIES:
    GROUPS += [(f"{_b}_mass_ratio", f"{_b}_mass"), (f"{_b}_orbital_period", f"{_b}_distance"),
               (f"{_b}_eccentricity",), (f"{_b}_inclination",)]


def arcsec_per_year(rate: float) -> float:
    return rate / ARCSEC * JULIAN_YEAR


def _values(given: Given, work: Work) -> dict[str, float]:
    """The file's values, with the preset's filling every group the file leaves out."""
    values = {k: v for k, v in given.values.items() if not isinstance(v, (str, tuple))}
    preset = given.word("preset")
    if preset is None:
        return values
    filled = []
    for group in GROUPS:
        if not any(k in values for k in group):
            key = group[0]
            values[key] = EARTH[key]
            filled.append(key)
    work.section("preset: earth (IERS Conventions 2010, IAU 2009 constants, J2000 elements)")
    for key in filled:
        work.text(*_preset_lines()[key])
    overridden = [k for k in given.values if k != "preset"]
    if overridden:
        work.text(f"given in the file instead of the preset: {', '.join(overridden)}")
    return values


def _symbols() -> dict[str, str]:
    return {p.name: p.symbol for p in KIND.params}


@cache
def _preset_lines() -> dict[str, tuple]:
    """Each preset key's line in the worked answer, ``key: symbol = value (source)``: the
    same words for every problem, so built once (on first use: they need KIND's symbols)."""
    symbols, lines = _symbols(), {}
    for key, (value, *rest) in _preset_text().items():
        chain = ("=", value) + (tuple(rest[:2]) if rest[:1] == ["="] else ())
        rest = rest[2:] if rest[:1] == ["="] else rest
        lines[key] = (f"{key}: ", rel(*names(symbols[key]), *chain), *rest)
    return lines




def _ellipticity(values: dict, work: Work) -> float:
    if "dynamical_ellipticity" in values:
        if "J2" in values or "polar_moment_factor" in values:
            raise InputError("give dynamical_ellipticity or J2 with polar_moment_factor, not "
                             "both", key="given.J2" if "J2" in values else
                             "given.polar_moment_factor")
        H = values["dynamical_ellipticity"]
    elif "J2" in values or "polar_moment_factor" in values:
        missing = "polar_moment_factor" if "J2" in values else "J2"
        if missing not in values:
            raise InputError(f"J2 and polar_moment_factor go together (H = J2 / (C / (M R^2))); "
                             f"give {missing} too", key=f"given.{missing}")
        J2, k = values["J2"], values["polar_moment_factor"]  # their limits are declared
        factor = Let(Sym("polar_moment_factor", k),
                     Sym("C", NAMED) / (Sym("M", NAMED) * Sym("R", NAMED) ** 2))
        J2_, C, A, M, R = names("J2 C A M R")
        H = work.step("H", Sym("J2", J2) / factor, note=(rel(J2_, "=", (C - A) / (M * R**2)),))
        if not H < 1:  # two keys: each within its limits, their quotient may not be
            raise InputError(f"J2 / polar_moment_factor gives a dynamical ellipticity (C - A) / C "
                             f"of {num(H)}; it lies between 0 and 1 for an oblate planet",
                             key="given.J2")
    else:
        raise InputError("give the planet's dynamical_ellipticity H = (C - A) / C (or J2 and "
                         "polar_moment_factor), or preset: earth",
                         key="given.dynamical_ellipticity")
    return H


def _spin(values: dict, work: Work) -> float:
    if "rotation_period" in values and "rotation_rate" in values:
        raise InputError("give rotation_period or rotation_rate, not both",
                         key="given.rotation_rate")
    if "rotation_rate" in values:
        return values["rotation_rate"]
    if "rotation_period" not in values:
        raise InputError("give the planet's rotation_period (sidereal) or rotation_rate",
                         key="given.rotation_period")
    P = values["rotation_period"]
    return work.step("omega", 2 * PI / Sym("P_rot", P, "s"), unit="rad/s")


def _tidal(values: dict, b: str, work: Work) -> float | None:
    """G M_b / a^3 for body b, or None when the file (and preset) name no such body."""
    keys = [k for k in values if k.startswith(f"{b}_")]
    if not keys:
        return None
    name = BODY_NAMES[b]
    amount = [k for k in (f"{b}_mass_ratio", f"{b}_mass") if k in values]
    orbit = [k for k in (f"{b}_orbital_period", f"{b}_distance") if k in values]
    for group, what in ((amount, "mass_ratio (to the planet) or mass"),
                        (orbit, "orbital_period or distance (semi-major axis)")):
        if len(group) > 1:
            raise InputError(f"give {b}_{what.split(' ')[0]} or the other, not both "
                             f"({' and '.join(group)})", key=f"given.{group[1]}")
        if not group:
            which = what.split(" or ")[0].split(" ")[0]
            raise InputError(f"{name} needs its {what}", key=f"given.{b}_{which}")
    amount_key, orbit_key = amount[0], orbit[0]
    a_value, o_value = values[amount_key], values[orbit_key]
    planet = None
    if (amount_key.endswith("_mass") and orbit_key.endswith("_period")) or \
            (amount_key.endswith("_ratio") and orbit_key.endswith("_distance")):
        if "planet_mass" not in values:
            raise InputError(f"{amount_key} with {orbit_key} needs the planet's mass "
                             "(planet_mass)", key="given.planet_mass")
        planet = values["planet_mass"]
    if orbit_key.endswith("_period"):
        ratio = a_value if planet is None else a_value / planet
        if planet is not None:
            ratio = work.step(f"q_{b}", Sym(f"M_{b}", a_value, "kg") / Sym("M", planet, "kg"))
        q_ = Sym(f"q_{b}", ratio)
        return work.step(_TIDAL_SYMBOL[b], (2 * PI / Sym(f"P_{b}", o_value, "s")) ** 2 * q_
                         / (1 + q_), unit="1/s^2", ref="Kepler III")
    mass = Sym(f"M_{b}", a_value, "kg") if planet is None else \
        Sym(f"q_{b}", a_value) * Sym("M", planet, "kg")
    return work.step(_TIDAL_SYMBOL[b], Const("G", G) * mass / Sym(f"a_{b}", o_value, "m") ** 3,
                     unit="1/s^2", note=_CONSTANT_OF_GRAVITATION)


def _tidal_symbol(b: str) -> Expr:
    """G M_b / a_b^3, the symbol of the tidal strength of body b."""
    G_, M_b, a_b = names(f"G M_{b} a_{b}")
    return G_ * M_b / a_b**3


_TIDAL_SYMBOL = {b: _tidal_symbol(b) for b in BODIES}
_CONSTANT_OF_GRAVITATION = (rel(*names("G"), "=", q(G, "m^3/(kg s^2)", label=f"{G:g}")),)


# The sentences that hold no values are built once, here: building their trees again on
# every solve was a large part of the kind's time in gyro check.
_A, _C, _M, _R, _H, _w, _e = names("A C M R H omega epsilon")  # C, M, R: polar_moment_factor's too
_M_b, _r, _u, _s, _G, _T, _a, _ecc, _n, _T_mean, _W_p, _i, _dH, _dt = names(
    "M_b r u s G T a e n T_mean Omega_p i dH dt")
_THREE_HALVES, _F_E = Num(1.5, "3/2"), (1 - _ecc**2) ** Num(-1.5, "-3/2")
_PLANET = (_A, ", ", _C, ": the planet's moments of inertia about an equatorial axis and about "
           "its polar axis; ", _M, ", ", _R, ": its mass and equatorial radius; ",
           rel(_H, "=", (_C - _A) / _C), ", its dynamical ellipticity; ", _w, ": its rate of "
           "rotation; ", _e, ": its obliquity")
_ELLIPTICITY = (_H, "=", (_C - _A) / _C, "=")
_MACCULLAGH = ("MacCullagh: a body of mass ", _M_b, " at distance ", _r, ", in the direction ",
               _u, ", exerts on the planet the torque ",
               rel(_T, "=", 3 * _G * _M_b * (_C - _A) / _r**3 * dot(_u, _s) * cross(_u, _s)),
               ", where ", _s, " is the spin axis and ", _G, " the constant of gravitation.")
_AVERAGED = ("Averaged over a Kepler orbit (semi-major axis ", _a, ") of eccentricity ", _ecc,
             ", ", _a**3 / _r**3, " becomes ", _F_E, ", and the direction ", _u, " is spread "
             "evenly round the orbit plane: the mean torque is ",
             rel(_T_mean, "=", -(_THREE_HALVES * (_G * _M_b / _a**3) * _F_E * (_C - _A)
                                 * cos(_e) * cross(_n, _s))), ", ", _n, " the orbit normal.")
_STEADY = ("Steady precession (the chapter's ", rel(_dH / _dt, "=", _T), ", the angular "
           "momentum being ", _C * _w * _s, "): ", _s, " turns about ", -_n, " (westward, "
           "retrograde) at ", rel(_W_p, "=", absolute(_T_mean) / (_C * _w * sin(_e)), "=",
                                  _THREE_HALVES * (_G * _M_b / _a**3) * _F_E * _H * cos(_e)
                                  / _w), ".")
_NODE = ("An orbit inclined at ", _i, " whose node turns round quickly (the Moon's, in "
         "18.6 years) is averaged over the node too: factor ",
         paren(1 - _THREE_HALVES * sin(_i) ** 2), ".")
_JULIAN_YEAR = ("(", rel(q(JULIAN_YEAR, "yr", True), "=", q(JULIAN_YEAR, "d", True)), ")")
_T_p, _t_1 = names("T_p t_1deg")
_SLOW, _GYROSCOPIC, _PER_DEGREE = _W_p / _w, _C * _w * _s, _T_p / _t_1


def _body_words(b: str) -> tuple[Expr, Expr]:
    """Body b's eccentricity and node factors as symbols: (1 - e_b^2)^(-3/2) and
    1 - (3/2) sin^2(i_b)."""
    e_b, i_b = names(f"e_{b} i_{b}")
    return (1 - e_b ** 2) ** Num(-1.5, "-3/2"), 1 - Num(1.5, "3/2") * sin(i_b) ** 2


_BODY_WORDS = {b: _body_words(b) for b in BODIES}


def solve(given: Given, find: frozenset[str], work: Work) -> None:
    values = _values(given, work)
    work.section("The planet")
    work.text(*_PLANET)
    H = _ellipticity(values, work)
    omega = _spin(values, work)
    if "obliquity" not in values:
        raise InputError("give the obliquity (angle between the spin axis and the orbit "
                         "normal)", key="given.obliquity")
    eps = values["obliquity"]
    work.text(rel(*_ELLIPTICITY, q(H)), ", ", rel(_e, "=", q(eps, "deg")), ", ",
              rel(_w, "=", q(omega, "rad/s")))
    work.section("Torque on the bulge, orbit-averaged, and the precession it drives")
    work.text(*_MACCULLAGH)
    work.text(*_AVERAGED)
    work.text(*_STEADY)
    work.text(*_NODE)
    shares: dict[str, float] = {}
    for b in BODIES:
        work.section(f"{BODY_NAMES[b][0].upper()}{BODY_NAMES[b][1:]}")
        tidal = _tidal(values, b, work)
        if tidal is None:
            work.text(f"no keys for {BODY_NAMES[b]}: it is left out")
            continue
        e = values.get(f"{b}_eccentricity", 0.0)
        i = values.get(f"{b}_inclination", 0.0)
        three_halves = Num(1.5, "3/2")
        fe_tree = (1 - Sym(f"e_{b}", e) ** 2) ** Num(-1.5, "-3/2")
        fe_symbol, fi_symbol = _BODY_WORDS[b]
        fe = work.step(fe_symbol, fe_tree, state=False)
        fi_tree = 1 - three_halves * sin(Sym(f"i_{b}", i, "deg")) ** 2
        fi = work.step(fi_symbol, fi_tree, state=False, note="node-averaged") if i else 1.0
        tidal_ = Let(Sym(f"GM_a3_{b}", tidal, "1/s^2"),
                     Const("G", G) * Sym(f"M_{b}", NAMED) / Sym(f"a_{b}", NAMED) ** 3)
        tree = three_halves * tidal_ * Let(Sym(f"f_e_{b}", fe), fe_tree) * Sym("H", H) * cos(
            Sym("epsilon", eps, "deg"))
        if i:
            tree = tree * Let(Sym(f"f_i_{b}", fi), fi_tree)
        rate = work.step(f"Omega_{b}", tree / Sym("omega", omega, "rad/s"), unit="rad/s")
        work.step(f"Omega_{b}", value=arcsec_per_year(rate), unit="arcsec/yr", note=_JULIAN_YEAR)
        if fi < 0:
            work.warn(f"{b}_inclination beyond ", q(math.radians(54.74), "deg", exact=True),
                      " reverses that body's mean torque")
        shares[b] = rate
        if abs(rate) > 1e-2 * math.sqrt(tidal):  # sqrt(G M_b / a^3) <= the orbital rate
            work.warn(f"the precession is not slow against {BODY_NAMES[b]}'s orbital motion: "
                      "averaging the torque over the orbit is not justified")
    if not shares:
        raise InputError("no torquing body: give sun_* or moon_* keys (mass_ratio and "
                         "orbital_period at least), or preset: earth", key="given")
    total = sum(shares.values())
    work.section("Lunisolar precession" if len(shares) > 1 else "Precession")
    if len(shares) > 1 and total != 0:
        parts = [Sym(f"Omega_{b}", r, "arcsec/yr") for b, r in shares.items()]
        work.step("Omega_p", reduce(operator.add, parts[1:], parts[0]), unit="arcsec/yr")
        for b, r in shares.items():
            work.text(f"{BODY_NAMES[b]}'s share: ", q(100 * r / total), " %")
    work.step("Omega_p", value=total, unit="rad/s")
    work.answer("precession_rate", "Omega_p", [total], "rate")
    for b, r in shares.items():
        work.answer(f"{b}_rate", f"Omega_{b}", [r], "rate")
    if total == 0:
        work.warn("the torques cancel: no precession")
        return
    if abs(total) > 1e-2 * omega:
        work.warn("the precession is not slow against the spin: the gyroscopic approximation "
                  "(angular momentum C omega s, and so this rate) is not accurate")
    if eps == 0:
        work.warn("obliquity 0: the axis lies along the orbit normal; the torque vanishes and "
                  "the rate is that of a cone of zero width")
    period = work.step("T_p", 2 * PI / Sym("Omega_p", abs(total), "rad/s"), unit="s")
    work.step("T_p", value=period / JULIAN_YEAR, unit="yr")
    # 360 (deg) is the full turn, 2 pi rad: the value is in s/rad, shown in yr/deg
    per_degree = work.step("t_1deg", Sym("T_p", period, "yr") / Const("360", 2 * math.pi),
                           unit="yr/deg")
    if given.word("preset", "") == "earth":  # the chapter's figures are the Earth's
        work.text("The chapter's 26,000 years; its '80 years' for ",
                  q(math.radians(1), "deg", True), " is a misprint: ",
                  Num(26000, "26,000") / 360, " is about 72 (the errata), here ",
                  q(per_degree), " years.")
    work.answer("precession_period", "T_p", [period], "time")
    work.answer("years_per_degree", "t_1deg", [1 / abs(total)], "time_per_angle")
    turned = math.radians(period / (per_degree * JULIAN_YEAR))  # T_p / t_1deg: 360 deg
    work.check(rel(_SLOW, "=", q(abs(total) / omega)), ": the precession is slow against "
               "the spin, so the angular momentum is ", _GYROSCOPIC, " (the gyroscopic "
               "approximation); ", rel(_PER_DEGREE, "=", q(turned, "deg")))


def _body_params(b: str) -> tuple[Param, ...]:
    name = BODY_NAMES[b]
    return (
        Param(f"{b}_mass_ratio", "dimensionless", f"q_{b}", f"mass of {name} over the planet's "
              "(0 leaves it out)", nonnegative=True),
        Param(f"{b}_mass", "mass", f"M_{b}", f"mass of {name} (instead of {b}_mass_ratio)",
              nonnegative=True),
        Param(f"{b}_orbital_period", "time", f"P_{b}", f"sidereal period of {name}'s orbit "
              "relative to the planet", positive=True),
        Param(f"{b}_distance", "length", f"a_{b}", f"semi-major axis of {name}'s orbit "
              f"(instead of {b}_orbital_period)", positive=True),
        Param(f"{b}_eccentricity", "dimensionless", f"e_{b}", f"eccentricity of {name}'s orbit "
              "(0 if absent)", range=(0.0, 1.0), bounds="[)", reason="an orbit is an ellipse"),
        Param(f"{b}_inclination", "angle", f"i_{b}", f"inclination of {name}'s orbit to the "
              "reference plane, averaged over its turning node (0 if absent)",
              range=(-math.pi / 2, math.pi / 2), bounds="()",
              reason="within 90 deg of the reference plane"),
    )



KIND = Kind(
    name="earth_precession",
    summary="precession of the equinoxes: an oblate planet as a top torqued by the Sun and "
            "the Moon (rate, period, years per degree)",
    chapter="section 11.3, precession of the equinoxes; steady precession dH/dt = T",
    params=(
        Param("preset", "word", "preset", "earth: the Earth, Sun and Moon from the IERS "
              "Conventions (2010) and the IAU 2009 constants; keys in the file override it",
              choices=("earth",)),
        Param("dynamical_ellipticity", "dimensionless", "H", "(C - A) / C of the planet",
              range=(0.0, 1.0), bounds="()", reason="an oblate planet; a sphere (H = 0) feels "
              "no torque"),
        Param("J2", "dimensionless", "J2", "the planet's J2 = (C - A) / (M R^2) (with "
              "polar_moment_factor, instead of dynamical_ellipticity)", positive=True,
              reason="the oblateness of the gravity field"),
        Param("polar_moment_factor", "dimensionless", "C/(M R^2)", "C / (M R^2) of the planet",
              range=(0.0, 2 / 3), bounds="(]", limits=("0", "2/3"),
              reason="2/3 for a hollow shell, 0.4 for a uniform sphere",
              symbol_tree=_C / (_M * _R**2)),
        Param("obliquity", "angle", "epsilon", "angle between the spin axis and the normal of the "
              "reference orbit plane (the ecliptic)", range=(0.0, math.pi / 2), bounds="[)",
              reason="at 90 deg the bulge lies in the orbit plane and the mean torque vanishes; "
              "for a retrograde rotator give 180 deg minus its obliquity, the axis then moves "
              "the other way"),
        Param("rotation_period", "time", "P_rot", "sidereal rotation period of the planet",
              positive=True),
        Param("rotation_rate", "rate", "omega", "rotation rate (instead of rotation_period)",
              positive=True),
        Param("planet_mass", "mass", "M", "mass of the planet (only to go with a body's mass "
              "and period, or mass_ratio and distance)", positive=True),
    ) + _body_params("sun") + _body_params("moon"),
    answers=(
        AnswerSpec("precession_rate", "rate", "Omega_p", "rate at which the spin axis turns "
                   "about the orbit normal, westward (retrograde) positive; e.g. arcsec/yr"),
        AnswerSpec("sun_rate", "rate", "Omega_sun", "the Sun's share of the rate"),
        AnswerSpec("moon_rate", "rate", "Omega_moon", "the Moon's share of the rate"),
        AnswerSpec("precession_period", "time", "T_p", "time for one turn of the axis, e.g. yr"),
        AnswerSpec("years_per_degree", "time_per_angle", "t_1deg", "time for the axis to turn "
                   "one degree: write the unit as yr/deg"),
    ),
    solve=solve,
    uses_body=False,
    example={
        "statement": ("Take the Earth, the Sun and the Moon with the constants of the IERS "
                      "Conventions. Find the rate at which the Earth's axis precesses, the time "
                      "for one turn of the axis, and the years it takes to turn one degree."),
        "given": {"preset": "earth"},
        "find": {"precession_rate": "arcsec/yr", "precession_period": "yr",
                 "years_per_degree": "yr/deg"},
        "vary": {"obliquity": "[10 deg, 40 deg]"}},
)
