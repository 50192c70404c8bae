"""Expression trees: each formula of a worked answer written once.

A kind builds a step's formula from symbols that carry their SI value, unit
and name, with Python's operators and the functions below::

    theta = Sym("theta", 0.5236, "deg")        # shown in deg, held in rad
    J, w = Sym("J", 5.12e-4, "kg m^2"), Sym("omega_z", 188.5, "rad/s")
    work.step("H", J * w, unit="kg m^2/s")

The tree evaluates itself (`Expr.value`) and is printed by printers with one
``_print_<Class>`` method per node, as sympy's printers are (sympy itself is
not imported: it costs about a whole solve): `formula` (``J omega_z``),
`substitution` (``0.0005120 kg m^2 (188.5 rad/s)``) and `python` (``J*omega_z``,
the JSON ``expr``). LaTeX and MathML are printed in ``render/`` from the same
tree. Brackets come from one rule, `needs_brackets`, shared by every printer:
by precedence, around a divided product or quotient, around a quantity that
is not a product's first factor, and around a negative number wherever it
would otherwise follow another sign or factor.
"""

from __future__ import annotations

import keyword
import math

TYPE_CHECKING = False  # typing is not imported on the solve path (its import costs ms)
if TYPE_CHECKING:
    from collections.abc import Callable
    from typing import Any

SIG = 4

#: units shown differently from the SI value held: unit -> (SI value of one unit, SI unit)
SHOWN = {"deg": (math.pi / 180, "rad"),
         "arcsec/yr": (math.pi / 180 / 3600 / (365.25 * 86400.0), "rad/s"),  # Julian year
         "yr": (365.25 * 86400.0, "s"), "min": (60.0, "s"), "h": (3600.0, "s"),
         "yr/deg": (365.25 * 86400.0 * 180 / math.pi, "s/rad"),
         "d": (86400.0, "s"), "deg/h": (math.pi / 180 / 3600, "rad/s")}

#: the value of a symbol only named, in a definition (a `Let`'s body): its value is not
#: needed. This very object (``math.nan``), so it is told from a nan made by an overflow.
NAMED = math.nan

#: kinds' spellings of units, as printed
UNIT_TEXT = {"kg*m^2": "kg m^2", "N*m": "N m", "kg*m^2/s": "kg m^2/s"}


def num(x: float, sig: int = SIG) -> str:
    """A number to ``sig`` significant figures, trailing zeros kept (0.8340)."""
    if x == 0:
        return "0"
    text = f"{x:#.{sig}g}"
    mantissa, _, exponent = text.partition("e")
    mantissa = mantissa.rstrip(".")
    return f"{mantissa}e{exponent}" if exponent else mantissa


#: the classes of tree nodes taken as operands as they are (every node but a Chain),
#: looked up by class before the general tests below (most operands are such nodes)
_OPERANDS: set[type] = set()


def _node(x: Expr | float) -> Expr:
    kind = x.__class__
    if kind in _OPERANDS:
        return x  # type: ignore[return-value]
    if kind is float:
        return Num(x)  # type: ignore[arg-type]
    if isinstance(x, Expr):
        if isinstance(x, Chain):
            raise TypeError("a chain of equal forms is a step's whole formula, not an operand")
        return x
    if isinstance(x, bool) or not isinstance(x, (int, float)):
        raise TypeError(f"not an expression: {x!r}")
    return Num(float(x))


