"""The blocks of the записка's document model (render/document.py builds the document, render/
report.py and report_formats.py write it out): headings, paragraphs, bullet lists, formulas,
numbered tables and figures with captions. A module of its own so that the sections other
renderers build (the force analysis, render/forces.py) use the same model without importing
the document builder.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field, replace

from flywheel.render.catalogue import words


@dataclass(frozen=True)
class Heading:
    level: int          # 1 the title, 2 a section, 3 a subsection
    text: str           # with its number ("5. Flywheel")


@dataclass(frozen=True)
class Paragraph:
    text: str           # may hold **bold** runs

    @property
    def leads_in(self) -> bool:
        """Whether it leads into the block after it (it ends with a colon: «Подстановка
        найденных значений в формулы (3) и (4):»): a page writer keeps the two on one page."""
        return self.text.rstrip().endswith(":")


@dataclass(frozen=True)
class Where(Paragraph):
    """The symbols of the formula above it explained, one a line, the first line opening with
    «где» ("where") and no colon (ГОСТ 7.32-2017, 6.8.2): ``text`` its lines joined by "\\n".
    A renderer that knows no line break sets it as a paragraph."""

    @property
    def lines(self) -> list[str]:
        return self.text.split("\n")


@dataclass(frozen=True)
class Source(Paragraph):
    """The line that names the case's source («Источник: учебная задача «Задача 2» …, таблица
    27, рис. 5»): a paragraph to every writer; its «таблица 27» is the source's, not a
    reference to this document's table (:func:`referenced`)."""


def sentence(text: str) -> str:
    """A line of the terminal (``ratio: 0,16``) as a paragraph of the записка: a capital
    first letter and a full stop.

    >>> sentence("доля цикла, занятая операцией: t_оп/T_ц = 0,16")
    'Доля цикла, занятая операцией: t_оп/T_ц = 0,16.'
    """
    text = text.strip()
    if not text:
        return text
    text = text[0].upper() + text[1:]
    return text if text[-1] in ".!?…:" else text + "."


@dataclass(frozen=True)
class Bullets:
    items: tuple[str, ...]


@dataclass(frozen=True)
class Formula:
    tex: str            # render/mathfmt.py notation


#: a cell that opens with a word (two lower-case letters or more, then a space, a full stop, a
#: bracket or nothing: «величина», «ед.», "no."), not with a symbol («φ, °», «k», «n_max»)
_OPENING_WORD = re.compile(r"[a-zа-яё]{2,}(?=$|[\s.,:;()])")


def capital(cell: str) -> str:
    """A table's column head or row head from a capital letter, where it opens with a word
    (ГОСТ 2.105-2019, 4.4.5: «Заголовки граф и строк таблицы следует писать с прописной
    буквы»); a cell that opens with a symbol as it is.

    >>> capital("величина"), capital("ед."), capital("φ, °"), capital("k"), capital("n_max")
    ('Величина', 'Ед.', 'φ, °', 'k', 'n_max')
    """
    return cell[0].upper() + cell[1:] if _OPENING_WORD.match(cell) else cell


#: a table's cell with nothing to say (ГОСТ 2.105-2019, 4.4.15: «Если в графе таблицы
#: отсутствуют данные, ставится прочерк»)
NO_DATA = "—"


@dataclass(frozen=True)
class Table:
    """A numbered table: its column heads and each row's head (its first cell) from a capital
    letter (:func:`capital`), an empty cell and a dimensionless unit a dash (:data:`NO_DATA`; a
    task sheet's blank cell to fill in is no-break spaces, not empty), whoever builds it."""

    number: int
    caption: str
    header: tuple[str, ...]
    rows: tuple[tuple[str, ...], ...]

    def __post_init__(self):
        object.__setattr__(self, "header", tuple(capital(h) for h in self.header))
        object.__setattr__(self, "rows", tuple(_row(r) for r in self.rows))


#: a cell that says "no unit" (a dimensionless quantity's, nomenclature.unit("-")): in a table
#: the same dash as a cell without data, so that a column holds one kind of dash
NO_UNIT = "–"


def _row(cells: tuple[str, ...]) -> tuple[str, ...]:
    """A table's row as :class:`Table` keeps it: its head from a capital, an empty cell and a
    dimensionless unit's «–» the one dash «—» (a «Ед.» column had mixed the two)."""
    cells = tuple(NO_DATA if not c or c == NO_UNIT else c for c in cells)
    return (capital(cells[0]), *cells[1:]) if cells else cells


@dataclass(frozen=True)
class Figure:
    number: int
    caption: str
    file: str           # the PNG's name under plots/


