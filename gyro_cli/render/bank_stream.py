"""Question banks written as their variants come, in constant memory.

`gyro export` (commands/export.py) solves a problem's variants one at a time
and hands each to a `Sink`: ``begin`` a problem, ``add`` each variant that asks
something, then ``commit`` it (or ``abort`` it: a bad file, a problem with
nothing to ask, and what it wrote is dropped). A sink lays the variant out at
once into a temporary file on disk, so a bank of 10,000 variants never sits in
memory; ``chunks`` then gives the finished file, byte for byte what the
renderers' whole-bank functions (`bank_moodle.xml`, ...) give for the same
banks.

A question's name says "variant n" only when its problem has several, which is
known once a second variant has come or the problem is committed: a sink holds
back at most the first variant (`_Marking`).
"""

from __future__ import annotations

import dataclasses
import tempfile
from typing import IO, Iterator

from .bank import ProblemBank, Variant

CHUNK = 1 << 20


class Sink:
    """Where a streamed bank's variants go (the in-memory sink: they are kept)."""

    def begin(self, bank: ProblemBank) -> None:
        self.bank = bank
        self.kept: list[Variant] = []

    def add(self, variant: Variant) -> None:
        self.kept.append(variant)

    def commit(self, bank: ProblemBank) -> ProblemBank:
        """The problem done (``bank``: its final slug); the bank as kept."""
        return dataclasses.replace(bank, variants=self.kept)

    def abort(self) -> None:
        self.kept = []


class _Marking(Sink):
    """A sink that lays out each variant knowing whether its problem has one or several:
    the first is held until the second comes or the problem is committed."""

    def begin(self, bank: ProblemBank) -> None:
        self.bank = bank
        self.held: Variant | None = None
        self.seen = 0
        self.start()

    def add(self, variant: Variant) -> None:
        self.seen += 1
        if self.seen == 1:
            self.held = variant
            return
        several = dataclasses.replace(self.bank, count=2)
        if self.held is not None:
            self.lay_out(several, self.held, True)
            self.held = None
        self.lay_out(several, variant, False)

    def commit(self, bank: ProblemBank) -> ProblemBank:
        self.bank = dataclasses.replace(bank, count=self.seen)
        if self.held is not None:
            self.lay_out(self.bank, self.held, True)
            self.held = None
        self.finish()
        return self.bank

    def abort(self) -> None:
        self.held = None
        self.drop()

    # what a format does
    def start(self) -> None: ...

    def lay_out(self, bank: ProblemBank, variant: Variant, first: bool) -> None: ...

    def finish(self) -> None: ...

    def drop(self) -> None: ...


class _Body(_Marking):
    """A file whose problems follow one another (Moodle XML, Blackboard): each problem is
    appended to one temporary file, cut back to where it began when it is aborted."""

    head = b""
    tail = b""

    def __init__(self) -> None:
        self.body: IO[bytes] = tempfile.TemporaryFile()
        self.mark = 0

    def start(self) -> None:
        self.mark = self.body.tell()

    def finish(self) -> None:
        self.mark = self.body.tell()  # an abort without a begin drops nothing committed

    def drop(self) -> None:
        self.body.truncate(self.mark)
        self.body.seek(self.mark)

    def write(self, text: str, encoding: str = "utf-8") -> None:
        self.body.write(text.encode(encoding))

    def chunks(self) -> Iterator[bytes]:
        """The file: head, every committed problem, tail (the body closed after)."""
        yield self.head
        self.body.seek(0)
        yield from _read(self.body)
        self.body.close()
        yield self.tail


def _read(handle: IO[bytes], size: int = -1) -> Iterator[bytes]:
    """``size`` bytes of ``handle`` from where it stands (-1: to the end), in chunks."""
    while size:
        data = handle.read(CHUNK if size < 0 else min(CHUNK, size))
        if not data:
            return
        size -= len(data) if size > 0 else 0
        yield data


class MoodleSink(_Body):
    """Moodle XML (bank_moodle)."""

    def __init__(self) -> None:
        from . import bank_moodle

        super().__init__()
        self.head, self.tail = bank_moodle.HEAD.encode(), bank_moodle.TAIL.encode()

    def lay_out(self, bank: ProblemBank, variant: Variant, first: bool) -> None:
        from . import bank_moodle

        for piece in bank_moodle.pieces(bank, variant, first):
            self.write(piece)


class BlackboardSink(_Body):
    """A Blackboard upload file (bank_blackboard): one line per number asked."""

    def __init__(self) -> None:
        super().__init__()
        self.records = 0
        self.choices = False
        self.undo = (0, False)

    def lay_out(self, bank: ProblemBank, variant: Variant, first: bool) -> None:
        from .bank_blackboard import line

        for blank in variant.blanks:
            self.write(f"{line(variant, blank)}\r\n", "ascii")
        self.records += len(variant.blanks)
        self.choices = self.choices or bool(variant.choices)

    def begin(self, bank: ProblemBank) -> None:
        self.undo = (self.records, self.choices)
        super().begin(bank)

    def finish(self) -> None:
        self.undo = (self.records, self.choices)
        super().finish()

    def drop(self) -> None:
        self.records, self.choices = self.undo
        super().drop()
