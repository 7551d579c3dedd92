"""The Russian words of a Notice's parameters: what its Russian template (the catalogue,
locale/ru/LC_MESSAGES/flywheel.po) says that the English text did not need — a parameter that is
itself a Notice said in Russian, the kinds of file and case, a unit, a count with its noun
(``count``: ngettext, the catalogue's three Russian plural forms), a clause that depends on a
flag. ``russian_params(code, params, say)`` runs the functions of ``HOOKS`` in order; ``DERIVED``
names every field they add (tests/render/test_catalogue.py checks each template's fields against the
Notice's parameters and these).
"""
from __future__ import annotations

from flywheel.render.catalogue import plural
from flywheel.render.library_ru import (JSON_RU, MATPLOTLIB_RU, os_reason_ru, said_ru,
                                        toml_detail_ru)
from flywheel.render.nomenclature import load_name, material, rotor_name, unit


def count(n, one: str, many: str) -> str:
    """``n`` with its noun in the form Russian gives it after that number (1 цикл, 2 цикла,
    5 циклов): the catalogue's plural entry ``one``/``many`` (msgctxt "count")."""
    return plural("count", one, many, int(n), "ru").format(n=int(n))


#: what a file was expected to be (io/toml.py's "is a folder, expected …")
_FILE_KINDS_RU = {"a TOML case file": "файл случая TOML", "a TOML template": "шаблон TOML"}


#: the case kinds (cases/__init__.py NAMES) for "this is …, not …"
_CASE_KINDS_RU = {"run": "случай для flywheel run",
                  "task2": "случай задачи 2 (заданные графики моментов)",
                  "aggregate": "случай агрегата (упругие муфты)",
                  "variants": "шаблон вариантов",
                  "duty_cycle": "случай рабочего цикла (пресс, клёпальная машина, ножницы)"}


DERIVED = {"where_ru", "what_variant", "detail_ru", "as_kind_ru", "what_ru", "need_ru", "kind_ru", "expected_ru", "hint_ru", "unit_ru", "got_ru"}


def _msgs_ru_params(p: dict, say) -> dict:
    """The Russian words of an error's parameters: a parameter that is itself a Notice (the
    group in "… cannot be assembled") said in Russian, the kinds of file and case, the unit."""
    p = dict(p)
    for k in ("what", "need", "detail"):
        if k in p:
            p[k + "_ru"] = say(p[k], "ru")
    if "what" in p and "what_ru" in p and p["what"] in _FILE_KINDS_RU:
        p["what_ru"] = _FILE_KINDS_RU[p["what"]]
    if "kind" in p and "expected" in p:
        p["kind_ru"] = _CASE_KINDS_RU.get(p["kind"], p["kind"])
        p["expected_ru"] = _CASE_KINDS_RU.get(p["expected"], p["expected"])
    if "as_kind" in p:
        p["as_kind_ru"] = _CASE_KINDS_RU.get(p["as_kind"], p["as_kind"])
    if "sheet" in p:
        p["where_ru"] = p["sheet"] if p["row"] is None else f"{p['sheet']}, строка {p['row']}"
    if "variant" in p and "allowed" in p:
        p["what_variant"] = (f"вариант {p['variant']!r} отсутствует в ключе" if p["variant"]
                             else "не указан вариант")
    if isinstance(p.get("expected"), str) and " or " in p["expected"]:   # pydantic's literal
        p["expected"] = p["expected"].replace(" or ", " или ")
    if "near" in p:
        p["hint_ru"] = f"; может быть, {p['near']!r}?" if p["near"] else ""
    if "unit" in p:
        p["unit_ru"] = unit(p["unit"], "ru")
        if "x" in p:                                         # out_of_range: "12 м/с"
            p["unit_ru"] = f" {p['unit_ru']}" if p["unit"] else ""
    p["got_ru"] = f" (задано {p['got']})" if p.get("got") else ""
    return p


_MSGS2_DERIVED = {"heads_ru", "unit_sp_ru", "tag_ru", "here_ru", "keys_ru", "what_ru", "expected_ru", "who_ru", "quantity_ru", "which_ru", "task_ru", "fix_ru", "sliders_ru", "whom_ru", "material_ru", "given_ru", "shafts", "why_ru"}


DERIVED |= _MSGS2_DERIVED


_WHOM_RU = {"the crank's tip": "конец кривошипа"}


