"""`gyro export`: question banks for Moodle, QTI 1.2, Blackboard Learn and PrairieLearn
(issue 28).

Every bundled problem is exported in the four formats (two variants where the
file has a `vary` block); each export is parsed back here with the standard
library and every number in it is compared with what the public API
(`gyro_cli.solve`) gives for the same variant, the variants being written by
`gyro vary` itself. Tolerances are checked against the problem's own tolerance
text, read here with a regular expression (not gyro's parser). PrairieLearn's
info.json is validated against the rules of PrairieLearn's question schema
(apps/prairielearn/src/schemas/schemas/infoQuestion.json: required uuid, type,
title, topic; no other keys than it lists), restated below.
"""

from __future__ import annotations

import csv
import json
import math
import re
import uuid
import xml.etree.ElementTree as ET
import zipfile
from pathlib import Path

import jsonschema
import pytest
import yaml
from conftest import PROBLEMS, read_yaml

import gyro_cli
from gyro_cli.render import html

VARIANTS = 2

QTI = "{http://www.imsglobal.org/xsd/ims_qtiasiv1p2}"
CP = "{http://www.imsglobal.org/xsd/imscp_v1p1}"

#: PrairieLearn's question info schema, the parts an export uses: its required keys,
#: the uuid pattern, the type enum, tags as strings, and no keys it does not list
PL_INFO_SCHEMA = {
    "type": "object",
    "required": ["uuid", "type", "title", "topic"],
    "additionalProperties": False,
    "properties": {
        "uuid": {"type": "string", "pattern": "^[0-9a-fA-F]{8}-[0-9a-fA-F]{4}-[0-9a-fA-F]{4}-"
                                              "[0-9a-fA-F]{4}-[0-9a-fA-F]{12}$"},
        "type": {"enum": ["Calculation", "MultipleChoice", "Checkbox", "File",
                          "MultipleTrueFalse", "v3"]},
        "title": {"type": "string"}, "topic": {"type": "string"},
        "tags": {"type": "array", "items": {"type": "string"}},
        "singleVariant": {"type": "boolean"}, "comment": {},
        "clientFiles": {"type": "array"}, "gradingMethod": {"enum": ["Internal", "External",
                                                                     "Manual"]},
        "partialCredit": {"type": "boolean"}, "showCorrectAnswer": {"type": "boolean"},
    },
}


# ---- the reference: gyro vary's files, solved through the public API -------------------

def _reference(path: Path, tmp: Path, run) -> dict[int, list[float]]:
    """Variant number -> the sorted numbers the export must hold, from gyro_cli.solve."""
    data = read_yaml(path.read_text())
    if "vary" in data:
        out_dir = tmp / path.stem
        done = run("vary", path, "--count", VARIANTS, "--seed", 0, "-o", out_dir)
        assert done.exit_code == 0, done.output
        files = sorted(out_dir.glob("*.yaml"))
    else:
        files = [path]
    out = {}
    for n, file in enumerate(files, 1):
        variant = read_yaml(file.read_text())
        find = variant["find"] if isinstance(variant["find"], dict) else \
            {name: None for name in variant["find"]}
        for name in variant.get("expected") or {}:
            find.setdefault(name, None)
        variant["find"] = find
        result = gyro_cli.solve(variant)
        magnitude = "magnitude" in str(variant.get("tolerance", ""))
        asked = variant.get("ask") or list(result.answers)  # a bank asks what `ask` names
        numbers = [abs(v) if magnitude else v for name, answer in result.answers.items()
                   if name in asked for v in answer.values if not isinstance(v, str)]
        out[n] = sorted(numbers)
    return out


def remembered(patch: pytest.MonkeyPatch, module, name: str) -> None:
    """``module.name`` (a function of one solved problem) made to answer a second call for
    the same problem from the first (the problem's repr: its data, what it finds, its
    units) instead of working again."""
    real = getattr(module, name)
    memo: dict[tuple, object] = {}

    def once(result, *args, **kwargs):
        key = (repr(result.problem), args, tuple(sorted(kwargs.items())))
        if key not in memo:
            memo[key] = real(result, *args, **kwargs)
        return memo[key]

    patch.setattr(module, name, once)


@pytest.fixture(scope="module")
def exported(tmp_path_factory):
    """The four exports of every bundled problem, and the reference numbers."""
    from click.testing import CliRunner

    from gyro_cli.cli import main

    tmp = tmp_path_factory.mktemp("export")

    def run(*args):
        return CliRunner().invoke(main, [str(a) for a in args])

    out = {}
    with pytest.MonkeyPatch.context() as patch:
        # The four formats lay out the same variants: each worked answer is typeset once
        # (most of an export's time), not once per format.
        remembered(patch, html, "worked_answer")
        for fmt, target in (("moodle", tmp / "bank.xml"), ("qti", tmp / "bank.zip"),
                            ("blackboard", tmp / "bank.txt"), ("prairielearn", tmp / "pl")):
            # (pictures are drawn by matplotlib, slowly: tests/test_i34_banks.py checks them)
            done = run("export", "--to", fmt, PROBLEMS, "--variants", VARIANTS,
                       "--no-pictures", "-o", target)
            assert done.exit_code == 0, done.output
            out[fmt] = target
            out[f"{fmt} stderr"] = done.stderr
    reference = {}
    for path in sorted(PROBLEMS.glob("*.yaml")):
        numbers = _reference(path, tmp / "vary", run)
        if any(numbers.values()):  # a problem with word answers only is not exported
            reference[path.stem] = numbers
    assert len(reference) >= 60
    out["reference"] = reference
    return out


def _accepted(half: float, value: float) -> float:
    """What a blank accepts around ``value`` for a problem tolerance of ``half``: that,
    unless it is tighter than rounding to 4 significant figures (the figures the feedback
    prints), then the student tolerance, 1% (issue 34)."""
    least = 0.5 * 10.0 ** (math.floor(math.log10(abs(value))) - 3) if value else 0.0
    return half if half >= least * (1 - 1e-9) else max(0.01 * abs(value), least)


