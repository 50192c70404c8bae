"""One bad file never stops a batch: an internal error is one line, exit 3, and the
next file goes on (solve, check in its three reports, simulate, grading)."""

from __future__ import annotations

import dataclasses
import importlib
import json
import shutil
import xml.etree.ElementTree as ET

import pytest
from conftest import PROBLEMS

LINE = "internal error: RuntimeError: injected fault (please report)"


@pytest.fixture
def broken_torque(monkeypatch):
    """gyroscopic_torque's solver raises an exception gyro does not expect."""
    module = importlib.import_module("gyro_cli.kinds.gyroscopic_torque")

    def boom(given, find, work):
        raise RuntimeError("injected fault")

    monkeypatch.setattr(module, "KIND", dataclasses.replace(module.KIND, solve=boom))


@pytest.fixture
def batch(tmp_path):
    """Three files: steady_precession, gyroscopic_torque (broken), rolling_disk."""
    names = ["11_3.yaml", "11_5.yaml", "11_6.yaml"]
    for name in names:
        shutil.copy(PROBLEMS / name, tmp_path / name)
    return [tmp_path / n for n in names]


@pytest.mark.parametrize("fmt", ["text", "json", "markdown", "latex", "html"])
def test_solve_goes_on_after_an_internal_error(run, batch, broken_torque, fmt):
    result = run("solve", "--format", fmt, *batch)
    assert result.exit_code == 3
    lines = result.stderr.splitlines()
    assert lines == [f"gyro: {batch[1]}: {LINE}"]
    assert "Traceback" not in result.output
    if fmt == "json":
        ids = [json.loads(line)["id"] for line in result.stdout.splitlines()]
        assert ids == ["11/3", "11/6"]
    else:
        import yaml

        titles = [yaml.safe_load(path.read_text())["title"] for path in batch]
        for title, shown in zip(titles, (True, False, True)):
            assert (title.split(",")[0] in result.stdout) == shown, title


def test_internal_error_wins_over_bad_input_in_the_exit_code(run, batch, broken_torque,
                                                             tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text("id: x\nkind: nope\ngiven: {}\nfind: [a]\n")
    result = run("solve", bad, *batch)
    assert result.exit_code == 3
    assert len(result.stderr.splitlines()) == 2


def test_check_reports_the_internal_error_in_every_report(run, batch, broken_torque, tmp_path):
    junit = tmp_path / "report.xml"
    table = run("check", *batch, "--junit", junit)
    assert table.exit_code == 3
    assert table.stderr.splitlines() == [f"gyro: {batch[1]}: {LINE}"]
    for path in batch:  # every file is listed
        assert str(path) in table.stdout
    assert f"  ERROR  {batch[1]}: {LINE}" in table.stdout
    assert table.stdout.splitlines()[-1].startswith("INTERNAL ERROR:")
    assert "1 internal error" in table.stdout.splitlines()[-1]
    assert table.stdout.count("PASS") > 5 and "FAIL" not in table.stdout

    document = json.loads(run("check", "--format", "json", *batch).stdout)
    assert document["summary"]["exit_code"] == 3
    assert document["summary"]["internal_errors"] == 1
    statuses = [(p["file"], p["status"], p["internal"]) for p in document["problems"]]
    assert statuses == [(str(batch[0]), "pass", False), (str(batch[1]), "error", True),
                        (str(batch[2]), "pass", False)]

    root = ET.parse(junit).getroot()
    assert root.get("errors") == "1" and root.get("failures") == "0"
    errors = root.findall(".//error")
    assert len(errors) == 1 and errors[0].get("type") == "InternalError"
    assert LINE in errors[0].get("message")


def test_check_directory_lists_every_file(run, batch, broken_torque, tmp_path):
    (tmp_path / "empty.yaml").write_text("")
    result = run("check", tmp_path)
    assert result.exit_code == 3
    assert len(result.stderr.splitlines()) == 2  # one line per bad file
    for name in ["11_3.yaml", "11_5.yaml", "11_6.yaml", "empty.yaml"]:
        assert name in result.stdout
    assert result.stdout.count("  ERROR  ") == 2


def test_simulate_internal_error_is_one_line(run, monkeypatch):
    from gyro_cli.commands import simulate as simulate_cmd

    def boom(*args, **kwargs):
        raise RuntimeError("injected\nover two lines")

    monkeypatch.setattr(simulate_cmd, "simulate_file", boom)
    path = PROBLEMS / "11_2_released_top.yaml"
    result = run("simulate", path)
    assert result.exit_code == 3
    assert result.stderr == (f"gyro: {path}: internal error: RuntimeError: injected over two "
                             "lines (please report)\n")


def test_grading_goes_on_after_an_internal_error(run, batch, broken_torque, tmp_path):
    sheet = tmp_path / "sheet.csv"
    sheet.write_text("student,problem,answer,value\n"
                     "ann,11/5,moment,-2.781 N*m\n"
                     "ann,11/6,normal_force,598 N\n")
    out = tmp_path / "grades.csv"
    result = run("check", "--answers", sheet, *batch, "--out", out)
    assert result.exit_code == 3
    assert result.stderr.splitlines() == [f"gyro: {batch[1]}: {LINE}"]
    rows = out.read_text().splitlines()
    assert any(",11/5,moment," in r and ",error," in r for r in rows)
    assert any(",11/6,normal_force," in r and ",error," not in r for r in rows)


def test_an_unexpected_error_outside_any_file_is_one_line_and_exit_3(run, monkeypatch):
    from gyro_cli.checking import check

    def boom(*args, **kwargs):
        raise KeyError("collect")

    monkeypatch.setattr(check, "collect", boom)
    result = run("check", PROBLEMS)
    assert result.exit_code == 3
    assert result.stderr == "gyro: internal error: KeyError: 'collect' (please report)\n"


def test_the_traceback_is_shown_on_request(run, batch, broken_torque, monkeypatch):
    monkeypatch.setenv("GYRO_DEBUG", "1")
    result = run("solve", batch[1])
    assert result.exit_code == 3
    assert "Traceback" in result.stderr and "injected fault" in result.stderr


def test_a_closed_pipe_ends_quietly():
    import subprocess
    import sys

    gyro = [sys.executable, "-m", "gyro_cli"]
    files = [str(p) for p in sorted(PROBLEMS.glob("*.yaml"))] * 5
    process = subprocess.Popen(gyro + ["solve", *files], stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE)
    process.stdout.readline()
    process.stdout.close()
    _, err = process.communicate(timeout=120)
    assert process.returncode == 141
    assert err == b""
