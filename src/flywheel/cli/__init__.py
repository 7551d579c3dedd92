"""The command line: thin wrappers that parse options, call the library, hand results to renderers.

Every user mistake becomes one line on stderr and exit code 2 (design.md §6).
"""
from __future__ import annotations

import os

# pydantic looks up its plugins (the entry points of every installed distribution, ≈ 12 ms)
# when typer builds its first parameter; a command line has none to use (one set by the user
# is kept)
os.environ.setdefault("PYDANTIC_DISABLE_PLUGINS", "__all__")
# numpy's BLAS (OpenBLAS) starts a thread per processor at import, and they spin after each
# product: a command's products are small (a 3 600-point grid), the spinning takes a core from
# the plot workers (a run with every figure: 3 – 5 % of its time, its CPU 5 %); the same
# numbers (one user's setting is kept)
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")


def __getattr__(name: str):
    """``flywheel.cli.app``: typer's application (cli/commands.py), imported when first asked
    for: the console entry point starts the first plot worker before it (``main``)."""
    if name == "app":
        from flywheel.cli.commands import app

        globals()["app"] = app
        return app
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


class Stopped(BaseException):
    """Ctrl-C (SIGINT) or SIGTERM, raised in the main thread so that every ``finally`` and
    ``except BaseException`` on the way out runs (an output folder's temporary is removed).
    Not a KeyboardInterrupt: click would turn that into "Aborted!" and exit 1."""

    def __init__(self, signum: int):
        super().__init__(signum)
        self.signum = signum


def _stop(signum, frame) -> None:
    raise Stopped(signum)


def _stop_line(signum: int) -> None:
    """The one line of an interruption (Ctrl-C) or a termination (SIGTERM)."""
    import signal

    from flywheel.cli.guard import say_error
    from flywheel.errors import Notice

    say_error(Notice.of("stopped_interrupted", "interrupted (Ctrl-C)") if signum == signal.SIGINT
              else Notice.of("stopped_terminated", "terminated (SIGTERM)"))


def _stopped(exc: Stopped) -> None:
    """One line and exit 130 (Ctrl-C) or 143 (SIGTERM)."""
    import signal
    import sys

    signal.signal(signal.SIGINT, signal.SIG_IGN)     # a second Ctrl-C or a SIGTERM now: the
    signal.signal(signal.SIGTERM, signal.SIG_IGN)    # line is said once, no traceback
    _Late.said = True
    _stop_line(exc.signum)
    sys.exit(128 + exc.signum)


class _Late:
    """A SIGTERM after the command is over (its outputs whole, or none), while Python exits
    (atexit: the plot workers joined): too late to stop anything, still one line and exit
    143 (not a silent death by the signal, exit −15)."""

    said = False            # the interruption's line is said already: nothing more to say

    @staticmethod
    def terminated(signum, frame) -> None:
        import os
        import sys

        try:
            _stop_line(signum)
            for stream in (sys.stdout, sys.stderr):
                stream.flush()
        except Exception:                     # a stream busy or closed: the exit code tells
            pass
        os._exit(128 + signum)


def _stop_in_chain(exc: BaseException) -> Stopped | None:
    """The Stopped an exception was raised while handling (a library's ``finally`` or
    ``except`` that failed on the way out of a Ctrl-C: matplotlib's "Invalid bounding box" when
    a sheet's figure was interrupted), if any."""
    seen = set()
    while exc is not None and id(exc) not in seen:
        if isinstance(exc, Stopped):
            return exc
        seen.add(id(exc))
        exc = exc.__cause__ or exc.__context__
    return None


def _is_usage_error(exc: Exception) -> bool:
    """A command-line usage error of the parser (an unknown option, a value of the wrong
    type, a missing argument): typer's vendored click raises these with exit code 2."""
    return any(c.__name__ == "UsageError" for c in type(exc).__mro__) and \
        getattr(exc, "exit_code", None) == 2


