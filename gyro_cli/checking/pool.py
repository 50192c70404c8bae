"""`gyro check --jobs N`: problem files checked by N worker processes, results in order.

Each worker is a forked copy of this process (modules already imported, the unit
table already read) that takes a batch of paths, checks them one by one (``work``,
i.e. ``check.check_file``) and sends their results back in one reply; it holds a
second batch in its pipe, so it never waits for the parent. The parent hands the
results on in the files' order, holding only those that finished ahead of a slower
file; it never sends work more than ``AHEAD`` files past the first unfinished one,
so memory stays flat however many files there are. One message per batch, not per
file: the parent wakes a sixteenth as often, and its time is the workers' too on a
machine with as many cores as workers.

Which file is under way, and since when, the worker writes in memory it shares with
the parent (two numbers per file, no message), so the time limit still applies to
each file and a crash is still laid at the right file.

A file that takes longer than the time limit, or that kills its worker (a crash
in compiled code), costs only that file: the worker is ended, the file is
reported as an internal error, the rest of its batch goes back to the queue and
a new worker takes over.

Where fork is not available (Windows), the files are checked in this process.
"""

from __future__ import annotations

import collections
import math
import mmap
import os
import pickle
import select
import signal
import struct
import sys
import time
from collections.abc import Callable, Iterator
from typing import Any, TypeVar

Result = TypeVar("Result")

AHEAD = 256  # files sent out beyond the first unfinished one, at most
BATCH = 16  # files per message to a worker (and per reply), at most
DONE, STARTED = 0, 1  # a worker's progress: files finished, when the file under way began
IDLE = math.inf  # STARTED between batches: no file under way


def _work(conn: _Channel, work: Callable[[str], Any], progress: Any) -> None:
    """A worker's loop: a batch of paths in, their results out in one reply, until None.

    Before each file it writes in shared memory when the file began, and after it how
    many it has finished, so the parent knows which file outlasts the time limit or
    kills the process without a message per file."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl-C is the parent's to handle
    clock = time.monotonic
    try:
        while (batch := conn.recv()) is not None:
            results = []
            for path in batch:
                progress[STARTED] = clock()
                results.append(work(path))
                progress[DONE] += 1
            progress[STARTED] = IDLE
            conn.send(results)
    except (EOFError, BrokenPipeError, KeyboardInterrupt):
        pass
    finally:
        from ..core import unit_cache

        unit_cache.save()  # units met here, for the next run (a fork skips atexit)


_HEAD = struct.Struct("!Q")  # a message's length, before its pickle


class _Channel:
    """One end of a worker's two pipes: each message a pickle after its length."""

    def __init__(self, read: int, write: int) -> None:
        self.read, self.write = read, write

    def fileno(self) -> int:
        return self.read

    def send(self, obj: Any) -> None:
        data = pickle.dumps(obj, pickle.HIGHEST_PROTOCOL)
        view = memoryview(_HEAD.pack(len(data)) + data)
        while view:
            view = view[os.write(self.write, view):]

    def _exactly(self, size: int) -> bytes:
        chunks = []
        while size:
            chunk = os.read(self.read, min(size, 1 << 20))
            if not chunk:
                raise EOFError("the other end closed its pipe")
            chunks.append(chunk)
            size -= len(chunk)
        return b"".join(chunks)

    def recv(self) -> Any:
        return pickle.loads(self._exactly(int(_HEAD.unpack(self._exactly(_HEAD.size))[0])))

    def poll(self) -> bool:
        """Whether a message (or the end of the pipe) is waiting."""
        waiting = select.poll()
        waiting.register(self.read, select.POLLIN)
        return bool(waiting.poll(0))

    def close(self) -> None:
        for fd in (self.read, self.write):
            try:
                os.close(fd)
            except OSError:
                pass


class _Worker:
    def __init__(self, work: Callable[[str], Any]) -> None:
        # DONE, STARTED: two doubles in memory shared with the child (an anonymous shared
        # mapping made before the fork: no file, so no writable folder needed)
        self.progress = memoryview(mmap.mmap(-1, 16)).cast("d")
        self.progress[STARTED] = IDLE
        down, up = os.pipe(), os.pipe()  # (read, write) each: parent -> child, child -> parent
        for stream in (sys.stdout, sys.stderr):  # nothing buffered is copied into the child
            try:
                stream.flush()
            except (OSError, ValueError, AttributeError):
                pass
        self.pid = os.fork()
        if self.pid == 0:  # the child: work, then leave without the parent's exit handlers
            code = 0
            try:
                os.close(down[1])
                os.close(up[0])
                _work(_Channel(down[0], up[1]), work, self.progress)
            except BaseException:  # noqa: BLE001 -- a signal, a bug: the parent reports it
                code = 1
            finally:
                os._exit(code)
        os.close(down[0])
        os.close(up[1])
        self.conn = _Channel(up[0], down[1])
        self.fd = self.conn.fileno()
        self.exitcode: int | None = None
        self.batches: collections.deque[list[int]] = collections.deque()  # sent, unanswered
        self.answered = 0  # files whose results have come back
        self.asked = False  # whether it has been told to stop

    def send(self, indices: list[int], files: list[str]) -> None:
        self.batches.append(indices)
        try:
            self.conn.send([files[i] for i in indices])
        except OSError:  # it has died: its end of the pipe reads as closed, and says so
            pass

    def current(self) -> int:
        """How many of its unanswered files it has finished: the next is the one under way."""
        return int(self.progress[DONE]) - self.answered

    def unanswered(self) -> list[int]:
        return [i for batch in self.batches for i in batch]

    def _reaped(self, wait: float) -> bool:
        """Whether the process has ended (its exit code kept), waiting up to ``wait`` s.

        It is waited for on its pipe, which reads as hung up once the process has ended
        (its end closes with it), rather than by naps of a fixed length: the parent's
        last step before its summary, so every millisecond of it is a run's."""
        end = time.monotonic() + wait
        hangup = None
        while self.exitcode is None:
            try:
                pid, status = os.waitpid(self.pid, os.WNOHANG)
            except ChildProcessError:
                self.exitcode = 0  # already reaped elsewhere: its code is lost
                break
            if pid:
                self.exitcode = os.waitstatus_to_exitcode(status)
                break
            left = end - time.monotonic()
            if left <= 0:
                return False
            if hangup is None:
                hangup = select.poll()
                hangup.register(self.conn.read, 0)  # no events asked: a hang-up only
            if hangup.poll(0):  # it has ended, or is ending: its exit code is a moment away
                time.sleep(min(left, 0.0005))
            else:  # until it hangs up, or a while
                hangup.poll(math.ceil(min(left, 0.05) * 1000))
        return True

    def ask_to_stop(self) -> None:
        """Tell the worker that no more files come: it ends after those it has."""
        if not self.asked:
            self.asked = True
            try:
                self.conn.send(None)
            except (OSError, ValueError):
                pass

    def stop(self, kill: bool = False) -> int | None:
        """End the process (at once if ``kill``) and return its exit code (minus the
        signal's number if a signal ended it)."""
        if not kill:
            self.ask_to_stop()
        if kill or not self._reaped(5):
            if not self._reaped(0):
                try:
                    os.kill(self.pid, signal.SIGKILL)
                except ProcessLookupError:
                    pass
            self._reaped(math.inf)
        self.conn.close()
        return self.exitcode


