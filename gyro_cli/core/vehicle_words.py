"""The words every vehicle kind opens its conventions with (aeroplane, ship, two- and
four-wheeler): kinds may not import each other, so the sentence they share lives here."""

from __future__ import annotations

from .prose import cross, names, plus, rel

_H, _WP, _C = names("H omega_p C")

#: omega_p x H, the couple on the spinning parts (Eq. 11.29), as every vehicle kind writes it
COUPLE = cross(_WP, _H)

#: the sign of a couple about the vehicle's y axis (to the left), where a kind states it
ALONG_LEFT = ("along ", plus(names("x y z")[1]), " (left) if positive")


def reactive_couple(vehicle: str, rotors: str = "rotor") -> tuple:
    """The pieces of ``H: the angular momentum ...; couple on the rotor C = omega_p x H
    (Eq. 11.29); the ship feels the reactive couple -C``, for the kind to finish."""
    return (_H, ": the angular momentum of the spinning parts; ", _WP, ": the precession (the "
            f"turn's angular velocity, about the vertical); couple on the {rotors} ",
            rel(_C, "=", COUPLE), f" (Eq. 11.29); the {vehicle} feels the reactive "
            "couple ", -_C)
