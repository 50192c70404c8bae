"""Records: dataclasses that cost nothing to define.

``@dataclass`` compiles an ``__init__``, ``__repr__`` and ``__eq__`` (and more when
frozen) for every class when its module is imported: about 0.5 ms a class, and the
fifteen classes a ``gyro solve`` imports were a tenth of its time. ``@record``
makes the same class without compiling anything: the fields are real
``dataclasses.Field`` objects (so ``dataclasses.replace``, ``fields``, ``asdict``
and ``is_dataclass`` work as before), ``__init__``, ``__repr__`` and ``__eq__`` are
shared functions that read the fields (``__post_init__`` is called, as
``@dataclass`` calls it). A class made often keeps its speed by
writing its own ``__init__`` (kept, as ``@dataclass`` keeps one).

``frozen=True`` makes instances hashable by their fields, as a frozen dataclass
is; it does not forbid assignment (nothing in gyro assigns to one).

``dataclasses`` itself (and ``copy``, which it imports) is imported only when a
record's ``__dataclass_fields__`` is first read, by ``dataclasses.fields`` and the
like: about 1.5 ms that a ``gyro solve`` never needs.
"""

from __future__ import annotations

import sys
from typing import Any, TypeVar, dataclass_transform

__all__ = ["record", "field"]

_T = TypeVar("_T", bound=type)


class _Missing:
    """No default: dataclasses.MISSING, before dataclasses is imported."""

    def __repr__(self) -> str:
        return "MISSING"


MISSING: Any = _Missing()


def _theirs(dataclasses: Any, value: Any) -> Any:
    """``value`` with this module's MISSING as dataclasses' own."""
    return dataclasses.MISSING if value is MISSING else value


def _ours(dataclasses: Any, value: Any) -> Any:
    """``value`` with dataclasses' MISSING as this module's."""
    return MISSING if value is dataclasses.MISSING else value


class _Field:
    """What ``field()`` says of a field (its default or default factory), until
    dataclasses is imported."""

    __slots__ = ("default", "default_factory")

    def __init__(self, default: Any, default_factory: Any) -> None:
        self.default, self.default_factory = default, default_factory


def field(*, default: Any = MISSING, default_factory: Any = MISSING) -> Any:
    """A record's field with a default or a default factory, as ``dataclasses.field``
    (whose Field it is once dataclasses is imported: a @dataclass may use it too)."""
    if default is not MISSING and default_factory is not MISSING:
        raise ValueError("cannot specify both default and default_factory")
    dataclasses = sys.modules.get("dataclasses")
    if dataclasses is not None:
        return dataclasses.field(default=_theirs(dataclasses, default),
                                 default_factory=_theirs(dataclasses, default_factory))
    return _Field(default, default_factory)


class _Fields:
    """A record's ``__dataclass_fields__``: its ``dataclasses.Field`` objects, made (and
    dataclasses imported) when first read."""

    def __init__(self, spec: dict[str, tuple[Any, Any, Any]]) -> None:
        self.spec = spec  # name -> (type, default, factory)
        self.made: dict | None = None

    def __get__(self, instance: Any, owner: type) -> dict:
        if self.made is None:
            import dataclasses

            made = {}
            for name, (type_, default, factory) in self.spec.items():
                one: Any = dataclasses.field(default=_theirs(dataclasses, default),
                                             default_factory=_theirs(dataclasses, factory))
                # the marker dataclasses.fields() keeps a field by
                one.name, one.type = name, type_
                one._field_type = dataclasses._FIELD  # type: ignore[attr-defined]
                made[name] = one
            self.made = made
        return self.made


def _init_spec(cls: type) -> tuple[tuple[str, Any, Any], ...]:
    return tuple((name, default, factory)
                 for name, (_, default, factory) in cls.__record_fields__.items())  # type: ignore[attr-defined]


# A class made this many times gets a compiled __init__ (what @dataclass writes): a
# solve makes most records once or twice, a checked bank thousands of times.
COMPILE_AFTER = 40


def _compiled_init(spec: tuple[tuple[str, Any, Any], ...], post_init: bool) -> Any:
    """The ``__init__`` @dataclass would write for these fields."""
    env: dict[str, Any] = {"MISSING": MISSING}
    params, lines = [], []
    for name, default, factory in spec:
        if default is not MISSING:
            env["_d_" + name] = default
            params.append(f"{name}=_d_{name}")
            lines.append(f"self.{name} = {name}")
        elif factory is not MISSING:
            env["_f_" + name] = factory
            params.append(f"{name}=MISSING")
            lines.append(f"self.{name} = _f_{name}() if {name} is MISSING else {name}")
        else:
            params.append(name)
            lines.append(f"self.{name} = {name}")
    if post_init:
        lines.append("self.__post_init__()")
    source = f"def __init__(self, {', '.join(params)}):\n    " + "\n    ".join(lines or ["pass"])
    exec(source, env)  # noqa: S102 - field names of gyro's own classes, never user text
    return env["__init__"]


