"""Batch grading of students' answers against an answer key (``flywheel grade``).

The key is the answers.json that ``flywheel variants`` writes — ``{"variants": {id: {answer:
value}}, "tolerance": t, "tolerances": {answer: t}, …}`` — or a plain ``{id: {answer: value}}``.
An answer sheet is a CSV file with the columns ``student``, ``variant`` and one column per
answer (the students.csv of ``flywheel variants``, filled in); ``,``, ``;`` and tab delimiters,
UTF-8 (with or without BOM) or Windows-1251, and a decimal comma are accepted.

Each answer is compared by its relative error |given − key|/|key| (the absolute error
|given| when the key is 0); it passes when that error is at most its tolerance. The score of a
student is passed/total. A broken file or row (unreadable, no student/variant column, an
unknown variant, a value that is not a number) is recorded as a :class:`Problem` and skipped;
the batch goes on.

Computation only: no typer, no rich.

>>> rel_error(101.0, 100.0)
(0.01, 'relative')
>>> rel_error(0.002, 0.0)
(0.002, 'absolute')
>>> parse_number("4,65"), parse_number("−1 204.5")
(4.65, -1204.5)
"""
from __future__ import annotations

import csv
import functools
import io
import json
import math
import re
from dataclasses import dataclass, field
from pathlib import Path

from flywheel.errors import CaseFileError, InputError, Notice, led, said

DEFAULT_TOLERANCE = 0.01
#: round-off allowance: an error of tolerance·(1 + SLACK) still passes (0.01 typed for 1 %)
SLACK = 1e-9


# -- the key ------------------------------------------------------------------------------------

@dataclass(frozen=True)
class Key:
    """An answer key: {variant id: {answer: value}} and the tolerances."""

    source: str
    variants: dict[str, dict[str, float]]
    tolerance: float = DEFAULT_TOLERANCE
    tolerances: dict[str, float] = field(default_factory=dict)
    answers: tuple[str, ...] = ()

    def tolerance_of(self, answer: str, default: float | None = None) -> float:
        """The per-answer tolerance of the key file, else ``default`` (e.g. ``--tolerance``),
        else the key's own default."""
        if answer in self.tolerances:
            return self.tolerances[answer]
        return self.tolerance if default is None else default

    def find(self, variant: str) -> str | None:
        """The key's id for a sheet's variant cell ("3", "03", "variant_03.toml" → "03")."""
        v = variant.strip()
        if v in self.variants:
            return v
        m = re.fullmatch(r"(?:variant[_ -]?)?0*(\d+)(?:\.toml)?", v, flags=re.IGNORECASE)
        if m is None:
            return None
        return self._by_number.get(m.group(1))

    @functools.cached_property
    def _by_number(self) -> dict[str, str]:
        """Variant number without leading zeros → the key's id (one dict per key: a sheet's
        rows are looked up in constant time, and a cell of 5 000 digits is only a string)."""
        out: dict[str, str] = {}
        for vid in self.variants:
            if vid.isdigit():
                out.setdefault(vid.lstrip("0") or "0", vid)
        return out


def _number(v) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)


def _positive(v) -> bool:
    return _number(v) and v > 0


