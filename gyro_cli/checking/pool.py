"""`gyro check --jobs N`: problem files checked by N worker processes, results in order.

Each worker is a forked copy of this process (modules already imported, the unit
table already read) that takes a small batch of paths, checks them one by one
(``work``, i.e. ``check.check_file``) and sends each result back as soon as it
is known. The parent hands the results on in the files' order, holding only those
that finished ahead of a slower file; it never sends work more than ``AHEAD``
files past the first unfinished one, so memory stays flat however many files
there are.

A file that takes longer than the time limit, or that kills its worker (a crash
in compiled code), costs only that file: the worker is ended, the file is
reported as an internal error, the rest of its batch goes back to the queue and
a new worker takes over.

Where fork is not available (Windows), the files are checked in this process.
"""

from __future__ import annotations

import collections
import multiprocessing
import signal
import time
from typing import Any, Iterator

from typing import Callable, TypeVar

Result = TypeVar("Result")

AHEAD = 256  # files sent out beyond the first unfinished one, at most
BATCH = 8  # files per message to a worker, at most


def _work(conn: Any, work: Callable[[str], Any]) -> None:
    """A worker's loop: a batch of paths in, one result out per file, until None."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl-C is the parent's to handle
    try:
        while (batch := conn.recv()) is not None:
            for path in batch:
                conn.send(work(path))
    except (EOFError, BrokenPipeError, KeyboardInterrupt):
        pass
    finally:
        from ..core import unit_cache

        unit_cache.save()  # units met here, for the next run (a fork skips atexit)


class _Worker:
    def __init__(self, context: Any, work: Callable[[str], Any]) -> None:
        self.conn, child = context.Pipe()
        self.process = context.Process(target=_work, args=(child, work), daemon=True)
        self.process.start()
        child.close()
        self.batch: collections.deque[int] = collections.deque()  # indices sent, unanswered
        self.since = time.monotonic()  # when its current file started

    def send(self, indices: list[int], files: list[str]) -> None:
        if not self.batch:  # else the next batch waits behind the file under way
            self.since = time.monotonic()
        self.batch.extend(indices)
        try:
            self.conn.send([files[i] for i in indices])
        except OSError:  # it has died: its end of the pipe reads as closed, and says so
            pass

    def stop(self, kill: bool = False) -> int | None:
        """End the process (at once if ``kill``) and return its exit code."""
        if kill and self.process.is_alive():
            self.process.kill()
        else:
            try:
                self.conn.send(None)
            except (OSError, ValueError):
                pass
        self.process.join(5)
        if self.process.is_alive():
            self.process.kill()
            self.process.join()
        self.conn.close()
        return self.process.exitcode


def forks() -> bool:
    """Whether worker processes can be forked here (not on Windows)."""
    return "fork" in multiprocessing.get_all_start_methods()


def pooled(files: list[str], work: Callable[[str], Result], jobs: int, timeout: float | None,
           timed_out: Callable[[str, float], Result],
           crashed: Callable[[str, int | None], Result]) -> Iterator[Result]:
    """``work(path)`` of each file in ``jobs`` forked workers, in the order of ``files``;
    ``timed_out(path, timeout)`` or ``crashed(path, exit code)`` for a file that outlasts
    the time limit or kills its worker."""
    from multiprocessing.connection import wait

    context = multiprocessing.get_context("fork")
    queue = collections.deque(range(len(files)))  # indices not yet sent
    done: dict[int, Result] = {}  # finished ahead of the next one to hand on
    next_out = 0
    workers = [_Worker(context, work) for _ in range(jobs)]
    try:
        while next_out < len(files):
            for worker in workers:  # keep every worker supplied, within the window
                if len(worker.batch) <= 1 and queue and queue[0] < next_out + AHEAD:
                    size = max(1, min(BATCH, (len(files) - next_out) // (2 * jobs)))
                    take = []
                    while queue and len(take) < size and queue[0] < next_out + AHEAD:
                        take.append(queue.popleft())
                    worker.send(take, files)
            busy = [w for w in workers if w.batch]
            wait_for = None
            if timeout and busy:
                now = time.monotonic()
                wait_for = max(0.0, min(w.since + timeout - now for w in busy))
            ready = wait([w.conn for w in busy], wait_for)
            for i, worker in enumerate(workers):
                if not worker.batch:
                    continue
                failed = None
                if worker.conn in ready:
                    try:  # every result already waiting, not one per wake-up
                        while True:
                            done[worker.batch[0]] = worker.conn.recv()
                            worker.batch.popleft()
                            if not worker.batch or not worker.conn.poll():
                                break
                    except (EOFError, OSError):
                        failed = crashed(files[worker.batch[0]], worker.stop())
                    else:
                        worker.since = time.monotonic()
                        continue
                elif timeout and time.monotonic() - worker.since >= timeout:
                    worker.stop(kill=True)
                    failed = timed_out(files[worker.batch[0]], timeout)
                if failed is not None:  # the file that failed, then the rest back to the queue
                    done[worker.batch.popleft()] = failed
                    queue.extendleft(reversed(worker.batch))
                    workers[i] = _Worker(context, work)
            handed = time.monotonic()
            while next_out in done:
                yield done.pop(next_out)
                next_out += 1
            waited = time.monotonic() - handed  # the reader's time, not the workers'
            for worker in workers:
                worker.since += waited
    finally:
        for worker in workers:
            worker.stop(kill=next_out < len(files))
