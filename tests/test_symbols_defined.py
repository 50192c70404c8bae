"""Every symbol of a worked answer is defined where it is first used (issue 9, item 3).

The worked answer is read in the order a student reads it: the Given table, then
each section's steps and lines of prose, then the checks. Formulas are parsed by
the write-up's own parser (`render/mathparse.py`); a symbol counts as defined
when it is in the Given table, when an earlier step computes it (``X = ...``),
when an earlier line states it (``X = ...`` in prose) or names it in words (a
lone symbol in a sentence: "K, the precession axis", "where D is ..."). A line
may define a symbol it also uses ("T = 2 pi / Omega, where Omega is ...").
Every bundled problem and every `gyro new KIND` example is walked.
"""

from __future__ import annotations

import re
import textwrap
from pathlib import Path

import pytest
from formula_oracle import FUNCTIONS, UNITS, dotted, is_word, spans, try_parse
from oracle_tree import (
    Abs,
    BinOp,
    Call,
    Group,
    Integral,
    Matrix,
    Neg,
    Pow,
    Prime,
    Quantity,
    Rel,
    Sum,
    Sym,
    Tuple,
)

from gyro_cli import kinds
from gyro_cli.commands.authoring import template
from gyro_cli.render.writeup import file_keys
from gyro_cli.solving.solve import solve_file

ROOT = Path(__file__).resolve().parent.parent
PROBLEMS = sorted((ROOT / "problems").glob("*.yaml"))

#: constants and notation every reader knows: pi, e, the imaginary unit, d of d/dt, time t,
#: Rx, Ry, Rz the rotations about x, y, z
UNIVERSAL = {"pi", "e", "i", "d", "dt", "du", "t", "Rx", "Ry", "Rz"}


def uses(node) -> list[str]:
    """The symbols a formula uses, in reading order."""
    out: list[str] = []

    def walk(n) -> None:
        if n is None:
            return
        if isinstance(n, Sym):
            out.append(n.name)
        elif isinstance(n, Call):
            if n.name not in FUNCTIONS and not _rotation(n.name):
                out.append(n.name)
            for a in n.args:
                walk(a)
            walk(n.power)
        elif isinstance(n, Quantity):
            walk(n.value)
        elif isinstance(n, Integral):
            walk(n.lower)
            walk(n.upper)
            walk(n.body)
        elif isinstance(n, Rel):
            walk(n.first)
            for _, rhs in n.rest:
                walk(rhs)
        elif isinstance(n, (Tuple,)):
            for x in n.items:
                walk(x)
        elif isinstance(n, Matrix):
            for row in n.rows:
                for x in row:
                    walk(x)
        elif isinstance(n, Group) and n.open == "[" and set(uses(n.body)) <= UNITS:
            return  # "[1/s^2]": the unit of a line, not symbols
        elif isinstance(n, (Group, Abs, Sum, Neg, Prime)):
            walk(n.body)
        elif isinstance(n, BinOp):
            walk(n.left)
            walk(n.right)
        elif isinstance(n, Pow):
            walk(n.base)
            walk(n.exp)
    walk(node)
    return out


def _rotation(name: str) -> bool:
    return name in ("Rx", "Ry", "Rz")


def _heads(node) -> list[str]:
    """The symbols a formula defines: the left side of ``X = ...`` (or of ``X, Y = ...``)."""
    if isinstance(node, Sym):
        return [node.name]
    if isinstance(node, Call) and node.name not in ("sin", "cos"):
        return [node.name]  # f(u) = ...
    if isinstance(node, (Tuple,)):
        return [h for x in node.items for h in _heads(x)]
    if isinstance(node, (Group, Sum)):
        return _heads(node.body)  # sum I_w: the wheels' I_w summed
    if isinstance(node, Abs):
        return _heads(node.body)
    return []


