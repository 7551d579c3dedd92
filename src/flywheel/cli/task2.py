"""`flywheel task2`: steady motion under given moment graphs (seed 002 and the textbook family).

Thin: parse the options, call :mod:`flywheel.constant_inertia.preset` (or :mod:`flywheel.cases.task2` for
``--case``), hand the result to :mod:`flywheel.render.task2`. Heavy imports live inside the
function so that ``flywheel task2 --json`` starts fast.

Help texts escape their units (``\\[deg]``): typer renders help through rich, which would read
``[deg]``, ``[rad/s]`` or ``[kg·m²]`` as markup tags and drop them. ``[N·m]`` starts with a
capital and is no tag, so it stays as it is.
"""
from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Annotated, List, Optional

import typer

from flywheel.cli.guard import report_formats
from flywheel.cli.options import (Frame, Group, Json, Lang, OutFolder, Quiet, Reports, Student,
                                  Teacher, title_page)

PROFILES = ("triangle", "rectangle")

def _check_at(at, cycle_deg: float) -> None:
    """Each --at angle finite and within the cycle 0…cycle_deg [deg]."""
    import math

    from flywheel.errors import InputError, Notice

    for x in at or ():
        if not (math.isfinite(x) and 0.0 <= x <= cycle_deg):
            raise InputError(Notice.of(
                "t2_at_option", "--at {x:g}: must lie within the cycle 0…{cycle:g}°", x=x,
                cycle=cycle_deg))


Profile = Annotated[Optional[str], typer.Option(
    "--profile", metavar="PROFILE", help="The resistance graph of the textbook task «Задача 2»: triangle (π/2…3π/2, "
    "peak in the middle) or rectangle (π/2…π) (default triangle).")]
Md = Annotated[Optional[float], typer.Option(
    "--md", metavar="TORQUE", help="Constant driving moment M_D [N·m] (default 15).")]
J = Annotated[Optional[float], typer.Option(
    "--j", metavar="INERTIA", help="Reduced moment of inertia J \\[kg·m²] (default 12).")]
Omega0 = Annotated[Optional[float], typer.Option(
    "--omega0", metavar="SPEED", help="ω at φ = 0 \\[rad/s] (default 200).")]
From = Annotated[Optional[float], typer.Option(
    "--from", metavar="DEG", help="Start of the resistance graph \\[deg] (default 90).")]
To = Annotated[Optional[float], typer.Option(
    "--to", metavar="DEG", help="End of the resistance graph \\[deg] (default 270 triangle, 180 rectangle).")]
Mc = Annotated[Optional[float], typer.Option(
    "--mc", metavar="TORQUE", help="Peak of the resistance [N·m] instead of the balance (the motion may not be "
    "steady).")]
Delta = Annotated[Optional[float], typer.Option(
    "--delta", metavar="DELTA", help="Ask for the J that gives this δ at the same mean speed.")]
Task2Case = Annotated[Optional[Path], typer.Option(
    "--case", metavar="FILE", help="A task-2 case file (TOML), see docs/task2.md; it gives all the data, so it "
    "takes none of the options above.")]
At = Annotated[Optional[List[float]], typer.Option(
    "--at", metavar="DEG", help="Report ω, ε and the time t at this crank angle \\[deg] (repeatable; added to a "
    "case's at_deg). Implies --epsilon.")]
Epsilon = Annotated[bool, typer.Option(
    "--epsilon", help="Also show ε(φ) = (M_D − M_C)/J (its extremes), the cycle time and the "
    "phases of rising and falling speed in the summary (the JSON always has them).")]
Plot = Annotated[Optional[Path], typer.Option(
    "--plot", metavar="FILE", help="Write a plot of M_D, M_C, A, ω(φ) and ε(φ) to this image file (.png, .svg, "
    ".pdf).")]