def _msgs2_ru_params(code: str, p: dict) -> dict:
    """The Russian words of the msgs2 errors' parameters."""
    if "sliders" in p:
        p["sliders_ru"] = p["sliders"] or "нет"
    if "whom" in p:
        w = p["whom"]
        p["whom_ru"] = _WHOM_RU.get(w, w.replace("pin (", "шейка ("))
    if code == "rim_speed_stress":
        p["material_ru"] = ("заданный материал" if p["material"] == "the given material"
                            else material(p["material"], "ru"))
    if "given" in p:
        p["given_ru"] = f" (задано {p['given']})" if p["given"] else ""
    if code == "shafts_count":
        p["shafts"] = p["rotors"] - 1
    if code == "not_finite":
        p["who_ru"] = f"{p['who']}: " if p["who"] else ""
        p["quantity_ru"] = "результат" if p["quantity"] == "a result" else p["quantity"]
    if "which" in p:
        p["which_ru"] = {"resistance": "момент сопротивления",
                         "driving": "движущий момент"}.get(p["which"], p["which"])
    if code == "too_many_steps":
        p["task_ru"] = {"start-up": "разгон", "steady check": "расчёт установившегося режима"
                        }.get(p["task"], p["task"])
        p["fix_ru"] = {
            "option": f"задайте {p['option']} короче",
            "motor": (f"характеристика двигателя крута для его ротора: M_п/ω_x на J_Д = "
                      f"{p['motor_rate']:.3g} 1/с; более пологая (motor.synchronous_rpm, момент) "
                      "или более тяжёлый ротор (J двигателя) делают задачу решаемой"),
            "stiff": ("демпфер или вал такой жёсткости для этих роторов делают систему жёсткой "
                      "(демпфирование, c)")}[p["fix_kind"]]
    if code == "path_not_in":
        p["here_ru"] = "верхнем уровне" if p["here"] == "the top level" else p["here"]
        p["keys_ru"] = "ничего" if p["keys"] == "nothing" else p["keys"]
    if code == "not_a_result":
        p["what_ru"] = ("не является результатом" if p["value"] is None
                        else f"— не конечное число (это {p['value']})")
    if code == "key_no_variants":
        p["where_ru"] = p["where"] or "ключ"
    if code == "option_is_a_folder":
        p["expected_ru"] = {"a CSV file name": "имя файла CSV",
                            "a file name": "имя файла",
                            "an image file": "файл изображения"}.get(p["expected"], p["expected"])
    if code == "must_be_positive":
        p["unit_sp_ru"] = f" {p['unit_ru']}" if p["unit"] else ""
    if code == "firing_order_fit":
        p["heads_ru"] = ", ".join(f"{n} при {a}/{b}" for n, a, b in p["heads"])
    if code == "graph_kind":
        p["tag_ru"] = f"неизвестный вид {p['tag']!r}" if p["tag"] else "не задан вид"
    if "below_zero" in p:
        p["why_ru"] = ": скорость упала бы до нуля или ниже" if p["below_zero"] else ""
    return p


# --- msgs_cli ---
# The command-line parser's own errors (cli/usage.py), the interruption and the internal-error
# lines (cli/__init__.py) in Russian.
_USAGE_VALUE_KINDS_RU = {"integer": "целым числом", "number": "числом",
                         "boolean": "логическим значением (true или false)"}


DERIVED |= {"possible_ru", "count_ru", "kind_ru", "value_kind_ru", "debug_ru"}


def _msgs_cli_ru_params(code: str, p: dict) -> dict:
    """The Russian words of the parser's errors' parameters."""
    if code == "usage_no_such_option":
        p["possible_ru"] = f" (похожие: {p['possible']})" if p["possible"] else ""
    elif code == "usage_needs_value":
        p["count_ru"] = "значение" if p["count"] == 1 else f"{p['count']} значения"
    elif code == "usage_missing":
        p["kind_ru"] = {"argument": "аргумент", "option": "параметр"}[p["kind"]]
    elif code == "usage_bad_value":
        p["value_kind_ru"] = _USAGE_VALUE_KINDS_RU[p["value_kind"]]
    elif code == "internal_error":
        p["debug_ru"] = "" if p["debug"] else " (--debug покажет трассировку)"
    return p


