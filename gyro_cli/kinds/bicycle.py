"""Why a bicycle stays up: the linearised Whipple bicycle and its self-stable speeds.

Chapter 11 ends: "Gyroscopic motion also partly explains why one can stay up on
a bicycle when it's moving (Fig. 11-14)". This kind answers "partly, how much"
with the benchmark model of Meijaard, Papadopoulos, Ruina and Schwab, "Linearized
dynamics equations for the balance and steer of a bicycle: a benchmark and
review", Proc. R. Soc. A 463 (2007) 1955-1982 (the paper's names are the keys).

Lean phi and steer delta obey M q'' + v C1 q' + (g K0 + v^2 K2) q = 0 (Eq. 5.3);
M, C1, K0, K2 come from the parameters by the paper's Appendix A
(physics/bicycle.py). The eigenvalues at the given speed say whether the
riderless bicycle balances itself there; the weave speed (a complex pair
crosses the imaginary axis) and the capsize speed (a real eigenvalue crosses
zero) bound the self-stable range. ``gyroscopic: false`` removes the wheels'
spin angular momentum (the terms in I_Ryy / r_R and I_Fyy / r_F), and the normal
worked answer says how the stable range moves without it.
"""

from __future__ import annotations

import dataclasses
import functools
import math

from ..core.errors import InputError
from ..core.expr import Expr, Num, Sym, absolute, cos, sin
from ..core.given import Given
from ..core.prose import bracket, fn, matrix, names, prime, q, rel, tup
from ..core.spec import AnswerSpec, Kind, Param
from ..core.work import GivenLine, Work, num

# key -> (dimension, symbol, meaning); order of Table 1.
KEYS: dict[str, tuple[str, str, str]] = {
    "w": ("length", "w", "wheel base"),
    "c": ("length", "c", "trail"),
    "lambda": ("angle", "lambda", "steer axis tilt from the vertical (pi/2 - head angle)"),
    "rR": ("length", "r_R", "rear wheel radius"),
    "mR": ("mass", "m_R", "rear wheel mass"),
    "IRxx": ("inertia", "I_Rxx", "rear wheel moment of inertia about a diameter (= I_Rzz)"),
    "IRyy": ("inertia", "I_Ryy", "rear wheel moment of inertia about its axle"),
    "xB": ("length", "x_B", "rear frame (with rider) centre of mass, forward of the rear "
           "contact"),
    "zB": ("length", "z_B", "rear frame centre of mass, z downward (negative: above the road)"),
    "mB": ("mass", "m_B", "rear frame mass (with rider)"),
    "IBxx": ("inertia", "I_Bxx", "rear frame inertia about its centre of mass, xx"),
    "IByy": ("inertia", "I_Byy", "rear frame inertia, yy"),
    "IBzz": ("inertia", "I_Bzz", "rear frame inertia, zz"),
    "IBxz": ("inertia", "I_Bxz", "rear frame inertia tensor, xz entry"),
    "xH": ("length", "x_H", "front frame (fork and handlebar) centre of mass, forward"),
    "zH": ("length", "z_H", "front frame centre of mass, z downward"),
    "mH": ("mass", "m_H", "front frame mass"),
    "IHxx": ("inertia", "I_Hxx", "front frame inertia about its centre of mass, xx"),
    "IHyy": ("inertia", "I_Hyy", "front frame inertia, yy"),
    "IHzz": ("inertia", "I_Hzz", "front frame inertia, zz"),
    "IHxz": ("inertia", "I_Hxz", "front frame inertia tensor, xz entry"),
    "rF": ("length", "r_F", "front wheel radius"),
    "mF": ("mass", "m_F", "front wheel mass"),
    "IFxx": ("inertia", "I_Fxx", "front wheel moment of inertia about a diameter (= I_Fzz)"),
    "IFyy": ("inertia", "I_Fyy", "front wheel moment of inertia about its axle"),
}
SI = {"length": "m", "mass": "kg", "inertia": "kg m^2", "angle": "rad"}
MASSES = ("mR", "mB", "mH", "mF")
_WHEEL = "a wheel's inertia tensor diag(Ixx, Iyy, Ixx) is positive definite"
_FRAME = "an inertia tensor is positive definite: its diagonal entries are positive"
_ABOVE = "z points down from the road: a centre of mass above the road has z < 0"
# key -> the limits its Param declares (the loader refuses a value outside them)
LIMITS: dict[str, dict] = {
    **{key: {"positive": True} for key in MASSES + ("w", "rR", "rF")},
    "lambda": {"range": (-math.pi / 2, math.pi / 2), "bounds": "()",
               "reason": "the steer axis tilt from the vertical"},
    **{key: {"range": (-math.inf, 0.0), "bounds": "()", "reason": _ABOVE}
       for key in ("zB", "zH")},
    **{key: {"positive": True, "reason": _WHEEL} for key in ("IRxx", "IRyy", "IFxx", "IFyy")},
    **{f"I{f}{a}": {"positive": True, "reason": _FRAME} for f in "BH" for a in ("xx", "yy", "zz")},
}
PRESET = "benchmark"


