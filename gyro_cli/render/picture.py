"""A solved problem's picture as inline SVG with alt text, for HTML pages and Jupyter.

Released tops draw the path of the axis seen from above (plot.py), bicycles
their eigenvalues against speed (plot_bicycle.py). The SVG is matplotlib's
with its text drawn as paths (no font is fetched), its ids prefixed so that
several pictures can share a page, and a ``<title>`` with the alt text that
says what the picture shows, for screen readers. matplotlib is imported only
here, only when a picture is asked for.
"""

from __future__ import annotations

import io
import math
import re
from dataclasses import dataclass
from html import escape


@dataclass(frozen=True)
class Picture:
    svg: str   # an <svg> element, ready to inline
    alt: str   # what it shows, in words


def picture(result, prefix: str = "fig") -> Picture | None:
    """The picture of a solved problem, or None for a kind without one (or a sleeping
    top, whose axis seen from above is one point)."""
    drawn = _figure(result)
    if drawn is None:
        return None
    fig, alt = drawn
    buffer = io.BytesIO()
    fig.savefig(buffer, format="svg", metadata={"Date": None})
    return Picture(inline_svg(buffer.getvalue().decode("utf-8"), alt, prefix), alt)


def png(result) -> tuple[bytes, str] | None:
    """The picture as PNG bytes (a file to package, for a question bank) and its alt
    text; None as for `picture`."""
    drawn = _figure(result)
    if drawn is None:
        return None
    fig, alt = drawn
    buffer = io.BytesIO()
    fig.savefig(buffer, format="png", dpi=100, metadata={"Software": None})
    return buffer.getvalue(), alt


def _figure(result):
    """The matplotlib figure of a solved problem and its alt text, or None."""
    kind = result.problem.kind.picture
    if kind == "axis_path":
        from .plot import figure, released_top_data

        data = released_top_data(result)
        if max(data.theta_max, float(data.theta.max())) < 1e-9:
            return None
        fig, alt = figure(data), _top_alt(data)
    elif kind == "eigenvalues":
        from .plot_bicycle import result_figure

        fig, alt = result_figure(result), _bicycle_alt(result)
    else:
        return None
    return fig, alt


# matplotlib names a marker or a clip path by a hash salted at random on each savefig
# (m0123456789, p0123456789): a page drawn twice would differ
_SALTED = re.compile(r"[mp][0-9a-f]{10}$")


def inline_svg(svg: str, alt: str, prefix: str) -> str:
    """matplotlib's SVG document as an element to inline: no XML prologue, ids made unique
    with ``prefix``, sized by CSS, and announced as one image with ``alt`` as its title."""
    svg = svg[svg.index("<svg"):]
    first: dict[str, str] = {}
    seen: set[str] = set()
    counts: dict[str, int] = {}

    def unique(m: re.Match) -> str:
        name = shown = m.group(2)
        if _SALTED.match(name):  # numbered in order: the same figure, the same page
            counts[name[0]] = counts.get(name[0], 0) + 1
            shown = f"{name[0]}{counts[name[0]]}"
        new = f"{prefix}-" + re.sub(r"[^A-Za-z0-9_-]+", "-", shown)
        while new in seen:  # matplotlib repeats a gid given to two lines
            new += "-"
        seen.add(new)
        first.setdefault(name, new)
        return m.group(1) + new

    svg = re.sub(r'(\bid=")([^"]+)', unique, svg)

    def ref(m: re.Match) -> str:
        return m.group(1) + first.get(m.group(2), m.group(2))

    svg = re.sub(r'(url\(#)([^)]+)', ref, svg)
    svg = re.sub(r'(href="#)([^"]+)', ref, svg)
    title_id = f"{prefix}-title"
    svg = re.sub(r"<svg\b", f'<svg role="img" aria-labelledby="{title_id}" '
                 f'class="picture"', svg, count=1)
    head_end = svg.index(">") + 1
    return svg[:head_end] + f'<title id="{title_id}">{escape(alt)}</title>' + svg[head_end:]


def _deg(x: float) -> str:
    return f"{math.degrees(x):.3g}"


def _top_alt(data) -> str:
    motion = f" ({data.motion})" if data.motion else ""
    return (f"Path of the top's symmetry axis seen from above{motion}: it moves between the "
            f"circles theta_min = {_deg(data.theta_min)} deg and theta_max = "
            f"{_deg(data.theta_max)} deg over {data.t[-1]:.3g} s. Below it, two graphs against "
            f"time: theta in degrees, and the precession rate phidot in {data.rate_unit}.")


def _bicycle_alt(result) -> str:
    from ..core.work import Work
    from ..physics import bicycle as bike

    given = result.problem.given
    gyroscopic = given.word("gyroscopic", "true") == "true"
    p = result.problem.kind.model(given, Work())
    stab = bike.stability(bike.matrices(p, gyroscopic), p["g"])
    ranges = "; ".join(f"self-stable from {lo:.3g} to {hi:.3g} m/s" if math.isfinite(hi)
                       else f"self-stable above {lo:.3g} m/s" for lo, hi in stab.stable)
    speed = given.get("speed")
    at = f" The problem's speed, {speed:.3g} m/s, is marked." if speed is not None else ""
    spin = "" if gyroscopic else " Without the wheels' spin."
    return (f"Graph of the eigenvalues of the linearised bicycle against forward speed: real "
            f"parts as solid lines, imaginary parts dashed.{spin} "
            f"{(ranges[0].upper() + ranges[1:] + ' (shaded).') if ranges else 'No speed is self-stable.'}"
            f"{at}")
