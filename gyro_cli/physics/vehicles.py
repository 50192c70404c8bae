"""Gyroscopic effects on vehicles: ships, aeroplanes, two- and four-wheelers.

Vehicle axes, fixed in the vehicle: x forward (toward the bow or nose), y to the
left (port), z up. A rotor of axial inertia J spinning at omega about its axis
has angular momentum H = J omega s (s the unit spin vector, by the right-hand
rule). When the vehicle turns at omega_p (the precession vector), H turns with
it, and the moment that must act on the rotor is (Eq. 11.29, vector form)

    C = dH/dt = omega_p x H            (the active gyroscopic couple, on the rotor)

The rotor pushes back on its bearings, so the vehicle feels the reactive
gyroscopic couple -C. Its effect is read off its components: about y it
pitches the vehicle (a couple along -y raises the bow), about z it turns it
(along +z to the left, to port), about x it heels it (along +x the port side
rises).

These are the rules of the engineering texts: R.S. Khurmi and J.K. Gupta,
"Theory of Machines", ch. 14 (gyroscopic couple and precessional motion), and
S.S. Rattan, "Theory of Machines", ch. 14, with the reactive couple on the
vehicle. Magnitudes: C = J omega omega_p (ship, aeroplane); for pitching in
simple harmonic motion theta = phi sin(omega_1 t), omega_1 = 2 pi / T:
omega_p,max = phi omega_1 and alpha_max = phi omega_1^2.

Two- and four-wheelers (same texts): the road wheels roll, omega_w = v / r_w;
the engine turns at G omega_w, in the wheels' sense or opposite. With the
precession v / R about the vertical, the gyroscopic couple is
C_g = (n_w I_w +- G I_E) v^2 / (R r_w) (times cos(theta) for a machine heeled
by theta), and the centrifugal couple about the ground line
C_c = m v^2 h / R (times cos(theta)). The centrifugal couple always overturns
the vehicle outward; the gyroscopic one does too when the net spin angular
momentum has the wheels' own sense (going forward it points to the vehicle's
left, whichever way the vehicle turns), and presses the inner wheels down when
engines running against the wheels dominate.

The scalar formulas the kinds print as steps (rates, couples, the heel, the pitching's
frequency) are written once for floats and formula trees (core/generic.py): the kinds call
them with their symbols to write the steps and with floats for their answers.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

from ..core.generic import V as F  # a float, or a formula tree
from ..core.generic import atan, pi_like, sqrt

Vector = tuple[float, float, float]

FORWARD: Vector = (1.0, 0.0, 0.0)
LEFT: Vector = (0.0, 1.0, 0.0)
UP: Vector = (0.0, 0.0, 1.0)


def cross(a: Vector, b: Vector) -> Vector:
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def scale(k: float, a: Vector) -> Vector:
    return (k * a[0], k * a[1], k * a[2])


def norm(a: Vector) -> float:
    return math.sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2])


# ---- formulas written once, for floats and trees ---------------------------------

def turn_rate(speed: F, turn_radius: F) -> F:
    """omega_p = v / R: the precession of a vehicle on a circle (or a loop)."""
    return speed / turn_radius


def rolling_rate(speed: F, wheel_radius: F) -> F:
    """omega_w = v / r_w: a road wheel rolling without slipping."""
    return speed / wheel_radius


def geared_rate(gear_ratio: F, wheel_rate: F) -> F:
    """omega_E = G omega_w: an engine geared to the wheels."""
    return gear_ratio * wheel_rate


def rotor_inertia(wheels: F, gear_ratio: F, engines: F, engine_sense: str) -> F:
    """sum I_w +- G sum I_E: the spinning parts' inertia referred to the wheels' rate, in the
    wheels' sense (minus with the engines turning against the wheels)."""
    geared = gear_ratio * engines
    return wheels + geared if engine_sense == "same" else wheels - geared


def spin_momentum(rotor_inertia: F, wheel_rate: F) -> F:
    """H = (sum I_w +- G sum I_E) omega_w: positive in the wheels' own sense."""
    return rotor_inertia * wheel_rate


def gyroscopic_couple(J: F, spin: F, precession: F) -> F:
    """C = J omega omega_p (Eq. 11.29): a rotor's couple, its spin across the precession."""
    return J * spin * precession


def precession_for_couple(couple: F, J: F, spin: F) -> F:
    """omega_p = M / (J omega): the precession at which a rotor gives the couple M."""
    return couple / (J * spin)


