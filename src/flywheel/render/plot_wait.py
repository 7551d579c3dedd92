"""The body of the first plot worker started with the process (render/plot_start.py): it
imports matplotlib, waits for its figures and draws them. Light to import (the console entry
point imports it before typer, numpy and pydantic): the drawing's modules are imported by the
worker only."""
from __future__ import annotations

from flywheel.render import plot_start


def wait_and_draw(reader, writer, counter, done, parent: int) -> None:
    """The started worker: its signals, matplotlib imported (figure.prepare), then the job
    read from the pipe and drawn with the workers it forks (plots.draw_with_others); the pipe
    closed without a job (the run drew nothing): it ends quietly."""
    import pickle

    writer.close()                        # the parent's end: EOF here when the parent closes
    plot_start.worker_signals(parent)
    from flywheel.render import figure as fg
    from flywheel.render import plots

    fg.prepare()
    try:
        blob = reader.recv_bytes()
    except (EOFError, OSError):
        return
    results, folder, lang, order, fmt, dpi, others = pickle.loads(blob)
    del blob
    plots.draw_with_others(results, folder, lang, order, counter, fmt, dpi, done, others)
