"""gyro's Python API: `solve`, `check`, `kinds`, `sweep`, and results that show themselves.

    >>> import gyro_cli
    >>> r = gyro_cli.solve("problems/11_3.yaml", spin="2000 rpm")
    >>> r.answers["precession"]          # both roots, in the unit the file asks for
    >>> r.answers["precession"].si       # the same in SI (rad/s)
    >>> r                                # in Jupyter: the worked answer, MathML formulas

A problem is a path, YAML text, or a mapping with the file's keys (values as
strings with units, plain numbers in SI, or pint Quantities). Bad input raises
`InputError` with ``key``, ``line`` and ``file``, the same one line the command
prints. The command line is a client of this module (`gyro solve`).

Nothing heavy is imported here: pint, numpy and the renderers load when a
result is shown or a unit is first met, as for the command.
"""

from __future__ import annotations

import itertools
import math
import os
import sys
from collections.abc import Iterable, Iterator, Mapping
from typing import TYPE_CHECKING, Any, Union

from .core.errors import InputError
from .render.formats import NAMES as FORMATS

if TYPE_CHECKING:
    from .checking.grades import Graded
    from .checking.results import CheckRun, ProblemCheck
    from .core.spec import Kind
    from .core.work import GivenLine, Section, Step
    from .solving.problem import Problem
    from .solving.solve import Reported
    from .solving.solve import Result as _Solved

__all__ = ["solve", "solve_file", "check", "check_files", "kinds", "sweep", "load", "Result", "Answer", "CheckReport",
           "Sweep", "InputError", "registry", "document", "FORMATS"]

#: what `solve` and `check` accept as a problem
Source = Union[str, "os.PathLike[str]", Mapping[str, Any]]


# ---- reading a problem ------------------------------------------------------------

def load(source: Source, /, *, path: bool = False, **given: Any) -> Problem:
    """The checked problem of ``source`` (path, YAML text or mapping), with ``given``
    keys replaced (``spin="2000 rpm"``; ``None`` removes a key). ``path=True``: a
    string is a file's path, never YAML text.

    Numbers in SI and pint Quantities are accepted in a mapping and in ``given``;
    a file or YAML text keeps the file format's rules (a length needs its unit).
    """
    from .solving import problem as loader

    name, data, lines = _read(source, path)
    changed: set[str] = set()
    if given:
        if not isinstance(data, dict) or not isinstance(data.get("given"), dict):
            return loader.build(name, data, lines)  # the loader says what is wrong
        data = dict(data, given=dict(data["given"]))
        for key, value in given.items():
            lines.pop(f"given.{key}", None)  # an override has no line in the file
            if value is None:
                data["given"].pop(key, None)
            else:
                data["given"][key] = value
                changed.add(key)
        if isinstance(data.get("statement"), str):
            from .core.statement import StatementError, placeholders

            try:
                stale = set(placeholders(data["statement"])) - set(data["given"])
            except StatementError:
                stale = set()  # the loader says what is wrong with it
            if stale:  # a key the statement names was removed: it no longer states this
                data = {k: v for k, v in data.items() if k != "statement"}
    if isinstance(data, dict) and (isinstance(source, Mapping) or changed):
        try:
            data = _plain(data, None if isinstance(source, Mapping) else changed)
        except InputError as err:
            raise err.located(file=name) from None
    return loader.build(name, data, lines)


def _read(source: Source, path: bool = False) -> tuple[str, Any, dict[str, int]]:
    """(name for messages, data, line of each key) of a path, YAML text or mapping."""
    from .solving import problem as loader

    if isinstance(source, Mapping):
        import copy

        data = copy.deepcopy(dict(source))
        if "id" not in data and isinstance(data.get("kind"), str):
            data["id"] = data["kind"]  # a dict in a notebook needs no name of its own
        return "<dict>", data, {}
    if isinstance(source, os.PathLike):
        source = os.fspath(source)
    if not isinstance(source, str):
        raise InputError(f"expected a path, YAML text or a mapping, got {type(source).__name__} "
                         f"{source!r:.40}")
    if not path and not os.path.exists(source) and ("\n" in source
                                                    or source.lstrip().startswith("{")):
        data, lines = loader.parse_yaml(source, "<yaml>")
        return "<yaml>", data, lines
    data, lines = loader.read_yaml(source)
    return source, data, lines


