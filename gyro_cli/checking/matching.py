"""Matching expected values to computed roots, and naming the likely slip when
one is off: pure functions on SI floats, plus ``compare`` that makes AnswerChecks."""

from __future__ import annotations

import dataclasses
import math
from typing import Any

from ..core.errors import InputError
from ..core.work import num
from .expected import Expected
from .results import AnswerCheck
from .tolerance import Tolerance

# ---- matching and diagnosis -------------------------------------------------

def distance(expected: float, got: float) -> float:
    """How far apart two values are for matching: |ln(|got| / |expected|)|.

    On a log scale a slip (10x, 2 pi, the sign) stays nearest to the root it
    spoils; a differing sign adds a hair so like signs pair first. A zero pairs
    only by absolute difference, after every non-zero pair.
    """
    if expected == 0 or got == 0:
        return 0.0 if expected == got else 1e6 + abs(got - expected)
    # log|got| - log|expected|, not log(|got| / |expected|): the ratio of 1e-300 and
    # 1e300 underflows to 0.
    return abs(math.log(abs(got)) - math.log(abs(expected))) + \
        (1e-9 if (got < 0) != (expected < 0) else 0)


def match_roots(expected: list[float], computed: list[float],
                passes: Any = None, slipped: Any = None) -> list[tuple[int | None, int | None]]:
    """Pairs (expected index, computed index): nearest first, none used twice.

    ``passes(i, j)`` (optional) says whether the pair is within tolerance; such
    pairs are taken before any other; then the pairs ``slipped(i, j)`` (optional) says
    a slip explains (`diagnose`: both roots in rad/s where rpm was asked are each the
    root 9.549 times theirs, though the larger is nearer the smaller root). Unpaired
    expected values come as (i, None), unclaimed roots as (None, j); the list is in the
    order of the expected values, then the extra roots.
    """
    pairs = sorted((not passes(i, j) if passes else False,
                    not slipped(i, j) if slipped else False, distance(e, c), i, j)
                   for i, e in enumerate(expected) for j, c in enumerate(computed))
    of_expected: dict[int, int] = {}
    used: set[int] = set()
    for _, _, _, i, j in pairs:
        if i not in of_expected and j not in used:
            of_expected[i] = j
            used.add(j)
    out: list[tuple[int | None, int | None]] = [(i, of_expected.get(i))
                                                for i in range(len(expected))]
    out += [(None, j) for j in range(len(computed)) if j not in used]
    return out


# (factor, what it suggests); both directions are tried, and each with the sign.
SLIPS: tuple[tuple[float, str], ...] = (
    (2 * math.pi, "a factor of 2 pi: rad/s against rev/s (Hz)"),
    (60 / (2 * math.pi), "a factor of 60/(2 pi) = 9.549: rpm against rad/s"),
    (60.0, "a factor of 60: rpm against rev/s (Hz), or minutes against seconds"),
    (9.81, "a factor of g = 9.81 m/s^2: mass against weight"),
    (32.174, "a factor of g = 32.2 ft/s^2: mass against weight (lbm against slug or lbf)"),
    (180 / math.pi, "a factor of 180/pi = 57.30: degrees against radians"),
)


def diagnose(expected: float, got: float, half_width: float,
             other_roots: list[float] | None = None) -> str | None:
    """The likely slip that turns ``expected`` into ``got``, or None.

    Tried in order: another computed root of the same answer, the sign, a power
    of ten, then the factors in SLIPS. A factor counts only when got is within the
    answer's own tolerance (``half_width`` relative to expected, at most 2%) of
    expected times it: a value that the slip, undone, would not make pass is just off.
    """
    for root in other_roots or []:
        if abs(root - expected) <= half_width:
            return f"the other root: expected matches the computed root {num(root)} (SI)"
    if expected == 0 or got == 0 or not math.isfinite(got):
        return None
    # 1e-12: the rounding of got / expected / factor, for an exact (zero) tolerance
    window = min(half_width / abs(expected), 0.02) + 1e-12
    ratio = got / expected
    if not math.isfinite(ratio) or ratio == 0 or not math.isfinite(window):
        return None  # a denormal expected value: no slip to name
    if abs(ratio + 1) <= window:
        return "the sign: got is minus the expected value"
    sign = " and the sign" if ratio < 0 else ""
    size = abs(ratio)
    power = round(math.log10(size))
    if power and abs(size / 10.0 ** power - 1) <= window:
        times = f"10^{power}" if abs(power) > 1 else ("10" if power == 1 else "1/10")
        return f"a power of ten{sign}: got is {times} times expected (a unit prefix or a " \
               "decimal point?)"
    best: tuple[float, str] | None = None
    for factor, what in SLIPS:
        for f, direction in ((factor, "got is larger"), (1 / factor, "got is smaller")):
            miss = abs(size / f - 1)
            if miss <= window and (best is None or miss < best[0]):
                best = (miss, f"{what} ({direction}){sign}")
    return best[1] if best else None



