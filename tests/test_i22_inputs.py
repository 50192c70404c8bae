"""Input reading without silent misreadings (issue 22 items 5-8, 16; issue 23 item 4).

Every expected number is worked by hand here from the definitions (1 rev =
2 pi rad, 1 min = 60 s, 1 kgf = 9.80665 N, 1 lb = 0.45359237 kg), never taken
from pint; a refusal must be one line with exit 2.
"""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

import pytest

from gyro_cli.core import unit_cache, units
from gyro_cli.core.errors import InputError

ROOT = Path(__file__).resolve().parents[1]
REV = 2 * math.pi

TWO_WHEELER = (ROOT / "problems" / "two_wheeler_250kg.yaml").read_text()
# without its statement, whose {weight} the tests below may replace by a mass
TOP_11_3 = (ROOT / "problems" / "11_3.yaml").read_text().split("\nstatement:")[0] + "\n"


def _json(result) -> dict:
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout.splitlines()[0])


def _one_line_refusal(result, *words: str) -> str:
    assert result.exit_code == 2, result.output
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1, result.stderr
    assert "Traceback" not in result.output
    for word in words:
        assert word in lines[0], lines[0]
    return lines[0]


# ---- item 5: a dimensionless key takes no angle ------------------------------------

@pytest.mark.parametrize("ratio", ["5 deg", "5 rev", "5 rpm*s", "5 rad", "5 mrad"])
def test_i22_05_dimensionless_key_refuses_angle(run, write, ratio):
    path = write(TWO_WHEELER.replace("gear_ratio: 5", f"gear_ratio: {ratio}"))
    _one_line_refusal(run("solve", path), "given.gear_ratio", "plain number", "angle")


def test_i22_05_plain_gear_ratio_still_gives_the_published_couple(run, write):
    # By hand (Khurmi): C_g = (n_w I_w + G I_E) v^2 / (R r_w)
    #   = (2 x 1 + 5 x 0.3) kg m^2 x (25 m/s)^2 / (50 m x 0.3 m) = 3.5 x 625 / 15 = 145.83 N m
    # (with 5 deg read as 0.0873 it was (2 + 0.0262) x 625 / 15 = 84.42 N m).
    answers = _json(run("solve", "--format", "json", write(TWO_WHEELER)))["answers"]
    assert answers["gyroscopic_couple"]["si_values"][0] == pytest.approx(3.5 * 625 / 15)


# ---- item 6: cycles and revolutions convert with 2 pi; ton is ambiguous -------------------

@pytest.mark.parametrize("text, si", [
    ("300 cps", 300 * REV), ("300 c/s", 300 * REV), ("300 CPS", 300 * REV),
    ("18000 min^-1", 18000 * REV / 60), ("18000 1/min", 18000 * REV / 60),
    ("3600 h^-1", REV), ("300 Hz", 300 * REV), ("5 1/s", 5.0), ("5 s^-1", 5.0),
])
def test_i22_06_cycles_and_iso_per_minute_convert_with_two_pi(text, si):
    assert units.parse(text, "rate", "given.spin")[0] == pytest.approx(si, rel=1e-12)


def test_i22_06_spin_in_cps_and_min_inverse_solves_as_rpm(run, write):
    # 1800 rpm = 30 rev/s = 30 cps = 1800 min^-1: the same top, the same roots.
    def roots(spin: str) -> list[float]:
        text = TOP_11_3.replace("spin: 1800 rpm", f"spin: {spin}")
        return _json(run("solve", "--format", "json", write(text)))["answers"][
            "precession"]["si_values"]

    reference = roots("1800 rpm")
    for spin in ("30 cps", "30 c/s", "1800 min^-1", "1800 r.p.m.", "30 r.p.s."):
        assert roots(spin) == pytest.approx(reference, rel=1e-12), spin


def test_i22_06_answer_asked_in_min_inverse_is_rev_per_min():
    unit = units.check_unit("min^-1", "rate", "find.precession")
    assert units.convert(REV, "rate", unit) == pytest.approx(60.0)  # 1 rev/s = 60 rev/min


