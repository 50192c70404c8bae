"""Property tests: problem files built from the kinds' specs keep gyro's promise.

The strategies build a problem of a random kind from its own spec (the given
keys with their dimensions and choices, the answers with theirs): each value
either valid (a number and a unit of the right dimension) or mutated (any YAML
type, a unit of another dimension, a near-miss from the unit grammar, an
extreme magnitude), keys sometimes misspelt or missing. For every file:

- ``gyro solve`` in text, json, markdown and latex: exit 0 with finite numbers,
  or exit 2 with one line ``gyro: FILE...``;
- ``gyro check``: exit 0 or 1 with finite numbers, or exit 2 with one line;

never a traceback and never an internal error. The examples are derandomized
(the same each run, so the suite is repeatable). The budgets are sized to what the
examples reach: the distinct lines of gyro_cli run by the solve-and-check examples grow
to 97 % of a thousand examples' by the 400th, the quantity examples' to all but one by
the 750th. `make props` runs ten times as many; the long random run is ``make fuzz``.
"""

from __future__ import annotations

import json
import math
import re
import sys
from functools import cache

import pytest

hypothesis = pytest.importorskip("hypothesis")
from conftest import ROOT, examples, read_yaml  # noqa: E402
from hypothesis import HealthCheck, given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

sys.path.insert(0, str(ROOT / "fuzz"))
from mutate import NEAR_MISSES, UNITS, Raw, emit  # noqa: E402

from gyro_cli import kinds  # noqa: E402
from gyro_cli.solving.problem import params_of  # noqa: E402

NOT_FINITE = re.compile(r"(?<![\w.\\])[-+]?(?:nan|inf)(?![\w])", re.I)
QUOTED = re.compile(r"'[^'\n]*'|\"[^\"\n]*\"")
SETTINGS = dict(deadline=None, derandomize=True, database=None,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                                       HealthCheck.filter_too_much])

pytestmark = pytest.mark.property

KIND_NAMES = kinds.names()
ALL_UNITS = sorted({u for us in UNITS.values() for u in us if u})

# ---- strategies ---------------------------------------------------------------

magnitudes = st.one_of(
    st.floats(min_value=0.01, max_value=5000, allow_nan=False),
    st.floats(min_value=-5000, max_value=5000, allow_nan=False),
    st.sampled_from([0.0, -0.0, 1e308, -1e308, 1e-320, 5e-324, 1e-300, 1e300, 1e200, 1e-200]),
    st.floats(allow_nan=False, allow_infinity=False),
)


def number_text(x: float) -> str:
    return repr(x) if abs(x) >= 1e-4 or x == 0 else f"{x:.6e}"


# unit strings from a grammar: names of the right dimension, of any dimension,
# products and quotients with small powers, and near misses
unit_names = st.sampled_from(ALL_UNITS)
powers = st.sampled_from(["", "", "^2", "^-1", "**3", "^ 2", "^+2", "^123", "**", "^"])
compound = st.builds(lambda a, op, b, p: f"{a}{op}{b}{p}", unit_names,
                     st.sampled_from(["*", "/", " ", " * ", " / ", "·", "**"]), unit_names, powers)
near_miss = st.one_of(
    st.sampled_from(NEAR_MISSES),
    st.builds(lambda u, junk: u + junk, unit_names,
              st.sampled_from(["*", "()", "(", ")", "/", "^", ",", " #c", " per", "s s", "\t"])),
    st.text(alphabet="abcmsNkgrpd*/()^ -+0123456789,.#", max_size=40),
)


def unit_of(dimension: str | None):
    right = st.sampled_from(UNITS.get(dimension or "", [""]) or [""])
    return st.one_of(right, right, right, unit_names, compound, near_miss)


def quantity(dimension: str | None):
    return st.builds(lambda x, u, gap: f"{number_text(x)}{gap}{u}".strip(), magnitudes,
                     unit_of(dimension), st.sampled_from([" ", " ", ""]))


scalars = st.one_of(
    st.none(), st.booleans(), st.integers(), st.floats(),
    st.text(max_size=20),
    st.sampled_from([Raw(r) for r in (
        "2024-02-31", "2024-02-29", "0x1F", "0xZZ", "0o17", "1_000", "1:30", "!!bool maybe",
        "!!bool yes", "!!int 0x", "!!float abc", "!!binary aGk=", "!!set {a, b}",
        "!!timestamp 2024-02-31", "9" * 5000, "9" * 320, ".inf", "-.inf", ".nan", "~",
        "*nope", "!!omap [a: 1]", "!!str 5 m")]),
)
any_yaml = st.recursive(scalars, lambda inner: st.one_of(
    st.lists(inner, max_size=3), st.dictionaries(st.text(max_size=5), inner, max_size=3)),
    max_leaves=6)