def task2_command(profile: Profile = None, md: Md = None, j: J = None, omega0: Omega0 = None,
                  start: From = None, end: To = None, mc: Mc = None, delta: Delta = None,
                  case: Task2Case = None, at: At = None, epsilon: Epsilon = False,
                  plot: Plot = None, as_json: Json = False, lang: Lang = "en", quiet: Quiet = False,
                  out: OutFolder = None, report: Reports = None, frame: Frame = "none",
                  student: Student = None, group: Group = None, teacher: Teacher = None) -> None:
    """Task 2: ω_max, ω_min, ω_ср and δ of a machine with constant J under given M_D(φ), M_C(φ)."""
    from flywheel.cli.guard import check_lang, guarded, solve_finite, write_plot
    from flywheel.cli.outputs import finish, written_line
    from flywheel.render import nomenclature as nm
    from flywheel.render.numbers import typeset
    from flywheel.render.task2 import print_summary, to_json

    given = [(name, v) for name, v in (("--md", md), ("--j", j), ("--omega0", omega0),
                                       ("--from", start), ("--to", end), ("--mc", mc),
                                       ("--delta", delta)) if v is not None]
    with guarded():
        check_lang(lang)
        formats = _check_options(plot, report, out, frame, lang)
        page = title_page(student, group, teacher)
        job = (_from_case(case, at, profile, given, lang) if case is not None else
               _from_options(profile, given, dict(md=md, j=j, omega0=omega0, start=start,
                                                  end=end, mc=mc, delta=delta), at, lang))
        result = solve_finite(job.run, job.blame, job.who)
        if plot is not None:
            from flywheel.render.task2 import plot as draw

            write_plot(plot, lambda tmp: draw(result, tmp, job.title, lang))
        written = _write_out(out, result, formats, job, lang, frame, page) if out else None
    finish(json_text=to_json(result, job.doc_title, job.doc_source) + "\n" if as_json else None,
           summary=lambda: typeset(lang, print_summary, result, job.title, job.source, lang=lang,
                                   motion=epsilon or bool(at)),
           lines=([nm.name("plot_written", lang, path=plot)] if plot is not None else [])
           + ([written_line(out, written, lang)] if out is not None else []))


def _check_options(plot: Optional[Path], report, out: Optional[Path], frame: str = "none",
                   lang: str = "en") -> list[str]:
    """Refuse a --plot that names a folder, a --report format not known, or --report without
    --out (an InputError); return the report formats."""
    from flywheel.errors import InputError, Notice

    if plot is not None and plot.is_dir():
        raise InputError(Notice.of(
            "plot_is_a_folder", "--plot {plot}: is a folder, expected an image file",
            plot=str(plot)))
    return report_formats(report, out, frame, lang)

@dataclass(frozen=True)
class _Job:
    """What the command solves: ``run()`` gives the result; ``blame`` the (name, value) of the
    inputs an overflow may come from, ``who`` the case file (None: the options); the title and
    source in the user's language and in the JSON's (English) one."""

    run: Callable
    blame: list
    who: Optional[Path]
    title: str
    source: str
    doc_title: str
    doc_source: str
    document: object = None         # the case's [document] (the title page), if a case
    case: object = None             # the validated case file (its data as given), if a case


def _from_case(case: Path, at, profile, given, lang: str = "en") -> _Job:
    """A task-2 case file (cases/task2.py): it gives all the data, so no other option."""
    from flywheel.cases.task2 import load_task2_case, solve_case
    from flywheel.cli.guard import case_numbers
    from flywheel.errors import InputError, Notice

    used = (["--profile"] if profile is not None else []) + [n for n, _ in given]
    if used:
        raise InputError(Notice.of(
            "case_drops_options", "--case takes its data from the file; drop {used}",
            used=", ".join(used)))
    c = load_task2_case(case)
    _check_at(at, c.cycle_deg)
    if at and c.diagram is not None:
        raise InputError(Notice.of(
            "t2_at_diagram", "--at: {case} gives a diagram by areas, which has no moments between "
            "its crossings: ε, ω and t at an angle need graphs", case=str(case)))
    from flywheel.io.text import in_language

    return _Job(lambda: solve_case(c, str(case), at_deg=at or ()), case_numbers(c.model_dump()),
                case, in_language(c.title, lang), in_language(c.source, lang), str(c.title),
                str(c.source), c.document, c)


