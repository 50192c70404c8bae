"""Issue 36 item 6 (part): the solving side of the package type-checks with mypy."""

from __future__ import annotations

import importlib.util
import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
#: the layers made mypy-clean so far; core's expression trees and prose are not yet
CLEAN = re.compile(r"^gyro_cli/(checking|physics|solving|kinds|core)/")
NOT_YET = ("gyro_cli/core/expr.py", "gyro_cli/core/prose.py")


@pytest.mark.slow
@pytest.mark.skipif(importlib.util.find_spec("mypy") is None, reason="mypy is not installed")
def test_item06_mypy_clean_checking_physics_solving_kinds_core(tmp_path: Path) -> None:
    run = subprocess.run([sys.executable, "-m", "mypy", "--cache-dir", str(tmp_path), "gyro_cli"],
                         cwd=ROOT, capture_output=True, text=True, timeout=600)
    errors = [line for line in run.stdout.splitlines()
              if ": error:" in line and CLEAN.match(line.replace("\\", "/"))
              and not line.replace("\\", "/").startswith(NOT_YET)]
    assert re.search(r"^(Found \d+ errors?|Success:)", run.stdout, re.M), run.stdout + run.stderr
    assert errors == []
