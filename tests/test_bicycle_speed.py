"""The bicycle's shortcuts give exactly what the plain computations give.

Solving a bicycle is the costliest check of a bank, so some of its work is cut; each
shortcut is held here to the computation it replaces, bit for bit, on random bicycles
(Table 1 with every parameter scaled at random, with and without wheel spin, as in
test_bicycle_hurwitz.py):

- ``stable_speeds``, the stable range alone (the range without the wheels' spin that the
  worked answer shows), is ``stability(...).stable`` without the eigenvalues at the
  candidate speeds.
"""

from __future__ import annotations

import pytest

from gyro_cli.physics import bicycle as bike
from test_bicycle_hurwitz import G, bicycles


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
