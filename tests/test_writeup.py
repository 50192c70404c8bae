"""Write-ups: `gyro solve --format markdown|latex`.

No LaTeX engine is installed here, so the LaTeX is checked structurally: braces,
$...$ and \\[...\\] balanced, every environment closed, and every control
sequence one that LaTeX2e or amsmath defines (a list written out below). When
pdflatex is on PATH the fragment is also compiled. Independent references: the
transliterations are written by hand; the numbers are the hand-worked answer of
the horizontal gyroscope (phidot = m g l / (J psidot)), printed to 4 figures here.
"""

from __future__ import annotations

import json
import re
import shutil
import subprocess
from pathlib import Path

import pytest
from formula_oracle import latex_math, latex_mixed
from test_check import GYRO_PRECESSION, gyro_file, put

from gyro_cli.render import writeup

# LaTeX2e + amsmath control sequences a fragment may use.
ALLOWED = {
    "dot", "ddot", "phi", "psi", "theta", "omega", "gamma", "beta", "alpha", "delta", "pi",
    "mu", "rho", "sigma", "tau", "lambda", "Omega", "Delta", "Phi", "Psi", "Theta", "Gamma",
    "Pi", "Lambda", "Xi", "Sigma", "zeta", "eta", "epsilon", "kappa", "nu", "xi", "chi", "iota",
    "sin", "cos", "tan", "exp", "ln", "log", "sqrt", "mathrm", "text", "textit", "textbf",
    "times", "cdot", "ge", "le", "pm", "ne", "sim", "circ", "qquad", "quad", "hline", "item",
    "begin", "end", "subsection", "paragraph", "textasciicircum", "textasciitilde",
    "textbackslash", "backslash", "hat", ",", " ", "{", "}", "$", "&", "#", "%", "_", "\\",
    "[", "]", "approx", "to",
    # the printers of render/mathprint.py
    "frac", "left", "right", "Bigl", "Bigr", "lvert", "rvert", "mid", "tag", "gg", "ll", "mp",
    "arccos", "arcsin", "arctan", "det", "operatorname", "sum", "int", "linewidth",
    "textbar", "textless", "textgreater", "allowbreak", "cosh", "sinh", "tanh", "cot", "sec",
    "csc", "max", "min", "section", "subsubsection", "maketitle", "date", "title", "documentclass", "usepackage",
    "setlength", "parindent", "longtable", "parskip", "emergencystretch", "allowdisplaybreaks",
}


def latex_problems(tex: str) -> list[str]:
    """Structural faults of a LaTeX fragment (empty when it is sound)."""
    faults = []
    body = re.sub(r"(?m)(?<!\\)%.*$", "", tex)  # comments
    depth = 0
    for i, c in enumerate(body):
        if c in "{}" and (i == 0 or body[i - 1] != "\\" or body[i - 2:i] == "\\\\"):
            depth += 1 if c == "{" else -1
            if depth < 0:
                faults.append(f"unbalanced }} at {i}")
                depth = 0
    if depth:
        faults.append(f"{depth} unclosed {{")
    if body.count("\\[") != body.count("\\]"):
        faults.append("unbalanced \\[ \\]")
    dollars = len(re.findall(r"(?<!\\)\$", body))
    if dollars % 2:
        faults.append("odd number of $")
    begins = re.findall(r"\\begin\{(\w+)\}", body)
    ends = re.findall(r"\\end\{(\w+)\}", body)
    if begins != ends[::-1] and sorted(begins) != sorted(ends):
        faults.append(f"environments {begins} closed by {ends}")
    outside = sorted({c for c in body if ord(c) > 127})
    if outside:
        faults.append(f"characters pdflatex may not typeset: {''.join(outside)}")
    for name in re.findall(r"\\([A-Za-z]+|.)", body):
        if name not in ALLOWED:
            faults.append(f"unknown control sequence \\{name}")
    return faults


@pytest.fixture
def gyro_path(tmp_path: Path) -> Path:
    return put(tmp_path, "g.yaml", gyro_file(extra_find="\n  moment: N m\n  min_spin: rpm"))


def test_formulas_typeset_by_hand():
    assert latex_math("phidot^2", units=False) == r"\dot{\phi}^{2}"
    assert latex_math("thetaddot = 0") == r"\ddot{\theta} = 0"
    assert latex_math("omega_z = psidot + phidot cos(theta)", units=False) == \
        r"\omega_{z} = \dot{\psi} + \dot{\phi} \cos \theta"
    assert latex_math("2 sqrt((I - J) D cos(theta)) / J", units=False) == \
        r"2 \sqrt{(I - J) D \cos \theta}/J"
    assert latex_math("2 sqrt((I - J) D cos(theta)) / J", units=False, display=True) == \
        r"\frac{2 \sqrt{(I - J) D \cos \theta}}{J}"
    assert latex_math("psidot_min") == r"\dot{\psi}_{\mathrm{min}}"
    assert latex_math("3.869e-05 kg m^2") == r"3.869\times 10^{-5}\,\mathrm{kg\,m^{2}}"
    assert latex_math("0.08498 kg (9.815 m/s^2)") == \
        r"0.08498\,\mathrm{kg}\,(9.815\,\mathrm{m/s^{2}})"
    assert latex_math("sin(30.00 deg)") == r"\sin 30.00^{\circ}"
    # "2 m g l" is twice mass times g times l, not two metres
    assert latex_math("a = 2 m g l / I") == "a = 2 m g l/I"
    assert writeup.symbol_tex("I_G") == "I_{G}" and writeup.symbol_tex("k_O") == "k_{O}"


