"""Pictures of the heavy top's motion, as in the chapter's Figs. 11-7, 11-9, 11-10.

The path of the symmetry axis on the unit sphere seen from above,
x = sin(theta) cos(phi), y = sin(theta) sin(phi), between the bounding circles
theta_min and theta_max; below it theta(t) and phidot(t). Cusps (Fig. 11-9) are
the points where phidot = 0 on the theta_min circle; loops (Fig. 11-10) appear
where phidot changes sign; waves where it keeps one sign.

matplotlib is imported inside the functions (Agg backend, no display needed).
"""

from __future__ import annotations

import io
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .picture_formats import FORMATS


@dataclass
class PathData:
    """What a plot shows: a time series (SI, rad) and the bounding circles."""

    t: np.ndarray
    theta: np.ndarray
    phi: np.ndarray
    phidot: np.ndarray
    theta_min: float
    theta_max: float
    title: str = ""
    motion: str = ""
    source: str = ""       # "simulated" or "analytic": said on the figure
    rate_unit: str = "rad/s"   # phidot is drawn in this unit ...
    rate_per_si: float = 1.0   # ... one rad/s being this many of it


# A band between the circles narrower than this fraction of its radius is no
# visible nutation (a steady precession integrated to 1e-12 wobbles by ~1e-10):
# it is drawn as one steady circle, never widened into a false nutation.
VISIBLE_BAND = 1e-6


def radius(theta, below: bool = False):
    """Distance from the centre of the picture: sin(theta) seen from above, or
    theta / 90 deg (azimuthal equidistant) when the path goes below the
    horizontal, where sin(theta) would fold the lower hemisphere back inside."""
    return np.asarray(theta) / (0.5 * math.pi) if below else np.sin(theta)


def path_xy(theta: np.ndarray, phi: np.ndarray,
            below: bool = False) -> tuple[np.ndarray, np.ndarray]:
    """The axis seen from above: x = r cos(phi), y = r sin(phi), r = sin(theta)."""
    r = radius(theta, below)
    return r * np.cos(phi), r * np.sin(phi)


def circle_xy(theta: float, n: int = 361,
              below: bool = False) -> tuple[np.ndarray, np.ndarray]:
    """The circle of constant theta seen from above (radius sin(theta))."""
    a = np.linspace(0.0, 2 * math.pi, n)
    r = float(radius(theta, below))
    return r * np.cos(a), r * np.sin(a)


def crosses_horizontal(data: PathData) -> bool:
    """True when the path reaches below the horizontal plane through the pivot."""
    return data.theta_max > 0.5 * math.pi + 1e-9


def is_steady(data: PathData) -> bool:
    """No visible nutation: the band is narrower than VISIBLE_BAND of its radius."""
    lo, hi = float(radius(data.theta_min)), float(radius(data.theta_max))
    mid = 0.5 * (abs(lo) + abs(hi))
    return mid > 0 and abs(hi - lo) <= VISIBLE_BAND * mid


def stationary_points(data: PathData, zero: float = 1e-3) -> np.ndarray:
    """Indices where phidot vanishes: sign changes (loop turn points) and touch-downs
    (cusps, local minima of |phidot| below ``zero`` times its largest value)."""
    d = np.asarray(data.phidot)
    scale = float(np.nanmax(np.abs(d))) if len(d) else 0.0
    if not scale:
        return np.array([], dtype=int)          # no precession at all (sleeping top)
    change = np.nonzero(np.sign(d[:-1]) * np.sign(d[1:]) < 0)[0]
    a = np.abs(d)
    inner = np.arange(1, len(d) - 1)
    touch = inner[(a[1:-1] <= a[:-2]) & (a[1:-1] <= a[2:]) & (a[1:-1] < zero * scale)]
    ends = [i for i in (0, len(d) - 1) if a[i] < zero * scale]     # e.g. the release point
    change = np.where(a[change] <= a[change + 1], change, change + 1)
    return np.unique(np.concatenate([change, touch, ends]).astype(int))


def radial_exaggeration(data: PathData, band: float = 0.3) -> float:
    """Factor k >= 1 by which the band between the circles is widened on the picture.

    A narrow nutation (a band thinner than 15% of its radius) would draw as one
    line; r -> r_mid + k (r - r_mid) with r = sin(theta) is monotonic and leaves
    phi alone, so cusps stay cusps (phidot = 0 where r turns), loops stay loops and
    waves waves. k makes the band ``band`` times its mean radius.
    """
    below = crosses_horizontal(data)
    r_lo, r_hi = sorted((float(radius(data.theta_min, below)), float(radius(data.theta_max, below))))
    r_mid = 0.5 * (r_lo + r_hi)
    width = r_hi - r_lo
    if r_mid <= 0 or width >= 0.15 * r_mid or is_steady(data):
        return 1.0          # wide enough, or no nutation to show (steady or sleeping)
    return band * r_mid / width