class Expr:
    """Base of every node: arithmetic builds trees, `value` evaluates them."""

    __slots__ = ()

    def __init_subclass__(cls, **kwargs: Any) -> None:
        super().__init_subclass__(**kwargs)
        if cls.__name__ != "Chain":  # a chain is a step's whole tree, never an operand
            _OPERANDS.add(cls)

    def __add__(self, other: Expr | float) -> Expr:
        return Add(self, _node(other))

    def __radd__(self, other: Expr | float) -> Expr:
        return Add(_node(other), self)

    def __sub__(self, other: Expr | float) -> Expr:
        return Sub(self, _node(other))

    def __rsub__(self, other: Expr | float) -> Expr:
        return Sub(_node(other), self)

    def __mul__(self, other: Expr | float) -> Expr:
        return Mul(self, _node(other))

    def __rmul__(self, other: Expr | float) -> Expr:
        return Mul(_node(other), self)

    def __truediv__(self, other: Expr | float) -> Expr:
        return Div(self, _node(other))

    def __rtruediv__(self, other: Expr | float) -> Expr:
        return Div(_node(other), self)

    def __pow__(self, other: Expr | float) -> Expr:
        return Pow(self, _node(other))

    def __neg__(self) -> Expr:
        return Neg(self)

    @property
    def value(self) -> float:
        raise NotImplementedError

    def children(self) -> tuple[Expr, ...]:
        """The nodes the value is computed from."""
        return ()

    def map_children(self, change: Callable[[Expr], Expr]) -> Expr:
        """The node rebuilt with ``change`` applied to each node it holds (a `Let`'s symbol
        too); a leaf is itself. `map_tree` walks a whole tree with it."""
        return self


class Sym(Expr):
    """A named quantity: its SI value, the unit it is shown in (``deg`` shows radians in
    degrees; "" for a pure number) and its plain name (``theta``, ``omega_z``,
    ``psidot_min``), from which LaTeX and MathML names are made."""

    __slots__ = ("name", "si", "unit")

    #: how many symbols have been made with a value that is not finite, other than
    #: `NAMED` (an overflow in the data): a solve during which this did not change made
    #: no such symbol, so its steps' trees need no walk to find one (solving/solve.py)
    unfinite = 0

    def __init__(self, name: str, si: float, unit: str = "") -> None:
        self.name, self.si, self.unit = name, si, unit
        try:
            if si - si != 0 and si is not NAMED:  # inf or nan: inf - inf is nan
                Sym.unfinite += 1
        except TypeError:  # not a number: counted, so the walk looks at it
            Sym.unfinite += 1

    def __repr__(self) -> str:
        return f"Sym({self.name!r}, {self.si!r}, {self.unit!r})"

    @property
    def value(self) -> float:
        return self.si


class Const(Expr):
    """A named constant printed by its name in substitutions too: ``pi``."""

    __slots__ = ("name", "si")

    def __init__(self, name: str, si: float) -> None:
        self.name, self.si = name, si

    @property
    def value(self) -> float:
        return self.si


PI = Const("pi", math.pi)


class Num(Expr):
    """An exact number of the formula: the 2 of ``2 pi``, the 4 of ``4 I m g l``;
    ``label`` writes a fraction as the chapter does (``Num(1.5, "3/2")``)."""

    __slots__ = ("si", "label")

    def __init__(self, si: float, label: str = "") -> None:
        self.si, self.label = float(si), label

    @property
    def value(self) -> float:
        return self.si

    @property
    def text(self) -> str:
        if self.label:
            return self.label
        return str(int(self.si)) if self.si.is_integer() and abs(self.si) < 1e15 else repr(self.si)


class Let(Expr):
    """A quantity known from an earlier step: the formula shows ``body`` (its
    definition), the substitution and ``expr`` only ``sym`` and its value (``D`` for
    ``H Omega_E cos(lambda)``). The body's symbols may be names only (``si`` nan)."""

    __slots__ = ("sym", "body")

    def __init__(self, sym: Sym, body: Expr) -> None:
        self.sym, self.body = sym, body

    @property
    def value(self) -> float:
        return self.sym.si

    def children(self) -> tuple[Expr, ...]:
        return (self.body,)

    def map_children(self, change: Callable[[Expr], Expr]) -> Expr:
        sym = change(self.sym)
        assert isinstance(sym, Sym)
        return Let(sym, change(self.body))


class Neg(Expr):
    __slots__ = ("arg",)

    def __init__(self, arg: Expr) -> None:
        self.arg = arg

    @property
    def value(self) -> float:
        return -self.arg.value

    def children(self) -> tuple[Expr, ...]:
        return (self.arg,)

    def map_children(self, change: Callable[[Expr], Expr]) -> Expr:
        return Neg(change(self.arg))


