"""The words every vehicle kind opens its conventions with (aeroplane, ship, two- and
four-wheeler): kinds may not import each other, so the sentence they share lives here."""

from __future__ import annotations

from .prose import cross, names, rel


def reactive_couple(vehicle: str, rotors: str = "rotor") -> tuple:
    """The pieces of ``H: the angular momentum ...; couple on the rotor C = omega_p x H
    (Eq. 11.29); the ship feels the reactive couple -C``, for the kind to finish."""
    H, wp, C = names("H omega_p C")
    return (H, ": the angular momentum of the spinning parts; ", wp, ": the precession (the "
            f"turn's angular velocity, about the vertical); couple on the {rotors} ",
            rel(C, "=", cross(wp, H)), f" (Eq. 11.29); the {vehicle} feels the reactive "
            "couple ", -C)
