"""The symmetric body: mass, axial inertia J, transverse inertia I.

Built once from the body keys of a problem file (see the format page): mass
from ``mass`` or ``weight``/g, J and the transverse inertias from moments of
inertia, radii of gyration, the parallel-axis theorem or a ``shape``. Every
formula used is written into the worked answer.
"""

from __future__ import annotations

import math
from collections.abc import Callable

from .errors import InputError
from .expr import Expr, Sym, tan
from .params import Param
from .prose import names, q, rel
from .record import record
from .work import Work

G_SI = 9.81         # m/s^2, the format's default
G_US = 32.2 * 0.3048  # 32.2 ft/s^2 in m/s^2, the textbook value for US data

# where the mass plays no part the file leaves it out (the loader adds this to a refusal)
_MASS_OUT = "where the mass plays no part (only a couple or a rate is asked), leave mass out"

BODY_PARAMS: tuple[Param, ...] = (
    Param("mass", "mass", "m", "mass of the body", positive=True, reason=_MASS_OUT),
    Param("weight", "force", "W", "weight of the body (lb and oz read as lbf and ozf)",
          positive=True, reason=_MASS_OUT),
    Param("g", "acceleration", "g", "gravity; default 9.81 m/s^2, or 32.2 ft/s^2 for US data",
          positive=True),
    Param("J", "inertia", "J", "moment of inertia about the symmetry axis", positive=True),
    Param("k_axial", "length", "k_z", "radius of gyration about the symmetry axis",
          positive=True),
    Param("I_pivot", "inertia", "I", "transverse moment of inertia about the fixed point",
          positive=True),
    Param("k_pivot", "length", "k_O", "transverse radius of gyration about the fixed point",
          positive=True),
    Param("I_cg", "inertia", "I_G", "transverse moment of inertia about the centre of mass",
          positive=True),
    Param("k_cg", "length", "k_G", "transverse radius of gyration about the centre of mass",
          positive=True),
    Param("shape", "word", "shape", "disk, ring, cylinder, sphere, cone (solid, apex at the "
          "fixed point), shell (thin tube), rod, hollow_sphere, box (square section) or "
          "annulus", choices=("disk", "ring", "cylinder", "sphere", "cone", "shell", "rod",
                              "hollow_sphere", "box", "annulus"),
          words=(("disc", "disk"), ("solid_disk", "disk"), ("solid_disc", "disk"),
                 ("hoop", "ring"), ("thin_ring", "ring"), ("solid_cylinder", "cylinder"),
                 ("solid_sphere", "sphere"), ("solid_cone", "cone"),
                 ("thin_cylindrical_shell", "shell"), ("cylindrical_shell", "shell"),
                 ("tube", "shell"), ("thin_tube", "shell"), ("spherical_shell", "hollow_sphere"),
                 ("thin_spherical_shell", "hollow_sphere"), ("thin_rod", "rod"),
                 ("slender_rod", "rod"), ("hollow_cylinder", "annulus"),
                 ("thick_ring", "annulus"), ("washer", "annulus"), ("block", "box"))),
    Param("radius", "length", "r", "radius of the shape (the outer radius of an annulus)",
          positive=True),
    Param("diameter", "length", "d", "diameter of the shape", positive=True),
    Param("inner_radius", "length", "r_i", "inner radius of an annulus", positive=True),
    Param("width", "length", "w", "side of a box's square cross-section", positive=True),
    Param("length", "length", "L", "length of a cylinder, shell, rod, box or annulus along "
          "its axis", positive=True),
    Param("height", "length", "h", "height of a cone, apex to base", positive=True),
    Param("vertex_angle", "angle", "theta_v", "a cone's total angle at its apex (twice the "
          "semi-angle alpha), with its height or radius, or alone where only ratios matter",
          range=(0.0, math.pi), bounds="()"),
    Param("cg_distance", "length", "l", "fixed point to centre of mass along the symmetry axis",
          nonnegative=True),
)

