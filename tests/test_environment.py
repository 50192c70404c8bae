"""gyro in a hostile environment (issue 22: data lost, environment).

Closed and full standard output, signals, a read-only or missing HOME, damaged
and racing caches, FIFOs where a cache should be, globs over folders linked
into themselves, and outputs that name an input. Every case runs without root
and leaves nothing outside pytest's tmp_path (``make environment`` runs this
file alone in a temporary folder it removes).

The whole-process cases run gyro in a subprocess: a pipe whose reader has
left, /dev/full and signals only exist there. A signal at a chosen moment is
sent by the process to itself from a hook (a small driver script), so the test
does not depend on timing.
"""

from __future__ import annotations

import hashlib
import os
import shutil
import signal
import subprocess
import sys
import textwrap
import threading
from pathlib import Path

import pytest
from conftest import PROBLEMS

from gyro_cli.core import files, unit_cache
from gyro_cli.core.errors import InputError
from gyro_cli.solving.paths import problem_files

ROOT = Path(__file__).resolve().parents[1]
P11_3 = PROBLEMS / "11_3.yaml"
RELEASED = PROBLEMS / "11_2_released_top.yaml"
VARY = PROBLEMS / "aeroplane_400kg_left.yaml"
ROOT_USER = hasattr(os, "geteuid") and os.geteuid() == 0
needs_fifo = pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="no FIFOs here")
needs_dev_full = pytest.mark.skipif(not os.path.exists("/dev/full"), reason="no /dev/full")


def gyro(*args, env=None, cwd=None, stdout=subprocess.PIPE, timeout=120, stdin=None):
    """Run ``python -m gyro_cli ARGS`` in a subprocess; returns the CompletedProcess."""
    full = dict(os.environ)
    full.update(env or {})
    full = {k: v for k, v in full.items() if v is not None}
    return subprocess.run([sys.executable, "-m", "gyro_cli", *map(str, args)], cwd=cwd or ROOT,
                          env=full, stdout=stdout, stderr=subprocess.PIPE, timeout=timeout,
                          stdin=stdin if stdin is not None else subprocess.DEVNULL)


# A process started from a terminal in the foreground: Ctrl-C raises KeyboardInterrupt,
# SIGTERM and SIGHUP kill. The suite itself may run with SIGINT or SIGHUP ignored (started
# in the background by a shell without job control, or under nohup), and an ignored
# disposition is inherited by every child: gyro then stays immune on purpose, and a test
# of how gyro answers a signal would see exit 0. So the driver sets the dispositions first.
FOREGROUND = """
import signal as _signal
_signal.signal(_signal.SIGINT, _signal.default_int_handler)
for _name in ("SIGTERM", "SIGHUP"):
    if hasattr(_signal, _name):
        _signal.signal(getattr(_signal, _name), _signal.SIG_DFL)
"""


def driver(code: str, *args, env=None, cwd=None, timeout=120, foreground=True):
    """Run gyro's main() in a subprocess after ``code`` (a hook) has run.

    ``foreground`` gives the child the signal dispositions of a foreground
    process, whatever the suite inherited.
    """
    script = ((FOREGROUND if foreground else "") + textwrap.dedent(code)
              + "\nfrom gyro_cli.cli import main\nmain()\n")
    full = dict(os.environ)
    full.update(env or {})
    return subprocess.run([sys.executable, "-c", script, *map(str, args)], cwd=cwd or ROOT,
                          env=full, capture_output=True, timeout=timeout,
                          stdin=subprocess.DEVNULL)


def one_line(stderr: bytes | str, *fragments: str) -> str:
    text = stderr.decode("utf-8", "replace") if isinstance(stderr, bytes) else stderr
    assert "Traceback" not in text, text
    lines = text.splitlines()
    assert len(lines) == 1 and lines[0].startswith("gyro: "), text
    for fragment in fragments:
        assert fragment in lines[0], (fragment, lines[0])
    return lines[0]


def leftovers(folder: Path) -> list[str]:
    return sorted(p.name for p in folder.iterdir() if p.name.endswith(".tmp"))


