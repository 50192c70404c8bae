"""The commands a `gyro solve` does not load: new, schema, vary, simulate, handout and
kinds, imported only when one of them runs (cli.py: `_Guarded.LAZY`, which holds the
short help `gyro --help` lists for each)."""

from __future__ import annotations

import sys

import click

from ..core.errors import InputError, terminal_text
from .exits import INTERNAL, fail, internal, outputs_apart


@click.command("new")
@click.argument("kind", required=False)
@click.option("-o", "--output", metavar="FILE", help="Write the template to FILE (not stdout).")
@click.option("--force", is_flag=True, help="Replace FILE if it exists.")
def new(kind: str | None, output: str | None, force: bool) -> None:
    """Print (or write) a commented problem template with every key of KIND.

    Without KIND, list the kinds to choose from."""
    from .authoring import template

    if kind is None:
        from ..kinds import get as kind_named
        from ..kinds import names as kind_names

        click.echo("gyro new KIND writes a template; KIND is one of:")
        for name in kind_names():
            click.echo(f"  {name:<19} {kind_named(name).summary}")
        return
    try:
        if output is not None:
            from ..core.files import refuse_input_as_output

            refuse_input_as_output(output, (), option="--output", yaml_output=True)
        text = template(kind)
        if output:
            from ..core.files import write_atomic

            write_atomic(output, text, force=force)
            click.echo(f"wrote {terminal_text(output)}", err=True)
        else:
            click.echo(text, nl=False)
    except InputError as err:
        fail(err)


@click.command()
def schema() -> None:
    """Print a JSON Schema of the problem format (for editors' YAML support)."""
    import json

    from .authoring import schema as make_schema

    click.echo(json.dumps(make_schema(), indent=2, ensure_ascii=False))


@click.command()
@click.argument("files", nargs=-1, required=True, metavar="FILE...")
@click.option("--count", "-n", type=int, default=None, help="How many variants (one FILE).")
@click.option("--roster", metavar="ROSTER.csv",
              help="Instead of --count: one variant per student of ROSTER (a CSV with a "
                   "student column) and problem FILE, and DIR/assignment.csv.")
@click.option("--seed", "-s", type=int, default=0, show_default=True,
              help="Random seed: the same seed gives the same files (with --roster, the "
                   "course seed: each student's numbers depend only on it and their id).")
@click.option("-o", "--out-dir", "out_dir", metavar="DIR", required=True,
              help="Directory to write the variants into (created if needed).")
@click.option("--force", is_flag=True, help="Replace variant files that exist.")
@click.option("--jobs", "-j", type=click.IntRange(min=1), default=None, metavar="N",
              help="With --roster: draw the set in N worker processes (default: the CPUs "
                   "available; a set of fewer than 200 variants is drawn in one). The "
                   "files are the same, byte for byte, with any N.")
def vary(files: tuple[str, ...], count: int | None, roster: str | None, seed: int,
         out_dir: str, force: bool, jobs: int | None) -> None:
    """Write COUNT variants of FILE with values drawn from its `vary:` block, or with
    --roster one variant per student of each FILE.

    Each variant has its computed `expected` answers; draws with no real
    solution are rejected and drawn again.
    """
    from .authoring import write_variants

    if (count is None) == (roster is None):
        fail("give --count N (variants of one FILE) or --roster ROSTER.csv (one per student)")
    try:
        if roster is not None:
            from ..core.streams import cpus
            from .roster import write_roster_variants

            written = write_roster_variants(list(files), roster, seed, out_dir, force,
                                            jobs or cpus())
            # written: the variants, then key.json, then the assignment
            click.echo(f"wrote {len(written) - 2} variant file(s), the key and the "
                       "assignment:", err=True)
            click.echo(written[-1])
            return
        if len(files) != 1 or count is None:
            fail("--count varies one FILE; give --roster for several")
        if jobs is not None:
            fail("--jobs goes with --roster")
        written = write_variants(files[0], count, seed, out_dir, force)
    except InputError as err:
        fail(err)
    for path in written:
        click.echo(path)


@click.command()
@click.argument("file")
@click.option("--periods", type=click.FloatRange(min=0, min_open=True, max=1e5), default=None,
              help="How long: nutation periods (precession revolutions for a steady top). "
                   "Default 5, or 3 for --animate.")
@click.option("--format", "fmt", type=click.Choice(("text", "json")), default="text",
              show_default=True, help="text: side-by-side table; json: one JSON object.")
@click.option("--csv", "csv_file", metavar="FILE",
              help="Write the time series t, theta, phi, psi and their rates (SI) to FILE.")
@click.option("--plot", "plot_file", metavar="FILE",
              help="Draw the axis's path, theta(t) and phidot(t) to FILE (.png, .svg, .pdf).")
@click.option("--animate", "animate_file", metavar="FILE",
              help="Animate the motion to FILE (.gif, .mp4 with ffmpeg, or .html): released "
                   "top, steady precession, torque-free body, rotor on a turning base, rolling "
                   "disk, bicycle.")
