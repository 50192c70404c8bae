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
from collections.abc import Iterable, Iterator, Sequence
from pathlib import Path

from .errors import InputError


def refuse_target(target: Path, force: bool) -> None:
    """InputError if ``target`` is no place to write (`refuse_special`) or exists (a
    dangling link too) and not ``force``: asked before work whose only use is to be
    written there (a figure drawn), and again as it is written."""
    refuse_special(target)
    if not force and (target.exists() or target.is_symlink()):
        raise InputError("exists; not overwritten (use --force to replace it)", file=str(target))


def write_atomic(path: str | os.PathLike, text: str | bytes | Iterable[str | bytes],
                 force: bool = False) -> Path:
    """Write ``text`` to ``path`` atomically; InputError if it exists and not ``force``.

    ``text`` may also be an iterable of pieces (a report too large to hold at once).
    The parent directory must exist. Returns the path written.
    """
    target = Path(path)
    refuse_target(target, force)
    parent = target.parent if str(target.parent) else Path(".")
    if not parent.is_dir():
        raise InputError(f"cannot write: no such directory {str(parent)!r}", file=str(target))
    import tempfile  # here: a solve to the terminal writes no file

    try:
        fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=parent)
    except OSError as err:
        raise InputError(f"cannot write: {err.strerror}", file=str(target)) from None
    try:
        with os.fdopen(fd, "wb") as handle:
            for piece in _pieces(text):
                handle.write(piece)
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


PROBLEM_SUFFIXES = (".yaml", ".yml")


def refuse_input_as_output(output: str | os.PathLike, inputs=(), *,
                           option: str = "the output", yaml_output: bool = False,
                           identities: dict[str, tuple[int, int]] | None = None) -> None:
    """InputError if writing ``output`` would replace one of the command's inputs.

    ``inputs`` are the files the command reads (problem files, an answer sheet):
    the output may not be any of them, by whatever path (a symlink, a hard link,
    ``./x``). Unless the output itself is YAML (``vary``, ``new``), an existing
    ``.yaml``/``.yml`` file is refused too: a report named like a problem file is
    a shell glob that swallowed the report's name (``--junit pj/*.yaml``).
    ``identities``: the (device, inode) of inputs already looked up
    (`solving.paths.problem_files`), so that a bank's files are not looked up twice.
    """
    name = os.fspath(output)
    if name.strip() and _identity(name) is None:
        return  # a new path: it cannot be an input (and the inputs need no lookup)
    known = identities or {}
    by_identity: dict[tuple[int, int], str] = {}
    for source in inputs:
        found = known.get(source) or _identity(source)
        if found is not None:
            by_identity.setdefault(found, os.fspath(source))
    _refuse_over(output, by_identity, option, yaml_output)


def refuse_outputs_over_inputs(outputs: Iterable[str | os.PathLike],
                               inputs: Iterable[str | os.PathLike], *,
                               option: str = "the output", yaml_output: bool = False) -> None:
    """:func:`refuse_input_as_output` for every file of a set (a file per student): the
    inputs are looked up once, so 10,000 outputs against 10,000 variant files cost one
    lookup each, not one per pair."""
    by_identity: dict[tuple[int, int], str] = {}
    for source in inputs:
        found = _identity(source)
        if found is not None:
            by_identity.setdefault(found, os.fspath(source))
    for output in outputs:
        _refuse_over(output, by_identity, option, yaml_output)


def _identity(path: str | os.PathLike) -> tuple[int, int] | None:
    """(device, inode) of an existing file, the test of os.path.samestat; None if absent."""
    try:
        info = os.stat(path)
    except (OSError, ValueError):
        return None
    return info.st_dev, info.st_ino


