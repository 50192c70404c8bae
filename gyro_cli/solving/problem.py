"""Reading a problem file: safe YAML, every rule of the format, SI floats out.

Errors name the file, the key, its YAML line and what was expected.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable
from typing import Any

from ..core import safeyaml, units  # safeyaml's imports are light (yaml comes later)
from ..core.alternatives import Alternative, alternatives_of, converted
from ..core.body import BODY_PARAMS
from ..core.errors import InputError, shown
from ..core.given import Given, Particles
from ..core.params import _OPS, normal_word, read_word, safe_choices, split_hemisphere
from ..core.record import field, record
from ..core.spec import Kind, Param
from ..kinds import get as kind_named

TOP_KEYS = ("id", "kind", "given", "find", "title", "source", "statement", "notes", "expected",
            "tolerance", "vary", "units", "ask", "steps")
UNIT_SYSTEMS = ("si", "us")
REQUIRED = ("id", "kind", "given", "find")
_TOP_KEY_SET = frozenset(TOP_KEYS)
MAX_FILE_BYTES = 1_000_000


@record
class Problem:
    """One problem file, checked and parsed (given data in SI)."""

    file: str
    id: str
    kind: Kind
    given: Given
    quantities: dict[str, Any]
    find: dict[str, str | None]
    title: str = ""
    source: str = ""
    notes: list[str] = field(default_factory=list)
    expected: dict[str, Any] = field(default_factory=dict)
    tolerance: Any = None
    vary: Any = None
    data: dict[str, Any] = field(default_factory=dict)
    lines: dict[str, int] = field(default_factory=dict)
    us_customary: bool = False
    units: str = "si"  # the worked answer's units: "si", or "us" (slug, ft, lbf)
    statement: str = ""  # as written, with {key} placeholders (core/statement.py)
    ask: list[str] = field(default_factory=list)  # the answers the statement asks ([]: all)
    #: worked-answer steps graded as questions, by symbol (checked against a solve)
    steps: list[str] = field(default_factory=list)

    def statement_text(self) -> str:
        """The statement with each {key} filled from `given` as written ("" if none)."""
        from ..core.statement import fill_statement

        return fill_statement(self.statement, self.data.get("given", {})) if self.statement \
            else ""

    def line(self, key: str | None) -> int | None:
        return self.lines.get(key or "")


def answer_names(problem: Any) -> list[str]:
    """Every answer a problem gives: its `find`, then those of its `expected` the kind has."""
    return list(dict.fromkeys([*problem.find, *(n for n in problem.expected
                                                if problem.kind.answer(n) is not None)]))


def asked(problem: Any) -> list[str]:
    """What its statement asks of a student (`ask:`), else every answer: what a question
    bank asks and grading by assignment grades."""
    return list(problem.ask) or answer_names(problem)


def graded_questions(problem: Any) -> list[str]:
    """What a student is graded on: the steps asked (`steps:`), then what the statement
    asks (:func:`asked`); grading by assignment and the handout's key list these."""
    return list(dict.fromkeys([*getattr(problem, "steps", []), *asked(problem)]))


def suggest(word: str, options: list[str] | tuple[str, ...]) -> str:
    """A "did you mean" for a misspelt key or answer.

    A compound name is matched first within its own family (``turn_diameter``
    -> ``turn_radius``, the same kind of thing, not the rotor's ``diameter``).
    """
    options = list(options)
    head = word.split("_")[0]
    family = [o for o in options if "_" in o and o.split("_")[0] == head] if "_" in word else []
    import difflib

    close = difflib.get_close_matches(word, family, n=1, cutoff=0.0) if family else \
        difflib.get_close_matches(word, options, n=1, cutoff=0.6)
    return f"; did you mean {close[0]!r}?" if close else ""


