"""Authoring problem files: `gyro new` (a commented template), `gyro schema` (JSON
Schema for editors) and `gyro vary` (random variants with their answer keys).

The `vary` block of a problem file (see docs/check.md) names given keys and a
range for each, in one of two forms:

    vary:
      spin: [0.8, 1.2]          # two plain numbers: factors on the given value
      theta: [20 deg, 40 deg]   # two quantities: an absolute range

Each variant draws every key uniformly in its range from ``random.Random(seed)``
(so the same seed gives the same files), rounds it to 3 significant figures,
solves the problem, and keeps it only when it has a real solution (a spin below
the least spin for steady precession is drawn again). Its `expected` answers
are the solver's, written to 4 significant figures (more where the tolerance
needs them).
"""

from __future__ import annotations

import copy
import math
import os
import random
import re
from collections.abc import Iterator
from typing import Any

from ..core import units
from ..core.alternatives import alternatives_of
from ..core.body import BODY_PARAMS
from ..core.errors import InputError
from ..core.spec import Kind, Param
from ..kinds import get as kind_named
from ..kinds import names as kind_names_of

EXAMPLE_QUANTITY = {
    "length": "150 mm", "mass": "2 kg", "force": "10 N", "acceleration": "9.81 m/s^2",
    "rate": "1800 rpm", "angle": "30 deg", "inertia": "0.01 kg m^2", "moment": "2 N m",
    "speed": "10 m/s", "time": "2 s", "dimensionless": "1",
    "angular_momentum": "2 kg m^2/s", "inverse_time": "-0.32 s^-1", "mass_length": "2 kg m",
    "energy": "3 J", "particles": "[{mass: 1 kg, x: 0.1 m, y: 0 m, z: 0 m}]",
    "stiffness": "0.5 N m/rad", "damping": "0.002 N m s/rad", "time_per_angle": "72 yr/deg",
}
ANSWER_UNIT = {"rate": "rpm", "angle": "deg", "inverse_time": "s^-1"}

VARIANT_DIGITS = 3
MAX_VARIANTS = 10_000


# ---- gyro new ---------------------------------------------------------------

def _line(text: str, comment: str, width: int = 30) -> str:
    return f"{text:<{width - 1}} # {comment}" if comment else text