def _refuse_over(output: str | os.PathLike, inputs: dict[tuple[int, int], str],
                 option: str, yaml_output: bool) -> None:
    name = os.fspath(output)
    if name.strip() == "":
        raise InputError(f"{option} needs a file name, got an empty one")
    found = _identity(name)
    if found is None:
        return  # a new path: it cannot be an input
    if found in inputs:
        raise InputError(f"{option} would replace an input file ({inputs[found]}); "
                         "refused, give the output another name", file=name)
    if not yaml_output and name.lower().endswith(PROBLEM_SUFFIXES):
        raise InputError(f"{option} would replace a YAML file; refused (was the output's "
                         "name left out, so that a shell glob filled it in?)", file=name)


def write_set_in(folder: str, items: Sequence[tuple[str, str | bytes]],
                 force: bool = False) -> list[Path]:
    """`write_set` into ``folder`` and the folders below it, made as needed: on failure the
    folders this call made are removed again (only if empty), so a rerun starts clean."""
    with StagedSet(force, folder, [path for path, _ in items]) as staged:
        for path, text in items:
            staged.add(path, text)
        return staged.place()


def _make_folders(folder: str, paths: Iterable[str]) -> list[str]:
    """Make ``folder`` and the folders of ``paths`` that are missing; the ones made."""
    made: list[str] = []
    wanted = {os.path.normpath(os.path.dirname(path) or ".") for path in paths}
    for parent in sorted(wanted | {os.path.normpath(folder)}, key=lambda d: d.count(os.sep)):
        chain = []
        while parent and parent not in (".", os.sep) and not os.path.isdir(parent):
            chain.append(parent)
            parent = os.path.dirname(parent)
        made += [d for d in reversed(chain) if d not in made]
    try:
        for d in made:
            os.mkdir(d)
    except (OSError, ValueError) as err:
        _remove_empty(made)
        raise InputError(f"cannot create the directory: {getattr(err, 'strerror', None) or err}",
                         file=folder) from None
    return made


def _remove_empty(folders: list[str]) -> None:
    for d in reversed(folders):
        try:
            os.rmdir(d)  # only if empty: what this call made, nothing else
        except OSError:
            pass


def write_set(items: Sequence[tuple[str, str | bytes]], force: bool = False) -> list[Path]:
    """Write several files as one: every file is written, or none is (and nothing is left).

    Each file is first written whole to a hidden temporary file beside it and
    flushed to disk; only when all of them are there are they renamed into
    place. A failure before (a full disk) removes the temporary files; a
    failure while renaming removes the files this call created. Without
    ``force`` an existing target is refused before anything is written.
    """
    with StagedSet(force, None, [path for path, _ in items]) as staged:
        for path, text in items:
            staged.add(path, text)
        return staged.place()


