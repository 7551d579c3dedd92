"""The figures' simple mathtext labels parsed without pyparsing (issue 26): a label whose
``$…$`` parts set only symbols — letters (Latin, Greek by name, Cyrillic), digits, a few
operators and brackets — with subscripts or superscripts of one symbol or of a ``{…}`` group
of them, and thin spaces (``\\,``), as in ``$\\Delta T_{I\\,max}$ = 843.88 J``. matplotlib's
grammar (pyparsing, 4 ms a label, each worker parsing every label it draws once) is replaced
for those by a reading of the string that calls the same parser's own actions (the symbols'
spacing, the sub- and superscripts' placing, the groups) in the order pyparsing calls them,
so the boxes, the glyphs and every side effect on the fonts are the same (tested against
matplotlib's parse, box by box). Anything else — fractions, fonts, accents, ``\\left``, a space
right after ``_`` (pyparsing reads it as a symbol), an unknown command — is left to
matplotlib's parser. :func:`install` puts it in place within render/figure.py's ``style()``.
"""
from __future__ import annotations

import re

_SPACES = (r"\,", r"\;", r"\:", r"\!")          # thin to thick, negative: Parser._space_widths
# Greek letters by name (matplotlib's tex2uni has them all); none is an accent, a font, a
# function or a space command, which matplotlib's grammar would try before a symbol
_GREEK = frozenset("""alpha beta gamma delta epsilon varepsilon zeta eta theta vartheta iota
    kappa lambda mu nu xi pi varpi rho varrho sigma varsigma tau upsilon phi varphi chi psi
    omega Gamma Delta Theta Lambda Xi Pi Sigma Upsilon Phi Psi Omega""".split())
_PLAIN = frozenset("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789"
                   "+-*/<>=:,.;!?&@()[]|")
_COMMAND = re.compile(r"\\([A-Za-z]+)")
_MATH = re.compile(r"(\$[^$]+\$)")


def _symbol(m: str, i: int):
    """The symbol of the math string ``m`` at ``i`` and the index after it, or None: one
    character of :data:`_PLAIN` or beyond ASCII (as matplotlib's symbol pattern takes them), or
    a Greek letter's command."""
    c = m[i] if i < len(m) else ""
    if c == "\\":
        found = _COMMAND.match(m, i)
        if found and found.group(1) in _GREEK:
            return ("sym", found.group(0), i), found.end()
        return None
    if c in _PLAIN or (c and 0x80 <= ord(c) <= 0x1FFFF and not c.isspace()):
        return ("sym", c, i), i + 1
    return None


def _atom(m: str, i: int):
    """A symbol or a space command at ``i``, and the index after it, or None."""
    for space in _SPACES:
        if m.startswith(space, i):
            return ("space", space), i + len(space)
    return _symbol(m, i)


def _skip(m: str, i: int) -> int:
    """Past the spaces at ``i`` (pyparsing skips them before a token)."""
    while i < len(m) and m[i] == " ":
        i += 1
    return i


def _script(m: str, i: int):
    """The argument of ``_`` or ``^`` at ``i`` (no space before it): a symbol, or a ``{…}``
    group of symbols and spaces; and the index after it, or None."""
    if m[i:i + 1] == "{":
        atoms, i = [], _skip(m, i + 1)
        while i < len(m) and m[i] != "}":
            found = _atom(m, i)
            if found is None:
                return None
            atoms.append(found[0])
            i = _skip(m, found[1])
        if i >= len(m) or not atoms:
            return None
        return ("group", atoms), i + 1
    return _symbol(m, i)


def read_math(m: str):
    """The tokens of the math string ``m`` (between its ``$``s), each a space command, a
    symbol, or a symbol with its sub- and superscripts; None if ``m`` is not that simple."""
    tokens, i = [], _skip(m, 0)
    while i < len(m):
        found = _atom(m, i)
        if found is None:
            return None
        token, i = found
        scripts = []
        while m[i:i + 1] in ("_", "^"):
            if token[0] != "sym" or m[i] in (op for op, _ in scripts):
                return None                     # a space's script, a double script
            found = _script(m, i + 1)
            if found is None:
                return None
            scripts.append((m[i], found[0]))
            i = found[1]
        tokens.append(("scripts", token, scripts) if scripts else token)
        i = _skip(m, i)
    return tokens or None


def read(s: str):
    """The pieces of the label ``s``: plain text and math strings' tokens, alternately,
    starting and ending with plain text (as matplotlib's grammar splits it); None if any math
    string is not simple, or the label holds what the grammar treats apart (escaped ``$``, tabs,
    line breaks)."""
    if "\\$" in s or "\t" in s or "\n" in s or "\r" in s or s.count("$") % 2:
        return None
    parts = _MATH.split(s)
    pieces = []
    for k, part in enumerate(parts):
        if k % 2:
            tokens = read_math(part[1:-1])
            if tokens is None:
                return None
            pieces.append((part[1:-1], tokens))
        elif "$" in part:                      # "$$": not a math string
            return None
        else:
            pieces.append(part)
    return pieces


class _Tokens(list):
    """The tokens handed to an action that reads them with ``as_list`` (pyparsing's results)."""

    def as_list(self):
        return list(self)


