"""A sheet as PDF or SVG at true size (1 mm on the drawing is 1 mm on paper), written
directly: a one-page PDF 1.4 whose content stream is scaled to millimetres, and an SVG whose
width and height are in mm with a viewBox in mm. Line thicknesses and dashes of ГОСТ 2.303;
the lettering drawn as the font's outlines (fonts.outline) sloped 15° (ГОСТ 2.304 type B) —
the same on every viewer, no font to embed. Coordinates to 0.01 mm; no date, no random ids:
the same sheet gives the same bytes.
"""
from __future__ import annotations

import math
import zlib
from pathlib import Path

from flywheel.render.drawings.model import LINE_TYPES, SLANT_DEG, Circle, Polyline, Text

PT_PER_MM = 72.0 / 25.4
_K = 0.5522847498          # a quarter circle as a cubic Bézier: 4/3·(√2 − 1)


def _f(x: float) -> str:
    s = f"{x:.2f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def _circle(c, r) -> list:
    """A circle as one contour of four cubic Béziers."""
    x, y = c
    k = _K * r
    return [("M", [(x + r, y)]),
            ("C", [(x + r, y + k), (x + k, y + r), (x, y + r)]),
            ("C", [(x - k, y + r), (x - r, y + k), (x - r, y)]),
            ("C", [(x - r, y - k), (x - k, y - r), (x, y - r)]),
            ("C", [(x + k, y - r), (x + r, y - k), (x + r, y)])]


def _glyphs(items) -> tuple[list[str], list[tuple[int, tuple]]]:
    """The characters the letters use (each drawn once: a PDF form, an SVG symbol) and every
    letter placed: (its character's index, the matrix (a, b, c, d, e, f) from the glyph's
    units — 1 = the capital height — to the sheet [mm]): scale by the height, slope 15°
    (ГОСТ 2.304 type B), turn by the text's angle, move to its place."""
    from flywheel.render.drawings.fonts import advance, drawn_char

    sh = math.tan(math.radians(SLANT_DEG))
    chars: dict[str, int] = {}
    placed = []
    for t in items:
        if not isinstance(t, Text) or not t.text.strip():
            continue
        dx = {"left": 0.0, "center": -t.width / 2, "right": -t.width}[t.halign]
        dy = {"bottom": 0.0, "middle": -t.height / 2, "top": -t.height}[t.valign]
        c, s = math.cos(math.radians(t.angle)), math.sin(math.radians(t.angle))
        h, q = t.height, t.squeeze
        pen = 0.0
        for ch in t.text:
            for sub in drawn_char(ch):
                if not sub.isspace():
                    k = chars.setdefault(sub, len(chars))
                    u, w = pen * h * q + dx, dy
                    placed.append((k, (h * q * c, h * q * s, h * (c * sh - s), h * (s * sh + c),
                                       t.x + c * u - s * w, t.y + s * u + c * w)))
                pen += advance(sub)
    return list(chars), placed


def _glyph_path(ch: str) -> list:
    from flywheel.render.drawings.fonts import outline

    return outline(ch)


def _strokes(items):
    """(line type, contours, closed) of every stroked item, by line type in a fixed order."""
    for key in LINE_TYPES:
        for it in items:
            if isinstance(it, Polyline) and not it.filled and it.line == key:
                yield key, [("M", [it.points[0]])] + [("L", [p]) for p in it.points[1:]], \
                    it.closed
            elif isinstance(it, Circle) and not it.filled and it.line == key:
                yield key, _circle(it.centre, it.radius), True


def _fills(items):
    """Every filled contour: arrow heads, dots (the letters: _glyphs)."""
    for it in items:
        if isinstance(it, Polyline) and it.filled:
            yield [("M", [it.points[0]])] + [("L", [p]) for p in it.points[1:]]
        elif isinstance(it, Circle) and it.filled:
            yield _circle(it.centre, it.radius)


# -- PDF ------------------------------------------------------------------------------------------
def _pdf_path(contour, closed: bool, digits: int = 2) -> str:
    f = _f if digits == 2 else (lambda v: f"{v:.{digits}f}")
    ops = []
    for op, pts in contour:
        ops.append(" ".join(f"{f(x)} {f(y)}" for x, y in pts) + {"M": " m", "L": " l",
                                                                 "C": " c"}[op])
    if closed:
        ops.append("h")
    return " ".join(ops)