def _same(got: list[float], want: list[float]) -> None:
    assert len(got) == len(want), (got, want)
    for g, w in zip(sorted(got), want):
        assert math.isclose(g, w, rel_tol=1e-12, abs_tol=1e-300), (got, want)


# ---- Moodle XML --------------------------------------------------------------------

CLOZE = re.compile(r"\{1:NUMERICAL:=([^:}]+):([^}]+)\}")


def _moodle(path: Path) -> dict[str, dict[int, list[tuple[float, float]]]]:
    """category -> variant -> [(answer, tolerance)], from the Moodle XML file."""
    root = ET.parse(path).getroot()
    assert root.tag == "quiz"
    out: dict = {}
    category = None
    for question in root.findall("question"):
        kind = question.get("type")
        if kind == "category":
            category = question.findtext("category/text")
            out[category] = {}
            continue
        assert category is not None, "a question before any category"
        name = question.findtext("name/text")
        match = re.search(r"variant (\d+)$", name)
        n = int(match.group(1)) if match else 1
        text = question.findtext("questiontext/text")
        assert question.find("questiontext").get("format") == "html"
        assert "<math" in question.findtext("generalfeedback/text")
        if kind == "numerical":
            answers = question.findall("answer")
            assert len(answers) == 1 and answers[0].get("fraction") == "100"
            pairs = [(float(answers[0].findtext("text")),
                      float(answers[0].findtext("tolerance")))]
        elif kind == "multichoice":  # a word answer alone (issue 34): no number
            pairs = []
        else:
            assert kind == "cloze"
            pairs = [(float(v), float(t)) for v, t in CLOZE.findall(text)]
            assert len(pairs) >= (1 if "{1:MULTICHOICE:" in text else 2)
        out[category][n] = pairs
    return out


def _stem_of(title_or_slug: str, reference: dict) -> str:
    return title_or_slug if title_or_slug in reference else ""


def test_moodle_export_holds_the_solvers_answers(exported):
    bank = _moodle(exported["moodle"])
    reference = exported["reference"]
    assert len(bank) == len(reference)
    by_id = {}
    for path in PROBLEMS.glob("*.yaml"):
        data = read_yaml(path.read_text())
        title = f"{data['id']}: {data['title']}" if data.get("title") else str(data["id"])
        by_id["$course$/top/gyro/" + " ".join(title.split()).replace("/", "//")] = path.stem
    for category, variants in bank.items():
        stem = by_id[category]
        want = reference[stem]
        assert sorted(variants) == sorted(want), category
        for n, pairs in variants.items():
            _same([v for v, _ in pairs], want[n])


def test_moodle_tolerance_is_the_problems(exported, run, tmp_path):
    """11/3 as written asks 1%: the +/- error of each answer is 1% of it (the book's
    45.1 rpm and 533 rpm roots, least spin 965 rpm)."""
    done = run("export", "--to", "moodle", PROBLEMS / "11_3.yaml", "-o", tmp_path / "m.xml")
    assert done.exit_code == 0, done.output
    (pairs,) = _moodle(tmp_path / "m.xml")[
        "$course$/top/gyro/11//3: Top with two possible rates of steady precession"].values()
    assert [round(v, 2) for v, _ in pairs] == [45.13, 533.53, 965.41]
    for value, tol in pairs:
        assert tol == pytest.approx(0.01 * value, rel=1e-12)
    bank = _moodle(exported["moodle"])
    # Every problem with a relative tolerance (one for the file): error = fraction * |answer|
    for path in PROBLEMS.glob("*.yaml"):
        data = read_yaml(path.read_text())
        match = re.fullmatch(r"([\d.]+)%", str(data.get("tolerance", "1%")))
        if not match or path.stem not in exported["reference"]:
            continue
        title = f"{data['id']}: {data['title']}" if data.get("title") else str(data["id"])
        category = "$course$/top/gyro/" + " ".join(title.split()).replace("/", "//")
        for pairs in bank[category].values():
            for value, tol in pairs:
                want = _accepted(float(match.group(1)) / 100 * abs(value), value)
                assert tol == pytest.approx(want, rel=1e-9, abs=1e-300), path.name


def test_moodle_units_and_question_types(exported):
    root = ET.parse(exported["moodle"]).getroot()
    numerical = [q for q in root.findall("question") if q.get("type") == "numerical"]
    spin = next(q for q in numerical if q.findtext("name/text").startswith("11/1"))
    assert spin.findtext("units/unit/unit_name") == "rpm"
    assert spin.findtext("units/unit/multiplier") == "1"
    assert "spin, in rpm" in spin.findtext("questiontext/text")
    assert str(PROBLEMS) not in exported["moodle"].read_text()  # no local path in a bank
    names = [q.findtext("name/text") for q in root.findall("question")
             if q.get("type") != "category"]
    categories = len(root.findall("question[@type='category']"))
    assert len(set(names)) == len(names) == len(root.findall("question")) - categories


# ---- QTI 1.2 -------------------------------------------------------------------------

#: the order of an item's children in the QTI 1.2 ASI schema (itemType's sequence)
ITEM_ORDER = ["qticomment", "duration", "itemmetadata", "objectives", "itemcontrol",
              "itemprecondition", "itempostcondition", "itemrubric", "rubric", "presentation",
              "resprocessing", "itemproc_extension", "itemfeedback", "reference"]


