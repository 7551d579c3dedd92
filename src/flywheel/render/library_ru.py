"""The words of the libraries and of the system inside an error line, in Russian: tomllib's
(Python 3.11's tomllib/_parser.py, every message it raises), json's, matplotlib's savefig and
the system's reasons by errno (OSError.strerror). A message not listed (another version's
wording) keeps its English words. These are fixed texts of other programs matched by pattern,
not flywheel's own sentences (those are in the catalogue, locale/ru/LC_MESSAGES/flywheel.po).
"""
from __future__ import annotations

import errno
import re

#: the system's reasons (OSError.strerror) by errno
_OS_REASONS_RU = {"ENOENT": "нет такого файла или папки", "EACCES": "нет доступа",
                  "EPERM": "операция не разрешена", "ENOTDIR": "часть пути — не папка",
                  "EISDIR": "это папка", "ENAMETOOLONG": "слишком длинное имя файла",
                  "EROFS": "файловая система только для чтения",
                  "ENOSPC": "на устройстве нет места", "EDQUOT": "превышена дисковая квота",
                  "EEXIST": "файл уже существует", "EIO": "ошибка ввода-вывода",
                  "ELOOP": "слишком много символических ссылок", "EBUSY": "устройство занято",
                  "ETXTBSY": "файл занят", "EINVAL": "недопустимый аргумент",
                  "EFBIG": "файл слишком велик", "EMFILE": "открыто слишком много файлов"}


def os_reason_ru(code: int | None, reason: str) -> str:
    """The system's reason (OSError.strerror) in Russian by its errno; another as it said it."""
    return _OS_REASONS_RU.get(errno.errorcode.get(code, ""), reason) if code else reason


TOML_RU = [
    (r"Invalid statement", "недопустимая инструкция"),
    (r"Expected newline or end of document after a statement",
     "после инструкции ожидается перевод строки или конец документа"),
    (r"Expected (?P<x>'.*')", "ожидается {x}"),
    (r"Found invalid character (?P<x>'.*')", "недопустимый символ {x}"),
    (r"Cannot declare (?P<x>.+) twice", "таблица {x} объявлена дважды"),
    (r"Cannot overwrite a value", "значение нельзя перезаписать"),
    (r"Expected '\]' at the end of a table declaration",
     "в конце объявления таблицы ожидается ']'"),
    (r"Expected '\]\]' at the end of an array declaration",
     "в конце объявления массива таблиц ожидается ']]'"),
    (r"Cannot mutate immutable namespace (?P<x>.+)",
     "нельзя изменить уже заданную таблицу {x}"),
    (r"Cannot redefine namespace (?P<x>.+)", "нельзя переопределить таблицу {x}"),
    (r"Expected '=' after a key in a key/value pair", "после ключа ожидается '='"),
    (r"Invalid initial character for a key part", "недопустимый первый символ ключа"),
    (r"Unclosed array", "массив не закрыт"),
    (r"Duplicate inline table key (?P<x>'.*')", "ключ {x} встроенной таблицы повторяется"),
    (r"Unclosed inline table", "встроенная таблица не закрыта"),
    (r"Unescaped '\\' in a string", "неэкранированный '\\' в строке"),
    (r"Invalid hex value", "недопустимое шестнадцатеричное значение"),
    (r"Escaped character is not a Unicode scalar value",
     "экранированный символ — не скалярное значение Unicode"),
    (r"Unterminated string", "строка не закрыта"),
    (r"Illegal character (?P<x>'.*')", "недопустимый символ {x}"),
    (r"Invalid date or datetime", "недопустимая дата или дата и время"),
    (r"Invalid value", "недопустимое значение"),
]


def toml_detail_ru(detail: str) -> str:
    """tomllib's message "<what> (at line N, column M)" in Russian, its place «(строка N,
    столбец M)»; a message not in TOML_RU keeps its words."""
    m = re.fullmatch(r"(?P<what>.*?)(?P<place> \(at line \d+, column \d+\)| \(at end of document\))?",
                     detail, re.S)
    what, place = said_ru(m.group("what"), TOML_RU), m.group("place") or ""
    place = re.sub(r"\(at line (\d+), column (\d+)\)", r"(строка \1, столбец \2)", place)
    return what + place.replace("(at end of document)", "(в конце документа)")


#: json's own words (Python's json/decoder.py, every message it raises) in Russian
JSON_RU = [
    (r"Expecting value", "ожидается значение"),
    (r"Expecting property name enclosed in double quotes",
     "ожидается имя свойства в двойных кавычках"),
    (r"Expecting ',' delimiter", "ожидается разделитель ','"),
    (r"Expecting ':' delimiter", "ожидается разделитель ':'"),
    (r"Extra data", "лишние данные после документа"),
    (r"Unterminated string starting at", "незакрытая строка, её начало"),
    (r"Invalid control character at", "недопустимый управляющий символ"),
    (r"Invalid control character (?P<x>'.*') at", "недопустимый управляющий символ {x}"),
    (r"Invalid \\escape", "недопустимая escape-последовательность"),
    (r"Invalid \\escape: (?P<x>'.*')", "недопустимая escape-последовательность {x}"),
    (r"Invalid \\uXXXX escape", "недопустимая последовательность \\uXXXX"),
]


def said_ru(text: str, table: list) -> str:
    """A library's fixed message in Russian from ``table`` (regex, template); as it is when
    no entry matches."""
    for rx, ru in table:
        hit = re.fullmatch(rx, text)
        if hit:
            return ru.format(**hit.groupdict())
    return text


#: matplotlib's reasons an image cannot be saved (savefig's ValueError)
MATPLOTLIB_RU = [
    (r"Format '(?P<x>.*)' is not supported \(supported formats: (?P<y>.*)\)",
     "формат '{x}' не поддерживается (поддерживаются: {y})"),
]