def _line_defs_uses(text: str) -> tuple[list[str], list[str]]:
    """What a line of prose (or a bare equation) defines and uses."""
    defs: list[str] = []
    used: list[str] = []
    # a key of the file is words in the write-up (sun_mass_ratio: "sun mass ratio")
    text = re.sub(r"\b[a-z]+(?:_[a-z0-9]+)+\b",
                  lambda m: m.group().replace("_", " ") if m.group().count("_") > 1
                  or is_word(m.group()) else m.group(), text)
    if KEYS[0] is not None:  # the kind's keys are words in the write-up (I_cg: "I cg")
        text = KEYS[0].sub("key", text)
    whole = try_parse(text)  # a line that is one formula is set as one (the write-up does)
    parts = [(True, whole)] if whole is not None else spans(text)
    for k, (is_math, part) in enumerate(parts):
        if not is_math:
            continue
        if isinstance(part, Sym):
            if _named(parts, k):  # named in words: "K: the precession axis"
                defs.append(part.name)
            else:
                used.append(part.name)
            continue
        if not isinstance(part, Rel) and set(uses(part)) <= UNITS:
            continue  # the tail of a unit after a word: "(0, 0) kg m^2/s", "[1/s^2]"
        if isinstance(part, Rel):
            # a chain a >= X = b: each member followed by "=" is defined by it
            members = [part.first] + [rhs for _, rhs in part.rest]
            ops = [op for op, _ in part.rest] + [""]
            dummies: set[str] = set()  # Pi(n|m) = ... R_J(..., 1 - n): n and m are its own
            here: list[str] = []
            for node, op in zip(members, ops):
                if op == "=" and _heads(node):
                    defs += _heads(node)
                    if isinstance(node, Call):
                        args = [uses(x) for x in node.args]
                        dummies |= {a[0] for a in args if len(a) == 1 and isinstance(
                            node.args[args.index(a)], Sym)}
                        here += [u for a in args for u in a]
                else:
                    here += uses(node)
            used += [u for u in here if u not in dummies]
            continue
        used += uses(part)
    return defs, used


#: words after a symbol that say what it is: "K: the precession axis", "where D is the ...",
#: "p, q, r: the components", "N of the plane", "u1, u2, u3 of f"
_AFTER = re.compile(r"^\s*(:|,|\)|;|\.(\s|$)|\s+(is|are)\s+(the|a|an|its|their|about|along|taken|"
                    r"measured)\b|\s+(of|from|and|the|its|\(|below|above|here|along|about|for|at|in|"
                    r"forward|up|down|to|toward|aft)\b|\s*$)")
#: words before a symbol that name it: "the precession rate phidot", "by the angle alpha"
_BEFORE = re.compile(r"(\b[a-z]{3,}[a-z'-]*|\()\s*$")


def _named(parts, k: int) -> bool:
    """A lone symbol in a sentence is named there: words before it ("the rate phidot") or
    after it ("K: the axis", "where D is the ...")."""
    after = parts[k + 1][1] if k + 1 < len(parts) and not parts[k + 1][0] else ""
    before = parts[k - 1][1] if k > 0 and not parts[k - 1][0] else ""
    if isinstance(after, str) and _AFTER.match(after):
        return True
    return isinstance(before, str) and bool(_BEFORE.search(before))


#: the keys of the kind being walked (writeup.file_keys)
KEYS: list = [None]


def _step_symbols(symbol: str) -> list[str]:
    """The symbols a step's left side defines (``phidot_slow, phidot_fast``); a step of one
    root, ``v_G (slow)``, defines v_G and v_G_slow."""
    out = []
    labelled = re.match(r"^(.*\S)\s*\((\w+)\)$", symbol)
    if labelled:
        base = _step_symbols(labelled.group(1))
        return base + [f"{b}_{labelled.group(2)}" for b in base]
    for piece in symbol.split(","):
        tree = try_parse(piece.strip(), units=False)
        out += _heads(tree) if tree is not None else []
    # a name like F_A,weight is one symbol
    tree = try_parse(symbol.strip(), units=False)
    if tree is not None:
        out += _heads(tree)
        if not out:  # a step computing a combination, "G M_sun / a_sun^3 = ...", names it
            out += uses(tree)
    return out


def undefined(solution, asked=None) -> list[tuple[str, str]]:
    """(symbol, where) for each symbol used before it is defined, in reading order; then
    each answer's symbol, which the work must have defined."""
    known = set(UNIVERSAL)
    known.update(g.symbol for g in solution.given)
    missing: list[tuple[str, str]] = []

    def need(names, where):
        for name in names:
            if name not in known and not _derived(name, known):
                missing.append((name, where))
                known.add(name)  # report each once

    for section in solution.sections:
        # a heading may announce the section's equation ("Moment on the rotor, dH/dt =
        # Omega K x H"): it defines what it names, and its other symbols are defined by the
        # end of its section
        defs, used = _line_defs_uses(section.title)
        known.update(defs)
        _walk([(section.title, step) for step in section.steps], known, need)
        need(used, f"heading: {section.title}")
    _walk([("Check", step) for step in solution.checks], known, need)
    # the answers' symbols, last: F with labels A, B is defined by F_A and F_B
    for answer in solution.answers.values():
        if asked is not None and answer.name not in asked or not answer.si_values:
            continue  # not in the sheet
        tree = try_parse(answer.symbol, units=False)
        if tree is None:
            continue  # a word: stability, motion
        names = [n for n in uses(tree) if n not in known and not _derived(n, known)]
        if names and answer.labels and all(_labelled(n, label) in known for n in names
                                           for label in answer.labels):
            continue
        need(names, f"Answer: {answer.name} {answer.symbol}")
    for warning in solution.warnings:  # printed after the answers
        defs, used = _line_defs_uses(warning)
        known.update(defs)
        need(used, f"Warning: {warning}")
    return missing


