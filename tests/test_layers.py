"""The package's layers (pyproject's import-linter contracts) and no import circles.

import-linter is the authority (`lint-imports`, run by `make test`); these tests
also look at the import graph directly, so a circle between two modules of one
layer, or a kind the registry names but cannot import, fails here too.
"""

from __future__ import annotations

import importlib
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

grimp = pytest.importorskip("grimp")

ROOT = Path(__file__).resolve().parents[1]
LAYERS = ["cli", "commands", "render", "checking", "solving", "kinds", "physics", "core"]


def _graph():
    return grimp.build_graph("gyro_cli", exclude_type_checking_imports=False)


def _layer(module: str) -> int | None:
    parts = module.split(".")
    return LAYERS.index(parts[1]) if len(parts) > 1 and parts[1] in LAYERS else None


def upward_imports(edges) -> list[tuple[str, str]]:
    """(importer, imported) pairs where a module imports from a layer above its own."""
    bad = []
    for importer, imported in edges:
        a, b = _layer(importer), _layer(imported)
        if a is not None and b is not None and b < a:
            bad.append((importer, imported))
    return bad


def _edges(graph) -> list[tuple[str, str]]:
    return [(m, i) for m in graph.modules for i in graph.find_modules_directly_imported_by(m)]


def cycles(edges) -> list[list[str]]:
    """Strongly connected components with more than one module (Tarjan)."""
    succ: dict[str, list[str]] = {}
    for a, b in edges:
        succ.setdefault(a, []).append(b)
        succ.setdefault(b, [])
    index, low, stack, on, out = {}, {}, [], set(), []
    sys.setrecursionlimit(10000)

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on.add(v)
        for w in succ[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    for v in succ:
        if v not in index:
            visit(v)
    return out


def _without_packages(edges):
    # a package's __init__ importing its own modules is not a circle of modules
    return [(a, b) for a, b in edges if not a.startswith(b + ".") and not b.startswith(a + ".")]


def test_lint_imports_passes():
    exe = shutil.which("lint-imports") or str(Path(sys.executable).parent / "lint-imports")
    run = subprocess.run([exe], cwd=ROOT, capture_output=True, text=True)
    assert run.returncode == 0, run.stdout[-2000:] + run.stderr[-2000:]


def test_no_module_imports_one_that_imports_it_back():
    assert cycles(_without_packages(_edges(_graph()))) == []


def test_no_upward_import():
    assert upward_imports(_edges(_graph())) == []


def test_an_upward_import_would_be_caught():
    edges = _edges(_graph()) + [("gyro_cli.core.units", "gyro_cli.render.report")]
    assert upward_imports(edges) == [("gyro_cli.core.units", "gyro_cli.render.report")]
    assert cycles([("a", "b"), ("b", "c"), ("c", "a")]) == [["a", "b", "c"]]


def test_every_registered_kind_imports():
    # the registry imports kinds by name, which no import linter sees
    from gyro_cli import kinds

    for name, module in kinds.REGISTRY.items():
        assert importlib.import_module(module).KIND.name == name
