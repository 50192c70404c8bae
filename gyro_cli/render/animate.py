"""Animations of a simulated motion: frames drawn with Pillow, written as GIF, MP4 or HTML.

A ``Scene`` is plain data: per frame, each body's attitude (a rotation matrix,
body axes -> fixed axes) and position, the symmetry axis to trace on a sphere
as in the chapter's Figs. 11-7 to 11-10, and the simulated time. The commands
layer builds it from a simulation; this module only draws it, so a test can
read back exactly what was drawn (``Scene.axis``) and compare it with the
simulation at that time.

Drawing is an orthographic view (elevation ELEVATION, azimuth AZIMUTH, the
fixed z axis upward) painted back to front with Pillow, at twice the size and
then reduced (anti-aliasing): a frame costs a few milliseconds, where
matplotlib's 3D axes cost tens. HTML is one page with the scene as JSON and a
small canvas script drawing the same projection: no request leaves the page.
"""

from __future__ import annotations

import json
import math
import shutil
import subprocess
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

ELEVATION = math.radians(18.0)
AZIMUTH = math.radians(-60.0)
SIZE = 360                 # pixels, one panel (square)
SUPERSAMPLE = 2
LIGHT = np.array([-0.4, -0.5, 0.77])
FORMATS = (".gif", ".mp4", ".html")
BACKGROUND = (255, 255, 255)
INK = (30, 30, 30)
COLOURS = {
    "body": (70, 110, 170),
    "stripe": (225, 120, 30),
    "rod": (120, 120, 120),
    "frame": (110, 110, 110),
    "tyre": (50, 50, 50),
    "trace": (200, 40, 40),
    "sphere": (190, 190, 190),
    "vertical": (40, 40, 40),
    "omega": (30, 140, 60),
    "H": (140, 60, 160),
    "ground": (215, 215, 205),
}


@dataclass
class Solid:
    """A mesh in body axes: vertices (V, 3) and faces (vertex indices, colour name)."""

    vertices: np.ndarray
    faces: list[tuple[tuple[int, ...], str]]
    convex: bool = True     # back faces are culled (a closed convex solid)


@dataclass
class Actor:
    """A solid moving with the frames: rotation (N, 3, 3) body -> fixed, position (N, 3)."""

    solid: Solid
    rotation: np.ndarray
    position: np.ndarray


@dataclass
class Arrow:
    """A vector drawn from the origin, per frame (N, 3), in the scene's length unit."""

    label: str
    tips: np.ndarray
    colour: str


@dataclass
class Panel:
    """One view: actors, the traced axis (N, 3 unit vectors) on a sphere of ``radius``."""

    title: str
    actors: list[Actor]
    axis: np.ndarray | None = None
    radius: float = 1.0
    arrows: list[Arrow] = field(default_factory=list)
    lines: list[tuple[np.ndarray, str]] = field(default_factory=list)   # fixed polylines
    labels: list[list[str]] = field(default_factory=list)               # per frame text
    extent: float = 1.0          # half-width of the view, scene units
    sphere: bool = True
    vertical: bool = True


@dataclass
class Scene:
    """Everything an animation shows: panels and the simulated time of each frame."""

    title: str
    panels: list[Panel]
    times: np.ndarray
    fps: float
    notes: list[str] = field(default_factory=list)

    @property
    def frames(self) -> int:
        return len(self.times)

    @property
    def duration(self) -> float:
        """Playback seconds."""
        return self.frames / self.fps


# ---- geometry -------------------------------------------------------------------

def zxz(phi, theta, psi) -> np.ndarray:
    """Rotation matrices Rz(phi) Rx(theta) Rz(psi) (Eqs. 11.5-11.8 angles), shape (N, 3, 3).

    The body's symmetry axis R e_z = (sin th sin phi, -sin th cos phi, cos th).
    """
    phi, theta, psi = (np.atleast_1d(np.asarray(a, float)) for a in (phi, theta, psi))
    cf, sf = np.cos(phi), np.sin(phi)
    ct, st = np.cos(theta), np.sin(theta)
    cp, sp = np.cos(psi), np.sin(psi)
    R = np.empty((len(phi), 3, 3))
    R[:, 0, 0] = cf * cp - sf * ct * sp
    R[:, 0, 1] = -cf * sp - sf * ct * cp
    R[:, 0, 2] = sf * st
    R[:, 1, 0] = sf * cp + cf * ct * sp
    R[:, 1, 1] = -sf * sp + cf * ct * cp
    R[:, 1, 2] = -cf * st
    R[:, 2, 0] = st * sp
    R[:, 2, 1] = st * cp
    R[:, 2, 2] = ct
    return R