def read_yaml(path: str, limit: int = MAX_FILE_BYTES) -> tuple[Any, dict[str, int]]:
    """Safe-load one YAML document; also the line of each key, two levels deep.

    Only a regular file of at most ``limit`` bytes is read; nesting and aliases
    are limited before anything is built (safeyaml.py).
    """
    return parse_yaml(safeyaml.read_text(path, limit), path, limit)


def parse_yaml(text: str, path: str, limit: int = MAX_FILE_BYTES) -> tuple[Any, dict[str, int]]:
    """Safe-load YAML text (a file's, or text given to the Python API, named ``path`` in
    messages); also the line of each key."""
    import yaml

    if len(text) > limit:  # read_text has already held a file to its limit
        raise InputError(f"longer than {limit:,} characters; a problem is at most that",
                         file=path)
    try:
        data, node = safeyaml.load(text)
    except InputError as err:
        raise err.located(file=path) from None
    except yaml.MarkedYAMLError as err:
        mark = err.problem_mark or err.context_mark
        raise InputError(safeyaml.message(err), file=path,
                         line=mark.line + 1 if mark else None) from None
    except yaml.YAMLError as err:
        raise InputError(f"YAML error: {err}", file=path) from None
    try:
        return data, _key_lines(node, data)
    except InputError as err:
        raise err.located(file=path) from None


TEXT_KEYS = ("id", "title", "source", "notes")


def _key_lines(node: Any, data: Any = None) -> dict[str, int]:
    """The line of each key, two levels deep (and of the items of a list of mappings under
    a second-level key, with their keys); InputError for a key written twice.

    In the same walk, ``id``, ``title``, ``source`` and ``notes`` of ``data`` (the
    document's mapping, if it is one) get back the text the user wrote. YAML 1.1 reads an
    unquoted ``11.10`` as the float 11.1, ``12:30`` as 750, ``011`` as 9 and ``yes`` as
    True; these keys are text, so a plain scalar's original characters (kept in its node)
    are used instead. ``null`` (or ``~``, or nothing) stays None and is refused where a
    value is required (the id).
    """
    import yaml

    lines: dict[str, int] = {}
    mapping = yaml.MappingNode
    if not isinstance(node, mapping):
        return lines
    sequence = yaml.SequenceNode
    texts = data if isinstance(data, dict) else {}
    for key, value in node.value:
        name = str(key.value)
        if name in lines:
            _once(lines, name, key)  # raises: written twice
        lines[name] = key.start_mark.line + 1
        if name in TEXT_KEYS and name in texts and not isinstance(texts[name], str):
            _keep_written_text(texts, name, value)  # (text is kept as it is)
        if isinstance(value, mapping):
            for sub_key, sub_value in value.value:
                sub_name = f"{name}.{sub_key.value}"
                if sub_name in lines:
                    _once(lines, sub_name, sub_key)  # raises: written twice
                lines[sub_name] = sub_key.start_mark.line + 1
                if isinstance(sub_value, sequence):  # a list of mappings (particles)
                    for i, item in enumerate(sub_value.value):
                        where = f"{name}.{sub_key.value}[{i}]"
                        lines[where] = item.start_mark.line + 1
                        if isinstance(item, mapping):
                            for item_key, _ in item.value:
                                _once(lines, f"{where}.{item_key.value}", item_key)
    return lines


def _keep_written_text(data: dict, name: str, node: Any) -> None:
    """``data[name]`` (a text key) as written: a plain scalar's own characters for the
    number, boolean or date YAML made of it, item by item in a list."""
    import yaml

    value = data[name]
    if isinstance(node, yaml.ScalarNode):
        data[name] = _written(value, node)
    elif isinstance(node, yaml.SequenceNode) and isinstance(value, list) and \
            len(node.value) == len(value):
        data[name] = [_written(v, n) if isinstance(n, yaml.ScalarNode) else v
                      for v, n in zip(value, node.value)]


def _written(value: Any, node: Any) -> Any:
    """A plain scalar that YAML turned into a number, a boolean or a date: its own text."""
    if value is None or isinstance(value, str) or node.style not in (None, ""):
        return value
    return node.value


