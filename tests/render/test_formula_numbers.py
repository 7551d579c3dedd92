"""The записка's formulas are numbered in every format and cited by their numbers (ГОСТ
7.32-2017, 6.8.3: «Ссылки в тексте на порядковые номера формул дают в скобках»), and a
formula that gives a result shows the numbers put into it (seed 000 §4: J_доп = ΔT/(δ·ω²) −
J_10 − J_ред). The numbers put in are checked by working the formula again from them: they give
the printed result to its last printed digit (the numbers put in to six digits,
numbers.fmt_worked; the Russian policy's four had given fourbar_rocker_load's J_I = 2,654 back
for a printed 2,656)."""
from __future__ import annotations

import io
import math
import re
from functools import lru_cache
from pathlib import Path

import pytest

from flywheel.render.blocks import Bullets, Formula

CASES = Path(__file__).resolve().parents[2] / "cases"


@lru_cache(maxsize=None)
def _document(name: str, lang: str = "ru"):
    from flywheel.cases.run import load_case
    from flywheel.dynamics.pipeline import analyze
    from flywheel.render.document import build_document
    from flywheel.render.numbers import typography

    res = analyze(load_case(CASES / f"{name}.toml"), n_points=720)
    with typography(lang):
        return res, build_document(res, lang)


def _num(text: str) -> float:
    """A number as the record prints it («−1241», «0,05», «4 500»)."""
    return float(text.replace("\u202f", "").replace(",", ".").replace("−", "-"))


def _formulas(doc) -> dict[int, str]:
    tex = [b.tex for b in doc.blocks if isinstance(b, Formula)]
    return {n: t for n, t in enumerate(tex, 1)}


def _cited(doc, pattern: str) -> int:
    """The number of the formula a bullet cites where ``pattern`` (a regex with one group,
    the number) matches."""
    for b in doc.blocks:
        if isinstance(b, Bullets):
            for item in b.items:
                if m := re.search(pattern, item):
                    return int(m.group(1))
    raise AssertionError(pattern)


N = r"(−?[\d\u202f]+(?:,\d+)?)"


def _put(doc) -> tuple[list[int], list[str]]:
    """The formula numbers the «Подстановка найденных значений в формулы …» line cites, and
    the worked formulas after it."""
    from flywheel.render.blocks import Paragraph

    k = next(i for i, b in enumerate(doc.blocks) if isinstance(b, Paragraph)
             and b.text.startswith("Подстановка найденных значений"))
    cited = [int(n) for n in re.findall(r"\((\d+)\)", doc.blocks[k].text)]
    worked = []
    for b in doc.blocks[k + 1:]:
        if not isinstance(b, Formula):
            break
        worked.append(b.tex)
    return cited, worked


def _close(worked: float, printed: str) -> None:
    """``worked`` (from the printed inputs) agrees with ``printed`` to its last digit."""
    digits = len(re.sub(r"\D", "", printed.lstrip("−0,").replace(",", "")))
    assert math.isclose(worked, _num(printed), rel_tol=1.5 * 10 ** (1 - digits)), (worked, printed)


def test_the_flywheel_formulas_show_their_numbers_and_the_text_cites_them():
    res, doc = _document("compressor")
    f = _formulas(doc)
    nJ = _cited(doc, r"по Мерцалову, формула \((\d+)\)")
    nM = _cited(doc, r"маховик, формула \((\d+)\)")
    m = re.search(rf"\\frac\{{{N}\}}\{{{N} \\cdot {N}\^\{{2\}}\}} = {N}", f[nJ])
    dT, delta, w, J = m.groups()
    _close(_num(dT) / (_num(delta) * _num(w) ** 2), J)
    assert _num(delta) == 0.05 and J == "4,642"        # seed 000 (the worksheet): J_PRI 4,64
    m = re.search(rf"= {N} - {N} = {N}", f[nM])
    _close(_num(m.group(1)) - _num(m.group(2)), m.group(3))
    assert _num(m.group(1)) == pytest.approx(_num(J), abs=5e-4) and f[nM].startswith("J_М = ")
    nA = _cited(doc, r"по формуле \((\d+)\); M_Д")
    nMD = _cited(doc, r"M_Д = [^;]* по формуле \((\d+)\)")
    assert r"\oint" in f[nA] and f[nMD].startswith("M_Д = ")
    m = re.search(rf"\\frac\{{{N}\}}\{{2\\pi\}} = {N}", f[nMD])
    _close(_num(m.group(1)) / (2 * math.pi), m.group(2))
    assert _num(m.group(2)) == pytest.approx(res.scalars.driving_moment, rel=1e-3)


