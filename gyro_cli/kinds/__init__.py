"""The registry of problem kinds: name -> module holding ``KIND``.

Adding a kind is one module in this package and one line here. Modules are
imported only when their kind is used, so start-up stays cheap.
"""

from __future__ import annotations

import sys
import types
from collections.abc import Iterable
from importlib import import_module

from ..core.errors import InputError
from ..core.spec import Kind

REGISTRY: dict[str, str] = {
    "steady_precession": "gyro_cli.kinds.steady_precession",
    "released_top": "gyro_cli.kinds.released_top",
    "gyroscopic_torque": "gyro_cli.kinds.gyroscopic_torque",
    "rolling_disk": "gyro_cli.kinds.rolling_disk",
    "swinging_rotor": "gyro_cli.kinds.swinging_rotor",
    "ship": "gyro_cli.kinds.ship",
    "aeroplane": "gyro_cli.kinds.aeroplane",
    "two_wheeler": "gyro_cli.kinds.two_wheeler",
    "four_wheeler": "gyro_cli.kinds.four_wheeler",
    "torque_free": "gyro_cli.kinds.torque_free",
    "bicycle": "gyro_cli.kinds.bicycle",
    "euler_angles": "gyro_cli.kinds.euler_angles",
    "gyro_drift": "gyro_cli.kinds.gyro_drift",
    "earth_precession": "gyro_cli.kinds.earth_precession",
    "gyrocompass": "gyro_cli.kinds.gyrocompass",
    "rate_gyro": "gyro_cli.kinds.rate_gyro",
    "directional_gyro": "gyro_cli.kinds.directional_gyro",
    "edge_runner": "gyro_cli.kinds.edge_runner",
}


def names() -> list[str]:
    return sorted(REGISTRY)


def get(name: object) -> Kind:
    """The Kind called ``name``; InputError naming the known kinds otherwise."""
    if not isinstance(name, str) or name not in REGISTRY:
        from ..core.errors import shown

        raise InputError(f"unknown kind {shown(name)}; known kinds: {', '.join(names())}",
                         key="kind")
    return import_module(REGISTRY[name]).KIND


def offering(capability: str, styles: Iterable[str]) -> list[str]:
    """The kinds whose ``capability`` (a Kind field: picture, animation, simulation) is one
    of ``styles``, in the order of ``styles`` (the layer's own table), then by name."""
    order = {style: i for i, style in enumerate(styles)}
    found = [(order[style], name) for name in names()
             if (style := getattr(get(name), capability)) in order]
    return [name for _, name in sorted(found)]


def preload() -> None:
    """Import every kind and the physics its solver imports when it first solves (so that
    `gyro solve` of one file loads only its own) now: for worker processes forked
    afterwards, which then start with them in memory instead of each importing them again."""
    for module in REGISTRY.values():
        for physics in import_module(module).KIND.physics:
            import_module(physics)


class _Registry(types.ModuleType):
    """This module, callable: ``gyro_cli.kinds()`` is every built kind by name."""

    def __call__(self) -> dict[str, Kind]:
        return {name: get(name) for name in names()}


sys.modules[__name__].__class__ = _Registry
