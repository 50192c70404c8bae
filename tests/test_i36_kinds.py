"""Issue 36, items 3-5 and the loose ends: a kind is its whole declaration, formulas are
written once, the CLI is a client of the API for check as for solve."""

from __future__ import annotations

import dataclasses
import importlib
import re
import sys
import types
from pathlib import Path

import pytest

from gyro_cli import kinds
from gyro_cli.core.errors import InputError
from gyro_cli.core.spec import Kind, OneOf, Param

ROOT = Path(__file__).resolve().parent.parent
PKG = ROOT / "gyro_cli"


# ---- item 4: typed fields, required keys, one_of, capabilities --------------------

def test_item04_a_kind_declares_typed_fields_not_an_untyped_extra():
    names = {f.name for f in dataclasses.fields(Kind)}
    assert "extra" not in names
    assert {"example", "gravity", "body_keys", "size_free", "one_of", "picture", "animation",
            "simulation", "physics"} <= names
    for name in kinds.names():
        kind = kinds.get(name)
        assert isinstance(kind.example, dict) and kind.example.get("given"), name
        assert isinstance(kind.gravity, bool) and isinstance(kind.size_free, bool)
        assert kind.body_keys is None or all(isinstance(k, str) for k in kind.body_keys)


def _fake_kind(monkeypatch, kind: Kind) -> str:
    """Register ``kind`` under its name for this test (a module of its own)."""
    module = types.ModuleType(f"gyro_cli.kinds._test_{kind.name}")
    module.KIND = kind  # type: ignore[attr-defined]
    monkeypatch.setitem(sys.modules, module.__name__, module)
    monkeypatch.setitem(kinds.REGISTRY, kind.name, module.__name__)
    return kind.name


def _refused(write, kind: str, given: str) -> str:
    from gyro_cli.solving.solve import solve_file

    path = write(f"id: t\nkind: {kind}\ngiven:\n{given}\nfind:\n  couple: N m\n")
    with pytest.raises(InputError) as caught:
        solve_file(str(path))
    return str(caught.value)


def test_item04_a_required_key_is_refused_before_the_solver_runs(monkeypatch, write):
    def never(given, find, work):  # the declaration alone refuses the file
        raise AssertionError("the solver ran without a required key")

    base = kinds.get("aeroplane")
    spin = dataclasses.replace(base.param("spin"), required="give the spin, please")
    turn = dataclasses.replace(base.param("turn_radius"), required=True)
    params = tuple(spin if p.name == "spin" else turn if p.name == "turn_radius" else p
                   for p in base.params)
    name = _fake_kind(monkeypatch, dataclasses.replace(base, name="plane_t", params=params,
                                                       solve=never))
    body = "  J: 1 kg m^2\n"
    message = _refused(write, name, body + "  speed: 1 m/s\n  turn_radius: 1 m")
    assert "given.spin" in message and message.endswith("give the spin, please")
    message = _refused(write, name, body + "  spin: 1 rpm\n  speed: 1 m/s")
    assert "given.turn_radius" in message and "needs this key in `given`" in message


def test_item04_one_of_refuses_none_and_two_in_the_declared_words(monkeypatch, write):
    def never(given, find, work):
        raise AssertionError("the solver ran without its one input")

    base = kinds.get("aeroplane")
    group = OneOf(("speed", "turn_radius"), "give speed or turn_radius")
    name = _fake_kind(monkeypatch, dataclasses.replace(base, name="plane_o", one_of=(group,),
                                                       params=tuple(dataclasses.replace(
                                                           p, required=False)
                                                           for p in base.params),
                                                       solve=never))
    none = _refused(write, name, "  J: 1 kg m^2\n  spin: 1 rpm")
    assert "given.speed" in none and none.endswith("give speed or turn_radius")
    two = _refused(write, name, "  J: 1 kg m^2\n  spin: 1 rpm\n  speed: 1 m/s\n  turn_radius: 1 m")
    assert "given.turn_radius" in two
    assert two.endswith("give one of speed, turn_radius, not speed and turn_radius: they say "
                        "the same thing")


def test_item04_rate_gyro_declares_its_one_input():
    kind = kinds.get("rate_gyro")
    assert [g.keys for g in kind.one_of] == [("rate", "deflection", "moment", "gimbal_rate",
                                              "input_angle")]
    source = (PKG / "kinds" / "rate_gyro.py").read_text()
    assert "len(inputs) != 1" not in source