def _once(lines: dict[str, int], name: str, key: Any) -> None:
    """Record a key's line; a key written twice is an error (YAML keeps the last silently)."""
    line = key.start_mark.line + 1
    if name in lines:
        raise InputError(f"key written twice (lines {lines[name]} and {line}); keep one",
                         key=name, line=line)
    lines[name] = line


def load(path: str) -> Problem:
    """Read and check a problem file; InputError (located) on anything wrong."""
    data, lines = read_yaml(path)
    return build(path, data, lines)


def build(path: str, data: Any, lines: dict[str, int]) -> Problem:
    """Check and parse a problem's data (from a file, YAML text or a mapping); InputError
    located at the key and its line."""
    try:
        return _build(path, data, lines)
    except InputError as err:
        key = err.key or ""
        line = lines.get(key)
        if line is None and "[" in key:  # a key missing from a list item: the item's line
            line = lines.get(key.rsplit(".", 1)[0])
        raise err.located(file=path, line=line) from None


def _build(path: str, data: Any, lines: dict[str, int]) -> Problem:
    if data is None:
        raise InputError("the file is empty; expected a mapping with id, kind, given and find")
    if not isinstance(data, dict):
        raise InputError(f"expected a mapping with id, kind, given and find at the top, got a "
                         f"{_type_name(data)}")
    for key in data:
        if key not in _TOP_KEY_SET:
            raise InputError(f"unknown key{suggest(str(key), TOP_KEYS)} (allowed: "
                             f"{', '.join(TOP_KEYS)})", key=str(key))
    for key in REQUIRED:
        if key not in data:
            raise InputError(f"missing required key `{key}`", key=key)
    kind = kind_named(data["kind"])
    if not isinstance(data["given"], dict):
        raise InputError(f"expected a mapping of quantities, got a {_type_name(data['given'])}",
                         key="given")
    given, quantities, us = parse_given(kind, data["given"])
    problem = Problem(
        file=path, id=_id(data["id"]), kind=kind, given=given, quantities=quantities,
        find=parse_find(kind, data["find"]), title=_text(data.get("title", ""), "title"),
        source=_text(data.get("source", ""), "source"), notes=_notes(data.get("notes")),
        expected=_expected(kind, data.get("expected"), _steps(data.get("steps"))),
        tolerance=data.get("tolerance"),
        vary=data.get("vary"), data=data, lines=lines, us_customary=us,
        units=_unit_system(data.get("units", "si")),
        statement=_statement(data.get("statement"), data["given"]))
    problem.ask = _ask(data.get("ask"), problem.find, problem.expected)
    problem.steps = _steps(data.get("steps"))
    return problem


def _steps(value: Any) -> list[str]:
    """``steps``: symbols of worked-answer steps asked as questions (``[m, I, M]``); that
    each is a step of the worked answer is checked once the problem is solved."""
    if value is None:
        return []
    names = value if isinstance(value, list) else [value]
    if not names or not all(isinstance(n, (str, int, float)) and not isinstance(n, bool)
                            and str(n).strip() for n in names):
        raise InputError(f"expected a list of step symbols of the worked answer, e.g. [m, I, M], "
                         f"got {shown(value)}", key="steps")
    return list(dict.fromkeys(str(n).strip() for n in names))


def _ask(value: Any, find: dict[str, Any], expected: dict[str, Any]) -> list[str]:
    """``ask``: the answers (of `find` and `expected`) that the statement asks a student
    for; a question bank asks only these (none given: every answer)."""
    if value is None:
        return []
    names = value if isinstance(value, list) else [value]
    if not names or not all(isinstance(name, str) for name in names):
        raise InputError(f"expected a list of answer names from find or expected, got "
                         f"{shown(value)}", key="ask")
    known = list(dict.fromkeys([*find, *expected]))
    for name in names:
        if name not in known:
            raise InputError(f"{name!r} is not an answer of find or expected"
                             f"{suggest(name, known)} (answers: {', '.join(known)})",
                             key="ask")
    return list(dict.fromkeys(names))


