"""A sheet as DXF (AutoCAD R2013, written with ezdxf): millimetres, one layer per line type of
ГОСТ 2.303 with its lineweight and line type, the lettering on a layer of its own in a text
style named for the ГОСТ font (a CAD program draws it in its own: КОМПАС's and AutoCAD's «GOST
type B»), sloped 15° (ГОСТ 2.304 type B). Polylines as LWPOLYLINE, arrow heads as solid
HATCH, circles as CIRCLE, lettering as TEXT. Same sheet → same bytes: the header's dates,
the document's and the entities' handles and GUIDs are fixed, the CLASS entries sorted.
"""
from __future__ import annotations

from pathlib import Path

from flywheel.render.drawings.model import LINE_TYPES, SLANT_DEG, Circle, Polyline, Text

#: line type → (layer, DXF line type, description)
LAYERS = {"main": ("MAIN", "Continuous", "ГОСТ 2.303: сплошная основная"),
          "thin": ("THIN", "Continuous", "ГОСТ 2.303: сплошная тонкая"),
          "axis": ("AXIS", "GOST_DASHDOT", "ГОСТ 2.303: штрихпунктирная тонкая"),
          "dashed": ("DASHED", "GOST_DASHED", "ГОСТ 2.303: штриховая")}
TEXT_LAYER = "TEXT"
TEXT_STYLE = "GOST type B"
TEXT_FONT = "GOST type B.ttf"
_FIXED_GUID = "{00000000-0000-0000-0000-000000000000}"


def write_dxf(path: Path, size: tuple[float, float], views) -> None:
    """Write the sheet's ``views`` to ``path`` as DXF R2013 [mm] (:func:`_write`), with ezdxf's
    fixed metadata (no date, no random GUID in the file: the same sheet, the same bytes)."""
    import ezdxf

    fixed = ezdxf.options.write_fixed_meta_data_for_testing
    ezdxf.options.write_fixed_meta_data_for_testing = True
    try:
        _write(path, size, views)
    finally:
        ezdxf.options.write_fixed_meta_data_for_testing = fixed


def _write(path: Path, size: tuple[float, float], views) -> None:
    """Write the sheet's ``views`` to ``path`` as DXF R2013 [mm], each view's entities a DXF
    group named for the view (a CAD program moves a view as one; the tests find a plan)."""
    import ezdxf
    from ezdxf import units

    doc = ezdxf.new("R2013", setup=False)
    doc.units = units.MM
    doc.header["$MEASUREMENT"] = 1
    doc.header["$LUNITS"] = 2
    doc.header["$LIMMIN"] = (0.0, 0.0)
    doc.header["$LIMMAX"] = size
    doc.header["$EXTMIN"] = (0.0, 0.0, 0.0)
    doc.header["$EXTMAX"] = (size[0], size[1], 0.0)
    doc.linetypes.add("GOST_DASHDOT", pattern=[21.5, 15.0, -3.0, 0.5, -3.0],
                      description="ГОСТ 2.303 ___ . ___ . ___")
    doc.linetypes.add("GOST_DASHED", pattern=[6.5, 5.0, -1.5],
                      description="ГОСТ 2.303 __ __ __")
    for key, (name, ltype, desc) in LAYERS.items():
        layer = doc.layers.add(name, linetype=ltype, color=7)
        layer.dxf.lineweight = int(round(LINE_TYPES[key][0] * 100))
        layer.description = desc
    tl = doc.layers.add(TEXT_LAYER, color=7)
    tl.dxf.lineweight = 25
    tl.description = "ГОСТ 2.304: шрифт типа Б"
    style = doc.styles.add(TEXT_STYLE, font=TEXT_FONT)
    style.dxf.oblique = SLANT_DEG
    style.dxf.width = 1.0
    msp = doc.modelspace()
    from ezdxf.enums import TextEntityAlignment

    align = {("left", "bottom"): TextEntityAlignment.BOTTOM_LEFT,
             ("center", "bottom"): TextEntityAlignment.BOTTOM_CENTER,
             ("right", "bottom"): TextEntityAlignment.BOTTOM_RIGHT,
             ("left", "middle"): TextEntityAlignment.MIDDLE_LEFT,
             ("center", "middle"): TextEntityAlignment.MIDDLE_CENTER,
             ("right", "middle"): TextEntityAlignment.MIDDLE_RIGHT,
             ("left", "top"): TextEntityAlignment.TOP_LEFT,
             ("center", "top"): TextEntityAlignment.TOP_CENTER,
             ("right", "top"): TextEntityAlignment.TOP_RIGHT}
    for view in views:
        group = doc.groups.new(view.name)
        with group.edit_data() as members:
            for it in view.items:
                members.append(_add(msp, it, align))
    _fix(doc)
    # ezdxf registers the CLASS of each object type in use in the order of a set, which
    # follows PYTHONHASHSEED (LAYOUT before ACDBPLACEHOLDER, or after): registered here
    # first, sorted, a sheet's bytes are the same from one process to the next
    for name in sorted(doc.entitydb.dxf_types_in_use()):
        doc.classes.add_class(name)
    doc.saveas(path, encoding="utf-8")


def _add(msp, it, align):
    """One primitive as its DXF entity."""
    if isinstance(it, Text):
        attribs = {"layer": TEXT_LAYER, "style": TEXT_STYLE}
        if it.squeeze != 1.0:
            attribs["width"] = it.squeeze
        e = msp.add_text(it.text, height=it.height, rotation=it.angle, dxfattribs=attribs)
        return e.set_placement((it.x, it.y), align=align[(it.halign, it.valign)])
    layer = LAYERS[it.line][0]
    if isinstance(it, Circle):
        if not it.filled:
            return msp.add_circle(it.centre, it.radius, dxfattribs={"layer": layer})
        h = msp.add_hatch(color=256, dxfattribs={"layer": layer})
        h.set_solid_fill(color=256)
        h.paths.add_edge_path().add_arc(it.centre, it.radius, 0.0, 360.0)
        return h
    if isinstance(it, Polyline):
        if not it.filled:
            return msp.add_lwpolyline(list(it.points), close=it.closed,
                                      dxfattribs={"layer": layer})
        h = msp.add_hatch(color=256, dxfattribs={"layer": layer})
        h.set_solid_fill(color=256)
        h.paths.add_polyline_path(list(it.points), is_closed=True)
        return h
    raise TypeError(f"not a sheet's primitive: {it!r}")


def _fix(doc) -> None:
    """The header's dates, edit time and GUIDs fixed: a rerun gives the same bytes."""
    h = doc.header
    for key in ("$TDCREATE", "$TDUCREATE", "$TDUPDATE", "$TDUUPDATE"):
        h[key] = 2451545.0                                   # 2000-01-01 12:00 (a fixed Julian day)
    for key in ("$TDINDWG", "$TDUSRTIMER"):
        h[key] = 0.0
    for key in ("$FINGERPRINTGUID", "$VERSIONGUID"):
        h[key] = _FIXED_GUID
