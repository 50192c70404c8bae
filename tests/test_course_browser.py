"""A student's handout page (`gyro handout -o X.html`) in headless Chromium: axe-core
(WCAG 2.1 AA), no horizontal overflow at 360 px, no console error, in both colour
schemes: the checks of test_browser.py, on the handout with solutions."""

from __future__ import annotations

from pathlib import Path

import pytest
from test_browser import MISSING, _inspect, shots  # noqa: F401 (a fixture)
from test_check import put

ROOT = Path(__file__).resolve().parent.parent

pytestmark = [pytest.mark.slow,  # `make test-slow`
              pytest.mark.skipif(MISSING is not None, reason=MISSING or "")]


def test_handout_page_with_solutions_in_chromium(run, browser, axe, shots, tmp_path):  # noqa: F811
    roster = put(tmp_path, "r.csv", "student,name\nann,Ann <i>Lee</i> & co\n")
    out = tmp_path / "hw.html"
    result = run("handout", ROOT / "problems" / "11_3.yaml", ROOT / "problems" / "11_5.yaml",
                 "--roster", roster, "--solutions", "--course", "ME 301", "-o", out)
    assert result.exit_code == 0, result.output
    assert _inspect(browser, axe, tmp_path / "hw-ann.html", shots) == []