def test_markdown_has_typeset_equations_and_the_numbers(run, gyro_path):
    result = run("solve", "--format", "markdown", gyro_path)
    assert result.exit_code == 0, result.output
    md = result.stdout
    assert md.startswith("## gyro-90: Horizontal gyroscope")
    assert "### Given" in md and "### Answer" in md
    assert "$$" in md and md.count("$$") % 2 == 0
    assert r"\dot{\phi}" in md and r"\dot{\psi}" in md
    # the hand-worked answer, to 4 significant figures, in the unit asked for
    assert f"{GYRO_PRECESSION:.4g}" + r"\,\mathrm{rad/s}" in md
    assert f"{2 * 9.81 * 0.1:.4g}" + r"\,\mathrm{N\,m}" in md
    # the given data substituted: 2 kg, 0.1 m
    assert r"2.000\,\mathrm{kg}" in md and r"0.1000\,\mathrm{m}" in md
    for line in md.splitlines():
        if not line.startswith("$$"):
            assert len(re.findall(r"(?<!\\)\$", line)) % 2 == 0, line


def test_latex_is_balanced_and_uses_only_amsmath(run, gyro_path, problems_dir):
    paths = [gyro_path] + sorted(problems_dir.glob("*.yaml"))
    for path in paths:
        result = run("solve", "--format", "latex", path)
        if result.exit_code == 2:
            continue  # another kind not built yet, or a file another helper is writing
        assert result.exit_code == 0, result.output
        assert latex_problems(result.stdout) == [], path
    tex = run("solve", "--format", "latex", gyro_path).stdout
    assert r"\subsection*{gyro-90: Horizontal gyroscope}" in tex
    assert f"{GYRO_PRECESSION:.4g}" in tex


def test_fault_finder_finds_faults():
    assert latex_problems(r"\[ x^{2 \]") != []
    assert latex_problems(r"$x") != []
    assert latex_problems(r"\begin{itemize}") != []
    assert latex_problems(r"\usepackage{siunitx} \SI{1}{m}") != []
    assert latex_problems(r"\[ \dot{\phi} = 1\,\mathrm{rad/s} \]") == []


def test_text_escapes_specials():
    assert writeup.text_escape("a_long_key & 50% #1 $x {y} ~ ^") == \
        r"a\_long\_key \& 50\% \#1 \$x \{y\} \textasciitilde{} \textasciicircum{}"
    # a short subscript is typeset in a file's words (ω_z, I_G); a key name is escaped
    assert writeup.text_escape("a_b") == r"a$_{b}$"
    tex = writeup.words("the rod's mass is 50% of m_total")
    assert tex == r"the rod's mass is 50\% of m$_{\mathrm{total}}$"
    assert latex_problems(tex) == []


@pytest.mark.skipif(shutil.which("pdflatex") is None, reason="pdflatex is not installed")
def test_latex_compiles(run, gyro_path, tmp_path):
    tex = run("solve", "--format", "latex", gyro_path).stdout
    doc = tmp_path / "doc.tex"
    doc.write_text("\\documentclass{article}\n\\usepackage{amsmath}\n\\begin{document}\n"
                   + tex + "\\end{document}\n")
    done = subprocess.run(["pdflatex", "-interaction=nonstopmode", "-halt-on-error", doc.name],
                          cwd=tmp_path, capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stdout[-2000:]


def test_json_and_text_formats_unchanged(run, gyro_path):
    doc = json.loads(run("solve", "--format", "json", gyro_path).stdout)
    assert doc["answers"]["precession"]["values"][0] == pytest.approx(GYRO_PRECESSION)
    assert doc["answers"]["min_spin"]["values"] == [0.0]
    text = run("solve", gyro_path).stdout
    assert f"{GYRO_PRECESSION:.4g}" in text and "$" not in text and "\\" not in text


def test_any_formula_text_gives_sound_latex():
    """Seeded random formula text (odd characters, Greek, units, words): never broken LaTeX."""
    import random

    vocab = ["phidot", "theta", "psidot_min", "omega_z", "sqrt(", "(", ")", "^", "^2", "^-1",
             "*", "/", "+", "-", "=", ">=", "<=", "+-", " ", "1.5e-07", "3", "0.25", "kg", "m",
             "s^2", "rad/s", "deg", "rpm", "N m", "because", "the", "a", "in", "{", "}", "%",
             "&", "#", "$", "_", "~", "\\", "|", "[", "]", ":", ";", ",", ".", "'", '"', "@",
             "θ", "°", "µ", "≥", "−", "I_G", "x_1", "1e5", "dH/dt"]
    rng = random.Random(7)
    for _ in range(3000):
        text = "".join(rng.choice(vocab) for _ in range(rng.randint(1, 12)))
        assert latex_problems(f"\\[ {latex_math(text)} \\]") == [], text
        assert latex_problems(f"\\[ {latex_math(text, units=False)} \\]") == [], text
        assert latex_problems(latex_mixed(text)) == [], text
        assert latex_problems(writeup.words(text)) == [], text


def test_file_keys_in_prose_stay_words():
    """`bearing_forces` in a note is a key of the file: words, "bearing forces"."""
    from gyro_cli.kinds import get

    keys = writeup.Keys.of(get("gyroscopic_torque"))
    assert writeup.words("bearing_forces lists A and B", keys=keys).startswith(
        "bearing forces lists")