@dataclass(frozen=True)
class TitlePage:
    """The title page of a Russian записка in PDF and DOCX (ГОСТ 7.32-2017, 6.1) and its right
    margin: the case's ``[document]`` table (cases/document.py), the command line's
    ``--student/--group/--teacher`` over it; a blank stays blank (a line to write on)."""

    machine: str = ""
    ministry: str = ""
    university: str = ""
    department: str = ""
    student: str = ""
    group: str = ""
    teacher: str = ""
    city: str = ""
    year: str = ""
    designation: str = ""
    tech_control: str = ""
    norm_control: str = ""
    approved: str = ""
    margin_right_mm: float = 10.0
    #: the page frame (``--frame``): "" none, "eskd" the ЕСКД frame with the title blocks of
    #: forms 2 and 2a (ГОСТ 2.104-2006; render/report_frame.py)
    frame: str = ""

    @classmethod
    def of(cls, spec, machine: str, **given: str | None) -> "TitlePage":
        """From a ``DocumentSpec`` (None: none given) and the options ``given`` (None or ""
        keeps the case's)."""
        names = ("ministry", "university", "department", "student", "group", "teacher", "city",
                 "designation", "tech_control", "norm_control", "approved")
        values = {k: (getattr(spec, k) or "") if spec is not None else "" for k in names}
        values.update({k: v for k, v in given.items() if v})
        year = getattr(spec, "year", None) if spec is not None else None
        return cls(machine=machine, year="" if year is None else str(year),
                   margin_right_mm=spec.margin_right_mm if spec is not None else 10.0, **values)


@dataclass
class Document:
    title: str
    lang: str
    blocks: list = field(default_factory=list)
    #: the title page of the ГОСТ layout (Russian PDF, DOCX); None: one with blanks
    front: TitlePage | None = None

    @property
    def tables(self) -> list[Table]:
        return [b for b in self.blocks if isinstance(b, Table)]

    @property
    def figures(self) -> list[Figure]:
        return [b for b in self.blocks if isinstance(b, Figure)]

    @property
    def headings(self) -> list[Heading]:
        return [b for b in self.blocks if isinstance(b, Heading)]

    def add_table(self, caption: str, header, rows) -> None:
        """Append a table numbered after the document's tables so far; cells as strings."""
        self.blocks.append(Table(len(self.tables) + 1, caption, tuple(header),
                                 tuple(tuple(str(c) for c in r) for r in rows)))

    def add_formula(self, tex: str) -> int:
        """Append a display formula; its number «(n)», which the text cites: every writer
        numbers the document's formulas in their order (ГОСТ 7.32-2017, 6.8.3)."""
        self.blocks.append(Formula(tex))
        return sum(isinstance(b, Formula) for b in self.blocks)

    @classmethod
    def titled(cls, heading: str, title: str, source: str, source_word: str,
               lang: str) -> "Document":
        """A document opened as every command's записка opens: "<heading>: <title>" as its
        first heading, then "<source_word>: <source>" when a source is given."""
        doc = cls(title or heading, lang)
        doc.blocks.append(Heading(1, f"{heading}: {title}" if title else heading))
        if source:
            doc.blocks.append(Source(f"{source_word}: {source}"))
        return doc


def front(doc: Document, spec, frame: str = "", **given: str | None) -> Document:
    """``doc`` with its title page from the case's ``[document]`` ``spec`` (None: blanks) and
    the options ``given``; the machine is the document's title; ``frame`` the page frame."""
    doc.front = replace(TitlePage.of(spec, doc.title, **given), frame=frame)
    return doc


#: the sentence that refers to a table or figure the text does not name (ГОСТ 7.32-2017, 6.5
#: and 6.6, as ГОСТ 2.105: every illustration and every table is referred to in the text, and
#: stands after the text that first names it): the caption and where it is — a dash, so that
#: no verb has to agree with the caption
REFERENCE = words("reference", {"table": "{caption} — in Table {n}.",
                                "figure": "{caption} — in Figure {n}.",
                                "table_short": "The values are in Table {n}.",
                                "figure_short": "See Figure {n}.",
                                "figures": "The graphs — in Figures {first}–{last}."})
#: a caption too long to open a sentence with, or with a dash or a semicolon of its own, or the
#: heading's words just above: the short reference («Данные приведены в таблице 18.»)
CAPTION_IN_SENTENCE = 70
#: a reference the text already makes: «в таблице 5», «(таблица 5)», «на рисунке 3», «рис. 3»
_CITED = {"table": re.compile(r"(?i)таблиц\w*\s+(\d+)"),
          "figure": re.compile(r"(?i)(?:рисун\w*|рис\.)\s+(\d+)")}


def _texts(b) -> tuple[str, ...]:
    """The text of a block that may refer to a table or figure (not the case's source line)."""
    if isinstance(b, Source):
        return ()
    if isinstance(b, Paragraph):
        return (b.text,)
    if isinstance(b, Bullets):
        return b.items
    return ()