def test_an_engine_finds_its_resistance_over_two_turns():
    """A four-stroke engine's cycle is 4π: M_С = −A_Д/Φ = −449,7/(4π)."""
    _, doc = _document("engine_4stroke")
    f = _formulas(doc)
    n = _cited(doc, r"M_С = [^;]* по формуле \((\d+)\)")
    m = re.search(rf"= -\\frac\{{{N}\}}\{{4\\pi\}} = {N}", f[n])
    _close(-_num(m.group(1)) / (4 * math.pi), m.group(2))


def test_a_given_flywheel_adds_up_rather_than_being_sized():
    """compressor_given_flywheel: the record had written the sizing formula J_I = ΔT_нб/(δ·ω²)
    = 4,674 and J_М = J_I − (J_10 + J_ред) = 4 for a flywheel that was given: the formula now
    runs the way the case does, J_I = J_М + (J_10 + J_ред)."""
    _, doc = _document("compressor_given_flywheel")
    f = _formulas(doc)
    n = _cited(doc, r"на валу кривошипа по формуле \((\d+)\)")
    m = re.search(rf"^J_I = J_М \+ \(J_\{{10\}} \+ J_\{{ред\}}\) = {N} \+ {N} = {N}", f[n])
    _close(_num(m.group(1)) + _num(m.group(2)), m.group(3))
    assert not any(r"\delta \cdot" in t for t in f.values())


def test_every_writer_numbers_the_formulas_in_their_order():
    """md, HTML, the plain typst and DOCX number them as the ГОСТ layout does: (1), (2), …"""
    from docx import Document as Docx

    from flywheel.render import report_formats
    from flywheel.render.blocks import Document, Heading, Paragraph
    from flywheel.render.report import markdown

    doc = Document("T", "en")
    doc.blocks += [Heading(1, "T"), Formula(r"a = b"), Paragraph("x"), Formula(r"c = d")]
    assert re.findall(r"\\tag\{(\d)\} \$\$", markdown(doc)) == ["1", "2"]
    page = report_formats.html(doc)
    assert re.findall(r'<span class="eqn">\((\d)\)</span>', page) == ["1", "2"]
    assert '#set math.equation(numbering: "(1)")' in report_formats.typst_source(doc)
    paragraphs = Docx(io.BytesIO(report_formats.docx(doc))).paragraphs
    numbered = [p for p in paragraphs if p._p.xpath(".//m:oMath")]
    assert [p.text.strip() for p in numbered] == ["(1)", "(2)"]
    assert [s.alignment for s in numbered[0].paragraph_format.tab_stops] == [1, 2]  # centre, right


@pytest.mark.parametrize("name", ["task2_seed_triangle", "task2_khurmi_16_4", "task2_khurmi_16_3",
                                  "task2_readme_press"])
