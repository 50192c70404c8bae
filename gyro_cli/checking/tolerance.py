"""Tolerances of `gyro check`: ``1%``, ``3 sig``, ``1% magnitude`` or an absolute
quantity; one for the file or one per answer (see docs/check.md)."""

from __future__ import annotations

import dataclasses
import functools
import math
import re
from dataclasses import dataclass
from typing import Any

from ..core import units
from ..core.errors import InputError, shown
from .expected import _guarded

DEFAULT_TOLERANCE = "1%"
_SIG = re.compile(r"\s*(\d{1,2})\s*(?:sig|sf|s\.f\.|sig\s*figs?|significant\s+figures?)\s*",
                  re.I)
_PERCENT = re.compile(r"\s*([-+]?\s*(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][-+]?\d{1,3})?)\s*"
                      r"(?:%|percent|per\s*cent|pct)\s*", re.I)
_MAGNITUDE = re.compile(r"\s*,?\s*\b(?:magnitudes?|abs)\b\s*,?\s*", re.I)


# ---- tolerances -------------------------------------------------------------

@dataclass(frozen=True)
class Tolerance:
    """How close is close enough: relative fraction, significant figures, or absolute SI."""

    form: str   # "relative" | "sig" | "absolute"
    value: float  # fraction (0.01), digits (3), or SI half-width
    text: str
    magnitude: bool = False  # compare absolute values (books that quote magnitudes)

    def half_width(self, expected_si: float, expected_number: float) -> float:
        """The allowed |got - expected| in SI for one expected value.

        ``expected_number`` is the value as written (in its own unit); significant
        figures count on it: 3 sig of 45.1 rpm allows 0.05 rpm.
        """
        if self.form == "relative":
            return self.value * abs(expected_si)
        if self.form == "absolute":
            return self.value
        if expected_number == 0 or expected_si == 0:
            return 0.0
        exponent = math.floor(math.log10(abs(expected_number)))
        half_unit = 0.5 * 10.0 ** (exponent - int(self.value) + 1)
        return half_unit * abs(expected_si / expected_number)


# What a student's answer is accepted within where the problem's own tolerance is tighter
# than the figures gyro prints (`gyro export --tolerance`'s default, and grading's).
STUDENT_TOLERANCE = "1%"


def rounding(value: float, digits: int) -> float:
    """How far ``value`` rounded to ``digits`` significant figures can be from it: half a
    unit of the last digit kept."""
    if not value or value != value:
        return 0.0
    return 0.5 * 10.0 ** (math.floor(math.log10(abs(value))) - digits + 1)


def student_width(tol: Tolerance, student: Tolerance, value: float, half: float,
                  digits: int) -> tuple[float, Tolerance]:
    """What a student's answer is accepted within around the solver's ``value`` (as
    printed, in its unit): ``half`` (the problem's tolerance ``tol``), unless that is
    tighter than rounding to ``digits`` figures can cost, so that the printed answer
    copied digit for digit would fail; then the student tolerance, never less than that
    cost. The half-width (in ``value``'s unit) and the tolerance used. A question bank's
    blank and `gyro check --answers` accept the same."""
    least = rounding(value, digits)
    if value == 0 and tol.form != "absolute":
        return half, student  # 0 either way; said as the others of the question
    if half < least * (1 - 1e-9):
        return max(student.half_width(value, value), least), student
    return half, tol


@functools.cache  # parsed once: a class grades every answer with it
def _student_tolerance() -> Tolerance:
    return parse_tolerance(STUDENT_TOLERANCE, None, "--tolerance")


def student_widths(tol: Tolerance, reported: Any) -> list[float]:
    """The SI half-width each computed root accepts a student's value within
    (:func:`student_width` at the solver's value as printed, SIG figures): measured from
    the solver's value, the truth, never from the student's."""
    from ..core.expr import SIG

    student = _student_tolerance()
    values = list(getattr(reported, "values", None) or reported.si_values)
    out = []
    for value, si in zip(values, reported.si_values):
        si = float(si)
        value = float(value) if isinstance(value, (int, float)) else si
        if not (math.isfinite(si) and math.isfinite(value)):
            out.append(0.0)
            continue
        if tol.magnitude:
            value, si = abs(value), abs(si)
        scale = abs(si / value) if value else 1.0  # SI per printed unit
        half, _ = student_width(tol, student, value, tol.half_width(si, value) / scale, SIG)
        out.append(half * scale)
    return out