def _msgs_duty_ru_params(code: str, p: dict) -> dict:
    """The motor that is too weak (its power, or its torque and the power it gives); why a
    file cannot be read."""
    if code == "dc_motor_weak":
        p["have_ru"] = (f"мощность двигателя {p['P']:.6g} Вт" if p["by"] == "power" else
                        f"момент двигателя {p['T']:.6g} Н·м (P = M_Д·ω_ср = {p['P']:.6g} Вт)")
    if code in ("grade_key_unreadable", "sheet_unreadable"):
        p["reason_ru"] = os_reason_ru(p.get("errno"), p["reason"])
        if code == "sheet_unreadable":          # its template (block msgs) says {reason}
            p["reason"] = p["reason_ru"]
    return p


DERIVED |= {"have_ru", "reason_ru"}


DERIVED |= {"cycle_note_ru", "rows_ru", "load_ru"}


def _msgs_tabulated_ru_params(code: str, p: dict) -> dict:
    """The Russian words of the [tabulated] checks' parameters."""
    if "own_cycle" in p:
        p["cycle_note_ru"] = ", цикл machine.cycle_deg" if p["own_cycle"] else ""
    if code in ("tab_mass_no_point", "tab_J_no_omega_q"):
        p["rows_ru"] = "нет" if p["rows"] == "none" else p["rows"]
    if code == "tab_moment_overflow":
        p["load_ru"] = load_name(p["load"], "ru")
    return p


# --- msgs_aggregate ---
# The errors of `flywheel aggregate` in Russian: the case's checks across fields
# (cases/aggregate.py), the chain reduced to shaft I (elastic/chain.py), the steady state
# (elastic/forced.py), the natural frequencies (elastic/modes.py), the integration
# (elastic/timedomain.py).
_AG_REVERSAL_TAIL = ("так что машина останавливалась бы и вращалась в обратную сторону каждый "
                     "период: установившегося движения у этой модели нет (увеличьте скорость, "
                     "добавьте инерции или маховик либо уменьшите M_amplitude)")


_AG_QUANTITIES_RU = {"moment of inertia": "момента инерции", "speed ratio": "передаточного "
                     "отношения", "stiffness": "жёсткости", "damping": "демпфирования"}


DERIVED |= {"ag_why", "ag_where", "ag_quantity", "ag_unit", "ag_overflow", "ag_held",
                  "ag_reason"}


def _msgs_aggregate_ru_params(code: str, p: dict) -> dict:
    """The Russian words of the aggregate's errors' parameters (the two-mass model's own rotor
    names said in Russian, rotor_name)."""
    if code in ("ag_reversal_rotor", "ag_J_not_positive", "ag_ground_not_finite"):
        p["name"] = rotor_name(p["name"], "ru")
    if code == "ag_motor_needs_line":
        p["ag_why"] = ("вал, закреплённый в стойке, не может вращаться непрерывно" if p["fixed"]
                       else "вынужденные колебания и пуск рассчитываются для неразветвлённой "
                            "цепочки")
    elif code == "ag_reduced_not_finite":
        p["ag_where"] = (f"ротор {rotor_name(p['rotor'], 'ru')}" if p["rotor"] is not None
                         else f"соединение {p['connection']}")
        p["ag_quantity"] = _AG_QUANTITIES_RU.get(p["quantity"], p["quantity"])
        p["ag_unit"] = f" {unit(p['unit'], 'ru')}" if p["unit"] else ""
        p["ag_overflow"] = ": оно выходит за пределы двойной точности" if p["overflow"] else ""
    elif code == "ag_reversal_rigid":
        p["ag_held"] = ("которую двигатель с постоянным моментом не удерживает" if p["constant"]
                        else "которую характеристика двигателя почти не удерживает")
    elif code == "ag_solve_ivp_failed":
        p["ag_reason"] = p["reason"] or "решение не конечно"
    return p


#: Python's words for an arithmetic failure (math.fsum, math) in Russian; others stay as they are
_T2_PYTHON_RU = {"-inf + inf in fsum": "−inf + inf при суммировании",
                 "intermediate overflow in fsum": "переполнение промежуточной суммы",
                 "math range error": "результат вне диапазона чисел",
                 "Numerical result out of range": "результат вне диапазона чисел",
                 "math domain error": "аргумент вне области определения функции",
                 "float division by zero": "деление на ноль",
                 "division by zero": "деление на ноль"}


#: the moment whose value a task2 error speaks of, in the genitive ("значение движущего момента")
_T2_WHICH_GEN = {"driving": "движущего момента", "resistance": "момента сопротивления"}