def digest(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def quickly(call, seconds=20.0):
    """Run ``call`` in a thread; fail instead of hanging the suite if it never ends."""
    box = {}
    thread = threading.Thread(target=lambda: box.setdefault("result", call()), daemon=True)
    thread.start()
    thread.join(seconds)
    assert not thread.is_alive(), f"still running after {seconds} s"
    return box["result"]


# ---- 1: no output is written over an input ------------------------------------------

def course(tmp_path: Path) -> Path:
    folder = tmp_path / "pj"
    folder.mkdir()
    for name in ("11_1.yaml", "11_3.yaml"):
        shutil.copy(PROBLEMS / name, folder / name)
    return folder


def test_i22_01_junit_never_overwrites_input(run, tmp_path):
    folder = course(tmp_path)
    before = {p.name: digest(p) for p in folder.iterdir()}
    # `gyro check --junit pj/*.yaml`: the shell hands the first problem file as the report
    names = sorted(str(p) for p in folder.glob("*.yaml"))
    result = run("check", "--junit", *names)
    one_line(result.stderr, "--junit", "11_1.yaml", "refused")
    # `gyro check pj --junit pj/11_3.yaml`: the report is one of the checked files
    result = run("check", folder, "--junit", folder / "11_3.yaml")
    one_line(result.stderr, "--junit", "would replace an input file")
    # the same file by another name: a symlink that is not even called .yaml
    (folder / "report.xml").symlink_to("11_3.yaml")
    result = run("check", folder, "--junit", folder / "report.xml")
    one_line(result.stderr, "would replace an input file")
    assert result.exit_code == 2
    assert {p.name: digest(p) for p in folder.iterdir() if p.suffix == ".yaml"} == before
    # a report of its own name is still written (and replaced on the next run, as before)
    for _ in range(2):
        result = run("check", folder, "--junit", tmp_path / "j.xml")
        assert result.exit_code == 0, result.output
    assert (tmp_path / "j.xml").read_text().startswith("<?xml")


def test_i22_01_no_output_of_gyro_replaces_an_input(run, tmp_path):
    folder = course(tmp_path)
    problem = folder / "11_3.yaml"
    released = tmp_path / "top.yaml"
    shutil.copy(RELEASED, released)
    sheet = tmp_path / "answers.csv"
    sheet.write_text("student,problem,answer,value\nada,11/3,precession,45.13 rpm\n")
    before = {p: digest(p) for p in (problem, released, sheet)}
    cases = [
        ("check", folder, "--html", problem, "--force"),
        ("check", "--answers", sheet, folder, "--out", sheet, "--force"),
        ("check", "--answers", sheet, folder, "--out", problem, "--force"),
        ("solve", released, "--plot", released, "--force"),
        ("simulate", released, "--csv", released, "--force"),
        ("simulate", released, "--plot", released, "--force"),
    ]
    for args in cases:
        result = run(*args)
        one_line(result.stderr, "refused")
    # a variant may not replace the file it is drawn from, even with --force
    source = tmp_path / "v" / "plane-v1.yaml"
    source.parent.mkdir()
    shutil.copy(VARY, source)
    kept = digest(source)
    result = run("vary", source, "-n", "1", "-o", source.parent, "--force")
    assert result.exit_code == 0  # its variant is plane-v1-v01.yaml, a new name
    assert digest(source) == kept
    assert {p: digest(p) for p in before} == before


def test_i22_01_junit_hard_linked_to_a_checked_file_is_refused(run, tmp_path):
    """The bank's files are looked up once (their device and inode, found while collecting
    them, serve the guard too): a report that is a hard link to one of them, in a folder
    checked recursively, is still refused, and the file is untouched."""
    folder = course(tmp_path)
    (folder / "deep").mkdir()
    shutil.copy(PROBLEMS / "11_5.yaml", folder / "deep" / "11_5.yaml")
    (tmp_path / "report.xml").hardlink_to(folder / "deep" / "11_5.yaml")
    kept = digest(folder / "deep" / "11_5.yaml")
    result = run("check", folder, "--junit", tmp_path / "report.xml")
    one_line(result.stderr, "--junit", "would replace an input file", "11_5.yaml")
    assert result.exit_code == 2 and digest(folder / "deep" / "11_5.yaml") == kept


def test_i22_01_guard_compares_files_not_names(tmp_path):
    a = tmp_path / "a.yaml"
    a.write_text("id: x\n")
    (tmp_path / "hard.txt").hardlink_to(a)
    with pytest.raises(InputError, match="would replace an input file"):
        files.refuse_input_as_output(tmp_path / "hard.txt", [str(a)], option="--out")
    with pytest.raises(InputError, match="would replace an input file"):
        files.refuse_input_as_output(f"{tmp_path}/./a.yaml", [str(a)], option="--out",
                                     yaml_output=True)
    files.refuse_input_as_output(tmp_path / "new.xml", [str(a)])  # a new path is fine
    with pytest.raises(InputError, match="needs a file name"):
        files.refuse_input_as_output("", [])


# ---- 2: files asked for are written whatever happens to stdout -----------------------

def reader_leaves(*args, cwd):
    """Run gyro with stdout on a pipe whose reader has already gone."""
    read, write = os.pipe()
    os.close(read)
    try:
        return gyro(*args, cwd=cwd, stdout=write)
    finally:
        os.close(write)


@pytest.mark.slow
def test_i22_02_junit_written_when_the_reader_leaves(tmp_path):
    result = reader_leaves("check", PROBLEMS, "--junit", "j.xml", cwd=tmp_path)
    assert result.returncode == 141, result.stderr
    assert b"Traceback" not in result.stderr and b"internal error" not in result.stderr
    assert (tmp_path / "j.xml").read_text().startswith("<?xml")
    assert leftovers(tmp_path) == []


@pytest.mark.slow
def test_i22_02_plot_written_when_the_reader_leaves(tmp_path):
    result = reader_leaves("solve", RELEASED, "--plot", "p.png", cwd=tmp_path)
    assert result.returncode == 141, result.stderr
    assert (tmp_path / "p.png").read_bytes().startswith(b"\x89PNG")


@needs_dev_full
@pytest.mark.slow
def test_i22_02_full_stdout_is_one_line_not_an_internal_error(tmp_path):
    with open("/dev/full", "w") as full:
        result = gyro("check", PROBLEMS, "--junit", "j.xml", cwd=tmp_path, stdout=full)
    assert result.returncode == 2
    one_line(result.stderr, "cannot write to standard output", "No space left")
    assert (tmp_path / "j.xml").read_text().startswith("<?xml")


# ---- 3: no temporary file is left, a set is written whole or not at all ---------------

SIGNAL_IN_FSYNC = """
    import os, signal
    real = os.fsync
    def fsync(fd):
        real(fd)
        os.kill(os.getpid(), signal.{name})
    os.fsync = fsync
"""


@pytest.mark.slow
@pytest.mark.parametrize("name, code", [("SIGTERM", 143), ("SIGINT", 130), ("SIGHUP", 129)])
def test_i22_03_signal_while_writing_the_csv_leaves_no_temporary_file(tmp_path, name, code):
    if not hasattr(signal, name):
        pytest.skip(f"no {name} here")
    result = driver(SIGNAL_IN_FSYNC.format(name=name), "simulate", RELEASED, "--periods", "1",
                    "--csv", "s.csv", cwd=tmp_path)
    assert result.returncode == code, result.stderr
    assert b"Traceback" not in result.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == []  # neither .s.csv.*.tmp nor s.csv


def test_i22_03_vary_on_a_full_disk_writes_nothing_and_a_rerun_works(run, tmp_path,
                                                                      monkeypatch):
    calls = []
    real = os.fsync

    def fsync_then_full(fd):
        calls.append(fd)
        if len(calls) == 3:
            raise OSError(28, "No space left on device")
        real(fd)

    monkeypatch.setattr(os, "fsync", fsync_then_full)
    out = tmp_path / "set"
    result = run("vary", VARY, "-n", "4", "-o", out)
    one_line(result.stderr, "No space left on device", "nothing of the set was written")
    assert not out.exists()  # the folder it made is gone too: no partial set, no .tmp
    monkeypatch.setattr(os, "fsync", real)
    result = run("vary", VARY, "-n", "4", "-o", out)
    assert result.exit_code == 0, result.output
    assert sorted(p.name for p in out.iterdir()) == [
        f"aeroplane_400kg_left-v0{i}.yaml" for i in range(1, 5)]


def test_i22_03_write_set_undoes_the_files_it_placed(tmp_path, monkeypatch):
    (tmp_path / "b.txt").write_text("old")
    real = os.link
    placed = []

    def link_then_fail(src, dst):
        if placed:
            raise OSError(5, "Input/output error")
        real(src, dst)
        placed.append(dst)

    def replace_fails(src, dst):
        raise OSError(5, "Input/output error")

    monkeypatch.setattr(os, "link", link_then_fail)
    monkeypatch.setattr(os, "replace", replace_fails)  # no fallback rename either
    with pytest.raises(InputError, match="nothing of the set"):
        files.write_set([(str(tmp_path / "a.txt"), "1"), (str(tmp_path / "c.txt"), "2")])
    assert sorted(p.name for p in tmp_path.iterdir()) == ["b.txt"]
    with pytest.raises(InputError, match="exists"):
        files.write_set([(str(tmp_path / "a.txt"), "1"), (str(tmp_path / "b.txt"), "2")])
    assert sorted(p.name for p in tmp_path.iterdir()) == ["b.txt"]


# ---- 9: the unit table is keyed by what decides a reading ----------------------------

def test_i22_09_unit_table_is_keyed_by_gyro_unit_sources(tmp_path, monkeypatch):
    core = Path(unit_cache.__file__).parent
    copy = tmp_path / "core"
    copy.mkdir()
    for name in os.listdir(core):
        if name.startswith("unit") and name.endswith(".py"):
            shutil.copy(core / name, copy / name)
    monkeypatch.setattr(unit_cache, "__file__", str(copy / "unit_cache.py"))
    unit_cache.forget()
    before = unit_cache.stamp()
    assert before is not None
    # one alias changed in core/units.py: a table made before must not be served
    text = (copy / "units.py").read_text()
    assert '"kph": ("kilometer / hour", "km/h")' in text
    (copy / "units.py").write_text(text.replace('"kph": ("kilometer / hour", "km/h")',
                                                '"kph": ("mile / hour", "mph")'))
    unit_cache.forget()
    after = unit_cache.stamp()
    assert after is not None and after != before
    unit_cache.forget()


def test_i22_09_a_table_with_another_stamp_is_not_served(tmp_path, monkeypatch):
    monkeypatch.setenv("GYRO_CACHE_DIR", str(tmp_path))
    unit_cache.forget()
    (tmp_path / "units.json").write_text(
        '{"stamp": [2, "made by other unit tables"], "parse": '
        '{"1 kph\\u001fspeed\\u001f0": [0.44704, "mph", true]}, "shown": {}, "to": {}}')
    assert unit_cache.get("parse", "1 kph", "speed", 0) is None
    unit_cache.forget()


def test_i22_09_no_private_pint_attribute_is_read():
    """pint's private ``_units`` (and any other underscore attribute of a pint object)."""
    offenders = []
    for path in (ROOT / "gyro_cli").rglob("*.py"):
        for number, line in enumerate(path.read_text().splitlines(), 1):
            if "._units" in line or "._REGISTRY" in line:
                offenders.append(f"{path.relative_to(ROOT)}:{number}")
    assert offenders == []


def test_i22_09_unit_names_come_from_public_pint_api():
    from gyro_cli.core import units

    ureg = units.registry()
    assert units.unit_names(ureg.parse_units("revolution / minute")) == {"turn", "minute"}
    assert units.unit_names(ureg.parse_units("pound_force * foot")) == {"force_pound", "foot"}
    assert units.unit_names(ureg.parse_units("dimensionless")) == set()


# ---- 12: no writable cache, damaged caches, racing first runs -------------------------

COLD = {"GYRO_CACHE_DIR": None, "XDG_CACHE_HOME": None}


def solves(env, cwd):
    result = gyro("solve", P11_3, env=env, cwd=cwd)
    assert result.returncode == 0, result.stderr
    assert result.stderr == b""
    assert b"45.13 rpm" in result.stdout
    return result


@pytest.mark.slow
def test_i22_12_solves_with_home_a_regular_file(tmp_path):
    home = tmp_path / "home"
    home.write_text("not a folder")  # nothing can be created under it, root or not
    solves(dict(COLD, HOME=str(home)), tmp_path)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["home"]


@pytest.mark.skipif(ROOT_USER, reason="root writes into a read-only folder")
def test_i22_12_solves_with_a_read_only_home(tmp_path):
    home = tmp_path / "home"
    home.mkdir()
    home.chmod(0o555)
    try:
        solves(dict(COLD, HOME=str(home)), tmp_path)
    finally:
        home.chmod(0o755)
    assert list(home.iterdir()) == []


@pytest.mark.slow
def test_i22_12_solves_with_home_missing_and_creates_none(tmp_path):
    home = tmp_path / "gone"
    solves(dict(COLD, HOME=str(home)), tmp_path)
    assert not home.exists()
    env = {k: None for k in ("HOME", "GYRO_CACHE_DIR", "XDG_CACHE_HOME")}
    solves(env, tmp_path)
    assert list(tmp_path.iterdir()) == []


@pytest.mark.slow
def test_i22_12_empty_cache_dir_means_no_cache_at_all(tmp_path):
    home = tmp_path / "home"
    home.write_text("not a folder")
    solves({"GYRO_CACHE_DIR": "", "XDG_CACHE_HOME": None, "HOME": str(home)}, tmp_path)
    solves({"GYRO_CACHE_DIR": "", "XDG_CACHE_HOME": str(tmp_path / "x")}, tmp_path)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["home"]


@pytest.mark.slow
def test_i22_12_a_truncated_pint_pickle_is_ignored_and_rebuilt(tmp_path):
    cache = tmp_path / "cache"
    solves({"GYRO_CACHE_DIR": str(cache)}, tmp_path)
    pickles = sorted((cache / "pint").glob("*.pickle"))
    assert pickles, "pint's cache is expected in gyro's folder"
    for pickle in pickles:
        pickle.write_bytes(pickle.read_bytes()[:100])
    (cache / "units.json").unlink()  # so that pint is asked again
    solves({"GYRO_CACHE_DIR": str(cache)}, tmp_path)
    (cache / "units.json").unlink()
    solves({"GYRO_CACHE_DIR": str(cache)}, tmp_path)
    rebuilt = sorted((cache / "pint").glob("*.pickle"))
    assert rebuilt and all(p.stat().st_size > 100 for p in rebuilt)


@pytest.mark.slow
@pytest.mark.parametrize("damage", [b"", b"{", b"\x80\x04garbage", b"[]"])
def test_i22_12_a_damaged_gyro_table_is_ignored(tmp_path, damage):
    cache = tmp_path / "cache"
    cache.mkdir()
    (cache / "units.json").write_bytes(damage)
    solves({"GYRO_CACHE_DIR": str(cache)}, tmp_path)
    assert (cache / "units.json").read_bytes() != damage  # rebuilt


@pytest.mark.slow
def test_i22_12_parallel_first_runs_on_a_fresh_home_both_succeed(tmp_path):
    for round_ in range(3):
        home = tmp_path / f"home{round_}"
        home.mkdir()
        env = dict(os.environ, HOME=str(home))
        env.pop("GYRO_CACHE_DIR", None)
        env.pop("XDG_CACHE_HOME", None)
        procs = [subprocess.Popen([sys.executable, "-m", "gyro_cli", "solve", str(P11_3)],
                                  env=env, cwd=tmp_path, stdout=subprocess.PIPE,
                                  stderr=subprocess.PIPE) for _ in range(2)]
        for proc in procs:
            out, err = proc.communicate(timeout=120)
            assert proc.returncode == 0, err
            assert b"45.13 rpm" in out


# ---- 13: each real file once, only regular files, never block ------------------------

def test_i22_13_glob_over_folders_linked_into_themselves_names_each_file_once(tmp_path):
    top = tmp_path / "dir"
    (top / "sub").mkdir(parents=True)
    shutil.copy(P11_3, top / "11_3.yaml")
    shutil.copy(PROBLEMS / "11_1.yaml", top / "sub" / "11_1.yaml")
    (top / "a").symlink_to(".")
    (top / "sub" / "b").symlink_to("..")  # a second loop: Python's glob never ends
    (top / "same.yaml").symlink_to("11_3.yaml")
    found, missing = quickly(lambda: problem_files([f"{top}/**/*.yaml"]))
    assert missing == []
    assert sorted(os.path.relpath(f, top) for f in found) == ["11_3.yaml", "sub/11_1.yaml"]
    found, _ = quickly(lambda: problem_files([str(top), str(top / "same.yaml"),
                                              f"{top}/./11_3.yaml"]))
    assert len(found) == 2


def test_i22_13_glob_still_matches_as_python_does(tmp_path):
    (tmp_path / "a" / "b").mkdir(parents=True)
    (tmp_path / ".hidden").mkdir()
    for name in ("x.yaml", "a/y.yaml", "a/b/z.yml", "a/b/.h.yaml", ".hidden/w.yaml"):
        (tmp_path / name).write_text("id: x\n")
    import glob

    for pattern in ("**/*.yaml", "a/**/*.yml", "**/b/*", "a/**", "**/*.y*ml"):
        expected = sorted(p for p in glob.glob(f"{tmp_path}/{pattern}", recursive=True)
                          if os.path.isfile(p))
        got = sorted(problem_files([f"{tmp_path}/{pattern}"])[0])
        assert got == expected, pattern


@needs_fifo
@pytest.mark.slow
@pytest.mark.parametrize("where", ["units.json", "pint/x.pickle", "pint"])
def test_i22_13_a_fifo_at_a_cache_path_does_not_block(tmp_path, where):
    cache = tmp_path / "cache"
    (cache / "pint").mkdir(parents=True)
    if where == "pint":
        (cache / "pint").rmdir()
    os.mkfifo(cache / where)
    result = gyro("solve", P11_3, env={"GYRO_CACHE_DIR": str(cache)}, cwd=tmp_path, timeout=60)
    assert result.returncode == 0, result.stderr
    assert b"45.13 rpm" in result.stdout


# ---- 14: exit codes -------------------------------------------------------------------

def test_i22_14_sigint_exits_130_not_1(tmp_path):
    hook = """
        import os, signal
        import gyro_cli.core.safeyaml as safeyaml
        real = safeyaml.read_bytes
        def read_bytes(*args, **kwargs):
            os.kill(os.getpid(), signal.SIGINT)
            return real(*args, **kwargs)
        safeyaml.read_bytes = read_bytes
    """
    result = driver(hook, "check", P11_3, "--junit", "j.xml", cwd=tmp_path)
    assert result.returncode == 130, result.stderr
    one_line(result.stderr, "interrupted")
    assert b"Aborted" not in result.stderr
    assert list(tmp_path.iterdir()) == []


def test_i22_14_an_ignored_sigint_is_inherited_and_stays_ignored(tmp_path):
    """nohup or a background job: SIGINT arrives ignored, and gyro keeps it so."""
    hook = """
        import os, signal
        signal.signal(signal.SIGINT, signal.SIG_IGN)
        import gyro_cli.core.safeyaml as safeyaml
        real = safeyaml.read_bytes
        def read_bytes(*args, **kwargs):
            os.kill(os.getpid(), signal.SIGINT)
            os.write(2, b"SIGINT sent\\n")
            return real(*args, **kwargs)
        safeyaml.read_bytes = read_bytes
    """
    result = driver(hook, "check", P11_3, "--junit", "j.xml", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert result.stderr.startswith(b"SIGINT sent\n")  # the hook did run
    assert (tmp_path / "j.xml").exists()


@needs_dev_full
@pytest.mark.parametrize("args", [["--help"], ["--version"], ["solve", "--help"],
                                  ["schema"], ["kinds"]])
def test_i22_14_stdout_on_dev_full_is_one_line_exit_2(args, tmp_path):
    with open("/dev/full", "w") as full:
        result = gyro(*args, cwd=tmp_path, stdout=full)
    assert result.returncode == 2
    one_line(result.stderr, "cannot write to standard output")


@pytest.mark.parametrize("args", [["--help"], ["--version"], ["kinds"]])
def test_i22_14_reader_leaving_is_141_as_for_every_command(args, tmp_path):
    result = reader_leaves(*args, cwd=tmp_path)
    assert result.returncode == 141, result.stderr
    assert result.stderr == b""


def test_i22_14_vary_to_a_looping_or_impossible_path_is_one_line(run, tmp_path):
    (tmp_path / "loop").symlink_to("loop")
    (tmp_path / "file").write_text("x")
    for out, words in ((tmp_path / "loop" / "x", "cannot create the directory"),
                       (tmp_path / "file" / "x", "cannot create the directory"),
                       (tmp_path / "file", "is not a directory"),
                       ("", "needs a directory name")):
        result = run("vary", VARY, "-n", "2", "-o", out)
        one_line(result.stderr, words)


@pytest.mark.skipif(ROOT_USER, reason="root writes into a read-only folder")
def test_i22_14_vary_to_an_unwritable_folder_is_one_line(run, tmp_path):
    locked = tmp_path / "locked"
    locked.mkdir()
    locked.chmod(0o555)
    try:
        result = run("vary", VARY, "-n", "2", "-o", locked / "set")
    finally:
        locked.chmod(0o755)
    one_line(result.stderr, "Permission denied")


@pytest.mark.skipif(sys.platform in ("darwin", "win32"), reason="file names must be UTF-8 here")
def test_i22_14_non_utf8_file_name_with_junit(tmp_path):
    folder = tmp_path / "p"
    folder.mkdir()
    name = os.fsdecode(b"\xff.yaml")
    shutil.copy(P11_3, folder / name)
    for encoding in ("utf-8:strict", "utf-8:surrogateescape"):
        result = gyro("check", folder, "--junit", "j.xml", cwd=tmp_path,
                      env={"PYTHONIOENCODING": encoding})
        assert result.returncode == 0, result.stderr
        assert b"\\udcff.yaml" in result.stdout or b"\xff.yaml" in result.stdout
        import xml.dom.minidom

        report = (tmp_path / "j.xml").read_text("utf-8")
        xml.dom.minidom.parseString(report)
        assert "\\udcff.yaml" in report


def test_i22_14_schema_to_a_cp1252_stdout_is_one_line_exit_2(tmp_path):
    result = gyro("schema", cwd=tmp_path, env={"PYTHONIOENCODING": "cp1252"})
    assert result.returncode == 2
    one_line(result.stderr, "cp1252", "PYTHONIOENCODING=utf-8")


@pytest.mark.parametrize("option", ["--junit", "--html"])
def test_i22_14_empty_output_name_is_refused(run, option):
    result = run("check", P11_3, option, "")
    one_line(result.stderr, f"{option} needs a file name")


@pytest.mark.parametrize("args", [["solve", P11_3, "--plot", ""],
                                  ["simulate", RELEASED, "--csv", ""],
                                  ["new", "steady_precession", "-o", ""]])
def test_i22_14_every_empty_output_name_is_refused(run, args):
    result = run(*args)
    one_line(result.stderr, "needs a file name")
