"""The report of ``flywheel grade`` as data: the JSON document (``--json``) and the CSV of
one line per student and answer (``--out``), written in pieces (teaching/grading.py's
:class:`~flywheel.teaching.grading.Report`; re-exported by teaching/grading.py).

Computation only: no typer, no rich.
"""
from __future__ import annotations

import csv
import io
import json
from typing import Iterator


def report_dict(r) -> dict:
    """The report as a JSON-ready document (``flywheel grade --json``)."""
    doc = _report_frame(r)
    doc["students"] = [_student_dict(s) for s in r.students]
    return doc


def _student_dict(s) -> dict:
    doc = {
        "student": s.student, "variant": s.variant, "file": s.file, "row": s.row,
        "score": s.score, "passed": s.passed, "carried_forward": s.carried_count,
        "total": s.total, "wrong": s.wrong,
        "answers": [{"answer": a.answer, "given": a.given, "key": a.key, "error": a.error,
                     "error_kind": a.error_kind, "tolerance": a.tolerance,
                     "pass": a.passed, "verdict": a.verdict, "diagnosis": a.diagnosis}
                    for a in s.answers],
    }
    if s.marking.tables:     # a key with tables (teaching/tables.py); without: as before
        doc["tables"] = [{"table": name, "right": right, "cells": n, "credit": right / n,
                          "off": [{"column": c, "rows": list(rows)} for c, rows in off]}
                         for name, right, n, off in s.table_grades]
    return doc


def _report_frame(r) -> dict:
    """The report's document with ``students`` empty (filled by the callers)."""
    worst = r.most_often_wrong()
    return {
        "key": r.key.source,
        "tolerance": r.tolerance,
        "carried_forward": r.carried_share,
        "tolerances": {a: r.key.tolerance_of(a, r.tolerance) for a in r.key.answers},
        "files": list(r.files),
        "students": [],
        "summary": {
            "graded": len(r.students),
            "mean_score": r.mean_score,
            "min_score": min((s.score for s in r.students), default=None),
            "max_score": max((s.score for s in r.students), default=None),
            "full_marks": sum(s.passed == s.total for s in r.students),
            "wrong_by_answer": {a: {"wrong": w, "graded": n}
                                for a, (w, n) in r.wrong_counts().items()},
            "most_often_wrong": None if worst is None else
            {"answers": worst[0], "wrong": worst[1]},
            "score_distribution": {str(k): n for k, n in r.score_distribution().items()},
            "handed_in_nothing": [s.student for s in r.handed_in_nothing],
            "unassigned_variants": r.unassigned_variants(),
        },
        "problems": [{"file": p.file, "row": p.row, "message": p.message} for p in r.problems],
    }


def report_json(r) -> Iterator[str]:
    """The text of ``json.dumps(report_dict(r), indent=2, ensure_ascii=False)`` and a newline,
    in pieces: one student's document at a time (a class of 200 000 never held whole).

    json's indented text of a nested value is its own indented text with every line after the
    first moved right by the indentation of its place, which this relies on."""
    def dumps(value, depth: int) -> str:
        return json.dumps(value, indent=2, ensure_ascii=False).replace("\n", "\n" + "  " * depth)

    frame = _report_frame(r)
    yield "{"
    for i, (name, value) in enumerate(frame.items()):
        yield ("," if i else "") + "\n  " + json.dumps(name, ensure_ascii=False) + ": "
        if name != "students" or not r.students:
            yield dumps(value, 1)
            continue
        yield "["
        for j, s in enumerate(r.students):
            yield ("," if j else "") + "\n    " + dumps(_student_dict(s), 2)
        yield "\n  ]"
    yield "\n}\n"


#: rows of a CSV report formatted per piece of text (report_csv_pieces, gradebook pieces)
CSV_ROWS_PER_PIECE = 2000


def report_csv(r) -> str:
    """One line per student and answer: student, variant, file, row, answer, given, key,
    error, error_kind, tolerance, pass (1/0), score."""
    return "".join(report_csv_pieces(r))


def report_csv_pieces(r) -> Iterator[str]:
    """The text of :func:`report_csv` in pieces of CSV_ROWS_PER_PIECE students."""
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(["student", "variant", "file", "row", "answer", "given", "key", "error",
                "error_kind", "tolerance", "pass", "score"])
    for i, s in enumerate(r.students, start=1):
        for a in s.answers:
            w.writerow([s.student, s.variant, s.file, s.row, a.answer,
                        "" if a.given is None else repr(a.given), repr(a.key),
                        "" if a.error is None else f"{a.error:.6g}", a.error_kind,
                        repr(a.tolerance), int(a.passed), f"{s.score:.4f}"])
        if i % CSV_ROWS_PER_PIECE == 0:
            yield buf.getvalue()
            buf.seek(0)
            buf.truncate()
    yield buf.getvalue()
