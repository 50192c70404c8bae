"""Mutated problem files for the fuzz run (fuzz.py) and the property tests.

``mutant(rng, base)`` takes a bundled problem (its parsed mapping) and returns
(YAML text, description of what was done). The mutations are those a careless
or hostile user makes: keys deleted, swapped, duplicated or misspelt; values of
every YAML type (dates, ``0x`` numbers, tags, 5000-digit integers, lists,
mappings); unit strings from a small grammar, valid and near-miss; extreme
magnitudes (1e308, denormals); damaged YAML (cut, stray characters, deep
nesting, alias bombs).
"""

from __future__ import annotations

import copy
import json
import random
from typing import Any

import yaml


class Raw(str):
    """A YAML fragment written as is (a tag, a 0x number, a date)."""


UNITS = {
    "length": ["m", "mm", "cm", "in", "ft", "km", "um"],
    "mass": ["kg", "g", "lb", "slug", "oz", "tonne"],
    "force": ["N", "kN", "lbf", "ozf", "kgf"],
    "rate": ["rpm", "rad/s", "rev/s", "Hz", "deg/s", "rev/min", "1/s"],
    "angle": ["deg", "rad", "degree", "arcmin", "turn"],
    "inertia": ["kg*m^2", "kg m^2", "slug*ft^2", "g*cm^2", "lb*in^2"],
    "moment": ["N*m", "N m", "lbf*ft", "kN*m", "ozf*in"],
    "speed": ["m/s", "ft/s", "km/h", "mph"],
    "time": ["s", "ms", "min", "h"],
    "acceleration": ["m/s^2", "ft/s^2", "g0"],
    "dimensionless": ["", "percent"],
}
ALL_UNITS = sorted({u for us in UNITS.values() for u in us if u})
NEAR_MISSES = [
    "N*m*", "N*()", "(N*m", "N*m)", "N**", "m^", "m^^2", "m**99", "m^-", "kg m^2^2",
    "rpm relative to the precessing frame psidot, see notes", "rmp", "radian/sec/", "m/", "/s",
    "1/", "kg*", "**2", "m^2.5", "m ** 2 ** 2", "°", "µm", "Ω", "deg deg", "rad/s # note",
    "rpm,", "N·m", "N.m", "kg·m²", "m²", "(" * 30 + "m" + ")" * 30, "m" * 200, "m/s/s/s/s",
    "1e3", "e", "_", "__init__", "m to ft", "9**9**9", "m;", "s\tN", "N\n", "rad/s * 0",
]


def unit_text(rng: random.Random, dimension: str | None) -> str:
    """A unit from the grammar: a valid one of the dimension, another, a product, or a near miss."""
    roll = rng.random()
    if dimension in UNITS and roll < 0.45:
        return rng.choice(UNITS[dimension])
    if roll < 0.6:
        return rng.choice(ALL_UNITS)
    if roll < 0.75:
        parts = [rng.choice(ALL_UNITS) for _ in range(rng.randint(1, 3))]
        text = parts[0]
        for part in parts[1:]:
            text += rng.choice(["*", "/", " ", " * ", " / "]) + part
        if rng.random() < 0.3:
            text += rng.choice(["^2", "^-1", "**3", "^ 2", "^+2"])
        if rng.random() < 0.2:
            text = f"({text})" + rng.choice(["", "^2", "/s"])
        return text
    return rng.choice(NEAR_MISSES)


def number_text(rng: random.Random) -> str:
    roll = rng.random()
    if roll < 0.4:
        return f"{rng.uniform(-1000, 1000):.{rng.randint(0, 6)}g}"
    if roll < 0.55:
        return rng.choice(["0", "-0", "0.0", "1", "-1", "1e308", "-1e308", "1.8e308", "1e-320",
                           "5e-324", "2.2e-308", "1e-300", "1e300", "1e200", "1e-200", ".5", "5.",
                           "+3", "1e999", "-1e-999"])
    if roll < 0.8:
        return f"{rng.uniform(1, 10):.3g}e{rng.randint(-330, 330)}"
    return f"{rng.randint(-10**6, 10**6)}"


def quantity(rng: random.Random, dimension: str | None) -> str:
    unit = unit_text(rng, dimension)
    number = number_text(rng)
    return f"{number} {unit}".strip() if rng.random() < 0.9 else f"{number}{unit}"


