"""`gyro solve --plot` for kind bicycle: the eigenvalues against speed.

As the paper's figure of the benchmark (Meijaard et al. 2007, Fig. 3): real
parts solid, imaginary parts dashed (the positive one of each complex pair),
the self-stable speed range shaded, the problem's speed marked. matplotlib is
imported inside the functions (Agg backend).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np


def eigenvalue_curves(p: dict[str, float], gyroscopic: bool, v_max: float,
                      n: int = 801) -> tuple[np.ndarray, np.ndarray]:
    """Speeds 0..v_max and the sorted eigenvalues at each (n x 4, complex)."""
    from ..physics import bicycle as bike

    m = bike.matrices(p, gyroscopic)
    speeds = np.linspace(0.0, v_max, n)
    return speeds, np.array([bike.eigenvalues(m, v, p["g"]) for v in speeds])


def figure(p: dict[str, float], gyroscopic: bool, speed: float | None, title: str = ""):
    """The matplotlib Figure of the eigenvalues against speed."""
    import matplotlib

    matplotlib.use("Agg", force=False)
    from matplotlib.figure import Figure

    from ..physics import bicycle as bike

    stab = bike.stability(bike.matrices(p, gyroscopic), p["g"])
    ends = [x for lo, hi in stab.stable for x in (lo, hi) if math.isfinite(x)]
    v_max = max([10.0] + [1.25 * x for x in ends] + ([1.25 * abs(speed)] if speed else []))
    speeds, ev = eigenvalue_curves(p, gyroscopic, v_max)
    fig = Figure(figsize=(7.5, 5.0), layout="constrained")
    ax = fig.add_subplot()
    for lo, hi in stab.stable:
        ax.axvspan(lo, min(hi, v_max), color="tab:green", alpha=0.15,
                   label=f"self-stable {lo:.4g}-{hi:.4g} m/s" if math.isfinite(hi)
                   else f"self-stable above {lo:.4g} m/s")
    for j in range(ev.shape[1]):
        ax.plot(speeds, ev[:, j].real, "-", color="k", lw=1.2,
                label="real parts" if j == 0 else None)
        imag = np.where(ev[:, j].imag > 0, ev[:, j].imag, np.nan)
        if np.any(np.isfinite(imag)):
            ax.plot(speeds, imag, "--", color="tab:blue", lw=1.2,
                    label="imaginary parts" if j == ev.shape[1] - 1 else None)
    ax.axhline(0.0, color="0.5", lw=0.8)
    for v, name in [(x, "v_w") for x in stab.weave] + [(x, "v_c") for x in stab.capsize]:
        ax.axvline(v, color="tab:green", lw=0.8, ls=":")
        ax.annotate(f"{name} = {v:.4f}", (v, 9.2), fontsize=8, ha="center")
    if speed is not None:
        ax.axvline(speed, color="tab:red", lw=1.0, label=f"v = {speed:.4g} m/s")
    ax.set_xlim(0.0, v_max)
    ax.set_ylim(-10.0, 10.0)
    ax.set_xlabel("speed v (m/s)")
    ax.set_ylabel("eigenvalues (1/s)")
    note = "" if gyroscopic else "  (no wheel spin: gyroscopic false)"
    ax.set_title((title + "\n" if title else "") + "eigenvalues of the linearised Whipple "
                 "bicycle against speed" + note, fontsize=10)
    ax.legend(loc="lower right", fontsize=8)
    return fig


def plot_result(result, path: str, force: bool = False) -> Path:
    """Draw a solved bicycle problem to ``path`` (.png, .svg, .pdf)."""
    import io

    from ..core.errors import InputError
    from ..core.files import write_atomic
    from .picture_formats import FORMATS

    suffix = Path(path).suffix
    fmt = FORMATS.get(suffix.lower())
    if fmt is None:
        raise InputError(f"plot format {suffix or '(none)'!r} not supported; name the file "
                         ".png, .svg or .pdf", file=path)
    if Path(path).exists() and not force:
        raise InputError("exists; not overwritten (use --force to replace it)", file=path)
    fig = result_figure(result)
    buffer = io.BytesIO()
    metadata = {"Software": None} if fmt == "png" else \
        ({"Date": None} if fmt == "svg" else {"CreationDate": None})
    fig.savefig(buffer, format=fmt, dpi=120, metadata=metadata)
    return write_atomic(path, buffer.getvalue(), force=force)


def result_figure(result):
    """The Figure of a solved bicycle problem (its parameters, wheel spin and speed)."""
    from ..core.work import Work

    problem = result.problem
    given = problem.given
    p = problem.kind.model(given, Work())
    title = f"{problem.id}  {problem.title}".strip()
    return figure(p, given.word("gyroscopic", "true") == "true", given.get("speed"), title)
