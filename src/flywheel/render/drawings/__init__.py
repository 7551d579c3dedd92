"""The graphic part of the course project: ЕСКД drawing sheets in PDF, SVG and DXF
(`flywheel run CASE --drawings`, `flywheel drawings CASE`; docs/drawings.md).

Sheet 1 the law of motion (sheet1.py), sheet 2 the force analysis (sheet2.py); each a list of
views (model.py: primitives in millimetres) packed by the layout (layout.py) into the field of
a sheet with its frame and title block (sheet.py); written by dxf.py (ezdxf) and paper.py
(matplotlib, PDF and SVG at true size). A sheet whose views do not fit continues on another
sheet of the same name (sheet1-2.pdf …), numbered in the title blocks.
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from flywheel.render.drawings.model import View
from flywheel.render.choices import SHEET_SIZES

SIZES = SHEET_SIZES
SUFFIXES = ("pdf", "svg", "dxf")


@dataclass(frozen=True)
class Sheet:
    """One sheet: ``stem`` its file name («sheet1», «sheet1-2»), ``size`` (A1 …), its views
    placed (the frame's first), ``number`` of ``count`` sheets."""

    stem: str
    size: str
    views: tuple[View, ...]
    number: int
    count: int
    left_out: tuple[str, ...] = ()

    @property
    def items(self) -> list:
        return [it for v in self.views for it in v.items]


#: the factors a sheet's room (sheet.ROOM) is tried at besides 1 (:func:`fitted`): smaller
#: where the views take more than one sheet, larger where they take one with room to spare
SHRINK = (0.9, 0.8)
GROW = (1.15, 1.3, 1.45, 1.6)


def _largest(factors, fits):
    """``fits(f)`` of the largest of ``factors`` it is not None for, bisected (it is None above
    some factor and not below it: a drawing that fits fits smaller); None if none fits."""
    order, found = sorted(factors), None
    lo, hi = 0, len(order)
    while lo < hi:
        mid = (lo + hi) // 2
        tried = fits(order[mid])
        if tried is not None:
            found, lo = tried, mid + 1
        else:
            hi = mid
    return found


def fitted(build, size: str):
    """The views ``build(room)`` makes and their pages (layout.pack) at the room that fills the
    sheets of ``size`` best: the fewest views left out, then the fewest sheets, then the
    largest drawings — sheet.ROOM times 1, or a factor of :data:`SHRINK` where the views take
    more sheets than one, or of :data:`GROW` where they take one; where they take more sheets
    whatever the room, the last sheet's views alone grown by :data:`GROW` while they keep to
    it (the lettering never changes). The factors are bisected: three or four builds, not one
    per factor. Returns (views, pages, left_out)."""
    from flywheel.render.drawings.layout import pack
    from flywheel.render.drawings.sheet import ROOM

    def views_at(factor: float):           # the views at sheet.ROOM × factor
        return build({k: v * factor for k, v in ROOM[size].items()})

    def attempt(factor: float):
        views = views_at(factor)
        return (views, *pack(views, size))

    def need(a) -> tuple[int, int]:        # views left out, then sheets
        return len(a[2]), len(a[1])

    def within(goal):                      # the attempt at a factor if it needs no more
        return lambda f: a if need(a := attempt(f)) <= goal else None

    base = attempt(1.0)
    if need(base) <= (0, 1):               # one sheet: the largest factor that keeps it one
        return _largest(GROW, within(need(base))) or base
    least = attempt(SHRINK[-1])            # more: the largest factor that saves a sheet, if
    if need(least) < need(base):           # the smallest does
        return _largest(SHRINK[:-1], within(need(least))) or least
    views, pages, left_out = base
    last = [v.name for v in pages[-1]]
    names = [v.name for v in views]
    if left_out or len(set(names)) < len(names):
        return base

    def alone(factor: float):              # the last sheet's views, larger, on one sheet
        grown = {v.name: v for v in views_at(factor)}
        if set(grown) != set(names):
            return None
        placed, out = pack([grown[n] for n in last], size)
        return placed[0] if len(placed) == 1 and not out else None

    page = _largest(GROW, alone)
    return base if page is None else (views, [*pages[:-1], page], left_out)


def build_sheets(results, document, *, lang: str = "ru", size: str = "A1") -> list[Sheet]:
    """The sheets of a run: sheet 1 (and sheet 2 for a linkage case with its plans), each at
    the room that fills its sheets best (:func:`fitted`); a title block's scale is its own
    sheet's (the first view drawn to a ГОСТ scale), blank on a sheet with none."""
    from flywheel.render.drawings import sheet1
    from flywheel.render.drawings.sheet import frame_view, words_of

    parts = [("sheet1", "sheet1", fitted(lambda room: sheet1.views(results, lang, room), size))]
    if results.plans:
        from flywheel.render.drawings import sheet2

        parts.append(("sheet2", "sheet2",
                      fitted(lambda room: sheet2.views(results, lang, room), size)))
    packed = []
    for stem, key, (views, pages, left_out) in parts:
        for k, page in enumerate(pages):
            # the title block's scale: its sheet's first view drawn to a ГОСТ scale (the
            # scheme, a group); none on a sheet of diagrams and plans (their μ by each view)
            scale = next((v.scales["label"] for v in page if "label" in v.scales), "")
            packed.append((stem if k == 0 else f"{stem}-{k + 1}", key, page, scale,
                           tuple(left_out)))
    count = len(packed)
    from flywheel.io.text import in_language   # the case's title in the sheet's language

    sheets = []
    for n, (stem, key, page, scale, left_out) in enumerate(packed, start=1):
        frame = frame_view(size, lang, document=document, title=in_language(results.title, lang),
                           sheet_name=words_of(lang)[key], number=n, count=count, scale=scale)
        sheets.append(Sheet(stem, size, (frame, *page), n, count, left_out))
    return sheets


def write_drawings(results, folder: Path, document, *, lang: str = "ru",
                   size: str = "A1") -> list[Path]:
    """Write every sheet as PDF, SVG and DXF into ``folder`` (made); the paths written."""
    from flywheel.render.drawings.dxf import write_dxf
    from flywheel.render.drawings.paper import write_paper
    from flywheel.render.drawings.sheet import FORMATS

    folder.mkdir(parents=True, exist_ok=True)
    written = []
    for s in build_sheets(results, document, lang=lang, size=size):
        items = s.items
        write_paper({f: folder / f"{s.stem}.{f}" for f in ("pdf", "svg")}, FORMATS[size], items)
        write_dxf(folder / f"{s.stem}.dxf", FORMATS[size], _named(s.views))
        written += [folder / f"{s.stem}.{x}" for x in SUFFIXES]
    return written


def _named(views) -> list[View]:
    """The views with names unique on their sheet («group B», «group B 2» …)."""
    seen: dict[str, int] = {}
    out = []
    for v in views:
        n = seen[v.name] = seen.get(v.name, 0) + 1
        out.append(v if n == 1 else View(f"{v.name} {n}", v.items, v.scales, v.labels))
    return out
