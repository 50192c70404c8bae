"""The shortcuts of reading a problem file give what the plain way gives.

Loading a file was made cheaper by: a table of quantity texts parsed before
(units._PARSED), per-kind tables in the loader (problem._KindFacts), a statement
checked without being filled in, one walk of the top-level keys for their lines
and the text keys, and a resolver and one-pass build in safeyaml with fewer
Python calls. Each is held here to the way it replaced, on the bundled problems
and on odd input, with the same results and the same refusals.
"""

from __future__ import annotations

import math
import random
from pathlib import Path

import pytest
import yaml

from gyro_cli import kinds
from gyro_cli.core import safeyaml, unit_cache, units
from gyro_cli.core.errors import InputError
from gyro_cli.core.statement import StatementError, fill_statement
from gyro_cli.solving import problem

ROOT = Path(__file__).resolve().parent.parent
PROBLEM_TEXTS = [p.read_text() for p in sorted((ROOT / "problems").glob("*.yaml"))]


# ---- units: quantity texts read before ------------------------------------------

QUANTITIES = [("1800 rpm", "rate", False), ("30 Hz", "rate", False), ("2 kg", "mass", False),
              ("3 oz", "force", True), ("20 lb", "force", False), ("50 lb ft", "moment", False),
              ("150 mm", "length", False), (" 1.5e2  mm ", "length", False),
              ("0.01 kg m^2", "inertia", False), ("36 r.p.m.", "rate", False),
              ("-0.3 1/s", "inverse_time", False), ("30 deg", "angle", False)]


def _parse(text, dimension, weight):
    return units.parse(text, dimension, "given.x", weight=weight)


@pytest.mark.parametrize("text, dimension, weight", QUANTITIES)
def test_a_text_read_again_is_read_as_the_first_time(text, dimension, weight):
    first = _parse(text, dimension, weight)
    again = _parse(text, dimension, weight)              # from the table
    units._PARSED.clear()
    fresh = _parse(text, dimension, weight)              # computed again
    assert again == first == fresh
    assert (text, dimension, weight) in units._PARSED


def test_a_text_read_before_is_not_used_once_its_unit_entry_is_gone(monkeypatch):
    _parse("1800 rpm", "rate", False)
    assert ("1800 rpm", "rate", False) in units._PARSED

    def refuse():
        raise AssertionError("pint asked")

    monkeypatch.setenv("GYRO_CACHE_DIR", "")
    unit_cache.forget()
    monkeypatch.setattr(units, "_CHECKED", {})           # the table replaced, as tests do
    monkeypatch.setattr(units, "registry", refuse)
    try:
        with pytest.raises(AssertionError, match="pint asked"):
            _parse("1800 rpm", "rate", False)
    finally:
        unit_cache.forget()


def test_the_table_of_texts_stays_small():
    for i in range(3 * units._PARSED_MAX):
        _parse(f"{i}.25 kg", "mass", False)
        assert len(units._PARSED) <= units._PARSED_MAX
    assert _parse("7.25 kg", "mass", False)[0] == 7.25


@pytest.mark.parametrize("text", [True, False, None, 3, 0, 2.5, float("nan"), [1], {"a": 1},
                                  b"2 kg", ("2", "kg")])
def test_values_that_are_not_text_meet_the_same_checks_in_the_same_order(text):
    """_split looks at text first now; any other value as before: a boolean or nothing, a
    number (read as a bare number), anything else refused."""
    if isinstance(text, bool) or text is None:
        expected = f"given.x: expected a quantity, got {text!r}"
    elif isinstance(text, (int, float)):
        expected = (float(text), "")
    else:
        expected = f"given.x: expected a quantity string such as '150 mm', got a " \
                   f"{type(text).__name__}"
    try:
        got = units._split(text, "given.x", ("mass", False))
    except InputError as err:
        got = str(err)
    if isinstance(expected, tuple) and math.isnan(expected[0]):
        assert math.isnan(got[0]) and got[1] == ""
    else:
        assert got == expected


# ---- problem: per-kind tables ---------------------------------------------------

SAMPLES = [-1e9, -1.0, -1e-9, 0.0, 1e-9, 0.5, 1.0, 1.5, math.pi / 2, 3.0, math.pi, 7.0,
           1e9, float("nan")]


