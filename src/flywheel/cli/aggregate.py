"""`flywheel aggregate`: the machine aggregate with elastic couplings (seed 003) and rotor chains.

Thin: load the case (:mod:`flywheel.cases.aggregate`), analyse (:mod:`flywheel.elastic.model`), hand
the result to :mod:`flywheel.render.aggregate`. Heavy imports live inside the function.
"""
from __future__ import annotations

from pathlib import Path
from typing import Annotated, Optional

import typer

from flywheel.cli.guard import report_formats
from flywheel.cli.options import Frame, Group, Json, Lang, Quiet, Reports, Student, Teacher, title_page
from flywheel.io.text import in_language


MAX_T_END = 600.0     # s: ten minutes of simulated start-up (about 15 s of computing)


Plot = Annotated[Optional[Path], typer.Option(
    "--plot", metavar="FILE", help="Write speeds and the elastic moment against time (start-up, steady state) to "
    "this image file (.png, .svg, .pdf).", dir_okay=False)]
TEnd = Annotated[Optional[float], typer.Option(
    "--t-end", metavar="SECONDS", help="Duration of the start-up integration, seconds (default: five time "
    "constants of the motor or 20 forcing periods, whichever is longer, at most 2000 periods of "
    "the highest natural frequency).")]
Modes = Annotated[bool, typer.Option(
    "--modes", help="Also show every mode's frequency in Hz and vibrations per minute with its "
    "nodes (positions along the shafts), and each shaft's equivalent length (the JSON always has "
    "them).")]
AggregateOut = Annotated[Optional[Path], typer.Option(
    "--out", "-o", metavar="DIR", help="Also write an output folder: summary.json (as --json), "
    "plots/aggregate.png (with a \\[motor]) and the report (see --report); a rerun replaces only "
    "its own files.")]
AggregateCase = Annotated[Path, typer.Argument(
    metavar="CASE", help="Aggregate case file (TOML), see docs/aggregate.md.")]


def aggregate_command(case: AggregateCase, json: Json = False, plot: Plot = None,
                      t_end: TEnd = None, lang: Lang = "en", quiet: Quiet = False, modes: Modes = False,
                      out: AggregateOut = None, report: Reports = None,
                      frame: Frame = "none", student: Student = None, group: Group = None,
                      teacher: Teacher = None) -> None:
    """Two-mass machine aggregate (Ефанов ch. 9) or a chain of rotors: coefficients a_ij, c_ij,
    natural frequencies, steady forced vibration, start-up."""
    from flywheel.cli.guard import guarded, write_plot
    from flywheel.cli.outputs import finish, written_line
    from flywheel.render import nomenclature as nm
    from flywheel.render.aggregate import print_summary, to_json
    from flywheel.render.numbers import typeset

    with guarded(source=case):      # an error of the analysis is prefixed with the case file
        formats = _check_options(lang, t_end, report, out, frame)
        page = title_page(student, group, teacher)
        c, result = _solve(case, plot, t_end, lang)
        if plot is not None:
            from flywheel.render.aggregate import plot as draw

            write_plot(plot, lambda tmp: draw(result, tmp, in_language(c.title, lang), lang))
        written = (_write_out(out, result, formats, c.title, c.source, lang, c.document,
                              frame, page) if out is not None else None)
    finish(json_text=to_json(result, c.title, c.source) + "\n" if json else None,
           summary=lambda: typeset(lang, print_summary, result, in_language(c.title, lang),
                                   in_language(c.source, lang), lang=lang, modes=modes),
           lines=([nm.name("plot_written", lang, path=plot)] if plot is not None else [])
           + ([written_line(out, written, lang)] if out is not None else []))


def _solve(case: Path, plot: Optional[Path], t_end: Optional[float], lang: str):
    """(the case, its AggregateResult): the case read (cases/aggregate.py), its chain analysed
    (elastic/model.py; a progress bar on a terminal, a long --t-end takes seconds); a --plot
    refused without a [motor], a result that is not finite refused (guard.not_finite)."""
    from flywheel.cases.aggregate import load_aggregate_case, to_model
    from flywheel.cli.guard import refuse_nonfinite
    from flywheel.cli.progress import stage_bar
    from flywheel.elastic.model import analyze
    from flywheel.errors import InputError, Notice

    c = load_aggregate_case(case)
    ch, drive = to_model(c, str(case))
    if plot is not None and drive is None:
        raise InputError(Notice.of(
            "plot_needs_motor", "--plot needs a [motor]: a chain without one has no motion in "
            "time"))
    with stage_bar(lang) as progress:
        result = analyze(ch, drive, t_end=t_end, progress=progress)
    # no Infinity/NaN printed, in the summary or the JSON (which has none): guard.not_finite
    refuse_nonfinite(result.to_document(), who=str(case))
    return c, result

def _check_options(lang: str, t_end, report, out, frame: str = "none"):
    """Refuse a language, --t-end, or --report (or --report without --out) beyond what is
    allowed (an InputError); return the report formats."""
    import math

    from flywheel.cli.guard import check_lang
    from flywheel.errors import InputError, Notice

    check_lang(lang)
    if t_end is not None and not (math.isfinite(t_end) and 0 < t_end <= MAX_T_END):
        raise InputError(Notice.of(
            "t_end_range", "--t-end: {t:g} s is out of range (allowed: 0 … {top:g} s; a "
            "start-up is over in seconds to a minute, and the integration time grows with it)",
            t=t_end, top=MAX_T_END))
    return report_formats(report, out, frame, lang)


def _write_out(out: Path, result, formats, title: str, source: str, lang: str,
               document=None, frame: str = "none", page: dict | None = None) -> list[str]:
    """The --out folder (cli/outputs.py, render/report_folder.py): summary.json,
    plots/aggregate.png (with a motor), the report with its title page from ``document``
    (the case's [document]) under ``page`` (--student, --group, --teacher); returns the names
    written."""
    from flywheel.cli.outputs import report_folder
    from flywheel.render.aggregate import plot as draw
    from flywheel.render.aggregate import to_json
    from flywheel.render.blocks import front
    from flywheel.render.numbers import typeset
    from flywheel.render.report_aggregate import FIGURE, build_aggregate_document

    shown, said = in_language(title, lang), in_language(source, lang)   # the JSON: English
    return report_folder(
        out, "aggregate", to_json(result, title, source) + "\n",
        lambda path: draw(result, path, shown, lang),
        FIGURE if result.startup is not None else None,
        lambda fig: front(typeset(lang, build_aggregate_document, result, shown, said, lang,
                                  fig), document, frame="" if frame == "none" else frame, **(page or {})),
        formats)