class BinOp(Expr):
    __slots__ = ("left", "right")
    op = ""

    def __init__(self, left: Expr, right: Expr) -> None:
        self.left, self.right = left, right

    def children(self) -> tuple[Expr, ...]:
        return (self.left, self.right)

    def map_children(self, change: Callable[[Expr], Expr]) -> Expr:
        return type(self)(change(self.left), change(self.right))


class Add(BinOp):
    __slots__ = ()
    op = "+"

    @property
    def value(self) -> float:
        return self.left.value + self.right.value


class Sub(BinOp):
    __slots__ = ()
    op = "-"

    @property
    def value(self) -> float:
        return self.left.value - self.right.value


class Mul(BinOp):
    __slots__ = ()
    op = "*"

    @property
    def value(self) -> float:
        return self.left.value * self.right.value


class Div(BinOp):
    __slots__ = ()
    op = "/"

    @property
    def value(self) -> float:
        return self.left.value / self.right.value


class Pow(BinOp):
    __slots__ = ()
    op = "^"

    @property
    def value(self) -> float:
        base, power = self.left.value, self.right.value
        if power == 2:
            return base * base  # inf past the float range, as x * x; x ** 2 would raise
        return base ** power


def agm_K(y: float) -> float:
    """K(m) = int_0^(pi/2) dx / sqrt(1 - m sin^2 x) from y = 1 - m (given exactly where m
    is near 1), by the arithmetic-geometric mean: pi / (2 M(1, sqrt(y))) (DLMF 19.8.5)."""
    a, b = 1.0, math.sqrt(y)
    while abs(a - b) > 1e-15 * a:
        a, b = (a + b) / 2, math.sqrt(a * b)
    return math.pi / (2 * a)


def _ellipk(m: float) -> float:
    """K(m), by the arithmetic-geometric mean (agm_K)."""
    return agm_K(1.0 - m)


def _ellipe(m: float) -> float:
    """E(m) = int_0^(pi/2) sqrt(1 - m sin^2 x) dx, by the arithmetic-geometric mean."""
    if m == 1.0:
        return 1.0
    a, b, power, total = 1.0, math.sqrt(1.0 - m), 0.5, m / 2
    while abs(a - b) > 1e-15 * a:
        a, b, c = (a + b) / 2, math.sqrt(a * b), (a - b) / 2
        power *= 2
        total += power * c * c
    return math.pi / (2 * a) * (1 - total)


#: the functions a formula may call: name -> (Python function, its name in `expr`)
FUNCTIONS: dict[str, Callable[..., float]] = {
    "sin": math.sin, "cos": math.cos, "tan": math.tan, "sqrt": math.sqrt,
    "asin": math.asin, "acos": math.acos, "atan": math.atan, "atan2": math.atan2,
    "exp": math.exp, "log": math.log, "abs": abs, "ellipk": _ellipk, "ellipe": _ellipe,
}
#: how the formulas show a function whose name in `expr` differs (the chapter's K(m), E(m))
SHOWN_NAMES = {"ellipk": "K", "ellipe": "E"}


class Call(Expr):
    """``name(args)`` for a function of `FUNCTIONS`."""

    __slots__ = ("name", "args")

    def __init__(self, name: str, args: tuple[Expr, ...]) -> None:
        if name not in FUNCTIONS:
            raise ValueError(f"unknown function {name!r}")
        self.name, self.args = name, args

    @property
    def value(self) -> float:
        return FUNCTIONS[self.name](*(a.value for a in self.args))

    def children(self) -> tuple[Expr, ...]:
        return self.args

    def map_children(self, change: Callable[[Expr], Expr]) -> Expr:
        return Call(self.name, tuple(change(a) for a in self.args))


