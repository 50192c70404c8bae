"""Regression tests, one per root the fuzzing found: each input gives exit 0 with finite
numbers, exit 1 (check), or exit 2 with one line naming the file and the key."""

from __future__ import annotations

import re
import time

import pytest
from conftest import PROBLEMS

from gyro_cli.core import safeyaml

BASE = (PROBLEMS / "11_5.yaml").read_text()  # gyroscopic_torque, expected answers
NOT_FINITE = re.compile(r"(?<![\w.\\])[-+]?(?:nan|inf)(?![\w])", re.I)


def variant(old: str, new: str, text: str = BASE) -> str:
    assert old in text, old
    return text.replace(old, new, 1)


def one_line(result, *fragments):
    assert result.exit_code == 2, result.output
    assert "Traceback" not in result.output
    lines = result.stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith("gyro: "), result.stderr
    for fragment in fragments:
        assert fragment in lines[0], (fragment, lines[0])
    return lines[0]


def everywhere(run, path, *fragments):
    """The same one line from solve in every format and from check."""
    for args in (["solve"], ["solve", "--format", "json"], ["solve", "--format", "latex"],
                 ["check"]):
        one_line(run(*args, path), str(path), *fragments)


@pytest.mark.parametrize("old, new, fragments", [
    # YAML 1.1 dates: 2024-02-31 raised inside PyYAML; dates now stay text.
    ('id: "11/5"', "id: 2024-02-31", None),
    ("k_axial: 35 mm", "k_axial: 2024-02-31", ["given.k_axial (line 12)", "2024-02-31"]),
    ("k_axial: 35 mm", "k_axial: !!timestamp 2024-02-31", ["given.k_axial"]),
    # 0x numbers are numbers without a unit; a broken one is a YAML error at its line.
    ("k_axial: 35 mm", "k_axial: 0x1F", ["given.k_axial", "expected a length"]),
    ("k_axial: 35 mm", "k_axial: !!int 0x", ["line 12", "cannot read '0x' as an integer"]),
    ("k_axial: 35 mm", "k_axial: 0o", ["given.k_axial"]),
    # !!bool tags
    ("k_axial: 35 mm", "k_axial: !!bool maybe", ["line 12", "as true/false"]),
    ("k_axial: 35 mm", "k_axial: !!bool yes", ["given.k_axial", "expected a quantity"]),
    ("k_axial: 35 mm", "k_axial: !!float abc", ["line 12", "as a number"]),
    ("k_axial: 35 mm", "k_axial: !!binary '@@@'",
     ["given.k_axial (line 12)", "tag not allowed (!!binary)"]),
    # huge integers: 5000 digits is past Python's int-from-text limit, 400 past a double
    ("k_axial: 35 mm", "k_axial: " + "9" * 5000, ["line 12", "as an integer"]),
    ("k_axial: 35 mm", "k_axial: " + "9" * 400, ["line 12", "400 digits is out of range"]),
    ("k_axial: 35 mm", "k_axial: -" + "9" * 320, ["line 12", "out of range"]),
    # non-finite YAML floats are named as YAML writes them
    ("k_axial: 35 mm", "k_axial: .nan", ["given.k_axial", "'.nan'"]),
    ("k_axial: 35 mm", "k_axial: -.inf", ["given.k_axial", "'-.inf'"]),
    # find as a list of mappings was "unhashable type: 'dict'"
    ("find:\n  bearing_forces: N\n  moment: N*m", "find:\n  - {moment: N*m}",
     ["find (line 17)", "got a mapping in the list"]),
    ("  moment: N*m", "  moment: [N*m, .nan]", ["find.moment", "[N*m, .nan]"]),
    # a newline inside a key is shown escaped, on the one line
    ("  k_axial: 35 mm", '  "k_ax\\nial": 35 mm', ["given.k_ax\\nial (line 12)"]),
    # units with a trailing *, empty (), unbalanced brackets: bad input, not a crash
    ("  moment: N*m", "  moment: N*m*", ["find.moment"]),
    ("  moment: N*m", "  moment: N*m()", ["find.moment"]),
    ("  moment: N*m", "  moment: (N*m", ["find.moment"]),
    ("spin: -1725 rpm", "spin: -1725 rpm relative to the precessing frame psidot, see notes",
     ["given.spin"]),
    # a kind's own check that would print inf (m l^2 = inf kg m^2) says it overflows
    ("mass: 2.5 kg", "mass: 1e300 kg", None),
])
def test_root(run, write, old, new, fragments):
    path = write(variant(old, new))
    if fragments is None:  # this one solves: finite numbers, exit 0 or 1
        for args in (["solve"], ["solve", "--format", "json"], ["check"]):
            result = run(*args, path)
            assert result.exit_code in (0, 1), result.output
            assert result.stderr == "" and not NOT_FINITE.search(result.stdout)
        return
    everywhere(run, path, *fragments)


