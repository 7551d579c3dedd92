"""Every sentence a person reads, in the user's language: the catalogue
(src/flywheel/locale/ru/LC_MESSAGES/flywheel.po, compiled to flywheel.mo; tools/i18n.py extracts,
updates, compiles and checks it) read with the standard library's gettext.

English is the msgid: a warning or an error is an errors.Notice (the English text itself, a
code and the parameters it was made from); its Russian form is the catalogue's entry whose
msgctxt is the Notice's code (``pgettext(code, english_template)``), filled from the parameters
with the Russian words render/message_params.py adds. Other entries: a count and its noun
(msgctxt "count", ngettext with Russian's three plural forms), the CLI's line prefixes
("prefix:<key>"), the progress bar's stages ("stage:<key>") and the nomenclature's labels and
sentences that have no symbol and no unit ("term:<key>").

>>> from flywheel.errors import Notice
>>> message(Notice("δ = 0.5: the speed swings by more than 30 % of the mean",
...                "duty_delta_large", delta=0.5), "ru")
'δ = 0.5: скорость колеблется больше чем на 30 % от средней'
"""
from __future__ import annotations

from flywheel.render.catalogue import (_english, catalogue, entry, has,  # noqa: F401
                                       notice_codes, plural, words)
from flywheel.io.text import Text
from flywheel.render.message_params import russian_params
from flywheel.render.numbers import typeset_params


#: the words of a Notice's lead (the place it names)
_LEAD = words("message_lead", {"top_level": ": (top level): "})


def message(text: str, lang: str = "en") -> str:
    """A warning, note or error in ``lang``: a Notice (errors.Notice) whose code the catalogue
    has is said in Russian (a parameter given in two languages, an io.text.Text such as a
    cylinder's label, in its Russian), anything else (English, or a plain string) as it is."""
    code = getattr(text, "code", "")
    if lang != "ru" or not code or not has(code):
        return str(text)
    lead = getattr(text, "lead", "").replace(_LEAD["en"]["top_level"], _LEAD["ru"]["top_level"])
    english = getattr(text, "template", "") or _english()[code]    # Notice.of gives its msgid
    russian = catalogue("ru").pgettext(code, english)
    if russian == english:                          # an English changed, not yet in the .po
        russian = entry(code, "ru")
    # a parameter given in two languages (a cylinder's label) in its Russian
    params = {k: v.ru if isinstance(v, Text) else v for k, v in text.params.items()}
    return lead + russian.format(**typeset_params(russian_params(code, params, message)))


def prefix(key: str, lang: str = "en") -> str:
    """A CLI line prefix ("warning", "note", "written", "error") in ``lang``."""
    return entry(f"prefix:{key}", lang)


def stage_name(stage: str, lang: str = "en") -> str:
    """A progress bar's stage ("start-up") in ``lang``; an unknown stage as it is."""
    return entry(f"stage:{stage}", lang) if has(f"stage:{stage}") else stage
