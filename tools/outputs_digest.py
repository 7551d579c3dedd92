"""Every output of every bundled case and command, hashed: the check that a restructure changed
no output byte (docs/architecture.md, "Same outputs across a change").

    python tools/outputs_digest.py write before.json      # on the old commit
    python tools/outputs_digest.py write after.json       # on the new one
    python tools/outputs_digest.py compare before.json after.json

Each command runs in a fresh scratch folder holding a copy of cases/ (so every path it prints
is the same relative one), with COLUMNS=100 and PYTHONHASHSEED=0; the digest records its exit
code, the SHA-256 of its stdout and stderr, and of every file it wrote. ``--quick`` leaves out
the PDF and DOCX reports and the SVG figures (about a third of the time).
"""
from __future__ import annotations

import csv
import hashlib
import json
import os
import shutil
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
RUN_CASES = ["compressor", "compressor_given_flywheel", "compressor_worksheet", "engine_4stroke",
             "engine_inline4", "fourbar", "fourbar_rocker_load", "press", "pump", "shaper",
             "slotted_link"]
LANGS = ("en", "ru")


def commands(quick: bool) -> list[tuple[str, list[str]]]:
    """(name, argv after `flywheel`) of every command in the digest."""
    cases = ROOT / "cases"
    heavy = [] if quick else ["--report", "pdf", "--report", "docx"]
    out: list[tuple[str, list[str]]] = []
    for lang in LANGS:
        for c in RUN_CASES:
            out.append((f"run-{c}-{lang}", ["run", f"cases/{c}.toml", "--out", "o", "--lang", lang,
                                            "--report", "md", "--report", "html", *heavy]))
            out.append((f"check-{c}-{lang}", ["check", f"cases/{c}.toml", "--lang", lang]))
        out.append((f"run-json-{lang}", ["run", "cases/compressor.toml", "--no-plots", "--json",
                                         "--lang", lang]))
        out.append((f"run-excel-svg-{lang}", ["run", "cases/fourbar.toml", "--out", "o", "--lang",
                                              lang, "--csv", "excel-ru", "--at", "75",
                                              "--motion", "steady", "--transients",
                                              *([] if quick else ["--figure-format", "svg"])]))
        for p in sorted(cases.glob("task2_*.toml")):
            out.append((f"task2-{p.stem}-{lang}", ["task2", "--case", f"cases/{p.name}", "--lang",
                                                  lang, "--out", "o", "--report", "md",
                                                  "--report", "html", *heavy]))
            out.append((f"task2-json-{p.stem}-{lang}", ["task2", "--case", f"cases/{p.name}",
                                                       "--json"]))
        for prof in ("triangle", "rectangle"):
            out.append((f"task2-{prof}-{lang}", ["task2", "--profile", prof, "--epsilon",
                                                 "--at", "100", "--lang", lang, "--plot", "t.png"]))
        for p in sorted(cases.glob("aggregate*.toml")):
            out.append((f"agg-{p.stem}-{lang}", ["aggregate", f"cases/{p.name}", "--modes",
                                                "--lang", lang, "--out", "o", *heavy]))
        for p in sorted(cases.glob("duty_*.toml")):
            out.append((f"duty-{p.stem}-{lang}", ["duty-cycle", f"cases/{p.name}", "--lang", lang,
                                                 "--out", "o", *heavy]))
        for p in sorted(cases.glob("variants_*.toml")):
            out.append((f"variants-{p.stem}-{lang}", ["variants", f"cases/{p.name}", "-n", "3",
                                                     "--seed", "5", "--out", "o", "--lang", lang,
                                                     *(["--sheets", "--sheets-format", "html"]
                                                       if quick else ["--sheets"])]))
        out.append((f"grade-{lang}", ["grade", "v/answers.json", "sheet.csv", "--out", "g.csv",
                                      "--gradebook", "gb.csv", "--lang", lang]))
        out.append((f"grade-json-{lang}", ["grade", "v/answers.json", "sheet.csv", "--json"]))
    return out


