"""Shared test fixtures, and the quick loop's marker: ``pytest -m "not slow"`` (README).

The slow tests — a headless browser, PDF and DOCX round trips, the mutation survey, whole
processes (``python -m flywheel``, a run killed or interrupted), a whole `run` drawing every
figure where a quicker test covers the same module, work at the stated limits — are marked
here, by module and by test (node-id) lists, not in the test files: a new slow test is one line
below. Every module of src/flywheel keeps quick tests of its own, and the quick loop proves it:
run over the whole tree (``pytest -m "not slow"`` or ``pytest -m "not slow" tests``) it fails
if some module of src/flywheel was imported by no quick test (:func:`pytest_sessionfinish`).

Hypothesis runs the profile ``quick`` (fewer examples) in the quick loop and ``full`` (the
suite's counts) otherwise; ``--hypothesis-profile NAME`` chooses one by hand.
"""
import builtins
import sys
from pathlib import Path

import pytest

#: ``--shard K/N``, ``--report-out``, ``--guard-out``: the shares of tools/pytest_shards.py
pytest_plugins = ("shards",)

#: test modules all of whose tests are slow (and why)
SLOW_MODULES = {
    "tests/test_mutations.py": "mutation survey: hundreds of mutated cases through every command",
    "tests/render/test_browser.py": "a headless browser prints the HTML",
}

