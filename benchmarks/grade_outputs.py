"""Every output of `flywheel grade` on a set of classes, hashed: the check that the streaming
reader of issue 23 changed no byte (stdout, stderr, exit code, --out, --gradebook).

    PYTHONPATH=/work/main/src python benchmarks/grade_outputs.py before.json
    PYTHONPATH=src            python benchmarks/grade_outputs.py after.json
    python benchmarks/grade_outputs.py --compare before.json after.json

The classes are generated here (seeded, no flywheel code): a key of 40 variants; sheets in
UTF-8, UTF-8 with BOM, UTF-16, cp1251, cp866, koi8-r, with ';' and decimal commas, broken rows,
a student twice, unknown and absent columns, binary and empty files, a quoted header, lone
carriage returns; and a big class past the 200 000-row limit (three sheets).
"""
from __future__ import annotations

import hashlib
import json
import os
import random
import subprocess
import sys
import tempfile
from pathlib import Path

ANSWERS = ["M_C", "J_required", "omega_max", "delta_T", "D_flywheel", "A_cycle"]
NAMES = ["Иванов Пётр", "Сидорова Анна", "Шевченко Тарас", "Kim Li", "Щукина Эльвира",
         "Petrov", "Смирнова Ольга", "Ёлкин Юрий"]


def _key(rng: random.Random) -> dict:
    variants = {f"{i:02d}": {a: round(rng.uniform(-50, 500), 6) if a != "delta_T" else 0.0
                             for a in ANSWERS} for i in range(1, 41)}
    return {"answers": ANSWERS, "tolerance": 0.01, "tolerances": {"A_cycle": 0.05},
            "variants": variants}


def _row(rng, key, name, vid, sep=",", comma=False) -> str:
    cells = [name, vid]
    for a in ANSWERS:
        v = key["variants"][vid][a] * rng.choice([1, 1, 1, 1.003, 1.2, -1])
        r = rng.random()
        t = "" if r < 0.05 else (repr(v) if not comma else repr(v).replace(".", ","))
        cells.append(t)
    return sep.join(cells)


