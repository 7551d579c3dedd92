"""The package's shape (docs/architecture.md): imports point one way, no cycles, and the
computation never imports the command line, the terminal or the plotting library.

Walks every module's imports with ``ast`` (module level and inside functions alike: a lazy
import is still a dependency) and checks them against the layer table below.
"""
from __future__ import annotations

import ast
from pathlib import Path

import pytest

from helpers import source_nodes

SRC = Path(__file__).resolve().parents[1] / "src" / "flywheel"

# package → the packages it may import (besides itself and the standard library / third
# parties). Top to bottom: cli → render → teaching → cases → domain → linkage → io → errors;
# `units` (the conversion constants) is a leaf beside errors that every package may import.
ALLOWED: dict[str, set[str]] = {
    "errors": set(),
    "units": set(),
    "io": {"errors"},
    "linkage": {"errors"},
    "dynamics": {"errors", "io", "linkage"},
    "constant_inertia": {"errors", "io", "dynamics"},
    "elastic": {"errors", "io", "dynamics"},
    "duty_cycle": {"errors", "io"},
    "cases": {"errors", "io", "linkage", "dynamics", "constant_inertia", "elastic", "duty_cycle"},
    "teaching": {"errors", "io", "linkage", "dynamics", "constant_inertia", "elastic",
                 "duty_cycle", "cases"},
    "render": {"errors", "io", "linkage", "dynamics", "constant_inertia", "elastic", "duty_cycle",
               "cases", "teaching"},
    "cli": {"errors", "io", "linkage", "dynamics", "constant_inertia", "elastic", "duty_cycle",
            "cases", "teaching", "render"},
    "__init__": {"cases", "dynamics"},     # the library's two front doors: load_case, analyze
    "__main__": {"cli"},
}
for _pkg in set(ALLOWED) - {"units", "errors"}:
    ALLOWED[_pkg].add("units")
# imports only the command line, the terminal and the plots may use
PRESENTATION = {"typer": {"cli"}, "rich": {"cli", "render"}, "matplotlib": {"render"}}