# ---- input ------------------------------------------------------------------

def parameters(given: Given, work: Work) -> dict[str, float]:
    """The paper's parameters in SI: from `given`, the rest from `preset: benchmark`."""
    preset = given.word("preset")
    p: dict[str, float] = {"g": given["g"]}
    for key, (dimension, symbol, _) in KEYS.items():
        if key in given:
            p[key] = given[key]
        elif preset == PRESET:
            p[key], text, shown = _preset()[key]
            work.given.append(GivenLine(key, symbol, text, p[key], SI[dimension],
                                        "preset: Table 1", shown=shown))
        else:
            raise InputError(f"needed: the {KEYS[key][2]} ({dimension}); give it, or write "
                             "`preset: benchmark` to take the rest from Table 1 of Meijaard et "
                             "al. (2007)", key=f"given.{key}")
    _validate(p)
    return p


@functools.cache
def _preset() -> dict[str, tuple[float, str, tuple[str, str] | None]]:
    """Each key's value in Table 1 with its Given line's text and number as printed (the
    same for every file: written once)."""
    from ..physics import bicycle as bike

    out: dict[str, tuple[float, str, tuple[str, str] | None]] = {}
    for key, (dimension, _, _) in KEYS.items():
        value = bike.BENCHMARK[key]
        text = "pi/10 rad" if key == "lambda" else f"{value:.12g} {SI[dimension]}"
        shown = None if key == "lambda" else (f"{value:.12g}", SI[dimension])
        out[key] = (value, text, shown)
    return out


def _validate(p: dict[str, float]) -> None:
    """Physically impossible data that no one key shows (each key's own limits are declared
    in LIMITS): exit 2 naming the key and the limit."""
    for wheel in ("R", "F"):
        xx, yy = p[f"I{wheel}xx"], p[f"I{wheel}yy"]
        if yy > 2 * xx * (1 + 1e-9):
            raise InputError(f"a wheel's moment about its axle is at most twice its moment about "
                             f"a diameter (all mass in the wheel's plane): I{wheel}yy <= 2 "
                             f"I{wheel}xx = {num(2 * xx)} kg m^2, got {num(yy)} kg m^2",
                             key=f"given.I{wheel}yy")
    for frame in ("B", "H"):
        xx, yy, zz, xz = (p[f"I{frame}{a}"] for a in ("xx", "yy", "zz", "xz"))
        if xz * xz >= xx * zz:
            raise InputError(f"the inertia tensor [[I{frame}xx, 0, I{frame}xz], [0, I{frame}yy, "
                             f"0], [I{frame}xz, 0, I{frame}zz]] is not positive definite: "
                             f"|I{frame}xz| must be less than sqrt(I{frame}xx I{frame}zz) = "
                             f"{num(math.sqrt(xx * zz))} kg m^2, got {num(xz)} kg m^2",
                             key=f"given.I{frame}xz")
        mean, half = 0.5 * (xx + zz), math.hypot(0.5 * (xx - zz), xz)
        principal = sorted((mean - half, mean + half, yy))
        if principal[2] > (principal[0] + principal[1]) * (1 + 1e-9):
            raise InputError(f"no body has these inertias: the principal moments "
                             f"{', '.join(num(x) for x in principal)} kg m^2 break the triangle "
                             f"inequality (the largest may not exceed the sum of the other two, "
                             f"{num(principal[0] + principal[1])} kg m^2)",
                             key=f"given.I{frame}{'yy' if principal[2] == yy else 'xz'}")


# ---- the worked answer ------------------------------------------------------

