"""Issue 39, the front door: the documentation site (item 2), a package that installs
alone (item 3), and the hooks for course repositories (item 4).

The slow ones build things as a user would, offline: the site with mkdocs in strict
mode (~10 s), the sdist and wheel with ``python -m build`` then the wheel in a fresh
virtual environment (~30 s), and the pre-commit hook named in a course repository's
configuration and run by ``pre-commit run`` (~10 s, most of it pre-commit making the hook's
environment). The wheel and the hook
take their dependencies (numpy, scipy, pint...) from this test's own environment rather
than from a package index, so they need no network; gyro itself is always the one
installed from the built package, never this checkout.
"""

from __future__ import annotations

import importlib.util
import json
import os
import re
import shutil
import stat
import subprocess
import sys
import sysconfig
import tarfile
import tomllib
import zipfile
from pathlib import Path
from types import ModuleType
from typing import Any

import pytest
import yaml

import gyro_cli

ROOT = Path(__file__).resolve().parent.parent
PROBLEM = ROOT / "problems" / "11_3.yaml"


def _need_module(name: str) -> None:
    if importlib.util.find_spec(name) is None:
        pytest.skip(f"{name} is not installed (pip install -e '.[dev]' installs it)")


def _source_files() -> list[str]:
    """The checkout's files as a clone would have them (tracked, and new ones not ignored)."""
    if shutil.which("git") is None or not (ROOT / ".git").exists():
        pytest.skip("not a git checkout: the package is built from the files git knows")
    out = subprocess.run(["git", "ls-files", "--cached", "--others", "--exclude-standard", "-z"],
                         cwd=ROOT, capture_output=True, check=True).stdout.decode()
    return [name for name in out.split("\0") if name and (ROOT / name).is_file()]


def _copy_source(target: Path) -> Path:
    for name in _source_files():
        (target / name).parent.mkdir(parents=True, exist_ok=True)
        try:
            shutil.copy2(ROOT / name, target / name)
        except FileNotFoundError:  # an untracked file another test removed meanwhile
            continue
    return target


def _dependencies_dir(target: Path) -> Path:
    """This environment's installed packages but gyro (and pip), as links in one folder.

    Put on a fresh environment's path, they stand in for what pip would download;
    leaving gyro out means the gyro that runs is the one installed from the package.
    """
    target.mkdir()
    for site in {sysconfig.get_paths()["purelib"], sysconfig.get_paths()["platlib"]}:
        for entry in Path(site).iterdir():
            name = entry.name
            if name.startswith(("gyro_cli", "__editable__", "pip-")) or name == "pip" \
                    or entry.suffix == ".pth" or (target / name).exists():
                continue
            (target / entry.name).symlink_to(entry)
    assert not (target / "gyro_cli").exists()
    return target


def _run(args: list[Any], **kwargs: Any) -> subprocess.CompletedProcess[str]:
    return subprocess.run([str(a) for a in args], check=False, capture_output=True, text=True, timeout=600,
                          **kwargs)


def _clean_env(**extra: str) -> dict[str, str]:
    """The environment without this checkout on the path."""
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONHOME", "VIRTUAL_ENV")}
    env.update(extra)
    return env


# ---- item 2: the documentation site ---------------------------------------------------

def _build_site(config: Path, site: Path) -> subprocess.CompletedProcess[str]:
    return _run([sys.executable, "-m", "mkdocs", "build", "--strict", "--config-file", config,
                 "--site-dir", site], cwd=config.parent)