@record(frozen=True)
class Shape:
    """A uniform body of revolution (or square section) about its symmetry axis.

    ``J`` and ``I_G`` take the mass and the dimensions (r, r_i, w, L, h) as symbols and
    give the trees of the axial and the transverse moment about the centre of mass;
    ``needs`` and ``may`` are the dimension keys it must and may have (radius stands for
    radius or diameter).
    """

    J: Callable[[Expr, dict[str, Expr]], Expr]
    I_G: Callable[[Expr, dict[str, Expr]], Expr]
    needs: tuple[str, ...]
    may: tuple[str, ...] = ()


SHAPES: dict[str, Shape] = {
    "disk": Shape(lambda m, d: m * d["r"] ** 2 / 2, lambda m, d: m * d["r"] ** 2 / 4,
                  ("radius",)),
    "ring": Shape(lambda m, d: m * d["r"] ** 2, lambda m, d: m * d["r"] ** 2 / 2, ("radius",)),
    "cylinder": Shape(lambda m, d: m * d["r"] ** 2 / 2,
                      lambda m, d: m * (3 * d["r"] ** 2 + d["L"] ** 2) / 12,
                      ("radius",), ("length",)),
    "sphere": Shape(lambda m, d: 2 * m * d["r"] ** 2 / 5, lambda m, d: 2 * m * d["r"] ** 2 / 5,
                    ("radius",)),
    "cone": Shape(lambda m, d: 3 * m * d["r"] ** 2 / 10,
                  lambda m, d: m * (3 * d["r"] ** 2 / 20 + 3 * d["h"] ** 2 / 80),
                  ("radius", "height")),
    # thin cylindrical tube: all its mass at r; a ring at each section, spread over L
    "shell": Shape(lambda m, d: m * d["r"] ** 2,
                   lambda m, d: m * d["r"] ** 2 / 2 + m * d["L"] ** 2 / 12,
                   ("radius", "length")),
    "rod": Shape(lambda m, d: m * d["r"] ** 2 / 2,
                 lambda m, d: m * (3 * d["r"] ** 2 + d["L"] ** 2) / 12, ("length",), ("radius",)),
    "hollow_sphere": Shape(lambda m, d: 2 * m * d["r"] ** 2 / 3,
                           lambda m, d: 2 * m * d["r"] ** 2 / 3, ("radius",)),
    "box": Shape(lambda m, d: m * d["w"] ** 2 / 6,
                 lambda m, d: m * (d["w"] ** 2 + d["L"] ** 2) / 12, ("width", "length")),
    "annulus": Shape(lambda m, d: m * (d["r"] ** 2 + d["r_i"] ** 2) / 2,
                     lambda m, d: m * (3 * (d["r"] ** 2 + d["r_i"] ** 2) + d["L"] ** 2) / 12,
                     ("radius", "inner_radius"), ("length",)),
}

DIMENSION_KEYS = {"radius": "r", "inner_radius": "r_i", "width": "w", "length": "L",
                  "height": "h"}

#: shapes whose J / I_G is a pure number (one size, r): a problem asking only rates may
#: give no size at all (a tossed coin), where the kind allows it
SIZELESS = ("disk", "ring", "sphere", "hollow_sphere")
_SIZE_KEYS = ("radius", "diameter", "inner_radius", "width", "length", "height")
# an inertia-only key that would fix the size
_INERTIA_KEYS = ("J", "k_axial", "I_pivot", "k_pivot", "I_cg", "k_cg")


def sizeless_body(values: dict, allowed: bool) -> bool:
    """Whether the body is a shape given with no size, its rates worked per unit r^2:
    a shape of SIZELESS (or a cone by its vertex angle), no dimension and no inertia, in a
    kind that ``allowed`` it."""
    shape = values.get("shape")
    return allowed and (shape in SIZELESS or shape == "cone" and "vertex_angle" in values) \
        and not any(k in values for k in _SIZE_KEYS + _INERTIA_KEYS)


