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

import codecs
import csv
import functools
import itertools
import json
import math
import os
import re
from array import array
from dataclasses import dataclass, field
from pathlib import Path

from flywheel.errors import CaseFileError, InputError, Notice, led, said
from flywheel.teaching.tables import cell_error
# the key's limits are those of every JSON flywheel reads (io/jsonfile.py)
from flywheel.io.jsonfile import MAX_DEPTH as MAX_KEY_DEPTH
from flywheel.io.jsonfile import MAX_DIGITS as MAX_KEY_DIGITS
# the sheet read as text, in pieces (re-exported: flywheel.teaching.grading keeps the names)
from flywheel.teaching.sheet_text import (  # noqa: F401
    DETECT_BYTES, ENCODINGS, MAX_SHEET_BYTES, READ_BYTES, SheetError, _check_size, _chunks,
    _delimiter, _head, _lines, _scan, _short, _text_chunks, decode_sheet, sheet_codec)

DEFAULT_TOLERANCE = 0.01
#: the largest --tolerance: a relative error of 100 % (any answer of the right sign passes)
MAX_TOLERANCE = 1.0
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
    givens: dict = field(default_factory=dict)   # variant id → teaching.chain.Givens
    tables: dict = field(default_factory=dict)   # name → teaching.tables.TableSpec
    kind: str = "run"   # the case kind the variants are of ("run", "task2"): the sheet's words
    at_deg: dict = field(default_factory=dict)   # variant id → its report angles [deg] (at.N)
    loads: tuple = ({}, {})     # the loads' titles and labels an at.N answer names them by

    def tolerance_of(self, answer: str, default: float | None = None) -> float:
        """The per-answer tolerance of the key file (a table's cell: its column's), else
        ``default`` (e.g. ``--tolerance``), else the key's own default."""
        if answer in self.tolerances:
            return self.tolerances[answer]
        t = self._cell_tolerances.get(answer)
        if t is not None:
            return t
        return self.tolerance if default is None else default

    @functools.cached_property
    def _cell_tolerances(self) -> dict[str, float | None]:
        return {spec.cell(r, c): t for spec in self.tables.values() for r in spec.rows
                for c, t in zip(spec.columns, spec.tolerances)}

    @functools.cached_property
    def units(self) -> tuple[str, ...]:
        """What earns credit, in order: the answers that are no table's cell, then the tables."""
        cells = self._cell_tolerances
        return tuple(a for a in self.answers if a not in cells) + tuple(self.tables)

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
    """A finite JSON number (an integer too large for a float is not: 10**400)."""
    if not isinstance(v, (int, float)) or isinstance(v, bool):
        return False
    try:
        return math.isfinite(v)
    except OverflowError:
        return False


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
        raise CaseFileError(led(f"{source}: ", Notice.of(
            "key_no_variants", "{where_shown}: must be a non-empty object {{variant: {{answer: "
            "value}}}}", where=where, where_shown=where or 'the key')))
    if not _positive(tol):
        raise CaseFileError(led(f"{source}: tolerance: ", Notice.of(
            "not_positive_number", "must be a positive number (got {got})", got=repr(tol))))
    if not isinstance(tols, dict) or not all(_positive(v) for v in tols.values()):
        raise CaseFileError(led(f"{source}: tolerances: ", Notice.of(
            "key_tolerances", "must be an object {{answer: positive number}} (got {got})",
            got=repr(tols))))
    variants: dict[str, dict[str, float]] = {}
    for vid, ans in table.items():
        at = f"{where}.{vid}" if where else str(vid)
        if not isinstance(ans, dict) or not ans:
            raise CaseFileError(led(f"{source}: {at}: ", Notice.of(
                "grade_answers_object", "must be an object {{answer: value}} (got {got})",
                got=repr(ans))))
        for name, value in ans.items():
            if not _number(value):
                raise CaseFileError(led(f"{source}: {at}.{name}: ", Notice.of(
                    "not_finite_number", "must be a finite number (got {got})", got=repr(value))))
        variants[str(vid)] = {str(k): float(v) for k, v in ans.items()}
    if answers is None:
        seen: dict[str, None] = {}
        for ans in variants.values():
            seen.update(dict.fromkeys(ans))
        answers = list(seen)
    if not isinstance(answers, list) or not all(isinstance(a, str) for a in answers):
        raise CaseFileError(led(f"{source}: answers: ", Notice.of(
            "grade_answers_list", "must be a list of answer names (got {got})", got=repr(answers))))
    givens = _chain_givens(doc.get("chain") if "variants" in doc else None, source)
    from flywheel.teaching.tables import parse_key_tables

    tables = parse_key_tables(doc.get("tables") if "variants" in doc else None, source)
    listed = set(answers)
    answers = list(answers) + [c for t in tables.values() for c in t.cells if c not in listed]
    kind = "task2" if "variants" in doc and doc.get("kind") == "task2" else "run"
    return Key(source, variants, float(tol), {str(k): float(v) for k, v in tols.items()},
               tuple(answers), givens, tables, kind,
               _at_deg(doc.get("at_deg") if "variants" in doc else None, source),
               _load_names(doc.get("load_names") if "variants" in doc else None, source))


