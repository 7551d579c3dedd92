"""The Russian catalogue (src/flywheel/locale/ru/LC_MESSAGES/flywheel.po): extract, update, compile,
check. English is the msgid, the Notice's code the msgctxt.

    python tools/i18n.py extract   # the raise sites → build/flywheel.pot (msgctxt = code, msgid =
                                   #   the English template, #: where it is raised), and every
                                   #   string of a renderer's words("kind", {key: english})
                                   #   (msgctxt "kind:key")
    python tools/i18n.py update    # merge the .pot into the .po (new entries untranslated)
    python tools/i18n.py compile   # the .po → flywheel.mo (committed; read at run time by gettext)
    python tools/i18n.py check     # every entry translated, no fuzzy, placeholders agree, .mo up to date
    python tools/i18n.py todo      # the raise sites still written Notice(f"…", code) (not Notice.of)
    python tools/i18n.py adopt F   # F: an old-style block of Russian templates (``MESSAGES_RU.update
                                   #   ({code: template})``, ``MESSAGES_RU[code] = …``) cut from
                                   #   render/nomenclature.py: its templates become the msgstrs of
                                   #   their codes (run update first; a block's function of Russian
                                   #   words goes to render/message_params.py HOOKS by hand)

Babel (the test extra) does the reading and writing of the catalogue; at run time only the
standard library's gettext reads the compiled .mo (render/messages.py).
"""
from __future__ import annotations

import ast
import io
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PACKAGE = ROOT / "src" / "flywheel"
LOCALE = PACKAGE / "locale"
PO = LOCALE / "ru" / "LC_MESSAGES" / "flywheel.po"
MO = PO.with_suffix(".mo")
POT = ROOT / "build" / "flywheel.pot"
#: Russian has three plural forms (1 цикл, 2 цикла, 5 циклов)
PLURAL_FORMS = ("nplurals=3; plural=(n%10==1 && n%100!=11 ? 0 : n%10>=2 && n%10<=4 && "
                "(n%100<10 || n%100>=20) ? 1 : 2);")
#: the helpers of render/messages.py whose literal arguments are catalogue entries
PLURAL_CALLS = {"plural": (0, 1, 2)}          # plural(context, singular, plural, n)
LABEL_CALLS = {"label": (0, 1)}               # label(context, english)
#: render/catalogue.py ``words(kind, {key: english})``: a renderer's sentences, msgctxt "kind:key"
WORDS_CALLS = {"words"}
#: the note an entry of ``words`` carries (update drops such an entry once its key is gone)
WORDS_NOTE = "a sentence of a renderer: words("
#: msgctxt and note of a case field's description (the JSON Schema of `flywheel schema`, the
#: generated field references docs/case-fields.md and docs/ru/case-format.md)
FIELD_CONTEXT = "field"
FIELD_NOTE = "a case field's description: "
#: msgctxt and note of a help text of the command line (an option's or argument's help, a
#: command's description; typer's own options too): `flywheel … --help --lang ru`
HELP_CONTEXT = "help"
HELP_NOTE = "a help text of: "


def _template(node: ast.expr, params: dict[str, str]) -> tuple[str, bool]:
    """The English template of a Notice's text: an f-string's ``{expr}`` named by the parameter
    given the same expression (``{x:g}`` for ``x=x``), else its source (listed: ``unclean``,
    the raise sites still to be written as templates of their parameters)."""
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        return node.value.replace("{", "{{").replace("}", "}}"), []
    if isinstance(node, ast.JoinedStr):
        out, unclean = [], []
        for part in node.values:
            if isinstance(part, ast.Constant):
                out.append(part.value.replace("{", "{{").replace("}", "}}"))
                continue
            src = ast.unparse(part.value)
            name = params.get(src)
            if name is None:
                name = src
                unclean.append(src)
            conv = "" if part.conversion == -1 else "!" + chr(part.conversion)
            spec = ""
            if part.format_spec is not None:
                spec = ":" + "".join(v.value if isinstance(v, ast.Constant) else
                                     "{" + ast.unparse(v.value) + "}"
                                     for v in part.format_spec.values)
                if not all(isinstance(v, ast.Constant) for v in part.format_spec.values):
                    unclean.append(src + spec)
            out.append("{" + name + conv + spec + "}")
        return "".join(out), unclean
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Add):
        a, ua = _template(node.left, params)
        b, ub = _template(node.right, params)
        return a + b, ua + ub
    return "{" + ast.unparse(node) + "}", [ast.unparse(node)]


