"""The HTML pages in a real browser: headless Chromium (Debian's `chromium`), driven by
Playwright through `executable_path` (no browser download), checked with axe-core.

For every bundled problem (on folder pages of a few problems each, one page of a single
problem), a folder page and a `gyro check --html` report: no console error and no
request leaving the page; no horizontal overflow at 360 px and at 1024 px; every <math>
element laid out with a non-zero box; no axe-core violation of WCAG 2.1 A/AA (tags
wcag2a, wcag2aa, wcag21a, wcag21aa) in the light scheme, and no contrast violation in
the dark one (`prefers-color-scheme: dark`). Where $GYRO_SCREENSHOT_DIR is set, a
screenshot at 360 px of each page is written there for the record (never committed).

Contrast is axe's costly rule (five sixths of its time on a folder page: it finds each
text's background). A text's colours and size follow from the CSS of its path (each
ancestor's tag, classes and style) and its own computed colour, size and weight, so the
contrast is checked on one text of each such style (marked; axe's contrast rule is
given their selector), in the same axe run as every other rule on the whole page.
`make browser` ($GYRO_BROWSER_SWEEP=1) checks the contrast of every text, on eight
smaller folder pages. The folder pages draw one problem's picture of each kind of
picture (DRAWN); `make browser` draws every picture.

One browser per test process (conftest.py); each page is loaded once and checked at both
widths and in both schemes (the scheme switched twice while the formulas are MathML,
whose style is most of a page's, and once after they are text). The tests skip, saying why, where Chromium or Playwright is
missing (`.ci/run` installs Chromium; `make test` installs the Python packages).
"""

from __future__ import annotations

import glob
import os
import shutil
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

ROOT = Path(__file__).resolve().parent.parent
PROBLEMS = sorted(glob.glob(str(ROOT / "problems" / "*.yaml")))
# $GYRO_BROWSER_SWEEP (`make browser`): the contrast of every text, not of one per style.
SWEEP = bool(os.environ.get("GYRO_BROWSER_SWEEP"))
# The bundled problems on PAGES folder pages (every PAGES-th problem on each, so that
# the pages are of like size): a page's fixed cost (load, axe injected) is paid a few
# times, not once a problem; one page per test process. The sweep's axe, whose contrast
# time grows faster than a page's size, sees smaller pages.
PAGES = 8 if SWEEP else 2
FOLDERS = [PROBLEMS[i::PAGES] for i in range(PAGES)]
WCAG = ["wcag2a", "wcag2aa", "wcag21a", "wcag21aa"]


def _chromium() -> str | None:
    for candidate in (os.environ.get("GYRO_CHROMIUM"), shutil.which("chromium"),
                      shutil.which("chromium-browser"), shutil.which("google-chrome")):
        if candidate and os.path.exists(candidate):
            return candidate
    return None


CHROMIUM = _chromium()
try:
    from axe_playwright_python.sync_playwright import Axe
    from playwright.sync_api import sync_playwright
except ImportError as err:  # pragma: no cover - the dev extra installs both
    sync_playwright = Axe = None
    MISSING = f"Playwright or axe-playwright-python is not installed ({err}): pip install -e '.[dev]'"
else:
    MISSING = None if CHROMIUM else (
        "no Chromium found (apt-get install chromium, or set GYRO_CHROMIUM to its path); "
        ".ci/run installs it")

pytestmark = [pytest.mark.slow,  # `make test-slow`
              pytest.mark.skipif(MISSING is not None, reason=MISSING or "")]


@pytest.fixture(scope="module")
def shots() -> Path | None:
    """Where the screenshots go ($GYRO_SCREENSHOT_DIR), or None: none taken."""
    where = os.environ.get("GYRO_SCREENSHOT_DIR")
    if not where:
        return None
    path = Path(where)
    path.mkdir(parents=True, exist_ok=True)
    return path


@pytest.fixture(scope="module")
def pages(tmp_path_factory) -> Path:
    return tmp_path_factory.mktemp("pages")