def test_qti_package_holds_the_solvers_answers(exported):
    reference = exported["reference"]
    with zipfile.ZipFile(exported["qti"]) as archive:
        manifest = ET.fromstring(archive.read("imsmanifest.xml"))
        assert manifest.tag == f"{CP}manifest"
        resources = manifest.findall(f"{CP}resources/{CP}resource")
        assert len(resources) == len(reference)
        assert set(archive.namelist()) == {"imsmanifest.xml"} | {r.get("href") for r in resources}
        for resource in resources:
            assert resource.get("type") == "imsqti_xmlv1p2"
            assert resource.find(f"{CP}file").get("href") == resource.get("href")
            root = ET.fromstring(archive.read(resource.get("href")))
            assert root.tag == f"{QTI}questestinterop"
            stem = resource.get("href").split("/")[0]
            numbers: dict[int, list[float]] = {}
            for item in root.iter(f"{QTI}item"):
                children = [c.tag.removeprefix(QTI) for c in item]
                assert children == sorted(children, key=ITEM_ORDER.index), children
                fields = {f.findtext(f"{QTI}fieldlabel"): f.findtext(f"{QTI}fieldentry")
                          for f in item.iter(f"{QTI}qtimetadatafield")}
                if fields["question_type"] == "multiple_choice_question":  # a word answer
                    assert item.find(f"{QTI}presentation/{QTI}response_lid") is not None
                    continue
                assert fields["question_type"] == "numerical_question"
                match = re.search(r"variant (\d+)", item.get("title"))
                n = int(match.group(1)) if match else 1
                value = float(item.find(f".//{QTI}varequal").text)
                low = float(item.find(f".//{QTI}vargte").text)
                high = float(item.find(f".//{QTI}varlte").text)
                assert low <= value <= high
                fib = item.find(f"{QTI}presentation/{QTI}response_str/{QTI}render_fib")
                assert fib.get("fibtype") == "Decimal"
                assert "<math" in item.find(f"{QTI}itemfeedback//{QTI}mattext").text
                numbers.setdefault(n, []).append(value)
            want = reference[stem]
            assert sorted(numbers) == sorted(want), stem
            for n in want:
                _same(numbers[n], want[n])


#: the content model of every element an export writes, restated from the QTI 1.2 ASI
#: schema (ims_qtiasiv1p2.xsd, IMS Global): a regular expression over the names of an
#: element's children (each followed by a space); an element not listed is refused
_VARS = "(not|and|or|unanswered|other|varequal|varlt|varlte|vargt|vargte|varsubset|" \
        "varinside|varsubstring|durequal|durlt|durlte|durgt|durgte)"
QTI_MODEL = {
    "questestinterop": r"(qticomment )?(objectbank |assessment |((section|item) )+)",
    "assessment": r"(qticomment )?(duration )?(qtimetadata )*(objectives )*"
                  r"(assessmentcontrol )*(rubric )*(presentation_material )?"
                  r"(outcomes_processing )*(assessproc_extension )?(assessfeedback )*"
                  r"(selection_ordering )?(reference )?((sectionref|section) )+",
    "section": r"(qticomment )?(duration )?(qtimetadata )*(objectives )*(sectioncontrol )*"
               r"(sectionprecondition )*(sectionpostcondition )*(rubric )*"
               r"(presentation_material )?(outcomes_processing )*(sectionproc_extension )?"
               r"(sectionfeedback )*(selection_ordering )?(reference )?"
               r"((itemref|item|sectionref|section) )*",
    "item": r"(qticomment )?(duration )?(itemmetadata )?(objectives )*(itemcontrol )*"
            r"(itemprecondition )*(itempostcondition )*((itemrubric|rubric) )*(presentation )?"
            r"(resprocessing )*(itemproc_extension )?(itemfeedback )*(reference )?",
    "itemmetadata": r"(qtimetadata )*",
    "qtimetadata": r"(vocabulary )?(qtimetadatafield )+",
    "qtimetadatafield": r"fieldlabel fieldentry ",
    "presentation": r"(qticomment )?(flow |((material|response_lid|response_xy|response_str|"
                    r"response_num|response_grp|response_extension) )+)",
    "material": r"(qticomment )?((mattext|matemtext|matimage|mataudio|matvideo|matapplet|"
                r"matapplication|matref|matbreak|mat_extension) )+(altmaterial )*",
    "response_str": r"((material|material_ref) )?(render_choice|render_hotspot|render_slider|"
                    r"render_fib|render_extension) ((material|material_ref) )?",
    "response_lid": r"((material|material_ref) )?(render_choice|render_hotspot|render_slider|"
                    r"render_fib|render_extension) ((material|material_ref) )?",
    "render_choice": r"((material|material_ref|response_label|flow_label) )*(response_na )?",
    "render_fib": r"((material|material_ref|response_label|flow_label) )*(response_na )?",
    "response_label": r"((qticomment|material|material_ref|flow_mat) )*",
    "resprocessing": r"(qticomment )?outcomes ((respcondition|itemproc_extension) )+",
    "outcomes": r"(qticomment )?(decvar (interpretvar )*)+",
    "respcondition": r"(qticomment )?conditionvar (setvar )*(displayfeedback )*"
                     r"(respcond_extension )?",
    "conditionvar": rf"(({_VARS[1:-1]}|var_extension) )+",
    "or": rf"({_VARS} )+", "and": rf"({_VARS} )+",
    "itemfeedback": r"((flow_mat|material|solution|hint) )+",
    "flow_mat": r"((flow_mat|material|material_ref) )+",
    **{leaf: "" for leaf in ("mattext", "varequal", "vargte", "varlte", "setvar", "decvar",
                             "displayfeedback", "fieldlabel", "fieldentry", "other")},
}
QTI_REQUIRED = {"assessment": {"ident"}, "section": {"ident"}, "item": {"ident"},
                "itemfeedback": {"ident"}, "response_str": {"ident"}, "response_lid": {"ident"},
                "response_label": {"ident"}, "displayfeedback": {"linkrefid"},
                "varequal": {"respident"}, "vargte": {"respident"}, "varlte": {"respident"}}
QTI_ENUMS = {"fibtype": {"String", "Integer", "Decimal", "Scientific"},
             "rcardinality": {"Single", "Multiple", "Ordered"}, "continue": {"Yes", "No"},
             "vartype": {"Integer", "String", "Decimal", "Scientific", "Boolean",
                         "Enumerated", "Set"},
             "feedbacktype": {"Response", "Solution", "Hint"},
             "action": {"Set", "Add", "Subtract", "Multiply", "Divide"}}


def _qti_valid(element) -> None:
    name = element.tag.removeprefix(QTI)
    assert name in QTI_MODEL, f"<{name}> is not an element an export may write"
    children = "".join(child.tag.removeprefix(QTI) + " " for child in element)
    assert re.fullmatch(QTI_MODEL[name], children), f"<{name}> holds {children!r}"
    assert QTI_REQUIRED.get(name, set()) <= set(element.attrib), (name, element.attrib)
    for attribute, allowed in QTI_ENUMS.items():
        assert element.get(attribute, next(iter(allowed))) in allowed, (name, attribute)
    for child in element:
        _qti_valid(child)


def test_qti_files_follow_the_qti_1_2_schema(exported):
    with zipfile.ZipFile(exported["qti"]) as archive:
        for name in archive.namelist():
            if name != "imsmanifest.xml":
                _qti_valid(ET.fromstring(archive.read(name)))


def test_qti_bounds_are_the_tolerance_and_the_zip_is_reproducible(exported, run, tmp_path):
    with zipfile.ZipFile(exported["qti"]) as archive:
        root = ET.fromstring(archive.read("11_3/11_3.xml"))
    for item in root.iter(f"{QTI}item"):
        value = float(item.find(f".//{QTI}varequal").text)
        low = float(item.find(f".//{QTI}vargte").text)
        high = float(item.find(f".//{QTI}varlte").text)
        assert (high - low) / 2 == pytest.approx(0.01 * value, rel=1e-9)  # tolerance: 1%
    again = tmp_path / "again.zip"
    done = run("export", "--to", "qti", PROBLEMS, "--variants", VARIANTS, "--no-pictures",
               "-o", again)
    assert done.exit_code == 0, done.output
    assert again.read_bytes() == exported["qti"].read_bytes()


# ---- Blackboard Learn (Upload Questions) -----------------------------------------------

#: a NUM line's fields: type, question text, answer, tolerance (Blackboard's "Upload
#: Questions" help page: NUM TAB question text TAB answer TAB [optional] tolerance)
NUM_FIELDS = 4


def _blackboard(path: Path) -> list[list[str]]:
    """The file's records, read as a tab-delimited file; every line a whole record."""
    data = path.read_bytes()
    assert data.isascii() and not data.startswith(b"\xef\xbb\xbf")
    assert data.endswith(b"\r\n") and b"\r\n\r\n" not in data  # no blank line
    assert data.count(b"\n") == data.count(b"\r\n") == data.count(b"\r")
    with path.open(newline="", encoding="ascii") as handle:
        rows = list(csv.reader(handle, delimiter="\t", quoting=csv.QUOTE_NONE))
    assert len(rows) == data.count(b"\r\n")
    for row in rows:
        assert len(row) == NUM_FIELDS and row[0] == "NUM", row
        assert all(re.fullmatch(r"-?\d+(\.\d+)?", number) for number in row[2:]), row
        assert float(row[3]) >= 0 and row[1].endswith(":</p>"), row
    return rows


def _question(row: list[str]) -> str:
    """The statement of a NUM line's question (its text without the last paragraph, which
    says what is asked)."""
    return row[1][:row[1].rindex("<p>")]


def test_blackboard_export_holds_the_solvers_answers(exported):
    """Every NUM line, read back, is one of the solver's numbers for its variant, within
    the tolerance the line gives; the lines come problem by problem (in file order),
    variant by variant, one per number asked."""
    rows = _blackboard(exported["blackboard"])
    reference = exported["reference"]
    assert len(rows) == sum(len(numbers) for want in reference.values()
                            for numbers in want.values())
    at = 0
    for stem, want in reference.items():  # the export's order: the files sorted
        for n in sorted(want):
            lines = rows[at:at + len(want[n])]
            at += len(want[n])
            assert len({_question(row) for row in lines}) == 1, stem  # one variant's text
            _same([float(row[2]) for row in lines], want[n])
            for row, value in zip(sorted(lines, key=lambda r: float(r[2])), want[n]):
                assert abs(float(row[2]) - value) <= float(row[3]) or value == float(row[2])
    assert at == len(rows)
    notes = exported["blackboard stderr"]
    assert "no feedback field" in notes
    assert ("recommends at most 250" in notes) == (len(rows) > 250)
    assert "word answers (multiple choice in the other formats) are not in" in notes


def test_blackboard_tolerance_is_the_problems(exported, run, tmp_path):
    """11/3 asks 1%: each NUM tolerance is 1% of its answer (45.13 and 533.53 rpm, each
    root a question saying which); every relative tolerance is made absolute around its
    variant's answer; an absolute one is itself."""
    done = run("export", "--to", "blackboard", PROBLEMS / "11_3.yaml", "-o", tmp_path / "b.txt")
    assert done.exit_code == 0, done.output
    rows = _blackboard(tmp_path / "b.txt")
    assert [round(float(r[2]), 2) for r in rows] == [45.13, 533.53, 965.41]
    assert [r[1].rsplit("<p>", 1)[1] for r in rows] == [
        "precession (slow), in rpm:</p>", "precession (fast), in rpm:</p>",
        "min spin, in rpm:</p>"]
    assert "1800 rpm" in rows[0][1] and "30 deg" in rows[0][1]
    for row in rows:
        assert float(row[3]) == pytest.approx(0.01 * float(row[2]), rel=1e-12)
    rows = _blackboard(exported["blackboard"])
    at = 0
    for stem, want in exported["reference"].items():
        lines = rows[at:at + sum(len(v) for v in want.values())]
        at += len(lines)
        tolerance = str(read_yaml((PROBLEMS / f"{stem}.yaml").read_text()).get(
            "tolerance", "1%"))
        relative = re.fullmatch(r"([\d.]+)%", tolerance)
        absolute = re.fullmatch(r"([\d.e+-]+) deg/s", tolerance)
        for row in lines:
            value = float(row[2])
            if relative:
                assert float(row[3]) == pytest.approx(_accepted(
                    float(relative.group(1)) / 100 * abs(value), value), rel=1e-9,
                    abs=1e-300), stem
            elif absolute:
                assert float(row[3]) == pytest.approx(
                    _accepted(float(absolute.group(1)), value)), stem


