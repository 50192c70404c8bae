"""Issue 37: free text set in LaTeX (render/unicode_tex.text_tex) takes a run of plain
ASCII whole and remembers what it set. Both must give, for any text, the LaTeX the
character-by-character reading gives: that reading is the same module with the run
switched off and nothing remembered."""

from __future__ import annotations

import re

import pytest
from conftest import examples
from hypothesis import given, settings
from hypothesis import strategies as st

from gyro_cli.render import unicode_tex

# What decides a reading: letters before "_" or a combining accent, the characters LaTeX
# must escape, Greek, sub- and superscripts, roots, control characters, accented letters.
ALPHABET = ("abIGxz019 .,()-+=/*:'\"" "_^\\{}$&#%~|<>" "θψωΔμ" "₀₁²³⁻" "√" "\u0307\u0301\u0308"
            "é°×·–\n\t\x07ß€")


def _one_by_one(text: str) -> str:
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(unicode_tex, "_PLAIN", re.compile(r"(?!)"))  # never matches
        patch.setattr(unicode_tex, "text_tex", unicode_tex.text_tex.__wrapped__)
        return unicode_tex.text_tex(text)


@settings(max_examples=examples(400), deadline=None)
@given(st.text(alphabet=ALPHABET, max_size=40))
def test_item02_plain_runs_set_as_one_by_one(text):
    assert unicode_tex.text_tex(text) == _one_by_one(text)


def test_item02_the_cases_where_a_run_must_stop_before_its_last_letter():
    cases = {"torque I_G about G": r"torque I$_{G}$ about G",
             "Poincare\u0301 spin": r"Poincar\'{e} spin",
             "q\u0307 and x_θ": r"\.{q} and x$_{\theta}$",
             "m r² over √(I m g l)": r"m r$^{2}$ over $\sqrt{\text{I m g l}}$",
             "10⁻³ kg, 50% of {a}": r"10$^{-3}$ kg, 50\% of \{a\}"}
    for text, tex in cases.items():
        assert unicode_tex.text_tex(text) == tex == _one_by_one(text), text
