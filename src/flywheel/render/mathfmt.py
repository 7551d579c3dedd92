"""The report's formulas: a small LaTeX-like notation, parsed once, written as MathML (HTML),
typst math (PDF) and plain Unicode text (Markdown alt text, Word).

The notation is the subset the report writes: letters, digits, operators, Greek letters and
a few symbols by name (``\\omega``, ``\\varphi``, ``\\Delta``, ``\\Sigma``, ``\\cdot``,
``\\oint``, ``\\approx``, ``\\le``), ``_{…}`` and ``^{…}``, ``\\frac{…}{…}``, ``\\sqrt{…}``
and ``\\text{…}`` (words, Cyrillic subscripts).

>>> plain(r"J_{\\text{I}} = \\frac{\\Delta T_{\\text{нб}}}{\\delta \\cdot \\omega_{\\text{ср}}^{2}}")
'J_I = ΔT_нб/(δ·ω_ср²)'
>>> typst(r"\\omega_{\\text{ср}} = 2\\pi n_{1}")
'ω_("ср") = 2 π n_(1)'
"""
from __future__ import annotations

from dataclasses import dataclass
from html import escape

SYMBOLS = {
    "alpha": "α", "beta": "β", "gamma": "γ", "delta": "δ", "varepsilon": "ε", "epsilon": "ε",
    "theta": "θ", "lambda": "λ", "mu": "μ", "pi": "π", "rho": "ρ", "sigma": "σ", "tau": "τ",
    "varphi": "φ", "phi": "φ", "psi": "ψ", "omega": "ω", "Delta": "Δ", "Sigma": "Σ",
    "Phi": "Φ", "Omega": "Ω",
    "cdot": "·", "oint": "∮", "int": "∫", "sum": "Σ", "approx": "≈", "le": "≤", "ge": "≥",
    "minus": "−", "times": "×", "infty": "∞", "prime": "′",
}
_OPERATORS = set("=+−-·×/(),;:≤≥≈∮∫Σ|′[]<>")
_SUP = str.maketrans("0123456789+−-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁺⁻⁻")
_SUB_DIGITS = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


def point_name(name: str) -> str:
    """A point's name as a figure letters it in plain text, its trailing digits a subscript
    as the course and the drawing sheets write them: "S3" → "S₃", "B1" → "B₁"; "B", "AB",
    "12" as they are.

    >>> point_name("S3"), point_name("S12"), point_name("B"), point_name("12")
    ('S₃', 'S₁₂', 'B', '12')
    """
    m = _re.match(r"^(.*?[^\d_])(\d+)$", name)
    return m.group(1) + m.group(2).translate(_SUB_DIGITS) if m else name


@dataclass(frozen=True)
class Node:
    """``kind``: "i" (identifier), "n" (number), "o" (operator), "t" (text), "row", "sub",
    "sup", "subsup", "frac", "sqrt"; ``text`` of a leaf, ``kids`` of the others."""

    kind: str
    text: str = ""
    kids: tuple = ()


def _tokens(src: str) -> list[str]:
    out, i = [], 0
    while i < len(src):
        c = src[i]
        if c == "\\":
            j = i + 1
            while j < len(src) and src[j].isalpha():
                j += 1
            out.append(src[i:j] if j > i + 1 else src[i:i + 2])
            i = max(j, i + 2) if j == i + 1 else j
        elif c.isdigit() or (c == "." and i + 1 < len(src) and src[i + 1].isdigit()):
            j = i
            while j < len(src) and (src[j].isdigit() or (src[j] in ".,\u202f" and j + 1 < len(src)
                                                          and src[j + 1].isdigit())):
                j += 1                   # a decimal comma and a thousands' narrow space (Russian
                #                          typography: «26 741,2») stay in the number
            out.append(src[i:j])
            i = j
        elif c.isalpha():
            j = i
            while j < len(src) and src[j].isalpha():
                j += 1
            out.append(src[i:j])
            i = j
        else:
            out.append(c)
            i += 1
    return out