def cylinder(radius: float, z0: float, z1: float, n: int = 28, stripe: bool = True,
             colour: str = "body") -> Solid:
    """A closed cylinder along body z from z0 to z1; one side face and one cap sector
    in the stripe colour, so the spin shows."""
    a = np.linspace(0.0, 2 * math.pi, n, endpoint=False)
    ring = np.column_stack([radius * np.cos(a), radius * np.sin(a)])
    vertices = np.vstack([np.column_stack([ring, np.full(n, z0)]),
                          np.column_stack([ring, np.full(n, z1)]),
                          [[0.0, 0.0, z0], [0.0, 0.0, z1]]])
    faces: list[tuple[tuple[int, ...], str]] = []
    for i in range(n):
        j = (i + 1) % n
        faces.append(((i, j, n + j, n + i), "stripe" if stripe and i == 0 else colour))
    c0, c1 = 2 * n, 2 * n + 1
    for i in range(n):
        j = (i + 1) % n
        mark = "stripe" if stripe and i in (0, 1) else colour
        faces.append(((c0, j, i), mark))
        faces.append(((c1, n + i, n + j), mark))
    return Solid(vertices, faces)


def equivalent_cylinder(m: float | None, J: float, I_cg: float | None,
                        fallback_radius: float) -> tuple[float, float]:
    """Radius and length of the uniform cylinder with the body's m, J and I_G.

    J = m r^2 / 2 and I_G = m r^2 / 4 + m h^2 / 12 (a uniform cylinder), so
    r = sqrt(2 J / m) and h = r sqrt(6 I_G / J - 3): the shape needs only I_G / J.
    Without the mass the radius is ``fallback_radius`` (the drawing's scale) and
    the proportions are still the body's. A body flatter than a thin disk
    (6 I_G / J < 3.12) is drawn as a disk 0.12 r thick; without I_G, too.
    """
    r = math.sqrt(2 * J / m) if m and m > 0 and J and J > 0 else fallback_radius
    if I_cg and J and J > 0:
        ratio = 6 * I_cg / J - 3
        if ratio > 0.12 ** 2:
            return r, r * math.sqrt(ratio)
    return r, 0.12 * r


# ---- projection and painting ----------------------------------------------------

