"""Rich output of `flywheel variants` and `flywheel grade`, and the gradebook CSV (formatting
only, no computation)."""
from __future__ import annotations

from flywheel.render.catalogue import words
from flywheel.render.numbers import fmt as _number
from flywheel.render.numbers import russian, to_tolerance

# sentence templates of the class summary and the gradebook (the quantities' names are
# answers' keys, which stay as the key spells them; a Russian report names them by their
# symbols: :func:`answer_names`)
TEXT = words("grading", {"summary": "Class summary: {n} graded, mean score {mean}", "dist": "Score distribution",
                         "passed": "answers passed", "students": "students", "wrong": "Most often wrong",
                         "none": "none", "nothing": "Handed in nothing ({n})", "unassigned":
                         "Variants nobody was graded on ({n})", "problems": "{n} problem(s) (skipped or not "
                         "graded); --json lists them", "verdict": "verdict", "error": "error", "score": "score",
                         "total": "total", "pass": "pass", "fail": "FAIL", "no_answer": "no answer",
                         "student": "student", "variant": "variant", "full": "full marks: {k} of {n}",
                         "each": "each", "of": "of",
                         "student_title": "{student} — variant {variant} — {passed}/{total} ({pct})",
                         "answer": "answer", "given": "student's answer", "key": "key", "tolerance": "tolerance",
                         "abs": "abs", "group": "Group: {n} graded, mean score {mean}", "wrong_col": "wrong",
                         "more_students": "… and {n} more students (the whole report: --out REPORT.csv or "
                         "--json)", "by_answer": "By answer",
                         "stats": "mean score {mean}; full marks: {k} of {n}; most often wrong: {worst}",
                         "problem_list": "{n} problem(s)", "problem_note": "(skipped or not graded):",
                         "more_problems": "… and {n} more (all of them: --json)",
                         "v_title": "{n} variant(s) of {name} ({kind}{grid})", "v_run": "flywheel run case",
                         "v_task2": "flywheel task2 case", "v_grid": ", answers on a {n}-interval grid",
                         "v_variant": "variant", "v_drawn": "drawn", "v_answers": "answers (SI)",
                         "v_failed": "{n} draw(s) failed validation or analysis and were drawn again",
                         "v_seed": "seed {seed} (the same seed gives the same files)",
                         "carried": "consistent with your earlier answer", "diagnosis": "diagnosis",
                         "carried_teacher": "consistent with the student's earlier answer",
                         "carried_col": "carried forward",
                         "carried_note": "carried forward: {n} answer(s) consistent with the "
                         "student's earlier ones, credited {share} each",
                         "carried_none": "carried forward: {n} answer(s) consistent with the "
                         "student's earlier ones, not credited (a share: --carried-forward)",
                         "check": "check {formula}",
                         "theirs": "; from the student's {symbol} = {given} it is {value}",
                         "cells": "{right}/{n} cells", "off_row": "row {rows}: {column} off",
                         "off_rows": "rows {rows}: {column} off",
                         "off_pair": "pair {rows}: {column} off",
                         "off_pairs": "pairs {rows}: {column} off"})

#: the names of the classic mistakes of teaching/mistakes.py's catalogue (by code), as the
#: feedback and the gradebook say them
MISTAKES = words("mistake", {
    "rpm_for_rad_s": "rev/min taken for rad/s",
    "rad_s_for_rpm": "rad/s converted again as if rev/min",
    "rps_for_rad_s": "rev/s taken for rad/s",
    "half_delta": "δ/2 used for δ",
    "double_delta": "2δ used for δ",
    "ratio_square_forgotten": "the square of the speed ratio forgotten",
    "local_extremum": "a local extremum of ΔT_I taken for the global one",
    "masses_halved": "the masses' kinetic energy halved (cos 45°)",
    "sign_lost": "a sign lost in the cycle balance",
    "degrees_for_radians": "degrees used for radians",
    "radius_for_diameter": "the radius given for the diameter",
    "first_group_not_subtracted": "J_10 + J_red not subtracted from J_I",
    "g_10": "g = 10 m/s² for 9.81 m/s² (within the tolerance)",
})


