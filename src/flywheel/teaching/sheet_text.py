"""Reading a student's answer sheet as text (``flywheel grade``): its size, its encoding
(a byte-order mark, strict UTF-8, else charset-normalizer on its first DETECT_BYTES), its
bytes in pieces of READ_BYTES decoded into lines, so that a sheet's memory does not grow with
its size. teaching/grading.py grades the lines.
"""
from __future__ import annotations

import codecs
import io
import itertools
import os
from pathlib import Path
from typing import Iterator

from flywheel.errors import Notice

MAX_SHEET_BYTES = 50_000_000       # a class's sheet is a few kB; 10⁵ rows of answers ≈ 8 MB
# the encodings a student's spreadsheet or editor writes: Unicode, Russian Windows, DOS, Unix
ENCODINGS = ("utf_8", "utf_16", "utf_32", "cp1251", "cp866", "koi8_r", "cp1252")
_BOMS = ((b"\xef\xbb\xbf", "utf-8-sig"), (b"\xff\xfe\x00\x00", "utf-32"),
         (b"\x00\x00\xfe\xff", "utf-32"), (b"\xff\xfe", "utf-16"), (b"\xfe\xff", "utf-16"))
#: a sheet is read in pieces of this many bytes (its memory does not grow with its size)
READ_BYTES = 1 << 16
#: charset-normalizer guesses the encoding from at most this many bytes of the sheet's start
DETECT_BYTES = 1 << 20
#: the bytes Windows-1251 leaves undefined: a cp1251 sheet holding one is refused, not
#: guessed as DOS or koi8-r text (garbled names)
_NOT_CP1251 = b"\x98"


class SheetError(ValueError):
    """A sheet that cannot be read as text: one problem row for the whole file."""


def _chunks(source) -> "Iterator[bytes]":
    """The bytes of ``source`` (a path, or bytes) in pieces of READ_BYTES."""
    if isinstance(source, (bytes, bytearray)):
        for i in range(0, len(source), READ_BYTES):
            yield bytes(source[i:i + READ_BYTES])
        return
    with open(source, "rb") as f:
        while piece := f.read(READ_BYTES):
            yield piece


def _head(source, n: int) -> bytes:
    """The first ``n`` bytes of ``source``."""
    if isinstance(source, (bytes, bytearray)):
        return bytes(source[:n])
    with open(source, "rb") as f:
        return f.read(n)


def _text_chunks(source, codec: str) -> "Iterator[str]":
    """The text of ``source`` decoded strictly with ``codec``, piece by piece; a
    UnicodeDecodeError carries ``byte``, its place counted from the file's start."""
    decoder = codecs.getincrementaldecoder(codec)("strict")
    done = 0
    for piece in itertools.chain(_chunks(source), [b""]):
        try:
            text = decoder.decode(piece, final=not piece)
        except UnicodeDecodeError as exc:    # exc.object: the bytes kept back, then the piece
            exc.byte = done - (len(exc.object) - len(piece)) + exc.start
            raise
        done += len(piece)
        if text:
            yield text


def _scan(source, codec: str) -> tuple[int | None, bool]:
    """(the first byte that is not ``codec`` text or None, whether the text holds a NUL),
    the whole of ``source`` read piece by piece (nothing kept)."""
    nul = False
    try:
        for text in _text_chunks(source, codec):
            nul = nul or "\x00" in text
    except UnicodeDecodeError as exc:
        return exc.byte, nul
    return None, nul


