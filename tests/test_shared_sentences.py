"""The sentences that hold no values are module constants of their kinds, one tree shared by
every solve (so that `gyro check` does not build them again for each file): a worked answer
must not depend on what was solved before it in the same process.

Each kind's bundled problems are solved, then all of them again in other units and in the
other order, then the first ones again: every format prints the same text both times.
"""

from __future__ import annotations

import re

import pytest

from gyro_cli import api, kinds

KINDS = kinds.names()
FORMATS = ("text", "latex", "markdown", "json")


def _files(problems_dir, kind: str) -> list:
    return [path for path in sorted(problems_dir.glob("*.yaml"))
            if re.search(rf"^kind: {kind}\s*$", path.read_text(), re.M)]


def _answers(files: list, units: str | None = None) -> list[str]:
    """Each file solved once and its worked answer in each format, as `gyro solve --format
    F` prints it (the command's formats are the API's registry: test_i36_printers)."""
    outputs = []
    for path in files:
        result = api.solve_file(str(path), units=units)
        outputs += [result.render(form) for form in FORMATS]
    return outputs


@pytest.mark.parametrize("kind", KINDS)
def test_worked_answer_is_the_same_whatever_was_solved_before(kind, problems_dir,
                                                              monkeypatch):
    # The JSON's graph is numbers found by solving again with each step nudged (no
    # sentence of its own; tests/test_i38_ecf.py tests it): left out here, where it was
    # half the test's time.
    from gyro_cli.render import report

    monkeypatch.setattr(report, "graph_data", lambda result: {})
    files = _files(problems_dir, kind)
    assert files, f"no bundled problem of kind {kind}"
    first = _answers(files)
    _answers(files[::-1], "us")  # other values through the same sentences
    assert _answers(files) == first