@cache  # built once per argument and validated once; the examples drawn are the same
def value_for(dimension: str | None, choices: tuple = ()):
    options = [quantity(dimension), quantity(dimension), quantity(dimension), any_yaml,
               st.lists(quantity(dimension), max_size=3)]
    if choices:
        options += [st.sampled_from(list(choices))] * 3
    return st.one_of(*options)


@cache
def key_variant(name: str):
    return st.one_of(st.just(name), st.just(name), st.just(name), st.just(name),
                     st.sampled_from([name.upper(), name + "\n", name[:-1], name + "_",
                                      name + " "]))


def _bases() -> list[dict]:
    """Solvable starting points: each kind's `gyro new` example and the bundled problems."""

    out = []
    for name in KIND_NAMES:
        example = kinds.get(name).example
        if example:
            out.append({"id": f"{name}-example", "kind": name,
                        "given": dict(example.get("given", {})),
                        "find": dict(example.get("find", {}))})
    for path in sorted((ROOT / "problems").glob("*.yaml")):
        out.append(read_yaml(path.read_text()))
    return out


BASES = _bases()


@st.composite
def mutation(draw, data: dict) -> None:
    """One change to ``data`` drawn from its kind's spec (in place)."""
    try:
        kind = kinds.get(data.get("kind"))
    except Exception:
        kind = kinds.get(draw(st.sampled_from(KIND_NAMES)))
    params = params_of(kind)
    given_map = data["given"] if isinstance(data.get("given"), dict) else {}
    find = data["find"] if isinstance(data.get("find"), dict) else {}
    what = draw(st.sampled_from(["given", "given", "given", "delete", "find", "expected",
                                 "tolerance", "rename", "top", "scale"]))
    if what == "given":
        p = draw(st.sampled_from(params))
        dimension = None if p.dimension == "word" else p.dimension
        given_map[p.name] = draw(value_for(dimension, p.choices or ()))
    elif what == "delete" and given_map:
        del given_map[draw(st.sampled_from(sorted(given_map, key=str)))]
    elif what == "find":
        a = draw(st.sampled_from(kind.answers))
        find[a.name] = draw(st.one_of(*[st.none()] * 4, any_yaml)) if a.dimension is None \
            else draw(st.one_of(st.none(), unit_of(a.dimension), unit_of(a.dimension),
                                any_yaml))
    elif what == "expected":
        expected = data.setdefault("expected", {})
        if isinstance(expected, dict):
            a = draw(st.sampled_from(kind.answers))
            expected[a.name] = draw(
                st.sampled_from(["cusps", "loops", "waves", "steady", "Steady", ""])
                if a.dimension is None else value_for(a.dimension))
    elif what == "tolerance":
        data["tolerance"] = draw(st.one_of(
            st.sampled_from(["1%", "3 sig", "0%", "100%", "1e309%", "-1%", "20 sig", "0 sig",
                             "0.01 rad/s", "1e-320 N", "5 %"]),
            any_yaml, st.dictionaries(st.sampled_from(["default", "nope"]
                                                      + [a.name for a in kind.answers]),
                                      st.sampled_from(["1%", "2 sig", 3, "x"]), max_size=2)))
    elif what == "rename":
        where = draw(st.sampled_from([data, given_map, find]))
        if where:
            key = draw(st.sampled_from(sorted(where, key=str)))
            where[draw(key_variant(str(key)))] = where.pop(key)
    elif what == "top":
        data[draw(st.sampled_from(["id", "kind", "given", "find", "expected", "tolerance",
                                   "title", "notes"]))] = draw(any_yaml)
    elif given_map:  # scale a number by a power of ten
        key = draw(st.sampled_from(sorted(given_map, key=str)))
        parts = str(given_map[key]).split(None, 1)
        try:
            number = float(parts[0]) * 10.0 ** draw(st.integers(-320, 320))
        except (ValueError, IndexError, OverflowError):
            number = 1e308
        given_map[key] = f"{number!r} {parts[1] if len(parts) > 1 else ''}".strip()