def _statement(value: Any, given: dict) -> str:
    """``statement``: text whose {key} placeholders are keys of `given` (checked here, so a
    handout never meets a bad one)."""
    if value is None:
        return ""
    if not isinstance(value, str) or not value.strip():
        raise InputError(f"expected the problem's text, got {shown(value)}", key="statement")
    # fill_statement refuses a lone brace and a name that is not a key of `given`. Where
    # every brace of the text is in a {name} and each name is a key of `given`, it has
    # nothing to refuse, so the text is not filled here (only where it is shown); anything
    # else ({{, }}, a lone brace, another name) is filled, to be refused in its words.
    names = re.findall(_PLACEHOLDER_NAMES, value) if "{" in value else []
    if value.count("{") + value.count("}") == 2 * len(names):
        for name in names:
            if name.strip() not in given:  # the test fill_statement makes of a name
                break
        else:
            return value.strip()
    from ..core.statement import StatementError, fill_statement

    try:
        fill_statement(value, given)
    except StatementError as err:
        raise InputError(str(err), key="statement") from None
    return value.strip()


# statement.PLACEHOLDER's {name}: where these account for every brace, the text holds no
# {{, }} or lone brace, and PLACEHOLDER reads the same names from it.
_PLACEHOLDER_NAMES = r"\{([^{}]*)\}"  # compiled on first use (re keeps it)


def _unit_system(value: Any) -> str:
    """``units``: the system the worked answer is written in."""
    if not isinstance(value, str) or value.lower() not in UNIT_SYSTEMS:
        raise InputError(f"expected si or us (slug, ft, lbf), got {value!r}"[:200], key="units")
    return value.lower()


def params_of(kind: Kind) -> tuple[Param, ...]:
    return kind.params + (BODY_PARAMS if kind.uses_body else ())


def params_by_name(kind: Kind) -> dict[str, Param]:
    """``params_of(kind)`` by name, made once per kind (read for every file)."""
    return _facts(kind).params


#: how a quantity is read: its param, its key in messages, whether lb means lbf, and its
#: declared limits as (test, bound) pairs (None: the param's own limits_broken decides)
_Reading = tuple[Param, str, bool, "tuple[tuple[Callable[[Any, Any], Any], float], ...] | None"]

class _KindFacts:
    """What reading a file of one kind looks up, made once per kind: its params by name,
    how each quantity is read (its key in messages, whether lb means lbf, its declared
    limits as tests) and the params with a default. (Answers by name: `Kind.answer`.)"""

    __slots__ = ("kind", "params", "reading", "defaults", "alternatives")

    def __init__(self, kind: Kind) -> None:
        self.kind = kind
        self.params = {p.name: p for p in params_of(kind)}
        self.reading: dict[str, _Reading] = {name: (p, f"given.{name}", name == "weight",
                               tuple((_OPS[op], x) for op, x in p.limits_declared()))
                        for name, p in self.params.items()}
        self.defaults = tuple(p for p in kind.params if p.default is not None)
        self.alternatives = alternatives_of(self.params)


def _facts(kind: Kind) -> _KindFacts:
    made = _FACTS.get(kind.name)
    if made is None or made.kind is not kind:
        made = _FACTS[kind.name] = _KindFacts(kind)
    return made


_FACTS: dict[str, _KindFacts] = {}


