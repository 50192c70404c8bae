"""The registry of problem kinds: name -> module holding ``KIND``.

Adding a kind is one module in this package and one line here. Modules are
imported only when their kind is used, so start-up stays cheap.
"""

from __future__ import annotations

import sys
import types
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

# In the format but not built yet: named plainly rather than "unknown".
PLANNED: dict[str, str] = {
}


def names() -> list[str]:
    return sorted(REGISTRY)


def get(name: object) -> Kind:
    """The Kind called ``name``; InputError naming the known kinds otherwise."""
    if not isinstance(name, str) or name not in REGISTRY:
        if isinstance(name, str) and name in PLANNED:
            raise InputError(f"kind {name!r} ({PLANNED[name]}) is not built in this version of "
                             f"gyro; built kinds: {', '.join(names())}", key="kind")
        from ..core.errors import shown

        raise InputError(f"unknown kind {shown(name)}; known kinds: {', '.join(names())}",
                         key="kind")
    return import_module(REGISTRY[name]).KIND


#: the physics the kinds import when they first solve (so that `gyro solve` of one file
#: loads only its own)
SOLVERS = ("gyro_cli.physics.bicycle", "gyro_cli.physics.elliptic",
           "gyro_cli.physics.nutation", "gyro_cli.physics.stability")


def preload() -> None:
    """Import every kind and its physics now: for worker processes forked afterwards,
    which then start with them in memory instead of each importing them again."""
    for module in (*REGISTRY.values(), *SOLVERS):
        import_module(module)


class _Registry(types.ModuleType):
    """This module, callable: ``gyro_cli.kinds()`` is every built kind by name."""

    def __call__(self) -> dict[str, Kind]:
        return {name: get(name) for name in names()}


sys.modules[__name__].__class__ = _Registry