@pytest.mark.slow
def test_item2_docs_site_builds_strict_offline_with_api_reference(tmp_path: Path) -> None:
    _need_module("mkdocs")
    _need_module("mkdocstrings_handlers.python")
    built = _build_site(ROOT / "mkdocs.yml", tmp_path / "site")
    assert built.returncode == 0, built.stderr
    assert "WARNING" not in built.stderr, built.stderr
    site = tmp_path / "site"
    # every page of docs/ is in the site, the example pages and the notebook beside them
    for page in (ROOT / "docs").glob("*.md"):
        assert (site / page.with_suffix(".html").name).is_file(), page.name
    for example in ("examples/11_3.html", "examples/11_2_released_top.html", "examples/gyro.ipynb"):
        assert (site / example).read_bytes() == (ROOT / "docs" / example).read_bytes()
    home = (site / "index.html").read_text()
    for link in ("examples/11_3.html", "examples/gyro.ipynb", "reference.html", "ci.html", "api.html"):
        assert f'href="{link}"' in home, link
    # the API reference is generated from the docstrings of gyro_cli.api
    reference = (site / "reference.html").read_text()
    for name in ("solve", "check", "sweep", "kinds", "Result", "Answer"):
        assert f'id="gyro_cli.api.{name}"' in reference, name
    assert "InputError" in reference and "YAML text" in reference
    # offline: no script, stylesheet, font or import fetched from another site
    remote = re.compile(r"""<(?:script|img|iframe)[^>]*\ssrc=["']?(?:https?:)?//|<link[^>]*\shref=["']?(?:https?:)?//"""
                        r"""|url\(\s*["']?(?:https?:)?//|@import\s+(?:url\()?["']?(?:https?:)?//""", re.IGNORECASE)
    for path in site.rglob("*"):
        if path.suffix in (".html", ".css", ".js") and "examples" not in path.parts:
            found = remote.search(path.read_text(errors="replace"))
            assert found is None, (path.relative_to(site), found and found.group(0))


@pytest.mark.slow
def test_item2_broken_link_or_anchor_fails_the_build(tmp_path: Path) -> None:
    _need_module("mkdocs")
    shutil.copytree(ROOT / "docs", tmp_path / "docs")
    config = yaml.safe_load((ROOT / "mkdocs.yml").read_text())
    config["plugins"] = ["search"]  # the same rules without the API reference (faster)
    (tmp_path / "mkdocs.yml").write_text(yaml.safe_dump(config))
    ci = tmp_path / "docs" / "ci.md"
    ci.write_text(ci.read_text() + "\nSee [the shards](check.md#no-such-heading) and [the README](../README.md).\n")
    (tmp_path / "docs" / "orphan.md").write_text("# A page in no nav\n")
    built = _build_site(tmp_path / "mkdocs.yml", tmp_path / "site")
    assert built.returncode != 0, built.stderr
    assert built.stderr.count("WARNING") == 3, built.stderr
    for named in ("no-such-heading", "../README.md", "orphan.md"):
        assert named in built.stderr, (named, built.stderr)


def test_item2_make_docs_target() -> None:
    makefile = (ROOT / "Makefile").read_text()
    assert re.search(r"^docs: \$\(STAMP\)\n\t\$\(BIN\)/mkdocs build --strict", makefile, re.MULTILINE)
    assert "make docs" in makefile.split("PYTHON ?=")[0]  # the header says what it does
    extras = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]["optional-dependencies"]
    for extra in ("docs", "dev"):
        assert any(d.startswith("mkdocs>=") for d in extras[extra])
        assert any(d.startswith("mkdocstrings[python]") for d in extras[extra])


# ---- item 3: a package that installs alone --------------------------------------------

