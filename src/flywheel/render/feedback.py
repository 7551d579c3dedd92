"""The feedback page of each student (``flywheel grade --feedback DIR``, issue 27): one
self-contained HTML page per graded student, in the teacher's ``--lang``, with each answer,
its verdict («верно по вашим данным» for an error carried forward), the named classic mistake
and the key's value (left out with ``--no-reveal``); a table: one line with its cells right
and the cells off, and each wrong cell on its own line. Formatting only: what is shown is the
grading's (teaching/grading.py, teaching/explain.py)."""
from __future__ import annotations

import html
import re

from flywheel.render.catalogue import words
from flywheel.render.grading import (MISTAKES, cells_off, key_spec, table_verdict, to_check,
                                    verdict_word)
from flywheel.render.numbers import fmt, typography
from flywheel.render.mathfmt import sub_html
from flywheel.render.sheet_labels import answer_words

T = words("feedback", {
    "title": "Feedback: {student}, variant {variant}",
    "score": "Score: {passed} of {total} answers right ({pct})",
    "carried": "{n} answer(s) consistent with your earlier answers (credited {share} each)",
    "answer": "Quantity", "given": "Your answer", "verdict": "Verdict",
    "diagnosis": "What went wrong", "expected": "Expected", "tolerance": "Tolerance",
    "none": "—",
    "note_carried": "«Consistent with your earlier answer»: wrong against the key, but right "
                    "when computed from your own earlier answers — the mistake is further up.",
    "hidden": "The expected values are not shown.",
    "check": "check {formula}",
    "yours": "; from your {symbol} = {given} it is {value}",
})


def _num(x, lang: str, given: bool = False, spec: str | None = None) -> str:
    """A number as the page writes it: the one formatter (render/numbers.py), in Russian its
    Russian policy (a result to four digits, the student's own answer — ``given`` — with its
    digits; decimal comma, true minus, no exponent); ``spec``: an expected value's digits
    (numbers.to_tolerance)."""
    if x is None:
        return "—"
    with typography(lang):
        return fmt(x, 6, spec=spec, zero=None, nonfinite="show", given=given)


def label(answer: str, lang: str, kind: str = "run", at_deg: tuple = (),
          loads: tuple = ({}, {})) -> str:
    """An answer as the task sheet of a ``kind`` case ("run", "task2") asks it
    (render/sheet_labels.py): «name symbol, unit»; an ``at.N.…`` one at its angle of
    ``at_deg``, the variant's report angles, a load by its title or label of ``loads``."""
    what, sym, u = answer_words(kind, answer, lang, at_deg, loads,  # a table's cell: its own
                                asked=False)
    return " ".join(x for x in (what, sym) if x) + (f", {u}" if u else "")


class _Whole:
    """A table's verdict as an answer's (render/grading.py ``verdict_word``)."""

    def __init__(self, passed: bool):
        self.passed = passed
        self.verdict = "pass" if passed else "fail"


def table_title(name: str, phi: dict, lang: str) -> str:
    """A table's title as the task sheet gives it (render/sheet_labels.py)."""
    from flywheel.render.sheet_labels import table_title as title

    return title(name, next(iter(phi.values()), 0.0), lang)


def _pct(x: float, lang: str) -> str:
    return _num(round(100 * x), lang) + " %"