V, S_, INF = names("v s infinity")

# The worked answer's formulas and sentences that no datum changes, built once (trees are
# not changed once made, so every solve can share them): building them for every file
# was a tenth of a bicycle's check. The data's trees and values are built in `solve`.
_x, _y, _z, _phi, _delta, _q, _g = names("x y z phi delta q g")
_M, _C1, _K0, _K2 = names("M C1 K0 K2")
_S_R, _S_F = names("S_R S_F")
_RE_S, _IM_S = fn("Re", S_), fn("Im", S_)
_A = names("a0 a1 a2 a3 a4")
_A_K, _H3 = names("a_k H3")
_H3_V, _A0_V = fn("H3", V), fn("a0", V)
_DET = fn("det", _M * S_ ** 2 + V * _C1 * S_ + _g * _K0 + V ** 2 * _K2)
_CONVENTIONS = (
    (_x, " forward, ", _y, " to the right, ", _z, " down; origin at the rear wheel's "
     "contact point. ", _phi, ": the lean to the right; ", _delta, ": the steer to the "
     "right (rad); ", rel(_q, "=", tup(_phi, _delta)), ". Small motions about upright "
     "straight running at speed ", V, ", no rider torques:"),
    (_M, ": the mass matrix; ", _C1, ": the velocity matrix (times ", V, "); ", _K0, ", ",
     _K2, ": the stiffness matrices of gravity (times ", _g, ") and of speed (times ",
     V ** 2, "):"),
    (rel(_M * prime(_q, 2) + V * _C1 * prime(_q) + (_g * _K0 + V ** 2 * _K2) * _q, "=", 0),
     "    (Eq. 5.3)"))


def _no_spin() -> tuple:
    """The line ``gyroscopic: false`` adds under the conventions."""
    I_Ryy, r_R, I_Fyy, r_F = names("I_Ryy r_R I_Fyy r_F")
    return ("gyroscopic: false -- the wheels' spin angular momentum is removed: ",
            rel(_S_R, "=", _S_F, "=", 0), " wherever ", I_Ryy / r_R, " and ", I_Fyy / r_F,
            " enter (", _C1, " and ", _K2, ").")


def _matrix_entries() -> tuple[tuple, ...]:
    """Eqs. A 20-A 23 as four lines, M, C1, K0, K2."""
    (I_Txx, I_Txz, I_Tzz, I_All, I_Alx, I_Alz, mu_, S_T, S_F, S_A, m_T, z_T, w_,
     lam_) = names("I_Txx I_Txz I_Tzz I_All I_Alx I_Alz mu S_T S_F S_A m_T z_T w lambda")
    sep = ";  "
    entries = {name: names(" ".join(f"{name}_{e}" for e in ("pp", "pd", "dp", "dd")))
               for name in ("M", "C1", "K0", "K2")}
    lines: list[tuple] = []
    pp, pd, dp, dd = entries["M"]
    lines.append((rel(pp, "=", I_Txx), sep, rel(pd, "=", dp, "=", I_Alx + mu_ * I_Txz), sep,
                  rel(dd, "=", I_All + 2 * mu_ * I_Alz + mu_ ** 2 * I_Tzz)))
    pp, pd, dp, dd = entries["C1"]
    lines.append((rel(pp, "=", 0), sep,
                  rel(pd, "=", mu_ * S_T + S_F * cos(lam_) + I_Txz * cos(lam_) / w_
                      - mu_ * m_T * z_T), sep,
                  rel(dp, "=", -(mu_ * S_T + S_F * cos(lam_))), sep,
                  rel(dd, "=", I_Alz * cos(lam_) / w_ + mu_ * (S_A + I_Tzz * cos(lam_) / w_))))
    pp, pd, dp, dd = entries["K0"]
    lines.append((rel(pp, "=", m_T * z_T), sep, rel(pd, "=", dp, "=", -S_A), sep,
                  rel(dd, "=", -S_A * sin(lam_))))
    pp, pd, dp, dd = entries["K2"]
    lines.append((rel(pp, "=", dp, "=", 0), sep,
                  rel(pd, "=", (S_T - m_T * z_T) * cos(lam_) / w_), sep,
                  rel(dd, "=", (S_A + S_F * sin(lam_)) * cos(lam_) / w_)))
    return tuple(lines)