def _msgs_task2_ru_params(code: str, p: dict) -> dict:
    """The Russian words of the task2 errors: the moment in the genitive, why a balance fails."""
    if code.startswith("t2_") and "which" in p:
        p["t2_which_gen"] = _T2_WHICH_GEN.get(p["which"], p["which"])
    if code == "t2_python_error":
        p["t2_python_ru"] = _T2_PYTHON_RU.get(p["words"], p["words"])
    if code == "t2_balance_negative":
        p["t2_balance_why"] = (
            "движущий момент совершает больше работы, чем может поглотить график момента "
            "сопротивления" if p["which"] == "resistance" else
            "момент сопротивления совершает меньше работы, чем может дать график движущего "
            "момента")
    return p


DERIVED |= {"t2_which_gen", "t2_balance_why", "t2_python_ru"}


#: the strokes of a four-stroke cycle in the genitive («такт расширения»)
_STROKES_RU = {"expansion": "расширения", "exhaust": "выпуска", "intake": "впуска",
               "compression": "сжатия"}


#: what a slider is to the load on it, in the genitive («у поршня 3»)
_ROLES_RU = {"piston": "поршня", "slider": "ползуна"}


def _msgs_run_ru_params(code: str, p: dict) -> dict:
    """The Russian words of the msgs_run errors' parameters."""
    if code == "run_point_not_on_link":
        p["placed_ru"] = (": точка, закреплённая на звене, строится по точкам самого этого звена"
                          if p["placed"] else "")
    if code == "run_diagram_step":
        p["end_ru"], p["begin_ru"] = _STROKES_RU[p["end"]], _STROKES_RU[p["begin"]]
        p["begins_ru"] = "начинался" if p["closing"] else "начинается"
    if code in ("run_diagram_ends_inside", "run_diagram_direction"):
        p["stroke_ru"] = _STROKES_RU[p["stroke"]]
    if code == "run_diagram_direction":
        p["way_ru"] = "расти" if p["up"] else "убывать"
    if code in ("run_firing_no_cylinder", "run_firing_not_four_stroke"):
        p["four_ru"] = p["four"] or "нет"
    if code == "run_no_dead_centres":
        p["role_ru"] = _ROLES_RU.get(p["role"], p["role"])
    if code in ("run_cannot_write", "run_cannot_read"):
        p["reason_ru"] = os_reason_ru(p["errno"], p["reason"])
    return p


DERIVED |= {"placed_ru", "end_ru", "begin_ru", "begins_ru", "stroke_ru", "way_ru",
                  "four_ru", "role_ru", "reason_ru"}


DERIVED |= {"from_ru"}


def _msgs_rim_ru_params(code: str, p: dict) -> dict:
    if code == "rim_thin":
        p["from_ru"] = "задана" if p["given"] else "наибольшая, какую допускает напряжение"
    return p


def _msgs_plural_ru_params(code: str, p: dict) -> dict:
    if code == "startup_not_steady":
        p["cycles_ru"] = count(p["cycles"], "{n} cycle", "{n} cycles")
    elif code in ("values_per_s", "values_per_position"):
        p["n_values_ru"] = count(p["n"], "{n} value", "{n} values")
    elif code == "shafts_count":
        p["shafts_ru"] = count(p["shafts"], "{n} shaft", "{n} shafts")
    elif code == "var_no_new_combination":
        p["draws_ru"] = count(p["draws"], "{n} attempt", "{n} attempts")
    return p


DERIVED |= {"cycles_ru", "n_values_ru", "shafts_ru", "draws_ru"}



def _msgs_libraries_ru_params(code: str, p: dict) -> dict:
    """The libraries' and the system's own words inside a line (render/library_ru.py)."""
    if code == "plot_cannot_write":
        p["reason_ru"] = (os_reason_ru(p["errno"], p["strerror"]) if p.get("strerror")
                          else said_ru(p["reason"], MATPLOTLIB_RU))
    elif code in ("toml_syntax", "toml_decimal_comma"):
        p["detail_ru"] = toml_detail_ru(p["detail"])
    elif code == "not_json":
        p["msg"] = said_ru(p["msg"], JSON_RU)
    return p


def _report_ru_params(code: str, p: dict) -> dict:
    """The warnings of a run (startup_not_steady, rim_speed, out_removed)."""
    if code == "startup_not_steady":
        p["target"] = (f"{p['omega_pred']:.5g} рад/с" if p.get("omega_pred") is not None
                       else "нет: характеристика двигателя не может нести среднюю нагрузку")
    elif code == "rim_speed":
        p["shape_ru"] = {"disk": "диска", "rim": "обода"}.get(p["shape"], p["shape"])
        p["material_ru"] = ("заданного" if p["material"] == "the given material"
                            else material(p["material"], "ru"))
    elif code == "out_removed":
        names = p["files"].split(", ")
        more = names[-1].split(" and ")
        if len(more) == 2 and more[1].endswith(" more"):
            names[-1] = f"{more[0]} и ещё {more[1][:-len(' more')]}"
        p["files_ru"] = ", ".join(names)
    return p


