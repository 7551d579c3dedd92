"""Every label, symbol and unit `flywheel task2` and `flywheel aggregate` print, in English and in
Russian: one table, key → :class:`Term` (symbol, unit, English name, Russian name).

The Russian follows the course's terms: seed 002 («Задача 2»: ω_max, ω_min, ω_ср, δ, J_пр, M_Д,
M_С, ΔT_нб, участок, цикл установившегося движения) and seed 003 (Ефанов, «Теория механизмов и
машин», ch. 9: вал I, J_Д, J_пр.I, обобщённые координаты, инерционные коэффициенты a_ij,
полумуфты), with the usual terms of torsional vibration (собственная частота, форма колебаний,
жёсткость, демпфирование, упругий момент, угол закручивания, пуск, установившийся режим).

A name may be a template with ``{fields}`` (``text(key, lang, **fields)`` fills them); text
handed to rich in a table title keeps its square brackets escaped (``\\[``), as the renderers
need. The English column is exactly what the commands printed before the table existed (their
output is byte-identical). A later step merges this table into the project-wide nomenclature.
"""
from __future__ import annotations

from dataclasses import dataclass

LANGS = ("en", "ru")


@dataclass(frozen=True)
class Term:
    """symbol : as printed in English ("" for a heading or a sentence); unit : SI, English
    notation ("" for none); en, ru : the name, label or sentence template; symbol_ru : the
    course's symbol where it differs from the English one (M_Д for M_D)."""

    symbol: str
    unit: str
    en: str
    ru: str
    symbol_ru: str = ""

    def name(self, lang: str) -> str:
        return self.ru if lang == "ru" else self.en

    def sym(self, lang: str) -> str:
        return (self.symbol_ru or self.symbol) if lang == "ru" else self.symbol


#: units as printed in English → in Russian
UNITS_RU = {
    "rad": "рад", "rad/s": "рад/с", "deg": "град", "rpm": "об/мин", "rev/min": "об/мин",
    "N·m": "Н·м", "J": "Дж", "W": "Вт", "kg·m²": "кг·м²", "kg": "кг", "m": "м", "s": "с",
    "Hz": "Гц", "N·m/rad": "Н·м/рад", "N·m·s/rad": "Н·м·с/рад", "rad/s²": "рад/с²",
    "Pa": "Па", "": "",
}

