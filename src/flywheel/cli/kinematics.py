"""`flywheel run` of a case that asks for the kinematics alone (``machine.analysis =
"kinematics"``, or a linkage with no masses, loads or flywheel): summary.json, table.csv,
positions.csv, the kinematic plots and the report, at the constant crank speed ω_m (written by
cli/outputs.py :func:`~flywheel.cli.outputs.write_kinematics`)."""
from __future__ import annotations

from pathlib import Path

from flywheel.cli.guard import _guard, fail
from flywheel.errors import Notice


def run_kinematics(c, case: Path, out: Path, points: int, at, what, as_json: bool, lang: str,
                   transients: bool) -> None:
    """The kinematics-only run of the validated case ``c`` read from ``case`` into ``out``;
    the options as `flywheel run` took them (``what``: cli/outputs.py ``RunOutputs``;
    ``--transients`` is refused: there is no motion to integrate)."""
    if transients:
        fail(Notice.of(
            "transients_kinematics", "--transients: {case} asks for the kinematics alone (no "
            "masses, loads or flywheel, or machine.analysis = \"kinematics\"): there is no "
            "equation of motion to integrate", case=str(case)))
    from flywheel.cli.outputs import KINEMATICS_TABLES, finish, write_kinematics, written_line
    from flywheel.dynamics.kinematics_only import analyze_kinematics
    from flywheel.render.report_kinematics import print_kinematics_summary

    results = _guard(analyze_kinematics, c, points, at, source=case, case=c)
    text_json = write_kinematics(out, results, c, what, lang)
    finish(warnings=results.warnings, json_text=text_json if as_json else None,
           summary=lambda: print_kinematics_summary(results, lang=lang),
           lines=[written_line(out, what.names(KINEMATICS_TABLES, drawings=False), lang)])
