"""`flywheel task2`: steady motion under given moment graphs (seed 002 and the textbook family).

Thin: parse the options, call :mod:`flywheel.constant_inertia.preset` (or :mod:`flywheel.cases.task2` for
``--case``), hand the result to :mod:`flywheel.render.task2`. Heavy imports live inside the
function so that ``flywheel task2 --json`` starts fast.

Help texts escape their units (``\\[deg]``): typer renders help through rich, which would read
``[deg]``, ``[rad/s]`` or ``[kg·m²]`` as markup tags and drop them. ``[N·m]`` starts with a
capital and is no tag, so it stays as it is.
"""
from __future__ import annotations

from pathlib import Path
from typing import List, Optional

import typer

PROFILES = ("triangle", "rectangle")

# |x| outside this range is a suspect when the results overflow double precision
_SANE = (1e-100, 1e100)


def _extreme(numbers: list[tuple[str, float]]) -> list[tuple[str, float]]:
    """The (name, value) pairs of extreme magnitude: the likely cause of an overflow."""
    return [(n, v) for n, v in numbers if v != 0 and not _SANE[0] <= abs(v) <= _SANE[1]]


def _case_numbers(data, path: str = "") -> list[tuple[str, float]]:
    """(field path, number) of every number in a case's fields, e.g. ("driving.value", 1e308)."""
    out: list[tuple[str, float]] = []
    if isinstance(data, dict):
        for k, v in data.items():
            out += _case_numbers(v, f"{path}.{k}" if path else str(k))
    elif isinstance(data, (list, tuple)):
        for i, v in enumerate(data):
            out += _case_numbers(v, f"{path}[{i}]")
    elif isinstance(data, (int, float)) and not isinstance(data, bool):
        out.append((path, float(data)))
    return out


def _check_at(at, cycle_deg: float) -> None:
    """Each --at angle finite and within the cycle 0…cycle_deg [deg]."""
    import math

    from flywheel.errors import InputError, Notice

    for x in at or ():
        if not (math.isfinite(x) and 0.0 <= x <= cycle_deg):
            raise InputError(Notice.of(
                "t2_at_option", "--at {x:g}: must lie within the cycle 0…{cycle:g}°", x=x,
                cycle=cycle_deg))