@click.option("--speed", type=float, default=1.0, show_default=True,
              help="Playback speed of --animate: 1 shows one period of the motion in 2 s.")
@click.option("--fps", type=float, default=30.0, show_default=True,
              help="Frames per second of --animate.")
@click.option("--force", is_flag=True, help="Replace output files that exist.")
def simulate(file: str, periods: float | None, fmt: str, csv_file: str | None,
             plot_file: str | None, animate_file: str | None, speed: float, fps: float,
             force: bool) -> None:
    """Integrate the top of FILE (released_top or steady_precession) from Euler's
    equations and compare with the analytic answer; --animate draws the motion."""
    from .simulate import simulate_file, terminal_progress

    outputs_apart([file], csv=csv_file, plot=plot_file, animate=animate_file)
    try:
        out = ""
        if animate_file:
            from .animate import animate_file as animate
            from .animate import check_output

            check_output(animate_file, force)
            text = animate(file, animate_file, periods=periods, speed=speed, fps=fps,
                           force=force)
            if csv_file or plot_file or fmt != "text":   # the comparison too, when asked
                out = simulate_file(file, periods=periods or 5.0, fmt=fmt, csv=csv_file,
                                    plot=plot_file, force=force)
            if fmt == "text":
                out += text
        else:
            out = simulate_file(file, periods=periods or 5.0, fmt=fmt, csv=csv_file,
                                plot=plot_file, force=force, progress=terminal_progress())
    except InputError as err:
        fail(err)
    except Exception as err:
        internal(file, err)
        sys.exit(INTERNAL)
    click.echo(out, nl=False)


@click.command()
@click.argument("files", nargs=-1, metavar="FILES|DIR")
@click.option("-o", "--output", "out", metavar="OUT", default="handout.html", show_default=True,
              help="OUT.html, OUT.tex or OUT.pdf (pdflatex); per student OUT-STUDENT.ext and "
                   "OUT-key.csv.")
@click.option("--roster", metavar="ROSTER.csv",
              help="One sheet per student, each with their own numbers (as gyro vary --roster "
                   "with the same --seed).")
@click.option("--assignment", metavar="ASSIGNMENT.csv",
              help="One sheet per student from gyro vary --roster's assignment (FILES not "
                   "needed).")
@click.option("--seed", "-s", type=int, default=0, show_default=True,
              help="With --roster: the course seed.")
@click.option("--key", metavar="KEY.csv",
              help="With --roster or --assignment: write the teacher's key there, not beside "
                   "the sheets as OUT-key.csv (a folder of the teacher's keeps it out of what "
                   "is handed out).")
@click.option("--solutions", is_flag=True, help="Add the worked answers.")
@click.option("--course", default="", help="The course's name, on the cover.")
@click.option("--title", default="Homework", show_default=True, help="The sheet's title.")
@click.option("--force", is_flag=True, help="Replace files that exist.")
def handout(files: tuple[str, ...], out: str, roster: str | None, assignment: str | None,
            seed: int, solutions: bool, course: str, title: str, force: bool,
            key: str | None = None) -> None:
    """Write the students' question sheets: a cover and each problem's statement with
    the student's numbers; --solutions adds the worked answers."""
    from .handout import write_handouts

    if not files and not assignment:
        fail("give the problem FILES (or a DIR), or --assignment")
    warnings: list[str] = []
    try:
        written = write_handouts(list(files), out, roster, assignment, seed, solutions,
                                 course, title, force, key, warnings)
    except InputError as err:
        fail(err)
    for warning in warnings:  # the sheets are written: the teacher decides
        click.echo(f"gyro: warning: {warning}: the sheet gives that answer away; leave one "
                   "of the two problems out, or ask it without that given", err=True)
    if roster:  # the numbers are drawn again: the seed must be gyro vary's
        click.echo(f"gyro: note: each student's numbers are drawn from --seed {seed}, as "
                   f"gyro vary --roster draws them with that seed; --assignment "
                   "DIR/assignment.csv prints the variants gyro vary wrote", err=True)
    if roster or assignment:  # the key, written last: by default beside the sheets
        click.echo(f"gyro: note: {written[-1]} is the teacher's key (every student's "
                   "answers): keep it back when the sheets are handed out", err=True)
    for path in written:
        click.echo(path)


@click.command()
def kinds() -> None:
    """List the problem kinds with their given keys and answers."""
    from .. import kinds as registry
    from ..core.body import BODY_PARAMS
    from ..render.kinds_list import kinds_text

    click.echo(kinds_text(registry, BODY_PARAMS))
    click.echo("Units as textbooks write them: rpm RPM rev/min r/min rps rev/s rev Hz; "
               "km/h km/hr kmph kph knot kn mph; t tonne kgf; lb and oz as lbf/ozf where a "
               "force or moment is meant (lb ft, lb-ft, ft lb, lb in, oz in); N m, N-m, N.m, "
               "Nm, kN m (docs/real_problems.md)")
