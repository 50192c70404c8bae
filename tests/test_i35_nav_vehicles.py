"""Issue 35, round four: navigation gyros on the rotating Earth (item 3), four-wheelers
as the books draw them (item 4), and `gyro new` statements that read as sentences
(item 9).

Every number is worked by hand here from the books' own formulas, or checked by an
independent law (the wheel loads add up to the weight, their moments balance the
couples), never by calling gyro's formula again.
"""

from __future__ import annotations

import re

import pytest
import yaml

from gyro_cli import kinds
from gyro_cli.commands import authoring
from gyro_cli.solving.problem import load


# ---- item 9: every template's statement reads as a sentence -------------------------

PLACEHOLDER = re.compile(r"\{([A-Za-z_][A-Za-z0-9_]*)\}")


def _fill(statement: str, given: dict) -> str:
    """The statement with each {key} replaced by the given value as written (our own
    filling, not gyro's)."""
    return PLACEHOLDER.sub(lambda m: " ".join(str(given[m.group(1)]).split())
                           if m.group(1) in given else m.group(0), statement)


def sentence_faults(text: str) -> list[str]:
    """What keeps ``text`` from reading as sentences: each fault found, in words."""
    faults = []
    if "{" in text or "}" in text:
        faults.append("an unfilled brace")
    if not re.match(r"[A-Z]", text):
        faults.append("does not start with a capital letter")
    if not re.search(r"[.?]$", text):
        faults.append("does not end with a full stop")
    op = r"[/*^=+<>-]"
    if re.search(rf"(^|\s){op}\s*([,.;:)]|$)", text):
        faults.append("an operator dangling before punctuation or the end")
    if re.search(rf"[(,;:]\s*{op}(\s|$)", text):
        faults.append("an operator dangling after punctuation")
    if re.search(rf"(^|\s){op}\s+{op}(\s|$)", text) or re.search(r"\^\d*\s*/", text):
        faults.append("two operators in a row")
    if text.count("(") != text.count(")") or "()" in text:
        faults.append("unbalanced or empty brackets")
    if re.search(r"\s[,.;:]|[,;:]{2}|\.\.|\s{2}", text):
        faults.append("stray punctuation or spacing")
    if re.search(r"\b[A-Za-z]+_[A-Za-z0-9_]*\b", text):
        faults.append("a key name (snake_case) in the prose")
    if re.search(r"\b(\w+) \1\b", text, re.I):
        faults.append("a doubled word")
    for piece in re.split(r"(?<=[.?])\s+", text):
        if piece and not re.match(r"[A-Z]", piece):
            faults.append(f"a sentence that starts in lower case: {piece[:30]!r}")
    return faults


def test_item09_sentence_check_catches_the_old_garbled_statements():
    """The check itself: the statements gyro new printed before the fix are faulted."""
    old_four = ("Given: total mass of the vehicle 2500 kg. Find [outer, inner]: vertical "
                "reaction on each outer and each inner wheel,  v^2 /, positive overturning "
                "outward, m v^2 h / R.")
    old_drift = "Given: rotor spin 24000 rpm. Find drift rate of the spin axis, H / sqrt, c /)."
    assert sentence_faults(old_four) and sentence_faults(old_drift)
    assert sentence_faults("Given the mass {mass}. Find the couple.")
    assert sentence_faults("Find the rotor_sense.")
    assert not sentence_faults("A top spins at 1800 rpm with its axis at 30 deg. Find the "
                               "rate of steady precession (slow root).")


@pytest.mark.parametrize("name", kinds.names())
def test_item09_every_gyro_new_statement_reads_as_a_sentence(run, tmp_path, name):
    out = tmp_path / f"{name}.yaml"
    assert run("new", name, "-o", out).exit_code == 0
    data = yaml.safe_load(out.read_text())
    filled = _fill(" ".join(data["statement"].split()), data["given"])
    assert sentence_faults(filled) == [], filled
    assert load(str(out)).statement_text() == filled  # gyro fills it the same way
    # the statement states the data: every given quantity (a value with a number)
    written = set(PLACEHOLDER.findall(data["statement"]))
    quantities = {k for k, v in data["given"].items() if re.match(r"\s*[-+]?[\d.]", str(v))}
    assert quantities <= written, (name, quantities - written)


@pytest.mark.parametrize("name", kinds.names())
def test_item09_a_kind_without_its_own_statement_still_gets_sentences(monkeypatch, name):
    """A new kind whose example carries no statement: the template's sentence is made
    from the keys' descriptions and still reads as one."""
    example = dict(kinds.get(name).extra.get("example") or {})
    example.pop("statement", None)
    monkeypatch.setitem(kinds.get(name).extra, "example", example)
    text = authoring.template(name)
    data = yaml.safe_load(text)
    filled = _fill(" ".join(data["statement"].split()), data["given"])
    assert sentence_faults(filled) == [], filled
