"""Issue 36, item 3: each formula written once, in physics/, generic over floats and trees.

A kind builds its steps by calling the physics functions with symbols; its answers and
fast paths call the same functions with floats. No physics function is a float copy that
only the tests call (those live in tests/oracles.py), so a step and a float cannot drift
apart unnoticed.
"""

from __future__ import annotations

import ast
import functools
import importlib
import inspect
import sys
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest
import yaml

from gyro_cli.core.expr import Expr, Sym
from gyro_cli.solving.solve import solve_file

ROOT = Path(__file__).resolve().parent.parent
PKG = ROOT / "gyro_cli"
PHYSICS = PKG / "physics"

#: physics functions production does not call, and why they stay
NOT_CALLED = {
    ("motion", "angles_of_t"): "the exact Euler angles in time (elliptic integrals), the "
                               "oracle the numerical integration is tested against",
}

#: for each kind, the physics functions it must call with symbols to write its steps
STEPS_FROM_PHYSICS = {
    "gyrocompass": ("gyrocompass.directive_stiffness", "gyrocompass.north_seeking_moment",
                    "gyrocompass.period"),
    "rate_gyro": ("rate_gyro.steady_deflection", "rate_gyro.natural_frequency",
                  "rate_gyro.damping_ratio"),
    "edge_runner": ("edge_runner.roller_spin", "edge_runner.couple",
                    "edge_runner.extra_pressure", "edge_runner.pan_force"),
    "directional_gyro": ("directional_gyro.earth_rate_drift", "directional_gyro.longitude_rate",
                         "directional_gyro.transport_wander", "directional_gyro.nut_correction",
                         "directional_gyro.nut_moment"),
    "gyro_drift": ("gyro_drift.drift_rate", "gyro_drift.nutation_frequency"),
    "two_wheeler": ("vehicles.rolling_rate", "vehicles.geared_rate", "vehicles.turn_rate",
                    "vehicles.rotor_inertia", "vehicles.spin_momentum",
                    "vehicles.overturning_couple", "vehicles.centrifugal_couple",
                    "vehicles.heel"),
    "four_wheeler": ("vehicles.rolling_rate", "vehicles.turn_rate", "vehicles.rotor_inertia",
                     "vehicles.spin_momentum", "vehicles.overturning_couple",
                     "vehicles.centrifugal_couple", "vehicles.weight_share",
                     "vehicles.couple_share", "vehicles.outer_reaction",
                     "vehicles.inner_reaction", "vehicles.limiting_speed"),
    "ship": ("vehicles.turn_rate", "vehicles.gyroscopic_couple", "vehicles.circular_frequency",
             "vehicles.max_pitching_rate", "vehicles.precession_for_couple"),
    "aeroplane": ("vehicles.turn_rate", "vehicles.gyroscopic_couple"),
    "released_top": ("nutation.fast_nutation_period", "nutation.fast_mean_precession",
                     "nutation.fast_nutation_amplitude"),
    "steady_precession": ("steady.precession_approx",),
    "rolling_disk": ("stability.disk_critical_axial_rate",),
    # helpers a kind keeps beside its solver, generic too
    "swinging_rotor": ("kinds.swinging_rotor.swing_rate_sq",
                       "kinds.swinging_rotor.swing_acceleration"),
    "gyroscopic_torque": ("kinds.gyroscopic_torque.couple_forces",),
}


def _public_functions(module: Path) -> Iterator[ast.FunctionDef]:
    for node in ast.parse(module.read_text()).body:
        if isinstance(node, ast.FunctionDef) and not node.name.startswith("_"):
            yield node


def _physics_module(node: ast.ImportFrom) -> str | None:
    """'vehicles' for ``from ..physics.vehicles import ...`` (or ``from .vehicles`` inside
    physics/), 'physics' for ``from ..physics import vehicles``."""
    module = node.module or ""
    if module == "physics" and node.level:
        return "physics"
    if module.startswith("physics.") and node.level:
        return module.split(".", 1)[1]
    return None


def _references() -> set[tuple[str, str]]:
    """(module, function) of every physics function named in gyro_cli/ outside its own
    definition: imported by name, taken as an attribute of the imported module, or called
    by a function of its own module."""
    found: set[tuple[str, str]] = set()
    for path in PKG.rglob("*.py"):
        tree = ast.parse(path.read_text())
        own = path.stem if path.parent == PHYSICS else None
        aliases: dict[str, str] = {}
        for node in ast.walk(tree):
            if isinstance(node, ast.ImportFrom):
                where = _physics_module(node) if own is None else \
                    (node.module if node.level == 1 and node.module else None)
                if where == "physics":
                    aliases.update({a.asname or a.name: a.name for a in node.names})
                elif where:
                    found.update((where, a.name) for a in node.names)
        for node in ast.walk(tree):
            if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name) \
                    and node.value.id in aliases:
                found.add((aliases[node.value.id], node.attr))
            elif own and isinstance(node, ast.Name) and isinstance(node.ctx, ast.Load):
                found.add((own, node.id))
    return found


def test_item03_every_public_physics_function_is_called_by_the_package():
    """A physics function only the tests call is a float copy of a step: it belongs in
    tests/oracles.py (or goes)."""
    used = _references()
    unused = [(m.stem, f.name) for m in sorted(PHYSICS.glob("*.py"))
              for f in _public_functions(m)
              if (m.stem, f.name) not in used and (m.stem, f.name) not in NOT_CALLED]
    assert not unused, unused