def yaml_value(rng: random.Random, dimension: str | None = None, depth: int = 0) -> Any:
    """A value of any YAML type, or a quantity string (often of the right dimension)."""
    roll = rng.random()
    if roll < 0.45:
        return quantity(rng, dimension)
    if roll < 0.55:
        return rng.choice([True, False, None, 0, 1, -1, 3.5, 1e308, -1e-320, float("inf"),
                           float("nan"), "", " ", "yes", "no", "~", "null", "NaN", "inf",
                           "-inf", "1e309 m", "nan m", "inf rpm"])
    if roll < 0.7:
        return Raw(rng.choice([
            "2024-02-31", "2024-02-29", "2001-12-14t21:59:43.10-05:00", "0x1F", "0xZZ", "0o17",
            "0b101", "1_000", "1:30", "190:20:30", "!!bool maybe", "!!bool yes", "!!int 0x",
            "!!int abc", "!!float abc", "!!binary '@@@'", "!!binary aGVsbG8=", "!!set {a, b}",
            "!!omap [a: 1]", "!!timestamp 2024-02-31", "!!str 5 m", "!!null ''", "!!python/object:os.system ls",
            "!foo bar", "&x 5 m", "*undefined", "'" + "9" * 5000 + "'", "9" * 5000, "9" * 320,
            "-" + "9" * 310, ".inf", "-.inf", ".nan", ".NaN", "'\\u0000'", '"\\x00 m"',
            '"5 m\\nfoo"', '"\\t5 m"', "|\n    5 m\n    more", "{}", "[]", "[[]]", "{a: {b: {c: 1}}}",
        ]))
    if roll < 0.8 and depth < 3:
        return [yaml_value(rng, dimension, depth + 1) for _ in range(rng.randint(0, 3))]
    if roll < 0.87 and depth < 3:
        return {key_text(rng, ["a", "value", "unit"]): yaml_value(rng, dimension, depth + 1)
                for _ in range(rng.randint(0, 2))}
    if roll < 0.95:
        return rng.choice(["x" * rng.choice([1, 99, 100, 101, 5000]), "é", "🙂 rpm", "\u202e5 m",
                           "5 m # comment", "5 m\n", "12 34 m", "5 m m", "- 5 m", "five metres"])
    return rng.randint(-10**18, 10**18)


def key_text(rng: random.Random, names: list[str]) -> Any:
    name = rng.choice(names) if names else "x"
    roll = rng.random()
    if roll < 0.6:
        return name
    if roll < 0.75 and len(name) > 2:
        i = rng.randrange(len(name))
        return name[:i] + name[i + 1:] if rng.random() < 0.5 else name[:i] + name[i] + name[i:]
    return rng.choice([name.upper(), name + "\n", "a\nb", name + " ", 5, True, None, 1.5,
                       "", "é", name + "\t", "[x]", Raw("[a, b]"), Raw("{a: 1}"), Raw("? [a]")])


def scalar(value: Any) -> str:
    if isinstance(value, Raw):
        return str(value)
    if isinstance(value, float):
        if value != value:
            return ".nan"
        if value in (float("inf"), float("-inf")):
            return ".inf" if value > 0 else "-.inf"
        return repr(value)
    if isinstance(value, str):
        return json.dumps(value)  # a JSON string is a YAML double-quoted scalar
    text = yaml.safe_dump(value, default_flow_style=True, width=10**9).strip()
    return text[:-4].strip() if text.endswith("\n...") else text.removesuffix("...").strip()


def emit(data: Any, indent: int = 0) -> str:
    """Block-style YAML that keeps Raw fragments (tags, 0x numbers) as written."""
    pad = "  " * indent
    if isinstance(data, dict):
        if not data:
            return pad + "{}\n"
        out = []
        for key, value in data.items():
            head = f"{pad}{scalar(key) if not isinstance(key, Raw) else key}:"
            if isinstance(value, dict) and value:
                out.append(head + "\n" + emit(value, indent + 1))
            elif isinstance(value, list) and value:
                out.append(head + "\n" + emit(value, indent + 1))
            else:
                out.append(head + " " + (scalar(value) if not isinstance(value, (dict, list))
                                         else ("{}" if isinstance(value, dict) else "[]"))
                           + "\n")
        return "".join(out)
    if isinstance(data, list):
        if not data:
            return pad + "[]\n"
        out = []
        for value in data:
            if isinstance(value, (dict, list)) and value:
                out.append(f"{pad}-\n" + emit(value, indent + 1))
            else:
                out.append(f"{pad}- " + (scalar(value) if not isinstance(value, (dict, list))
                                        else ("{}" if isinstance(value, dict) else "[]")) + "\n")
        return "".join(out)
    return pad + scalar(data) + "\n"


