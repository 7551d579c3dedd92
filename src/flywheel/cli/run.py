"""`flywheel run`, `flywheel check`, `flywheel schema`: the linkage (and tabulated) route.

Thin: parse the options, call the library, hand results to renderers. Heavy imports live
inside the functions.
"""
from __future__ import annotations

import math
import os
import sys
from pathlib import Path
from typing import Optional

import typer

from flywheel.cli.guard import _guard, check_lang, choice, fail
from flywheel.cli.options import CsvStyle, Group, Json, Lang, Reports, Student, Teacher, note, warn
from flywheel.errors import Notice


def schema_command(results: bool = typer.Option(
        False, "--results", help="The JSON Schema of a run's summary.json instead (docs/results.md).")) -> None:
    """Print the JSON Schema of case files (for editors: completion and checking), or with
    --results that of summary.json."""
    import json

    if results:
        from flywheel.dynamics.results import summary_json_schema

        typer.echo(json.dumps(summary_json_schema(), indent=2, ensure_ascii=False))
        return
    from flywheel.cases.run import case_json_schema

    typer.echo(json.dumps(case_json_schema(), indent=2, ensure_ascii=False))


def check_command(case: Path = typer.Argument(..., help="Case file (TOML)."),
                  lang: Lang = "en") -> None:
    """Validate a case file and print what it describes; exit 0 if valid, 2 if not."""
    from flywheel.cases.run import load_case
    from flywheel.dynamics.check import check_case
    from flywheel.render.check import print_check

    check_lang(lang)
    c = _guard(load_case, case)
    print_check(_guard(check_case, c, source=case, case=c), lang=lang)