def test_blackboard_numbers_are_plain_decimals():
    from gyro_cli.render.bank_blackboard import number

    assert number(45.13) == "45.13" and number(-0.0) == "0" and number(3.0) == "3"
    assert number(1e-05) == "0.00001" and number(1.5e20) == "150000000000000000000"
    assert number(0.1 + 0.2) == "0.3" and number(2 / 3) == "0.6666666666666666"
    with pytest.raises(ValueError):
        number(float("nan"))


def test_blackboard_line_breaks_tabs_and_html_never_break_a_line(run, write, tmp_path):
    """A title, a statement and the data with TABs, line breaks (LF, CR, U+2028), quotes
    and HTML: each question stays one line of four fields, its text escaped."""
    path = write("""\
        id: "x/1 <i>"
        title: "Tab\\there, line\\nbreak <script>alert('t')</script> & \\"q\\" \\u2028 end"
        kind: steady_precession
        given:
          mass: 2 kg
          J: 0.01 kg m^2
          I_pivot: 0.05 kg m^2
          cg_distance: 0.1 m
          theta: 90 deg
          spin: 1800 rpm
        find:
          precession: rpm
        """)
    title = read_yaml(path.read_text())["title"]
    assert "\t" in title and "\n" in title and "\u2028" in title
    done = run("export", "--to", "blackboard", path, "-o", tmp_path / "b.txt")
    assert done.exit_code == 0, done.output
    (row,) = _blackboard(tmp_path / "b.txt")
    assert "<script>" not in row[1] and "&lt;script&gt;" in row[1]
    assert "&quot;q&quot;" in row[1] and "&amp;" in row[1]
    path = write("""\
        id: s
        kind: steady_precession
        statement: "A <script>x</script>\\ttop\\r\\nat {spin}.\\n\\nIt \\u00e9 \\u03c9."
        given:
          mass: 2 kg
          J: 0.01 kg m^2
          I_pivot: 0.05 kg m^2
          cg_distance: 0.1 m
          theta: 90 deg
          spin: 1800 rpm
        find:
          precession: rpm
        """, "s.yaml")
    done = run("export", "--to", "blackboard", path, "-o", tmp_path / "s.txt")
    assert done.exit_code == 0, done.output
    (row,) = _blackboard(tmp_path / "s.txt")
    assert row[1].startswith("<p>A &lt;script&gt;x&lt;/script&gt; top at 1800 rpm.</p>")
    assert "<p>It &#233; &#969;.</p>" in row[1]  # ASCII: character references


def test_blackboard_fields_hold_no_tab_or_line_break_whatever_the_html(tmp_path):
    """The renderer itself, given HTML with every kind of line break and control
    character: one line per question, four fields."""
    from gyro_cli.render import bank_blackboard
    from gyro_cli.render.bank import Blank, ProblemBank, Variant

    nasty = "<p>a\tb\nc\rd\x0be\x0cf\x1cg\x85h\u2028i\u2029j\x00k \u03c9</p>"
    blanks = [Blank(k, k, 45.0, "rpm\t\n", 0.45, "1%", "relative", 0.01)
              for k in ("slow", "fast")]
    bank = ProblemBank("t", "T", "steady_precession", "", "t", "steady precession",
                       [Variant(1, "t", {}, nasty, "<p>worked</p>", blanks)])
    out = tmp_path / "t.txt"
    out.write_bytes(bank_blackboard.text([bank]).encode("ascii"))
    rows = _blackboard(out)
    assert len(rows) == 2
    assert rows[0][1].startswith("<p>a b c d e f g h i j k &#969;</p>")
    assert rows[0][1].endswith("<p>slow, in rpm  :</p>") and rows[0][2:] == ["45", "0.45"]


def test_blackboard_many_questions_are_reported(run, tmp_path):
    done = run("export", "--to", "blackboard", PROBLEMS / "11_3.yaml", "--variants", 90,
               "-o", tmp_path / "b.txt")
    assert done.exit_code == 0, done.output
    assert len(_blackboard(tmp_path / "b.txt")) > 250
    assert "recommends at most 250 per uploaded file" in done.stderr
    done = run("export", "--to", "blackboard", PROBLEMS / "11_3.yaml", "-o", tmp_path / "c.txt")
    assert "recommends" not in done.stderr and "(3 NUM questions)" in done.stderr


# ---- PrairieLearn --------------------------------------------------------------------

def _generate(server: Path, seed: int) -> dict:
    namespace: dict = {}
    exec(compile(server.read_text(), str(server), "exec"), namespace)  # our own output
    data = {"variant_seed": seed, "params": {}, "correct_answers": {}}
    namespace["generate"](data)
    return data


#: pl-number-input's attributes (PrairieLearn docs/elements/pl-number-input.md)
PL_NUMBER_INPUT = {"allow-blank", "allow-complex", "allow-fractions", "answers-name",
                   "aria-label", "atol", "blank-value", "comparison", "correct-answer",
                   "custom-format", "digits", "display", "initial-value", "label",
                   "placeholder", "rtol", "show-correct-answer", "show-help-text",
                   "show-placeholder", "show-score", "size", "suffix", "weight"}