class Chain(Expr):
    """One quantity written in equal forms, ``A = B``: ``m g L sin(theta) / I_O = g L
    sin(theta) / (k_G^2 + L^2)``. The formula prints every form, joined by ``=``; the
    substitution, the value and ``expr`` are the last form's. A chain is a step's whole
    tree, never an operand. Its value evaluates every form and refuses forms that disagree
    beyond 1e-9 relative (a slip in one form, or magnitudes beyond double precision)."""

    __slots__ = ("forms",)

    def __init__(self, *forms: Expr | float) -> None:
        if len(forms) < 2:
            raise ValueError("a chain holds two forms or more")
        self.forms = tuple(_node(f) for f in forms)

    def _refuse(self, *other: object) -> Expr:
        raise TypeError("a chain of equal forms is a step's whole formula, not an operand")

    __add__ = __radd__ = __sub__ = __rsub__ = __mul__ = __rmul__ = _refuse
    __truediv__ = __rtruediv__ = __pow__ = __neg__ = _refuse

    @property
    def value(self) -> float:
        values = [f.value for f in self.forms]
        last = values[-1]
        for k, v in enumerate(values[:-1]):
            if v != last and not math.isclose(v, last, rel_tol=1e-9):
                raise ValueError(f"its forms disagree: form {k + 1} gives {v!r}, the last "
                                 f"{last!r}")
        return last

    def children(self) -> tuple[Expr, ...]:
        return self.forms

    def map_children(self, change: Callable[[Expr], Expr]) -> Expr:
        return Chain(*(change(f) for f in self.forms))


class SumOf(Expr):
    """``sum m (y^2 + z^2)``: a sum over the particles of a body (Eq. 11.3). The formula
    prints ``body`` (over the symbols by name, with no value); the value, the substitution
    and ``expr`` are the sum of ``terms``, one per particle (``m_0 (y_0^2 + z_0^2) + ...``)."""

    __slots__ = ("body", "terms")

    def __init__(self, body: Expr, terms: tuple[Expr, ...]) -> None:
        if not terms:
            raise ValueError("a sum over particles needs one term or more")
        self.body, self.terms = body, tuple(_node(t) for t in terms)

    @property
    def value(self) -> float:
        return math.fsum(t.value for t in self.terms)

    def children(self) -> tuple[Expr, ...]:
        return self.terms

    def map_children(self, change: Callable[[Expr], Expr]) -> Expr:
        return SumOf(self.body, tuple(change(t) for t in self.terms))  # the body: names only

    def expanded(self) -> Expr:
        """The terms as one sum, left to right."""
        out = self.terms[0]
        for term in self.terms[1:]:
            out = Add(out, term)
        return out


def _call(name: str) -> Callable[..., Expr]:
    def build(*args: Expr | float) -> Expr:
        return Call(name, tuple(_node(a) for a in args))
    build.__name__ = name
    return build


sin, cos, tan, sqrt = _call("sin"), _call("cos"), _call("tan"), _call("sqrt")
asin, acos, atan, atan2 = _call("asin"), _call("acos"), _call("atan"), _call("atan2")
exp, log, ellipk, ellipe = _call("exp"), _call("log"), _call("ellipk"), _call("ellipe")
absolute = _call("abs")


def symbols(expr: Expr) -> dict[str, Sym]:
    """The symbols the value is computed from (of a `Let`, its symbol), by name."""
    out: dict[str, Sym] = {}

    def walk(node: Expr) -> None:
        if isinstance(node, Sym):
            out.setdefault(node.name, node)
        elif isinstance(node, Let):
            walk(node.sym)
            return
        elif isinstance(node, Chain):  # the value and `expr` are the last form's
            walk(node.forms[-1])
            return
        for child in node.children():
            walk(child)

    walk(expr)
    return out


def map_tree(expr: Expr, change: Callable[[Expr], Expr | None]) -> Expr:
    """The tree with each node for which ``change`` gives a node replaced by it, the others
    rebuilt from their mapped children (`Expr.map_children`): one walk for every mapping
    (``--units us`` of formulas and sentences, values)."""
    out = change(expr)
    if out is not None:
        return out
    return expr.map_children(lambda child: map_tree(child, change))


def map_syms(expr: Expr, change: Callable[[Sym], Sym]) -> Expr:
    """The tree with every symbol replaced by ``change(symbol)`` (``--units us``)."""
    return map_tree(expr, lambda node: change(node) if isinstance(node, Sym) else None)


# ---- brackets: one rule for every printer -----------------------------------

#: binding strength, loosest first
ADD, MUL, NEG, POW, ATOM = 10, 20, 25, 30, 50


def precedence(node: Expr, values: bool) -> int:
    """How tightly the node binds as printed; with ``values`` a symbol is its value,
    a quantity with a unit (``0.5 kg``) binds as a product and a negative number as a
    unary minus."""
    fixed = _OPERATORS.get(node.__class__)  # the operators, a third of all calls
    if fixed is not None:
        return fixed
    if isinstance(node, Let):
        return precedence(node.sym if values else node.body, values)
    own = getattr(node, "binding", None)  # the typeset-only nodes of core/prose.py
    if own is not None:
        return own
    if isinstance(node, (Add, Sub)):
        return ADD
    if isinstance(node, (Mul, Div)):
        return MUL
    if isinstance(node, SumOf):
        return ADD if values else MUL  # the terms added; sum m x y binds as a product
    if isinstance(node, Neg):
        return NEG
    if isinstance(node, Pow):
        return POW
    if isinstance(node, Num) and node.label and not values:
        return NEG if node.si < 0 else MUL
    if (values or isinstance(node, Num)) and isinstance(node, (Sym, Num)):
        if node.value < 0:
            return NEG
        if isinstance(node, Num) and node.label:
            return MUL
        if isinstance(node, Sym) and node.unit:
            return MUL
    return ATOM


#: the binding of each operator's own class (its subclasses, typeset nodes among them,
#: go the long way above)
_OPERATORS: dict[type, int] = {Add: ADD, Sub: ADD, Mul: MUL, Div: MUL, Neg: NEG, Pow: POW}


def leaf(node: Expr, values: bool) -> Expr:
    """What a `Let` prints as: its symbol's value, or in the formula its definition."""
    while isinstance(node, Let):
        node = node.sym if values else node.body
    return node


def negative_leaf(node: Expr, values: bool) -> bool:
    """A number printed with a leading minus sign."""
    node = leaf(node, values)
    return values and isinstance(node, (Sym, Num)) and node.value < 0 \
        or (not values and isinstance(node, Num) and node.value < 0)


def needs_brackets(parent: Expr, child: Expr, right: bool, values: bool) -> bool:
    """Whether ``child``, an operand of ``parent`` (its right one if ``right``), is printed
    in brackets."""
    p, c = precedence(parent, values), precedence(leaf(child, values), values)
    node = leaf(child, values)
    if isinstance(parent, (Add, Sub)):
        # a - (b + c), but a + -b is folded to a - b by the printers
        return c < p or (right and isinstance(parent, Sub) and c == p)
    if isinstance(parent, Mul):
        # ``child`` is one factor of the flattened product (`factors`); ``right``: not the first
        if c < MUL or isinstance(node, Div) or (isinstance(node, Num) and "/" in node.label):
            return True  # (a + b) c, (M / H) t, (3/2) H
        if right:
            # every factor after the first that is a quantity or a signed number:
            # 0.0005120 kg m^2 (-179.7 rad/s), 2 (0.5 kg)
            return c in (MUL, NEG) or (values and isinstance(node, (Num, Sym)))
        return False
    if isinstance(parent, Div):
        if right:  # a / (b c), a / (b / c), a / (-b), a / (0.3 kg m^2/s)
            return c <= MUL or c == NEG
        return c < MUL or isinstance(node, Div)
    if isinstance(parent, Pow):
        return c < ATOM or isinstance(node, (Pow,)) if not right else c < ATOM
    if isinstance(parent, Neg):
        # -(-2.000 rad/s sin(x)): a product or quotient printed with a leading minus
        return c < MUL or c == NEG or leading_negative(node, values) or \
            getattr(node, "bracket_after_sign", False)  # -(omega_p x H)
    return False


