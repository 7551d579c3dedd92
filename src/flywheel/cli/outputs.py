"""The one output path of every command (`run`, `task2`, `aggregate`, `duty-cycle`, `variants`,
`grade`): the output folder, written whole or not at all through :mod:`flywheel.io.output`,
and what the terminal shows — notes and warnings on stderr, then the JSON or the summary and
the lines that say what was written (:func:`finish`).

A command is parse → load → solve → write: it hands its result here. `run`'s folder
(:func:`write_run`) starts the plot workers as soon as the results exist, the costliest figures
first, writes summary.json, the CSVs and the report texts meanwhile, then waits for the figures
(a progress bar on a terminal) before the reports that embed them. task2, aggregate and
duty-cycle write their folders through :func:`report_folder` (render/report_folder.py);
`variants` its folder, task sheets and Moodle file through :func:`write_variant_files`;
`grade` its CSV files and feedback pages through :func:`write_grade_files` and its terminal
end through :func:`finish_grade`. A kinematics-only run (``machine.analysis = "kinematics"``) writes its folder through
:func:`write_kinematics`. A new output of `run`: a field of :class:`RunOutputs` and a step of
:func:`write_run`; its name in :meth:`RunOutputs.names` (the "written:" line).
"""
from __future__ import annotations

import os
import sys
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from pathlib import Path

import typer

from flywheel.cli.options import note, warn

#: the CSV tables of `run`, in the order written and listed
RUN_TABLES = ("table.csv", "positions.csv", "forces.csv", "forces_positions.csv")
#: those of a kinematics-only run (no forces)
KINEMATICS_TABLES = ("table.csv", "positions.csv")


@dataclass(frozen=True)
class RunOutputs:
    """What `run` writes besides summary.json and the CSVs: the report formats, the CSV
    dialect, which figures (render/plots.py ``CHOICES``), their format and dpi, the GIF, the
    drawing sheets and their format."""

    formats: tuple[str, ...] = ("md", "html")
    csv_style: str = "plain"
    plots: str = "all"
    figure_format: str = "png"
    dpi: int = 120
    animate: bool = False
    drawings: bool = False              # the ЕСКД sheets (render/drawings, docs/drawings.md)
    sheet_size: str = "A1"
    #: --student, --group, --teacher (None: the case's [document]) for the title page
    title_page: tuple = (None, None, None)
    #: --frame: the page frame of the Russian PDF and DOCX (render/report_frame.py FRAMES)
    frame: str = "none"

    @property
    def frame_of_front(self) -> str:
        """The frame as the title page carries it ("" none)."""
        return "" if self.frame == "none" else self.frame

    def names(self, tables: tuple[str, ...] = RUN_TABLES, drawings: bool = True) -> list[str]:
        """The files listed on the "written:" line (``tables``: the CSVs written; the sheets
        only if ``drawings`` may be written: not by a kinematics-only run)."""
        figures = [] if self.plots == "none" else ["plots/*.png"] + (
            [] if self.figure_format == "png" else [f"plots/*.{self.figure_format}"])
        return (["summary.json", *tables]
                + [f"report.{f}" for f in dict.fromkeys(self.formats)] + figures
                + (["mechanism.gif"] if self.animate else [])
                + (["drawings/sheet*.{pdf,svg,dxf}"] if self.drawings and drawings else []))

def write_run(out: Path, results, case, what: RunOutputs, lang: str,
              meanwhile: Callable[[], object] | None = None) -> str:
    """`run`'s output folder ``out``: summary.json, the CSVs, the figures (drawn by forked
    workers started first), mechanism.gif, the reports; notes of a rerun on stderr;
    ``meanwhile()`` called while the figures are drawn (the terminal's summary rendered:
    :class:`Summary`). Returns the text of summary.json. Errors are the caller's guard's."""
    return _write_folder(out, results, lambda folder, summary_text: _build_run(
        folder, results, case, what, lang, summary_text, meanwhile))


def _write_folder(out: Path, results, build) -> str:
    """A run's output folder ``out`` written whole (io/output.py write_folder): ``build(folder,
    summary_text)`` fills the temporary folder; the notes of a rerun on stderr. Returns the
    text of summary.json."""
    from flywheel.cli.guard import _guard
    from flywheel.io.output import write_folder
    from flywheel.render.tables import summary_json

    summary_text = summary_json(results)
    notes: list[str] = []
    _guard(write_folder, out, lambda folder: build(folder, summary_text), "summary.json",
           notes=notes)
    for n in notes:
        note(n)
    return summary_text


class Summary:
    """`run`'s summary on the terminal (render/summary.py print_summary): rendered once
    (:meth:`render`, called while the figures are drawn: rich's import and its tables, 60 ms
    that a run would otherwise spend after its last figure), then printed as it would have
    been printed (:meth:`print`: the same console, so the same width and colours)."""

    def __init__(self, results, lang: str):
        self.results, self.lang, self.text = results, lang, None

    def render(self) -> None:
        from rich.console import Console

        from flywheel.render.numbers import typeset
        from flywheel.render.summary import print_summary

        if self.text is None:
            console = Console()
            with console.capture() as captured:
                typeset(self.lang, print_summary, self.results, console=console, lang=self.lang)
            self.text = captured.get()

    def print(self) -> None:
        self.render()
        sys.stdout.write(self.text)
        sys.stdout.flush()