def _grade_inputs(work: Path, env: dict) -> None:
    """A key (variants of the task-2 template) and a sheet with one wrong and one blank answer."""
    subprocess.run([sys.executable, "-m", "flywheel", "variants", "cases/variants_task2.toml",
                    "-n", "3", "--seed", "5", "--out", "v"], cwd=work, env=env,
                   capture_output=True, check=True)
    key = json.loads((work / "v" / "answers.json").read_text())
    names = list(key["answers"])
    with open(work / "sheet.csv", "w", newline="", encoding="utf-8") as f:
        w = csv.writer(f)
        w.writerow(["student", "variant", *names])
        for i, (vid, ans) in enumerate(key["variants"].items()):
            row = [repr(ans[a]) if isinstance(ans[a], float) else ans[a] for a in names]
            if i == 1:
                row[0] = "1.5" if row[0] != "1.5" else "2.5"
            if i == 2:
                row[-1] = ""
            w.writerow([f"student{i}", vid, *row])


def run_one(name: str, argv: list[str]) -> dict:
    env = {**os.environ, "COLUMNS": "100", "PYTHONHASHSEED": "0", "NO_COLOR": "1",
           "TERM": "dumb"}
    with tempfile.TemporaryDirectory(prefix="digest-") as tmp:
        work = Path(tmp)
        shutil.copytree(ROOT / "cases", work / "cases")
        if argv[0] == "grade":
            _grade_inputs(work, env)
        before = {p for p in work.rglob("*")}
        res = subprocess.run([sys.executable, "-m", "flywheel", *argv], cwd=work, env=env,
                             capture_output=True)
        files = {}
        for p in sorted(work.rglob("*")):
            if p.is_file() and p not in before:
                files[str(p.relative_to(work))] = hashlib.sha256(p.read_bytes()).hexdigest()
        return {"argv": argv, "rc": res.returncode,
                "stdout": hashlib.sha256(res.stdout).hexdigest(),
                "stderr": hashlib.sha256(res.stderr).hexdigest(),
                "stderr_text": res.stderr.decode(errors="replace")[-300:], "files": files}


def write(path: Path, quick: bool) -> None:
    cmds = commands(quick)
    with ThreadPoolExecutor(max_workers=int(os.environ.get("DIGEST_JOBS", "2"))) as ex:
        results = list(ex.map(lambda c: run_one(*c), cmds))
    doc = {name: r for (name, _), r in zip(cmds, results)}
    path.write_text(json.dumps(doc, indent=1, ensure_ascii=False, sort_keys=True))
    print(f"{len(doc)} commands, {sum(len(r['files']) for r in doc.values())} files -> {path}")


def compare(a: Path, b: Path) -> int:
    da, db = json.loads(a.read_text()), json.loads(b.read_text())
    bad = 0
    for name in sorted(set(da) | set(db)):
        ra, rb = da.get(name), db.get(name)
        if ra is None or rb is None:
            print(f"{name}: only in {'after' if ra is None else 'before'}")
            bad += 1
            continue
        for k in ("rc", "stdout", "stderr"):
            if ra[k] != rb[k]:
                print(f"{name}: {k} differs" + (f" ({rb['stderr_text']!r})" if k != "stdout" else ""))
                bad += 1
        for f in sorted(set(ra["files"]) | set(rb["files"])):
            if ra["files"].get(f) != rb["files"].get(f):
                print(f"{name}: {f} differs")
                bad += 1
    print("identical" if not bad else f"{bad} differences")
    return 1 if bad else 0


if __name__ == "__main__":
    args = [a for a in sys.argv[1:] if a != "--quick"]
    if args[:1] == ["write"]:
        write(Path(args[1]), "--quick" in sys.argv)
    elif args[:1] == ["compare"]:
        sys.exit(compare(Path(args[1]), Path(args[2])))
    else:
        sys.exit(__doc__)
