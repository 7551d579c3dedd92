"""Shared test fixtures, and the quick loop's marker: ``pytest -m "not slow"`` (README).

The slow tests — a headless browser, PDF and DOCX round trips, the mutation survey, whole
processes (``python -m flywheel``, a run killed or interrupted), a whole `run` drawing every
figure where a quicker test covers the same module — are marked here, by module and by test
(node-id) lists, not in the test files: a new slow test is one line below. Every module of
src/flywheel keeps quick tests of its own.
"""
import sys

import pytest

#: test modules all of whose tests are slow (and why)
SLOW_MODULES = {
    "tests/test_mutations.py": "mutation survey: hundreds of mutated cases through every command",
    "tests/render/test_browser.py": "a headless browser prints the HTML",
}

#: slow tests of other modules: "path::name" (every parametrization of it)
SLOW_TESTS = {
    # whole processes: python -m flywheel, signals, kills, an interpreter started per test
    "tests/cli/test_cli_check.py::test_python_m_flywheel_help",
    "tests/cli/test_cli_check.py::test_python_m_flywheel_check_bad_file",
    "tests/cli/test_cli_conventions.py::test_a_closed_pipe_ends_quietly",
    "tests/cli/test_cli_run.py::test_python_dash_m",
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
}


def pytest_collection_modifyitems(config, items):
    """Mark the tests of :data:`SLOW_MODULES` and :data:`SLOW_TESTS` ``slow``."""
    slow = pytest.mark.slow
    for item in items:
        path = item.nodeid.split("::", 1)[0]
        name = item.nodeid.split("[", 1)[0]
        if path in SLOW_MODULES or name in SLOW_TESTS:
            item.add_marker(slow)


@pytest.fixture(autouse=True)
def _close_pyplot_figures():
    """Tests draw figures; pyplot keeps the ones it made and past 20 open it warns (an error
    here, RuntimeWarnings being errors): close them after every test, whatever its order."""
    yield
    plt = sys.modules.get("matplotlib.pyplot")
    if plt is not None:
        plt.close("all")