def page(s, lang: str = "en", reveal: bool = True, share: float = 0.0, kind: str = "run",
         at_deg: tuple = (), loads: tuple = ({}, {})) -> str:
    """The HTML page of one graded student (``StudentGrade``) of a key of ``kind`` variants
    (``at_deg``: the student's variant's report angles, where the key keeps them; ``loads``:
    the key's loads' titles and labels)."""
    t = T[lang]
    e = html.escape
    rows = []
    in_table = s.marking.cells
    for j, a in enumerate(s.answers):
        if in_table >> j & 1 and a.passed:
            continue                  # a table's right cell: counted in its table's line
        # a wrong answer no classic mistake explains: the formula to check
        check = to_check(s, j, kind, lang, reveal)
        why = (MISTAKES[lang].get(a.diagnosis, a.diagnosis) if a.diagnosis else
               t["check"].format(formula=check[0]) if check else t["none"])
        if check and check[1]:        # worked from the student's own earlier answer
            symbol, given, value = check[1]
            why += t["yours"].format(symbol=symbol, given=_num(given, lang, given=True),
                                     value=_num(value, lang, spec=key_spec(a)))
        cells = [f"{sub_html(label(a.answer, lang, kind, at_deg, loads))}<br>"
                 f"<small>{e(a.answer)}</small>",
                 _num(a.given, lang, given=True), e(verdict_word(a, lang)), sub_html(why)]
        if reveal:
            cells.append(_num(a.key, lang, spec=key_spec(a)))
        cells.append("±" + _num(100 * a.tolerance, lang, given=True) + " %")
        cls = a.verdict.replace(" ", "-")
        rows.append(f'<tr class="{cls}">' + "".join(f"<td>{c}</td>" for c in cells) + "</tr>")
    for name, right, n, off in s.table_grades:
        cls = "pass" if right == n else "fail"
        cells = [f"{sub_html(table_title(name, s.marking.table_phi[name], lang))}<br><small>{e(name)}"
                 "</small>", e(table_verdict(right, n, lang)),
                 e(verdict_word(_Whole(right == n), lang)), e(cells_off(off, lang, name) or t["none"])]
        cells += [""] if reveal else []
        cells.append("")
        rows.append(f'<tr class="{cls}">' + "".join(f"<td>{c}</td>" for c in cells) + "</tr>")
    head = [t["answer"], t["given"], t["verdict"], t["diagnosis"]]
    head += [t["expected"]] if reveal else []
    head += [t["tolerance"]]
    title = t["title"].format(student=s.student, variant=s.variant)
    notes = [t["score"].format(passed=s.passed, total=s.total, pct=_pct(s.score, lang))]
    if s.carried_count:
        notes.append(t["carried"].format(n=s.carried_count, share=_num(share, lang)))
        notes.append(t["note_carried"])
    if not reveal:
        notes.append(t["hidden"])
    return (
        "<!DOCTYPE html>\n"
        f'<html lang="{lang}">\n<head>\n<meta charset="utf-8">\n<title>{e(title)}</title>\n'
        "<style>body{font-family:sans-serif;margin:2em;max-width:60em}"
        "table{border-collapse:collapse}td,th{border:1px solid #999;padding:.3em .6em}"
        "td:nth-child(2),td:nth-child(5),td:nth-child(6){text-align:right}"
        "tr.pass td:nth-child(3){color:#070}tr.carried td:nth-child(3){color:#a60}"
        "tr.fail td:nth-child(3),tr.no-answer td:nth-child(3){color:#b00}</style>\n"
        f"</head>\n<body>\n<h1>{e(title)}</h1>\n"
        + "".join(f"<p>{e(n)}</p>\n" for n in notes)
        + "<table>\n<tr>" + "".join(f"<th>{e(h)}</th>" for h in head) + "</tr>\n"
        + "\n".join(rows) + "\n</table>\n</body>\n</html>\n")


def file_name(number: int, student: str) -> str:
    """``007_Ivanov.html``: the student's place in the report and a name safe on any system
    (letters, digits, '-', '_'; at most 60 characters)."""
    safe = re.sub(r"[^\w-]+", "_", student, flags=re.UNICODE).strip("_")[:60] or "student"
    return f"{number:03d}_{safe}.html"


def write_feedback(report, folder, lang: str = "en", reveal: bool = True, notes=None):
    """One page per student of ``report`` into ``folder``, written whole or not at all
    (io.output.write_folder: an earlier feedback folder's own files replaced, anything else
    refused)."""
    from pathlib import Path

    from flywheel.io.output import write_folder

    def build(tmp: Path) -> None:
        for i, s in enumerate(report.students, start=1):
            angles = report.key.at_deg.get(report.key.find(s.variant) or "", ())
            (tmp / file_name(i, s.student)).write_text(
                page(s, lang, reveal, report.carried_share, report.key.kind, angles,
                     report.key.loads),
                encoding="utf-8")

    return write_folder(Path(folder), build, "", "feedback", notes)
