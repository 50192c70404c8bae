"""The Python API (gyro_cli.solve, check, kinds, sweep; Result, Answer, InputError)."""

from __future__ import annotations

import json
import math
import subprocess
import sys
from pathlib import Path

import pytest

import gyro_cli

ROOT = Path(__file__).resolve().parent.parent
TOP = str(ROOT / "problems" / "11_3.yaml")
RPM = 2 * math.pi / 60

# Problem 11/3 as a mapping, every quantity in SI as plain numbers (3 ozf, 0.84 in, ...).
OZF = 0.27801385095378125  # N
INCH = 0.0254
TOP_SI = {
    "id": "11/3 in SI", "kind": "steady_precession",
    "given": {"weight": 3 * OZF, "g": 32.2 * 0.3048, "k_axial": 0.84 * INCH,
              "k_pivot": 1.80 * INCH, "cg_distance": 1.5 * INCH, "theta": math.radians(30),
              "spin": 1800 * RPM},
    "find": {"precession": "rpm", "min_spin": "rpm"},
}


def test_acceptance_command_prints_both_roots_in_rpm():
    out = subprocess.run([sys.executable, "-c", "import gyro_cli; r = gyro_cli.solve("
                          "'problems/11_3.yaml'); print(r.answers['precession'])"],
                         capture_output=True, text=True, cwd=ROOT, check=True)
    assert out.stdout.strip() == "45.13 rpm (slow), 533.5 rpm (fast)"


def test_answers_in_the_unit_asked_and_in_si():
    r = gyro_cli.solve(TOP)
    precession = r.answers["precession"]
    assert precession.unit == "rpm" and precession.si_unit == "rad/s"
    assert precession.labels == ("slow", "fast") and len(precession) == 2
    slow, fast = precession.values
    assert precession["slow"] == slow and precession[1] == fast
    assert precession.si == pytest.approx((slow * RPM, fast * RPM), rel=1e-12)
    # the roots satisfy Eq. 11.13 with thetaddot = 0, written out here with the file's data:
    m = 3 * OZF / (32.2 * 0.3048)
    J, I = m * (0.84 * INCH) ** 2, m * (1.80 * INCH) ** 2
    mgl, c, psidot = 3 * OZF * 1.5 * INCH, math.cos(math.radians(30)), 1800 * RPM
    for phidot in precession.si:
        assert (J - I) * c * phidot ** 2 + J * psidot * phidot - mgl == \
            pytest.approx(0, abs=1e-12)
    assert float(r.answers["min_spin"]) == pytest.approx(965.4, rel=1e-4)
    with pytest.raises(ValueError, match="2 values"):
        precession.value  # noqa: B018 (the access is what raises)
    assert r.answers["min_spin"].quantity().to("rad/s").magnitude == \
        pytest.approx(r.answers["min_spin"].si)


def test_a_mapping_in_si_numbers_gives_the_files_answers():
    from_file = gyro_cli.solve(TOP).answers["precession"].si
    r = gyro_cli.solve(TOP_SI)
    assert r.answers["precession"].si == pytest.approx(from_file, rel=1e-9)
    assert r.file == "<dict>" and r.id == "11/3 in SI"


def test_pint_quantities_from_the_users_registry_and_from_gyros():
    import pint

    ureg = pint.UnitRegistry()
    problem = dict(TOP_SI, given=dict(TOP_SI["given"], spin=1800 * ureg.rpm,
                                      theta=30 * ureg.degree, cg_distance=1.5 * ureg.inch))
    r = gyro_cli.solve(problem)
    assert r.answers["precession"].si == pytest.approx(gyro_cli.solve(TOP).answers[
        "precession"].si, rel=1e-9)
    u = gyro_cli.registry()
    assert gyro_cli.solve(TOP, spin=30 * u.Hz).answers["precession"].si == pytest.approx(
        gyro_cli.solve(TOP, spin="1800 rpm").answers["precession"].si, rel=1e-12)


def test_overrides_sweep_a_file():
    slow = [gyro_cli.solve(TOP, spin=f"{s} rpm").answers["precession"]["slow"]
            for s in (1500, 1800, 2400)]
    assert slow[1] == pytest.approx(45.13, rel=1e-3)
    assert slow[0] > slow[1] > slow[2]   # faster spin, slower slow precession
    # without its spin (None removes a key) but with a precession: the spin follows
    r = gyro_cli.solve(TOP, spin=None, precession="45.134 rpm", units=None)
    assert "spin" in gyro_cli.load(TOP).given.values
    assert r.problem.given.values.get("spin") is None


def test_sweep_records_keep_errors():
    sweep = gyro_cli.sweep(TOP, spin=["500 rpm", "1800 rpm", "3000 rpm"])
    rows = sweep.records()
    assert [row["spin"] for row in rows] == ["500 rpm", "1800 rpm", "3000 rpm"]
    assert "too low for steady precession" in rows[0]["error"] and "spin_si" not in rows[0]
    assert rows[1]["error"] is None
    assert rows[1]["precession_slow"] == pytest.approx(45.13, rel=1e-3)
    assert rows[1]["spin_si"] == pytest.approx(1800 * RPM)
    assert sweep.units()["precession"] == "rpm"
    table = sweep._repr_html_()
    assert '<th scope="col">precession_slow (rpm)</th>' in table and "45.13" in table
    assert table.index("<th scope=\"col\">error</th>") > table.index("min_spin")


