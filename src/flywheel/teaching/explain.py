"""Grading that explains (issue 27): error carried forward and the classic mistakes named,
for one student's values of one variant (``Marking.explain`` of teaching/grading.py).

An answer wrong against the key is *carried forward* («верно по вашим данным», "consistent
with your earlier answer") when the variant's chain (teaching/chain.py) recomputed from the
student's own earlier answers gives it within its tolerance — unless it merely repeats the
earlier answer it is computed from where the key's two values differ beyond the tolerance
(copying one wrong number everywhere earns nothing). A wrong answer that is not carried
forward is tried against the catalogue of classic mistakes (teaching/mistakes.py).

Computation only: no typer, no rich.
"""
from __future__ import annotations

import math

from flywheel.teaching.mistakes import diagnose


def explain(marking, given, mask: int, close) -> tuple[int, tuple[tuple[int, str], ...]]:
    """(carried, diagnoses): the answers carried forward as a bit mask (bit j: answer j) and
    the (answer j, mistake code) of the wrong answers a classic mistake reproduces.
    ``close(given, value, tolerance)``: grading's own test of an answer (teaching/grading.py
    ``within``)."""
    chain = marking.chain
    names = marking.names
    values = dict(zip(names, given))
    pos = {a: j for j, a in enumerate(names)}
    carried = 0
    named = []
    for j, a in enumerate(names):
        g = given[j]
        if mask >> j & 1 or g != g or not chain.knows(a):
            continue
        tol = marking.tolerances[j]
        cands, source = _recomputed(chain, a, values)
        if source is not None and cands and math.isfinite(cands[0]) and close(g, cands[0], tol):
            k = pos[source]
            repeats = close(g, given[k], tol) and not close(marking.keys[j], marking.keys[k], tol)
            if not repeats:
                carried |= 1 << j
                continue
        code = diagnose(chain, a, values, tol, close, dict(zip(names, marking.tolerances)))
        if code is not None:
            named.append((j, code))
    return carried, tuple(named)


def _recomputed(chain, answer: str, values: dict) -> tuple[tuple[float, ...], str | None]:
    """``chain.recompute(answer, values)``, a step the student's numbers cannot be put through
    (a root of a negative, a division by 0) giving no value: ((), None)."""
    try:
        return chain.recompute(answer, values)
    except (ArithmeticError, ValueError):
        return (), None


def from_own(student, j: int) -> tuple[float, str] | None:
    """(value, source): answer j of a graded ``student`` (grading.StudentGrade) as the variant's
    chain computes it from the student's own earlier answer ``source``, for a feedback page to
    work a wrong answer from the student's own numbers; None where the chain does not know the
    answer or none of the student's answers feeds it."""
    marking = student.marking
    chain, a = marking.chain, marking.names[j]
    if chain is None or not chain.knows(a):
        return None
    values, source = _recomputed(chain, a, dict(zip(marking.names, student.given)))
    if source is None or not values or not math.isfinite(values[0]):
        return None
    return values[0], source
