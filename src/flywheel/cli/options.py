"""The options every command shares, declared once, and the state of the running command.

Each shared option is an ``Annotated`` alias: ``lang: Lang = "en"``; ``as_json: Json = False``.
Their help texts say what the option means in every command; a command's own help (its
docstring) says what it prints. The callbacks record what the command line gave into
:data:`state`, so the error guard says its line in the user's ``--lang`` and ``--quiet`` lets
a command's ``--json`` through without anyone reading ``sys.argv`` or typer's internals:

* ``--lang`` is recorded as soon as the parser reads it (an error raised later, inside the
  command, is said in that language; an error of the parser itself, before the option is read,
  takes the language the entry point found in its own arguments, :func:`lang_of_argv`);
* ``--quiet`` (the root callback) silences stdout and every note and warning; a ``--json``
  of the command restores stdout, since JSON is what the caller asked for.

Lines on stderr other than the error line go through :func:`note` and :func:`warn` (one
place, so ``--quiet`` needs no filter on what was written).
"""
from __future__ import annotations

import re
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Annotated, Optional

import typer
from typer.core import TyperCommand, TyperGroup


@dataclass
class State:
    """What the command line gave, as the parser reads it (one process runs one command)."""

    lang: str = "en"
    argv_lang: str = "en"      # the entry point's own reading of its arguments (lang_of_argv)
    quiet: bool = False
    debug: bool = False
    stdout: object = None      # the real stdout while --quiet has silenced it


state = State()


def lang_of_argv(argv: list[str]) -> str:
    """The ``--lang`` among the entry point's arguments, for an error of the parser itself (the
    option is not parsed yet): "ru" or "en".

    >>> lang_of_argv(["run", "c.toml", "--lang", "ru"]), lang_of_argv(["--lang=ru"])
    ('ru', 'ru')
    >>> lang_of_argv(["run", "--lang"]), lang_of_argv([])
    ('en', 'en')
    """
    for i, a in enumerate(argv):
        if a == "--lang" and i + 1 < len(argv):
            return "ru" if argv[i + 1] == "ru" else "en"
        if a.startswith("--lang="):
            return "ru" if a == "--lang=ru" else "en"
    return "en"


def _lang(value: str) -> str:
    state.lang = "ru" if value == "ru" else "en"
    return value


def _json(value: bool) -> bool:
    if value and state.stdout is not None:       # --quiet --json: the JSON is still printed
        sys.stdout = state.stdout
        state.stdout = None
    return value


def be_quiet() -> None:
    """``--quiet``: stdout silenced (until a ``--json`` asks for it back), notes and warnings
    not written, and Python's own warnings (a library's) ignored."""
    import os
    import warnings

    state.quiet = True
    state.stdout = sys.stdout
    sys.stdout = open(os.devnull, "w", encoding="utf-8")
    warnings.simplefilter("ignore")


def _line(kind: str, text: str) -> None:
    if state.quiet:
        return
    from flywheel.render.nomenclature import message, prefix
    from flywheel.render.numbers import typeset

    sys.stderr.write(f"{prefix(kind, state.lang)}: {typeset(state.lang, message, text, state.lang)}\n")


def note(text: str) -> None:
    """A note on stderr in the user's ``--lang`` («note:» / «примечание:»), not under --quiet."""
    _line("note", text)


def warn(text: str) -> None:
    """A warning on stderr in the user's ``--lang``, not under --quiet."""
    _line("warning", text)


QUIET_HELP = "Print nothing but errors (files are written as usual; --json still prints its JSON)."


def _quiet(value: bool) -> bool:
    if value and not state.quiet:
        be_quiet()
    return value


#: the root's -q/--quiet, taken after a command's name too (`flywheel run c.toml -q`, as one
#: writes it); eager, so that a --json before it still gets its stdout back
Quiet = Annotated[bool, typer.Option("--quiet", "-q", callback=_quiet, is_eager=True,
                                     help=QUIET_HELP)]
Lang = Annotated[str, typer.Option(
    "--lang", callback=_lang, metavar="LANG",
    help="Language of what is printed and written (summary, plots, report, error line): "
         "en | ru.")]