def _is_quantity(value: Any) -> bool:
    return hasattr(value, "magnitude") and hasattr(value, "units") and hasattr(value, "to")


def _quantity_text(value: Any, key: str) -> str:
    """A pint Quantity as the text a file would hold: ``1800.0 rpm``, ``0.01 kg * m ** 2``
    (read back with gyro's own registry, where Hz on a rotor is revolutions per second)."""
    magnitude = value.magnitude
    if getattr(magnitude, "shape", ()) != ():
        raise InputError(f"expected one quantity, got an array of shape {magnitude.shape}",
                         key=key)
    number = _real(magnitude, key)
    if number is None:
        raise InputError(f"expected one quantity, got a {type(magnitude).__name__} "
                         "magnitude", key=key)
    return f"{float(number)!r} {value.units:~}".strip()


def _real(value: Any, key: str) -> float | int | None:
    """A real number given to the API as a Python number: an int, a float, numpy's
    integers and floats (and a 0-d array of one), a Decimal or a Fraction; None for
    anything else (a string, a list: the loader reads or refuses it). A boolean, a
    complex number, an array of several values and a number beyond a double's range
    (or inf, nan) are refused naming the key."""
    import numbers

    if isinstance(value, (str, bytes)) or value is None:
        return None
    shape = getattr(value, "shape", None)
    if shape == () and hasattr(value, "item"):  # a numpy scalar or 0-d array: its number
        value = value.item()
    elif shape:
        raise InputError(f"expected one number, got an array of shape {shape}; "
                         "sweep() takes several", key=key)
    if isinstance(value, bool):  # numpy's bool_ is a bool once item() has taken it out
        raise InputError(f"expected a number, got {value!r} (true/false is not a number)",
                         key=key)
    decimal = sys.modules.get("decimal")  # never imported for this: no Decimal without it
    if not isinstance(value, numbers.Real) and not (
            decimal is not None and isinstance(value, decimal.Decimal)):
        if isinstance(value, numbers.Complex):
            raise InputError(f"expected a real number, got {value!r}", key=key)
        return None
    try:
        number = float(value)
    except OverflowError:  # a huge int or Fraction
        number = math.inf
    except ValueError:  # a signalling NaN
        number = math.nan
    if not math.isfinite(number):
        what = "not a number" if math.isnan(number) else \
            "out of range (beyond a double's 1.8e308)"
        raise InputError(f"{_short_number(value)} is {what}; expected a finite number",
                         key=key)
    return int(value) if isinstance(value, numbers.Integral) else number


def _short_number(value: Any) -> str:
    """A number for a message: a 400-digit one by its length."""
    text = str(value)
    if len(text) <= 30:
        return text
    return f"an integer of {len(text)} digits" if isinstance(value, int) else \
        f"a number of {len(text)} characters ({text[:12]}...)"


def _si_number(value: Any, dimension: str, key: str) -> Any:
    """A plain number of the API is in SI: ``0.3`` for a length is ``0.3 m``."""
    from .core import units

    if dimension in ("word", "particles"):
        return value
    number = _real(value, key)
    if number is None:
        return value
    if dimension == "dimensionless":
        return number
    return f"{float(number)!r} {units.si_text(dimension)}".strip()


