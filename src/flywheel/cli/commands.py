"""The command line's application: typer's app, its root options and its commands (the
commands' own modules: cli/run.py, cli/task2.py, …). Imported by cli/__init__.py ``main``
after the first plot worker is started (render/plot_start.py), and as ``flywheel.cli.app``.
"""
from __future__ import annotations

import typer

from flywheel.cli.options import HelpCommand, HelpGroup

app = typer.Typer(
    cls=HelpGroup,
    add_completion=True,
    no_args_is_help=True,
    help="Dynamic analysis of machines: kinematics, reduction, flywheel sizing, true motion.",
    pretty_exceptions_enable=False,
)


from flywheel.cli.options import QUIET_HELP, be_quiet, state  # noqa: E402


def _version(value: bool) -> None:
    if value:
        from flywheel import __version__

        typer.echo(f"flywheel {__version__}")
        raise typer.Exit()


@app.callback()
def _root(
    version: bool = typer.Option(False, "--version", is_eager=True, callback=_version,
                                 help="Print the version and exit."),
    debug: bool = typer.Option(False, "--debug", help="On an internal error (a bug), print "
                               "the Python traceback too."),
    quiet: bool = typer.Option(False, "--quiet", "-q", help=QUIET_HELP),
) -> None:
    """Dynamic analysis of machines: kinematics, reduction, flywheel sizing, true motion."""
    state.lang, state.quiet, state.debug, state.stdout = state.argv_lang, False, debug, None
    if quiet:
        be_quiet()


from flywheel.cli.aggregate import aggregate_command  # noqa: E402
from flywheel.cli.drawings import drawings_command  # noqa: E402
from flywheel.cli.duty_cycle import duty_cycle_command  # noqa: E402
from flywheel.cli.new import new_command  # noqa: E402
from flywheel.cli.run import check_command, run_command, schema_command  # noqa: E402
from flywheel.cli.task2 import task2_command  # noqa: E402
from flywheel.cli.teaching import grade_command, variants_command  # noqa: E402

app.command("schema", cls=HelpCommand)(schema_command)
app.command("check", cls=HelpCommand)(check_command)
app.command("run", cls=HelpCommand)(run_command)
app.command("drawings", cls=HelpCommand)(drawings_command)
app.command("task2", cls=HelpCommand)(task2_command)
app.command("aggregate", cls=HelpCommand)(aggregate_command)
app.command("duty-cycle", cls=HelpCommand)(duty_cycle_command)
app.command("variants", cls=HelpCommand)(variants_command)
app.command("grade", cls=HelpCommand)(grade_command)
app.command("new", cls=HelpCommand)(new_command)
