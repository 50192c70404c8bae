"""Reading input a careless or hostile user wrote: limits before anything is built.

Two guards sit in front of every problem file and answer sheet:

- ``read_bytes`` reads only a regular file (a FIFO, a device such as
  ``/dev/zero``, a socket or a directory is refused at once, without reading or
  waiting), and never more than the size limit: it reads limit + 1 bytes and
  refuses if it got them, so a file that grows or lies about its size cannot
  make gyro read more.
- ``load`` parses YAML in two passes. The first walks the parser's events
  without building anything and refuses nesting deeper than ``MAX_DEPTH`` and
  documents whose aliases would expand to more than ``MAX_NODES`` values (a
  "billion laughs" bomb), or an alias inside its own anchor (a cycle). Only
  then is the document built, with a loader that keeps dates as text (YAML
  1.1 turns ``2024-02-31`` into a date, or an exception) and turns a value
  PyYAML cannot construct (``!!bool maybe``, ``!!int 0x``, a 5000-digit
  integer, ``!!map 1800 rpm``, a tag YAML does not know, ``!!python/...``, or
  ``!!binary``, ``!!set``, ``!!omap`` and ``!!pairs``, which no file needs) into
  a YAML error naming its key and line.
"""

from __future__ import annotations

import os
import re
import stat
from typing import Any

from .errors import InputError

MAX_DEPTH = 64          # nested mappings and lists; a problem file uses 3
MAX_NODES = 100_000     # values after alias expansion; a problem file has ~50
MAX_INT_DIGITS = 308    # beyond a double's range anyway

_KINDS = ((stat.S_ISFIFO, "a FIFO (named pipe)"), (stat.S_ISCHR, "a character device"),
          (stat.S_ISBLK, "a block device"), (stat.S_ISSOCK, "a socket"))


def _not_regular(mode: int, what: str) -> str:
    if stat.S_ISDIR(mode):
        return f"is a directory, expected {what}"
    name = next((text for test, text in _KINDS if test(mode)), "not a regular file")
    return f"is {name}, not a regular file; gyro reads only regular files"


# Read only, never waiting on a FIFO or a device, never taking a terminal as ours.
_OPEN_FLAGS = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_NOCTTY", 0) \
    | getattr(os, "O_BINARY", 0)


def read_bytes(path: str, limit: int, what: str = "a problem file (.yaml)") -> bytes:
    """The bytes of a regular file of at most ``limit`` bytes; InputError otherwise."""
    try:
        mode = os.stat(path).st_mode
    except FileNotFoundError:
        raise InputError("no such file", file=path) from None
    except (OSError, ValueError) as err:
        raise InputError(f"cannot read: {getattr(err, 'strerror', None) or err}",
                         file=path) from None
    if not stat.S_ISREG(mode):
        raise InputError(_not_regular(mode, what), file=path)
    try:
        fd = os.open(path, _OPEN_FLAGS)
    except OSError as err:
        raise InputError(f"cannot read: {err.strerror}", file=path) from None
    try:
        mode = os.fstat(fd).st_mode  # the file opened, not the one stat'ed before
        if not stat.S_ISREG(mode):
            raise InputError(_not_regular(mode, what), file=path)
        chunks = []
        left = limit + 1
        while left > 0:
            chunk = os.read(fd, min(left, 1 << 20))
            if not chunk:
                break
            chunks.append(chunk)
            left -= len(chunk)
    except OSError as err:
        raise InputError(f"cannot read: {err.strerror}", file=path) from None
    finally:
        os.close(fd)
    data = b"".join(chunks)
    if len(data) > limit:
        raise InputError(f"file is larger than {limit} bytes; not {what}", file=path)
    return data


def read_text(path: str, limit: int, what: str = "a problem file (.yaml)",
              encoding: str = "utf-8") -> str:
    data = read_bytes(path, limit, what)
    try:
        return data.decode(encoding)
    except UnicodeDecodeError:
        raise InputError("is not UTF-8 text", file=path) from None


# ---- YAML -------------------------------------------------------------------

_loader_class: Any = None


