"""A parser for the small mathematical language of the worked answers: a test oracle.

gyro itself reads no formula text (every formula is a tree the kind wrote, issue
21); the tests keep this parser, which gyro once used, to look for maths left
in a sentence's plain words and to read symbols back from printed output.

A tokenizer and a precedence-climbing parser, loosest binding first:

    relation   a = b, >=, <=, <, >, >>, ->, ~, !=    (a chain, may start with =)
    sum        + - +- -+
    product    * / x (cross product) . (dot product) and juxtaposition
               (``m g l``), all left-associative at one level: ``a / b c`` is (a/b) c
    unary      -x, +x
    power      x^y (right-associative; ``M^-1``)
    postfix    primes: q', theta''
    atom       numbers (with a unit after them when units are read: ``9.815 m/s^2``),
               symbols, f(x), sin^2(x), ``cos theta0``, sqrt(x), |x|, (x), [x],
               tuples (a, b), ``sum x``, ``int_a^b body``

`parse` raises `ParseError` on anything else. `spans` splits a line of prose
into words and the maths inside it, each maths span checked by the parser:
what does not parse stays prose.
"""

from __future__ import annotations

import re

from oracle_tree import (
    PRECEDENCE,
    SUMS,
    Abs,
    BinOp,
    Call,
    Group,
    Integral,
    Matrix,
    Neg,
    Node,
    Num,
    Pow,
    Prime,
    Quantity,
    Rel,
    Sum,
    Sym,
    Text,
    Tuple,
    Unsupported,
    fold,
    precedence,
    to_core,
)

from gyro_cli.core.expr import Printer as CorePrinter
from gyro_cli.render.conventions import GREEK, Token, dotted, tokens  # noqa: F401 (re-exported)
from gyro_cli.render.conventions import symbolic as _symbolic  # noqa: F401

FUNCTIONS = {"sin", "cos", "tan", "cot", "sec", "csc", "exp", "ln", "log", "arcsin", "arccos",
             "arctan", "asin", "acos", "atan", "atan2", "sinh", "cosh", "tanh", "det", "sqrt",
             "Re", "Im", "max", "min", "sign"}
UNITS = {"kg", "m", "s", "N", "rad", "rpm", "deg", "mm", "cm", "km", "in", "ft", "lb", "lbf",
         "oz", "ozf", "slug", "Hz", "min", "h", "J", "W", "revolution", "rev", "lbm", "degree",
         "radian", "second", "minute", "meter", "metre", "newton", "kip", "mi", "yd", "knot",
         "knots", "t", "mph", "kN", "rps", "hr", "g", "dyne", "gal", "psi"}
RELATIONS = {"=", ">=", "<=", "<", ">", ">>", "<<", "->", "~", "!="}
#: symbols that name vectors: between two of them a spaced ``x`` is a cross product
VECTORS = {"K", "k", "i", "j", "n", "H", "omega", "omega_p", "H_O", "H_G", "C", "M", "F",
           "Omega_E", "U", "u", "s"}

class ParseError(ValueError):
    pass


def parse(text: str, units: bool = True) -> Node:
    """The expression tree of ``text``; raises ParseError when it is not maths."""
    parser = _Parser(tokens(text), units)
    if not parser.toks:
        raise ParseError("empty")
    node = parser.relation()
    if parser.i != len(parser.toks):
        raise ParseError(f"unexpected {parser.toks[parser.i].text!r}")
    return node


def try_parse(text: str, units: bool = True) -> Node | None:
    try:
        return parse(text, units)
    except (ParseError, RecursionError):
        return None