def template(kind_name: str) -> str:
    """A commented problem file with every key of ``kind_name``."""
    kind = kind_named(kind_name)
    example = kind.example  # a complete, solvable example of the kind
    given_ex: dict[str, str] = dict(example.get("given", {}))
    find_ex: dict[str, Any] = dict(example.get("find", {}))
    out = [f"# A gyro problem file of kind {kind.name}: {kind.summary}.",
           f"# Chapter: {kind.chapter}." if kind.chapter else "# Chapter 11.",
           "# Quantities are strings with a unit: \"150 mm\", \"1800 rpm\", \"30 deg\".",
           "# Lines starting with # are comments; uncomment the keys you need.",
           "# Solve it with `gyro solve FILE`; verify the answer key with `gyro check FILE`.",
           "",
           _line('id: "new-1"', "required: how reports name this problem"),
           _line('title: "Describe the problem"', "optional"),
           _line(f"kind: {kind.name}", "required"),
           _line('source: ""', "optional: book, chapter, problem number"),
           _line("statement: >-", "optional: the problem as students read it; {key} is "
                 "the given value as written"),
           "  " + _statement_example(kind, given_ex, find_ex),
           _line("notes:", "optional: lines printed with the worked answer; maths in "
                 "Unicode (ψ̇, θ₀, √, ω_z, m²)"),
           "  - Spin is the rate relative to the precessing frame (ψ̇)."
           if "precessing frame" in getattr(kind.param("spin"), "doc", "")
           else "  - State here what the problem assumes.",
           "",
           _line("given:", "required: the data, each with its unit")]
    if not given_ex:
        out.append("  # (fill in: uncomment and edit the keys this problem gives)")
    body_keys = kind.body_keys or [b.name for b in BODY_PARAMS]
    body = [p for p in BODY_PARAMS if p.name in body_keys and (p.name != "g" or kind.gravity)
            ] if kind.uses_body else []
    params = list(kind.params) + body
    for i, p in enumerate(params):
        if kind.uses_body and i == len(kind.params):
            out.append("  # the body: " + ("mass or weight; J or k_axial; I_pivot, k_pivot, "
                                           "I_cg, k_cg or shape; cg_distance"
                                           if kind.body_keys is None else
                                           "the rotor's J, or k_axial with mass, or a shape"))
        what = p.dimension
        comment = f"{what}: {p.doc}" + (f" (default {p.default})" if p.default else "")
        if p.name in given_ex:
            out.append(_line(f"  {p.name}: {given_ex[p.name]}", comment))
        else:
            value = p.choices[0] if p.dimension == "word" else \
                p.default or EXAMPLE_QUANTITY.get(p.dimension, "1")
            out.append(_line(f"  # {p.name}: {value}", comment))
    out += ["", _line("find:", "required: answer name -> the unit to print it in")]
    first = next(iter(find_ex), None) or kind.answers[0].name
    for a in kind.answers:
        unit = "null" if a.dimension is None else \
            (find_ex.get(a.name) or ANSWER_UNIT.get(a.dimension) or units.si_text(a.dimension))
        comment = f"{a.dimension or 'word'}: {a.doc}"
        text = f"  {a.name}: {unit}"
        out.append(_line(text if a.name in find_ex or (not find_ex and a.name == first)
                         else f"  # {text.strip()}", comment))
    expected_ex = _example_expected(kind, given_ex, find_ex)
    out += ["", _line("expected:" if expected_ex else "# expected:",
                      "optional: what `gyro check` compares against (roots in any order)")]
    for a in kind.answers:
        if a.name in expected_ex:
            out.append(f"  {a.name}: {expected_ex[a.name]}")
        else:
            value = (a.words[0] if a.words else "cusps") if a.dimension is None else \
                EXAMPLE_QUANTITY.get(a.dimension, "1").split()[0] + " " + (
                    ANSWER_UNIT.get(a.dimension) or units.si_text(a.dimension))
            out.append(f"  # {a.name}: {value}".rstrip())
    out += [_line("tolerance: 1%", "optional: \"1%\" relative, \"3 sig\" significant "
                  "figures, or a quantity (\"0.01 rad/s\") absolute; or answer -> tolerance"),
            _line(f"# ask: [{first}]", "optional: the answers the statement asks (a question "
                  "bank asks only these)"),
            "", _line("# vary:" if not example.get("vary") else "vary:",
                      "optional, for `gyro vary`: factors [0.8, 1.2] or a range "
                      "[20 deg, 40 deg]")]
    vary_ex = example.get("vary") or {params[0].name: "[0.9, 1.1]"}
    for key, value in vary_ex.items():
        out.append(f"  {key}: {value}" if example.get("vary") else f"#   {key}: {value}")
    return "\n".join(out) + "\n"


def _statement_example(kind: Kind, given: dict[str, str], find: dict[str, Any]) -> str:
    """A statement for the template that names each given value by placeholder.

    A kind's example carries its own statement, written as a book states the problem;
    without one the sentence is made from the keys' plain descriptions (never from the
    formulas in the answers' docs, which read badly cut out of a sentence).
    """
    example = kind.example
    if example.get("statement"):
        return " ".join(str(example["statement"]).split())
    params = {p.name: p for p in list(kind.params) +
              (list(BODY_PARAMS) if kind.uses_body else [])}
    data = [f"{_phrase(_prose(params.get(k)), k)} {_value(params.get(k), k, given[k])}"
            for k in given]
    asked = [_phrase(a.doc if a.dimension else "", a.name) for a in kind.answers
             if a.name in find] or [_phrase(kind.answers[0].doc, kind.answers[0].name)]
    if not data:
        return f"State the problem here; write {{key}} for a given value. Find {_and(asked)}."
    return f"Given {_and(data)}. Find {_and(asked)}."


def _value(param: Param | None, key: str, value: str) -> str:
    """A given value in the statement: ``{key}``, or a word key's value in words."""
    if param is not None and param.dimension == "word":
        words = " ".join(str(value).replace("_", " ").split())
        return words.replace("{", "{{").replace("}", "}}")
    return f"{{{key}}}"


def _prose(param: Param | None) -> str:
    """A key's description, or nothing for a word key (its doc lists the choices)."""
    return "" if param is None or param.dimension == "word" else param.doc


def _phrase(doc: str, name: str) -> str:
    """A noun phrase for a key or an answer: its description up to the first clause
    break, when that is plain words, else its name in words ("the heel angle")."""
    import re

    text = re.sub(r"\s*\([^()]*\)", "", doc).split(";")[0].split(",")[0]
    text = text.split(":")[-1].strip()
    if not text or re.search(r"[/*^=+<>()\[\]{}'`_]|\d|\b[A-Z]\b|\bsqrt\b", text) \
            or not re.fullmatch(r"[A-Za-z' -]+", text) or " or " in f" {text} " \
            or text.split()[0] in ("along", "about", "at", "to", "from", "instead", "each"):
        text = name.replace("_", " ")
    return text if text.split()[0] in ("the", "a", "an") else f"the {text}"


