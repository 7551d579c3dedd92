"""ω_max and ω_min of a run told apart at a small δ (render/numbers.apart): the record's
line and the ω figure's legend."""
from pathlib import Path

CASES = Path(__file__).resolve().parents[2] / "cases"


def test_a_runs_omega_extremes_read_apart_at_a_small_delta(tmp_path):
    """The run's record and ω figure: δ = 10⁻⁴ puts ω_max and ω_min within 0.0063 rad/s of
    each other, which four digits (the Russian policy) write alike, «62,83»; they are written
    to the decimals that tell them apart, and one more (numbers.apart). Where four digits tell
    them apart (δ = 0.05), the record is as it was."""
    from flywheel import analyze, load_case
    from flywheel.render import plots
    from flywheel.render.document import build_document
    from flywheel.render.numbers import typeset

    text = (CASES / "compressor.toml").read_text(encoding="utf-8")
    assert "\ndelta     = 0.05 " in text
    case = tmp_path / "tiny.toml"
    case.write_text(text.replace("\ndelta     = 0.05 ", "\ndelta = 0.0001 "), encoding="utf-8")
    r = analyze(load_case(case), n_points=3600)
    w_max, w_min = r.scalars.omega_max, r.scalars.omega_min
    assert f"{w_max:.2f}" == f"{w_min:.2f}" and f"{w_max:.3f}" != f"{w_min:.3f}"
    shown = (f"{w_max:.4f}".replace(".", ","), f"{w_min:.4f}".replace(".", ","))
    lines = _record_lines(typeset("ru", build_document, r, "ru", []))
    assert any(shown[0] in x and shown[1] in x for x in lines), lines
    fig = plots.figure_omega(r, "ru")
    legend = [t.get_text().replace(".", ",") for t in fig.axes[0].get_legend().get_texts()]
    assert any(shown[0] in x for x in legend) and any(shown[1] in x for x in legend), legend
    # δ = 0.05: four digits tell them apart, the record unchanged
    r = analyze(load_case(CASES / "compressor.toml"), n_points=3600)
    (line,) = _record_lines(typeset("ru", build_document, r, "ru", []))
    assert f"ω_max = {r.scalars.omega_max:.2f}".replace(".", ",") in line, line


def _record_lines(doc) -> list[str]:
    """The record's paragraphs and list items that give ω_max."""
    texts = [x for b in doc.blocks for x in ((b.text,) if hasattr(b, "text") else
                                             getattr(b, "items", ()))]
    return [x for x in texts if isinstance(x, str) and "ω_max =" in x]