def _plain(data: dict, only: set[str] | None = None) -> dict:
    """The mapping as a file would hold it: Quantities and SI numbers become quantity
    strings (what the loader checks), everything else stays as it is. ``only``: convert
    just these given keys (the overrides of a file)."""
    from .kinds import get as kind_named
    from .solving.problem import params_of

    given = data.get("given")
    try:
        params = {p.name: p for p in params_of(kind_named(data.get("kind")))}
    except InputError:
        params = {}
    if isinstance(given, dict):
        out = {}
        for key, value in given.items():
            param = params.get(str(key))
            where = f"given.{key}"
            if only is not None and key not in only:
                pass
            elif _is_quantity(value):
                value = _quantity_text(value, where)
            elif param is not None and param.dimension == "particles" and isinstance(value, list):
                value = [{k: _quantity_text(v, f"{where}.{k}") if _is_quantity(v) else
                          _si_number(v, "mass" if k == "mass" else "length", f"{where}.{k}")
                          for k, v in item.items()} if isinstance(item, dict) else item
                         for item in value]
            elif param is not None:
                value = _si_number(value, param.dimension, where)
            out[key] = value
        data = dict(data, given=out)
    if only is not None:
        return data
    find = data.get("find")
    if isinstance(find, dict):
        data = dict(data, find={k: f"{v:~}" if hasattr(v, "dimensionality") and
                                not _is_quantity(v) else v for k, v in find.items()})
    expected = data.get("expected")
    if isinstance(expected, dict):
        def text(v: Any, key: str) -> Any:
            if _is_quantity(v):
                return _quantity_text(v, key)
            if isinstance(v, list):
                return [text(x, key) for x in v]
            return v
        data = dict(data, expected={k: text(v, f"expected.{k}") for k, v in expected.items()})
    return data


# ---- answers and results ------------------------------------------------------------

class Answer:
    """One answer: its values in the unit asked for (``values``, ``unit``) and in SI
    (``si``). Several values (the two roots of a steady precession) are labelled
    (``slow``, ``fast``); ``answer["slow"]`` or ``answer[0]`` picks one."""

    # a plain class, not a dataclass: `gyro solve` imports this module, and a dataclass
    # costs its start-up a millisecond
    __slots__ = ("name", "symbol", "values", "unit", "si_values", "si_unit", "labels")

    def __init__(self, name: str, symbol: str, values: tuple, unit: str | None,
                 si_values: tuple, si_unit: str | None, labels: tuple = ()) -> None:
        self.name, self.symbol, self.values, self.unit = name, symbol, tuple(values), unit
        self.si_values, self.si_unit, self.labels = tuple(si_values), si_unit, tuple(labels)

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Answer) and all(
            getattr(self, k) == getattr(other, k) for k in self.__slots__)

    __hash__ = None  # type: ignore[assignment]

    @property
    def value(self) -> float | str:
        """The one value, in the unit asked for (ValueError when there are several)."""
        if len(self.values) != 1:
            raise ValueError(f"{self.name} has {len(self.values)} values "
                             f"({self}); use .values or answer[i]")
        return self.values[0]

    @property
    def si(self) -> float | str | tuple:
        """The value in SI (``si_unit``); a tuple when there are several."""
        return self.si_values[0] if len(self.si_values) == 1 else tuple(self.si_values)

    def __float__(self) -> float:
        return float(self.value)

    def __len__(self) -> int:
        return len(self.values)

    def __iter__(self) -> Iterator:
        return iter(self.values)

    def __getitem__(self, index: int | str) -> float | str:
        if isinstance(index, str):
            if index not in self.labels:
                raise KeyError(f"{self.name} has no value labelled {index!r}; labels: "
                               f"{', '.join(l for l in self.labels if l) or 'none'}")
            index = self.labels.index(index)
        return self.values[index]

    def quantity(self) -> Any:
        """The value(s) as a pint Quantity of gyro's registry (`registry()`)."""
        if any(isinstance(v, str) for v in self.values):
            raise ValueError(f"{self.name} is a word, not a quantity")
        ureg = registry()
        values = self.values[0] if len(self.values) == 1 else list(self.values)
        try:
            return ureg.Quantity(values, self.unit or self.si_unit or "")
        except Exception:  # noqa: BLE001 - a unit pint spells otherwise: SI
            si = self.si_values[0] if len(self.si_values) == 1 else list(self.si_values)
            return ureg.Quantity(si, self.si_unit or "")

    def __str__(self) -> str:
        from .render.report import _answer_text

        return _answer_text(list(self.values), self.unit, list(self.labels)).replace(
            "   ", ", ")

    def __repr__(self) -> str:
        return f"<Answer {self.name} = {self}>"