@pytest.mark.parametrize("key, text", [("mass", "2 ton"), ("mass", "2 tons"),
                                       ("weight", "2 ton"), ("mass", "2 ton*kg/kg")])
def test_i22_06_ton_is_refused_with_the_three_choices(run, write, key, text):
    body = TOP_11_3.replace("weight: 3 oz", f"{key}: {text}")
    line = _one_line_refusal(run("solve", write(body)), f"given.{key}", "ambiguous")
    for choice in ("short_ton", "long_ton", "907.2 kg", "1016 kg", "1000 kg"):
        assert choice in line


# ---- item 7: values whose products underflow --------------------------------------------

def test_i22_07_underflowing_mass_is_refused(run, write):
    body = TOP_11_3.replace("weight: 3 oz", "mass: 1e-170 kg")
    _one_line_refusal(run("solve", write(body)), "given.mass", "underflow", "1e-60")


def test_i22_07_underflowing_particle_is_refused(run, write):
    path = write("""\
        id: tiny
        kind: euler_angles
        given:
          particles:
            - {mass: 1e-200 kg, x: 1 m, y: 0 m, z: 0 m}
        find: {principal_moments: kg*m^2}
        """)
    _one_line_refusal(run("solve", path), "particles[0].mass", "underflow")


def test_i22_07_small_mass_that_cancels_gives_the_same_rates(run, write):
    # With radii of gyration, J = m k_z^2, I = m k_O^2 and m g l all scale with m, so
    # Eq. 11.13 divided by m does not hold m: 1e-50 kg and 1 kg give the same roots.
    def answers(mass: str) -> dict:
        body = TOP_11_3.replace("weight: 3 oz", f"mass: {mass}")
        return _json(run("solve", "--format", "json", write(body)))["answers"]

    small, unit = answers("1e-50 kg"), answers("1 kg")
    for name in ("precession", "min_spin"):
        assert small[name]["si_values"] == pytest.approx(unit[name]["si_values"], rel=1e-9)
    assert 0 < small["min_spin"]["si_values"][0]


# ---- item 8: the text written for an id (and title, source, notes) ----------------------

@pytest.mark.parametrize("written", ["11.10", "12:30", "011", "yes", "0x1F", "1e3", ".inf"])
def test_i22_08_unquoted_id_keeps_the_text_written(run, write, written):
    path = write(TOP_11_3.replace('id: "11/3"', f"id: {written}")
                 .replace("title: Top with two possible rates of steady precession",
                          f"title: {written}"))
    out = _json(run("solve", "--format", "json", path))
    assert out["id"] == written
    assert out["title"] == written


def test_i22_08_unquoted_notes_and_source_keep_the_text_written(run, write):
    path = write(TOP_11_3.replace("source: Chapter 11, problem 11/3", "source: 11.10")
                 .replace("  - Spin is the rate relative to the precessing frame (ψ̇).",
                          "  - 12:30\n  - no"))
    out = run("solve", path)
    assert out.exit_code == 0, out.output
    assert "Note: 12:30" in out.stdout and "Note: no" in out.stdout
    assert "750" not in out.stdout and "False" not in out.stdout


@pytest.mark.parametrize("written", ["null", "~", "", "''"])
def test_i22_08_empty_id_is_refused_with_a_hint_to_quote(run, write, written):
    path = write(TOP_11_3.replace('id: "11/3"', f"id: {written}"))
    _one_line_refusal(run("solve", path), "id (line 1)", "empty", "quotes")


def test_i22_08_ids_11_1_and_11_10_stay_two_problems(run, write, tmp_path):
    write(TOP_11_3.replace('id: "11/3"', "id: 11.1"), "a.yaml")
    write(TOP_11_3.replace('id: "11/3"', "id: 11.10"), "b.yaml")
    result = run("solve", "--format", "json", tmp_path)
    ids = sorted(json.loads(line)["id"] for line in result.stdout.splitlines())
    assert ids == ["11.1", "11.10"]


