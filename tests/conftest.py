"""Shared helpers: run the CLI in-process and write problem files."""

from __future__ import annotations

import atexit
import os
import re
import shutil
import tempfile
import textwrap
from pathlib import Path

# The unit cache of the test run is its own, never the user's (~/.cache/gyro), and it is
# removed when the process that made it ends (each of the three processes of a `make test`
# left one in the temporary folder: 1,454 of them, 300 MB, on the project's machine).
TEST_CACHE = tempfile.mkdtemp(prefix="gyro-test-cache-")
os.environ["GYRO_CACHE_DIR"] = TEST_CACHE


def _remove_test_cache(owner: int = os.getpid()) -> None:
    if os.getpid() == owner:  # not a child forked by a test, which ends while the run goes on
        shutil.rmtree(TEST_CACHE, ignore_errors=True)


atexit.register(_remove_test_cache)

import pytest
from click.testing import CliRunner

from gyro_cli.cli import main

ROOT = Path(__file__).resolve().parent.parent
PROBLEMS = ROOT / "problems"


def read_yaml(text: str):  # type: ignore[no-untyped-def]
    """Test data (a bundled problem, a variant file) read with libyaml where PyYAML has
    it: the objects of ``yaml.safe_load``, ten times sooner (4 ms a problem file)."""
    import yaml

    return yaml.load(text, Loader=getattr(yaml, "CSafeLoader", yaml.SafeLoader))


def examples(n: int) -> int:
    """A property test's hypothesis budget: ``n`` examples, sized to what the test finds
    in a `make test`; GYRO_EXAMPLES times as many in a long run (`make props`)."""
    return n * max(1, int(os.environ.get("GYRO_EXAMPLES") or 1))


@pytest.fixture
def tmp_path(tmp_path_factory: pytest.TempPathFactory, request: pytest.FixtureRequest) -> Path:
    """pytest's own, made without its scan: pytest numbers a test's folder by listing every
    folder made before it in the process, which cost each test process of a `make test`
    about two seconds (1,500 tests write files). A folder of its own under the same base
    (named after the test, as pytest's is, with a random end), kept as pytest keeps its."""
    name = re.sub(r"\W", "_", request.node.name)[:30]
    return Path(tempfile.mkdtemp(prefix=name, dir=tmp_path_factory.getbasetemp()))


@pytest.fixture
def run():
    """run(*args) -> click Result with .exit_code, .stdout, .stderr."""
    def _run(*args: str):
        return CliRunner().invoke(main, [str(a) for a in args])
    return _run


@pytest.fixture
def write(tmp_path):
    """write(text, name='p.yaml') -> path of a problem file with dedented text."""
    def _write(text: str, name: str = "p.yaml") -> Path:
        path = tmp_path / name
        path.write_text(textwrap.dedent(text))
        return path
    return _write


def class_set(run, folder: Path, ids: list[str], problem: Path = PROBLEMS / "11_3.yaml",
              seed: int = 7, name: str = "hw") -> Path:
    """`gyro vary --roster` of the students ``ids`` into ``folder/name``; its assignment."""
    roster = folder / f"{name}-roster.csv"
    roster.write_text("student,name\n" + "".join(f"{i},{i.title()}\n" for i in ids))
    done = run("vary", problem, "--roster", roster, "--seed", str(seed), "-o", folder / name)
    assert done.exit_code == 0, done.output
    return folder / name / "assignment.csv"


@pytest.fixture
def problems_dir() -> Path:
    return PROBLEMS


@pytest.fixture(scope="session")
def browser():
    """One headless Chromium per test process, shared by every page test
    (tests/test_browser.py finds it and says why it is missing)."""
    from test_browser import CHROMIUM, MISSING, sync_playwright

    if MISSING is not None:
        pytest.skip(MISSING)
    os.environ.setdefault("PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD", "1")
    with sync_playwright() as p:
        b = p.chromium.launch(executable_path=CHROMIUM,
                              args=["--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage"])
        yield b
        b.close()


@pytest.fixture(scope="session")
def axe():
    """axe-core's script, read once per test process."""
    from test_browser import Axe

    return Axe()