def _dimension_of(kind: Any, section: str, key: str) -> str | None:
    if kind is None:
        return None
    from gyro_cli.solving.problem import params_of

    if section == "given":
        for p in params_of(kind):
            if p.name == key:
                return p.dimension if p.dimension != "word" else None
    else:
        answer = kind.answer(key)
        return answer.dimension if answer else None
    return None


def mutate_data(rng: random.Random, data: dict) -> tuple[dict, str]:
    """One structural or value mutation of a problem mapping."""
    from gyro_cli import kinds

    data = copy.deepcopy(data)
    try:
        kind = kinds.get(data.get("kind"))
    except Exception:
        kind = None
    sections = [s for s in ("given", "find", "expected", "tolerance") if isinstance(data.get(s), dict)]
    roll = rng.random()
    if roll < 0.3 and sections:  # a value of a given, find or expected key
        section = rng.choice(sections)
        names = list(data[section]) or ["x"]
        key = rng.choice(names)
        dimension = _dimension_of(kind, section, str(key))
        if section == "find":
            data[section][key] = unit_text(rng, dimension) if rng.random() < 0.7 else \
                yaml_value(rng, dimension)
        else:
            data[section][key] = yaml_value(rng, dimension)
        return data, f"{section}.{key} = {str(data[section][key])[:80]!r}"
    if roll < 0.4 and sections:  # add a key of the kind's spec with a value
        section = rng.choice([s for s in sections if s != "tolerance"] or sections)
        if kind is not None and section == "given":
            from gyro_cli.solving.problem import params_of

            params = params_of(kind)
            param = rng.choice(params)
            data[section][param.name] = (rng.choice(param.choices) if param.choices and
                                         rng.random() < 0.5 else
                                         yaml_value(rng, param.dimension))
            return data, f"given.{param.name} added"
        if kind is not None:
            answer = rng.choice(kind.answers)
            data[section][answer.name] = (unit_text(rng, answer.dimension) if section == "find"
                                          else yaml_value(rng, answer.dimension))
            return data, f"{section}.{answer.name} added"
    if roll < 0.5:  # delete a key
        where = data
        if sections and rng.random() < 0.6:
            where = data[rng.choice(sections)]
        if where:
            key = rng.choice(list(where))
            del where[key]
            return data, f"deleted {key!r}"
    if roll < 0.58 and sections:  # swap two values
        section = rng.choice(sections)
        keys = list(data[section])
        if len(keys) >= 2:
            a, b = rng.sample(keys, 2)
            data[section][a], data[section][b] = data[section][b], data[section][a]
            return data, f"swapped {section}.{a} and {b}"
    if roll < 0.66:  # rename a key
        where = data[rng.choice(sections)] if sections and rng.random() < 0.6 else data
        if where:
            key = rng.choice(list(where))
            new = key_text(rng, [str(key)])
            value = where.pop(key)
            try:
                where[new] = value
            except TypeError:
                where[str(new)] = value
            return data, f"renamed {key!r} to {new!r}"
    if roll < 0.74:  # a top-level value of another type
        key = rng.choice(["id", "kind", "given", "find", "expected", "tolerance", "title", "notes",
                          "source", "vary"])
        choices = [yaml_value(rng), [{"moment": "N*m"}], ["precession", {"a": 1}], "precession",
                   [], {}, None, rng.choice(list(kinds.names()) + ["gyroscopic", "rolling"])]
        if key == "tolerance":
            choices += ["1%", "3 sig", "0.01 rad/s", "1e-320 N", "0%", "100%", "1e309%", "-1%",
                        "20 sig", "0 sig", {"default": "2%"}, {"nope": "1%"}]
        data[key] = rng.choice(choices)
        return data, f"{key} = {str(data[key])[:80]!r}"
    if roll < 0.82 and sections:  # scale a number by a power of ten
        section = rng.choice([s for s in sections if s in ("given", "expected")] or sections)
        keys = [k for k, v in data[section].items() if isinstance(v, str)]
        if keys:
            key = rng.choice(keys)
            parts = data[section][key].split(None, 1)
            try:
                number = float(parts[0]) * 10.0 ** rng.randint(-320, 320)
            except (ValueError, OverflowError, IndexError):
                number = 1e308
            data[section][key] = f"{number!r} {parts[1] if len(parts) > 1 else ''}".strip()
            return data, f"{section}.{key} scaled to {data[section][key]!r}"
    if roll < 0.9 and sections:  # a list of values (roots)
        section = rng.choice(sections)
        if data[section]:
            key = rng.choice(list(data[section]))
            dimension = _dimension_of(kind, section, str(key))
            data[section][key] = [quantity(rng, dimension) for _ in range(rng.randint(0, 4))]
            return data, f"{section}.{key} = a list"
    # a whole problem of another kind's keys
    data["kind"] = rng.choice(list(kinds.names()))
    return data, f"kind = {data['kind']}"