def parse_given(kind: Kind, raw: dict,
                memo: dict[tuple[str, str], tuple[Any, Any]] | None = None
                ) -> tuple[Given, dict[str, Any], bool]:
    """Parse every given quantity into SI; apply the kind's defaults. ``memo``: each string
    read before for a key of this kind (its value and reading), kept by a caller that
    parses many givens of one kind that share most strings (a roster's variants)."""
    facts = _facts(kind)
    params = facts.params
    values: dict[str, float | str | Particles] = {}
    quantities: dict[str, Any] = {}
    derived: dict[str, tuple[str, float]] = {}
    for key, text in raw.items():
        param = params.get(str(key))
        if param is None and str(key) in facts.alternatives:
            _parse_alternative(facts, facts.alternatives[str(key)], raw, values, quantities,
                               derived)
            continue
        if param is None:
            known = [*params, *facts.alternatives]
            raise InputError(f"unknown key for kind {kind.name}{suggest(str(key), known)}"
                             f" (see `gyro kinds`)", key=f"given.{key}")
        values[param.name], quantities[param.name] = _parse_remembered(param, text, facts, memo)
    _hemisphere_once(params, raw, values)
    defaulted = set()
    for param in facts.defaults:
        if param.name not in values:
            values[param.name], quantities[param.name] = _parse_remembered(
                param, param.default, facts, memo)
            defaulted.add(param.name)
    us = any(units.is_us_customary(quantities[k]) for k in ("mass", "weight") if k in quantities)
    if not us and "mass" not in quantities and "weight" not in quantities:
        us = any(_us_length(q) for q in quantities.values())  # inches, no mass: US data
    return Given(values, defaulted=defaulted, derived=derived), quantities, us


def _parse_remembered(param: Param, text: Any, facts: _KindFacts,
                      memo: dict[tuple[str, str], tuple[Any, Any]] | None) -> tuple[Any, Any]:
    """`_parse_param` of a string looked up in ``memo`` first (a refusal is not kept)."""
    if memo is None or text.__class__ is not str:
        return _parse_param(param, text, facts)
    known = memo.get((param.name, text))
    if known is None:
        known = _parse_param(param, text, facts)
        if len(memo) < _MEMO_MAX:  # a varied value is seldom seen again
            memo[(param.name, text)] = known
    return known


_MEMO_MAX = 1024


# US customary units of length (and speed) as gyro prints them: a file in these with no
# mass is US data, and its default g is the US textbook 32.2 ft/s^2
_US_LENGTHS = frozenset({"in", "ft", "yd", "mi", "mph", "inch", "foot", "yard", "mile"})


def _us_length(quantity: Any) -> bool:
    """Whether a parsed quantity's unit holds a US customary length (``12 in``, ``ft/s``)."""
    text = getattr(quantity, "unit_text", None)
    return isinstance(text, str) and not _US_LENGTHS.isdisjoint(re.findall(r"[A-Za-z]+", text))


def _parse_alternative(facts: _KindFacts, alternative: Alternative, raw: dict,
                       values: dict, quantities: dict,
                       derived: dict[str, tuple[str, float]]) -> None:
    """A key stated as books do (``wheel_diameter``, ``theta_from_horizontal``), read into
    the key the kind declares; refused beside that key or another way of stating it."""
    target = facts.params[alternative.target]
    key = f"given.{alternative.key}"
    others = [k for k in raw if k != alternative.key and (
        k == target.name or getattr(facts.alternatives.get(k), "target", None) == target.name)]
    if others:
        raise InputError(f"give {target.name} one way: {alternative.key} and {others[0]} "
                         f"both state it ({alternative.reading})", key=key)
    text = raw[alternative.key]
    si, quantity = _parse_quantity(alternative.param_for(target), text)
    value = converted(alternative, si)
    if target.limits_broken(value):
        unit = units.si_text(target.dimension)
        raise InputError(f"this gives {target.name} = {_shown_si(value, target.dimension)}, "
                         f"outside {target.expectation(unit)} ({alternative.reading}), got "
                         f"{shown(text)}", key=key)
    values[target.name], quantities[target.name] = value, quantity
    derived[target.name] = (alternative.key, si)