@pytest.mark.parametrize("name", ["edge_runner.edge_runner", "vehicles.two_wheeler",
                                  "vehicles.limiting_speed_squared",
                                  "earth_precession.precession_rate",
                                  "earth_precession.tidal_from_period",
                                  "earth_precession.node_factor",
                                  "earth_precession.eccentricity_factor",
                                  "gyro_drift.spin_momentum",
                                  "euler_kinematics.fixed_accel_zxz",
                                  "nutation.released_u1", "nutation.psidot",
                                  "nutation.shifted_cubic", "nutation.d_roots",
                                  "bicycle.spectral_abscissa"])
def test_item03_float_copies_of_the_steps_are_gone(name):
    module, function = name.split(".")
    assert not hasattr(importlib.import_module(f"gyro_cli.physics.{module}"), function)


def _generic(module: str) -> list[tuple[str, Callable[..., Any]]]:
    """The module's functions written for floats and trees (annotated V)."""
    mod = importlib.import_module(f"gyro_cli.physics.{module}")
    out = []
    for node in _public_functions(PHYSICS / f"{module}.py"):
        returns = node.returns
        if isinstance(returns, ast.Name) and returns.id in ("V", "F"):
            out.append((node.name, getattr(mod, node.name)))
    return out


GENERIC = [(m, n, f) for m in ("gyrocompass", "rate_gyro", "edge_runner", "directional_gyro",
                               "gyro_drift", "vehicles", "nutation", "steady", "stability")
           for n, f in _generic(m)]


def _arguments(function: Callable[..., Any], tree: bool) -> list[Any]:
    args: list[Any] = []
    for i, (name, param) in enumerate(inspect.signature(function).parameters.items()):
        if param.annotation in ("str", str):
            args.append("same")
        else:
            value = 0.3 + 0.17 * i
            args.append(Sym(name, value, "") if tree else value)
    return args


@pytest.mark.parametrize("module, name, function", GENERIC,
                         ids=[f"{m}.{n}" for m, n, _ in GENERIC])
def test_item03_one_function_gives_the_float_and_the_tree(module, name, function):
    """Called with floats it gives a float; with symbols, the tree that evaluates to it."""
    value = function(*_arguments(function, tree=False))
    tree = function(*_arguments(function, tree=True))
    assert isinstance(value, float), (module, name)
    assert isinstance(tree, Expr), (module, name)
    assert tree.value == pytest.approx(value, rel=1e-14)


def test_item03_the_vehicles_cover_what_the_brief_names():
    names = {n for m, n, _ in GENERIC if m == "vehicles"}
    assert {"turn_rate", "rolling_rate", "overturning_couple", "centrifugal_couple", "heel",
            "limiting_speed", "gyroscopic_couple", "circular_frequency"} <= names


#: a problem that asks what no bundled problem of the kind asks
EXTRA = {"directional_gyro": "id: dg\nkind: directional_gyro\ngiven:\n  latitude: 35 S\n"
                             "  latitude_nut: 48 N\n  angular_momentum: 0.5 kg m^2/s\n"
                             "find: {nut_moment: N m}\n"}


def _problems(kind: str) -> list[Path]:
    return list(_bundled_kinds().get(kind, []))


@functools.cache
def _bundled_kinds() -> dict[str, list[Path]]:
    """The bundled problems by kind, each file read once for every kind's test (PyYAML's
    pure-Python loader read all 96 again for each of 15 kinds)."""
    loader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)
    out: dict[str, list[Path]] = {}
    for path in sorted((ROOT / "problems").glob("*.yaml")):
        out.setdefault(yaml.load(path.read_text(), Loader=loader).get("kind"), []).append(path)
    return out


@pytest.mark.parametrize("kind", sorted(STEPS_FROM_PHYSICS))
def test_item03_each_kind_writes_its_steps_with_the_physics_functions(kind, monkeypatch,
                                                                      tmp_path):
    """Solve the kind's bundled problems with each physics function wrapped: every one the
    kind's steps need is called with a tree (the step), not written again by hand."""
    called: set[str] = set()
    for dotted in STEPS_FROM_PHYSICS[kind]:
        module, name = dotted.rsplit(".", 1)
        package = "gyro_cli" if module.startswith("kinds.") else "gyro_cli.physics"
        real = getattr(importlib.import_module(f"{package}.{module}"), name)

        def spy(*args: Any, _real: Any = real, _dotted: str = dotted) -> Any:
            if any(isinstance(a, Expr) for a in args):
                called.add(_dotted)
            return _real(*args)

        for mod in list(sys.modules.values()):  # the module, and kinds that import the name
            if getattr(mod, "__name__", "").startswith("gyro_cli") and \
                    getattr(mod, name, None) is real:
                monkeypatch.setattr(mod, name, spy)
    problems = _problems(kind)
    assert problems
    if kind in EXTRA:
        problems.append(tmp_path / "extra.yaml")
        problems[-1].write_text(EXTRA[kind])
    for path in problems:
        solve_file(str(path))
    assert called == set(STEPS_FROM_PHYSICS[kind]), set(STEPS_FROM_PHYSICS[kind]) - called