def _cone_by_vertex_angle(values: dict, sizeless: bool, work: Work) -> dict:
    """``values`` with a cone's radius or height from its total vertex angle 2 alpha and
    the other size (per unit radius where the body has no size), each a step."""
    if "vertex_angle" not in values:
        return values
    if values.get("shape") != "cone":
        raise InputError("vertex_angle is a cone's angle at its apex: give `shape: cone`",
                         key="given.vertex_angle")
    sizes = [k for k in ("radius", "diameter", "height") if k in values]
    if len(sizes) > 1:
        raise InputError(f"a cone is given by two of radius (or diameter), height and "
                         f"vertex_angle: {sizes[0]}, {sizes[1]} and vertex_angle are three",
                         key="given.vertex_angle")
    if not sizes and not sizeless:
        raise InputError("a cone by its vertex_angle needs its height or radius too (only "
                         "rates that need no gravity moment can do without)",
                         key="given.height")
    values = dict(values)
    alpha = Sym("alpha", work.step("alpha", Sym("theta_v", values["vertex_angle"], "deg") / 2,
                                   unit="deg", note="the cone's semi-angle") * math.pi / 180,
                "deg")
    if "height" in values:
        values["radius"] = work.step("r", Sym("h", values["height"], "m") * tan(alpha),
                                     unit="m", note="base radius")
    else:
        r = values["radius"] if "radius" in values else \
            values["diameter"] / 2 if "diameter" in values else 1.0  # no size: per unit r
        values["height"] = work.step("h", Sym("r", r, "m") / tan(alpha), unit="m",
                                     note="height, apex to base")
    return values


def _shape_keys(shape: str) -> str:
    spec = SHAPES[shape]
    names = [("radius or diameter" if k == "radius" else k) for k in spec.needs]
    names += [("radius or diameter" if k == "radius" else k) + " (optional)" for k in spec.may]
    return ", ".join(names)


def _check_shape_keys(values: dict, shape: str | None, sizeless: bool = False) -> None:
    """Every dimension a shape needs is there (none, for a body of no size whose rates
    need only its ratios); none it does not use is (a ring's length)."""
    if shape is None:
        for key in ("inner_radius", "width", "height", "length"):
            if key in values:
                raise InputError(f"{key} is a dimension of a shape: give `shape` too (see "
                                 "`gyro kinds`)", key=f"given.{key}")
        return
    spec = SHAPES[shape]
    used = set(spec.needs) | set(spec.may)
    for key in ("radius", "diameter", "inner_radius", "width", "length", "height"):
        if key in values and ("radius" if key == "diameter" else key) not in used:
            hint = {("ring", "length"): "; a thin tube with a length is `shape: shell`",
                    ("disk", "length"): "; a disk with a length is `shape: cylinder`",
                    ("disk", "inner_radius"): "; a disk with a hole is `shape: annulus`",
                    ("ring", "inner_radius"): "; a thick ring is `shape: annulus`"}.get(
                (shape, key), "")
            raise InputError(f"shape {shape} does not use {key}: its keys are "
                             f"{_shape_keys(shape)}{hint}", key=f"given.{key}")
    for key in spec.needs:
        if key == "radius" and "radius" not in values and "diameter" not in values and \
                not sizeless and not (shape == "cone" and "vertex_angle" in values):
            raise InputError(f"shape {shape!r} needs radius or diameter (its keys: "
                             f"{_shape_keys(shape)})", key="given.shape")
        if key != "radius" and key not in values and not (shape == "cone"):
            raise InputError(f"shape {shape} needs {key} (its keys: {_shape_keys(shape)})",
                             key=f"given.{key}")
    if shape == "annulus" and values["inner_radius"] >= _outer(values):
        raise InputError("inner_radius must be less than the outer radius", 
                         key="given.inner_radius")


