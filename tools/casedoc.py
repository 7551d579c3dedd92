"""Write the generated field references of the case file: docs/case-fields.md (English) and
docs/ru/case-format.md (Russian), from the JSON Schema (render/case_reference.py).

    python tools/casedoc.py          # write both
    python tools/casedoc.py check    # exit 1 if either is stale
"""
from __future__ import annotations

import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "src"))
FILES = {"en": ROOT / "docs" / "case-fields.md", "ru": ROOT / "docs" / "ru" / "case-format.md"}


def texts() -> dict[str, str]:
    from flywheel.cases.describe import tables
    from flywheel.render.case_reference import reference_markdown

    tabs = tables()
    return {lang: reference_markdown(tabs, lang) for lang in FILES}


def main(argv: list[str]) -> int:
    new = texts()
    if argv[1:] == ["check"]:
        stale = [str(FILES[k]) for k, v in new.items()
                 if not FILES[k].exists() or FILES[k].read_text(encoding="utf-8") != v]
        for s in stale:
            print(f"stale: {s} (run python tools/casedoc.py)")
        return 1 if stale else 0
    for lang, text in new.items():
        FILES[lang].parent.mkdir(parents=True, exist_ok=True)
        FILES[lang].write_text(text, encoding="utf-8")
        print(f"written: {FILES[lang]}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv))