def finish_run(out: Path, results, what: RunOutputs, lang: str, summary_text: str,
               as_json: bool, summary: Summary | None = None) -> None:
    """The terminal end of `run` (:func:`finish`): the warnings, then summary.json's text
    (``--json``) or the summary (``summary``, perhaps rendered already) and the "written:"
    line."""
    summary = summary or Summary(results, lang)
    finish(warnings=results.warnings, json_text=summary_text if as_json else None,
           summary=summary.print, lines=[written_line(out, what.names(), lang)])


def write_kinematics(out: Path, results, case, what: RunOutputs, lang: str) -> str:
    """The output folder of a kinematics-only `run` (dynamics/kinematics_only.py):
    summary.json, table.csv, positions.csv, the kinematic plots (every one unless
    ``--plots none``), mechanism.gif, the reports; notes of a rerun on stderr. Returns the
    text of summary.json."""
    return _write_folder(out, results, lambda folder, summary_text: _build_kinematics(
        folder, results, case, what, lang, summary_text))


def _build_kinematics(folder: Path, results, case, what: RunOutputs, lang: str,
                      summary_text: str) -> None:
    """Fill the temporary ``folder`` of :func:`write_kinematics`."""
    from flywheel.render.csvfmt import restyle
    from flywheel.render.report_formats import write_reports
    from flywheel.render.report_kinematics import build_kinematics_document
    from flywheel.render.tables import positions_csv, table_csv

    (folder / "summary.json").write_text(summary_text, encoding="utf-8")
    for name, table in zip(KINEMATICS_TABLES, (table_csv, positions_csv)):
        (folder / name).write_text(restyle(table(results), what.csv_style), encoding="utf-8")
    pngs: list[str] = []
    if what.plots != "none":
        from flywheel.render.plots import write_plots

        (folder / "plots").mkdir()
        pngs += [p.with_suffix(".png").name for p in write_plots(
            results, folder / "plots", lang=lang, jobs=min(2, os.cpu_count() or 1),
            fmt=what.figure_format, dpi=what.dpi)]
    if what.animate:
        from flywheel.render.animate import write_animation

        write_animation(results, folder / "mechanism.gif", lang=lang)
    doc = build_kinematics_document(results, lang, pngs, case=case)
    if what.frame != "none":            # the title blocks need [document]'s names
        from flywheel.render.blocks import front

        doc = front(doc, case.document, frame=what.frame)
    write_reports(doc, folder, list(what.formats), folder / "plots" if pngs else None)

def _build_run(folder: Path, results, case, what: RunOutputs, lang: str,
               summary_text: str, meanwhile: Callable[[], object] | None = None) -> None:
    """Fill the temporary ``folder`` of :func:`write_run`."""
    from contextlib import nullcontext

    from flywheel.render.csvfmt import restyle
    from flywheel.render.document import build_document
    from flywheel.render.forces import forces_csv, forces_positions_csv
    from flywheel.render.report_formats import start_reports
    from flywheel.render.tables import positions_csv, table_csv

    job = nullcontext()
    if what.plots != "none":
        from flywheel.render.plots import start_plots

        (folder / "plots").mkdir()
        job = start_plots(results, folder / "plots", lang=lang,
                          jobs=min(2, os.cpu_count() or 1), fmt=what.figure_format,
                          dpi=what.dpi, which=what.plots)
    with job:                            # the workers stop if anything below fails
        (folder / "summary.json").write_text(summary_text, encoding="utf-8")
        for name, table in zip(RUN_TABLES, (table_csv, positions_csv, forces_csv,
                                            forces_positions_csv)):
            (folder / name).write_text(restyle(table(results), what.csv_style),
                                       encoding="utf-8")
        pngs = [] if what.plots == "none" else \
            [Path(n).with_suffix(".png").name for n in job.names]
        from flywheel.render.blocks import front
        from flywheel.render.numbers import typeset

        doc = front(typeset(lang, build_document, results, lang, pngs, case=case), case.document,
                    frame=what.frame_of_front,
                    **dict(zip(("student", "group", "teacher"), what.title_page)))
        if what.animate:
            from flywheel.render.animate import write_animation

            write_animation(results, folder / "mechanism.gif", lang=lang)
        if what.drawings:
            from flywheel.render.drawings import write_drawings

            write_drawings(results, folder / "drawings", case.document, lang=lang,
                           size=what.sheet_size)
        reports = start_reports(doc, what.formats)
        if meanwhile is not None:
            meanwhile()
        if what.plots != "none":
            from flywheel.cli.progress import count_bar

            with count_bar("figures", lang) as progress:
                job.wait(progress)
    reports(folder, folder / "plots" if pngs else None)