# Labels of roots: values of one answer that a book may quote in any order, or one of.
ROOT_LABELS = frozenset({"slow", "fast", "approximation", "rotor side heavier",
                         "block side heavier"})


def ordered(labels: list[str]) -> bool:
    """Whether an answer's values have a fixed order (A then B, outer then inner, a
    force's components, a matrix's entries): labelled, and not labelled as roots."""
    return bool(labels) and not ROOT_LABELS & set(labels)


def match_in_order(n_expected: int, n_computed: int) -> list[tuple[int | None, int | None]]:
    """Pairs for an ordered answer: the i-th expected value with the i-th computed one."""
    out: list[tuple[int | None, int | None]] = [(i, i if i < n_computed else None)
                                                for i in range(n_expected)]
    return out + [(None, j) for j in range(n_expected, n_computed)]


def compare(name: str, values: list[Expected], tolerance: Tolerance, reported: Any,
            strict: bool = True, convention: str = "",
            signs: tuple[tuple[str, int], ...] = (),
            root_widths: list[float] | None = None) -> list[AnswerCheck]:
    """Compare the expected values of one answer with its computed values: roots as sets
    (each expected value with its nearest root), an ordered answer (labelled A, B, outer,
    inner, components) position by position.

    With ``strict`` False a computed root that no expected value claims, where
    every expected value found its root, is "not keyed": listed, not failed
    (a book quotes the slow precession and not the fast one). ``convention``: how
    the kind signs this answer, quoted when an expected value is a computed one's size;
    ``signs``, the words that sign its sizes (``up``, ``down``), offered in that case. A
    value whose words name its place (``1.4 kN down at B``) is compared with that place.
    ``root_widths``: the SI half-width of each computed root, when the computed values are
    the truth and the values compared are a student's (grading: `tolerance.student_widths`);
    else each expected value's own tolerance decides.
    """
    computed = shown = list(reported.si_values)  # shown: as the solver signs them
    if tolerance.magnitude and reported.si_unit is not None:
        computed = [abs(c) for c in computed]
        values = [dataclasses.replace(v, si=abs(float(v.si)), number=abs(v.number))
                  for v in values]
    labels = list(reported.labels)
    out: list[AnswerCheck] = []
    if reported.unit is None and reported.si_unit is None:  # a word answer
        got = [str(v) for v in computed]
        several = len(values) > 1
        for n, value in enumerate(values):
            ok = str(value.si).lower() in (g.lower() for g in got)
            out.append(AnswerCheck(name, n + 1 if several else None, value.text, ", ".join(got),
                                   ok, expected_value=value.text, got_value=", ".join(got),
                                   expected_si=value.si, got_si=", ".join(got),
                                   tolerance="exact", message="" if ok else
                                   f"expected {value.text}, got {', '.join(got)}"))
        return out
    widths_si = [tolerance.half_width(float(v.si), v.number) for v in values]
    for v, w in zip(values, widths_si):
        if not math.isfinite(w / v.factor):  # 1e300 rev/s in arcsec/yr
            raise InputError(f"tolerance {tolerance.text!r} is too large to express in "
                             f"{v.unit or reported.unit}; give a smaller one", key="tolerance")

    def width(i: int, j: int | None) -> float:
        return root_widths[j] if root_widths is not None and j is not None else widths_si[i]

    def within(i: int, j: int) -> bool:
        return abs(computed[j] - float(values[i].si)) <= width(i, j) * (1 + 1e-12) + 1e-300

    in_order = ordered(labels)
    if any(v.side is not None for v in values):  # placed by their words
        pairs = placed_pairs([v.side for v in values], len(computed))
    elif len(values) == 1 and len(computed) == 1:  # most answers: one value, one root
        pairs = [(0, 0)]
    elif in_order:
        pairs = match_in_order(len(values), len(computed))
    else:
        def slip(i: int, j: int) -> str | None:
            return diagnose(computed[j], float(values[i].si), width(i, j))

        given = [float(v.si) for v in values]
        pairs = match_roots(given, computed, within)
        # Paired by a slip instead where one slip explains every value that is off (bob's
        # two roots in rad/s, written as rpm); two different slips, or the two directions
        # of one, are a coincidence of the roots' ratio, not the student's slip.
        by_slip = match_roots(given, computed, within, lambda i, j: slip(i, j) is not None)
        slips = {slip(i, j) for i, j in by_slip
                 if i is not None and j is not None and not within(i, j)}
        if by_slip != pairs and len(slips) == 1 and None not in slips:
            pairs = by_slip
        # A root equal to one an expected value already matched (the moment, the
        # same for both precession rates) is covered by it, not a missing value.
        pairs = [(i, j) for i, j in pairs
                 if i is not None or (j is not None and not any(within(k, j)
                                                                for k in range(len(values))))]
    all_found = all(j is not None and within(i, j) for i, j in pairs if i is not None)
    several = len(values) > 1 or len(pairs) > 1
    for position, (i, j) in enumerate(pairs):
        index = position + 1 if several else None
        label = f" ({labels[j]})" if j is not None and j < len(labels) and labels[j] else ""
        if i is None:  # a computed root that no expected value claims
            assert j is not None, "no pairing pairs nothing with nothing"
            unit, factor = values[0].unit or reported.unit or "", values[0].factor
            got_value = computed[j] / factor
            got_text = _shown(shown[j] / factor, unit, label)  # as signed (above)
            if not strict and all_found:
                out.append(AnswerCheck(
                    name, index, None, got_text, True,
                    unit=unit, got_value=got_value, got_si=computed[j],
                    si_unit=reported.si_unit, tolerance=tolerance.text, keyed=False,
                    message="not keyed: the key quotes no value for this root "
                            "(gyro check --strict fails it)"))
                continue
            out.append(AnswerCheck(
                name, index, None, got_text, False,
                unit=unit, got_value=got_value, got_si=computed[j],
                si_unit=reported.si_unit, tolerance=tolerance.text,
                message=f"computed root {num(got_value)} {unit}{label} has no expected "
                        f"value ({len(values)} expected, {len(computed)} computed)"))
            continue
        value = values[i]
        unit = value.unit or reported.unit or ""
        width_si = width(i, j)
        half = width_si / value.factor
        check = AnswerCheck(name, index, value.text, None, False, unit=unit,
                            expected_value=value.number, expected_si=value.si,
                            si_unit=reported.si_unit, tolerance=tolerance.text,
                            tolerance_value=half)
        if j is None:
            check.message = (f"expected {value.text} +- {num(half)} {unit}, got no root "
                             f"({len(values)} expected, {len(computed)} computed)").replace(" ,", ",")
            check.slip = diagnose(float(value.si), math.nan, width_si, computed)
            if check.slip:
                check.slip = _other_root(value, computed, width_si, unit)
            out.append(check)
            continue
        got_si = computed[j]
        got = got_si / value.factor
        check.got_si, check.got_value = got_si, got
        # the computed value as signed, beside the expected one as written, where only
        # sizes are compared (`magnitude`): "-1.4 kN" against "-1.396 kN (B)", not "1.396"
        check.got = _shown(shown[j] / value.factor, unit, label)
        if not math.isfinite(got):  # finite in SI, too large for the expected value's unit
            check.got_value = None
            check.got = _shown(got_si, reported.si_unit or "", label)
        relative = (got_si - value.si) / abs(float(value.si)) if value.si else None
        check.relative_error = relative if relative is not None and abs(relative) < 1e300 \
            else None  # in percent it would overflow
        check.passed = within(i, j)
        if not check.passed:
            off = ("expected is 0" if not value.si else "more than 1e308 times the expected value" if
                   check.relative_error is None else f"{check.relative_error * 100:+.3g}%")
            check.message = (f"expected {value.text} +- {num(half)} {unit}, got "
                             f"{num(got)} {unit}; off by {num(got - value.number)} {unit} "
                             f"({off})").replace("  ", " ")
            if not math.isfinite(got):
                check.message = (f"expected {value.text}, got {check.got}: too large to "
                                 f"express in {unit}")
            others = [c for k, c in enumerate(computed) if k != j]
            if _size_only(float(value.si), got_si, width_si):
                check.slip = _sign_convention(name, value, got, unit, label, tolerance, convention,
                                              signs)
                out.append(check)
                continue
            check.slip = diagnose(float(value.si), got_si, width_si, others)
            if check.slip and check.slip.startswith("the other root") and (
                    in_order or value.side is not None):  # a root named by its label
                k = next(k for k, c in enumerate(computed)
                         if k != j and abs(c - float(value.si)) <= width_si)
                where = labels[k] if k < len(labels) and labels[k] else f"value {k + 1}"
                check.slip = (f"the order: {value.text} is the computed {where}; this answer "
                              f"lists {', '.join(labels)} in that order")
                if value.side is not None:
                    check.slip = (f"the place: {value.text} is the computed {where}, not the "
                                  f"{labels[j]} its words name")
            elif check.slip and check.slip.startswith("the other root"):
                check.slip = _other_root(value, others, width_si, unit)
        out.append(check)
    return out