@pytest.mark.parametrize("old, new", [
    ('title: Motor on a turntable, forces in its supports', "title: .nan"),
    ('id: "11/5"', "id: -.inf"),
    ("notes:\n", "notes:\n  - .inf\n"),
])
def test_non_finite_text_is_shown_as_yaml_writes_it(run, write, old, new):
    path = write(variant(old, new))
    for fmt in ("text", "json", "markdown", "latex"):
        result = run("solve", "--format", fmt, path)
        assert result.exit_code == 0, result.output
        assert not NOT_FINITE.search(result.stdout), fmt
    assert run("check", path).exit_code == 0


def test_a_kind_that_is_not_a_word(run, write):
    everywhere(run, write(variant("kind: gyroscopic_torque", "kind: .nan")), "kind",
               "unknown kind .nan")


def test_a_kind_message_that_would_print_inf(run, write):
    path = write(variant("k_axial: 35 mm", "k_axial: 1e200 m"))
    for args in (["solve"], ["check"]):
        result = run(*args, path)
        if result.exit_code == 2:
            line = one_line(result, str(path))
            assert not NOT_FINITE.search(line.replace("'", ""))
        else:
            assert result.exit_code in (0, 1) and not NOT_FINITE.search(result.stdout)


@pytest.mark.parametrize("depth", [65, 1000, 100_000])
@pytest.mark.parametrize("style", ["flow", "block"])
def test_deep_nesting_is_refused_before_it_is_built(run, write, depth, style):
    if style == "flow":
        text = variant("kind: gyroscopic_torque", "kind: " + "[" * depth + "]" * depth)
    else:
        depth = min(depth, 500)  # indentation grows as depth squared
        text = BASE + "vary:\n" + "".join("  " * i + f"k{i}:\n" for i in range(1, depth)) \
            + "  " * depth + "x: 1\n"
    path = write(text)
    began = time.monotonic()
    everywhere(run, path, "nested deeper than 64 levels")
    assert time.monotonic() - began < 20


def test_nesting_at_the_limit_is_read(write):
    from gyro_cli.solving.problem import read_yaml

    inner = "[" * (safeyaml.MAX_DEPTH - 1) + "]" * (safeyaml.MAX_DEPTH - 1)
    data, _ = read_yaml(str(write(f"a: {inner}\n")))
    assert isinstance(data["a"], list)


def test_an_alias_bomb_is_refused_before_it_is_expanded(run, write):
    bomb = "a0: &a0 [lol, lol, lol, lol, lol, lol, lol, lol, lol]\n" + "".join(
        f"a{i}: &a{i} [{', '.join([f'*a{i - 1}'] * 9)}]\n" for i in range(1, 10))
    path = write(bomb + BASE)
    began = time.monotonic()
    everywhere(run, path, "expand to more than 100000 values")
    assert time.monotonic() - began < 10


def test_ordinary_aliases_are_fine(run, write):
    text = variant("  spin: -1725 rpm", "  spin: &s -1725 rpm")
    text = text.replace("  spin: [0.8, 1.2]", "  spin: *s")  # 11/5's own vary block
    assert "spin: *s" in text
    assert run("check", write(text)).exit_code == 0


def test_an_alias_cycle_is_refused(run, write):
    everywhere(run, write("x: &a [1, *a]\n" + BASE), "alias *a", "cycle")


def test_a_denormal_expected_value_fails_with_finite_figures(run, write):
    path = write(variant("moment: -2.781 N*m", "moment: 1e-320 N*m"))
    result = run("check", path)
    assert result.exit_code == 1 and result.stderr == ""
    assert "FAIL  moment" in result.stdout and not NOT_FINITE.search(result.stdout)
    result = run("check", "--format", "json", path)
    assert result.exit_code == 1 and "Infinity" not in result.stdout