def _and(items: list[str]) -> str:
    """'a', 'a and b', 'a, b and c'."""
    return items[0] if len(items) == 1 else ", ".join(items[:-1]) + " and " + items[-1]


def _example_expected(kind: Kind, given: dict[str, str], find: dict[str, Any]) -> dict[str, str]:
    """The example's answers as the solver gives them, for the template's `expected`."""
    from ..solving.problem import _build
    from ..solving.solve import solve

    if not given or not find:
        return {}
    data = {"id": "example", "kind": kind.name, "given": dict(given), "find": dict(find)}
    try:
        result = solve(_build("<template>", data, {}))
    except InputError:
        return {}
    out = {}
    for name, answer in result.answers.items():
        texts = [str(v) if answer.unit is None else
                 f"{number_text(round_sig(v, 4))} {answer.unit}" for v in answer.values]
        out[name] = texts[0] if len(texts) == 1 else "[" + ", ".join(texts) + "]"
    return out


# ---- gyro schema ------------------------------------------------------------

QUANTITY_PATTERN = (r"^\s*[-+\u2212]?(\d+(\.\d*)?|\.\d+)([eE][-+\u2212]?\d{1,3})?\s*"
                    r"[A-Za-z_°µΩ(1]?[A-Za-z0-9_°µΩ*/^() \t.+-]*$")

#: a latitude or longitude written with its hemisphere first, "S 30", "N45.5 deg"
HEMISPHERE_FIRST = (r"^\s*([NSEWnsew]|[Nn]orth|[Ss]outh|[Ee]ast|[Ww]est)\.?\s*"
                    r"(\d+(\.\d*)?|\.\d+)([eE][-+]?\d{1,3})?\s*[A-Za-z0-9_°µΩ*/^() \t.+-]*$")


def schema() -> dict[str, Any]:
    """A JSON Schema (draft-07) of the problem format, for editors."""
    quantity = {"type": "string", "maxLength": units.MAX_TEXT, "pattern": QUANTITY_PATTERN}
    tolerance_one = {"type": "string", "maxLength": units.MAX_TEXT,
                     "description": "\"1%\" relative, \"3 sig\" significant figures, or a "
                                    "quantity (\"0.01 rad/s\") absolute"}
    kind_names = kind_names_of()
    rules = []
    for name in kind_names:
        kind = kind_named(name)
        rules.append({"if": {"properties": {"kind": {"const": name}}, "required": ["kind"]},
                      "then": {"properties": _kind_properties(kind, quantity, tolerance_one)}})
    return {
        "$schema": "http://json-schema.org/draft-07/schema#",
        "title": "gyro problem file",
        "description": "A textbook problem of gyroscopic motion for `gyro solve` and "
                       "`gyro check` (see docs/check.md and the format page).",
        "type": "object",
        "required": ["id", "kind", "given", "find"],
        "additionalProperties": False,
        "properties": {
            "id": {"type": ["string", "number"], "description": "how reports name the problem"},
            "title": {"type": "string"},
            "statement": {"type": "string", "minLength": 1,
                          "description": "the problem as students read it; {key} is replaced "
                                         "by the given value as written ({{ and }} for "
                                         "braces)"},
            "kind": {"enum": kind_names, "description": "the problem kind (`gyro kinds`)"},
            "source": {"type": "string"},
            "notes": {"oneOf": [{"type": "string"},
                                {"type": "array", "items": {"type": ["string", "number"]}}]},
            "given": {"type": "object", "description": "the data, each quantity with its unit"},
            "find": {"oneOf": [{"type": "object", "minProperties": 1},
                               {"type": "array", "minItems": 1, "items": {"type": "string"}}],
                     "description": "answer name -> the unit to print it in"},
            "expected": {"type": "object",
                         "description": "answers `gyro check` compares against"},
            "tolerance": {"oneOf": [tolerance_one, {"type": "object",
                                                    "additionalProperties": tolerance_one}]},
            "ask": {"type": "array", "minItems": 1, "items": {"type": "string"},
                    "description": "the answers (of find and expected) the statement asks; "
                                   "a question bank asks only these"},
            "steps": {"type": "array", "minItems": 1, "items": {"type": ["string", "number"]},
                      "description": "symbols of worked-answer steps graded as questions "
                                     "(`gyro solve --format json` lists them)"},
            "units": {"enum": ["si", "us", "SI", "US"],
                      "description": "the worked answer in SI (default) or slug, ft, lbf"},
            "vary": {"type": "object", "description": "for `gyro vary`: given key -> [low, high]"
                                                      " factors or quantities",
                     "additionalProperties": {"type": "array", "minItems": 2, "maxItems": 2,
                                              "items": {"oneOf": [{"type": "number"},
                                                                  quantity]}}},
        },
        "allOf": rules,
    }


