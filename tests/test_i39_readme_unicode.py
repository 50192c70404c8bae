"""Issue 39: the README as a newcomer's page (item 1) and notes that typeset (item 5).

Item 1: the README is short, shows its first example early, and every gyro command it
shows runs; its worked example is what gyro prints (up to the lines it marks "...").
Item 5: the bundled problems' own words (title, source, notes, statement) hold their
maths in Unicode, LaTeX typesets it, and the other printers keep it.
"""

from __future__ import annotations

import functools
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
import yaml

from gyro_cli.render.mathprint import text_escape

ROOT = Path(__file__).resolve().parent.parent
README = (ROOT / "README.md").read_text(encoding="utf-8")
PROBLEMS = sorted((ROOT / "problems").glob("*.yaml"))
FREE_TEXT = ("title", "source", "notes", "statement")

# ASCII maths a reader should never see: dotted names, a digit glued to a Greek name, a
# root, a caret, a Greek letter spelled out (alone or with a short subscript), 1.5e-3
ASCII_MATHS = re.compile(
    r"psidot|phidot|thetadot|theta0|sqrt|\^|"
    r"\b(?:theta|phi|psi|omega|Omega|gamma|beta|alpha|delta|pi)(?:_[A-Za-z0-9]{1,3})?\b|"
    r"\d[eE][-+]?\d")


@functools.cache  # two tests read every problem's words
def _free_text(path: Path) -> list[tuple[str, str]]:
    """(field, text) of a problem's own words, without what is not prose: key names in
    backticks, {placeholders} of a statement and web addresses."""
    data = yaml.load(path.read_text(encoding="utf-8"),
                     Loader=getattr(yaml, "CSafeLoader", yaml.SafeLoader))
    out = []
    for field in FREE_TEXT:
        value = data.get(field)
        for text in value if isinstance(value, list) else [value] if value else []:
            out.append((field, re.sub(r"`[^`]*`|\{\w+\}|https?://\S+", "", str(text))))
    return out


# ---- item 1: the README as a newcomer's page ------------------------------------------

def _blocks(language: str) -> list[tuple[int, str]]:
    """(line of the opening fence, body) of each fenced block in that language."""
    return [(README[:m.start()].count("\n") + 1, m.group(1))
            for m in re.finditer(rf"^```{language}\n(.*?)^```", README, re.DOTALL | re.MULTILINE)]


@pytest.fixture(scope="module")
def copy(tmp_path_factory) -> Path:
    """A copy of the files the README's commands read, and `gyro` on the PATH."""
    folder = tmp_path_factory.mktemp("readme")
    shutil.copytree(ROOT / "problems", folder / "problems")
    shutil.copytree(ROOT / "docs" / "examples", folder / "docs" / "examples")
    bin_dir = folder / "bin"
    bin_dir.mkdir()
    gyro = bin_dir / "gyro"
    gyro.write_text(f'#!/bin/sh\nexec "{sys.executable}" -m gyro_cli "$@"\n')
    gyro.chmod(0o755)
    return folder


def _env(copy: Path) -> dict[str, str]:
    return {**os.environ, "PATH": f"{copy / 'bin'}{os.pathsep}{os.environ['PATH']}",
            "PYTHONPATH": str(ROOT)}


def test_item01_readme_is_short_and_shows_its_example_early():
    assert README.count("\n") <= 120
    (line, problem), = [(n, body) for n, body in _blocks("yaml")]
    assert line <= 40 and "kind: steady_precession" in problem
    setup = _blocks("sh")[0][1]
    assert [c.split("#")[0].strip() for c in setup.splitlines()] == ["make demo", "make test"]
    for heading in ("Spellings and words", "The bundled problems", "Exit codes", "Layout",
                    "Performance", "The kinds"):
        assert f"## {heading}" not in README  # the reference sections live in docs/


def test_item01_readme_problem_is_the_bundled_file():
    (_, shown), = _blocks("yaml")
    data = yaml.safe_load((ROOT / "problems" / "11_3.yaml").read_text(encoding="utf-8"))
    for key, value in yaml.safe_load(shown).items():
        assert data[key] == value, key


def test_item01_readme_output_is_what_gyro_prints(run):
    shown = re.search(r"`gyro solve problems/11_3.yaml` prints[^\n]*:\n\n```\n(.*?)```",
                      README, re.DOTALL)
    assert shown, "the README's worked answer is missing"
    printed = run("solve", ROOT / "problems" / "11_3.yaml").stdout.splitlines()
    parts = [part.strip("\n").splitlines() for part in re.split(r"^\.\.\.$", shown.group(1),
                                                                 flags=re.MULTILINE)]
    assert len(parts) > 2 and parts[0] == printed[:len(parts[0])]  # abridged, not rewritten
    assert parts[-1] == printed[-len(parts[-1]):]
    at = len(parts[0])
    for part in parts[1:]:
        found = next(i for i in range(at, len(printed) - len(part) + 1)
                     if printed[i:i + len(part)] == part)  # StopIteration: not printed so
        at = found + len(part)


@pytest.mark.slow  # fresh interpreters: `make test-slow`
def test_item01_every_gyro_command_of_the_readme_runs(copy):
    commands = [line for _, body in _blocks("sh") for line in body.splitlines()
                if line.startswith("gyro ")]
    assert len(commands) >= 5
    assert {c.split()[1] for c in commands} >= {"solve", "check", "vary", "handout", "export"}
    for command in commands:
        done = subprocess.run(["bash", "-c", command], cwd=copy, env=_env(copy),
                              capture_output=True, text=True, timeout=600, check=False)
        assert done.returncode == 0, (command, done.stderr[-2000:])
    assert "\\begin{document}" in (copy / "sheet.tex").read_text(encoding="utf-8")
    assert "ann" in (copy / "grades.csv").read_text(encoding="utf-8")