def _at_deg(table, source: str) -> dict:
    """The key's ``at_deg`` {variant: [report angles, deg]}: what an ``at.N.…`` answer is
    asked at (a feedback page says it); {} without one; a broken one is one CaseFileError
    line."""
    if table is None:
        return {}
    if not isinstance(table, dict) or not all(
            isinstance(a, list) and all(_number(x) for x in a) for a in table.values()):
        raise CaseFileError(led(f"{source}: at_deg: ", Notice.of(
            "key_at_deg", "must be an object {{variant: [angles in degrees]}} (got {got})",
            got=repr(table)[:80])))
    return {str(k): tuple(float(x) for x in a) for k, a in table.items()}


def _load_names(table, source: str) -> tuple:
    """The key's ``load_names`` {"titles": {load: {en, ru}}, "labels": {…}} (teaching/
    variants.py) as (titles, labels) {LoadKey: Text}: what names a load's ``at.N.moments.…`` or
    ``at.N.forces.…`` answer on a feedback page; ({}, {}) without one; a broken one is one
    CaseFileError line."""
    from flywheel.dynamics.loads import LoadKey
    from flywheel.io.text import Text

    if table is None:
        return {}, {}

    def texts(part) -> bool:
        return isinstance(part, dict) and all(
            isinstance(v, dict) and isinstance(v.get("en"), str) and isinstance(v.get("ru"), str)
            for v in part.values())

    if not isinstance(table, dict) or not all(texts(table.get(k, {})) for k in ("titles", "labels")):
        raise CaseFileError(led(f"{source}: load_names: ", Notice.of(
            "key_load_names", "must be an object {{\"titles\": {{load: {{\"en\": …, \"ru\": …}}}}, "
            "\"labels\": {{…}}}} (got {got})", got=repr(table)[:80])))
    return tuple({LoadKey.parse(k): Text(v["en"], v["ru"]) for k, v in table.get(part, {}).items()}
                 for part in ("titles", "labels"))


def _chain_givens(chain, source: str) -> dict:
    """The key's ``chain.givens`` {variant: Givens} (teaching/chain.py); {} without a chain;
    a broken one is one CaseFileError line."""
    from flywheel.teaching.chain import Givens
    from flywheel.teaching.chain_task2 import Task2Givens

    if chain is None:
        return {}
    table = chain.get("givens") if isinstance(chain, dict) else None
    if not isinstance(table, dict):
        raise CaseFileError(led(f"{source}: chain: ", Notice.of(
            "key_chain_broken", "must be the chain flywheel variants writes ({{\"steps\": …, "
            "\"givens\": {{variant: …}}}}); allowed: that, or no chain")))
    out = {}
    for vid, g in table.items():
        try:
            kind = Task2Givens if isinstance(g, dict) and g.get("kind") == "task2" else Givens
            out[str(vid)] = kind.from_document(g)
        except (KeyError, TypeError, ValueError, AttributeError):
            raise CaseFileError(led(f"{source}: chain.givens.{vid}: ", Notice.of(
                "key_chain_broken", "must be the chain flywheel variants writes ({{\"steps\": "
                "…, \"givens\": {{variant: …}}}}); allowed: that, or no chain"))) from None
    return out