def _answer(reported: Reported) -> Answer:
    return Answer(reported.name, reported.symbol, tuple(reported.values), reported.unit,
                  tuple(reported.si_values), reported.si_unit, tuple(reported.labels))


class Result:
    """A solved problem: ``answers`` (name -> `Answer`), ``steps`` (the worked answer's
    sections of structured steps), ``checks``, ``given``, ``warnings``; `to_dict` is the
    JSON of ``gyro solve --format json``. In Jupyter it shows the worked answer."""

    def __init__(self, solved: _Solved, units: str | None = None) -> None:
        self._si = solved
        self.units = (units or solved.problem.units or "si").lower()
        self._shown: _Solved | None = None

    # -- the solved problem, in the unit system asked for
    @property
    def solved(self) -> _Solved:
        """The solver's own result (in US units when asked for)."""
        if self._shown is None:
            if self.units == "us":
                from .render.us_units import to_us

                self._shown = to_us(self._si)
            else:
                self._shown = self._si
        return self._shown

    @property
    def problem(self) -> Problem:
        return self._si.problem

    @property
    def id(self) -> str:
        return str(self.problem.id)

    @property
    def kind(self) -> str:
        return self.problem.kind.name

    @property
    def title(self) -> str:
        return self.problem.title

    @property
    def file(self) -> str:
        return self.problem.file

    @property
    def answers(self) -> dict[str, Answer]:
        return {name: _answer(a) for name, a in self.solved.answers.items()}

    @property
    def steps(self) -> list[Section]:
        return list(self.solved.solution.sections)

    @property
    def checks(self) -> list[Step]:
        return list(self.solved.solution.checks)

    @property
    def given(self) -> list[GivenLine]:
        return list(self.solved.solution.given)

    @property
    def warnings(self) -> list[str]:
        return list(self.solved.solution.warnings)

    # -- outputs
    def to_dict(self) -> dict[str, Any]:
        """The JSON object of ``gyro solve --format json`` (full precision)."""
        from .render import report

        solved = self._si
        if self.units == "us":
            from .render.us_units import to_us

            solved = to_us(self._si, given=False)  # JSON's si_value stays SI
        return report.as_dict(solved) | {"graph": report.graph_data(self._si)}

    def to_json(self) -> str:
        import json

        return json.dumps(self.to_dict(), allow_nan=False)

    def render(self, fmt: str = "text", level: int = 2) -> str:
        """The worked answer in the output format ``fmt`` (one of `FORMATS`), as ``gyro
        solve --format FMT`` writes this one file (html: its <article>, a title of
        ``level``); `document` composes several."""
        return _format(fmt).one(self, level)

    def text(self) -> str:
        """The worked answer as ``gyro solve`` prints it."""
        return self.render("text")

    def markdown(self) -> str:
        return self.render("markdown")

    def latex(self) -> str:
        return self.render("latex")

    def html(self, page: bool = False, picture: bool = True, level: int = 2,
             animation: str = "") -> str:
        """The worked answer as HTML: an <article> (MathML formulas, the picture as inline
        SVG; its title a heading of ``level``), or with ``page=True`` the self-contained
        page of ``--format html``. ``animation``: a figure of the motion to embed
        (`animation_html`)."""
        from .render import html

        if page:
            return html.page([self.solved])
        return html.worked_answer(self.solved, level=level, picture=picture,
                                  animation=animation)

    def animation_html(self, periods: float | None = None, speed: float = 1.0,
                       fps: float = 30.0) -> str:
        """A figure of the motion (a canvas and its player, drawn from a simulation, as
        ``gyro simulate --animate OUT.html``) to embed in `html`; "" for a kind that does
        not move. A page that shows it must allow its script (`animation_script`)."""
        from .commands import animate
        from .render.animate import html_fragment

        if self.solved.problem.kind.animation not in animate.BUILDERS:
            return ""
        scene, _ = animate.scene_of(self.solved.problem, self.solved, periods, speed, fps)
        return html_fragment(scene, self.animation_id)

    @property
    def animation_id(self) -> str:
        """The element id of the embedded animation (unique on a page of several)."""
        from .render import html

        return f"{html.anchor(self.solved)}-animation"

    def _repr_html_(self) -> str:
        from .render import html

        return (f"<div class=\"gyro\"><style>{html.STYLE}</style>"
                f"{html.worked_answer(self.solved, level=3)}</div>")

    def _repr_markdown_(self) -> str:
        return self.markdown()

    def _repr_latex_(self) -> str:
        return self.latex()

    def __str__(self) -> str:
        return self.text()

    def __repr__(self) -> str:
        parts = "; ".join(f"{name} = {answer}" for name, answer in self.answers.items())
        return f"<Result {self.id} [{self.kind}]: {parts}>"