@st.composite
def problem_files(draw):
    """A solvable problem (a kind's example or a bundled one) with 0-3 spec mutations."""
    import copy

    data = copy.deepcopy(draw(st.sampled_from(BASES)))
    for _ in range(draw(st.sampled_from([0, 1, 1, 1, 2, 3]))):
        draw(mutation(data))
    return emit(data)


# ---- the promise --------------------------------------------------------------

def not_finite(text: str) -> bool:
    return bool(NOT_FINITE.search(QUOTED.sub("''", text)))


def keeps_promise(result, path, command: str, source: str) -> None:
    assert result.exception is None or isinstance(result.exception, SystemExit), \
        (source, repr(result.exception))
    assert "Traceback" not in result.output, source
    code = result.exit_code
    echoed = bool(NOT_FINITE.search(source))  # a note saying "inf" is printed back as written
    assert code in ((0, 1, 2) if command == "check" else (0, 2)), (code, result.output, source)
    if code == 2:
        lines = result.stderr.splitlines()
        assert len(lines) == 1 and lines[0].startswith(f"gyro: {path}"), (result.stderr, source)
        if command == "solve":
            assert result.stdout == "", source
    else:
        assert result.stderr == "", (result.stderr, source)
        assert echoed or not not_finite(result.stdout), (result.stdout, source)


def _json_finite(text: str) -> None:
    for line in text.splitlines():
        json.loads(line, parse_constant=lambda c: pytest.fail(f"{c} in JSON output"))


@pytest.fixture(scope="module")
def workdir(tmp_path_factory):
    return tmp_path_factory.mktemp("props")


@settings(max_examples=examples(400), **SETTINGS)
@given(source=problem_files())
def test_solve_and_check_keep_the_promise(run_in_process, workdir, source):
    path = workdir / "p.yaml"
    path.write_text(source, encoding="utf-8", errors="surrogatepass")
    # `gyro solve` once (its exit code, its one-line error); the other formats rendered
    # from one solve as `gyro solve --format X` renders them (Result.render, the registry the CLI reads), not four
    # runs of the command: a format that raises fails here as it would exit 3 there.
    result = run_in_process("solve", path)
    keeps_promise(result, path, "solve", source)
    solved, made = _every_format(path)
    fmt_results = {fmt: code for fmt, (code, _) in solved.items()}
    assert set(fmt_results.values()) == {result.exit_code}, (fmt_results, source)  # agree
    if result.exit_code == 0:
        assert solved["text"][1] == result.stdout, source
        echoed = bool(NOT_FINITE.search(source))
        for fmt, (_, text) in solved.items():
            assert echoed or not not_finite(text), (fmt, text, source)
        _json_finite(solved["json"][1])
        _well_formed_html(made.solved, source)
    result = run_in_process("check", path)
    keeps_promise(result, path, "check", source)
    hypothesis.event(f"solve exit {fmt_results['text']}, check exit {result.exit_code}")
    if fmt_results["text"] == 2:
        assert result.exit_code == 2, (result.output, source)


def _well_formed_html(result, source: str) -> None:
    """Whatever solves renders as well-formed, escaped HTML without an exception (once
    tests/test_html.py's own property test, which solved 60 more examples for it)."""
    from test_html import _parsed

    from gyro_cli.render import html

    text = html.worked_answer(result, picture=False)
    if text not in _WELL_FORMED:  # a page another example made is not parsed again
        tags = _parsed(text)
        assert not tags.errors and not tags.stack, (tags.errors, source)
        _WELL_FORMED.add(text)
    assert "<script" not in text


#: the worked answers found well-formed (two in five examples repeat one: parsing took
#: longer than rendering)
_WELL_FORMED: set[str] = set()


def _every_format(path):  # type: ignore[no-untyped-def]
    """The exit code and output `gyro solve --format X FILE` has for each format X, from
    one solve: 2 and nothing where the file or the format's rendering is bad input; and
    the solve's result (None where the file is bad input)."""
    from gyro_cli.api import solve_file
    from gyro_cli.core.errors import InputError

    formats = ("text", "json", "markdown", "latex")
    try:
        result = solve_file(str(path))
    except InputError:
        return {fmt: (2, "") for fmt in formats}, None
    out = {}
    for fmt in formats:
        try:
            out[fmt] = (0, result.render(fmt, level=1))  # gyro solve's own renderer
        except InputError:
            out[fmt] = (2, "")
    return out, result


