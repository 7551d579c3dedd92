"""render/mathparse.py: the simple mathtext labels read without pyparsing give matplotlib's
own parse — the same boxes (every node's kind, size, shift, glue, glyph and font) and the same
glyphs placed — and the others are left to matplotlib's parser; the glyphs' metrics are loaded
once for every parse. Work is counted, not timed."""
from __future__ import annotations

import pytest

pytest.importorskip("matplotlib")

from flywheel.render import figure as fg  # noqa: E402
from flywheel.render import figure_cache  # noqa: E402
from flywheel.render import mathparse  # noqa: E402

# the forms the figures' labels take (render/nomenclature.py's symbols, plots' sentences),
# Russian subscripts, operators that matplotlib spaces, punctuation it spaces or not
SIMPLE = [
    r"$J_I$", r"$J_{II}$ [kg·m²]", r"$\Delta T_{I\,max}$ = 843.88 J at φ = 224.3°",
    r"$\Delta T_{нб}$ = 916.28 J", r"$M_Д$ [N·m]", r"$\omega_{ср}$ = 52,3 рад/с",
    r"$J = J_I + J_{II}$", r"$T = T_0 + \Delta T$", r"$\Delta T = A(\varphi)$ [J]",
    r"$|R_{ij}|(\varphi)$", r"$|v_{qS1}|$", r"$-J_I\varepsilon$", r"$p/p_{max}$",
    r"$dJ_{II}/d\varphi$", r"$M_{y,gr}$", r"$R_{0,p1}$ (O)", r"$x_a^b$ and $x^b_a$",
    r"$-x = -1, 2.5; y$", r"$a_{ b }$", r"$\alpha\beta_{\gamma\,\delta}$", r"$a b$",
    "plain words only", "", r"$S$ of slider 3 (point B) from its outer dead centre",
    r"$\mu_F$ = 10 N/mm, $\mu_v$ = 0.01 m/s/mm", r"$(a)|b|[c]$ $1+2-3*4/5<6>7=8:9,0.1;!?&@$",
    r"$\Phi_x$, $\Sigma$, $\psi_{min}$",
]
# what pyparsing reads otherwise than this reading would, or what it does not read: left to it
LEFT = [r"p / p$_\mathregular{max}$", r"$a_ b$", r"$a_{}$", "$$", "a $b", r"$\frac{a}{b}$",
        r"$\Deltax$", r"$a_b_c$", r"$x'$", r"$\,_a$", r"$\mathrm{d}x$", r"$\sin x$",
        r"$\hat{a}$", r"$a~b$", "$a$\t", r"100\$ and $a$", r"$\left(a\right)$", r"$a_{b_c}$",
        r"$\sqrt{2}$", r"$\text{ab}$"]


def _tree(node):
    """Everything of a parse's node that its drawing reads, and its children's."""
    out = [type(node).__name__]
    for name in ("c", "font", "font_class", "fontsize", "width", "height", "depth",
                 "shift_amount", "glue_set", "glue_sign", "glue_order", "_metrics"):
        if hasattr(node, name):
            out.append((name, getattr(node, name)))
    if hasattr(node, "children"):
        out.append([_tree(child) for child in node.children])
    return out


def _parses(parse, labels, size=9.0, dpi=120):
    """Each label parsed by ``parse`` with a new set of fonts (as matplotlib parses each
    string), as its boxes and its glyphs placed; None where ``parse`` gives None."""
    from matplotlib import _mathtext
    from matplotlib.backends.backend_agg import get_hinting_flag
    from matplotlib.font_manager import FontProperties

    parser = _mathtext.Parser()
    out = []
    for s in labels:
        fonts = _mathtext.DejaVuSansFonts(FontProperties(size=size), get_hinting_flag())
        box = parse(parser, s, fonts, size, dpi)
        out.append(None if box is None else (_tree(box), _mathtext.ship(box).to_vector()))
    return out


def _matplotlibs_own(labels, size=9.0, dpi=120):
    """The labels parsed by matplotlib alone (pyparsing, none of the style's caches), in the
    style's font settings."""
    import matplotlib
    from matplotlib import _mathtext

    with matplotlib.rc_context():
        matplotlib.rcdefaults()
        matplotlib.rcParams.update(fg.RC)
        return _parses(_mathtext.Parser.parse, labels, size, dpi)


@pytest.mark.parametrize("size", [9.0, 6.3])
def test_simple_labels_give_matplotlibs_own_parse(size):
    reference = _matplotlibs_own(SIMPLE, size)
    with fg.style():                          # the glyph metrics shared, as in the figures
        ours = _parses(mathparse.parse, SIMPLE, size)
        again = _parses(mathparse.parse, SIMPLE, size)   # every glyph's metrics shared now
    assert None not in ours
    for s, a, b, c in zip(SIMPLE, reference, ours, again):
        assert a == b == c, s


