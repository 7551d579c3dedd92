"""`flywheel run` of a case that asks for the kinematics alone (``machine.analysis =
"kinematics"``, or a linkage with no masses, loads or flywheel): summary.json, table.csv,
positions.csv, the kinematic plots and the report, at the constant crank speed ω_m."""
from __future__ import annotations

import os
import sys
from pathlib import Path

import typer

from flywheel.cli.guard import _guard, fail
from flywheel.cli.options import note, warn
from flywheel.errors import Notice


def run_kinematics(c, case: Path, out: Path | None, points: int, at, no_plots: bool,
                   as_json: bool, lang: str, transients: bool, formats: list[str],
                   csv_style: str, figure_format: str, dpi: int, animate: bool = False,
                   frame: str = "none") -> None:
    """The kinematics-only run of the validated case ``c`` read from ``case``; the options as
    `flywheel run` took them (``--transients`` is refused: there is no motion to integrate;
    ``--frame eskd`` frames the Russian PDF and DOCX, their title page from ``[document]``)."""
    if transients:
        fail(Notice.of(
            "transients_kinematics", "--transients: {case} asks for the kinematics alone (no "
            "masses, loads or flywheel, or machine.analysis = \"kinematics\"): there is no "
            "equation of motion to integrate", case=str(case)))
    from flywheel.dynamics.kinematics_only import analyze_kinematics
    from flywheel.io.output import write_folder
    from flywheel.render.csvfmt import restyle
    from flywheel.render.tables import positions_csv, table_csv

    results = _guard(analyze_kinematics, c, points, at, source=case, case=c)
    out = out if out is not None else Path("out") / case.stem
    from flywheel.render.tables import summary_json

    text_json = summary_json(results)

    def build(folder: Path) -> None:
        (folder / "summary.json").write_text(text_json, encoding="utf-8")
        for name, table in (("table.csv", table_csv), ("positions.csv", positions_csv)):
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
        from flywheel.render.report_formats import write_reports
        from flywheel.render.report_kinematics import build_kinematics_document

        doc = build_kinematics_document(results, lang, pngs, case=c)
        if frame != "none":                 # the title blocks need [document]'s names
            from flywheel.render.blocks import front

            doc = front(doc, c.document, frame=frame)
        write_reports(doc, folder, formats, folder / "plots" if pngs else None)

    notes: list[str] = []
    _guard(write_folder, out, build, "summary.json", notes=notes)
    from flywheel.render.nomenclature import prefix

    for n in notes:
        note(n)
    for w in results.warnings:
        warn(w)
    if as_json:
        sys.stdout.write(text_json)
    else:
        from flywheel.render.report_kinematics import print_kinematics_summary

        print_kinematics_summary(results, lang=lang)
        typer.echo(f"{prefix('written', lang)}: {out}/ (summary.json, table.csv, positions.csv, "
                   + ", ".join(f"report.{f}" for f in dict.fromkeys(formats))
                   + ("" if no_plots else ", plots/*.png"
                      + ("" if figure_format == "png" else f", plots/*.{figure_format}"))
                   + (", mechanism.gif" if animate else "") + ")")