def parse_key(doc, source: str = "<key>") -> Key:
    """Check a parsed answers.json document (one CaseFileError line if it is not a key)."""
    if not isinstance(doc, dict):
        raise CaseFileError(led(f"{source}: ", Notice.of(
            "key_not_object", "must be a JSON object {{variant: {{answer: value}}}} (got {type})",
            type=type(doc).__name__)))
    if "variants" in doc:
        table = doc["variants"]
        where = "variants"
        tol = doc.get("tolerance", DEFAULT_TOLERANCE)
        tols = doc.get("tolerances", {})
        answers = doc.get("answers")
    else:
        table, where, tol, tols, answers = doc, "", DEFAULT_TOLERANCE, {}, None
    if not isinstance(table, dict) or not table:
        raise CaseFileError(led(f"{source}: ", Notice(
            f"{where or 'the key'}: must be a non-empty object {{variant: {{answer: value}}}}",
            "key_no_variants", where=where)))
    if not _positive(tol):
        raise CaseFileError(led(f"{source}: tolerance: ", Notice(
            f"must be a positive number (got {tol!r})", "not_positive_number", got=repr(tol))))
    if not isinstance(tols, dict) or not all(_positive(v) for v in tols.values()):
        raise CaseFileError(led(f"{source}: tolerances: ", Notice(
            f"must be an object {{answer: positive number}} (got {tols!r})", "key_tolerances",
            got=repr(tols))))
    variants: dict[str, dict[str, float]] = {}
    for vid, ans in table.items():
        at = f"{where}.{vid}" if where else str(vid)
        if not isinstance(ans, dict) or not ans:
            raise CaseFileError(led(f"{source}: {at}: ", Notice(
                f"must be an object {{answer: value}} (got {ans!r})", "grade_answers_object",
                got=repr(ans))))
        for name, value in ans.items():
            if not _number(value):
                raise CaseFileError(led(f"{source}: {at}.{name}: ", Notice(
                    f"must be a finite number (got {value!r})", "not_finite_number",
                    got=repr(value))))
        variants[str(vid)] = {str(k): float(v) for k, v in ans.items()}
    if answers is None:
        seen: dict[str, None] = {}
        for ans in variants.values():
            seen.update(dict.fromkeys(ans))
        answers = list(seen)
    if not isinstance(answers, list) or not all(isinstance(a, str) for a in answers):
        raise CaseFileError(led(f"{source}: answers: ", Notice(
            f"must be a list of answer names (got {answers!r})", "grade_answers_list",
            got=repr(answers))))
    return Key(source, variants, float(tol), {str(k): float(v) for k, v in tols.items()},
               tuple(answers))


def load_key(path) -> Key:
    """Read an answers.json (see :func:`parse_key`)."""
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8-sig")
    except FileNotFoundError:
        raise CaseFileError(Notice(f"{path}: no such file", "no_such_file", path=str(path))) from None
    except IsADirectoryError:
        raise CaseFileError(Notice(f"{path}: is a folder, expected the answers.json of "
                                   "flywheel variants", "key_is_a_folder", path=str(path))) from None
    except UnicodeDecodeError as exc:
        raise CaseFileError(Notice(f"{path}: not UTF-8 text ({exc.reason} at byte {exc.start})",
                                   "not_utf8", path=str(path), reason=exc.reason,
                                   byte=exc.start)) from None
    except OSError as exc:
        raise CaseFileError(Notice(f"{path}: cannot be read ({exc.strerror})",
                                   "grade_key_unreadable", path=str(path),
                                   reason=exc.strerror, errno=exc.errno)) from None
    try:
        doc = json.loads(text)
    except json.JSONDecodeError as exc:
        raise CaseFileError(Notice(f"{path}: not JSON: {exc.msg} at line {exc.lineno} column "
                                   f"{exc.colno}", "not_json", path=str(path), msg=exc.msg,
                                   line=exc.lineno, col=exc.colno)) from None
    return parse_key(doc, str(path))


# -- numbers ------------------------------------------------------------------------------------

_SPACES = str.maketrans("", "", " \u00a0\u202f\u2009_")


def parse_number(text: str) -> float:
    """A student's number: spaces and thin spaces dropped, a decimal comma accepted, the minus
    sign − accepted. ValueError if it is not a finite number."""
    t = text.strip().translate(_SPACES).replace("\u2212", "-").replace("\u2013", "-")
    if t.count(",") == 1 and "." not in t:
        t = t.replace(",", ".")
    x = float(t)
    if not math.isfinite(x):
        raise ValueError(Notice.of("grade_not_finite", "{value!r} is not finite", value=text))
    return x


def rel_error(given: float, key: float) -> tuple[float, str]:
    """(error, kind): |given − key|/|key|, or |given − key| when the key is 0."""
    if key == 0:
        return abs(given), "absolute"
    return abs(given - key) / abs(key), "relative"


# -- grading ------------------------------------------------------------------------------------

@dataclass(frozen=True)
class Problem:
    """Something that could not be graded: file, row (1 = the header; None: the whole file);
    ``message`` an errors.Notice (said in Russian under ``grade --lang ru``)."""

    file: str
    row: int | None
    message: str

    def __str__(self) -> str:
        return self.said()

    def said(self) -> str:
        """``file, row N: message``: a Notice (its ``lead`` the place) for the CLI's lines."""
        where = self.file if self.row is None else f"{self.file}, row {self.row}"
        if not getattr(self.message, "code", ""):
            return f"{where}: {self.message}"
        return Notice(f"{where}: {self.message}", "sheet_problem", sheet=self.file, row=self.row,
                      detail=self.message)


@dataclass(frozen=True)
class AnswerGrade:
    answer: str
    given: float | None          # None: no answer
    key: float
    error: float | None          # relative (absolute for a key of 0); None: no answer
    error_kind: str              # "relative" | "absolute"
    tolerance: float
    passed: bool


@dataclass(frozen=True)
class StudentGrade:
    student: str
    variant: str                 # the key's id
    file: str
    row: int
    answers: tuple[AnswerGrade, ...]

    @property
    def passed(self) -> int:
        return sum(a.passed for a in self.answers)

    @property
    def total(self) -> int:
        return len(self.answers)

    @property
    def score(self) -> float:
        return self.passed / self.total if self.total else 0.0

    @property
    def wrong(self) -> list[str]:
        return [a.answer for a in self.answers if not a.passed]


@dataclass(frozen=True)
class Report:
    key: Key
    tolerance: float             # the default in force (--tolerance or the key's)
    students: tuple[StudentGrade, ...]
    problems: tuple[Problem, ...]
    files: tuple[str, ...]

    @property
    def mean_score(self) -> float | None:
        if not self.students:
            return None
        return sum(s.score for s in self.students) / len(self.students)

    def wrong_counts(self) -> dict[str, tuple[int, int]]:
        """{answer: (wrong, graded)} in the key's order."""
        out: dict[str, list[int]] = {}
        for a in self.key.answers:
            out[a] = [0, 0]
        for s in self.students:
            for a in s.answers:
                c = out.setdefault(a.answer, [0, 0])
                c[0] += not a.passed
                c[1] += 1
        return {k: (w, n) for k, (w, n) in out.items() if n}

    @property
    def handed_in_nothing(self) -> list[StudentGrade]:
        """Students on a sheet whose answers are all empty (missing work)."""
        return [s for s in self.students if all(a.given is None for a in s.answers)]

    def score_distribution(self) -> dict[int, int]:
        """{answers passed: students} from 0 to the most answers any variant asks."""
        top = max((s.total for s in self.students), default=0)
        out = {k: 0 for k in range(top + 1)}
        for s in self.students:
            out[s.passed] += 1
        return out

    def unassigned_variants(self) -> list[str]:
        """The key's variants nobody was graded on (in the key's order)."""
        taken = {s.variant for s in self.students}
        return [v for v in self.key.variants if v not in taken]

    def most_often_wrong(self) -> tuple[list[str], int] | None:
        """([answers], wrong) of the answer(s) wrong most often (all of a tie, in the key's
        order), or None if no answer was ever wrong."""
        counts = self.wrong_counts()
        most = max((w for w, _ in counts.values()), default=0)
        if not most:
            return None
        return [a for a, (w, _) in counts.items() if w == most], most


MAX_SHEET_BYTES = 50_000_000       # a class's sheet is a few kB; 10⁵ rows of answers ≈ 8 MB
MAX_ROWS = 200_000                 # per grading run, over all sheets
# the encodings a student's spreadsheet or editor writes: Unicode, Russian Windows, DOS, Unix
ENCODINGS = ("utf_8", "utf_16", "utf_32", "cp1251", "cp866", "koi8_r", "cp1252")
_BOMS = ((b"\xef\xbb\xbf", "utf-8-sig"), (b"\xff\xfe\x00\x00", "utf-32"),
         (b"\x00\x00\xfe\xff", "utf-32"), (b"\xff\xfe", "utf-16"), (b"\xfe\xff", "utf-16"))


