"""Solution sheets: the formula parser, its printers, the standalone document, the sample.

Expected strings are written out by hand for each construct of the formula
language, in the plain text the kinds write and in LaTeX (the Markdown write-up
puts the same LaTeX between $ signs). The standalone document is compiled with
pdflatex when it is installed (`make handout` says how) and the text pdftotext
extracts from it must hold no raw identifier of the plain form.
"""

from __future__ import annotations

import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
import yaml
from conftest import read_yaml
from formula_oracle import latex_math, latex_mixed, parse, spans, text, try_parse
from oracle_tree import (
    Abs,
    BinOp,
    Call,
    Group,
    Integral,
    Neg,
    Num,
    Pow,
    Quantity,
    Rel,
    Sym,
    to_core,
)

from gyro_cli.core.work import num
from gyro_cli.render.mathprint import latex, symbol_tex

ROOT = Path(__file__).resolve().parent.parent
PROBLEMS = sorted((ROOT / "problems").glob("*.yaml"))

# (plain text as a kind writes it, canonical plain text, LaTeX inline, LaTeX display)
CONSTRUCTS = [
    ("m g l sin(theta)", "m g l sin(theta)", r"m g l \sin \theta", r"m g l \sin \theta"),
    ("2 sqrt((I - J) D cos(theta)) / J", "2 sqrt((I - J) D cos(theta)) / J",
     r"2 \sqrt{(I - J) D \cos \theta}/J", r"\frac{2 \sqrt{(I - J) D \cos \theta}}{J}"),
    ("phidot sin(theta) (J omega_z - I phidot cos(theta))",
     "phidot sin(theta) (J omega_z - I phidot cos(theta))",
     r"\dot{\phi} \sin \theta (J \omega_{z} - I \dot{\phi} \cos \theta)",
     r"\dot{\phi} \sin \theta (J \omega_{z} - I \dot{\phi} \cos \theta)"),
    ("0.08498 kg (9.815 m/s^2) (0.03810 m) sin(30.00 deg)",
     "0.08498 kg (9.815 m/s^2) (0.03810 m) sin(30.00 deg)",
     r"0.08498\,\mathrm{kg}\,(9.815\,\mathrm{m/s^{2}}) (0.03810\,\mathrm{m}) \sin 30.00^{\circ}",
     r"0.08498\,\mathrm{kg}\,(9.815\,\mathrm{m/s^{2}}) (0.03810\,\mathrm{m}) \sin 30.00^{\circ}"),
    ("n = K x k / sin(theta)", "n = K x k / sin(theta)", r"n = K \times k/\sin \theta",
     r"n = \frac{K \times k}{\sin \theta}"),
    ("|dH/dt| = |Omega| |K x H|", "|dH / dt| = |Omega| |K x H|",
     r"\lvert \mathrm{d}H/\mathrm{d}t\rvert = \lvert \Omega\rvert \lvert K \times H\rvert",
     r"\left|\frac{\mathrm{d}H}{\mathrm{d}t}\right| = \lvert \Omega\rvert \lvert K \times H\rvert"),
    ("gamma^2 >> a", "gamma^2 >> a", r"\gamma^{2} \gg a", r"\gamma^{2} \gg a"),
    ("theta_max -> theta_min", "theta_max -> theta_min",
     r"\theta_{\mathrm{max}} \to \theta_{\mathrm{min}}",
     r"\theta_{\mathrm{max}} \to \theta_{\mathrm{min}}"),
    ("psidot >= psidot_min", "psidot >= psidot_min", r"\dot{\psi} \ge \dot{\psi}_{\mathrm{min}}",
     r"\dot{\psi} \ge \dot{\psi}_{\mathrm{min}}"),
    ("theta0 + theta_0 + u1 + P2", "theta0 + theta_0 + u1 + P2",
     r"\theta_{0} + \theta_{0} + u_{1} + P_{2}", r"\theta_{0} + \theta_{0} + u_{1} + P_{2}"),
    ("T = 2 int_u1^u2 du/sqrt(f(u))", "T = 2 int_u1^u2 du / sqrt(f(u))",
     r"T = 2 \int_{u_{1}}^{u_{2}} \mathrm{d}u/\sqrt{f(u)}",
     r"T = 2 \int_{u_{1}}^{u_{2}} \frac{\mathrm{d}u}{\sqrt{f(u)}}"),
    ("g = 32.2 ft/s^2", "g = 32.2 ft/s^2", r"g = 32.2\,\mathrm{ft/s^{2}}",
     r"g = 32.2\,\mathrm{ft/s^{2}}"),
    ("188.5 rad/s + -2.094 rad/s (0.8660)", "188.5 rad/s - 2.094 rad/s (0.8660)",
     r"188.5\,\mathrm{rad/s} - 2.094\,\mathrm{rad/s}\,(0.8660)",
     r"188.5\,\mathrm{rad/s} - 2.094\,\mathrm{rad/s}\,(0.8660)"),
    ("-(-2.781 N m) / 0.2000 m", "-(-2.781 N m) / (0.2000 m)",
     r"-(-2.781\,\mathrm{N\,m})/(0.2000\,\mathrm{m})",
     r"\frac{-(-2.781\,\mathrm{N\,m})}{0.2000\,\mathrm{m}}"),
    ("(1995) u^2 + (-954.0)", "(1995) u^2 - 954.0", r"(1995) u^{2} - 954.0",
     r"(1995) u^{2} - 954.0"),
    ("sin^2(theta0) thetadot0^2", "sin^2(theta0) thetadot0^2",
     r"\sin^{2} \theta_{0} {\dot{\theta}_{0}}^{2}", r"\sin^{2} \theta_{0} {\dot{\theta}_{0}}^{2}"),
    ("3.869e-05 kg m^2", "3.869e-05 kg m^2", r"3.869\times 10^{-5}\,\mathrm{kg\,m^{2}}",
     r"3.869\times 10^{-5}\,\mathrm{kg\,m^{2}}"),
    ("atan2(|omega x H|, omega . H)", "atan2(|omega x H|, omega . H)",
     r"\operatorname{atan2}(\lvert \omega \times H\rvert, \omega \cdot H)",
     r"\operatorname{atan2}(\lvert \omega \times H\rvert, \omega \cdot H)"),
    ("f(+-1) = -(beta -+ gamma)^2", "f(+-1) = -(beta -+ gamma)^2",
     r"f(\pm 1) = -(\beta \mp \gamma)^{2}", r"f(\pm 1) = -(\beta \mp \gamma)^{2}"),
    ("M q'' + v C1 q'", "M q'' + v C1 q'", r"M q'' + v C_{1} q'", r"M q'' + v C_{1} q'"),
    ("sum I_w - G sum I_E", "sum I_w - G sum I_E", r"\sum I_{w} - G \sum I_{E}",
     r"\sum I_{w} - G \sum I_{E}"),
    ("Pi(n1|m)", "Pi(n1 | m)", r"\Pi(n_{1} \mid m)", r"\Pi(n_{1} \mid m)"),
    ("Rz(yaw) = [1 0; 0 -1]", "Rz(yaw) = [1 0; 0 -1]",
     r"R_{z}(\mathrm{yaw}) = \begin{bmatrix} 1 & 0 \\ 0 & -1 \end{bmatrix}",
     r"R_{z}(\mathrm{yaw}) = \begin{bmatrix} 1 & 0 \\ 0 & -1 \end{bmatrix}"),
    # a quantity whose number is a product: the oracle reads it; no kind's tree holds one
    ("1 x 10^6 g cm^2/s", "1 x 10^6 g cm^2/s", None, None),
    ("s = -0.7753 - 4.465 i 1/s", "s = -0.7753 - 4.465i 1/s",
     r"s = -0.7753 - 4.465\,\mathrm{i}\,\mathrm{1/s}",
     r"s = -0.7753 - 4.465\,\mathrm{i}\,\mathrm{1/s}"),
]