def _run_atom(parser, m: str, atom):
    """A symbol's or a space's nodes, made by the parser's action for it."""
    if atom[0] == "space":
        return parser.space({"space": atom[1]})
    _, c, loc = atom
    return parser.symbol(m, loc, {"sym": c})


def _run_script(parser, m: str, arg):
    """A script's node: a symbol's, or a group's (its state pushed and popped as the
    grammar's ``{`` and ``}`` do)."""
    if arg[0] == "sym":
        (node,) = _run_atom(parser, m, arg)
        return node
    parser.start_group({})
    nodes = []
    for atom in arg[1]:
        nodes.extend(_run_atom(parser, m, atom))
    parser.end_group()
    (node,) = parser.group({"group": nodes})
    return node


def _run_math(parser, m: str, tokens):
    """The math string's Hlist, as ``Parser.math`` makes it (and pops the state)."""
    nodes = []
    for token in tokens:
        if token[0] != "scripts":
            nodes.extend(_run_atom(parser, m, token))
            continue
        _, symbol, scripts = token
        (nucleus,) = _run_atom(parser, m, symbol)
        pairs = []
        for op, arg in scripts:
            pairs += [op, _run_script(parser, m, arg)]
        made = parser.subsuper(m, symbol[2], {"nucleus": nucleus, "subsuper": pairs,
                                              "apostrophes": ""})
        nodes.extend(made if isinstance(made, list) else [made])
    (hlist,) = parser.math(_Tokens(nodes))
    return hlist


def parse(parser, s: str, fonts_object, fontsize: float, dpi: float):
    """``parser.parse(s, …)`` (a matplotlib ``_mathtext.Parser``) for a simple label: its
    top Hlist made by the parser's actions, with the parser's state set up and cleared as its
    ``parse`` does; None if ``s`` is not simple (nothing touched then)."""
    pieces = read(s)
    if pieces is None:
        return None
    from matplotlib._mathtext import ParserState

    parser._state_stack = [ParserState(fonts_object, "default", "rm", fontsize, dpi)]
    parser._em_width_cache = {}
    try:
        nodes = []
        for k, piece in enumerate(pieces):
            if k % 2:
                nodes.append(_run_math(parser, *piece))
            else:
                nodes.extend(parser.non_math([piece]))
        (top,) = parser.main(_Tokens(nodes))
    finally:
        parser._state_stack = []
        parser._needs_space_after_subsuper = False
        parser._em_width_cache = {}
    return top


def install():
    """Within render/figure.py's ``style()``: matplotlib's mathtext parser reads the simple
    labels by :func:`parse`, the others as before (where this matplotlib's parser lacks the
    actions :func:`parse` calls, nothing changes), and the glyphs' metrics are shared by every
    parse (:func:`_share_glyph_infos`). Returns the function that undoes both."""
    from matplotlib import _mathtext

    restore_infos = _share_glyph_infos(_mathtext)
    cls = getattr(_mathtext, "Parser", None)
    needed = ("parse", "symbol", "space", "subsuper", "start_group", "end_group", "group",
              "math", "non_math", "main")
    if cls is None or not all(hasattr(cls, name) for name in needed) \
            or not hasattr(_mathtext, "ParserState"):
        return restore_infos
    own = cls.__dict__["parse"]

    def quick(self, s, fonts_object, fontsize, dpi):
        try:
            top = parse(self, s, fonts_object, fontsize, dpi)
        except Exception:                   # an unknown glyph …: matplotlib's own error
            top = None
        return own(self, s, fonts_object, fontsize, dpi) if top is None else top

    cls.parse = quick

    def restore() -> None:
        cls.parse = own
        restore_infos()
    return restore


def _share_glyph_infos(_mathtext):
    """A glyph's metrics for mathtext (FreeType loading it: a third of a parse) read once for
    every parse, not once per parse: matplotlib keeps them per set of fonts, and each parse
    makes a new set. The glyph is found as matplotlib finds it (its font object, its index in
    the font, whether slanted) and its font sized as matplotlib sizes it — kerning reads the
    font's size — and the metrics kept by that glyph, size, dpi, loading flags and font set's
    class. matplotlib's own cache per font set stays in front of this one, so each font set
    sizes its fonts exactly when it would have. Returns the function that undoes it."""
    cls = getattr(_mathtext, "TruetypeFonts", None)
    own = None if cls is None else cls.__dict__.get("_get_info")
    if own is None or not hasattr(cls, "_get_glyph"):
        return lambda: None
    infos: dict = {}
    most = 20000                      # emptied rather than grown past it, as figure's caches

    def get_info(self, fontname, font_class, sym, fontsize, dpi):
        font, num, slanted = self._get_glyph(fontname, font_class, sym)
        font.set_size(fontsize, dpi)
        key = (type(self), font, num, slanted, fontsize, dpi,
               getattr(self, "load_glyph_flags", None))
        found = infos.get(key)
        if found is None:
            if len(infos) > most:
                infos.clear()
            found = infos[key] = own(self, fontname, font_class, sym, fontsize, dpi)
        return found

    cls._get_info = get_info

    def restore() -> None:
        cls._get_info = own
    return restore