_NO_SPIN = _no_spin()
_MATRIX_ENTRIES = _matrix_entries()
_T_TITLE: tuple[str | Expr, ...] = ("The whole bicycle ", *names("T"), " about the rear contact point (Eqs. A 1-A 5)")
_WHEELS_ZZ = ("for the wheels ", rel(*names("I_Rzz"), "=", *names("I_Rxx")),
              " and ", rel(*names("I_Fzz"), "=", *names("I_Fxx")))
_A_, _H_, _F_ = names("A H F")
# the assembly named in words: its parts are bodies, not terms of a sum
_A_TITLE = ("The front assembly ", _A_, " = front frame ", _H_, " + front wheel ", _F_,
            " (Eqs. A 6-A 15)")
_U_A_NOTE = ("distance of ", *names("A"), "'s centre of mass ahead of the steer axis")
_MATRICES_TITLE = ("The matrices (Eqs. A 20-A 23), rows and columns ", tup(_phi, _delta))
_CHAR_TITLE = ("The characteristic equation: ", rel(_DET, "=", 0))
_CHAR_POLY = (rel(_A[4] * S_ ** 4 + _A[3] * S_ ** 3 + _A[2] * S_ ** 2 + _A[1] * S_ + _A[0],
                  "=", 0),
              ": the characteristic polynomial in the eigenvalue ", S_, "; its coefficients ",
              _A_K, ", below, are ", _A[4], ", ", _A[3], ", ", _A[2], ", ", _A[1], ", ", _A[0],
              " (", V, " in m/s, ", S_, " in 1/s)")
_ROUTH_HURWITZ = (
    "Routh-Hurwitz: all four roots have ", rel(_RE_S, "<", 0), " iff every ",
    rel(_A_K, ">", 0), " and ",
    rel(_H3, "=", _A[1] * _A[2] * _A[3] - _A[0] * _A[3] ** 2 - _A[1] ** 2 * _A[4], ">", 0),
    ". A real root crosses ", Num(0), " where ", rel(_A0_V, "=", 0),
    " (capsize speed); a complex pair crosses the imaginary axis where ",
    rel(_H3_V, "=", 0), " (weave speed).")
_STABLE_TITLE = ("Self-stable speeds (", rel(V, ">", 0), ")")
_H3_ZERO = (": ", rel(_H3_V, "=", 0), ", a complex pair on the imaginary axis")
_A0_ZERO = (": ", rel(_A0_V, "=", 0), ", a real eigenvalue at ", Num(0))
_STABLE_EVERY = ("stable (every ", rel(_RE_S, "<", 0), "): ")
_SHARE_TITLE = ("The wheels' gyroscopic share (", rel(_S_R, "=", _S_F, "=", 0),
                ": no spin angular momentum)")
_I = names("I")[0]
_STATE_MATRIX = (": the eigenvalues of the state matrix ",
                 bracket(bracket(0, _I), bracket(-_M ** -1 * (_g * _K0 + V ** 2 * _K2),
                                                 -_M ** -1 * V * _C1)))
_IDENTITY: tuple[str | Expr, ...] = (*names("I"), ": the identity matrix; ", S_, ": an eigenvalue")
_MOTION = {
    "stable": (" -- every eigenvalue has ", rel(_RE_S, "<", 0), ": a small disturbance "
               "dies out, the bicycle balances itself"),
    "capsize": (" -- a real eigenvalue ", rel(S_, ">", 0), ": it falls over without "
                "oscillating"),
    "weave": (" -- a complex pair with ", rel(_RE_S, ">", 0), ": lean and steer "
              "oscillate and grow"),
    "capsize and weave": (" -- both a capsize and a weave mode grow",)}
_RESIDUAL = absolute(_DET) / _A[4]
_NEAREST = absolute(_RE_S)
_V_POWERS = {1: V, **{k: V ** k for k in range(2, 13)}}


def _speeds(intervals: list[tuple[float, float]]) -> tuple:
    """The self-stable ranges as pieces: ``4.292383 m/s < v < 6.024262 m/s``."""
    if not intervals:
        return ("no self-stable speed",)
    pieces: list = []
    for lo, hi in intervals:
        if pieces:
            pieces.append(", ")
        pieces.append(rel(q(lo, "m/s", sig=7), "<", V, "<",
                          q(hi, "m/s", sig=7) if math.isfinite(hi) else INF))
    return tuple(pieces)