#: slow tests of other modules: "path::name" (every parametrization of it) or
#: "path::name[id]" (that parametrization only: the others stay in the quick loop)
SLOW_TESTS = {
    # whole processes: python -m flywheel, signals, kills, an interpreter started per test
    "tests/cli/test_cli_check.py::test_python_m_flywheel_help",
    "tests/cli/test_cli_check.py::test_python_m_flywheel_check_bad_file",
    "tests/cli/test_cli_conventions.py::test_a_closed_pipe_ends_quietly",
    "tests/cli/test_cli_run.py::test_python_dash_m",
    "tests/cli/test_cli_run.py::test_run_no_plots_imports_nothing_it_does_not_use",
    "tests/dynamics/test_plans.py::test_plan_images_keep_their_order_under_any_hash_seed",
    "tests/io/test_output_folders.py::test_a_temporary_of_a_killed_run_is_removed_by_the_next",
    "tests/io/test_output_folders.py::test_an_interrupted_run_leaves_the_output_folder_as_it_was",
    "tests/io/test_output_folders.py::test_ctrl_c_to_the_process_group_stops_the_plot_workers_too",
    "tests/io/test_output_folders.py::test_a_killed_run_takes_its_workers_along_and_the_next_run_cleans_up",
    "tests/io/test_output_folders.py::test_a_ctrl_c_while_the_interpreter_exits_prints_no_traceback",
    "tests/io/test_output_folders.py::test_a_sigterm_after_the_output_is_whole_is_one_line_and_143",
    "tests/io/test_output_links.py::test_a_run_killed_at_any_step_of_the_swap_is_undone_by_the_next",
    "tests/io/test_output_links.py::test_a_killed_swap_is_undone_by_a_real_rerun",
    "tests/render/test_messages.py::test_the_error_language_comes_from_the_raw_arguments_too",
    "tests/render/test_messages.py::test_usage_errors_are_russian_and_english_is_the_parsers_own",
    "tests/render/test_messages.py::test_a_value_of_an_option_given_last_is_still_said",
    "tests/render/test_plots.py::test_importing_plots_does_not_import_matplotlib",
    "tests/test_bounds.py::test_a_deep_file_through_the_whole_process",
    # PDF and DOCX round trips (typst, python-docx, pdftotext)
    "tests/elastic/test_aggregate.py::test_cli_plot_svg_pdf_same_bytes_on_a_rerun",
    "tests/render/test_plots.py::test_svg_and_pdf_are_the_same_bytes_on_a_rerun",
    "tests/render/test_report_formats.py::test_pdf_is_a_pdf",
    "tests/render/test_report_formats.py::test_docx_has_the_models_headings_and_tables",
    "tests/render/test_report_formats.py::test_reruns_are_byte_identical_and_no_plots_says_so",
    "tests/render/test_report_formats.py::test_docx_formulas_are_word_equations",
    "tests/render/test_report_formats.py::test_wide_tables_fit_a4",
    "tests/render/test_report_formats.py::test_symbols_are_typeset_with_subscripts",
    "tests/render/test_report_out.py::test_task2_summary_json_is_the_json_document",
    "tests/render/test_report_out.py::test_task2_html_reads_back",
    "tests/render/test_report_out.py::test_task2_pdf_and_docx_read_back",
    "tests/render/test_report_out.py::test_aggregate_reads_back",
    "tests/render/test_report_out.py::test_reruns_are_byte_identical_and_replace_only_their_files",
    "tests/render/test_report_out.py::test_duty_cycle_out",
    "tests/teaching/test_sheets.py::test_one_sheet_per_variant_html_and_one_page_pdf",
    "tests/teaching/test_sheets.py::test_the_pdf_carries_the_same_values_and_no_answer",
    "tests/teaching/test_sheets.py::test_byte_identical_on_rerun",
    # a whole run drawing every figure (test_plots.py and test_cli_run.py keep the quick ones)
    "tests/cases/test_cycles.py::test_a_720_degree_run_writes_every_output",
    "tests/dynamics/test_engines.py::test_engine_case_runs_end_to_end",
    "tests/linkage/test_sixbar.py::test_shaper_cuts_on_the_slow_stroke_only",
    "tests/render/test_animate.py::test_gif_has_72_frames_and_the_same_bytes_twice",
    "tests/render/test_messages.py::test_transients_reasons_are_russian",
    "tests/render/test_plots.py::test_write_plots_svg_keeps_the_pngs_the_reports_embed",
    # every figure of the labelled kinds of ten more cases, drawn and measured (the compressor's
    # stay quick, with the placer's own tests in tests/render/test_labels.py)
    "tests/render/test_labels.py::test_no_label_meets_another_or_covers_a_marker[compressor_given_flywheel]",
    "tests/render/test_labels.py::test_no_label_meets_another_or_covers_a_marker[compressor_worksheet]",
    "tests/render/test_labels.py::test_no_label_meets_another_or_covers_a_marker[engine_4stroke]",
    "tests/render/test_labels.py::test_no_label_meets_another_or_covers_a_marker[engine_inline4]",
    "tests/render/test_labels.py::test_no_label_meets_another_or_covers_a_marker[engine_measured]",
    "tests/render/test_labels.py::test_no_label_meets_another_or_covers_a_marker[fourbar]",
    "tests/render/test_labels.py::test_no_label_meets_another_or_covers_a_marker[fourbar_rocker_load]",
    "tests/render/test_labels.py::test_no_label_meets_another_or_covers_a_marker[pump]",
    "tests/render/test_labels.py::test_no_label_meets_another_or_covers_a_marker[shaper]",
    "tests/render/test_labels.py::test_no_label_meets_another_or_covers_a_marker[slotted_link]",
    # the plans of four more cases drawn and measured (the compressor's stay quick)
    "tests/dynamics/test_plans.py::test_plans_are_drawn[engine_inline4]",
    "tests/dynamics/test_plans.py::test_plans_are_drawn[slotted_link]",
    "tests/dynamics/test_plans.py::test_plans_are_drawn[shaper]",
    "tests/dynamics/test_plans.py::test_plans_are_drawn[compressor]",     # [fourbar] stays quick
    "tests/dynamics/test_plans.py::test_no_label_sits_on_another_on_any_plan[engine_inline4]",
    "tests/dynamics/test_plans.py::test_no_label_sits_on_another_on_any_plan[slotted_link]",
    "tests/dynamics/test_plans.py::test_no_label_sits_on_another_on_any_plan[shaper]",
    "tests/dynamics/test_plans.py::test_no_label_sits_on_another_on_any_plan[fourbar]",
    "tests/dynamics/test_plans.py::test_force_polygon_panels_fit_a4_apart[engine_inline4]",
    "tests/dynamics/test_plans.py::test_force_polygon_panels_fit_a4_apart[slotted_link]",
    "tests/dynamics/test_plans.py::test_force_polygon_panels_fit_a4_apart[shaper]",
    "tests/dynamics/test_plans.py::test_force_polygon_panels_fit_a4_apart[fourbar]",
    # the hodographs of three more cases (the compressor's stay quick)
    "tests/dynamics/test_forces_run.py::test_hodograph_angle_labels_do_not_overlap[en-engine_inline4]",
    "tests/dynamics/test_forces_run.py::test_hodograph_angle_labels_do_not_overlap[en-shaper]",
    "tests/dynamics/test_forces_run.py::test_hodograph_angle_labels_do_not_overlap[en-slotted_link]",
    "tests/dynamics/test_forces_run.py::test_hodograph_angle_labels_do_not_overlap[ru-engine_inline4]",
    "tests/dynamics/test_forces_run.py::test_hodograph_angle_labels_do_not_overlap[ru-shaper]",
    "tests/dynamics/test_forces_run.py::test_hodograph_angle_labels_do_not_overlap[ru-slotted_link]",
    # every figure written (twice: the same bytes) or built in a second language
    "tests/render/test_plots.py::test_write_plots_files_and_bytes",
    "tests/render/test_plots.py::test_write_plots_russian",
    "tests/render/test_plots.py::test_every_figure_has_title_labels_legend_and_fits[ru]",
    "tests/render/test_plots.py::test_task2_plot_by_suffix_is_the_same_bytes_on_a_rerun[.pdf]",
    "tests/render/test_plots_extra.py::test_time_law_and_transients_written_with_every_figure",
    "tests/render/test_nomenclature.py::test_figure_text_has_no_literal_underscores_and_one_unit_style",
    "tests/io/test_output_links.py::test_the_issues_plots_link_deletes_nothing_outside",
    "tests/cli/test_cli_run.py::test_rerun_replaces_its_own_files_only",
    "tests/render/test_report_formats.py::test_html_is_self_contained_and_numbered",  # + PDF, DOCX
    # work at the stated limits: the largest inputs solved, the stiffest machines integrated
    "tests/test_bounds.py::test_terms_at_the_limit_are_solved",
    "tests/test_bounds.py::test_points_at_the_limit_are_solved",
    "tests/teaching/test_grading.py::test_a_large_sheet_grades_in_linear_time_and_prints_a_page",
    "tests/elastic/test_aggregate.py::test_stiff_slow_machine_is_checked_with_an_implicit_method",
    "tests/elastic/test_aggregate.py::test_lang_ru_notes",
    "tests/test_work_bounds.py::test_stiff_start_up_lsoda_agrees_with_dop853[10.0-1.5]",
    # whole processes on a terminal, or started for a usage error
    "tests/test_work_bounds.py::test_the_bar_shows_on_a_terminal_and_not_when_piped",
    "tests/test_work_bounds.py::test_an_error_on_a_terminal_is_still_one_line",
    "tests/test_work_bounds.py::test_a_variants_error_on_a_terminal_is_still_one_line",
    "tests/test_bad_inputs.py::test_usage_error_is_one_error_line",
    "tests/cli/test_cli_conventions.py::test_an_internal_error_is_one_line_naming_it_a_bug",
    "tests/cli/test_cli_conventions.py::test_debug_shows_the_traceback",
    # more whole runs drawing figures, a GIF or a second language of them, where the module
    # keeps quicker tests of the same code
    "tests/constant_inertia/test_task2_motion.py::test_cli_new_cases_run",
    "tests/cli/test_outputs.py::test_run_plots_choice[record-True]",
    "tests/cli/test_outputs.py::test_drawn_in_process_the_progress_is_counted_too",
    "tests/render/test_plot_start.py::test_the_started_worker_draws_the_bytes_drawn_in_process",
    "tests/cli/test_task2_cli.py::test_lang_ru_plot_labels",
    "tests/dynamics/test_kinematics_only.py::test_animate_and_a_given_motion_option",
    "tests/dynamics/test_forces_run.py::test_hodograph_angle_labels_do_not_overlap[ru-compressor]",
    "tests/render/test_plots.py::test_scheme_at_several_angles",
    "tests/render/test_plots.py::test_task2_plot_by_suffix_is_the_same_bytes_on_a_rerun[.svg]",
    "tests/teaching/test_variants_machines.py::test_every_variant_runs_and_gives_the_key",
    "tests/teaching/test_sheets.py::test_text_data_are_on_the_sheet_in_words",
    "tests/teaching/test_sheets.py::test_flywheel_J_is_worded_by_the_case_kind",
    "tests/cases/test_cycles.py::test_cycle_deg_is_in_every_summary",
    "tests/cases/test_document.py::test_every_kind_reads_the_document_table[['task2', '--case']-task2_seed_triangle.toml]",
    "tests/io/test_output_folders.py::test_a_rerun_of_the_newer_writers_keeps_the_users_files[aggregate]",
    "tests/duty_cycle/test_press.py::test_transients_run",
    "tests/render/test_animate.py::test_run_animate_writes_mechanism_gif",
    "tests/teaching/test_sheets.py::test_the_sheet_gives_the_defaults_a_flywheels_diameter_needs",
    "tests/render/test_frame.py::test_every_framed_page_of_the_pdf_has_its_title_block",  # PDF
    # more integrations that count work or compare solvers (the quick estimates stay)
    "tests/test_bounds.py::test_points_beyond_the_limit_are_refused",
    "tests/test_work_bounds.py::test_progress_does_not_change_the_results",
    "tests/test_work_bounds.py::test_stiff_motor_start_up_is_computed_with_lsoda",
    "tests/test_work_bounds.py::test_aggregate_step_estimate_against_the_solver",
    "tests/test_work_bounds.py::test_estimates_of_the_bundled_cases_agree_with_their_integration[press]",
    "tests/test_work_bounds.py::test_startup_estimate_is_the_closed_form_for_constant_inertia",
    "tests/test_work_bounds.py::test_progress_of_run_transients_is_monotone_per_stage",
    "tests/test_work_bounds.py::test_steady_check_lsoda_agrees_with_dop853",
    "tests/test_work_bounds.py::test_stiff_start_up_lsoda_agrees_with_dop853[100.0-3.0]",
    "tests/test_work_bounds.py::test_stiff_start_up_beyond_the_resolving_steps_is_still_refused",
    "tests/dynamics/test_timedomain.py::test_slow_motor_on_a_pulsating_load_reaches_the_motor_line_speed",
    # tools/pytest_shards.py on small trees of its own: two pytest processes a test
    "tests/tools/test_pytest_shards.py::test_a_failure_in_one_share_fails_the_run_and_is_named",
    "tests/tools/test_pytest_shards.py::test_a_collection_error_fails_the_run_and_is_named_once",
    "tests/tools/test_pytest_shards.py::test_all_passed_is_exit_0_and_record_writes_a_table_the_split_then_reads",
    "tests/tools/test_pytest_shards.py::test_ctrl_c_stops_every_share_and_the_run_says_so",
}