def _shown_si(value: float, dimension: str) -> str:
    """An SI value as a refusal prints it (an angle in degrees)."""
    if dimension == "angle":
        return f"{math.degrees(value):.6g} deg"
    return f"{value:.6g} {units.si_text(dimension)}".rstrip()


def _hemisphere_once(params: dict[str, Param], raw: dict, values: dict) -> None:
    """A `hemisphere` word beside a latitude that writes its own (``30 S``) is refused: the
    two could disagree, and neither should silently win."""
    if "hemisphere" not in values:
        return
    for key, param in params.items():
        text = raw.get(key)
        if param.hemisphere == "NS" and key == "latitude" and isinstance(text, str) and \
                split_hemisphere(text, param.hemisphere) is not None:
            raise InputError(f"the latitude already names its hemisphere ({shown(text)}): "
                             "give the hemisphere once", key="given.hemisphere")


def _parse_param(param: Param, text: Any,
                 facts: _KindFacts | None = None) -> tuple[float | str | Particles, Any]:
    dimension = param.dimension
    if dimension == "word":
        key = f"given.{param.name}"
        if isinstance(text, bool) and set(param.choices) == {"true", "false"}:
            text = "true" if text else "false"  # YAML reads `false` as a boolean
        word = read_word(param, text) if isinstance(text, str) else None
        if word is None:
            safe = safe_choices(str(text), param.choices)
            raise InputError(f"expected one of {', '.join(param.choices)}, got {shown(text)}"
                             f"{suggest(normal_word(str(text)), safe) if safe else ''}",
                             key=key)
        return word, text
    if dimension == "particles":
        return parse_particles(text, f"given.{param.name}"), text
    return _parse_quantity(param, text, facts)


def _parse_quantity(param: Param, text: Any,
                    facts: _KindFacts | None = None) -> tuple[float, Any]:
    """A quantity given for ``param`` (not a word or particles): its SI value and reading."""
    dimension = param.dimension
    reading: _Reading | None = facts.reading.get(param.name) if facts is not None else None
    if reading is None or reading[0] is not param:
        reading = (param, f"given.{param.name}", param.name == "weight", None)
    _, key, weight, limits = reading
    if param.hemisphere and isinstance(text, str):
        with_hemisphere = _parse_hemisphere(param, text, key)
        if with_hemisphere is not None:
            return with_hemisphere
    if text.__class__ is str:  # guarded's own checks are of other values; its refusal here
        try:
            value, quantity = units.parse(text, dimension, key, weight=weight)
        except InputError:
            raise
        except Exception as err:  # noqa: BLE001 - as guarded
            raise _unreadable(text, err, key) from None
    else:
        value, quantity = guarded(units.parse, text, dimension, key, weight=weight)
    if value != 0 and abs(value) < LEAST_MAGNITUDE:
        representable(value, text, dimension, key)  # refused
    if limits is None:
        within_limits(param, value, text, key)
    else:
        for test, x in limits:  # the declared limits, as Param.limits_broken tests them
            if not test(value, x):
                within_limits(param, value, text, key)  # refused, in its words
    return value, quantity


def _parse_hemisphere(param: Param, text: str, key: str) -> tuple[float, Any] | None:
    """A latitude or longitude written with its hemisphere (``30 S``, ``30 deg S``, ``S 30``):
    the angle read without the letter, negative south (west), within the key's limits;
    None when no hemisphere is written."""
    try:
        split = split_hemisphere(text, param.hemisphere)
    except ValueError as err:
        raise InputError(f"{err}, got {shown(text)}", key=key) from None
    if split is None:
        return None
    angle, sign = split
    value, quantity = guarded(units.parse, angle, param.dimension, key)
    value = sign * value
    within_limits(param, value, text, key)
    return value, quantity