#: how an answer of a chain is computed, in the course's notation (seed 000 §4, the task-2
#: seeds), for the feedback page to point a wrong answer that no classic mistake explains at
#: the formula to check: a run case's answers
FORMULAS_RUN = words("formula_run", {
    "balancing_moment": "the cycle condition: A_D + A_C = 0 over the cycle, M = −A(Φ)/Φ",
    "driving_moment": "the cycle condition: A_D + A_C = 0 over the cycle, M_D = −A_C/Φ",
    "cycle_work_resistance": "the cycle condition: A_D + A_C = 0 over the cycle",
    "delta_T_max": "ΔT_max = max ΔT_I − min ΔT_I over the whole cycle, "
                   "ΔT_I = A − (T_II − T_II(0))",
    "J_required": "J_I = ΔT_max/(δ·ω_m²)",
    "J_flywheel": "J_M = J_I − (J_10 + J_red)",
    "flywheel_J_on_its_shaft": "J_M reduced to the flywheel's shaft: J_M/i²",
    # a flywheel's dimensions (dynamics/sizing.py; the course's D = 0.366·J^(1/5) is this
    # for steel and ψ = 0.2): J the flywheel's on its own shaft, ψ = b/D, c = D₁/D
    "flywheel_disk.D": "J = π·ρ·b·D⁴/32 of a solid disk, b = ψ·D, so D = ⁵√(32·J/(π·ρ·ψ))",
    "flywheel_disk.b": "b = ψ·D",
    "flywheel_disk.mass": "m = ρ·π·D²·b/4 = 8·J/D²",
    "flywheel_rim.D": "the rim's share of J = π·ρ·b·(D⁴ − D₁⁴)/32, b = ψ·D, D₁ = c·D",
    "flywheel_rim.D_inner": "D₁ = c·D",
    "flywheel_rim.b": "b = ψ·D",
    "flywheel_rim.mass": "m = ρ·π·(D² − D₁²)·b/4",
})
#: the same of a task-2 case's answers
FORMULAS_TASK2 = words("formula_task2", {
    "M_C": "the cycle condition: ∮M_D dφ = ∮M_C dφ",
    "M_D": "the cycle condition: ∮M_D dφ = ∮M_C dφ",
    "delta_T_max": "ΔT_max = A_max − A_min, A(φ) = ∫(M_D − M_C) dφ",
    "omega_max": "ω_max = √(ω₀² + 2·A_max/J)",
    "omega_min": "ω_min = √(ω₀² + 2·A_min/J)",
    "delta": "δ = ΔT_max/(J·ω_m²)",
    "J_required": "J_req = ΔT_max/([δ]·ω_m²)",
    "rim_mass": "m = J/R²",
})


def formulas(kind: str, lang: str) -> dict[str, str]:
    """The formulas of a ``kind`` ("run", "task2") key's answers in ``lang``, by answer."""
    return (FORMULAS_TASK2 if kind == "task2" else FORMULAS_RUN)[lang]


def answer_names(answers, kind: str = "run", lang: str = "en") -> dict[str, str]:
    """How the tables and lists of `grade` and `variants` name the ``answers`` of a ``kind``
    key ("run", "task2"): in Russian by the symbols the task sheet prints («M_Д», «ΔT_нб»,
    «J_пр»; a table's cell by its column and row, «T_II, положение 4»; a table by its short
    name, «работа и энергия»), where two answers share one symbol (a disk's D and a rim's) by
    the key; in English by the key."""
    from flywheel.render.sheet_labels import TABLE_NAMES, answer_words, cell_name, table_name

    keys = list(answers)
    if lang != "ru":
        return {a: a for a in keys}
    sym = {a: (table_name(a, lang) if a in TABLE_NAMES else cell_name(a, lang)
               or answer_words(kind, a, lang)[1]) for a in keys}
    taken = list(sym.values())
    return {a: sym[a] if sym[a] and taken.count(sym[a]) == 1 else a for a in keys}