@pytest.mark.parametrize("source, plain, inline, display", CONSTRUCTS)
def test_each_construct_in_text_and_latex(source, plain, inline, display):
    tree = parse(source)
    assert text(tree) == plain
    if inline is not None:  # typeset from the core tree the parse stands for
        assert latex(to_core(tree), display=False) == inline
        assert latex(to_core(tree), display=True) == display
    # the plain form reads back to the same print
    assert text(parse(plain)) == plain


def test_trees_by_hand():
    assert parse("m g l sin(theta)", units=False) == BinOp(
        " ", BinOp(" ", BinOp(" ", Sym("m"), Sym("g")), Sym("l")),
        Call("sin", (Sym("theta"),)))
    # a / b c is (a / b) c, as the chapter writes gamma^2/a cos(theta0)
    assert parse("a / b c", units=False) == BinOp(" ", BinOp("/", Sym("a"), Sym("b")), Sym("c"))
    assert parse("M^-1") == Pow(Sym("M"), Neg(Num("1")))
    assert parse("9.815 m/s^2") == Quantity(Num("9.815"), "m/s^2")
    assert parse("2 m g l") == BinOp(" ", BinOp(" ", BinOp(" ", Num("2"), Sym("m")), Sym("g")),
                                     Sym("l"))  # not two metres
    assert parse("357.8 1/s^2") == Quantity(Num("357.8"), "1/s^2")
    assert parse("|K x H|") == Abs(BinOp("x", Sym("K"), Sym("H")))
    # x between symbols that are not vectors is a distance: m g x R
    assert parse("g x R") == BinOp(" ", BinOp(" ", Sym("g"), Sym("x")), Sym("R"))
    assert parse("= 1") == Rel(None, (("=", Num("1")),))
    assert parse("int_u1^u2 du") == Integral(Sym("u1"), Sym("u2"), Sym("du"))
    assert parse("cos theta0 - cos theta") == BinOp(
        "-", Call("cos", (Sym("theta0"),), parens=False), Call("cos", (Sym("theta"),),
                                                                parens=False))
    assert parse("(a)") == Group("(", Sym("a"))
    for prose in ("the axis falls", "a complex pair", "(gyroscopic: false)", "x = (", ""):
        assert try_parse(prose) is None