class StagedSet:
    """`write_set` for a set too large to hold (a file per student of 10,000): each file is
    written to its hidden temporary file as it is made (`add`), and `place` renames them
    all when the set is whole. Leaving the ``with`` block without `place` (an error, a
    signal) removes every temporary file, and the folders made for the set when
    ``folder`` is given (as `write_set_in`): nothing of the set is left. ``sync_each``:
    flush each file to disk as it is written (else all at once before they are placed)."""

    def __init__(self, force: bool, folder: str | None, paths: Iterable[str],
                 sync_each: bool = True) -> None:
        paths = list(paths)
        for path in paths:
            target = Path(path)
            refuse_special(target)
            if not force and (target.exists() or target.is_symlink()):
                raise InputError("exists; not overwritten (use --force to replace it)",
                                 file=str(target))
        self.force = force
        self.sync_each = sync_each
        self.made = _make_folders(folder, paths) if folder is not None else []
        self.staged: list[tuple[str, str]] = []  # (target, its temporary file)
        self.placed: list[Path] = []
        self.done = False

    def __enter__(self) -> StagedSet:
        return self

    def __exit__(self, *exc: object) -> None:
        for _, tmp in self.staged:
            try:
                os.unlink(tmp)
            except OSError:
                pass
        if not self.done:
            for target in self.placed:
                try:
                    os.unlink(target)
                except OSError:
                    pass
            _remove_empty(self.made)

    def add(self, path: str | os.PathLike, text: str | bytes | Iterable[str | bytes]) -> None:
        """Write one file of the set to its temporary file (``text``: its content, or the
        pieces of it)."""
        import tempfile  # here: a solve to the terminal writes no file

        target = Path(path)
        try:
            fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp",
                                       dir=target.parent if str(target.parent) else ".")
        except OSError as err:
            raise InputError(f"cannot write: {err.strerror}", file=str(target)) from None
        self.staged.append((os.fspath(path), tmp))
        try:
            with os.fdopen(fd, "wb") as handle:
                for piece in _pieces(text):
                    handle.write(piece)
                handle.flush()
                if self.sync_each:
                    os.fsync(handle.fileno())
        except OSError as err:
            raise InputError(f"cannot write: {err.strerror}; nothing of the set was "
                             "written", file=str(target)) from None

    def place(self) -> list[Path]:
        """Rename every file into place: all of them, or (on a failure) none. Without
        ``sync_each`` the files are flushed to disk here, all at once (one sync instead of
        one per file: 20,000 of them cost more than drawing the set)."""
        if not self.sync_each:
            os.sync()
        mode = 0o666 & ~_umask()
        for name, tmp in self.staged:
            target = Path(name)
            try:
                if self.force:
                    existed = target.exists()
                    os.replace(tmp, target)
                else:
                    existed = False
                    try:
                        os.link(tmp, target)  # fails if the name was taken meanwhile
                    except FileExistsError:
                        raise
                    except OSError:  # no hard links here: a checked rename
                        if target.exists():
                            raise FileExistsError from None
                        os.replace(tmp, target)
            except FileExistsError:
                raise InputError("exists; not overwritten (use --force to replace it)",
                                 file=str(target)) from None
            except OSError as err:
                raise InputError(f"cannot write: {err.strerror}; nothing of the set was "
                                 "written", file=str(target)) from None
            if not existed:
                self.placed.append(target)
            try:
                os.chmod(target, mode)
            except OSError:
                pass
        self.done = True
        return [Path(name) for name, _ in self.staged]