def _mustache(template: str, params: dict) -> str:
    """The mustache a question.html uses, rendered: {{#params.ask.KEY}}...{{/...}}
    sections kept where ``params["ask"]`` has KEY, {{{params.NAME}}} inserted as it is."""
    def section(match: re.Match) -> str:
        found = params
        for name in match.group(1).split("."):
            found = found.get(name) if isinstance(found, dict) else None
        return match.group(2) if found else ""
    out = re.sub(r"\{\{#params\.([\w.]+)\}\}(.*?)\{\{/params\.\1\}\}", section,
                 template, flags=re.S)
    out = re.sub(r"\{\{\{params\.(\w+)\}\}\}", lambda m: params[m.group(1)], out)
    out = re.sub(r"\{\{params\.(\w+)\.(\w+)\.(\w+)\}\}",
                 lambda m: str(params[m.group(1)][m.group(2)][m.group(3)]), out)
    return re.sub(r"\{\{params\.(\w+)\.(\w+)\}\}",
                  lambda m: str(params[m.group(1)][m.group(2)]), out)


def test_prairielearn_questions_hold_the_solvers_answers(exported):
    reference = exported["reference"]
    root = exported["prairielearn"]
    questions = sorted(p for p in root.iterdir() if p.is_dir())
    assert len(questions) == len(reference)
    uuids = set()
    for question in questions:
        info = json.loads((question / "info.json").read_text())
        jsonschema.validate(info, PL_INFO_SCHEMA)
        assert uuid.UUID(info["uuid"]).version == 5
        uuids.add(info["uuid"])
        want = reference[question.name]
        assert info["singleVariant"] == (len(want) == 1)
        html = (question / "question.html").read_text()
        inputs = re.findall(r'<pl-number-input answers-name="(\w+)"', html)
        assert len(inputs) == len(set(inputs))
        for name in inputs:  # each input shows only in the variants that ask it
            assert f"{{{{#params.ask.{name}}}}}" in html
        for element in re.findall(r"<pl-number-input ([^>]*)>", html):
            attributes = dict(re.findall(r'([\w-]+)="([^"]*)"', element))
            assert set(attributes) <= PL_NUMBER_INPUT, attributes
            assert attributes["comparison"] in ("relabs", "sigfig", "decdig")
        got = {}
        for seed in range(len(want)):
            data = _generate(question / "server.py", seed)
            answers = data["correct_answers"]
            assert set(answers) <= set(inputs) and set(answers) == set(data["params"]["ask"])
            assert "<math" in data["params"]["feedback"]
            page = _mustache(html, data["params"])
            assert re.findall(r'<pl-number-input answers-name="(\w+)"', page) == list(answers)
            assert data["params"]["statement"] in page and "{{" not in page
            got[seed + 1] = list(answers.values())
        for n in want:
            _same(got[n], want[n])
    assert len(uuids) == len(reference)


def test_prairielearn_tolerances_are_attributes(exported):
    """Each input's atol is its variant's half-width (a param): 1% of the answer for 11/3
    (tolerance 1%), and the student tolerance, 1%, where the problem asks more than the 4
    figures the feedback prints (the bicycle's 12 sig, euler's 1e-9 deg/s)."""
    def widths(stem: str) -> list[tuple[float, float]]:
        question = exported["prairielearn"] / stem
        html = (question / "question.html").read_text()
        data = _generate(question / "server.py", 0)
        page = _mustache(html, data["params"])
        return [(data["correct_answers"][name], float(atol)) for name, atol in re.findall(
            r'answers-name="(\w+)" comparison="relabs" rtol="0" atol="([^"]+)"', page)]

    html = (exported["prairielearn"] / "11_3" / "question.html").read_text()
    assert 'answers-name="precession_slow" comparison="relabs" rtol="0" ' \
           'atol="{{params.atol.precession_slow}}"' in html
    assert 'suffix="rpm"' in html and 'label="precession (slow) ="' in html
    tolerances = {"11_3": lambda v: 0.01 * abs(v),            # tolerance: 1%
                  "bicycle_benchmark": lambda v: 0.5e-11 * abs(v),  # 12 sig (about)
                  "euler_aircraft_zyx": lambda v: 1e-9}             # 1e-9 deg/s
    for stem, problem_half in tolerances.items():
        pairs = widths(stem)
        assert pairs, stem
        for value, atol in pairs:
            want = _accepted(problem_half(value), value) if value else \
                (1e-9 if stem == "euler_aircraft_zyx" else 0.0)
            assert atol == pytest.approx(want, rel=1e-9, abs=1e-300), (stem, value)


def test_uuids_are_stable_across_exports(exported, run, tmp_path):
    done = run("export", "--to", "prairielearn", PROBLEMS / "11_3.yaml", "-o", tmp_path)
    assert done.exit_code == 0, done.output
    first = json.loads((exported["prairielearn"] / "11_3" / "info.json").read_text())
    again = json.loads((tmp_path / "11_3" / "info.json").read_text())
    assert first["uuid"] == again["uuid"]


# ---- user text never breaks the output ------------------------------------------------

HOSTILE = 'A <b>bold</b> & \\"top\\" ]]> {1:NUMERICAL:=1:0} {{params.x}} --> \\x01 end'  # YAML


def test_hostile_text_is_escaped_in_every_format(run, write, tmp_path):
    path = write(f"""\
        id: "x/1 <i>"
        title: "{HOSTILE}"
        kind: steady_precession
        source: "]]><evil/>"
        statement: "A <b>top</b> {{{{1:NUMERICAL:=1:0}}}} {{{{params.x}}}} spins at {{spin}}."
        notes: ["{HOSTILE}"]
        given:
          mass: 2 kg
          J: 0.01 kg m^2
          I_pivot: 0.05 kg m^2
          cg_distance: 0.1 m
          theta: 90 deg
          spin: 1800 rpm
        find:
          precession: rpm
        """)
    title = read_yaml(path.read_text())["title"]
    assert "\x01" in title and "]]>" in title
    for fmt, out in (("moodle", tmp_path / "m.xml"), ("qti", tmp_path / "q.zip"),
                     ("prairielearn", tmp_path / "pl")):
        done = run("export", "--to", fmt, path, "-o", out)
        assert done.exit_code == 0, done.output
    root = ET.parse(tmp_path / "m.xml").getroot()         # parses: nothing broke the XML
    question = root.findall("question")[1]
    assert question.get("type") == "numerical"  # theta = 90 deg: one root
    text = question.findtext("questiontext/text")
    assert "{1:NUMERICAL" not in text and "&lt;b&gt;top" in text and "\x01" not in text
    assert "&#123;1:NUMERICAL:=1:0&#125;" in text and "spins at 1800 rpm" in text
    assert root.find("question/category/text").text.startswith("$course$/top/gyro/x//1 <i>")
    with zipfile.ZipFile(tmp_path / "q.zip") as archive:
        for name in archive.namelist():
            ET.fromstring(archive.read(name))
    pl = next((tmp_path / "pl").iterdir())
    info = json.loads((pl / "info.json").read_text())
    assert info["title"] == "x/1 <i>: " + title
    html = (pl / "question.html").read_text()
    assert "{{params.x}}" not in html and "<b>" not in html
    assert html.count("<!--") == 1 and html.count("-->") == 1
    compile((pl / "server.py").read_text(), "server.py", "exec")
    data = _generate(pl / "server.py", 0)
    assert "{1:NUMERICAL" not in data["params"]["statement"]
    assert "{{params.x}}" not in data["params"]["statement"]
    assert "&lt;b&gt;" in data["params"]["statement"]