# -- one click command per typer app ---------------------------------------------------------------

def _command_of(app, _built={}):
    """typer's CliRunner builds the whole click command tree of an app (every option of every
    command, from the functions' signatures) on each invoke: about 0.05 s, a third of a quick
    test that runs a command. The tree depends on the app alone, built once at import and never
    changed: build it once per app."""
    command = _built.get(id(app))
    if command is None or command[0] is not app:
        command = _built[id(app)] = (app, _typer_get_command(app))
    return command[1]


import typer.testing  # noqa: E402

_typer_get_command = typer.testing._get_command
typer.testing._get_command = _command_of


def _a_process_of_the_catalogue(item) -> bool:
    """A bad input of tests/bad_inputs/catalogue.toml run as a whole process (``subprocess =
    true`` or a ``timeout``: tests/test_bad_inputs.py), by test_bad_input or by the Russian
    lines' test of tests/render/test_messages.py."""
    params = getattr(getattr(item, "callspec", None), "params", {})
    entry = params.get("entry")
    if entry is None and "eid" in params and hasattr(item.module, "bad"):
        entry = next((e for e in item.module.bad.ENTRIES if e.id == params["eid"]), None)
    return bool(getattr(entry, "subprocess", False) or getattr(entry, "timeout", 0))


@pytest.hookimpl(tryfirst=True)
def pytest_collection_modifyitems(config, items):
    """Mark the tests of :data:`SLOW_MODULES` and :data:`SLOW_TESTS`, and the bad inputs the
    catalogue runs as whole processes, ``slow``. Collecting the whole tree, an entry of the
    lists that names no test is an error (a test renamed: it would run in the quick loop)."""
    slow = pytest.mark.slow
    named = set()
    for item in items:
        path = item.nodeid.split("::", 1)[0]
        name = item.nodeid.split("[", 1)[0]
        hits = {path, name, item.nodeid} & (SLOW_MODULES.keys() | SLOW_TESTS)
        named |= hits
        if hits or _a_process_of_the_catalogue(item):
            item.add_marker(slow)
    unknown = sorted((SLOW_MODULES.keys() | SLOW_TESTS) - named)
    if unknown and _whole_tree(config):
        raise pytest.UsageError("tests/conftest.py names tests that do not exist: "
                                + ", ".join(unknown))