def task2_command(
    profile: Optional[str] = typer.Option(
        None, "--profile",
        help="The resistance graph of the textbook task «Задача 2»: triangle (π/2…3π/2, peak in the middle) or rectangle "
             "(π/2…π) (default triangle)."),
    md: Optional[float] = typer.Option(None, "--md", help="Constant driving moment M_D [N·m] "
                                       "(default 15)."),
    j: Optional[float] = typer.Option(None, "--j", help="Reduced moment of inertia J "
                                      "\\[kg·m²] (default 12)."),
    omega0: Optional[float] = typer.Option(None, "--omega0", help="ω at φ = 0 \\[rad/s] "
                                           "(default 200)."),
    start: Optional[float] = typer.Option(None, "--from", help="Start of the resistance "
                                          "graph \\[deg] (default 90)."),
    end: Optional[float] = typer.Option(None, "--to", help="End of the resistance graph \\[deg] "
                                        "(default 270 triangle, 180 rectangle)."),
    mc: Optional[float] = typer.Option(None, "--mc", help="Peak of the resistance [N·m] instead "
                                       "of the balance (the motion may not be steady)."),
    delta: Optional[float] = typer.Option(None, "--delta", help="Ask for the J that gives this "
                                          "δ at the same mean speed."),
    case: Optional[Path] = typer.Option(None, "--case", help="A task-2 case file (TOML), "
                                        "see docs/task2.md; it gives all the data, so it takes "
                                        "none of the options above."),
    at: Optional[List[float]] = typer.Option(
        None, "--at", help="Report ω, ε and the time t at this crank angle \\[deg] (repeatable; "
                           "added to a case's at_deg). Implies --epsilon."),
    epsilon: bool = typer.Option(False, "--epsilon", help="Also show ε(φ) = (M_D − M_C)/J (its "
                                 "extremes), the cycle time and the phases of rising and falling "
                                 "speed in the summary (the JSON always has them)."),
    plot: Optional[Path] = typer.Option(None, "--plot", help="Write a plot of M_D, M_C, A, "
                                        "ω(φ) and ε(φ) to this image file (.png, .svg, .pdf)."),
    as_json: bool = typer.Option(False, "--json", help="Print the results as JSON (the same "
                                 "document in every language)."),
    lang: str = typer.Option("en", "--lang", help="Language of the summary and the plot: en | ru."),
    out: Optional[Path] = typer.Option(None, "--out", "-o", help="Also write an output folder: "
                                       "summary.json (as --json), plots/task2.png and the "
                                       "report (see --report); a rerun replaces only its own "
                                       "files."),
    report: Optional[List[str]] = typer.Option(None, "--report", help="Report format with --out: "
                                               "md, html, pdf, docx; repeatable (default: md and "
                                               "html)."),
) -> None:
    """Task 2: ω_max, ω_min, ω_ср and δ of a machine with constant J under given M_D(φ), M_C(φ)."""
    import math

    from flywheel.cli.guard import (check_lang, first_nonfinite, guarded, needs_out, not_finite,
                                    plot_failed)
    from flywheel.errors import FlywheelError, InputError, Notice

    title = source = ""
    given = [(name, v) for name, v in (("--md", md), ("--j", j), ("--omega0", omega0),
                                       ("--from", start), ("--to", end), ("--mc", mc),
                                       ("--delta", delta)) if v is not None]
    with guarded():
        from flywheel.render import nomenclature as nm

        check_lang(lang)
        if plot is not None and plot.is_dir():
            raise InputError(Notice(f"--plot {plot}: is a folder, expected an image file",
                                        "plot_is_a_folder", plot=str(plot)))
        from flywheel.render.report_folder import check_formats

        formats = check_formats(report)
        if report and out is None:
            raise InputError(needs_out())
        if case is not None:
            used = (["--profile"] if profile is not None else []) + [n for n, _ in given]
            if used:
                raise InputError(Notice.of(
                    "case_drops_options", "--case takes its data from the file; drop {used}",
                    used=", ".join(used)))
            from flywheel.cases.task2 import load_task2_case, solve_case

            c = load_task2_case(case)
            blame = _case_numbers(c.model_dump())
            _check_at(at, c.cycle_deg)
            if at and c.diagram is not None:
                raise InputError(Notice(f"--at: {case} gives a diagram by areas, which has no "
                                        "moments between its crossings: ε, ω and t at an angle "
                                        "need graphs", "t2_at_diagram", case=str(case)))

            def run():
                return solve_case(c, str(case), at_deg=at or ())

            title, source = c.title, c.source
            doc_title, doc_source = title, source
        else:
            from flywheel.constant_inertia.preset import SEED_DEFAULTS, seed_task

            profile = "triangle" if profile is None else profile
            if profile not in PROFILES:
                raise InputError(Notice(f"--profile must be triangle or rectangle (got {profile!r})",
                                        "profile_choice", value=repr(profile)))
            for name, v in given:
                if not math.isfinite(v):
                    raise InputError(Notice(f"{name} must be a finite number (got {v})",
                                            "option_not_finite", option=name, got=str(v)))
            for name, v, unit in (("--md", md, "N·m"), ("--j", j, "kg·m²"),
                                  ("--omega0", omega0, "rad/s"), ("--mc", mc, "N·m")):
                if v is not None and v <= 0:
                    raise InputError(Notice.of(
                        "option_not_positive", "{option} must be positive (got {v:g} {unit})",
                        option=name, v=v, unit=unit))
            if delta is not None and not 0 < delta < 2:
                raise InputError(Notice.of(
                    "option_delta", "--delta must lie between 0 and 2 (got {delta:g})", delta=delta
                ))
            if start is not None and end is not None and start >= end:
                raise InputError(Notice.of(
                    "option_from_to", "--from ({start:g}°) must be less than --to ({end:g}°)",
                    start=start, end=end))
            _check_at(at, 360.0)
            blame = given

            def run():
                return seed_task(
                    profile,
                    M_D=SEED_DEFAULTS["M_D"] if md is None else md,
                    J=SEED_DEFAULTS["J"] if j is None else j,
                    omega0=SEED_DEFAULTS["omega0"] if omega0 is None else omega0,
                    start=None if start is None else math.radians(start),
                    end=None if end is None else math.radians(end),
                    M_C=mc, delta=delta, at=[math.radians(x) for x in at or ()])

            # the JSON document is the same in every language; the summary and plot speak lang
            doc_title = nm.name("t2_seed_title", profile=profile)
            doc_source = nm.name("t2_seed_source")
            title = nm.name("t2_seed_title", lang, profile=nm.name(profile, lang))
            source = nm.name("t2_seed_source", lang)
        from flywheel.constant_inertia.solve import NotFiniteError, python_detail

        # inputs near the limits of double precision: no Infinity/NaN in the output (it is not
        # JSON), and no traceback from inf − inf inside the formulas (guard.not_finite)
        hit = None
        try:
            result = run()
            found = first_nonfinite(result.to_document())
            if found is not None:
                hit = (found[0], repr(found[1]))
        except NotFiniteError as exc:
            hit = (exc.quantity, exc.detail)
        except FlywheelError:
            raise
        except (ArithmeticError, ValueError) as exc:
            hit = ("a result",
                   python_detail(f"{exc.args[-1] if exc.args else type(exc).__name__}"))
        if hit is not None:
            if case is not None:     # "file: field, field" (the file alone if none stands out)
                fields = [n for n, _ in _extreme(blame)]
                who = f"{case}: {', '.join(fields)}" if fields else str(case)
            else:                    # "--md 1e+308" (every given option if none stands out)
                who = ", ".join(f"{n} {v:g}" for n, v in (_extreme(blame) or blame))
            not_finite(*hit, who=who)
        if plot is not None:
            from flywheel.render.task2 import plot as draw

            try:
                draw(result, plot, title, lang)
            except (OSError, ValueError) as exc:
                raise InputError(plot_failed(plot, exc)) from None
        if out is not None:
            written = _write_out(out, result, formats, title, source, doc_title, doc_source, lang)
    if as_json:
        from flywheel.render.task2 import to_json

        typer.echo(to_json(result, doc_title, doc_source))
    else:
        from flywheel.render.task2 import print_summary

        print_summary(result, title, source, lang=lang, motion=epsilon or bool(at))
        from flywheel.render import nomenclature as nm

        if plot is not None:
            typer.echo(nm.name("plot_written", lang, path=plot))
        if out is not None:
            from flywheel.render.messages import prefix

            typer.echo(f"{prefix('written', lang)}: {out}/ "
                       f"({', '.join(written)})")


def _write_out(out: Path, result, formats, title, source, doc_title, doc_source, lang):
    """The --out folder (render/report_folder.py): summary.json, plots/task2.png, the report.
    Notes of a rerun go to stderr; returns the names written."""
    import sys

    from flywheel.render.report_folder import write_report_folder
    from flywheel.render.report_task2 import FIGURE, build_task2_document
    from flywheel.render.task2 import plot as draw
    from flywheel.render.task2 import to_json

    names, notes = write_report_folder(
        out, "task2", to_json(result, doc_title, doc_source) + "\n",
        lambda path: draw(result, path, title, lang), FIGURE,
        lambda fig: build_task2_document(result, title, source, lang, fig), formats)
    from flywheel.render.messages import message, prefix

    for n in notes:
        sys.stderr.write(f"{prefix('note', lang)}: {message(n, lang)}\n")
    return names