def overturning_couple(rotor_inertia: F, speed: F, turn_radius: F, wheel_radius: F) -> F:
    """C_g = (sum I_w +- G sum I_E) v^2 / (R r_w): the geared rotors' gyroscopic couple."""
    return rotor_inertia * speed ** 2 / (turn_radius * wheel_radius)


def centrifugal_couple(mass: F, speed: F, cg_height: F, turn_radius: F) -> F:
    """C_c = m v^2 h / R: the centrifugal force's couple about the ground line."""
    return mass * speed ** 2 * cg_height / turn_radius


def heel(gyroscopic: F, centrifugal: F, mass: F, g: F, cg_height: F) -> F:
    """theta = atan((C_g + C_c) / (m g h)): the heel that balances both couples
    (m g h sin(theta) = (C_g + C_c) cos(theta))."""
    return atan((gyroscopic + centrifugal) / (mass * g * cg_height))


def circular_frequency(period: F) -> F:
    """omega_1 = 2 pi / T (and T = 2 pi / omega_1): simple harmonic pitching."""
    return 2 * pi_like(period) / period


def max_pitching_rate(amplitude: F, frequency: F) -> F:
    """omega_p,max = phi omega_1: the pitching's largest rate, at the mean position."""
    return amplitude * frequency


# ---- the rotor's spin vector ----------------------------------------------------

# rotor_sense words: the sense of rotation seen by an observer at one end of the
# vehicle looking along its length. A rotation that looks clockwise to an observer
# has its vector pointing away from the observer (right-hand rule).
SHIP_SENSES = ("clockwise_from_stern", "counterclockwise_from_stern",
               "clockwise_from_bow", "counterclockwise_from_bow")
AEROPLANE_SENSES = ("clockwise_from_rear", "counterclockwise_from_rear",
                    "clockwise_from_front", "counterclockwise_from_front")


def spin_direction(sense: str) -> float:
    """+1 if the spin vector points forward (+x), -1 if aft, from a rotor_sense word.

    Seen from the stern (rear) the observer looks forward: clockwise points away,
    forward. Seen from the bow (front) the observer looks aft: clockwise points aft.
    """
    turn, _, end = sense.partition("_from_")
    if turn not in ("clockwise", "counterclockwise") or end not in ("stern", "rear", "bow",
                                                                    "front"):
        raise ValueError(f"not a rotor sense: {sense!r}")
    away = 1.0 if turn == "clockwise" else -1.0
    looking_forward = end in ("stern", "rear")
    return away if looking_forward else -away


def spin_vector(J: float, spin: float, direction: float) -> Vector:
    """H = J omega along the fore-and-aft axis; direction +1 forward, -1 aft (spin_direction)."""
    return scale(J * spin * direction, FORWARD)


# ---- the precession vector ------------------------------------------------------

def steering_precession(speed: float, radius: float, turn: str) -> Vector:
    """Turning on a circle: omega_p = v / R about +z for a left turn, -z for a right one."""
    rate = turn_rate(speed, radius)
    return scale(rate if turn == "left" else -rate, UP)


def pitching_precession(rate: float, bow: str) -> Vector:
    """Pitching at |rate|: the bow rising turns x toward z, a rotation about -y."""
    return scale(-abs(rate) if bow == "rising" else abs(rate), LEFT)


def rolling_precession(rate: float) -> Vector:
    """Rolling: about the fore-and-aft axis x, parallel to the spin axis."""
    return scale(rate, FORWARD)


# ---- a ship's stabiliser gyro: a rotor spinning about the vertical -----------------

GYRO_SENSES = ("clockwise_from_above", "counterclockwise_from_above",
               "clockwise_from_below", "counterclockwise_from_below")


def vertical_spin_direction(sense: str) -> float:
    """+1 if a vertical rotor's spin vector points up (+z), -1 if down: clockwise seen
    from above points away from the observer, down."""
    turn, _, end = sense.partition("_from_")
    if turn not in ("clockwise", "counterclockwise") or end not in ("above", "below"):
        raise ValueError(f"not a vertical rotor's sense: {sense!r}")
    away = 1.0 if turn == "clockwise" else -1.0
    return -away if end == "above" else away


def stabiliser_precession(rate: float, axle_top: str) -> Vector:
    """The stabiliser's axle precessed about the athwartship axis y at |rate|: its top moving
    forward is a rotation about +y (y x z = x), aft about -y."""
    return scale(abs(rate) if axle_top == "forward" else -abs(rate), LEFT)