class _Parser:
    def __init__(self, toks: list[Token], units: bool) -> None:
        self.toks, self.units, self.i = toks, units, 0
        self.bars = 0  # open |...| (a | closes instead of opening)
        self.sep = ","
        self.in_call = 0  # inside f(...): Rz(yaw) names an angle by a word

    # -- helpers
    def peek(self, k: int = 0) -> Token | None:
        j = self.i + k
        return self.toks[j] if j < len(self.toks) else None

    def at(self, *texts: str) -> bool:
        t = self.peek()
        return t is not None and t.kind in ("op", "name") and t.text in texts

    def take(self) -> Token:
        t = self.peek()
        if t is None:
            raise ParseError("unexpected end")
        self.i += 1
        return t

    def expect(self, text: str) -> None:
        t = self.take()
        if t.text != text:
            raise ParseError(f"expected {text!r}, found {t.text!r}")

    # -- grammar
    def relation(self) -> Node:
        first = None if self.at(*RELATIONS) else self.sum()
        rest = []
        while self.at(*RELATIONS):
            op = self.take().text
            rest.append((op, self.sum()))
        return Rel(first, tuple(rest)) if rest else first

    def sum(self) -> Node:
        left = self.product()
        while self.at("+", "-", "+-", "-+"):
            op = self.take().text
            left = BinOp(op, left, self.product())
        return left

    def product(self) -> Node:
        left = self.unary()
        while True:
            t = self.peek()
            if t is None:
                return left
            if t.kind == "op" and t.text in ("*", "/"):
                self.i += 1
                left = BinOp(t.text, left, self.unary())
            elif t.kind == "op" and t.text == "." and t.space:
                self.i += 1
                left = BinOp(".", left, self.unary())
            elif t.kind == "name" and t.text == "x" and _numeric_expr(left) and \
                    self.peek(1) is not None and self.peek(1).kind == "num":
                self.i += 1  # 1 x 10^6: times
                left = BinOp("x", left, self.power())
                left = self._unit_after(left)
            elif self._cross(left):
                self.i += 1
                left = BinOp("x", left, self.power())
            elif self._starts_factor(t):
                left = BinOp(" ", left, self.power())
            else:
                return left

    def _unit_after(self, node: Node) -> Node:
        return self._with_unit(node)

    def _with_unit(self, node: Node) -> Node:
        """``node`` followed by unit words (``9.815 m/s^2``) is a Quantity."""
        if self.units:
            n = unit_run(self.toks, self.i)
            if n:
                unit = _join(self.toks[self.i:self.i + n])
                self.i += n
                return Quantity(node, unit)
        return node

    def _cross(self, left: Node) -> bool:
        t, nxt = self.peek(), self.peek(1)
        if t is None or nxt is None or t.kind != "name" or t.text != "x" or not t.space:
            return False
        right_vec = (nxt.kind == "name" and nxt.text in VECTORS) or nxt.text == "("
        return right_vec and _is_vector(left)

    def _starts_factor(self, t: Token) -> bool:
        if t.kind in ("num", "name"):
            return True
        if t.kind == "op" and t.text in ("(", "["):
            return True
        return t.kind == "op" and t.text == "|" and not self.bars

    def unary(self) -> Node:
        if self.at("-", "+", "+-", "-+"):
            sign = self.take().text
            return Neg(self.unary(), sign)
        return self.power()

    def power(self) -> Node:
        base = self.postfix()
        if self.at("^"):
            self.i += 1
            units, self.units = self.units, False  # no unit in an exponent: sin^2 s
            try:
                if self.at("-"):
                    self.i += 1
                    return Pow(base, Neg(self.power()))
                return Pow(base, self.power())
            finally:
                self.units = units
        return base

    def postfix(self) -> Node:
        node = self.atom()
        count = 0
        while self.at("'") and not self.peek().space:
            self.i += 1
            count += 1
        return Prime(node, count) if count else node

    def atom(self) -> Node:
        t = self.take()
        if t.kind == "num":
            return self._number(t)
        if t.kind == "name":
            return self._name(t)
        if t.kind == "op" and t.text in ("(", "["):
            return self._group(t.text)
        if t.kind == "op" and t.text == "|" and not self.bars:
            self.bars += 1
            body = self.sum()
            self.bars -= 1
            self.expect("|")
            return Abs(body)
        raise ParseError(f"unexpected {t.text!r}")

    def _number(self, t: Token) -> Node:
        node = Num(t.text)
        nxt, after = self.peek(), self.peek(1)
        if nxt is not None and nxt.kind == "name" and nxt.text == "i" and (
                after is None or after.kind == "op" or after.kind == "num"
                and after.text == "1" or after.kind == "name" and after.text in UNITS):
            self.i += 1  # an imaginary part: 4.46 i, 3.07911i
            node = Num(t.text + "i")
        return self._with_unit(node)

    def _name(self, t: Token) -> Node:
        name = t.text
        nxt = self.peek()
        glued = nxt is not None and not nxt.space and nxt.text == "("
        if name in FUNCTIONS:
            power = None
            if self.at("^") and name != "sqrt":
                self.i += 1
                units, self.units = self.units, False
                power = self.atom()
                self.units = units
            if self.at("(") and (not self.peek().space or power is not None or name == "sqrt"):
                self.i += 1
                args = self._args(")")
                return Call(name, args, power, sep=self.sep)
            if name == "sqrt":
                raise ParseError("sqrt without brackets")
            if nxt is None or power is None and (nxt.kind not in ("name", "num")
                                                 and nxt.text != "("):
                raise ParseError(f"{name} without an argument")
            return Call(name, (self.power(),), power, parens=False)
        if name == "sum" and nxt is not None and self._starts_factor(nxt):
            return Sum(self.product())
        if name.startswith("int_") and self.at("^"):
            lower = Sym(name[4:])
            self.i += 1
            upper = self.postfix()
            return Integral(lower, upper, self.product())
        if is_word(name) and not name.startswith("int_") and not (
                self.in_call and name in ANGLE_WORDS):
            raise ParseError(f"{name!r} is a word")
        if glued:
            self.i += 1
            args = self._args(")")
            return Call(name, args, sep=self.sep)
        return Sym(name)

    def _args(self, close: str) -> tuple:
        start = self.i
        try:
            return self._arglist(close)
        except ParseError:
            self.i = start
            self.bars += 1  # "Pi(n|m)": a bar separates, it does not open
            try:
                return self._arglist(close)
            finally:
                self.bars -= 1

    def _arglist(self, close: str) -> tuple:
        self.in_call += 1
        try:
            return self._arglist_in(close)
        finally:
            self.in_call -= 1

    def _arglist_in(self, close: str) -> tuple:
        args = [self.relation()]
        sep = ","
        while self.at(",", "|"):
            sep = self.take().text
            args.append(self.relation())
        self.expect(close)
        self.sep = sep
        return tuple(args)

    def _matrix(self) -> Node | None:
        """``[1 0 0; 0 1 0; 0 0 1]`` when the bracket holds a top-level ';'."""
        depth, j = 0, self.i
        while j < len(self.toks):
            t = self.toks[j].text
            if t in ("(", "["):
                depth += 1
            elif t in (")", "]"):
                if depth == 0:
                    break
                depth -= 1
            elif t == ";" and depth == 0:
                rows, row = [], []
                while not self.at("]"):
                    if self.at(";"):
                        self.i += 1
                        rows.append(tuple(row))
                        row = []
                        continue
                    row.append(self.unary())
                self.i += 1
                rows.append(tuple(row))
                if len({len(r) for r in rows}) != 1 or not rows[0]:
                    raise ParseError("rows of a matrix differ in length")
                return Matrix(tuple(rows))
            j += 1
        return None

    def _group(self, open_: str) -> Node:
        if open_ == "[":
            matrix = self._matrix()
            if matrix is not None:
                return matrix
        close = ")" if open_ == "(" else "]"
        saved = self.bars
        self.bars = 0
        items = [self.relation()]
        while self.at(","):
            self.i += 1
            items.append(self.relation())
        self.bars = saved
        self.expect(close)
        body = items[0] if len(items) == 1 else Tuple(tuple(items))
        node = Group(open_, body)
        if isinstance(body, Tuple) and all(_numeric(x) for x in body.items):
            return self._with_unit(node)
        return node


