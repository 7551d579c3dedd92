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


@pytest.mark.parametrize("text, key, found", [
    ("gravity = [0.0, -9,81]  # g\n", "gravity", ("-9,81", 1)),
    ("guide = { through = [0,5, 0.0], angle_deg = 90.0 }\n", "through", ("0,5", 1)),
    ("s = [0, 0.1,\n     0,2, 0.3]\n", "s", ("0,2", 2)),        # an array over two lines
    ("s = [0, 0.1]\nt = [0,2]\n", "s", ("", 0)),                 # another key's array
    ("s = [0, 0.1]\nt = [0,2]\n", "", ("0,2", 2)),               # any array
    ("s = [0, 0.1]\nu = 1,5\n", "", ("", 0)),                    # not in an array
    ("s = [0, 0.1] , 2,5\n", "", ("", 0)),                        # after the array's end
    ("s = [0, 0.1, 0.2]  # 0,5 in a comment\n", "s", ("", 0)),
    ("xs = [1, 2]\n", "s", ("", 0)),                             # a longer key is not it
    ("s = [1, 2, 3]\n", "s", ("", 0)),
])
def test_a_number_with_a_comma_in_an_array_is_found(text, key, found):
    from flywheel.io.toml import comma_in_array

    assert comma_in_array(text, key) == found


@pytest.mark.parametrize("old, new, field, en_start, ru_start", [
    ("gravity   = [0.0, -9.81]", "gravity   = [0.0, -9,81]", "machine.gravity",
     "tuple should have at most 2 items", "слишком много элементов"),
    ("towards_head   = [1, 1, 1, 0.75,", "towards_head   = [1, 1, 1, 0,75,",
     "cylinders[0].towards_head", "needs 11 values", "нужно 11 значений"),
])
def test_an_array_read_as_more_numbers_says_the_comma_may_be_meant(tmp_path, old, new, field,
                                                                    en_start, ru_start):
    """«[0.0, -9,81]» is three numbers to TOML; the field's error (too many items, a list of
    the wrong length) says what to write if -9,81 was meant."""
    from pathlib import Path

    from flywheel.cases.run import load_case

    text = Path("cases/compressor.toml").read_text(encoding="utf-8")
    assert old in text
    path = tmp_path / "c.toml"
    path.write_text(text.replace(old, new, 1), encoding="utf-8")
    with pytest.raises(CaseFileError) as exc:
        load_case(path)
    given = new.split("[", 1)[1].split()[-1].rstrip(",]")
    line = 1 + text.split(old)[0].count("\n")
    en, ru = message(said(exc.value), "en"), message(said(exc.value), "ru")
    assert en.startswith(f"{path}: {field}: {en_start}"), en
    assert en.endswith(f"; if {given} on line {line} is one number written with a decimal "
                       f"comma, write it with a point: {given.replace(',', '.')}"), en
    assert ru.startswith(f"{path}: {field}: {ru_start}"), ru
    assert ru.endswith(f"; если {given} в строке {line} — одно число с десятичной запятой, "
                       f"пишите его с точкой: {given.replace(',', '.')}"), ru


def test_an_array_without_a_comma_gets_no_hint(tmp_path):
    from pathlib import Path

    from flywheel.cases.run import load_case

    text = Path("cases/compressor.toml").read_text(encoding="utf-8")
    path = tmp_path / "c.toml"
    path.write_text(text.replace("gravity   = [0.0, -9.81]", "gravity   = [0.0, -9.81, 1.0]"),
                    encoding="utf-8")
    with pytest.raises(CaseFileError) as exc:
        load_case(path)
    assert "at most 2 items" in str(exc.value) and "decimal comma" not in str(exc.value)