def forks() -> bool:
    """Whether worker processes can be forked here (not on Windows)."""
    return hasattr(os, "fork")


def pooled(files: list[str], work: Callable[[str], Result], jobs: int, timeout: float | None,
           timed_out: Callable[[str, float], Result],
           crashed: Callable[[str, int | None], Result],
           idle: Callable[[], Any] | None = None) -> Iterator[Result]:
    """``work(path)`` of each file in ``jobs`` forked workers, in the order of ``files``;
    ``timed_out(path, timeout)`` or ``crashed(path, exit code)`` for a file that outlasts
    the time limit or kills its worker. ``idle()``, if given, is called before waiting
    for a worker when results were handed on since the last wait (the caller flushes
    its output then: one write per wake-up, not one per file)."""
    poller = select.poll()  # one for the run: polled workers change by (un)registering
    polled: dict[int, _Worker] = {}
    handed_on = False
    queue = collections.deque(range(len(files)))  # indices not yet sent
    done: dict[int, Result] = {}  # finished ahead of the next one to hand on
    next_out = 0
    workers = [_Worker(work) for _ in range(jobs)]
    try:
        while next_out < len(files):
            for worker in workers:  # two batches each (one under way, one waiting), in the window
                while len(worker.batches) < 2 and queue and queue[0] < next_out + AHEAD:
                    size = max(1, min(BATCH, (len(files) - next_out) // (2 * jobs)))
                    take: list[int] = []
                    while queue and len(take) < size and queue[0] < next_out + AHEAD:
                        take.append(queue.popleft())
                    worker.send(take, files)
            busy = {w.fd: w for w in workers if w.batches}
            for fd in polled.keys() - busy.keys():
                poller.unregister(fd)
            for fd in busy.keys() - polled.keys():
                poller.register(fd, select.POLLIN)
            polled = busy
            wait_for = None
            if timeout and busy:
                # a worker between batches has no file under way: look again within a second
                now = time.monotonic()
                wait_for = max(0.0, min(min(w.progress[STARTED] + timeout, now + 1.0) - now
                                        for w in busy.values()))
            ready: set[int] = set()
            if handed_on and idle is not None:
                ready = {fd for fd, _ in poller.poll(0)}
                if not ready:
                    idle()
                    handed_on = False
            if not ready:
                ready = {fd for fd, _ in poller.poll(
                    None if wait_for is None else math.ceil(wait_for * 1000))}
            for i, worker in enumerate(workers):
                if not worker.batches:
                    continue
                failed: Callable[[str, Any], Result] | None = None  # who reports the file
                if worker.fd in ready:
                    try:  # every reply already waiting, not one per wake-up
                        while True:
                            results = worker.conn.recv()
                            batch = worker.batches.popleft()
                            done.update(zip(batch, results))
                            worker.answered += len(batch)
                            if not worker.batches or not worker.conn.poll():
                                break
                    except (EOFError, OSError):
                        failed = crashed
                    else:
                        continue
                elif timeout and time.monotonic() - worker.progress[STARTED] >= timeout:
                    failed = timed_out
                if failed is not None:
                    # the file under way fails; the rest (finished or not) go back to the queue
                    left = worker.unanswered()
                    k = min(max(worker.current(), 0), len(left) - 1)
                    # one that died is waited for, not killed: its exit status names the crash
                    code = worker.stop(kill=failed is timed_out)
                    if failed is crashed:
                        done[left[k]] = crashed(files[left[k]], code)
                    else:
                        assert timeout is not None, "only a time limit times a file out"
                        done[left[k]] = timed_out(files[left[k]], timeout)
                    queue.extendleft(reversed(left[:k] + left[k + 1:]))
                    workers[i] = _Worker(work)
            while next_out in done:
                yield done.pop(next_out)
                next_out += 1
                handed_on = True
    finally:
        kill = next_out < len(files)
        if not kill:  # all told first, so that they end together
            for worker in workers:
                worker.ask_to_stop()
        for worker in workers:
            worker.stop(kill=kill)
