"""The catalogue of every sentence a person reads (src/flywheel/locale/ru/LC_MESSAGES/flywheel.po,
compiled to flywheel.mo; tools/i18n.py extracts, updates, compiles and checks it), read with the
standard library's gettext. English is the msgid; the msgctxt says what an entry is: a Notice's
code (render/messages.py), "count" (a number and its noun, Russian's three plural forms),
"prefix:<key>", "stage:<key>", "term:<key>" (the nomenclature's labels and sentences that have
no symbol and no unit), "<kind>:<key>" (a renderer's sentences: ``words``).

>>> plural("count", "{n} cycle", "{n} cycles", 22, "ru").format(n=22)
'22 цикла'
>>> entry("prefix:warning"), entry("prefix:warning", "ru")
('warning', 'предупреждение')
"""
from __future__ import annotations

import gettext
from functools import lru_cache
from pathlib import Path

LOCALE = Path(__file__).resolve().parents[1] / "locale"
DOMAIN = "flywheel"


@lru_cache(maxsize=None)
def catalogue(lang: str = "ru") -> gettext.NullTranslations:
    """The compiled catalogue of ``lang`` (gettext; English: the msgids themselves)."""
    if lang == "en":
        return gettext.NullTranslations()
    return gettext.translation(DOMAIN, localedir=str(LOCALE), languages=[lang])


@lru_cache(maxsize=None)
def _english() -> dict[str, str]:
    """msgctxt → msgid of the catalogue's singular entries: the English template of a Notice's
    code, the English label of a "term:"/"prefix:"/"stage:" key (what ``pgettext`` needs)."""
    out = {}
    for key in _mo_msgids(LOCALE / "ru" / "LC_MESSAGES" / f"{DOMAIN}.mo"):
        if "\x04" in key and "\x00" not in key:     # "msgctxt\x04msgid"; plurals: "one\x00many"
            ctx, msgid = key.split("\x04", 1)
            out[ctx] = msgid
    return out


def _mo_msgids(path: Path) -> list[str]:
    """The original strings of a compiled GNU catalogue, in its order (the .mo layout of the GNU
    gettext manual, "The Format of GNU MO Files": a magic number, the revision, the count N, the
    offset of the table of originals; each entry a length and an offset; UTF-8)."""
    import struct

    data = path.read_bytes()
    order = "<" if struct.unpack("<I", data[:4])[0] == 0x950412DE else ">"
    _magic, _revision, n, originals = struct.unpack(order + "4I", data[:16])
    out = []
    for i in range(n):
        length, offset = struct.unpack(order + "II", data[originals + 8 * i: originals + 8 * i + 8])
        out.append(data[offset: offset + length].decode("utf-8"))
    return out


def has(context: str) -> bool:
    """Whether the catalogue has an entry of this msgctxt (a Notice's code, "term:J_I", …)."""
    return context in _english()


def notice_codes() -> set[str]:
    """The codes of the Notices the catalogue says (its msgctxts that are no "kind:key", no
    case field's description and no help text)."""
    return {ctx for ctx in _english() if ":" not in ctx and ctx not in ("field", "help")}


def entry(context: str, lang: str = "en") -> str:
    """The entry of msgctxt ``context`` in ``lang``: its msgid in English, its msgstr else."""
    english = _english()[context]
    return english if lang != "ru" else catalogue("ru").pgettext(context, english)


def plural(context: str, one: str, many: str, n: int, lang: str = "en") -> str:
    """The plural entry ``one``/``many`` in the form ``lang`` gives it after ``n``."""
    return catalogue("ru" if lang == "ru" else "en").npgettext(context, one, many, n)


#: the renderers' sentences: kind → the English dict given to ``words`` (tests/render/test_catalogue.py)
WORDS: dict[str, dict] = {}


def words(kind: str, english: dict) -> dict[str, dict]:
    """A renderer's sentences in both languages, ``{"en": english, "ru": …}``: each string of
    ``english`` (a dict literal; a nested dict's keys joined by ".") is the msgid of msgctxt
    ``"<kind>:<key>"`` (tools/i18n.py extracts the call), its Russian the msgstr.

    >>> from flywheel.render.document import T     # T = words("report", {…, "fig": {"works": …}})
    >>> T["en"]["fig"]["works"], T["ru"]["fig"]["works"]
    ('Works and kinetic energy', 'Работы и кинетическая энергия')
    """
    WORDS.setdefault(kind, english)
    ru = catalogue("ru")

    def said(d: dict, prefix: str) -> dict:
        return {k: said(v, f"{prefix}{k}.") if isinstance(v, dict) else
                ru.pgettext(f"{kind}:{prefix}{k}", v) if isinstance(v, str) and v else v
                for k, v in d.items()}

    return {"en": english, "ru": said(english, "")}


def description(english: str, lang: str = "en") -> str:
    """A case field's description (msgctxt "field", tools/i18n.py extracts them from the schema)
    in ``lang``; English, or a description the catalogue does not have yet, as it is."""
    return english if lang != "ru" or not english else catalogue("ru").pgettext("field", english)


def translated_schema(schema, lang: str = "en"):
    """The JSON Schema with every ``description`` in ``lang`` (`flywheel schema --lang ru`: an
    editor's completion then speaks Russian); the rest as it is."""
    if isinstance(schema, dict):
        return {k: description(v, lang) if k == "description" and isinstance(v, str)
                else translated_schema(v, lang) for k, v in schema.items()}
    if isinstance(schema, list):
        return [translated_schema(v, lang) for v in schema]
    return schema


def compiled_msgstrs(lang: str, prefix: str) -> dict[str, str]:
    """msgctxt → msgstr of the ``lang`` catalogue's entries whose msgctxt starts with ``prefix``
    ("term:"), read from the compiled catalogue directly: what ``catalogue(lang).pgettext(ctx,
    msgid)`` gives (the last entry of a msgctxt, as :func:`_english` keeps), without gettext
    parsing every entry of the file — which an English run never asks for. The .mo layout: the
    GNU gettext manual, "The Format of GNU MO Files" (a magic number, the revision, the count N,
    the offsets of the originals' and the translations' tables; each entry a length and an
    offset; UTF-8)."""
    import struct

    data = (LOCALE / lang / "LC_MESSAGES" / f"{DOMAIN}.mo").read_bytes()
    order = "<" if struct.unpack("<I", data[:4])[0] == 0x950412DE else ">"
    _magic, _revision, n, originals, translations = struct.unpack(order + "5I", data[:20])
    start = prefix.encode("utf-8")
    out = {}
    for i in range(n):
        length, offset = struct.unpack_from(order + "II", data, originals + 8 * i)
        key = data[offset: offset + length]
        if key.startswith(start) and b"\x04" in key and b"\x00" not in key:
            t_length, t_offset = struct.unpack_from(order + "II", data, translations + 8 * i)
            out[key.split(b"\x04", 1)[0].decode("utf-8")] = \
                data[t_offset: t_offset + t_length].decode("utf-8")
    return out