def load_key(path) -> Key:
    """Read an answers.json (see :func:`parse_key`)."""
    from flywheel.io.jsonfile import JsonNumberTooLong, JsonTooDeep, read_json

    path = Path(path)
    try:
        doc = read_json(path)               # its limits: MAX_KEY_DEPTH, MAX_KEY_DIGITS
    except FileNotFoundError:
        raise CaseFileError(Notice.of(
            "no_such_file", "{path}: no such file", path=str(path))) from None
    except IsADirectoryError:
        raise CaseFileError(Notice.of(
            "key_is_a_folder", "{path}: is a folder, expected the answers.json of flywheel "
            "variants", path=str(path))) from None
    except UnicodeDecodeError as exc:
        from flywheel.io.toml import not_utf8

        raise CaseFileError(not_utf8(path, exc)) from None
    except OSError as exc:
        raise CaseFileError(Notice.of(
            "grade_key_unreadable", "{path}: cannot be read ({reason})", path=str(path),
            reason=exc.strerror, errno=exc.errno)) from None
    except JsonTooDeep as exc:
        raise CaseFileError(Notice.of(
            "key_too_deep", "{path}: nested too deep ({depth} levels of [] and {{}}; allowed: up "
            "to {top})", path=str(path), depth=exc.depth, top=MAX_KEY_DEPTH)) from None
    except json.JSONDecodeError as exc:
        raise CaseFileError(Notice.of(
            "not_json", "{path}: not JSON: {msg} at line {line} column {col}", path=str(path),
            msg=exc.msg, line=exc.lineno, col=exc.colno)) from None
    except JsonNumberTooLong as exc:
        raise CaseFileError(Notice.of(
            "key_number_too_long", "{path}: a number of {digits} digits is too long (allowed: up "
            "to {top} digits)", path=str(path), digits=exc.digits, top=MAX_KEY_DIGITS)) from None
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


def within(given: float, value: float, tolerance: float) -> bool:
    """``given`` passes against ``value``: its error (:func:`rel_error`) at most
    ``tolerance``, with the round-off allowance SLACK."""
    return rel_error(given, value)[0] <= tolerance * (1 + SLACK)


def within_cell(given: float, value: float, tolerance: float, floor: float) -> bool:
    """:func:`within` for a table's cell (teaching/tables.py ``cell_error``)."""
    return cell_error(given, value, floor)[0] <= tolerance * (1 + SLACK)


# -- grading ------------------------------------------------------------------------------------

@dataclass(frozen=True, slots=True)
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
        return Notice.of(
            "sheet_problem", "{where}: {detail}", sheet=self.file, row=self.row,
            detail=self.message, where=where)


@dataclass(frozen=True)
class AnswerGrade:
    answer: str
    given: float | None          # None: no answer
    key: float
    error: float | None          # relative (absolute for a key of 0); None: no answer
    error_kind: str              # "relative" | "absolute"
    tolerance: float
    passed: bool
    verdict: str = ""            # "pass" | "carried" | "fail" | "no answer"
    diagnosis: str | None = None  # a code of teaching/mistakes.py's catalogue