def sheet_codec(source) -> str:
    """The codec a sheet is read with (``source``: a path or bytes), checked over the whole
    file without keeping it: a byte-order mark decides (UTF-8, UTF-16, UTF-32: Excel's
    "Unicode text"), else strict UTF-8, else the most plausible of :data:`ENCODINGS` by
    charset-normalizer on the first DETECT_BYTES (cp1251 of a Russian Excel, cp866 of DOS,
    koi8-r). Raises SheetError for binary data (an image renamed .csv), text in none of those
    encodings, a guess the rest of the file does not decode in, or a Windows-1251 sheet with
    a stray byte it leaves undefined (which charset-normalizer would read as DOS or koi8-r
    text, garbling every name).

    >>> sheet_codec("student;вариант".encode("cp1251"))
    'cp1251'
    """
    head = _head(source, 4)
    for bom, enc in _BOMS:
        if head.startswith(bom):
            if _scan(source, enc)[0] is not None:
                raise SheetError(Notice.of(
                    "sheet_bad_bom", "starts with a {enc} byte-order mark but is not {enc} text",
                    enc=enc))
            return enc
    bad, nul = _scan(source, "utf-8")
    if bad is None:
        if nul:
            raise SheetError(Notice.of("sheet_binary", "binary data, not a CSV text file"))
        return "utf-8"
    from charset_normalizer import from_bytes

    sample = _head(source, DETECT_BYTES)
    best = from_bytes(sample, cp_isolation=list(ENCODINGS)).best()
    codec = None if best is None else best.encoding
    if codec != "cp1251" and _NOT_CP1251 in sample:
        clean = sample.replace(_NOT_CP1251, b"")
        again = from_bytes(clean, cp_isolation=list(ENCODINGS)).best()
        if again is not None and again.encoding == "cp1251":
            at = sample.index(_NOT_CP1251)
            raise SheetError(Notice.of(
                "sheet_stray_byte", "Windows-1251 text with a stray byte {byte} at byte {at} (not "
                "a Windows-1251 character: the sheet would be read garbled or not at all; "
                "allowed: the sheet saved again as UTF-8 or Windows-1251)",
                byte=f"0x{sample[at]:02X}", at=at))
    if best is None:
        raise SheetError(Notice.of(
            "sheet_no_encoding", "binary data, not a CSV text file (no text encoding fits: UTF-8, "
            "UTF-16, cp1251, cp866, koi8-r)"))
    at, nul = _scan(source, codec)
    if at is not None:
        raise SheetError(Notice.of(
            "sheet_undecodable", "not {codec} text at byte {at} (the encoding guessed from the "
            "sheet's start; allowed: one encoding for the whole sheet: UTF-8, Windows-1251, "
            "cp866, koi8-r)", codec=codec, at=at))
    if nul:
        raise SheetError(Notice.of("sheet_binary", "binary data, not a CSV text file"))
    return codec


def decode_sheet(data: bytes) -> tuple[str, str]:
    """(text, encoding) of a sheet's bytes (see :func:`sheet_codec`; the whole text, for a
    library user: the grader reads a sheet in pieces).

    >>> decode_sheet("student;вариант".encode("cp1251"))
    ('student;вариант', 'cp1251')
    """
    codec = sheet_codec(data)
    return "".join(_text_chunks(data, codec)), codec.replace("-sig", "")


def _lines(pieces) -> "Iterator[str]":
    """Lines ending at "\\n" (kept), as io.StringIO gives them to the csv module, from pieces
    of text; a line never holds more than itself."""
    pending: list[str] = []
    for piece in pieces:
        start = 0
        while (end := piece.find("\n", start)) >= 0:
            if pending:
                pending.append(piece[start:end + 1])
                yield "".join(pending)
                pending = []
            else:
                yield piece[start:end + 1]
            start = end + 1
        if start < len(piece):
            pending.append(piece[start:])
    if pending:
        yield "".join(pending)


def _check_size(path: Path) -> None:
    """SheetError if the sheet is larger than MAX_SHEET_BYTES."""
    size = path.stat().st_size
    if size > MAX_SHEET_BYTES:
        raise SheetError(Notice.of(
            "sheet_too_large", "{mb:.0f} MB is too large for an answer sheet (allowed: up to "
            "{top:.0f} MB)", mb=size / 1e6, top=MAX_SHEET_BYTES / 1e6))


def _delimiter(header: str) -> str:
    counts = {d: header.count(d) for d in (",", ";", "\t")}
    return max(counts, key=lambda d: (counts[d], d == ","))


def _short(text: str, n: int = 60) -> str:
    text = "".join(c if c.isprintable() else "?" for c in text)
    return text if len(text) <= n else text[:n] + "…"
