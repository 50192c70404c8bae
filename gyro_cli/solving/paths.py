"""Which problem files a command line names: files, directories and globs."""

from __future__ import annotations

import fnmatch
import os

YAML_SUFFIXES = (".yaml", ".yml")


def problem_files(paths: list[str] | tuple[str, ...],
                  identities: dict[str, tuple[int, int]] | None = None,
                  ) -> tuple[list[str], list[tuple[str, str]]]:
    """Problem files from files, directories (recursive, *.yaml and *.yml) and globs.

    Hidden directories (.git, .venv) are skipped; each real file is named once,
    however many paths lead to it (a symlink, a hard link, ``./x``, a folder
    linked into itself under a ``**`` glob). A directory or a pattern that
    names nothing comes back as (path, message), so the others are still solved.
    ``identities``, if given, gets each file's (device, inode), found on the way
    (for `core.files.refuse_input_as_output`, which then need not look again).
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
        elif os.path.exists(path) or not _has_magic(path):
            files.append(path)  # a missing plain path is reported when it is loaded
        else:
            found = sorted(p for p in _glob(path) if os.path.isfile(p))
            if not found:
                errors.append((path, f"{path}: no files match this pattern"))
            files += found
    seen: set[object] = set()
    unique = []
    for f in files:
        try:
            info = os.stat(f)
            identity = (info.st_dev, info.st_ino)
            if identities is not None:
                identities[f] = identity
            key: object = identity
        except (OSError, ValueError):
            key = os.path.normpath(f)
        if key not in seen:
            seen.add(key)
            unique.append(f)
    return unique, errors


def _has_magic(path: str) -> bool:
    """``glob.has_magic``: a ``*``, ``?`` or ``[`` makes a pattern."""
    return any(c in path for c in "*?[")


def _glob(pattern: str) -> list[str]:
    """``glob.glob(pattern, recursive=True)``, but a ``**`` visits each real directory once.

    Python's glob follows a symlinked directory every time it meets it: a link
    ``a -> .`` makes ``dir/**/*.yaml`` name each file dozens of times, and two
    such links make it never end. Here the walk below ``**`` follows links but
    enters each directory (by device and inode) once.
    """
    import glob  # only for a pattern: a plain path never loads it

    parts = pattern.split(os.sep)
    if "**" not in parts:
        return glob.glob(pattern)
    first = parts.index("**")
    prefix = os.sep.join(parts[:first])
    if first and not prefix:
        prefix = os.sep  # the pattern starts at the root
    rest = parts[first:]
    bases = glob.glob(prefix) if _has_magic(prefix) else [prefix]
    out: list[str] = []
    for base in bases:
        top = base or os.curdir
        if not os.path.isdir(top):
            continue
        seen: set[tuple[int, int]] = set()
        for root, dirs, names in os.walk(top, followlinks=True):
            try:
                info = os.stat(root)
            except OSError:
                dirs[:] = []
                continue
            if (info.st_dev, info.st_ino) in seen:
                dirs[:] = []
                continue
            seen.add((info.st_dev, info.st_ino))
            dirs[:] = sorted(d for d in dirs if not d.startswith("."))
            relative = os.path.relpath(root, top)
            inner = [] if relative == os.curdir else relative.split(os.sep)
            for name in names:
                if _matches(inner + [name], rest):
                    out.append(os.path.join(base, *inner, name) if base else
                               os.path.join(*inner, name))
    return out


def _matches(names: list[str], pattern: list[str]) -> bool:
    """Whether path components match pattern components (``**``: any number of them).

    As glob does, a hidden name matches only a component that starts with a dot.
    """
    if not pattern:
        return not names
    if pattern[0] == "**":
        return any(_matches(names[k:], pattern[1:]) for k in range(len(names) + 1)
                   if not any(n.startswith(".") for n in names[:k]))
    if not names:
        return False
    name, part = names[0], pattern[0]
    if name.startswith(".") and not part.startswith("."):
        return False
    return fnmatch.fnmatch(name, part) and _matches(names[1:], pattern[1:])