@pytest.mark.parametrize("name", kinds.names())
def test_a_kinds_table_holds_what_the_kind_declares(name):
    kind = kinds.get(name)
    facts = problem._facts(kind)
    assert facts is problem._facts(kind)                 # made once
    assert facts.params == {p.name: p for p in problem.params_of(kind)}
    assert facts.defaults == tuple(p for p in kind.params if p.default is not None)
    for answer in [a.name for a in kind.answers] + ["nothing", "steps"]:  # Kind.answer's table
        assert kind.answer(answer) is next((a for a in kind.answers if a.name == answer), None)
    for param_name, (param, key, weight, limits) in facts.reading.items():
        assert param is facts.params[param_name]
        assert key == f"given.{param_name}" and weight == (param_name == "weight")
        for value in SAMPLES + [x for _, x in param.limits_declared()]:
            broken = any(not test(value, x) for test, x in limits)
            assert broken == bool(param.limits_broken(value)), (param_name, value)


# ---- problem: the statement checked without filling it in -------------------------

GIVEN = {"mass": "2 kg", "spin": "1800 rpm", "theta": "30 deg"}
PIECES = ["{", "}", "{{", "}}", "{mass}", "{ spin }", "{nope}", "{}", "{1x}", "{ma ss}",
          " text ", "a", "\n", "{theta}"]


def _plain_statement(text):
    try:
        fill_statement(text, GIVEN)
    except StatementError as err:
        return str(err)
    return text.strip()


def test_a_statement_is_refused_or_kept_as_filling_it_would():
    rng = random.Random(7)
    texts = ["{mass} at {spin}", "{{mass}}", "{mass}}", "{{mass}", "}{", "{mass}{theta}",
             "{ mass}", "no braces at all"]
    texts += ["".join(rng.choice(PIECES) for _ in range(rng.randint(1, 8))) for _ in range(3000)]
    for text in texts:
        if not text.strip():
            continue
        try:
            got = problem._statement(text, GIVEN)
        except InputError as err:
            assert err.key == "statement"
            got = err.message
        assert got == _plain_statement(text), text


# ---- problem: one walk for the key lines and the text keys ------------------------

def _old_keep_written_text(data, node):
    if not isinstance(data, dict) or not isinstance(node, yaml.MappingNode):
        return
    for key_node, value_node in node.value:
        name = key_node.value
        if name not in problem.TEXT_KEYS or name not in data:
            continue
        if isinstance(value_node, yaml.ScalarNode):
            data[name] = problem._written(data[name], value_node)
        elif isinstance(value_node, yaml.SequenceNode) and isinstance(data[name], list) and \
                len(value_node.value) == len(data[name]):
            data[name] = [problem._written(v, n) if isinstance(n, yaml.ScalarNode) else v
                          for v, n in zip(data[name], value_node.value)]


def _old_key_lines(node):
    lines = {}
    if not isinstance(node, yaml.MappingNode):
        return lines
    for key, value in node.value:
        name = str(key.value)
        problem._once(lines, name, key)
        if isinstance(value, yaml.MappingNode):
            for sub_key, sub_value in value.value:
                problem._once(lines, f"{name}.{sub_key.value}", sub_key)
                if isinstance(sub_value, yaml.SequenceNode):
                    for i, item in enumerate(sub_value.value):
                        where = f"{name}.{sub_key.value}[{i}]"
                        lines[where] = item.start_mark.line + 1
                        if isinstance(item, yaml.MappingNode):
                            for item_key, _ in item.value:
                                problem._once(lines, f"{where}.{item_key.value}", item_key)
    return lines


def _outcome(walk, text):
    data, node = safeyaml.load(text)
    try:
        lines = walk(data, node)
    except InputError as err:
        return ("refused", err.message, err.key, err.line)
    return (lines, repr(data))


ODD_DOCUMENTS = [
    "id: 11.10\ntitle: yes\nsource: 012\nnotes: [12:30, 1.50, text, [a], ~]\n",
    "id: a\nid: b\n", "given: {a: 1, a: 2}\n", "given.mass: 1\ngiven: {mass: 2}\n",
    "given: {x.y: 1}\ngiven.x: {y: 2}\n", "title: {a: 1, a: 2}\n", "notes: {x: 1}\n",
    "given:\n  parts:\n    - {mass: 1, x: 2}\n    - {mass: 1, mass: 3}\n",
    "given:\n  parts[0]: 1\n  parts:\n    - {mass: 1}\n", "- 1\n- 2\n", "text\n", "",
    "? [a]\n: 1\n", "id: !!float 1.10\ntitle: !!int 011\n", "notes: 3.0\n",
    "base: &b {mass: 2 kg}\ngiven:\n  <<: *b\n  mass: 3 kg\n",
]


