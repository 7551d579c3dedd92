"""The typst both writers of a записка share: render/report_formats.py (the plain layout, and
the task sheets) and render/report_gost.py (the ГОСТ layout of the Russian PDF).

Text is written as typst string literals (nothing in a case's words is markup), **bold** as
#strong and the symbols' subscripts (J_II, ΔT_нб: mathfmt.subscripts) as #sub; a paragraph, a
list and a formula are the same lines in both layouts (:func:`typst_block`). Headings, tables
and figures are each writer's own.
"""
from __future__ import annotations

from collections.abc import Callable

from flywheel.render import mathfmt
from flywheel.render.blocks import Bullets, Formula, Paragraph, Where


def literal(s: str) -> str:
    """A run of text as one typst string literal ("" for none)."""
    return '#"' + s.replace("\\", "\\\\").replace('"', '\\"') + '"' if s else ""


def boxed_literal(s: str) -> str:
    """A run of text as typst string literals, a narrow no-break space (the numbers' thousands,
    render/numbers.py) as a box of its width, which no line breaks (the ГОСТ layout)."""
    if not s:
        return ""
    return "#box(width: 0.2em)".join(literal(p) for p in s.split("\u202f"))


def markup(text: str, lit: Callable[[str], str] = literal) -> str:
    """``text`` as typst markup: each run written by ``lit``, **bold** as #strong, the symbols'
    subscripts as #sub."""
    def subs(s: str) -> str:
        return "".join(f"#sub[{lit(r)}]" if b else lit(r) for r, b in mathfmt.subscripts(s))

    parts = text.split("**")
    return "".join(subs(p) if i % 2 == 0 else f"#strong[{subs(p)}]" for i, p in enumerate(parts))


def typst_block(b, ts: Callable[[str], str] = markup, spacing: str = "1.2em") -> list[str] | None:
    """The typst lines of a paragraph, a bulleted list or a display formula, its text written
    by ``ts``; None for another kind of block (a heading, a table, a figure: the writer's).
    A paragraph that leads into what follows (``Paragraph.leads_in``) is kept on one page
    with it: a sticky block, ``spacing`` the layout's paragraph spacing, so that it stands as
    a paragraph would."""
    if isinstance(b, Where):                           # a forced line break between lines
        return [" \\\n".join(ts(line) for line in b.lines)]
    if isinstance(b, Paragraph):
        if b.leads_in:
            return [f"#block(sticky: true, spacing: {spacing})[#par[{ts(b.text)}]]"]
        return [ts(b.text)]
    if isinstance(b, Bullets):
        return ["- " + ts(i) for i in b.items]
    if isinstance(b, Formula):
        return [f"$ {mathfmt.typst(b.tex)} $"]
    return None
