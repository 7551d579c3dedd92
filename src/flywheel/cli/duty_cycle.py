"""`flywheel duty-cycle`: a press, riveter or shear whose flywheel gives each operation's energy.

Thin: load the case (:mod:`flywheel.cases.duty_cycle`), solve (:mod:`flywheel.duty_cycle.solve`),
hand the result to :mod:`flywheel.render.duty_cycle`. Heavy imports live inside the function.
"""
from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from flywheel.cli.guard import report_formats
from flywheel.cli.options import (Frame, Group, Json, Lang, OutFolder, Quiet, Reports, Student,
                                  Teacher, title_page)
from flywheel.io.text import in_language


DutyCase = Annotated[Path, typer.Argument(
    metavar="CASE", help="Duty-cycle case file (TOML), see docs/duty-cycle.md.")]


def duty_cycle_command(case: DutyCase, as_json: Json = False, lang: Lang = "en", quiet: Quiet = False,
                       out: OutFolder = None, report: Reports = None,
                       frame: Frame = "none", student: Student = None, group: Group = None,
                       teacher: Teacher = None) -> None:
    """Duty-cycle machines (punching, riveting, shearing presses): the motor's power and torque,
    the energy the flywheel gives, its J and mass, the speed at the end of the operation, the
    time and angle to recover, the cycle."""
    from flywheel.cases.duty_cycle import load_duty_case, solve_case
    from flywheel.cli.guard import check_lang, guard
    from flywheel.cli.outputs import finish, written_line
    from flywheel.render.duty_cycle import print_summary, to_json
    from flywheel.render.numbers import typeset

    check_lang(lang)
    formats = guard(report_formats, report, out, frame, lang)
    page = guard(title_page, student, group, teacher)
    c = guard(load_duty_case, case)
    result = guard(solve_case, c, str(case))
    written = None if out is None else guard(_write_out, out, result, c, formats, lang, frame,
                                                page)
    finish(warnings=result.warnings,
           json_text=to_json(result, c.title, c.source) + "\n" if as_json else None,
           summary=lambda: typeset(lang, print_summary, result, in_language(c.title, lang),
                                   in_language(c.source, lang), lang=lang),
           lines=[] if written is None else [written_line(out, written, lang)])


def _write_out(out: Path, result, c, formats, lang: str, frame: str = "none",
               page: dict | None = None) -> list[str]:
    """The --out folder (cli/outputs.py, render/report_folder.py): summary.json and the report
    with its title page from the case's [document] under ``page`` (--student, --group,
    --teacher; no figure); returns the names written."""
    from flywheel.cli.outputs import report_folder
    from flywheel.render.blocks import front
    from flywheel.render.duty_cycle import to_json
    from flywheel.render.numbers import typeset
    from flywheel.render.report_duty_cycle import build_duty_cycle_document

    return report_folder(
        out, "duty-cycle", to_json(result, c.title, c.source) + "\n", None, None,
        lambda fig: front(typeset(lang, build_duty_cycle_document, result,
                                  in_language(c.title, lang), in_language(c.source, lang), lang),
                          c.document, frame="" if frame == "none" else frame, **(page or {})),
        formats)