T = Term
TERMS: dict[str, Term] = {
    # -- quantities of task 2 ----------------------------------------------------------------
    "J": T("J", "kg·m²", "J (reduced inertia)", "J_пр (приведённый момент инерции)", "J_пр"),
    "omega0": T("ω0", "rad/s", "ω0 (at φ = 0)", "ω0 (при φ = 0)"),
    "omega_max": T("ω_max", "rad/s", "ω_max", "ω_max"),
    "omega_min": T("ω_min", "rad/s", "ω_min", "ω_min"),
    "omega_mean": T("ω_ср", "rad/s", "ω_ср = (ω_max + ω_min)/2", "ω_ср = (ω_max + ω_min)/2"),
    "delta": T("δ", "", "δ = (ω_max − ω_min)/ω_ср",
               "δ = (ω_max − ω_min)/ω_ср, коэффициент неравномерности"),
    "delta_T_max": T("ΔT_нб", "J", "ΔT_нб = A_max − A_min", "ΔT_нб = A_max − A_min"),
    "power": T("P", "W", "power = mean M_D · ω_ср", "мощность = среднее M_Д · ω_ср"),
    "J_required": T("J", "kg·m²", "J for δ = {delta}", "J_пр для δ = {delta}", "J_пр"),
    "J_required_how": T("", "", "ΔT_нб/(δ·ω_ср²)", "ΔT_нб/(δ·ω_ср²)"),
    "rim_mass": T("m", "kg", "rim mass at R = {R} m", "масса обода при R = {R} м"),
    "rim_mass_how": T("", "", "m = J/R²", "m = J_пр/R²"),
    "M_D": T("M_D", "N·m", "M_D", "M_Д", "M_Д"),
    "M_C": T("M_C", "N·m", "M_C", "M_С", "M_С"),
    "A": T("A", "J", "A", "A"),
    "omega": T("ω", "rad/s", "ω", "ω"),
    "phi_deg": T("φ°", "deg", "φ°", "φ°"),
    "phi_pi": T("φ/π", "", "φ/π", "φ/π"),
    "rpm": T("n", "rpm", "{n} rpm", "{n} об/мин"),
    "rpm_at": T("", "", "{n} rpm at {angle}", "{n} об/мин при {angle}"),
    "angle": T("φ", "deg", "φ = {deg}° ({pi}π rad)", "φ = {deg}° ({pi}π рад)"),
    "angle_unknown": T("", "", "(angle not given)", "(угол не задан)"),
    # -- task 2: headings and sentences -------------------------------------------------------
    "t2_seed_title": T("", "", "«Задача 2», {profile} resistance moment",
                       "Задача 2, момент сопротивления — {profile}"),
    "t2_seed_source": T("", "", "textbook task «Задача 2» (steady motion under given moment "
                        "graphs, table 27)", "задача «Задача 2» (установившееся движение "
                        "при заданных графиках моментов, табл. 27)"),
    "triangle": T("", "", "triangle", "треугольник"),
    "rectangle": T("", "", "rectangle", "прямоугольник"),
    "t2_balance": T("", "", "cycle balance ∮M_D dφ = ∮M_C dφ gives {name} = {value} N·m "
                            "(work per cycle {work} J)",
                    "баланс работ за цикл ∮M_Д dφ = ∮M_С dφ даёт {name} = {value} Н·м "
                    "(работа за цикл {work} Дж)"),
    "t2_given": T("", "", "M_D = {M_D} N·m, M_C = {M_C} N·m (given)",
                  "M_Д = {M_D} Н·м, M_С = {M_C} Н·м (заданы)"),
    "t2_unsteady": T("", "", "[yellow]the motion is not steady:[/yellow] the work over the cycle "
                             "is {work} J, so ω after one cycle is {omega_end} rad/s "
                             "(ω0 = {omega0} rad/s)",
                     "[yellow]движение не установившееся:[/yellow] работа за цикл {work} Дж, "
                     "поэтому ω в конце цикла {omega_end} рад/с (ω0 = {omega0} рад/с)"),
    "t2_segments": T("", "", "Segments: ½·J·(ω² − ω0²) = A(φ) = ∫(M_D − M_C) dφ\n"
                             "φ \\[deg], M \\[N·m], A \\[J], ω \\[rad/s]",
                     "Участки: ½·J_пр·(ω² − ω0²) = A(φ) = ∫(M_Д − M_С) dφ\n"
                     "φ \\[град], M \\[Н·м], A \\[Дж], ω \\[рад/с]"),
    "point": T("", "", "point", "точка"),
    "crossing_MD_MC": T("", "", "M_D = M_C", "M_Д = M_С"),
    "crossing": T("", "", "crossing", "пересечение"),
    "bound": T("", "", "bound", "граница"),
    "results": T("", "", "Results", "Результаты"),
    "quantity": T("", "", "quantity", "величина"),
    "value": T("", "", "value", "значение"),
    "unit": T("", "", "unit", "ед."),
    # -- task 2: angular acceleration and time (shown with --epsilon or --at) -------------------
    "t2_motion": T("", "", "Acceleration and time: ε(φ) = (M_D − M_C)/J, t(φ) = ∫₀^φ dφ/ω",
                   "Угловое ускорение и время: ε(φ) = (M_Д − M_С)/J_пр, t(φ) = ∫₀^φ dφ/ω"),
    "epsilon": T("ε", "rad/s²", "ε", "ε"),
    "epsilon_max": T("ε_max", "rad/s²", "ε_max (largest over the cycle)",
                     "ε_max (наибольшее за цикл)"),
    "epsilon_min": T("ε_min", "rad/s²", "ε_min (smallest over the cycle)",
                     "ε_min (наименьшее за цикл)"),
    "cycle_time": T("T_ц", "s", "cycle time ∫₀^Φ dφ/ω", "время цикла ∫₀^Φ dφ/ω"),
    "energy_fluctuation_coefficient": T("C_E", "", "C_E = ΔT_нб / work per cycle",
                                        "C_E = ΔT_нб / работа за цикл"),
    "at_angle": T("", "", "at {angle}", "при {angle}"),
    "t2_phases": T("", "", "Phases between the extremes of ω (crossings and jumps of M_D − M_C)",
                   "Участки между экстремумами ω (пересечения и скачки M_Д − M_С)"),
    "phi_from": T("φ", "deg", "from φ°", "от φ°"),
    "phi_to": T("φ", "deg", "to φ°", "до φ°"),
    "trend": T("", "", "speed", "скорость"),
    "trend_up": T("", "", "rises (M_D > M_C)", "растёт (M_Д > M_С)"),
    "trend_down": T("", "", "falls (M_D < M_C)", "падает (M_Д < M_С)"),
    "trend_steady": T("", "", "constant (M_D = M_C)", "постоянна (M_Д = M_С)"),
    "t_start": T("t", "s", "t at start \\[s]", "t в начале \\[с]"),
    "duration": T("Δt", "s", "duration \\[s]", "длительность \\[с]"),
    "t2_at": T("", "", "At the asked angles", "В заданных положениях"),
    "t": T("t", "s", "t \\[s]", "t \\[с]"),
    "phi_col": T("φ", "deg", "φ°", "φ°"),
    "omega_col": T("ω", "rad/s", "ω \\[rad/s]", "ω \\[рад/с]"),
    "epsilon_col": T("ε", "rad/s²", "ε \\[rad/s²]", "ε \\[рад/с²]"),
    "flywheel_mass": T("m", "kg", "mass at k = {k} m", "масса при k = {k} м"),
    "flywheel_mass_how": T("", "", "m = J/k²", "m = J_пр/k²"),
    "t2_power": T("", "", "mean power P = {P} W at ω_ср: mean {name} = P/ω_ср = {T} N·m",
                  "средняя мощность P = {P} Вт при ω_ср: среднее {name} = P/ω_ср = {T} Н·м"),
    # -- task 2: the plot ----------------------------------------------------------------------
    "t2_plot_epsilon": T("ε", "rad/s²", "ε(φ) = (M_D − M_C)/J", "ε(φ) = (M_Д − M_С)/J_пр"),
    "t2_plot_epsilon_axis": T("ε", "rad/s²", "ε [rad/s²]", "ε [рад/с²]"),
    "t2_plot_epsilon_max": T("ε_max", "rad/s²", "ε_max = {value} rad/s² at {deg}°",
                             "ε_max = {value} рад/с² при {deg}°"),
    "t2_plot_epsilon_min": T("ε_min", "rad/s²", "ε_min = {value} rad/s² at {deg}°",
                             "ε_min = {value} рад/с² при {deg}°"),
    "t2_plot_MD": T("M_D", "N·m", "M_D (driving)", "M_Д (движущий)", "M_Д"),
    "t2_plot_MC": T("M_C", "N·m", "M_C (resistance)", "M_С (сопротивления)", "M_С"),
    "t2_plot_moment": T("M", "N·m", "moment [N·m]", "момент [Н·м]"),
    "t2_plot_A": T("A", "J", "A(φ) = ∫(M_D − M_C) dφ", "A(φ) = ∫(M_Д − M_С) dφ"),
    "t2_plot_A_axis": T("A", "J", "A [J]", "A [Дж]"),
    "t2_plot_omega": T("ω", "rad/s", "ω(φ)", "ω(φ)"),
    "t2_plot_A_areas": T("", "", "energy at the crossings", "энергия в точках пересечения"),
    "t2_plot_omega_areas": T("", "", "ω at the crossings", "ω в точках пересечения"),
    "t2_plot_omega_mean": T("ω_ср", "rad/s", "ω_ср", "ω_ср"),
    "t2_plot_omega_axis": T("ω", "rad/s", "ω [rad/s]", "ω [рад/с]"),
    "t2_plot_phi_axis": T("φ", "deg", "φ [deg]", "φ [град]"),
    "t2_plot_crossing_no": T("", "", "crossing number", "номер пересечения"),
    "t2_plot_title": T("", "", "task 2: δ = {delta}, ΔT_нб = {dT} J",
                       "задача 2: δ = {delta}, ΔT_нб = {dT} Дж"),
    "plot_written": T("", "", "plot written to {path}", "график записан в {path}"),
    # -- aggregate: the model ------------------------------------------------------------------
    "ag_rotors": T("", "", "Rotors reduced to shaft I (J·u², u = ω/ω_I)",
                   "Массы, приведённые к валу I (J·u², u = ω/ω_I)"),
    "rotor": T("", "", "rotor", "масса"),
    "J_reduced": T("J", "kg·m²", "J_reduced [kg·m²]", "J_пр [кг·м²]", "J_пр"),
    "u": T("u", "", "u", "u"),
    "ag_connections": T("", "", "Connections reduced to shaft I (c·u²)",
                        "Упругие связи, приведённые к валу I (c·u²)"),
    "between": T("", "", "between", "между"),
    "c": T("c", "N·m/rad", "c [N·m/rad]", "жёсткость c [Н·м/рад]"),
    "damping": T("b", "N·m·s/rad", "damping [N·m·s/rad]", "демпфирование [Н·м·с/рад]"),
    "rotor_motor": T("", "", "motor J_Д", "двигатель J_Д"),
    "rotor_machine": T("", "", "machine J_пр.I", "машина J_пр.I"),
    "ag_equations": T("", "", "Equations (9.24): Σ_j a_ij·q̈_j + Σ_j c_ij·q_j = Q_i, "
                              "q1 = φ1, q_(k+1) = φ_(k+1) − φ_k",
                      "Уравнения (9.24): Σ_j a_ij·q̈_j + Σ_j c_ij·q_j = Q_i, обобщённые "
                      "координаты q1 = φ1, q_(k+1) = φ_(k+1) − φ_k"),
    "a_ij": T("a_ij", "kg·m²", "inertia coefficients a_ij", "инерционные коэффициенты a_ij"),
    "c_ij": T("c_ij", "N·m/rad", "stiffness coefficients c_ij", "коэффициенты жёсткости c_ij"),
    "matrix_j": T("", "", "j = {j}", "j = {j}"),
    "matrix_i": T("", "", "i = {i}", "i = {i}"),
    "ag_equations_fixed": T("", "", "Equations: Σ_j a_ij·φ̈_j + Σ_j c_ij·φ_j = 0 in the rotors' "
                                    "absolute angles (a shaft fixed to the frame: no rigid "
                                    "rotation; a = M, c = K)",
                            "Уравнения: Σ_j a_ij·φ̈_j + Σ_j c_ij·φ_j = 0 в абсолютных углах масс "
                            "(вал заделан в стойку: вращения как твёрдого тела нет; a = M, c = K)"),
    "ag_equations_tree": T("", "", "Equations (9.24): Σ_j a_ij·q̈_j + Σ_j c_ij·q_j = Q_i, "
                                   "q1 = φ of the first rotor, q_(k+1) = φ_to − φ_from of shaft k",
                           "Уравнения (9.24): Σ_j a_ij·q̈_j + Σ_j c_ij·q_j = Q_i, обобщённые "
                           "координаты q1 = φ первой массы, q_(k+1) = φ_to − φ_from вала k"),
    "frame": T("", "", "frame", "стойка"),
    # -- aggregate: modes, nodes and shafts (shown with --modes) -------------------------------
    "ag_mode_nodes": T("", "", "Modes: frequencies and nodes (points that stand still)",
                       "Формы колебаний: частоты и узлы (неподвижные точки)"),
    "rpm_col": T("n", "rpm", "n [vib/min]", "n [кол/мин]"),
    "nodes": T("", "", "nodes", "узлы"),
    "node_shaft": T("", "", "shaft {a}–{b}: {dist}{frac} % of its compliance from {a}",
                    "вал {a}–{b}: {dist}{frac} % податливости от {a}"),
    "node_dist": T("", "m", "{d} m from {a}, ", "{d} м от {a}, "),
    "node_rotor": T("", "", "rotor {name} stands still", "масса {name} неподвижна"),
    "node_frame": T("", "", "the fixed end {name}", "заделка {name}"),
    "ag_shafts": T("", "", "Shafts: stiffness and equivalent length (uniform shaft of the first "
                           "piece's diameter)",
                   "Валы: жёсткость и приведённая длина (гладкий вал диаметра первого участка)"),
    "gear_ratio": T("i", "", "gear i", "передача i"),
    "c_input": T("c", "N·m/rad", "c (input side) [N·m/rad]", "c (со стороны входа) [Н·м/рад]"),
    "length": T("L", "m", "length [m]", "длина [м]"),
    "equivalent_length": T("L_eq", "m", "L_eq [m]", "L_прив [м]"),
    "d_ref": T("d", "m", "at d [m]", "при d [м]"),
    # -- aggregate: natural frequencies, resonance -----------------------------------------------
    "ag_modes": T("", "", "Natural frequencies (K·x = ω²·M·x)",
                  "Собственные частоты (K·x = ω²·M·x)"),
    "mode": T("", "", "mode", "№ формы"),
    "omega_n": T("ω", "rad/s", "ω [rad/s]", "ω [рад/с]"),
    "f_n": T("f", "Hz", "f [Hz]", "f [Гц]"),
    "shape": T("", "", "shape (φ, largest = 1)", "форма колебаний (φ, наибольшая = 1)"),
    "rigid_body": T("", "", "rigid body", "твёрдое тело"),
    "ag_no_motor": T("", "", "no [motor]: natural frequencies only",
                     "нет [motor]: только собственные частоты"),
    "ag_forcing": T("", "", "forcing ω_III = {w} rad/s ({f} Hz) at the steady speed "
                            "ω_I = {omega} rad/s ({n} rev/min)",
                    "вынуждающая частота ω_III = {w} рад/с ({f} Гц) при установившейся скорости "
                    "ω_I = {omega} рад/с ({n} об/мин)"),
    "ag_resonance": T("", "", "Resonance margins", "Отстройка от резонанса"),
    "f_n_col": T("f_n", "Hz", "f_n [Hz]", "f_n [Гц]"),
    "ratio": T("", "", "ω_forcing/ω_n", "ω_вын/ω_n"),
    "margin": T("", "", "margin |1 − ω_f/ω_n|", "отстройка |1 − ω_вын/ω_n|"),
    # -- aggregate: steady state and start-up ------------------------------------------------------
    "ag_steady": T("", "", "Steady state (closed form; solve_ivp check on the periodic orbit)",
                   "Установившийся режим (точное решение; проверка solve_ivp на периодической "
                   "траектории)"),
    "solve_ivp": T("", "", "solve_ivp", "solve_ivp"),
    "twist_mean": T("q2", "rad", "twist q2 = φ2 − φ1, mean",
                    "угол закручивания q2 = φ2 − φ1, среднее"),
    "twist_amp": T("q2", "rad", "twist q2, amplitude", "угол закручивания q2, амплитуда"),
    "moment_mean": T("M_у", "N·m", "elastic moment c·(φ1 − φ2) = −c·q2, mean",
                     "упругий момент c·(φ1 − φ2) = −c·q2, среднее"),
    "moment_amp": T("M_у", "N·m", "elastic moment −c·q2, amplitude",
                    "упругий момент −c·q2, амплитуда"),
    "omega_motor": T("ω1", "rad/s", "ω1 (motor) min … max", "ω1 (двигатель) min … max"),
    "delta_motor": T("δ", "", "δ motor", "δ двигателя"),
    "omega_machine": T("ω2", "rad/s", "ω2 (machine, own shaft) min … max",
                       "ω2 (машина, на своём валу) min … max"),
    "delta_machine": T("δ", "", "δ machine", "δ машины"),
    "startup_peak": T("", "N·m", "start-up: peak elastic moment",
                      "пуск: наибольший упругий момент"),
    "startup_over": T("", "s", "over {t} s", "за {t} с"),
    "startup_time": T("t", "s", "start-up: time to 95 % of ω1", "пуск: время до 95 % ω1"),
    "note": T("", "", "note: {note}", "примечание: {note}"),
    "note_radau": T("", "", "solve_ivp check: 5 forcing periods are {fast:.4g} periods of the "
                            "highest natural frequency {f_top:.6g} Hz, more than the explicit "
                            "method's {limit}: integrated with the implicit Radau method and the "
                            "constant Jacobian, which follows the forced motion but damps that "
                            "mode's own oscillation",
                    "проверка solve_ivp: 5 периодов возмущения — это {fast:.4g} периодов высшей "
                    "собственной частоты {f_top:.6g} Гц, больше предела явного метода ({limit}): "
                    "интегрирование неявным методом Radau с постоянной матрицей Якоби, который "
                    "следует вынужденному движению, но гасит собственные колебания этой формы"),
    "note_cap_linear": T("", "", "start-up: integrated over {t_end:.4g} s = {limit} periods of the "
                                 "highest natural frequency {f_top:.6g} Hz (the cap), not the "
                                 "default {wanted:.4g} s (the longer of five time constants and 20 "
                                 "forcing periods); --t-end sets the duration",
                         "пуск: проинтегрирован за {t_end:.4g} с = {limit} периодов высшей "
                         "собственной частоты {f_top:.6g} Гц (предел), а не {wanted:.4g} с по "
                         "умолчанию (большее из пяти постоянных времени и 20 периодов "
                         "возмущения); длительность задаёт --t-end"),
    "note_cap_constant": T("", "", "start-up: integrated over {t_end:.4g} s = {limit} periods of "
                                   "the highest natural frequency {f_top:.6g} Hz (the cap), not the "
                                   "default {wanted:.4g} s (20 forcing periods); --t-end sets the "
                                   "duration",
                           "пуск: проинтегрирован за {t_end:.4g} с = {limit} периодов высшей "
                           "собственной частоты {f_top:.6g} Гц (предел), а не {wanted:.4g} с по "
                           "умолчанию (20 периодов возмущения); длительность задаёт --t-end"),
    # -- aggregate: the plot ---------------------------------------------------------------------
    "ag_plot_startup": T("", "", "start-up", "пуск"),
    "ag_plot_steady": T("", "", "steady state", "установившийся режим"),
    "ag_plot_omega1": T("ω1", "rad/s", "ω1, {name}", "ω1, {name}"),
    "ag_plot_omegaN": T("ω", "rad/s", "ω{n}, {name} (reduced to shaft I)",
                        "ω{n}, {name} (приведена к валу I)"),
    "ag_plot_omega_axis": T("ω", "rad/s", "ω [rad/s]", "ω [рад/с]"),
    "ag_plot_moment": T("M_у", "N·m", "elastic moment c·(φ1 − φ2) = −c·q2",
                        "упругий момент c·(φ1 − φ2) = −c·q2"),
    "ag_plot_moment_axis": T("M", "N·m", "moment [N·m]", "момент [Н·м]"),
    "ag_plot_t_axis": T("t", "s", "t [s]", "t [с]"),
    "ag_plot_title": T("", "", "machine aggregate", "машинный агрегат"),
    # --- flywheel ---
    "rim_design": T("", "", "rim (share {share} of J, b/t = {ratio})",
                    "обод (доля {share} от J_пр, b/t = {ratio})"),
    "rim_design_dims": T("", "m", "D_mean = {D}, t = {t}, b = {b} m; m = {m} kg",
                         "D_ср = {D}, t = {t}, b = {b} м; m = {m} кг"),
    "rim_design_how": T("", "", "v = {v} m/s ({src}), σ = ρ·v² = {sigma} MPa; m = share·J/R²",
                        "v = {v} м/с ({src}), σ = ρ·v² = {sigma} МПа; m = доля·J_пр/R²"),
    "rim_from_stress": T("", "", "from σ_allow", "по σ_доп"),
    "rim_from_given": T("", "", "given", "задана"),
}
del T


def text(key: str, lang: str = "en", **fields) -> str:
    """The name of ``key`` in ``lang``, its ``{fields}`` filled (none: the name as it is).

    >>> text("t2_balance", "ru", name="M_С", value="60", work="94.2478")
    'баланс работ за цикл ∮M_Д dφ = ∮M_С dφ даёт M_С = 60 Н·м (работа за цикл 94.2478 Дж)'
    >>> text("omega_max"), text("J", "ru")
    ('ω_max', 'J_пр (приведённый момент инерции)')
    """
    name = TERMS[key].name(lang)
    return name.format(**fields) if fields else name


def unit(u: str, lang: str = "en") -> str:
    """An SI unit as printed in ``lang``: ``unit("rad/s", "ru") == "рад/с"``."""
    return UNITS_RU[u] if lang == "ru" else u


def symbol(key: str, lang: str = "en") -> str:
    """The symbol of ``key`` in ``lang`` (the course's where it differs: M_Д, M_С, J_пр)."""
    return TERMS[key].sym(lang)


def rotor_name(name: str, lang: str = "en") -> str:
    """A rotor's name in ``lang``: the two-mass model's own names translate, a user's stay."""
    if lang != "ru":
        return name
    for key in ("rotor_motor", "rotor_machine"):
        if name == TERMS[key].en:
            return TERMS[key].ru
    return name


__all__ = ["LANGS", "Term", "TERMS", "UNITS_RU", "text", "unit", "symbol", "rotor_name"]