def pdf_bytes(size: tuple[float, float], items) -> bytes:
    """The sheet as a one-page PDF [size in mm]."""
    W, H = size
    out = [f"{PT_PER_MM:.6f} 0 0 {PT_PER_MM:.6f} 0 0 cm 1 J 1 j 0 g 0 G"]
    current = None
    for key, contour, closed in _strokes(items):
        if key != current:
            width, dashes = LINE_TYPES[key]
            out.append(f"{_f(width)} w [{' '.join(_f(d) for d in dashes)}] 0 d")
            current = key
        out.append(_pdf_path(contour, closed) + " S")
    for contour in _fills(items):
        out.append(_pdf_path(contour, True) + " f")
    chars, placed = _glyphs(items)
    for k, m in placed:
        out.append(f"q {' '.join(f'{v:.4f}' for v in m[:4])} {_f(m[4])} {_f(m[5])} cm /G{k} Do Q")
    stream = zlib.compress("\n".join(out).encode("ascii"), 6)
    forms = []
    for ch in chars:
        path = " ".join(_pdf_path(c, True, 4) for c in _glyph_path(ch))
        data = ((path + " f") if path else "").encode("ascii")
        forms.append(f"<< /Type /XObject /Subtype /Form /BBox [-2 -2 3 3] /Length {len(data)} "
                     f">>\nstream\n".encode("ascii") + data + b"\nendstream")
    xobjects = " ".join(f"/G{k} {6 + k} 0 R" for k in range(len(chars)))
    objs = [b"<< /Type /Catalog /Pages 2 0 R >>",
            b"<< /Type /Pages /Kids [3 0 R] /Count 1 >>",
            (f"<< /Type /Page /Parent 2 0 R /MediaBox [0 0 {W * PT_PER_MM:.4f} "
             f"{H * PT_PER_MM:.4f}] /Contents 4 0 R /Resources << /XObject << {xobjects} >> >> "
             ">>").encode("ascii"),
            f"<< /Length {len(stream)} /Filter /FlateDecode >>\nstream\n".encode("ascii")
            + stream + b"\nendstream",
            b"<< /Producer (flywheel) >>"] + forms
    body = bytearray(b"%PDF-1.4\n%\xe2\xe3\xcf\xd3\n")
    offsets = []
    for n, obj in enumerate(objs, start=1):
        offsets.append(len(body))
        body += f"{n} 0 obj\n".encode("ascii") + obj + b"\nendobj\n"
    xref = len(body)
    body += f"xref\n0 {len(objs) + 1}\n0000000000 65535 f \n".encode("ascii")
    for off in offsets:
        body += f"{off:010d} 00000 n \n".encode("ascii")
    body += (f"trailer\n<< /Size {len(objs) + 1} /Root 1 0 R /Info 5 0 R >>\nstartxref\n"
             f"{xref}\n%%EOF\n").encode("ascii")
    return bytes(body)


# -- SVG ------------------------------------------------------------------------------------------
def _svg_path(contour, closed: bool, digits: int = 2) -> str:
    f = _f if digits == 2 else (lambda v: f"{v:.{digits}f}")
    return "".join(op + " ".join(f"{f(x)},{f(y)}" for x, y in pts)
                   for op, pts in contour) + ("Z" if closed else "")


def svg_text(size: tuple[float, float], items) -> str:
    """The sheet as SVG [size in mm]; the drawing in a group that turns y up."""
    W, H = size
    chars, placed = _glyphs(items)
    out = ['<?xml version="1.0" encoding="utf-8"?>',
           f'<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" '
           f'width="{_f(W)}mm" height="{_f(H)}mm" viewBox="0 0 {_f(W)} {_f(H)}">', "<defs>"]
    for k, ch in enumerate(chars):
        d = "".join(_svg_path(c, True, 4) for c in _glyph_path(ch))
        out.append(f'<path id="g{k}" d="{d}"/>')
    out += ["</defs>", f'<rect width="{_f(W)}" height="{_f(H)}" fill="white"/>',
            f'<g transform="matrix(1 0 0 -1 0 {_f(H)})">']
    groups: dict[str, list[str]] = {}
    for key, contour, closed in _strokes(items):
        groups.setdefault(key, []).append(_svg_path(contour, closed))
    for key, paths in groups.items():
        width, dashes = LINE_TYPES[key]
        dash = f' stroke-dasharray="{" ".join(_f(d) for d in dashes)}"' if dashes else ""
        out.append(f'<g id="{key}" fill="none" stroke="black" stroke-width="{_f(width)}" '
                   f'stroke-linecap="round" stroke-linejoin="round"{dash}>')
        out += [f'<path d="{d}"/>' for d in paths]
        out.append("</g>")
    out.append('<g id="fill" fill="black" stroke="none">')
    out += [f'<path d="{_svg_path(c, True)}"/>' for c in _fills(items)]
    out += [f'<use xlink:href="#g{k}" transform="matrix({" ".join(f"{v:.4f}" for v in m[:4])} '
            f'{_f(m[4])} {_f(m[5])})"/>' for k, m in placed]
    out += ["</g>", "</g>", "</svg>", ""]
    return "\n".join(out)


def write_paper(paths: dict[str, Path], size: tuple[float, float], items) -> None:
    """Write the sheet's ``items`` as each format of ``paths`` (pdf, svg → its path)."""
    for fmt, path in paths.items():
        if fmt == "pdf":
            Path(path).write_bytes(pdf_bytes(size, items))
        else:
            Path(path).write_text(svg_text(size, items), encoding="utf-8")