def _numeric_expr(node: Node) -> bool:
    """A number written with a power of ten: 1 x 10^6."""
    if isinstance(node, Num):
        return True
    if isinstance(node, Pow):
        return isinstance(node.base, Num)
    return isinstance(node, BinOp) and node.op == "x" and _numeric_expr(node.left) \
        and _numeric_expr(node.right)


def _numeric(node: Node) -> bool:
    return isinstance(node, Num) or isinstance(node, Neg) and isinstance(node.body, Num)


def _is_vector(node: Node) -> bool:
    while isinstance(node, BinOp) and node.op in (" ", "*"):
        node = node.right
    if isinstance(node, Sym):
        return node.name in VECTORS
    return isinstance(node, Group)


def _join(toks: list[Token]) -> str:
    return "".join((" " if t.space and k else "") + t.text for k, t in enumerate(toks))


def unit_run(toks: list[Token], k: int) -> int:
    """How many tokens from toks[k] make the unit after a number (0 when none):
    ``kg m^2/s``, ``m/s^2``, ``1/s^2``. A unit followed by a symbol is not one:
    ``2 m g l`` is a product of symbols."""
    j = k
    n = len(toks)

    def is_unit(t: Token) -> bool:
        return t.kind == "name" and t.text in UNITS

    def power(j: int) -> int:
        if j < n and toks[j].text == "^" and not toks[j].space:
            if j + 1 < n and toks[j + 1].kind == "num":
                return j + 2
            if j + 2 < n and toks[j + 1].text == "-" and toks[j + 2].kind == "num":
                return j + 3
        return j

    if j + 2 < n and toks[j].text == "1" and toks[j + 1].text == "/" and is_unit(toks[j + 2]) \
            and toks[j].space and not toks[j + 2].space:
        j += 2
    elif j >= n or not is_unit(toks[j]):
        return 0
    while True:
        j = power(j + 1)
        if j + 1 < n and toks[j].text in ("/", "*") and is_unit(toks[j + 1]) \
                and not toks[j].space:
            j += 1
            continue
        if j < n and is_unit(toks[j]) and toks[j].space and _unit_follows(toks, j):
            continue
        break
    # a symbol after the unit: "2 m g l" is twice m g l, not two metres
    if j < n and toks[j].kind == "name" and toks[j].text not in FUNCTIONS \
            and not toks[j].text.startswith("int_") and not is_word(toks[j].text) \
            and not (toks[j].text == "i"):
        return 0
    return j - k