def test_task2_puts_its_found_values_into_the_method_formulas(name):
    """Task 2's solution works ω_ср, δ (and J_пр where a δ is asked) with the numbers printed
    in its results table, citing the method's formulas by number; each gives its result again
    from the numbers put in."""
    from flywheel.cases.task2 import load_task2_case, solve_case
    from flywheel.render.numbers import typography
    from flywheel.render.report_task2 import build_task2_document

    case = load_task2_case(CASES / f"{name}.toml")
    r = solve_case(case, name)
    with typography("ru"):
        doc = build_task2_document(r, "T", "S", "ru")
    f = _formulas(doc)
    cited, worked = _put(doc)
    assert r"\delta = \frac{\omega_{max} - \omega_{min}}" in f[cited[0]]
    m = re.search(rf"\\frac\{{{N} \+ {N}\}}\{{2\}} = {N}", worked[0])
    _close((_num(m.group(1)) + _num(m.group(2))) / 2, m.group(3))
    m = re.search(rf"\\delta = \\frac\{{{N} - {N}\}}\{{{N}\}} = {N}", worked[1])
    _close((_num(m.group(1)) - _num(m.group(2))) / _num(m.group(3)), m.group(4))
    if r.J_required is not None:
        assert len(cited) == 2 and r"\delta \omega" in f[cited[1]]
        m = re.search(rf"\\frac\{{{N}\}}\{{{N} \\cdot {N}\^\{{2\}}\}} = {N}", worked[2])
        _close(_num(m.group(1)) / (_num(m.group(2)) * _num(m.group(3)) ** 2), m.group(4))


@pytest.mark.parametrize("name", ["duty_khurmi_16_19_punch", "duty_khurmi_16_22_punch",
                                  "duty_readme_press"])
def test_a_duty_cycles_flywheel_is_worked_with_its_numbers(name):
    """A punching press's flywheel found from its speeds: J = ΔE/(ω_ср²·δ) and m = J/k², the
    numbers put in to six digits, each giving its result again (Khurmi & Gupta Ex. 16.19 prints
    m = 618 kg: 617,94 here)."""
    from flywheel.cases.duty_cycle import load_duty_case, solve_case
    from flywheel.render.numbers import typography
    from flywheel.render.report_duty_cycle import build_duty_cycle_document

    r = solve_case(load_duty_case(CASES / f"{name}.toml"), name)
    with typography("ru"):
        doc = build_duty_cycle_document(r, "T", "S", "ru")
    f = _formulas(doc)
    cited, (dE, J, m) = _put(doc)
    assert r"\Delta E = E - P" in f[cited[0]]
    assert r"\Delta E = \frac{J (\omega_{max}^{2}" in f[cited[1]] and "J = m k^{2}" in f[cited[2]]
    _energy_comes_back(dE, r)
    got = re.search(rf"= \\frac\{{{N}\}}\{{{N}\^\{{2\}} \\cdot {N}\}} = {N}", J)
    _close(_num(got.group(1)) / (_num(got.group(2)) ** 2 * _num(got.group(3))), got.group(4))
    assert _num(got.group(4)) == pytest.approx(r.J, rel=1e-5)
    got = re.search(rf"= \\frac\{{{N}\}}\{{{N}\^\{{2\}}\}} = {N}", m)
    _close(_num(got.group(1)) / _num(got.group(2)) ** 2, got.group(3))
    assert _num(got.group(3)) == pytest.approx(r.mass, rel=1e-5)


def test_a_given_flywheels_speed_after_the_operation_is_worked_with_its_numbers():
    """Khurmi & Gupta Ex. 16.21 gives the riveter's flywheel (150 kg at k = 0,6 m) and its speed
    before riveting: the record works J = m·k² and ω_min = √(ω_max² − 2·ΔE/J) with the numbers
    the tables print, citing formulas (3) and the new one, and n_min = 30·ω_min/π. The FOSSEE
    companion prints N2 = 257.6 rpm; exactly ΔE = 7000 J, ω_min = √((10π)² − 14000/54)."""
    from flywheel.cases.duty_cycle import load_duty_case, solve_case
    from flywheel.render.numbers import typography
    from flywheel.render.report_duty_cycle import build_duty_cycle_document

    name = "duty_khurmi_16_21_riveting"
    r = solve_case(load_duty_case(CASES / f"{name}.toml"), name)
    with typography("ru"):
        doc = build_duty_cycle_document(r, "T", "S", "ru")
    f = _formulas(doc)
    cited, (dE, J, w, n) = _put(doc)
    _energy_comes_back(dE, r)
    assert _num(re.search(rf"= {N}\\,", dE).group(1)) == 7000           # printed: 7000 J
    assert "J = m k^{2}" in f[cited[1]]
    assert f[cited[2]].startswith(r"\omega_{min} = \sqrt{\omega_{max}^{2} - \frac{2 \Delta E}{J}}")
    got = re.search(rf"J = m k\^\{{2\}} = {N} \\cdot {N}\^\{{2\}} = {N}", J)
    _close(_num(got.group(1)) * _num(got.group(2)) ** 2, got.group(3))
    got = re.search(rf"\\sqrt\{{{N}\^\{{2\}} - \\frac\{{2 \\cdot {N}\}}\{{{N}\}}\}} = {N}", w)
    w1, dE, J_, w2 = (_num(got.group(k)) for k in range(1, 5))
    _close(math.sqrt(w1 ** 2 - 2 * dE / J_), got.group(4))
    assert w2 == pytest.approx(math.sqrt((10 * math.pi) ** 2 - 14000 / 54), rel=5e-6)
    got = re.search(rf"n_{{min}} = \\frac\{{30 \\omega_\{{min\}}\}}\{{\\pi\}} = {N}", n)
    assert round(_num(got.group(1)), 1) == 257.6             # printed: 257.6 rpm