def referenced(blocks, lang: str) -> list:
    """A Russian записка's blocks with a sentence before each table and each figure the text
    does not refer to (ГОСТ 7.32-2017, 6.5, 6.6: every table and illustration is referred to
    in the text): «Аналоги скоростей в стандартных положениях — в таблице 5.»; a run of two
    or more figures one after the other, «Графики — на рисунках 14–26.» before the first. Placed
    before a paragraph that leads into the table (:attr:`Paragraph.leads_in`), so that the two
    stay together. Another language's blocks as they are (the ГОСТ layout is the Russian
    record's). A reference counts where it stands before the table or figure (a table stands
    after the text that first names it): a sentence after it is no reference to it."""
    blocks = list(blocks)
    if lang != "ru":
        return blocks
    cited: dict[str, set] = {kind: set() for kind in _CITED}     # by the text so far

    def read(b) -> None:
        for kind, rx in _CITED.items():
            cited[kind] |= {int(m) for t in _texts(b) for m in rx.findall(t)}

    out: list = []
    i, sources = 0, False               # the list of sources cites other works' tables
    while i < len(blocks):
        b = blocks[i]
        if isinstance(b, Heading):
            sources = HEADING_NUMBER.sub("", b.text).rstrip(".") in SOURCES
        kind = "table" if isinstance(b, Table) else "figure" if isinstance(b, Figure) else ""
        if not kind or b.number in cited[kind]:
            if not sources:
                read(b)
            out.append(b)
            i += 1
            continue
        run = 1
        while (kind == "figure" and i + run < len(blocks)
               and isinstance(blocks[i + run], Figure)
               and blocks[i + run].number not in cited["figure"]):
            run += 1
        said = REFERENCE[lang]
        if run > 1:
            text = said["figures"].format(first=b.number, last=blocks[i + run - 1].number)
        elif (len(b.caption) > CAPTION_IN_SENTENCE or " — " in b.caption
              or ";" in b.caption or _heads(out, b.caption)):
            text = said[kind + "_short"].format(n=b.number)
        else:
            text = said[kind].format(caption=_caption_start(b.caption), n=b.number)
        at = len(out)
        while at and isinstance(out[at - 1], Paragraph) and out[at - 1].leads_in:
            at -= 1
        out.insert(at, Paragraph(text))
        out.extend(blocks[i:i + run])
        i += run
    return out


def _heads(out: list, caption: str) -> bool:
    """Whether the last heading of ``out`` says ``caption`` («1.1 Машина, кривошип и маховик»
    over «Таблица 1 — Машина, кривошип и маховик»): the caption a third time would be too
    many."""
    heading = next((b for b in reversed(out) if isinstance(b, Heading)), None)
    return heading is not None and HEADING_NUMBER.sub("", heading.text).strip(" .").lower() \
        == caption.strip(" .").lower()


def _caption_start(caption: str) -> str:
    """A caption as the start of a sentence: from a capital letter, no full stop of its own."""
    caption = caption.strip().rstrip(".")
    return caption[:1].upper() + caption[1:]


#: the headings the builders give their list of sources (unnumbered: a structural element)
SOURCES = {"Источники", "Список источников", "Список использованных источников", "Sources"}
#: a heading's own number, «1.6. », «7 »
HEADING_NUMBER = re.compile(r"^\s*\d+(\.\d+)*\.?\s+")


def section_numbers(blocks):
    """Each block with, for a section or subsection heading, its number counted without a gap
    (2, then 2.1, 2.2; "" for the sources, a structural element) and its text without the
    number its builder wrote; (block, None, None) for any other block. :func:`numbered` and
    the ГОСТ layout (report_gost.sections) number by it."""
    n, m = 0, 0
    for b in blocks:
        if not isinstance(b, Heading) or b.level not in (2, 3):
            yield b, None, None
            continue
        text = HEADING_NUMBER.sub("", b.text)
        if b.level == 2 and text.rstrip(".") in SOURCES:
            yield b, "", text
        elif b.level == 2:
            n, m = n + 1, 0
            yield b, str(n), text
        else:
            m += 1
            yield b, f"{max(n, 1)}.{m}", text


def numbered(blocks) -> list:
    """The blocks with their sections numbered 1, 2, … and subsections 1.1, 1.2, … without a
    gap, whatever numbers the builders wrote (a section left out where the case has nothing
    for it — the compressor's technological forces — had left «1.4» followed by «1.6»; the
    force analysis and the warnings had none); the sources unnumbered
    (:func:`section_numbers`)."""
    return [b if number is None else replace(b, text=f"{number}. {text}" if number else text)
            for b, number, text in section_numbers(blocks)]