_KEYWORDS = {">": "exclusiveMinimum", ">=": "minimum", "<": "exclusiveMaximum",
             "<=": "maximum", "whole": "multipleOf"}


def limits_schema(p: Param) -> dict[str, Any]:
    """A Param's declared limits (SI) as JSON Schema keywords: ``{"exclusiveMinimum": 0}``;
    ``nonzero`` as ``{"not": {"const": 0}}``, a whole number as ``{"multipleOf": 1}``."""
    out: dict[str, Any] = {}
    for op, x in p.limits_declared():
        if op == "!=":
            out["not"] = {"const": x}
        else:
            out[_KEYWORDS[op]] = x
    return out


def _described(p: Param, dimension: str = "") -> str:
    """The key's meaning, its dimension and its limits as the loader states them."""
    notes = [dimension] if dimension else []
    if p.limits_declared():
        notes.append(p.expectation(units.si_text(p.dimension)))
    return f"{p.doc} ({'; '.join(notes)})" if notes else p.doc


def _kind_properties(kind: Kind, quantity: dict, tolerance_one: dict) -> dict[str, Any]:
    params = list(kind.params) + (list(BODY_PARAMS) if kind.uses_body else [])
    given: dict[str, Any] = {}
    for p in params:
        if p.dimension == "word":
            words: list = list(p.choices)
            if set(words) == {"true", "false"}:
                words += [True, False]  # YAML reads `false` as a boolean
            # the books' spellings (docs/real_problems.md), with _ or spaces
            spelt = [w for w, _ in p.words] + [c for c in p.choices if "_" in c]
            words += [w for w, _ in p.words] + [w.replace("_", " ") for w in spelt]
            if any("clockwise" in str(w) for w in words):
                # a sense of rotation, in any of the books' phrasings (anticlockwise,
                # seen from the stern, ...): the loader reads it or says why not
                given[p.name] = {"anyOf": [{"enum": words},
                                           {"type": "string", "pattern": "[Cc][Ll][Oo][Cc][Kk]"}],
                                 "description": p.doc}
            else:
                given[p.name] = {"enum": words, "description": p.doc}
        elif p.dimension == "dimensionless":
            given[p.name] = {"oneOf": [dict({"type": "number"}, **limits_schema(p)), quantity],
                             "description": _described(p)}
        elif p.dimension == "particles":
            given[p.name] = {"type": "array", "minItems": 1, "description": p.doc,
                             "items": {"type": "object", "additionalProperties": False,
                                       "required": ["mass", "x", "y", "z"],
                                       "properties": {n: quantity for n in
                                                      ("mass", "x", "y", "z")}}}
        else:
            given[p.name] = dict(quantity, description=_described(p, p.dimension))
            if p.hemisphere:  # "S 30" as well as "30 S" (which the quantity pattern takes)
                given[p.name] = {"anyOf": [quantity, {"type": "string", "maxLength":
                                                      units.MAX_TEXT,
                                                      "pattern": HEMISPHERE_FIRST}],
                                 "description": given[p.name]["description"]}
            if p.limits_declared():
                # a quantity is text with a unit: the limits, in SI, are for editors to show
                si = units.si_text(p.dimension)
                given[p.name]["x-si-limits"] = dict(limits_schema(p), unit=si)
    for key, alternative in alternatives_of({p.name: p for p in params}).items():
        given[key] = dict(quantity, description=f"instead of {alternative.target}: "
                          f"{alternative.reading}")  # the books' way of stating it
    answers = [a.name for a in kind.answers]
    find = {a.name: ({"type": "null"} if a.dimension is None else
                     {"type": ["string", "null"], "description": f"unit for {a.doc}"})
            for a in kind.answers}
    expected: dict[str, Any] = {}
    for a in kind.answers:
        one: dict[str, Any] = ({"type": "string"} if a.dimension is None else
               {"oneOf": [{"type": "number"}, quantity]} if a.dimension == "dimensionless" else
               quantity)
        expected[a.name] = {"oneOf": [one, {"type": "array", "minItems": 1, "items": one}],
                            "description": a.doc}
    if "steps" not in expected:
        expected["steps"] = {"type": "object", "minProperties": 1,
                             "additionalProperties": {"oneOf": [{"type": "number"}, quantity]},
                             "description": "intermediate values graded by the step's symbol "
                                            "in the worked answer, e.g. {omega_z: 1850 rpm} "
                                            "(docs/check.md)"}
    return {
        "given": {"type": "object", "additionalProperties": False, "properties": given},
        "find": {"oneOf": [{"type": "object", "minProperties": 1, "additionalProperties": False,
                            "properties": find},
                           {"type": "array", "minItems": 1, "items": {"enum": answers}}]},
        "expected": {"type": "object", "additionalProperties": False, "properties": expected},
        "tolerance": {"oneOf": [tolerance_one, {
            "type": "object", "additionalProperties": False,
            "properties": {name: tolerance_one for name in answers + ["default"]}}]},
        "vary": {"type": "object", "propertyNames": {"enum": [
            p.name for p in params if p.dimension not in ("word", "particles")]}},
    }