def _camera() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Screen right, screen up and toward-the-viewer unit vectors in fixed axes."""
    ce, se = math.cos(ELEVATION), math.sin(ELEVATION)
    ca, sa = math.cos(AZIMUTH), math.sin(AZIMUTH)
    toward = np.array([ce * ca, ce * sa, se])
    right = np.array([-sa, ca, 0.0])
    up = np.cross(toward, right)
    return right, up, toward


RIGHT, UP, TOWARD = _camera()


def _shade(colour: tuple[int, int, int], normal: np.ndarray) -> tuple[int, int, int]:
    k = 0.45 + 0.55 * max(0.0, float(normal @ LIGHT) / float(np.linalg.norm(LIGHT)))
    r, g, b = (int(min(255, c * k + 20)) for c in colour)
    return r, g, b


def _great_circles(radius: float, n: int = 72) -> list[np.ndarray]:
    """Equator, two latitudes and four meridians of the sphere, as point lists."""
    a = np.linspace(0.0, 2 * math.pi, n + 1)
    circles = []
    for lat in (0.0, math.radians(45), math.radians(-45)):
        circles.append(np.column_stack([radius * math.cos(lat) * np.cos(a),
                                        radius * math.cos(lat) * np.sin(a),
                                        np.full_like(a, radius * math.sin(lat))]))
    for lon in np.arange(4) * math.pi / 4:
        circles.append(np.column_stack([radius * np.cos(a) * math.cos(lon),
                                        radius * np.cos(a) * math.sin(lon),
                                        radius * np.sin(a)]))
    return circles


class _Painter:
    """Draws one panel's frames into a Pillow image region."""

    def __init__(self, panel: Panel, size: int) -> None:
        self.panel = panel
        self.size = size
        self.scale = 0.46 * size / panel.extent
        self.circles = _great_circles(panel.radius) if panel.sphere else []

    def xy(self, p: np.ndarray) -> np.ndarray:
        """Screen coordinates (pixels) of points (..., 3)."""
        x = p @ RIGHT
        y = p @ UP
        return np.stack([self.size / 2 + self.scale * x, self.size / 2 - self.scale * y], -1)

    def draw(self, draw, frame: int, offset: tuple[int, int], font) -> None:
        ox, oy = offset
        panel = self.panel
        w = max(1, self.size // 240)
        back: list[tuple[np.ndarray, np.ndarray]] = []
        front: list[tuple[np.ndarray, np.ndarray]] = []
        for circle in self.circles:
            depth = circle @ TOWARD
            pts = self.xy(circle) + (ox, oy)
            for k in range(len(circle) - 1):
                (front if depth[k] + depth[k + 1] > 0 else back).append(
                    (pts[k], pts[k + 1]))
        for a, b in back:
            draw.line([tuple(a), tuple(b)], fill=(225, 225, 225), width=w)
        for points, colour in panel.lines:
            polyline = [tuple(p) for p in (self.xy(points) + (ox, oy))]
            draw.line(polyline, fill=COLOURS[colour], width=w)
        if panel.vertical:
            top = panel.radius * 1.15
            pts = self.xy(np.array([[0, 0, -top], [0, 0, top]])) + (ox, oy)
            draw.line([tuple(pts[0]), tuple(pts[1])], fill=COLOURS["vertical"], width=w)
        self._bodies(draw, frame, (ox, oy))
        if panel.axis is not None:     # over the body: the trace is what the picture is for
            trace = panel.radius * panel.axis[: frame + 1]
            if len(trace) > 1:
                path = [tuple(p) for p in (self.xy(trace) + (ox, oy))]
                draw.line(path, fill=COLOURS["trace"], width=2 * w)
        for a, b in front:
            draw.line([tuple(a), tuple(b)], fill=COLOURS["sphere"], width=w)
        for arrow in panel.arrows:
            tip = arrow.tips[frame]
            pts = self.xy(np.array([[0.0, 0.0, 0.0], tip])) + (ox, oy)
            draw.line([tuple(pts[0]), tuple(pts[1])], fill=COLOURS[arrow.colour], width=2 * w)
            draw.text((pts[1][0] + 3 * w, pts[1][1] - 6 * w), arrow.label,
                      fill=COLOURS[arrow.colour], font=font)
        if panel.axis is not None:
            tip = self.xy(panel.radius * panel.axis[frame]) + (ox, oy)
            r = 3 * w
            draw.ellipse([tip[0] - r, tip[1] - r, tip[0] + r, tip[1] + r],
                         fill=COLOURS["trace"])
        draw.text((ox + 6 * w, oy + 4 * w), panel.title, fill=INK, font=font)
        if panel.labels:
            for k, line in enumerate(panel.labels[frame]):
                draw.text((ox + 6 * w, oy + self.size - (16 + 13 * k) * w), line,
                          fill=INK, font=font)

    def _bodies(self, draw, frame: int, offset) -> None:
        polys = []
        for actor in self.panel.actors:
            R = actor.rotation[frame]
            verts = actor.solid.vertices @ R.T + actor.position[frame]
            screen = self.xy(verts) + offset
            depth = verts @ TOWARD
            for idx, colour in actor.solid.faces:
                p = verts[list(idx)]
                normal = np.cross(p[1] - p[0], p[2] - p[0])
                if actor.solid.convex and normal @ TOWARD <= 0:
                    continue
                norm = float(np.linalg.norm(normal)) or 1.0
                polys.append((float(depth[list(idx)].mean()),
                              [tuple(screen[i]) for i in idx],
                              _shade(COLOURS[colour], normal / norm)))
        for _, pts, fill in sorted(polys, key=lambda item: item[0]):
            draw.polygon(pts, fill=fill, outline=fill)


def _font(size: int):
    from PIL import ImageFont

    try:
        return ImageFont.load_default(size=size)
    except TypeError:      # Pillow < 10.1: one bitmap size
        return ImageFont.load_default()


def _fit(text: str, chars: int) -> str:
    return text if len(text) <= chars else text[: max(1, chars - 3)] + "..."


def frame_images(scene: Scene, size: int = SIZE):
    """Yield each frame as an RGB Pillow image (panels side by side, a clock below)."""
    from PIL import Image, ImageDraw

    big = size * SUPERSAMPLE
    painters = [_Painter(panel, big) for panel in scene.panels]
    font = _font(11 * SUPERSAMPLE)
    clock_h = 22 * SUPERSAMPLE
    width, height = big * len(painters), big + clock_h
    for i, t in enumerate(scene.times):
        image = Image.new("RGB", (width, height), BACKGROUND)
        draw = ImageDraw.Draw(image)
        for k, painter in enumerate(painters):
            painter.draw(draw, i, (k * big, 0), font)
        draw.text((6 * SUPERSAMPLE, big + 4 * SUPERSAMPLE),
                  _fit(f"t = {t:.4f} s (simulated)   {scene.title}", width // (6 * SUPERSAMPLE)), fill=INK, font=font)
        yield image.reduce(SUPERSAMPLE)


# ---- writers ----------------------------------------------------------------------

def gif_durations(frames: int, fps: float) -> list[int]:
    """Per-frame GIF delays in ms. GIF counts in 10 ms ticks, so 30 frames/s alternates
    30 and 40 ms; the running total stays within 10 ms of frames / fps."""
    edges = [int(round(100 * k / fps)) * 10 for k in range(frames + 1)]
    return [max(10, b - a) for a, b in zip(edges, edges[1:])]


def gif_bytes(scene: Scene, size: int = SIZE) -> bytes:
    """The animation as a looping GIF (Pillow), one palette for every frame."""
    import io

    from PIL import Image

    images = list(frame_images(scene, size))
    sample = Image.new("RGB", (images[0].width, images[0].height * 3))
    for k, index in enumerate((0, len(images) // 2, len(images) - 1)):
        sample.paste(images[index], (0, k * images[0].height))
    palette = sample.quantize(colors=128, method=Image.Quantize.MEDIANCUT)
    frames = [im.quantize(palette=palette, dither=Image.Dither.NONE) for im in images]
    out = io.BytesIO()
    frames[0].save(out, format="GIF", save_all=True, append_images=frames[1:], loop=0,
                   duration=gif_durations(len(frames), scene.fps), optimize=False,
                   disposal=1)
    return out.getvalue()


def mp4_bytes(scene: Scene, size: int = SIZE) -> bytes:
    """H.264 MP4 through ffmpeg (raw RGB frames on its standard input)."""
    import tempfile

    ffmpeg = shutil.which("ffmpeg")
    if not ffmpeg:
        raise FileNotFoundError("MP4 needs ffmpeg, which is not installed (apt-get install "
                                "ffmpeg); write .gif or .html instead")
    images = frame_images(scene, size)
    first = next(images)
    w, h = first.width - first.width % 2, first.height - first.height % 2
    with tempfile.TemporaryDirectory() as tmp:
        target = Path(tmp) / "out.mp4"
        cmd = [ffmpeg, "-loglevel", "error", "-y", "-f", "rawvideo", "-pix_fmt", "rgb24",
               "-s", f"{w}x{h}", "-r", f"{scene.fps:g}", "-i", "-", "-an", "-c:v", "libx264",
               "-pix_fmt", "yuv420p", "-movflags", "+faststart", str(target)]
        proc = subprocess.Popen(cmd, stdin=subprocess.PIPE, stderr=subprocess.PIPE)
        assert proc.stdin is not None and proc.stderr is not None  # both PIPE
        try:
            for image in [first, *images]:
                proc.stdin.write(image.crop((0, 0, w, h)).tobytes())
            proc.stdin.close()
        except BrokenPipeError:
            pass
        err = proc.stderr.read().decode(errors="replace")
        if proc.wait() != 0:
            raise RuntimeError(f"ffmpeg failed: {err.strip()[:200]}")
        return target.read_bytes()


def scene_json(scene: Scene) -> dict:
    """The scene as plain lists, for the HTML player (rounded to 5 digits: pixels)."""
    def r(a):
        return np.round(np.asarray(a, float), 5).tolist()

    panels = []
    for panel in scene.panels:
        panels.append({
            "title": panel.title, "radius": panel.radius, "extent": panel.extent,
            "sphere": panel.sphere, "vertical": panel.vertical,
            "axis": r(panel.axis) if panel.axis is not None else None,
            "actors": [{"vertices": r(a.solid.vertices),
                        "faces": [[list(idx), COLOURS[c]] for idx, c in a.solid.faces],
                        "convex": a.solid.convex,
                        "rotation": r(a.rotation.reshape(len(a.rotation), 9)),
                        "position": r(a.position)} for a in panel.actors],
            "arrows": [{"label": a.label, "tips": r(a.tips), "colour": COLOURS[a.colour]}
                       for a in panel.arrows],
            "lines": [[r(points), COLOURS[c]] for points, c in panel.lines],
            "labels": panel.labels,
        })
    return {"title": scene.title, "fps": scene.fps, "times": r(scene.times),
            "camera": {"right": RIGHT.tolist(), "up": UP.tolist(), "toward": TOWARD.tolist()},
            "light": (LIGHT / np.linalg.norm(LIGHT)).tolist(), "panels": panels,
            "notes": scene.notes}


def html_fragment(scene: Scene, element_id: str = "gyro-animation") -> str:
    """A <figure> with a canvas and its script: embeddable in a solution page."""
    from html import escape

    data = json.dumps(scene_json(scene), separators=(",", ":"), allow_nan=False)
    data = data.replace("<", "\\u003c")       # no tag, so no </script>, inside the data
    panels = len(scene.panels)
    alt = (f"Animation: {escape(scene.title)}; {scene.frames} frames at {scene.fps:g} "
           f"frames per second. " + " ".join(escape(n) for n in scene.notes))
    return (f'<figure class="gyro-animation" id="{escape(element_id)}">'
            f'<canvas width="{SIZE * panels}" height="{SIZE + 22}" role="img" '
            f'aria-label="{alt}" style="max-width:100%;height:auto"></canvas>'
            f'<figcaption>{escape(scene.title)} '
            f'<button type="button">Pause</button></figcaption>'
            f'<script type="application/json">{data}</script>'
            f'<script>{player_script(element_id)}</script>'
            '</figure>')


def player_script(element_id: str) -> str:
    """The inline script that plays the figure ``element_id`` (a page's CSP allows it by
    its hash)."""
    return f"{_PLAYER}(document.getElementById({json.dumps(element_id)}));"


def html_page(scene: Scene) -> str:
    """One self-contained page: no request leaves it."""
    from html import escape

    return ("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
            "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">"
            f"<title>{escape(scene.title)}</title>"
            "<style>body{font-family:system-ui,sans-serif;margin:1rem;color:#1e1e1e;"
            "background:#fff}figure{margin:0}canvas{border:1px solid #ccc}</style>"
            f"</head><body><main><h1>{escape(scene.title)}</h1>"
            f"{html_fragment(scene)}"
            + "".join(f"<p>{escape(n)}</p>" for n in scene.notes)
            + "</main></body></html>\n")


_PLAYER = """(function(fig){
var c=fig.querySelector('canvas'),g=c.getContext('2d'),S=JSON.parse(
fig.querySelector('script[type="application/json"]').textContent),
R=S.camera.right,U=S.camera.up,T=S.camera.toward,L=S.light,N=S.times.length,
size=c.height-22,i=0,run=true,btn=fig.querySelector('button');
function dot(a,b){return a[0]*b[0]+a[1]*b[1]+a[2]*b[2];}
function rgb(a,k){return 'rgb('+a.map(function(v){return Math.min(255,Math.round(v*k+20));})+')';}
btn.onclick=function(){run=!run;btn.textContent=run?'Pause':'Play';};
function draw(){
g.fillStyle='#fff';g.fillRect(0,0,c.width,c.height);
S.panels.forEach(function(P,k){
var s=0.46*size/P.extent,ox=k*size;
function xy(p){return [ox+size/2+s*dot(p,R),size/2-s*dot(p,U)];}
function line(pts,col,w){g.strokeStyle=col;g.lineWidth=w;g.beginPath();
pts.forEach(function(p,j){var q=xy(p);if(j)g.lineTo(q[0],q[1]);else g.moveTo(q[0],q[1]);});g.stroke();}
P.lines.forEach(function(l){line(l[0],'rgb('+l[1]+')',1);});
if(P.vertical)line([[0,0,-1.15*P.radius],[0,0,1.15*P.radius]],'#282828',1);
if(P.axis)line(P.axis.slice(0,i+1).map(function(a){return a.map(function(v){return v*P.radius;});}),'rgb(200,40,40)',2);
var polys=[];
P.actors.forEach(function(A){var M=A.rotation[i],o=A.position[i];
var V=A.vertices.map(function(v){return [M[0]*v[0]+M[1]*v[1]+M[2]*v[2]+o[0],
M[3]*v[0]+M[4]*v[1]+M[5]*v[2]+o[1],M[6]*v[0]+M[7]*v[1]+M[8]*v[2]+o[2]];});
A.faces.forEach(function(f){var p=f[0].map(function(j){return V[j];}),
a=[p[1][0]-p[0][0],p[1][1]-p[0][1],p[1][2]-p[0][2]],b=[p[2][0]-p[0][0],p[2][1]-p[0][1],p[2][2]-p[0][2]],
n=[a[1]*b[2]-a[2]*b[1],a[2]*b[0]-a[0]*b[2],a[0]*b[1]-a[1]*b[0]];
if(A.convex&&dot(n,T)<=0)return;var m=Math.hypot(n[0],n[1],n[2])||1;
var d=0;p.forEach(function(q){d+=dot(q,T);});
polys.push([d/p.length,p,rgb(f[1],0.45+0.55*Math.max(0,dot(n,L)/m))]);});});
polys.sort(function(a,b){return a[0]-b[0];}).forEach(function(q){g.fillStyle=q[2];g.strokeStyle=q[2];
g.beginPath();q[1].forEach(function(p,j){var z=xy(p);if(j)g.lineTo(z[0],z[1]);else g.moveTo(z[0],z[1]);});
g.closePath();g.fill();g.stroke();});
P.arrows.forEach(function(a){var col='rgb('+a.colour+')';line([[0,0,0],a.tips[i]],col,2);
var q=xy(a.tips[i]);g.fillStyle=col;g.fillText(a.label,q[0]+3,q[1]-3);});
g.fillStyle='#1e1e1e';g.font='11px sans-serif';g.fillText(P.title,ox+6,14);
(P.labels[i]||[]).forEach(function(t,j){g.fillText(t,ox+6,size-8-13*j);});});
g.fillStyle='#1e1e1e';g.fillText('t = '+S.times[i].toFixed(4)+' s (simulated)   '+S.title,6,size+15);}
var last=0;function tick(ms){if(run&&ms-last>=1000/S.fps){last=ms;i=(i+1)%N;draw();}
requestAnimationFrame(tick);}draw();requestAnimationFrame(tick);})"""


def write(scene: Scene, path: str, force: bool = False) -> Path:
    """Render to the format the name asks for and write atomically."""
    from ..core.files import write_atomic

    suffix = Path(path).suffix.lower()
    if suffix == ".gif":
        payload: str | bytes = gif_bytes(scene)
    elif suffix == ".mp4":
        payload = mp4_bytes(scene)
    else:
        payload = html_page(scene)
    return write_atomic(path, payload, force=force)