def make_inputs(d: Path) -> list[tuple[str, list[str]]]:
    rng = random.Random(23)
    key = _key(rng)
    (d / "k.json").write_text(json.dumps(key, indent=2))
    ids = list(key["variants"])
    head = "student,variant," + ",".join(ANSWERS)
    small = d / "small"
    small.mkdir()

    def class_text(n, sep=",", comma=False, names=NAMES):
        lines = [head.replace(",", sep)]
        for i in range(n):
            lines.append(_row(rng, key, f"{rng.choice(names)} {i}", rng.choice(ids), sep, comma))
        return "\n".join(lines) + "\n"

    (small / "a_utf8.csv").write_text(class_text(30))
    (small / "b_bom.csv").write_bytes(b"\xef\xbb\xbf" + class_text(10).encode())
    (small / "c_utf16.csv").write_bytes(class_text(10).encode("utf-16"))
    for enc in ("cp1251", "cp866", "koi8_r"):
        (small / f"d_{enc}.csv").write_bytes(class_text(25, ";", True).encode(enc))
    broken = [head, "Ivanov,99," + ",".join("1" * len(ANSWERS)),
              ",01," + ",".join("1" * len(ANSWERS)), "Petrov,01,abc,1,2,3,4,5",
              ",,,,,,,", "Kim Li 3,variant_07.toml,1,2,3,4,5,6", "Kim Li 3,7,1,2,3,4,5,6",
              "short,01,1", "   ", "Sidorov,03," + "1e999,2,3,4,5,6"]
    (small / "e_broken.csv").write_text("\n".join(broken) + "\n")
    (small / "f_columns.csv").write_text("student,variant,M_C,extra,J_required\n"
                                         "Z,01,1,x,2\nY,02,3,y,\n")
    (small / "g_binary.csv").write_bytes(bytes(range(256)) * 4)
    (small / "h_empty.csv").write_text("")
    (small / "i_blank_first.csv").write_text("\n" + class_text(3))
    (small / "j_quoted.csv").write_text('"student","variant","M_C"\n"A, B",01,"1,5"\nC,02,7\n')
    (small / "k_cr.csv").write_text(class_text(3).replace("\n", "\r"))
    (small / "l_crlf.csv").write_bytes(class_text(5).replace("\n", "\r\n").encode())
    (small / "m_nocol.csv").write_text("name,var,M_C\nA,01,1\n")
    (small / "n_tab.csv").write_text(class_text(5, "\t"))
    (small / "o_ff.csv").write_text("student,variant,M_C\x0cJ_required\nA,01,1,2\n")
    (small / "p_bad_quote.csv").write_text('student,variant,M_C\nA,01,"1\n')
    (small / "q_nul_late.csv").write_text(class_text(5) + "X,01,1\x00\n")
    big = d / "big"
    big.mkdir()
    for j, n in enumerate((150_000, 70_000, 1_000)):
        text = class_text(n)
        if j == 1:                    # rows past the limit: graded rows and a broken one
            text += "late,99,1,2,3,4,5,6\n" + _row(rng, key, "late 2", "05") + "\n"
        (big / f"s{j}.csv").write_text(text)
    runs = []
    for lang in ("en", "ru"):
        for name, sheets in (("small", ["small"]), ("big", ["big"]), ("files", [
                "small/a_utf8.csv", "small/d_cp1251.csv", "small/e_broken.csv"])):
            base = ["grade", "k.json", *sheets, "--lang", lang]
            runs += [(f"{name}-{lang}", base + ["--out", "o.csv", "--gradebook", "b.csv"]),
                     (f"{name}-{lang}-summary", base + ["--summary"]),
                     (f"{name}-{lang}-json", base + ["--json", "--tolerance", "0.05"]),
                     (f"{name}-{lang}-excel", base + ["--csv", "excel-ru", "--out", "o.csv",
                                                     "--gradebook", "b.csv", "--summary"])]
    runs.append(("nothing", ["grade", "k.json", "small/g_binary.csv", "small/h_empty.csv"]))
    return runs


def _sha(data: bytes) -> str:
    return hashlib.sha256(data).hexdigest()[:16]


def digest(out: Path) -> None:
    result = {}
    with tempfile.TemporaryDirectory() as tmp:
        d = Path(tmp)
        runs = make_inputs(d)
        env = dict(os.environ, COLUMNS="100", PYTHONHASHSEED="0")
        for name, argv in runs:
            for f in ("o.csv", "b.csv"):
                (d / f).unlink(missing_ok=True)
            p = subprocess.run([sys.executable, "-m", "flywheel", *argv], cwd=d, env=env,
                               capture_output=True)
            files = {f: _sha((d / f).read_bytes()) for f in ("o.csv", "b.csv")
                     if (d / f).exists()}
            result[name] = {"exit": p.returncode, "stdout": _sha(p.stdout),
                            "stderr": _sha(p.stderr), "files": files,
                            "stdout_bytes": len(p.stdout)}
            print(name, result[name], flush=True)
    out.write_text(json.dumps(result, indent=1))


def compare(a: Path, b: Path) -> int:
    x, y = json.loads(a.read_text()), json.loads(b.read_text())
    bad = [k for k in x if x[k] != y.get(k)] + [k for k in y if k not in x]
    for k in bad:
        print(f"differs: {k}\n  {x.get(k)}\n  {y.get(k)}")
    print(f"{len(x) - len(bad)} of {len(x)} runs identical")
    return 1 if bad else 0


if __name__ == "__main__":
    if sys.argv[1] == "--compare":
        sys.exit(compare(Path(sys.argv[2]), Path(sys.argv[3])))
    digest(Path(sys.argv[1]))