def damage(rng: random.Random, text: str) -> tuple[str, str]:
    """Damage the YAML text itself."""
    roll = rng.random()
    if roll < 0.2 and text:
        i = rng.randrange(len(text))
        return text[:i], f"cut at {i}"
    if roll < 0.4 and text:
        i = rng.randrange(len(text))
        c = rng.choice(["\t", ":", "{", "[", "]", "}", "&a", "*a", "!", "%", "@", "`", "|", ">",
                        "'", '"', "#", "\x00", "\ufeff", "\u2028", "- ", "? ", "\n  ", "\\"])
        return text[:i] + c + text[i:], f"inserted {c!r} at {i}"
    if roll < 0.5 and text:
        lines = text.splitlines(True)
        i = rng.randrange(len(lines))
        lines.insert(i, lines[i])
        return "".join(lines), f"duplicated line {i + 1}"
    if roll < 0.6:
        depth = rng.choice([10, 63, 64, 65, 200, 5000, 100_000])
        key = rng.choice(["kind", "given", "vary", "notes", "zz"])
        nested = "[" * depth + "]" * depth if rng.random() < 0.5 else \
            "{a: " * depth + "1" + "}" * depth
        return text + f"\n{key}: {nested}\n", f"nested {depth} deep in {key}"
    if roll < 0.7:
        depth = rng.choice([5, 9, 12])
        bomb = "a0: &a0 [lol, lol, lol, lol, lol, lol, lol, lol, lol]\n" + "".join(
            f"a{i}: &a{i} [{', '.join([f'*a{i - 1}'] * 9)}]\n" for i in range(1, depth))
        return bomb + text, f"alias bomb {9 ** depth:.0e}"
    if roll < 0.8:
        return rng.choice(["", "---\n", "--- a\n--- b\n", "[]", "5", "~", "? a\n", "a: b: c",
                           "\ufeff" + text, text.replace("\n", "\r\n"), text + "\n---\n" + text,
                           text.replace("  ", "\t")]), "whole document replaced"
    if roll < 0.9 and text:
        i = rng.randrange(len(text))
        return text[:i] + text[i + 1:], f"deleted a character at {i}"
    return text + "\n" + rng.choice(["x: &x [*x]", "given: *nope", "<<: {a: 1}", "? [a, b]\n: 1",
                                     "id: !!binary aGVsbG8=", "find: [{a: b}]"]) + "\n", \
        "appended a bad key"


def mutant(rng: random.Random, base: dict) -> tuple[str, str]:
    """A mutated problem file: 1-3 mutations of the data, sometimes damaged text."""
    data, what = base, []
    for _ in range(rng.choice([1, 1, 1, 2, 3])):
        data, done = mutate_data(rng, data)
        what.append(done)
    try:
        text = emit(data)
    except Exception:  # an unemittable mutation: fall back to PyYAML
        text = yaml.safe_dump(json.loads(json.dumps(data, default=str)))
    if rng.random() < 0.2:
        text, done = damage(rng, text)
        what.append(done)
    return text, "; ".join(what)
