"""Units pint has resolved before, kept on disk so that later runs need no pint.

pint stays the one authority on units: an entry is only ever written from
pint's own answer (a unit's SI factor, its printed form, whether it is US
customary). The file is keyed by a hash of everything that decides a reading:
gyro's version and its own unit sources (``core/unit*.py``: the aliases, the
words, the registry's definitions) and the pint installed (its version, the
path and modification time of its package and of its definitions file), so
changing any of them starts a new table; a file that is unreadable, damaged,
too large, not a regular file or written for another stamp is ignored and
rebuilt. It lives in ``$GYRO_CACHE_DIR``, else ``$XDG_CACHE_HOME/gyro``, else
``~/.cache/gyro``; ``GYRO_CACHE_DIR=""`` turns it off (and pint's own disk
cache with it). It is written once, atomically, when the process ends, and only
if a new unit was met; a cache never fails a run.

pint's disk cache sits in ``pint/`` beside it (``pint_folder``), gyro's own, so
that a read-only or missing HOME, or a damaged pickle, is never pint's problem
to fail on: see ``units.registry``.
"""

from __future__ import annotations

import atexit
import math
import os

TYPE_CHECKING = False  # typing is not imported here: its names are only for mypy
if TYPE_CHECKING:
    import ast

FORMAT = 2
MAX_BYTES = 1 << 20      # a cache file larger than this is not read
MAX_ENTRIES = 4096       # per table
SEP = "\x1f"             # joins the parts of a key (never in a unit string)

_tables: dict[str, dict] | None = None
_dirty = False
_registered = False


def directory() -> str | None:
    """Where the cache lives, or None when it is switched off or has no home.

    An XDG_CACHE_HOME that is not absolute is ignored (the XDG rule); a HOME
    that is unset, empty, relative or not a directory means no cache, rather
    than a ``.cache`` folder in the working directory or a HOME created anew.
    """
    env = os.environ.get("GYRO_CACHE_DIR")
    if env is not None:
        return env or None
    xdg = os.environ.get("XDG_CACHE_HOME")
    if xdg and os.path.isabs(xdg):
        return os.path.join(xdg, "gyro")
    home = os.path.expanduser("~")
    if not (home and os.path.isabs(home) and os.path.isdir(home)):
        return None
    return os.path.join(home, ".cache", "gyro")


def pint_folder() -> str | None:
    """A folder for pint's own disk cache, or None: no cache, or one gyro cannot trust.

    None when the cache is off, when the folder cannot be made, or when it holds
    anything but regular files (a FIFO there would block pint's read).
    """
    folder = directory()
    if folder is None:
        return None
    where = os.path.join(folder, "pint")
    try:
        os.makedirs(where, exist_ok=True)
        with os.scandir(where) as entries:
            for entry in entries:
                if not entry.is_file(follow_symlinks=False):
                    return None
    except (OSError, ValueError):
        return None
    return where


def clear_pint_folder(where: str) -> None:
    """Remove pint's cache files from gyro's folder (damaged: pint rebuilds them)."""
    try:
        with os.scandir(where) as entries:
            for entry in entries:
                if entry.is_file(follow_symlinks=False) and \
                        entry.name.endswith((".pickle", ".json")):
                    try:
                        os.unlink(entry.path)
                    except OSError:
                        pass
    except OSError:
        pass


def path() -> str | None:
    folder = directory()
    return os.path.join(folder, "units.json") if folder else None


_stamp: list | None = None