def to_check(s, j: int, kind: str, lang: str, reveal: bool = True):
    """What to check in answer ``j`` of a graded student ``s`` (grading.StudentGrade) that is
    wrong and no classic mistake explains: (formula, worked) — the answer's formula in
    ``lang`` (:func:`formulas`) and, with ``reveal``, (symbol, given, value): the student's
    own earlier answer the formula starts from (its symbol as the task sheet prints it, the
    student's value of it) and what the formula gives from it (teaching/explain.py
    ``from_own``), else None. None for an answer right, carried forward, named as a classic
    mistake, or without a formula. Shared by the terminal report and the feedback page."""
    from flywheel.render.sheet_labels import answer_words
    from flywheel.teaching.explain import from_own

    a = s.answers[j]
    said = formulas(kind, lang)
    if a.diagnosis or a.verdict != "fail" or a.answer not in said:
        return None
    own = from_own(s, j) if reveal else None
    if own is None:
        return said[a.answer], None
    value, source = own
    given = s.given[s.marking.names.index(source)]
    return said[a.answer], (answer_words(kind, source, lang)[1] or source, given, value)


def key_spec(a) -> str | None:
    """The digits of an answer's key (an AnswerGrade's) that its tolerance tells apart
    (numbers.to_tolerance; a key of 0, judged absolutely, as it is): the report's «ключ» and a
    feedback page's «ожидалось»."""
    return to_tolerance(a.key, a.tolerance) if a.error_kind == "relative" else None


def _most_often_wrong(r, lang: str, shown: dict | None = None) -> str:
    """The answers of the report ``r`` most often wrong, «J_I, D (2 из 3 каждый)», named as
    :func:`answer_names` names them (``shown``, if at hand); «нет» if none."""
    t = TEXT[lang]
    worst = r.most_often_wrong()
    if worst is None:
        return t["none"]
    shown = shown or answer_names(r.key.answers + tuple(r.key.tables), r.key.kind, lang)
    names, count = worst
    return (f"{', '.join(shown.get(a, a) for a in names)} ({count} {t['of']} {len(r.students)}"
            + (f" {t['each']})" if len(names) > 1 else ")"))


def verdict_word(a, lang: str = "en", to_student: bool = True) -> str:
    """An answer's verdict as the feedback page says it to the student («верно по вашим
    данным») or, ``to_student`` False, as the teacher's gradebook and terminal report say it
    («верно по данным студента»)."""
    t = TEXT[lang]
    carried = t["carried"] if to_student else t["carried_teacher"]
    return {"pass": t["pass"], "carried": carried, "fail": t["fail"],
            "no answer": t["no_answer"]}.get(a.verdict, t["pass"] if a.passed else t["fail"])


def diagnosis_text(s, kind: str = "run", lang: str = "en") -> str:
    """A student's diagnosis (the gradebook's column): each answer named as a classic mistake
    as «answer: mistake», each other wrong answer with a formula as «answer: check …»
    (:func:`check_text`, with the student's own numbers), in the order of the answers; then
    each table's cells off («analogues: rows 3, 7: vq_B off»); carried-forward answers are
    their own verdict. ``kind``: the key's ("run", "task2")."""
    from flywheel.render.numbers import typography

    m = MISTAKES[lang]
    names = s.marking.names
    named = dict(s.diagnoses)
    parts = []
    with typography(lang):
        for j in range(len(names)):
            if j in named:
                parts.append(f"{names[j]}: {m.get(named[j], named[j])}")
            elif (check := to_check(s, j, kind, lang)) is not None:
                parts.append(f"{names[j]}: {check_text(check, s.answers[j], lang)}")
    parts += [f"{name}: {off}" for name, _, _, cells in s.table_grades
              if (off := cells_off(cells, lang, name))]
    return "; ".join(parts)


