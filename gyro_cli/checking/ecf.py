"""Steps as questions, and errors carried forward (``--credit ecf=S``).

A problem's ``steps: [m, I]`` are graded like answers, by symbol, against the first step
of that symbol in the worked answer (`solving.deps.graded_steps`).

Errors carried forward, as an examiner marks: a wrong answer or step earns the share S
when it is right for the student's own wrong earlier values (the steps and closed
answers it depends on, `solving.deps`), the problem solved again with those values in
place of the solver's (`solve(problem, overrides)`), so roots, eigenvalues and
integrations follow as closed formulas do. The earlier wrong value itself earns nothing.

- the student's value is used as written, and the tolerance widened by what half a unit
  of its last written digit moves the later answer;
- no follow-through from a stock value (0, 1), nor from one that barely moves the later
  answer (the carried answer within the tolerance of the solver's) or leaves it 0;
- a blank earlier part is not carried (the solver's value is used);
- a carried value already credited as a named slip earns the later answer its full point
  (the slip is not penalised twice);
- a later answer of several roots is compared as a set with the carried roots, so a
  student who carried one branch is graded on it.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from types import SimpleNamespace
from typing import Any

from ..core.errors import InputError
from .expected import Expected, parse_value
from .matching import graded_lines
from .tolerance import Tolerance, student_widths, tolerance_for

ECF = "ecf"


def step_names(result: Any) -> dict[str, tuple[float, str, str]]:
    from ..solving.deps import graded_steps

    return graded_steps(result.solution)


def check_steps(problem: Any, result: Any) -> None:
    """Every symbol of the problem's ``steps`` is a step of its worked answer (InputError
    naming the key and the symbols there are)."""
    if not problem.steps:
        return
    known = step_names(result)
    for symbol in problem.steps:
        if symbol not in known:
            from ..solving.problem import suggest

            raise InputError(f"no step of the worked answer is {symbol!r}"
                             f"{suggest(symbol, list(known))} (steps: {', '.join(known)})",
                             file=problem.file, line=problem.line("steps"), key="steps")


def step_reported(result: Any, symbol: str) -> Any:
    """A step's value as an answer is reported (SI unit), for grading it as a question."""
    value, unit, dimension = step_names(result)[symbol]
    return SimpleNamespace(name=symbol, symbol=symbol, values=[value], unit=unit,
                           si_values=[value], si_unit=unit, labels=[], dimension=dimension)


def step_tolerance(problem: Any, symbol: str, dimension: str) -> Tolerance:
    """A step's tolerance: the file's (its ``default:`` for a mapping); a file-wide
    absolute tolerance of another dimension gives way to the default 1%."""
    spec = problem.tolerance
    if isinstance(spec, dict):
        spec = spec.get("default")
    try:
        return tolerance_for(spec, symbol, dimension, [])
    except InputError:
        return tolerance_for(None, symbol, dimension, [])


# ---- errors carried forward --------------------------------------------------

@dataclass
class Item:
    """One graded question of a student's problem, as ECF needs it."""

    name: str         # the answer name or step symbol
    row: Any          # its GradeRow
    values: list[Any]  # as submitted
    dimension: str | None
    tolerance: Tolerance
    is_step: bool


def _written_place(text: str, number: float) -> float | None:
    """Half a unit of the last digit of the number written first in ``text`` (in the
    number's own unit), at most that of its third significant figure (``0.02`` is taken
    as 0.0200: a round number is no claim of one figure); None when there is no number."""
    match = re.match(r"\s*[-+\u2212]?(\d*)(?:\.(\d*))?(?:[eE]([-+\u2212]?\d+))?", text)
    if not match or not (match.group(1) or match.group(2)) or not number:
        return None
    decimals = len(match.group(2) or "")
    exponent = int((match.group(3) or "0").replace("\u2212", "-"))
    third = 0.5 * 10.0 ** (math.floor(math.log10(abs(number))) - 2)
    return min(0.5 * 10.0 ** (exponent - decimals), third)


def _stock(value: Expected) -> bool:
    """A stock answer: 0 or 1 (either sign) as written."""
    return value.number in (0.0, 1.0, -1.0)


def carry(items: list[Item], problem: Any, result: Any, graph: Any, share: float,
          slipped: set[str]) -> None:
    """Give each wrong item that follows from the student's own wrong earlier values the
    ``share`` (notes naming the values carried); ``slipped``: the items whose wrong value
    was credited as a named slip."""
    follow_branch(items, result)
    symbol_of = {it.name: (it.name if it.is_step else graph.answer_step.get(it.name))
                 for it in items}
    wrong = [it for it in items if it.row.result in ("wrong", "partial") and
             symbol_of[it.name] is not None and len(it.values) == 1]
    for item in items:
        if item.row.result not in ("wrong", "partial") or item.dimension is None:
            continue
        key = item.name if item.is_step else f"answer:{item.name}"
        depends = set(graph.depends.get(key, [])) - {symbol_of[item.name]}
        sources = [it for it in wrong if it is not item and symbol_of[it.name] in depends]
        if sources:
            _carry_one(item, sources, symbol_of, problem, result, share, slipped)
        elif not depends and not item.is_step and item.name not in graph.closed and \
                any(it.is_step for it in wrong):
            _note(item, f"errors are not carried into {item.name}: gyro works it from the "
                  "data given, not from the steps of the working")


def follow_branch(items: list[Item], result: Any) -> None:
    """A root followed: once a student gives one branch of a labelled answer (the fast
    precession alone), a later answer with the same labels for which they give fewer
    values than roots is graded on that branch only."""
    branch: set[str] | None = None
    for item in items:
        answer = None if item.is_step else result.answers.get(item.name)
        if answer is None or len(set(answer.labels)) < 2 or item.dimension is None:
            continue
        parsed = _parsed(item)
        if not parsed or len(parsed) >= len(answer.si_values):
            continue
        if branch is None:
            branch = _branch(item, parsed, answer)
            continue
        if not branch <= set(answer.labels):
            continue
        keep = [i for i, label in enumerate(answer.labels) if label in branch]
        sub = SimpleNamespace(si_values=[answer.si_values[i] for i in keep],
                              si_unit=answer.si_unit, unit=answer.si_unit,
                              labels=[answer.labels[i] for i in keep],
                              values=[answer.values[i] for i in keep])  # printed figures
        lines = graded_lines(item.name, parsed, item.tolerance, sub)
        if len(lines) == len(keep) and all(line.passed for line in lines):
            item.row.points, item.row.result = 1.0, "correct"
            item.row.note = item.row.feedback = ""  # the other root is not missing
            if item.row.plain is not None:
                item.row.plain = ""
            _note(item, f"graded on the {' and '.join(sorted(branch))} branch you followed")


def _branch(item: Item, parsed: list[Expected], answer: Any) -> set[str] | None:
    """The labels of the roots a student's values matched (all of them must match)."""
    lines = graded_lines(item.name, parsed, item.tolerance, answer)
    labels = set()
    for line in lines:
        if line.expected is None:
            continue
        if not line.passed:
            return None
        for value, label in zip(answer.si_values, answer.labels):
            if line.got_si is not None and float(line.got_si) == float(value):
                labels.add(label)
    return labels or None


def _parsed(item: Item) -> list[Expected] | None:
    try:
        return [parse_value(v, item.dimension, item.name) for v in item.values]
    except Exception:  # an invalid value: nothing to carry or compare
        return None


def _follow(item: Item, carried: dict[str, float], result: Any, symbol: str | None
            ) -> list[float] | None:
    """The item's values with the carried values in place: the problem solved again, or,
    where the kind refuses those values, a closed formula's tree worked out again."""
    from ..solving.deps import through_trees
    from ..solving.solve import solve

    try:
        return _carried_values(item, solve(result.problem, carried))
    except (InputError, ArithmeticError, ValueError):
        pass
    if symbol is None:
        return None  # a root, an eigenvalue: only the solver gives it
    try:
        env = through_trees(result.solution, carried)
    except (ArithmeticError, ValueError):
        return None
    return [env[symbol]] if symbol in env and symbol not in carried else None


def _as_carried(source: Item, value: float, result: Any) -> float:
    """A student's value as it is carried: as written, but under a magnitude tolerance
    (the book quotes a size) with the solver's sign, so a size written without its sign
    carries the quantity the student meant, not its reverse."""
    if not source.tolerance.magnitude:
        return value
    truth = _carried_values(source, result)
    return math.copysign(abs(value), truth[0]) if truth else value


def _carried_values(item: Item, solved: Any) -> list[float] | None:
    if item.is_step:
        step = step_names(solved).get(item.name)
        return None if step is None else [step[0]]
    answer = solved.answers.get(item.name)
    return None if answer is None else [float(v) for v in answer.si_values]


def _carry_one(item: Item, sources: list[Item], symbol_of: dict[str, str | None],
               problem: Any, result: Any, share: float, slipped: set[str]) -> None:
    carried: dict[str, float] = {}
    written: list[tuple[str, Expected]] = []
    used: list[Item] = []
    for source in sources:
        parsed = _parsed(source)
        if not parsed:
            continue
        symbol = symbol_of[source.name]
        assert symbol is not None
        if _stock(parsed[0]):
            _note(item, f"no follow-through from your {symbol} = {parsed[0].text} (a stock "
                  "value makes the rest another problem)")
            return
        carried[symbol] = _as_carried(source, float(parsed[0].si), result)
        written.append((symbol, parsed[0]))
        used.append(source)
    submitted = _parsed(item)
    if not carried or not submitted:
        return
    again = _follow(item, carried, result, symbol_of[item.name])
    if again is None:
        _note(item, "your values give this problem no solution: nothing to follow through")
        return
    truth = _carried_values(item, result)
    # a value the student's values leave 0 is degenerate; one 0 in the solver's answer too
    # (the imaginary part of a real eigenvalue) is not
    if not again or not truth or not all(math.isfinite(v) for v in again) or \
            again.count(0.0) > truth.count(0.0):
        return
    # each carried value accepts what grading accepts around the solver's (measured from
    # it, never tighter than its printed figures: tolerance.student_widths); a carried
    # value inside the band grading accepts around the truth barely moves the answer
    widths = student_widths(item.tolerance, _reported(item, result, again))
    bands = student_widths(item.tolerance, _reported(item, result, truth))
    if len(again) == len(truth) and all(
            abs(a - t) <= band for a, t, band in zip(again, truth, bands)):
        # a hint (the student's earlier values are near enough the solver's for this
        # answer): left out of --no-hints
        _note(item, "the values carried barely change this answer: no follow-through",
              hint=True)
        return
    extra = _propagated(item, written, carried, result, again, symbol_of[item.name])
    labels = _reported(item, result, again).labels
    sizes = [float(v.si) for v in submitted]
    if item.tolerance.magnitude:  # the book quotes sizes: sizes are compared
        sizes, again = [abs(v) for v in sizes], [abs(v) for v in again]
    hits, total = _matched(sizes, widths, again, extra, labels)
    if not hits:
        return
    full = all(source.name in slipped for source in used)
    # a root right against the solver's value keeps its whole point; a root right only
    # for the student's own earlier values earns the ECF share
    right = _right(item, submitted, result)
    earned = (len(right) + (1.0 if full else share) * len(hits - right)) / total
    values = ", ".join(f"{symbol} = {value.text}" for symbol, value in written)
    why = f"consistent with your {values} (ECF" + (
        "; the slip there was already marked down)" if full else ")")
    if earned > item.row.points:
        item.row.points = round(earned, 4)
        item.row.result = "carried" if len(hits | right) == total else "partial"
        why += f" [credit {earned:g}]"
    _note(item, why)


def _right(item: Item, submitted: list[Expected], result: Any) -> set[int]:
    """Which of the submitted values are right against the solver's own (as graded)."""
    reported = step_reported(result, item.name) if item.is_step \
        else result.answers[item.name]
    lines = graded_lines(item.name, submitted, item.tolerance, reported)
    passed = [float(line.expected_si) for line in lines
              if line.passed and line.expected_si is not None]
    out = set()
    for i, value in enumerate(submitted):
        si = abs(float(value.si)) if item.tolerance.magnitude else float(value.si)
        if si in passed:
            passed.remove(si)
            out.add(i)
    return out


def _matched(submitted: list[float], widths: list[float], carried: list[float],
             extra: list[float], labels: list[str]) -> tuple[set[int], int]:
    """Which submitted values match a carried value (within the carried value's width,
    ``widths[j]``, and what the last digit carried moves that value), and how many values
    are graded: roots as sets, places (labelled A, B, outer, ...) in order."""
    from .matching import match_roots, ordered

    def passes(i: int, j: int) -> bool:
        return abs(submitted[i] - carried[j]) <= widths[j] + extra[j] + 1e-300

    if ordered(labels):
        pairs: list[tuple[int | None, int | None]] = [
            (i if i < len(submitted) else None, i if i < len(carried) else None)
            for i in range(max(len(submitted), len(carried)))]
    else:
        pairs = match_roots(submitted, carried, passes)
    hits = {i for i, j in pairs if i is not None and j is not None and passes(i, j)}
    return hits, len(pairs)


def _reported(item: Item, result: Any, again: list[float]) -> Any:
    """The carried values as `compare` reads a solver's answer."""
    if item.is_step:
        unit = step_names(result)[item.name][1]
        return SimpleNamespace(si_values=again, si_unit=unit, unit=unit, labels=[])
    answer = result.answers[item.name]
    # the carried values as the answer prints them (its unit), for the printed figures
    scale = next((v / si for v, si in zip(answer.values, answer.si_values)
                  if isinstance(v, (int, float)) and si), 1.0)
    return SimpleNamespace(si_values=again, si_unit=answer.si_unit, unit=answer.si_unit,
                           labels=list(answer.labels), values=[a * scale for a in again])


def _note(item: Item, text: str, hint: bool = False) -> None:
    """The same words for the teacher and the student: they name only the student's own
    values, never the solver's (a ``hint`` not under --no-hints)."""
    row = item.row
    row.note = "; ".join(p for p in (row.note, text) if p)
    row.feedback = "; ".join(p for p in (row.feedback, text) if p)
    if row.plain is not None and not hint:
        row.plain = "; ".join(p for p in (row.plain, text) if p)


def _propagated(item: Item, written: list[tuple[str, Expected]], carried: dict[str, float],
                result: Any, again: list[float], target: str | None) -> list[float]:
    """How far half a unit of each carried value's last written digit moves each value of
    the later answer (summed over the values carried)."""
    total = [0.0] * len(again)
    for symbol, value in written:
        place = _written_place(value.text, value.number)
        if place is None:
            continue
        moved = dict(carried)
        moved[symbol] = carried[symbol] + place * value.factor
        shifted = _follow(item, moved, result, target)
        if shifted and len(shifted) == len(again):
            total = [t + abs(a - b) for t, a, b in zip(total, shifted, again)]
    return total


def policy_share(credit: dict[str, float] | None) -> float | None:
    """The ECF share of a --credit policy, or None when it carries nothing."""
    if not credit or ECF not in credit:
        return None
    return credit[ECF]


# ---- banks: errors carried forward without gyro (PrairieLearn's server.py) -------------

#: the grid of a carried value, as factors of the solver's: 0.25x to 4x, evenly in log
GRID = tuple(math.exp(math.log(0.25) + k * math.log(16) / 96) for k in range(97))


@dataclass(frozen=True)
class Part:
    """One blank of a bank's question: an answer's value (by index) or a step's."""

    key: str
    name: str        # the answer name or step symbol
    index: int       # which of the answer's values
    is_step: bool
    unit: str        # the blank's unit ("" for SI or a pure number)
    dimension: str | None = None
    magnitude: bool = False  # the blank asks a size (a magnitude tolerance): sizes carried


def followers(graph: Any, parts: list[Part]) -> dict[str, list[str]]:
    """Each step blank's key -> the keys of the blanks that depend on it (ECF targets); an
    answer that is the step itself is none (gyro check's rule: the same slip written twice
    is not consistent working)."""
    out: dict[str, list[str]] = {}
    for source in parts:
        if not source.is_step:
            continue
        for target in parts:
            key = target.name if target.is_step else f"answer:{target.name}"
            itself = target.name if target.is_step else graph.answer_step.get(target.name)
            if itself != source.name and source.name in graph.depends.get(key, []):
                out.setdefault(source.key, []).append(target.key)
    return {k: v for k, v in out.items() if v}


def table(problem: Any, result: Any, parts: list[Part]) -> dict[str, dict[str, Any]]:
    """For each step blank some later blank depends on: its values on `GRID` (``at``), and
    each dependent blank's value, in its unit, with the step carried at each (``to``; None
    where the problem has no solution). A bank's grader interpolates in it."""
    from ..core import units
    from ..solving.deps import graph as make_graph
    from ..solving.deps import through_trees
    from ..solving.solve import solve

    g = make_graph(result.problem, result)
    by_key = {p.key: p for p in parts}
    out: dict[str, dict[str, Any]] = {}
    for source_key, targets in followers(g, parts).items():
        symbol = by_key[source_key].name
        value = step_names(result)[symbol][0]
        column: dict[str, list[float | None]] = {t: [] for t in targets}
        for factor in GRID:
            carried = {symbol: value * factor}
            try:
                again: Any = solve(result.problem, carried)
                env = None
            except (InputError, ArithmeticError, ValueError):
                again = None
                try:
                    env = through_trees(result.solution, carried)
                except (ArithmeticError, ValueError):
                    env = {}
            for t in targets:
                part = by_key[t]
                column[t].append(_part_value(part, again, env, g, units))
        out[source_key] = {"at": [value * f for f in GRID], "to": column}
    return out


def _part_value(part: Part, again: Any, env: dict[str, float] | None, g: Any,
                units: Any) -> float | None:
    """A blank's value in one carried solve (``again``), or through the trees (``env``)."""
    si: float | None = None
    if again is not None:
        if part.is_step:
            step = step_names(again).get(part.name)
            si = None if step is None else step[0]
        else:
            answer = again.answers.get(part.name)
            if answer is not None and part.index < len(answer.si_values):
                si = float(answer.si_values[part.index])
    elif env is not None:
        symbol = part.name if part.is_step else g.answer_step.get(part.name)
        if symbol is not None and symbol in env and part.index == 0:
            si = env[symbol]
    if si is None or not math.isfinite(si):
        return None
    if part.magnitude:  # the blank holds the size, as the student types it
        si = abs(si)
    if part.is_step or not part.unit or part.dimension is None:
        return si
    return float(units.convert(si, part.dimension, part.unit))


# ---- test cases made for every problem ------------------------------------------------

@dataclass(frozen=True)
class Case:
    """A student's values for one problem (name -> value as written) and what ECF should
    give the later one: ``carried`` True for a consistent follow-through, False for a stock
    earlier value."""

    step: str
    answer: str
    values: dict[str, list[str]]
    carried: bool


def cases(problem: Any, result: Any, graph: Any, factor: float = 1.1) -> list[Case]:
    """For each numeric answer and each step it depends on: the step ``factor`` times the
    solver's and the answer worked from it (to 15 figures: a tolerance may ask
    for 12, the bicycle's), and the step a stock 1 with the
    answer worked from that. Pairs whose carried solve fails, or leaves a value 0, are
    left out."""
    from ..solving.solve import solve

    steps = step_names(result)
    out = []
    stocked: set[str] = set()  # the stock case once per step
    for name, answer in result.answers.items():
        if answer.si_unit is None:
            continue
        own = graph.answer_step.get(name)
        for symbol in graph.depends.get(f"answer:{name}", []):
            if symbol == own or symbol not in steps:
                continue
            value, unit, _ = steps[symbol]
            trials = [(True, value * factor)]
            if symbol not in stocked and abs(value - 1) > 0.1 and value > 0:
                stocked.add(symbol)  # (a step near 1 has no stock case)
                trials.append((False, 1.0))
            for carried, written in trials:
                try:
                    again = solve(result.problem, {symbol: written}).answers[name]
                except (InputError, ArithmeticError, ValueError, KeyError):
                    continue
                if len(again.si_values) != len(answer.si_values) or \
                        again.si_values.count(0.0) > answer.si_values.count(0.0):
                    continue  # (a value the wrong step leaves 0 is not followed)
                later = [f"{v:.15g} {answer.si_unit}" for v in again.si_values]
                step_text = f"{written:.15g} {unit}" if carried else f"1 {unit}"
                out.append(Case(symbol, name, {symbol: [step_text], name: later}, carried))
    return out