def report_folder(out: Path, kind: str, json_text: str, draw, figure, document,
                  formats) -> list[str]:
    """The output folder of task2, aggregate and duty-cycle (render/report_folder.py:
    summary.json, the figure ``figure`` drawn by ``draw`` if given, the reports of
    ``document``); notes of a rerun on stderr; returns the names written."""
    from flywheel.render.report_folder import write_report_folder

    names, notes = write_report_folder(out, kind, json_text, draw, figure, document, formats)
    for n in notes:
        note(n)
    return names



def write_variant_files(vs, out: Path, template: Path, lang: str, sheets_format: str | None,
                        moodle: Path | None) -> None:
    """`variants`' folder ``out`` (teaching/variants.py ``write_variants``: the variant files,
    answers.json/csv, students.csv) with the task sheets if ``sheets_format`` (render/sheets.py,
    a progress bar on a terminal), and the Moodle XML file ``moodle`` (render/moodle.py);
    notes on stderr. Errors: one line, exit 2."""
    from flywheel.cli.guard import _guard
    from flywheel.teaching.variants import write_variants

    extra = None if sheets_format is None else _sheet_writer(vs, template, lang, sheets_format)
    notes: list[str] = []
    _guard(write_variants, vs, out, notes, extra)
    for n in notes:
        note(n)
    if moodle is not None:
        from flywheel.io.output import write_file
        from flywheel.render.moodle import quiz_xml

        _guard(write_file, moodle, quiz_xml(vs, lang), "--moodle", expected="an XML file name")


def _sheet_writer(vs, template: Path, lang: str, sheets_format: str):
    """``extra(folder)`` of ``write_variants``: the task sheets of the variants ``vs``; a sheet
    without its drawing said once for the batch (a note), not once per sheet."""
    from flywheel.cli.guard import _guard
    from flywheel.cli.progress import count_bar
    from flywheel.errors import led
    from flywheel.render.sheets import write_sheets
    from flywheel.teaching.sheets import sheets_of

    pages = _guard(sheets_of, vs)
    for why in sorted({p.no_drawing for p in pages if p.no_drawing}):
        note(led(f"--sheets: {template}: ", why))

    def extra(folder: Path) -> None:
        with count_bar("task sheets", lang, start=True, total=len(pages)) as progress:
            write_sheets(pages, folder, lang, sheets_format, lambda i: progress(i, len(pages)))

    return extra


def write_grade_files(report, out: Path | None, gradebook: Path | None, feedback: Path | None,
                      csv_style: str, lang: str, reveal: bool) -> None:
    """`grade`'s files, each given: ``out`` one CSV line per student and answer
    (teaching/grading.py, restyled by render/csvfmt.py), the ``gradebook``
    (render/grading.py), the ``feedback`` pages (render/feedback.py; the expected values
    unless not ``reveal``); notes on stderr. Errors: one line, exit 2."""
    from flywheel.cli.guard import _guard
    from flywheel.io.output import write_file

    if out is not None:
        from flywheel.render.csvfmt import excel_ru_pieces
        from flywheel.teaching.grading import report_csv_pieces

        pieces = report_csv_pieces(report)
        if csv_style == "excel-ru":
            pieces = excel_ru_pieces(pieces)
        _guard(write_file, out, pieces, expected="a CSV file name")
    if gradebook is not None:
        from flywheel.render.grading import gradebook_pieces

        _guard(write_file, gradebook, gradebook_pieces(report, csv_style, lang), "--gradebook",
               expected="a CSV file name")
    if feedback is not None:
        from flywheel.render.feedback import write_feedback

        notes: list = []
        _guard(write_feedback, report, feedback, lang, reveal, notes)
        for n in notes:
            note(n)


def finish_grade(report, as_json: bool, summary: bool, paths: Iterable[Path | None],
                 lang: str) -> None:
    """The terminal end of `grade`: the report as JSON (streamed in pieces), or the class
    summary (``summary``) or the whole report, and a "written:" line for each of ``paths``
    given."""
    if as_json:
        from flywheel.teaching.grading import report_json

        for piece in report_json(report):
            sys.stdout.write(piece)
        return
    from flywheel.render.grading import print_class_summary, print_report
    from flywheel.render.messages import prefix

    from flywheel.render.numbers import typeset

    if summary:
        typeset(lang, print_class_summary, report, lang)
    else:
        typeset(lang, print_report, report, lang=lang)
    for path in paths:
        if path is not None and report.students:
            typer.echo(f"{prefix('written', lang)}: {path}")

def written_line(out: Path, names: Iterable[str], lang: str) -> str:
    """"written: OUT/ (a, b, …)" in ``lang``."""
    from flywheel.render.messages import prefix

    return f"{prefix('written', lang)}: {out}/ ({', '.join(names)})"


def finish(*, warnings: Iterable = (), json_text: str | None = None,
           summary: Callable[[], None] | None = None, lines: Iterable[str] = ()) -> None:
    """The terminal end of a command: its warnings on stderr (once each, as they came), then
    ``json_text`` on stdout as it is, or the ``summary`` printed and the ``lines`` after it
    (what was written)."""
    for w in warnings:                  # on stderr too: `2>/dev/null` and pipes behave
        warn(w)
    if json_text is not None:
        sys.stdout.write(json_text)
        return
    if summary is not None:
        summary()
    for line in lines:
        typer.echo(line)