# ---- gyro vary --------------------------------------------------------------

def parse_vary(problem: Any) -> list[tuple[str, str, float, float, str, float]]:
    """The `vary` block: (key, form, low, high, unit, SI per unit) per key, in file order.

    form "scale": low/high are factors on the given number; "range": numbers in ``unit``.
    """
    raw = problem.vary
    if raw is None:
        raise InputError("no `vary` block: add one, e.g. `vary: {spin: [0.8, 1.2]}` (factors) "
                         "or `vary: {theta: [20 deg, 40 deg]}` (a range)", key="vary")
    if not isinstance(raw, dict) or not raw:
        raise InputError("expected a mapping of given keys to [low, high]", key="vary")
    params = {p.name: p for p in list(problem.kind.params) +
              (list(BODY_PARAMS) if problem.kind.uses_body else [])}
    given_raw = problem.data.get("given", {})
    stated = alternatives_of(params)  # a key as books state it (wheel_diameter)
    out = []
    for key, bounds in raw.items():
        where = f"vary.{key}"
        param = params.get(str(key))
        if param is None and str(key) in stated:
            param = stated[str(key)].param_for(params[stated[str(key)].target])
        if param is None or param.dimension in ("word", "particles"):
            raise InputError(f"{key!r} is not a numeric given key of kind {problem.kind.name}",
                             key=where)
        if not isinstance(bounds, list) or len(bounds) != 2:
            raise InputError("expected [low, high]: two factors such as [0.8, 1.2] or two "
                             "quantities such as [20 deg, 40 deg]", key=where)
        weight = param.name == "weight"
        if all(isinstance(b, (int, float)) and not isinstance(b, bool) for b in bounds):
            low, high = float(bounds[0]), float(bounds[1])
            if key not in given_raw:
                raise InputError(f"factors scale the given value, but `given` has no {key}; "
                                 "give a range with units instead", key=where)
            if not (0 < low <= high and math.isfinite(high)):
                raise InputError(f"factors must satisfy 0 < low <= high, got {bounds}", key=where)
            number, unit = units._split(given_raw[key], f"given.{key}")
            out.append((str(key), "scale", low * number, high * number, unit, 1.0))
            continue
        if not all(isinstance(b, str) for b in bounds):
            raise InputError("expected two plain factors or two quantities with units",
                             key=where)
        low_si, _ = units.parse(bounds[0], param.dimension, where, weight=weight)
        high_si, _ = units.parse(bounds[1], param.dimension, where, weight=weight)
        number, unit = units._split(bounds[0], where)
        if low_si > high_si:
            raise InputError(f"low must not exceed high, got {bounds}", key=where)
        factor = low_si / number if number else \
            units.parse(f"1 {unit}", param.dimension, where, weight=weight)[0]
        out.append((str(key), "range", low_si / factor, high_si / factor, unit, factor))
    return out


def round_sig(value: float, digits: int) -> float:
    if value == 0 or not math.isfinite(value):
        return value
    return round(value, digits - 1 - math.floor(math.log10(abs(value))))


def number_text(value: float, digits: int = 12) -> str:
    """A number as written in a variant: ``digits`` significant figures, at least 12."""
    return f"{value:.{max(12, digits)}g}"


def _expected_text(values: list, unit: str | None, tol_halfwidths: list[float]) -> Any:
    if unit is None:
        texts = [str(v) for v in values]
    else:
        texts = []
        for value, width in zip(values, tol_halfwidths):
            digits = 4
            while digits < 15 and abs(round_sig(value, digits) - value) > width / 10:
                digits += 1
            texts.append(f"{number_text(round_sig(value, digits), digits)} {unit}")
    return texts[0] if len(texts) == 1 else texts