def _format(fmt: str) -> Any:
    from .render import formats

    if fmt not in formats.REGISTRY:
        raise ValueError(f"unknown format {fmt!r}: one of {', '.join(formats.NAMES)}")
    return formats.get(fmt)


def document(results: list[Result], fmt: str = "text", *, standalone: bool = False,
             pieces: list[str | None] | None = None, scripts: Iterable[str] = ()) -> str:
    """Several solved problems as one output of ``fmt``, as ``gyro solve --format FMT``
    prints them: one after another, or one document (html: a page with a contents list;
    latex with ``standalone``: a document pdflatex compiles). ``pieces``: each result's
    `Result.render`, when already made; ``scripts``: inline scripts the page may run."""
    output = _format(fmt)
    if pieces is None:
        level = 1 if len(results) == 1 else 2
        pieces = [None if standalone else r.render(fmt, level) for r in results]
    return output.document(results, pieces, standalone, tuple(scripts))


def solve(source: Source, /, *, units: str | None = None, **given: Any) -> Result:
    """Solve a problem: a path, YAML text, or a mapping with the file's keys.

    ``given`` replaces keys of the problem's ``given`` (``spin="2000 rpm"``,
    ``spin=pint_quantity``, ``spin=209.4`` in SI; ``None`` removes the key).
    ``units="us"`` works it in slug, ft and lbf. Raises `InputError` (with ``key``,
    ``line`` and ``file``) for bad input, as the command exits 2.
    """
    _units_known(units)
    return _solved(load(source, **given), units)


def solve_file(path: str, /, *, units: str | None = None, **given: Any) -> Result:
    """`solve` for a file's path (a string here is never read as YAML text): what
    ``gyro solve FILE`` runs."""
    _units_known(units)
    return _solved(load(path, path=True, **given), units)


def _units_known(units: str | None) -> None:
    if units is not None and str(units).lower() not in ("si", "us"):
        raise InputError(f"expected si or us, got {units!r}", key="units")


def _solved(problem: Problem, units: str | None) -> Result:
    """The Result of a loaded problem worked in ``units``."""
    from .solving.solve import solve as solve_problem

    return Result(solve_problem(problem), units)


def registry() -> Any:
    """gyro's pint registry (Hz on a rate is revolutions per second), for Quantities
    that mean what gyro means: ``u = gyro_cli.registry(); gyro_cli.solve(p, spin=30 *
    u.Hz)``."""
    from .core import units

    return units.registry()


# ---- sweeps --------------------------------------------------------------------------

class Point:
    """One solve of a sweep: the values given, and the result or the error."""

    __slots__ = ("given", "result", "error")

    def __init__(self, given: dict[str, Any], result: Result | None = None,
                 error: InputError | None = None) -> None:
        self.given, self.result, self.error = given, result, error

    def __repr__(self) -> str:
        return f"<Point {self.given}: {self.result!r}>" if self.error is None else \
            f"<Point {self.given}: InputError {self.error.message!r}>"