def test_i22_08_unquoted_problem_id_in_a_yaml_sheet_keeps_its_text(run, write, tmp_path):
    problem = write(TOP_11_3.replace('id: "11/3"', "id: 11.10"), "p.yaml")
    write(TOP_11_3.replace('id: "11/3"', "id: 11.1"), "q.yaml")
    sheet = write("""\
        ann:
          11.10: {min_spin: 965.4 rpm}
          11.1: {min_spin: 900 rpm}
        """, "sheet.yaml")
    result = run("check", "--answers", sheet, problem, tmp_path / "q.yaml", "--format", "json")
    assert result.exit_code in (0, 1), result.output
    rows = {row["problem"]: row["result"] for row in json.loads(result.stdout)["rows"]}
    assert rows == {"11.10": "correct", "11.1": "wrong"}


# ---- item 16: messages ----------------------------------------------------------------

@pytest.mark.parametrize("text, si", [("1 mrad", 0.001), ("1 mdeg", math.pi / 180e3),
                                      ("100 grad", math.pi / 2), ("100 gon", math.pi / 2)])
def test_i22_16_mrad_and_grad_are_read_as_angles(text, si):
    # a gradian is a 400th of a turn: 100 grad = 90 deg
    assert units.parse(text, "angle", "given.theta")[0] == pytest.approx(si, rel=1e-12)


def test_i22_16_merge_key_override_is_not_written_twice(run, write):
    path = write("""\
        id: merged
        kind: steady_precession
        given:
          <<: {mass: 1 kg, k_axial: 0.84 in, k_pivot: 1.80 in, cg_distance: 1.5 in,
               spin: 900 rpm, theta: 30 deg}
          spin: 1800 rpm
        find: {precession: rpm}
        """)
    result = run("solve", "--format", "json", path)
    given = _json(result)["given"]
    assert "1800" in json.dumps(given) and "900" not in json.dumps(given)


def test_i22_16_a_key_written_twice_is_still_refused(run, write):
    path = write("""\
        id: twice
        kind: steady_precession
        given:
          <<: {mass: 1 kg}
          spin: 900 rpm
          spin: 1800 rpm
        find: {precession: rpm}
        """)
    _one_line_refusal(run("solve", path), "given.spin", "written twice")


# ---- issue 23 item 4 and the documented spellings -------------------------------------------

def _documented_rows() -> list[tuple[str, str, str]]:
    """(written, dimension, read as) from the table in docs/real_problems.md."""
    text = (ROOT / "docs" / "real_problems.md").read_text()
    section = text.split("### Units as books print them", 1)[1].split("\n- ", 1)[0]
    rows = re.findall(r"^\| `([^`]+)` \| (\w+) \| (.+?) \|$", section, re.M)
    assert len(rows) >= 20
    return rows


def _check_row(written: str, dimension: str, read_as: str) -> float | None:
    weight = dimension == "weight"
    if read_as.startswith("refused: "):
        with pytest.raises(InputError) as err:
            units.parse(written, "force" if weight else dimension, "given.x", weight=weight)
        assert read_as.removeprefix("refused: ") in str(err.value), str(err.value)
        return None
    number, si = read_as.split(" ", 1)
    assert si == (units.si_text(dimension) or "1"), (written, si)
    value = units.parse(written, dimension, "given.x")[0]
    assert value == pytest.approx(float(number), rel=1e-7), written
    return value


@pytest.mark.parametrize("written, dimension, read_as", _documented_rows())
def test_i23_04_units_as_printed_read_as_documented(written, dimension, read_as):
    _check_row(written, dimension, read_as)


def test_i23_04_documented_rows_match_hand_values():
    # The docs' numbers, worked by hand: the table must say what the definitions say.
    hand = {"1 r.p.m.": REV / 60, "1 r.p.s.": REV, "300 cps": 300 * REV,
            "18000 min^-1": 300 * REV, "3 kgf-m": 3 * 9.80665, "100 grad": math.pi / 2,
            "1 short_ton": 2000 * 0.45359237, "1 long_ton": 2240 * 0.45359237,
            "2 kg.m2": 2.0}
    rows = {w: r for w, _, r in _documented_rows()}
    for written, value in hand.items():
        assert float(rows[written].split()[0]) == pytest.approx(value, rel=1e-7), written


