"""`gyro solve --format html`, `gyro check --html` and the MathML printer, without a browser
(tests/test_browser.py opens the pages in Chromium)."""

from __future__ import annotations

import glob
import re
import subprocess
import sys
from html.parser import HTMLParser
from pathlib import Path

import pytest
from formula_oracle import parse as parsed
from oracle_tree import to_core

from gyro_cli.render import html, mathml
from gyro_cli.solving.solve import solve_file


def parse(text: str):  # type: ignore[no-untyped-def]
    """The core tree gyro prints for formula text (read by the oracle)."""
    return to_core(parsed(text))


ROOT = Path(__file__).resolve().parent.parent
PROBLEMS = sorted(glob.glob(str(ROOT / "problems" / "*.yaml")))


class _Tags(HTMLParser):
    """Every start tag with its attributes, and whether the nesting closes."""

    VOID = {"meta", "br", "img", "input", "link", "hr", "mspace", "path", "use", "rect",
            "circle", "stop", "ellipse", "line", "polyline", "polygon"}

    def __init__(self) -> None:
        super().__init__()
        self.tags: list[tuple[str, dict]] = []
        self.stack: list[str] = []
        self.errors: list[str] = []

    def handle_starttag(self, tag, attrs):
        self.tags.append((tag, dict(attrs)))
        if tag not in self.VOID:
            self.stack.append(tag)

    def handle_startendtag(self, tag, attrs):
        self.tags.append((tag, dict(attrs)))

    def handle_endtag(self, tag):
        if tag in self.VOID:
            return
        if not self.stack or self.stack[-1] != tag:
            self.errors.append(f"</{tag}> closes {self.stack[-1:]}")
            return
        self.stack.pop()


def _parsed(text: str) -> _Tags:
    tags = _Tags()
    tags.feed(text)
    tags.close()
    return tags


def test_mathml_of_the_chapters_symbols():
    """phidot is phi with a dot accent, theta_0 theta sub 0, a/b a fraction in a display,
    sqrt a root, a unit upright after a thin space."""
    out = mathml.tree_mathml(parse("psidot_min = 2 sqrt((I - J) m g l cos(theta)) / J"), True)
    assert '<mover accent="true"><mi>ψ</mi><mo>˙</mo></mover>' in out
    assert "<msub>" in out and "<mi>min</mi>" in out
    assert "<mfrac>" in out and "<msqrt>" in out
    assert "<mi>cos</mi><mo>&#x2061;</mo>" in out
    q = mathml.tree_mathml(parse("9.815 m/s^2"))
    assert '<mn>9.815</mn><mspace width="0.1667em"/>' in q
    assert '<msup><mi mathvariant="normal">s</mi><mn>2</mn></msup>' in q
    assert "<mo>×</mo><msup><mn>10</mn><mrow><mo>−</mo><mn>5</mn></mrow></msup>" in \
        mathml.tree_mathml(parse("3.869e-05"))
    # minus a negative value is plus (never "- -"); a negative factor keeps its brackets
    assert "<mi>a</mi><mo>+</mo><mrow><mn>2.5</mn>" in mathml.tree_mathml(parse("a - (-2.5 N)"))
    product = mathml.tree_mathml(parse("J (-179.7 rad/s)"))
    assert re.search(r"<mo>\(</mo><mrow><mo>−</mo><mrow><mn>179.7</mn>", product), product


def test_page_is_self_contained_and_well_formed():
    text = html.page([solve_file(str(ROOT / "problems" / "11_3.yaml"))])
    tags = _parsed(text)
    assert not tags.errors and not tags.stack
    names = [t for t, _ in tags.tags]
    assert "script" not in names and "link" not in names and "img" not in names
    assert not re.search(r"""(src|href)\s*=\s*["'](https?:)?//""", text)
    assert "@import" not in text and "url(http" not in text
    assert ("html", {"lang": "en"}) in tags.tags
    assert "prefers-color-scheme: dark" in text and "@media print" in text
    assert names.count("math") > 20 and names.count("h1") == 1
    assert ("th", {"scope": "col"}) in tags.tags
    assert "45.13" in text and "533.5" in text   # the answers, as the text report has them


