"""`flywheel … --help --lang ru`: the help page in Russian — each option's and argument's help,
each command's description and typer's own words (panel titles, ``Usage:``, ``[default: …]``,
``[required]``, the --help and completion options) — and the English page as typer makes it,
untouched by a Russian page printed before it."""
import re
import subprocess
import sys

import pytest
import typer
from typer import rich_utils
from typer.testing import CliRunner

from flywheel.cli import app
from flywheel.cli.options import help_msgid
from flywheel.render.catalogue import catalogue

runner = CliRunner()
COMMAND = typer.main.get_command(app)
WIDE = {"env": {"COLUMNS": "400"}, "terminal_width": 400}

#: typer's English words and English sentences of the help texts, none of which may be left on
#: a Russian page
ENGLISH = ["Usage:", "Options", "Arguments", "Commands", "[default:", "[required]",
           "Show this message and exit", "Install completion", "Case file (TOML)",
           "Output folder", "Report angle", "Language of what is printed", "repeatable",
           "Print the results as JSON", "The student on the title page", "Dynamic analysis",
           "Run the whole dynamic analysis", "Grade students' answers", "answer key"]
#: English function words: a Russian page has none (option values, file names and symbols
#: it keeps — all, record, steady, excel-ru, summary.json, a_ij — are none of them)
FUNCTION_WORDS = {"the", "of", "and", "with", "to", "is", "for", "in", "an", "if", "its", "by",
                  "or", "from", "this", "at", "as", "per", "instead", "also", "each", "write",
                  "print", "show"}


def _page(*args: str) -> str:
    res = runner.invoke(app, list(args), **WIDE)
    assert res.exit_code == 0, res.output
    return res.output


def _english_left(page: str) -> set[str]:
    return {w for w in re.findall(r"(?<![\w./-])[a-z]+(?![\w./-])", page) if w in FUNCTION_WORDS}


@pytest.mark.parametrize("args, russian", [
    (["run", "--help", "--lang", "ru"],
     ["Использование:", "[ПАРАМЕТРЫ] CASE", "Аргументы", "Параметры", "Файл задания (TOML).",
      "[обязательный]", "[по умолчанию: 3600]", "Выполнить полный динамический анализ",
      "Число интервалов сетки по φ за цикл.", "Показать эту справку и выйти.",
      "Движение кривошипа в силовом расчёте", "пояснительной записки"]),
    (["--help", "--lang", "ru"],
     ["Использование:", "[ПАРАМЕТРЫ] КОМАНДА [АРГУМЕНТЫ]...", "Команды",
      "Динамический анализ машин", "расчёт маховика", "Установить автодополнение",
      "Проверить ответы студентов по ключу"]),
    (["grade", "--help", "--lang", "ru"],
     ["Проверить ответы студентов по ключу", "Относительный допуск", "0,01"]),
    (["task2", "--help", "--lang", "ru"],
     ["Приведённый момент инерции J [кг·м²]", "коэффициент неравномерности δ",
      "Постоянный движущий момент M_D [Н·м]", "(M_D − M_C)/J"]),
])
def test_a_russian_help_page_is_in_russian(args, russian):
    page = _page(*args)
    flat = " ".join(page.split())
    for text in russian:
        assert text in flat, text
    for text in ENGLISH:
        assert text not in flat, text
    assert not _english_left(page), _english_left(page)


@pytest.mark.parametrize("name", [None, *sorted(COMMAND.commands)])
def test_no_help_page_in_russian_has_english_words_left(name):
    page = _page(*([] if name is None else [name]), "--help", "--lang", "ru")
    assert "Использование:" in page and "Usage:" not in page
    assert not _english_left(page), (name, _english_left(page))


def test_every_help_text_has_its_russian():
    """Each parameter's help and each command's description (typer's --help and completion
    options too) is an entry of the catalogue (msgctxt "help") with a Russian msgstr."""
    ru = catalogue("ru")

    def walk(command):
        ctx = typer._click.Context(command, info_name=command.name)
        texts = [command.help] + [p.help for p in command.get_params(ctx)]
        for text in filter(None, texts):
            msgid = help_msgid(text)
            russian = ru.pgettext("help", msgid)
            assert russian != msgid and re.search("[а-яё]", russian), msgid
        for sub in getattr(command, "commands", {}).values():
            walk(sub)

    walk(COMMAND)


@pytest.mark.parametrize("name", [None, "run", "grade"])
def test_the_english_page_is_typers_own_before_and_after_a_russian_one(name):
    """The English page says typer's words and the English help, and a Russian page printed in
    between leaves it byte-identical (typer's constants and the help texts put back)."""
    args = [] if name is None else [name]
    constants = {k: getattr(rich_utils, k) for k in dir(rich_utils) if k.isupper()}
    before = _page(*args, "--help")
    _page(*args, "--help", "--lang", "ru")
    assert _page(*args, "--help") == before
    assert _page(*args, "--help", "--lang", "en") == before if name else True
    assert {k: getattr(rich_utils, k) for k in dir(rich_utils) if k.isupper()} == constants
    assert "Usage:" in before and "Options" in before and "Show this message and exit." in before
    assert not re.search("[а-яё]{4}", before.replace("ω_ср", "").replace("Задача", "")
                         .replace("Ефанов", "").replace("ЕСКД", "").replace("ГОСТ", "")
                         .replace("записка", ""))


def test_the_entry_point_prints_the_russian_page():
    """`python -m flywheel run --help --lang ru` (the console entry point): Russian, exit 0."""
    res = subprocess.run([sys.executable, "-m", "flywheel", "run", "--help", "--lang", "ru"],
                         capture_output=True, text=True, encoding="utf-8", timeout=120,
                         env={**__import__("os").environ, "COLUMNS": "100"})
    assert res.returncode == 0, res.stderr
    assert "Использование:" in res.stdout and "Файл задания (TOML)." in res.stdout
    assert "Show this message" not in res.stdout and res.stderr == ""