class StagedFolder:
    """`StagedSet` for a folder that does not exist yet (a roster's set): its files are
    written into a hidden folder beside it, ``.NAME.XXXXXXXX.tmp``, and `place` syncs the
    disks once and renames that folder into place. One rename for the whole set instead
    of a temporary file, a rename and a chmod per file (20,000 of them cost as much as
    drawing the set), and no file of the set can exist before. A thread creates and
    writes the files (a few at a time, handed over as they are made) while the set is
    drawn: the system's time creating 20,000 files is spent beside the drawing, on the
    other core. The thread starts with the first file handed over, so processes forked
    before that (the roster's workers) are forked from one thread; such a process writes
    its own files with `write_now`. Leaving the ``with`` block without `place` removes the
    hidden folder and the parents made for it."""

    QUEUED = 64  # files handed over and not written yet, at most

    def __init__(self, folder: str) -> None:
        import queue
        import secrets
        import threading

        self.folder = os.path.normpath(folder)
        self.prefix = os.path.join(folder, "")  # what every path given to `add` starts with
        parent = os.path.dirname(self.folder) or "."
        self.made = _make_folders(parent, []) if parent != "." else []
        name = os.path.basename(self.folder)
        for _ in range(100):
            self.stage = os.path.join(parent, f".{name}.{secrets.token_hex(4)}.tmp")
            try:
                os.mkdir(self.stage)  # the mode a folder made by _make_folders has
                break
            except FileExistsError:
                continue
            except OSError as err:
                _remove_empty(self.made)
                raise InputError(f"cannot create the directory: {err.strerror}",
                                 file=folder) from None
        else:
            _remove_empty(self.made)
            raise InputError("cannot create a hidden folder beside it", file=folder)
        self.folders = {""}  # those made in the hidden folder, by their relative name
        self.done = False
        self.failed: Exception | None = None  # the writer's error, raised by the next call
        self.dropped = False  # the set failed: what is still handed over is not written
        self.queue: queue.Queue[tuple[str, str, str | bytes] | None] = queue.Queue(self.QUEUED)
        self.writer = threading.Thread(target=self._write_queued, daemon=True)

    def __enter__(self) -> StagedFolder:
        return self

    def __exit__(self, *exc: object) -> None:
        self._stop(drop=not self.done)
        if not self.done:
            import shutil

            shutil.rmtree(self.stage, ignore_errors=True)
            _remove_empty(self.made)

    def add(self, path: str, text: str | bytes | Iterable[str | bytes]) -> None:
        """Write one file of the set (``path``: the folder's name joined to the file's):
        a text is handed to the writer; pieces (a file too large to hold) are written
        here, once the writer has written the files before."""
        if self.failed is not None:
            raise self.failed
        if not path.startswith(self.prefix):
            raise ValueError(f"{path} is not in {self.prefix}")
        relative = path[len(self.prefix):]
        if isinstance(text, (str, bytes)):
            if self.writer.ident is None:
                self.writer.start()
            self.queue.put((path, relative, text))
            return
        self.queue.join()
        if self.failed is not None:
            raise self.failed
        self._write(path, relative, text)

    def write_now(self, name: str, text: str) -> None:
        """Write the file ``name`` (inside the set's folder) here, not by the writer
        thread: what a process forked from this one (a roster's worker) does with the
        files it makes. Its folder is made if need be; bad input as `add`'s."""
        self._write(self.prefix + name, name, text)

    def _write_queued(self) -> None:
        while True:
            item = self.queue.get()
            try:
                if item is None:
                    return
                if self.failed is None and not self.dropped:
                    self._write(*item)
            except Exception as err:  # raised in the drawing thread by its next call
                self.failed = err
            finally:
                self.queue.task_done()

    def _write(self, path: str, relative: str, text: str | bytes | Iterable[str | bytes]) -> None:
        below = os.path.dirname(relative)
        try:
            if below not in self.folders:
                os.makedirs(os.path.join(self.stage, below), exist_ok=True)
                self.folders.add(below)
            fd = os.open(os.path.join(self.stage, relative),
                         os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_BINARY", 0),
                         0o666)  # the mode StagedSet gives its files: umask applies
            try:
                for piece in _pieces(text):
                    _write_all(fd, piece)
            finally:
                os.close(fd)
        except OSError as err:
            raise InputError(f"cannot write: {err.strerror}; nothing of the set was "
                             "written", file=path) from None

    def _stop(self, drop: bool = False) -> None:
        """Let the writer write what it was handed (``drop``: nothing more) and end."""
        self.dropped = self.dropped or drop
        if self.writer.is_alive():
            self.queue.put(None)
            self.writer.join()

    def place(self) -> None:
        """Wait for the writer, sync the disks once and rename the hidden folder into
        place."""
        self._stop()
        if self.failed is not None:
            raise self.failed
        os.sync()
        try:
            os.rename(self.stage, self.folder)  # fails if the folder was filled meanwhile
        except OSError as err:
            raise InputError(f"cannot write: {err.strerror}; nothing of the set was "
                             "written", file=self.folder) from None
        self.done = True


def _write_all(fd: int, data: bytes) -> None:
    """os.write until every byte is written (a write may take fewer)."""
    view = memoryview(data)
    while view:
        view = view[os.write(fd, view):]


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


def _pieces(text: str | bytes | Iterable[str | bytes]) -> Iterator[bytes]:
    """A file's content, given whole or in pieces, as bytes to write (`_utf8` for text)."""
    for piece in [text] if isinstance(text, (str, bytes)) else text:
        yield _utf8(piece) if isinstance(piece, str) else piece


def _utf8(text: str) -> bytes:
    """UTF-8 bytes; a lone surrogate (a file name that is not UTF-8, as Python keeps
    it) is written as its escape ``\\udcff``, so the file stays valid UTF-8."""
    return text.encode("utf-8", "backslashreplace")


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask
