"""The words every vehicle kind opens its conventions with (aeroplane, ship, two- and
four-wheeler): kinds may not import each other, so the sentence they share lives here."""

from __future__ import annotations

from .expr import Sym
from .given import Given
from .prose import cross, names, plus, rel
from .work import Work

_H, _WP, _C = names("H omega_p C")

#: omega_p x H, the couple on the spinning parts (Eq. 11.29), as every vehicle kind writes it
COUPLE = cross(_WP, _H)

#: the sign of a couple about the vehicle's y axis (to the left), where a kind states it
ALONG_LEFT = ("along ", plus(names("x y z")[1]), " (left) if positive")


def reactive_couple(vehicle: str, rotors: str = "rotor",
                    precession: str = "the turn's angular velocity, about the vertical") -> tuple:
    """The pieces of ``H: the angular momentum ...; omega_p: the precession (``precession``);
    couple on the rotor C = omega_p x H (Eq. 11.29); the ship feels the reactive couple -C``,
    for the kind to finish."""
    return (_H, ": the angular momentum of the spinning parts; ", _WP, f": the precession "
            f"({precession}); couple on the {rotors} ",
            rel(_C, "=", COUPLE), f" (Eq. 11.29); the {vehicle} feels the reactive "
            "couple ", -_C)


#: said where a vehicle's turn is stated and the data give none: the senses printed are then a
#: left turn's (the sizes do not depend on it)
TAKEN_LEFT = " (no turn is given: taken left; only the senses depend on it)"


def turn_of(given: Given) -> tuple[str, str]:
    """The vehicle's turn, "left" or "right" (left when none is given), and what to add
    where it is stated: TAKEN_LEFT when it was not given."""
    return given.word("turn", "left"), "" if "turn" in given else TAKEN_LEFT


def rotor_steps(work: Work, J: float, spin: float, inertia: str,
                speed: str) -> tuple[Sym, Sym, float]:
    """The rotor's steps every vehicle kind opens with: J and omega (with the notes
    ``inertia`` and ``speed``), and H = J omega; the symbols J, omega and H's size."""
    work.step("J", value=J, unit="kg*m^2", note=inertia)
    work.step("omega", value=spin, unit="rad/s", note=speed)
    J_, omega = Sym("J", J, "kg m^2"), Sym("omega", spin, "rad/s")
    return J_, omega, work.step("H", J_ * omega, unit="kg m^2/s")