@dataclass(frozen=True)
class Marking:
    """How one variant is marked: its answers in the key's order, their key values and
    tolerances (one object shared by every student of that variant), its chain (None: the
    key has none) and the share of credit of a carried-forward answer."""

    names: tuple[str, ...]
    keys: tuple[float, ...]
    tolerances: tuple[float, ...]
    chain: object = None         # teaching.chain.Chain
    carried_share: float = 0.0
    # tables (teaching/tables.py): a TableMark each, every answer's floor (0: no cell), the
    # bits of the cells and each table's rows' angles [deg] {table: {row: φ}}
    tables: tuple = ()
    floors: tuple[float, ...] = ()
    cells: int = 0
    table_phi: dict = field(default_factory=dict)

    def explain(self, given: array, mask: int) -> tuple[int, tuple[tuple[int, str], ...]]:
        """(carried, diagnoses) of a student's values: teaching/explain.py, and a table's
        cells tried against the classic mistakes (teaching/tables.py)."""
        carried, named = 0, ()
        if self.chain is not None:
            from flywheel.teaching.explain import explain

            carried, named = explain(self, given, mask, within)
        if self.tables:
            from flywheel.teaching.tables import diagnose_cells

            named = tuple(sorted(named + diagnose_cells(
                self, given, mask, None if self.chain is None else self.chain.g, within_cell)))
        return carried, named

    def error(self, j: int, given: float) -> tuple[float, str]:
        """Answer j's error (:func:`rel_error`; a table's cell: teaching/tables.py
        ``cell_error``)."""
        if self.cells >> j & 1:
            return cell_error(given, self.keys[j], self.floors[j])
        return rel_error(given, self.keys[j])

    @functools.cached_property
    def index(self) -> dict[str, int]:
        """Answer name → its position j."""
        return {a: j for j, a in enumerate(self.names)}

    def verdicts(self, given: array) -> int:
        """The answers passed as a bit mask (bit j: answer j); ``given`` NaN = no answer."""
        mask = 0
        if self.cells:
            # a cell: |given − key| ≤ tolerance·max(|key|, floor) (teaching/tables.py); the
            # floor of an answer that is no cell is 0: rel_error's test
            for j, (g, k, tol, floor) in enumerate(zip(given, self.keys, self.tolerances,
                                                       self.floors)):
                if g == g:
                    scale = max(abs(k), floor)
                    err = abs(g - k) / scale if scale else abs(g)
                    if err <= tol * (1 + SLACK):
                        mask |= 1 << j
            return mask
        for j, (g, k, tol) in enumerate(zip(given, self.keys, self.tolerances)):
            if g == g and rel_error(g, k)[0] <= tol * (1 + SLACK):
                mask |= 1 << j
        return mask

    @functools.cached_property
    def units(self) -> tuple[tuple[str, int], ...]:
        """What earns credit: (name, bits) of each answer that is no cell, then each table."""
        out = tuple((a, 1 << j) for j, a in enumerate(self.names) if not self.cells >> j & 1)
        return out + tuple((t.name, t.bits) for t in self.tables)


