"""Only regular files are read, never more than the limit; outputs go only to a regular
file or a new path, and a failed write leaves nothing behind."""

from __future__ import annotations

import errno
import os
import shutil
import stat
import threading
import time

import pytest
from conftest import PROBLEMS

from gyro_cli.core import files, safeyaml
from gyro_cli.core.errors import InputError

needs_fifo = pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="no FIFOs here")


def one_line(result, *fragments):
    assert result.exit_code == 2, result.output
    assert "Traceback" not in result.output
    lines = result.stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith("gyro: "), result.stderr
    for fragment in fragments:
        assert fragment in lines[0], (fragment, lines[0])
    return lines[0]


def device_link(tmp_path, device):
    if not os.path.exists(device):
        pytest.skip(f"no {device} here")
    link = tmp_path / f"{os.path.basename(device)}.yaml"
    try:
        link.symlink_to(device)
    except OSError:
        pytest.skip("no symlinks here")
    return link


def quickly(call, seconds=5.0):
    """Run ``call`` in a thread; fail (instead of hanging the suite) if it blocks."""
    box = {}
    thread = threading.Thread(target=lambda: box.setdefault("result", call()), daemon=True)
    began = time.monotonic()
    thread.start()
    thread.join(seconds)
    assert not thread.is_alive(), f"still blocked after {seconds} s"
    assert time.monotonic() - began < seconds
    return box["result"]


@needs_fifo
@pytest.mark.parametrize("command", ["solve", "check", "simulate"])
def test_a_fifo_is_refused_at_once(run, tmp_path, command):
    fifo = tmp_path / "pipe.yaml"
    os.mkfifo(fifo)
    result = quickly(lambda: run(command, fifo))
    one_line(result, str(fifo), "FIFO", "only regular files")


@needs_fifo
def test_check_directory_with_a_fifo_lists_it_and_checks_the_rest(run, tmp_path):
    os.mkfifo(tmp_path / "a_pipe.yaml")
    shutil.copy(PROBLEMS / "11_3.yaml", tmp_path / "b.yaml")
    result = quickly(lambda: run("check", tmp_path))
    assert result.exit_code == 2
    assert len(result.stderr.splitlines()) == 1
    assert "a_pipe.yaml" in result.stdout and "ERROR" in result.stdout
    assert "b.yaml" in result.stdout and "PASS" in result.stdout


@pytest.mark.parametrize("device", ["/dev/zero", "/dev/urandom"])
@pytest.mark.parametrize("command", ["solve", "check"])
def test_a_symlink_to_a_device_is_refused_at_once(run, tmp_path, device, command):
    link = device_link(tmp_path, device)
    result = quickly(lambda: run(command, link))
    one_line(result, str(link), "character device", "only regular files")


def test_a_device_as_answer_sheet_is_refused(run, tmp_path):
    link = device_link(tmp_path, "/dev/zero")
    sheet = tmp_path / "sheet.csv"
    sheet.symlink_to(link)
    result = quickly(lambda: run("check", "--answers", sheet, PROBLEMS))
    one_line(result, "character device")


def test_a_directory_named_as_a_file(run, tmp_path):
    folder = tmp_path / "folder.yaml"
    folder.mkdir()
    # solve takes directories of problems (issue 8): an empty one is one line, exit 2
    one_line(run("solve", folder), "no .yaml or .yml files in this directory")
    one_line(run("simulate", folder), "is a directory")


def test_never_more_than_the_limit_is_read(tmp_path, monkeypatch):
    path = tmp_path / "big.yaml"
    path.write_bytes(b"x" * 5000)
    reads = []
    real_read = os.read

    def counting_read(fd, n):
        reads.append(n)
        return real_read(fd, n)

    monkeypatch.setattr(os, "read", counting_read)
    with pytest.raises(InputError, match="larger than 1000 bytes"):
        safeyaml.read_bytes(str(path), 1000)
    assert sum(reads) <= 1001
    assert safeyaml.read_bytes(str(path), 5000) == b"x" * 5000