def test_i23_04_documented_rows_read_the_same_from_the_unit_cache(tmp_path, monkeypatch):
    """pint's reading (cold) and the disk table's (warm, pint unusable) agree."""
    monkeypatch.setenv("GYRO_CACHE_DIR", str(tmp_path))
    for table in ("_CHECKED", "_SHOWN", "_TO"):
        monkeypatch.setattr(units, table, {})
    unit_cache.forget()
    rows = [r for r in _documented_rows() if not r[2].startswith("refused")]
    cold = [_check_row(*row) for row in rows]
    unit_cache.save()
    monkeypatch.setattr(units, "registry", lambda: (_ for _ in ()).throw(
        AssertionError("pint asked although cached")))
    for table in ("_CHECKED", "_SHOWN", "_TO"):
        monkeypatch.setattr(units, table, {})
    unit_cache.forget()
    try:
        assert [_check_row(*row) for row in rows] == cold
    finally:
        unit_cache.forget()


@pytest.mark.parametrize("unit, shown", [("r.p.m.", "rpm"), ("r.p.s.", "rps"), ("c/s", "cps")])
def test_i23_04_answer_units_as_printed(unit, shown):
    assert units.check_unit(unit, "rate", "find.spin") == shown
    assert units.convert(REV, "rate", shown) == pytest.approx(
        {"rpm": 60.0, "rps": 1.0, "cps": 1.0}[shown])


# ---- item 16 (continued): the messages -------------------------------------------------

def test_i22_16_negative_tolerance_says_it_must_be_positive(run, write):
    path = write(TOP_11_3.replace("tolerance: 1%", "tolerance: -1%"))
    result = run("check", path)
    assert result.exit_code == 2
    assert "must be positive" in result.stderr and "unexpected '%'" not in result.stderr


def test_i22_16_value_in_find_says_a_unit_is_expected(run, write):
    path = write(TOP_11_3.replace("  precession: rpm", "  precession: 45.13 rpm"))
    line = _one_line_refusal(run("solve", path), "find.precession", "expected a unit",
                             "not a value")
    assert "'1 45.13 rpm'" not in line


def test_i22_16_per_second_is_still_a_unit_in_find(run, write):
    path = write(TOP_11_3.replace("  precession: rpm", "  precession: 1/s"))
    result = run("solve", path)
    assert result.exit_code == 0, result.output
    # 45.13 rpm = 45.13 x 2 pi / 60 = 4.726 rad/s, printed per second
    assert "4.726 1/s" in result.stdout


def test_i22_16_simulate_a_millionth_of_a_period_is_too_short_to_classify(run):
    for name in ("11_2_released_top.yaml", "11_3.yaml"):
        result = run("simulate", ROOT / "problems" / name, "--periods", "1e-6",
                     "--format", "json")
        assert result.exit_code == 0, result.output
        report = json.loads(result.stdout)
        assert report["simulated"]["motion"] == "too short to classify", name
        assert report["difference"]["motion"] is None


def test_i22_16_newline_in_a_file_name_keeps_the_table_one_line_a_problem(run, tmp_path):
    (tmp_path / "new\nline.yaml").write_text(TOP_11_3)
    result = run("check", tmp_path)
    assert result.exit_code == 0, result.output
    heads = [line for line in result.stdout.splitlines() if "11/3" in line]
    assert len(heads) == 1 and "new\\nline.yaml" in heads[0]
    assert all(line.startswith(("  ", "OK")) for line in result.stdout.splitlines()
               if "11/3" not in line)


def _exit_with_reader_gone(*args: str) -> int:
    """Run gyro with a stdout pipe whose reader has already left (as `| true`)."""
    import os
    import subprocess
    import sys

    read, write = os.pipe()
    os.close(read)
    try:
        return subprocess.run([sys.executable, "-m", "gyro_cli", *args], stdout=write,
                              stderr=subprocess.PIPE, timeout=120).returncode
    finally:
        os.close(write)