def axle_top_against(roll: str, spin_up: float) -> str:
    """Which way the top of the stabiliser's axle must move so that the reactive couple
    -(omega_p x H) lifts the side the ship rolls toward: about +x for a roll to port.

    omega_p = s q y, H = h z: -(omega_p x H) = -s q h x, so s = -sign(h) to lift port."""
    s = -spin_up if roll == "port" else spin_up
    return "forward" if s > 0 else "aft"


def couple_on_rotor(precession: Vector, H: Vector) -> Vector:
    """The active gyroscopic couple C = omega_p x H (Eq. 11.29 in vector form)."""
    return cross(precession, H)


def reactive_couple(precession: Vector, H: Vector) -> Vector:
    """The couple the rotor exerts on the vehicle through its bearings: -(omega_p x H)."""
    return scale(-1.0, couple_on_rotor(precession, H))


# ---- effect words ---------------------------------------------------------------

ENDS = {"ship": ("bow", "stern"), "aeroplane": ("nose", "tail")}


#: every single effect `effect` names, per vehicle (a question bank's choices)
EFFECT_WORDS = {
    "ship": ("raises the bow and lowers the stern", "lowers the bow and raises the stern",
             "turns the ship to port", "turns the ship to starboard", "none",
             "lifts the port side and dips the starboard",
             "lifts the starboard side and dips the port"),
    "aeroplane": ("raises the nose and dips the tail", "dips the nose and raises the tail",
                  "turns the nose to the left", "turns the nose to the right")}


def effect(couple: Vector, vehicle: str, tol: float = 1e-12) -> str:
    """Words for what the reactive couple on the vehicle does; "none" if it is zero.

    Pitch (about y): a rotation about -y lifts the front. Yaw (about z): about +z
    turns the vehicle left (to port). Roll (about x): about +x lifts the left
    (port) side.
    """
    size = norm(couple)
    if size == 0 or not math.isfinite(size):
        return "none"
    x, y, z = couple[0] / size, couple[1] / size, couple[2] / size
    words = []
    if abs(y) > tol:
        if vehicle == "ship":
            words.append("raises the bow and lowers the stern" if y < 0 else
                         "lowers the bow and raises the stern")
        else:
            words.append("raises the nose and dips the tail" if y < 0 else
                         "dips the nose and raises the tail")
    if abs(z) > tol:
        if vehicle == "ship":
            words.append("turns the ship to port" if z > 0 else "turns the ship to starboard")
        else:
            words.append("turns the nose to the left" if z > 0 else
                         "turns the nose to the right")
    if abs(x) > tol:
        side = ("port", "starboard") if vehicle == "ship" else ("left wing", "right wing")
        words.append(f"lifts the {side[0]} side and dips the {side[1]}" if x > 0 else
                     f"lifts the {side[1]} side and dips the {side[0]}")
    return "; ".join(words) if words else "none"


def direction(v: Vector) -> Vector | None:
    """The unit vector along v, exact for overflowing (inf) or underflowing (tiny) v; None if 0.

    Written out component by component, without generators: the vehicle kinds ask it twice
    for every effect they name."""
    x, y, z = v
    isinf = math.isinf
    if isinf(x) or isinf(y) or isinf(z):  # the infinite components alone, as +-1
        x = math.copysign(1.0, x) if isinf(x) else 0.0
        y = math.copysign(1.0, y) if isinf(y) else 0.0
        z = math.copysign(1.0, z) if isinf(z) else 0.0
    big = max(abs(x), abs(y), abs(z))
    if big == 0 or not math.isfinite(big):
        return None
    x, y, z = x / big, y / big, z / big
    size = math.sqrt(x * x + y * y + z * z)  # norm((x, y, z))
    return (x / size, y / size, z / size)


def effect_of(precession: Vector, H: Vector, vehicle: str) -> str:
    """The effect words of -(omega_p x H) from the directions alone, so that extreme
    magnitudes cannot change the words; "none" if either vector is zero."""
    p, h = direction(precession), direction(H)
    if p is None or h is None:
        return "none"
    return effect(reactive_couple(p, h), vehicle)


# ---- ship pitching (simple harmonic) ---------------------------------------------

@dataclass(frozen=True)
class Pitching:
    """theta = phi sin(omega_1 t): frequency, largest pitching rate and acceleration."""

    frequency: float          # omega_1 = 2 pi / T
    max_precession: float     # phi omega_1
    max_acceleration: float   # phi omega_1^2