def _write(folder: Path, name: str, text: str) -> Path:
    path = folder / name
    path.write_text(text, encoding="utf-8")
    return path


_OVERFLOW = "() => document.documentElement.scrollWidth - document.documentElement.clientWidth"
# The problems (their articles' headings) with something past the right edge: which
# problem of a folder page overflows (asked only when the page does).
_OVERFLOWING = """() => { const w = document.documentElement.clientWidth, where = new Set();
  for (const e of document.querySelectorAll('main *')) if (e.getBoundingClientRect().right > w) {
    const a = e.closest('article'); where.add(a ? a.getAttribute('aria-labelledby') : e.tagName); }
  return Array.from(where).slice(0, 5); }"""
_MATH = """() => Array.from(document.querySelectorAll('math')).filter(m => {
    const r = m.getBoundingClientRect(); return !(r.width > 0 && r.height > 0);
  }).map(m => m.textContent.slice(0, 60))"""
# Formulas take their colour from the text around them (axe sees each <math> as a span
# of its text below, for time: its contrast is then the contrast of that text, which axe
# checks).
_MATH_COLOUR = """() => Array.from(document.querySelectorAll('math, math *')).filter(m => {
    const own = getComputedStyle(m), up = getComputedStyle(m.parentElement);
    return own.color !== up.color || (own.backgroundColor !== 'rgba(0, 0, 0, 0)');
  }).length"""


# Each <math> becomes a span of its text once its layout and colour are checked: axe
# then walks a tenth of the nodes (MathML is most of a page's elements) and matches no
# list of every formula against each node (what excluding <math> cost: half its time).
_MATH_AS_TEXT = """() => { for (const m of Array.from(document.querySelectorAll('math'))) {
  const s = document.createElement('span'); s.textContent = m.textContent; m.replaceWith(s); } }"""


# The first text of each style is marked, and axe's contrast rule looks only at the
# marked (its selector; every other rule at the whole page). The number marked.
_ONE_TEXT_A_STYLE = """() => { const seen = new Set();
  const mark = e => e.tagName + Array.from(e.classList).sort().map(c => '.' + c).join('')
    + (e.getAttribute('style') ? '{' + e.getAttribute('style') + '}' : '');
  for (const e of document.body.querySelectorAll('*')) {
    if (!Array.from(e.childNodes).some(n => n.nodeType === Node.TEXT_NODE
                                            && n.textContent.trim())) continue;
    const s = getComputedStyle(e);
    let key = [s.color, s.fontSize, s.fontWeight, s.opacity].join(' ');
    for (let x = e; x; x = x.parentElement) key = mark(x) + '>' + key;
    if (!seen.has(key)) { seen.add(key); e.setAttribute('data-contrast', ''); }
  }
  axe.configure({rules: [{id: 'color-contrast', selector: '[data-contrast]'}]});
  return seen.size; }"""
_CONTRAST = {"type": "rule", "values": ["color-contrast"]}


def _axe(page, only: dict, marked: bool = False) -> dict:
    """axe-core's violations on the page as it is now (formulas as text, see above).
    ``marked``: only the texts marked by _ONE_TEXT_A_STYLE and what is inside them are
    axe's context (its contrast rule then builds its tree of the page's nodes for those
    alone: a third less time, the same passes and violations)."""
    context = "{include: [['[data-contrast]']]}" if marked else "document"
    return page.evaluate(f"(only) => axe.run({context}, {{runOnly: only, "
                         "resultTypes: ['violations']})", only)


