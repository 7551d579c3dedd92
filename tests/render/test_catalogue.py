"""The Russian catalogue (src/flywheel/locale/ru/LC_MESSAGES/flywheel.po; tools/i18n.py): every
entry translated and none fuzzy, the committed .mo the compiled .po, the fields of each Russian
template ones its Notice gives (or render/message_params.py derives), the English msgid the text
the code raises, Russian plural forms chosen by the number, and no English word left in a
Russian sentence that the English one did not have as a name (a key, an option, a symbol)."""
from __future__ import annotations

import ast
import re
import string
import sys
from pathlib import Path

import pytest

pytest.importorskip("babel")

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tools"))
import i18n  # noqa: E402

from flywheel.render import message_params, messages  # noqa: E402
from helpers import source_nodes  # noqa: E402

PO = i18n.read_po()
ENTRIES = [m for m in PO if m.id]


def _fields(text: str) -> set[str]:
    """The names a template fills ("{J:.3g}" → "J", "{name!r}" → "name")."""
    return {re.split(r"[.\[]", f)[0] for _, f, _, _ in string.Formatter().parse(text) if f}


def test_every_entry_is_translated_and_none_is_fuzzy():
    assert len(ENTRIES) > 400
    assert i18n.problems(PO) == []


def test_the_committed_mo_is_the_compiled_po():
    assert i18n.MO.read_bytes() == i18n.mo_bytes(PO), "run `python tools/i18n.py compile`"


def test_the_po_is_what_update_makes_of_it():
    """Every Notice the code raises is in the .po with the English it is raised with (its
    msgid, where it is raised, its parameters); no entry of a code no longer raised."""
    updated = i18n.update(i18n.read_po())
    def said(m):          # (a long comment is wrapped in the .po)
        return m.string, sorted(m.locations), " ".join(m.auto_comments), m.fuzzy

    now = {(m.context, m.id): said(m) for m in ENTRIES}
    then = {(m.context, m.id): said(m) for m in updated if m.id}
    assert now == then, "run `python tools/i18n.py update`, translate, compile"


@pytest.mark.parametrize("n,form", [(1, 0), (21, 0), (101, 0), (2, 1), (4, 1), (23, 1), (104, 1),
                                    (0, 2), (5, 2), (11, 2), (12, 2), (14, 2), (19, 2), (111, 2),
                                    (112, 2), (25, 2)])
def test_russian_plural_forms(n, form):
    """Russian grammar: 1, 21, 101 take the first form; 2–4, 22–24 the second; 0, 5–20, 11–14
    after any hundreds and 25–30 the third (Розенталь, «Справочник по правописанию», § 142)."""
    forms = ("{n} цикл", "{n} цикла", "{n} циклов")
    assert messages.plural("count", "{n} cycle", "{n} cycles", n, "ru") == forms[form]
    assert messages.plural("count", "{n} cycle", "{n} cycles", n, "en") == (
        "{n} cycle" if n == 1 else "{n} cycles")


def _raise_sites():
    """(file, code, keyword names) of every Notice(text, "code", …) in the package."""
    for path in i18n.PACKAGE.rglob("*.py"):
        for node in source_nodes(path):
            if not isinstance(node, ast.Call) or len(node.args) < 2:
                continue
            code = (node.args[0] if ast.unparse(node.func) == "Notice.of" else node.args[1]
                    if getattr(node.func, "id", None) == "Notice" else None)
            if isinstance(code, ast.Constant):
                yield path.name, code.value, {k.arg for k in node.keywords}


def test_each_russian_template_takes_only_fields_its_notice_gives():
    russian = {m.context: m.string for m in ENTRIES if i18n.is_notice(m.context)}
    for file, code, keys in _raise_sites():
        assert code in russian, (file, code, "not in the catalogue")
        extra = _fields(russian[code]) - keys - message_params.DERIVED
        assert not extra, (file, code, extra)


# Latin words a Russian sentence may hold that its English has not: names of the program, of
# formats and of methods
LATIN_OK = {"flywheel", "TOML", "UTF", "CSV", "JSON", "SI", "LSODA", "solve_ivp", "cp1251",
            "cp866", "koi8", "uXXXX", "escape", "SIGTERM", "Ctrl", "true", "false", "debug",
            "RRP", "RRR", "RPR"}   # the Assur groups as the case file names them