def _poly(coeffs) -> Expr:
    """A polynomial in v by its coefficients (ascending powers), 7 figures each:
    ``-755.0919 + 65.65200 v^2``."""
    tree: Expr | None = None
    for power, c in enumerate(coeffs):
        if c == 0:
            continue
        term: Expr = q(abs(c) if tree is not None else c, sig=7)
        if power:
            term = term * (_V_POWERS[power] if power in _V_POWERS else V ** power)
        tree = term if tree is None else tree - term if c < 0 else tree + term
    return tree if tree is not None else Num(0)


def solve(given: Given, find: frozenset[str], work: Work) -> None:
    from ..physics import bicycle as bike

    p = parameters(given, work)
    g = p["g"]
    gyroscopic = given.word("gyroscopic", "true") == "true"
    speed = given.get("speed")
    m = bike.matrices(p, gyroscopic)
    _positive_definite(m)

    work.section("Conventions (Meijaard, Papadopoulos, Ruina & Schwab 2007)")
    for line in _CONVENTIONS:
        work.text(*line)
    if not gyroscopic:
        work.text(*_NO_SPIN)

    work.section(*_T_TITLE)
    S = _symbols(p)
    mR, mB, mH, mF = S["mR"], S["mB"], S["mH"], S["mF"]
    xB, zB, xH, zH, rR, rF, w, c, lam = (S[k] for k in ("xB", "zB", "xH", "zH", "rR", "rF",
                                                        "w", "c", "lambda"))
    I = {k: S[k] for k in S if k.startswith("I")}

    def step(symbol: str, tree: Expr, unit: str, note: str | tuple = "") -> Sym:
        """A formula step (the values are the paper's, printed in the Given table)."""
        value = work.step(symbol, tree, unit=unit, note=note, substitute=False)
        assert value is not None
        return Sym(symbol, value, unit)

    mT = step("m_T", mR + mB + mH + mF, "kg")
    xT = step("x_T", (xB * mB + xH * mH + w * mF) / mT, "m")
    zT = step("z_T", (-(rR * mR) + zB * mB + zH * mH - rF * mF) / mT, "m",
              note="centre of mass of the whole bicycle")
    ITxx = step("I_Txx", I["IRxx"] + I["IBxx"] + I["IHxx"] + I["IFxx"] + mR * rR ** 2 + mB * zB ** 2
                + mH * zH ** 2 + mF * rF ** 2, "kg*m^2")
    ITxz = step("I_Txz", I["IBxz"] + I["IHxz"] - mB * xB * zB - mH * xH * zH + mF * w * rF,
                "kg*m^2")
    ITzz = step("I_Tzz", I["IRxx"] + I["IBzz"] + I["IHzz"] + I["IFxx"] + mB * xB ** 2 + mH * xH ** 2
                + mF * w ** 2, "kg*m^2", note=_WHEELS_ZZ)

    work.section(*_A_TITLE)
    mA = step("m_A", mH + mF, "kg")
    xA = step("x_A", (xH * mH + w * mF) / mA, "m")
    zA = step("z_A", (zH * mH - rF * mF) / mA, "m")
    IAxx = step("I_Axx", I["IHxx"] + I["IFxx"] + mH * (zH - zA) ** 2 + mF * (rF + zA) ** 2,
                "kg*m^2")
    IAxz = step("I_Axz", I["IHxz"] - mH * (xH - xA) * (zH - zA) + mF * (w - xA) * (rF + zA),
                "kg*m^2")
    IAzz = step("I_Azz", I["IHzz"] + I["IFxx"] + mH * (xH - xA) ** 2 + mF * (w - xA) ** 2,
                "kg*m^2")
    uA = step("u_A", (xA - w - c) * cos(lam) - zA * sin(lam), "m", note=_U_A_NOTE)
    IAll = step("I_All", mA * uA ** 2 + IAxx * sin(lam) ** 2
                + 2 * IAxz * sin(lam) * cos(lam) + IAzz * cos(lam) ** 2, "kg*m^2",
                note="about the steer axis")
    IAlx = step("I_Alx", -(mA * uA * zA) + IAxx * sin(lam) + IAxz * cos(lam), "kg*m^2")
    IAlz = step("I_Alz", mA * uA * xA + IAxz * sin(lam) + IAzz * cos(lam), "kg*m^2")
    mu = step("mu", c * cos(lam) / w, "", note="trail ratio")
    if gyroscopic:
        SR = step("S_R", I["IRyy"] / rR, "kg m",
                  note="rear wheel spin angular momentum per unit speed")
        SF = step("S_F", I["IFyy"] / rF, "kg m")
        ST = step("S_T", SR + SF, "kg m")
    else:  # the spin terms removed: a datum of the problem (0), not a formula
        t = bike.totals(p, gyroscopic)
        SR = Sym("S_R", work.step("S_R", value=t.SR, unit="kg m", note="gyroscopic: false; "
                                  "rear wheel spin angular momentum per unit speed"), "kg m")
        SF = Sym("S_F", work.step("S_F", value=t.SF, unit="kg m", note="gyroscopic: false"),
                 "kg m")
        ST = step("S_T", SR + SF, "kg m")
    SA = step("S_A", mA * uA + mu * mT * xT, "kg m",
              note="lean-steer static moment: the steering assembly's own and the trail's share "
                   "of the whole bicycle's")
    if work.overrides:  # a student's values carried: the matrices from the steps shown
        m, no_spin = _from_steps((mT, xT, zT, ITxx, ITxz, ITzz, mA, xA, zA, IAxx, IAxz, IAzz,
                                  uA, IAll, IAlx, IAlz, mu, SR, SF, ST, SA), p)
    else:  # nothing carried: the totals of physics/bicycle.py (the same values)
        no_spin = bike.matrices(p, gyroscopic=False)

    work.section(*_MATRICES_TITLE)
    for entries, (name, a, unit) in zip(_MATRIX_ENTRIES, ((_M, m.M, "kg m^2"),
                                                          (_C1, m.C1, "kg m"),
                                                          (_K0, m.K0, "kg m"),
                                                          (_K2, m.K2, "kg"))):
        work.text(*entries)
        work.text(rel(name, "=", matrix(a, unit, sig=10)))

    coeffs = bike.characteristic(m, g)
    work.section(*_CHAR_TITLE)
    work.text(*_CHAR_POLY)
    for k in (4, 3, 2, 1, 0):
        work.text(rel(_A[k], "=", _poly(coeffs[k])))
    work.text(*_ROUTH_HURWITZ)

    stab = bike.stability(m, g)
    work.section(*_STABLE_TITLE)
    work.text(rel(_H3_V, "=", _poly(bike.hurwitz_of(m, g))))
    # the speeds are roots of H3(v) and a0(v), conditions rather than formulas: value steps
    for v in stab.weave:
        work.step("v_w", value=v, unit="m/s", note=("weave speed, ", q(v, "m/s", sig=12),
                                                    *_H3_ZERO))
    for v in stab.capsize:
        work.step("v_c", value=v, unit="m/s", note=("capsize speed, ", q(v, "m/s", sig=12),
                                                    *_A0_ZERO))
    stable = _speeds(stab.stable)       # trees: the share section shows the same range
    work.text(*_STABLE_EVERY, *stable)
    if not stab.stable:
        work.warn("no self-stable speed for these data: the bicycle needs a rider's control at "
                  "every speed")
    elif not math.isfinite(stab.stable[-1][1]):
        work.warn("the stable range has no upper end for these data (no capsize speed)")

    if gyroscopic:
        # only the range without the spin is shown: no weave or capsize speed of its own
        plain = bike.stable_speeds(no_spin, g)
        work.section(*_SHARE_TITLE)
        work.text("with the wheels' spin angular momentum: ", *stable)
        work.text("without it (gyroscopic: false): ", *_speeds(plain))
        work.text(*_share(stab.stable, plain))

    if speed is not None:
        ev = bike.eigenvalues(m, speed, g)
        state = bike.motion(ev)
        work.section("At ", rel(V, "=", q(speed, "m/s", label=f"{speed:.12g}")),
                     *_STATE_MATRIX)
        work.text(*_IDENTITY)
        for e in ev:
            work.text(rel(S_, "=", q(_eigen(e), "1/s", sig=12)))
        work.text(f"motion: {state}", *_MOTION[state])
        a_k = [bike.polyval(speed, c) for c in coeffs]     # a_k at this speed
        for e in ev:
            residual = _char_value(a_k, e)
            work.check(rel(S_, "=", q(_eigen(e), sig=6)), ": ",
                       rel(_RESIDUAL, "=", q(abs(residual), sig=2)))
        work.answer("eigenvalues_real", _RE_S, [float(e.real) for e in ev], "inverse_time")
        work.answer("eigenvalues_imag", _IM_S, [float(e.imag) for e in ev], "inverse_time")
        work.answer("motion", "motion", [state], None)
    elif find & {"eigenvalues_real", "eigenvalues_imag", "motion"}:
        raise InputError("the eigenvalues and the motion are at a speed: give `speed`",
                         key="given.speed")
    for v in stab.weave + stab.capsize:
        nearest = min(abs(x) for x in _spectrum(stab, m, v, g).real)
        work.check(rel(V, "=", q(v, "m/s", sig=10)), ": the eigenvalue nearest the imaginary "
                   "axis has ", rel(_NEAREST, "=", q(nearest, "1/s", sig=2)))
    work.answer("weave_speed", "v_w", stab.weave, "speed")
    work.answer("capsize_speed", "v_c", stab.capsize, "speed")
    ends = [x for lo, hi in stab.stable for x in (lo, hi) if math.isfinite(x)]
    labels = [lab for lo, hi in stab.stable
              for lab in (("low", "high") if math.isfinite(hi) else ("low, no upper end",))]
    work.answer("stable_speeds", "v", ends, "speed", labels)
    for key, values, dim in (("M", m.M, "inertia"), ("C1", m.C1, "mass_length"),
                             ("K0", m.K0, "mass_length"), ("K2", m.K2, "mass")):
        work.answer(key, key, [float(x) + 0.0 for x in values.ravel()], dim,
                    ["phi,phi", "phi,delta", "delta,phi", "delta,delta"])


