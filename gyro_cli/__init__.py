"""gyro: worked answers to textbook problems of gyroscopic motion (Chapter 11).

The Python API (`gyro_cli.api`), loaded on first use so that ``import gyro_cli``
and the command's start-up stay cheap:

    solve(source, **given) -> Result     a path, YAML text or a mapping
    check(*sources) -> CheckReport        compare with the expected answers
    kinds() -> dict[str, Kind]            the problem kinds, their keys and answers
                                          (the registry module gyro_cli.kinds, called)
    sweep(source, **values) -> Sweep      one problem over a grid of given values
    InputError                            bad input: .key, .line, .file, .message
"""

from __future__ import annotations

from importlib import import_module

__version__ = "0.5.0"

__all__ = ["solve", "solve_file", "check", "check_files", "kinds", "sweep", "load", "registry", "Result",
           "Answer", "CheckReport", "Sweep", "InputError", "__version__"]

# Loaded by name on first use (type checkers read __init__.pyi): the core layer imports
# this package for its version, and must not see the API above it.


def __getattr__(name: str) -> object:  # no typing import: start-up stays as it was
    if name == "InputError":
        return import_module(".core.errors", __name__).InputError
    if name == "kinds":  # the registry package, callable: gyro_cli.kinds() lists the kinds
        return import_module(".kinds", __name__)
    if name in __all__:
        return getattr(import_module(".api", __name__), name)
    raise AttributeError(f"module 'gyro_cli' has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))
