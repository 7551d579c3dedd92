"""report.md: the записка (render/document.py) written as Markdown — numbered sections, tables
with their captions «Таблица N — …», formulas as ``$$ … \\tag{n} $$`` (LaTeX; numbered in their
order through the document, as every writer numbers them: ГОСТ 7.32-2017, 6.8.3), figures
«Рис. N — …».

Text only: every number comes from the document model, built once from Results.
"""
from __future__ import annotations

from flywheel.render.document import (Bullets, Document, Figure, Formula, Heading, Paragraph, Table, Where,
                                      build_document)
from flywheel.render.catalogue import words

_CAPTION = words("report_caption", {"table": "Table", "figure": "Figure"})
CAPTION = {lang: (w["table"], w["figure"]) for lang, w in _CAPTION.items()}


def _cell(x: str) -> str:
    return x.replace("|", "\\|")


def markdown(doc: Document) -> str:
    """The document as Markdown."""
    tab, fig = CAPTION[doc.lang]
    parts: list[str] = []
    formulas = 0
    for blk in doc.blocks:
        if isinstance(blk, Heading):
            parts.append("#" * blk.level + " " + blk.text + "\n")
        elif isinstance(blk, Where):                   # a line each, hard breaks between
            parts.append("  \n".join(blk.lines) + "\n")
        elif isinstance(blk, Paragraph):
            parts.append(blk.text + "\n")
        elif isinstance(blk, Bullets):
            parts.append("\n".join(f"- {x}" for x in blk.items) + "\n")
        elif isinstance(blk, Formula):
            formulas += 1
            parts.append(f"$$ {blk.tex} \\tag{{{formulas}}} $$\n")
        elif isinstance(blk, Table):
            out = [f"{tab} {blk.number} — {blk.caption}\n",
                   "| " + " | ".join(map(_cell, blk.header)) + " |", "|" + "---|" * len(blk.header)]
            out += ["| " + " | ".join(map(_cell, r)) + " |" for r in blk.rows]
            parts.append("\n".join(out) + "\n")
        elif isinstance(blk, Figure):
            parts.append(f"![{fig} {blk.number} — {blk.caption}](plots/{blk.file})\n\n"
                         f"{fig} {blk.number} — {blk.caption}\n")
    return "\n".join(parts)


def report_markdown(results, lang: str = "en", plots: list[str] | None = None, case=None) -> str:
    """The report as Markdown; ``plots``: PNG file names under plots/ to embed."""
    return markdown(build_document(results, lang, plots, case))
