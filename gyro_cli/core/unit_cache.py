"""Units pint has resolved before, kept on disk so that later runs need no pint.

pint stays the one authority on units: an entry is only ever written from
pint's own answer (a unit's SI factor, its printed form, whether it is US
customary). The file is keyed by gyro's version and by the pint installed (the
path and modification time of its package), so upgrading either starts a new
table; a file that is unreadable, damaged, too large or written for another
version is ignored and rebuilt. It lives in ``$GYRO_CACHE_DIR``, else
``$XDG_CACHE_HOME/gyro``, else ``~/.cache/gyro``; ``GYRO_CACHE_DIR=""`` turns it
off. It is written once, atomically, when the process ends, and only if a new
unit was met.
"""

from __future__ import annotations

import atexit
import json
import math
import os

FORMAT = 1
MAX_BYTES = 1 << 20      # a cache file larger than this is not read
MAX_ENTRIES = 4096       # per table
SEP = "\x1f"             # joins the parts of a key (never in a unit string)

_tables: dict[str, dict] | None = None
_dirty = False
_registered = False


def directory() -> str | None:
    """Where the cache lives, or None when it is switched off."""
    env = os.environ.get("GYRO_CACHE_DIR")
    if env is not None:
        return env or None
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return os.path.join(base, "gyro")


def path() -> str | None:
    folder = directory()
    return os.path.join(folder, "units.json") if folder else None


def stamp() -> list | None:
    """What the table was made with: gyro's version and the installed pint (path, mtime)."""
    import importlib.util

    from .. import __version__

    try:
        spec = importlib.util.find_spec("pint")
        origin = spec.origin if spec else None
        return [FORMAT, __version__, origin, os.stat(origin).st_mtime_ns] if origin else None
    except (OSError, ImportError, ValueError):
        return None


def _valid(table: str, key: object, value: object) -> bool:
    if not isinstance(key, str):
        return False
    if table == "shown":
        return isinstance(value, str)
    if table == "to":
        return isinstance(value, float) and math.isfinite(value) and value != 0
    return (isinstance(value, list) and len(value) == 3 and isinstance(value[0], float)
            and math.isfinite(value[0]) and isinstance(value[1], str)
            and isinstance(value[2], bool))


def _load() -> dict[str, dict]:
    tables: dict[str, dict] = {"parse": {}, "shown": {}, "to": {}}
    where, made = path(), stamp()
    if where is None or made is None:
        return tables
    try:
        with open(where, "rb") as handle:
            raw = handle.read(MAX_BYTES + 1)
        data = json.loads(raw) if len(raw) <= MAX_BYTES else None
    except (OSError, ValueError, RecursionError):
        return tables
    if not isinstance(data, dict) or data.get("stamp") != made:
        return tables
    for name, table in tables.items():
        stored = data.get(name)
        if isinstance(stored, dict):
            table.update((k, v) for k, v in list(stored.items())[:MAX_ENTRIES]
                         if _valid(name, k, v))
    return tables


def _tables_now() -> dict[str, dict]:
    global _tables
    if _tables is None:
        _tables = _load()
    return _tables


def get(table: str, *key: object):
    """The stored entry for ``key`` in ``table`` (parse, shown, to), or None."""
    return _tables_now()[table].get(SEP.join(map(str, key)))


def put(table: str, value, *key: object) -> None:
    """Remember an entry pint gave; written to disk when the process ends."""
    global _dirty, _registered
    entries = _tables_now()[table]
    name = SEP.join(map(str, key))
    if entries.get(name) == value or len(entries) >= MAX_ENTRIES or path() is None:
        return
    entries[name] = value
    _dirty = True
    if not _registered:
        atexit.register(save)
        _registered = True


def save() -> None:
    """Write the table atomically if it changed; a cache never fails a run."""
    global _dirty
    where, made = path(), stamp()
    if not _dirty or _tables is None or where is None or made is None:
        return
    import tempfile

    tmp = None
    try:
        os.makedirs(os.path.dirname(where), exist_ok=True)
        fd, tmp = tempfile.mkstemp(prefix=".units-", suffix=".tmp", dir=os.path.dirname(where))
        with os.fdopen(fd, "w", encoding="utf-8") as handle:
            json.dump(dict(_tables, stamp=made), handle)
        os.replace(tmp, where)
        tmp = None
        _dirty = False
    except OSError:
        pass
    finally:
        if tmp is not None:
            try:
                os.unlink(tmp)
            except OSError:
                pass


def forget() -> None:
    """Drop what is held in memory (tests: the next get reads the file again)."""
    global _tables, _dirty
    _tables, _dirty = None, False
