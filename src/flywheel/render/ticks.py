"""An axis's ticks made by copying its first tick (issue 26): matplotlib makes each tick of
an axis anew — two tick marks and a grid line (Line2D), two labels (Text), each set up from
the settings one by one (0.5 – 0.7 ms a tick; 750 ticks for the compressor's 22 figures, a
sixth of their time) — and then copies the axis's first tick's properties onto it
(``Axis._copy_tick_props``). Within render/figure.py's ``style()``, a tick after the first is
that first tick's copy instead: each of its five artists a new object with the first's state,
its own callbacks, its own font properties and sticky edges (the state an artist changes in
place); everything else an artist holds is replaced, not changed in place, when it changes.
matplotlib still copies the first tick's properties onto it, and places it and sets its label
before it is drawn, as for a new tick; so the figures are the same, pixel for pixel (tested).
"""
from __future__ import annotations

#: the artists a Tick is made of (matplotlib's Tick.__init__)
PARTS = ("tick1line", "tick2line", "gridline", "label1", "label2")

made = {"copied": 0}      # ticks made by copying, for the tests (work counted, not timed)


def _copy_artist(artist, registry):
    """A new artist of the same class and state as ``artist``, with its own callbacks,
    sticky edges and (a text) font properties."""
    new = object.__new__(type(artist))
    state = dict(artist.__dict__)
    state["_callbacks"] = registry(signals=["pchanged"])
    edges = state.get("_sticky_edges")
    if edges is not None:
        state["_sticky_edges"] = type(edges)(list(edges.x), list(edges.y))
    font = state.get("_fontproperties")
    if font is not None:
        state["_fontproperties"] = font.copy()
    new.__dict__ = state
    return new


def copy_tick(tick, registry):
    """A new tick like ``tick``: its five artists copies (:func:`_copy_artist`)."""
    new = _copy_artist(tick, registry)
    for part in PARTS:
        setattr(new, part, _copy_artist(getattr(tick, part), registry))
    made["copied"] += 1
    return new


def install():
    """``Axis._get_tick`` copies the axis's first tick of the kind asked (major, minor) when
    it has one of matplotlib's own tick classes; otherwise (the first, another class) makes it
    as matplotlib does. Where this matplotlib's Tick or Axis differs from what this copies
    (3.11's), nothing changes. Returns the function that undoes it."""
    from matplotlib import axis, cbook

    own = axis.Axis.__dict__.get("_get_tick")
    if own is None or not hasattr(axis.Axis, "_copy_tick_props") \
            or not hasattr(axis, "_LazyTickList"):
        return lambda: None
    kinds = (axis.XTick, axis.YTick)

    def get_tick(self, major):
        ticks = self.__dict__.get("majorTicks" if major else "minorTicks")
        if ticks and type(ticks[0]) in kinds and type(ticks[0]) is self._tick_class \
                and all(part in ticks[0].__dict__ for part in PARTS):
            return copy_tick(ticks[0], cbook.CallbackRegistry)
        return own(self, major)

    axis.Axis._get_tick = get_tick

    def restore() -> None:
        axis.Axis._get_tick = own
    return restore