def _shown(value: float, unit: str, label: str) -> str:
    """A computed value as the report prints it: ``-1.396 kN (B)``."""
    return f"{num(value)} {unit}".rstrip() + label


def graded_lines(name: str, parsed: list[Any], tolerance: Any, reported: Any) -> list[Any]:
    """A student's values of one answer against the solver's (`matching.compare`), each
    accepted within the tolerance measured from the solver's value, and never within less
    than its printed figures cost (`tolerance.student_widths`): the printed answer copied
    digit for digit is right, as in a question bank's blank."""
    from .tolerance import student_widths

    return compare(name, parsed, tolerance, reported,
                   root_widths=student_widths(tolerance, reported))


def _other_root(value: Expected, roots: list[float], width_si: float, unit: str) -> str:
    root = next(c for c in roots if abs(c - float(value.si)) <= width_si)
    return (f"the other root: {value.text} is the computed root {num(root / value.factor)} "
            f"{unit}, which another expected value took")


def _size_only(expected: float, got: float, width: float) -> bool:
    """Whether got differs from expected in its sign alone: a book's magnitude
    against gyro's signed value (checked before "the order", which the equal
    sizes of a couple's two forces would also fit)."""
    return (expected < 0 < got or got < 0 < expected) and \
        abs(abs(got) - abs(expected)) <= width * (1 + 1e-12)


