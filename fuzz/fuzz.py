"""Long fuzz run: mutate the bundled problems for N minutes and hold gyro to its promise.

    python fuzz/fuzz.py --minutes 30 [--seed 1] [--out fuzz/out] [--timeout 10]
    make fuzz MINUTES=30

Every input is a bundled problem (problems/*.yaml) mutated by fuzz/mutate.py,
written to a temporary file and run in this process (click's CliRunner, one
pint registry) through ``gyro solve`` in one of the four formats (cycling) and
``gyro check``, each under a per-input timeout (SIGALRM). The promise:

- exit 0 with finite numbers (no nan or inf in the output);
- exit 1 (check: an answer does not match), again with finite numbers;
- exit 2 with exactly one line on stderr, ``gyro: FILE...``, naming the file;

never a traceback, never a hang. Outcomes are counted by class; the first
examples of each class that breaks the promise are saved under OUT/cases/ with
what was done to the file, and OUT/summary.json and OUT/summary.txt hold the
figures.
"""

from __future__ import annotations

import argparse
import json
import os
import random
import re
import signal
import sys
import tempfile
import time
from collections import Counter
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(ROOT))

NOT_FINITE = re.compile(r"(?<![\w.\\])[-+]?(?:nan|inf)(?![\w])", re.I)
QUOTED = re.compile(r"'[^'\n]*'|\"[^\"\n]*\"")  # the user's own text, quoted in a message


def not_finite(text: str) -> bool:
    """A nan or inf that gyro printed (not one quoted from the input)."""
    return bool(NOT_FINITE.search(QUOTED.sub("''", text)))
GOOD = ("exit 0", "exit 1", "exit 2 one line")
BROKEN = ("internal error (exit 3)", "traceback", "hang", "nan/inf printed",
          "exit 2 not one line", "exit 2 unlocated", "output on error", "other exit code")


class Hang(BaseException):
    """Raised by the alarm; a BaseException so no `except Exception` in gyro swallows it."""


def _alarm(signum, frame):  # noqa: ARG001
    raise Hang()


def _clear_click_stream_caches() -> None:
    """click caches a text wrapper per stream in a WeakKeyDictionary whose values hold
    their keys, so every CliRunner run keeps its captured output alive (about 7 kB a
    file, 2 GB over a long run). A harness matter, not gyro's: clear it now and then."""
    import weakref

    from click import _compat

    for func in (_compat._default_text_stdout, _compat._default_text_stderr,
                 _compat._default_text_stdin):
        for cell in getattr(func, "__closure__", None) or ():
            if isinstance(cell.cell_contents, weakref.WeakKeyDictionary):
                cell.cell_contents.clear()


def classify(result, path: str, command: str, text: str = "") -> str:
    """The outcome class of one CliRunner result (``text``: the input file)."""
    echoed = bool(NOT_FINITE.search(text))  # a note saying "inf" may be printed back
    if result.exception is not None and not isinstance(result.exception, SystemExit):
        return "traceback"
    code = result.exit_code
    out, err = result.stdout, result.stderr
    if code == 3:
        return "internal error (exit 3)"
    if code in (0, 1):
        if code == 1 and command != "check":
            return "other exit code"
        if (not_finite(out) or not_finite(err)) and not echoed:
            return "nan/inf printed"
        return f"exit {code}"
    if code == 2:
        lines = err.splitlines()
        if len(lines) != 1 or not lines[0].startswith("gyro: ") or "Traceback" in err:
            return "exit 2 not one line"
        if os.path.basename(path) not in lines[0]:
            return "exit 2 unlocated"
        if command == "solve" and out.strip():
            return "output on error"
        if not_finite(out) and not echoed:
            return "nan/inf printed"
        return "exit 2 one line"
    return "other exit code"


def run(minutes: float, seed: int, out_dir: Path, timeout: float, keep: int = 5) -> dict:
    import yaml
    from click.testing import CliRunner
    from mutate import mutant

    from gyro_cli.cli import main

    os.environ["GYRO_DEBUG"] = "1"  # internal errors come with their traceback
    bases = []
    for path in sorted((ROOT / "problems").glob("*.yaml")):
        bases.append((path.name, yaml.safe_load(path.read_text())))
    rng = random.Random(seed)
    runner = CliRunner()
    counts: Counter[str] = Counter()
    by_command: dict[str, Counter[str]] = {"solve": Counter(), "check": Counter()}
    examples: dict[str, list[dict]] = {}
    (out_dir / "cases").mkdir(parents=True, exist_ok=True)
    signal.signal(signal.SIGALRM, _alarm)
    formats = ("text", "json", "markdown", "latex")
    start = time.monotonic()
    deadline = start + minutes * 60
    files = slowest = 0
    slowest_case = ""
    with tempfile.TemporaryDirectory(prefix="gyro-fuzz-") as tmp:
        while time.monotonic() < deadline:
            name, base = rng.choice(bases)
            text, what = mutant(rng, base)
            path = os.path.join(tmp, f"m{files % 100}.yaml")
            with open(path, "w", encoding="utf-8", errors="surrogatepass") as handle:
                handle.write(text)
            files += 1
            if files % 1000 == 0:
                _clear_click_stream_caches()
            fmt = formats[files % 4]
            for command, args in (("solve", ["solve", "--format", fmt, path]),
                                  ("check", ["check", path])):
                began = time.monotonic()
                signal.setitimer(signal.ITIMER_REAL, timeout)
                try:
                    result = runner.invoke(main, args)
                    outcome = classify(result, path, command, text)
                except Hang:
                    result, outcome = None, "hang"
                finally:
                    signal.setitimer(signal.ITIMER_REAL, 0)
                took = time.monotonic() - began
                if took > slowest:
                    slowest, slowest_case = took, f"{name}: {what}"
                counts[outcome] += 1
                by_command[command][outcome] += 1
                if outcome in BROKEN and len(examples.setdefault(outcome, [])) < keep:
                    slug = re.sub(r"\W+", "_", outcome).strip("_")
                    case = out_dir / "cases" / f"{slug}-{sum(counts[o] for o in BROKEN)}.yaml"
                    case.write_text(text, encoding="utf-8", errors="surrogatepass")
                    examples[outcome].append({
                        "base": name, "mutation": what, "command": " ".join(args[:-1]),
                        "file": str(case),
                        "stderr": (result.stderr if result else "")[-2000:],
                        "exception": repr(result.exception) if result and result.exception
                        and not isinstance(result.exception, SystemExit) else None})
    elapsed = time.monotonic() - start
    summary = {
        "seed": seed, "minutes": round(elapsed / 60, 2), "files_tried": files,
        "runs": sum(counts.values()), "per_input_timeout_s": timeout,
        "outcomes": dict(counts.most_common()),
        "by_command": {c: dict(v.most_common()) for c, v in by_command.items()},
        "tracebacks": counts["traceback"] + counts["internal error (exit 3)"],
        "hangs": counts["hang"], "broken": sum(counts[o] for o in BROKEN),
        "slowest_run_s": round(slowest, 3), "slowest_case": slowest_case[:200],
        "max_rss_mb": round(_max_rss_mb(), 1),
        "examples": examples,
    }
    (out_dir / "summary.json").write_text(json.dumps(summary, indent=1))
    lines = [f"gyro fuzz: {files} files tried in {summary['minutes']} min (seed {seed}), "
             f"{summary['runs']} runs (solve in text/json/markdown/latex, and check), "
             f"timeout {timeout} s per run",
             f"tracebacks {summary['tracebacks']}, hangs {summary['hangs']}, "
             f"promise broken {summary['broken']}; slowest run {summary['slowest_run_s']} s; "
             f"peak memory {summary['max_rss_mb']} MB"]
    for outcome, count in counts.most_common():
        lines.append(f"  {outcome:<26}{count:>9}")
    (out_dir / "summary.txt").write_text("\n".join(lines) + "\n")
    return summary


def _max_rss_mb() -> float:
    try:
        import resource

        return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    except (ImportError, OSError):
        return 0.0


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--minutes", type=float, default=5.0)
    parser.add_argument("--seed", type=int, default=int(time.time()) % 100000)
    parser.add_argument("--out", type=Path, default=HERE / "out")
    parser.add_argument("--timeout", type=float, default=10.0, help="seconds per run")
    args = parser.parse_args()
    summary = run(args.minutes, args.seed, args.out, args.timeout)
    print((args.out / "summary.txt").read_text(), end="")
    for outcome, cases in summary["examples"].items():
        for case in cases[:2]:
            print(f"- {outcome}: {case['base']}: {case['mutation']} [{case['command']}] "
                  f"{case['file']}\n    {case['stderr'].strip().splitlines()[-1:] if case['stderr'] else case['exception']}")
    return 1 if summary["broken"] else 0


if __name__ == "__main__":
    sys.exit(main())
