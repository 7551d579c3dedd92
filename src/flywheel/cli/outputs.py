"""The one output path of every command (`run`, `task2`, `aggregate`, `duty-cycle`): the output
folder, written whole or not at all through :mod:`flywheel.io.output`, and what the terminal
shows — notes and warnings on stderr, then the JSON or the summary and the lines that say what
was written (:func:`finish`).

A command is parse → load → solve → write: it hands its result here. `run`'s folder
(:func:`write_run`) starts the plot workers as soon as the results exist, the costliest figures
first, writes summary.json, the CSVs and the report texts meanwhile, then waits for the figures
(a progress bar on a terminal) before the reports that embed them. task2, aggregate and
duty-cycle write their folders through :func:`report_folder` (render/report_folder.py).
A new output of `run`: a field of :class:`RunOutputs` and a step of :func:`write_run`; its
name in :meth:`RunOutputs.names` (the "written:" line).
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

    def names(self) -> list[str]:
        """The files listed on the "written:" line."""
        figures = [] if self.plots == "none" else ["plots/*.png"] + (
            [] if self.figure_format == "png" else [f"plots/*.{self.figure_format}"])
        return (["summary.json", *RUN_TABLES]
                + [f"report.{f}" for f in dict.fromkeys(self.formats)] + figures
                + (["mechanism.gif"] if self.animate else [])
                + (["drawings/sheet*.{pdf,svg,dxf}"] if self.drawings else []))


def write_run(out: Path, results, case, what: RunOutputs, lang: str, summary_text: str) -> None:
    """`run`'s output folder ``out``: summary.json (``summary_text``), the CSVs, the figures
    (drawn by forked workers started first), mechanism.gif, the reports; notes of a rerun on
    stderr. Errors are the caller's guard's."""
    from flywheel.cli.guard import _guard
    from flywheel.io.output import write_folder

    notes: list[str] = []
    _guard(write_folder, out, lambda folder: _build_run(folder, results, case, what, lang,
                                                        summary_text),
           "summary.json", notes=notes)
    for n in notes:
        note(n)


def _build_run(folder: Path, results, case, what: RunOutputs, lang: str,
               summary_text: str) -> None:
    """Fill the temporary ``folder`` of :func:`write_run`."""
    from contextlib import nullcontext

    from flywheel.render.csvfmt import restyle
    from flywheel.render.document import build_document
    from flywheel.render.forces import forces_csv, forces_positions_csv
    from flywheel.render.report_formats import write_reports
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
        if what.plots != "none":
            from flywheel.cli.progress import count_bar

            with count_bar("figures", lang) as progress:
                job.wait(progress)
    write_reports(doc, folder, what.formats, folder / "plots" if pngs else None)


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
