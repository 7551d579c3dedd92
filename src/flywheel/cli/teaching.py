"""`flywheel variants` and `flywheel grade`: a teacher's variants with an answer key, and the
batch grading of the students' answers (docs/teacher.md).

Thin: parse the options, call :mod:`flywheel.teaching.variants` / :mod:`flywheel.teaching.grading`, hand the
results to :mod:`flywheel.render.grading`. Heavy imports live inside the functions.
"""
from __future__ import annotations

from pathlib import Path
from typing import Optional

import typer

from flywheel.cli.options import CsvStyle, Json, Lang, note, state


def variants_command(
    template: Path = typer.Argument(..., help="Template: a run or task2 case file plus a "
                                    "\\[variants] table (see docs/teacher.md).",),
    count: int = typer.Option(..., "--count", "-n", help="How many variants."),
    out: Path = typer.Option(..., "--out", "-o", help="Output folder (written whole or not at "
                             "all; in an earlier variants folder only flywheel's own files "
                             "are replaced)."),
    seed: Optional[int] = typer.Option(None, "--seed", help="Seed of numpy's default_rng: the "
                                       "same seed gives the same files (default: a random "
                                       "one, printed and written into every file)."),
    points: int = typer.Option(1440, "--points", help="Intervals of the φ grid for the "
                               "answers of a run case."),
    sheets: bool = typer.Option(False, "--sheets", help="Also write a printable task sheet per "
                                "variant (sheets/variant_NN.html and .pdf, and sheets.pdf with "
                                "them all): the drawing, the data, what to find; no answers."),
    sheets_format: Optional[str] = typer.Option(None, "--sheets-format", help="Formats of "
                                                "--sheets: both | html | pdf (default both; "
                                                "only with --sheets)."),
    moodle: Optional[Path] = typer.Option(None, "--moodle", help="Also write the variants as "
                                          "a Moodle XML question bank to this file: a category "
                                          "per variant, a numerical question per answer with "
                                          "its unit and tolerance (worded in --lang)."),
    lang: Lang = "en",
) -> None:
    """Individual variants of a task from a template, with the answer key (answers.json,
    answers.csv), a blank answer sheet (students.csv) and, with --sheets, a printable task
    sheet per variant."""
    from flywheel.cli.guard import _guard, check_lang, choice, fail
    from flywheel.errors import Notice, led

    if not 1 <= count <= 9999:
        fail(Notice.of(
            "option_not_allowed", "--count: {got} is not allowed (allowed: 1…9999)",
            option="--count", got=count, allowed="1…9999"))
    if seed is not None and not 0 <= seed < 2 ** 63:
        fail(Notice.of(
            "option_not_allowed", "--seed: {got} is not allowed (allowed: 0 … 2^63 − 1)",
            option="--seed", got=seed, allowed="0 … 2^63 − 1"))
    if moodle is not None and (moodle.resolve() == template.resolve()
                               or moodle.resolve().is_relative_to(out.resolve())):
        fail(Notice.of(
            "moodle_path", "--moodle {path}: names the template or a file inside --out {out} "
            "(allowed: a file name outside the variants folder)", path=str(moodle), out=str(out)))
    if points < 36:
        fail(Notice.of(
            "points_too_few", "--points: {n} is too few (allowed: 36 or more)", n=points))
    check_lang(lang)
    if sheets_format is not None and not sheets:
        fail(Notice.of(
            "sheets_format_without_sheets", "--sheets-format {got}: given without --sheets (it "
            "says the format of the task sheets; allowed: --sheets --sheets-format FORMAT, or "
            "neither)", got=sheets_format))
    if sheets_format is None:
        sheets_format = "both"
    if sheets_format not in ("both", "html", "pdf"):
        fail(choice("--sheets-format", sheets_format, "a sheet format", "both, html, pdf"))
    import secrets

    from rich.console import Console
    from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn

    from flywheel.render.messages import stage_name

    from flywheel.render.grading import print_variants
    from flywheel.teaching.variants import generate, load_template, write_variants

    if seed is None:
        seed = secrets.randbelow(2 ** 32)
    t = _guard(load_template, template, points)
    console = Console(stderr=True)

    def generate_with_bar():            # the bar is gone before an error line is printed
        with Progress(TextColumn(stage_name("variants", lang)), BarColumn(), MofNCompleteColumn(), console=console,
                      transient=True, disable=state.quiet or not console.is_terminal) as bar:
            task = bar.add_task("variants", total=count)
            return generate(t, count, seed, points, lambda i: bar.update(task, completed=i))

    vs = _guard(generate_with_bar)
    notes: list[str] = []
    extra = None
    if sheets:
        from flywheel.render.sheets import write_sheets
        from flywheel.teaching.sheets import sheets_of

        pages = _guard(sheets_of, vs)
        missing = sorted({p.no_drawing for p in pages if p.no_drawing})
        for why in missing:                 # one line for the batch, not one per sheet
            note(led(f"--sheets: {template}: ", why))

        def extra(folder):
            with Progress(TextColumn(stage_name("task sheets", lang)), BarColumn(), MofNCompleteColumn(),
                          console=console, transient=True, disable=state.quiet or not console.is_terminal) as b:
                t = b.add_task("sheets", total=len(pages))
                write_sheets(pages, folder, lang, sheets_format,
                             lambda i: b.update(t, completed=i))
    _guard(write_variants, vs, out, notes, extra)
    for n in notes:
        note(n)
    if moodle is not None:
        from flywheel.io.output import write_file
        from flywheel.render.moodle import quiz_xml

        _guard(write_file, moodle, quiz_xml(vs, lang), "--moodle", expected="an XML file name")
    from flywheel.render.numbers import typeset

    typeset(lang, print_variants, vs, out, sheets=sheets_format if sheets else None, lang=lang)


