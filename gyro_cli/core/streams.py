"""The process's surroundings: standard output that may fail, signals, and the CPUs it
may run on.

A command's files (``--junit``, ``--plot``, ``--csv``, ...) are written whatever
happens to standard output. ``guard_output`` puts a thin wrapper on
``sys.stdout`` and ``sys.stderr`` that turns a failed write (the reader left
the pipe, ``/dev/full``, an encoding that cannot show a character) into a
note instead of an exception; the command goes on, and ``Guard.exit_code``
says at the end what the failure means:

- the reader left (EPIPE): 141, quietly, as a program killed by SIGPIPE;
- any other failure of standard output: exit 2 and one line on stderr;
- a failure of stderr alone changes nothing (there is nowhere to say it).

``on_signals`` turns SIGTERM and SIGHUP (and SIGINT) into an exception that
``except Exception`` does not catch, so ``finally`` blocks run and no
temporary file is left behind; the exit code is 128 + the signal's number.
"""

from __future__ import annotations

import errno
import os
import re
import sys
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    import signal
else:
    try:  # the C module alone: `signal` builds three enums when imported (about 1 ms)
        import _signal as signal
    except ImportError:
        import signal

_SURROGATE = "[\ud800-\udfff]"  # compiled on first use (re keeps it): 0.2 ms at start
EXIT_PIPE = 141   # 128 + SIGPIPE
EXIT_USAGE = 2


class Interrupted(BaseException):
    """A signal asked gyro to stop (not an Exception: nothing in a command catches it)."""

    def __init__(self, signum: int) -> None:
        super().__init__(signum)
        self.signum = signum

    @property
    def exit_code(self) -> int:
        return 128 + self.signum


class _Stream:
    """A text (or, as ``.buffer``, binary) stream whose failures are noted, not raised."""

    def __init__(self, stream: Any, guard: Guard, name: str) -> None:
        self._stream = stream
        self._guard = guard
        self._name = name

    def write(self, data: Any) -> int:
        if self._guard.failed(self._name):
            return len(data)
        try:
            try:
                return self._stream.write(data)
            except UnicodeEncodeError:
                if not isinstance(data, str) or not re.search(_SURROGATE, data):
                    raise
                # A file name that is not UTF-8 (Python keeps its bytes as lone
                # surrogates): shown escaped, as in gyro's one-line messages.
                return self._stream.write(re.sub(_SURROGATE, _escaped, data))
        except (OSError, UnicodeEncodeError, ValueError) as err:
            if isinstance(err, ValueError) and not isinstance(err, UnicodeEncodeError) \
                    and "closed file" not in str(err):
                raise
            self._guard.note(self._name, err, self._stream)
            return len(data)

    def writelines(self, lines: Any) -> None:
        for line in lines:
            self.write(line)

    def flush(self) -> None:
        if self._guard.failed(self._name):
            return
        try:
            self._stream.flush()
        except (OSError, ValueError) as err:
            self._guard.note(self._name, err, self._stream)

    @property
    def buffer(self) -> _Stream:
        return _Stream(self._stream.buffer, self._guard, self._name)

    def __getattr__(self, name: str) -> Any:
        return getattr(self._stream, name)


class Guard:
    """What went wrong with stdout and stderr while a command ran."""

    def __init__(self) -> None:
        self.errors: dict[str, BaseException] = {}
        self.encodings: dict[str, str | None] = {}
        self._saved: tuple[Any, Any] | None = None

    def failed(self, name: str) -> bool:
        return name in self.errors

    def note(self, name: str, err: BaseException, stream: Any = None) -> None:
        self.errors.setdefault(name, err)
        self.encodings.setdefault(name, getattr(stream, "encoding", None))
        # Whatever is still buffered would fail again when Python exits, with a
        # message of its own: send the rest of that stream's output nowhere.
        try:
            fd = stream.fileno()
        except Exception:  # noqa: BLE001 - not a file (a test's capture): nothing to do
            return
        if fd not in (1, 2):
            return
        try:
            devnull = os.open(os.devnull, os.O_WRONLY)
            os.dup2(devnull, fd)
            os.close(devnull)
        except OSError:
            pass

    def install(self) -> Guard:
        self._saved = (sys.stdout, sys.stderr)
        if sys.stdout is not None:
            sys.stdout = _Stream(sys.stdout, self, "stdout")  # type: ignore[assignment]
        if sys.stderr is not None:
            sys.stderr = _Stream(sys.stderr, self, "stderr")  # type: ignore[assignment]
        return self

    def restore(self) -> None:
        if self._saved is not None:
            for stream in (sys.stdout, sys.stderr):
                if isinstance(stream, _Stream):
                    stream.flush()
            sys.stdout, sys.stderr = self._saved
            self._saved = None

    def message(self) -> str | None:
        """The one line for a failed stdout (None when it did not fail or the reader left)."""
        err = self.errors.get("stdout")
        if err is None or _reader_left(err):
            return None
        if isinstance(err, UnicodeEncodeError):
            shown = err.object[err.start:err.end]
            encoding = self.encodings.get("stdout") or err.encoding
            return (f"standard output is {encoding}, which cannot show {shown!r}; "
                    "set PYTHONIOENCODING=utf-8 (or a UTF-8 locale)")
        if isinstance(err, OSError):
            return f"cannot write to standard output: {err.strerror or err}"
        return f"cannot write to standard output: {err}"

    def exit_code(self, code: int) -> int:
        """The command's exit code, corrected for what happened to stdout."""
        err = self.errors.get("stdout")
        if err is None:
            return code
        if _reader_left(err):
            return EXIT_PIPE
        return max(code, EXIT_USAGE)


def _escaped(match: re.Match[str]) -> str:
    return match.group().encode("unicode_escape").decode("ascii")


def _reader_left(err: BaseException) -> bool:
    return isinstance(err, OSError) and err.errno in (errno.EPIPE, errno.ECONNRESET)


def guard_output() -> Guard:
    """Wrap sys.stdout and sys.stderr for the length of one command."""
    return Guard().install()


def on_signals() -> Callable[[], None]:
    """Make SIGINT, SIGTERM and SIGHUP raise ``Interrupted``; returns the undo.

    Only in the main thread (elsewhere Python does not allow handlers; then
    nothing changes).
    """
    def raise_interrupted(signum: int, frame: Any) -> None:
        raise Interrupted(signum)

    saved = []
    for name in ("SIGINT", "SIGTERM", "SIGHUP"):
        signum = getattr(signal, name, None)
        if signum is None:
            continue
        try:
            previous = signal.getsignal(signum)
            if previous == signal.SIG_IGN:
                continue  # nohup, or a background job: stay immune
            signal.signal(signum, raise_interrupted)
            saved.append((signum, previous))
        except (ValueError, OSError):  # not the main thread
            pass

    def undo() -> None:
        for signum, previous in saved:
            try:
                signal.signal(signum, previous if previous is not None else signal.SIG_DFL)
            except (ValueError, OSError):
                pass
    return undo


def cpus() -> int:
    """The CPUs this process may run on (its affinity, e.g. a CI container's share): the
    workers `gyro check` and `gyro vary --roster` start unless told."""
    try:
        return len(os.sched_getaffinity(0)) or 1
    except (AttributeError, OSError):
        return os.cpu_count() or 1