def _labelled(name: str, label: str) -> str:
    """F, A -> F_A; F_arm, A -> F_A,arm (the steps' names of one labelled value)."""
    base, _, sub = name.partition("_")
    label = label.replace(" ", ",")  # "front outer": P_front,outer
    return f"{base}_{label},{sub}" if sub else f"{base}_{label}"


def _walk(lines, known: set[str], need) -> None:
    for title, step in lines:
        if step.symbol:
            where = f"{title}: {step.as_text()}"
            note_defs, note_uses = _line_defs_uses(step.text) if step.text else ([], [])
            defs = _step_symbols(step.symbol)
            known.update(note_defs)
            for part in (step.formula, step.substitution):
                tree = try_parse(part, units=part is step.substitution) if part else None
                if tree is not None:
                    need(uses(tree), where)
                elif part:  # set piece by piece: the maths in it
                    need(_line_defs_uses(part)[1], where)
            known.update(defs)
            need(note_uses, where)
        else:
            defs, used = _line_defs_uses(step.text)
            known.update(defs)
            need(used, f"{title}: {step.text}")


def _derived(name: str, known: set[str]) -> bool:
    """d of a known symbol (``dH``, ``dtheta``) and its rates (``thetadot``, ``alphaddot``)
    are notation, not new symbols."""
    dot = dotted(name.split("_")[0].rstrip("0123456789"))
    return name.startswith("d") and name[1:] in known or dot is not None and dot[0] in known


#: branches no bundled problem reaches (each once had a gap the walk found)
BRANCHES = {
    "steady precession from an axial rate, the spin at each root": """
        kind: steady_precession
        given: {weight: 3 oz, k_axial: 0.84 in, k_pivot: 1.8 in, cg_distance: 1.5 in,
                theta: 30 deg, axial_rate: 1800 rpm}
        find: {spin_slow: rpm, spin_fast: rpm, pivot_force: N, precession_period: s}""",
    "steady precession of a torque-free body": """
        kind: steady_precession
        given: {J: 0.02 kg m^2, I_pivot: 0.01 kg m^2, cg_distance: 0 m, spin: 100 rad/s,
                theta: 30 deg}
        find: {precession: rad/s}""",
    "steady precession under an applied moment": """
        kind: steady_precession
        given: {J: 0.02 kg m^2, I_pivot: 0.03 kg m^2, moment: 1.7 N m, spin: 80 rad/s,
                theta: 60 deg}
        find: {precession: rad/s}""",
    "gyroscopic torque: the precession an applied moment sustains": """
        kind: gyroscopic_torque
        given: {mass: 5 kg, shape: disk, diameter: 300 mm, spin: 300 rpm, moment: 29.43 N*m}
        find: {precession: rad/s}""",
    "gyroscopic torque: spin axis along the precession axis": """
        kind: gyroscopic_torque
        given: {mass: 2 kg, J: 0.01 kg*m^2, spin: 100 rad/s, precession: 1 rad/s, theta: 0 deg}
        find: {moment: N*m}""",
    "released top: a sleeping top too slow to stay up": """
        kind: released_top
        given: {weight: 3 oz, k_axial: 0.84 in, k_pivot: 1.8 in, cg_distance: 1.5 in,
                theta0: 0 deg, spin: 600 rpm}
        find: {motion: null}""",
}


def _solutions():
    for path in PROBLEMS:
        yield path.name, path
    for name in kinds.names():
        yield f"gyro new {name}", name
    for label, text in BRANCHES.items():
        yield label, "id: branch" + textwrap.dedent(text)


CASES = list(_solutions())


def _path(source, tmp_path) -> Path:
    """A bundled problem, a `gyro new` example (by kind) or a problem's text, as a file."""
    if isinstance(source, Path):
        return source
    path = tmp_path / "problem.yaml"
    path.write_text(source if "\n" in source else template(source))
    return path