def pitching(amplitude: float, period: float) -> Pitching:
    w1 = circular_frequency(period)
    return Pitching(w1, max_pitching_rate(amplitude, w1), amplitude * w1 * w1)


# ---- four-wheeler ---------------------------------------------------------------

@dataclass(frozen=True)
class FourWheeler:
    """Vertical reactions of each wheel, by cause, SI; outer then inner."""

    wheel_rate: float
    precession: float
    gyroscopic_couple: float   # C_g = H omega_p, positive overturning outward
    centrifugal_couple: float  # C_c = m v^2 h / R
    weight_share: float        # m g / 4 on every wheel
    gyroscopic_share: float    # C_g / (2 x): + on each outer wheel, - on each inner
    centrifugal_share: float   # C_c / (2 x)

    @property
    def outer(self) -> float:
        return outer_reaction(self.weight_share, self.gyroscopic_share, self.centrifugal_share)

    @property
    def inner(self) -> float:
        return inner_reaction(self.weight_share, self.gyroscopic_share, self.centrifugal_share)


def four_wheeler(mass: float, g: float, cg_height: float, track: float, wheel_radius: float,
                 wheel_inertia_total: float, engine_inertia_total: float, gear_ratio: float,
                 engine_sense: str, speed: float, turn_radius: float) -> FourWheeler:
    """Each couple is taken by the outer and inner wheel pairs, x apart: P = C / x per
    pair, C / (2 x) per wheel; the weight is shared equally by the four wheels."""
    w = rolling_rate(speed, wheel_radius)
    wp = turn_rate(speed, turn_radius)
    H = spin_momentum(rotor_inertia(wheel_inertia_total, gear_ratio, engine_inertia_total,
                                    engine_sense), w)
    Cg, Cc = book_couples(H, wp, mass, speed, cg_height, turn_radius)
    return FourWheeler(w, wp, Cg, Cc, weight_share(mass, g), couple_share(Cg, track),
                       couple_share(Cc, track))


def book_couples(H: float, precession: float, mass: float, speed: float, cg_height: float,
                 turn_radius: float) -> tuple[float, float]:
    """(C_g, C_c) for the answers, worked as the books do: H omega_p, and m v v h / R.

    The steps print the same couples as (sum I_w +- G sum I_E) v^2 / (R r_w) and
    m v^2 h / R (overturning_couple, centrifugal_couple); the two orders of working can
    differ in the last bit, and the answers keep the books' order."""
    return H * precession, mass * speed * speed * cg_height / turn_radius


def weight_share(mass: F, g: F) -> F:
    """m g / 4: the weight, shared equally by the four wheels."""
    return mass * g / 4


def couple_share(couple: F, track: F) -> F:
    """C / (2 x): a couple about the fore-and-aft axis taken by the outer and inner wheel
    pairs, x apart; + on each outer wheel, - on each inner one."""
    return couple / (2 * track)


def outer_reaction(weight: F, gyroscopic: F, centrifugal: F) -> F:
    """An outer wheel's reaction: its weight share plus both couples' shares."""
    return weight + gyroscopic + centrifugal


def inner_reaction(weight: F, gyroscopic: F, centrifugal: F) -> F:
    """An inner wheel's reaction: its weight share less both couples' shares."""
    return weight - gyroscopic - centrifugal


def limiting_speed(mass: F, g: F, track: F, turn_radius: F, rotor_inertia: F,
                   wheel_radius: F, cg_height: F) -> F:
    """The speed at which the inner wheels' reaction falls to zero (the rotors' and the
    centre of mass's overturning, I_eq / r_w + m h, must be > 0):

    m g / 4 = (v^2 / (2 x R)) (I_eq / r_w + m h),  I_eq = sum I_w +- G sum I_E.
    """
    return sqrt(mass * g * track * turn_radius
                / (2 * (rotor_inertia / wheel_radius + mass * cg_height)))


# ---- a four-wheeler as the books draw it: bank, wheelbase, engine along the car ---