def cells_off(off, lang: str = "en", table: str = "") -> str:
    """A table's cells off, by column: «rows 3, 7: vq_B off; row 5: vq_C off»; a reaction's
    row as the sheet prints it, «O (0→1)»; in Russian by the sheet's words and column
    symbols: «положения 3, 7: v_q(B) неверно», «пара O (0→1): R неверно»."""
    from flywheel.render.sheet_labels import TABLE_ROWS, column_symbol, row_text

    t = TEXT[lang]
    pair = TABLE_ROWS.get(table) == "joint"
    word = ("off_pair", "off_pairs") if pair else ("off_row", "off_rows")
    return "; ".join(t[word[len(rows) > 1]].format(
        rows=", ".join(row_text(table, r) for r in rows),
        column=column_symbol(table, column, lang) if lang == "ru" else column)
        for column, rows in off)


def table_verdict(right: int, n: int, lang: str = "en") -> str:
    """A table's verdict: the cells right of its cells («70/72 cells»)."""
    return TEXT[lang]["cells"].format(right=right, n=n)


def gradebook_rows(r, lang: str = "en") -> list[list]:
    """The gradebook: one row per student in the order of the sheets — student, variant, per
    answer its verdict and relative (or absolute) error, passed, total, score."""
    return list(_gradebook_rows(r, lang))


def _gradebook_rows(r, lang: str = "en"):
    """The rows of :func:`gradebook_rows`, one at a time."""
    t = TEXT[lang]
    answers = list(r.key.units) or sorted({a.answer for s in r.students for a in s.answers})
    head = [t["student"], t["variant"]]
    for a in answers:
        head += [f"{a} {t['verdict']}", f"{a} {t['error']}"]
    explained = bool(r.key.givens) or bool(r.key.tables)
    yield head + [t["passed"], t["total"], t["score"]] + (
        [t["carried_col"], t["diagnosis"]] if explained else [])
    for s in r.students:
        index, named = s.marking.index, dict(s.diagnoses)
        tables = {name: (right, n) for name, right, n, _ in s.table_grades}
        row = [s.student, s.variant]
        for a in answers:
            if a in tables:                     # a table: its cells right, no one error
                row += [table_verdict(*tables[a], lang), None]
                continue
            j = index.get(a)
            g = None if j is None else s.grade_of(j, named)
            if g is None:
                row += ["", None]
                continue
            row += [verdict_word(g, lang, to_student=False), g.error]
        yield row + [s.passed, s.total, round(s.score, 4)] + (
            [s.carried_count, diagnosis_text(s, r.key.kind, lang)] if explained else [])


def gradebook_csv(r, style: str = "plain", lang: str = "en") -> str:
    """The gradebook as CSV text (``plain`` or ``excel-ru``: see render/csvfmt.py)."""
    return "".join(gradebook_pieces(r, style, lang))


#: gradebook rows formatted per piece of text
ROWS_PER_PIECE = 2000


def gradebook_pieces(r, style: str = "plain", lang: str = "en"):
    """The text of :func:`gradebook_csv` in pieces of ROWS_PER_PIECE rows (a class of 200 000
    is never held whole); the BOM of excel-ru only at the start."""
    from itertools import islice

    from flywheel.render.csvfmt import csv_text

    rows = _gradebook_rows(r, lang)
    first = True
    while chunk := list(islice(rows, ROWS_PER_PIECE)):
        text = csv_text(chunk, style, fmt=lambda x: f"{x:.6g}")
        yield text if first else text.removeprefix("\ufeff")
        first = False


