"""Whose numbers a wrong answer used: another student's variant is named only when
chance cannot explain the match (docs/course.md, section 5).

A student's answers to a problem *match* another variant when every value they gave
(every root of every question answered) equals that variant's value to the digits the
student wrote (half a unit of the last digit, relative, at most ``EPS_MAX``). Every
problem the student got wrong must match the same other student. The match is named
only when the expected number of students so named by chance in the class,
N (N - 1) times the product over those problems of the chance that one random variant
lands in the student's box of values, is below ``ALPHA``. That chance is measured on
the variants themselves (:meth:`VariantIndex.chance`): the share of the class's
variants in a box of ``WINDOWS`` around the student's values, times the share of that
box the student's values cover along each direction in which the variants spread
(a problem whose answers all follow one number, such as a moment and the forces it
makes, counts as one value, not three).
"""

from __future__ import annotations

import bisect
import math
import re
from dataclasses import dataclass
from typing import Any

from .expected import parse_value

ALPHA = 0.01  # bound on the expected number of students named by chance, per class
EPS_MAX = 1e-3  # a value written to fewer digits is matched to 0.1%, no looser
EPS_MIN = 1e-9  # below this, floating point and not the student's digits decide
# half-widths (on a log scale) of the boxes the variants' density is taken in: the first
# that holds enough variants
WINDOWS = (0.05, 0.1, 0.2, 0.4, 0.8)

_NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


def written_precision(raw: Any) -> float:
    """Half a unit of the last digit written, relative to the value (``45.13 rpm``:
    0.005 / 45.13), between EPS_MIN and EPS_MAX; EPS_MAX when no number is found."""
    found = _NUMBER.search(str(raw))
    if not found:
        return EPS_MAX
    text = found.group(0).lstrip("+-")
    mantissa, _, exponent = text.lower().partition("e")
    place = -len(mantissa.partition(".")[2]) + (int(exponent) if exponent else 0)
    try:
        value = abs(float(text))
    except ValueError:
        return EPS_MAX
    if value == 0 or not math.isfinite(value):
        return EPS_MAX
    return min(max(0.5 * 10.0 ** place / value, EPS_MIN), EPS_MAX)


@dataclass
class Answered:
    """One student's numeric values of one problem: (question, SI value, precision) in
    the order of the variants' coordinates (questions in order, each one's values sorted)."""

    values: list[tuple[str, float, float]]

    def shape(self) -> tuple[tuple[str, int], ...]:
        counts: dict[str, int] = {}
        for question, _, _ in self.values:
            counts[question] = counts.get(question, 0) + 1
        return tuple(counts.items())


@dataclass
class Match:
    """Another student whose variants every wrong problem's answers match."""

    student: str
    variants: dict[str, tuple[str, str]]  # problem -> (other's variant, own variant)
    chance: float  # expected number of students so named by chance in the class
    #: the other students whose variants have the same numbers (drawn alike): any of them
    #: may be the source, so the note names them all
    also: tuple[str, ...] = ()


