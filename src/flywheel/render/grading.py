"""Rich output of `flywheel variants` and `flywheel grade` (formatting only, no computation)."""
from __future__ import annotations


def _g(x, fmt: str = ".6g") -> str:
    if x is None:
        return "—"
    if isinstance(x, float):
        return format(x, fmt)
    return str(x)


def print_variants(vs, out, console=None) -> None:
    """The variants drawn and their answers, one row each."""
    from rich.console import Console
    from rich.table import Table

    console = console or Console()
    t = vs.template
    kind = "flywheel run case" if t.kind == "run" else "flywheel task2 case"
    grid = f", answers on a {vs.n_points}-interval grid" if t.kind == "run" else ""
    table = Table(title=f"{len(vs.variants)} variant(s) of {t.name} ({kind}{grid})")
    table.add_column("variant", no_wrap=True)
    table.add_column("drawn", style="cyan")
    table.add_column("answers (SI)")
    for v in vs.variants:
        table.add_row(v.id, "\n".join(f"{p.path} = {_g(v.drawn[p.path])}" for p in t.varied),
                      "\n".join(f"{a} = {_g(v.answers[a])}" for a in t.answers))
    console.print(table)
    for w in vs.warnings:
        console.print(f"[yellow]warning:[/] {w}")
    if vs.failed_draws:
        console.print(f"{vs.failed_draws} draw(s) failed validation or analysis and were drawn "
                      "again")
    console.print(f"seed {vs.seed} (the same seed gives the same files)", highlight=False,
                  soft_wrap=True)
    console.print(f"written: {out}/ (variant_*.toml, answers.json, answers.csv, students.csv)",
                  highlight=False, markup=False, soft_wrap=True)


def _pct(x: float | None) -> str:
    return "—" if x is None else f"{100 * x:.0f} %"


DETAIL_STUDENTS = 60      # a class: per student a table of the answers; more: the group table only
GROUP_ROWS = 500          # rows of the group table and problem lines shown on the terminal


def print_report(r, console=None) -> None:
    """Per student a table of the answers (for a class of up to DETAIL_STUDENTS); then the
    group table, statistics and problems, each cut at GROUP_ROWS lines with a note where the
    whole report is (--out, --json): the terminal gets a readable page, not megabytes."""
    from rich.console import Console
    from rich.table import Table

    console = console or Console()
    for s in (r.students if len(r.students) <= DETAIL_STUDENTS else ()):
        table = Table(title=f"{s.student} — variant {s.variant} — {s.passed}/{s.total} "
                            f"({_pct(s.score)})", title_justify="left")
        table.add_column("answer")
        table.add_column("given", justify="right")
        table.add_column("key", justify="right")
        table.add_column("error", justify="right")
        table.add_column("tolerance", justify="right")
        table.add_column("")
        for a in s.answers:
            err = "—" if a.error is None else (
                f"{100 * a.error:.3g} %" if a.error_kind == "relative" else f"{a.error:.3g} abs")
            mark = "[green]pass[/]" if a.passed else (
                "[red]FAIL[/]" if a.given is not None else "[red]no answer[/]")
            table.add_row(a.answer, _g(a.given), _g(a.key), err, f"{100 * a.tolerance:g} %",
                          mark)
        console.print(table)

    if r.students:
        group = Table(title=f"Group: {len(r.students)} graded, mean score "
                            f"{_pct(r.mean_score)}", title_justify="left")
        group.add_column("student")
        group.add_column("variant")
        group.add_column("score", justify="right")
        group.add_column("wrong")
        for s in r.students[:GROUP_ROWS]:
            group.add_row(s.student, s.variant, f"{s.passed}/{s.total} ({_pct(s.score)})",
                          ", ".join(s.wrong) or "—")
        console.print(group)
        if len(r.students) > GROUP_ROWS:
            console.print(f"… and {len(r.students) - GROUP_ROWS} more students (the whole report: "
                          "--out REPORT.csv or --json)", highlight=False)
        per = Table(title="By answer", title_justify="left")
        per.add_column("answer")
        per.add_column("wrong", justify="right")
        per.add_column("tolerance", justify="right")
        for a, (w, n) in r.wrong_counts().items():
            per.add_row(a, f"{w}/{n}", f"{100 * r.key.tolerance_of(a, r.tolerance):g} %")
        console.print(per)
        worst = r.most_often_wrong()
        full = sum(s.passed == s.total for s in r.students)
        console.print(f"mean score {_pct(r.mean_score)}; full marks: {full} of "
                      f"{len(r.students)}; most often wrong: "
                      + ("none" if worst is None else
                         f"{', '.join(worst[0])} ({worst[1]} of {len(r.students)}"
                         + (" each)" if len(worst[0]) > 1 else ")")),
                      highlight=False)
    if r.problems:
        console.print(f"[yellow]{len(r.problems)} problem(s)[/] (skipped or not graded):")
        for p in r.problems[:GROUP_ROWS]:
            console.print(f"  {p}", highlight=False, markup=False, soft_wrap=True)
        if len(r.problems) > GROUP_ROWS:
            console.print(f"  … and {len(r.problems) - GROUP_ROWS} more (all of them: --json)",
                          highlight=False)