def print_class_summary(r, lang: str = "en", console=None) -> None:
    """Only the class summary: the score distribution, the answers most often wrong, who
    handed in nothing, the variants nobody was graded on, the number of problems."""
    from rich.console import Console
    from rich.table import Table

    t = TEXT[lang]
    console = console or Console()
    mean = "—" if r.mean_score is None else f"{100 * r.mean_score:.0f} %"
    dist = Table(title=t["summary"].format(n=len(r.students), mean=mean), title_justify="left")
    dist.add_column(t["passed"], justify="right")
    dist.add_column(t["students"], justify="right")
    dist.add_column("")
    most = max(r.score_distribution().values(), default=0) or 1
    for k, n in r.score_distribution().items():
        dist.add_row(str(k), str(n), "█" * round(30 * n / most))
    console.print(dist)
    full = sum(s.passed == s.total for s in r.students)
    console.print(t["full"].format(k=full, n=len(r.students)), highlight=False)
    console.print(f"{t['wrong']}: {_most_often_wrong(r, lang)}", highlight=False)
    for key, names in (("nothing", [s.student for s in r.handed_in_nothing]),
                       ("unassigned", r.unassigned_variants())):
        if names:
            console.print(t[key].format(n=len(names)) + ": " + ", ".join(names[:50])
                          + (" …" if len(names) > 50 else ""), highlight=False, markup=False,
                          soft_wrap=True)
    if r.problems:
        console.print(t["problems"].format(n=len(r.problems)), highlight=False)


def _g(x, fmt: str = ".6g", given: bool = False) -> str:
    """A value of the terminal's tables through the one formatter (in Russian, within the
    CLI's ``typeset``: a result to four digits, an input — ``given`` — with its own, whole
    numbers grouped); "—" for none, a text as it is."""
    if x is None:
        return "—"
    if isinstance(x, float) or (isinstance(x, int) and not isinstance(x, bool) and russian()):
        return _number(float(x), spec=fmt, zero=None, nonfinite="show", given=given)
    return str(x)


def _pct_of(share: float) -> str:
    """A tolerance as a percentage («1», «0,5»: Python's ``g`` in English as before)."""
    return _number(100 * share, spec="g", zero=None, nonfinite="show", given=True)


def drawn_line(template, variant, path: str, lang: str = "en") -> str:
    """A value drawn for a variant as `variants` prints it: in English by the case file's path
    («machine.speed_rps = 9», what the teacher edits in the template); in Russian worded as
    the task sheet words it, with its unit («частота вращения кривошипа n_1 = 9 об/с»)."""
    value = variant.drawn[path]
    if lang != "ru":
        return f"{path} = {_g(value, given=True)}"
    from flywheel.cases.describe import unit_of_path
    from flywheel.render.nomenclature import unit
    from flywheel.render.sheet_labels import as_printed, field_kinds, field_label, field_value
    from flywheel.teaching.sheets import element_names

    fw = template.document.get("flywheel")
    ratio = variant.drawn.get("flywheel.speed_ratio",
                              fw.get("speed_ratio", 1) if isinstance(fw, dict) else 1)
    label = field_label(path, lang, element_names(template.document),
                        field_kinds(template.kind, ratio))
    value, si = as_printed(value, unit_of_path(template.kind, path))     # a pressure in MPa
    said = field_value(path, value, lang) if isinstance(value, str) else _g(value, given=True)
    u = unit(si, lang)
    return f"{label} = {said}" + ("" if u in ("", "–") else u if u == "°" else f" {u}")