@dataclass(frozen=True, slots=True)
class StudentGrade:
    """One graded row, kept small (a class of 200 000 rows fits in tens of MB): the values
    given (NaN: no answer), the passed answers as a bit mask and the variant's shared
    :class:`Marking`; :attr:`answers` builds the full grades when asked."""

    student: str
    variant: str                 # the key's id
    file: str
    row: int
    given: array                 # array('d'), NaN = no answer
    mask: int                    # bit j set: answer j passed
    marking: Marking
    carried: int = 0             # bit j set: answer j consistent with the student's earlier ones
    diagnoses: tuple[tuple[int, str], ...] = ()   # (answer j, mistake code)

    @property
    def answers(self) -> tuple[AnswerGrade, ...]:
        named = dict(self.diagnoses)
        return tuple(self.grade_of(j, named) for j in range(len(self.marking.names)))

    def grade_of(self, j: int, named: dict | None = None) -> AnswerGrade:
        """The grade of answer j (``named``: the diagnoses as a dict, if at hand)."""
        m = self.marking
        a, k, tol, g = m.names[j], m.keys[j], m.tolerances[j], self.given[j]
        if g != g:
            return AnswerGrade(a, None, k, None, "relative" if k else "absolute", tol, False,
                               "no answer")
        err, kind = m.error(j, g)
        passed = bool(self.mask >> j & 1)
        verdict = ("pass" if passed else "carried" if self.carried >> j & 1 else "fail")
        diagnosis = (dict(self.diagnoses) if named is None else named).get(j)
        return AnswerGrade(a, g, k, err, kind, tol, passed, verdict, diagnosis)

    @property
    def passed(self) -> int:
        """Answers right (a table counts as one, right when all its cells are)."""
        if self.marking.tables:
            return sum((self.mask & b) == b for _, b in self.marking.units)
        return self.mask.bit_count()

    @property
    def carried_count(self) -> int:
        return self.carried.bit_count()

    @property
    def total(self) -> int:
        if self.marking.tables:
            return len(self.marking.units)
        return len(self.marking.names)

    @property
    def score(self) -> float:
        """(passed + share·carried forward + each table's share of cells right not yet
        counted)/total (``--carried-forward SHARE``, default 0): a table of 12 cells with 9
        right earns 9/12 of one answer."""
        if not self.total:
            return 0.0
        part = 0.0
        for t in self.marking.tables:
            if (self.mask & t.bits) != t.bits:
                part += t.right(self.mask) / len(t.indices)
        return (self.passed + self.marking.carried_share * self.carried_count + part) / self.total

    @property
    def wrong(self) -> list[str]:
        if self.marking.tables:
            return [a for a, b in self.marking.units if (self.mask & b) != b]
        return [a for j, a in enumerate(self.marking.names) if not self.mask >> j & 1]

    @property
    def table_grades(self) -> tuple[tuple[str, int, int, tuple], ...]:
        """Per table (name, cells right, cells, the cells off by column: ((column, rows), …))."""
        return tuple((t.name, t.right(self.mask), len(t.indices), t.off(self.mask))
                     for t in self.marking.tables)

    @property
    def nothing_given(self) -> bool:
        return all(g != g for g in self.given)


@dataclass(frozen=True)
class Report:
    key: Key
    tolerance: float             # the default in force (--tolerance or the key's)
    students: tuple[StudentGrade, ...]
    problems: tuple[Problem, ...]
    files: tuple[str, ...]
    carried_share: float = 0.0   # --carried-forward

    @property
    def mean_score(self) -> float | None:
        if not self.students:
            return None
        return sum(s.score for s in self.students) / len(self.students)

    def wrong_counts(self) -> dict[str, tuple[int, int]]:
        """{answer: (wrong, graded)} in the key's order."""
        out: dict[str, list[int]] = {}
        for a in self.key.units:
            out[a] = [0, 0]
        for s in self.students:
            for a, b in s.marking.units:
                c = out.setdefault(a, [0, 0])
                c[0] += (s.mask & b) != b
                c[1] += 1
        return {k: (w, n) for k, (w, n) in out.items() if n}

    @property
    def handed_in_nothing(self) -> list[StudentGrade]:
        """Students on a sheet whose answers are all empty (missing work)."""
        return [s for s in self.students if s.nothing_given]

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


MAX_ROWS = 200_000                 # per grading run, over all sheets


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


def _same_file(a: Path, b: Path) -> bool:
    """Whether ``a`` and ``b`` name one file: the same resolved path (``./x`` and ``x``, a
    symbolic link and its target), or, when both exist, the same file on the disc
    (os.path.samefile: a hard link, another spelling on a case-insensitive system)."""
    try:
        if a.resolve() == b.resolve():
            return True
        return a.exists() and b.exists() and os.path.samefile(a, b)
    except (OSError, RuntimeError):        # a name too long, a loop of links: not provably one
        return False