def _from_steps(steps: tuple[Sym, ...], p: dict[str, float]):  # type: ignore[no-untyped-def]
    """The matrices, and those without the wheels' spin, from the values of the worked
    answer's steps m_T ... S_A (in the order of `physics.bicycle.Totals`): a student's
    value in a step's place reaches the eigenvalues and the speeds."""
    from ..physics import bicycle as bike

    shown = bike.Totals(*(step.si for step in steps))
    m = bike.matrices_of(shown, p["w"], p["lambda"])
    _positive_definite(m)
    no_spin = dataclasses.replace(shown, SR=0.0, SF=0.0, ST=0.0)
    return m, bike.matrices_of(no_spin, p["w"], p["lambda"])


def _positive_definite(m) -> None:  # type: ignore[no-untyped-def]
    """Exit 2 unless the mass matrix M is positive definite."""
    if not (m.M[0, 0] > 0 and m.M[0, 0] * m.M[1, 1] - m.M[0, 1] ** 2 > 0):
        raise InputError("the mass matrix M is not positive definite for these data; check the "
                         "inertias and their units", key="given")


def _spectrum(stab, m, v: float, g: float):  # type: ignore[no-untyped-def]
    """The eigenvalues at speed v: those the stability search worked out there, else anew."""
    from ..physics import bicycle as bike

    return stab.spectra[v] if v in stab.spectra else bike.eigenvalues(m, v, g)