def _unit_follows(toks: list[Token], j: int) -> bool:
    """A unit word after a unit continues the unit unless a symbol follows it (``N m``
    but not ``kg m g``)."""
    k = j + 1
    while k < len(toks) and toks[k].text in ("^", "-") or (k < len(toks) and toks[k].kind == "num"
                                                           and toks[k - 1].text in ("^", "-")):
        k += 1
    if k < len(toks) and toks[k].kind == "name" and toks[k].space and toks[k].text not in UNITS \
            and toks[k].text not in FUNCTIONS and not is_word(toks[k].text):
        return False
    return True


# ---- words and symbols ------------------------------------------------------

SHORT_WORDS = {"a", "an", "as", "at", "be", "by", "if", "in", "is", "it", "no", "of", "on", "or",
               "so", "to", "we", "up", "iff", "and"}


def is_symbol_name(name: str) -> bool:
    """A name that is a symbol, not an English word: ``theta0``, ``u1``, ``I_G``, ``phidot``,
    ``dH``, ``P2``, ``a0``."""
    base = name.split("_", 1)[0]
    stem = base.rstrip("0123456789")
    if not stem:
        return False
    if stem != base and (stem in GREEK or len(stem) <= 2 or dotted(stem)):
        return True
    if "_" in name:
        return stem in GREEK or len(stem) <= 3 or bool(dotted(stem)) or stem[0] == "d" \
            and _symbolic(stem[1:])
    if stem in GREEK or dotted(stem) or len(stem) == 1:
        return True
    if len(stem) == 2 and stem[0].isupper() and stem[1] in "xyz":
        return True  # Rz, Ry: a rotation about z, y
    return stem[0] == "d" and len(stem) > 1 and _symbolic(stem[1:]) and stem not in WORDS_D


ANGLE_WORDS = {"yaw", "pitch", "roll", "heading", "bank"}
UPPER_WORDS = {"US", "SI", "UK", "PDF", "CSV", "JSON", "YAML", "OK", "NB", "IERS", "IAU",
               "J2000"}
WORDS_D = {"do", "dip", "die", "dies", "due", "down", "deg", "dot", "ddot"}


def is_word(name: str) -> bool:
    """An English word (``because``, ``the``) rather than a symbol."""
    if name in UPPER_WORDS:
        return True
    if name in FUNCTIONS or name in GREEK or name.isupper():
        return False
    if is_symbol_name(name):
        return False
    return len(name) > 1 and name.replace("_", "").isalpha()


# ---- prose ----------------------------------------------------------------

def spans(text: str, keep_unparsed: bool = False) -> list[tuple[bool, object]]:
    """Split a line of prose into (False, words) and (True, tree) spans.

    Words are English words and the punctuation of sentences; everything else is a
    candidate for maths, which is kept as maths only when it parses.
    """
    toks = tokens(text, keep_space=True)
    classes = _classify(toks)
    runs: list[tuple[bool, list[Token]]] = []
    for tok, is_math in zip(toks, classes):
        if runs and runs[-1][0] == is_math:
            runs[-1][1].append(tok)
        else:
            runs.append((is_math, [tok]))
    out: list[tuple[bool, object]] = []

    def prose(s: str) -> None:
        if not s:
            return
        if out and not out[-1][0]:
            out[-1] = (False, out[-1][1] + s)
        else:
            out.append((False, s))

    for is_math, part in runs:
        raw = "".join(t.text for t in part)
        if not is_math:
            prose(raw)
            continue
        core = raw.strip()
        lead = raw[: len(raw) - len(raw.lstrip())]
        trail = raw[len(raw.rstrip()):]
        head = tail = ""
        # brackets open or closed outside the maths belong to the sentence
        while core and (core[-1] in "([" or core[-1] in ")]" and _depth(core) < 0):
            tail = core[-1] + tail
            core = core[:-1]
            tail = core[len(core.rstrip()):] + tail
            core = core.rstrip()
        while core and (core[0] in ")]" or core[0] in "([" and _depth(core) > 0):
            head += core[0]
            core = core[1:]
            head += core[: len(core) - len(core.lstrip())]
            core = core.lstrip()
        # a bracketed aside, "(psidot)": the brackets are the sentence's
        if len(core) > 2 and core[0] == "(" and core[-1] == ")" and _depth(core[1:-1]) == 0 \
                and core[1:-1].count("(") == core[1:-1].count(")"):
            inner = try_parse(core[1:-1])
            if inner is not None and not isinstance(inner, (BinOp, Neg)):
                head, core, tail = head + "(", core[1:-1], ")" + tail
        tree = try_parse(core) if core else None
        if tree is None and core:
            # a run that does not parse: the longest pieces of it that do, the rest prose
            words = re.split(r"(?<=\S)(?=\s)|(?<=\s)(?=\S)", core)
            prose(lead + head)
            lead = head = ""
            i = 0
            while i < len(words):
                found = None
                if words[i].strip():
                    for j in range(len(words), i, -1):
                        if not words[j - 1].strip():
                            continue  # the space after a piece stays in the sentence
                        piece = "".join(words[i:j]).strip()
                        sub = try_parse(piece) if piece else None
                        if sub is not None:
                            found = (j, sub)
                            break
                if found is None:
                    prose(words[i])
                    i += 1
                else:
                    out.append((True, found[1]))
                    i = found[0]
            prose(tail + trail)
            continue
        prose(lead + head)
        if tree is not None:
            out.append((True, tree))
        prose(tail + trail)
    return out


def _depth(s: str) -> int:
    return s.count("(") + s.count("[") - s.count(")") - s.count("]")


def _classify(toks: list[Token]) -> list[bool]:
    classes: list[bool] = []
    unit_left = 0
    sig = [k for k, t in enumerate(toks) if t.kind != "space"]
    pos = {k: n for n, k in enumerate(sig)}

    def nxt(k: int, d: int = 1) -> Token | None:
        n = pos[k] + d
        return toks[sig[n]] if 0 <= n < len(sig) else None

    depth = 0
    last_ref = False
    for k, t in enumerate(toks):
        if t.kind == "space":
            classes.append(classes[-1] if classes else False)
            continue
        if unit_left:
            unit_left -= 1
            classes.append(True)
            continue
        after, before = nxt(k), nxt(k, -1)
        if t.kind == "name":
            if t.text == "a":
                # "a F_A - b F_B" is maths, "a complex pair" is prose
                op_before = before is not None and before.kind == "op" \
                    and before.text in ("=", "+", "-", "*", "/", "(", "^", ">=", "<=", "<", ">") \
                    and not (before.text == "-" and nxt(k, -2) is not None
                             and nxt(k, -2).text == "-")  # "-- a real root": a dash
                classes.append(op_before or after is not None and not (
                    after.kind == "name" and is_word(after.text))
                    and after.text not in (",", ".", ";", ":")
                    and not (before is not None and before.text == "'"))
            elif t.text == "A" and (before is None or before.text in (".", ":", ";")) \
                    and after is not None and after.kind == "name" and is_word(after.text) \
                    and after.text.islower():
                classes.append(False)  # "A gyro wheel": the article opening a sentence
            elif before is not None and before.text == "'" and t.text == "s":
                classes.append(False)  # possessive
            elif t.text in ANGLE_WORDS and before is not None and before.text == "(" \
                    and pos[k] >= 2 and nxt(k, -2).text in ("Rx", "Ry", "Rz"):
                classes.append(True)  # Rz(yaw): the rotation by the yaw angle
            elif len(t.text) == 1 and t.text.isupper() and after is not None \
                    and after.kind == "num" and before is not None and (
                        before.text == "." and pos[k] >= 2 and nxt(k, -2).text in ("Eq", "Eqs")
                        or before.text == "-" and last_ref):
                classes.append(False)  # "Eqs. A 1-A 5": equations of an appendix
            elif (before is not None and before.text == "-" and not before.space
                  and not t.space and k >= 2 and toks[k - 2].kind == "name"
                  and not classes[-1]):
                classes.append(False)
            else:
                classes.append(not (is_word(t.text) or t.text in SHORT_WORDS))
        elif t.kind == "num":
            ref = before is not None and before.text == "." and pos[k] >= 2 \
                and nxt(k, -2).text in ("Eq", "Eqs", "Sec", "Fig", "ch", "p")
            ref = ref or (before is not None and before.text in ("Eq", "Eqs", "Fig", "Sec",
                                                                  "A", "ch"))
            ref = ref or (before is not None and before.text == "-" and classes
                          and not classes[-1] and not before.space)
            # "Eqs. 11.8, 11.14 and 11.17": every number of the list is a reference
            ref = ref or (before is not None and before.text in (",", "and") and last_ref)
            last_ref = ref
            classes.append(not ref)
            if not ref:
                j = k + 1
                while j < len(toks) and toks[j].kind == "space":
                    j += 1
                sub = [x for x in toks[j:] if x.kind != "space"]
                # unit_run works on tokens without spaces; count spaced tokens back
                run = unit_run([Token("num", t.text, False)] + sub, 1) if sub else 0
                unit_left = run
        elif t.kind == "op" and t.text in "([":
            depth += 1
            classes.append(True)
        elif t.kind == "op" and t.text in ")]":
            depth -= 1
            classes.append(True)
        elif t.kind == "op" and t.text == "." and t.space and after is not None \
                and after.space and before is not None and before.kind != "op":
            classes.append(True)  # omega . H: a dot product
        elif t.kind == "op" and t.text in (",", ";", ":", ".", "?", "!"):
            spaced_after = after is None or k + 1 < len(toks) and toks[k + 1].kind == "space"
            classes.append(depth > 0 and t.text == "," or not spaced_after and t.text == ".")
        elif t.kind == "op" and t.text == "'":
            classes.append(before is not None and before.kind == "name"
                           and not is_word(before.text))
        elif t.kind == "op" and t.text == "-" and last_ref and not t.space \
                and after is not None and after.kind == "num" and classes and not classes[-1]:
            classes.append(False)  # "Eqs. 11.22-11.25": a range of references, not a minus
        elif t.kind == "op" and t.text == "-" and not t.space and after is not None \
                and not after.space and before is not None and before.kind == "name" \
                and after.kind in ("name", "num") and (is_word(before.text)
                                                        or len(before.text) == 1
                                                        and len(after.text) == 1):
            classes.append(False)  # a hyphen: z-x-z, Routh-Hurwitz
            if classes[-2::-1]:
                # the letter before a hyphen is prose too
                for m in range(len(classes) - 2, -1, -1):
                    if toks[m].kind == "space":
                        break
                    classes[m] = False
        elif t.kind == "other":
            classes.append(False)
        else:
            classes.append(True)
    # the letter after a hyphen is prose
    for k, t in enumerate(toks):
        if k and t.kind == "name" and toks[k - 1].text == "-" and not classes[k - 1]:
            classes[k] = False
    return classes


# ---- the printers over the oracle's trees (what the write-up once did with text) ----------

def latex_math(text: str, units: bool = True, display: bool = False) -> str:
    """Formula text typeset by gyro's LaTeX printer from the oracle's tree; what does not
    parse as words."""
    from gyro_cli.render.mathprint import LatexPrinter, text_escape

    tree = try_parse(text, units)
    if tree is not None:
        try:
            return LatexPrinter(display).doprint(to_core(tree))
        except Unsupported:
            pass
    return f"\\text{{{text_escape(text)}}}"