@pytest.mark.slow
def test_item3_sdist_and_wheel_build_pass_twine_and_install_alone(tmp_path: Path) -> None:
    _need_module("build")
    _need_module("twine")
    source = _copy_source(tmp_path / "src")
    dist = tmp_path / "dist"
    built = _run([sys.executable, "-m", "build", "--no-isolation", "--outdir", dist, source],
                 env=_clean_env())
    assert built.returncode == 0, built.stdout[-3000:] + built.stderr[-3000:]
    version = gyro_cli.__version__
    wheel = dist / f"gyro_cli-{version}-py3-none-any.whl"
    assert wheel.is_file() and (dist / f"gyro_cli-{version}.tar.gz").is_file(), sorted(dist.iterdir())
    twine = _run([sys.executable, "-m", "twine", "check", "--strict", *sorted(dist.iterdir())])
    assert twine.returncode == 0, twine.stdout + twine.stderr

    with tarfile.open(dist / f"gyro_cli-{version}.tar.gz") as sdist:
        names = set(sdist.getnames())
    for name in ("CHANGELOG.md", "README.md", "problems/11_3.yaml", "gyro_cli/py.typed"):
        assert f"gyro_cli-{version}/{name}" in names, name
    # every file of the package the code may read at run time is in the wheel
    packaged = set(zipfile.ZipFile(wheel).namelist())
    package_files = {n for n in _source_files() if n.startswith("gyro_cli/")}
    assert package_files - packaged == set()

    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", "--without-pip", venv], check=True)
    python = venv / "bin" / "python"
    install = _run([sys.executable, "-m", "pip", "--python", python, "install", "--no-index",
                    "--no-deps", "--no-cache-dir", wheel], env=_clean_env())
    assert install.returncode == 0, install.stderr
    site = _run([python, "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"]).stdout.strip()
    (Path(site) / "gyro_deps.pth").write_text(f"{_dependencies_dir(tmp_path / 'deps')}\n")

    work = tmp_path / "work"
    work.mkdir()
    shutil.copy(PROBLEM, work / "11_3.yaml")
    env = _clean_env(GYRO_CACHE_DIR=str(tmp_path / "cache"))
    gyro = venv / "bin" / "gyro"

    def run(*args: str) -> str:
        done = _run([gyro, *args], cwd=work, env=env)
        assert done.returncode == 0, (args, done.stderr)
        return done.stdout

    assert run("--version").strip() == f"gyro, version {version}"
    assert "533.5 rpm" in run("solve", "11_3.yaml")
    # The other commands in one process of the virtual environment's Python (the console
    # script is the same `main`; a process each cost 0.3 s): each command's exit code and
    # output, with the package's own data files, from the wheel alone.
    commands = [["solve", "--format", "html", "11_3.yaml"],
                ["solve", "--format", "latex", "--standalone", "11_3.yaml"],
                ["check", "11_3.yaml"], ["kinds"], ["schema"], ["new", "steady_precession"],
                # the course layer: variants, a question bank, a report page
                ["vary", "11_3.yaml", "--count", "2", "--seed", "1", "-o", "variants"],
                ["export", "--to", "qti", "11_3.yaml", "-o", "bank.zip"],
                ["check", "11_3.yaml", "--html", "report.html"]]
    script = ("import json, sys, gyro_cli\nfrom click.testing import CliRunner\n"
              "from gyro_cli.cli import main\nruns = [CliRunner().invoke(main, a) for a in "
              "json.loads(sys.argv[1])]\nprint(json.dumps([gyro_cli.__file__] + "
              "[[r.exit_code, r.stdout, r.stderr] for r in runs]))")
    done = _run([python, "-c", script, json.dumps(commands)], cwd=work, env=env)
    assert done.returncode == 0, done.stderr
    where, *outputs = json.loads(done.stdout)
    assert where.startswith(str(venv)), where
    for args, (code, _, errors) in zip(commands, outputs, strict=True):
        assert code == 0, (args, errors)
    html, latex, check, kinds, schema, new = (text for _, text, _ in outputs[:6])
    assert "<math" in html and "\\begin" in latex and "OK: 3 answers" in check
    assert "steady_precession" in kinds and '"$schema"' in schema
    assert "kind: steady_precession" in new
    assert sorted(p.name for p in (work / "variants").iterdir()) == ["11_3-v01.yaml", "11_3-v02.yaml"]
    assert zipfile.ZipFile(work / "bank.zip").namelist()
    assert (work / "report.html").read_text().startswith("<!DOCTYPE html>")
    assert (Path(where).parent / "py.typed").is_file()


def test_item3_version_from_one_place_and_changelog() -> None:
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())
    assert "version" not in project["project"] and "version" in project["project"]["dynamic"]
    assert project["tool"]["setuptools"]["dynamic"]["version"] == {"attr": "gyro_cli.__version__"}
    version = gyro_cli.__version__
    assert tuple(int(p) for p in version.split(".")) > (0, 1, 0)
    printed = _run([sys.executable, "-m", "gyro_cli", "--version"], env=_clean_env(PYTHONPATH=str(ROOT)))
    assert printed.stdout.strip() == f"gyro, version {version}"

    changelog = (ROOT / "CHANGELOG.md").read_text()
    assert changelog.startswith("# Changelog\n") and "keepachangelog.com" in changelog
    headings = re.findall(r"^## \[(\d+\.\d+\.\d+)\] - (\d{4}-\d\d-\d\d|Unreleased)$", changelog, re.MULTILINE)
    assert headings and headings[0][0] == version, headings
    versions = [tuple(int(p) for p in v.split(".")) for v, _ in headings]
    assert versions == sorted(versions, reverse=True) and len(set(versions)) == len(versions)
    for section in re.split(r"^## ", changelog, flags=re.MULTILINE)[1:]:
        assert re.search(r"^### (Added|Changed|Fixed|Removed|Deprecated|Security)$", section, re.MULTILINE), section[:80]


@pytest.mark.slow  # fresh interpreters: `make test-slow`
def test_item3_version_costs_no_metadata_import(tmp_path: Path) -> None:
    """gyro --version, and a solve with the unit table warm, take the version from
    gyro_cli/__init__.py, without importlib.metadata (a few ms of every start-up)."""
    env = _clean_env(PYTHONPATH=str(ROOT), GYRO_CACHE_DIR=str(tmp_path))
    assert _run([sys.executable, "-m", "gyro_cli", "solve", PROBLEM], env=env).returncode == 0
    for args in (["--version"], ["solve", PROBLEM]):
        done = _run([sys.executable, "-X", "importtime", "-m", "gyro_cli", *args], env=env)
        assert done.returncode == 0, done.stderr
        assert "importlib.metadata" not in done.stderr, args


# ---- item 4: hooks for course repositories --------------------------------------------

def _git(repo: Path, *args: str) -> None:
    subprocess.run(["git", "-c", "user.name=gyro test", "-c", "user.email=gyro@example.invalid",
                    "-c", "commit.gpgsign=false", *args], cwd=repo, check=True, capture_output=True)


def _wrong_key(text: str) -> str:
    wrong = text.replace("min_spin: 965.4 rpm", "min_spin: 1100 rpm")
    assert wrong != text
    return wrong


def _course_repo(path: Path) -> Path:
    """A course repository: a right and a wrong answer key, and a workflow (not a problem)."""
    (path / "problems").mkdir(parents=True)
    (path / "problems" / "right.yaml").write_text(PROBLEM.read_text())
    (path / "problems" / "wrong.yaml").write_text(_wrong_key(PROBLEM.read_text()))
    (path / ".github" / "workflows").mkdir(parents=True)
    (path / ".github" / "workflows" / "ci.yml").write_text("name: ci\non: push\njobs: {}\n")
    _git(path, "init", "-q")
    _git(path, "add", "-A")
    _git(path, "commit", "-q", "-m", "problems")
    return path


@pytest.mark.slow
def test_item4_pre_commit_hook_passes_right_key_and_fails_wrong(tmp_path: Path) -> None:
    _need_module("pre_commit")
    hooks = yaml.safe_load((ROOT / ".pre-commit-hooks.yaml").read_text())
    hook = next(h for h in hooks if h["id"] == "gyro-check")
    assert hook["entry"].split()[:2] == ["gyro", "check"] and hook["language"] == "python"
    assert re.search(hook["files"], "problems/11_3.yml") and hook.get("pass_filenames", True)

    gyro_repo = _copy_source(tmp_path / "gyro")
    _git(gyro_repo, "init", "-q")
    _git(gyro_repo, "add", "-A")
    _git(gyro_repo, "commit", "-q", "-m", "gyro")
    course = _course_repo(tmp_path / "course")
    # pre-commit pip-installs gyro into the hook's environment; its dependencies come from here
    env = _clean_env(PRE_COMMIT_HOME=str(tmp_path / "pre-commit"), PIP_NO_INDEX="1", PIP_NO_DEPS="1",
                     PIP_NO_BUILD_ISOLATION="0",  # pip reads this "no" option inverted: no isolation
                     VIRTUALENV_NO_PERIODIC_UPDATE="1",
                     VIRTUALENV_OVERRIDE_APP_DATA=str(tmp_path / "virtualenv"),
                     PYTHONPATH=str(_dependencies_dir(tmp_path / "deps")),
                     GYRO_CACHE_DIR=str(tmp_path / "cache"))

    # The course repository names the hook as course repositories do (repo and rev in its
    # .pre-commit-config.yaml): the hook's environment is made once, for both runs (try-repo
    # would make it again for each, 6 s).
    rev = subprocess.run(["git", "rev-parse", "HEAD"], cwd=gyro_repo, check=True,
                         capture_output=True, text=True).stdout.strip()
    (course / ".pre-commit-config.yaml").write_text(
        f"repos:\n  - repo: {gyro_repo}\n    rev: {rev}\n    hooks:\n      - id: gyro-check\n")
    _git(course, "add", ".pre-commit-config.yaml")

    def hook(*files: str) -> subprocess.CompletedProcess[str]:
        return _run([sys.executable, "-m", "pre_commit", "run", "gyro-check", "--files", *files],
                    cwd=course, env=env)

    right = hook("problems/right.yaml", ".github/workflows/ci.yml")
    assert right.returncode == 0, right.stdout + right.stderr
    assert re.search(r"gyro check \(answer keys\)\.+Passed", right.stdout), right.stdout
    wrong = hook("problems/wrong.yaml", "problems/right.yaml")
    assert wrong.returncode == 1, wrong.stdout + wrong.stderr
    assert re.search(r"FAIL\s+min_spin", wrong.stdout) and "exit code: 1" in wrong.stdout, wrong.stdout


