"""A question bank as PrairieLearn questions: a directory per problem with
``info.json``, ``question.html`` and ``server.py``.

``info.json`` carries the keys PrairieLearn's question schema requires (uuid,
type, title, topic) and tags; the UUID is derived from the problem id, so a
second export of the same problem updates the question instead of adding one.
``question.html`` shows the statement, one ``pl-number-input`` per number asked
(its ``answers-name``, the variant's half-width as ``atol`` (a param), a
``label`` and the unit as ``suffix``) and the worked answer in the
answer panel. ``server.py`` holds the variants computed at export (the solver's
answers, so PrairieLearn needs no gyro) and its ``generate(data)`` picks one from
``data["variant_seed"]``, setting ``data["params"]`` and
``data["correct_answers"]``.

The statement and the worked answer reach the page as ``params`` (mustache's
triple braces insert them as they are, and nothing inside them is read as a
template); every text written into ``question.html`` itself is escaped, braces
included.
"""

from __future__ import annotations

import json
from collections.abc import Iterable, Iterator

from .bank import Blank, Choice, ProblemBank, Variant, html_text, number_text, stable_uuid, xml_attr

TOPIC = "Gyroscopic motion"


def info(bank: ProblemBank) -> dict:
    """The question's info.json."""
    return {"uuid": str(stable_uuid(bank.id)), "type": "v3", "title": bank.name,
            "topic": TOPIC, "tags": ["gyro", bank.kind],
            "singleVariant": bank.size == 1}


def _blanks(bank: ProblemBank) -> list[Blank]:
    """Every blank some variant asks, in order (a variant at theta = 90 deg has one
    precession root where the others have two)."""
    seen: dict[str, Blank] = {}
    for variant in bank.variants:
        for blank in variant.blanks:
            seen.setdefault(blank.key, blank)
    return list(seen.values())


def _input(blank: Blank) -> str:
    # The half-width is each variant's own (a relative tolerance widened to what rounding
    # to the figures asked can cost differs from variant to variant): a param.
    tolerance = f'comparison="relabs" rtol="0" atol="{{{{params.atol.{blank.key}}}}}"'
    # The half-width is no hint to give: pl-number-input prints it as the placeholder
    # ("number ±0.451344") and in its help popup, and with the statement's "within 1%" it
    # tells the answer (45.1344 rpm). The statement says what is accepted.
    tolerance += ' show-help-text="false" placeholder="number"'
    suffix = f' suffix="{_attr(blank.unit)}"' if blank.unit else ""
    return (f"{{{{#params.ask.{blank.key}}}}}\n"
            f'<pl-number-input answers-name="{blank.key}" {tolerance} '
            f'label="{_attr(blank.label)} =" size="20"{suffix}></pl-number-input>\n'
            f"{{{{/params.ask.{blank.key}}}}}")


def _choices(bank: ProblemBank) -> dict[str, tuple[str, tuple[str, ...]]]:
    """Every multiple choice some variant asks: key -> (label, the words of all variants)."""
    seen: dict[str, tuple[str, tuple[str, ...]]] = {}
    for variant in bank.variants:
        for choice in variant.choices:
            label, words = seen.get(choice.key, (choice.label, ()))
            seen[choice.key] = (label, tuple(dict.fromkeys([*words, *choice.choices])))
    return seen


def _multiple_choice(key: str, label: str, words: tuple[str, ...]) -> str:
    # Which word is right differs from variant to variant: a param ("true"/"false").
    answers = "".join(f'\n  <pl-answer correct="{{{{params.correct.{key}.c{n}}}}}">'
                      f"{html_text(word)}</pl-answer>" for n, word in enumerate(words, 1))
    return (f"{{{{#params.choose.{key}}}}}\n<p>{html_text(label)}:</p>\n"
            f'<pl-multiple-choice answers-name="{key}">{answers}\n</pl-multiple-choice>\n'
            f"{{{{/params.choose.{key}}}}}")


def _attr(text: str) -> str:
    return xml_attr(text).replace("{", "&#123;").replace("}", "&#125;")


def question_html(bank: ProblemBank) -> str:
    """The question's template: statement, inputs, worked answer."""
    inputs = "\n".join([*(_input(b) for b in _blanks(bank)),
                        *(_multiple_choice(key, label, words)
                          for key, (label, words) in _choices(bank).items())])
    return (f"<!-- {html_text(bank.name).replace('--', '- -')}: written by gyro export "
            "(the answers are gyro's) -->\n"
            "<pl-question-panel>\n{{{params.statement}}}\n</pl-question-panel>\n\n"
            f"{inputs}\n\n"
            "<pl-answer-panel>\n{{{params.feedback}}}\n{{#params.figure}}\n"
            '<pl-figure file-name="{{params.figure}}" directory="clientFilesQuestion" '
            'alt="{{params.figure_alt}}"></pl-figure>\n{{/params.figure}}\n'
            "</pl-answer-panel>\n")


