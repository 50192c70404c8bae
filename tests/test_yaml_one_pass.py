"""The one-pass build of a problem file (safeyaml._plain_data) gives what PyYAML's safe
constructor with gyro's rules gives, or leaves the document to it."""

from __future__ import annotations

import glob
import math

import pytest

from gyro_cli.core import safeyaml

TEXTS = [
    "a: 1\nb: [1, 2.5, .inf, -.inf, yes, no, ~, 0x1f, 0o17, 1_000, 1:30, 2024-02-31, '3']\n",
    "11.10: a\n011: b\nyes: c\n~: d\nnull: e\n'12': f\n",
    "a: 1\na: 2\n", "- 1\n- [2, {x: 3}]\n", "just text\n", "{1: a, 1.0: b, true: c}\n",
    "a: !!str 5\nb: !!float 1\nc: !!binary aGVsbG8=\nd: !!timestamp 2020-01-01\n",
    "<<: {a: 1}\nb: 2\n", "=: 1\n", "? [a]\n: 1\n", "a: !!set {x, y}\n", "a: !foo bar\n",
    "a: !!int 0x\n", "a: " + "9" * 5000 + "\n", "x: " + "[" * 70 + "]" * 70 + "\n",
]


def _same(a, b) -> bool:
    if isinstance(a, float) and isinstance(b, float) and math.isnan(a):
        return math.isnan(b)
    if type(a) is not type(b):
        return False
    if isinstance(a, dict):
        return list(a) == list(b) and all(_same(a[k], b[k]) for k in a)
    if isinstance(a, list):
        return len(a) == len(b) and all(_same(x, y) for x, y in zip(a, b))
    return a == b


@pytest.mark.parametrize("text", TEXTS + [open(f).read() for f in sorted(glob.glob("problems/*.yaml"))])
def test_one_pass_builds_what_pyyaml_builds(text: str) -> None:
    loader = safeyaml.loader_class()(text)
    node = loader.get_single_node()
    fast = safeyaml._plain_data(loader, node)
    try:
        usual = loader.construct_document(node)
    except Exception:  # noqa: BLE001
        assert fast is safeyaml._UNUSUAL  # refused: left to PyYAML, which says why
        return
    finally:
        loader.dispose()
    assert fast is safeyaml._UNUSUAL or _same(fast, usual)


def test_problem_files_take_the_one_pass() -> None:
    for path in sorted(glob.glob("problems/*.yaml")):
        loader = safeyaml.loader_class()(open(path).read())
        assert safeyaml._plain_data(loader, loader.get_single_node()) is not safeyaml._UNUSUAL
        loader.dispose()
