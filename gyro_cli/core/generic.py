"""Maths written once for numbers and formula trees.

``cos(x)`` is ``math.cos(x)`` when x is a number and the node ``cos(x)`` of
core/expr.py when x is a tree, and likewise for the other functions, so a
physics function written with them gives a float called with floats (tests,
fast paths) and the step's tree called with symbols (a kind's worked answer):
the formula is written once. ``pi_like(x)`` is the constant pi of the same sort.

    def directive_stiffness(H: V, rate: V, latitude: V) -> V:
        return H * rate * cos(latitude)        # a float, or H Omega_E cos(lambda)
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any, TypeVar, overload

if TYPE_CHECKING:
    from .expr import Expr

#: a physics function's value: all floats, or all trees
V = TypeVar("V", float, "Expr")


def _numbers(args: tuple[Any, ...]) -> bool:
    return all(isinstance(a, (int, float)) for a in args)


class _Both:
    """A function of `math` on numbers, the node of core/expr.py on trees."""

    def __init__(self, name: str) -> None:
        self.name = name
        self._math = getattr(math, name)

    @overload
    def __call__(self, *args: float) -> float: ...  # type: ignore[overload-overlap]

    @overload
    def __call__(self, *args: Expr | float) -> Expr: ...

    def __call__(self, *args: Any) -> Any:
        if _numbers(args):
            return self._math(*args)
        from . import expr

        return getattr(expr, self.name)(*args)

    def __repr__(self) -> str:
        return f"<generic {self.name}>"


sin, cos, tan, sqrt = _Both("sin"), _Both("cos"), _Both("tan"), _Both("sqrt")
asin, acos, atan, atan2 = _Both("asin"), _Both("acos"), _Both("atan"), _Both("atan2")
exp, log = _Both("exp"), _Both("log")


@overload
def pi_like(*args: float) -> float: ...  # type: ignore[overload-overlap]


@overload
def pi_like(*args: Expr | float) -> Expr: ...


def pi_like(*args: Any) -> Any:
    """pi as a number beside numbers, the constant node ``pi`` beside trees."""
    if _numbers(args):
        return math.pi
    from .expr import PI

    return PI
