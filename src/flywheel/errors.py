"""Errors: computation raises these, the CLI prints one line and exits 2."""


class FlywheelError(Exception):
    """Base of every error a user's input can cause."""


class CaseFileError(FlywheelError, ValueError):
    """A case file cannot be read or does not validate: the message names file and field."""


class AssemblyError(FlywheelError, ValueError):
    """A dyad cannot be assembled at some crank angle."""


class InputError(FlywheelError, ValueError):
    """A command-line value or a combination of inputs is not allowed."""