def variants(path: str, count: int, seed: int) -> list[tuple[str, str]]:
    """``count`` variants of the problem in ``path``: (file name, YAML text) each."""
    return list(each_variant(path, count, seed))


def each_variant(path: str, count: int, seed: int) -> Iterator[tuple[str, str]]:
    """`variants`, one at a time (a bank of 10,000 need not hold them all)."""
    from ..solving.problem import load

    if not 1 <= count <= MAX_VARIANTS:
        raise InputError(f"--count must lie between 1 and {MAX_VARIANTS}, got {count}")
    problem = load(path)
    try:
        ranges = parse_vary(problem)
    except InputError as err:
        raise err.located(file=path, line=problem.line(err.key)) from None
    base = copy.deepcopy(problem.data)
    base.pop("vary", None)
    keyed = [name for name in problem.expected if problem.kind.answer(name) is not None] \
        or list(problem.find)  # not `steps` nor a step asked (`steps:`)
    rng = random.Random(seed)
    stem = os.path.splitext(os.path.basename(path))[0]
    width = max(2, len(str(count)))
    made = 0
    shared: dict[str, tuple[Any, str]] = {}  # the YAML of what the variants share
    draws = 0
    max_draws = 50 * count + 50
    while made < count:
        if draws >= max_draws:
            raise InputError(f"only {made} of {count} variants have a real solution after "
                             f"{draws} draws; narrow the ranges in `vary`", file=path, key="vary")
        draws += 1
        n = made + 1
        data = draw_variant(problem, base, ranges, rng, keyed,
                            variant_id=f"{problem.id}-v{n:0{width}d}",
                            title=f"{problem.title} (variant {n})",
                            source=f"gyro vary {os.path.basename(path)} --seed {seed}: "
                                   f"variant {n}")
        if data is None:
            continue  # no real solution (or an impossible body): draw again
        text = (f"# Generated by `gyro vary {os.path.basename(path)} --count {count} "
                f"--seed {seed}`: variant {n} of {count}.\n" + variant_yaml(data, shared))
        made += 1
        yield f"{stem}-v{n:0{width}d}.yaml", text


def write_variants(path: str, count: int, seed: int, out_dir: str, force: bool) -> list[str]:
    """Write the variants into ``out_dir`` (created if needed); never overwrite without force.

    The set is written whole or not at all (core/files.py: write_set): a full
    disk or a signal leaves no variant and no temporary file, so a rerun starts
    clean. A variant may not replace the file it is drawn from.
    """
    from ..core.files import refuse_input_as_output, write_set_in

    if not out_dir.strip():
        raise InputError("-o/--out-dir needs a directory name, got an empty one")
    made = variants(path, count, seed)
    if os.path.exists(out_dir) and not os.path.isdir(out_dir):
        raise InputError("exists and is not a directory", file=out_dir)
    targets = [(os.path.join(out_dir, name), text) for name, text in made]
    for target, _ in targets:
        refuse_input_as_output(target, [path], option="a variant", yaml_output=True)
    if not force:
        clash = [name for name, _ in targets if os.path.lexists(name)]
        if clash:
            raise InputError(f"exists; not overwritten (use --force to replace it; {len(clash)} "
                             "variant file(s) already there)", file=clash[0])
    write_set_in(out_dir, targets, force=force)
    return [target for target, _ in targets]