#: the garbage collector's thresholds for a command (gc.set_threshold): a command's objects —
#: the modules', the case's, the results' arrays — live to its end, and the interpreter's
#: default (a collection per 700 new objects: ≈ 150 in a `run`, one of them of everything)
#: spends 60 – 120 ms finding nothing; the collector still runs every 200 000 (mypy's
#: setting). The plot workers go back to the default (render/plots.py): their figures are
#: the garbage.
GC_THRESHOLDS = (200_000, 30, 30)


def _app():
    """typer's application: this module's ``app`` (cli/commands.py's, or one a test put
    here)."""
    return globals()["app"] if "app" in globals() else __getattr__("app")


def main() -> None:
    """Console-script entry point: exit 130 on Ctrl-C, 143 on SIGTERM, with one line."""
    import gc
    import signal
    import sys

    gc.set_threshold(*GC_THRESHOLDS)
    from flywheel.render import plot_start, plot_wait

    # a run's first plot worker, started before the imports below
    plot_start.start(sys.argv[1:], plot_wait.wait_and_draw)
    signal.signal(signal.SIGINT, _stop)
    signal.signal(signal.SIGTERM, _stop)
    try:
        from flywheel.cli.options import lang_of_argv, state

        state.lang = state.argv_lang = lang_of_argv(sys.argv[1:])  # an error of the parser
        code = _app()(standalone_mode=False)
        if isinstance(code, int) and code:
            sys.exit(code)
    except BrokenPipeError:                   # `flywheel grade … | head`: quiet
        import os

        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        sys.exit(141)
    except Stopped as exc:
        _stopped(exc)
    except Exception as exc:                  # not the user's input: a bug of flywheel
        cause = _stop_in_chain(exc)
        if cause is not None:                 # raised by a library's clean-up of the Ctrl-C
            _stopped(cause)
        if _is_usage_error(exc):
            if type(exc).__name__ == "NoArgsIsHelpError":
                sys.exit(0)                   # the help is printed already
            ctx = getattr(exc, "ctx", None)
            from flywheel.cli.guard import lang, say_error
            from flywheel.cli.usage import usage_notice

            where = f"{ctx.command_path}: " if ctx is not None else ""
            see = (f" ({'см.' if lang() == 'ru' else 'see'} {ctx.command_path} --help)"
                   if ctx is not None else "")
            say_error(usage_notice(exc), where, see)
            sys.exit(2)
        from flywheel import __version__
        from flywheel.cli.guard import say_error
        from flywheel.errors import Notice

        from flywheel.cli.options import state

        if state.debug:
            import traceback

            traceback.print_exc()
        what = f"{type(exc).__name__}: {exc}".splitlines()[0][:300]
        text = Notice.of("internal_error", "internal error in flywheel {version} (a bug, not "
                         "your input): {what}; please report it with the command and its input "
                         "files{hint}", version=__version__, what=what, debug=state.debug,
                         hint="" if state.debug else " (--debug shows the traceback)")
        say_error(text)
        sys.exit(1)
    finally:
        plot_start.release()            # not claimed by the run: it drew nothing
        # the command's objects live to its end: the interpreter's exit need not traverse them
        # all in its last collection (0.1 s after a run)
        gc.freeze()
        # the command is over (its outputs whole, or none): a Ctrl-C during the interpreter's
        # exit (atexit: the plot workers joined) is too late to stop anything and would print
        # "Exception ignored in atexit callback" with a traceback: ignored; a SIGTERM is said
        # in one line and exits 143 at once (_Late)
        signal.signal(signal.SIGINT, signal.SIG_IGN)
        if _Late.said:
            signal.signal(signal.SIGTERM, signal.SIG_IGN)
        else:
            import importlib

            importlib.import_module("flywheel.cli.guard")    # now, not in the handler
            signal.signal(signal.SIGTERM, _Late.terminated)


if __name__ == "__main__":  # pragma: no cover
    main()