def test_far_apart_roots_are_matched_without_a_math_error(run, write):
    # log(|1e-300| / |1e300|) underflowed to log(0)
    path = write(variant("bearing_forces: [35.15 N, 62.95 N]",
                         "bearing_forces: [1e-300 N, 1e300 N]"))
    result = run("check", path)
    assert result.exit_code == 1 and result.stderr == ""
    assert not NOT_FINITE.search(result.stdout)


def test_an_answer_that_overflows_only_in_the_asked_unit(run, write):
    path = write(variant("mass: 2.5 kg", "mass: 1e300 kg").replace("  moment: N*m",
                                                                    "  moment: fN*m"))
    everywhere(run, path, "find.moment (line 19)", "too large to express in fN m")


def test_a_got_value_too_large_for_the_expected_values_unit(run, write):
    text = variant("mass: 2.5 kg", "mass: 1e300 kg")
    path = write(variant("moment: -2.781 N*m", "moment: -2.781 fN*m", text))
    result = run("check", path)
    assert result.exit_code == 1 and result.stderr == ""
    assert "too large to express in fN m" in result.stdout
    assert not NOT_FINITE.search(result.stdout)


def test_a_tolerance_too_large_for_the_expected_unit(run, problems_dir, write):
    """Found by the fuzz run: 1e300 rev/s in arcsec/yr printed '+-inf arcsec/yr'."""
    text = (problems_dir / "11_3_equinoxes.yaml").read_text()
    text = re.sub(r"tolerance:(.|\n)*", 'tolerance:\n  precession_rate: "1e300 rev/s"\n'
                  '  default: 1%\n', text)
    result = run("check", write(text))
    assert result.exit_code == 2
    assert "too large to express in arcsec/yr" in result.stderr
    assert result.stderr.count("\n") == 1 and not NOT_FINITE.search(result.output)


def test_inf_inside_a_step_is_not_printed(run, write):
    """A top thrown through the lowest point: n2 = (u2 - u1)/(1 + u1) has u1 = -1."""
    top = (PROBLEMS / "11_2_released_top.yaml").read_text()
    text = re.sub(r"theta0: .*", "theta0: 180 deg", top)
    text = re.sub(r"(theta0: 180 deg\n)", r"\1  theta_rate0: 1 rad/s\n", text)
    text = re.sub(r"expected:(.|\n)*", "", text)
    path = write(text)
    for fmt in ("text", "json", "markdown", "latex"):
        result = run("solve", "--format", fmt, path)
        assert result.exit_code == 0, result.output
        assert not NOT_FINITE.search(result.stdout.replace("\\infty", "")), fmt


def test_a_step_that_overflows_is_bad_input(run, write, monkeypatch):
    import dataclasses
    import importlib

    module = importlib.import_module("gyro_cli.kinds.gyroscopic_torque")
    real = module.KIND.solve

    def overflowing(given, find, work):
        real(given, find, work)
        work.step("Q", value=float("inf"), unit="N")

    monkeypatch.setattr(module, "KIND", dataclasses.replace(module.KIND, solve=overflowing))
    everywhere(run, PROBLEMS / "11_5.yaml", "given", "the step Q is not a finite number")


@pytest.mark.parametrize("bad", [float("inf"), float("-inf")])
def test_a_symbol_that_overflows_in_a_tree_is_bad_input(run, write, monkeypatch, bad):
    """A step whose value is finite (1/inf = 0) but whose formula shows a symbol that
    overflowed: the solve made a symbol that is not finite, so its trees are walked and
    the step refused. (A solve that made none skips the walk: Sym.unfinite.)"""
    import dataclasses
    import importlib

    from gyro_cli.core.expr import Num, Sym

    module = importlib.import_module("gyro_cli.kinds.gyroscopic_torque")
    real = module.KIND.solve

    def overflowing(given, find, work):
        real(given, find, work)
        work.step("Q", Num(1.0) / Sym("F_big", bad, "N"), unit="1/N")

    monkeypatch.setattr(module, "KIND", dataclasses.replace(module.KIND, solve=overflowing))
    everywhere(run, PROBLEMS / "11_5.yaml", "given", "the step Q overflows for these data")