def run_command(
    case: Path = typer.Argument(..., help="Case file (TOML)."),
    out: Optional[Path] = typer.Option(None, "--out", "-o",
                                       help="Output folder (default: out/<case name>); in an "
                                       "earlier output folder only flywheel's own files are "
                                       "replaced, any other non-empty folder is refused."),
    points: int = typer.Option(3600, "--points", help="Intervals of the φ grid over the cycle."),
    at: Optional[list[float]] = typer.Option(None, "--at", help="Report angle \\[deg]; repeatable "
                                             "(default: the case's output.at_deg, else 120)."),
    no_plots: bool = typer.Option(False, "--no-plots", help="Skip the PNG plots (faster)."),
    as_json: Json = False,
    lang: Lang = "en",
    transients: bool = typer.Option(False, "--transients", help="Also integrate the equation of "
                                    "motion in time: check ω(φ), start-up (needs \\[motor]), run-down."),
    animate: bool = typer.Option(False, "--animate", help="Also write mechanism.gif: the linkage "
                                 "moving over one cycle with its points' trajectories (72 frames)."),
    motion: Optional[str] = typer.Option(None, "--motion", help="Crank motion of the force "
                                         "analysis: true (ω(φ), ε(φ) of the dynamics) | steady "
                                         "(ω_m, ε = 0); default: the case's force_analysis.motion, "
                                         "else true."),
    report: Reports = None,
    csv_style: CsvStyle = "plain",
    figure_format: str = typer.Option("png", "--figure-format", help="Format of plots/*: png, svg "
                                      "or pdf (svg, pdf: written beside the PNGs the reports embed)."),
    dpi: int = typer.Option(120, "--dpi", help="Resolution of the plots [dots per inch], 50…600."),
    student: Student = None,
    group: Group = None,
    teacher: Teacher = None,
) -> None:
    """Run the whole dynamic analysis of a case; write summary.json, table.csv, positions.csv,
    forces.csv, forces_positions.csv, report.md and plots/*.png to the output folder."""
    check_lang(lang)
    names = dict(student=student, group=group, teacher=teacher)
    from flywheel.io.schema import MAX_TEXT

    for option, value in names.items():
        if value is not None and len(value) > MAX_TEXT:
            fail(Notice.of(
                "option_text_too_long", "--{option}: {length} characters (allowed: at most "
                "{most})", option=option, length=len(value), most=MAX_TEXT))
    from flywheel.render.csvfmt import STYLES, restyle

    if csv_style not in STYLES:
        fail(choice("--csv", csv_style, "a CSV dialect", ", ".join(STYLES)))
    from flywheel.render.figure import DPI_RANGE, FORMATS as FIGURE_FORMATS
    from flywheel.render.report_formats import FORMATS

    if figure_format not in FIGURE_FORMATS:
        fail(choice("--figure-format", figure_format, "a figure format", ", ".join(FIGURE_FORMATS)))
    if not DPI_RANGE[0] <= dpi <= DPI_RANGE[1]:
        fail(Notice.of(
            "option_range", "--dpi: {got} is out of range (allowed: {lo} to {hi})", option="--dpi",
            got=dpi, lo=DPI_RANGE[0], hi=DPI_RANGE[1]))
    _check_at(at)
    formats = report or ["md", "html"]
    for f in formats:
        if f not in FORMATS:
            fail(choice("--report", f, "a report format", ", ".join(FORMATS)))
    from flywheel.cases.run import load_case
    from flywheel.dynamics.pipeline import analyze
    from flywheel.io.output import write_folder
    from flywheel.render.forces import forces_csv, forces_positions_csv
    from flywheel.render.tables import positions_csv, summary_json, table_csv

    c = _guard(load_case, case)
    if animate and c.tabulated is not None:
        fail(Notice.of(
            "animate_tabulated", "--animate: {case} gives its kinematics as a table "
            "([tabulated]): there is no mechanism to animate (allowed: a case with [crank] and "
            "[[dyads]])", case=str(case)))
    from flywheel.cli.progress import stage_bar

    def analyze_with_bar():             # a bar on a terminal only (the transients take seconds),
        with stage_bar(lang) as progress:   # gone before an error line is printed
            return analyze(c, n_points=points, at_deg=at, transients=transients, motion=motion,
                           progress=progress)

    results = _guard(analyze_with_bar, source=case, case=c)
    out = out if out is not None else Path("out") / case.stem
    text_json = summary_json(results)

    def build(folder: Path) -> None:
        (folder / "summary.json").write_text(text_json, encoding="utf-8")
        for name, table in (("table.csv", table_csv), ("positions.csv", positions_csv),
                            ("forces.csv", forces_csv),
                            ("forces_positions.csv", forces_positions_csv)):
            (folder / name).write_text(restyle(table(results), csv_style), encoding="utf-8")
        pngs: list[str] = []
        if not no_plots:
            from flywheel.render.plots import write_plots

            (folder / "plots").mkdir()
            pngs += [p.with_suffix(".png").name for p in write_plots(
                results, folder / "plots", lang=lang, jobs=min(2, os.cpu_count() or 1),
                fmt=figure_format, dpi=dpi)]
        if animate:
            from flywheel.render.animate import write_animation

            write_animation(results, folder / "mechanism.gif", lang=lang)
        from flywheel.render.document import build_document
        from flywheel.render.report_formats import write_reports

        from flywheel.render.blocks import TitlePage
        from flywheel.render.numbers import typeset

        doc = typeset(lang, build_document, results, lang, pngs, case=c)
        doc.front = TitlePage.of(c.document, results.title, **names)
        write_reports(doc, folder, formats, folder / "plots" if pngs else None)

    notes: list[str] = []
    _guard(write_folder, out, build, "summary.json", notes=notes)
    from flywheel.render.nomenclature import prefix

    for n in notes:
        note(n)
    for w in results.warnings:              # on stderr too: `2>/dev/null` and pipes behave
        warn(w)
    if as_json:
        sys.stdout.write(text_json)
    else:
        from flywheel.render.numbers import typeset
        from flywheel.render.summary import print_summary

        typeset(lang, print_summary, results, lang=lang)
        typer.echo(f"{prefix('written', lang)}: {out}/ (summary.json, table.csv, "
                   "positions.csv, forces.csv, forces_positions.csv, "
                   + ", ".join(f"report.{f}" for f in dict.fromkeys(formats))
                   + ("" if no_plots else ", plots/*.png"
                      + ("" if figure_format == "png" else f", plots/*.{figure_format}"))
                   + (", mechanism.gif" if animate else "") + ")")


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