def test_question_text_is_the_statement_with_each_variants_numbers(run, tmp_path):
    """11/3's statement names {spin} and {theta}: as written the question reads 1800 rpm
    and 30 deg, and each variant reads the numbers gyro vary gave it."""
    statement = read_yaml((PROBLEMS / "11_3.yaml").read_text())["statement"]
    assert "{spin}" in statement and "{theta}" in statement
    done = run("export", "--to", "moodle", PROBLEMS / "11_3.yaml", "-o", tmp_path / "a.xml")
    assert done.exit_code == 0, done.output
    text = ET.parse(tmp_path / "a.xml").getroot().findall("question")[1].findtext(
        "questiontext/text")
    assert "1800 rpm" in text and "30 deg" in text and "{" not in text.split("<ul>")[0]
    done = run("export", "--to", "moodle", PROBLEMS / "11_3.yaml", "--variants", 3, "-o",
               tmp_path / "v.xml")
    assert done.exit_code == 0, done.output
    done = run("vary", PROBLEMS / "11_3.yaml", "--count", 3, "-o", tmp_path / "v")
    assert done.exit_code == 0, done.output
    questions = ET.parse(tmp_path / "v.xml").getroot().findall("question")[1:]
    for question, file in zip(questions, sorted((tmp_path / "v").glob("*.yaml"))):
        given = read_yaml(file.read_text())["given"]
        text = question.findtext("questiontext/text")
        assert given["spin"] in text and given["theta"] in text, (given, text)


def test_question_text_without_a_statement_is_built_from_the_data():
    from gyro_cli.render.bank import statement_html

    assert statement_html("First <b>.\n\nSecond {1:NUMERICAL:=1}.", "ignored", [], []) == \
        "<p>First &lt;b&gt;.</p><p>Second &#123;1:NUMERICAL:=1&#125;.</p>"
    fallback = statement_html(None, "A top", [("spin", "1800 rpm")], ["precession, in rpm"])
    assert fallback == ("<p>A top.</p><p>Data:</p><ul><li>spin: 1800 rpm</li></ul>"
                        "<p>Find precession, in rpm.</p>")


# ---- bad input: one line, exit 2, nothing overwritten ---------------------------------

def test_existing_output_is_not_overwritten_without_force(run, tmp_path):
    out = tmp_path / "bank.xml"
    out.write_text("mine")
    done = run("export", "--to", "moodle", PROBLEMS / "11_3.yaml", "-o", out)
    assert done.exit_code == 2
    assert "exists; not overwritten" in done.stderr and len(done.stderr.splitlines()) == 1
    assert out.read_text() == "mine"
    done = run("export", "--to", "moodle", PROBLEMS / "11_3.yaml", "-o", out, "--force")
    assert done.exit_code == 0 and out.read_text().startswith("<?xml")
    pl = tmp_path / "pl"
    assert run("export", "--to", "prairielearn", PROBLEMS / "11_3.yaml", "-o", pl).exit_code == 0
    (pl / "11_3" / "server.py").write_text("# mine\n")
    done = run("export", "--to", "prairielearn", PROBLEMS / "11_3.yaml", "-o", pl)
    assert done.exit_code == 2 and "exists; not overwritten" in done.stderr
    assert (pl / "11_3" / "server.py").read_text() == "# mine\n"


def test_bad_files_are_one_line_each_and_the_others_exported(run, write, tmp_path):
    bad = write("id: b\nkind: steady_precession\ngiven: {spin: 12 parsecs}\nfind: [precession]\n",
                "bad.yaml")
    out = tmp_path / "bank.xml"
    done = run("export", "--to", "moodle", bad, PROBLEMS / "11_1.yaml", "-o", out)
    assert done.exit_code == 2
    lines = [line for line in done.stderr.splitlines() if line.startswith("gyro: ")]
    assert any(str(bad) in line and "given.spin" in line for line in lines)
    assert "Traceback" not in done.output
    assert len(_moodle(out)) == 1
    done = run("export", "--to", "moodle", bad, "-o", tmp_path / "none.xml")
    assert done.exit_code == 2 and "nothing to export" in done.stderr
    assert not (tmp_path / "none.xml").exists()


def test_a_repeated_id_is_refused_for_the_second_file(run, tmp_path):
    copy = tmp_path / "copy.yaml"
    copy.write_text((PROBLEMS / "11_1.yaml").read_text())
    out = tmp_path / "bank.xml"
    done = run("export", "--to", "moodle", PROBLEMS / "11_1.yaml", copy, "-o", out)
    assert done.exit_code == 2
    assert f"{copy}: id (line 1): id '11/1' is already exported from" in done.stderr
    assert len(_moodle(out)) == 1