def _char_value(a: list[float], s: complex) -> complex:
    """The characteristic polynomial at s over its lead, sum a_k s^k / a4 (a_k at the speed)."""
    return sum(a[k] * s ** k for k in range(5)) / a[4]


def _eigen(e: complex) -> float | complex:
    """An eigenvalue as a quantity holds it: real, or complex with its imaginary part."""
    return complex(e) if e.imag else float(e.real)


def _share(with_spin: list[tuple[float, float]], without: list[tuple[float, float]]) -> tuple:
    """How the wheels' spin moves the self-stable range (the stable intervals with and
    without it), as pieces of a sentence."""
    if not with_spin and not without:
        return ("neither has a self-stable speed.",)
    if not without:
        return ("without the wheels' spin angular momentum there is no self-stable speed at all: "
                "the weave never stabilises. For these data the wheels' spin is needed for "
                "self-stability; the spin, the trail, the steer-axis tilt and the mass "
                "distribution together decide where the range lies: the chapter's 'partly'.",)
    if not with_spin:
        return ("the wheels' spin removes the self-stable range these data have without it.",)
    (lo1, hi1), (lo0, hi0) = with_spin[0], without[0]

    def end(x: float) -> Expr:
        return q(x, "m/s", sig=6) if math.isfinite(x) else INF

    return ("the wheels' spin moves the lower end from ", end(lo0), " to ", end(lo1),
            " and the upper end from ", end(hi0), " to ", end(hi1), ".")