def test_bad_key_raises_input_error_naming_it_with_its_line(tmp_path):
    text = Path(TOP).read_text().replace("  spin: 1800 rpm", "  spinn: 1800 rpm")
    path = tmp_path / "typo.yaml"
    path.write_text(text)
    with pytest.raises(gyro_cli.InputError) as caught:
        gyro_cli.solve(str(path))
    err = caught.value
    assert err.key == "given.spinn" and "did you mean 'spin'" in err.message
    assert err.line == text.splitlines().index("  spinn: 1800 rpm") + 1
    assert err.file == str(path)
    with pytest.raises(gyro_cli.InputError) as caught:
        gyro_cli.solve(TOP, spinn="2000 rpm")
    assert caught.value.key == "given.spinn"
    with pytest.raises(gyro_cli.InputError) as caught:
        gyro_cli.solve(dict(TOP_SI, given=dict(TOP_SI["given"], theta="30 furlongs")))
    assert caught.value.key == "given.theta" and caught.value.line is None


def test_a_file_keeps_the_format_rules():
    """A bare number in a file or YAML text is still refused for a length; only the API's
    mapping and keyword values read numbers as SI."""
    text = Path(TOP).read_text().replace("cg_distance: 1.5 in", "cg_distance: 0.0381")
    with pytest.raises(gyro_cli.InputError) as caught:
        gyro_cli.solve(text)
    assert caught.value.key == "given.cg_distance" and caught.value.file == "<yaml>"
    assert gyro_cli.solve(TOP, cg_distance=0.0381).answers["precession"].si == \
        pytest.approx(gyro_cli.solve(TOP).answers["precession"].si, rel=1e-3)


def test_to_dict_is_the_json_of_the_command():
    out = subprocess.run([sys.executable, "-m", "gyro_cli", "solve", "--format", "json",
                          "problems/11_3.yaml"], capture_output=True, text=True, cwd=ROOT,
                         check=True)
    r = gyro_cli.solve("problems/11_3.yaml")
    assert json.loads(out.stdout) == r.to_dict()
    us = subprocess.run([sys.executable, "-m", "gyro_cli", "solve", "--units", "us",
                         "problems/11_3.yaml"], capture_output=True, text=True, cwd=ROOT,
                        check=True)
    assert us.stdout == gyro_cli.solve("problems/11_3.yaml", units="us").text()
    us_json = subprocess.run([sys.executable, "-m", "gyro_cli", "solve", "--units", "us",
                              "--format", "json", "problems/11_3.yaml"], capture_output=True,
                             text=True, cwd=ROOT, check=True)
    assert json.loads(us_json.stdout) == gyro_cli.solve("problems/11_3.yaml",
                                                         units="us").to_dict()


def test_results_show_themselves():
    r = gyro_cli.solve(TOP)
    html = r._repr_html_()
    assert html.count("<math") > 20 and "45.13" in html and "<table" in html
    assert "$$" in r._repr_markdown_() and "\\subsubsection*{Answer}" in r._repr_latex_()
    assert r.text() == str(r) and "Answer" in str(r)
    assert repr(r).startswith("<Result 11/3 [steady_precession]: precession = 45.13 rpm")
    top = gyro_cli.solve(str(ROOT / "problems" / "11_2_released_top.yaml"))
    assert '<svg role="img"' in top._repr_html_()


def test_check_paths_and_mappings():
    report = gyro_cli.check(TOP, str(ROOT / "problems" / "11_4.yaml"))
    assert report.passed and report.exit_code == 0 and len(report.problems) == 2
    wrong = dict(TOP_SI, expected={"precession": ["45.13 rpm", "600 rpm"]})
    report = gyro_cli.check(wrong)
    assert not report.passed and report.exit_code == 1
    assert [a.passed for a in report.problems[0].answers] == [True, False]
    page = report._repr_html_()
    assert "FAIL" in page and 'href="#p-dict-precession"' in page
    assert report.to_dict()["summary"]["failed"] == 1


def test_kinds_lists_the_registry():
    kinds = gyro_cli.kinds()
    assert "steady_precession" in kinds and "bicycle" in kinds
    assert kinds["steady_precession"].answer("precession").dimension == "rate"
    import gyro_cli.kinds as registry

    assert registry.names() == sorted(kinds)


def test_import_is_cheap_and_typed():
    code = ("import sys, gyro_cli; heavy = [m for m in ('yaml', 'pint', 'numpy', 'click', "
            "'gyro_cli.api') if m in sys.modules]; print(heavy)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True)
    assert out.stdout.strip() == "[]"
    assert (ROOT / "gyro_cli" / "py.typed").exists()
    assert set(gyro_cli.__all__) <= set(dir(gyro_cli))


def test_a_mapping_without_an_id_is_named_by_its_kind():
    """A notebook's dict needs no id (a file still does: the format's rule)."""
    data = {k: v for k, v in TOP_SI.items() if k != "id"}
    r = gyro_cli.solve(data)
    assert r.id == "steady_precession"
    assert r.answers["precession"].si == pytest.approx(gyro_cli.solve(TOP_SI).answers[
        "precession"].si, rel=1e-12)
    with pytest.raises(gyro_cli.InputError, match="id"):
        gyro_cli.solve("kind: steady_precession\ngiven: {}\nfind: [precession]\n")
