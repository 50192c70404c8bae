"""The bicycle's stability at a speed decided from the characteristic quartic's coefficients
(Routh-Hurwitz) against the decision from its eigenvalues.

``stability`` tests one speed between consecutive candidate speeds. It used to ask for the
eigenvalues there (the sign of the spectral abscissa); it now asks ``routh_hurwitz`` on
a_k(v) and finds the roots only where rounding could decide. Here, on random bicycles
(Table 1 with every parameter scaled at random, with and without wheel spin) at random
speeds and at speeds ever closer to the weave and capsize speeds, the two decisions must
agree wherever ``routh_hurwitz`` decides, and ``stability`` must give exactly what the
eigenvalue decision gives.
"""

from __future__ import annotations

import math
import random

import pytest

from gyro_cli.physics import bicycle as bike

G = 9.81


def random_bicycle(rng: random.Random) -> dict[str, float]:
    """Table 1 with each parameter scaled by a factor in [0.5, 1.5] (signs kept: z < 0), the
    trail anywhere in [-0.05, 0.25] m and the steer-axis tilt in [-0.3, 0.8] rad; frame
    products of inertia kept inside the positive-definite range."""
    p = {key: value * rng.uniform(0.5, 1.5) for key, value in bike.BENCHMARK.items()}
    p["g"] = G
    p["c"] = rng.uniform(-0.05, 0.25)
    p["lambda"] = rng.uniform(-0.3, 0.8)
    for frame in "BH":
        limit = math.sqrt(p[f"I{frame}xx"] * p[f"I{frame}zz"])
        p[f"I{frame}xz"] = rng.uniform(-0.9, 0.9) * limit
    return p


def by_eigenvalues(m: bike.Matrices, v: float) -> bool:
    """The old decision: every eigenvalue at v has a negative real part."""
    return max(bike.eigenvalues(m, v, G).real) < 0


def decide(m: bike.Matrices, v: float) -> bool | None:
    coeffs = bike.characteristic(m, G)
    a = [bike.polyval(v, c) for c in coeffs]
    terms = [bike.polyval(v, [abs(x) for x in c]) for c in coeffs]
    return bike.routh_hurwitz(a, terms)


def stability_by_eigenvalues(m: bike.Matrices) -> list[tuple[float, float]]:
    """The stable intervals as ``stability`` found them before: the same candidate speeds,
    each interval decided by the eigenvalues at its probe speed."""
    stab = bike.stability(m, G)
    edges = sorted(set(stab.capsize + stab.weave + stab.other))
    points = [0.0] + edges + [math.inf]
    stable: list[tuple[float, float]] = []
    for lo, hi in zip(points, points[1:]):
        probe = 0.5 * (lo + hi) if math.isfinite(hi) else (2 * lo if lo > 0 else 1.0)
        if by_eigenvalues(m, probe):
            if stable and stable[-1][1] == lo:
                stable[-1] = (stable[-1][0], hi)
            else:
                stable.append((lo, hi))
    return stable


def bicycles(count: int, seed: int):
    rng = random.Random(seed)
    out = [bike.matrices(bike.BENCHMARK), bike.matrices(bike.BENCHMARK, gyroscopic=False)]
    while len(out) < count:
        p = random_bicycle(rng)
        m = bike.matrices(p, gyroscopic=rng.random() < 0.75)
        if m.M[0, 0] * m.M[1, 1] - m.M[0, 1] ** 2 > 0:      # the kind refuses the others
            out.append(m)
    return out


def test_routh_hurwitz_agrees_with_the_eigenvalues_wherever_it_decides():
    rng = random.Random(2007)
    decided = {True: 0, False: 0}
    undecided = 0
    flips = 0                       # stable on one side of an edge, unstable on the other
    for m in bicycles(80, seed=1955):
        stab = bike.stability(m, G)
        speeds = [rng.uniform(0.0, 30.0) for _ in range(30)] + [rng.uniform(0, 1e-3)]
        speeds += [rng.lognormvariate(0.0, 3.0) for _ in range(10)]
        for edge in stab.weave + stab.capsize + stab.other:
            speeds.append(edge)
            for k in range(1, 16):
                speeds += [edge * (1 - 10.0 ** -k), edge * (1 + 10.0 ** -k)]
            flips += by_eigenvalues(m, edge * 0.99) != by_eigenvalues(m, edge * 1.01)
        for v in speeds:
            want = by_eigenvalues(m, v)
            got = decide(m, v)
            if got is None:
                undecided += 1
            else:
                decided[got] += 1
                assert got == want, (m, v)
            assert bike._stable_at(m, v, G) == want, (m, v)
    # the comparison means something: most speeds decided without roots, both answers
    # met, the edges crossed, and rounding's cases (within 1e-9 or so of an edge) left
    # to the eigenvalues
    assert decided[True] > 300 and decided[False] > 1000
    assert decided[True] + decided[False] > 4 * undecided > 0
    assert flips > 40


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_stability_is_what_the_eigenvalues_decide(seed):
    for m in bicycles(60, seed=seed):
        assert bike.stability(m, G).stable == stability_by_eigenvalues(m)


def test_undecided_where_rounding_decides():
    """At the weave speed H3 = 0 and at the capsize speed a0 = 0: both to rounding."""
    m = bike.matrices(bike.BENCHMARK)
    stab = bike.stability(m, G)
    assert decide(m, stab.weave[0]) is None and decide(m, stab.capsize[0]) is None
    assert decide(m, 5.0) is True and decide(m, 4.0) is False and decide(m, 10.0) is False
    # a lead a4 <= 0, a zero or a non-finite coefficient: left to the eigenvalues
    terms = [1.0] * 5
    assert bike.routh_hurwitz([1.0, 2.0, 3.0, 1.0, 0.0], terms) is None
    assert bike.routh_hurwitz([1.0, 2.0, 3.0, 1.0, -1.0], terms) is None
    assert bike.routh_hurwitz([0.0, 2.0, 3.0, 1.0, 1.0], terms) is None
    assert bike.routh_hurwitz([math.nan, 2.0, 3.0, 1.0, 1.0], terms) is None
    # (s + 1)^4 = s^4 + 4 s^3 + 6 s^2 + 4 s + 1: stable
    a = [1.0, 4.0, 6.0, 4.0, 1.0]
    assert bike.routh_hurwitz(a, a) is True
    # (s - 1)(s + 1)(s + 2)(s + 3) = s^4 + 5 s^3 + 5 s^2 - 5 s - 6: a1, a0 < 0
    a = [-6.0, -5.0, 5.0, 5.0, 1.0]
    assert bike.routh_hurwitz(a, [abs(x) for x in a]) is False
    # s^4 + s^3 + s^2 + s + 1: the fifth roots of unity but 1, a pair with Re(s) > 0,
    # every a_k > 0 and H3 = 1 - 1 - 1 < 0
    a = [1.0, 1.0, 1.0, 1.0, 1.0]
    assert bike.routh_hurwitz(a, a) is False
    # (s^2 + 1)(s + 1)^2 = s^4 + 2 s^3 + 2 s^2 + 2 s + 1: roots +-i, H3 = 8 - 4 - 4 = 0
    a = [1.0, 2.0, 2.0, 2.0, 1.0]
    assert bike.routh_hurwitz(a, a) is None