def loader_class() -> Any:
    """A safe loader: dates stay text, unconstructible scalars are YAML errors."""
    global _loader_class
    if _loader_class is not None:
        return _loader_class
    import yaml
    from yaml.constructor import ConstructorError

    base = getattr(yaml, "CSafeLoader", yaml.SafeLoader)

    class Loader(base):  # type: ignore[misc, valid-type]
        pass

    Loader.yaml_implicit_resolvers = {
        first: [(tag, regexp) for tag, regexp in resolvers
                if tag != "tag:yaml.org,2002:timestamp"]
        for first, resolvers in base.yaml_implicit_resolvers.items()}

    def guarded(method: Any, what: str) -> Any:
        def construct(self: Any, node: Any) -> Any:
            try:
                value = method(self, node)
            except ConstructorError:
                raise
            except Exception as err:  # ValueError, KeyError, binascii.Error, OverflowError
                text = " ".join(str(node.value)[:40].split())
                raise ConstructorError(None, None, f"cannot read {text!r} as {what} "
                                       f"({type(err).__name__})", node.start_mark) from None
            if isinstance(value, int) and not isinstance(value, bool) and \
                    value.bit_length() > MAX_INT_DIGITS * 3.33:
                raise ConstructorError(None, None, f"an integer of {len(str(node.value))} "
                                       "digits is out of range", node.start_mark)
            return value
        return construct

    for tag, what in (("int", "an integer"), ("float", "a number"), ("bool", "true/false"),
                      ("binary", "base64 data")):
        full = f"tag:yaml.org,2002:{tag}"
        Loader.add_constructor(full, guarded(base.yaml_constructors[full], what))
    Loader.add_constructor("tag:yaml.org,2002:timestamp",
                           lambda self, node: str(self.construct_scalar(node)))
    for tag in REFUSED_TAGS:
        Loader.add_constructor(f"tag:yaml.org,2002:{tag}", _refuse_tag)

    def construct_mapping(self: Any, node: Any, deep: bool = False) -> Any:
        # `!!map 1800 rpm` or `!!map [1]`: PyYAML's flatten_mapping would unpack the text
        # or the list as pairs (a ValueError, not a YAML error).
        if not isinstance(node, yaml.MappingNode):
            raise ConstructorError(None, None, f"expected a mapping node, but found {node.id}",
                                   node.start_mark)
        # A key is a name (a key of the format, a student, a problem id): an unquoted
        # `11.10:`, `011:`, `yes:` or `~:` keeps the characters written, not 11.1, 9, True, None.
        self.flatten_mapping(node)
        for key, _ in node.value:
            if isinstance(key, yaml.ScalarNode) and key.style in (None, "") and \
                    key.tag in _NAME_TAGS:
                key.tag = "tag:yaml.org,2002:str"
        return base.construct_mapping(self, node, deep)

    Loader.construct_mapping = construct_mapping

    # The tag of a plain scalar depends on its text alone (no path resolvers here), and a
    # bank of problems repeats the same texts (keys, kinds, units) in every file: each
    # is resolved once, not once per occurrence, which was a third of composing a file.
    # The table stops growing at _RESOLVED_MAX texts, so memory stays flat.
    # Without path resolvers, whatever is not a plain scalar gets its kind's default tag
    # (BaseResolver.resolve): answered here, without a second call, for every quoted or
    # block scalar, mapping and list of a file.
    resolved: dict[str, str] = {}
    resolve = base.resolve
    scalar, mapping, sequence = yaml.ScalarNode, yaml.MappingNode, yaml.SequenceNode
    text_tag, map_tag, seq_tag = (base.DEFAULT_SCALAR_TAG, base.DEFAULT_MAPPING_TAG,
                                  base.DEFAULT_SEQUENCE_TAG)

    def resolve_plain(self: Any, kind: Any, value: str, implicit: Any) -> str:
        if kind is scalar:
            if not implicit[0]:
                return text_tag
            tag = resolved.get(value)
            if tag is None:
                tag = resolve(self, kind, value, implicit)
                if len(resolved) < _RESOLVED_MAX:
                    resolved[value] = tag
            return tag
        if kind is mapping:
            return map_tag
        if kind is sequence:
            return seq_tag
        return resolve(self, kind, value, implicit)

    if not base.yaml_path_resolvers:
        Loader.resolve = resolve_plain
        # The composer calls these two around every node, and without path resolvers they
        # do nothing (BaseResolver): a builtin that takes the same arguments does nothing
        # faster than a Python function. (A slice of the parent node and the index, made
        # and dropped; an empty tuple.)
        Loader.descend_resolver = staticmethod(slice)
        Loader.ascend_resolver = staticmethod(tuple)
    _loader_class = Loader
    return Loader


_RESOLVED_MAX = 4096