Json = Annotated[bool, typer.Option(
    "--json", callback=_json,
    help="Print the results as JSON instead of the summary (the same document in every "
         "language).")]
OutFolder = Annotated[Optional[Path], typer.Option(
    "--out", "-o", metavar="DIR",
    help="Also write an output folder: summary.json (as --json), the plots and the report "
         "(see --report); a rerun replaces only its own files.")]
Reports = Annotated[Optional[list[str]], typer.Option(
    "--report", metavar="FORMAT", help="Report format: md, html, pdf, docx; repeatable (default: md and html).")]
CsvStyle = Annotated[str, typer.Option(
    "--csv", metavar="DIALECT", help="CSV dialect: plain, or excel-ru (';', decimal commas, BOM: opens in a "
                  "Russian Excel).")]
Student = Annotated[Optional[str], typer.Option(
    "--student", metavar="NAME", help="The student on the title page of a Russian PDF or DOCX report (over the "
                      "case's \\[document] student).")]
Group = Annotated[Optional[str], typer.Option(
    "--group", metavar="GROUP", help="The student's group on the title page (over \\[document] group).")]
Frame = Annotated[str, typer.Option(
    "--frame", metavar="FRAME", help="Page frame of the Russian PDF and DOCX report: none, or eskd (every page "
                    "but the title page inside the ЕСКД frame, the title block of form 2 on "
                    "the contents page and 2a on the rest, ГОСТ 2.104; filled from "
                    "\\[document]); needs --lang ru and --report pdf or docx.")]


Teacher = Annotated[Optional[str], typer.Option(
    "--teacher", metavar="NAME", help="The teacher on the title page (over \\[document] teacher).")]
CaseFile = Annotated[Path, typer.Argument(metavar="CASE", help="Case file (TOML).")]


def title_page(student: str | None, group: str | None, teacher: str | None) -> dict:
    """--student, --group and --teacher as the title page takes them over the case's
    ``[document]`` (render.blocks.front, as `run` merges them): None keeps the case's; each at
    most MAX_TEXT characters, else an InputError (one line)."""
    from flywheel.errors import InputError, Notice
    from flywheel.io.schema import MAX_TEXT

    given = {"student": student, "group": group, "teacher": teacher}
    for option, value in given.items():
        if value is not None and len(value) > MAX_TEXT:
            raise InputError(Notice.of(
                "option_text_too_long", "--{option}: {length} characters (allowed: at most "
                "{most})", option=option, length=len(value), most=MAX_TEXT))
    return given


def _no_type(ctx=None) -> None:
    """An argument's type column: empty (its metavar, CASE or KEY, says what it is)."""
    return None


#: msgctxt of a help text in the catalogue (msgid: the English help, its lines joined)
HELP_CONTEXT = "help"
_HELP_LANG = "flywheel.help_lang"      # ctx.meta: the language of the help page being printed
_RESTORE = "flywheel.help_restore"     # ctx.meta: (object, attribute, English) put back after it


def help_msgid(text: str | None) -> str:
    """The catalogue's msgid of a help text: dedented, each paragraph's lines joined by one
    space (as typer shows a paragraph).

    >>> help_msgid("Run the whole analysis;\\n    write summary.json.")
    'Run the whole analysis; write summary.json.'
    """
    import inspect

    paragraphs = inspect.cleandoc(text or "").split("\n\n")
    return "\n\n".join(" ".join(line.strip() for line in p.splitlines()) for p in paragraphs)


def _typer_words() -> dict[str, dict]:
    """typer's own words on a help page, in both languages (render/help_page.py)."""
    from flywheel.render.help_page import TYPER_WORDS

    return TYPER_WORDS


def _translated(obj, attribute: str, ctx) -> None:
    """``obj.attribute`` (a help text) in Russian for the page being printed, its English
    recorded to be put back; a text the catalogue lacks stays as it is."""
    from flywheel.render.catalogue import catalogue

    english = getattr(obj, attribute, None)
    if not english:
        return
    msgid = help_msgid(english)
    russian = catalogue("ru").pgettext(HELP_CONTEXT, msgid)
    if russian != msgid:
        ctx.meta[_RESTORE].append((obj, attribute, english))
        setattr(obj, attribute, russian)


