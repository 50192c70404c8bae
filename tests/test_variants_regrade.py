"""`gyro check --responses canvas|blackboard --variants N --seed S`: a bank exported with
drawn variants, regraded from the platform's download. Each response is graded against
the variant its question drew (known by the question's text), each student on their own
variants only, every student on every answer once."""

from __future__ import annotations

import csv
import json
import xml.etree.ElementTree as ET
import zipfile
from pathlib import Path

from test_i38_regrade import canvas_analysis, qti_questions

ROOT = Path(__file__).resolve().parent.parent


def _top(tmp_path: Path) -> Path:
    top = tmp_path / "a.yaml"
    top.write_text((ROOT / "problems" / "11_3.yaml").read_text())
    return top


def _qti_values(package: Path) -> list[float]:
    """Each item's right value, in the items' order."""
    with zipfile.ZipFile(package) as z:
        name = next(n for n in z.namelist() if n.endswith(".xml") and "manifest" not in n)
        root = ET.fromstring(z.read(name))
    return [float([el.text for el in item.iter() if el.tag.endswith("varequal")][0])
            for item in root.iter() if item.tag.endswith("}item") or item.tag == "item"]


def _by_hand(run, top: Path, tmp_path: Path) -> dict[str, dict]:  # type: ignore[no-untyped-def]
    """Each drawn variant solved alone, from the files `gyro vary --count 3 --seed 5`
    writes (the variants the export drew): id -> its answers in rpm."""
    folder = tmp_path / "drawn"
    assert run("vary", top, "--count", "3", "--seed", "5", "-o", folder).exit_code == 0
    out = {}
    for path in sorted(folder.glob("*.yaml")):
        solved = json.loads(run("solve", "--format", "json", path).stdout)
        out[solved["id"]] = {n: a["values"] for n, a in solved["answers"].items()}
    return out


def test_canvas_each_student_graded_against_the_variant_drawn(tmp_path, run):
    """Three variants of 11/3, one item a number (slow and fast root, least spin): ann
    answers variant 2 right, bob variant 3 with a least spin 10% high, cy leaves all blank,
    dee takes the two roots from variant 1 and the least spin from variant 3. Each answer
    once for each student, against the variant of the question typed into."""
    top = _top(tmp_path)
    package = tmp_path / "bank.zip"
    assert run("export", "--to", "qti", top, "--variants", "3", "--seed", "5",
               "-o", package).exit_code == 0
    texts, values = qti_questions(package), _qti_values(package)
    assert len(texts) == 9  # 3 variants x (slow, fast, least spin)
    hand = _by_hand(run, top, tmp_path)
    ids = sorted(hand)
    assert len(ids) == 3 and values[3:6] == [*hand[ids[1]]["precession"],
                                             *hand[ids[1]]["min_spin"]]

    def typed(picks: dict[int, float]) -> list[str]:
        return [f"{picks[k]:.5g}" if k in picks else "" for k in range(9)]

    rows = [["Ann", "101", "ann", "1", *typed({3: values[3], 4: values[4], 5: values[5]})],
            ["Bob", "102", "bob", "1", *typed({6: values[6], 7: values[7],
                                                8: 1.1 * values[8]})],
            ["Cy", "103", "cy", "1", *typed({})],
            ["Dee", "104", "dee", "1", *typed({0: values[0], 1: values[1], 8: values[8]})]]
    path = canvas_analysis(tmp_path, texts, rows)
    graded = run("check", "--answers", path, "--responses", "canvas", top,
                 "--variants", "3", "--seed", "5", "--format", "json")
    assert graded.exit_code == 0, graded.output
    result = json.loads(graded.stdout)
    got = {(r["student"], r["answer"]): (r["problem"], r["points"]) for r in result["rows"]}
    assert got == {("ann", "precession"): (ids[1], 1), ("ann", "min_spin"): (ids[1], 1),
                   ("bob", "precession"): (ids[2], 1), ("bob", "min_spin"): (ids[2], 0),
                   ("cy", "precession"): (ids[0], 0), ("cy", "min_spin"): (ids[0], 0),
                   ("dee", "precession"): (ids[0], 1), ("dee", "min_spin"): (ids[2], 1)}
    # without --variants the questions are not the files': refused, saying why
    refused = run("check", "--answers", path, "--responses", "canvas", top)
    assert refused.exit_code == 2 and "--variants and --seed" in refused.output