def test_item04_required_keys_are_declared_not_rechecked():
    assert all(kinds.get("aeroplane").param(k).required for k in ("spin", "speed"))
    # the radius is the motion's: turn_radius on a turn, loop_radius in a loop (the kind's)
    assert kinds.get("ship").param("spin").required
    assert "needs spin (engine speed), speed and turn_radius\",\n" not in (
        PKG / "kinds" / "aeroplane.py").read_text().split("def solve", 1)[1]
    with pytest.raises(ValueError, match="required key has no default"):
        Param("x", "length", "x", "a length", default="1 m", required=True)


def test_item04_the_overflow_refusal_is_written_once():
    phrase = "(a product overflows)"
    holders = [p.relative_to(PKG).as_posix() for p in PKG.rglob("*.py")
               if phrase in p.read_text()]
    assert holders == ["core/errors.py"]


def _kind_strings(path: Path) -> list[str]:
    names = kinds.names()
    return [m for _, m in re.findall(r"([\"'])([a-z_]+)\1", path.read_text()) if m in names]


def test_item04_no_layer_above_kinds_names_a_kind_by_a_string():
    files = [*(PKG / "render").glob("*.py"), *(PKG / "commands").glob("*.py"),
             PKG / "cli.py", PKG / "api.py"]
    named = {f.relative_to(PKG).as_posix(): _kind_strings(f) for f in files}
    assert {f: n for f, n in named.items() if n} == {}
    pattern = rf"kinds\.({'|'.join(kinds.names())})\b|kinds import ({'|'.join(kinds.names())})\b"
    imported = {f.relative_to(PKG).as_posix() for f in files if re.search(pattern, f.read_text())}
    assert imported == set()  # what a layer needs of a kind, the kind declares (Kind.model)
    assert not hasattr(kinds, "SOLVERS")


def test_item04_capabilities_are_found_from_the_kinds_declarations(monkeypatch):
    from gyro_cli.commands import animate, simulate
    from gyro_cli.render import plot

    assert kinds.offering("animation", animate.BUILDERS) == [
        "released_top", "steady_precession", "torque_free", "gyroscopic_torque",
        "rolling_disk", "bicycle"]
    assert kinds.offering("simulation", simulate.SIMULATIONS) == ["released_top",
                                                                  "steady_precession"]
    assert kinds.offering("picture", plot.PICTURES) == ["released_top", "bicycle"]
    # a new kind that declares a motion is animated with no line elsewhere
    new = dataclasses.replace(kinds.get("torque_free"), name="spinning_plate")
    _fake_kind(monkeypatch, new)
    assert "spinning_plate" in kinds.offering("animation", animate.BUILDERS)


def test_item04_preload_imports_the_physics_each_kind_declares(monkeypatch):
    declared = {m for n in kinds.names() for m in kinds.get(n).physics}
    assert "gyro_cli.physics.nutation" in declared
    for module in declared:
        monkeypatch.delitem(sys.modules, module, raising=False)
    kinds.preload()
    assert declared <= set(sys.modules)


def test_item04_adding_a_kind_lists_few_places():
    section = (ROOT / "docs" / "design.md").read_text().split("### Adding a kind")[1]
    section = section.split("\n### ")[0]
    steps = re.findall(r"^\d+\. ", section, re.M)
    assert len(steps) <= 6
    assert "extra=" not in section


def test_item04_test_lists_of_kinds_come_from_the_registry():
    for name in ("test_prose.py", "test_shared_sentences.py"):
        text = (ROOT / "tests" / name).read_text()
        hand = re.findall(r"\"(?:steady_precession|aeroplane)\", \"[a-z_]+\", \"[a-z_]+\"",
                          text)
        assert not hand, name


# ---- loose ends ----------------------------------------------------------------

@pytest.mark.parametrize("module, name", [
    ("gyro_cli.kinds.gyro_drift", "_h"), ("gyro_cli.physics.simulate", "simulate_periods"),
    ("gyro_cli.physics.motion", "phi_of_t"), ("gyro_cli.physics.gyro_drift",
                                              "moment_for_drift"),
    ("gyro_cli.physics.earth_precession", "tidal_from_distance"),
    ("gyro_cli.kinds", "PLANNED")])
def test_loose_ends_dead_code_is_gone(module, name):
    assert not hasattr(importlib.import_module(module), name)


# ---- item 3: formulas written once, for floats and trees ----------------------------

def test_item03_generic_maths_gives_floats_on_numbers_and_nodes_on_trees():
    import math

    from gyro_cli.core import generic
    from gyro_cli.core.expr import Expr, Sym, formula

    assert generic.cos(0.3) == math.cos(0.3) and isinstance(generic.sqrt(4), float)
    lam = Sym("lambda", 0.3, "deg")
    tree = generic.cos(lam)
    assert isinstance(tree, Expr) and formula(tree) == "cos(lambda)"
    assert generic.pi_like(1.0) == math.pi and isinstance(generic.pi_like(lam), Expr)