DERIVED |= {"target", "shape_ru", "material_ru", "files_ru"}
def _safe_out_ru_params(code: str, p: dict) -> dict:
    """The output folder's notes and refusals (io/output.py, issue 23)."""
    if code == "out_user_kept":
        names = p["files"].split(", ")
        more = names[-1].rsplit(" and ", 1)
        if len(more) == 2 and more[1].endswith(" more"):
            names[-1] = f"{more[0]} и ещё {more[1][:-len(' more')]}"
        p["files_ru"] = ", ".join(names)
    elif code == "out_restore_failed":
        p["reason_ru"] = {"a path changed since": "с тех пор изменился путь",
                          "its journal is not one flywheel wrote": "его журнал записан не flywheel",
                          }.get(p["reason"]) or os_reason_ru(p.get("errno"), p["reason"])
    return p


#: grade's inputs, as its refusal to write over them names them
_GRADE_INPUTS_RU = {"the answer key": "ключ ответов", "the answer sheet": "лист ответов"}


def _safe_grade_ru_params(code: str, p: dict) -> dict:
    """grade's refusals of issue 23 (teaching/grading.py)."""
    if code == "grade_output_is_input":
        p["what_ru"] = _GRADE_INPUTS_RU.get(p["what"], p["what"])
    return p


#: the things a limit counts (too_many_items): the English noun of the count entry
_BOUNDS_ITEMS = {"points": "point", "terms": "term", "orders": "order", "angles": "angle",
                 "areas": "area", "energies": "energy"}
_BOUNDS_PLURAL = {"energy": "energies"}


def _bounds_count(n, noun: str) -> str:
    return count(n, "{n} " + noun, "{n} " + _BOUNDS_PLURAL.get(noun, noun + "s"))


def _bounds_num_ru(x) -> str:
    """A number as a Russian line writes it: decimal comma, true minus (−1e+06)."""
    text = f"{x:g}" if isinstance(x, float) else str(x)
    return text.replace(".", ",").replace("-", "−")


def _bounds_ru_params(code: str, p: dict) -> dict:
    """The limits of the work (issue 23): counts, nesting, long integers, cycles, angles."""
    if code == "too_many_items":
        p["count_items_ru"] = _bounds_count(p["count"], _BOUNDS_ITEMS.get(p["items"], "element"))
    elif code == "at_too_many":
        p["count_angles_ru"] = _bounds_count(p["count"], "angle")
    if code in ("doc_too_deep", "doc_number_too_long"):
        p["where_at_ru"] = f"{p['where']}: " if p.get("where") else ""
    if code == "t2_graphs_too_big":
        p["most_ru"] = _bounds_num_ru(float(p["most"]))
    for k in ("cycle", "k", "step", "a", "lo", "hi"):
        if k in p and code in ("cycle_out_of_range", "t2_cycle_not_whole",
                               "t2_order_not_periodic", "at_out_of_range",
                               "doc_number_too_long"):
            p[k + "_ru"] = _bounds_num_ru(p[k])
    return p


DERIVED |= {"files_ru", "reason_ru", "what_ru", "count_items_ru", "count_angles_ru",
            "where_at_ru", "cycle_ru", "k_ru", "most_ru", "step_ru", "a_ru", "lo_ru", "hi_ru"}


#: the functions (code, params) -> params, in the order they run (the order of the old blocks)
HOOKS = (_msgs2_ru_params, _msgs_cli_ru_params, _msgs_duty_ru_params, _msgs_tabulated_ru_params,
         _msgs_aggregate_ru_params, _msgs_task2_ru_params, _msgs_run_ru_params,
         _msgs_rim_ru_params, _msgs_libraries_ru_params, _msgs_plural_ru_params,
         _report_ru_params, _safe_out_ru_params, _safe_grade_ru_params, _bounds_ru_params)


def russian_params(code: str, params: dict, say) -> dict:
    """The parameters of a Notice with the Russian words its template needs; ``say(notice,
    "ru")`` says a parameter that is a Notice itself (render/messages.py ``message``)."""
    p = _msgs_ru_params(params, say)
    for hook in HOOKS:
        p = hook(code, p)
    return p
