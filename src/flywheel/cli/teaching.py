"""`flywheel variants` and `flywheel grade`: a teacher's variants with an answer key, and the
batch grading of the students' answers (docs/teacher.md).

Thin: parse the options (declared once below as ``Annotated`` aliases, checked by
:func:`_check_variants` and :func:`_check_grade`), call :mod:`flywheel.teaching.variants` /
:mod:`flywheel.teaching.grading`, hand the results to cli/outputs.py (the folder, the files,
the terminal). Heavy imports live inside the functions.
"""
from __future__ import annotations

from pathlib import Path
from typing import Annotated, Optional

import typer

from flywheel.cli.options import CsvStyle, Json, Lang, Quiet

Template = Annotated[Path, typer.Argument(
    metavar="TEMPLATE", help="Template: a run or task2 case file plus a \\[variants] table (see docs/teacher.md).")]
Count = Annotated[int, typer.Option("--count", "-n", metavar="N", help="How many variants.")]
VariantsOut = Annotated[Path, typer.Option(
    "--out", "-o", metavar="DIR", help="Output folder (written whole or not at all; in an earlier variants "
    "folder only flywheel's own files are replaced).")]
Seed = Annotated[Optional[int], typer.Option(
    "--seed", metavar="N", help="Seed of numpy's default_rng: the same seed gives the same files (default: a "
    "random one, printed and written into every file).")]
Points = Annotated[int, typer.Option(
    "--points", metavar="N", help="Intervals of the φ grid for the answers of a run case.")]
Sheets = Annotated[bool, typer.Option(
    "--sheets", help="Also write a printable task sheet per variant (sheets/variant_NN.html and "
    ".pdf, and sheets.pdf with them all): the drawing, the data, what to find; no answers.")]
SheetsFormat = Annotated[Optional[str], typer.Option(
    "--sheets-format", metavar="FORMATS", help="Formats of --sheets: both | html | pdf (default both; only with "
    "--sheets).")]
Moodle = Annotated[Optional[Path], typer.Option(
    "--moodle", metavar="FILE", help="Also write the variants as a Moodle XML question bank to this file: a "
    "category per variant, a numerical question per answer with its unit and tolerance (worded "
    "in --lang).")]

Key = Annotated[Path, typer.Argument(metavar="KEY", help="The answers.json written by flywheel variants.")]
Answers = Annotated[list[Path], typer.Argument(
    metavar="ANSWERS", help="Filled-in answer sheets (CSV: student,variant,<answers…>) or folders of them.")]
Tolerance = Annotated[Optional[float], typer.Option(
    "--tolerance", metavar="SHARE", help="Relative tolerance (default: the key's, else 0.01); a per-answer "
    "tolerance in the key still applies.")]
GradeOut = Annotated[Optional[Path], typer.Option(
    "--out", "-o", metavar="FILE", help="Write one CSV line per student and answer to this file.")]
Gradebook = Annotated[Optional[Path], typer.Option(
    "--gradebook", metavar="FILE", help="Write the gradebook: one row per student (each answer's verdict and "
    "error, score, total) to this CSV file.")]
ClassSummary = Annotated[bool, typer.Option(
    "--summary", help="Print only the class summary (score distribution, answers most often "
    "wrong, who handed in nothing).")]
CarriedForward = Annotated[float, typer.Option(
    "--carried-forward", metavar="SHARE", help="Share of the credit (0…1) of an answer wrong against the key but "
    "right from the student's own earlier answers (default 0: shown as such, not scored).")]
Feedback = Annotated[Optional[Path], typer.Option(
    "--feedback", metavar="DIR", help="Write a feedback page per student (HTML, in --lang) into this folder: "
    "each answer, its verdict, the mistake named, the expected value.")]
NoReveal = Annotated[bool, typer.Option(
    "--no-reveal", help="Leave the expected values out of the feedback pages (with --feedback).")]


def variants_command(template: Template, count: Count, out: VariantsOut, seed: Seed = None,
                     points: Points = 1440, sheets: Sheets = False,
                     sheets_format: SheetsFormat = None, moodle: Moodle = None,
                     lang: Lang = "en", quiet: Quiet = False) -> None:
    """Individual variants of a task from a template, with the answer key (answers.json,
    answers.csv), a blank answer sheet (students.csv) and, with --sheets, a printable task
    sheet per variant."""
    import secrets

    from flywheel.cli.guard import _guard
    from flywheel.cli.outputs import write_variant_files
    from flywheel.cli.progress import count_bar
    from flywheel.render.grading import print_variants
    from flywheel.teaching.variants import generate, load_template

    sheets_format = _check_variants(template, count, out, seed, points, sheets, sheets_format,
                                    moodle, lang)
    seed = secrets.randbelow(2 ** 32) if seed is None else seed
    t = _guard(load_template, template, points)

    def generate_with_bar():            # the bar is gone before an error line is printed
        with count_bar("variants", lang, start=True, total=count) as progress:
            return generate(t, count, seed, points, lambda i: progress(i, count))

    vs = _guard(generate_with_bar)
    write_variant_files(vs, out, template, lang, sheets_format, moodle)
    from flywheel.render.numbers import typeset

    typeset(lang, print_variants, vs, out, sheets=sheets_format, lang=lang)


def _check_variants(template: Path, count: int, out: Path, seed, points: int, sheets: bool,
                    sheets_format, moodle, lang: str) -> str | None:
    """Refuse an option of `variants` beyond what is allowed (one error line, exit 2); return
    the format of the task sheets (None: no --sheets)."""
    from flywheel.cli.guard import check_lang, choice, fail
    from flywheel.errors import Notice

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
    return sheets_format if sheets else None


def grade_command(key: Key, answers: Answers, tolerance: Tolerance = None, out: GradeOut = None,
                  gradebook: Gradebook = None, summary: ClassSummary = False,
                  carried_forward: CarriedForward = 0.0, feedback: Feedback = None,
                  no_reveal: NoReveal = False, csv_style: CsvStyle = "plain", lang: Lang = "en", quiet: Quiet = False,
                  as_json: Json = False) -> None:
    """Grade students' answers against an answer key: per student each answer's error and
    pass/fail, the score, group statistics; broken files and rows are reported and skipped.
    A student who appears twice: the later row counts (the earlier is reported)."""
    from flywheel.cli.guard import _guard
    from flywheel.cli.outputs import finish_grade, write_grade_files
    from flywheel.cli.progress import count_bar
    from flywheel.teaching.grading import check_graded, grade, load_key

    _check_grade(key, answers, out, gradebook, feedback, no_reveal, csv_style, lang)
    k = _guard(load_key, key)

    def grade_with_bar():               # the bar is gone before an error line is printed
        with count_bar("answer sheets", lang, start=True) as progress:
            return grade(k, answers, tolerance, progress, carried_forward)

    report = _guard(grade_with_bar)
    _guard(check_graded, report, answers)   # nothing graded: one error line, nothing written
    write_grade_files(report, out, gradebook, feedback, csv_style, lang, not no_reveal)
    finish_grade(report, as_json, summary, (out, gradebook, feedback), lang)


def _check_grade(key: Path, answers, out, gradebook, feedback, no_reveal: bool, csv_style: str,
                 lang: str) -> None:
    """Refuse an option of `grade` beyond what is allowed, or an output that names an input or
    another output (teaching/grading.py ``check_outputs``): one error line, exit 2, before
    anything is read."""
    from flywheel.cli.guard import _guard, check_lang, choice, fail
    from flywheel.errors import Notice
    from flywheel.teaching.grading import check_outputs

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