def placed_pairs(sides: list[int | None], n_computed: int) -> list[tuple[int | None, int | None]]:
    """Pairs for values whose words name their places: each with the computed value at its
    place, then the places no value names."""
    out: list[tuple[int | None, int | None]] = [
        (i, side if side is not None and side < n_computed else None)
        for i, side in enumerate(sides)]
    return out + [(None, j) for j in range(n_computed) if j not in sides]


def _sign_convention(name: str, value: Expected, got: float, unit: str, label: str,
                     tolerance: Tolerance, convention: str,
                     signs: tuple[tuple[str, int], ...] = ()) -> str:
    """The sign slip of a value quoted as a size, naming how gyro signs the answer."""
    place = label.strip(" ()")
    where = f"the computed {place}" if label else "the computed value"
    rule = f"gyro's sign convention for {name}: {convention}" if convention else ""
    if value.sign:  # the book's words give the sign: they and gyro disagree
        word = next((w for w, s in signs if s == (1 if got > 0 else -1)), "")
        return (f"the sign: {value.text} is the size of {where}, but gyro finds it "
                f"{word + ' ' if word else ''}({num(got)} {unit}".rstrip() + ")" +
                (f"; {rule}" if rule else "") + "; is the book's place or sense the other one?")
    in_words = ""
    word = next((w for w, s in signs if s == (1 if got > 0 else -1)), "")
    if word:
        at = f" at {place}" if place else ""
        in_words = f", or write it with its word, `{num(abs(got))} {unit} {word}{at}`"
    return (f"the sign: got is minus the expected value: {value.text} is the size of {where}, "
            f"{num(got)} {unit}".rstrip() + (f"; {rule}; " if rule else "; ") +
            f"write the signed value{in_words}, or compare sizes with "
            f"`tolerance: {tolerance.text} magnitude`")