def test_no_english_is_left_in_a_russian_sentence():
    """Every Latin word of a Russian entry (its fields aside) is one its English has too (a key
    of the case file, an option, a symbol, a value the user writes), a name with an underscore
    (a key, a symbol: M_amplitude, J_I) or a name of LATIN_OK."""
    left = []
    for m in ENTRIES:
        ids = m.id if isinstance(m.id, tuple) else (m.id,)
        forms = m.string if isinstance(m.string, tuple) else (m.string,)
        english = set(re.findall(r"[A-Za-z_][A-Za-z_0-9]*", " ".join(ids)))
        for text in forms:
            bare = re.sub(r"\{[^{}]*\}", " ", text)
            for word in re.findall(r"[A-Za-z_][A-Za-z_0-9]*", bare):
                if (len(word) > 2 and "_" not in word and word not in english
                        and word not in LATIN_OK):
                    left.append((m.context, word))
    assert not left, left


def test_a_russian_sentence_is_russian():
    """Each Russian template of an English sentence has Cyrillic words (not the English
    copied)."""
    for m in ENTRIES:
        if i18n.is_notice(m.context) and re.search("[a-z]{3,}", re.sub(r"\{[^{}]*\}", "", m.id)):
            assert re.search("[а-яё]{3,}", m.string, re.I), (m.context, m.string)


def _flat(d: dict, prefix: str = "") -> dict[str, str]:
    out = {}
    for k, v in d.items():
        if isinstance(v, dict):
            out.update(_flat(v, f"{prefix}{k}."))
        elif isinstance(v, str) and v:
            out[f"{prefix}{k}"] = v
    return out


def test_every_sentence_of_a_renderer_is_its_catalogue_entry():
    """Each string a renderer gives ``words(kind, {…})`` is found by tools/i18n.py (msgctxt
    "kind:key", its English the msgid), and the Russian the renderer prints is that entry's
    msgstr in the .po (never its English falling through)."""
    import importlib

    from flywheel.render import catalogue

    render = i18n.PACKAGE / "render"
    for path in sorted(render.rglob("*.py")):          # render/drawings/ too
        if "words(" in path.read_text(encoding="utf-8"):
            parts = path.relative_to(render).with_suffix("").parts
            importlib.import_module(".".join(("flywheel", "render") + parts))
    extracted = i18n.extract_words()
    po = {m.context: m for m in ENTRIES}
    assert "report" in catalogue.WORDS
    seen = set()
    for kind, english in catalogue.WORDS.items():
        russian = _flat(catalogue.words(kind, english)["ru"])
        for key, text in _flat(english).items():
            ctx = f"{kind}:{key}"
            seen.add(ctx)
            assert extracted[ctx]["msgid"] == text, ctx
            assert po[ctx].id == text and russian[key] == po[ctx].string, ctx
    assert seen == set(extracted), set(extracted) ^ seen


def test_update_follows_the_sentences_of_the_renderers():
    """A renderer's sentence whose English changed turns fuzzy (its Russian kept to be checked),
    one no longer said is dropped, a new one comes untranslated; a term stays as it is."""
    po = i18n.new_catalog()
    note = [i18n.WORDS_NOTE + '"report", …)']
    po.add("Sources", "Источники", context="report:sources", auto_comments=note,
           locations=[("src/flywheel/render/document.py", 1)])
    po.add("Gone", "Нет", context="report:gone", auto_comments=note,
           locations=[("src/flywheel/render/document.py", 2)])
    po.add("flywheel material", "материал маховика", context="term:flywheel_material")
    template = i18n.new_catalog()
    template.add("Sources of the method", "", context="report:sources", auto_comments=note,
                 locations=[("src/flywheel/render/document.py", 1)])
    template.add("Figures", "", context="report:figures", auto_comments=note,
                 locations=[("src/flywheel/render/document.py", 3)])
    out = {m.context: m for m in i18n.update(po, template) if m.id}
    assert set(out) == {"report:sources", "report:figures", "term:flywheel_material"}
    assert out["report:sources"].id == "Sources of the method"
    assert out["report:sources"].fuzzy and out["report:sources"].string == "Источники"
    assert out["report:figures"].string == "" and not out["report:figures"].fuzzy
    assert out["term:flywheel_material"].string == "материал маховика"