def check_outputs(key, answers, outputs) -> None:
    """Refuse, before anything is read, an output of ``flywheel grade`` that would write over
    one of its inputs (the key, a sheet, a sheet in a folder of sheets) or over the other
    output. ``outputs``: [(option, path or None)]. Raises InputError, one line naming both."""
    named = [(o, Path(p)) for o, p in outputs if p is not None]
    inputs = [("the answer key", Path(key))]
    for a in map(Path, answers):
        try:
            found = sorted(q for q in a.iterdir() if q.suffix.lower() == ".csv") \
                if a.is_dir() else [a]
        except OSError:
            found = [a]
        inputs += [("the answer sheet", q) for q in found]
    for i, (option, path) in enumerate(named):
        for what, given in inputs:
            if _same_file(path, given):
                raise InputError(Notice.of(
                    "grade_output_is_input", "{option} {path}: is {what} {given} (flywheel grade "
                    "never writes over its inputs; allowed: another file name)", option=option,
                    path=str(path), what=what, given=str(given)))
        for other, there in named[i + 1:]:
            if _same_file(path, there):
                raise InputError(Notice.of(
                    "grade_outputs_same", "{option} {path} and {other} {there}: the same file "
                    "(allowed: two different file names)", option=option, path=str(path),
                    other=other, there=str(there)))


class _Kept(list):
    """A list of problems that keeps at most ``room`` and counts the rest (``dropped``): a
    sheet of 10⁵ broken rows (graded against another class's key) is not 10⁵ records."""

    def __init__(self, room: int | None = None):
        super().__init__()
        self.room = room
        self.dropped = 0

    def append(self, problem) -> None:
        if self.room is not None and len(self) >= self.room:
            self.dropped += 1
        else:
            super().append(problem)


#: problems kept per run (the rest counted and named in one last problem)
MAX_PROBLEMS = 10_000


def grade_sheet(key: Key, path, tolerance: float | None = None
                ) -> tuple[list[StudentGrade], list[Problem]]:
    """Grade every student row of one CSV file; broken rows become Problems."""
    graded, problems, _, _ = _grade_sheet(key, path, tolerance, None)
    return graded, problems


def _grade_sheet(key: Key, path, tolerance: float | None, limit: int | None,
                 room: int | None = None, carried_share: float = 0.0
                 ) -> tuple[list[StudentGrade], list[Problem], int, int | None]:
    """(graded, problems, rows past ``limit``, the first of them) of one CSV file, read as a
    stream of rows: at most ``limit`` graded rows are kept (None: all); the rows past it are
    still read for their problems and counted."""
    path = Path(path)
    name = str(path)
    try:
        _check_size(path)
        codec = sheet_codec(path)               # the whole file checked, nothing kept
        return _grade_rows(key, name, _lines(_text_chunks(path, codec)), tolerance, limit,
                           room, carried_share)
    except OSError as exc:
        return [], [Problem(name, None, Notice.of(
            "sheet_unreadable", "cannot be read ({reason})", reason=exc.strerror,
            errno=exc.errno))], 0, None
    except SheetError as exc:
        return [], [Problem(name, None, said(exc))], 0, None
    except UnicodeDecodeError as exc:           # the file changed since it was checked
        return [], [Problem(name, None, Notice.of(
            "sheet_undecodable", "not {codec} text at byte {at} (the encoding guessed from the "
            "sheet's start; allowed: one encoding for the whole sheet: UTF-8, Windows-1251, "
            "cp866, koi8-r)", codec=exc.encoding, at=exc.byte))], 0, None


