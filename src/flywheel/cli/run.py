"""`flywheel run`, `flywheel check`, `flywheel schema`: the linkage (and tabulated) route.

Thin: parse the options, call the library, hand results to renderers (cli/outputs.py). `run`'s
own options are declared once below as ``Annotated`` aliases (the shared ones in
cli/options.py). Heavy imports live inside the functions.
"""
from __future__ import annotations

import math
from pathlib import Path
from typing import Annotated, Optional

import typer

from flywheel.cli.guard import _guard, check_lang, choice, fail, frame_notice
from flywheel.cli.options import (CaseFile, CsvStyle, Frame, Group, Json, Lang, Quiet, Reports,
                                  Student, Teacher)
from flywheel.errors import Notice

RunOut = Annotated[Optional[Path], typer.Option(
    "--out", "-o", metavar="DIR", help="Output folder (default: out/<case name>); in an earlier output folder "
    "only flywheel's own files are replaced, any other non-empty folder is refused.")]
Points = Annotated[int, typer.Option("--points", metavar="N", help="Intervals of the φ grid over the cycle.")]
At = Annotated[Optional[list[float]], typer.Option(
    "--at", metavar="DEG", help="Report angle \\[deg]; repeatable (default: the case's output.at_deg, else 120).")]
Plots = Annotated[str, typer.Option(
    "--plots", metavar="WHICH", help="Which figures to draw: all | record (the figures of a course project's "
    "записка: kinematics, plans, reduced quantities, energy–mass diagram, ω(φ)) | none "
    "(fastest).")]
NoPlots = Annotated[bool, typer.Option("--no-plots", help="No figures: the same as --plots none.")]
Transients = Annotated[bool, typer.Option(
    "--transients", help="Also integrate the equation of motion in time: check ω(φ), start-up "
    "(needs \\[motor]), run-down.")]
Animate = Annotated[bool, typer.Option(
    "--animate", help="Also write mechanism.gif: the linkage moving over one cycle with its "
    "points' trajectories (72 frames).")]
Motion = Annotated[Optional[str], typer.Option(
    "--motion", metavar="MOTION", help="Crank motion of the force analysis: true (ω(φ), ε(φ) of the dynamics) | "
    "steady (ω_m, ε = 0); default: the case's force_analysis.motion, else true.")]
FigureFormat = Annotated[str, typer.Option(
    "--figure-format", metavar="FORMAT", help="Format of plots/*: png, svg or pdf (svg, pdf: written beside the "
    "PNGs the reports embed).")]
Dpi = Annotated[int, typer.Option(
    "--dpi", metavar="DPI", help="Resolution of the plots \\[dots per inch], 50…600.")]
Drawings = Annotated[bool, typer.Option(
    "--drawings", help="Also write the project's drawing sheets (ЕСКД): "
    "drawings/sheet1.pdf, .svg and .dxf (the law of motion), sheet2.* (the force analysis); "
    "docs/drawings.md.")]
SheetSize = Annotated[str, typer.Option(
    "--sheet-size", metavar="SIZE", help="Format of the --drawings sheets, landscape: A1, A2 or A3.")]
Snapshot = Annotated[Optional[list[str]], typer.Option(
    "--snapshot", metavar="PHI_DEG:RPM", help="The crank's ε at the angle PHI_DEG \\[deg] and the "
    "speed RPM \\[rev/min]; repeatable.")]
AtTravel = Annotated[Optional[list[str]], typer.Option(
    "--at-travel", metavar="POINT:METRES", help="Report the positions where slider point POINT "
    "is METRES from its outer dead centre; repeatable.")]
Roots = Annotated[Optional[list[str]], typer.Option(
    "--roots", metavar="COLUMN", help="The crank angles where the table.csv column COLUMN "
    "changes sign; repeatable.")]


SchemaResults = Annotated[bool, typer.Option(
    "--results", help="The JSON Schema of a run's summary.json instead (docs/results.md).")]


def schema_command(results: SchemaResults = False, lang: Lang = "en", quiet: Quiet = False) -> None:
    """Print the JSON Schema of case files (for editors: completion and checking; --lang ru: the
    fields described in Russian), or with --results that of summary.json."""
    import json

    check_lang(lang)

    if results:
        from flywheel.dynamics.results import summary_json_schema

        typer.echo(json.dumps(summary_json_schema(), indent=2, ensure_ascii=False))
        return
    from flywheel.cases.run import case_json_schema
    from flywheel.render.catalogue import translated_schema

    typer.echo(json.dumps(translated_schema(case_json_schema(), lang), indent=2, ensure_ascii=False))


def check_command(case: CaseFile, lang: Lang = "en", quiet: Quiet = False) -> None:
    """Validate a case file and print what it describes; exit 0 if valid, 2 if not."""
    from flywheel.cases.run import load_case
    from flywheel.dynamics.check import check_case
    from flywheel.render.check import print_check

    check_lang(lang)
    from flywheel.render.numbers import typeset

    c = _guard(load_case, case)
    typeset(lang, print_check, _guard(check_case, c, source=case, case=c), lang=lang)


