"""`make test` and `make test-slow` split the suite between them, and CI runs both: a test
marked slow (it waits on Chromium, a build, a hook's environment or a process it signals)
leaves the developer's `make test` but never CI."""

from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def _recipe(target: str) -> str:
    makefile = (ROOT / "Makefile").read_text()
    found = re.search(rf"^{re.escape(target)}:[^\n]*\n((?:\t[^\n]*\n|#[^\n]*\n)+)", makefile, re.M)
    assert found, target
    return found.group(1)


def test_make_test_leaves_out_the_slow_tests_and_test_slow_runs_only_them():
    test, slow = _recipe("test"), _recipe("test-slow")
    assert test.count('pytest -q -n auto') == 1 and '-m "not slow"' in test
    assert re.search(r"pytest -q -n auto [^\n]*-m slow\b", slow)
    # each reruns its own failed tests, not the other's
    assert '-m "not slow" --last-failed' in test and "-m slow --last-failed" in slow


def test_ci_runs_make_test_then_make_test_slow():
    steps = [line.split("#")[0].strip() for line in (ROOT / ".ci" / "run").read_text().splitlines()]
    assert "make test" in steps and "make test-slow" in steps
    assert steps.index("make test") < steps.index("make test-slow")
    assert "set -euo pipefail" in steps  # a failing make test-slow fails CI


def test_the_slow_marker_is_registered_and_marks_every_page_in_chromium(pytestconfig):
    markers = pytestconfig.getini("markers")
    assert any(m.startswith("slow:") and "make test-slow" in m for m in markers), markers
    for name in ("test_browser.py", "test_course_browser.py"):  # the whole module
        assert re.search(r"^pytestmark = \[pytest\.mark\.slow,",
                         (ROOT / "tests" / name).read_text(), re.M), name
