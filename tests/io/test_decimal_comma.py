"""A Russian user writes a decimal comma («delta = 0,05»): TOML reads it as a syntax error, or
inside an array as two numbers, and in quotes as a string. The error line says what to write
(io/toml.py ``decimal_comma``, io/schema.py ``_as_number``), in the user's language."""
from __future__ import annotations

import pytest

from flywheel.errors import CaseFileError, said
from flywheel.io.toml import decimal_comma, read_toml
from flywheel.render.messages import message


@pytest.mark.parametrize("text, found", [
    ("a = 1\ndelta = 0,05\n", "0,05"),
    ("x = { m = 0,8, J = 1.0 }\n", "0,8"),
    ("g = -9,81  # m/s²\n", "-9,81"),
    ('title = "bad\n', ""),                     # an unclosed string: no number to blame
    ("a = 1\nb = 2 3\n", ""),
    ("a = 1 # 0,5 in a comment\nb = = 2\n", ""),
])
def test_the_number_with_a_comma_on_the_lines_error_is_found(text, found):
    import tomllib

    with pytest.raises(tomllib.TOMLDecodeError) as exc:
        tomllib.loads(text)
    assert decimal_comma(text, str(exc.value)) == found


def test_the_error_line_says_what_to_write_in_both_languages(tmp_path):
    path = tmp_path / "c.toml"
    path.write_text("[machine]\ndelta = 0,05\n", encoding="utf-8")
    with pytest.raises(CaseFileError) as exc:
        read_toml(path)
    en, ru = message(said(exc.value), "en"), message(said(exc.value), "ru")
    assert en.endswith(": a number takes a decimal point: 0.05, not 0,05"), en
    assert ru.endswith(": число пишется с десятичной точкой: 0.05, а не 0,05"), ru
    assert "синтаксическая ошибка TOML" in ru and "(строка 2, столбец" in ru, ru
