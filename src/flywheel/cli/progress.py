"""The progress bars of the long computations (`run --transients`, `aggregate`, the figures,
`variants`, the task sheets, `grade`): rich on a terminal, nothing at all when stderr is piped
or redirected, or under ``--quiet``.

The computation takes a plain callable ``progress(stage, fraction)`` (fractions 0 … 1, never
decreasing within a stage) and knows nothing of rich; :func:`stage_bar` gives one.
"""
from __future__ import annotations

import os
import sys
from collections.abc import Callable, Iterator
from contextlib import contextmanager

#: the environment variables by which rich may take a pipe for a terminal (rich.console)
_TERMINAL_HINTS = ("FORCE_COLOR", "TTY_COMPATIBLE", "FORCE_TERMINAL")


def _may_show() -> bool:
    """False when no bar can show — ``--quiet``, or stderr not a terminal and nothing telling
    rich otherwise — so that rich (≈ 50 ms to import) is not imported for nothing; True
    leaves the decision to rich's own ``Console.is_terminal``."""
    from flywheel.cli.options import state

    if state.quiet:
        return False
    if any(name in os.environ for name in _TERMINAL_HINTS):
        return True
    try:
        return sys.stderr.isatty()
    except (AttributeError, ValueError):      # no stderr, or a closed one
        return False


@contextmanager
def stage_bar(lang: str = "en") -> Iterator[Callable[[str, float], None]]:
    """``with stage_bar(lang) as progress: compute(progress=progress)``: one bar per stage on
    stderr while a terminal shows it, removed when done (``transient``); the stage's name
    ("start-up") in ``lang`` (render/messages.py ``stage_name``)."""
    if not _may_show():
        yield lambda *_: None
        return
    from rich.console import Console
    from rich.progress import BarColumn, Progress, TaskProgressColumn, TextColumn, TimeElapsedColumn

    from flywheel.cli.options import state
    from flywheel.render.nomenclature import stage_name

    console = Console(stderr=True)
    tasks: dict[str, int] = {}
    with Progress(TextColumn("{task.description}"), BarColumn(), TaskProgressColumn(),
                  TimeElapsedColumn(), console=console, transient=True,
                  disable=state.quiet or not console.is_terminal) as bar:

        def progress(stage: str, fraction: float) -> None:
            if stage not in tasks:
                tasks[stage] = bar.add_task(stage_name(stage, lang), total=1.0)
            bar.update(tasks[stage], completed=fraction)

        yield progress


@contextmanager
def count_bar(stage: str, lang: str = "en", *, start: bool = False,
              total: int | None = None) -> Iterator[Callable[[int, int], None]]:
    """``with count_bar("figures", lang) as progress: work(progress=progress)``: one bar of
    things done out of a total ("figures 7/22") on stderr while a terminal shows it, removed
    when done; nothing on a pipe or under ``--quiet``. The stage's name in ``lang``. The bar
    appears at the first ``progress(done, total)``, or at once with ``start`` (``total``:
    None while not known: the answer sheets before the folders are read)."""
    if not _may_show():
        yield lambda *_: None
        return
    from rich.console import Console
    from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn

    from flywheel.cli.options import state
    from flywheel.render.nomenclature import stage_name

    console = Console(stderr=True)
    with Progress(TextColumn("{task.description}"), BarColumn(), MofNCompleteColumn(),
                  console=console, transient=True,
                  disable=state.quiet or not console.is_terminal) as bar:
        task = bar.add_task(stage_name(stage, lang), total=total) if start else None

        def progress(done: int, total: int) -> None:
            nonlocal task
            if task is None:
                task = bar.add_task(stage_name(stage, lang), total=total)
            bar.update(task, completed=done, total=total)

        yield progress
