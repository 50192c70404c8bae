"""The bicycle's shortcuts give exactly what the plain computations give.

Solving a bicycle is the costliest check of a bank, so some of its work is cut; each
shortcut is held here to the computation it replaces, bit for bit, on random bicycles
(Table 1 with every parameter scaled at random, with and without wheel spin, as in
test_bicycle_hurwitz.py):

- ``stable_speeds``, the stable range alone (the range without the wheels' spin that the
  worked answer shows), is ``stability(...).stable`` without the eigenvalues at the
  candidate speeds.
- ``roots`` stops its Aberth sweeps once z comes back to where an earlier sweep left it
  (the sweeps would go round that cycle to the 500th), and its Newton polish at a step
  that leaves x as it is: the roots are those of every sweep and step run
  (``roots_plain`` below, the finder as it was, in its plainest form).
- the characteristic coefficients a_k(v) and H3(v) have their polynomial products
  written out: they are what the polynomial arithmetic gives (``polymul``, ``polyadd``,
  ``polysub``), also for matrices with zero, negative-zero, tiny and huge entries.
- ``stability`` and ``stable_speeds`` are remembered per bicycle, as the characteristic
  coefficients are (keyed by the matrices' values: 0.0 and -0.0 are one key, and the
  answers are the same bits for both); each call gets lists of its own.
"""

from __future__ import annotations

import cmath
import math
import random

import pytest
from test_bicycle_hurwitz import G, bicycles, random_bicycle

from gyro_cli.physics import bicycle as bike

# ---- the plain computations -----------------------------------------------------

def _trim(c):
    c = list(c)
    while len(c) > 1 and c[-1] == 0:
        c.pop()
    return c or [0.0]


def _polyval(x, c):
    value = c[-1] + x * 0
    for coefficient in reversed(c[:-1]):
        value = coefficient + value * x
    return value


def _polyder(c):
    return [k * c[k] for k in range(1, len(c))] or [0.0]


def _newton(x, c, d, steps=4):
    value = _polyval(x, c)
    for _ in range(steps):
        if value == 0:
            break
        slope = _polyval(x, d)
        if slope == 0:
            break
        trial = x - value / slope
        new = _polyval(trial, c)
        if not abs(new) <= abs(value):
            break
        x, value = trial, new
    return x


SWEEPS_RUN = []      # how many sweeps each call of roots_plain ran


def roots_plain(c):
    """The root finder with its Aberth sweeps run until none moves a root, or 500."""
    c = _trim([float(x) for x in c])
    zeros = 0
    while len(c) > 1 and c[0] == 0:
        c.pop(0)
        zeros += 1
    n = len(c) - 1
    out = [0j] * zeros
    if n < 1:
        return out
    if n == 1:
        return out + [complex(-c[0] / c[1])]
    monic = [x / c[-1] for x in c]
    if not all(math.isfinite(x) for x in monic):
        return out + [complex(math.nan, 0.0)] * n
    radius = 2 * max(abs(monic[k]) ** (1.0 / (n - k)) for k in range(n))
    z = [radius * cmath.exp(1j * (2 * math.pi * k / n + 0.4)) for k in range(n)]
    dmonic = _polyder(monic)
    for sweep in range(500):  # noqa: B007 (counted after the loop)
        moved = False
        for i in range(n):
            zi = z[i]
            value = _polyval(zi, monic)
            if value == 0:
                continue
            slope = _polyval(zi, dmonic)
            others = 0
            for j in range(n):
                if j != i and zi != z[j]:
                    others = others + 1.0 / (zi - z[j])
            ratio = value / slope if slope != 0 else complex(math.inf)
            denominator = 1.0 - ratio * others
            step = ratio if denominator == 0 else ratio / denominator
            if not cmath.isfinite(step):
                continue
            z[i] = zi = zi - step
            if abs(step) > 4 * bike._EPS * abs(zi):
                moved = True
        if not moved:
            break
    SWEEPS_RUN.append(sweep + 1)
    d = _polyder(c)
    polished = [complex(_newton(zi, c, d)) for zi in z]
    real, upper, lower = [], [], []
    for zi in polished:
        if abs(zi.imag) <= 1e-10 * max(1.0, abs(zi)):
            real.append(zi.real)
        elif zi.imag > 0:
            upper.append(zi)
        else:
            lower.append(zi)
    while len(upper) != len(lower):
        side = upper if len(upper) > len(lower) else lower
        nearest = min(side, key=lambda e: abs(e.imag))
        side.remove(nearest)
        real.append(nearest.real)
    for x in real:
        out.append(complex(float(_newton(x, c, d)), 0.0))
    for zu in upper:
        partner = min(lower, key=lambda e: abs(e - zu.conjugate()))
        lower.remove(partner)
        zp = complex(_newton(0.5 * (zu + partner.conjugate()), c, d))
        zp = complex(zp.real, abs(zp.imag))
        out.extend([zp, zp.conjugate()])
    return out