@pytest.mark.parametrize("text", PROBLEM_TEXTS + ODD_DOCUMENTS)
def test_one_walk_finds_what_the_two_walks_found(text):
    def old(data, node):
        _old_keep_written_text(data, node)
        return _old_key_lines(node)

    def new(data, node):
        return problem._key_lines(node, data)

    try:
        expected = _outcome(old, text)
    except (yaml.YAMLError, InputError):
        return  # refused by the YAML reader, before either walk
    assert _outcome(new, text) == expected


# ---- safeyaml: the resolver and the one-pass build ---------------------------------

def _plain_loader():
    """loader_class's loader with PyYAML's own resolve and resolver hooks."""
    from yaml.resolver import BaseResolver

    class Plain(safeyaml.loader_class()):
        pass

    Plain.descend_resolver = BaseResolver.descend_resolver
    Plain.ascend_resolver = BaseResolver.ascend_resolver
    Plain.resolve = lambda self, kind, value, implicit: BaseResolver.resolve(
        self, kind, value, implicit)
    return Plain


def _tree(node):
    if node is None:
        return None
    marks = (node.start_mark.line, node.start_mark.column, node.end_mark.line,
             node.end_mark.column)
    if isinstance(node, yaml.ScalarNode):
        return ("scalar", node.tag, node.value, node.style, marks)
    if isinstance(node, yaml.SequenceNode):
        return ("seq", node.tag, node.flow_style, marks, [_tree(n) for n in node.value])
    return ("map", node.tag, node.flow_style, marks,
            [(_tree(k), _tree(v)) for k, v in node.value])


COMPOSED = ["a: 'q'\nb: \"d\"\nc: |\n  lit\nd: >\n  fold\ne: !!str 5\nf: !custom x\n",
            "[1, 'a', {b: ~}, !!set {x}, !!omap [a: 1]]\n", "? complex\n: 1\n", "x\n", ""]


@pytest.mark.parametrize("text", PROBLEM_TEXTS + COMPOSED)
def test_nodes_are_composed_with_the_tags_pyyaml_gives(text):
    def compose(cls):
        loader = cls(text)
        try:
            return _tree(loader.get_single_node())
        finally:
            loader.dispose()

    assert compose(safeyaml.loader_class()) == compose(_plain_loader())


def _left_to_pyyaml(text: str) -> tuple[bool, bool]:
    """(the one-pass build left the document to PyYAML, _check_tree refuses it)."""
    loader = safeyaml.loader_class()(text)
    try:
        node = loader.get_single_node()
        unusual = safeyaml._plain_data(loader, node) is safeyaml._UNUSUAL
        try:
            safeyaml._check_tree(node)
            refused = False
        except InputError:
            refused = True
    finally:
        loader.dispose()
    return unusual, refused


@pytest.mark.parametrize("nesting", range(safeyaml.MAX_DEPTH - 2, safeyaml.MAX_DEPTH + 2))
def test_the_one_pass_build_keeps_the_depth_limit(nesting):
    unusual, refused = _left_to_pyyaml("x: " + "[" * nesting + "1" + "]" * nesting + "\n")
    assert unusual == refused == (nesting + 1 > safeyaml.MAX_DEPTH)


@pytest.mark.parametrize("extra", [-1, 0, 1])
def test_the_one_pass_build_keeps_the_node_limit(extra, monkeypatch):
    # The limit lowered: both counts read it where they compare, and documents of 100,000
    # values took seconds to build for the same comparisons one past and one short of it.
    monkeypatch.setattr(safeyaml, "MAX_NODES", 1_000)
    items = safeyaml.MAX_NODES - 3 + extra   # + the root mapping, its key and the list
    unusual, refused = _left_to_pyyaml("x: [" + ", ".join(["1"] * items) + "]\n")
    assert unusual == refused == (extra > 0)
    pairs = (safeyaml.MAX_NODES - 1) // 2 + extra    # + the root mapping
    unusual, refused = _left_to_pyyaml("".join(f"k{i}: {i}\n" for i in range(pairs)))
    assert unusual == refused == (1 + 2 * pairs > safeyaml.MAX_NODES)