@dataclass(frozen=True)
class CarLoads:
    """Each wheel's load (the track's force normal to its plane), by cause, SI.

    Axes in the track's plane: x forward, y' across it toward the centre of the curve,
    n normal to it; the track is banked by ``bank`` with its outer side higher. The
    forces on the car in the frame turning with it (weight, the centrifugal m v^2 / R
    through G) and the moments about G of the track's forces equal dH/dt of the rotors,
    omega_p x H (Eq. 11.29):

    - normal:      N = m (g cos(bank) + (v^2 / R) sin(bank))
    - roll (about x, overturning outward): C_c = m h ((v^2 / R) cos(bank) - g sin(bank))
      from the friction across the track at height h below G, and
      C_g = H_across omega_p cos(bank) from the rotors turning with the axles
    - pitch (about y', loading the front wheels when positive):
      C_p = -t s H_along omega_p cos(bank), t = +1 turning left, s = +1 for a spin
      vector pointing forward (an engine along the car)

    Vertical balance and the pitch moment give the axle loads:
    front N a_r / L + C_p / L, rear N a_f / L - C_p / L (a_f, a_r: G to the front and
    rear axles). The roll moment is one equation for two axles: as the books do, each
    axle takes half of it, (C_g + C_c) / (2 x) more on its outer wheel and less on its
    inner one.
    """

    normal: float
    front_share: float  # a_r / L
    wheelbase: float
    track: float
    gyroscopic_couple: float
    centrifugal_couple: float
    pitch_couple: float

    @property
    def front_axle(self) -> float:
        return self.normal * self.front_share + self.pitch_couple / self.wheelbase

    @property
    def rear_axle(self) -> float:
        return self.normal * (1 - self.front_share) - self.pitch_couple / self.wheelbase

    @property
    def side_share(self) -> float:
        """Each wheel's share of the roll couple, + outer, - inner."""
        return (self.gyroscopic_couple + self.centrifugal_couple) / (2 * self.track)

    @property
    def wheels(self) -> tuple[float, float, float, float]:
        """(front outer, front inner, rear outer, rear inner)."""
        f, r, s = self.front_axle / 2, self.rear_axle / 2, self.side_share
        return f + s, f - s, r + s, r - s


def car_loads(mass: float, g: float, cg_height: float, track: float, wheelbase: float,
              cg_to_front: float, bank: float, speed: float, turn_radius: float,
              across: tuple[float, float], along: tuple[float, float]) -> CarLoads:
    """The loads of :class:`CarLoads` at ``speed``.

    Each rotor group's angular momentum is given as (per m/s of speed, fixed): a rotor
    geared to the wheels has H = I G v / r_w, one at a given speed H = I omega. ``across``
    is the sum over the rotors across the car (wheels, transverse engines), signed with
    the wheels' sense; ``along`` is t s H of the engine along the car (the signs of
    C_p's docstring). omega_p = v / R.
    """
    wp = speed / turn_radius
    cos_b, sin_b = math.cos(bank), math.sin(bank)
    centripetal = speed * speed / turn_radius
    H_across = across[0] * speed + across[1]
    H_along = along[0] * speed + along[1]
    return CarLoads(
        normal=mass * (g * cos_b + centripetal * sin_b),
        front_share=(wheelbase - cg_to_front) / wheelbase,
        wheelbase=wheelbase, track=track,
        gyroscopic_couple=H_across * wp * cos_b,
        centrifugal_couple=mass * cg_height * (centripetal * cos_b - g * sin_b),
        pitch_couple=-H_along * wp * cos_b)


def first_lift_speed(load_at: Callable[[float], tuple[float, ...]]) -> float | None:
    """The least speed > 0 at which a wheel's load falls to zero, None if none does.

    Each load is a + b v + c v^2 (the couples grow with v^2, or with v for a rotor at a
    fixed speed), so three speeds fix it exactly; the root is then found in closed form.
    """
    l0, l1, l2 = load_at(0.0), load_at(1.0), load_at(2.0)
    roots = []
    for a, p, q in zip(l0, l1, l2):
        c = (q - 2 * p + a) / 2
        b = p - a - c
        roots += _positive_roots(a, b, c)
    return min(roots) if roots else None


def _positive_roots(a: float, b: float, c: float) -> list[float]:
    """Positive roots of a + b v + c v^2 = 0 where the load goes from positive to
    negative (a wheel lifting, not one landing)."""
    scale = max(abs(a), abs(b), abs(c), 1e-300)
    if abs(c) < 1e-12 * scale:
        return [-a / b] if b and -a / b > 0 and b < 0 else []
    disc = b * b - 4 * a * c
    if disc < 0:
        return []
    root = math.sqrt(disc)
    out = []
    for v in ((-b - root) / (2 * c), (-b + root) / (2 * c)):
        slope = b + 2 * c * v
        if v > 0 and slope < 0:
            out.append(v)
    return out