def run_command(case: CaseFile, out: RunOut = None, points: Points = 3600, at: At = None,
                plots: Plots = "all", no_plots: NoPlots = False, as_json: Json = False,
                lang: Lang = "en", quiet: Quiet = False, transients: Transients = False, animate: Animate = False,
                motion: Motion = None, report: Reports = None, csv_style: CsvStyle = "plain",
                figure_format: FigureFormat = "png", dpi: Dpi = 120, drawings: Drawings = False,
                sheet_size: SheetSize = "A1", snapshot: Snapshot = None,
                at_travel: AtTravel = None, roots: Roots = None, student: Student = None,
                group: Group = None, teacher: Teacher = None, frame: Frame = "none") -> None:
    """Run the whole dynamic analysis of a case; write summary.json, table.csv, positions.csv,
    forces.csv, forces_positions.csv, report.md and plots/*.png to the output folder."""
    from flywheel.cli.outputs import RunOutputs, Summary, finish_run, write_run

    check_lang(lang)
    what = RunOutputs(formats=tuple(report or ["md", "html"]), csv_style=csv_style,
                      plots="none" if no_plots else plots, figure_format=figure_format, dpi=dpi,
                      animate=animate, drawings=drawings, sheet_size=sheet_size,
                      title_page=(student, group, teacher), frame=frame)
    _check_options(what, at, lang)
    c = _load(case, animate)
    out = out if out is not None else Path("out") / case.stem
    if c.kinematics_only:               # the kinematics alone (cli/kinematics.py)
        from flywheel.cli.kinematics import run_kinematics

        return run_kinematics(c, case, out, points, at, what, as_json, lang, transients)
    results = _solve(c, case, points, at, transients, motion, snapshot, at_travel, roots, lang)
    summary = Summary(results, lang)     # rendered while the figures are drawn
    finish_run(out, results, what, lang, write_run(
        out, results, c, what, lang, None if as_json else summary.render), as_json, summary)


def _load(case: Path, animate: bool):
    """The run case read from ``case`` (cases/run.py); ``--animate`` refused for a tabulated
    case (no mechanism to animate)."""
    from flywheel.cases.run import load_case

    c = _guard(load_case, case)
    if animate and c.tabulated is not None:
        fail(Notice.of(
            "animate_tabulated", "--animate: {case} gives its kinematics as a table "
            "([tabulated]): there is no mechanism to animate (allowed: a case with [crank] and "
            "[[dyads]])", case=str(case)))
    return c


def _solve(c, case: Path, points: int, at, transients: bool, motion, snapshot, at_travel, roots,
           lang: str):
    """The results of the run case ``c`` (dynamics.analyze, a progress bar on a terminal), with
    the textbook asks (dynamics/asks.py): --at-travel's angles added to the report angles,
    --snapshot, --roots."""
    from flywheel.cli.progress import stage_bar
    from flywheel.dynamics.asks import at_with_travel, with_asks
    from flywheel.dynamics.pipeline import analyze

    travel = _guard(at_with_travel, c, at_travel)   # --at-travel: its angles are report angles
    at = travel.at_deg(at, c)

    def analyze_with_bar():             # a bar on a terminal only (the transients take seconds),
        with stage_bar(lang) as progress:   # gone before an error line is printed
            return analyze(c, n_points=points, at_deg=at, transients=transients, motion=motion,
                           progress=progress)

    results = _guard(analyze_with_bar, source=case, case=c)
    return _guard(with_asks, results, c, snapshot, travel.found, roots)   # textbook asks

def _check_options(what, at, lang: str = "en") -> None:
    """Refuse an option's value outside its choices or range, or one that cannot apply (a
    frame without a Russian PDF or DOCX report): one error line, exit 2."""
    from flywheel.render.choices import (CSV_STYLES as STYLES, DPI_RANGE, FIGURE_FORMATS,
                                         PLOT_CHOICES as CHOICES, REPORT_FORMATS as FORMATS,
                                         SHEET_SIZES)

    if what.csv_style not in STYLES:
        fail(choice("--csv", what.csv_style, "a CSV dialect", ", ".join(STYLES)))
    if what.plots not in CHOICES:
        fail(choice("--plots", what.plots, "a set of figures", ", ".join(CHOICES)))
    if what.figure_format not in FIGURE_FORMATS:
        fail(choice("--figure-format", what.figure_format, "a figure format",
                    ", ".join(FIGURE_FORMATS)))
    if not DPI_RANGE[0] <= what.dpi <= DPI_RANGE[1]:
        fail(Notice.of(
            "option_range", "--dpi: {got} is out of range (allowed: {lo} to {hi})", option="--dpi",
            got=what.dpi, lo=DPI_RANGE[0], hi=DPI_RANGE[1]))
    _check_at(at)
    if what.sheet_size not in SHEET_SIZES:
        fail(choice("--sheet-size", what.sheet_size, "a sheet format", ", ".join(SHEET_SIZES)))
    for f in what.formats:
        if f not in FORMATS:
            fail(choice("--report", f, "a report format", ", ".join(FORMATS)))
    refused = frame_notice(what.frame, lang, what.formats)
    if refused is not None:
        fail(refused)
    from flywheel.cli.options import title_page

    _guard(title_page, *what.title_page)        # --student, --group, --teacher: at most MAX_TEXT


#: the report angles --at takes: at most AT_MOST of them, each within ±AT_LIMIT_DEG [deg] (an
#: angle is taken modulo the cycle, so a larger one says nothing more, and its own digits
#: would be printed as the report angle φ)
AT_LIMIT_DEG = 1e6
AT_MOST = 72


def _check_at(at: list[float] | None) -> None:
    """Refuse a --at angle outside ±AT_LIMIT_DEG or not finite, or more than AT_MOST of them:
    one error line, exit 2."""
    if not at:
        return
    if len(at) > AT_MOST:
        fail(Notice.of(
            "at_too_many", "--at: {count} angles given (allowed: at most {most})", count=len(at),
            most=AT_MOST))
    for a in at:
        if math.isfinite(a) and not -AT_LIMIT_DEG <= a <= AT_LIMIT_DEG:   # NaN: grid_options
            fail(Notice.of(
                "at_out_of_range", "--at: {a:g}° is out of range (allowed: {lo:g} … {hi:g}°, "
                "taken modulo the cycle)", a=a, lo=-AT_LIMIT_DEG, hi=AT_LIMIT_DEG))