def leading_negative(node: Expr, values: bool) -> bool:
    """A product or quotient whose printed text starts with a minus sign."""
    while isinstance(node, (Mul, Div)):
        node = leaf(factors(node, values)[0] if isinstance(node, Mul) else node.left, values)
    return negative_leaf(node, values) or isinstance(node, Neg)


def trig_power(node: Pow) -> str:
    """``"2"`` for sin(x)^2 (printed sin^2(x)), else ""."""
    if isinstance(node.left, Call) and node.left.name in ("sin", "cos", "tan") \
            and isinstance(node.right, Num) and node.right.si in (2.0, 3.0):
        return node.right.text
    return ""


def factors(node: Expr, values: bool) -> list[Expr]:
    """The factors of a product, left to right: ``(a b) (c d)`` -> [a, b, c, d] (and in
    the formula, those of a `Let`'s definition)."""
    if isinstance(node, Mul):
        return factors(node.left, values) + factors(node.right, values)
    if not values and isinstance(node, Let) and isinstance(node.body, Mul):
        return factors(node.body, values)
    return [node]


# ---- printers ---------------------------------------------------------------

_METHODS: dict[tuple[type, type], Callable[..., Any]] = {}  # (printer, node class) -> method


class Printer:
    """The one base of gyro's printers, as sympy's: dispatch on the node's class along its
    bases (``_print_Sym`` prints a Sym), settings as attributes. ``values``: print the
    substitution (each symbol's value and unit) rather than the formula. The text and
    Python printers here, `core.prose`'s, and the LaTeX and MathML printers of
    ``render/`` subclass it."""

    values = False

    def __init__(self, values: bool = False) -> None:
        self.values = values

    def doprint(self, node: Any) -> Any:
        return self._print(node)

    def _print(self, node: Any) -> Any:
        # the method for each (printer class, node class) is looked up once, not at
        # every node: the lookup by name along the node's classes was a third of printing
        key = (self.__class__, node.__class__)
        method = _METHODS.get(key)
        if method is None:
            for cls in type(node).__mro__:
                method = getattr(type(self), f"_print_{cls.__name__}", None)
                if method is not None:
                    break
            else:
                raise TypeError(f"no printer for {type(node).__name__}")
            _METHODS[key] = method
        return method(self, node)

    def operand(self, parent: Expr, child: Expr, right: bool = False) -> Any:
        text = self._print(child)
        return self.brackets(text) if needs_brackets(parent, child, right, self.values) else text

    def brackets(self, inner: str, open_: str = "(", close: str = ")") -> str:
        return f"{open_}{inner}{close}"


def quantity_text(value: float, unit: str) -> str:
    """``0.5000 kg``; an angle held in rad and shown in deg is converted."""
    unit = UNIT_TEXT.get(unit, unit)
    shown = value / SHOWN[unit][0] if unit in SHOWN else value
    return f"{num(shown)} {unit}".rstrip()


