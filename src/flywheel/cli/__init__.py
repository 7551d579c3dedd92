"""The command line: thin wrappers that parse options, call the library, hand results to renderers.

Every user mistake becomes one line on stderr and exit code 2 (design.md §6).
"""
from __future__ import annotations

import typer

app = typer.Typer(
    add_completion=False,
    no_args_is_help=True,
    help="Dynamic analysis of machines: kinematics, reduction, flywheel sizing, true motion.",
    pretty_exceptions_enable=False,
)

from flywheel.cli.aggregate import aggregate_command  # noqa: E402
from flywheel.cli.run import check_command, run_command, schema_command  # noqa: E402
from flywheel.cli.task2 import task2_command  # noqa: E402
from flywheel.cli.teaching import grade_command, variants_command  # noqa: E402

app.command("schema")(schema_command)
app.command("check")(check_command)
app.command("run")(run_command)
app.command("task2")(task2_command)
app.command("aggregate")(aggregate_command)
app.command("variants")(variants_command)
app.command("grade")(grade_command)


class Stopped(BaseException):
    """Ctrl-C (SIGINT) or SIGTERM, raised in the main thread so that every ``finally`` and
    ``except BaseException`` on the way out runs (an output folder's temporary is removed).
    Not a KeyboardInterrupt: click would turn that into "Aborted!" and exit 1."""

    def __init__(self, signum: int):
        super().__init__(signum)
        self.signum = signum


def _stop(signum, frame) -> None:
    raise Stopped(signum)


def main() -> None:
    """Console-script entry point: exit 130 on Ctrl-C, 143 on SIGTERM, with one line."""
    import signal
    import sys

    signal.signal(signal.SIGINT, _stop)
    signal.signal(signal.SIGTERM, _stop)
    try:
        app()
    except Stopped as exc:
        signal.signal(signal.SIGINT, signal.SIG_IGN)     # a second Ctrl-C: no traceback
        name = "interrupted (Ctrl-C)" if exc.signum == signal.SIGINT else "terminated (SIGTERM)"
        sys.stderr.write(f"error: {name}\n")
        sys.exit(128 + exc.signum)


if __name__ == "__main__":  # pragma: no cover
    main()
