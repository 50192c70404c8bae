"""Writing output files safely: never clobber without --force, never leave half a file.

``write_atomic`` writes to a temporary file in the same directory, flushes it to
disk and renames it over the target (``os.replace`` is atomic on POSIX and
Windows), so a reader sees either the old file or the whole new one.

Only a regular file or a new path is written, with or without --force: a
device (``/dev/full``, ``/dev/null``), a FIFO, a socket or a directory is
refused with one line, never replaced by a regular file. A failed write (a
full disk) is reported as bad input (exit 2) and its temporary file removed.
The temporary file is named ``.NAME.XXXXXXXX.tmp``: hidden and ending in
``.tmp``, so one left by a killed run is never read as output (``gyro check``
skips hidden files, and ``*.yaml`` does not match it).
"""

from __future__ import annotations

import os
import stat
import tempfile
from pathlib import Path
from typing import Iterable

from .errors import InputError


def write_atomic(path: str | os.PathLike, text: str | bytes | Iterable[str | bytes],
                 force: bool = False) -> Path:
    """Write ``text`` to ``path`` atomically; InputError if it exists and not ``force``.

    ``text`` may also be an iterable of pieces (a report too large to hold at once).
    The parent directory must exist. Returns the path written.
    """
    target = Path(path)
    refuse_special(target)
    if not force and (target.exists() or target.is_symlink()):
        raise InputError("exists; not overwritten (use --force to replace it)", file=str(target))
    parent = target.parent if str(target.parent) else Path(".")
    if not parent.is_dir():
        raise InputError(f"cannot write: no such directory {str(parent)!r}", file=str(target))
    pieces = [text] if isinstance(text, (str, bytes)) else text
    try:
        fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=parent)
    except OSError as err:
        raise InputError(f"cannot write: {err.strerror}", file=str(target)) from None
    try:
        with os.fdopen(fd, "wb") as handle:
            for piece in pieces:
                handle.write(piece.encode("utf-8") if isinstance(piece, str) else piece)
            handle.flush()
            os.fsync(handle.fileno())
        if not force:
            # Claim the name without replacing: fails if someone created it meanwhile.
            try:
                os.link(tmp, target)
            except FileExistsError:
                raise InputError("exists; not overwritten (use --force to replace it)",
                                 file=str(target)) from None
            except OSError:
                # Filesystems without hard links: fall back to a checked rename.
                if target.exists():
                    raise InputError("exists; not overwritten (use --force to replace it)",
                                     file=str(target)) from None
                os.replace(tmp, target)
        else:
            os.replace(tmp, target)
        mode = 0o666 & ~_umask()
        try:
            os.chmod(target, mode)
        except OSError:
            pass
    except OSError as err:
        raise InputError(f"cannot write: {err.strerror}", file=str(target)) from None
    finally:
        try:
            os.unlink(tmp)
        except OSError:
            pass
    return target


def refuse_special(path: str | os.PathLike) -> None:
    """InputError unless ``path`` is a regular file (or its link) or does not exist."""
    try:
        mode = os.stat(path).st_mode
    except (OSError, ValueError):
        return  # a new path (or a dangling symlink: refused later without --force)
    if not stat.S_ISREG(mode):
        from .safeyaml import _not_regular

        message = _not_regular(mode, "a file to write").replace("reads", "writes")
        raise InputError(message, file=str(path))


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask
