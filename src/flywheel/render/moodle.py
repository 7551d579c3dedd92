"""The variants as a Moodle XML question bank (``flywheel variants … --moodle quiz.xml``,
issue 27, step 6): one category per variant, one numerical question per answer, with its
unit, its tolerance and, as the general feedback shown after the attempt, the course's formula
it is computed by. The structure is Moodle's documented "Moodle XML format"
(docs.moodle.org, Moodle XML format: ``<quiz>``, ``<question type="category">``,
``<question type="numerical">`` with ``name``, ``questiontext``, ``answer fraction="100"``
holding ``text`` and ``tolerance``, ``units``); a numerical answer's tolerance is absolute,
so the key's relative one is written as tolerance·|value| (a table's cell, one question
each: tolerance·max(|value|, its column's floor), as ``flywheel grade`` judges it). Each question's text starts with
the tag ``[flywheel VARIANT ANSWER]`` (teaching/moodle.py) by which ``flywheel grade`` reads
the quiz's Responses export. Formatting only."""
from __future__ import annotations

from xml.sax.saxutils import escape

from html import escape as html_escape

from flywheel.render.catalogue import words
from flywheel.render.mathfmt import sub_html
from flywheel.teaching.moodle import tag
from flywheel.teaching.tables import cell_floors

T = words("moodle", {
    "category": "Variant {variant}",
    "question": "Variant {variant}. Determine {what}{symbol}{unit} (accepted within ±{pct} %). "
                "The data are those of your variant's task sheet.",
    "how": "How it is computed: {formula}",
})


def _unit_and_words(answer: str, kind: str, lang: str, at_deg: tuple = (),
                    loads: tuple = ({}, {})) -> tuple[str, str, str, str]:
    """(what, symbol, unit as the sheet prints it, SI unit symbol for Moodle's units); a report
    angle's quantity at its angle of ``at_deg`` (the variant's), a load by its title or label
    of ``loads`` (the variant's)."""
    from flywheel.render.nomenclature import unit_of
    from flywheel.render.sheet_labels import answer_words

    what, sym, u = answer_words(kind, answer, lang, at_deg, loads)
    try:
        si = unit_of(answer.rsplit(".", 1)[-1], "en")
    except KeyError:
        si = answer_words(kind, answer, "en")[2]     # a reaction's cell: its term's unit
    return what, sym, u, "" if si in ("–", "-") else si


def _text(s: str) -> str:
    return f"<text>{escape(s)}</text>"


def quiz_xml(vs, lang: str = "en") -> str:
    """The question bank of a VariantSet as Moodle XML text."""
    from flywheel.render.grading import formulas

    t = vs.template
    w = T[lang]
    said = formulas(t.kind, lang)
    out = ['<?xml version="1.0" encoding="UTF-8"?>', "<quiz>"]
    top = f"$course$/top/flywheel/{t.name}"
    for v in vs.variants:
        out += ['  <question type="category">',
                f"    <category>{_text(top + '/' + w['category'].format(variant=v.id))}"
                "</category>", "  </question>"]
        floors = cell_floors(t.tables, v.answers) if t.tables else {}
        for a in t.keyed:
            value = v.answers[a]
            rel = t.tolerance_of(a)
            what, sym, unit, si = _unit_and_words(a, t.kind, lang, v.at_deg, v.loads)
            pct = f"{100 * rel:g}".replace(".", "," if lang == "ru" else ".")
            # the question's HTML: the symbol's subscript in <sub> (M<sub>Д</sub>, as the task
            # sheet sets it), the rest escaped; the tag as it is, for grade to read back
            text = (html_escape(tag(v.id, a)) + " " + html_escape(w["question"]).format(
                variant=html_escape(v.id), what=html_escape(what),
                symbol=f" {sub_html(sym)}" if sym else "",
                unit=f", {html_escape(unit)}" if unit else "", pct=pct))
            # shown after the attempt: the formula of the course it is computed by, where the
            # chain has one (render/grading.py)
            general = sub_html(w["how"].format(formula=said[a])) if a in said else ""
            # a table's cell: judged against its column's scale too (teaching/tables.py)
            scale = max(abs(value), floors.get(a, 0.0))
            absolute = rel * scale if scale else rel
            out += [
                '  <question type="numerical">',
                f"    <name>{_text(f'{v.id} {a}')}</name>",
                f'    <questiontext format="html">{_text(text)}</questiontext>',
                f'    <generalfeedback format="html">{_text(general)}</generalfeedback>',
                "    <defaultgrade>1</defaultgrade>",
                "    <penalty>0</penalty>",
                "    <hidden>0</hidden>",
                f"    <idnumber>{escape(f'{v.id}-{a}')}</idnumber>",
                '    <answer fraction="100" format="moodle_auto_format">',
                f"      <text>{value!r}</text>",
                f"      <tolerance>{absolute!r}</tolerance>",
                '      <feedback format="html"><text></text></feedback>',
                "    </answer>",
                "    <unitgradingtype>0</unitgradingtype>",
                "    <unitpenalty>0</unitpenalty>",
                "    <showunits>3</showunits>",
                "    <unitsleft>0</unitsleft>",
            ]
            if si:
                out += ["    <units>", "      <unit>", "        <multiplier>1</multiplier>",
                        f"        <unit_name>{escape(si)}</unit_name>", "      </unit>",
                        "    </units>"]
            out.append("  </question>")
    out.append("</quiz>")
    return "\n".join(out) + "\n"