class SheetError(ValueError):
    """A sheet that cannot be read as text: one problem row for the whole file."""


def decode_sheet(data: bytes) -> tuple[str, str]:
    """(text, encoding) of a sheet's bytes: a byte-order mark decides (UTF-8, UTF-16, UTF-32:
    Excel's "Unicode text"), else strict UTF-8, else the most plausible of :data:`ENCODINGS`
    by charset-normalizer (cp1251 of a Russian Excel, cp866 of DOS, koi8-r). Raises
    SheetError for binary data (an image renamed .csv) or text in none of those encodings.

    >>> decode_sheet("student;вариант".encode("cp1251"))
    ('student;вариант', 'cp1251')
    """
    for bom, enc in _BOMS:
        if data.startswith(bom):
            try:
                return data.decode(enc), enc.replace("-sig", "")
            except UnicodeDecodeError:
                raise SheetError(Notice.of(
                    "sheet_bad_bom", "starts with a {enc} byte-order mark but is not {enc} text",
                    enc=enc)) from None
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError:
        pass
    else:
        if "\x00" in text:
            raise SheetError(Notice.of("sheet_binary", "binary data, not a CSV text file"))
        return text, "utf-8"
    from charset_normalizer import from_bytes

    best = from_bytes(data, cp_isolation=list(ENCODINGS)).best()
    if best is None:
        raise SheetError(Notice.of(
            "sheet_no_encoding", "binary data, not a CSV text file (no text encoding fits: UTF-8, "
            "UTF-16, cp1251, cp866, koi8-r)"))
    text = str(best)
    if "\x00" in text:
        raise SheetError(Notice.of("sheet_binary", "binary data, not a CSV text file"))
    return text, best.encoding


def _read_text(path: Path) -> str:
    """The text of a sheet (see :func:`decode_sheet`); SheetError if too large or not text."""
    size = path.stat().st_size
    if size > MAX_SHEET_BYTES:
        raise SheetError(Notice.of(
            "sheet_too_large", "{mb:.0f} MB is too large for an answer sheet (allowed: up to "
            "{top:.0f} MB)", mb=size / 1e6, top=MAX_SHEET_BYTES / 1e6))
    return decode_sheet(path.read_bytes())[0]


def _delimiter(header: str) -> str:
    counts = {d: header.count(d) for d in (",", ";", "\t")}
    return max(counts, key=lambda d: (counts[d], d == ","))


def _short(text: str, n: int = 60) -> str:
    text = "".join(c if c.isprintable() else "?" for c in text)
    return text if len(text) <= n else text[:n] + "…"


def sheet_files(paths) -> tuple[list[Path], list[Problem]]:
    """The CSV files named by ``paths``: files as given, folders by their ``*.csv`` (sorted).
    A path that does not exist or a folder without CSV files is a Problem."""
    files, problems = [], []
    for p in map(Path, paths):
        if p.is_dir():
            found = sorted(q for q in p.iterdir() if q.suffix.lower() == ".csv" and q.is_file())
            if not found:
                problems.append(Problem(str(p), None, Notice.of(
                    "sheet_folder_empty", "folder without *.csv files")))
            files += found
        elif p.exists():
            files.append(p)
        else:
            problems.append(Problem(str(p), None, Notice.of(
                "sheet_missing", "no such file or folder")))
    return files, problems