def grade_command(
    key: Path = typer.Argument(..., help="The answers.json written by flywheel variants."),
    answers: list[Path] = typer.Argument(..., help="Filled-in answer sheets (CSV: student,"
                                         "variant,<answers…>) or folders of them."),
    tolerance: Optional[float] = typer.Option(None, "--tolerance", help="Relative tolerance "
                                              "(default: the key's, else 0.01); a per-answer "
                                              "tolerance in the key still applies."),
    out: Optional[Path] = typer.Option(None, "--out", "-o", help="Write one CSV line per "
                                       "student and answer to this file.",),
    gradebook: Optional[Path] = typer.Option(None, "--gradebook", help="Write the gradebook: one "
                                             "row per student (each answer's verdict and "
                                             "error, score, total) to this CSV file."),
    summary: bool = typer.Option(False, "--summary", help="Print only the class summary (score "
                                 "distribution, answers most often wrong, who handed in "
                                 "nothing)."),
    carried_forward: float = typer.Option(0.0, "--carried-forward", help="Share of the credit "
                                          "(0…1) of an answer wrong against the key but right "
                                          "from the student's own earlier answers (default 0: "
                                          "shown as such, not scored)."),
    feedback: Optional[Path] = typer.Option(None, "--feedback", help="Write a feedback page "
                                            "per student (HTML, in --lang) into this folder: "
                                            "each answer, its verdict, the mistake named, the "
                                            "expected value."),
    no_reveal: bool = typer.Option(False, "--no-reveal", help="Leave the expected values out "
                                   "of the feedback pages (with --feedback)."),
    csv_style: CsvStyle = "plain",
    lang: Lang = "en",
    as_json: Json = False,
) -> None:
    """Grade students' answers against an answer key: per student each answer's error and
    pass/fail, the score, group statistics; broken files and rows are reported and skipped.
    A student who appears twice: the later row counts (the earlier is reported)."""
    import sys

    from flywheel.cli.guard import _guard, check_lang, choice, fail
    from flywheel.errors import Notice
    from flywheel.io.output import write_file
    from flywheel.render.nomenclature import stage_name
    from flywheel.teaching.grading import (check_outputs, grade, load_key,
                                           report_csv_pieces, report_json)

    check_lang(lang)
    if csv_style not in ("plain", "excel-ru"):
        fail(choice("--csv", csv_style, "a CSV dialect", "plain, excel-ru"))
    def is_dir(path: Path) -> bool:         # a name too long for the system is no folder:
        try:                                # write_file says it cannot be written
            return path.is_dir()
        except OSError:
            return False

    for option, path in (("--out", out), ("--gradebook", gradebook)):
        if path is not None and not is_dir(path) and not is_dir(path.parent):
            fail(Notice.of(
                "csv_folder_missing", "{option} {path}: the folder {parent} does not exist "
                "(allowed: a CSV file name in an existing folder)", option=option, path=str(path),
                parent=str(path.parent)))
    if no_reveal and feedback is None:
        fail(Notice.of(
            "no_reveal_without_feedback", "--no-reveal: given without --feedback (it hides the "
            "expected values of the feedback pages; allowed: --feedback DIR --no-reveal)"))
    _guard(check_outputs, key, answers, [("--out", out), ("--gradebook", gradebook),
                                         ("--feedback", feedback)])
    k = _guard(load_key, key)
    from rich.console import Console
    from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn

    console = Console(stderr=True)

    def grade_with_bar():               # the bar is gone before an error line is printed
        with Progress(TextColumn(stage_name("answer sheets", lang)), BarColumn(),
                      MofNCompleteColumn(), console=console, transient=True,
                      disable=state.quiet or not console.is_terminal) as bar:
            task = bar.add_task("sheets", total=None)
            return grade(k, answers, tolerance,
                         lambda done, total: bar.update(task, completed=done, total=total),
                         carried_forward)

    report = _guard(grade_with_bar)
    if not report.students:                 # an error: one line, nothing else written
        if report.problems:
            first = report.problems[0].said()
            fail(Notice.of(
                "nothing_graded", "nothing could be graded ({n} problem(s); the first: {detail})",
                n=len(report.problems), detail=first))
        files = ", ".join(report.files) or ", ".join(map(str, answers))
        fail(Notice.of(
            "no_student_rows", "{files}: nothing could be graded: no filled-in student rows (a row "
            "needs a student name and a variant)", files=files))
    if out is not None:
        pieces = report_csv_pieces(report)
        if csv_style == "excel-ru":
            pieces = _excel_ru(pieces)
        _guard(write_file, out, pieces, expected="a CSV file name")
    if gradebook is not None:
        from flywheel.render.grading import gradebook_pieces

        _guard(write_file, gradebook, gradebook_pieces(report, csv_style, lang), "--gradebook",
               expected="a CSV file name")
    if feedback is not None:
        from flywheel.render.feedback import write_feedback

        notes: list = []
        _guard(write_feedback, report, feedback, lang, not no_reveal, notes)
        for n in notes:
            note(n)
    if as_json:
        for piece in report_json(report):
            sys.stdout.write(piece)
    else:
        from flywheel.render.grading import print_class_summary, print_report

        from flywheel.render.numbers import typeset

        if summary:
            typeset(lang, print_class_summary, report, lang)
        else:
            typeset(lang, print_report, report, lang=lang)
        for path in (out, gradebook, feedback):
            if path is not None and report.students:
                from flywheel.render.messages import prefix

                typer.echo(f"{prefix('written', lang)}: {path}")


def _number_or_text(cell: str):
    """A CSV cell back as a float if it is one (for the decimal commas of excel-ru)."""
    try:
        return float(cell) if cell.strip() and cell.strip()[0] in "-0123456789" else cell
    except ValueError:
        return cell


def _excel_ru(pieces):
    """The pieces of the --out report restyled for a Russian Excel (';', decimal commas, a
    BOM at the start only; render/csvfmt.py), piece by piece."""
    import csv
    import io

    from flywheel.render.csvfmt import csv_text

    for i, text in enumerate(pieces):
        rows = list(csv.reader(io.StringIO(text)))
        out = csv_text([[_number_or_text(c) for c in row] for row in rows], "excel-ru",
                       fmt=lambda x: f"{x!r}")
        yield out if i == 0 else out.removeprefix("\ufeff")