def _inspect(browser, axe, path: Path, shots: Path | None,
             at_1024: Callable[[Any], None] | None = None) -> list[str]:
    """Every check on one page; the list of what failed. ``at_1024``: a test's own checks
    of the page as loaded, at 1024 px (the page then scrolled back to its top), so that
    the page is not loaded a second time for them."""
    problems: list[str] = []
    page = browser.new_page(viewport={"width": 360, "height": 800}, color_scheme="light")
    errors: list[str] = []
    page.on("console", lambda m: errors.append(f"console {m.type}: {m.text}")
            if m.type == "error" else None)
    page.on("pageerror", lambda e: errors.append(f"page error: {e}"))
    page.on("request", lambda r: errors.append(f"request left the page: {r.url}")
            if not r.url.startswith(("file:", "data:", "about:")) else None)
    try:
        page.goto(path.as_uri(), wait_until="load")
        for width in (360, 1024):
            page.set_viewport_size({"width": width, "height": 800})
            over = page.evaluate(_OVERFLOW)
            if over > 0:
                problems.append(f"{width} px: {over} px of horizontal overflow in "
                                f"{page.evaluate(_OVERFLOWING)}")
            empty = page.evaluate(_MATH)
            if empty:
                problems.append(f"{width} px: <math> with an empty box: {empty[:3]}")
            if width == 360 and shots is not None:
                page.screenshot(path=str(shots / f"{path.stem}-360.png"), full_page=True)
        if at_1024 is not None:
            at_1024(page)
            page.evaluate("window.scrollTo(0, 0)")
        if page.evaluate("document.querySelectorAll('math').length"):
            if page.evaluate(_MATH_COLOUR):
                problems.append("a formula sets its own colour or background")
            page.emulate_media(color_scheme="dark")
            if page.evaluate(_MATH_COLOUR):
                problems.append("dark: a formula sets its own colour or background")
            page.evaluate(_MATH_AS_TEXT)  # before light comes back: its styles are then found
            # for spans of text, not again for every MathML element
            page.emulate_media(color_scheme="light")
        page.evaluate(axe.axe_script)  # axe-core, once per page
        if not SWEEP:
            assert page.evaluate(_ONE_TEXT_A_STYLE) > 0
        light = _axe(page, {"type": "tag", "values": WCAG})
        page.emulate_media(color_scheme="dark")
        dark = _axe(page, _CONTRAST, marked=not SWEEP)
        for scheme, result in (("light", light), ("dark", dark)):
            for v in result["violations"]:
                node = v["nodes"][0]
                problems.append(f"axe {scheme}: {v['id']} ({v['impact']}, {len(v['nodes'])} "
                                f"nodes): {node['html'][:160]} {node.get('failureSummary', '')[:200]}")
    finally:
        page.close()
    return errors + problems


# The pictures the folder pages draw: one of each picture (of each, its own markup around
# matplotlib's; test_html holds every bundled picture's markup, and
# test_problem_page_in_chromium draws 11_2_released_top's). The others' are left out: a
# folder page's pictures took a fifth of its time, in matplotlib. `make browser` draws all.
DRAWN = ("11_2_released_top_loops.yaml", "bicycle_benchmark.yaml")


def test_the_folder_pages_draw_each_kind_of_picture():
    """DRAWN holds a bundled problem of each picture there is (a new one is added to it)."""
    import gyro_cli
    from gyro_cli import kinds

    pictures = {kinds.get(k).picture for k in kinds.names()} - {None, ""}
    drawn = [gyro_cli.load(str(ROOT / "problems" / name), path=True).kind for name in DRAWN]
    assert sorted(k.picture for k in drawn) == sorted(pictures), (drawn, pictures)


@pytest.mark.parametrize("paths", FOLDERS, ids=[f"{k + 1}-of-{PAGES}" for k in range(PAGES)])
def test_bundled_problems_in_chromium(browser, axe, pages, shots, paths):
    """Every bundled problem, on folder pages of a few (the nav and h2 titles of a folder
    page; test_problem_page_in_chromium has the h1 page of one problem)."""
    from gyro_cli.render import html
    from gyro_cli.solving.solve import solve_file

    name = f"folder-{FOLDERS.index(paths) + 1}.html"
    results = [solve_file(p) for p in paths]
    drawn = [SWEEP or Path(r.problem.file).name in DRAWN for r in results]
    articles = [html.worked_answer(r, picture=d) for r, d in zip(results, drawn, strict=True)]
    assert SWEEP or "".join(articles).count('class="picture"') == sum(drawn)
    page = _write(pages, name, html.page(results, articles=articles))
    assert _inspect(browser, axe, page, shots) == []