class _Parser:
    def __init__(self, src: str):
        self.src = src
        self.tok = _tokens(src)
        self.i = 0

    def peek(self):
        return self.tok[self.i] if self.i < len(self.tok) else None

    def take(self):
        t = self.peek()
        self.i += 1
        return t

    def group(self) -> Node:
        """``{…}`` or one atom."""
        if self.peek() == "{":
            self.take()
            row = self.row("}")
            self.take()
            return row
        return self.atom()

    def text_group(self) -> str:
        assert self.take() == "{", f"\\text needs {{…}} in {self.src!r}"
        out, depth = [], 1
        while True:
            t = self.take()
            if t is None:
                # library use only: no CLI input reaches this
                raise ValueError(f"unclosed \\text in {self.src!r}")
            depth += (t == "{") - (t == "}")
            if depth == 0:
                return "".join(out)
            out.append(t)

    def atom(self) -> Node:
        t = self.take()
        if t is None:
            # library use only: no CLI input reaches this
            raise ValueError(f"formula ends too early: {self.src!r}")
        if t.startswith("\\") and len(t) > 1:
            name = t[1:]
            if name == "frac":
                return Node("frac", kids=(self.group(), self.group()))
            if name == "sqrt":
                return Node("sqrt", kids=(self.group(),))
            if name in ("text", "mathrm"):
                return Node("t", self.text_group())
            if name in (",", " ", ";"):
                return Node("o", " ")
            if name in ("{", "}"):
                return Node("o", name)
            if name not in SYMBOLS:
                # library use only: no CLI input reaches this
                raise ValueError(f"unknown command \\{name} in {self.src!r}")
            s = SYMBOLS[name]
            return Node("o" if s in _OPERATORS else "i", s)
        if t[0].isdigit() or t[0] == ".":
            return Node("n", t)
        if t == "-":
            return Node("o", "−")
        return Node("o" if t in _OPERATORS else "i", t)

    def row(self, end: str | None = None) -> Node:
        kids = []
        while self.peek() is not None and self.peek() != end:
            if self.peek() == " ":
                self.take()
                continue
            base = self.atom() if self.peek() != "{" else self.group()
            sub = sup = None
            while self.peek() in ("_", "^"):
                if self.take() == "_":
                    sub = self.group()
                else:
                    sup = self.group()
            if sub is not None and sup is not None:
                base = Node("subsup", kids=(base, sub, sup))
            elif sub is not None:
                base = Node("sub", kids=(base, sub))
            elif sup is not None:
                base = Node("sup", kids=(base, sup))
            kids.append(base)
        return Node("row", kids=tuple(kids))


def parse(src: str) -> Node:
    """The tree of a formula string (ValueError on what the notation does not have)."""
    return _Parser(src).row()


# -- MathML ---------------------------------------------------------------------------------------
def _mml(n: Node) -> str:
    k = n.kind
    if k == "i":
        return f'<mi>{escape(n.text)}</mi>'
    if k == "n":
        return f"<mn>{escape(n.text)}</mn>"
    if k == "o":
        return "<mspace width=\"0.2em\"/>" if n.text == " " else f"<mo>{escape(n.text)}</mo>"
    if k == "t":
        return f"<mtext>{escape(n.text)}</mtext>"
    inner = "".join(_mml(c) for c in n.kids)
    tag = {"row": "mrow", "sub": "msub", "sup": "msup", "subsup": "msubsup", "frac": "mfrac",
           "sqrt": "msqrt"}[k]
    if k in ("sub", "sup", "subsup", "frac"):
        parts = [f"<mrow>{_mml(c)}</mrow>" if c.kind != "row" else _mml(c) for c in n.kids]
        if k in ("sub", "subsup") and _roman_one(n.kids[1]):
            parts[1] = '<mrow><mi mathvariant="normal">I</mi></mrow>'
        inner = "".join(parts)
    return f"<{tag}>{inner}</{tag}>"


def mathml(src: str, display: bool = True) -> str:
    """The formula as presentation MathML (no namespace URL: HTML5 knows <math>)."""
    return (f'<math display="{"block" if display else "inline"}">'
            f"{_mml(parse(src))}</math>")


# -- typst ----------------------------------------------------------------------------------------
def _roman_one(n: Node) -> bool:
    """A subscript that is the Roman numeral I (J_I, ΔT_I: the first group of links), set
    upright as II, III are (ISO 80000-2, ГОСТ 2.105: an index that is not a variable is
    upright); a lone letter is otherwise a variable, italic."""
    while n.kind == "row" and len(n.kids) == 1:
        n = n.kids[0]
    return n.kind == "i" and n.text == "I"


def _ty(n: Node) -> str:
    k = n.kind
    if k == "i":
        return n.text if len(n.text) == 1 else f'"{n.text}"'
    if k == "n":                         # "0,452", "26 741" as text: typst's math spaces a comma
        return f'"{n.text}"' if "," in n.text or "\u202f" in n.text else n.text
    if k == "o":
        return {"/": "\\/", " ": "thin", ",": "\\,", "(": "\\(", ")": "\\)", "[": "\\[",
                "]": "\\]", ";": "\\;", "|": "|"}.get(n.text, n.text)
    if k == "t":
        return '"' + n.text.replace("\\", "\\\\").replace('"', '\\"') + '"'
    if k == "row":
        return " ".join(_ty(c) for c in n.kids)
    a = [_ty(c) for c in n.kids]
    if k in ("sub", "subsup") and _roman_one(n.kids[1]):
        a[1] = '"I"'                      # upright as the longer group numbers, "II"
    if k == "sub":
        return f"{a[0]}_({a[1]})"
    if k == "sup":
        return f"{a[0]}^({a[1]})"
    if k == "subsup":
        return f"{a[0]}_({a[1]})^({a[2]})"
    if k == "frac":
        return f"frac({a[0]}, {a[1]})".replace(", ,", ", \\,")
    return f"sqrt({a[0]})"