@pytest.fixture(autouse=True)
def _close_pyplot_figures():
    """Tests draw figures; pyplot keeps the ones it made and past 20 open it warns (an error
    here, RuntimeWarnings being errors): close them after every test, whatever its order."""
    yield
    plt = sys.modules.get("matplotlib.pyplot")
    if plt is not None:
        plt.close("all")


# -- hypothesis: fewer examples in the quick loop -------------------------------------------------

def _quick_loop(config) -> bool:
    """``-m "not slow"``: the quick loop."""
    return " ".join((config.getoption("markexpr", "") or "").split()) == "not slow"


def _hypothesis_profiles(config) -> None:
    from hypothesis import settings

    settings.register_profile("full", max_examples=60)      # the suite's count (CI)
    settings.register_profile("quick", max_examples=15)     # the quick loop
    if not config.getoption("hypothesis_profile", None):    # --hypothesis-profile wins
        settings.load_profile("quick" if _quick_loop(config) else "full")


# -- the quick loop covers every module ------------------------------------------------------------

ROOT = Path(__file__).resolve().parents[1]
SRC = ROOT / "src"
TESTS = ROOT / "tests"
_real_import = builtins.__import__
_imported: set[str] = set()        # flywheel modules an import statement of a test reached
_recording = [False]


def _recording_import(name, globals=None, locals=None, fromlist=(), level=0):
    """builtins.__import__ that notes every flywheel module an executed import statement names
    (also one already in sys.modules: the statement runs the hook each time)."""
    module = _real_import(name, globals, locals, fromlist, level)
    if _recording[0]:
        full = name
        if level:
            package = (globals or {}).get("__package__") or ""
            base = package.rsplit(".", level - 1)[0] if level > 1 else package
            full = f"{base}.{name}" if name else base
        if full == "flywheel" or full.startswith("flywheel."):
            parts = full.split(".")
            _imported.update(".".join(parts[:i]) for i in range(1, len(parts) + 1))
            for item in fromlist or ():
                if f"{full}.{item}" in sys.modules:
                    _imported.add(f"{full}.{item}")
    return module