def _interpolate(value: str, inputs: dict[str, str]) -> str:
    """A GitHub expression of the two kinds the action may use: inputs.NAME, github.action_path."""
    def one(match: re.Match[str]) -> str:
        expression = match.group(1).strip()
        if expression == "github.action_path":
            return str(ROOT)
        assert expression.startswith("inputs."), f"action.yml: unexpected expression {expression}"
        return inputs[expression.removeprefix("inputs.")]
    return re.sub(r"\$\{\{(.*?)\}\}", one, str(value))


def _gyro_shim(folder: Path) -> str:
    """A `gyro` on PATH that is this checkout's, so the action's steps run here as on a runner."""
    folder.mkdir()
    shim = folder / "gyro"
    shim.write_text(f'#!/bin/sh\nPYTHONPATH="{ROOT}" exec "{sys.executable}" -m gyro_cli "$@"\n')
    shim.chmod(shim.stat().st_mode | stat.S_IEXEC)
    return f"{folder}{os.pathsep}{Path(sys.executable).parent}{os.pathsep}{os.environ.get('PATH', '')}"


def _run_action(action: dict[str, Any], given: dict[str, str], work: Path, path: str,
                ) -> tuple[int, str, str]:
    """Run the action's steps after the installation, as a runner would; exit, summary, outputs."""
    inputs = {name: given.get(name, spec.get("default", "")) for name, spec in action["inputs"].items()}
    summary, outputs = work / "summary.md", work / "outputs.txt"
    summary.write_text("")
    outputs.write_text("")
    for step in action["runs"]["steps"]:
        if "uses" in step or "pip install" in step["run"]:
            continue
        env = _clean_env(PATH=path, GITHUB_ACTION_PATH=str(ROOT), GITHUB_STEP_SUMMARY=str(summary),
                         GITHUB_OUTPUT=str(outputs), GYRO_CACHE_DIR=str(work / "cache"))
        env.update({k: _interpolate(v, inputs) for k, v in step.get("env", {}).items()})
        assert step["shell"] == "bash"
        done = _run(["bash", "--noprofile", "--norc", "-eo", "pipefail", "-c", _interpolate(step["run"], inputs)],
                    cwd=work, env=env)
        if done.returncode:
            return done.returncode, summary.read_text(), outputs.read_text()
    return 0, summary.read_text(), outputs.read_text()