def test_an_input_is_never_the_output(run, tmp_path):
    source = tmp_path / "p.yaml"
    source.write_text((PROBLEMS / "11_1.yaml").read_text())
    for fmt in ("moodle", "qti", "blackboard"):
        done = run("export", "--to", fmt, source, "-o", source, "--force")
        assert done.exit_code == 2 and "would replace an input file" in done.stderr
    assert source.read_text() == (PROBLEMS / "11_1.yaml").read_text()


@pytest.mark.parametrize("args, message", [
    (["--to", "moodle", "-o", "{tmp}"], "is a directory"),
    (["--to", "blackboard", "-o", "{tmp}"], "a .txt for blackboard"),
    (["--to", "excel", "-o", "{tmp}/x"], "Invalid value for '--to'"),
    (["--to", "qti", "--variants", "0", "-o", "{tmp}/x.zip"], "Invalid value for '--variants'"),
])
def test_bad_options_exit_2(run, tmp_path, args, message):
    args = [a.replace("{tmp}", str(tmp_path)) for a in args]
    done = run("export", PROBLEMS / "11_3.yaml", *args)
    assert done.exit_code == 2
    assert message in done.stderr


def test_prairielearn_inputs_do_not_show_their_half_width(exported):
    """pl-number-input prints its atol as the input's placeholder (``number ±0.451344``)
    and in its help popup unless told not to (PrairieLearn's pl-number-input.py: the
    placeholder from the same text as the help, show-help-text default true); with the
    statement's "within 1%" that half-width is the answer, 45.1344 rpm (an adversarial
    pass: 252 of 300 blanks). Every input hides both and says only "number"."""
    for html_path in (exported["prairielearn"]).glob("*/question.html"):
        inputs = re.findall(r"<pl-number-input [^>]*>", html_path.read_text())
        assert inputs, html_path
        for tag in inputs:
            assert 'show-help-text="false"' in tag and 'placeholder="number"' in tag, tag


def test_prairielearn_shows_each_variant_only_its_own_inputs(tmp_path):
    """A variant at theta = 90 deg has one precession root where the others have two:
    question.html holds the union, and each variant's page only the inputs it asks."""
    from gyro_cli.render import bank_prairielearn
    from gyro_cli.render.bank import Blank, ProblemBank, Variant

    def blank(key: str, value: float) -> Blank:
        return Blank(key, key, value, "rpm", 0.01 * value, "1%", "relative", 0.01)

    two = Variant(1, "t-v1", {}, "<p>one</p>", "<p>worked</p>",
                  [blank("precession_slow", 45.0), blank("precession_fast", 533.0)])
    one = Variant(2, "t-v2", {}, "<p>two</p>", "<p>worked</p>", [blank("precession", 60.0)])
    bank = ProblemBank("t", "T", "steady_precession", "", "t", "steady precession", [two, one])
    for rel, text in bank_prairielearn.files([bank]).items():
        (tmp_path / rel).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / rel).write_text(text)
    html = (tmp_path / "t" / "question.html").read_text()
    for seed, keys in ((0, ["precession_slow", "precession_fast"]), (1, ["precession"])):
        data = _generate(tmp_path / "t" / "server.py", seed)
        assert list(data["correct_answers"]) == keys
        assert re.findall(r'answers-name="(\w+)"', _mustache(html, data["params"])) == keys


def test_gyro_check_accepts_every_exported_answer(exported, run, tmp_path):
    """Each bundled problem (and gyro vary's variants of it) with its `expected` replaced by
    the numbers of the PrairieLearn export passes `gyro check`: the bank's answers are
    the ones gyro check verifies."""
    written = 0
    for question in sorted(p for p in exported["prairielearn"].iterdir() if p.is_dir()):
        source = PROBLEMS / f"{question.name}.yaml"
        data = read_yaml(source.read_text())
        if "vary" in data:
            done = run("vary", source, "--count", VARIANTS, "--seed", 0, "-o",
                       tmp_path / "v" / question.name)
            assert done.exit_code == 0, done.output
            files = sorted((tmp_path / "v" / question.name).glob("*.yaml"))
        else:
            files = [source]
        for seed, file in enumerate(files):
            variant = read_yaml(file.read_text())
            answers = _generate(question / "server.py", seed)["correct_answers"]
            names = list(variant["find"]) + list(variant.get("expected") or {})
            html = (question / "question.html").read_text()
            expected: dict[str, list[str]] = {}
            for key, value in answers.items():
                name = max((n for n in names if key == n or key.startswith(n + "_")), key=len)
                unit = re.search(rf'answers-name="{key}"[^>]*?(?:suffix="([^"]*)")?>',
                                 html).group(1) or ""
                expected.setdefault(name, []).append(f"{value!r} {unit}".strip())
            variant["expected"] = {n: v if len(v) > 1 else v[0] for n, v in expected.items()}
            variant.pop("vary", None)
            target = tmp_path / "checked" / f"{question.name}-{seed}.yaml"
            target.parent.mkdir(exist_ok=True)
            target.write_text(yaml.safe_dump(variant, sort_keys=False, allow_unicode=True))
            written += 1
    done = run("check", tmp_path / "checked")
    assert done.exit_code == 0, done.output
    assert written >= len(exported["reference"]) and "FAIL" not in done.output


def test_a_value_too_small_for_a_platform_is_named(run, tmp_path):
    """Gravity Probe B's moment, 4.7e-19 N m: an older Moodle adds 1e-14 to every
    numerical tolerance (question/type/numerical/question.php), so any answer near 0
    would pass (an adversarial pass). The export names such blanks and says what to do."""
    done = run("export", "--to", "moodle", PROBLEMS / "drift_gpb_budget.yaml",
               "-o", tmp_path / "g.xml")
    assert done.exit_code == 0, done.output
    line = next(l for l in done.stderr.splitlines() if "below 1e-09" in l)
    assert "moment = 4.726e-19 N m (drift_gpb_budget.yaml)" in line and "smaller unit" in line
    done = run("export", "--to", "moodle", PROBLEMS / "11_3.yaml", "-o", tmp_path / "a.xml")
    assert "below 1e-09" not in done.stderr