def print_variants(vs, out, console=None, sheets: str | None = None, lang: str = "en") -> None:
    """The variants drawn and their answers, one row each; ``sheets``: the format of the task
    sheets written (both, html, pdf), None if none; the wording in ``lang``."""
    from rich.console import Console
    from rich.table import Table

    from flywheel.render.messages import message, prefix

    console = console or Console()
    t = vs.template
    w = TEXT[lang]
    kind = w["v_run"] if t.kind == "run" else w["v_task2"]
    grid = w["v_grid"].format(n=vs.n_points) if t.kind == "run" else ""
    table = Table(title=w["v_title"].format(n=len(vs.variants), name=t.name, kind=kind, grid=grid))
    table.add_column(w["v_variant"], no_wrap=True)
    table.add_column(w["v_drawn"], style="cyan")
    table.add_column(w["v_answers"])
    shown = answer_names(t.answers, t.kind, lang)
    for v in vs.variants:
        table.add_row(v.id, "\n".join(drawn_line(t, v, p.path, lang) for p in t.varied),
                      "\n".join(f"{shown[a]} = "
                                f"{_g(v.answers[a], to_tolerance(v.answers[a], t.tolerance_of(a)) or '.6g')}"
                                for a in t.answers))
    console.print(table)
    for x in vs.warnings:
        console.print(f"[yellow]{prefix('warning', lang)}:[/] {message(x, lang)}")
    if vs.failed_draws:
        console.print(w["v_failed"].format(n=vs.failed_draws))
    console.print(w["v_seed"].format(seed=vs.seed), highlight=False, soft_wrap=True)
    written = {None: "", "both": ", sheets/*.html, sheets/*.pdf, sheets.pdf",
               "html": ", sheets/*.html", "pdf": ", sheets/*.pdf, sheets.pdf"}[sheets]
    console.print(f"{prefix('written', lang)}: {out}/ (variant_*.toml, answers.json, answers.csv, students.csv"
                  f"{written})",
                  highlight=False, markup=False, soft_wrap=True)


def check_text(check, a, lang: str = "en") -> str:
    """The teacher's diagnosis of a wrong answer ``a`` no classic mistake explains
    (:func:`to_check`'s ``check``), as the terminal report and the gradebook say it: «проверить
    J_I = ΔT_нб/(δ·ω_ср²); из ΔT_нб = 810,1 студента получается 1,781». Numbers in the
    typography in force (the CLI's ``typeset``)."""
    t = TEXT[lang]
    formula, worked = check
    text = t["check"].format(formula=formula)
    if worked:
        symbol, given, value = worked
        text += t["theirs"].format(symbol=symbol, given=_g(given, given=True),
                                   value=_g(value, key_spec(a) or ".6g"))
    return text


def _pct(x: float | None) -> str:
    return "—" if x is None else _number(100 * x, spec=".0f", zero=None, nonfinite="show") + " %"


DETAIL_STUDENTS = 60      # a class: per student a table of the answers; more: the group table only
GROUP_ROWS = 500          # rows of the group table and problem lines shown on the terminal