class _UserWords:
    """A help page in the user's words, not typer's (0.29 shows each option's Python type:
    ``<bool>``, ``<list[float]>``, ``<path>``, and a required argument as ``{case}``): a flag
    shows no value (it takes none), an option its metavar (DIR, DEG, PHI_DEG:RPM: given where it is
    declared), an argument its metavar alone, and the usage line ``run [OPTIONS] CASE``.

    With ``--lang ru`` among the arguments the page is in Russian: each help text (msgctxt
    "help", msgid :func:`help_msgid` of the English) and typer's words (:func:`_typer_words`)
    from the catalogue, set while the page is formatted and put back after it (the English
    page is typer's own, untouched). A help text's paragraphs have their lines joined
    (:func:`help_msgid`): typer's rich help would keep a docstring's line breaks in the root's
    list of commands."""

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        if self.help:
            self.help = help_msgid(self.help)

    def parse_args(self, ctx, args):
        ctx.meta.setdefault(_HELP_LANG, lang_of_argv(list(args)))
        if isinstance(self, TyperGroup) and "--help" in args and "--lang" in args:
            i = args.index("--lang")            # `flywheel --help --lang ru`: the root has no
            if i + 1 < len(args) and not any(a in getattr(self, "commands", {})
                                             for a in args[:i]):
                args = args[:i] + args[i + 2:]   # --lang; its help is the page's language
        return super().parse_args(ctx, args)

    def _russian(self, ctx) -> bool:
        lang = ctx.meta.get(_HELP_LANG)
        return (lang if lang is not None else state.argv_lang) == "ru"

    def get_params(self, ctx):
        params = super().get_params(ctx)
        for p in params:
            if getattr(p, "is_flag", False) and p.metavar is None:
                p.metavar = ""
            elif p.param_type_name == "argument" and p.metavar is not None:
                p.display_type_rich = _no_type
            if _RESTORE in ctx.meta:
                _translated(p, "help", ctx)
        return params

    def collect_usage_pieces(self, ctx) -> list[str]:
        pieces = [re.sub(r"^\{(.*)\}", r"\1", piece)
                  for piece in super().collect_usage_pieces(ctx)]
        if _RESTORE in ctx.meta:                     # a Russian page: [ПАРАМЕТРЫ], КОМАНДА
            said = _typer_words()
            russian = {said["en"][k]: said["ru"][k] for k in ("options", "command")}
            pieces = [russian.get(piece, piece) for piece in pieces]
        return pieces

    def get_usage(self, ctx) -> str:
        usage = super().get_usage(ctx)
        if _RESTORE not in ctx.meta:
            return usage
        said = _typer_words()
        return re.sub("^" + re.escape(said["en"]["usage"]), said["ru"]["usage"], usage)

    def format_help(self, ctx, formatter) -> None:
        if not self._russian(ctx) or _RESTORE in ctx.meta:
            return super().format_help(ctx, formatter)
        from typer import rich_utils

        said = _typer_words()
        typer_words = {k: getattr(rich_utils, k) for k in said["en"] if k.isupper()}
        ctx.meta[_RESTORE] = []
        try:
            for k in typer_words:
                setattr(rich_utils, k, said["ru"][k])
            _translated(self, "help", ctx)
            for name in getattr(self, "list_commands", lambda ctx: [])(ctx):
                command = self.get_command(ctx, name)
                for attribute in ("short_help", "help"):
                    _translated(command, attribute, ctx)
            return super().format_help(ctx, formatter)
        finally:
            for obj, attribute, english in reversed(ctx.meta.pop(_RESTORE)):
                setattr(obj, attribute, english)
            for k, english in typer_words.items():
                setattr(rich_utils, k, english)


class HelpCommand(_UserWords, TyperCommand):
    """Every command's class (cli/commands.py): its help page in the user's words."""


class HelpGroup(_UserWords, TyperGroup):
    """The root's class: its help page in the user's words."""