def test_only_a_symbol_made_with_a_value_that_is_not_finite_is_counted():
    """Sym.unfinite counts inf and a nan made by arithmetic, not NAMED (a symbol only named
    in a definition) nor any finite value."""
    from gyro_cli.core.expr import NAMED, Sym

    before = Sym.unfinite
    for value in (0.0, -2.5, 1e308, 5e-324, 3, NAMED):
        Sym("x", value)
    assert Sym.unfinite == before
    for value in (float("inf"), -float("inf"), float("inf") * 0, float("nan"), "text"):
        Sym("x", value)
    assert Sym.unfinite == before + 5


def test_check_directory_lists_every_file_with_one_line_per_bad_file(run, tmp_path):
    good = (PROBLEMS / "11_3.yaml").read_text()
    (tmp_path / "a_good.yaml").write_text(good)
    (tmp_path / "b_date.yaml").write_text(variant("k_axial: 35 mm", "k_axial: !!bool maybe"))
    (tmp_path / "c_deep.yaml").write_text("kind: " + "[" * 100_000 + "]" * 100_000 + "\n")
    (tmp_path / "d_bomb.yaml").write_text("a: &a [x, x, x, x, x, x, x, x, x, x]\n" + "".join(
        f"a{i}: &a{i} [{', '.join(['*a' if i == 1 else f'*a{i - 1}'] * 10)}]\n"
        for i in range(1, 8)))
    (tmp_path / "e_find.yaml").write_text(variant("find:\n  bearing_forces: N\n  moment: N*m",
                                                  "find:\n  - {moment: N*m}"))
    (tmp_path / "f_empty.yaml").write_text("")
    (tmp_path / "g_binary.yaml").write_bytes(b"\xff\xfe\x00garbage")
    result = run("check", tmp_path)
    assert result.exit_code == 2
    bad = ["b_date", "c_deep", "d_bomb", "e_find", "f_empty", "g_binary"]
    lines = result.stderr.splitlines()
    assert len(lines) == len(bad)
    for name in bad:
        assert sum(name in line for line in lines) == 1
        row = next(i for i, line in enumerate(result.stdout.splitlines()) if name in line)
        following = result.stdout.splitlines()[row + 1]
        assert following.startswith("  ERROR  ") and name in following
    assert "a_good.yaml" in result.stdout and "PASS" in result.stdout
    assert "Traceback" not in result.output


def test_inertia_about_the_centre_without_a_mass(run, write):
    """Found by the fuzz run on merged main: J and I_cg given, cg_distance given and no
    mass made the parallel-axis step format a missing mass (internal error, exit 3)."""
    free = write("id: x\nkind: torque_free\ngiven:\n  J: 8e37 kg m^2\n  I_cg: 7.9e37 kg m^2\n"
                 "  axial_rate: 7.3e-5 rad/s\n  omega_angle: 0.25 arcsec\n  cg_distance: 0 um\n"
                 "find:\n  precession: rad/s\n", "free.yaml")
    one_line(run("solve", free), "given.cg_distance", "does not apply")
    # steady precession under an applied moment, balanced (l = 0): I about the pivot is I_G
    top = write("id: y\nkind: steady_precession\ngiven:\n  J: 0.02 kg m^2\n  I_cg: 0.05 kg m^2\n"
                "  cg_distance: 0 m\n  theta: 60 deg\n  spin: 100 rad/s\n  moment: 2 N m\n"
                "find:\n  precession: rad/s\n", "top.yaml")
    result = run("solve", "--format", "json", top)
    assert result.exit_code == 0, result.output
    import json
    import math
    # (J - I) cos(th) x^2 + J psidot x - M / sin(th) = 0, I = I_G = 0.05 (l = 0), by hand
    a, b, c = (0.02 - 0.05) * 0.5, 0.02 * 100, -2 / math.sin(math.radians(60))
    roots = sorted([(-b + math.sqrt(b * b - 4 * a * c)) / (2 * a),
                    (-b - math.sqrt(b * b - 4 * a * c)) / (2 * a)])
    got = json.loads(result.stdout)["answers"]["precession"]["si_values"]
    assert got == pytest.approx(roots, rel=1e-12)
