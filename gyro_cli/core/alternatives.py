"""Other ways books state a given quantity: a wheel's diameter for its radius, an axis's
angle from the horizontal or from the downward vertical for the chapter's theta (from
the upward vertical).

The loader reads an alternative key into the key the kind declares (one place, so no kind
changes); the worked answer shows the conversion as a step under "Data as given".
"""

from __future__ import annotations

from collections.abc import Callable

from .expr import PI, Expr, Sym
from .params import Param
from .record import record

#: a param's doc holding this measures its angle as the chapter does
UPWARD = "from the upward vertical"

#: radii a book may give as a diameter ("treads 1.8 m in diameter"), and the key for it
DIAMETERS = {"wheel_radius": "wheel_diameter"}


@record(frozen=True)
class Alternative:
    """``key`` stated as books do, read into the kind's ``target``."""

    key: str
    target: str
    symbol: str
    reading: str  # how the key is read, for the worked answer and `gyro kinds`
    to_target: Callable[[Expr], Expr]
    unit: str  # the unit the step shows ("m", "deg")
    note: str = ""  # the step's note in the worked answer: words, no formula

    def param_for(self, target: Param) -> Param:
        """The Param this key is read with: the target's dimension; a diameter positive
        where the radius is (an angle's limits are the target's, checked after)."""
        return Param(self.key, target.dimension, self.symbol, self.reading,
                     positive=target.positive and self.unit == "m")


def alternatives_of(params: dict[str, Param]) -> dict[str, Alternative]:
    """The alternative keys a kind with these params accepts, by key."""
    found: dict[str, Alternative] = {}
    for name, param in params.items():
        if name in DIAMETERS and DIAMETERS[name] not in params:
            key = DIAMETERS[name]
            found[key] = Alternative(key, name, "d" + param.symbol[1:], f"{name} = {key} / 2",
                                     lambda d: d / 2, "m", "half the diameter given")
        if param.dimension == "angle" and UPWARD in param.doc:
            s = param.symbol
            found[f"{name}_from_horizontal"] = Alternative(
                f"{name}_from_horizontal", name, f"{s}_h", f"the angle above the "
                f"horizontal (negative below): {name} = 90 deg - {name}_from_horizontal, "
                "from the upward vertical", lambda a: PI / 2 - a, "deg",
                "the angle given from the horizontal, read from the upward vertical")
            found[f"{name}_from_downward_vertical"] = Alternative(
                f"{name}_from_downward_vertical", name, f"{s}_d", f"the angle from the "
                f"downward vertical: {name} = 180 deg - {name}_from_downward_vertical, from "
                "the upward vertical", lambda a: PI - a, "deg",
                "the angle given from the downward vertical, read from the upward vertical")
    return found


def converted(alternative: Alternative, si: float) -> float:
    """The target's SI value for the alternative's SI value."""
    return alternative.to_target(Sym(alternative.symbol, si)).value


def step_tree(alternative: Alternative, si: float) -> Expr:
    """The conversion as a tree, for the worked answer."""
    return alternative.to_target(Sym(alternative.symbol, si, alternative.unit))