def _outer(values: dict) -> float:
    return values["radius"] if "radius" in values else values["diameter"] / 2


@record(frozen=True)
class Body:
    """A symmetric body, SI. Absent inertias are None; ``require`` names what is missing."""

    mass: float | None
    g: float
    J: float | None = None
    I_cg: float | None = None
    I_pivot: float | None = None
    l: float = 0.0
    radius: float | None = None
    shape: str | None = None
    per_kg: bool = False  # no mass given and none needed: inertias and m g l per kilogram
    per_size: bool = False  # a shape with no size: inertias per unit r^2 (only ratios used)

    @property
    def mass_for_rates(self) -> float:
        """The mass in J, I and m g l: the mass, or 1 kg where it cancels from the rates."""
        return 1.0 if self.per_kg else self.m

    @property
    def m(self) -> float:
        """The mass; InputError where the file gave neither mass nor weight."""
        if self.mass is None:
            raise InputError("this problem needs the body's `mass` or `weight`", key="given.mass")
        return self.mass

    @property
    def weight(self) -> float:
        return self.m * self.g

    @property
    def mgl(self) -> float:
        """m g l: the gravity moment per unit sin(theta) (Eq. 11.11); 0 when l = 0."""
        return self.mass_for_rates * self.g * self.l if self.l else 0.0

    def needed(self, name: str) -> float:
        """The body's ``name`` (J, I_cg, I_pivot, radius), refused as `require` refuses it."""
        self.require(name)
        value: float = getattr(self, name)
        return value

    def require(self, *names: str) -> None:
        """Raise InputError naming the body data a kind needs but lacks."""
        how = {"J": "J, k_axial or a shape", "I_pivot": "I_pivot, k_pivot, I_cg or k_cg "
               "(with cg_distance) or a shape", "I_cg": "I_cg, k_cg or a shape",
               "radius": "radius or diameter"}
        for name in names:
            if getattr(self, name) is None:
                raise InputError(f"this problem needs {how.get(name, name)} in `given`",
                                 key=f"given.{name}")