# Tags YAML 1.1 allows that make a Python type no problem file or sheet has (bytes, a set,
# a list of pairs): refused at their line, like a tag YAML does not know.
REFUSED_TAGS = ("binary", "set", "omap", "pairs")


def _refuse_tag(self: Any, node: Any) -> Any:
    from yaml.constructor import ConstructorError

    raise ConstructorError(None, None, f"could not determine a constructor for the tag "
                           f"{node.tag!r}", node.start_mark)


def message(err: Any) -> str:
    """The text of a YAML error for a one-line message (without where it is)."""
    what = f"{getattr(err, 'problem', None) or getattr(err, 'context', None) or err}"
    if "python/" in what or "could not determine a constructor" in what:
        tag = what.rsplit("tag ", 1)[-1].strip("'")
        what = f"tag not allowed ({_short(tag)}); gyro reads plain YAML only (text, " \
            "numbers, true/false, null, lists and mappings)"
    elif "expected a" in what and " node, but found " in what:
        # `spin: !!map 1800 rpm`: the tag asks for another kind of value than is written
        wanted, found = what.removeprefix("expected a").split(" node, but found ")
        what = f"a{wanted} was tagged but a {found} is written; drop the tag"
    elif what == "found unhashable key":
        what = "a key is a list or a mapping; a key is a name"
    return f"YAML error: {what}"


def _short(tag: str) -> str:
    """``tag:yaml.org,2002:binary`` as it is written, ``!!binary``."""
    prefix = "tag:yaml.org,2002:"
    return "!!" + tag.removeprefix(prefix) if tag.startswith(prefix) else tag


def key_at(root: Any, mark: Any) -> str | None:
    """The key path (``given.spin``, ``notes[2]``) of the value or key that starts at
    ``mark`` in the composed document ``root``; None if none does."""
    import yaml

    if root is None or mark is None:
        return None
    where = (mark.line, mark.column)
    seen: set[int] = set()
    todo: list[tuple[Any, str]] = [(root, "")]
    while todo:
        node, path = todo.pop()
        if id(node) in seen:
            continue
        seen.add(id(node))
        if path and (node.start_mark.line, node.start_mark.column) == where:
            return path
        if isinstance(node, yaml.MappingNode):
            for key, value in node.value:
                name = str(key.value) if isinstance(key, yaml.ScalarNode) else "?"
                if (key.start_mark.line, key.start_mark.column) == where:  # the key itself
                    return path or None if name == "?" else f"{path}.{name}" if path else name
                todo.append((value, f"{path}.{name}" if path else name))
        elif isinstance(node, yaml.SequenceNode):
            todo += ((item, f"{path}[{i}]") for i, item in enumerate(node.value))
    return None

# Plain scalars YAML 1.1 turns into something else than text; as a key, text is meant.
_NAME_TAGS = {f"tag:yaml.org,2002:{t}" for t in ("int", "float", "bool", "timestamp", "null")}


def prescan(text: str) -> None:
    """Refuse deep nesting, alias bombs and alias cycles before anything is built.

    Walks the parser's events (libyaml's parser keeps its own stack, so a
    100,000-level file is read, not recursed into) and counts every value as
    it would be after alias expansion.
    """
    import yaml

    loader = loader_class()(text)
    try:
        _walk_events(loader, yaml)
    except yaml.YAMLError as err:
        raise _too_deep(err) from None
    finally:
        loader.dispose()


def _too_deep(err: Exception) -> Exception:
    """libyaml 0.2.6 (PyYAML 6.0.3+) stops deep collections itself: the same refusal as
    ours, in our words (any other YAML error as it is)."""
    if "maximum nesting depth" not in str(err):
        return err
    mark = getattr(err, "problem_mark", None) or getattr(err, "context_mark", None)
    return InputError(f"nested deeper than {MAX_DEPTH} levels; a problem file needs three",
                      line=mark.line + 1 if mark else None)


