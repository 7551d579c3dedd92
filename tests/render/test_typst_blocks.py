"""The typst both writers of the записка share (render/typst_blocks.py): a paragraph, a list
and a formula are the same lines in the plain layout and the ГОСТ one, written once."""
from flywheel.render import report_formats, report_gost
from flywheel.render.blocks import Bullets, Document, Formula, Heading, Paragraph, Table
from flywheel.render.typst_blocks import boxed_literal, literal, markup, typst_block


def test_text_is_string_literals_with_bold_and_subscripts():
    assert literal('a "b" \\ c') == '#"a \\"b\\" \\\\ c"'
    assert literal("") == ""
    assert markup("J_II is **big**") == '#"J"#sub[#"II"]#" is "#strong[#"big"]'
    # the ГОСТ layout keeps a narrow no-break space (thousands) as a box no line breaks
    assert boxed_literal("12\u202f345") == '#"12"#box(width: 0.2em)#"345"'
    assert markup("12\u202f345") == '#"12\u202f345"'


def test_paragraphs_lists_and_formulas_are_the_same_lines_in_both_layouts():
    blocks = [Paragraph("δ = **0.05**"), Bullets(("first", "M_D")), Formula(r"\omega^2")]
    lines = [typst_block(b) for b in blocks]
    assert lines[0] == ['#"δ = "#strong[#"0.05"]']
    assert lines[1] == ['- #"first"', '- #"M"#sub[#"D"]']
    assert lines[2][0].startswith("$ ") and lines[2][0].endswith(" $")
    assert typst_block(Heading(1, "x")) is None
    assert typst_block(Table(1, "t", ("a",), (("1",),))) is None
    doc = Document("T", "ru")
    doc.blocks += [Heading(1, "T"), Heading(2, "1. Раздел"), *blocks]
    plain, gost = report_formats.typst_source(doc), report_gost.typst_source(doc, plots=False)
    for group in lines:
        text = "\n".join(group)
        assert text in plain and text in gost, text


def test_the_first_groups_index_is_upright_as_the_seconds():
    """J_I and ΔT_I (the first group) were set with an italic I beside J_II's upright II in the
    PDF and the DOCX: a Roman numeral index is upright (ГОСТ 2.105); a letter index i stays a
    variable, italic."""
    from flywheel.render import mathfmt

    assert mathfmt.typst(r"J_{I} = \frac{\Delta T}{\delta}").startswith('J_("I") = ')
    assert mathfmt.typst(r"\Delta T_I") == 'Δ T_("I")'
    assert mathfmt.typst(r"J_{II}") == 'J_("II")'
    assert mathfmt.typst(r"m_{i} v_{i}^{2}") == "m_(i) v_(i)^(2)"
    upright = '<m:sub><m:r><m:rPr><m:sty m:val="p"/></m:rPr><m:t xml:space="preserve">I</m:t>'
    assert upright in mathfmt.omml(r"J_{I}")
    assert '<m:sub><m:r><m:t xml:space="preserve">i</m:t>' in mathfmt.omml(r"J_{i}")
    assert '<mrow><mi mathvariant="normal">I</mi></mrow></msub>' in mathfmt.mathml(r"J_{I}")
    assert "<mrow><mi>i</mi></mrow></msub>" in mathfmt.mathml(r"J_{i}")


def test_no_line_opens_with_a_dash():
    """The aggregate's PDF had a line open with «— коэффициент…» (the break fell between «δ»
    and its dash): every writer of a document now sets the space before a dash as a no-break
    space, so the dash stays on the line of the word before it; a dash alone (a table's «—»,
    nothing there) and an en dash are left as they are."""
    import io

    from docx import Document as Docx

    from flywheel.render import mathfmt, report_formats

    assert mathfmt.subscripts("δ — коэффициент") == [("δ\u00a0— коэффициент", False)]
    assert mathfmt.subscripts("ΔT_нб — перепад") == [("ΔT", False), ("нб", True),
                                                    ("\u00a0— перепад", False)]
    assert mathfmt.subscripts("—") == [("—", False)]
    assert mathfmt.subscripts("0 – 1") == [("0 – 1", False)]
    doc = Document("T", "ru")
    doc.blocks += [Heading(1, "T"), Paragraph("где δ — коэффициент неравномерности"),
                   Table(1, "Маховик — размеры", ("форма", "b"), (("диск", "—"),))]
    typst = report_formats.typst_source(doc)
    html = report_formats.html(doc)
    docx_text = "\n".join(p.text for p in Docx(io.BytesIO(report_formats.docx(doc))).paragraphs)
    for text in (typst, html, docx_text):
        assert "δ\u00a0— коэффициент" in text and "δ — " not in text


def test_an_index_that_abbreviates_a_word_is_upright_in_every_writer():
    """ω_ср, ΔT_нб, ω_max: an index that abbreviates a word is set upright (ISO 80000-2), a
    one-letter variable italic. typst and MathML set a many-letter identifier upright; Word's
    OMML had kept a Cyrillic one («ср», «нб») italic beside an upright "max", so the run's
    record and the duty cycle's (\\text{ср}) set the same ω_ср two ways."""
    import re

    from flywheel.render import mathfmt

    om = mathfmt.omml(r"\omega_{ср} = \omega_{max} - \Delta T_{нб}")
    upright = {text for style, text in re.findall(
        r"<m:r>(<m:rPr><m:sty m:val=\"p\"/></m:rPr>)?<m:t xml:space=\"preserve\">([^<]*)</m:t>",
        om) if style}
    assert {"ср", "max", "нб"} <= upright and "ω" not in upright and "T" not in upright, om
    assert '"ср"' in mathfmt.typst(r"\omega_{ср}")                  # typst: upright text
    assert "<mi>ср</mi>" in mathfmt.mathml(r"\omega_{ср}")          # MathML: many letters, upright


def test_a_number_with_grouped_thousands_is_one_number_in_a_formula():
    """«26 741,2 − 2674,12·1,6» (Russian typography: a narrow no-break space between the
    thousands) had been read as 26, a space and 741,2, and typst set the minus after it without
    its spaces («26 741,2−2674,12»): the whole number is one, in every writer."""
    from flywheel.render import mathfmt

    tex = "E = 26\u202f741,2 - 2674,12"
    assert mathfmt.typst(tex) == 'E = "26\u202f741,2" − "2674,12"'
    assert "<mn>26\u202f741,2</mn><mo>−</mo>" in mathfmt.mathml(tex)
    assert mathfmt.plain(tex) == "E = 26\u202f741,2 − 2674,12"
