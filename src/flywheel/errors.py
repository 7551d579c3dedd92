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
    (render/messages.py, ``message``; the Russian templates in the catalogue,
    locale/ru/LC_MESSAGES/flywheel.po, msgctxt = the code).

    >>> w = Notice("δ = 0.5: too much", "delta_swing", delta=0.5)
    >>> w == "δ = 0.5: too much", w.code, w.params
    (True, 'delta_swing', {'delta': 0.5})

    An error's message may be a Notice too (``CaseFileError(Notice(…))``): the CLI's guard then
    says it in the user's ``--lang``. ``lead`` is the language-neutral beginning of the text (the
    file and field path, "cases/c.toml: machine.delta: ") that the translation keeps.
    """

    code: str
    params: dict
    lead: str = ""
    template: str = ""

    def __new__(cls, text: str, code: str = "", **params):
        self = super().__new__(cls, text)
        self.code = code
        self.params = params
        return self

    @classmethod
    def of(cls, code: str, template: str, **params) -> "Notice":
        """The Notice whose English is ``template`` (``str.format`` fields of ``params``): the
        gettext msgid of its entry in the catalogue (msgctxt ``code``), written once, here.

        >>> n = Notice.of("no_such_file", "{path}: no such file", path="c.toml")
        >>> n, n.code, n.params, n.template
        ('c.toml: no such file', 'no_such_file', {'path': 'c.toml'}, '{path}: no such file')
        """
        self = cls(template.format(**params), code, **params)
        self.template = template
        return self


def led(lead: str, text) -> str:
    """``lead + text``, a Notice still (its ``lead`` grown) when ``text`` is one.

    >>> n = led("c.toml: ", Notice("x: missing required field", "missing", where="x"))
    >>> n, n.code, n.lead
    ('c.toml: x: missing required field', 'missing', 'c.toml: ')
    """
    if not getattr(text, "code", ""):
        return lead + str(text)
    out = Notice(lead + str(text), text.code, **text.params)
    out.lead = lead + text.lead
    out.template = text.template
    return out


def said(exc: BaseException) -> str:
    """An exception's message, the Notice itself when it was raised with one."""
    first = exc.args[0] if len(exc.args) == 1 else None
    return first if isinstance(first, Notice) else str(exc)