def _from_options(profile, given, v: dict, at, lang: str) -> _Job:
    """The textbook task «Задача 2» (constant_inertia/preset.py) with the options' values:
    each finite, the moments, J and ω positive, 0 < δ < 2, --from before --to."""
    import math

    from flywheel.constant_inertia.preset import SEED_DEFAULTS, seed_task
    from flywheel.errors import InputError, Notice
    from flywheel.render import nomenclature as nm

    profile = "triangle" if profile is None else profile
    if profile not in PROFILES:
        raise InputError(Notice.of(
            "profile_choice", "--profile must be triangle or rectangle (got {value})",
            value=repr(profile)))
    for name, x in given:
        if not math.isfinite(x):
            raise InputError(Notice.of("option_not_finite", "{option} must be a finite number "
                                       "(got {got})", option=name, got=str(x)))
    for name, x, unit in (("--md", v["md"], "N·m"), ("--j", v["j"], "kg·m²"),
                          ("--omega0", v["omega0"], "rad/s"), ("--mc", v["mc"], "N·m")):
        if x is not None and x <= 0:
            raise InputError(Notice.of(
                "option_not_positive", "{option} must be positive (got {v:g} {unit})", option=name,
                v=x, unit=unit))
    delta, start, end = v["delta"], v["start"], v["end"]
    if delta is not None and not 0 < delta < 2:
        raise InputError(Notice.of(
            "option_delta", "--delta must lie between 0 and 2 (got {delta:g})", delta=delta))
    if start is not None and end is not None and start >= end:
        raise InputError(Notice.of(
            "option_from_to", "--from ({start:g}°) must be less than --to ({end:g}°)", start=start,
            end=end))
    _check_at(at, 360.0)

    def run():
        return seed_task(
            profile,
            M_D=SEED_DEFAULTS["M_D"] if v["md"] is None else v["md"],
            J=SEED_DEFAULTS["J"] if v["j"] is None else v["j"],
            omega0=SEED_DEFAULTS["omega0"] if v["omega0"] is None else v["omega0"],
            start=None if start is None else math.radians(start),
            end=None if end is None else math.radians(end),
            M_C=v["mc"], delta=delta, at=[math.radians(x) for x in at or ()])

    # the JSON document is the same in every language; the summary and plot speak lang
    return _Job(run, given, None,
                nm.name("t2_seed_title", lang, profile=nm.name(profile, lang)),
                nm.name("t2_seed_source", lang),
                nm.name("t2_seed_title", profile=profile), nm.name("t2_seed_source"))


def _write_out(out: Path, result, formats, job: _Job, lang: str, frame: str = "none",
               page: dict | None = None):
    """The --out folder (cli/outputs.py, render/report_folder.py): summary.json,
    plots/task2.png, the report with its title page (the case's [document] under ``page``:
    --student, --group, --teacher); returns the names written."""
    from flywheel.cli.outputs import report_folder
    from flywheel.render.blocks import front
    from flywheel.render.numbers import typeset
    from flywheel.render.report_task2 import FIGURE, build_task2_document
    from flywheel.render.task2 import plot as draw
    from flywheel.render.task2 import to_json

    return report_folder(
        out, "task2", to_json(result, job.doc_title, job.doc_source) + "\n",
        lambda path: draw(result, path, job.title, lang), FIGURE,
        lambda fig: front(typeset(lang, build_task2_document, result, job.title, job.source, lang,
                                  fig, job.case), job.document,
                          frame="" if frame == "none" else frame, **(page or {})),
        formats)