SERVER = '''"""{doc}

Written by `gyro export --to prairielearn`: the variants and their answers were
computed by gyro's solver at export; generate() picks one from the variant seed.
"""

import json

VARIANTS = json.loads({variants})


def generate(data):
    variant = VARIANTS[int(data["variant_seed"]) % len(VARIANTS)]
    data["params"]["statement"] = variant["statement"]
    data["params"]["feedback"] = variant["feedback"]
    data["params"]["ask"] = {{key: True for key in variant["answers"]}}
    data["params"]["atol"] = variant["atol"]
    data["params"]["choose"] = {{key: True for key in variant["correct"]}}
    data["params"]["correct"] = variant["correct"]
    data["params"]["figure"] = variant["figure"]
    data["params"]["figure_alt"] = variant["figure_alt"]
    for key, value in variant["answers"].items():
        data["correct_answers"][key] = value
'''


# Errors carried forward across the inputs (a problem with `steps:`), standing alone: each
# variant holds, for each step input, the later inputs' values with that step carried at
# points of a grid (gyro's solver at export; checking/ecf.py `table`), and grade()
# interpolates at the student's own value. One wrong step is carried at a time.
GRADE = '''

def _place(raw, number):
    """Half a unit of the last digit written in the raw input ("1.95e-4": 5e-7), at most
    that of its third significant figure (a round 0.02 is no claim of one figure)."""
    import math
    import re

    match = re.match(r"\\s*[-+]?(\\d*)(?:\\.(\\d*))?(?:[eE]([-+]?\\d+))?", str(raw or ""))
    if not match or not (match.group(1) or match.group(2)) or not number:
        return 0.0
    third = 0.5 * 10.0 ** (math.floor(math.log10(abs(number))) - 2)
    return min(0.5 * 10.0 ** (int(match.group(3) or 0) - len(match.group(2) or "")), third)


def _at(xs, ys, x):
    """ys at x, linear in log |x| between the grid's points; None outside it or where the
    problem has no solution. The grid holds the step's own sign (a negative step's grid
    is negative): a value of the other sign is on no point of it."""
    import math

    if xs[0] < 0:
        xs, x = [-v for v in xs], -x
    if not x > 0 or not xs[0] <= x <= xs[-1]:
        return None
    for k in range(1, len(xs)):
        if x <= xs[k]:
            if ys[k - 1] is None or ys[k] is None:
                return None
            t = (math.log(x) - math.log(xs[k - 1])) / (math.log(xs[k]) - math.log(xs[k - 1]))
            return ys[k - 1] + t * (ys[k] - ys[k - 1])
    return None


def _band(variant, target, carried, atol):
    """The half-width a carried value accepts, measured from it as the variant's own is
    from the solver's value (gyro check's rule): a relative tolerance or figures of the
    carried value, never less than half a unit of its last printed figure; an absolute
    one as it is."""
    import math

    form, fraction, digits = variant.get("tol", {}).get(target, ["absolute", atol, 4])
    if form == "absolute" or not carried:
        return atol
    exponent = math.floor(math.log10(abs(carried)))
    least = 0.5 * 10.0 ** (exponent - int(digits) + 1)
    if form == "sig":
        return max(0.5 * 10.0 ** (exponent - int(fraction) + 1), least)
    return max(float(fraction) * abs(carried), least)


def grade(data):
    """Errors carried forward: a wrong input that is right for the student's own wrong
    earlier step earns the share (not from a stock 0 or 1, nor from a step that barely
    moves it); the score is then the weighted mean of the parts."""
    variant = VARIANTS[int(data["variant_seed"]) % len(VARIANTS)]
    carry = variant.get("ecf")
    scores = data.get("partial_scores", {})
    if carry:
        for source, table in carry["from"].items():
            _carry(data, variant, carry, source, table, scores)
    weights = [(p.get("score") or 0.0, p.get("weight", 1)) for p in scores.values()]
    if weights and sum(w for _, w in weights):
        data["score"] = sum(s * w for s, w in weights) / sum(w for _, w in weights)


def _carry(data, variant, carry, source, table, scores):
    own = data.get("submitted_answers", {}).get(source)
    part = scores.get(source)
    if part is None or (part.get("score") or 0) >= 1 or not isinstance(own, (int, float)):
        return
    raw = data.get("raw_submitted_answers", {}).get(source, own)
    if own in (0, 1, -1):
        return  # a stock value: no follow-through
    for target, ys in table["to"].items():
        later, got = scores.get(target), data.get("submitted_answers", {}).get(target)
        if later is None or (later.get("score") or 0) >= 1 or not isinstance(got, (int, float)):
            continue
        carried = _at(table["at"], ys, own)
        if carried is None:
            continue
        atol = float(variant["atol"][target])
        if abs(carried - variant["answers"][target]) <= atol:
            continue  # the step barely moves this answer
        moved = _at(table["at"], ys, own + _place(raw, own))
        widen = abs(moved - carried) if moved is not None else 0.0
        if abs(got - carried) <= _band(variant, target, carried, atol) + widen:
            later["score"] = max(later.get("score") or 0.0, carry["share"])
            note = "consistent with your %s = %s (ECF)" % (carry["labels"][source], raw)
            later["feedback"] = note
            data.setdefault("feedback", {})[target] = note
'''