def _labels_figure() -> bytes:
    """A figure of every simple label, in three sizes, as a PNG."""
    import io

    fig, ax = fg.figure((8.0, 9.0), right=0.3)
    ax.set_axis_off()
    for k, s in enumerate(SIMPLE):
        fig.text(0.02, 0.97 - k * 0.034, s, fontsize=(9.0, 8.0, 11.0)[k % 3])
    out = io.BytesIO()
    fg.save(fig, out)
    return out.getvalue()


def test_simple_labels_drawn_with_matplotlibs_pixels():
    import matplotlib

    with matplotlib.rc_context(), figure_cache.whole_texts():
        matplotlib.rcdefaults()
        matplotlib.rcParams.update(fg.RC)
        reference = _labels_figure()   # pyparsing, texts drawn whole, none of the caches
    with fg.style():
        assert _labels_figure() == reference


def test_other_labels_left_to_matplotlibs_parser():
    assert all(mathparse.read(s) is None for s in LEFT)
    assert _parses(mathparse.parse, LEFT) == [None] * len(LEFT)
    assert all(mathparse.read(s) is not None for s in SIMPLE)


def test_reading_splits_as_matplotlibs_grammar():
    """Plain text and math strings alternate, plain first and last; spaces between a math
    string's tokens skipped; a symbol's place kept (matplotlib spaces an operator by it)."""
    pieces = mathparse.read(r"$\Delta T_{I\,max}$ = 8")
    assert pieces[0] == "" and pieces[2] == " = 8"
    m, tokens = pieces[1]
    assert m == r"\Delta T_{I\,max}"
    assert tokens == [("sym", r"\Delta", 0),
                      ("scripts", ("sym", "T", 7),
                       [("_", ("group", [("sym", "I", 10), ("space", r"\,"), ("sym", "m", 13),
                                         ("sym", "a", 14), ("sym", "x", 15)]))])]


def test_labels_in_a_style_go_to_pyparsing_only_when_not_simple(monkeypatch):
    """Drawn in a figure within the style, the simple labels never reach pyparsing's parse;
    the others do, once each — and their pixels are matplotlib's own (test_figure_cost)."""
    import io

    from matplotlib import _mathtext

    read: list[str] = []
    own = _mathtext.Parser.parse

    def counting(self, s, *args, **kw):
        read.append(s)
        return own(self, s, *args, **kw)

    monkeypatch.setattr(_mathtext.Parser, "parse", counting)
    with fg.style():
        fig, ax = fg.figure((6.0, 3.0), right=0.3)
        ax.plot([0, 1], [0, 1], label=r"$\omega_{q}(\varphi)$ of link 2")
        ax.plot([0, 1], [1, 0], label=r"$\frac{a}{b}$")
        ax.set_xlabel(r"$\Delta T_{I\,max}$ [J]")
        ax.legend()
        fg.save(fig, io.BytesIO())
    assert read == [r"$\frac{a}{b}$"]


def test_glyph_metrics_loaded_once_for_every_parse(monkeypatch):
    """A label parsed again with a new set of fonts (a new figure's) loads no glyph."""
    from matplotlib.ft2font import FT2Font

    loaded: list[int] = []
    own = FT2Font.load_glyph

    def counting(self, index, *args, **kw):
        loaded.append(index)
        return own(self, index, *args, **kw)

    monkeypatch.setattr(FT2Font, "load_glyph", counting)
    with fg.style():
        _parses(mathparse.parse, [r"$\Delta T_{I\,max}$ = 843.88 J qwz"])
        first = len(loaded)
        _parses(mathparse.parse, [r"$\Delta T_{I\,max}$ = 843.88 J qwz"])
    assert first >= len(set("ΔTImax=843.8Jqwz"))
    assert len(loaded) == first


def test_a_symbol_without_a_glyph_gets_matplotlibs_error():
    """A glyph the fonts lack: the style's parse ends as matplotlib's does (its error)."""
    from matplotlib.mathtext import MathTextParser

    errors = []
    for styled in (False, True):
        try:
            if styled:
                with fg.style():
                    MathTextParser("path").parse("$\U0001F9EA_x$")
            else:
                MathTextParser("path").parse("$\U0001F9EA_x$")
        except Exception as err:                 # noqa: BLE001 (whatever matplotlib raises)
            errors.append((type(err), str(err)))
        else:
            errors.append(None)
    assert errors[0] == errors[1]
