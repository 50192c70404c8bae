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
from collections.abc import Iterator
from typing import IO, TYPE_CHECKING

if TYPE_CHECKING:
    import zipfile

from .bank import ProblemBank, Variant

CHUNK = 1 << 18


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
    the first is held until the second comes or the problem is committed. An abort
    without a begin (a file refused before its variants) drops nothing."""

    open = False

    def begin(self, bank: ProblemBank) -> None:
        self.bank = bank
        self.held: Variant | None = None
        self.seen = 0
        self.open = True  # begun and not yet committed: an abort drops what it wrote
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
        self.open = False
        return self.bank

    def abort(self) -> None:
        if self.open:
            self.held = None
            self.drop()
        self.open = False

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


class QtiSink(_Marking):
    """A QTI 1.2 zip (bank_qti): each problem's QTI file and pictures go to two temporary
    files as the variants come; `chunks` packs them after the manifest, which names them
    all (so the zip is made at the end, from disk)."""

    def __init__(self) -> None:
        self.items: IO[bytes] = tempfile.TemporaryFile()
        self.pictures: IO[bytes] = tempfile.TemporaryFile()
        #: each problem committed: its bank, where its QTI file lies, and its pictures'
        #: paths in the zip and where they lie
        self.done: list[tuple[ProblemBank, tuple[int, int], list[tuple[str, int, int]]]] = []

    def start(self) -> None:
        from .bank_qti import assessment_head

        self.marks = (self.items.tell(), self.pictures.tell())
        self.figures: list[tuple[str, int, int]] = []
        self.items.write(assessment_head(self.bank).encode())

    def lay_out(self, bank: ProblemBank, variant: Variant, first: bool) -> None:
        from .bank_qti import items

        for item in items(bank, variant):
            self.items.write(f"{item}\n".encode())
        if variant.figure:
            self.figures.append((variant.figure_name, self.pictures.tell(), len(variant.figure)))
            self.pictures.write(variant.figure)

    def finish(self) -> None:
        from .bank_qti import ASSESSMENT_TAIL

        self.items.write(ASSESSMENT_TAIL.encode())
        start = self.marks[0]
        self.done.append((self.bank, (start, self.items.tell() - start),
                          [(f"{self.bank.slug}/{name}", at, size)
                           for name, at, size in self.figures]))

    def drop(self) -> None:
        for handle, mark in zip((self.items, self.pictures), self.marks):
            handle.truncate(mark)
            handle.seek(mark)

    def chunks(self) -> Iterator[bytes]:
        """The zip, as `bank_qti.package` makes it from whole banks."""
        import zipfile

        from .bank_qti import entry, file_name, manifest

        pictures = {bank.id: [path for path, _, _ in figures] for bank, _, figures in self.done}
        packed = tempfile.TemporaryFile()
        with zipfile.ZipFile(packed, "w", zipfile.ZIP_DEFLATED) as archive:
            archive.writestr(entry("imsmanifest.xml"), manifest(
                [bank for bank, _, _ in self.done], lambda bank: pictures[bank.id]).encode())
            for bank, (at, size), figures in self.done:
                _copy(archive, file_name(bank), self.items, at, size)
                for path, where, length in figures:
                    _copy(archive, path, self.pictures, where, length)
        self.items.close()
        self.pictures.close()
        packed.seek(0)
        yield from _read(packed)
        packed.close()


def _copy(archive: zipfile.ZipFile, name: str, source: IO[bytes], at: int, size: int) -> None:
    """Pack ``size`` bytes of ``source`` from ``at`` as the entry ``name``, as
    ``ZipFile.writestr`` packs the same bytes (its size known before it is written)."""
    from .bank_qti import entry

    info = entry(name)
    info.file_size = size
    source.seek(at)
    with archive.open(info, "w") as dest:
        for data in _read(source, size):
            dest.write(data)


class PrairieLearnSink(Sink):
    """PrairieLearn questions (bank_prairielearn): each variant is kept on disk (pickled,
    its picture beside it) as it comes; `files` gives each question's files, read back
    from disk a variant at a time (the page's inputs and the choices' words are known only
    once every variant has come)."""

    def __init__(self) -> None:
        self.spool: IO[bytes] = tempfile.TemporaryFile()
        self.done: list[tuple[ProblemBank, list[tuple[int, int, int, str]]]] = []
        self.open = False

    def begin(self, bank: ProblemBank) -> None:
        self.bank = bank
        self.mark = self.spool.tell()
        self.open = True
        #: each variant: where its pickle lies, its size, its PNG's size and its name
        self.where: list[tuple[int, int, int, str]] = []

    def add(self, variant: Variant) -> None:
        import pickle

        at = self.spool.tell()
        name = variant.figure_name
        kept = dataclasses.replace(variant, figure=b"", figure_tag=variant.figure_digest)
        self.spool.write(pickle.dumps(kept))
        size = self.spool.tell() - at
        self.spool.write(variant.figure)
        self.where.append((at, size, len(variant.figure), name))

    def commit(self, bank: ProblemBank) -> ProblemBank:
        done = dataclasses.replace(bank, count=len(self.where))
        self.done.append((done, self.where))
        self.open = False
        return done

    def abort(self) -> None:
        if self.open:  # else nothing of this problem was written
            self.spool.truncate(self.mark)
            self.spool.seek(self.mark)
        self.open = False

    def _variants(self, where: list[tuple[int, int, int, str]]
                  ) -> Iterator[tuple[Variant, int]]:
        """Each variant back from disk (without its PNG) and where its PNG lies."""
        import pickle

        for at, size, _, _ in where:
            self.spool.seek(at)
            yield pickle.loads(self.spool.read(size)), at + size

    def files(self) -> Iterator[tuple[str, Iterator[bytes]]]:
        """Relative path and content (in chunks) of every file, in `bank_prairielearn.files`'s
        order; the choices' words come from every variant (read once before server.py)."""
        import json

        from . import bank_prairielearn as pl

        for bank, where in self.done:
            yield f"{bank.slug}/info.json", iter([(json.dumps(
                pl.info(bank), indent=2, ensure_ascii=False) + "\n").encode()])
            shown = self._shown(bank, where)
            yield f"{bank.slug}/question.html", iter([pl.question_html(shown).encode()])
            words = {key: choices for key, (_, choices) in pl._choices(shown).items()}
            entries = (pl.variant_entry(v, words, figure=bool(where[k][2]))
                       for k, (v, _) in enumerate(self._variants(where)))
            yield f"{bank.slug}/server.py", (piece.encode() for piece in
                                             pl.server_pieces(bank, entries))
            for at, size, png, name in where:
                if png:
                    yield (f"{bank.slug}/clientFilesQuestion/{name}",
                           self._png(at + size, png))

    def names(self) -> list[str]:
        """The relative path of every file `files` gives, in its order."""
        return [name for bank, where in self.done
                for name in [f"{bank.slug}/info.json", f"{bank.slug}/question.html",
                             f"{bank.slug}/server.py",
                             *(f"{bank.slug}/clientFilesQuestion/{name}"
                               for _, _, png, name in where if png)]]

    def _shown(self, bank: ProblemBank, where: list[tuple[int, int, int, str]]
               ) -> ProblemBank:
        """The bank with variants enough for its page (every blank and choice of all of
        them, each choice with the words of all variants): a pass over the variants,
        keeping only what is new."""
        kept: list[Variant] = []
        keys: set[str] = set()
        words: dict[str, set[str]] = {}
        for variant, _ in self._variants(where):
            new = [*(b.key for b in variant.blanks if b.key not in keys),
                   *(c.key for c in variant.choices if c.key not in keys)]
            fresh = any(set(c.choices) - words.get(c.key, set()) for c in variant.choices)
            if new or fresh:
                kept.append(variant)
                keys.update(new)
                for c in variant.choices:
                    words.setdefault(c.key, set()).update(c.choices)
        return dataclasses.replace(bank, variants=kept)

    def _png(self, at: int, size: int) -> Iterator[bytes]:
        self.spool.seek(at)
        yield from _read(self.spool, size)