class Sweep:
    """Solves of one problem over a grid of given values; `records` gives rows for a
    table (``pandas.DataFrame(sweep.records())``)."""

    def __init__(self, points: list[Point] | None = None) -> None:
        self.points: list[Point] = list(points or [])

    def __repr__(self) -> str:
        bad = sum(p.error is not None for p in self.points)
        return f"<Sweep of {len(self.points)} points, {bad} not solved>"

    def __iter__(self) -> Iterator[Point]:
        return iter(self.points)

    def __len__(self) -> int:
        return len(self.points)

    @property
    def results(self) -> list[Result | None]:
        return [p.result for p in self.points]

    def records(self) -> list[dict[str, Any]]:
        """One dict per point: each swept key as given and in SI (``spin``, ``spin_si``),
        each answer's value(s) in the unit asked for (``precession_slow``,
        ``precession_fast``, ``min_spin``), and ``error`` (None, or the message)."""
        rows = []
        for point in self.points:
            row: dict[str, Any] = {}
            for key, value in point.given.items():
                row[key] = str(value) if _is_quantity(value) else value
                if point.result is not None:
                    si = point.result.problem.given.values.get(key)
                    row[f"{key}_si"] = si
            if point.result is not None:
                for name, answer in point.result.answers.items():
                    if len(answer.values) == 1:
                        row[name] = answer.values[0]
                        continue
                    for i, v in enumerate(answer.values):
                        label = answer.labels[i] if i < len(answer.labels) and \
                            answer.labels[i] else str(i + 1)
                        row[f"{name}_{label}"] = v
            row["error"] = None if point.error is None else point.error.message
            rows.append(row)
        return rows

    def _repr_html_(self) -> str:
        """The records as an HTML table (Jupyter without pandas)."""
        from html import escape

        from .core.work import num

        rows = self.records()
        columns: list[str] = []
        for row in rows:
            columns += [c for c in row if c not in columns]
        columns = [c for c in columns if c != "error"] + ["error"]
        units = self.units()

        def cell(value: Any) -> str:
            if value is None:
                return ""
            if isinstance(value, float):
                return num(value)
            return escape(str(value))

        def head(column: str) -> str:
            unit = units.get(column) or units.get(column.rsplit("_", 1)[0])
            return escape(column) + (f" ({escape(unit)})" if unit else "")

        body = "".join("<tr>" + "".join(f"<td>{cell(row.get(c))}</td>" for c in columns)
                       + "</tr>" for row in rows)
        return ('<table class="gyro-sweep"><thead><tr>'
                + "".join(f'<th scope="col">{head(c)}</th>' for c in columns)
                + f"</tr></thead><tbody>{body}</tbody></table>")

    def units(self) -> dict[str, str | None]:
        """The unit of each answer column of `records`."""
        out: dict[str, str | None] = {}
        for result in self.results:
            if result is None:
                continue
            for name, answer in result.answers.items():
                out[name] = answer.unit
        return out


def sweep(source: Source, /, *, units: str | None = None, **values: Iterable[Any]) -> Sweep:
    """Solve ``source`` at every combination of the given values:
    ``sweep("top.yaml", spin=[f"{s} rpm" for s in range(1000, 3001, 250)])``.

    A point that cannot be solved (a spin below the least one) is kept with its
    error; the sweep goes on.
    """
    names = list(values)
    grids = [_grid(name, values[name]) for name in names]
    out = Sweep()
    for combo in itertools.product(*grids):
        given = dict(zip(names, combo))
        try:
            out.points.append(Point(given, solve(source, units=units, **given)))
        except InputError as err:
            out.points.append(Point(given, error=err))
    return out


def _grid(name: str, values: Any) -> list[Any]:
    """The values swept for one key: a list, a tuple, a range, a generator or a 1-d
    array (numpy's, or a pint Quantity of one); InputError naming the key otherwise."""
    key = f"given.{name}"
    if isinstance(values, (str, bytes, Mapping)) or values is None:
        raise InputError(f"expected the values to sweep (a list or a 1-d array), got "
                         f"{type(values).__name__} {values!r:.40}", key=key)
    ndim = getattr(values, "ndim", 1)
    if ndim != 1:
        raise InputError(f"expected a list or a 1-d array of values to sweep, got a "
                         f"{ndim}-d array", key=key)
    try:
        return list(values)
    except TypeError:
        raise InputError(f"expected the values to sweep (a list or a 1-d array), got "
                         f"{type(values).__name__} {values!r:.40}", key=key) from None