def build_body(values: dict, us_customary: bool, work: Work, sizeless_ok: bool = False,
               gravity: bool = True) -> Body:
    """Make the Body from SI values; writes the 'Body' section of the answer.

    ``sizeless_ok``: the kind's rates need only J / I (no gravity, no force), so a shape
    of SIZELESS may come with no size; ``gravity``: the kind has a gravity moment (a cone
    pivoted at its apex unless cg_distance says otherwise)."""
    if "mass" in values and "weight" in values:
        raise InputError("give mass or weight, not both", key="given.weight")
    needs_mass = [k for k in ("k_axial", "k_pivot", "k_cg", "shape", "cg_distance") if k in values
                  and not (k == "cg_distance" and values[k] == 0)]  # l = 0: no gravity moment
    per_kg = bool(needs_mass) and "mass" not in values and "weight" not in values and \
        not {"J", "I_pivot", "I_cg"} & set(values) and \
        bool({"shape", "k_axial", "k_pivot", "k_cg"} & set(values))
    if "mass" not in values and "weight" not in values and needs_mass and not per_kg:
        raise InputError(f"the body needs `mass` or `weight` (to go with {needs_mass[0]})",
                         key="given.mass")
    if "radius" in values and "diameter" in values:
        raise InputError("give radius or diameter, not both", key="given.diameter")
    sizeless = sizeless_body(values, sizeless_ok)
    if sizeless and values.get("cg_distance"):
        raise InputError("the gravity moment m g l against the inertia (m r^2) needs the "
                         "body's size: give radius or diameter", key="given.radius")
    if sizeless and gravity and values.get("shape") == "cone" and "cg_distance" not in values:
        raise InputError("the gravity moment m g l (l = 3 h / 4, apex at the fixed point) "
                         "against the inertia needs the cone's size: give its height or "
                         "radius with vertex_angle", key="given.height")
    _check_shape_keys(values, values.get("shape"), sizeless)

    work.section("Body")
    g = values.get("g", G_US if us_customary else G_SI)
    if "mass" in values:
        m = values["mass"]
    elif per_kg:
        m = 1.0
        mass = names("m")[0]
        work.text("no mass given: the inertias and the gravity moment are all proportional to "
                  "the mass ", mass, ", so the rates do not depend on it; the work below is per "
                  "kilogram (", rel(mass, "=", q(1.0, "kg", exact=True)), ")")
    elif "weight" not in values:
        m = None
    else:
        m = work.step("m", Sym("W", values["weight"], "N") / Sym("g", g, "m/s^2"), unit="kg")
    r = values.get("radius")
    if r is None and "diameter" in values:
        r = work.step("r", Sym("d", values["diameter"], "m") / 2, unit="m")
    if sizeless:
        r = 1.0
        radius = names("r")[0]
        work.text("no size given: the inertias below are all proportional to ", radius ** 2,
                  ", so the rates, which need only their ratio, do not depend on it; the "
                  "work is per unit radius (", rel(radius, "=", q(1.0, "m", exact=True)), ")")
    values = _cone_by_vertex_angle(values, sizeless, work)
    if r is None and "radius" in values:  # a cone's, from its height and vertex angle
        r = values["radius"]
    shape = values.get("shape")
    l = values.get("cg_distance")
    if shape == "cone" and l is None and "height" in values:
        l = work.step("l", 3 * Sym("h", values["height"], "m") / 4, unit="m",
                      note="apex at the fixed point")
    J = _axial(values, m, r, shape, work)
    I_cg = _transverse_cg(values, m, r, shape, work)
    I_pivot = _transverse_pivot(values, m, I_cg, l, work)
    _check_inertias(values, m, J, I_cg, I_pivot, l, work)
    return Body(mass=None if per_kg else m, g=g, J=J, I_cg=I_cg, I_pivot=I_pivot, l=l or 0.0,
                radius=None if sizeless else r, shape=shape, per_kg=per_kg, per_size=sizeless)


# Rounded textbook data may miss the inequalities below by a little; more than this is an error.
INERTIA_SLACK = 0.01


def _check_inertias(values: dict, m: float | None, J: float | None, I_cg: float | None,
                    I_pivot: float | None, l: float | None, work: Work) -> None:
    """Warn of inertias no rigid body has: J <= 2 I_G (I_z <= I_x + I_y) and I >= m l^2.

    Textbooks do print such data (a radius of gyration about the pivot shorter
    than the pivot-to-centre distance); the problem is solved as given, and the
    warning names the inconsistency. The equations stay meaningful.
    """
    if I_pivot is not None and l and m is not None:
        if I_pivot < m * l * l * (1 - INERTIA_SLACK):
            key = "k_pivot" if "k_pivot" in values else "I_pivot"
            I, I_G, m_, l_ = names("I I_G m l")
            work.warn(f"{key}: ", I, " about the fixed point ",
                      rel(None, "=", q(I_pivot, "kg m^2")), " is less than ",
                      rel(m_ * l_**2, "=", q(m * l * l, "kg m^2")), ", which no rigid body can "
                      "have (parallel axes: ", rel(I, "=", I_G + m_ * l_**2), ", with ", I_G,
                      " about the centre of mass); solved with the data as given")
        if I_cg is None:
            I_cg = max(I_pivot - m * l * l, 0.0)
    if J is not None and I_cg is not None and J > 2 * I_cg * (1 + INERTIA_SLACK):
        key = "J" if "J" in values else "k_axial" if "k_axial" in values else "shape"
        J_, I_G = names("J I_G")
        work.warn(J_ if key == "J" else key, ": ", rel(J_, "=", q(J, "kg m^2")), " exceeds twice "
                  "the transverse moment ", I_G, " about the centre of mass, ",
                  rel(2 * I_G, "=", q(2 * I_cg, "kg m^2")), ", which no rigid body can have (the "
                  "axial moment is at most the sum of the two transverse ones); solved with the "
                  "data as given")