def grade_sheet(key: Key, path, tolerance: float | None = None
                ) -> tuple[list[StudentGrade], list[Problem]]:
    """Grade every student row of one CSV file; broken rows become Problems."""
    path = Path(path)
    name = str(path)
    try:
        text = _read_text(path)
    except OSError as exc:
        return [], [Problem(name, None, Notice.of(
            "sheet_unreadable", "cannot be read ({reason})", reason=exc.strerror, errno=exc.errno))]
    except SheetError as exc:
        return [], [Problem(name, None, said(exc))]
    lines = text.splitlines()
    if not lines or not lines[0].strip():
        return [], [Problem(name, None, Notice.of(
            "sheet_empty", "empty file (expected a header student,variant,…)"))]
    try:
        rows = list(csv.reader(io.StringIO(text), delimiter=_delimiter(lines[0])))
    except csv.Error as exc:
        return [], [Problem(name, None, Notice(f"not a readable CSV file ({exc})",
                                               "sheet_not_csv", detail=str(exc)))]
    header = [h.strip() for h in rows[0]]
    lower = [h.lower() for h in header]
    missing = [c for c in ("student", "variant") if c not in lower]
    if missing:
        return [], [Problem(name, 1, Notice(
            f"no {' and no '.join(repr(c) for c in missing)} column (the header must be "
            f"student,variant,<answers…>; got {_short(','.join(header))})", "sheet_no_column",
            columns=' и '.join(repr(c) for c in missing), header=_short(','.join(header))))]
    col_student, col_variant = lower.index("student"), lower.index("variant")
    columns = {h: i for i, h in enumerate(header) if i not in (col_student, col_variant) and h}
    problems: list[Problem] = []
    known = set(key.answers) | {a for v in key.variants.values() for a in v}
    unknown = [h for h in columns if h not in known]
    if unknown:
        problems.append(Problem(name, 1, Notice.of(
            "sheet_unknown_columns", "column(s) {columns} are not answers of the key (ignored; "
            "answers: {answers})", columns=', '.join(map(repr, unknown)),
            answers=', '.join(key.answers))))
    absent = [a for a in key.answers if a not in columns]
    if absent:
        problems.append(Problem(name, 1, Notice.of(
            "sheet_absent_columns", "no column for {columns}: those answers count as not given",
            columns=', '.join(map(repr, absent)))))
    graded: list[StudentGrade] = []
    for n, row in enumerate(rows[1:], start=2):
        cells = [c.strip() for c in row]
        if not any(cells):
            continue
        cells += [""] * (len(header) - len(cells))
        student, variant = cells[col_student], cells[col_variant]
        given = {h: cells[i] for h, i in columns.items() if h in known}
        if not student and not any(given.values()):
            continue  # a row of the blank sheet nobody filled in
        if not student:
            problems.append(Problem(name, n, Notice.of(
                "row_no_student", "no student name; row skipped")))
            continue
        who = f"{student!r}: "
        vid = key.find(variant)
        if vid is None:
            ids = list(key.variants)
            allowed = f"{ids[0]}…{ids[-1]}" if len(ids) > 3 else ", ".join(ids)
            what = "no variant" if not variant else f"variant {variant!r} is not in the key"
            problems.append(Problem(name, n, Notice(
                f"{who}{what} (allowed: {allowed}); row skipped", "row_variant",
                student=student, variant=variant, allowed=allowed)))
            continue
        values: dict[str, float | None] = {}
        bad = []
        for a in key.variants[vid]:
            t = given.get(a, "")
            if not t:
                values[a] = None
                continue
            try:
                values[a] = parse_number(t)
            except ValueError:
                bad.append(f"{a} = {t!r}")
        if bad:
            problems.append(Problem(name, n, Notice(f"{who}not a number: {'; '.join(bad)}; "
                                                    "row skipped", "row_not_a_number",
                                                    student=student, bad='; '.join(bad))))
            continue
        grades = []
        for a, k in key.variants[vid].items():
            tol = key.tolerance_of(a, tolerance)
            g = values[a]
            if g is None:
                grades.append(AnswerGrade(a, None, k, None, "relative" if k else "absolute",
                                          tol, False))
                continue
            err, kind = rel_error(g, k)
            grades.append(AnswerGrade(a, g, k, err, kind, tol, err <= tol * (1 + SLACK)))
        graded.append(StudentGrade(student, vid, name, n, tuple(grades)))
    return graded, problems


