"""Reading a table of numbers from a CSV text file (a measured indicator diagram): bounded in
size and rows, tolerant of the encodings a spreadsheet writes (a byte-order mark: UTF-8,
UTF-16, UTF-32; else UTF-8; else Windows-1251 of a Russian Excel), of its separators (comma,
semicolon, tab, spaces) and of the decimal comma of a semicolon- or tab-separated file. Every
problem is one :class:`TableError` carrying a Notice; the caller puts the field path before it.
"""
from __future__ import annotations

import re
from pathlib import Path

from flywheel.errors import Notice

MAX_TABLE_BYTES = 20_000_000       # a measured cycle at 0.1° is 7 200 rows ≈ 200 kB
MAX_TABLE_ROWS = 100_000
_BOMS = ((b"\xef\xbb\xbf", "utf-8-sig"), (b"\xff\xfe\x00\x00", "utf-32"),
         (b"\x00\x00\xfe\xff", "utf-32"), (b"\xff\xfe", "utf-16"), (b"\xfe\xff", "utf-16"))


class TableError(ValueError):
    """A table file that cannot be read as the numbers asked for: one line (a Notice)."""


def _text(path: Path) -> str:
    """The text of the file at ``path``, its size checked before it is read."""
    try:
        size = path.stat().st_size
        if path.is_dir():
            raise TableError(Notice.of("table_is_folder", "{path}: is a folder, not a CSV file",
                                       path=str(path)))
        if size > MAX_TABLE_BYTES:
            raise TableError(Notice.of(
                "table_too_big", "{path}: {size} bytes (allowed: at most {most} bytes)",
                path=str(path), size=size, most=MAX_TABLE_BYTES))
        data = path.read_bytes()
    except FileNotFoundError:
        raise TableError(Notice.of("no_such_file", "{path}: no such file", path=str(path))) from None
    except OSError as exc:
        raise TableError(Notice.of("run_cannot_read", "{path}: cannot be read ({reason})",
                                   path=str(path), reason=exc.strerror, errno=exc.errno)) from None
    for bom, codec in _BOMS:
        if data.startswith(bom):
            try:
                return data.decode(codec)
            except UnicodeDecodeError:
                raise TableError(Notice.of(
                    "table_bad_bom", "{path}: starts with a {codec} byte-order mark but is not "
                    "{codec} text", path=str(path), codec=codec)) from None
    if b"\x00" in data:
        raise TableError(Notice.of("table_binary", "{path}: binary data, not a CSV text file",
                                   path=str(path)))
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError:
        return data.decode("cp1251", errors="replace")


def _cells(line: str) -> list[str]:
    """The cells of one line: split at semicolons or tabs (the decimal comma allowed), else
    at commas, else at spaces."""
    for sep in (";", "\t"):
        if sep in line:
            return [c.strip().replace(",", ".") for c in line.split(sep)]
    if "," in line:
        return [c.strip() for c in line.split(",")]
    return line.split()


def _number(cell: str) -> float | None:
    try:
        v = float(cell.replace("\u2212", "-"))
    except ValueError:
        return None
    return v if v == v and abs(v) != float("inf") else None


def read_columns(path, columns: list[str] | None) -> tuple[list[str], list[list[float]]]:
    """The named ``columns`` (header names, matched without regard to case; None: the first
    two) of the CSV file at ``path``, as lists of floats, with the header's names. Lines
    empty or starting with '#' are left out; the first other line is the header if it holds a
    cell that is not a number. Raises TableError: no such file, too big, binary, too many rows,
    a column not in the header, a cell that is not a finite number, fewer than 2 rows."""
    path = Path(path)
    header: list[str] | None = None
    rows: list[tuple[int, list[str]]] = []
    for n, line in enumerate(_text(path).splitlines(), start=1):
        if not line.strip() or line.lstrip().startswith("#"):
            continue
        cells = _cells(line)
        if header is None and not rows and any(_number(c) is None for c in cells if c):
            header = cells
            continue
        rows.append((n, cells))
        if len(rows) > MAX_TABLE_ROWS:
            raise TableError(Notice.of(
                "table_too_many_rows", "{path}: more than {most} rows (allowed: at most {most})",
                path=str(path), most=MAX_TABLE_ROWS))
    names = header if header is not None else [f"{k + 1}" for k in range(len(rows[0][1]) if rows else 0)]
    if columns is None:
        want = [0, 1]
    else:
        low = [h.strip().lower() for h in names]
        want = []
        for c in columns:
            if c.strip().lower() not in low:
                raise TableError(Notice.of(
                    "table_no_column", "{path}: no column {column!r} (the header has: {have})",
                    path=str(path), column=c, have=", ".join(names) or "no header"))
            want.append(low.index(c.strip().lower()))
    if len(rows) < 2:
        raise TableError(Notice.of("table_too_short", "{path}: {n} rows of numbers (allowed: at "
                                   "least 2)", path=str(path), n=len(rows)))
    out: list[list[float]] = [[] for _ in want]
    for n, cells in rows:
        for k, j in enumerate(want):
            v = _number(cells[j]) if j < len(cells) else None
            if v is None:
                cell = cells[j] if j < len(cells) else ""
                raise TableError(Notice.of(
                    "table_not_a_number", "{path}: line {line}, column {column}: {cell!r} is not "
                    "a finite number", path=str(path), line=n, column=names[j] if j < len(names)
                    else str(j + 1), cell=re.sub(r"\s+", " ", cell)[:40]))
            out[k].append(v)
    return [names[j] for j in want], out