def extract_notices(package: Path = PACKAGE) -> dict[str, dict]:
    """Every ``Notice.of("code", template, **params)`` and ``Notice(text, "code", **params)`` of
    the package: code → its English template (the first raise site's; an f-string's fields
    named by the parameters), where it is raised, the fields that are no parameter."""
    found: dict[str, dict] = {}
    for path in sorted(package.rglob("*.py")):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for node in ast.walk(tree):
            if not isinstance(node, ast.Call) or len(node.args) < 2:
                continue
            if ast.unparse(node.func) == "Notice.of":              # Notice.of(code, template, …)
                code_arg, text = node.args
                msgid, unclean = text.value, []
            elif getattr(node.func, "id", "") == "Notice":         # Notice(f"…", code, …)
                text, code_arg = node.args[:2]
                params = {ast.unparse(k.value): k.arg for k in node.keywords if k.arg}
                msgid, unclean = _template(text, params)
            else:
                continue
            if not isinstance(code_arg, ast.Constant):
                continue
            code = code_arg.value
            loc = (str(path.relative_to(package.parent.parent)), node.lineno)
            entry = found.setdefault(code, {"msgid": msgid, "unclean": unclean, "locs": [],
                                            "params": set()})
            entry["locs"].append(loc)
            entry["params"] |= {k.arg for k in node.keywords if k.arg}
    return found


def extract_words(package: Path = PACKAGE) -> dict[str, dict]:
    """Every string of every ``words("kind", {key: "english", …})`` of the package (a nested
    dict's keys joined by "."): msgctxt "kind:key" → its English (the msgid) and where it is."""
    found: dict[str, dict] = {}

    def walk(d: ast.Dict, ctx: str, loc):
        for k, v in zip(d.keys, d.values):
            if not (isinstance(k, ast.Constant) and isinstance(k.value, str)):
                continue
            if isinstance(v, ast.Dict):
                walk(v, f"{ctx}{k.value}.", loc)
            elif isinstance(v, ast.Constant) and isinstance(v.value, str) and v.value:
                found[f"{ctx}{k.value}"] = {"msgid": v.value, "locs": [(loc[0], v.lineno)],
                                            "kind": loc[1]}

    for path in sorted(package.rglob("*.py")):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for node in ast.walk(tree):
            if (isinstance(node, ast.Call) and len(node.args) == 2
                    and getattr(node.func, "id", getattr(node.func, "attr", "")) in WORDS_CALLS
                    and isinstance(node.args[0], ast.Constant)
                    and isinstance(node.args[1], ast.Dict)):
                rel = str(path.relative_to(package.parent.parent))
                walk(node.args[1], node.args[0].value + ":", (rel, node.args[0].value))
    return found


def extract_fields() -> dict[str, list[str]]:
    """Every description of the case-file schema (`flywheel schema`: the fields' and the
    tables' own), English → the schema paths that use it."""
    sys.path.insert(0, str(PACKAGE.parent))
    from flywheel.cases.describe import descriptions

    return descriptions()


def extract_help() -> dict[str, list[str]]:
    """Every help text of the command line as its help page shows it (cli/options.py
    ``help_msgid``): each command's description and each of its parameters' help, typer's
    --help and completion options included; English → where it is ("run --out", "run")."""
    sys.path.insert(0, str(PACKAGE.parent))
    import typer.main
    from typer import _click

    from flywheel.cli.commands import app
    from flywheel.cli.options import help_msgid

    found: dict[str, list[str]] = {}

    def walk(command, path: str) -> None:
        ctx = _click.Context(command, info_name=command.name)
        if command.help:
            found.setdefault(help_msgid(command.help), []).append(path or "flywheel")
        for param in command.get_params(ctx):
            if getattr(param, "help", None):
                name = max(param.opts, key=len) if param.param_type_name == "option" else \
                    (param.metavar or param.name)
                found.setdefault(help_msgid(param.help), []).append(f"{path} {name}".strip())
        for name in sorted(getattr(command, "commands", {})):
            walk(command.commands[name], name)

    walk(typer.main.get_command(app), "")
    return found


