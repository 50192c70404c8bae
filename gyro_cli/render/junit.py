"""JUnit XML for `gyro check --junit FILE`: what CI servers show as test results.

The common shape that Jenkins, GitLab, GitHub test reporters and Azure read:
``<testsuites>`` holding a ``<testsuite>`` per problem file, a ``<testcase>``
per compared answer, ``<failure message="expected X +- tol, got Y">`` for a
miss, ``<error>`` for a bad file and ``<skipped>`` for a problem without
expected answers. Built with ElementTree, so every attribute is escaped.
"""

from __future__ import annotations

import os
import xml.etree.ElementTree as ET

from ..checking.results import CheckRun, ProblemCheck

# Characters XML 1.0 forbids even escaped; a file name or message could hold them.
_FORBIDDEN = {c: None for c in range(32) if c not in (9, 10, 13)}


def _clean(text: str) -> str:
    return text.translate(_FORBIDDEN)


def _classname(problem: ProblemCheck) -> str:
    """Dotted like a class name (CI servers group by the dots): problems/11_3.yaml -> problems.11_3."""
    stem = os.path.splitext(os.path.normpath(problem.file))[0]
    parts = [p for p in stem.replace("\\", "/").split("/") if p not in ("", ".", "..")]
    return _clean(".".join(p.replace(".", "_") for p in parts) or "gyro")


def suite(problem: ProblemCheck) -> ET.Element:
    """One testsuite: the answers of one problem file."""
    node = ET.Element("testsuite", name=_clean(problem.file))
    classname = _classname(problem)
    failures = errors = skipped = 0
    if problem.status == "error":
        case = ET.SubElement(node, "testcase", classname=classname, name="load and solve",
                             time="0")
        ET.SubElement(case, "error", message=_clean(problem.error or "bad file"),
                      type="InternalError" if problem.internal else "InputError").text = _clean(problem.error or "")
        errors = 1
    elif problem.status == "no expected answers":
        case = ET.SubElement(node, "testcase", classname=classname,
                             name=_clean(f"{problem.id} (no expected answers)"), time="0")
        ET.SubElement(case, "skipped", message="no expected answers")
        skipped = 1
    for answer in problem.answers:
        case = ET.SubElement(node, "testcase", classname=classname,
                             name=_clean(f"{problem.id} {answer.label}"), time="0")
        if not answer.passed:
            failures += 1
            message = answer.message.split("; ")[0]  # "expected X +- tol, got Y"
            detail = answer.message + (f"\nlikely slip: {answer.slip}" if answer.slip else "")
            ET.SubElement(case, "failure", message=_clean(message),
                          type="AnswerMismatch").text = _clean(detail)
    node.set("tests", str(len(node)))
    node.set("failures", str(failures))
    node.set("errors", str(errors))
    node.set("skipped", str(skipped))
    node.set("time", "0")
    return node


def xml(run: CheckRun) -> str:
    """The whole report as an XML document (UTF-8 declaration included)."""
    root = ET.Element("testsuites", name="gyro check")
    totals = dict(tests=0, failures=0, errors=0, skipped=0)
    for problem in run.problems:
        node = suite(problem)
        root.append(node)
        for key in totals:
            totals[key] += int(node.get(key))
    for key, value in totals.items():
        root.set(key, str(value))
    root.set("time", "0")
    ET.indent(root)
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + ET.tostring(root, encoding="unicode") \
        + "\n"