def _axial(values: dict, m: float, r: float | None, shape: str | None, work: Work) -> float | None:
    if "J" in values:
        return values["J"]
    if "k_axial" in values:
        k = values["k_axial"]
        return work.step("J", Sym("m", m, "kg") * Sym("k_z", k, "m") ** 2, unit="kg*m^2")
    if shape:
        spec, dims = SHAPES[shape], _dimensions(values, r)
        return work.step("J", spec.J(Sym("m", m, "kg"), dims), unit="kg*m^2",
                         note=f"({shape.replace('_', ' ')})")
    return None


def _dimensions(values: dict, r: float | None) -> dict[str, Expr]:
    """The shape's dimensions as symbols (r, r_i, w, L, h), 0 where not given."""
    dims = {symbol: values.get(key, 0.0) for key, symbol in DIMENSION_KEYS.items()}
    dims["r"] = r if r is not None else 0.0
    return {symbol: Sym(symbol, value, "m") for symbol, value in dims.items()}


def _transverse_cg(values: dict, m: float, r: float | None, shape: str | None,
                   work: Work) -> float | None:
    if "I_cg" in values:
        return values["I_cg"]
    if "k_cg" in values:
        k = values["k_cg"]
        return work.step("I_G", Sym("m", m, "kg") * Sym("k_G", k, "m") ** 2, unit="kg*m^2")
    if shape:
        if shape == "cone" and "height" not in values:
            raise InputError("a cone needs its height", key="given.height")
        spec, dims = SHAPES[shape], _dimensions(values, r)
        L, h, w = names("L h w")  # the shape's dimensions, as its formula names them
        what: tuple = {"cylinder": ("cylinder of length ", L), "cone": ("cone of height ", h),
                       "shell": ("thin tube of length ", L), "rod": ("rod of length ", L),
                       "box": ("box of square section ", w, " and length ", L),
                       "annulus": ("annulus of length ", L)}.get(shape,
                                                                 (shape.replace("_", " "),))
        if shape in ("cylinder", "annulus") and "length" not in values:
            what = (f"{shape}; its length ", L, " not given, taken as 0")
        note = ("(", *what, ", about its centre of mass)")
        return work.step("I_G", spec.I_G(Sym("m", m, "kg"), dims), unit="kg*m^2",
                         note=note if len(what) > 1 else "".join(note))
    return None


def _transverse_pivot(values: dict, m: float, I_cg: float | None, l: float | None,
                      work: Work) -> float | None:
    if "I_pivot" in values:
        return values["I_pivot"]
    if "k_pivot" in values:
        if m is None:
            return None  # needs the mass, which the kind did not ask for
        k = values["k_pivot"]
        return work.step("I", Sym("m", m, "kg") * Sym("k_O", k, "m") ** 2, unit="kg*m^2")
    if I_cg is not None and l is not None and m is None:
        # no mass given (none needed): only a fixed point at the centre of mass is known
        return work.step("I", Sym("I_G", I_cg, "kg m^2"), unit="kg*m^2", substitute=False,
                         note=("(", rel(names("l")[0], "=", 0), ": the fixed point is the centre "
                               "of mass)")) if l == 0 else None
    if I_cg is not None and l is not None:
        return work.step("I", Sym("I_G", I_cg, "kg m^2") + Sym("m", m, "kg") * Sym("l", l, "m")
                         ** 2, unit="kg*m^2", note="(parallel axes, about the fixed point)")
    return None