def within_limits(param: Param, value: float, text: Any, key: str) -> None:
    """Refuse a value outside the limits the param declares (positive, a range, ...), in
    one style for every kind: ``expected 0 deg <= obliquity < 90 deg, got '95 deg'; why``."""
    if not param.limits_broken(value):
        return
    unit = units.si_text(param.dimension)
    reason = f"; {param.reason}" if param.reason else ""
    raise InputError(f"expected {param.expectation(unit)}, got {shown(text)}{reason}", key=key)


# The least magnitude (SI) of a given value that is not zero. The chapter's equations
# multiply up to five given values (J^2 psidot^2 against 4 I m g l cos(theta)); a product of
# five values of at least 1e-60 stays above the least normal double, 2.2e-308, where one of
# 1e-170 kg would underflow to 0 and print 0 rpm or a wrong root without a word.
LEAST_MAGNITUDE = 1e-60


def representable(value: float, text: Any, dimension: str, key: str) -> float:
    """``value`` unless it is non-zero and so small that products of it underflow."""
    if value != 0 and abs(value) < LEAST_MAGNITUDE:
        unit = units.si_text(dimension)
        raise InputError(f"{shown(text)} is {value:.3g}{' ' + unit if unit else ''}: a non-zero "
                         f"value below {LEAST_MAGNITUDE:g} (SI) is refused, since products and "
                         "quotients of a few such values overflow or underflow double precision "
                         "(an underflow to 0 below 2.2e-308) and the answers would be wrong; "
                         "check the unit, or use 0", key=key)
    return value


def guarded(parse: Any, text: Any, dimension: str, key: str, **options: Any) -> Any:
    """A units call whose unexpected failure on odd text (the unit parser's own
    exceptions) is bad input at ``key``, not a crash."""
    if parse is units.check_unit and not isinstance(text, str):
        raise InputError(f"expected a unit for this answer such as "
                         f"'{units.si_text(dimension)}', got {shown(text)}", key=key)
    if isinstance(text, float) and not math.isfinite(text):
        written = ".nan" if text != text else ("-.inf" if text < 0 else ".inf")
        raise InputError(f"expected a finite quantity such as '150 mm', got {written!r}",
                         key=key)
    try:
        return parse(text, dimension, key, **options)
    except InputError:
        raise
    except Exception as err:  # noqa: BLE001 - e.g. AssertionError, TokenError from pint
        raise _unreadable(text, err, key) from None


def _unreadable(text: Any, err: Exception, key: str) -> InputError:
    """guarded's refusal of text the unit parser failed on unexpectedly."""
    written = " ".join(str(text).split())[:60]
    return InputError(f"cannot read the unit in {written!r} ({type(err).__name__})", key=key)


PARTICLE_KEYS = ("mass", "x", "y", "z")
MAX_PARTICLES = 10_000


def parse_particles(raw: Any, key: str) -> Particles:
    """A list of {mass, x, y, z} mappings -> ((m, x, y, z) in SI, ...); positive masses."""
    if not isinstance(raw, list) or not raw:
        raise InputError("expected a list of particles, each {mass: .., x: .., y: .., z: ..}, "
                         f"got a {_type_name(raw)}", key=key)
    if len(raw) > MAX_PARTICLES:
        raise InputError(f"{len(raw)} particles; at most {MAX_PARTICLES} are accepted", key=key)
    out: list[tuple[float, float, float, float]] = []
    for i, item in enumerate(raw):
        where = f"{key}[{i}]"
        if not isinstance(item, dict):
            raise InputError(f"expected a mapping {{mass: .., x: .., y: .., z: ..}}, got a "
                             f"{_type_name(item)}", key=where)
        for name in item:
            if name not in PARTICLE_KEYS:
                raise InputError(f"unknown key{suggest(str(name), PARTICLE_KEYS)} (a particle "
                                 "has mass, x, y, z)", key=f"{where}.{name}")
        for name in PARTICLE_KEYS:
            if name not in item:
                what = "its mass" if name == "mass" else f"its position {name} (body axes)"
                raise InputError(f"this particle needs {what}", key=f"{where}.{name}")
        m = representable(units.parse(item["mass"], "mass", f"{where}.mass")[0], item["mass"],
                          "mass", f"{where}.mass")
        if m <= 0:
            raise InputError(f"a particle's mass must be positive, got {item['mass']!r}",
                             key=f"{where}.mass")
        x, y, z = [representable(units.parse(item[n], "length", f"{where}.{n}")[0], item[n],
                                 "length", f"{where}.{n}") for n in ("x", "y", "z")]
        out.append((m, x, y, z))
    return tuple(out)