def same(a, b) -> bool:
    """Equal bit for bit (repr tells 0.0 from -0.0 and prints every digit)."""
    return repr(a) == repr(b)


@pytest.mark.parametrize("seed", [4, 5, 6])
def test_stable_speeds_are_the_stable_range_of_stability(seed):
    ranges, others = set(), 0
    for m in bicycles(80, seed=seed):
        stab = bike.stability(m, G)
        assert bike.stable_speeds(m, G) == stab.stable
        ranges.add(len(stab.stable))
        others += bool(stab.other)
    # the comparison means something: bicycles with no stable range and with one, and
    # candidates where the stability does not change (edges all the same)
    assert ranges == {0, 1} and others > 10


def polynomials(seed: int):
    """What ``roots`` is asked: the characteristic quartic of random bicycles at random
    speeds and at every candidate speed (where a root is at 0 or a pair is +-i omega or
    +-sigma: the sweeps that never meet their tolerance), the polynomials in v^2 of the
    candidates, and quartics with double roots and pairs +-sigma made on purpose."""
    rng = random.Random(seed)
    for m in bicycles(40, seed=seed):
        coeffs = bike.characteristic(m, G)
        even = [c[::2] for c in (coeffs[0], bike.hurwitz_of(m, G))]
        yield from even
        stab = bike.stability(m, G)
        for v in stab.weave + stab.capsize + stab.other + [rng.uniform(0, 20) for _ in range(3)]:
            yield [bike.polyval(v, c) for c in coeffs]
    for _ in range(60):
        a, b, c = (rng.uniform(-5, 5) for _ in range(3))
        yield [a * a * b * c, -(a * a * (b + c) + 2 * a * b * c), a * a + 2 * a * (b + c) + b * c,
               -(2 * a + b + c), 1.0]                       # (s - a)^2 (s - b) (s - c)
        yield [-a * a * b, 0.0, a * a - b, 0.0, 1.0][::rng.choice((1, -1))]
        yield [rng.uniform(-1, 1) * 10.0 ** rng.randint(-3, 3) for _ in range(rng.randint(2, 7))]


@pytest.mark.parametrize("seed", [7, 8])
def test_roots_are_those_of_every_sweep_run(seed):
    SWEEPS_RUN.clear()
    count = 0
    for c in polynomials(seed):
        assert same(bike.roots(c), roots_plain(c)), c
        count += 1
    # the comparison means something: polynomials whose sweeps never settle (the cycle
    # found), some settling after the watch begins, most before
    assert SWEEPS_RUN.count(500) >= 3
    assert any(bike._WATCH < k < 500 for k in SWEEPS_RUN)
    assert sum(k <= bike._WATCH for k in SWEEPS_RUN) > count / 2


def test_roots_cycle_of_a_pair_plus_minus_sigma():
    """A quartic met at a root of H3(v) of a random bicycle, where the stability does not
    change (a real pair +-sigma): the sweeps go round a cycle in the last bits."""
    for seed in range(200):
        m = bike.matrices(random_bicycle(random.Random(seed)))
        if m.M[0, 0] * m.M[1, 1] - m.M[0, 1] ** 2 <= 0:
            continue
        for v in bike.stability(m, G).other:
            c = [bike.polyval(v, a) for a in bike.characteristic(m, G)]
            SWEEPS_RUN.clear()
            want = roots_plain(c)
            if SWEEPS_RUN == [500]:
                assert same(bike.roots(c), want)
                return
    pytest.fail("no quartic whose sweeps never settle")


def special_matrices(seed: int, count: int):
    """Matrices whose entries are drawn from ordinary numbers, 0.0, -0.0, numbers whose
    products underflow or overflow, and infinities: where the written-out products must
    still be the polynomials' (or be left to them)."""
    rng = random.Random(seed)
    special = (0.0, -0.0, 1e-170, -3e-200, 1e160, -2e200, math.inf)

    def entry():
        return rng.choice(special) if rng.random() < 0.3 else rng.gauss(0.0, 10.0)

    for _ in range(count):
        yield bike.Matrices(*(bike.Matrix2([[entry(), entry()], [entry(), entry()]])
                              for _ in range(4)))