def typst(src: str) -> str:
    """The formula as typst math (the inside of ``$ … $``)."""
    return _ty(parse(src))


# -- plain text -----------------------------------------------------------------------------------
def _simple(n: Node) -> bool:
    return n.kind != "row" or (len(n.kids) == 1 and _simple(n.kids[0])) or all(
        c.kind in ("i", "n", "t", "sub", "sup", "subsup") for c in n.kids)


def _pl(n: Node) -> str:
    k = n.kind
    if k in ("i", "n", "o", "t"):
        return n.text
    if k == "row":
        out = ""
        for c in n.kids:
            s = _pl(c)
            if c.kind == "o" and c.text in "=≈≤≥+−" and c.text:
                out = out.rstrip() + f" {s} "
            else:
                out += s
        return out.strip()
    a = [_pl(c) for c in n.kids]
    if k in ("sup", "subsup"):
        sup = a[-1]
        sup = sup.translate(_SUP) if all(ch in "0123456789+−-" for ch in sup) else f"^{sup}"
        base = a[0] + (f"_{a[1]}" if k == "subsup" else "")
        return base + sup
    if k == "sub":
        return f"{a[0]}_{a[1]}"
    if k == "frac":
        num = a[0] if _simple(n.kids[0]) else f"({a[0]})"
        den = a[1] if _simple(n.kids[1]) else f"({a[1]})"
        return f"{num}/{den}"
    return f"√({a[0]})"


def plain(src: str) -> str:
    """The formula as one line of Unicode text (Word, the Markdown's alt text)."""
    return _pl(parse(src))


# -- OMML (Word's native equations) ---------------------------------------------------------------
OMML_NS = "http://schemas.openxmlformats.org/officeDocument/2006/math"
_W_NS = "http://schemas.openxmlformats.org/wordprocessingml/2006/main"


def _om_run(text: str, plain: bool) -> str:
    """One math run; a one-letter identifier (a variable) keeps Word's math italic; numbers,
    operators, words and a many-letter identifier — an index that abbreviates a word, «ср»,
    «нб», "max" (ISO 80000-2, as typst and MathML set it) — upright."""
    sty = '<m:rPr><m:sty m:val="p"/></m:rPr>' if plain else ""
    return f'<m:r>{sty}<m:t xml:space="preserve">{escape(text, quote=False)}</m:t></m:r>'


def _om(n: Node) -> str:
    k = n.kind
    if k == "i":
        return _om_run(n.text, plain=len(n.text) > 1)
    if k in ("n", "o", "t"):
        return _om_run(n.text, plain=True)
    if k == "row":
        return "".join(_om(c) for c in n.kids)
    a = [_om(c) for c in n.kids]
    if k in ("sub", "subsup") and _roman_one(n.kids[1]):
        a[1] = _om_run("I", plain=True)
    if k == "sub":
        return f"<m:sSub><m:e>{a[0]}</m:e><m:sub>{a[1]}</m:sub></m:sSub>"
    if k == "sup":
        return f"<m:sSup><m:e>{a[0]}</m:e><m:sup>{a[1]}</m:sup></m:sSup>"
    if k == "subsup":
        return f"<m:sSubSup><m:e>{a[0]}</m:e><m:sub>{a[1]}</m:sub><m:sup>{a[2]}</m:sup></m:sSubSup>"
    if k == "frac":
        return f"<m:f><m:num>{a[0]}</m:num><m:den>{a[1]}</m:den></m:f>"
    return f'<m:rad><m:radPr><m:degHide m:val="1"/></m:radPr><m:deg/><m:e>{a[0]}</m:e></m:rad>'


def omml(src: str) -> str:
    """The formula as Office Math (OMML, ECMA-376 part 1 §22.1): an ``m:oMathPara`` element
    that Word (and LibreOffice) show as an editable equation — fractions, sub- and superscripts,
    radicals, Greek letters; written directly for this notation's small tree (no XSLT).

    >>> x = omml(r"\\frac{\\omega}{2}")
    >>> x[x.index("<m:f>"):x.index("</m:f>") + 6]
    '<m:f><m:num><m:r><m:t xml:space="preserve">ω</m:t></m:r></m:num><m:den><m:r><m:rPr><m:sty m:val="p"/></m:rPr><m:t xml:space="preserve">2</m:t></m:r></m:den></m:f>'
    """
    return (f'<m:oMathPara xmlns:m="{OMML_NS}" xmlns:w="{_W_NS}"><m:oMath>'
            f"{_om(parse(src))}</m:oMath></m:oMathPara>")