def draw_variant(problem: Any, base: dict[str, Any], ranges: list, rng: random.Random,
                 keyed: list[str], variant_id: str, title: str,
                 source: str, solved: list[Any] | None = None) -> dict[str, Any] | None:
    """One draw of every `vary` key from ``rng``, solved: the variant's data with its
    computed `expected` answers, or None when the draw has no real solution. The
    solver's result is appended to ``solved`` when that is given."""
    from ..checking.tolerance import tolerance_for
    from ..solving.solve import solve

    answer_names = [a.name for a in problem.kind.answers]
    data = dict(base)  # what is drawn is set anew below; the rest is base's, unchanged
    data["given"] = dict(base["given"])
    for key, _form, low, high, unit, _ in ranges:
        value = round_sig(low + rng.random() * (high - low), VARIANT_DIGITS)
        data["given"][key] = f"{number_text(value)} {unit}".strip()
    data["id"] = variant_id
    if problem.title:
        data["title"] = title
    data["source"] = source + (f" of {problem.source}" if problem.source else "")
    find = dict(data["find"]) if isinstance(data["find"], dict) else \
        {name: None for name in data["find"]}
    for name in keyed:
        find.setdefault(name, None)
    data["find"] = find
    data.pop("expected", None)
    try:
        result = solve(_variant_problem(problem.file, base, keyed, data))
    except InputError:
        return None
    expected = {}
    for name in keyed:
        answer = result.answers[name]
        if not answer.values:  # none for this draw (a bicycle that never weaves): the key
            continue           # quotes no value, as a book would not; `find` still asks
        spec = problem.kind.answer(name)
        tol = tolerance_for(problem.tolerance, name, spec.dimension, answer_names)
        widths = [tol.half_width(si, v) / (si / v if v and si else 1.0)
                  if isinstance(v, float) else 0.0
                  for si, v in zip(answer.si_values, answer.values)]
        expected[name] = _expected_text(answer.values, answer.unit, widths)
    data["expected"] = expected
    if solved is not None:
        solved.append(result)
    order = ["id", "title", "kind", "source", "statement", "notes", "given", "find",
             "expected", "tolerance", "ask", "steps"]
    return {k: data[k] for k in order if k in data}


# The last problem built whole for a variant, as one tuple (read and replaced whole, so
# threads drawing from two files never mix one's base with the other's problem): its base
# data, the keys keyed, the problem, the given strings read for its variants (most are
# the base's, read again for each).
_TEMPLATE: list[tuple[dict[str, Any], list[str], Any, dict]] = []


def _variant_problem(path: str, base: dict[str, Any], keyed: list[str],
                     data: dict[str, Any]) -> Any:
    """``_build(path, data, {})`` of a variant drawn from ``base``. A variant's data differ
    from another's of the same base only in its given values, id, title and source, so
    after the first is built whole (every key checked), only those are read again: the
    rest (kind, find, statement, notes, ask, steps) would be checked to the same end."""
    from ..solving.problem import _build, _id, _text, parse_given

    for held_base, held_keyed, template, memo in _TEMPLATE[-1:]:
        if held_base is base and held_keyed == keyed and template.file == path:
            problem = copy.copy(template)
            problem.given, problem.quantities, problem.us_customary = parse_given(
                problem.kind, data["given"], memo)
            problem.id = _id(data["id"])
            problem.title = _text(data.get("title", ""), "title")
            problem.source = _text(data.get("source", ""), "source")
            problem.data = data
            return problem
    problem = _build(path, data, {})
    _TEMPLATE[:] = [(base, list(keyed), problem, {})]
    return problem


def variant_yaml(data: dict[str, Any], shared: dict[str, tuple[Any, str]] | None = None) -> str:
    """A variant's data as YAML, keys in the problem format's order: the text of
    ``yaml.safe_dump(data, sort_keys=False, allow_unicode=True, width=100)``, written a key
    at a time (a block mapping's entries are written independently). ``shared``: the text
    of each key's last value, kept between the variants of a problem, so what they share
    (the statement, `find`, the tolerance) is written once; a value of plain printable
    ASCII is written by libyaml's emitter where PyYAML has it (the same text, 20 times
    faster: tests/test_i37_stream.py holds them equal)."""
    if not data:
        return _key_yaml_all(data)
    memo: dict[str, tuple[Any, str]] = {} if shared is None else shared
    out = []
    for key, value in data.items():
        known = memo.get(key)
        if known is None or known[0] != value:
            known = (_copied(value), _key_yaml(key, value))
            memo[key] = known
        out.append(known[1])
    return "".join(out)


def _copied(value: Any) -> Any:
    """``copy.deepcopy(value)``, its strings shared (a variant's given and expected:
    made for each variant, so copied quickly)."""
    if isinstance(value, str):
        return value
    if value.__class__ is list and all(isinstance(v, str) for v in value):
        return list(value)
    if value.__class__ is dict:
        return {k: _copied(v) for k, v in value.items()}
    return copy.deepcopy(value)


def _key_yaml_all(data: dict[str, Any]) -> str:
    import yaml

    return yaml.safe_dump(data, sort_keys=False, allow_unicode=True, width=100)


def _key_yaml(key: str, value: Any) -> str:
    import yaml

    fast = _simple_yaml(key, value)
    if fast is not None:
        return fast
    dumper = getattr(yaml, "CSafeDumper", None)
    if dumper is None or not (_plain_ascii(key) and _plain_ascii(value)):
        dumper = yaml.SafeDumper
    return yaml.dump({key: value}, Dumper=dumper, sort_keys=False, allow_unicode=True,
                     width=100)


