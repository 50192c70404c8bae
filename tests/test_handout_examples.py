"""Solution sheets of the `gyro new KIND` examples, and the file's keys written as words.

The bundled problems are compiled in test_handout.py; a new user starts from the
examples `gyro new` writes, so those sheets compile clean too: zero Overfull
hbox, no raw identifiers in the text pdftotext extracts. A key of the file named
in prose (``bearing_forces``, ``engine_sense``, ``psi_rate``) is written as words
in Markdown and LaTeX, never with a raw underscore.
"""

from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

import pytest
from test_handout import RAW, without_authors_words

from gyro_cli import kinds
from gyro_cli.commands.authoring import template

ROOT = Path(__file__).resolve().parent.parent
PROBLEMS = sorted((ROOT / "problems").glob("*.yaml"))


@pytest.fixture
def examples(tmp_path) -> list[Path]:
    paths = []
    for name in kinds.names():
        path = tmp_path / f"new_{name}.yaml"
        path.write_text(template(name))
        paths.append(path)
    return paths


@pytest.mark.skipif(shutil.which("pdflatex") is None or shutil.which("pdftotext") is None,
                    reason="pdflatex/pdftotext not installed (see `make handout`)")
def test_every_gyro_new_example_compiles_clean(run, tmp_path, examples):
    """The examples compile clean, and what gyro writes holds no raw identifier (the
    template's notes are the author's words, printed as written)."""
    result = run("solve", "--format", "latex", "--standalone",
                 *without_authors_words(examples, tmp_path))
    assert result.exit_code == 0, result.output
    assert result.stdout.count("\\section{") == len(kinds.names())
    (tmp_path / "examples.tex").write_text(result.stdout)
    done = subprocess.run(["pdflatex", "-interaction=nonstopmode", "-halt-on-error",
                           "examples.tex"], cwd=tmp_path, capture_output=True, text=True,
                          timeout=300)
    assert done.returncode == 0, done.stdout[-3000:]
    log = (tmp_path / "examples.log").read_text(errors="replace")
    assert re.findall(r"Overfull \\hbox.*", log) == []
    subprocess.run(["pdftotext", "examples.pdf", "examples.txt"], cwd=tmp_path, check=True)
    assert RAW.findall((tmp_path / "examples.txt").read_text(errors="replace")) == []


def _raw_underscores(tex: str) -> list[str]:
    """Escaped underscores in the text of a LaTeX write-up, outside web addresses."""
    tex = re.sub(r"https?:\S+", "", tex)
    return re.findall(r"\S*\\_\S*", tex)


def test_no_raw_underscore_in_any_sheet(run, examples, tmp_path):
    """No escaped underscore in what gyro writes (a file's notes are its author's words)."""
    for path in without_authors_words(PROBLEMS + examples, tmp_path):
        for fmt in ("latex", "markdown"):
            out = run("solve", "--format", fmt, path).stdout
            if fmt == "markdown":  # the source line is the file's text, escaped as it is
                out = "\n".join(line for line in out.splitlines()
                                 if not line.startswith("*Kind:"))
            assert _raw_underscores(out) == [], (path.name, fmt)


def test_file_keys_in_prose_are_words(run, problems_dir, examples):
    """11/5's note names the answer bearing_forces; the two-wheeler's conventions name the
    key engine_sense: both come out as words. A key that is also a symbol of its kind
    (theta_max of the released top) stays a symbol."""
    tex = run("solve", "--format", "latex", problems_dir / "11_5.yaml").stdout
    assert "bearing forces are the vertical forces" in tex
    md = run("solve", "--format", "markdown", problems_dir / "two_wheeler_250kg.yaml").stdout
    assert "(engine sense: same)" in md
    tex = run("solve", "--format", "latex", problems_dir / "11_2_released_top.yaml").stdout
    assert r"\theta_{\mathrm{max}}" in tex
