"""Small pieces of algebra that several kinds share."""

from __future__ import annotations

import math


def quadratic_roots(a: float, b: float, c: float) -> list[float]:
    """Real roots of a x^2 + b x + c = 0, ascending, without cancellation; [] if none."""
    if a == 0:
        return [-c / b] if b != 0 else []
    disc = b * b - 4 * a * c
    if disc < 0:
        return []
    q = -0.5 * (b + math.copysign(math.sqrt(disc), b))
    if q == 0:
        return [0.0]
    return sorted({q / a, c / q})


def cos_theta(theta: float) -> float:
    """cos(theta), exactly 0 at 90 deg (pi/2 in floating point gives 6e-17)."""
    cos = math.cos(theta)
    return 0.0 if abs(cos) < 1e-12 else cos