@pytest.mark.parametrize("label, source", CASES, ids=[c[0] for c in CASES])
def test_every_symbol_is_defined_where_first_used(label, source, tmp_path):
    path = _path(source, tmp_path)
    result = solve_file(str(path))
    KEYS[0] = file_keys(result.problem.kind)
    try:
        missing = undefined(result.solution, set(result.answers))
    finally:
        KEYS[0] = None
    assert missing == [], "\n".join(f"{name!r} in {where}" for name, where in missing)


def test_the_walk_finds_what_the_issue_reported():
    """Worked answers written by hand: 11/3's old check used D before any step defined it,
    11/5 wrote a = AG with AG never said; defining them (a step, a line of prose naming the
    symbol) makes the walk pass."""
    from gyro_cli.core.work import GivenLine, Work

    def solution(*lines, given=("m", "g", "l", "theta")):
        work = Work()
        work.given += [GivenLine(s, s, "1", 1.0, "") for s in given]
        for kind, *args in lines:
            if kind == "value":  # a step that shows its value only
                symbol, value, unit, note = args
                work.step(symbol, value=value, unit=unit, note=note)
            else:
                getattr(work, kind)(*args)
        return work.solution()

    from gyro_cli.core.expr import sin
    from gyro_cli.core.prose import names, q, rel

    m, g, l, theta, D, AG, L, a, G = names("m g l theta D AG L a G")
    bad = solution(("step", "M", m * g * l * sin(theta)),
                   ("check", "applied ", rel(D * sin(theta), "=", q(1.0, "N m"))))
    assert [name for name, _ in undefined(bad)] == ["D"]
    assert undefined(solution(("step", "D", m * g * l),
                              ("check", "applied ", rel(D * sin(theta), "=", 1)))) == []
    assert [n for n, _ in undefined(solution(("step", "a", AG)))] == ["AG"]
    named = solution(("text", G, ": the centre of mass"),
                     ("value", "a", 0.1, "m", "from bearing A to G"),
                     ("step", "b", L - a), given=("L", "A"))
    assert undefined(named) == []
    # a line may define what it uses; a chain defines each member followed by '='
    assert undefined(solution(("text", "T = 2 pi / Omega, where Omega is the rate"))) == []
    assert undefined(solution(("text", "psidot >= psidot_min = 2 sqrt(m g l) / J"),
                              given=("m", "g", "l", "J", "psidot"))) == []
    # a rate of a known angle is notation; a new letter is not
    assert undefined(solution(("text", "thetadot = 0"))) == []
    assert [n for n, _ in undefined(solution(("text", "x = k theta")))] == ["k"]


#: data the model does not use: the frames' inertia about the lateral axis (Meijaard et al.
#: 2007 need only the wheels' I_Ryy and I_Fyy), and g where gravity plays no part
UNUSED = {("bicycle", "I_Byy"), ("bicycle", "I_Hyy")}


def _all_uses(solution) -> set[str]:
    used: set[str] = set()
    for step in [s for sec in solution.sections for s in sec.steps] + solution.checks:
        for part, units in ((step.formula, False), (step.substitution, True)):
            tree = try_parse(part, units) if part else None
            used.update(uses(tree) if tree is not None else
                        _line_defs_uses(part)[1] if part else [])
        if step.text:
            defs, line = _line_defs_uses(step.text)
            used.update(defs + line)
    return used


def _used(symbol: str, used: set[str]) -> bool:
    """A symbol of the table is used; one written as an expression (C/(M R^2)) is used when
    all its symbols are."""
    tree = try_parse(symbol, units=False)
    return symbol in used or tree is not None and not isinstance(tree, Sym) \
        and set(uses(tree)) <= used


SHEETS = [c for c in CASES if c[0] not in BRANCHES]  # a branch may leave data unused


@pytest.mark.parametrize("label, source", SHEETS, ids=[c[0] for c in SHEETS])
def test_steps_use_the_given_tables_symbols(label, source, tmp_path):
    """A datum of the Given table is worked with under the table's symbol: a step that
    wrote the same quantity under another name (spin for psidot, eps for epsilon, drift
    for the budget) leaves the table's symbol unused."""
    path = _path(source, tmp_path)
    result = solve_file(str(path))
    used = _all_uses(result.solution)
    kind = result.problem.kind.name
    unused = [g.symbol for g in result.solution.given
              if not isinstance(g.si_value, str) and not _used(g.symbol, used)
              and (kind, g.symbol) not in UNUSED and g.symbol != "g"]
    assert unused == []