@pytest.mark.parametrize("module, call", [
    ("gyrocompass", lambda P, a, b, c: P.period(a, P.north_seeking_moment(
        P.directive_stiffness(a, b, c), c))),
    ("rate_gyro", lambda P, a, b, c: P.damping_ratio(a, b, c) + P.natural_frequency(b, c)
     + P.steady_deflection(a, b, c) + P.gimbal_rate(a, b, c) + P.rate_from_moment(a, b))])
def test_item03_one_physics_function_gives_the_float_and_the_tree(module, call):
    """The same function, called with floats (an independent value) and with symbols (the
    tree a kind writes as its step): the tree evaluates to the float."""
    from gyro_cli.core.expr import Expr, Sym

    P = importlib.import_module(f"gyro_cli.physics.{module}")
    a, b, c = 0.7, 1.3, 0.4
    value = call(P, a, b, c)
    assert isinstance(value, float)
    tree = call(P, Sym("a", a, ""), Sym("b", b, ""), Sym("c", c, ""))
    assert isinstance(tree, Expr) and tree.value == pytest.approx(value, rel=1e-14)


def test_item03_the_kinds_build_their_steps_from_the_physics_functions():
    compass = (PKG / "kinds" / "gyrocompass.py").read_text()
    assert "directive_stiffness(H_, Omega_E, lam)" in compass
    rate = (PKG / "kinds" / "rate_gyro.py").read_text()
    assert "# steady_deflection" not in rate and "steady_deflection(H_, Omega, k_)" in rate
    for name in ("swing_period", "_agm"):
        assert not hasattr(importlib.import_module("gyro_cli.physics.gyrocompass"), name)
    torque = importlib.import_module("gyro_cli.kinds.gyroscopic_torque")
    for name in ("gyroscopic_moment", "counterweight_offset", "tilt_rate_uniform",
                 "tilt_rate_harmonic"):  # float copies only tests called: now the tests' own
        assert not hasattr(torque, name)
    drift = importlib.import_module("gyro_cli.physics.gyro_drift")
    assert not hasattr(drift, "gimbal_angles") and not hasattr(drift, "nutation_amplitudes")


# ---- item 5: the CLI a client of the API, one check driver ------------------------

def test_item05_gyro_check_runs_through_the_api(monkeypatch, run):
    from gyro_cli import api

    calls = []
    real = api.check_stream

    def spy(*args, **kwargs):
        calls.append(kwargs)
        return real(*args, **kwargs)

    monkeypatch.setattr(api, "check_stream", spy)
    result = run("check", ROOT / "problems" / "11_3.yaml")
    assert result.exit_code == 0 and calls
    cli = (PKG / "cli.py").read_text()
    assert "from .checking" not in cli and "checking." not in cli


def test_item05_one_check_driver_in_process_and_in_workers():
    check = (PKG / "checking" / "check.py").read_text()
    api = (PKG / "api.py").read_text()
    # check_file is called by the one driver (checks) and its pool only
    assert api.count("check_file(") == 0
    assert "[check_file(f, strict) for f in files]" not in check


def test_item05_widening_find_and_the_units_check_are_written_once():
    for path in [PKG / "api.py", PKG / "commands" / "export.py",
                 *(PKG / "checking").glob("*.py")]:
        text = path.read_text()
        assert "find.setdefault(name, None)" not in text, path.name
        assert "dataclasses.replace(problem, find=" not in text, path.name
    assert (PKG / "api.py").read_text().count("expected si or us") == 1
    grades = (PKG / "checking" / "grades.py").read_text()
    assert "this problem's rows are errors" not in grades
    assert "this variant's rows are errors" not in grades
    assert grades.count("_solved_for(") == 3  # its definition and the two gradings


def test_item05_solve_asking_adds_the_answers_in_si(tmp_path):
    from gyro_cli.solving.problem import load
    from gyro_cli.solving.solve import asking, solve_asking

    problem = load(str(ROOT / "problems" / "11_3.yaml"))
    assert asking(problem, ["precession"]) is problem
    wider = asking(problem, ["precession", "min_spin", "axial_rate"])
    assert list(wider.find) == [*problem.find, "axial_rate"] and wider.find["axial_rate"] is None
    assert "axial_rate" in solve_asking(problem, ["axial_rate"]).answers