def new_catalog():
    """An empty Russian catalogue with its header (Babel)."""
    from babel.messages.catalog import Catalog

    cat = Catalog(locale="ru", domain="flywheel", project="flywheel", version="0.1.0",
                  copyright_holder="flywheel", charset="utf-8", fuzzy=False,
                  creation_date=_EPOCH, revision_date=_EPOCH)
    return cat


def read_po(path: Path = PO):
    from babel.messages.pofile import read_po as _read

    with open(path, "rb") as fh:
        return _read(fh, locale="ru", domain="flywheel")


def write_po(cat, path: Path = PO) -> None:
    """The catalogue as a .po, its order kept, lines as they are (no wrapping: a msgid is one
    line, diffs stay readable)."""
    from babel.messages.pofile import write_po as _write

    path.parent.mkdir(parents=True, exist_ok=True)
    buf = io.BytesIO()
    _write(buf, cat, width=0, omit_header=False, sort_output=False, include_previous=False)
    path.write_bytes(buf.getvalue())


def mo_bytes(cat) -> bytes:
    """The compiled catalogue (GNU .mo) of ``cat``, as gettext reads it."""
    from babel.messages.mofile import write_mo

    buf = io.BytesIO()
    write_mo(buf, cat, use_fuzzy=False)
    return buf.getvalue()


import datetime as _dt  # noqa: E402

_EPOCH = _dt.datetime(2026, 1, 1, tzinfo=_dt.timezone.utc)


# -- the commands -----------------------------------------------------------------------------------
def is_notice(context: str | None) -> bool:
    """A Notice's entry (msgctxt = its code) rather than a "kind:key" label or a "count"."""
    return bool(context) and ":" not in context and context not in ("count", FIELD_CONTEXT,
                                                                    HELP_CONTEXT)


def pot():
    """The template (.pot) of the raise sites: msgctxt = the Notice's code, msgid = its English
    template, #: where it is raised, #. its parameters."""
    cat = new_catalog()
    for code, e in extract_notices().items():
        notes = ["params: " + (", ".join(sorted(e["params"])) or "none")]
        if e["unclean"]:
            notes.append("not a parameter: " + " | ".join(e["unclean"]))
        cat.add(e["msgid"], "", locations=e["locs"], context=code, auto_comments=notes)
    for ctx, e in extract_words().items():
        cat.add(e["msgid"], "", locations=e["locs"], context=ctx,
                auto_comments=[f"{WORDS_NOTE}\"{e['kind']}\", …)"])
    for english, paths in extract_fields().items():
        cat.add(english, "", context=FIELD_CONTEXT,
                auto_comments=[FIELD_NOTE + ", ".join(paths[:3]) + (" …" if len(paths) > 3 else "")])
    for english, places in extract_help().items():
        cat.add(english, "", context=HELP_CONTEXT,
                auto_comments=[HELP_NOTE + ", ".join(places[:3]) + (" …" if len(places) > 3 else "")])
    return cat


def update(po=None, template=None):
    """The .po with the raise sites' English: a Notice's msgid, places and parameters as the
    source says them now (a changed English marks the entry fuzzy: check its Russian), a new
    code untranslated, a code no longer raised dropped; the same of the renderers' sentences
    (``words``: msgctxt "kind:key"); the other entries (labels, counts, the codes made by
    io/schema.py from pydantic's error types) kept as they are."""
    po = read_po() if po is None else po
    template = pot() if template is None else template
    codes = {_key(m): m for m in template if m.id}
    out = new_catalog()
    out._messages.clear()
    for m in po:
        if not m.id:
            continue
        said = is_notice(m.context) or any(WORDS_NOTE in c or FIELD_NOTE in c or HELP_NOTE in c
                                           for c in m.auto_comments)
        new = codes.pop(_key(m), None) if said or _key(m) in codes else None
        if new is None:
            if said and not m.locations == [("src/flywheel/io/schema.py", 151)]:
                continue                                   # no longer raised or said
            out.add(m.id, m.string, locations=m.locations, flags=m.flags,
                    auto_comments=m.auto_comments, context=m.context)
            continue
        flags = set(m.flags) | ({"fuzzy"} if new.id != m.id else set())
        out.add(new.id, m.string, locations=new.locations, flags=flags,
                auto_comments=new.auto_comments, context=m.context)
    for new in codes.values():
        out.add(new.id, "", locations=new.locations, auto_comments=new.auto_comments,
                context=new.context)
    return out