def _energy_comes_back(worked: str, r) -> None:
    """ΔE = E − P·t_оп worked from its printed numbers gives the printed ΔE, the result's."""
    got = re.search(rf"= {N} - {N} \\cdot {N} = {N}", worked)
    E, P, t, dE = (_num(got.group(k)) for k in range(1, 5))
    _close(E - P * t, got.group(4))
    assert dE == pytest.approx(r.delta_E, rel=1e-5)


def test_a_flywheel_given_by_its_rim_speeds_is_worked_with_its_numbers():
    """Khurmi & Gupta Ex. 16.20 gives the rim's mean speed (25 m/s) and δ = 0,03, no radius: the
    record works ΔE = E − P·t_оп and m = ΔE/(v_ср²·δ) with the numbers its tables print, citing
    formulas (1) and (3). The FOSSEE companion prints m = 1198 kg; exactly 22 462,6/(625·0,03)."""
    from flywheel.cases.duty_cycle import load_duty_case, solve_case
    from flywheel.render.numbers import typography
    from flywheel.render.report_duty_cycle import build_duty_cycle_document

    name = "duty_khurmi_16_20_punch_stroke"
    r = solve_case(load_duty_case(CASES / f"{name}.toml"), name)
    with typography("ru"):
        doc = build_duty_cycle_document(r, "T", "S", "ru")
    f = _formulas(doc)
    cited, (dE, m) = _put(doc)
    assert r"\Delta E = E - P" in f[cited[0]] and r"\Delta E = m v^{2} \delta" in f[cited[1]]
    _energy_comes_back(dE, r)
    got = re.search(rf"= \\frac\{{{N}\}}\{{{N}\^\{{2\}} \\cdot {N}\}} = {N}", m)
    _close(_num(got.group(1)) / (_num(got.group(2)) ** 2 * _num(got.group(3))), got.group(4))
    assert round(_num(got.group(4))) == 1198                   # printed: 1198 kg


def test_a_line_leading_into_formulas_stays_on_their_page():
    """«Подстановка найденных значений в формулы (3) и (4):» had closed page 4 of Ex. 16.21's
    PDF, its formulas on page 5: the typst of both layouts keeps it with them (a sticky block,
    still a paragraph with its indent) and both DOCX writers set keep-with-next."""
    from docx import Document as Docx

    from flywheel.render import report_formats, report_gost
    from flywheel.render.blocks import Document, Heading, Paragraph

    doc = Document("T", "ru")
    doc.blocks += [Heading(1, "T"), Heading(2, "1. Метод"), Paragraph("Текст."),
                   Paragraph("Подстановка в формулу (1):"), Formula(r"a = b")]
    for source in (report_formats.typst_source(doc), report_gost.typst_source(doc)):
        assert "#block(sticky: true" in source and "#par[" in source
        assert source.count("sticky: true, spacing") == 1          # the lead-in alone
    for data in (report_formats.docx(doc), report_gost.docx(doc)):
        paragraphs = Docx(io.BytesIO(data)).paragraphs
        lead = next(p for p in paragraphs if p.text.startswith("Подстановка"))
        plain = next(p for p in paragraphs if p.text == "Текст.")
        assert lead.paragraph_format.keep_with_next and not plain.paragraph_format.keep_with_next