def stamp() -> list | None:
    """What decides a reading, as [FORMAT, hash]; None when it cannot be told.

    The hash covers gyro's version, the bytes of gyro's own unit sources
    (every ``core/unit*.py``) and the installed pint: its version (from its
    dist-info folder's name), and the path, size and modification time of its
    package and of its unit definitions (``default_en.txt``). Computed once a
    process, without importing pint.
    """
    global _stamp
    if _stamp is not None:
        return _stamp
    import binascii  # CRC-32 and the size: enough to tell an edit; loaded with yaml already
    import importlib.util

    from .. import __version__

    parts = [f"{FORMAT}\0{__version__}".encode()]
    try:
        here = os.path.dirname(os.path.abspath(__file__))
        for name in sorted(os.listdir(here)):
            if name.startswith("unit") and name.endswith(".py"):
                with open(os.path.join(here, name), "rb") as handle:
                    parts.append(b"\0" + name.encode() + b"\0" + handle.read())
        spec = importlib.util.find_spec("pint")
        origin = spec.origin if spec else None
        if not origin:
            return None
        package = os.path.dirname(origin)
        for name in ("__init__.py", "default_en.txt"):
            info = os.stat(os.path.join(package, name))
            parts.append(f"\0{package}/{name}\0{info.st_size}\0{info.st_mtime_ns}".encode())
        site = os.path.dirname(package)
        versions = sorted(n for n in os.listdir(site)
                          if n.startswith("pint-") and n.endswith((".dist-info", ".egg-info")))
        parts.append(("\0" + "\0".join(versions)).encode())
    except (OSError, ImportError, ValueError):
        return None
    data = b"".join(parts)
    _stamp = [FORMAT, f"{binascii.crc32(data):08x}{len(data):x}"]
    return _stamp


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
    from .errors import InputError
    from .safeyaml import read_bytes

    try:
        # Only a regular file, opened without blocking: a FIFO put there is ignored.
        data = read_table(read_bytes(where, MAX_BYTES, "a unit cache").decode("utf-8"))
    except (InputError, OSError, ValueError, SyntaxError, RecursionError, MemoryError):
        return tables
    if not isinstance(data, dict) or data.get("stamp") != made:
        return tables
    for name, table in tables.items():
        stored = data.get(name)
        if isinstance(stored, dict):
            table.update((k, v) for k, v in list(stored.items())[:MAX_ENTRIES]
                         if _valid(name, k, v))
    return tables


_JSON_NAMES = {"true": True, "false": False, "null": None}
AST_MAX = 4096  # characters: a longer table is read by json (see read_table)


def read_table(text: str) -> object:
    """The table's JSON text as Python values: by `from_json` while it is short (the few
    units a course uses), by json when longer, where importing json (about 2.5 ms) costs
    less than ``ast.parse`` (about 0.4 ms a kilobyte: 400 ms for a table at MAX_BYTES)."""
    if len(text) <= AST_MAX:
        return from_json(text)
    import json

    return json.loads(text)


def from_json(text: str) -> object:
    """The JSON ``text`` (as ``json.dump`` writes it) as Python values, read by Python's
    own parser: ``ast`` is loaded with click already, ``json`` is not (`read_table` says
    when each is used). ValueError or SyntaxError when it is not such a text."""
    import ast
    import warnings

    with warnings.catch_warnings():  # a foreign file's "\/" is no warning of gyro's
        warnings.simplefilter("ignore")
        return _json_value(ast.parse(text, mode="eval").body, 0)


def _json_value(node: ast.expr | None, depth: int) -> object:
    import ast

    if depth > 4:  # the table is three deep
        raise ValueError("nested too deep for a unit table")
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub):
        value = _json_value(node.operand, depth + 1)
        if type(value) in (int, float):
            return -value  # type: ignore[operator]
    elif isinstance(node, ast.Constant) and isinstance(node.value, (str, int, float)):
        return node.value
    elif isinstance(node, ast.Name) and node.id in _JSON_NAMES:
        return _JSON_NAMES[node.id]
    elif isinstance(node, ast.List):
        return [_json_value(item, depth + 1) for item in node.elts]
    elif isinstance(node, ast.Dict):
        keys = [key.value for key in node.keys if isinstance(key, ast.Constant)]
        if all(isinstance(key, str) for key in keys) and len(keys) == len(node.keys):
            return {key: _json_value(value, depth + 1) for key, value in zip(keys, node.values)}
    raise ValueError("not a JSON unit table")


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
    import json
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
    global _tables, _dirty, _stamp
    _tables, _dirty, _stamp = None, False, None