def _grade_rows(key: Key, name: str, lines, tolerance: float | None, limit: int | None,
                room: int | None = None, carried_share: float = 0.0
                ) -> tuple[list[StudentGrade], list[Problem], int, int | None]:
    """Grade the rows of a sheet given as its lines (see :func:`_grade_sheet`). A CSV error
    anywhere refuses the whole sheet, as before any row is graded."""
    first = next(lines, "")
    head = first.splitlines()
    if not head or not head[0].strip():
        return [], [Problem(name, None, Notice.of(
            "sheet_empty", "empty file (expected a header student,variant,…)"))], 0, None
    rows = csv.reader(itertools.chain([first], lines), delimiter=_delimiter(head[0]))
    try:
        return _graded(key, name, rows, tolerance, limit, room, carried_share)
    except csv.Error as exc:
        return [], [Problem(name, None, Notice.of(
            "sheet_not_csv", "not a readable CSV file ({detail})", detail=str(exc)))], 0, None


def _graded(key: Key, name: str, rows, tolerance: float | None, limit: int | None,
            room: int | None = None, carried_share: float = 0.0
            ) -> tuple[list[StudentGrade], list[Problem], int, int | None]:
    header = [h.strip() for h in next(rows)]
    lower = [h.lower() for h in header]
    if "student" not in lower:
        from flywheel.teaching.moodle import NotResponses, is_responses, native_rows

        if is_responses(header):                # Moodle's quiz Responses report
            try:
                header, rows = native_rows(header, rows, key.answers)
            except NotResponses as exc:
                for _ in rows:
                    pass
                return [], [Problem(name, 1, exc.args[0])], 0, None
            lower = [h.lower() for h in header]
    missing = [c for c in ("student", "variant") if c not in lower]
    if missing:
        for _ in rows:                          # a CSV error further on says more
            pass
        return [], [Problem(name, 1, Notice.of(
            "sheet_no_column", "no {missing_columns} column (the header must be "
            "student,variant,<answers…>; got {header})",
            columns=' и '.join(repr(c) for c in missing), header=_short(','.join(header)),
            missing_columns=' and no '.join((repr(c) for c in missing))))], 0, None
    col_student, col_variant = lower.index("student"), lower.index("variant")
    columns = {h: i for i, h in enumerate(header) if i not in (col_student, col_variant) and h}
    problems: list[Problem] = _Kept(room)
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
    markings: dict[str, Marking] = {}
    graded: list[StudentGrade] = []
    over, first_over = 0, None
    for n, row in enumerate(rows, start=2):
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
            problems.append(Problem(name, n, Notice.of(
                "row_variant", "{who}{problem} (allowed: {allowed}); row skipped", student=student,
                variant=variant, allowed=allowed, who=who, problem=what)))
            continue
        values = array("d")
        bad = []
        for a in key.variants[vid]:
            t = given.get(a, "")
            if not t:
                values.append(math.nan)
                continue
            try:
                values.append(parse_number(t))
            except ValueError:
                bad.append(f"{a} = {t!r}")
        if bad:
            problems.append(Problem(name, n, Notice.of(
                "row_not_a_number", "{who}not a number: {bad}; row skipped", student=student,
                bad='; '.join(bad), who=who)))
            continue
        if limit is not None and len(graded) >= limit:
            over += 1                           # past the run's limit: counted, not kept
            first_over = n if first_over is None else first_over
            continue
        marking = markings.get(vid)
        if marking is None:
            answers = key.variants[vid]
            chain = None
            if vid in key.givens:
                from flywheel.teaching.chain import Chain

                chain = Chain(key.givens[vid], tuple(answers))
            extra = {}
            if key.tables:
                from flywheel.teaching.tables import table_marks

                marks, floors, cells = table_marks(key.tables, tuple(answers),
                                                   tuple(answers.values()))
                extra = dict(tables=marks, floors=floors, cells=cells, table_phi={
                    t.name: dict(zip(t.rows, t.phi_deg)) for t in key.tables.values()})
            marking = markings[vid] = Marking(
                tuple(answers), tuple(answers.values()),
                tuple(key.tolerance_of(a, tolerance) for a in answers), chain, carried_share,
                **extra)
        mask = marking.verdicts(values)
        carried, diagnoses = marking.explain(values, mask)
        graded.append(StudentGrade(student, vid, name, n, values, mask, marking, carried,
                                   diagnoses))
    return graded, problems, over, first_over