RUN = sorted(p.stem for p in CASES.glob("*.toml")
             if not p.stem.startswith(("task2", "aggregate", "duty", "variants")))


@pytest.mark.parametrize("name", RUN)
def test_every_run_records_flywheel_comes_back_from_its_numbers(name):
    """Each bundled run case's J_I (or a given flywheel's sum), worked again from the numbers
    its record puts into the formula, is the printed J_I to its last digit."""
    res, doc = _document(name)
    texts = list(_formulas(doc).values())
    sized = [re.search(rf"\\frac\{{{N}\}}\{{{N} \\cdot {N}\^\{{2\}}\}} = {N}", t) for t in texts]
    given = [re.search(rf"^J_I = J_М \+ .* = {N} \+ {N} = {N}", t) for t in texts]
    if m := next((m for m in sized if m), None):
        dT, delta, w, J = m.groups()
        worked = _num(dT) / (_num(delta) * _num(w) ** 2)
    else:
        m = next(m for m in given if m)
        worked, J = _num(m.group(1)) + _num(m.group(2)), m.group(3)
    digits = len(re.sub(r"\D", "", J.lstrip("−0,").replace(",", "")))
    last = 10.0 ** (math.floor(math.log10(abs(_num(J)))) - digits + 1)   # the last digit's unit
    assert abs(worked - _num(J)) <= 0.5 * last * 1.01, (worked, J)


def test_the_two_mass_aggregates_frequency_and_margin_are_worked_with_their_numbers():
    """The seed's two-mass aggregate (seed 003, Ефанов ch. 9): ω = √(c·(J_1 + J_2)/(J_1·J_2))
    and Δ = |1 − ω_вын/ω_n| worked with the numbers of the record's tables, each giving its
    result again; ω is the modal analysis's (an independent route: the eigenvalues of
    K·x = ω²·M·x) to the six digits printed."""
    from flywheel.cases.aggregate import load_aggregate_case, to_model
    from flywheel.elastic.model import analyze
    from flywheel.render.numbers import typography
    from flywheel.render.report_aggregate import build_aggregate_document

    ch, drive = to_model(load_aggregate_case(CASES / "aggregate.toml"))
    r = analyze(ch, drive, t_end=0.2)
    with typography("ru"):
        doc = build_aggregate_document(r, "T", "S", "ru", figure=None)
    from flywheel.render.blocks import Paragraph

    f = _formulas(doc)
    starts = [k for k, b in enumerate(doc.blocks) if isinstance(b, Paragraph)
              and b.text.startswith("Подстановка найденных значений")]
    assert len(starts) == 2
    cited = [int(re.search(r"\((\d+)\)", doc.blocks[k].text).group(1)) for k in starts]
    assert r"\omega = \sqrt{\frac{c (J_{1} + J_{2})}{J_{1} J_{2}}}" == f[cited[0]]
    assert r"\Delta = |1 - \frac{\omega_{\text{вын}}}" in f[cited[1]]
    w, margin = (doc.blocks[k + 1].tex for k in starts)
    got = re.search(rf"\\frac\{{{N} \\cdot \({N} \+ {N}\)\}}\{{{N} \\cdot {N}\}}\}} = {N}", w)
    c, J1, J2 = (_num(got.group(k)) for k in (1, 2, 3))
    _close(math.sqrt(c * (J1 + J2) / (J1 * J2)), got.group(6))
    assert _num(got.group(6)) == pytest.approx(r.modes.omega[-1], rel=1e-5)
    got = re.search(rf"\|1 - \\frac\{{{N}\}}\{{{N}\}}\| = {N}", margin)
    _close(abs(1 - _num(got.group(1)) / _num(got.group(2))), got.group(3))