def omml_inline(src: str) -> str:
    """The formula as an ``m:oMath`` element in a line of a paragraph (a formula numbered by
    tabs beside it, ГОСТ 7.32-2017, 6.8.3)."""
    return f'<m:oMath xmlns:m="{OMML_NS}" xmlns:w="{_W_NS}">{_om(parse(src))}</m:oMath>'


# -- symbols in running text: their subscripts (the report's prose, tables; the figures) ----------
import re as _re

#: a symbol's subscript in running text: a symbol of one to three letters (ΔT, dJ, p, ω) at a
#: word's start, "_", then up to four letters or digits (or a braced group) ending the word —
#: J_II, M_Д, ΔT_нб, ω_ср, v_qS2, p/p_max, R_{12}; not an identifier (flywheel_rim, at_deg in
#: backticks, a.b_c, plots/J_II.png, x_y_z); a Roman shaft number after a dot stays in the
#: subscript (J_пр.I)
_L = "0-9A-Za-zА-Яа-яЁёΑ-Ωα-ω"         # a subscript's letters and digits (not ², ³: they stay)
_SUB_RX = _re.compile(r"(?<![\w.`\\])([^\W\d_][^\W\d_]{0,2})_"
                      r"(\{[^{}\s]{1,12}\}|[" + _L + r"]{1,4}(?:\.[IVX]{1,3})?)"
                      r"(?![" + _L + r"_`])(?!\.\w)")


#: " — " as the documents write it: the space before the dash a no-break space, so a line may
#: end with the dash but never open with it (the rule of Russian typesetting that a dash inside
#: a sentence stays on the line of the word before it: Мильчин А. Э., Чельцова Л. К.
#: Справочник издателя и автора, the chapter on typesetting)
NO_BREAK_DASH = "\u00a0\u2014 "


def subscripted(base: str, sub: str) -> str:
    """``base`` with the subscript ``sub`` as the record's text writes a symbol, for
    :func:`subscripts` to read back: braces only where the subscript is over four letters.

    >>> subscripted("l", "AB"), subscripted("l", "A1B1S")
    ('l_AB', 'l_{A1B1S}')
    """
    return f"{base}_{sub}" if len(sub) <= 4 else f"{base}_{{{sub}}}"


def subscripts(text: str) -> list[tuple[str, bool]]:
    """``text`` cut into runs (text, is a subscript) at its symbols' subscripts, the "_" (and a
    subscript's braces) dropped; text without a symbol's subscript is one run. The space before
    a dash becomes a no-break space (:data:`NO_BREAK_DASH`): no line of a document, a figure or
    a sheet opens with «—».

    >>> subscripts("J_I = ΔT_нб/(δ·ω_m²)")
    [('J', False), ('I', True), (' = ΔT', False), ('нб', True), ('/(δ·ω', False), ('m', True), ('²)', False)]
    >>> subscripts("`results.flywheel_rim` in summary.json")
    [('`results.flywheel_rim` in summary.json', False)]
    """
    text = text.replace(" — ", NO_BREAK_DASH)
    out: list[tuple[str, bool]] = []
    pos = 0
    for m in _SUB_RX.finditer(text):
        if text.count("`", 0, m.start()) % 2:        # inside `code`: left alone
            continue
        out.append((text[pos:m.end(1)], False))
        sub = m.group(2)
        out.append((sub[1:-1] if sub.startswith("{") else sub, True))
        pos = m.end()
    if pos < len(text) or not out:
        out.append((text[pos:], False))
    return [(s, b) for s, b in out if s] or [(text, False)]


def sub_html(text: str) -> str:
    """``text`` as escaped HTML with its symbols' subscripts in <sub>."""
    return "".join(f"<sub>{escape(s, quote=False)}</sub>" if b else escape(s, quote=False)
                   for s, b in subscripts(text))


def sub_mathtext(text: str) -> str:
    """``text`` for a matplotlib label with its symbols' subscripts as mathtext ("M_D (driving)"
    → "M$_\\mathregular{D}$ (driving)": upright, in the label's font). A "$" in ``text``
    is escaped."""
    runs = subscripts(text)
    if len(runs) == 1:
        return text
    return "".join(r"$_\mathregular{" + s + "}$" if b else s.replace("$", r"\$")
                   for s, b in runs)