def _module_name(path: Path) -> str:
    rel = path.relative_to(SRC.parent).with_suffix("")
    parts = list(rel.parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


def _imports(path: Path) -> list[str]:
    """Absolute names of every module ``path`` imports (relative imports resolved)."""
    me = _module_name(path)
    package = me if path.name == "__init__.py" else me.rpartition(".")[0]
    out = []
    for node in source_nodes(path):
        if isinstance(node, ast.Import):
            out += [a.name for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                up = package.split(".")
                up = up[: len(up) - node.level + 1]
                base = ".".join(up + ([base] if base else []))
            out.append(base)
            # `from flywheel.dynamics import energy` imports the module flywheel.dynamics.energy
            out += [f"{base}.{a.name}" for a in node.names
                    if (SRC.parent / Path(*f"{base}.{a.name}".split("."))).with_suffix(".py").exists()
                    or (SRC.parent / Path(*f"{base}.{a.name}".split("."))).is_dir()]
    return out


MODULES = {_module_name(p): p for p in sorted(SRC.rglob("*.py"))}


def _package(module: str) -> str:
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else "__init__"


def _graph() -> dict[str, set[str]]:
    g = {}
    for name, path in MODULES.items():
        g[name] = {m for m in _imports(path) if m in MODULES and m != name}
    return g


@pytest.mark.parametrize("module", sorted(MODULES))
def test_imports_follow_the_layers(module):
    path = MODULES[module]
    pkg = _package(module)
    if module == "flywheel":
        pkg = "__init__"
    allowed = ALLOWED[pkg] | {pkg}
    bad = sorted({m for m in _imports(path) if m.startswith("flywheel.")
                  and _package(m) not in allowed})
    assert not bad, f"{module} ({pkg}) imports {bad}: against the layers of docs/architecture.md"
    third = {m.split(".")[0] for m in _imports(path)}
    for lib, who in PRESENTATION.items():
        assert lib not in third or pkg in who, f"{module} imports {lib} (only {sorted(who)} may)"


def test_no_import_cycles():
    g = _graph()
    state: dict[str, int] = {}
    stack: list[str] = []

    def visit(n: str) -> None:
        state[n] = 1
        stack.append(n)
        for m in sorted(g[n]):
            # a package's __init__ importing its own modules is how packages work, not a cycle
            if m.startswith(n + "."):
                continue
            if state.get(m) == 1:
                cycle = stack[stack.index(m):] + [m]
                pytest.fail("import cycle: " + " → ".join(cycle))
            if m not in state:
                visit(m)
        stack.pop()
        state[n] = 2

    for n in sorted(g):
        if n not in state:
            visit(n)


def test_every_package_is_in_the_layer_table():
    pkgs = {_package(m) for m in MODULES if m != "flywheel"}
    assert pkgs <= set(ALLOWED), f"add {sorted(pkgs - set(ALLOWED))} to ALLOWED and the docs"


# -- thin commands (issue 22): each command function is parse → load → solve → write ---------

#: the most lines a command function of cli/ may span, from its ``def`` to its last line
#: (signature and docstring included); its checks, solving and writing go to the modules
#: where they belong (cli/options.py, cli/outputs.py, teaching/, …)
COMMAND_MOST_LINES = 40
CLI = SRC / "cli"


def _span(func: ast.FunctionDef) -> int:
    """Lines of a function from its ``def`` to its last line (decorators not counted)."""
    return func.end_lineno - func.lineno + 1


def _registered_commands() -> dict[str, tuple[str, str]]:
    """command name → (cli module, function) of every ``app.command("name")(function)`` in
    cli/commands.py, the function found through that file's ``from flywheel.cli.X import``."""
    tree = ast.parse((CLI / "commands.py").read_text(encoding="utf-8"))
    where = {a.asname or a.name: node.module.rpartition(".")[2]
             for node in ast.walk(tree) if isinstance(node, ast.ImportFrom)
             and (node.module or "").startswith("flywheel.cli.") for a in node.names}
    found = {}
    for node in ast.walk(tree):
        if (isinstance(node, ast.Call) and isinstance(node.func, ast.Call)
                and ast.unparse(node.func.func) == "app.command"
                and len(node.args) == 1 and isinstance(node.args[0], ast.Name)):
            name = node.func.args[0].value
            found[name] = (where.get(node.args[0].id, "commands"), node.args[0].id)
    return found


def _functions(module: str) -> dict[str, ast.FunctionDef]:
    tree = ast.parse((CLI / f"{module}.py").read_text(encoding="utf-8"))
    return {n.name: n for n in tree.body if isinstance(n, ast.FunctionDef)}


def test_the_span_counts_from_def_to_the_last_line():
    """The measure itself, on functions whose lines are counted by hand."""
    text = ("@decorator\ndef f(a,\n      b):\n    \"\"\"Doc.\"\"\"\n" + "    x = 1\n" * 38
            + "\n\ndef g(): return 1\n")
    f, g = [n for n in ast.parse(text).body if isinstance(n, ast.FunctionDef)]
    assert (_span(f), _span(g)) == (3 + 38, 1)


def test_every_command_is_found():
    """All the commands of the command line are measured (the test below is not empty)."""
    commands = _registered_commands()
    assert set(commands) >= {"schema", "check", "run", "drawings", "task2", "aggregate",
                             "duty-cycle", "variants", "grade", "new"}
    for name, (module, function) in commands.items():
        assert function in _functions(module), f"{name}: {function} not found in cli/{module}.py"


def test_command_functions_are_thin():
    """Each command function of cli/ (registered in cli/commands.py, or named ``*_command``)
    spans at most COMMAND_MOST_LINES lines: parse → load → solve → write."""
    measured = {(m, f) for m, f in _registered_commands().values()}
    measured |= {(p.stem, name) for p in CLI.glob("*.py") for name in _functions(p.stem)
                 if name.endswith("_command")}
    long = {f"cli/{m}.py {f}: {_span(_functions(m)[f])} lines" for m, f in measured
            if _span(_functions(m)[f]) > COMMAND_MOST_LINES}
    assert not long, (f"commands longer than {COMMAND_MOST_LINES} lines (def to end): "
                      f"{sorted(long)}; move their checks, solving and writing out "
                      "(docs/architecture.md, 'A new command')")


def test_the_quick_loops_guard_names_every_module_and_resolves_imports():
    """tests/conftest.py's guard (the quick loop fails naming a module no quick test imported):
    its list is every .py of src/flywheel, a package by its name; the import statements it
    notes resolve as Python resolves them (relative ones from the importer's package, a
    module named in `from … import`)."""
    import conftest

    files = sorted(SRC.rglob("*.py"))
    names = conftest.every_module()
    assert len(names) == len(set(names)) == len(files)
    assert "flywheel" in names and "flywheel.render.drawings" in names
    assert "flywheel.render.numbers" in names and "flywheel.__main__" in names
    noted, was = set(conftest._imported), conftest._recording[0]
    conftest._imported.clear()
    conftest._recording[0] = True
    try:
        conftest._recording_import("", {"__package__": "flywheel.render"}, None, ("numbers",), 1)
        conftest._recording_import("model", {"__package__": "flywheel.render.drawings"}, None,
                                   ("View",), 1)
        conftest._recording_import("io.text", {"__package__": "flywheel.render.drawings"}, None,
                                   ("cut",), 3)
        conftest._recording_import("json", {"__package__": "flywheel.render"})
        got = set(conftest._imported)
    finally:
        conftest._imported.clear()
        conftest._imported.update(noted)
        conftest._recording[0] = was
    assert got == {"flywheel", "flywheel.render", "flywheel.render.numbers",
                   "flywheel.render.drawings", "flywheel.render.drawings.model",
                   "flywheel.io", "flywheel.io.text"}