def latex_mixed(text: str) -> str:
    """A sentence with the oracle's maths spans typeset inline and the words escaped."""
    from gyro_cli.render.writeup import words

    return "".join(f"${_inline(part)}$" if is_math else words(str(part))
                   for is_math, part in spans(text))


def _inline(part: Node) -> str:
    from gyro_cli.render.mathprint import LatexPrinter, text_escape

    try:
        return LatexPrinter(False).doprint(to_core(part))
    except Unsupported:
        return f"\\text{{{text_escape(text(part))}}}"


# ---- plain text of the oracle's trees ------------------------------------------

class BasePrinter(CorePrinter):
    """Gyro's printer base (dispatch by class), brackets by the oracle's precedence."""

    def parenthesize(self, node: Node, level: int, strict: bool = False) -> str:
        p = precedence(node)
        if p < level or (strict and p == level):
            return self.brackets(self._print(node))
        return self._print(node)


class TextPrinter(BasePrinter):
    """The plain form of a parsed tree, one spelling per tree: the parser's round trip
    (gyro prints its own trees' text with `core.expr.TextPrinter`)."""

    def _print_Num(self, node: Num) -> str:
        return node.text

    def _print_Sym(self, node: Sym) -> str:
        return node.name

    def _print_Text(self, node: Text) -> str:
        return node.text

    def _print_Quantity(self, node: Quantity) -> str:
        return f"{self._print(node.value)} {node.unit}"

    def _print_Neg(self, node: Neg) -> str:
        body = node.body
        inner = self._print(body) if isinstance(body, (Num, Quantity)) else \
            self.parenthesize(body, PRECEDENCE["Neg"]) if not isinstance(body, Neg) \
            else self.brackets(self._print(body))
        return node.sign + inner

    def _print_BinOp(self, node: BinOp) -> str:
        op = node.op
        if op in SUMS:
            right, op = fold(node.right, op)
            left = self.parenthesize(node.left, PRECEDENCE["+"])
            rtext = self.parenthesize(right, PRECEDENCE["+"], strict=op != "+")
            return f"{left} {op} {rtext}"
        left = self.parenthesize(node.left, PRECEDENCE["*"])
        factor = self.parenthesize(node.right, PRECEDENCE["*"], strict=op == "/")
        if isinstance(node.right, Neg):
            factor = self.brackets(factor)
        sep = {"/": " / ", "x": " x ", ".": " . ", "*": " * ", " ": " "}[op]
        return f"{left}{sep}{factor}"

    def _print_Pow(self, node: Pow) -> str:
        base = self.parenthesize(node.base, PRECEDENCE["Atom"])
        if isinstance(node.base, Quantity):
            base = self.brackets(self._print(node.base))
        return f"{base}^{self.parenthesize(node.exp, PRECEDENCE['Pow'])}"

    def _print_Call(self, node: Call) -> str:
        args = (" | " if node.sep == "|" else ", ").join(self._print(a) for a in node.args)
        power = f"^{self._print(node.power)}" if node.power is not None else ""
        if not node.parens:
            return f"{node.name}{power} {self._print(node.args[0])}"
        return f"{node.name}{power}({args})"

    def _print_Group(self, node: Group) -> str:
        inner = self._print(node.body)
        return f"[{inner}]" if node.open == "[" else f"({inner})"

    def _print_Tuple(self, node: Tuple) -> str:
        return ", ".join(self._print(x) for x in node.items)

    def _print_Abs(self, node: Abs) -> str:
        return f"|{self._print(node.body)}|"

    def _print_Rel(self, node: Rel) -> str:
        parts = [self._print(node.first)] if node.first is not None else []
        parts += [f"{op} {self._print(rhs)}" for op, rhs in node.rest]
        return " ".join(parts)

    def _print_Sum(self, node) -> str:
        return "sum " + self._print(node.body)

    def _print_Integral(self, node) -> str:
        return (f"int_{self._print(node.lower)}^{self._print(node.upper)} "
                f"{self._print(node.body)}")

    def _print_Prime(self, node) -> str:
        return self.parenthesize(node.body, PRECEDENCE["Atom"]) + "'" * node.count

    def _print_Matrix(self, node) -> str:
        return "[" + "; ".join(" ".join(self._print(x) for x in row) for row in node.rows) + "]"


def text(node: Node) -> str:
    return TextPrinter().doprint(node)