# ---- checking ----------------------------------------------------------------------

class CheckReport:
    """What ``gyro check`` finds: ``problems`` (one ProblemCheck per file), ``passed``,
    ``exit_code``, `to_dict` (the JSON of ``--format json``); in Jupyter the table,
    failing answers first, each linking to its worked answer."""

    def __init__(self, run: CheckRun, worked: dict[str, _Solved]) -> None:
        self.run = run
        self.worked = worked

    @property
    def problems(self) -> list[ProblemCheck]:
        return list(self.run.problems)

    @property
    def exit_code(self) -> int:
        return self.run.exit_code

    @property
    def passed(self) -> bool:
        return self.run.exit_code == 0

    @property
    def counts(self) -> dict[str, int]:
        return self.run.counts()

    def to_dict(self) -> dict[str, Any]:
        from .render import check_report

        return check_report.as_dict(self.run)

    def html(self, page: bool = True) -> str:
        from .render import html

        if page:
            return html.check_page(self.run, self.worked)
        return html.check_body(self.run, self.worked, level=3)

    def _repr_html_(self) -> str:
        from .render import html

        return f"<div class=\"gyro\"><style>{html.STYLE}</style>{self.html(page=False)}</div>"

    def __str__(self) -> str:
        from .render import check_report

        return check_report.table(self.run)

    def __repr__(self) -> str:
        from .render import check_report

        return f"<CheckReport {check_report.summary_line(self.run)}>"


def check(*sources: Source, strict: bool = False, worked: bool = True) -> CheckReport:
    """Compare problems with their ``expected`` answers, as ``gyro check`` does: paths
    (files, directories, globs), YAML text or mappings. ``worked``: also keep each
    problem's worked answer (for the HTML report's links)."""
    from .checking import check as checking
    from .checking.results import CheckRun

    paths = [os.fspath(s) for s in sources if isinstance(s, os.PathLike) or
             isinstance(s, str) and "\n" not in s and not s.lstrip().startswith("{")]
    report = check_files(paths, strict=strict, worked=worked)
    problems, solved = list(report.run.problems), report.worked
    for source in sources:
        if isinstance(source, os.PathLike) or isinstance(source, str) and \
                os.fspath(source) in paths:
            continue
        try:
            problem = load(source)
        except InputError as err:
            from .checking.results import ProblemCheck

            problems.append(ProblemCheck(err.file or "<input>", status="error",
                                         error=str(err)))
            continue
        try:
            result = checking.check_problem(problem, strict=strict)
        except InputError as err:
            from .checking.results import ProblemCheck

            err.located(file=problem.file, line=problem.line(err.key))
            result = ProblemCheck(problem.file, problem.id, problem.title, problem.kind.name,
                                  status="error", error=str(err))
        problems.append(result)
        if worked and result.status != "error":
            key = problem.file if problem.file not in solved else f"{problem.file}#{len(solved)}"
            _keep(solved, key, lambda problem=problem: problem)
            result.file = key
    return CheckReport(CheckRun(problems, strict=strict), solved)


def check_files(paths: Iterable[str], /, *, strict: bool = False,
                worked: bool = True) -> CheckReport:
    """`check` for paths only (files, directories, globs; a string is never YAML text),
    all in this process, without a time limit."""
    from .checking import check as checking
    from .checking.results import CheckRun

    solved: dict[str, _Solved] = {}
    files, problems = checking.collect(list(paths))  # what names nothing first, as gyro check
    for path, result in zip(files, checking.checks(files, strict, timeout=None)):
        problems.append(result)
        if worked and result.status != "error":
            _keep(solved, path, lambda path=path: load(path, path=True))
    return CheckReport(CheckRun(problems, strict=strict), solved)