# A string both YAML emitters write on its line as it is, or in single quotes, and never
# fold: ASCII letters, digits and these marks, words one space apart, no indicator first.
_SIMPLE_TEXT = re.compile(r"(?:[A-Za-z0-9(]|-(?=[0-9]))(?:[A-Za-z0-9()._/+*,:%-]| (?! ))*")
_SIMPLE_KEY = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
_FOLD_AT = 100  # the width given to the emitters: a line no longer is never folded
_RESOLVER: list[Any] = []


def _simple_yaml(key: str, value: Any) -> str | None:
    """`_key_yaml`'s text written here, where PyYAML's is known without running it (a
    variant's id, title, given values and expected answers: a fifth of drawing a set of
    variants): a key whose value is a simple string, a list of them, or a mapping of
    those. None for anything else. tests/test_i37_speed.py holds it to PyYAML's text."""
    if not isinstance(key, str) or not _simple_word(key):
        return None
    if isinstance(value, dict):
        if not value:
            return None
        out = [f"{key}:\n"]
        for name, item in value.items():
            text = _ENTRIES.get((name, item)) if isinstance(item, str) else None
            if text is None:
                if not isinstance(name, str) or not _simple_word(name):
                    return None
                text = _simple_entry("  ", name, item)
                if text is None:
                    return None
                if isinstance(item, str):
                    if len(_ENTRIES) >= 4096:  # the drawn values: each met once
                        _ENTRIES.clear()
                    _ENTRIES[(name, item)] = text
            out.append(text)
        return "".join(out)
    return _simple_entry("", key, value)


#: a mapping's entry ``  name: text`` by (name, text), as `_simple_entry` writes it (the
#: given values a problem's variants share are written once)
_ENTRIES: dict[tuple[Any, str], str] = {}


def _simple_entry(indent: str, key: str, value: Any) -> str | None:
    """``key: value`` at ``indent``: a simple string, or a block list of them."""
    if isinstance(value, str):
        scalar = _simple_scalar(value)
        if scalar is None or len(indent) + len(key) + 2 + len(scalar) > _FOLD_AT:
            return None
        return f"{indent}{key}: {scalar}\n"
    if isinstance(value, list) and value:
        out = [f"{indent}{key}:\n"]
        for item in value:
            scalar = _simple_scalar(item) if isinstance(item, str) else None
            if scalar is None or len(indent) + 2 + len(scalar) > _FOLD_AT:
                return None
            out.append(f"{indent}- {scalar}\n")
        return "".join(out)
    return None


def _simple_word(text: str) -> bool:
    """A mapping key written plain (``spin``, not ``yes`` or ``null``)."""
    known = _SIMPLE_WORDS.get(text)
    if known is None:
        known = _SIMPLE_WORDS[text] = _SIMPLE_KEY.fullmatch(text) is not None and \
            _resolves_to_text(text)
    return known


_SIMPLE_WORDS: dict[str, bool] = {}


def _simple_scalar(text: str) -> str | None:
    """A simple string as a block mapping's value or a list item: plain, or in single
    quotes where plain would read otherwise (``: `` in it, a trailing colon, a number,
    a boolean); None for a string not simple."""
    if _SIMPLE_TEXT.fullmatch(text) is None or text.endswith(" "):
        return None
    if ": " in text or text.endswith(":") or not _resolves_to_text(text):
        return f"'{text}'"
    return text


def _resolves_to_text(text: str) -> bool:
    """Whether YAML reads ``text`` written plain as a string (PyYAML's own resolver)."""
    first, space, _ = text.partition(" ")
    if space and "-" not in first[1:]:
        return True  # a number and its unit: only a timestamp (2001-12-14 21:59) has a space
    if not _RESOLVER:
        import yaml

        _RESOLVER.append(yaml.resolver.Resolver())
    return bool(_RESOLVER[0].resolve(_scalar_node(), text, (True, False))
                == "tag:yaml.org,2002:str")


def _scalar_node() -> Any:
    import yaml

    return yaml.ScalarNode


def _plain_ascii(value: Any) -> bool:
    """Every string in ``value`` printable ASCII, every scalar a string or a number."""
    if isinstance(value, str):
        return value.isascii() and value.isprintable()
    if isinstance(value, dict):
        return all(_plain_ascii(k) and _plain_ascii(v) for k, v in value.items())
    if isinstance(value, list):
        return all(_plain_ascii(v) for v in value)
    return isinstance(value, (int, float)) and not isinstance(value, bool) or value is None
