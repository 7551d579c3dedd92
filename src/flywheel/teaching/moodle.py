"""Moodle's quiz "Responses" report read as answer sheets (issue 27, step 6).

The question bank of ``flywheel variants … --moodle quiz.xml`` (render/moodle.py) starts
every question's text with a tag ``[flywheel VARIANT ANSWER]``, e.g. ``[flywheel 03
J_required]``. Moodle's Responses report, downloaded as CSV with "Question text" and
"Response" included, has per attempt the columns ``Surname``, ``First name`` (and e-mail,
state, times, grade) and per slot N ``Question N`` (the question's text as plain text) and
``Response N`` (the answer given, ``-`` for none; a number, perhaps followed by its unit).
:func:`native_rows` turns such rows into the rows of a native sheet — ``student, variant,
<answers…>``, the student being "Surname First name" — so that ``flywheel grade`` grades a
Moodle export exactly as the equivalent native sheet (same reader, same limits: 50 MB,
200 000 attempts per run; at most :data:`MAX_SLOTS` questions per attempt).

Computation only: no typer, no rich.
"""
from __future__ import annotations

import re

from flywheel.errors import Notice

#: questions (slots) of one attempt read from a Responses export; an export with more
#: ``Response N`` columns is refused in one problem line
MAX_SLOTS = 1000
TAG = re.compile(r"\[flywheel\s+([^\s\]]+)\s+([^\s\]]+)\]")
_NUMBER = re.compile(r"^\s*([−\-+]?[\d\s\u00a0\u202f.,]*\d(?:[eE][−\-+]?\d+)?)")


def tag(variant: str, answer: str) -> str:
    """The tag that starts a question's text: ``[flywheel 03 J_required]``."""
    return f"[flywheel {variant} {answer}]"


def is_responses(header: list[str]) -> bool:
    """A header of Moodle's Responses report (Surname, First name, Response 1 …)."""
    names = {h.strip().lower() for h in header}
    return "surname" in names and "response 1" in names


def _slots(header: list[str]) -> list[tuple[int, int | None]]:
    """(column of Response N, column of Question N or None) for N = 1, 2, …"""
    lower = [h.strip().lower() for h in header]
    out = []
    n = 1
    while f"response {n}" in lower:
        q = f"question {n}"
        out.append((lower.index(f"response {n}"), lower.index(q) if q in lower else None))
        n += 1
    return out


def number_of(response: str) -> str:
    """The number at the start of a response ("4.65 kg·m²" → "4.65"); "" for none ("-")."""
    r = response.strip()
    if r in ("", "-", "–", "—"):
        return ""
    m = _NUMBER.match(r)
    return m.group(1).strip() if m else r


class NotResponses(Exception):
    """A Responses export that cannot be read as sheets: its message a Notice."""


def native_rows(header: list[str], rows, answers):
    """(native header, rows): Moodle Responses ``rows`` as ``student, variant, <answers…>``
    rows. A row whose slots carry no flywheel tag, or tags of two variants, becomes a row
    with the variant cell saying so (graded as a problem: not in the key)."""
    slots = _slots(header)
    if len(slots) > MAX_SLOTS:
        raise NotResponses(Notice.of(
            "moodle_too_many_slots", "{n} questions per attempt are too many (allowed: at most "
            "{top} Response columns)", n=len(slots), top=MAX_SLOTS))
    if not slots or all(q is None for _, q in slots):
        raise NotResponses(Notice.of(
            "moodle_no_question_text", "a Moodle Responses export without the questions' text "
            "(allowed: download it with \"Question text\" and \"Response\" included, so each "
            "answer is known by its [flywheel VARIANT ANSWER] tag)"))
    lower = [h.strip().lower() for h in header]
    surname, first = lower.index("surname"), lower.index("first name") \
        if "first name" in lower else None
    answers = list(answers)
    out_header = ["student", "variant", *answers]

    def convert():
        for row in rows:
            cells = list(row) + [""] * (len(header) - len(row))
            name = " ".join(c.strip() for c in (cells[surname], cells[first] if first is not
                                                 None else "") if c.strip())
            if not name or name.lower().startswith("overall average"):
                continue                        # the report's own summary rows
            given = dict.fromkeys(answers, "")
            variants = set()
            for r, q in slots:
                m = TAG.search(cells[q]) if q is not None else None
                if m is None:
                    continue
                variants.add(m.group(1))
                if m.group(2) in given:
                    given[m.group(2)] = number_of(cells[r])
            variant = variants.pop() if len(variants) == 1 else (
                "" if not variants else "+".join(sorted(variants)))
            yield [name, variant, *given.values()]

    return out_header, convert()