class TextPrinter(Printer):
    """The plain text of the reports: ``m g l sin(theta)`` or, with ``values``,
    ``0.08498 kg (9.815 m/s^2) (0.03810 m) sin(30.00 deg)``."""

    def _print_Sym(self, node: Sym) -> str:
        return quantity_text(node.si, node.unit) if self.values else node.name

    def _print_Const(self, node: Const) -> str:
        return node.name

    def _print_Num(self, node: Num) -> str:
        return node.text

    def _print_Let(self, node: Let) -> str:
        return self._print(node.sym) if self.values else self._print(node.body)

    def _print_Neg(self, node: Neg) -> str:
        return "-" + self.operand(node, node.arg)

    def _print_Chain(self, node: Chain) -> str:
        if self.values:
            return self._print(node.forms[-1])
        return " = ".join(self._print(f) for f in node.forms)

    def _print_SumOf(self, node: SumOf) -> str:
        if self.values:
            return self._print(node.expanded())
        body = self._print(node.body)
        return "sum " + (f"({body})" if precedence(node.body, False) <= ADD else body)

    def _sum(self, node: BinOp, op: str) -> str:
        left = self.operand(node, node.left)
        right = self.operand(node, node.right, right=True)
        if right.startswith("-"):  # a + -b -> a - b; a - -b -> a + b
            op, right = {"+": "-", "-": "+"}[op], right[1:]
        return f"{left} {op} {right}"

    def _print_Add(self, node: Add) -> str:
        return self._sum(node, "+")

    def _print_Sub(self, node: Sub) -> str:
        return self._sum(node, "-")

    def _print_Mul(self, node: Mul) -> str:
        return " ".join(self.operand(node, f, k > 0) for k, f in enumerate(factors(node, self.values)))

    def _print_Div(self, node: Div) -> str:
        return f"{self.operand(node, node.left)} / {self.operand(node, node.right, True)}"

    def _print_Pow(self, node: Pow) -> str:
        n = trig_power(node)
        if n:  # sin^2(theta), as the chapter writes it
            call = node.left
            assert isinstance(call, Call)
            return f"{call.name}^{n}({', '.join(self._print(a) for a in call.args)})"
        return f"{self.operand(node, node.left)}^{self.operand(node, node.right, True)}"

    def _print_Call(self, node: Call) -> str:
        if node.name == "abs":
            return f"|{self._print(node.args[0])}|"
        name = SHOWN_NAMES.get(node.name, node.name)
        return f"{name}({', '.join(self._print(a) for a in node.args)})"


class PythonPrinter(Printer):
    """The formula in Python syntax over its symbols' names (the JSON ``expr``):
    ``m*g*l*sin(theta)``; evaluated with `python_names` it gives the step's value."""

    def __init__(self) -> None:
        super().__init__(values=False)

    def _print_Sym(self, node: Sym) -> str:
        return python_name(node.name)

    def _print_Const(self, node: Const) -> str:
        return node.name if node.name == "pi" else repr(node.si)

    def _print_Num(self, node: Num) -> str:
        return node.text

    def _print_Let(self, node: Let) -> str:
        return python_name(node.sym.name)

    def _prec(self, node: Expr) -> int:
        if isinstance(node, Let):
            return ATOM
        if isinstance(node, Num) and node.si < 0:
            return NEG
        return precedence(node, values=False)

    def _print_Neg(self, node: Neg) -> str:
        inner = self._print(node.arg)
        return f"-({inner})" if self._prec(node.arg) < POW else f"-{inner}"

    def _print_BinOp(self, node: BinOp) -> str:
        op = {"^": "**"}.get(node.op, node.op)
        mine, lp, rp = self._prec(node), self._prec(node.left), self._prec(node.right)
        left, right = self._print(node.left), self._print(node.right)
        if lp < mine or (isinstance(node, Pow) and lp <= POW):
            left = f"({left})"
        if rp < mine or (rp == mine and not isinstance(node, Pow)) or \
                (isinstance(node, Pow) and rp < ATOM):
            right = f"({right})"
        return f"{left}{op}{right}"

    def _print_Call(self, node: Call) -> str:
        return f"{node.name}({', '.join(self._print(a) for a in node.args)})"

    def _print_Chain(self, node: Chain) -> str:
        return self._print(node.forms[-1])

    def _print_SumOf(self, node: SumOf) -> str:
        return f"({self._print(node.expanded())})"


def python_name(name: str) -> str:
    """A symbol's name as a Python identifier: ``lambda`` -> ``lambda_``, ``F_A,weight``
    -> ``F_A_weight``."""
    out = "".join(c if c.isalnum() or c == "_" else "_" for c in name)
    if not out or out[0].isdigit():
        out = "_" + out
    return out + "_" if keyword.iskeyword(out) else out


def formula(expr: Expr) -> str:
    return TextPrinter(values=False).doprint(expr)


def substitution(expr: Expr) -> str:
    return TextPrinter(values=True).doprint(expr)


def python(expr: Expr) -> str:
    return PythonPrinter().doprint(expr)


def python_names() -> dict[str, object]:
    """What an ``expr`` may call: the functions above and ``pi``."""
    return {**FUNCTIONS, "pi": math.pi}