def spin_angular_momentum(given, work: Work) -> float:
    """A rotor's spin angular momentum H = J psidot, or ``angular_momentum`` as given.

    For the kinds that need only H (gyro drift, the gyrocompass, rate gyros):
    either the rotor (J, k_axial or a shape) with its spin, or H itself, not both.
    """
    if "angular_momentum" in given:
        for key in ("spin", "J", "k_axial", "shape"):
            if key in given:
                raise InputError(f"give angular_momentum, or the rotor ({key}) and its spin, "
                                 "not both", key=f"given.{key}")
        H = given["angular_momentum"]
        work.step("H", value=H, unit="kg m^2/s", note="as given")
        return H
    if "spin" not in given:
        raise InputError("give the rotor's spin (with J, k_axial or a shape), or "
                         "angular_momentum", key="given.spin")
    J = given.body.J if given.body is not None else None
    if J is None:
        raise InputError("the rotor needs its axial inertia: J, k_axial or a shape (or give "
                         "angular_momentum)", key="given.J")
    spin = given["spin"]
    return work.step("H", Sym("J", J, "kg m^2") * Sym("psidot", spin, "rad/s"), unit="kg m^2/s",
                     ref="angular momentum of the rotor")


# ---- the vehicles' data as books give them ---------------------------------------

def vehicle_params(*rotors: str) -> tuple[Param, ...]:
    """The keys a vehicle kind adds for books' data: its weight, and each rotor (wheel,
    axle, engine) by its mass and radius of gyration."""
    params = [Param("weight", "force", "W", "instead of mass: the weight ('weighs 20 kN'); "
                    "m = W / g", positive=True)]
    for rotor in rotors:
        params += [Param(f"{rotor}_mass", "mass", f"m_{rotor[0]}", f"instead of "
                         f"{rotor}_inertia: the {rotor}'s mass, with {rotor}_k", nonnegative=True),
                   Param(f"{rotor}_k", "length", f"k_{rotor[0]}", f"the {rotor}'s radius of "
                         f"gyration about its axle: {rotor}_inertia = {rotor}_mass {rotor}_k^2",
                         nonnegative=True)]
    return tuple(params)


def vehicle_data(given, work: Work, *rotors: str):
    """A copy of ``given`` with ``mass`` from ``weight`` and each ``<rotor>_inertia`` from
    ``<rotor>_mass`` and ``<rotor>_k``, each written as a step."""
    from dataclasses import replace

    values = dict(given.values)
    steps = []
    if "weight" in values:
        if "mass" in values:
            raise InputError("give mass or weight, not both", key="given.weight")
        W, g = values["weight"], values["g"]
        values["mass"] = W / g
        steps.append(("m", Sym("W", W, "N") / Sym("g", g, "m/s^2"), "kg"))
    for rotor in rotors:
        mass_key, k_key, inertia_key = f"{rotor}_mass", f"{rotor}_k", f"{rotor}_inertia"
        if mass_key not in values and k_key not in values:
            continue
        if mass_key not in values or k_key not in values:
            missing = k_key if mass_key in values else mass_key
            raise InputError(f"{inertia_key} from the mass needs {mass_key} and {k_key} "
                             f"({inertia_key} = {mass_key} {k_key}^2)", key=f"given.{missing}")
        if inertia_key in values and inertia_key not in given.defaulted:
            raise InputError(f"give {inertia_key}, or {mass_key} with {k_key}, not both",
                             key=f"given.{mass_key}")
        m, k = values[mass_key], values[k_key]
        symbol = {"wheel": "I_w", "engine": "I_E", "axle": "I_axle"}.get(rotor, inertia_key)
        values[inertia_key] = m * k * k
        steps.append((symbol, Sym(f"m_{rotor[0]}", m, "kg") * Sym(f"k_{rotor[0]}", k, "m") ** 2,
                      "kg*m^2"))
    if steps:
        work.section("Data as given")
        for symbol, tree, unit in steps:
            work.step(symbol, tree, unit=unit)
    return replace(given, values=values, defaulted={k for k in given.defaulted
                                                    if values.get(k) == given.values.get(k)})