def parse_find(kind: Kind, raw: Any) -> dict[str, str | None]:
    """``find``: answer name -> unit to print it in (None for words or SI)."""
    if isinstance(raw, list):
        for name in raw:
            if not isinstance(name, str):
                raise InputError(f"expected answer names (a list of words, or a mapping of "
                                 f"names to units), got a {_type_name(name)} in the list",
                                 key="find")
        raw = {name: None for name in raw}
    if not isinstance(raw, dict) or not raw:
        raise InputError("expected a mapping of answer names to units, e.g. {precession: rpm}",
                         key="find")
    find: dict[str, str | None] = {}
    for name, unit in raw.items():
        answer = kind.answer(str(name))
        if answer is None:
            names = [a.name for a in kind.answers]
            raise InputError(f"unknown answer for kind {kind.name}{suggest(str(name), names)} "
                             f"(answers: {', '.join(names)})", key=f"find.{name}")
        if answer.dimension is None:
            if unit is not None:
                raise InputError(f"{name} is a word, not a quantity: write `{name}: null`",
                                 key=f"find.{name}")
            find[answer.name] = None
        else:
            find[answer.name] = (None if unit is None else
                                 guarded(units.check_unit, unit, answer.dimension,
                                         f"find.{name}"))
    return find


def _expected(kind: Kind, raw: Any, steps: list[str] | None = None) -> dict[str, Any]:
    if raw is None:
        return {}
    if not isinstance(raw, dict):
        raise InputError("expected a mapping of answer names to values", key="expected")
    for name in raw:
        if name == "steps" and kind.answer("steps") is None:
            steps = raw[name]
            if not isinstance(steps, dict) or not steps:
                raise InputError("expected a mapping of the worked answer's step symbols to "
                                 "values, e.g. {omega_z: 1850 rpm}", key="expected.steps")
            continue
        if kind.answer(str(name)) is None and str(name) not in (steps or []):
            names = [a.name for a in kind.answers] + (steps or [])
            raise InputError(f"unknown answer{suggest(str(name), names)} (answers: "
                             f"{', '.join(names)})", key=f"expected.{name}")
    return dict(raw)


def _id(value: Any) -> str:
    """The problem's id, as text; an empty id is refused (answers and reports use it)."""
    text = _text(value, "id")
    if not text.strip():
        raise InputError(f"the id is empty ({shown(value)}); write the problem's id, in quotes "
                         "if it could be read as something else ('11.10', '12:30', 'null')",
                         key="id")
    return text


def _text(value: Any, key: str) -> str:
    if isinstance(value, (dict, list)):
        raise InputError(f"expected text, got a {_type_name(value)}", key=key)
    if isinstance(value, float) and not math.isfinite(value):
        return shown(value)  # `title: .nan` is the text .nan, not a number nan
    return "" if value is None else str(value)


def _notes(value: Any) -> list[str]:
    if value is None:
        return []
    if isinstance(value, str):
        return [value]
    if isinstance(value, list) and all(isinstance(v, (str, int, float)) for v in value):
        return [_text(v, "notes") for v in value]
    raise InputError("expected a list of lines of text", key="notes")


def _type_name(value: Any) -> str:
    return {dict: "mapping", list: "list", str: "string", int: "number", float: "number",
            bool: "boolean", type(None): "empty value"}.get(type(value), type(value).__name__)
