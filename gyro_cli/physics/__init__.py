"""Physics on plain floats: the exact nutation solution, theta(t), the
integrator of Euler's equations, shared algebra. No files, no units, no
printing; imports only the standard library, numpy, scipy and core.errors."""

#: what the solvers import inside the functions that need it (so that a command that does
#: not solve such a problem never loads it)
LAZY_IMPORTS = ("numpy",)


def preload() -> None:
    """Import ``LAZY_IMPORTS`` now (before forking workers); one that is missing is
    left to fail where it is used, as it would have."""
    from importlib import import_module

    for name in LAZY_IMPORTS:
        try:
            import_module(name)
        except ImportError:
            pass