def test_symbol_names():
    assert symbol_tex("theta_0") == symbol_tex("theta0") == r"\theta_{0}"
    assert symbol_tex("u1") == "u_{1}" and symbol_tex("P2") == "P_{2}"
    assert symbol_tex("phidot") == r"\dot{\phi}" and symbol_tex("thetaddot") == r"\ddot{\theta}"
    assert symbol_tex("psidot_min") == r"\dot{\psi}_{\mathrm{min}}"
    assert symbol_tex("F_A,weight") == r"F_{A,\mathrm{weight}}"
    assert symbol_tex("omega_p,max") == r"\omega_{p,\mathrm{max}}"
    assert symbol_tex("K0_pp") == r"K_{0,\mathrm{pp}}"
    assert symbol_tex("dH_O") == r"\mathrm{d}H_{O}" and symbol_tex("dtheta") == r"\mathrm{d}\theta"
    assert symbol_tex("m_s") == "m_{s}" and symbol_tex("Omega") == r"\Omega"


def test_prose_is_split_by_the_parser():
    got = spans("real roots exist because psidot >= psidot_min = 101.1 rad/s (Eq. 11.21)")
    assert got[0] == (False, "real roots exist because ")
    assert got[1][0] and text(got[1][1]) == "psidot >= psidot_min = 101.1 rad/s"
    assert got[2] == (False, " (Eq. 11.21)")
    # "a" the article is prose, "a" the symbol is maths; hyphenated words stay words
    assert spans("a complex pair") == [(False, "a complex pair")]
    assert [p for m, p in spans("Euler angles z-x-z; theta from") if not m][0] == \
        "Euler angles z-x-z; "
    assert text(spans("up: a F_A - b F_B = M")[1][1]) == "a F_A - b F_B = M"


_MARKDOWN: dict[str, str] = {}  # path -> its write-up: three tests read every problem's


def _markdown(run, path) -> str:
    if str(path) not in _MARKDOWN:
        result = run("solve", "--format", "markdown", path)
        assert result.exit_code == 0, result.output
        _MARKDOWN[str(path)] = result.stdout
    return _MARKDOWN[str(path)]


def test_markdown_has_no_raw_signs_or_names(run):
    for path in PROBLEMS:
        md = _markdown(run, path)
        maths = " ".join(re.findall(r"\$\$(.*?)\$\$|\$([^$]*)\$", md, re.S).__str__())
        assert "--" not in maths.replace("---", ""), path
        assert "+ -" not in maths and "+ (-" not in maths, path
        assert r"\mathrm{theta" not in md and r"\mathrm{phidot" not in md, path
        assert "sqrt(" not in maths, path