def figure(data: PathData):
    """The matplotlib Figure: path on the sphere (top), theta(t) and phidot(t) (below)."""
    import matplotlib

    matplotlib.use("Agg", force=False)
    from matplotlib.figure import Figure

    fig = Figure(figsize=(7.0, 10.5), layout="constrained")
    grid = fig.add_gridspec(3, 1, height_ratios=[3.4, 1, 1])
    ax = fig.add_subplot(grid[0])
    notes = _draw_path(ax, data)
    head = data.title + (f"  [{data.motion}]" if data.motion else "")
    ax.set_title(f"{head}\npath of the symmetry axis seen from above"
                 + (f"\n({'; '.join(notes)})" if notes else ""), fontsize=10)
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.09), ncol=3, fontsize=7,
              frameon=False)

    ax_theta = fig.add_subplot(grid[1])
    ax_theta.plot(data.t, np.degrees(data.theta), color="k", lw=1.0)
    for theta, colour in ((data.theta_min, "tab:blue"), (data.theta_max, "tab:red")):
        ax_theta.axhline(math.degrees(theta), ls="--", color=colour, lw=0.8)
    if crosses_horizontal(data):
        ax_theta.axhline(90.0, ls="-", color="0.6", lw=0.8)
    ax_theta.set_ylabel("theta (deg)")
    ax_theta.set_xlim(data.t[0], data.t[-1])

    ax_rate = fig.add_subplot(grid[2], sharex=ax_theta)
    ax_rate.plot(data.t, np.asarray(data.phidot) * data.rate_per_si, color="k", lw=1.0)
    ax_rate.axhline(0.0, color="0.5", lw=0.8)
    ax_rate.set_ylabel(f"phidot ({data.rate_unit})")
    ax_rate.set_xlabel("t (s)" + (f"   [{data.source}]" if data.source else ""))
    return fig


