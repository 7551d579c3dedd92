"""The first plot worker of `flywheel run`, started with the process (issue 26 item 2).

A run's figures are drawn by forked workers (render/plots.py, :class:`~flywheel.render.plots.
PlotJob`); the first imports matplotlib (0.4 – 0.5 s) before it can draw. Forked when the
results exist, that import begins only after the run's own imports and analysis (0.35 s). The
console entry point (cli/__init__.py ``main``) calls :func:`start` before it imports anything
else when its words are those of a run that draws figures (:func:`wanted`): the worker then
imports matplotlib while the run parses its options, reads the case and analyses it, and
waits; the run's :class:`PlotJob` hands it its figures through a pipe (:meth:`Early.send`,
the results pickled), or :func:`release` ends it if the run ends without figures (bad input,
``--plots none`` given another way, an error).

A guess from the words only decides when the worker starts, never what is drawn: the options
are read by the parser as ever, and a run whose worker was not started, or cannot take the
results, forks its workers as before. Imports here: the standard library's only (this module
is imported before typer, numpy and pydantic).
"""
from __future__ import annotations

import os
import sys

#: the words after which `flywheel run` draws no figure
_NO_FIGURES = ("--no-plots", "--plots=none", "--help", "-h")


def wanted(argv: list[str]) -> bool:
    """Whether ``flywheel ARGV`` (the words after the program's name) is a run that draws
    figures, as far as the words show: the command is `run` (after the root's flags), none of
    ``--no-plots``, ``--plots none`` (``--plots=none``), ``--help`` is given, and the machine
    has two processors or more and can fork (as :class:`~flywheel.render.plots.PlotJob`
    needs)."""
    words = [w for w in argv if w != "--"]
    command = next((w for w in words if not w.startswith("-")), None)
    if command != "run":
        return False
    if any(w in _NO_FIGURES for w in words):
        return False
    if any(a == "--plots" and b == "none" for a, b in zip(words, words[1:])):
        return False
    return (os.cpu_count() or 1) >= 2 and sys.platform.startswith("linux")


class Early:
    """The started worker: its process, its end of the pipe, the two shared counters a
    :class:`~flywheel.render.plots.PlotJob` reads (the next figure to draw, the figures
    done)."""

    def __init__(self, target) -> None:
        import multiprocessing as mp

        ctx = mp.get_context("fork")
        reader, self.writer = ctx.Pipe(duplex=False)
        self.counter, self.done = ctx.Value("i", 0), ctx.Value("i", 0)
        self.process = ctx.Process(target=target, args=(
            reader, self.writer, self.counter, self.done, os.getpid()))
        self.sender = None
        start_held([self.process])          # the worker sets its own signals (worker_signals)
        reader.close()

    def send(self, job: tuple) -> bool:
        """Hand the worker its figures: ``job`` = (results, folder, lang, order, fmt, dpi,
        others), pickled here and written by a thread (the worker reads it when its import
        is done; this process goes on with the tables). False if the results cannot be
        pickled or the worker is gone: the caller then forks its workers itself."""
        import pickle
        import threading

        if not self.process.is_alive():
            return False
        try:
            blob = pickle.dumps(job, protocol=pickle.HIGHEST_PROTOCOL)
        except (pickle.PicklingError, TypeError, AttributeError):
            return False

        def write() -> None:
            try:
                self.writer.send_bytes(blob)
            except OSError:               # the worker is gone: PlotJob sees its exit code
                pass
            finally:
                self.writer.close()

        self.sender = threading.Thread(target=write, name="flywheel-plot-job", daemon=True)
        self.sender.start()
        return True

    def end(self) -> None:
        """Stop the worker (it draws nothing yet, or is no longer wanted) and wait for it."""
        if self.sender is None:
            self.writer.close()
        if self.process.is_alive():
            self.process.terminate()
        self.process.join()


_EARLY: Early | None = None


def start(argv: list[str], target) -> None:
    """Start the first plot worker if ``argv`` is a run that draws figures (:func:`wanted`):
    ``target(reader, writer, counter, done, parent)`` in a forked process
    (render/plot_wait.py ``wait_and_draw``)."""
    global _EARLY
    if _EARLY is None and wanted(argv):
        try:
            _EARLY = Early(target)
        except OSError:             # no process to spare (EAGAIN, ENOMEM, no /dev/shm): the
            _EARLY = None           # run forks its workers later, or draws them itself


def claim() -> Early | None:
    """The started worker, now the caller's (a :class:`~flywheel.render.plots.PlotJob`), or
    None."""
    global _EARLY
    early, _EARLY = _EARLY, None
    return early


def release() -> None:
    """End a started worker nobody claimed (the run ended without figures)."""
    early = claim()
    if early is not None:
        early.end()


def start_held(processes, signals=None) -> None:
    """Start ``processes`` (forked) with ``signals`` (default: SIGINT and SIGTERM) held back
    until every one is started, then delivered here. No Ctrl-C or SIGTERM handler may run
    inside fork(): Python ignores an exception raised in its after-fork hooks, and the signal
    would be lost (the run then ends 0, not 130/143)."""
    import signal

    held = signal.pthread_sigmask(signal.SIG_BLOCK, signals or {signal.SIGINT, signal.SIGTERM})
    try:
        for process in processes:
            process.start()
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, held)


def worker_signals(parent: int | None) -> None:
    """A plotting process's signals: Ctrl-C ignored (its parent stops it), SIGTERM ends it, and
    it dies with ``parent`` (Linux: PR_SET_PDEATHSIG; gone already: it ends now). Its garbage
    collector is the interpreter's default again (cli/__init__.py GC_THRESHOLDS): a figure
    dropped after saving is garbage of cycles, freed figure by figure."""
    import gc
    import signal

    gc.set_threshold(700, 10, 10)         # the interpreter's default

    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGINT, signal.SIGTERM})  # held at fork
    try:
        import ctypes

        ctypes.CDLL(None, use_errno=True).prctl(1, signal.SIGKILL)   # 1 = PR_SET_PDEATHSIG
    except (OSError, AttributeError):
        pass                              # not Linux: the parent still terminates it
    if parent is not None and os.getppid() != parent:
        os._exit(1)                       # the parent died before the line above
