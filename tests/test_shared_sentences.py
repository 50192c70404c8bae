"""The sentences that hold no values are module constants of their kinds, one tree shared by
every solve (so that `gyro check` does not build them again for each file): a worked answer
must not depend on what was solved before it in the same process.

Each kind's bundled problems are solved, then all of them again in other units and in the
other order, then the first ones again: every format prints the same text both times.
"""

from __future__ import annotations

import re

import pytest

from gyro_cli import kinds

KINDS = kinds.names()
FORMATS = ("text", "latex", "markdown", "json")


def _files(problems_dir, kind: str) -> list:
    return [path for path in sorted(problems_dir.glob("*.yaml"))
            if re.search(rf"^kind: {kind}\s*$", path.read_text(), re.M)]


def _answers(run, files: list, *options: str) -> list[str]:
    outputs = []
    for path in files:
        for form in FORMATS:
            result = run("solve", "--format", form, *options, path)
            assert result.exit_code == 0, result.output
            outputs.append(result.output)
    return outputs


@pytest.mark.parametrize("kind", KINDS)
def test_worked_answer_is_the_same_whatever_was_solved_before(kind, run, problems_dir):
    files = _files(problems_dir, kind)
    assert files, f"no bundled problem of kind {kind}"
    first = _answers(run, files)
    _answers(run, files[::-1], "--units", "us")  # other values through the same sentences
    assert _answers(run, files) == first
