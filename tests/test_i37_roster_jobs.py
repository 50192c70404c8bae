"""Issue 37, item 3: `gyro vary --roster` draws a class of `POOLED` variants or more in
forked workers (`--jobs N`, default the CPUs), to the same bytes as one process: a
variant depends only on the seed, its problem and its student."""

from __future__ import annotations

import errno
import os
import threading
import time
from pathlib import Path

import pytest
from test_i37_roster_fast import _roster, _tree

from gyro_cli.checking import pool
from gyro_cli.commands import roster
from gyro_cli.core.files import StagedFolder

ROOT = Path(__file__).resolve().parent.parent
TOP = ROOT / "problems" / "11_3.yaml"
FIVE = ROOT / "problems" / "11_5.yaml"

needs_fork = pytest.mark.skipif(not pool.forks(), reason="no fork here: one process draws")


@pytest.fixture
def forks(monkeypatch):  # type: ignore[no-untyped-def]
    """The threads alive at each fork of this process (the parent's record)."""
    seen: list[int] = []
    real = os.fork

    def fork() -> int:
        seen.append(threading.active_count())
        return real()

    monkeypatch.setattr(os, "fork", fork)
    return seen


@pytest.fixture
def handed(monkeypatch):  # type: ignore[no-untyped-def]
    """The files this process hands to a staged folder's writer (its name, from the set's
    folder), or writes there itself; a worker's own writes are not seen here."""
    seen: list[str] = []
    real = StagedFolder.add

    def add(self, path, text):  # type: ignore[no-untyped-def]
        seen.append(os.path.relpath(path, self.folder))
        return real(self, path, text)

    monkeypatch.setattr(StagedFolder, "add", add)
    return seen


@needs_fork
def test_item03_two_workers_write_the_bytes_one_process_writes(run, tmp_path, forks, handed):
    students = roster.POOLED // 2  # two problems: exactly POOLED variants
    names = _roster(tmp_path / "r.csv", students)
    one, two = tmp_path / "one", tmp_path / "two"
    threads = threading.active_count()  # the test run's own
    assert run("vary", TOP, FIVE, "--roster", names, "-o", one, "--jobs", "1").exit_code == 0
    assert forks == [] and len(handed) == 2 * students + 2
    handed.clear()
    result = run("vary", TOP, FIVE, "--roster", names, "-o", two, "--jobs", "2")
    assert result.exit_code == 0, result.output
    # two workers, each forked while gyro had started no thread (the staged folder's
    # writer starts after them, with the key)
    assert forks == [threads, threads]
    # the workers wrote the variants' files; this process only the key and the assignment
    assert handed == ["key.json", "assignment.csv"]
    assert _tree(two) == _tree(one)
    assert len(list((two / "11_3").iterdir())) == students


@needs_fork
def test_item03_a_file_a_worker_cannot_write_is_one_line_and_nothing_left(run, tmp_path,
                                                                          monkeypatch):
    """A worker that cannot write a variant's file (a full disk, here at the 151st
    student's, after the workers have written others) stops the set as one process
    would: one line naming the file, exit 2, and no file and no hidden folder left."""
    real = os.open

    def full(path, flags, mode=0o777, *, dir_fd=None):  # type: ignore[no-untyped-def]
        name = os.path.basename(str(path))
        if str(path).endswith(os.path.join("11_3", "s150.yaml")):
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), path)
        if name.startswith("s") and name.endswith(".yaml") and name > "s150.yaml":
            time.sleep(0.02)  # the other worker is still writing when the error is back
        return real(path, flags, mode, dir_fd=dir_fd)

    monkeypatch.setattr(os, "open", full)  # in this process, and so in its forked workers
    names = _roster(tmp_path / "r.csv", roster.POOLED)
    result = run("vary", TOP, FIVE, "--roster", names, "-o", tmp_path / "set", "--jobs", "2")
    assert result.exit_code == 2, result.output
    assert result.stderr.strip().splitlines() == [
        f"gyro: {tmp_path / 'set' / '11_3' / 's150.yaml'}: cannot write: No space left on "
        "device; nothing of the set was written"]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["r.csv"]


@needs_fork
def test_item03_a_class_under_pooled_is_drawn_in_this_process(run, tmp_path, forks):
    names = _roster(tmp_path / "r.csv", roster.POOLED // 2 - 1)
    result = run("vary", TOP, FIVE, "--roster", names, "-o", tmp_path / "set", "--jobs", "4")
    assert result.exit_code == 0, result.output
    assert forks == []


@needs_fork
@pytest.mark.parametrize("jobs", ["1", "2"])
def test_item03_no_real_draw_in_a_worker_is_one_line_and_nothing_written(run, tmp_path,
                                                                          jobs):
    slow = tmp_path / "slow.yaml"  # a spin of 180-360 rpm: below the least for steady precession
    slow.write_text(TOP.read_text().replace("spin: [0.8, 1.25]", "spin: [0.1, 0.2]"))
    names = _roster(tmp_path / "r.csv", roster.POOLED)
    result = run("vary", slow, "--roster", names, "-o", tmp_path / "set", "--jobs", jobs)
    assert result.exit_code == 2, result.output
    assert "no draw of 200 for student 's000' has a real solution" in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1
    assert sorted(p.name for p in tmp_path.iterdir()) == ["r.csv", "slow.yaml"]


def test_item03_jobs_goes_with_roster(run, tmp_path):
    result = run("vary", TOP, "-n", "2", "-o", tmp_path / "v", "--jobs", "2")
    assert result.exit_code == 2 and "--jobs goes with --roster" in result.stderr