def test_markdown_and_text_of_the_same_step(run, problems_dir):
    """11/3: the moment step in the text report and in Markdown, written out by hand."""
    path = problems_dir / "11_3.yaml"
    out = run("solve", path).stdout
    assert ("  M = m g l sin(theta) = 0.08498 kg (9.815 m/s^2) (0.03810 m) sin(30.00 deg) = "
            "0.01589 N m    (Eq. 11.11, gravity)") in out
    md = _markdown(run, path)
    assert (r"$$ \begin{aligned}" "\n" r"M &= m g l \sin \theta \\" "\n"
            r" &= 0.08498\,\mathrm{kg}\,(9.815\,\mathrm{m/s^{2}}) (0.03810\,\mathrm{m}) "
            r"\sin 30.00^{\circ} \\" "\n" r" &= 0.01589\,\mathrm{N\,m}" "\n"
            r"\end{aligned} \qquad \text{(gravity)} \qquad \text{(11.11)} $$") in md
    tex = run("solve", "--format", "latex", path).stdout
    assert r"\end{aligned} \qquad \text{(gravity)} \tag{11.11}" in tex


def test_standalone_is_a_whole_document(run):
    result = run("solve", "--format", "latex", "--standalone", PROBLEMS[0], PROBLEMS[1])
    assert result.exit_code == 0
    tex = result.stdout
    assert tex.startswith(r"\documentclass") and tex.rstrip().endswith(r"\end{document}")
    assert tex.count(r"\section{") == 2
    assert r"\tag{11.8}" in tex  # omega_z = psidot + phidot cos(theta), numbered as the chapter
    bad = run("solve", "--standalone", PROBLEMS[0])
    assert bad.exit_code == 2 and "--format latex" in bad.stderr


RAW = re.compile(r"phidot|psidot|thetadot|theta0|theta_|sqrt|\^|_|\u02c6")  # U+02C6: a text ^


def without_authors_words(paths, folder: Path) -> list[Path]:
    """Copies of the problem files without their notes and source: the author's words,
    which gyro prints as written."""
    out = []
    for path in paths:
        data = read_yaml(Path(path).read_text())
        data.pop("notes", None), data.pop("source", None)
        out.append(folder / f"plain_{Path(path).name}")
        out[-1].write_text(yaml.safe_dump(data, sort_keys=False))
    return out


@pytest.mark.skipif(shutil.which("pdflatex") is None or shutil.which("pdftotext") is None,
                    reason="pdflatex/pdftotext not installed (see `make handout`)")