def _symbols(p: dict[str, float]) -> dict[str, Sym]:
    """The paper's parameters as symbols: mR -> m_R (kg), IBxz -> I_Bxz (kg m^2)."""
    out = {"w": Sym("w", p["w"], "m"), "c": Sym("c", p["c"], "m"),
           "lambda": Sym("lambda", p["lambda"], "deg")}
    for key, value in p.items():
        if key[0] in "mxzr" and len(key) == 2:
            out[key] = Sym(f"{key[0]}_{key[1]}", value, "kg" if key[0] == "m" else "m")
        elif key[0] == "I":
            out[key] = Sym(f"I_{key[1:]}", value, "kg m^2")
    return out


KIND = Kind(
    name="bicycle",
    summary="the linearised Whipple bicycle (Meijaard et al. 2007): eigenvalues, weave and "
            "capsize speeds, the self-stable range and the wheels' gyroscopic share",
    chapter="Fig. 11-14 and the chapter's last paragraph; Meijaard et al., Proc. R. Soc. A 463 "
            "(2007) 1955, Eq. 5.3 and Appendix A",
    params=(
        Param("preset", "word", "preset", "benchmark: Table 1 of Meijaard et al. (2007) for "
              "every key not given", choices=(PRESET,)),
        Param("speed", "speed", "v", "forward speed (for the eigenvalues and the motion)"),
        Param("g", "acceleration", "g", "gravity", default="9.81 m/s^2", positive=True),
        Param("gyroscopic", "word", "gyroscopic", "true (default) or false: false removes the "
              "wheels' spin angular momentum (I_Ryy / r_R, I_Fyy / r_F)",
              choices=("true", "false")),
    ) + tuple(Param(key, dim, symbol, doc, **LIMITS.get(key, {}))
              for key, (dim, symbol, doc) in KEYS.items()),
    answers=(
        AnswerSpec("weave_speed", "speed", "v_w", "speed where the weave (a complex pair) "
                   "crosses the imaginary axis: the low end of the self-stable range"),
        AnswerSpec("capsize_speed", "speed", "v_c", "speed where the capsize mode (a real "
                   "eigenvalue) crosses zero: the high end of the self-stable range"),
        AnswerSpec("stable_speeds", "speed", "v", "the self-stable range, [low, high]"),
        AnswerSpec("eigenvalues_real", "inverse_time", "Re(s)", "real parts of the four "
                   "eigenvalues at `speed` (ascending real part, then imaginary part)"),
        AnswerSpec("eigenvalues_imag", "inverse_time", "Im(s)", "imaginary parts, same order"),
        AnswerSpec("motion", None, "motion", "at `speed`: stable, capsize, weave, or capsize "
                   "and weave (which mode grows)", words=tuple(_MOTION)),
        AnswerSpec("M", "inertia", "M", "mass matrix, entries phi-phi, phi-delta, delta-phi, "
                   "delta-delta"),
        AnswerSpec("C1", "mass_length", "C1", "velocity matrix (times v), same order"),
        AnswerSpec("K0", "mass_length", "K0", "gravity stiffness matrix (times g), same order"),
        AnswerSpec("K2", "mass", "K2", "speed stiffness matrix (times v^2), same order"),
    ),
    solve=solve,
    picture="eigenvalues", animation="lean_and_steer", physics=("gyro_cli.physics.bicycle",),
    model=parameters,
    uses_body=False,
    example={
        "statement": ("The benchmark bicycle of Meijaard, Papadopoulos, Ruina and Schwab (2007) "
                      "rides straight ahead at "
                      "{speed}. Find the speeds at which the weave and the capsize modes change "
                      "their stability, the eigenvalues at this speed, and whether the bicycle is "
                      "then self-stable."),
        "given": {"preset": "benchmark", "speed": "5 m/s"},
        "find": {"weave_speed": "m/s", "capsize_speed": "m/s", "eigenvalues_real": "s^-1",
                 "eigenvalues_imag": "s^-1", "motion": None},
        "vary": {"speed": "[0.8, 1.2]"}},
)
