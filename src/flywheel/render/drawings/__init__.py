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
    more sheets than one, or of :data:`GROW` where they take one. Where they take more sheets
    than one at the room chosen, the last two sheets share their views (:func:`_shared`): up
    to :data:`MOVE` views of the one before go on to the last, as many as leave the emptier of
    the two fullest, each sheet's views then drawn alone at that room or larger while they keep
    to it (:func:`_shared`; the lettering never changes). The factors are bisected, each room
    built once. Returns (views, pages, left_out)."""
    from flywheel.render.drawings.layout import pack
    from flywheel.render.drawings.sheet import ROOM

    built: dict[float, list] = {}

    def views_at(factor: float):           # the views at sheet.ROOM × factor, built once
        if factor not in built:
            built[factor] = build({k: v * factor for k, v in ROOM[size].items()})
        return built[factor]

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
        chosen = _largest(SHRINK[:-1], within(need(least))) or least
    else:
        chosen = base
    views, pages, left_out = chosen
    names = [v.name for v in views]
    if left_out or len(set(names)) < len(names) or len(pages) < 2:
        return chosen
    factor = next(f for f, built_views in built.items() if built_views is views)
    return views, [*pages[:-2], *_shared(pages[-2:], names, views_at, size, factor)], left_out


#: the most views of the sheet before the last that :func:`fitted` moves on to the last
MOVE = 4


def _shared(two: list[list[View]], names: list[str], views_at, size: str,
            factor: float = 1.0) -> list[list[View]]:
    """The last two pages of :func:`fitted` (packed at the room's ``factor``) with the last
    ``m`` ≤ MOVE views of the first moved to the second (in the views' order), each page's
    views drawn alone at the largest room that keeps them to one sheet — of 1 and
    :data:`GROW` at ``factor`` 1, of ``factor`` … 1 at a SHRINK ``factor``: of m = 0 … MOVE
    the one whose emptier page is fullest (the views' area over the field; the fewest moved of
    equals). A page of diagrams left at a sixth of
    its sheet while the sheet before is crowded is what this mends."""
    from flywheel.render.drawings.layout import pack
    from flywheel.render.drawings.sheet import field_of

    fx0, fy0, fx1, fy1 = field_of(size)

    def fill(page) -> float:
        return sum(v.size[0] * v.size[1] for v in page) / ((fx1 - fx0) * (fy1 - fy0))

    def alone(page_names):                 # the page's views at a factor, if on one sheet
        def at(factor: float):
            grown = {v.name: v for v in views_at(factor)}
            if set(grown) != set(names):
                return None
            placed, out = pack([grown[n] for n in page_names], size)
            return placed[0] if len(placed) == 1 and not out else None
        return at

    # each page's room: at 1, the room or larger (GROW); at a SHRINK that saved a sheet, that
    # room up to the room itself (the rooms its search has built already)
    rooms = (1.0, *GROW) if factor >= 1.0 else tuple(f for f in (*SHRINK, 1.0) if f >= factor)
    first, last = [v.name for v in two[0]], [v.name for v in two[1]]
    best, best_fill = two, -1.0
    for m in range(0, min(MOVE, len(first) - 1) + 1):
        kept = first[:len(first) - m]
        moved = sorted(first[len(first) - m:] + last, key=names.index)
        pages = [_largest(rooms, alone(p)) for p in (kept, moved)]
        if any(p is None for p in pages):
            break                          # more moved would not keep to one sheet either
        emptier = min(fill(p) for p in pages)
        if emptier > best_fill + 1e-9:
            best, best_fill = pages, emptier
    return best


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