def test_item01_readme_python_runs(copy):
    (_, code), = _blocks("python")
    done = subprocess.run([sys.executable, "-c", code], cwd=copy, env=_env(copy),
                          capture_output=True, text=True, timeout=600, check=False)
    assert done.returncode == 0, done.stderr[-2000:]
    assert "rpm" in done.stdout


def test_item01_readme_links_are_relative_and_lead_to_pages():
    links = re.findall(r"\]\(([^)#]+)", README)
    assert links and all(not re.match(r"[a-z]+:|/", link) for link in links)
    # docs/ci.md comes with the course-repository integrations of the same issue
    missing = [link for link in links if not (ROOT / link).exists() and link != "docs/ci.md"]
    assert missing == []
    assert "make docs" in README
    assert not re.search(r"(?<![\w.])/(?:work|home|tmp|root|usr)/", README)


# ---- item 5: notes that typeset ------------------------------------------------------

def test_item05_bundled_problems_write_their_maths_in_unicode():
    found = [f"{path.name} {field}: {m.group()!r} in ...{text[max(0, m.start() - 30):m.end() + 10]}"
             for path in PROBLEMS for field, text in _free_text(path)
             for m in ASCII_MATHS.finditer(text)]
    assert found == []


@pytest.mark.parametrize(("text", "tex"), [
    ("ψ̇", r"$\dot{\psi}$"),
    ("θ₀ = 30°", r"$\theta_{0}$ = 30$^{\circ}$"),
    ("ω_z", r"$\omega_{z}$"),
    ("ψ̇_min ≥ 1", r"$\dot{\psi}_{\mathrm{min}}$ $\ge$ 1"),
    ("J² ω_z²", r"J$^{2}$ $\omega_{z}^{2}$"),
    ("2 √(I m g l) / J", r"2 $\sqrt{\text{I m g l}}$ / J"),
    ("√(γ² − 2 a)", r"$\sqrt{\text{$\gamma^{2}$ $-$ 2 a}}$"),
    ("1.5 × 10⁻³ kg m²", r"1.5 $\times$ 10$^{-3}$ kg m$^{2}$"),
    ("I_G = m r² / 4", r"I$_{G}$ = m r$^{2}$ / 4"),
    ("θ̈ + k θ", r"$\ddot{\theta}$ + k $\theta$"),
    ("φ̇ · ψ̇ ≈ Ω", r"$\dot{\phi}$ $\cdot$ $\dot{\psi}$ $\approx$ $\Omega$"),
    ("θθ", r"$\theta\theta$"),  # one run of maths, never "$$" (display maths)
    ("T₀ = ½ J ω²", r"T$_{0}$ = $\tfrac{1}{2}$ J $\omega^{2}$"),
    ("Poincaré", r"Poincar\'{e}"),
    ("a_long_key", r"a\_long\_key"),
])
def test_item05_latex_sets_unicode_maths_as_maths(text, tex):
    assert text_escape(text) == tex


def test_item05_latex_never_opens_display_maths_nor_lets_a_command_through():
    tex = text_escape("θ²ω √θ ≥≤ \\input{x} $ % _ ^ \n\x1b ψ̇φ̇")
    assert "$$" not in tex and len(re.findall(r"(?<!\\)\$", tex)) % 2 == 0
    assert "\\input" not in tex and "\x1b" not in tex and "\n" not in tex
    assert all(escaped in tex for escaped in (r"\$", r"\%", r"\_", r"\textasciicircum{}"))


def test_item05_latex_handout_of_every_bundled_problem_has_no_ascii_maths(run):
    result = run("solve", "--format", "latex", "--standalone", *PROBLEMS)
    assert result.exit_code == 0, result.output
    tex = result.stdout
    assert r"\textasciicircum" not in tex
    words = re.sub(r"\\[A-Za-z]+", " ", tex)  # commands (\sqrt, \dot, \theta) are not read
    assert re.findall(r"psidot|phidot|thetadot|theta0|sqrt|omega_|theta_", words) == []
    for path in PROBLEMS:  # every character of the files' words has a LaTeX form
        for field, text in _free_text(path):
            assert text_escape(text).count("?") == text.count("?"), (path.name, field, text)
            # a symbol's subscript is maths; only a key's underscore stays one (bearing_forces)
            assert not re.search(r"(?<![A-Za-z])[A-Za-z]\\_|\$\\_", text_escape(text)), text


def test_item05_text_html_and_markdown_keep_the_unicode(run):
    top = ROOT / "problems" / "11_3.yaml"
    for form in ("text", "markdown", "html"):
        out = run("solve", "--format", form, top)
        assert out.exit_code == 0 and "ψ̇" in out.stdout and "psidot)" not in out.stdout, form


def test_item05_gyro_new_templates_write_notes_in_unicode(run):
    template = run("new", "steady_precession").stdout
    notes = template.split("\nnotes:", 1)[1].split("\n\n", 1)[0]
    assert "(ψ̇)" in notes and not ASCII_MATHS.search(notes.split("\n", 1)[1])
    note = "Spin is the rate relative to the precessing frame (ψ̇)."
    assert yaml.safe_load(template)["notes"] == [note]