def test_characteristic_and_hurwitz_written_out_are_the_polynomials():
    ms = bicycles(150, seed=9)
    ms += [bike.matrices(dict(bike.BENCHMARK, c=0.0)), bike.matrices(dict(bike.BENCHMARK,
                                                                           **{"lambda": 0.0}))]
    ms += list(special_matrices(10, 3000))
    finite = 0
    for m in ms:
        for g in (G, 0.0):
            want = bike._characteristic_by_polynomials(m, g)
            got = bike._characteristic_computed(m, g)
            assert same(got, want), m
            resolved = bike.characteristic(m, g)  # H3 of the coefficients as printed
            assert same(bike._hurwitz_of(m, g), tuple(bike.hurwitz(resolved)))
            finite += all(math.isfinite(x) for a in want for x in a)
    # the comparison means something: many finite, many not (left to the polynomials)
    assert finite > 1000 and 2 * len(ms) - finite > 1000


def _flipped_zeros(m: bike.Matrices) -> bike.Matrices:
    """The same matrices with every zero entry of the other sign."""
    def flip(a):
        return bike.Matrix2([[-x if x == 0 else x for x in row] for row in a])
    return bike.Matrices(flip(m.M), flip(m.C1), flip(m.K0), flip(m.K2))


def _forget() -> None:
    for cached in (bike._characteristic, bike._hurwitz_of, bike._magnitudes, bike._stability,
                   bike._stable_speeds):
        cached.cache_clear()


def test_stability_remembered_per_bicycle_is_what_it_works_out():
    for m in bicycles(40, seed=13):
        other = _flipped_zeros(m)
        assert other == m and hash(other) == hash(m)       # one key for the cache
        _forget()
        first = bike.stability(m, G)
        want = repr((first, first.spectra, bike.stable_speeds(m, G)))
        _forget()
        flipped = bike.stability(other, G)
        assert repr((flipped, flipped.spectra, bike.stable_speeds(other, G))) == want
        again = bike.stability(m, G)                       # remembered
        assert repr((again, again.spectra, bike.stable_speeds(m, G))) == want
        # lists of its own: changing them changes nothing remembered
        again.weave.append(1.0)
        again.stable.clear()
        again.spectra.clear()
        bike.stable_speeds(m, G).append((0.0, 1.0))
        last = bike.stability(m, G)
        assert repr((last, last.spectra, bike.stable_speeds(m, G))) == want


def test_without_spin_a0_has_no_v2_term_and_no_capsize_speed():
    """Without the wheels' spin (S_T = S_F = 0), K2_pp = K2_dp = 0, K2_dd = S_A cos(lambda)
    / w and K2_pd = -m_T z_T cos(lambda) / w, while K0_pp = m_T z_T and K0_dp = -S_A. So
    a0 = det(g K0 + v^2 K2) has the v^2 coefficient g (K0_pp K2_dd - K2_pd K0_dp) =
    g (m_T z_T S_A - m_T z_T S_A) cos(lambda) / w = 0: a0 does not depend on v and no
    speed makes it 0. The products came out as +-4.5e-13, printed as a coefficient, and
    -4.5e-13 gave a quarter of these bicycles a capsize speed near 1e8 m/s."""
    rng = random.Random(1)
    for _ in range(200):
        p = {k: v * rng.uniform(0.7, 1.3) if isinstance(v, float) and v and k != "lambda"
             else v for k, v in bike.BENCHMARK.items()}
        m = bike.matrices(p, gyroscopic=False)
        a0 = bike.characteristic(m, G)[0]
        assert len(a0) == 1, a0  # a number: positive, or negative for a bicycle that falls
        assert bike.stability(m, G).capsize == []


def test_a_coefficient_is_zeroed_only_below_its_rounding():
    """With the wheels spinning every coefficient is kept, bit for bit (the benchmark's,
    and 150 drawn bicycles'): only what double precision cannot resolve is set to 0."""
    for m in [bike.matrices(dict(bike.BENCHMARK))] + bicycles(150, seed=4):
        for g in (G, 0.0):
            computed = bike._characteristic_computed(m, g)
            for got, was in zip(bike._characteristic(m, g), computed):
                for c, x in zip(got, was):
                    assert c == x or (c == 0.0 and abs(x) < 1e-9 * max(map(abs, was))), (got, was)
    benchmark = bike.matrices(dict(bike.BENCHMARK))
    assert same(bike._characteristic(benchmark, G), bike._characteristic_computed(benchmark, G))