@pytest.mark.slow
def test_item4_github_action_is_composite_and_writes_junit_and_summary(tmp_path: Path) -> None:
    action = yaml.safe_load((ROOT / "action.yml").read_text())
    assert action["runs"]["using"] == "composite"
    steps = action["runs"]["steps"]
    assert all("shell" in step for step in steps if "run" in step)
    setup = next(step for step in steps if step.get("uses", "").startswith("actions/setup-python@"))
    assert setup["with"]["python-version"] == "${{ inputs.python-version }}"
    assert any("pip install" in step.get("run", "") and "GITHUB_ACTION_PATH" in step["run"] for step in steps)
    assert set(action["inputs"]) >= {"python-version", "paths", "shard", "junit"}
    for step in steps:  # inputs reach a script through env, never pasted into the shell text
        assert "${{" not in step.get("run", ""), step["name"]

    work = tmp_path / "course"
    (work / "problems").mkdir(parents=True)
    (work / "problems" / "right.yaml").write_text(PROBLEM.read_text())
    (work / "problems" / "wrong.yaml").write_text(_wrong_key(PROBLEM.read_text()))
    path = _gyro_shim(tmp_path / "bin")

    status, summary, outputs = _run_action(action, {"paths": "problems/"}, work, path)
    assert status == 1 and "exit-code=1" in outputs
    assert "| problems/wrong.yaml | 3 | 2 | 1 | 0 |" in summary, summary
    assert "| problems/right.yaml | 3 | 3 | 0 | 0 |" in summary, summary
    assert re.search(r"\| problems/wrong.yaml \| 11/3 min_spin \| expected 1100 rpm", summary), summary
    junit = (work / "gyro-check.xml").read_text()
    assert junit.count("<failure") == 1

    # a matrix of two shards checks each file exactly once between them
    seen: list[str] = []
    for shard in ("1/2", "2/2"):
        status, summary, _ = _run_action(action, {"shard": shard, "junit": f"s{shard[0]}.xml",
                                                  "paths": "problems/*.yaml"}, work, path)
        assert f"shard {shard}" in summary
        seen += re.findall(r'<testsuite name="([^"]+)"', (work / f"s{shard[0]}.xml").read_text())
    assert sorted(seen) == ["problems/right.yaml", "problems/wrong.yaml"]


def _load_summary_module() -> ModuleType:
    spec = importlib.util.spec_from_file_location("junit_summary", ROOT / "ci" / "junit_summary.py")
    assert spec and spec.loader
    module = importlib.util.module_from_spec(spec)
    sys.modules.setdefault(spec.name, module)  # dataclasses look their module up there
    spec.loader.exec_module(module)
    return module


def test_item4_job_summary_escapes_what_files_hold() -> None:
    summary = _load_summary_module()
    result = summary.FileResult("a|b<script>.yaml", answers=1, failed=1,
                                failures=[("x", "got `1`\n| injected | row |")])
    text = summary.summary([result], "gyro check")
    row = next(line for line in text.splitlines() if line.startswith("| a"))
    assert row.startswith("| a\\|b&lt;script&gt;.yaml |")
    failure = text.splitlines()[-1]
    assert "\n" not in failure and failure.count(" | ") == 2 and "&#96;1&#96;" in failure


@pytest.mark.slow
def test_item4_gitlab_template_reports_junit_and_shards(tmp_path: Path) -> None:
    template = yaml.safe_load((ROOT / "ci" / "gyro-check.gitlab-ci.yml").read_text())
    job = template["gyro-check"]
    base = template[job["extends"]]
    assert base["artifacts"]["reports"]["junit"] == "gyro-check.xml"
    assert base["artifacts"]["when"] == "always"
    script = base["script"]
    check = next(line for line in script if "gyro check" in line)
    assert "--junit gyro-check.xml" in check

    # without GYRO_PIP the job says what to set, before any install
    work = tmp_path / "course"
    (work / "problems").mkdir(parents=True)
    (work / "problems" / "right.yaml").write_text(PROBLEM.read_text())
    (work / "problems" / "wrong.yaml").write_text(_wrong_key(PROBLEM.read_text()))
    env = _clean_env(PATH=_gyro_shim(tmp_path / "bin"), GYRO_CACHE_DIR=str(tmp_path / "cache"),
                     **{k: str(v) for k, v in base["variables"].items()})
    unset = _run(["sh", "-ec", script[0]], cwd=work, env=env)
    assert unset.returncode == 2 and "set GYRO_PIP" in unset.stderr

    # a job of `parallel: 2` checks its shard, and the report is where artifacts look
    seen: list[str] = []
    for index in ("1", "2"):
        done = _run(["sh", "-ec", check], cwd=work, env={**env, "CI_NODE_INDEX": index, "CI_NODE_TOTAL": "2"})
        assert done.returncode in (0, 1), done.stderr
        seen += re.findall(r'<testsuite name="([^"]+)"', (work / "gyro-check.xml").read_text())
    assert sorted(seen) == ["problems/right.yaml", "problems/wrong.yaml"]
    done = _run(["sh", "-ec", check], cwd=work, env=env)
    assert done.returncode == 1 and "FAIL" in done.stdout and "2 problems" in done.stdout
