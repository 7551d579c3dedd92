"""`flywheel duty-cycle`: a press, riveter or shear whose flywheel gives each operation's energy.

Thin: load the case (:mod:`flywheel.cases.duty_cycle`), solve (:mod:`flywheel.duty_cycle.solve`),
hand the result to :mod:`flywheel.render.duty_cycle`. Heavy imports live inside the function.
"""
from __future__ import annotations

from pathlib import Path
import typer

from flywheel.cli.guard import frame_notice
from flywheel.cli.options import Frame, Json, Lang, OutFolder, Reports
from flywheel.io.text import in_language


def duty_cycle_command(
    case: Path = typer.Argument(..., help="Duty-cycle case file (TOML), see docs/duty-cycle.md."),
    as_json: Json = False,
    lang: Lang = "en",
    out: OutFolder = None,
    report: Reports = None,
    frame: Frame = "none",
) -> None:
    """Duty-cycle machines (punching, riveting, shearing presses): the motor's power and torque,
    the energy the flywheel gives, its J and mass, the speed at the end of the operation, the
    time and angle to recover, the cycle."""
    from flywheel.cli.guard import check_lang, fail, guard, needs_out

    check_lang(lang)
    from flywheel.render.report_folder import check_formats

    formats = guard(check_formats, report)
    if report and out is None:
        fail(needs_out())
    refused = frame_notice(frame, lang, formats)
    if refused is not None:
        fail(refused)
    from flywheel.cases.duty_cycle import load_duty_case, solve_case

    from flywheel.render.numbers import typeset

    c = guard(load_duty_case, case)
    result = guard(solve_case, c, str(case))
    written = None
    if out is not None:
        from flywheel.cli.outputs import report_folder
        from flywheel.render.duty_cycle import to_json
        from flywheel.render.blocks import front
        from flywheel.render.report_duty_cycle import build_duty_cycle_document

        written = guard(report_folder, out, "duty-cycle", to_json(result, c.title, c.source) + "\n",
                        None, None, lambda fig: front(typeset(
                            lang, build_duty_cycle_document, result, in_language(c.title, lang),
                            in_language(c.source, lang), lang), c.document,
                            frame="" if frame == "none" else frame),
                        formats)
    from flywheel.cli.outputs import finish, written_line
    from flywheel.render.duty_cycle import print_summary, to_json

    finish(warnings=result.warnings,
           json_text=to_json(result, c.title, c.source) + "\n" if as_json else None,
           summary=lambda: typeset(lang, print_summary, result, in_language(c.title, lang),
                                   in_language(c.source, lang), lang=lang),
           lines=[] if written is None else [written_line(out, written, lang)])