def _init(self: Any, *args: Any, **kwargs: Any) -> None:
    """The generated ``__init__`` of a dataclass, read from the fields."""
    cls = type(self)
    spec = cls.__record_init__
    calls = cls.__dict__.get("__record_calls__", 0) + 1
    cls.__record_calls__ = calls
    if calls == COMPILE_AFTER and cls.__dict__.get("__init__") is _init:
        cls.__init__ = _compiled_init(spec, hasattr(cls, "__post_init__"))
    if len(args) > len(spec):
        raise TypeError(f"{type(self).__name__}() takes {len(spec)} positional arguments "
                        f"but {len(args)} were given")
    for i, (name, default, factory) in enumerate(spec):
        if i < len(args):
            if name in kwargs:
                raise TypeError(f"{type(self).__name__}() got multiple values for {name!r}")
            value = args[i]
        elif name in kwargs:
            value = kwargs.pop(name)
        elif default is not MISSING:
            value = default
        elif factory is not MISSING:
            value = factory()
        else:
            raise TypeError(f"{type(self).__name__}() missing argument {name!r}")
        setattr(self, name, value)
    if kwargs:
        raise TypeError(f"{type(self).__name__}() got an unexpected keyword argument "
                        f"{next(iter(kwargs))!r}")
    post_init = getattr(self, "__post_init__", None)
    if post_init is not None:
        post_init()


def _values(self: Any) -> tuple:
    return tuple(getattr(self, name) for name in self.__record_fields__)


def _repr(self: Any) -> str:
    inner = ", ".join(f"{name}={getattr(self, name)!r}" for name in self.__record_fields__)
    return f"{type(self).__qualname__}({inner})"


def _eq(self: Any, other: Any) -> Any:
    if other.__class__ is not self.__class__:
        return NotImplemented
    return _values(self) == _values(other)


def _hash(self: Any) -> int:
    return hash(_values(self))


def _inherited(base: type) -> dict[str, tuple[Any, Any, Any]]:
    """The fields of a base class, a record's or a dataclass's, as (type, default, factory)."""
    if "__record_fields__" in base.__dict__:
        return base.__dict__["__record_fields__"]
    if "__dataclass_fields__" not in base.__dict__:
        return {}
    import dataclasses

    return {f.name: (f.type, _ours(dataclasses, f.default), _ours(dataclasses, f.default_factory))
            for f in dataclasses.fields(base)}


def _make(cls: _T, frozen: bool) -> _T:
    fields: dict[str, tuple[Any, Any, Any]] = {}  # name -> (type, default, factory)
    for base in reversed(cls.__mro__[1:]):  # a record's fields are inherited, as a dataclass's
        fields.update(_inherited(base))
    dataclasses = sys.modules.get("dataclasses")  # a field made by dataclasses.field
    for name, type_ in cls.__dict__.get("__annotations__", {}).items():
        if str(type_).startswith(("ClassVar", "typing.ClassVar")):
            continue
        default = cls.__dict__.get(name, MISSING)
        if isinstance(default, _Field) or (dataclasses and isinstance(default, dataclasses.Field)):
            value, factory = default.default, default.default_factory
            if dataclasses and isinstance(default, dataclasses.Field):
                value, factory = _ours(dataclasses, value), _ours(dataclasses, factory)
            if value is MISSING:
                delattr(cls, name)
            else:
                setattr(cls, name, value)
        else:
            value, factory = default, MISSING
        fields[name] = (type_, value, factory)
    setattr(cls, "__record_fields__", fields)
    setattr(cls, "__dataclass_fields__", _Fields(fields))
    setattr(cls, "__record_init__", _init_spec(cls))
    own = cls.__dict__
    if "__init__" not in own:
        setattr(cls, "__init__", _init)
    if "__repr__" not in own:
        setattr(cls, "__repr__", _repr)
    if "__eq__" not in own:
        setattr(cls, "__eq__", _eq)
        if "__hash__" not in own:
            setattr(cls, "__hash__", _hash if frozen else None)
    return cls


@dataclass_transform(field_specifiers=(field,))
def record(cls: Any = None, /, *, frozen: bool = False) -> Any:
    """``@record`` or ``@record(frozen=True)``: a dataclass without compiled methods."""
    def wrap(cls: _T) -> _T:
        return _make(cls, frozen)

    return wrap if cls is None else wrap(cls)
