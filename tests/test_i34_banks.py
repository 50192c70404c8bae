"""Issue 34, question banks (`gyro export`): one key per asked value, blanks that accept
the answer as its feedback prints it, the precision stated, Moodle's units graded, only
what the statement asks, and every export valid against the platforms' published
schemas (tests/lms-schemas/, SOURCES.md there).

A few bundled problems are exported once per format with two variants (module fixture)
and read back here with lxml (QTI 1.2 and IMS CP 1.1 XSD), jsonschema (PrairieLearn's
infoQuestion.json and pl-number-input.json) and Moodle's own cloze grammar (restated from
question/type/multianswer/questiontype.php). Moodle's grading of a numerical question
is restated from question/type/numerical (question.php, the answer processor's
apply_units) to try typed responses against an exported question.
"""

from __future__ import annotations

import html
import json
import math
import re
import xml.etree.ElementTree as ET
import zipfile
from pathlib import Path

import jsonschema
import pytest
import yaml
from conftest import PROBLEMS
from lxml import etree
from test_export import remembered

import gyro_cli
from gyro_cli.render import html as worked
from gyro_cli.render import picture

SCHEMAS = Path(__file__).parent / "lms-schemas"
QTI = "{http://www.imsglobal.org/xsd/ims_qtiasiv1p2}"
CP = "{http://www.imsglobal.org/xsd/imscp_v1p1}"
#: the bundled problems exported here: two roots and a least spin (11/3), a file that asks
#: less than it finds (the released top, the bicycle at 12 sig), one number in kN m
#: (ship_steering_3500kg asks couple and precession), and a plain one-number problem
FILES = ["11_3.yaml", "11_2_released_top.yaml", "bicycle_benchmark.yaml",
         "aircraft_360_kmph.yaml", "11_1.yaml", "ship_steering_3500kg.yaml"]
DIGITS = 4

#: a problem whose answers collide on the old keys: the slow root of `precession` and the
#: answer `precession_slow`, in different units
COLLIDING = """\
id: collide
kind: steady_precession
given:
  weight: 3 oz
  k_axial: 0.84 in
  k_pivot: 1.80 in
  cg_distance: 1.5 in
  theta: 30 deg
  spin: 1800 rpm
find:
  precession: rpm
  precession_slow: rad/s
"""


def _run(*args):
    from click.testing import CliRunner

    from gyro_cli.cli import main

    return CliRunner().invoke(main, [str(a) for a in args])