def test_a_file_past_the_size_limit(run, tmp_path):
    path = tmp_path / "big.yaml"
    path.write_text("id: x\nnotes: |\n" + "  padding\n" * 110_000)
    one_line(run("solve", path), "larger than 1000000 bytes")


# ---- outputs ----------------------------------------------------------------

@pytest.mark.parametrize("force", [[], ["--force"]])
def test_out_to_a_device_is_refused_and_the_device_kept(run, tmp_path, force):
    if not os.path.exists("/dev/full"):
        pytest.skip("no /dev/full here")
    sheet = tmp_path / "sheet.csv"
    sheet.write_text("ann,11/3,precession,1 rad/s\n")
    result = run("check", "--answers", sheet, PROBLEMS, "--out", "/dev/full", *force)
    one_line(result, "/dev/full", "character device")
    assert stat.S_ISCHR(os.stat("/dev/full").st_mode)


@needs_fifo
@pytest.mark.parametrize("force", [[], ["--force"]])
def test_plot_to_a_fifo_or_directory_is_refused(run, tmp_path, force):
    fifo = tmp_path / "plot.png"
    os.mkfifo(fifo)
    problem = PROBLEMS / "11_2_released_top.yaml"
    one_line(quickly(lambda: run("solve", problem, "--plot", fifo, *force)), "FIFO")
    assert stat.S_ISFIFO(os.stat(fifo).st_mode)
    one_line(quickly(lambda: run("simulate", problem, "--periods", "0.5", "--plot", fifo,
                                 *force)), "FIFO")
    folder = tmp_path / "dir.png"
    folder.mkdir()
    one_line(run("solve", problem, "--plot", folder, *force), "is a directory")


def test_a_full_disk_is_reported_and_leaves_no_temporary_file(tmp_path, monkeypatch):
    def full(fd):
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    monkeypatch.setattr(os, "fsync", full)
    target = tmp_path / "grades.csv"
    with pytest.raises(InputError, match="No space left on device"):
        files.write_atomic(target, "a,b\n", force=True)
    assert os.listdir(tmp_path) == []


def test_a_full_disk_through_the_command_is_exit_2(run, tmp_path, monkeypatch):
    monkeypatch.setattr(os, "fsync", lambda fd: (_ for _ in ()).throw(
        OSError(errno.ENOSPC, "No space left on device")))
    sheet = tmp_path / "sheet.csv"
    sheet.write_text("ann,11/3,precession,1 rad/s\n")
    out = tmp_path / "grades.csv"
    one_line(run("check", "--answers", sheet, PROBLEMS, "--out", out), "No space left")
    assert sorted(os.listdir(tmp_path)) == ["sheet.csv"]


def test_an_interrupted_write_leaves_no_temporary_file(tmp_path, monkeypatch):
    def interrupted(fd):
        raise KeyboardInterrupt

    monkeypatch.setattr(os, "fsync", interrupted)
    with pytest.raises(KeyboardInterrupt):
        files.write_atomic(tmp_path / "x.csv", "data")
    assert os.listdir(tmp_path) == []


def test_a_stale_temporary_file_is_never_taken_for_output(run, tmp_path):
    """A killed run's temporary file is hidden and ends in .tmp: not a problem file."""
    shutil.copy(PROBLEMS / "11_3.yaml", tmp_path / "11_3.yaml")
    stale = tmp_path / ".11_4.yaml.k3j2h1.tmp"
    stale.write_text((PROBLEMS / "11_4.yaml").read_text()[:40])  # half written
    result = run("check", tmp_path)
    assert result.exit_code == 0, result.output
    assert ".tmp" not in result.stdout
    result = run("check", str(tmp_path / "*.yaml"))
    assert result.exit_code == 0 and ".tmp" not in result.stdout
    written = files.write_atomic(tmp_path / "11_4.yaml", "id: new\n")
    assert written.read_text() == "id: new\n"
    assert stale.exists()  # not ours to remove, and not read
