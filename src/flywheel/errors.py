"""Errors: computation raises these, the CLI prints one line and exits 2."""


class FlywheelError(Exception):
    """Base of every error a user's input can cause."""


class CaseFileError(FlywheelError, ValueError):
    """A case file cannot be read or does not validate: the message names file and field."""


class AssemblyError(FlywheelError, ValueError):
    """A dyad cannot be assembled at some crank angle."""


class InputError(FlywheelError, ValueError):
    """A command-line value or a combination of inputs is not allowed."""


class Notice(str):
    """A warning or message of the computation: the English text itself (a ``str``, so results,
    summary.json and every English output hold it unchanged), with a ``code`` and the
    ``params`` its text was made from, so that a renderer can say it in another language
    (render/nomenclature.py, ``message``; the Russian templates in MESSAGES).

    >>> w = Notice("δ = 0.5: too much", "delta_swing", delta=0.5)
    >>> w == "δ = 0.5: too much", w.code, w.params
    (True, 'delta_swing', {'delta': 0.5})
    """

    code: str
    params: dict

    def __new__(cls, text: str, code: str = "", **params):
        self = super().__new__(cls, text)
        self.code = code
        self.params = params
        return self