@pytest.fixture(scope="module")
def banks(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("banks")
    out = {}
    with pytest.MonkeyPatch.context() as patch:
        # The formats lay out the same variants: each picture is drawn (most of the time)
        # and each worked answer typeset once, not once per format.
        remembered(patch, picture, "png")
        remembered(patch, worked, "worked_answer")
        for fmt, target in (("moodle", tmp / "m.xml"), ("qti", tmp / "q.zip"),
                            ("blackboard", tmp / "b.txt"), ("prairielearn", tmp / "pl")):
            done = _run("export", "--to", fmt, *(PROBLEMS / f for f in FILES), "--variants",
                        2, "-o", target)
            assert done.exit_code == 0, done.output
            out[fmt], out[f"{fmt} stderr"] = target, done.stderr
    return out


# ---- reading the exports back ---------------------------------------------------------

def _pl_generate(server: Path, seed: int) -> dict:
    namespace: dict = {}
    exec(compile(server.read_text(), str(server), "exec"), namespace)  # our own output
    data = {"variant_seed": seed, "params": {}, "correct_answers": {}}
    namespace["generate"](data)
    return data


def _pl_page(template: str, params: dict) -> str:
    """question.html rendered as PrairieLearn's mustache does for these tags."""
    def value(path: str):
        found = params
        for name in path.split("."):
            found = found.get(name) if isinstance(found, dict) else None
        return found

    def section(match: re.Match) -> str:
        return match.group(2) if value(match.group(1)) else ""

    def lookup(match: re.Match) -> str:
        return html.escape(str(value(match.group(1))))
    out = re.sub(r"\{\{#params\.([\w.]+)\}\}(.*?)\{\{/params\.\1\}\}", section,
                 template, flags=re.S)
    out = re.sub(r"\{\{\{params\.(\w+)\}\}\}", lambda m: params[m.group(1)], out)
    return re.sub(r"\{\{params\.([\w.]+)\}\}", lookup, out)


def _pl_inputs(page: str) -> list[dict[str, str]]:
    return [{k: html.unescape(v) for k, v in re.findall(r'([\w-]+)="([^"]*)"', attrs)}
            for attrs in re.findall(r"<pl-number-input ([^>]*)>", page)]


def _pl_blanks(root: Path) -> list[tuple[str, float, float, str]]:
    """(statement, answer, half-width, label) of every input of every variant."""
    out = []
    for question in sorted(p for p in root.iterdir() if p.is_dir()):
        template = (question / "question.html").read_text()
        seeds = 1 if json.loads((question / "info.json").read_text())["singleVariant"] else 2
        for seed in range(seeds):
            data = _pl_generate(question / "server.py", seed)
            for attrs in _pl_inputs(_pl_page(template, data["params"])):
                value = data["correct_answers"][attrs["answers-name"]]
                out.append((data["params"]["statement"], value, float(attrs["atol"]),
                            attrs["label"]))
    return out


def _moodle_blanks(path: Path) -> list[tuple[str, float, float, str]]:
    out = []
    for question in ET.parse(path).getroot().findall("question"):
        text = question.findtext("questiontext/text") or ""
        if question.get("type") == "numerical":
            answer = question.find("answer")
            out.append((text, float(answer.findtext("text")),
                        float(answer.findtext("tolerance")), ""))
        elif question.get("type") == "cloze":
            out += [(text, float(v), float(t), "")
                    for v, t in re.findall(r"\{1:NUMERICAL:=([^:}]+):([^}]+)\}", text)]
    return out


def _qti_items(path: Path):
    with zipfile.ZipFile(path) as archive:
        for name in archive.namelist():
            if name != "imsmanifest.xml" and name.endswith(".xml"):
                yield from ET.fromstring(archive.read(name)).iter(f"{QTI}item")


def _qti_blanks(path: Path) -> list[tuple[str, float, float, str]]:
    out = []
    for item in _qti_items(path):
        if item.find(f".//{QTI}response_lid") is not None:
            continue  # a word answer's multiple choice
        value = float(item.find(f".//{QTI}varequal").text)
        low = float(item.find(f".//{QTI}vargte").text)
        high = float(item.find(f".//{QTI}varlte").text)
        out.append((item.find(f"{QTI}presentation//{QTI}mattext").text, value,
                    min(value - low, high - value), item.get("title")))
    return out


def _blackboard_blanks(path: Path) -> list[tuple[str, float, float, str]]:
    rows = [line.split("\t") for line in path.read_bytes().decode("ascii").split("\r\n") if line]
    return [(html.unescape(row[1]), float(row[2]), float(row[3]), "") for row in rows]


READERS = {"moodle": _moodle_blanks, "qti": _qti_blanks, "blackboard": _blackboard_blanks,
           "prairielearn": _pl_blanks}


def _printed(value: float) -> float:
    """The value as the worked answer prints it (4 significant figures)."""
    return float(f"{value:.{DIGITS - 1}e}")


# ---- item 1: one key per asked value -----------------------------------------------------

def test_item01_every_asked_value_has_its_own_key_in_every_format(write, tmp_path):
    path = write(COLLIDING)
    for fmt, out in (("prairielearn", tmp_path / "pl"), ("qti", tmp_path / "q.zip"),
                     ("moodle", tmp_path / "m.xml")):
        done = _run("export", "--to", fmt, path, "-o", out)
        assert done.exit_code == 0, done.output
    solved = gyro_cli.solve(yaml.safe_load(COLLIDING))
    rpm = dict(zip(solved.answers["precession"].labels, solved.answers["precession"].values))
    (slow_rad,) = solved.answers["precession_slow"].values
    question = tmp_path / "pl" / "p"
    data = _pl_generate(question / "server.py", 0)
    inputs = _pl_inputs(_pl_page((question / "question.html").read_text(), data["params"]))
    assert len(inputs) == 3 == len({i["answers-name"] for i in inputs})
    assert len(data["correct_answers"]) == 3
    by_label = {(i["label"], i.get("suffix")): data["correct_answers"][i["answers-name"]]
                for i in inputs}
    assert by_label[("precession (slow) =", "rpm")] == pytest.approx(rpm["slow"], rel=1e-12)
    assert by_label[("precession (fast) =", "rpm")] == pytest.approx(rpm["fast"], rel=1e-12)
    assert by_label[("precession slow =", "rad/s")] == pytest.approx(slow_rad, rel=1e-12)
    idents = [item.get("ident") for item in _qti_items(tmp_path / "q.zip")]
    assert len(idents) == 3 == len(set(idents))
    assert len(_moodle_blanks(tmp_path / "m.xml")) == 3


# ---- items 18 and 19: what a blank accepts, and saying so --------------------------------

@pytest.mark.parametrize("fmt", sorted(READERS))
def test_item18_a_blank_accepts_the_answer_as_its_feedback_prints_it(banks, fmt):
    blanks = READERS[fmt](banks[fmt])
    assert len(blanks) >= 20
    for _text, value, half, label in blanks:
        assert abs(_printed(value) - value) <= half * (1 + 1e-12), (fmt, label, value, half)
    # the bicycle asks 12 sig: its blanks take the student tolerance (1%), and stderr says so
    bicycle = [(v, h) for text, v, h, _ in blanks if "benchmark bicycle" in text]
    assert bicycle and all(h == pytest.approx(max(0.01 * abs(v), h), rel=1e-9)
                           and h >= 0.01 * abs(v) * (1 - 1e-12) for v, h in bicycle)
    note = banks[f"{fmt} stderr"]
    assert "tighter than the 4 significant figures" in note and "bicycle_benchmark" in note
    assert "accept 1% (--tolerance)" in note
    # 11/3 asks 1%, looser than 4 figures: its own tolerance stays
    for text, value, half, _ in blanks:
        if "least spin for which steady precession" in text:
            assert half == pytest.approx(0.01 * abs(value), rel=1e-9)


def test_item18_student_tolerance_option(tmp_path):
    out = tmp_path / "b.txt"
    done = _run("export", "--to", "blackboard", PROBLEMS / "bicycle_benchmark.yaml",
                "--tolerance", "2%", "-o", out)
    assert done.exit_code == 0, done.output
    for _, value, half, _ in _blackboard_blanks(out):
        assert half >= 0.02 * abs(value) * (1 - 1e-9)
    assert "accept 2% (--tolerance)" in done.stderr
    done = _run("export", "--to", "blackboard", PROBLEMS / "11_3.yaml", "--tolerance",
                "0.1 rad/s", "-o", tmp_path / "x.txt")
    assert done.exit_code == 2 and "--tolerance" in done.stderr
    assert len(done.stderr.strip().splitlines()) == 1 and not (tmp_path / "x.txt").exists()


@pytest.mark.parametrize("fmt", sorted(READERS))
def test_item19_every_question_states_the_precision_asked(banks, fmt):
    blanks = READERS[fmt](banks[fmt])
    for text, *_ in blanks:
        assert re.search(r"Give 4 significant figures; answers (within [\d.]+%|correct to \d+ "
                         r"significant figures) are accepted\.",
                         html.unescape(text)), text[-300:]


# ---- item 20: Moodle's units -------------------------------------------------------------

def _moodle_grade(question: ET.Element, response: str) -> float:
    """Moodle's numerical question grading a typed response, restated from
    question/type/numerical: the answer processor deletes the spaces, takes the number
    at the front and the rest as the unit; a listed unit scales the number, any other
    leaves it; the unit penalty applies when the unit is not a listed one
    (unitgradingtype 1: a fraction of the mark, 2: of the maximum, 0: none)."""
    units = {u.findtext("unit_name"): float(u.findtext("multiplier"))
             for u in question.findall("units/unit")}
    answer = question.find("answer")
    value, tol = float(answer.findtext("text")), float(answer.findtext("tolerance"))
    response = response.replace(" ", "")
    match = re.match(r"[+-]?(?:\d+(?:\.\d*)?|\.\d+)(?:e[-+]?\d+)?", response)
    if not match:
        return 0.0
    number, unit = float(match.group(0)), response[match.end():]
    multiplier = 1 / units[unit] if unit in units else None
    candidates = [(number * multiplier, True)] if multiplier is not None else []
    candidates.append((number, False))
    for typed, unit_right in candidates:
        if value - tol <= typed <= value + tol:
            fraction = 1.0
            if not unit_right:
                kind = int(question.findtext("unitgradingtype") or 0)
                penalty = float(question.findtext("unitpenalty") or 0.1)
                fraction = fraction - penalty * fraction if kind == 1 else \
                    fraction - penalty if kind == 2 else fraction
            return max(fraction, 0.0)
    return 0.0


def test_item20_moodle_grades_the_unit_gyro_asks(banks):
    root = ET.parse(banks["moodle"]).getroot()
    numerical = [q for q in root.findall("question") if q.get("type") == "numerical"]
    spaced = [q for q in numerical
              if "kN m" in (q.findtext("questiontext/text") or "")]
    assert spaced, "aircraft_360_kmph asks one moment in kN m"
    for question in numerical:
        value = float(question.findtext("answer/text"))
        text = question.findtext("questiontext/text")
        unit = re.search(r", in ([^<(:]+?)\s*[(:][^<]*</p>$", text).group(1)
        shown = f"{_printed(value):.{DIGITS - 1}e}"
        assert _moodle_grade(question, f"{shown} {unit}") == 1.0, (unit, text[-200:])
        assert _moodle_grade(question, f"{shown} furlongs") == 0.0
        assert "type the number and its unit" in text         # the question says so
        assert _moodle_grade(question, shown) == 0.0          # the unit is asked for
        assert _moodle_grade(question, f"{shown} rad/s") == 0.0 or unit == "rad/s"
        for name in (u.findtext("unit_name") for u in question.findall("units/unit")):
            assert " " not in name  # Moodle deletes spaces from the response first
    for question in spaced:
        value = float(question.findtext("answer/text"))
        assert _moodle_grade(question, f"{value} kN m") == 1.0
        assert _moodle_grade(question, f"{value} kN*m") == 1.0
        assert _moodle_grade(question, "201.1 rad/s") == 0.0


# ---- item 21: only what is asked ---------------------------------------------------------

def test_item21_banks_ask_only_what_the_statement_asks(banks):
    titles = [item.get("title") for item in _qti_items(banks["qti"])]
    released = [t for t in titles if t.startswith("11.2-released")]
    assert released and not any("u roots" in t for t in released)
    bicycle = [t for t in titles if t.startswith("bicycle-benchmark")]
    assert bicycle and not any(re.search(r": (M|C1|K0|K2) ", t) for t in bicycle)
    assert not any("stable speeds" in t for t in bicycle)
    pl = (banks["prairielearn"] / "11_2_released_top" / "question.html").read_text()
    assert "u_roots" not in pl


def test_item21_ask_option_and_the_ask_key(write, tmp_path):
    out = tmp_path / "b.txt"
    done = _run("export", "--to", "blackboard", PROBLEMS / "11_3.yaml", "--ask", "min_spin",
                "-o", out)
    assert done.exit_code == 0, done.output
    rows = _blackboard_blanks(out)
    assert len(rows) == 1 and "min spin" in rows[0][0].rsplit("<p>", 1)[1]
    done = _run("export", "--to", "blackboard", PROBLEMS / "11_3.yaml", "--ask", "nosuch",
                "-o", tmp_path / "n.txt")
    assert done.exit_code == 2 and "--ask" in done.stderr and "nosuch" in done.stderr
    bad = write(COLLIDING + "ask: [precesion]\n", "bad.yaml")
    done = _run("check", bad)
    assert done.exit_code == 2 and "ask (line 13)" in done.output
    assert "did you mean 'precession'" in done.output and "Traceback" not in done.output
    good = write(COLLIDING + "ask: [precession_slow]\n", "good.yaml")
    done = _run("export", "--to", "blackboard", good, "-o", tmp_path / "g.txt")
    assert done.exit_code == 0, done.output
    (row,) = _blackboard_blanks(tmp_path / "g.txt")
    assert "precession slow, in rad/s" in row[0]
    varied = write(COLLIDING + "ask: [precession_slow]\nvary:\n  spin: [0.8, 1.2]\n",
                   "varied.yaml")
    done = _run("vary", varied, "--count", 2, "-o", tmp_path / "v")
    assert done.exit_code == 0, done.output
    variants = sorted((tmp_path / "v").glob("*.yaml"))
    assert len(variants) == 2  # each variant keeps what its statement asks
    assert all(yaml.safe_load(v.read_text())["ask"] == ["precession_slow"] for v in variants)
    schema = json.loads(_run("schema").output)
    assert schema["properties"]["ask"]["type"] == "array"


# ---- item 22: word answers as multiple choice ---------------------------------------------

def _words(stem: str) -> tuple[tuple[str, ...], str]:
    """The kind's words for the file's word answer, and the solver's word."""
    from gyro_cli import kinds

    data = yaml.safe_load((PROBLEMS / f"{stem}.yaml").read_text())
    name = "motion" if "motion" in data["find"] else "effect"
    (word,) = gyro_cli.solve(data).answers[name].values
    return kinds.get(data["kind"]).answer(name).words, word


def test_item22_word_answers_are_multiple_choice_in_every_format(banks, tmp_path):
    cases = {"11_2_released_top": "motion", "ship_steering_3500kg": "effect"}
    for stem, name in cases.items():
        words, word = _words(stem)
        assert len(words) >= 2 and word in words
        # Moodle: a cloze drop-down, the solver's word the one right answer
        root = ET.parse(banks["moodle"]).getroot()
        texts = [q.findtext("questiontext/text") for q in root.findall("question")]
        menus = [m for t in texts for m in re.findall(r"\{1:MULTICHOICE:([^}]*)\}", t or "")]
        assert "~".join(("=" if w == word else "") + w for w in words) in menus, stem
        # QTI: a multiple-choice item whose right ident is the label of the word
        ident = str(yaml.safe_load((PROBLEMS / f"{stem}.yaml").read_text())["id"])
        items = [i for i in _qti_items(banks["qti"]) if i.find(f".//{QTI}response_lid")
                 is not None and i.get("title").startswith(ident)]
        assert items, stem
        for item in items:
            labels = {lab.get("ident"): lab.findtext(f".//{QTI}mattext")
                      for lab in item.iter(f"{QTI}response_label")}
            right = item.find(f".//{QTI}varequal").text
            assert item.get("title").endswith(f": {name}")
            if stem == "11_2_released_top" or "variant 1" in item.get("title"):
                assert tuple(labels.values()) == words and labels[right] == word
        # PrairieLearn: pl-multiple-choice, exactly the solver's word marked correct
        question = banks["prairielearn"] / stem
        data = _pl_generate(question / "server.py", 0)
        page = _pl_page((question / "question.html").read_text(), data["params"])
        block = re.search(rf'<pl-multiple-choice answers-name="{name}">(.*?)'
                          r"</pl-multiple-choice>", page, re.S).group(1)
        answers = re.findall(r'<pl-answer correct="(\w+)">([^<]*)</pl-answer>', block)
        assert tuple(w for _, w in answers) == words
        assert [w for c, w in answers if c == "true"] == [word]
    # a word answer asked alone is a Moodle multichoice question
    done = _run("export", "--to", "moodle", PROBLEMS / "11_2_released_top.yaml", "--ask",
                "motion", "-o", tmp_path / "w.xml")
    assert done.exit_code == 0, done.output
    (question,) = ET.parse(tmp_path / "w.xml").getroot().findall("question[@type='multichoice']")
    right = [a.findtext("text") for a in question.findall("answer") if a.get("fraction") == "100"]
    assert right == ["cusps"] and question.findtext("single") == "true"
    assert len(question.findall("answer")) == len(_words("11_2_released_top")[0])


def test_item22_the_worked_answers_picture_travels_with_the_feedback(banks):
    """The released top's axis path (and the bicycle's eigenvalues) as a PNG packaged with
    the feedback: Moodle's @@PLUGINFILE@@ with the file in base64, a file of the QTI zip
    listed in the manifest, a clientFilesQuestion file shown by pl-figure."""
    import base64

    png = b"\x89PNG\r\n\x1a\n"
    root = ET.parse(banks["moodle"]).getroot()
    category = None
    pictured = []
    for question in root.findall("question"):
        if question.get("type") == "category":
            category = question.findtext("category/text")
            continue
        feedback = question.find("generalfeedback")
        files = feedback.findall("file")
        if "released" in category or "bicycle" in category:
            (file,) = files
            assert file.get("encoding") == "base64" and file.get("path") == "/"
            assert base64.b64decode(file.text).startswith(png)
            assert f'src="@@PLUGINFILE@@/{file.get("name")}"' in feedback.findtext("text")
            pictured.append(category)
        else:
            assert not files and "<img" not in feedback.findtext("text")
    assert len(pictured) == 2
    with zipfile.ZipFile(banks["qti"]) as archive:
        manifest = ET.fromstring(archive.read("imsmanifest.xml"))
        listed = {f.get("href") for f in manifest.iter(f"{CP}file")}
        [figure] = [n for n in archive.namelist() if n.startswith("11_2_released_top/figure-")]
        assert archive.read(figure).startswith(png) and figure in listed
        name = _unguessable(figure.split("/")[-1], archive.read(figure))
        feedback = ET.fromstring(archive.read("11_2_released_top/11_2_released_top.xml")).find(
            f".//{QTI}itemfeedback//{QTI}mattext").text
        assert f'<img src="{name}" alt="Path of the top' in feedback
        assert set(archive.namelist()) == listed | {"imsmanifest.xml"}
    question = banks["prairielearn"] / "11_2_released_top"
    [path] = (question / "clientFilesQuestion").glob("figure-*.png")
    assert path.read_bytes().startswith(png)
    name = _unguessable(path.name, path.read_bytes())
    page = _pl_page((question / "question.html").read_text(),
                    _pl_generate(question / "server.py", 0)["params"])
    assert re.search(rf'<pl-answer-panel>.*<pl-figure file-name="{re.escape(name)}" '
                     r'directory="clientFilesQuestion" alt="Path of the top', page, re.S)
    plain = banks["prairielearn"] / "11_3"
    page = _pl_page((plain / "question.html").read_text(),
                    _pl_generate(plain / "server.py", 0)["params"])
    assert "<pl-figure" not in page and not (plain / "clientFilesQuestion").exists()


def _unguessable(name: str, data: bytes) -> str:
    """A picture's name in a package holds a digest of the picture: PrairieLearn serves
    clientFilesQuestion to whoever can open the question, and a plot prints its answers
    (an adversarial pass fetched figure-1.png before submitting)."""
    import hashlib

    assert name == f"figure-1-{hashlib.sha256(data).hexdigest()[:16]}.png", name
    return name


# ---- the platforms' schemas --------------------------------------------------------------

class _LocalXml(etree.Resolver):
    """The XSDs import the W3C's xml.xsd by its web address: the copy here instead."""

    def resolve(self, url, pubid, context):
        if url.endswith("xml.xsd"):
            return self.resolve_filename(str(SCHEMAS / "qti12" / "xml.xsd"), context)
        return None


def _xsd(path: Path) -> etree.XMLSchema:
    parser = etree.XMLParser(no_network=True)
    parser.resolvers.add(_LocalXml())
    return etree.XMLSchema(etree.parse(str(path), parser))


def test_qti_and_manifest_validate_against_the_ims_schemas(banks):
    qti = _xsd(SCHEMAS / "qti12" / "domainProfile_4" / "ims_qtiasiv1p2.xsd")
    cp = _xsd(SCHEMAS / "imscp" / "imscp_v1p1.xsd")
    with zipfile.ZipFile(banks["qti"]) as archive:
        manifest = etree.fromstring(archive.read("imsmanifest.xml"))
        cp.assertValid(manifest)
        files = [name for name in archive.namelist()
                 if name != "imsmanifest.xml" and name.endswith(".xml")]
        assert len(files) == len(FILES)
        for name in files:
            qti.assertValid(etree.fromstring(archive.read(name)))


_PL_FORMATS = jsonschema.FormatChecker()


@_PL_FORMATS.checks("number", raises=ValueError)
def _number(text: object) -> bool:
    return not isinstance(text, str) or math.isfinite(float(text))


@_PL_FORMATS.checks("integer", raises=ValueError)
def _integer(text: object) -> bool:
    return not isinstance(text, str) or int(text) == int(text)


@_PL_FORMATS.checks("boolean")
def _boolean(text: object) -> bool:
    return not isinstance(text, str) or text.lower() in ("true", "false")


def test_prairielearn_validates_against_its_schemas(banks):
    info_schema = json.loads((SCHEMAS / "prairielearn" / "infoQuestion.json").read_text())
    input_schema = json.loads((SCHEMAS / "prairielearn" / "pl-number-input.json").read_text())
    questions = sorted(p for p in banks["prairielearn"].iterdir() if p.is_dir())
    assert len(questions) == len(FILES)
    pages = 0
    for question in questions:
        info = json.loads((question / "info.json").read_text())
        jsonschema.validate(info, info_schema, format_checker=jsonschema.FormatChecker())
        template = (question / "question.html").read_text()
        for seed in range(1 if info["singleVariant"] else 2):
            page = _pl_page(template, _pl_generate(question / "server.py", seed)["params"])
            inputs = _pl_inputs(page)
            assert inputs and "{{" not in page
            for attrs in inputs:
                jsonschema.validate(attrs, input_schema, format_checker=_PL_FORMATS)
            pages += 1
    assert pages >= len(FILES)


#: Moodle's cloze grammar for a numerical blank (question/type/multianswer/questiontype.php:
#: ANSWER_START_REGEX, then alternatives; a NUMERICAL alternative's answer must match
#: NUMERICAL_ALTERNATIVE_REGEX, number and optional ":" absolute error)
_NUMBER = r"-?(([0-9]+[.,]?[0-9]*|[.,][0-9]+)([eE][-+]?[0-9]+)?)"
_NUMERICAL_ALTERNATIVE = re.compile(rf"^({_NUMBER})(:{_NUMBER})?$")
_SUBQUESTION = re.compile(r"\{([0-9]*):(NUMERICAL|NM|MULTICHOICE[A-Z_]*|MC[A-Z]*|"
                          r"SHORTANSWER|SA|MW):(.*?)(?<!\\)\}")


def test_moodle_xml_parses_and_its_cloze_is_what_moodle_reads(banks):
    root = ET.parse(banks["moodle"]).getroot()
    assert root.tag == "quiz"
    cloze = [q for q in root.findall("question") if q.get("type") == "cloze"]
    assert cloze
    for question in cloze:
        text = question.findtext("questiontext/text")
        found = _SUBQUESTION.findall(text)
        assert len(found) >= 2 and text.count("{") == len(found)  # nothing else looks like one
        for weight, kind, body in found:
            assert kind in ("NUMERICAL", "MULTICHOICE") and weight == "1"
            alternatives = re.split(r"(?<!\\)~", body)
            assert sum(a.startswith("=") for a in alternatives) == 1, body
            if kind == "NUMERICAL":
                (alternative,) = alternatives
                assert _NUMERICAL_ALTERNATIVE.match(alternative[1:]), alternative
            else:  # no unescaped } # / " in an answer
                assert len(alternatives) >= 2 and not any(
                    re.search(r'(?<!\\)[}#/"]', a) for a in alternatives), body
    for question in root.findall("question[@type='numerical']"):
        assert float(question.findtext("answer/tolerance")) > 0