class CheckStream:
    """A check run as it goes (what ``gyro check PATHS`` prints): ``results``, each file's
    result (``then`` of its ProblemCheck) in the files' order as soon as it is known;
    ``tally``, the counts and exit code of what the caller has counted; ``shards``, (K, N)
    of a shard; ``report``, the CheckReport with the worked answers (``worked=True``).
    ``close()`` ends the worker processes of a run left early."""

    def __init__(self, results: Iterator[Any], strict: bool, shards: tuple[int, int] | None,
                 report: CheckReport | None = None, close: Any = None) -> None:
        from .checking.results import Tally

        self.results, self.shards, self.report = results, shards, report
        self.tally = Tally(strict)
        self._close = close

    def close(self) -> None:
        if self._close is not None:
            self._close()


def check_stream(paths: Iterable[str], /, *, strict: bool = False, jobs: int = 1,
                 timeout: float | None = 60.0, shard: str | None = None, merge: bool = False,
                 worked: bool = False, then: Any = None, idle: Any = None,
                 found: tuple[list[str], list[tuple[str, str]]] | None = None) -> CheckStream:
    """Check problem files (files, directories, globs) over ``jobs`` worker processes,
    each file under ``timeout`` seconds; ``shard`` "K/N" checks the K-th of N parts;
    ``merge`` joins the JSON reports ``paths`` of a sharded run instead. ``then(problem)``
    is applied where each file was checked (a worker hands back the caller's report text);
    ``idle()`` is called while the next result is not ready. ``worked``: checked in this
    process, keeping the worked answers (``report``). ``found``: ``problem_files(paths)``
    when the caller has it. InputError for a bad path, shard or report."""
    from itertools import chain

    from .checking import check as checking

    then = then or (lambda problem: problem)
    if merge:
        return CheckStream(map(then, checking.merged(list(paths), strict)), strict, None)
    files, missing = checking.collect(list(paths), found)
    shards = None
    if shard:
        k, n = shards = checking.parse_shard(shard)
        files = [f for f in files if checking.shard_of(f, n) == k]
        missing = [m for m in missing if checking.shard_of(m.file, n) == k]
    if worked:  # the page needs every worked answer: checked here, kept
        report = check_files([m.file for m in missing] + files, strict=strict)
        return CheckStream(map(then, report.run.problems), strict, shards, report)
    # each file's report text is made where it is checked: in the workers
    checked = checking.checks(files, strict, jobs, timeout, then=then, idle=idle)
    return CheckStream(chain(map(then, missing), checked), strict, shards, close=checked.close)


def grade(sheet: str, paths: Iterable[str], /, *, assignment: str | None = None,
          credit: str | None = None, student: str | None = None,
          reveal: bool = False, decimal_comma: bool = False, hints: bool = True) -> Graded:
    """Grade the answer sheet ``sheet`` (a CSV of students' answers) against the problems
    under ``paths``, or each student's own variant by ``assignment``, as ``gyro check
    --answers`` does; ``credit`` "SLIP=SHARE,..." gives part credit for a known slip;
    ``decimal_comma``: the class writes ``965,4`` for 965.4; ``hints=False`` (``--no-hints``):
    each row's ``feedback`` says only whether a value is right."""
    from .checking import grades

    policy = grades.parse_credit(credit) if credit is not None else None
    graded = grades.grade(sheet, list(paths), assignment=assignment, credit=policy,
                          student=student, reveal=reveal, decimal_comma=decimal_comma)
    return graded if hints else grades.withhold_hints(graded)


def _keep(solved: dict, key: str, problem_of) -> None:
    """The worked answer of a checked problem, its expected answers among its answers."""
    from .solving.solve import solve_asking

    try:
        problem = problem_of()
        solved[key] = solve_asking(problem, problem.expected)
    except InputError:
        pass


# ---- kinds ---------------------------------------------------------------------------

def kinds() -> dict[str, Kind]:
    """Every problem kind by name (what ``gyro kinds`` lists): its ``summary``, ``params``
    (the given keys; ``uses_body`` adds the body's keys), ``answers`` and ``chapter``."""
    from .kinds import get as kind_named
    from .kinds import names as kind_names

    return {name: kind_named(name) for name in kind_names()}