def _walk_events(loader: Any, yaml: Any) -> None:
    """The event walk of ``prescan``: depth, cycles and the expanded size."""
    sizes: dict[str, int] = {}
    stack: list[list[Any]] = []  # [anchor, size so far]
    total = 0
    while loader.check_event():
        event = loader.get_event()
        if isinstance(event, (yaml.MappingStartEvent, yaml.SequenceStartEvent)):
            if len(stack) >= MAX_DEPTH:
                raise InputError(f"nested deeper than {MAX_DEPTH} levels; a problem file "
                                 "needs three", line=event.start_mark.line + 1)
            stack.append([event.anchor, 1])
            total += 1
            size = 0
        elif isinstance(event, (yaml.MappingEndEvent, yaml.SequenceEndEvent)):
            anchor, size = stack.pop()
            if anchor is not None:
                sizes[anchor] = size
        elif isinstance(event, yaml.ScalarEvent):
            size = 1
            total += 1
            if event.anchor is not None:
                sizes[event.anchor] = 1
        elif isinstance(event, yaml.AliasEvent):
            if any(entry[0] == event.anchor for entry in stack):
                raise InputError(f"alias *{event.anchor} refers to a value that contains "
                                 "it (a cycle)", line=event.start_mark.line + 1)
            size = sizes.get(event.anchor, 1)
            total += size
        else:
            continue
        if total > MAX_NODES:
            raise InputError(f"aliases and values expand to more than {MAX_NODES} values; "
                             "refused (a problem file has about fifty)",
                             line=event.start_mark.line + 1)
        if stack and not isinstance(event, (yaml.MappingStartEvent,
                                            yaml.SequenceStartEvent)):
            stack[-1][1] += size


def _nests_itself() -> bool:
    """Whether the parser refuses deep nesting on its own: libyaml 0.2.6 and later stop
    both block and flow collections at 1000 levels, so composing is safe to recurse."""
    try:
        import yaml
        from yaml import _yaml  # type: ignore[attr-defined]

        version = tuple(int(p) for p in _yaml.get_version_string().split("."))
    except (ImportError, AttributeError, ValueError):
        return False
    return getattr(yaml, "CSafeLoader", None) is not None and version >= (0, 2, 6)


_COMPOSE_FIRST: bool | None = None
# An anchor is "&" and at least one character that is neither a space nor a flow
# indicator (YAML 1.2, ns-anchor-name): "Ruina & Schwab" holds none.
_ANCHOR = r"&[^\s,\[\]{}]"  # compiled on first use (re keeps it)


def _check_tree(root: Any) -> None:
    """``prescan``'s depth and size limits on a composed document without anchors (so
    without aliases: every value is one node): the nodes in document order, the same
    refusals at the same lines."""
    import yaml

    if root is None:
        return
    total = 0
    todo = [(root, 1)]
    while todo:
        node, depth = todo.pop()
        total += 1
        if isinstance(node, yaml.MappingNode):
            if depth > MAX_DEPTH:
                raise InputError(f"nested deeper than {MAX_DEPTH} levels; a problem file "
                                 "needs three", line=node.start_mark.line + 1)
            for key, value in reversed(node.value):
                todo += ((value, depth + 1), (key, depth + 1))
        elif isinstance(node, yaml.SequenceNode):
            if depth > MAX_DEPTH:
                raise InputError(f"nested deeper than {MAX_DEPTH} levels; a problem file "
                                 "needs three", line=node.start_mark.line + 1)
            todo += ((item, depth + 1) for item in reversed(node.value))
        if total > MAX_NODES:
            raise InputError(f"aliases and values expand to more than {MAX_NODES} values; "
                             "refused (a problem file has about fifty)",
                             line=node.start_mark.line + 1)


def load(text: str) -> tuple[Any, Any]:
    """(data, root node) of one YAML document, within the limits.

    A document without anchors (no ``&name`` anywhere: no alias can expand or loop) is
    composed first, by a libyaml that bounds nesting itself, and its nodes counted
    (half the work of walking the parser's events, for the same refusals); any other
    goes through ``prescan``. Raises yaml.YAMLError for malformed YAML and InputError
    (with a line) for input refused by the limits, or (with its key) for a value that
    cannot be built.
    """
    global _COMPOSE_FIRST
    if _COMPOSE_FIRST is None:
        _COMPOSE_FIRST = _nests_itself()
    compose_first = _COMPOSE_FIRST and ("&" not in text or not re.search(_ANCHOR, text))
    if not compose_first:
        prescan(text)
    import yaml

    loader = loader_class()(text)
    try:
        try:
            node = loader.get_single_node()
        except yaml.YAMLError as err:
            raise _too_deep(err) from None
        data = _plain_data(loader, node) if compose_first else _UNUSUAL
        if data is _UNUSUAL:
            if compose_first:
                _check_tree(node)
            written = _mapping_values(node)
            data = _construct(loader, node)
        else:
            written = []
        # Building a mapping with a merge key (<<: *base) rewrites the node's pairs, the
        # merged ones first; give the node back the pairs as written, so that a key that
        # overrides a merged one is not taken for a key written twice.
        for mapping, pairs in written:
            mapping.value = pairs
    finally:
        loader.dispose()
    return data, node