def parse_tolerance(raw: Any, dimension: str | None, key: str = "tolerance") -> Tolerance:
    """One tolerance: ``"1%"``, ``"3 sig"`` or a quantity in the answer's dimension.

    A text read before for the same dimension is not read again: a bank's files repeat
    a few tolerances (``1%``), each read twice per answer (validated, then used). Only
    tolerances that were read without error are kept; a bad one is refused each time,
    at its own key."""
    if raw.__class__ is str:
        cached = _READ.get((raw, dimension))
        if cached is not None:
            return cached
    tolerance = _parse_tolerance(raw, dimension, key)
    if raw.__class__ is str and len(_READ) < 1024:
        _READ[(raw, dimension)] = tolerance
    return tolerance


_READ: dict[tuple[str, str | None], Tolerance] = {}


def _parse_tolerance(raw: Any, dimension: str | None, key: str) -> Tolerance:
    if isinstance(raw, bool) or not isinstance(raw, (str, int, float)):
        raise InputError(f"expected a tolerance such as '1%', '3 sig' or '0.01 rad/s', got "
                         f"{shown(raw)}", key=key)
    if isinstance(raw, (int, float)):
        raise InputError(f"a bare number {shown(raw)} is ambiguous as a tolerance: write '{raw}%' "
                         "(relative), '3 sig' (significant figures) or a quantity with a unit "
                         "(absolute)", key=key)
    text = raw.strip()
    if len(text) <= units.MAX_TEXT and _MAGNITUDE.search(text):
        rest = _MAGNITUDE.sub(" ", text).strip()
        one = parse_tolerance(rest or DEFAULT_TOLERANCE, dimension, key)
        return dataclasses.replace(one, magnitude=True, text=text)
    match = _PERCENT.fullmatch(text)
    if match:
        fraction = float(match.group(1).replace(" ", "")) / 100
        if fraction < 0:
            raise InputError(f"a relative tolerance must be positive (a width either side of "
                             f"the expected value), got {text!r}; write e.g. "
                             f"'{text.lstrip().lstrip('-').strip()}'", key=key)
        if not 0 <= fraction <= 1:
            raise InputError(f"a relative tolerance lies between 0% and 100%, got {text!r}",
                             key=key)
        return Tolerance("relative", fraction, text)
    match = _SIG.fullmatch(text)
    if match:
        digits = int(match.group(1))
        if not 1 <= digits <= 15:
            raise InputError(f"significant figures run from 1 to 15, got {text!r}", key=key)
        return Tolerance("sig", digits, text)
    if dimension is None:
        # A word answer: compared exactly, but the text must still be a tolerance.
        _guarded(lambda t, d, k: units._split(t, k), text, "", key)  # no dimension to give
        return Tolerance("absolute", 0.0, text)
    value, _ = _guarded(units.parse, text, dimension, key)
    if value < 0:
        raise InputError(f"a tolerance cannot be negative, got {text!r}", key=key)
    return Tolerance("absolute", value, text)


def tolerance_for(spec: Any, name: str, dimension: str | None, answer_names: list[str]) -> Tolerance:
    """The tolerance of answer ``name`` from the file's ``tolerance`` (None, one, or a mapping)."""
    if spec is None:
        return parse_tolerance(DEFAULT_TOLERANCE, dimension)
    if isinstance(spec, dict):
        for entry in spec:
            if entry != "default" and entry not in answer_names:
                from ..solving.problem import suggest

                raise InputError(f"unknown answer {entry!r}{suggest(str(entry), answer_names)} "
                                 f"(answers: {', '.join(answer_names)}; or `default`)",
                                 key=f"tolerance.{entry}")
        if name in spec:
            return parse_tolerance(spec[name], dimension, f"tolerance.{name}")
        if "default" in spec:
            return parse_tolerance(spec["default"], dimension, "tolerance.default")
        return parse_tolerance(DEFAULT_TOLERANCE, dimension)
    return parse_tolerance(spec, dimension, "tolerance")


def validate_tolerance(spec: Any, kind: Any) -> None:
    """Check every entry of a file's `tolerance`, used or not (InputError if malformed)."""
    names = [a.name for a in kind.answers]
    if spec is None:
        return
    if not isinstance(spec, dict):
        # The form here; an absolute value's dimension against each answer when it is used.
        parse_tolerance(spec, None, "tolerance")
        return
    tolerance_for(spec, "", None, names)  # unknown answer names
    for name, value in spec.items():
        answer = kind.answer(name)
        parse_tolerance(value, answer.dimension if answer else None,
                        f"tolerance.{name}")