def test_a_text_unreadable_in_the_dark_scheme_is_found(browser, axe, pages, shots):
    """The checks themselves: a page readable in the light scheme and not in the dark one
    fails on the dark scheme's contrast alone (axe run on the marked texts)."""
    page = _write(pages, "dark.html", """<!DOCTYPE html><html lang="en"><head>
<meta charset="utf-8"><title>dark</title><style>
@media (prefers-color-scheme: dark) { body { background: #000; } p.note { color: #222; } }
</style></head><body><main><h1>A page</h1><p>Readable text.</p>
<p class="note">A note no one reads in the dark.</p></main></body></html>""")
    found = _inspect(browser, axe, page, shots)
    assert len(found) == 1 and found[0].startswith("axe dark: color-contrast"), found
    assert "A note no one reads" in found[0]


def test_problem_page_in_chromium(browser, axe, pages, shots):
    """The page of one problem (its title an h1, no contents list), with a picture."""
    from gyro_cli.render import html
    from gyro_cli.solving.solve import solve_file

    path = ROOT / "problems" / "11_2_released_top.yaml"
    page = _write(pages, path.stem + ".html", html.page([solve_file(str(path))]))
    assert _inspect(browser, axe, page, shots) == []


def test_check_report_in_chromium(browser, axe, pages, shots, tmp_path):
    """A check report with a failing answer first, linked to its worked answer (folder
    pages of several problems, pictures among them, are test_bundled_problems_in_chromium's)."""
    import gyro_cli

    wrong = (ROOT / "problems" / "11_3.yaml").read_text().replace("533.5 rpm", "600 rpm")
    (tmp_path / "wrong.yaml").write_text(wrong)
    report = gyro_cli.check(str(tmp_path / "wrong.yaml"), str(ROOT / "problems" / "11_4.yaml"))
    assert report.exit_code == 1
    check = _write(pages, "check.html", report.html(page=True))
    links: list[tuple[str, str, bool]] = []

    def follow_the_first_row(page) -> None:  # type: ignore[no-untyped-def]
        first = page.locator("tbody tr").first
        result = first.locator("td").first.inner_text()
        first.locator("a").first.click()
        target = page.evaluate("location.hash")
        links.append((result, target, page.locator(target).is_visible()))

    assert _inspect(browser, axe, check, shots, at_1024=follow_the_first_row) == []
    [(result, target, visible)] = links
    assert result == "FAIL"
    assert target.endswith("-precession") and visible


def test_solution_page_embeds_animations_that_play(browser, axe, pages, shots):
    """`gyro solve --format html --animate`: each moving problem's article carries its
    animation; the page's CSP lets exactly those players run (a blocked script would be a
    console error), and every canvas is drawn."""
    from click.testing import CliRunner

    from gyro_cli.cli import main

    names = ["11_2_released_top.yaml", "11_3.yaml", "11_1.yaml"]
    out = CliRunner().invoke(main, ["solve", "--format", "html", "--animate"]
                             + [str(ROOT / "problems" / n) for n in names])
    assert out.exit_code == 0, out.output
    assert out.output.count("<canvas") == 3 and "script-src 'sha256-" in out.output
    path = _write(pages, "animated.html", out.output)
    ink: list[int] = []

    def drawn(page) -> None:  # type: ignore[no-untyped-def]
        page.wait_for_timeout(400)
        ink.extend(page.evaluate("""() => Array.from(document.querySelectorAll('canvas')).map(c => {
            const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
            let n = 0; for (let i = 0; i < d.length; i += 4) if (d[i] < 200) n++; return n; })"""))

    assert _inspect(browser, axe, path, shots, at_1024=drawn) == []
    assert len(ink) == 3 and min(ink) > 1000