def grade(key: Key, paths, tolerance: float | None = None, progress=None) -> Report:
    """Grade every CSV file (or folder of them) in ``paths``; never stops at a broken one.

    ``tolerance`` replaces the key's default tolerance (a per-answer one of the key stays);
    ``progress(done, total)`` is called after each sheet (a progress bar).
    """
    if tolerance is not None and not _positive(tolerance):
        raise InputError(Notice(f"--tolerance: must be a positive number (got {tolerance!r})",
                                "option_not_positive_number", option="--tolerance",
                                got=repr(tolerance)))
    files, problems = sheet_files(paths)
    students: list[StudentGrade] = []
    for i, f in enumerate(files):
        if len(students) >= MAX_ROWS:
            problems += [Problem(str(g), None, Notice.of(
                "run_rows_reached", "not graded: the run has reached {top} student rows (grade the "
                "sheets in parts)", top=MAX_ROWS))
                         for g in files[i:]]
            break
        s, p = grade_sheet(key, f, tolerance)
        if len(students) + len(s) > MAX_ROWS:
            keep = MAX_ROWS - len(students)
            p.append(Problem(str(f), s[keep].row, Notice.of(
                "run_rows_cut", "this row and the {n} after it not graded: at most {top} student "
                "rows per run (grade the sheets in parts)", n=len(s) - keep - 1, top=MAX_ROWS)))
            s = s[:keep]
        students += s
        problems += p
        if progress is not None:
            progress(i + 1, len(files))
    # a student graded twice: the later row counts (a corrected resubmission), in the place
    # of the first; the earlier row is named as not counted
    latest: dict[str, StudentGrade] = {}
    for s in students:
        if s.student in latest:
            first = latest[s.student]
            problems.append(Problem(s.file, s.row, Notice.of(
                "row_again", "{student!r} appears again (first at {file}, row {row}): the later "
                "row counts, the earlier is not graded", student=s.student, file=first.file,
                row=first.row)))
        latest[s.student] = s
    order = list(dict.fromkeys(s.student for s in students))
    students = [latest[name] for name in order]
    return Report(key, key.tolerance if tolerance is None else tolerance, tuple(students),
                  tuple(problems), tuple(map(str, files)))


# -- the report as data -------------------------------------------------------------------------

def report_dict(r: Report) -> dict:
    """The report as a JSON-ready document (``flywheel grade --json``)."""
    worst = r.most_often_wrong()
    return {
        "key": r.key.source,
        "tolerance": r.tolerance,
        "tolerances": {a: r.key.tolerance_of(a, r.tolerance) for a in r.key.answers},
        "files": list(r.files),
        "students": [{
            "student": s.student, "variant": s.variant, "file": s.file, "row": s.row,
            "score": s.score, "passed": s.passed, "total": s.total, "wrong": s.wrong,
            "answers": [{"answer": a.answer, "given": a.given, "key": a.key, "error": a.error,
                         "error_kind": a.error_kind, "tolerance": a.tolerance,
                         "pass": a.passed} for a in s.answers],
        } for s in r.students],
        "summary": {
            "graded": len(r.students),
            "mean_score": r.mean_score,
            "min_score": min((s.score for s in r.students), default=None),
            "max_score": max((s.score for s in r.students), default=None),
            "full_marks": sum(s.passed == s.total for s in r.students),
            "wrong_by_answer": {a: {"wrong": w, "graded": n}
                                for a, (w, n) in r.wrong_counts().items()},
            "most_often_wrong": None if worst is None else
            {"answers": worst[0], "wrong": worst[1]},
            "score_distribution": {str(k): n for k, n in r.score_distribution().items()},
            "handed_in_nothing": [s.student for s in r.handed_in_nothing],
            "unassigned_variants": r.unassigned_variants(),
        },
        "problems": [{"file": p.file, "row": p.row, "message": p.message} for p in r.problems],
    }


def report_csv(r: Report) -> str:
    """One line per student and answer: student, variant, file, row, answer, given, key,
    error, error_kind, tolerance, pass (1/0), score."""
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(["student", "variant", "file", "row", "answer", "given", "key", "error",
                "error_kind", "tolerance", "pass", "score"])
    for s in r.students:
        for a in s.answers:
            w.writerow([s.student, s.variant, s.file, s.row, a.answer,
                        "" if a.given is None else repr(a.given), repr(a.key),
                        "" if a.error is None else f"{a.error:.6g}", a.error_kind,
                        repr(a.tolerance), int(a.passed), f"{s.score:.4f}"])
    return buf.getvalue()