def _key(m):
    """An entry's identity across an update: its msgctxt, and for a field's description or a
    help text (one context, many entries) the English too."""
    return (m.context, m.id) if m.context in (FIELD_CONTEXT, HELP_CONTEXT) else m.context


def problems(po=None) -> list[str]:
    """What is wrong with the catalogue: untranslated or fuzzy entries, plural forms missing,
    ``{fields}`` that differ between an entry's forms."""
    import string

    po = read_po() if po is None else po
    out = []

    def fields(text):
        return {f for _, f, _, _ in string.Formatter().parse(text) if f is not None}

    for m in po:
        if not m.id:
            continue
        where = f"{m.context}: {m.id!r}"
        if m.fuzzy:
            out.append(f"{where}: fuzzy")
        forms = m.string if isinstance(m.string, tuple) else (m.string,)
        if not all(forms) or len(forms) not in (1, 3):
            out.append(f"{where}: not translated")
            continue
        if m.context in (FIELD_CONTEXT, HELP_CONTEXT):   # prose: its braces are no fields
            continue
        if not is_notice(m.context):           # a label, a count: the same fields in each form
            ids = m.id if isinstance(m.id, tuple) else (m.id,)
            want = fields(ids[0])
            if any(fields(t) != want for t in (*ids, *forms)):
                out.append(f"{where}: fields differ")
    return out


def main(argv: list[str]) -> int:
    cmd = argv[1] if len(argv) > 1 else ""
    if cmd == "extract":
        from babel.messages.pofile import write_po as _write

        POT.parent.mkdir(parents=True, exist_ok=True)
        with open(POT, "wb") as fh:
            _write(fh, pot(), width=0)
        print(f"written: {POT}")
    elif cmd == "update":
        write_po(update())
        print(f"written: {PO} (translate the empty and fuzzy entries, then compile)")
    elif cmd == "compile":
        MO.write_bytes(mo_bytes(read_po()))
        print(f"written: {MO}")
    elif cmd == "check":
        bad = problems()
        if MO.read_bytes() != mo_bytes(read_po()):
            bad.append(f"{MO.name} is not the compiled {PO.name}: run `python tools/i18n.py compile`")
        print("\n".join(bad) or "ok")
        return 1 if bad else 0
    elif cmd == "adopt":
        space = {"MESSAGES_RU": {}, "_PARAM_HOOKS": [], "_MSGS_DERIVED": set()}
        exec("from flywheel.render.nomenclature import *\n" + Path(argv[2]).read_text(
            encoding="utf-8"), space)
        po, left = read_po(), dict(space["MESSAGES_RU"])
        for m in po:
            if m.context in left:
                m.string = left.pop(m.context)
                m.flags.discard("fuzzy")
        write_po(po)
        print(f"written: {PO}" + (f"; not raised anywhere (left out): {', '.join(left)}"
                                  if left else ""))
        if space["_PARAM_HOOKS"] or space["_MSGS_DERIVED"]:
            print("move by hand to render/message_params.py (HOOKS, DERIVED): "
                  + ", ".join(f.__name__ for f in space["_PARAM_HOOKS"]))
    elif cmd == "todo":
        for path in sorted(PACKAGE.rglob("*.py")):
            for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
                if (isinstance(node, ast.Call) and getattr(node.func, "id", "") == "Notice"
                        and len(node.args) >= 2 and isinstance(node.args[1], ast.Constant)):
                    _, unclean = _template(node.args[0], {ast.unparse(k.value): k.arg
                                                          for k in node.keywords if k.arg})
                    print(f"{path.relative_to(ROOT)}:{node.lineno}: {node.args[1].value}: "
                          f"not a parameter: {' | '.join(unclean) or '(layout)'}")
    else:
        print(__doc__)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