def test_i22_16_help_into_a_closed_pipe_exits_as_the_commands_do():
    command = _exit_with_reader_gone("kinds", "--help")
    assert command == 141
    assert _exit_with_reader_gone("--help") == command
    assert _exit_with_reader_gone("--version") == command


# ---- item 10: user strings escaped in every output ------------------------------------------

HOSTILE = ('id: "x\\n\\\\input{/etc/hostname}\\n\\e[31mred"\n'
           'title: "<script>alert(1)</script><img src=x onerror=alert(2)> \\e]0;pwned\\a\\u202e"\n'
           'source: "<b>s</b> \\e[2J"\n'
           'notes: ["<script>n</script>\\n\\\\input{x}\\n\\e[1m"]\n')


def _hostile(write, name: str = "p.yaml"):
    body = TOP_11_3.split("kind:", 1)[1]
    return write(HOSTILE + "kind:" + body.replace("source: Chapter 11, problem 11/3\n", "")
                 .replace("notes:\n  - Spin is the rate relative to the precessing frame "
                          "(ψ̇).\n", ""), name)


def test_i22_10_latex_id_newline_cannot_run_input(run, write):
    result = run("solve", "--format", "latex", "--standalone", _hostile(write))
    assert result.exit_code == 0, result.output
    for line in result.stdout.splitlines():
        code = line.split("%", 1)[0] if not line.startswith("%") else ""
        assert not re.search(r"\\input\b", code), line
        assert "\x1b" not in line and "\x07" not in line
    assert "\\textbackslash{}input" in result.stdout


def test_i22_10_markdown_carries_no_raw_html(run, write):
    result = run("solve", "--format", "markdown", _hostile(write))
    assert result.exit_code == 0, result.output
    out = result.stdout
    # a raw < opens HTML in Markdown; \< is a literal sign
    assert not re.search(r"(?<!\\)<", out), out
    assert "\\<script\\>" in out
    assert "\x1b" not in out and "\u202e" not in out
    heading = [line for line in out.splitlines() if line.startswith("## ")]
    assert len(heading) == 1 and "alert(1)" in heading[0]  # the title, on its own line


def test_i22_10_html_carries_no_raw_html(run, write):
    result = run("solve", "--format", "html", _hostile(write))
    assert result.exit_code == 0, result.output
    assert "<script>alert" not in result.stdout and "<img src=x" not in result.stdout


@pytest.mark.parametrize("command", [("solve",), ("check",), ("simulate", "--periods", "1")])
def test_i22_10_terminal_output_has_no_escape_sequences(run, write, command):
    result = run(command[0], _hostile(write), *command[1:])
    assert result.exit_code == 0, result.output
    for text in (result.stdout, result.stderr):
        for raw in ("\x1b", "\x07", "\u202e"):
            assert raw not in text
    assert "\\x1b[31mred" in result.stdout  # shown, not run


def test_i22_10_file_name_and_message_escaped_on_stderr(run, tmp_path):
    path = tmp_path / "bad\x1b[2J.yaml"
    path.write_text("id: x\nkind: nope\ngiven: {}\nfind: [a]\n")
    result = run("solve", path)
    assert result.exit_code == 2
    assert "\x1b" not in result.stderr and "\\x1b[2J" in result.stderr


# ---- item 15: simulate bounds its cost from the whole motion ---------------------------------

SLOW_TOP = (ROOT / "problems" / "11_2_released_top.yaml").read_text().replace(
    "spin: 1800 rpm ", "spin: 60 rpm ")


def test_i22_15_simulate_refuses_a_slow_top_before_starting(run, write, monkeypatch):
    import scipy.integrate

    def started(*args, **kwargs):
        raise AssertionError("the integration started")

    monkeypatch.setattr(scipy.integrate, "DOP853", started)
    result = run("simulate", write(SLOW_TOP), "--periods", "5e4")
    line = _one_line_refusal(result, "integration steps", "rad/s")
    assert "fewer --periods" in line