def _draw_path(ax, data: PathData) -> list[str]:
    """The view from above on ``ax``; returns the notes for the title."""
    below = crosses_horizontal(data)
    steady = is_steady(data)
    k = radial_exaggeration(data)
    r_mid = 0.5 * (float(radius(data.theta_min, below)) + float(radius(data.theta_max, below)))

    def warp(x: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        if k == 1.0:
            return x, y
        r = np.hypot(x, y)
        scale = np.where(r > 0, (r_mid + k * (r - r_mid)) / np.where(r > 0, r, 1.0), 0.0)
        return x * scale, y * scale

    notes = []
    if steady:
        theta = 0.5 * (data.theta_min + data.theta_max)
        cx, cy = circle_xy(theta, below=below)
        ax.plot(cx, cy, "--", color="tab:blue", lw=1.0, gid="theta circle",
                label=f"steady: theta = {math.degrees(theta):.4g} deg")
        notes.append(f"no visible nutation (band under {VISIBLE_BAND:.0e} of its radius): "
                     "a steady circle")
    else:
        for theta, colour, label in ((data.theta_min, "tab:blue", "theta_min"),
                                     (data.theta_max, "tab:red", "theta_max")):
            cx, cy = warp(*circle_xy(theta, below=below))
            ax.plot(cx, cy, "--", color=colour, lw=1.0, gid="theta circle",
                    label=f"{label} = {math.degrees(theta):.4g} deg")
            if k != 1.0:  # the true angle written on the circle, since the axes are warped
                ax.annotate(f"{math.degrees(theta):.6g} deg", (cx[45], cy[45]), fontsize=7,
                            color=colour, gid="true theta")
    if below:
        cx, cy = circle_xy(0.5 * math.pi, below=True)
        ax.plot(cx, cy, "-", color="0.6", lw=0.8, gid="horizontal",
                label="horizontal, theta = 90 deg")
        notes.append("radius theta / 90 deg (azimuthal equidistant), so circles keep "
                     "their order below the horizontal")
    elif k == 1.0 and not steady and data.theta_max > math.pi / 2 > 0.5 * data.theta_min:
        cx, cy = circle_xy(math.pi / 2)
        ax.plot(cx, cy, ":", color="0.6", lw=0.8, label="theta = 90 deg")
    x, y = warp(*path_xy(data.theta, data.phi, below))
    if below:
        lower = np.asarray(data.theta) > 0.5 * math.pi
        ax.plot(np.ma.masked_where(lower, x), np.ma.masked_where(lower, y), "-", color="k",
                lw=1.0, gid="upper hemisphere", label="axis above the horizontal")
        ax.plot(np.ma.masked_where(~lower, x), np.ma.masked_where(~lower, y), "-",
                color="tab:purple", lw=1.4, gid="lower hemisphere",
                label="axis below the horizontal")
    else:
        ax.plot(x, y, "-", color="k", lw=1.0, label="symmetry axis")
    ax.plot(x[:1], y[:1], "o", color="tab:green", ms=6, label="start")
    marks = stationary_points(data)
    if len(marks) and not steady:
        ax.plot(x[marks], y[marks], "v", color="tab:orange", ms=5, label="phidot = 0")
    ax.plot([0], [0], "+", color="0.4", ms=8)
    reach = max(float(np.max(np.hypot(x, y))), 0.25)
    if k == 1.0 and data.theta_min < math.pi / 2 < data.theta_max:
        reach = max(reach, 1.0)
    lim = 1.06 * reach
    ax.set_xlim(-lim, lim)
    ax.set_ylim(-lim, lim)
    ax.set_aspect("equal")
    r_name = "theta/90deg" if below else "sin(theta)"
    ax.set_xlabel(f"{r_name} cos(phi)")
    ax.set_ylabel(f"{r_name} sin(phi)")
    if data.theta_min > math.pi / 2:
        notes.append("centre of mass below the pivot")
    if k != 1.0:
        # a warped radius has no true tick values: drop the ticks, label the circles
        ax.set_xticks([])
        ax.set_yticks([])
        notes.append(f"band between the circles widened x{k:.3g}; circles labelled "
                     "with their true theta")
    return notes


def render(data: PathData, suffix: str) -> bytes:
    """The figure as PNG, SVG or PDF bytes."""
    fmt = FORMATS.get(suffix.lower())
    if fmt is None:
        raise ValueError(f"plot format {suffix!r} not supported; use .png, .svg or .pdf")
    fig = figure(data)
    buffer = io.BytesIO()
    metadata = {"Software": None} if fmt == "png" else \
        ({"Date": None} if fmt == "svg" else {"CreationDate": None})
    fig.savefig(buffer, format=fmt, dpi=120, metadata=metadata)
    return buffer.getvalue()


def save(data: PathData, path: str, force: bool = False) -> Path:
    """Render and write atomically; InputError if the file exists and not ``force``."""
    from ..core.errors import InputError
    from ..core.files import refuse_target, write_atomic

    suffix = Path(path).suffix
    if suffix.lower() not in FORMATS:
        raise InputError(f"plot format {suffix or '(none)'!r} not supported; name the file "
                         ".png, .svg or .pdf", file=path)
    if max(data.theta_max, float(np.max(data.theta))) < 1e-9:
        raise InputError("the axis stays on the vertical (a sleeping top): seen from above "
                         "its path is one point, so there is no figure to draw", file=path)
    refuse_target(Path(path), force)  # before the drawing, a second or more of matplotlib
    return write_atomic(path, render(data, suffix), force=force)


def from_simulation(sim, title: str = "", motion: str = "") -> PathData:
    """PathData from a simulate.Simulation (measured bounding circles)."""
    return PathData(t=sim.t, theta=sim.theta, phi=sim.phi, phidot=sim.phidot,
                    theta_min=sim.theta_min, theta_max=sim.theta_max, title=title,
                    motion=motion, source="simulated: Euler's equations + quaternion, DOP853")


def from_analysis(top, start, periods: float = 3.0, samples_per_period: int = 600,
                  title: str = "") -> PathData:
    """PathData from the analytic solution: exact theta(t) (motion.theta_of_t),
    phidot from Eq. 11.16 and phi by integrating it (cumulative Simpson's rule).

    Where the top does not nutate, the path is simulated instead (simulate.py)
    and the figure says so.
    """
    from ..physics.motion import theta_of_t
    from ..physics.nutation import analyse, phidot

    nut = analyse(top, start)
    period = nut.nutation_period
    if not (period and math.isfinite(period) and period > 0):
        return _simulated_path(top, start, nut, periods, samples_per_period, title)
    from scipy.integrate import cumulative_simpson

    n = int(max(201, round(periods * samples_per_period) + 1))
    t = np.linspace(0.0, periods * period, n)
    theta = np.asarray(theta_of_t(top, start, t), dtype=float)
    with np.errstate(invalid="ignore", divide="ignore"):       # on the vertical: 0 / 0
        rate = np.asarray(phidot(nut, np.cos(theta)), dtype=float)
    rate = np.where(np.isfinite(rate), rate, 0.0)
    phi = cumulative_simpson(rate, x=t, initial=0.0)
    return PathData(t=t, theta=theta, phi=phi, phidot=rate, theta_min=nut.theta_min,
                    theta_max=nut.theta_max, title=title, motion=nut.motion,
                    source="analytic: exact theta(t), phi from Eq. 11.16")


def _simulated_path(top, start, nut, periods: float, samples_per_period: int,
                    title: str) -> PathData:
    from ..physics.simulate import simulate

    period = nut.nutation_period
    if not (period and math.isfinite(period) and period > 0):
        omega_z = start.spin + start.precession0 * math.cos(start.theta0)
        rate = nut.mean_precession if nut.mean_precession and math.isfinite(
            nut.mean_precession) else 0.0
        period = 2 * math.pi / abs(rate) if rate else \
            2 * math.pi * top.I / (top.J * abs(omega_z)) if omega_z else 1.0
    n = int(max(201, round(periods * samples_per_period) + 1))
    sim = simulate(top, start, periods * period, samples=n)
    data = from_simulation(sim, title=title, motion=nut.motion)
    data.theta_min, data.theta_max = nut.theta_min, nut.theta_max
    return data


def with_rate_unit(data: PathData, problem) -> PathData:
    """Draw phidot in the unit the file asks its precession answers in (rad/s if none)."""
    from ..core import units

    for name, unit in problem.find.items():
        answer = problem.kind.answer(name)
        if unit and answer is not None and answer.dimension == "rate":
            data.rate_unit, data.rate_per_si = unit, units.convert(1.0, "rate", unit)
            break
    return data


#: the pictures a kind may declare (Kind.picture), in the order messages list them
PICTURES = ("axis_path", "eigenvalues")


def plot_result(result, path: str, force: bool = False, periods: float | None = None) -> Path:
    """``gyro solve --plot``: draw a solved released_top problem; InputError otherwise.

    By default enough nutation periods for the axis to go once round the vertical
    (at least 3, at most 12).
    """
    from ..core.errors import InputError

    problem = result.problem
    if problem.kind.picture == "eigenvalues":  # the bicycle's: eigenvalues against speed
        from .plot_bicycle import plot_result as plot_bicycle

        return plot_bicycle(result, path, force=force)
    if problem.kind.picture != "axis_path":
        from ..kinds import offering

        raise InputError(f"plots exist for kinds {' and '.join(offering('picture', PICTURES))}"
                         f" only; this file is kind {problem.kind.name!r}", file=problem.file,
                         key="kind")
    suffix = Path(path).suffix
    if suffix.lower() not in FORMATS:
        raise InputError(f"plot format {suffix or '(none)'!r} not supported; name the file "
                         ".png, .svg or .pdf", file=path)
    from ..core.files import refuse_special

    refuse_special(path)  # a device, FIFO or directory: refused with or without --force
    if Path(path).exists() and not force:
        raise InputError("exists; not overwritten (use --force to replace it)", file=path)
    return save(released_top_data(result, periods), path, force=force)


def released_top_data(result, periods: float | None = None) -> PathData:
    """What the picture of a solved released_top problem shows (by default enough
    nutation periods for the axis to go once round the vertical)."""
    from ..physics.nutation import Start, Top

    problem = result.problem
    given, body = problem.given, problem.given.body
    top = Top(I=body.I_pivot, J=body.J, mgl=body.mgl)
    start = Start(theta0=given["theta0"], spin=given["spin"],
                  precession0=given.get("precession0", 0.0) or 0.0,
                  theta_rate0=given.get("theta_rate0", 0.0) or 0.0)
    title = f"{problem.id}  {problem.title}".strip()
    if periods is None:
        periods = _periods_for_one_turn(top, start)
    return with_rate_unit(from_analysis(top, start, periods=periods, title=title), problem)


def _periods_for_one_turn(top, start) -> float:
    from ..physics.nutation import analyse

    nut = analyse(top, start)
    period, rate = nut.nutation_period, nut.mean_precession
    if not (period and rate and math.isfinite(period) and math.isfinite(rate)):
        return 3.0
    return float(min(12, max(3, math.ceil(2 * math.pi / abs(rate * period)))))