def print_report(r, console=None, lang: str = "en") -> None:
    """Per student a table of the answers (for a class of up to DETAIL_STUDENTS); then the
    group table, statistics and problems, each cut at GROUP_ROWS lines with a note where the
    whole report is (--out, --json): the terminal gets a readable page, not megabytes. The
    wording in ``lang`` (the problems too: render/messages.py, the catalogue)."""
    from flywheel.render.messages import message

    from rich.console import Console
    from rich.markup import escape
    from rich.table import Table

    t = TEXT[lang]
    console = console or Console()
    shown = answer_names(r.key.answers + tuple(r.key.tables), r.key.kind, lang)
    for s in (r.students if len(r.students) <= DETAIL_STUDENTS else ()):
        table = Table(title=t["student_title"].format(student=s.student, variant=s.variant,
                                                      passed=s.passed, total=s.total,
                                                      pct=_pct(s.score)), title_justify="left")
        table.add_column(t["answer"])
        table.add_column(t["given"], justify="right")
        table.add_column(t["key"], justify="right")
        table.add_column(t["error"], justify="right")
        table.add_column(t["tolerance"], justify="right")
        table.add_column(t["verdict"])
        # the diagnosis column where there is one to show: a named mistake, a table's cells
        # off, or the formula to check of a wrong answer no classic mistake explains
        checks = {j: c for j in range(len(s.answers)) if (c := to_check(s, j, r.key.kind, lang))}
        explained = any(a.diagnosis for a in s.answers) or any(
            off for *_, off in s.table_grades) or bool(checks)
        if explained:
            table.add_column(t["diagnosis"])
        in_table = s.marking.cells
        for j, a in enumerate(s.answers):
            if in_table >> j & 1 and not a.diagnosis:
                continue                        # a table's cell: in its table's line
            err = "—" if a.error is None else (
                f"{_number(100 * a.error, spec='.3g', zero=None, nonfinite='show')} %"
                if a.error_kind == "relative"
                else f"{_number(a.error, spec='.3g', zero=None, nonfinite='show')} {t['abs']}")
            colour = "green" if a.passed else "yellow" if a.verdict == "carried" else "red"
            mark = f"[{colour}]{verdict_word(a, lang, to_student=False)}[/]"
            key = _g(a.key, key_spec(a) or ".6g")     # the digits its tolerance tells apart
            cells = [shown.get(a.answer, a.answer), _g(a.given, given=True), key, err,
                     f"{_pct_of(a.tolerance)} %", mark]
            if explained:
                cells.append(MISTAKES[lang].get(a.diagnosis, a.diagnosis or "")
                             if j not in checks else escape(check_text(checks[j], a, lang)))
            table.add_row(*cells)
        for name, right, n, off in s.table_grades:
            mark = f"[green]{t['pass']}[/]" if right == n else f"[red]{t['fail']}[/]"
            table.add_row(shown.get(name, name), table_verdict(right, n, lang), "", "", "",
                          mark, cells_off(off, lang, name))
        console.print(table)

    if r.students:
        group = Table(title=t["group"].format(n=len(r.students), mean=_pct(r.mean_score)),
                      title_justify="left")
        group.add_column(t["student"])
        group.add_column(t["variant"])
        group.add_column(t["score"], justify="right")
        group.add_column(t["wrong_col"])
        for s in r.students[:GROUP_ROWS]:
            group.add_row(s.student, s.variant, f"{s.passed}/{s.total} ({_pct(s.score)})",
                          ", ".join(shown.get(a, a) for a in s.wrong) or "—")
        console.print(group)
        if len(r.students) > GROUP_ROWS:
            console.print(t["more_students"].format(n=len(r.students) - GROUP_ROWS),
                          highlight=False)
        per = Table(title=t["by_answer"], title_justify="left")
        per.add_column(t["answer"])
        per.add_column(t["wrong_col"], justify="right")
        per.add_column(t["tolerance"], justify="right")
        for a, (w, n) in r.wrong_counts().items():
            per.add_row(shown.get(a, a), f"{w}/{n}",
                        f"{_pct_of(r.key.tolerance_of(a, r.tolerance))} %")
        console.print(per)
        full = sum(s.passed == s.total for s in r.students)
        console.print(t["stats"].format(mean=_pct(r.mean_score), k=full, n=len(r.students),
                                        worst=_most_often_wrong(r, lang, shown)),
                      highlight=False)
        carried = sum(s.carried_count for s in r.students)
        if carried:
            share = _number(r.carried_share, sig=3)
            console.print(t["carried_note" if r.carried_share else "carried_none"].format(
                n=carried, share=share.replace(".", ",") if lang == "ru" else share),
                highlight=False)
    if r.problems:
        console.print(f"[yellow]{t['problem_list'].format(n=len(r.problems))}[/] "
                      f"{t['problem_note']}")
        for p in r.problems[:GROUP_ROWS]:
            console.print(f"  {message(p.said(), lang)}", highlight=False, markup=False,
                          soft_wrap=True)
        if len(r.problems) > GROUP_ROWS:
            console.print("  " + t["more_problems"].format(n=len(r.problems) - GROUP_ROWS),
                          highlight=False)