def grade(key: Key, paths, tolerance: float | None = None, progress=None,
          carried_share: float = 0.0) -> Report:
    """Grade every CSV file (or folder of them) in ``paths``; never stops at a broken one.

    ``tolerance`` replaces the key's default tolerance (a per-answer one of the key stays);
    ``carried_share`` is the credit of an answer consistent with the student's own earlier
    ones (error carried forward: 0 … 1, default 0: shown, not scored);
    ``progress(done, total)`` is called after each sheet (a progress bar). Each sheet is read
    as a stream of rows; what is kept is one small record per graded row (at most MAX_ROWS).
    """
    if tolerance is not None and not _positive(tolerance):
        raise InputError(Notice.of(
            "option_not_positive_number", "--tolerance: must be a positive number (got {got})",
            option="--tolerance", got=repr(tolerance)))
    if tolerance is not None and tolerance > MAX_TOLERANCE:
        raise InputError(Notice.of(
            "grade_tolerance_too_large", "--tolerance: {got} is too large (allowed: 0 < tolerance "
            "≤ {top:g}, a relative error: 0.01 is 1 %)", got=repr(tolerance), top=MAX_TOLERANCE))
    if not (_number(carried_share) and 0 <= carried_share <= 1):
        raise InputError(Notice.of(
            "carried_share_range", "--carried-forward: {got} is not allowed (allowed: a share of "
            "the credit from 0 to 1, e.g. 0.5)", got=repr(carried_share)))
    files, found = sheet_files(paths)
    problems = _Kept(MAX_PROBLEMS)
    for p in found:
        problems.append(p)
    students: list[StudentGrade] = []
    for i, f in enumerate(files):
        if len(students) >= MAX_ROWS:
            for g in files[i:]:
                problems.append(Problem(str(g), None, Notice.of(
                    "run_rows_reached", "not graded: the run has reached {top} student rows "
                    "(grade the sheets in parts)", top=MAX_ROWS)))
            break
        s, p, over, first_over = _grade_sheet(key, f, tolerance, MAX_ROWS - len(students),
                                              MAX_PROBLEMS - len(problems), carried_share)
        if over:
            p.append(Problem(str(f), first_over, Notice.of(
                "run_rows_cut", "this row and the {n} after it not graded: at most {top} student "
                "rows per run (grade the sheets in parts)", n=over - 1, top=MAX_ROWS)))
        problems.dropped += getattr(p, "dropped", 0)
        students += s
        for x in p:
            problems.append(x)
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
    if problems.dropped:
        list.append(problems, Problem(str(files[-1]) if files else "", None, Notice.of(
            "run_problems_cut", "… and {n} more problem(s) up to this sheet not listed (at most "
            "{top} per run; grade the sheets in parts)", n=problems.dropped, top=MAX_PROBLEMS)))
    return Report(key, key.tolerance if tolerance is None else tolerance, tuple(students),
                  tuple(problems), tuple(map(str, files)), carried_share)


def check_graded(report: Report, paths) -> None:
    """Refuse a report with no student graded (an InputError: the first problem, or no
    filled-in row in ``paths``), so that nothing is written."""
    if report.students:
        return
    if report.problems:
        raise InputError(Notice.of(
            "nothing_graded", "nothing could be graded ({n} problem(s); the first: {detail})",
            n=len(report.problems), detail=report.problems[0].said()))
    files = ", ".join(report.files) or ", ".join(map(str, paths))
    raise InputError(Notice.of(
        "no_student_rows", "{files}: nothing could be graded: no filled-in student rows (a row "
        "needs a student name and a variant)", files=files))


# the report as data (``--json``, ``--out``): teaching/report_data.py, re-exported here
from flywheel.teaching.report_data import (  # noqa: E402,F401
    CSV_ROWS_PER_PIECE, report_csv, report_csv_pieces, report_dict, report_json)