def test_i22_15_largest_rate_bounds_the_integrated_motion():
    """The energy bound on |omega| holds along an integration that does not use it."""
    import numpy as np

    from gyro_cli.commands import simulate as command
    from gyro_cli.physics import simulate as physics

    path = ROOT / "problems" / "11_2_released_top.yaml"
    import tempfile
    with tempfile.TemporaryDirectory() as folder:
        slow = Path(folder) / "slow.yaml"
        slow.write_text(SLOW_TOP)
        setup = command.prepare(str(slow))
    p = setup.params
    sim = physics.simulate(p, p, 3 * setup.period, samples=3001)
    omega_z = p.spin + p.precession0 * math.cos(p.theta0)
    # |omega|^2 = thetadot^2 + phidot^2 sin^2(theta) + omega_z^2 (Eq. 11.8)
    omega = np.sqrt(sim.theta_rate ** 2 + (sim.phidot * np.sin(sim.theta)) ** 2 + omega_z ** 2)
    bound = physics.largest_rate(p, command._theta_range(setup.analytic))
    assert omega.max() <= bound * (1 + 1e-9)
    assert omega.max() >= 0.99 * bound           # reached at theta_max: the bound is tight
    start = math.sqrt(omega_z ** 2 + (p.precession0 * math.sin(p.theta0)) ** 2)
    assert omega.max() > 3 * start               # the starting |omega| alone was far off
    assert path.exists()


def test_i22_10_answer_sheet_text_reaches_the_terminal_escaped(run, write, tmp_path):
    problem = write(TOP_11_3, "p.yaml")
    sheet = tmp_path / "sheet.csv"
    sheet.write_text("student,problem,answer,value\n"
                     "\"ann\x1b]0;owned\x07\",11/3,min_spin,\"965.4 rpm \x1b[2J\"\n")
    result = run("check", "--answers", sheet, problem)
    for text in (result.stdout, result.stderr):
        assert "\x1b" not in text and "\x07" not in text
    assert "ann\\x1b]0;owned\\x07" in result.stdout


@pytest.mark.parametrize("raw, shown", [
    ("plain θ title", "plain θ title"), ("a\nb", "a\\nb"), ("\x1b[31mred", "\\x1b[31mred"),
    ("bell\x07", "bell\\x07"), ("rtl\u202eevil", "rtl\\u202eevil"), ("csi\x9b", "csi\\x9b"),
    ("no\xa0break", "no break")])
def test_i22_10_terminal_text_shows_controls_as_escapes(raw, shown):
    from gyro_cli.core.errors import terminal_text

    assert terminal_text(raw) == shown


def test_i22_10_html_and_json_send_no_control_characters(run, write):
    for fmt in ("html", "json"):
        result = run("solve", "--format", fmt, _hostile(write))
        assert result.exit_code == 0, result.output
        for raw in ("\x1b", "\x07", "\u202e"):
            assert raw not in result.stdout, (fmt, raw)


def _first_table_spellings() -> list[str]:
    """Every unit spelled in the first column of the docs' first units table."""
    text = (ROOT / "docs" / "real_problems.md").read_text()
    table = text.split("| written | read as |", 1)[1].split("\n\n", 1)[0]
    spellings = []
    for row in table.splitlines()[2:]:
        first = row.split("|")[1]
        spellings += [s for s in re.findall(r"`([^`]+)`", first) if s != "weight"]
    assert len(spellings) >= 30
    return spellings


@pytest.mark.parametrize("spelling", _first_table_spellings())
def test_i23_04_every_documented_spelling_is_accepted(spelling):
    text = spelling if re.match(r"\d+ ", spelling) else f"1 {spelling}"  # `360 kmph`
    readings = []
    for dimension in ("rate", "angle", "speed", "mass", "force", "moment", "inverse_time"):
        for weight in (False, True):
            try:
                readings.append(units.parse(text, dimension, "given.x", weight=weight)[0])
            except InputError:
                pass
    assert readings, f"{spelling!r} is documented but read for no dimension"
