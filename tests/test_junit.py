"""JUnit XML of `gyro check --junit`: parsed back with ElementTree and checked.

Independent reference: the structure CI consumers read (testsuites > testsuite
> testcase with failure/error/skipped; counts that add up) and failure messages
"expected X +- tol, got Y" whose numbers are re-read here and compared with the
hand-worked answer of the horizontal gyroscope (phidot = m g l / (J psidot)).
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from pathlib import Path

from test_check import FAST, GYRO_PRECESSION, SLOW, gyro_file, put, top_file

from gyro_cli.checking import check
from gyro_cli.render import junit

MESSAGE = re.compile(r"expected (\S+) (\S+) \+- (\S+) (\S+), got (\S+) (\S+)$")


def _report(run, tmp_path: Path, *paths: Path) -> ET.Element:
    out = tmp_path / "junit.xml"
    run("check", *paths, "--junit", out)
    return ET.parse(out).getroot()


def test_a_suite_per_file_a_case_per_answer(run, tmp_path):
    good = put(tmp_path, "good.yaml", top_file(f"precession: [{SLOW:.6g} rad/s, {FAST:.6g} rad/s]"
                                               "\n"))
    wrong = put(tmp_path, "wrong.yaml", gyro_file("precession: 19.62 rad/s\nmoment: 1.962 N m\n"))
    root = _report(run, tmp_path, good, wrong)
    assert root.tag == "testsuites"
    suites = root.findall("testsuite")
    assert [s.get("name") for s in suites] == [str(good), str(wrong)]
    cases = [len(s.findall("testcase")) for s in suites]
    assert cases == [2, 2]
    assert [s.get("tests") for s in suites] == ["2", "2"]
    assert [s.get("failures") for s in suites] == ["0", "1"]
    assert root.get("tests") == "4" and root.get("failures") == "1" and root.get("errors") == "0"
    failures = root.findall(".//failure")
    assert len(failures) == 1
    match = MESSAGE.match(failures[0].get("message"))
    assert match, failures[0].get("message")
    expected, unit, tol, tol_unit, got, got_unit = match.groups()
    assert (unit, tol_unit, got_unit) == ("rad/s",) * 3
    assert float(expected) == 19.62
    assert float(tol) == 0.1962  # 1% of 19.62, the default tolerance
    assert float(got) == round(GYRO_PRECESSION, 3)  # 4 significant figures
    assert abs(float(got) - float(expected)) > float(tol)
    assert "power of ten" in failures[0].text
    # the failing case is named after the problem and the answer
    case = root.find(".//failure/..")
    assert case.get("name") == "gyro-90 precession"
    assert case.get("classname").endswith("wrong")


def test_bad_file_is_an_error_and_no_expected_is_skipped(run, tmp_path):
    bad = put(tmp_path, "bad.yaml", gyro_file("precession: 3 kg\n"))
    plain = put(tmp_path, "plain.yaml", gyro_file())
    good = put(tmp_path, "good.yaml", gyro_file(f"precession: {GYRO_PRECESSION} rad/s\n"))
    root = _report(run, tmp_path, bad, plain, good)
    assert root.get("errors") == "1" and root.get("skipped") == "1" and root.get("tests") == "3"
    error = root.find(".//error")
    assert "expected.precession" in error.get("message")
    assert root.find(".//skipped").get("message") == "no expected answers"


def test_special_characters_are_escaped(tmp_path):
    text = gyro_file("precession: 5 rad/s\n").replace("id: gyro-90", 'id: "a<b & \\"c\\" \\u0001"')
    path = put(tmp_path, "we<ird&.yaml", text)
    doc = junit.xml(check.run([str(path)]))
    root = ET.fromstring(doc.encode("utf-8"))  # well-formed, control characters removed
    case = root.find(".//testcase")
    assert case.get("name").startswith('a<b & "c"')
    assert root.find("testsuite").get("name").endswith("we<ird&.yaml")


# ---- the direct writer against ElementTree ------------------------------------------

import pytest  # noqa: E402
from conftest import examples  # noqa: E402
from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st

_texts = st.text(alphabet=st.characters(blacklist_categories=("Cs",)), max_size=30)


@pytest.mark.property
@settings(max_examples=examples(300), deadline=None)
@given(file=_texts, pid=_texts, status=st.sampled_from(["pass", "fail", "error",
                                                         "no expected answers"]),
       error=_texts, messages=st.lists(st.tuples(_texts, st.booleans(), _texts), max_size=3))
def test_suite_text_is_elementtree_s_text(file, pid, status, error, messages):
    """suite_text writes what ElementTree writes for suite(): escaping (&, <, quotes,
    newlines, tabs) and characters XML forbids, for any file name, id or message."""
    import xml.etree.ElementTree as ET

    from gyro_cli.checking.results import AnswerCheck, ProblemCheck
    from gyro_cli.render.junit import suite, suite_text

    answers = [AnswerCheck("n", None, "1", "2", passed, message=message, slip=slip or None)
               for message, passed, slip in messages]
    problem = ProblemCheck(file or "f.yaml", pid, "t", "k", status=status,
                           error=error if status == "error" else None, answers=answers)
    root = ET.Element("testsuites")
    root.append(suite(problem))
    ET.indent(root)
    whole = ET.tostring(root, encoding="unicode")
    inner = whole[len("<testsuites>\n  "):-len("\n</testsuites>")]
    assert suite_text(problem)[0] == inner