def _correct(choice: Choice, words: tuple[str, ...]) -> dict[str, str]:
    """Each word of the question's choice (c1, c2, ...): "true" for this variant's."""
    return {f"c{n}": "true" if word == choice.answer else "false"
            for n, word in enumerate(words, 1)}


def server_py(bank: ProblemBank) -> str:
    """The question's server.py, with every variant's statement, feedback and answers."""
    words = {key: choices for key, (_, choices) in _choices(bank).items()}
    return "".join(server_pieces(bank, (variant_entry(v, words) for v in bank.variants)))


def variant_entry(v: Variant, words: dict[str, tuple[str, ...]],
                  figure: bool | None = None) -> dict:
    """One variant as server.py holds it (``words``: each choice's words over all the
    variants; ``figure``: whether it has a picture, when its PNG is not held)."""
    pictured = bool(v.figure) if figure is None else figure
    return {"variant": v.number, "id": v.ident, "given": v.given,
            "statement": v.statement_html, "feedback": v.feedback_html,
            "answers": {b.key: b.value for b in v.blanks},
            "atol": {b.key: number_text(b.half_width) for b in v.blanks},
            # how the half-width is made (form, fraction or figures, figures printed), so
            # that grade() measures a carried value's band as gyro check does
            "tol": {b.key: [b.form, b.fraction, b.digits] for b in v.blanks},
            "correct": {c.key: _correct(c, words[c.key]) for c in v.choices},
            "figure": v.figure_name if pictured else "", "figure_alt": v.figure_alt} | (
                {"ecf": v.carry} if v.carry else {})


def server_pieces(bank: ProblemBank, entries: Iterable[dict]) -> Iterator[str]:
    """server.py in pieces, a variant at a time: the text of `server_py`, whose
    ``VARIANTS`` is the repr of the JSON of ``entries``."""
    doc = "".join(c for c in " ".join(bank.name.split()) if c.isprintable())
    doc = doc.replace("\\", "/").replace('"', "'")
    head, tail = SERVER.split("{variants}")
    yield head.format(doc=f"{doc} ({bank.kind})") + "'["
    carries = False
    for n, entry in enumerate(entries):
        carries = carries or "ecf" in entry
        text = json.dumps(entry, ensure_ascii=True, allow_nan=False)
        # JSON always holds a double quote, so repr quotes it in single quotes: the
        # repr of the whole list is the reprs of its parts between one pair of them.
        yield (", " if n else "") + repr(text + '"')[1:-2]
    yield "]'" + tail.format() + (GRADE if carries else "")


def files(banks: list[ProblemBank]) -> dict[str, str | bytes]:
    """Relative path -> text (or PNG bytes) of every file of the export: a picture of the
    worked answer is in the question's clientFilesQuestion/."""
    out: dict[str, str | bytes] = {}
    for bank in banks:
        out[f"{bank.slug}/info.json"] = json.dumps(info(bank), indent=2,
                                                   ensure_ascii=False) + "\n"
        out[f"{bank.slug}/question.html"] = question_html(bank)
        out[f"{bank.slug}/server.py"] = server_py(bank)
        for variant in bank.variants:
            if variant.figure:
                out[f"{bank.slug}/clientFilesQuestion/{variant.figure_name}"] = variant.figure
    return out