@pytest.mark.parametrize("kind_file", ["11_2_released_top.yaml", "bicycle_benchmark.yaml"])
def test_pictures_are_inline_svg_with_alt_text(kind_file):
    text = html.page([solve_file(str(ROOT / "problems" / kind_file))])
    svg = re.search(r"<svg[^>]*>", text).group()
    assert 'role="img"' in svg and "aria-labelledby" in svg
    title_id = re.search(r'aria-labelledby="([^"]+)"', svg).group(1)
    title = re.search(rf'<title id="{title_id}">([^<]+)</title>', text).group(1)
    assert len(title) > 60
    assert ("theta_min" in title) if "released" in kind_file else ("speed" in title)
    assert "<?xml" not in text and "<!DOCTYPE svg" not in text


def test_folder_page_has_unique_ids():
    files = [str(ROOT / "problems" / f) for f in
             ("11_2_released_top.yaml", "11_2_released_top_loops.yaml", "bicycle_benchmark.yaml")]
    text = html.page([solve_file(f) for f in files])
    ids = re.findall(r'\bid="([^"]+)"', text)
    assert len(ids) == len(set(ids))
    for ref in re.findall(r'href="#([^"]+)"', text):
        assert ref in ids


@pytest.mark.parametrize("name", ["11_3.yaml", "11_2_released_top.yaml"])
def test_user_strings_are_escaped(tmp_path, name):
    """Also inside the picture, whose SVG carries the title as a comment."""
    source = (ROOT / "problems" / name).read_text()
    source = re.sub(r"^title:.*$", 'title: "--><script>alert(1)</script> & <b>x</b><!--"',
                    source, flags=re.M)
    source = re.sub(r"^id:.*$", 'id: "a<i>b"', source, flags=re.M)
    path = tmp_path / "evil<x>.yaml"
    path.write_text(source)
    text = html.page([solve_file(str(path))])
    assert "<script>" not in text and "<b>x</b>" not in text and "a<i>b" not in text
    assert "--&gt;&lt;script&gt;alert(1)&lt;/script&gt; &amp; &lt;b&gt;x&lt;/b&gt;" in text
    body = text.split("</style>", 1)[1]
    assert body.count("<!--") == body.count("-->")   # no comment of the SVG closed early
    assert not _parsed(text).errors


def test_cli_html_one_page_for_a_folder(tmp_path):
    folder = tmp_path / "set"
    folder.mkdir()
    for name in ("11_3.yaml", "11_4.yaml"):
        (folder / name).write_text((ROOT / "problems" / name).read_text())
    out = subprocess.run([sys.executable, "-m", "gyro_cli", "solve", "--format", "html",
                          str(folder)], capture_output=True, text=True, cwd=ROOT)
    assert out.returncode == 0, out.stderr
    assert out.stdout.count("<!DOCTYPE html>") == 1 and out.stdout.count("<article") == 2
    assert "<nav" in out.stdout


@pytest.mark.parametrize("path", PROBLEMS, ids=lambda p: Path(p).name)
def test_every_bundled_problem_renders(path):
    result = solve_file(path)
    text = html.worked_answer(result, picture=False)
    tags = _parsed(text)
    assert not tags.errors and not tags.stack, tags.errors
    for name, _answer in result.answers.items():
        assert name.replace("_", " ") in text


def test_cli_check_html_failing_first_and_linked(tmp_path):
    wrong = (ROOT / "problems" / "11_3.yaml").read_text().replace("533.5 rpm", "600 rpm")
    (tmp_path / "wrong.yaml").write_text(wrong)
    report = tmp_path / "report.html"
    args = [sys.executable, "-m", "gyro_cli", "check", "--html", str(report),
            str(ROOT / "problems" / "11_4.yaml"), str(tmp_path / "wrong.yaml")]
    out = subprocess.run(args, capture_output=True, text=True, cwd=ROOT)
    assert out.returncode == 1 and "FAILED" in out.stdout   # the table is still printed
    text = report.read_text()
    rows = re.findall(r"<tr><td[^>]*>(PASS|FAIL|----)</td>", text)
    assert rows[0] == "FAIL" and rows.count("FAIL") == 1 and "PASS" in rows
    first = text[text.index("<tbody>"):].split("</tr>")[0]
    link = re.search(r'<a href="#([^"]+-precession)">precession\[2\]</a>', first).group(1)
    assert f'id="{link}"' in text                     # the failing answer's worked answer
    again = subprocess.run(args, capture_output=True, text=True, cwd=ROOT)
    assert again.returncode == 2 and "exists; not overwritten" in again.stderr
    assert subprocess.run(args + ["--force"], capture_output=True, cwd=ROOT).returncode == 1