def _construct(loader: Any, node: Any) -> Any:
    """PyYAML's build of a composed document; a value it cannot build (a tag it does not
    know or that does not fit the value) is an InputError naming the key and line."""
    import yaml

    if node is None:
        return None
    try:
        return loader.construct_document(node)
    except yaml.MarkedYAMLError as err:
        mark = err.problem_mark or err.context_mark
        raise InputError(message(err), key=key_at(node, mark),
                         line=mark.line + 1 if mark else None) from None


_UNUSUAL = object()  # _plain_data's answer for a document it leaves to PyYAML
_STR, _NULL = "tag:yaml.org,2002:str", "tag:yaml.org,2002:null"
_MAP, _SEQ = "tag:yaml.org,2002:map", "tag:yaml.org,2002:seq"
_SCALAR_TAGS = {f"tag:yaml.org,2002:{t}" for t in ("bool", "int", "float", "binary",
                                                    "timestamp")}


class _Unusual(Exception):
    pass


def _plain_data(loader: Any, root: Any) -> Any:
    """The data of a composed document without anchors, built in one pass that also
    holds it to the depth and size limits; ``_UNUSUAL`` for anything else.

    A problem file is mappings, lists and plain scalars: built here, as PyYAML's safe
    constructor with ``loader_class``'s rules builds them (keys as written, the same
    constructor for every scalar that is not text), without its generic machinery.
    A merge key (``<<``), a ``=`` key, a key that is not a scalar, an explicit tag on
    a collection, a value PyYAML refuses or a document past a limit is ``_UNUSUAL``:
    the caller builds and refuses it the way it always has, with the same messages.
    """
    import yaml

    if root is None:
        return None
    constructors = loader.yaml_constructors
    scalar, mapping, sequence = yaml.ScalarNode, yaml.MappingNode, yaml.SequenceNode
    count = 1  # the nodes met so far; a collection counts its items as it is entered

    def value_of(node: Any) -> Any:
        """A scalar that is not text: null, or what PyYAML's constructor makes of it."""
        tag = node.tag
        if tag == _NULL:
            return None
        if tag in _SCALAR_TAGS:
            return constructors[tag](loader, node)
        raise _Unusual

    # Scalars, most of a file, are read in the loops (text first), without a call each.
    def build(node: Any, depth: int) -> Any:
        nonlocal count
        if depth > MAX_DEPTH:
            raise _Unusual
        kind, items = node.__class__, node.value
        if kind is mapping and node.tag == _MAP:
            count += 2 * len(items)
            if count > MAX_NODES:
                raise _Unusual
            out = {}
            for key_node, value_node in items:
                if key_node.__class__ is not scalar:
                    raise _Unusual
                tag = key_node.tag
                if tag in _NAME_TAGS and key_node.style in (None, ""):
                    key_node.tag = tag = _STR  # as loader_class's construct_mapping does
                key = key_node.value if tag == _STR else value_of(key_node)
                if value_node.__class__ is not scalar:
                    out[key] = build(value_node, depth + 1)
                elif value_node.tag == _STR:
                    out[key] = value_node.value
                else:
                    out[key] = value_of(value_node)
            return out
        if kind is sequence and node.tag == _SEQ:
            count += len(items)
            if count > MAX_NODES:
                raise _Unusual
            return [(item.value if item.tag == _STR else value_of(item))
                    if item.__class__ is scalar else build(item, depth + 1) for item in items]
        raise _Unusual

    try:
        if root.__class__ is scalar:
            return root.value if root.tag == _STR else value_of(root)
        return build(root, 1)
    except Exception:  # noqa: BLE001 -- refused or unusual: built the usual way, which says why
        return _UNUSUAL


def _mapping_values(node: Any) -> list[tuple[Any, list]]:
    """Every mapping node under ``node`` with its own list of pairs (iteratively; aliases
    are the same node objects, visited once)."""
    import yaml

    found: list[tuple[Any, list]] = []
    seen: set[int] = set()
    stack = [node] if node is not None else []
    while stack:
        item = stack.pop()
        if id(item) in seen:
            continue
        seen.add(id(item))
        if isinstance(item, yaml.MappingNode):
            found.append((item, list(item.value)))
            for key, value in item.value:
                stack.extend((key, value))
        elif isinstance(item, yaml.SequenceNode):
            stack.extend(item.value)
    return found
