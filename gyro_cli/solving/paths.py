"""Which problem files a command line names: files, directories and globs."""

from __future__ import annotations

import glob
import os

YAML_SUFFIXES = (".yaml", ".yml")


def problem_files(paths: list[str] | tuple[str, ...]) -> tuple[list[str], list[tuple[str, str]]]:
    """Problem files from files, directories (recursive, *.yaml and *.yml) and globs.

    Hidden directories (.git, .venv) are skipped; each file is named once. A
    directory or a pattern that names nothing comes back as (path, message), so
    the others are still solved.
    """
    files: list[str] = []
    errors: list[tuple[str, str]] = []
    for path in paths:
        if os.path.isdir(path):
            found = []
            for root, dirs, names in os.walk(path):
                dirs[:] = sorted(d for d in dirs if not d.startswith("."))
                found += [os.path.join(root, n) for n in names
                          if n.endswith(YAML_SUFFIXES) and not n.startswith(".")]
            if not found:
                errors.append((path, f"{path}: no .yaml or .yml files in this directory"))
            files += sorted(found)
        elif os.path.exists(path) or not glob.has_magic(path):
            files.append(path)  # a missing plain path is reported when it is loaded
        else:
            found = sorted(p for p in glob.glob(path, recursive=True) if os.path.isfile(p))
            if not found:
                errors.append((path, f"{path}: no files match this pattern"))
            files += found
    seen: set[str] = set()
    unique = []
    for f in files:
        key = os.path.normpath(f)
        if key not in seen:
            seen.add(key)
            unique.append(f)
    return unique, errors