@settings(max_examples=examples(750), **SETTINGS)
@given(dimension=st.sampled_from(sorted(UNITS)), text=st.one_of(
    quantity("rate"), quantity("length"), near_miss, any_yaml,
    st.builds(lambda n, u: f"{n} {u}", magnitudes, near_miss)))
def test_a_quantity_is_a_finite_number_or_one_located_error(dimension, text):
    """The loader's quantity parsing, straight: a finite SI float or InputError at the key."""
    from gyro_cli.core import units
    from gyro_cli.core.errors import InputError
    from gyro_cli.solving.problem import guarded

    try:
        value, _ = guarded(units.parse, text, dimension, "given.x")
    except InputError as err:
        assert err.key == "given.x" and "\n" not in str(err)
        return
    assert isinstance(value, float) and math.isfinite(value)


@settings(max_examples=examples(50), **SETTINGS)
@given(sources=st.lists(problem_files(), min_size=2, max_size=4))
def test_check_of_a_directory_lists_every_file(run_in_process, tmp_path_factory, sources):
    folder = tmp_path_factory.mktemp("dir")
    for i, source in enumerate(sources):
        (folder / f"f{i}.yaml").write_text(source, encoding="utf-8", errors="surrogatepass")
    result = run_in_process("check", folder)
    assert result.exception is None or isinstance(result.exception, SystemExit)
    assert result.exit_code in (0, 1, 2), result.output
    errors = result.stdout.count("  ERROR  ")
    assert len(result.stderr.splitlines()) == errors  # one line per bad file, no more
    for i in range(len(sources)):
        assert f"f{i}.yaml" in result.stdout


@pytest.fixture(scope="module")
def run_in_process():
    from click.testing import CliRunner

    from gyro_cli.cli import main

    runner = CliRunner()

    def _run(*args):
        return runner.invoke(main, [str(a) for a in args])
    return _run


# A value holding a line break is a cell over two lines, which the sheet's reader refuses
# as a whole (tests/test_csv_one_line_cells.py): not a row to grade, so none is drawn.
sheet_values = st.one_of(quantity("rate"), quantity("time"), near_miss,
                         st.sampled_from(["cusps", "Loops.", "WAVY", "steady precession", "",
                                          "1e308 s", "965.4 rpm*", "nan rpm", "motion",
                                          "45.13; 533.5 rpm", "≈965.4 rpm", "45.13 rpm (slow)",
                                          "9.654×10^2 rpm", "965,4 rpm", "35.15 N at B"]),
                         st.text(alphabet="abcdefgh0123456789 .;,-+*/()^e≈~–×·²⁻",
                                 max_size=30)).filter(lambda v: "\n" not in v and "\r" not in v)


@settings(max_examples=examples(150), **SETTINGS)
@given(values=st.lists(st.tuples(st.sampled_from(["precession", "min_spin"]), sheet_values),
                       min_size=1, max_size=4),
       words=st.lists(sheet_values, max_size=2))
def test_every_sheet_row_is_graded(run_in_process, tmp_path_factory, values, words):
    """Whatever a student writes, the row is graded (invalid at worst), the rest goes on."""
    import csv
    import io

    folder = tmp_path_factory.mktemp("sheet")
    out = io.StringIO()
    writer = csv.writer(out)
    writer.writerow(["student", "problem", "answer", "value"])
    for i, (answer, value) in enumerate(values):
        writer.writerow([f"s{i}", "11/3", answer, value])
    for i, value in enumerate(words):
        writer.writerow([f"w{i}", "11.2-released", "motion", value])
    sheet = folder / "sheet.csv"
    sheet.write_text(out.getvalue())
    grades = folder / "grades.csv"
    result = run_in_process("check", "--answers", sheet, ROOT / "problems" / "11_3.yaml",
                            ROOT / "problems" / "11_2_released_top.yaml", "--out", grades)
    assert result.exit_code == 0, (result.output, out.getvalue())
    rows = list(csv.DictReader(io.StringIO(grades.read_text())))
    assert {r["result"] for r in rows} <= {"correct", "partial", "wrong", "invalid", "missing",
                                           "score"}
    for row in rows:  # the student's own text may be quoted back; gyro's figures are finite
        note = row["note"].replace(row["submitted"], "")
        for value in row["submitted"].split(";"):
            note = note.replace(value.strip(), "")
        assert not not_finite(row["relative_error"] + " " + note), row