def test_canvas_one_answer_from_two_variants_is_refused(tmp_path, run):
    """The slow root from variant 1 and the fast from variant 2 (a group a number): one
    answer cannot be graded against two problems. One line, exit 2."""
    top = _top(tmp_path)
    package = tmp_path / "bank.zip"
    assert run("export", "--to", "qti", top, "--variants", "3", "--seed", "5",
               "-o", package).exit_code == 0
    texts, values = qti_questions(package), _qti_values(package)
    cells = [f"{values[0]:.5g}", "", "", "", f"{values[4]:.5g}", "", "", "", ""]
    path = canvas_analysis(tmp_path, texts, [["Eve", "105", "eve", "1", *cells]])
    refused = run("check", "--answers", path, "--responses", "canvas", top,
                  "--variants", "3", "--seed", "5")
    assert refused.exit_code == 2, refused.output
    assert len(refused.output.strip().splitlines()) == 1 and "two variants" in refused.output


def test_blackboard_each_student_graded_against_the_variant_drawn(tmp_path, run):
    """Blackboard's download lists each student's own questions: ann's are variant 3's,
    answered right; bob's variant 1's, his least spin 10% low."""
    top = _top(tmp_path)
    upload = tmp_path / "upload.txt"
    assert run("export", "--to", "blackboard", top, "--variants", "3", "--seed", "5",
               "-o", upload).exit_code == 0
    lines = upload.read_text().splitlines()
    assert len(lines) == 9
    hand = _by_hand(run, top, tmp_path)
    ids = sorted(hand)
    own = {"ann": lines[6:9], "bob": lines[0:3]}
    right = {who: [float(line.split("\t")[2]) for line in picked] for who, picked in own.items()}
    assert right["ann"] == [*hand[ids[2]]["precession"], *hand[ids[2]]["min_spin"]]
    path = tmp_path / "downloadlong.csv"
    with path.open("w", newline="", encoding="utf-8") as out:
        writer = csv.writer(out, quoting=csv.QUOTE_ALL)
        writer.writerow(["Username", "Last Name", "First Name", "Question ID", "Question",
                         "Answer", "Possible Points", "Auto Score", "Manual Score"])
        for who, picked in own.items():
            for k, line in enumerate(picked):
                value = right[who][k] * (0.9 if who == "bob" and k == 2 else 1)
                writer.writerow([who, who.title(), "A", f"_{k}_1", line.split("\t")[1],
                                 f"{value:.5g}", "1", "0", ""])
    graded = run("check", "--answers", path, "--responses", "blackboard", top,
                 "--variants", "3", "--seed", "5", "--format", "json")
    assert graded.exit_code == 0, graded.output
    got = {(r["student"], r["answer"]): (r["problem"], r["points"])
           for r in json.loads(graded.stdout)["rows"]}
    assert got == {("ann", "precession"): (ids[2], 1), ("ann", "min_spin"): (ids[2], 1),
                   ("bob", "precession"): (ids[0], 1), ("bob", "min_spin"): (ids[0], 0)}


def test_variants_go_with_canvas_or_blackboard_responses(tmp_path, run):
    top = _top(tmp_path)
    sheet = tmp_path / "s.csv"
    sheet.write_text("student,problem,answer,value\nann,11/3,min_spin,965 rpm\n")
    for extra in (["--responses", "moodle"], []):
        refused = run("check", "--answers", sheet, *extra, top, "--variants", "3")
        assert refused.exit_code == 2 and "--variants and --seed go with" in refused.output