class VariantIndex:
    """Every variant's computed values, per problem, to find whose numbers a student's
    wrong answers are and how likely that is by chance."""

    def __init__(self, plan: Any, variants: dict[str, Any], solved: dict[str, Any]) -> None:
        self.plan, self.variants, self.solved = plan, variants, solved
        self._tables: dict[tuple[str, str], tuple[list[float], list[str]]] = {}
        self._vectors: dict[tuple[str, tuple[tuple[str, int], ...]], Any] = {}

    def _values(self, variant: str, question: str) -> list[float] | None:
        answer = self.solved[variant].answers.get(question) if variant in self.solved else None
        if answer is None or answer.si_unit is None and answer.unit is None:
            return None
        values = [float(v) for v in answer.si_values if isinstance(v, (int, float))]
        return sorted(values) if values and all(math.isfinite(v) for v in values) else None

    def _table(self, problem: str, question: str) -> tuple[list[float], list[str]]:
        """Every variant's values of one question, sorted, with the variant of each."""
        table = self._tables.get((problem, question))
        if table is None:
            pairs = [(v, row.variant) for row in self.plan.rows if row.problem == problem
                     for v in self._values(row.variant, question) or []]
            pairs.sort()
            table = ([p[0] for p in pairs], [p[1] for p in pairs])
            self._tables[(problem, question)] = table
        return table

    def _vector(self, variant: str, shape: tuple[tuple[str, int], ...]) -> list[float] | None:
        out: list[float] = []
        for question, count in shape:
            values = self._values(variant, question)
            if values is None or len(values) != count:
                return None
            out += values
        return out

    def answered(self, own: Any, given: dict[str, list[Any]]) -> Answered | None:
        """A student's values of one problem (words left out), or None when a value
        does not parse or is 0."""
        problem = self.variants[own.variant]
        values: list[tuple[str, float, float]] = []
        for question, raw in given.items():
            spec = problem.kind.answer(question)
            if spec is None or not raw:
                return None
            if spec.dimension is None:  # a word: a few possible, no evidence either way
                continue
            parsed = []
            for value in raw:
                try:
                    si = float(parse_value(value, spec.dimension, question).si)
                except Exception:  # the grade row already says what is wrong with it
                    return None
                if si == 0 or not math.isfinite(si):
                    return None
                parsed.append((si, written_precision(value)))
            values += [(question, si, eps) for si, eps in sorted(parsed)]
        return Answered(values) if values else None

    def matching(self, problem: str, own_variant: str, answered: Answered) -> set[str]:
        """The other variants that every value of ``answered`` equals to its digits."""
        question, first, eps = answered.values[0]
        keys, owners = self._table(problem, question)
        width = abs(first) * eps * (1 + 1e-9)
        lo = bisect.bisect_left(keys, first - width)
        hi = bisect.bisect_right(keys, first + width)
        shape = answered.shape()
        found = set()
        for variant in {owners[k] for k in range(lo, hi)} - {own_variant}:
            vector = self._vector(variant, shape)
            if vector is not None and all(
                    abs(x - v) <= abs(x) * e * (1 + 1e-9)
                    for (_, x, e), v in zip(answered.values, vector)):
                found.add(variant)
        return found

    def _logs(self, problem: str, shape: tuple[tuple[str, int], ...]) -> Any:
        """({variant: row}, signs, log |values|) of every variant of ``problem`` of this
        shape."""
        import numpy as np

        cached = self._vectors.get((problem, shape))
        if cached is None:
            ids, rows = [], []
            for row in self.plan.rows:
                if row.problem == problem:
                    vector = self._vector(row.variant, shape)
                    if vector is not None and all(v != 0 for v in vector):
                        ids.append(row.variant)
                        rows.append(vector)
            values = np.array(rows, dtype=float).reshape(len(rows), sum(c for _, c in shape))
            cached = ({v: k for k, v in enumerate(ids)}, np.sign(values),
                      np.log(np.abs(values)))
            self._vectors[(problem, shape)] = cached
        return cached

    def chance(self, problem: str, own_variant: str, answered: Answered) -> float:
        """The chance that one random other variant equals every value of ``answered`` to
        its digits, estimated from the class's variants (an overestimate by design)."""
        import numpy as np

        ids, signs, logs = self._logs(problem, answered.shape())
        others = np.ones(len(ids), dtype=bool)
        if own_variant in ids:
            others[ids[own_variant]] = False
        if not others.any():
            return 1.0
        x = np.array([math.log(abs(v)) for _, v, _ in answered.values])
        sign = np.array([math.copysign(1.0, v) for _, v, _ in answered.values])
        eps = np.array([e for _, _, e in answered.values])
        alike = others & (signs == sign).all(axis=1)
        for window in WINDOWS:  # the smallest box with enough variants to see their spread
            box = logs[alike & (np.abs(logs - x) <= window).all(axis=1)]
            if len(box) >= 2 * len(x) + 2:
                break
        share = 1.0
        if len(box) >= 2 * len(x) + 2:
            spread, directions = np.linalg.eigh(np.cov(box, rowvar=False).reshape(len(x),
                                                                                     len(x)))
            widest = math.sqrt(max(float(spread.max()), 0.0))
            for variance, direction in zip(spread, directions.T):
                half = float(np.abs(direction) @ eps)  # the student's box seen along it
                sigma = math.sqrt(max(float(variance), 0.0))
                # it tells the variants apart: they spread along it much more than the
                # student's digits, and not only as the curve of a lesser dimension bends
                if sigma >= max(10 * half, 0.1 * widest):
                    share *= min(1.0, 2 * half / (math.sqrt(12) * sigma))
        else:  # too few variants near to see how they spread: as if along one direction
            share = min(1.0, float(eps.max()) / window)
        return min(1.0, (len(box) + 1) / int(others.sum()) * share)


def whose(index: VariantIndex, student: str, wrong: dict[str, tuple[Any, dict[str, list[Any]]]],
          class_size: int) -> Match | None:
    """The other student whose variants all of ``student``'s wrong problems match
    (problem -> (own assignment row, question -> values given)), when chance cannot
    explain it; else None."""
    if not wrong:
        return None
    common: set[str] | None = None
    found: dict[str, Answered] = {}
    for problem, (own, given) in wrong.items():
        answered = index.answered(own, given)
        if answered is None:
            return None
        owners = {index.plan.by_variant[v].student
                  for v in index.matching(problem, own.variant, answered)} - {student}
        common = owners if common is None else common & owners
        if not common:
            return None
        found[problem] = answered
    other, *also = sorted(common or ())
    chance = float(class_size) * (class_size - 1)
    variants = {}
    for problem, answered in found.items():
        own = wrong[problem][0]
        theirs = index.plan.by_item[(other, problem)].variant
        variants[problem] = (theirs, own.variant)
        chance *= index.chance(problem, own.variant, answered)
    return Match(other, variants, chance, tuple(also)) if chance < ALPHA else None
