"""physics/elliptic.py against scipy.special's Carlson forms (an independent
implementation) and against closed forms in the limits."""

from __future__ import annotations

import math
import random

import pytest

from gyro_cli.physics.elliptic import carlson_rj, complete_K

scipy_special = pytest.importorskip("scipy.special")


def _cases(count: int = 3000) -> list[tuple[float, float]]:
    """(y = 1 - m, n) spread over the released top's range: m from 0 to 1 - 1e-14,
    n from -1e4 to 1 - 1e-12 (the axis nearly reaching a pole)."""
    rng = random.Random(11)
    cases = []
    while len(cases) < count:
        y = rng.choice([rng.random(), 10 ** rng.uniform(-14, 0), 1 - 10 ** rng.uniform(-14, 0)])
        n = rng.choice([rng.uniform(-50, 1), 1 - 10 ** rng.uniform(-12, 0),
                        -(10 ** rng.uniform(-12, 4)), 10 ** rng.uniform(-12, 0)])
        if 1 - n > 0:
            cases.append((y, n))
    return cases


def test_K_and_RJ_agree_with_scipy() -> None:
    worst_K = worst_J = 0.0
    for y, n in _cases():
        K = float(scipy_special.elliprf(0.0, y, 1.0))
        J = float(scipy_special.elliprj(0.0, y, 1.0, 1 - n))
        worst_K = max(worst_K, abs(complete_K(y) - K) / K)
        worst_J = max(worst_J, abs(carlson_rj(0.0, y, 1.0, 1 - n) - J) / J)
    assert worst_K < 1e-14
    assert worst_J < 1e-13  # scipy's own error reaches 2e-14 near the poles


def test_limits_in_closed_form() -> None:
    assert complete_K(1.0) == pytest.approx(math.pi / 2, rel=1e-15)          # m = 0
    assert complete_K(0.0) == math.inf                                       # m = 1
    # m -> 1: K ~ ln(4 / sqrt(1 - m))
    assert complete_K(1e-20) == pytest.approx(math.log(4 / 1e-10), rel=1e-15)
    for x in (1e-3, 0.5, 2.0, 7.0):
        assert carlson_rj(x, x, x, x) == pytest.approx(x ** -1.5, rel=1e-15)
    # m = 0: Pi(n, 0) = pi / (2 sqrt(1 - n)), so n/3 R_J(0, 1, 1, 1 - n) = Pi - pi/2
    for n in (-100.0, -1.0, -1e-6, 1e-6, 0.5, 1 - 1e-9):
        expected = math.pi / 2 * (1 / math.sqrt(1 - n) - 1)
        assert n / 3 * carlson_rj(0.0, 1.0, 1.0, 1 - n) == pytest.approx(expected, rel=1e-13)
    # p = z: R_J(x, y, z, z) = R_D(x, y, z); R_D(0, 1, 1) = 3 pi / 4 (DLMF 19.20.18 family)
    assert carlson_rj(0.0, 1.0, 1.0, 1.0) == pytest.approx(3 * math.pi / 4, rel=1e-15)