def _whole_tree(config) -> bool:
    """The whole tests/ tree collected (``pytest``, ``pytest tests``)."""
    where = config.rootpath if config.args_source == pytest.Config.ArgsSource.TESTPATHS \
        else config.invocation_params.dir
    return any("::" not in a and (where / a).resolve() in (TESTS, ROOT) for a in config.args)


def _guarding(config) -> bool:
    """The quick loop over the whole tests/ tree, nothing else left out."""
    if not _quick_loop(config) or config.getoption("keyword", "") or \
            config.getoption("deselect", None) or config.getoption("lf", False) or \
            config.getoption("collectonly", False):
        return False
    return _whole_tree(config)


def pytest_configure(config):
    _hypothesis_profiles(config)
    config._flywheel_guard = _guarding(config)
    if config._flywheel_guard:
        builtins.__import__ = _recording_import
        _recording[0] = True


def pytest_unconfigure(config):
    if builtins.__import__ is _recording_import:
        builtins.__import__ = _real_import


@pytest.hookimpl(wrapper=True)
def pytest_make_collect_report(collector):
    """Collecting src/flywheel's doctests imports every module: not a test's import."""
    inside = collector.path is not None and SRC in Path(collector.path).parents
    was = _recording[0]
    if inside:
        _recording[0] = False
    try:
        return (yield)
    finally:
        _recording[0] = was


def pytest_runtest_call(item):
    """A module's own doctest, run, is a quick test of it."""
    dtest = getattr(item, "dtest", None)
    if dtest is not None:
        _imported.add(dtest.globs.get("__name__", ""))


def every_module() -> list[str]:
    """The dotted name of every module of src/flywheel (a package by its __init__)."""
    names = []
    for path in sorted((SRC / "flywheel").rglob("*.py")):
        parts = path.relative_to(SRC).with_suffix("").parts
        names.append(".".join(parts[:-1] if parts[-1] == "__init__" else parts))
    return names


def pytest_sessionfinish(session, exitstatus):
    """The quick loop over the whole tree, all passed: every module of src/flywheel imported
    by a quick test, or the run fails naming the ones none imported."""
    config = session.config
    out = config.getoption("guard_out", None)
    if out and getattr(config, "_flywheel_guard", False):      # one share: its union is checked
        import json                                            # by tools/pytest_shards.py

        Path(out).write_text(json.dumps({"imported": sorted(_imported),
                                         "every": every_module()}), encoding="utf-8")
        return
    if not getattr(config, "_flywheel_guard", False) or exitstatus != 0 or \
            session.shouldfail or session.shouldstop:
        return
    missing = [m for m in every_module() if m not in _imported]
    if missing:
        tr = config.pluginmanager.get_plugin("terminalreporter")
        if tr is not None:
            tr.write_sep("=", "the quick loop imports no quick test of these modules", red=True)
            for m in missing:
                tr.write_line(m)
        session.exitstatus = pytest.ExitCode.TESTS_FAILED