def test_every_bundled_problem_compiles_clean(run, tmp_path):
    """The whole handout compiles with no overfull line and no raw identifier in its text:
    neither in what gyro writes nor in the files' own notes and sources, whose maths is
    written in Unicode (issue 39: psi-dot as ψ̇, θ₀, √) and set as maths."""
    result = run("solve", "--format", "latex", "--standalone", *PROBLEMS)
    assert result.exit_code == 0, result.output
    doc = tmp_path / "handout.tex"
    doc.write_text(result.stdout)
    done = subprocess.run(["pdflatex", "-interaction=nonstopmode", "-halt-on-error", doc.name],
                          cwd=tmp_path, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stdout[-3000:]
    log = (tmp_path / "handout.log").read_text(errors="replace")
    overfull = re.findall(r"Overfull \\hbox.*", log)
    assert overfull == []
    subprocess.run(["pdftotext", "handout.pdf", "handout.txt"], cwd=tmp_path, check=True)
    words = (tmp_path / "handout.txt").read_text(errors="replace")
    assert RAW.findall(words) == [], [words[max(0, m.start() - 40):m.end() + 40]
                                      for m in RAW.finditer(words)][:8]


def test_problem_file_page_sample_is_the_real_output(run):
    """The full sample moved from the README to docs/problem_file.md (issue 39)."""
    page = (ROOT / "docs" / "problem_file.md").read_text()
    block = re.search(r"`gyro solve problems/11_3.yaml` prints:\n\n```\n(.*?)```", page, re.S)
    assert block, "the page's sample block is missing"
    assert block.group(1) == run("solve", ROOT / "problems" / "11_3.yaml").stdout


def test_solve_text_and_json_do_not_load_the_typesetting():
    """Text loads no typesetting; JSON loads the LaTeX printer for its equations' LaTeX
    (from the trees) but never the write-ups (LaTeX, Markdown, HTML)."""
    code = ("import sys; from click.testing import CliRunner; from gyro_cli.cli import main; "
            "r2 = CliRunner().invoke(main, ['solve', sys.argv[1]]); "
            "print(sorted(m for m in sys.modules if 'render.math' in m "
            "or 'writeup' in m or 'render.html' in m)); "
            "r = CliRunner().invoke(main, ['solve', '--format', 'json', sys.argv[1]]); "
            "print(sorted(m for m in sys.modules if 'writeup' in m or 'render.html' in m "
            "or 'render.mathml' in m))")
    out = subprocess.run([sys.executable, "-c", code, str(ROOT / "problems" / "11_3.yaml")],
                         capture_output=True, text=True, timeout=120)
    assert out.stdout.split() == ["[]", "[]"], out.stderr


def test_us_units_work_the_problem_in_slug_ft_lbf(run, problems_dir):
    """11/3 by hand in US units: W = 3 oz = 0.1875 lbf, g = 32.2 ft/s^2, k_z = 0.84 in =
    0.07 ft, k_O = 1.80 in = 0.15 ft, l = 1.5 in = 0.125 ft."""
    out = run("solve", "--units", "us", problems_dir / "11_3.yaml").stdout
    W, g, kz, kO, l = 3 / 16, 32.2, 0.84 / 12, 1.80 / 12, 1.5 / 12
    m = W / g
    assert f"m = W / g = 0.1875 lbf / (32.20 ft/s^2) = {m:.4g} slug" in out
    assert f"J = m k_z^2 = {num(m)} slug (0.07000 ft)^2 = {num(m * kz ** 2)} slug ft^2" in out
    assert f"I = m k_O^2 = {num(m)} slug (0.1500 ft)^2 = {num(m * kO ** 2)} slug ft^2" in out
    assert f"= {num(W * l * 0.5)} lbf ft    (Eq. 11.11, gravity)" in out
    assert "Given                           US" in out
    assert " kg" not in out and " N m" not in out
    # the answers the file asks for in rpm stay in rpm; rates are the same in both systems
    assert "precession  phidot = 45.13 rpm (slow)   533.5 rpm (fast)" in out
    si = run("solve", problems_dir / "11_3.yaml").stdout
    assert "Given                           SI" in si and "0.08498 kg" in si
    import json

    doc = json.loads(run("solve", "--units", "us", "--format", "json",
                         problems_dir / "11_3.yaml").stdout)
    assert doc["units"] == "us" and doc["steps"][0]["lines"][0].endswith("= 0.005823 slug")
    assert doc["given"][0]["si_unit"] == "N"  # si_value stays SI, as its name says


@pytest.mark.skipif(shutil.which("pdflatex") is None, reason="pdflatex is not installed")
def test_us_units_sheet_compiles(run, tmp_path, problems_dir):
    result = run("solve", "--units", "us", "--format", "latex", "--standalone",
                 problems_dir / "11_3.yaml", problems_dir / "11_5.yaml")
    (tmp_path / "us.tex").write_text(result.stdout)
    done = subprocess.run(["pdflatex", "-interaction=nonstopmode", "-halt-on-error", "us.tex"],
                          cwd=tmp_path, capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stdout[-2000:]
    assert "slug" in result.stdout and "Overfull" not in (tmp_path / "us.log").read_text()


def test_steps_use_the_given_tables_symbols(run, problems_dir):
    """11/5 calls the supported mass m_s in its Given table, and so do its steps; 11/3's
    check writes the moment with the symbols of its steps (m g l), not an undefined D."""
    out = run("solve", problems_dir / "11_5.yaml").stdout
    assert "  m_s     10 kg" in out
    assert "F_A,weight = m_s g sin(theta) b / L" in out
    assert "m g sin(theta) b" not in out
    out = run("solve", problems_dir / "11_3.yaml").stdout
    assert " D " not in out and "applied m g l sin(theta) = 0.01589 N m" in out


def test_any_text_parses_or_is_refused_and_converts_cleanly():
    """Seeded random formula text: the parser answers a tree or ParseError (never another
    exception), the write-up is sound LaTeX and --units us never fails on it."""
    import random

    from test_writeup import latex_problems

    from gyro_cli.render import writeup

    vocab = ["phidot", "theta", "psidot_min", "omega_z", "sqrt(", "(", ")", "^", "^2", "^-1",
             "*", "/", "+", "-", "=", ">=", "+-", " ", "1.5e-07", "3", "kg", "m", "s^2",
             "rad/s", "deg", "N m", "because", "the", "a", "|", "[", "]", ":", ",", ".", "'",
             "I_G", "dH/dt", "x", "K", "int_u1", "sum", "sin", "cos", "i", "A", "F_A,w", "->",
             ">>", "1/s", "g", "10", "%", "_", "θ"]
    rng = random.Random(11)
    for _ in range(3000):
        line = "".join(rng.choice(vocab) for _ in range(rng.randint(1, 14)))
        try_parse(line)
        assert latex_problems(f"\\[ {latex_math(line, display=True)} \\]") == [], line
        assert latex_problems(latex_mixed(line)) == [], line
        assert latex_problems(writeup.words(line)) == [], line


def test_units_key_in_the_file(run, tmp_path, problems_dir):
    text = (problems_dir / "11_3.yaml").read_text()
    path = tmp_path / "us.yaml"
    path.write_text(text + "\nunits: us\n")
    out = run("solve", path).stdout
    assert "0.1875 lbf" in out and "Given                           US" in out
    assert "0.8340 N" in run("solve", "--units", "si", path).stdout
    path.write_text(text + "\nunits: metric\n")
    bad = run("solve", path)
    assert bad.exit_code == 2
    assert bad.stderr.strip().splitlines() == [
        f"gyro: {path}: units (line {len(text.splitlines()) + 2}): expected si or us "
        "(slug, ft, lbf), got 'metric'"]


# Commands that MathJax (GitHub, Jupyter) and KaTeX both typeset; Pandoc passes maths through.
MATHJAX = {
    "mathrm", "text", "frac", "sqrt", "dot", "ddot", "times", "cdot", "circ", "qquad", "quad",
    "begin", "end", "left", "right", "Bigl", "Bigr", "lvert", "rvert", "mid", "operatorname",
    "sum", "int", "le", "ge", "gg", "ll", "to", "approx", "pm", "mp", "ne",
    "sin", "cos", "tan", "cot", "sec", "csc", "arcsin", "arccos", "arctan", "sinh", "cosh",
    "tanh", "exp", "ln", "log", "det", "max", "min",
    "alpha", "beta", "gamma", "delta", "epsilon", "zeta", "eta", "theta", "iota", "kappa",
    "lambda", "mu", "nu", "xi", "pi", "rho", "sigma", "tau", "phi", "chi", "psi", "omega",
    "Gamma", "Delta", "Theta", "Lambda", "Xi", "Pi", "Sigma", "Phi", "Psi", "Omega",
}


def _markdown_maths(md: str) -> list[str]:
    blocks = re.findall(r"\$\$(.*?)\$\$", md, re.S)
    rest = re.sub(r"\$\$.*?\$\$", "", md, flags=re.S)
    inline = re.findall(r"(?<![\\$])\$([^$\n]+?)(?<!\\)\$", rest)
    return [f"\\[{b}\\]" for b in blocks] + [f"${i}$" for i in inline]


def test_markdown_maths_uses_what_mathjax_and_katex_typeset(run):
    for path in PROBLEMS:
        md = _markdown(run, path)
        for maths in _markdown_maths(md):
            names = set(re.findall(r"\\([A-Za-z]+)", maths))
            assert names <= MATHJAX, (path, names - MATHJAX)
            envs = set(re.findall(r"\\begin\{(\w+)\}", maths))
            assert envs <= {"aligned", "bmatrix"}, (path, envs)
            # Pandoc: no space just inside inline $ ... $
            if maths.startswith("$"):
                assert maths[1] != " " and maths[-2] != " ", (path, maths)


@pytest.mark.skipif(shutil.which("pdflatex") is None, reason="pdflatex is not installed")
def test_markdown_maths_compiles(run, tmp_path):
    """Every formula of every Markdown write-up, set by LaTeX itself."""
    body = []
    for path in PROBLEMS:
        body += _markdown_maths(_markdown(run, path))
    doc = tmp_path / "md.tex"
    doc.write_text("\\documentclass{article}\n\\usepackage{amsmath}\n\\begin{document}\n"
                   + "\n\n".join(body) + "\n\\end{document}\n")
    done = subprocess.run(["pdflatex", "-interaction=nonstopmode", "-halt-on-error", doc.name],
                          cwd=tmp_path, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stdout[-3000:]
