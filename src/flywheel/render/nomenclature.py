"""The nomenclature: every quantity flywheel prints, once — key → symbol, unit, English and
Russian name. CSV headers, plot axes and legends, the rich summary and the report take their
names from here; the renderers keep only sentence templates.

The commands other than ``run`` (task2, aggregate) and the plots take their row labels,
headings and sentence templates from the same table (the block marked ``--- nom`` at its end);
a name may be a template with ``{fields}`` that :func:`name` fills.

Symbols are the course's (Артоболевский, «Теория механизмов и машин», ch. 16–17; the course
worksheet on the two-stage compressor): ω_ср, M_Д, A_С, ΔT_нб, J_I, J_II. ``symbol`` is the
course's plain-text form (Russian subscripts), ``symbol_en`` the English text's where it differs
(ω_m, M_D), ``math`` the mathtext for plots. Units are SI as written in English; :func:`unit`
gives the Russian form (Н·м, кг·м², рад/с).

A key may stand for a family: ``x_{point}``, ``J_{link}``, ``M {load}`` — :func:`term` finds the
term of a concrete key ("x_B", "M gas HP") and the name filled in ("x of B").

>>> axis("J_II", "ru")
'$J_{II}$, кг·м²'
>>> name("vq_B", "en"), name("vq_B", "ru")
('|v_q| of B', 'аналог скорости точки B')
>>> unit("kg·m²/rad", "ru")
'кг·м²/рад'
"""
from __future__ import annotations

import errno
import re
from dataclasses import dataclass


@dataclass(frozen=True)
class Term:
    """One quantity: ``symbol`` (plain text, the course's), ``math`` (mathtext, for plots),
    ``unit`` (SI, English; "-" dimensionless, "" a record or a text that has no unit), ``en``
    and ``ru`` (names; ``{x}`` stands for the family member), ``symbol_en`` and ``math_en`` (the
    English text's symbol where the course's subscript is Cyrillic: ω_m, M_D)."""

    symbol: str
    math: str
    unit: str
    en: str
    ru: str
    symbol_en: str = ""
    math_en: str = ""

    def sym(self, lang: str) -> str:
        """The plain-text symbol in ``lang``."""
        return self.symbol_en if (lang == "en" and self.symbol_en) else self.symbol

    def tex(self, lang: str) -> str:
        """The mathtext symbol in ``lang``."""
        return self.math_en if (lang == "en" and self.math_en) else self.math


def _t(symbol, math, unit, en, ru, symbol_en="", math_en=""):
    return Term(symbol, math, unit, en, ru, symbol_en, math_en)


def _ci(symbol_en, unit, en, ru, symbol_ru=""):
    """A label of task2 / aggregate / a plot, given as those tables were written: the English
    symbol first and the course's (Russian) one only where it differs (M_Д for M_D); no mathtext."""
    return Term(symbol_ru or symbol_en, "", unit, en, ru, symbol_en if symbol_ru else "")


LANGS = ("en", "ru")


# -- the table ------------------------------------------------------------------------------------
TERMS: dict[str, Term] = {
    # crank, speed, cycle
    "phi_deg": _t("φ", r"$\varphi$", "deg", "crank angle φ", "угол поворота кривошипа φ"),
    "crank_length": _t("l₁", r"$l_1$", "m", "crank length l1", "длина кривошипа l₁", "l1"),
    "crank_speed": _t("n₁", r"$n_1$", "rev/s", "crank speed n1", "частота вращения кривошипа n₁",
                      "n1"),
    "omega_mean": _t("ω_ср", r"$\omega_{ср}$", "rad/s", "mean angular velocity ω_m",
                     "средняя угловая скорость ω_ср", "ω_m", r"$\omega_m$"),
    "n_points": _t("N", "$N$", "-", "grid nodes over the cycle", "число узлов сетки по φ"),
    "balance": _t("", "", "", "which constant moment balances the cycle (driving, resistance)",
                  "какой постоянный момент уравновешивает цикл (движущий, сопротивления)"),
    "cycle_time": _t("T_ц", r"$T_ц$", "s", "cycle time", "время цикла", "T_c", r"$T_c$"),
    # loads and works
    "cycle_work_resistance": _t("A_С", r"$A_С$", "J", "work of the resistance over a cycle A_C",
                                "работа сил сопротивления за цикл A_С", "A_C", "$A_C$"),
    "driving_moment": _t("M_Д", r"$M_Д$", "N·m", "driving moment M_D (cycle mean)",
                         "приведённый движущий момент M_Д", "M_D", "$M_D$"),
    "M_C": _t("M_С", r"$M_С$", "N·m", "reduced moment of the resistance M_C",
              "приведённый момент сил сопротивления M_С", "M_C", "$M_C$"),
    "balancing_moment": _t("M_const", r"$M_{const}$", "N·m",
                           "constant moment from the cycle balance",
                           "постоянный момент из условия цикла"),
    "M_known": _t("M_изв", r"$M_{изв}$", "N·m", "sum of the given loads' reduced moments",
                  "суммарный приведённый момент заданных сил", "M_known", r"$M_{known}$"),
    "M_sum": _t("M_Σ", r"$M_\Sigma$", "N·m", "total reduced moment M_Σ",
                "суммарный приведённый момент M_Σ"),
    "M {load}": _t("M", "$M$", "N·m", "reduced moment: {x}", "приведённый момент: {x}"),
    "M_st": _t("M_ст", r"$M_{ст}$", "N·m", "static moment M_ст = −Σ reduced moments of the "
               "loads (resisting positive)", "приведённый момент сил статического "
               "сопротивления M_ст"),
    "M_dyn": _t("M_дин", r"$M_{дин}$", "N·m", "dynamic moment M_дин = ω_m²/2·dJ_II/dφ",
                "динамический момент M_дин = ω_ср²/2·dJ_II/dφ"),
    "A_D": _t("A_Д", r"$A_Д$", "J", "work of the driving forces A_D", "работа движущих сил A_Д",
              "A_D", "$A_D$"),
    "A_C": _t("A_С", r"$A_С$", "J", "work of the resistance A_C", "работа сил сопротивления A_С",
              "A_C", "$A_C$"),
    "A": _t("A", "$A$", "J", "total work A", "суммарная работа A"),
    "s_{cylinder}": _t("s", "$s$", "-", "relative piston travel from the head, {x}",
                       "относительное перемещение поршня от головки, {x}"),
    "stroke_{cylinder}": _t("такт", "", "-", "stroke of {x}: 0 intake, 1 compression, 2 expansion, "
                            "3 exhaust", "такт {x}: 0 впуск, 1 сжатие, 2 расширение, 3 выпуск",
                            "stroke"),
    "cycle_deg": _t("Φ", r"$\Phi$", "deg", "the cycle", "цикл"),
    "firing_deg": _t("φ_всп", r"$\varphi_{всп}$", "deg", "where each cylinder fires",
                     "угол вспышки в каждом цилиндре", "φ_fire"),
    "p_{cylinder}": _t("p", "$p$", "Pa", "gas pressure, {x}", "давление газа, {x}"),
    "p_rel": _t("p/p_max", r"$p/p_{max}$", "-", "relative gas pressure p/p_max",
                "относительное давление газа p/p_max"),
    "F_{load}": _t("F", "$F$", "N", "force {x}", "сила {x}"),
    "slider_travel": _t("S", "$S$", "m", "slider travel S from its outer dead centre",
                        "перемещение ползуна S от внешней мёртвой точки"),
    # tabulated kinematics (summary.json of a [tabulated] case)
    "kinematics": _t("", "", "", "how the kinematics are given (\"tabulated\")",
                     "как заданы кинематические характеристики (по таблице)"),
    "tabulated_interpolation": _t("", "", "", "interpolation of J_II between the positions",
                                  "интерполяция J_II между положениями"),
    "tabulated_positions_deg": _t("φ", r"$\varphi$", "deg", "crank angles of the table's positions",
                                  "углы поворота кривошипа в положениях таблицы"),
    # what a case gives (flywheel check)
    "link_mass": _t("m", "$m$", "kg", "mass", "масса"),
    "J_S": _t("J_S", "$J_S$", "kg·m²", "moment of inertia about the centroid J_S",
              "момент инерции относительно центра масс J_S"),
    "link_J": _t("J", "$J$", "kg·m²", "moment of inertia of a link (about its centroid, or "
                 "its fixed pivot if it only turns)", "момент инерции звена (относительно центра "
                 "масс или неподвижной оси)"),
    "bore": _t("d", "$d$", "m", "bore", "диаметр цилиндра"),
    "link_length": _t("l", "$l$", "m", "length of a link", "длина звена"),
    "guide_angle": _t("α", r"$\alpha$", "deg", "direction of a guide", "направление направляющей"),
    "guide_offset": _t("e", "$e$", "m", "offset of a guide", "смещение направляющей"),
    "gravity": _t("g", "$g$", "m/s²", "gravity", "ускорение свободного падения"),
    "force_magnitude": _t("F", "$F$", "N", "force", "сила"),
    "couple_moment": _t("M", "$M$", "N·m", "moment of a couple", "момент пары сил"),
    "p_max": _t("p_max", r"$p_{max}$", "Pa", "greatest gas pressure p_max",
                "наибольшее давление газа p_max"),
    # reduction of masses, energy
    "J_II": _t("J_II", r"$J_{II}$", "kg·m²", "reduced moment of inertia of the second group J_II",
               "приведённый момент инерции второй группы звеньев J_II"),
    "dJ_II": _t("dJ_II/dφ", r"$dJ_{II}/d\varphi$", "kg·m²/rad", "dJ_II/dφ",
                "производная dJ_II/dφ"),
    "J_{link}": _t("J_i", "$J_i$", "kg·m²", "link {x}'s share of J_II", "вклад звена {x} в J_II"),
    "dJ_{link}": _t("dJ_i/dφ", r"$dJ_i/d\varphi$", "kg·m²/rad", "link {x}'s share of dJ_II/dφ",
                    "вклад звена {x} в dJ_II/dφ"),
    "J_II_mean": _t("J_II ср", r"$\overline{J_{II}}$", "kg·m²", "J_II, cycle mean",
                    "J_II, среднее за цикл", "mean J_II"),
    "J_II_min": _t("J_II min", r"$J_{II\,min}$", "kg·m²", "J_II, least", "J_II, наименьшее"),
    "J_II_max": _t("J_II max", r"$J_{II\,max}$", "kg·m²", "J_II, greatest", "J_II, наибольшее"),
    "T_II": _t("T_II", r"$T_{II}$", "J", "kinetic energy of the second group T_II",
               "кинетическая энергия второй группы T_II"),
    "dT_I": _t("ΔT_I", r"$\Delta T_I$", "J", "change of kinetic energy of the first group ΔT_I",
               "изменение кинетической энергии первой группы ΔT_I"),
    "delta_T_max": _t("ΔT_нб", r"$\Delta T_{нб}$", "J", "largest energy fluctuation ΔT_нб",
                      "наибольшее изменение кинетической энергии ΔT_нб"),
    "delta_T_I_max": _t("ΔT_I max", r"$\Delta T_{I\,max}$", "J", "ΔT_I, greatest",
                        "ΔT_I, наибольшее"),
    "delta_T_I_min": _t("ΔT_I min", r"$\Delta T_{I\,min}$", "J", "ΔT_I, least", "ΔT_I, наименьшее"),
    "phi_delta_T_I_max_deg": _t("φ", r"$\varphi$", "deg", "φ of ΔT_I max", "φ при ΔT_I max"),
    "phi_delta_T_I_min_deg": _t("φ", r"$\varphi$", "deg", "φ of ΔT_I min", "φ при ΔT_I min"),
    "T0": _t("T₀", "$T_0$", "J", "total kinetic energy at φ = 0",
             "полная кинетическая энергия при φ = 0", "T0"),
    # flywheel
    "delta": _t("δ", r"$\delta$", "-", "target δ", "заданный коэффициент неравномерности δ"),
    "J_first_group": _t("J_10 + J_ред", r"$J_{10} + J_{ред}$", "kg·m²",
                        "already on the crank shaft", "уже на валу кривошипа (J_10 + J_ред)"),
    "J_required": _t("J_I", "$J_I$", "kg·m²", "required inertia of the first group J_I "
                     "(Merzalov)", "необходимый момент инерции первой группы J_I (Мерцалов)"),
    "J_required_exact": _t("J_I", "$J_I$", "kg·m²", "required J_I, exact (energy–mass diagram)",
                           "необходимый J_I, точно (диаграмма Виттенбауэра)"),
    "J_flywheel": _t("J_М", "$J_М$", "kg·m²", "flywheel J_M = J_I − first group",
                     "момент инерции маховика J_М = J_I − (J_10 + J_ред)", "J_M", "$J_M$"),
    "J_flywheel_exact": _t("J_М", "$J_М$", "kg·m²", "flywheel J_M, exact",
                           "момент инерции маховика J_М, точно", "J_M", "$J_M$"),
    "delta_achieved": _t("δ", r"$\delta$", "-", "δ achieved with J_I (Merzalov)",
                         "достигнутый δ (Мерцалов)"),
    "delta_achieved_exact": _t("δ", r"$\delta$", "-", "δ achieved with the exact J_I",
                               "достигнутый δ (точный J_I)"),
    "flywheel_J_on_its_shaft": _t("J_М/i²", r"$J_М/i^2$", "kg·m²",
                                  "flywheel J on its own shaft, J_M/i²",
                                  "момент инерции маховика на его валу J_М/i²", "J_M/i²",
                                  r"$J_M/i^2$"),
    "flywheel_speed_ratio": _t("i", "$i$", "-", "flywheel shaft speed ratio i",
                               "передаточное отношение к валу маховика i"),
    "flywheel_rim_share": _t("k_об", r"$k_{об}$", "-", "rim share of J_M (hub and spokes the rest)",
                             "доля J_М на ободе (остальное — ступица и спицы)", "k_rim",
                             r"$k_{rim}$"),
    "flywheel_material": _t("", "", "", "flywheel material", "материал маховика"),
    "flywheel_material_density": _t("ρ", r"$\rho$", "kg/m³", "density of the flywheel material",
                                    "плотность материала маховика"),
    "flywheel_rim_speed_limit": _t("v_доп", r"$v_{доп}$", "m/s", "rim speed ≤",
                                   "окружная скорость ≤", "v_max", r"$v_{max}$"),
    "flywheel_formulas": _t("", "", "", "how the disk and the rim are sized",
                            "как рассчитаны диск и обод"),
    "flywheel_disk": _t("", "", "", "flywheel as a solid disk", "маховик — сплошной диск"),
    "flywheel_rim": _t("", "", "", "flywheel as a rim", "маховик — обод"),
    "D": _t("D", "$D$", "m", "outer diameter", "наружный диаметр"),
    "D_inner": _t("D₁", "$D_1$", "m", "inner diameter of the rim", "внутренний диаметр обода",
                  "D1"),
    "b": _t("b", "$b$", "m", "width", "ширина"),
    "mass": _t("m", "$m$", "kg", "mass", "масса"),
    "rim_speed": _t("v", "$v$", "m/s", "rim speed", "окружная скорость обода"),
    # true motion
    "omega": _t("ω", r"$\omega$", "rad/s", "crank angular velocity ω",
                "угловая скорость звена приведения ω"),
    "epsilon": _t("ε", r"$\varepsilon$", "rad/s²", "crank angular acceleration ε",
                  "угловое ускорение звена приведения ε"),
    "omega_exact": _t("ω", r"$\omega$", "rad/s", "ω with the exact flywheel size",
                      "ω при точном моменте инерции маховика"),
    "omega_max": _t("ω_max", r"$\omega_{max}$", "rad/s", "ω_max", "ω_max"),
    "omega_min": _t("ω_min", r"$\omega_{min}$", "rad/s", "ω_min", "ω_min"),
    "phi_omega_max_deg": _t("φ", r"$\varphi$", "deg", "φ of ω_max", "φ при ω_max"),
    "phi_omega_min_deg": _t("φ", r"$\varphi$", "deg", "φ of ω_min", "φ при ω_min"),
    "t": _t("t", "$t$", "s", "time t(φ)", "время t(φ)"),
    # --transients (summary.json results.time_domain)
    "time_domain": _t("", "", "", "motion in time (--transients)", "движение во времени"),
    "omega_final_predicted": _t("ω_s", r"$\omega_s$", "rad/s",
                                "steady cycle-mean speed of the motor line ω_s",
                                "установившаяся средняя скорость по характеристике двигателя ω_s"),
    # kinematics on the grid
    "x_{point}": _t("x", "$x$", "m", "x of {x}", "x точки {x}"),
    "y_{point}": _t("y", "$y$", "m", "y of {x}", "y точки {x}"),
    "vq_{point}": _t("v_q", "$|v_q|$", "m/rad", "|v_q| of {x}", "аналог скорости точки {x}"),
    "vqx_{point}": _t("v_qx", "$v_{qx}$", "m/rad", "v_qx of {x}", "v_qx точки {x}"),
    "vqy_{point}": _t("v_qy", "$v_{qy}$", "m/rad", "v_qy of {x}", "v_qy точки {x}"),
    "aq_{point}": _t("a_q", "$|a_q|$", "m/rad²", "|a_q| of {x}", "аналог ускорения точки {x}"),
    "aqx_{point}": _t("a_qx", "$a_{qx}$", "m/rad²", "a_qx of {x}", "a_qx точки {x}"),
    "aqy_{point}": _t("a_qy", "$a_{qy}$", "m/rad²", "a_qy of {x}", "a_qy точки {x}"),
    "theta_{link}": _t("θ", r"$\theta$", "deg", "angle of link {x}", "угол звена {x}"),
    "omega_q_{link}": _t("ω_q", r"$\omega_q$", "-", "ω_q of link {x}",
                         "аналог угловой скорости звена {x}"),
    "eps_q_{link}": _t("ε_q", r"$\varepsilon_q$", "1/rad", "ε_q of link {x}",
                       "аналог углового ускорения звена {x}"),
    # at a report angle (summary.json results.at[])
    "at": _t("", "", "", "the motion at each report angle", "движение в расчётных положениях"),
    "x": _t("x", "$x$", "m", "x of a point", "координата x точки"),
    "y": _t("y", "$y$", "m", "y of a point", "координата y точки"),
    "v_q": _t("v_q", "$v_q$", "m/rad", "velocity analogue", "аналог скорости"),
    "a_q": _t("a_q", "$a_q$", "m/rad²", "acceleration analogue", "аналог ускорения"),
    "v": _t("v", "$v$", "m/s", "velocity", "скорость"),
    "a": _t("a", "$a$", "m/s²", "acceleration", "ускорение"),
    "v_x": _t("v_x", "$v_x$", "m/s", "velocity, x component", "проекция скорости на ось x"),
    "v_y": _t("v_y", "$v_y$", "m/s", "velocity, y component", "проекция скорости на ось y"),
    "a_x": _t("a_x", "$a_x$", "m/s²", "acceleration, x component",
              "проекция ускорения на ось x"),
    "a_y": _t("a_y", "$a_y$", "m/s²", "acceleration, y component",
              "проекция ускорения на ось y"),
    "epsilon_q": _t("ε_q", r"$\varepsilon_q$", "1/rad", "angular acceleration analogue",
                    "аналог углового ускорения"),
    "omega_q": _t("ω_q", r"$\omega_q$", "-", "angular velocity analogue",
                  "аналог угловой скорости"),
    # duty cycle (flywheel duty-cycle) ------------------------------------------------------------
    # (omega_max, omega_min, omega_mean and cycle_time above serve it too)
    "energy_per_operation": _t("E", "$E$", "J", "work of one operation E",
                               "работа одной операции E"),
    "sheared_area": _t("A", "$A$", "m²", "sheared area A", "площадь среза A"),
    "energy_per_area": _t("e", "$e$", "J/m²", "work per unit of sheared area e",
                          "удельная работа на единицу площади среза e"),
    "force_max": _t("F_max", r"$F_{max}$", "N", "largest force F_max",
                    "наибольшая сила F_max"),
    "plate_thickness": _t("t", "$t$", "m", "plate thickness t (the force's travel)",
                          "толщина листа t (ход силы)"),
    "force_shape": _t("F(s)", "$F(s)$", "-", "force over the travel", "сила по ходу"),
    "delta_E": _t("ΔE", r"$\Delta E$", "J", "energy the flywheel gives per operation ΔE",
                  "энергия, отдаваемая маховиком за операцию ΔE"),
    "energy_fluctuation_coefficient": _t("C_E", "$C_E$", "-",
                                         "coefficient of fluctuation of energy C_E = ΔE/E",
                                         "коэффициент колебания энергии C_E = ΔE/E"),
    "motor_power": _t("P", "$P$", "W", "motor power P (while it works)",
                      "мощность двигателя P (во время работы)"),
    "motor_input_power": _t("P/η", r"$P/\eta$", "W", "power the motor draws P/η",
                            "потребляемая мощность P/η"),
    "motor_efficiency": _t("η", r"$\eta$", "-", "efficiency of the drive η", "КПД привода η"),
    "motor_torque": _t("M_Д", "$M_Д$", "N·m", "motor torque M_D = P/ω_m",
                       "момент двигателя M_Д = P/ω_ср", "M_D"),
    "mean_power": _t("P_ср", r"$P_{ср}$", "W", "mean power of the operations E/T_c",
                     "средняя мощность операций E/T_ц", "P_m"),
    "speed_fluctuation": _t("δ", r"$\delta$", "-",
                            "coefficient of fluctuation of speed δ = (ω_max − ω_min)/ω_m",
                            "коэффициент неравномерности хода δ = (ω_max − ω_min)/ω_ср"),
    "rpm_max": _t("n_max", r"$n_{max}$", "rpm", "top speed (at the start of the operation)",
                  "наибольшая частота вращения (в начале операции)"),
    "rpm_min": _t("n_min", r"$n_{min}$", "rpm", "lowest speed (at the end of the operation)",
                  "наименьшая частота вращения (в конце операции)"),
    "rpm_mean": _t("n_ср", r"$n_{ср}$", "rpm", "mean speed (n_max + n_min)/2",
                   "средняя частота вращения (n_max + n_min)/2", "n_m"),
    "flywheel_J": _t("J", "$J$", "kg·m²", "flywheel moment of inertia J",
                     "момент инерции маховика J"),
    "flywheel_mass": _t("m", "$m$", "kg", "flywheel mass m = J/k²", "масса маховика m = J/k²"),
    "flywheel_radius": _t("k", "$k$", "m", "radius of gyration k (a rim's mean radius)",
                          "радиус инерции k (средний радиус обода)"),
    "rim_speed_max": _t("v_max", r"$v_{max}$", "m/s", "speed at the radius k, top",
                        "скорость на радиусе k, наибольшая"),
    "rim_speed_min": _t("v_min", r"$v_{min}$", "m/s", "speed at the radius k, lowest",
                        "скорость на радиусе k, наименьшая"),
    "rim_speed_mean": _t("v_ср", r"$v_{ср}$", "m/s", "speed at the radius k, mean",
                         "скорость на радиусе k, средняя", "v_m"),
    "operation_time": _t("t_оп", r"$t_{оп}$", "s", "the operation", "операция", "t_op"),
    "recovery_time": _t("t_вос", r"$t_{вос}$", "s", "recovery to ω_max by the motor's torque",
                        "восстановление ω_max моментом двигателя", "t_rec"),
    "idle_time": _t("t_х", r"$t_х$", "s", "idle at ω_max", "холостой ход при ω_max", "t_idle"),
    "cycle_phase": _t("T_ц", r"$T_ц$", "s", "the whole cycle", "весь цикл", "T_c"),
    "phase_time": _t("t", "$t$", "s", "time", "время"),
    "phase_angle_deg": _t("Δφ", r"$\Delta\varphi$", "deg", "angle of the flywheel shaft",
                          "угол поворота вала маховика"),
    "operation_share": _t("t_оп/T_ц", r"$t_{оп}/T_ц$", "-", "share of the cycle the operation "
                          "takes", "доля цикла, занятая операцией", "t_op/T_c"),
    "operation_moment": _t("M_оп", r"$M_{оп}$", "N·m", "resisting moment during the operation "
                           "E/Δφ_op", "момент сопротивления при операции E/Δφ_оп", "M_op"),
    "revolutions_per_operation": _t("k", "$k$", "-", "revolutions per operation",
                                    "оборотов на одну операцию"),
    "operations_per_hour": _t("z", "$z$", "1/h", "operations per hour", "операций в час"),
    "operations_per_minute": _t("z", "$z$", "1/min", "operations per minute",
                                "операций в минуту"),
    "flywheel_energy": _t("½J(ω_max² − ω_min²) − ΔE", "", "J",
                          "flywheel: ½J(ω_max² − ω_min²) = ΔE",
                          "маховик: ½J(ω_max² − ω_min²) = ΔE"),
    "operation_energy_balance": _t("E − P·t_оп − ΔT", "", "J",
                                   "operation: E = P·t_op + ½J(ω_max² − ω_min²)",
                                   "операция: E = P·t_оп + ½J(ω_max² − ω_min²)"),
    "recovery_energy_balance": _t("P·t_вос − ΔT", "", "J",
                                  "recovery: P·t_rec = ½J(ω_max² − ω_min²)",
                                  "восстановление: P·t_вос = ½J(ω_max² − ω_min²)"),
    "cycle_energy_balance": _t("P·(t_оп + t_вос) − E", "", "J",
                               "cycle: P·(t_op + t_rec) = E", "цикл: P·(t_оп + t_вос) = E"),
    "cycle_time_balance": _t("t_оп + t_вос + t_х − T_ц", "", "s",
                             "cycle: t_op + t_rec + t_idle = T_c",
                             "цикл: t_оп + t_вос + t_х = T_ц"),
    "recovery_time_two_ways": _t("J(ω_max − ω_min)/M_Д − t_вос", "", "s",
                                 "recovery time: J(ω_max − ω_min)/M_D = Δφ_rec/ω_m",
                                 "время восстановления: J(ω_max − ω_min)/M_Д = Δφ_вос/ω_ср"),
    # force analysis ---------------------------------------------------------------------------
    # (issue 12; docs/forces.md, docs/results.md). {x} in a reaction's name is its key
    # "<point>:<i>-><j>": the force of link i on link j at the point (the frame is "0"); in a
    # slider-crank quantity's, the slider.
    "Rx_{point}": _t("R_x", "$R_x$", "N", "reaction {x}: x component",
                     "реакция в кинематической паре {x}: проекция на ось x"),
    "Ry_{point}": _t("R_y", "$R_y$", "N", "reaction {x}: y component",
                     "реакция в кинематической паре {x}: проекция на ось y"),
    "R_{point}": _t("R", "$R$", "N", "reaction {x}: magnitude",
                    "реакция в кинематической паре {x}: модуль"),
    "reaction": _t("R_ij", "$R_{ij}$", "N", "reaction in a joint (force of link i on link j)",
                   "реакция в кинематической паре (сила действия звена i на звено j)"),
    "M_y": _t("M_у", r"$M_у$", "N·m", "balancing moment M_y (kinetostatics)",
              "уравновешивающий момент M_у (кинетостатика)", "M_y"),
    "M_y_zhukovsky": _t("M_у", r"$M_у$", "N·m", "balancing moment M_y by Zhukovsky's lever",
                        "уравновешивающий момент M_у по рычагу Жуковского", "M_y"),
    "M_y_power": _t("M_у", r"$M_у$", "N·m", "balancing moment M_y by the power balance",
                    "уравновешивающий момент M_у из баланса мощностей", "M_y"),
    "balancing_moment_closure": _t("max|M_у − M_Д|/|M_Д|", r"$\max|M_у - M_Д|/|M_Д|$", "-",
                                   "closure of the force analysis with the dynamics, "
                                   "max|M_y − M_D|/|M_D| (true motion)",
                                   "сходимость силового расчёта с динамикой, "
                                   "max|M_у − M_Д|/|M_Д| (истинное движение)",
                                   "max|M_y − M_D|/|M_D|"),
    "piston_effort": _t("F_P", "$F_P$", "N", "piston effort (towards the crank axis)",
                        "движущая сила на поршне (к оси кривошипа)"),
    "side_thrust": _t("F_N", "$F_N$", "N", "side thrust on the cylinder wall",
                      "боковое давление на стенку цилиндра"),
    "rod_thrust": _t("F_Q", "$F_Q$", "N", "thrust along the connecting rod (compression positive)",
                     "усилие вдоль шатуна (сжатие положительно)"),
    "crank_pin_tangential": _t("F_T", "$F_T$", "N", "crank-pin effort, tangential (drives positive)",
                               "тангенциальная сила на шатунной шейке (движущая положительна)"),
    "crank_pin_radial": _t("F_R", "$F_R$", "N", "crank-pin effort, radial (towards the shaft)",
                           "радиальная сила на шатунной шейке (к оси вала)"),
    "turning_moment": _t("T", "$T$", "N·m", "turning moment on the crank",
                         "крутящий момент на кривошипе"),
    "piston_effort_{link}": _t("F_P", "$F_P$", "N", "piston effort, slider {x}",
                               "движущая сила на поршне {x}"),
    "side_thrust_{link}": _t("F_N", "$F_N$", "N", "side thrust on the cylinder wall, slider {x}",
                             "боковое давление на стенку цилиндра, ползун {x}"),
    "rod_thrust_{link}": _t("F_Q", "$F_Q$", "N", "thrust along the connecting rod, slider {x}",
                            "усилие вдоль шатуна, ползун {x}"),
    "crank_pin_tangential_{link}": _t("F_T", "$F_T$", "N",
                                      "crank-pin effort, tangential, from the rod of slider {x}",
                                      "тангенциальная сила на шатунной шейке от шатуна ползуна {x}"),
    "crank_pin_radial_{link}": _t("F_R", "$F_R$", "N",
                                  "crank-pin effort, radial, from the rod of slider {x}",
                                  "радиальная сила на шатунной шейке от шатуна ползуна {x}"),
    "turning_moment_{link}": _t("T", "$T$", "N·m", "turning moment from the rod of slider {x}",
                                "крутящий момент на кривошипе от шатуна ползуна {x}"),
    "crank_pin_Fx": _t("P_x", "$P_x$", "N", "load on the crank pin: x component",
                       "нагрузка на шатунную шейку: проекция на ось x"),
    "crank_pin_Fy": _t("P_y", "$P_y$", "N", "load on the crank pin: y component",
                       "нагрузка на шатунную шейку: проекция на ось y"),
    "crank_pin_F": _t("P", "$P$", "N", "load on the crank pin", "нагрузка на шатунную шейку"),
    "main_bearing_Fx": _t("R_10x", "$R_{10x}$", "N", "load on the main bearing: x component",
                          "нагрузка на коренной подшипник: проекция на ось x"),
    "main_bearing_Fy": _t("R_10y", "$R_{10y}$", "N", "load on the main bearing: y component",
                          "нагрузка на коренной подшипник: проекция на ось y"),
    "main_bearing_F": _t("R_10", "$R_{10}$", "N", "load on the main bearing",
                         "нагрузка на коренной подшипник"),
    "shaking_Fx": _t("Φ_x", r"$\Phi_x$", "N", "shaking force on the frame: x component",
                     "сила, действующая на стойку (фундамент): проекция на ось x"),
    "shaking_Fy": _t("Φ_y", r"$\Phi_y$", "N", "shaking force on the frame: y component",
                     "сила, действующая на стойку (фундамент): проекция на ось y"),
    "shaking_F": _t("Φ", r"$\Phi$", "N", "shaking force on the frame",
                    "сила, действующая на стойку (фундамент)"),
    "shaking_M": _t("M_Φ", r"$M_\Phi$", "N·m", "shaking moment on the frame (about the crank axis, ccw)",
                    "момент, действующий на стойку (относительно оси кривошипа, против часовой)"),
    # the records of summary.json's force analysis (results.force_analysis, at[].…)
    "force_analysis": _t("", "", "-", "force analysis (kinetostatics)",
                         "силовой расчёт (кинетостатика)"),
    "joints": _t("R_ij", r"$R_{ij}$", "N", "reactions in the kinematic pairs",
                 "реакции в кинематических парах"),
    "slider_crank": _t("", "", "-", "slider-crank quantities", "величины кривошипно-ползунной группы"),
    "crank_pin_load": _t("R_A", "$R_A$", "N", "load on the crank pin", "нагрузка на шатунную шейку"),
    "main_bearing_load": _t("R_O", "$R_O$", "N", "load on the main bearing",
                            "нагрузка на коренной подшипник"),
    "shaking_force": _t("F_ст", r"$F_{ст}$", "N", "shaking force on the frame",
                        "неуравновешенная сила на стойку", "F_sh"),
    "shaking_moment": _t("M_ст", r"$M_{ст}$", "N·m", "shaking moment on the frame",
                         "неуравновешенный момент на стойку", "M_sh"),
    # end force analysis -----------------------------------------------------------------------
    # --- flywheel ---  (the designed rim, [flywheel.rim]: results.flywheel_rim)
    "D_mean": _t("D_ср", r"$D_{ср}$", "m", "mean diameter of the rim", "средний диаметр обода",
                 "D_m", "$D_m$"),
    "thickness": _t("t", "$t$", "m", "radial thickness of the rim", "толщина обода"),
    "width": _t("b", "$b$", "m", "width of the rim", "ширина обода"),
    "stress": _t("σ", r"$\sigma$", "Pa", "hoop stress of the rim ρ·v²",
                 "напряжение в ободе ρ·v²"),
    "share": _t("k_об", r"$k_{об}$", "-", "share of J carried by the rim", "доля J на ободе",
                "k_rim", r"$k_{rim}$"),
    "flywheel_rim_design": _t("", "", "", "the rim as designed", "спроектированный обод"),
    "flywheel_given": _t("", "", "", "the flywheel is given (not sized)",
                         "маховик задан (не подбирается)"),
    "J_flywheel_given": _t("J_М", "$J_М$", "kg·m²", "the given flywheel's J on its shaft",
                           "заданный момент инерции маховика на его валу", "J_M", "$J_M$"),
    "delta_given": _t("δ", r"$\delta$", "-", "δ the given flywheel gives",
                      "δ при заданном маховике"),
    "power": _t("P", "$P$", "W", "mean power at ω_m (given)", "средняя мощность при ω_ср (задана)"),
    "power_moment": _t("P/ω_m", r"$P/\omega_m$", "N·m", "mean moment P/ω_m of the given power",
                       "средний момент P/ω_ср по заданной мощности", "P/ω_m", r"$P/\omega_m$"),
    "epsilon_max": _t("ε_max", r"$\varepsilon_{max}$", "rad/s²", "largest ε over the cycle",
                      "наибольшее ε за цикл"),
    "epsilon_min": _t("ε_min", r"$\varepsilon_{min}$", "rad/s²", "smallest ε over the cycle",
                      "наименьшее ε за цикл"),
    "phi_epsilon_max_deg": _t("φ", r"$\varphi$", "deg", "φ of ε_max", "φ при ε_max"),
    "phi_epsilon_min_deg": _t("φ", r"$\varphi$", "deg", "φ of ε_min", "φ при ε_min"),
    "power_from_loads": _t("P", "$P$", "W", "power of the loads |M|·ω_m",
                           "мощность нагрузок |M|·ω_ср"),
    # --- plans ---
    # (issue 12 item 6; docs/forces.md "The plans"): the scales of the drawn plans and the
    # plans' names; plots/plan_*.png
    "mu_v": _t("μ_v", r"$\mu_v$", "(m/s)/mm", "scale of the velocity plan",
               "масштаб плана скоростей"),
    "mu_a": _t("μ_a", r"$\mu_a$", "(m/s²)/mm", "scale of the acceleration plan",
               "масштаб плана ускорений"),
    "mu_F": _t("μ_F", r"$\mu_F$", "N/mm", "scale of the force plan", "масштаб плана сил"),
    "velocity_plan": _t("", "", "", "velocity plan", "план скоростей"),
    "acceleration_plan": _t("", "", "", "acceleration plan", "план ускорений"),
    "force_polygon": _t("", "", "", "force polygons of the Assur groups", "планы сил групп Ассура"),
    "zhukovsky_lever": _t("", "", "", "Zhukovsky's lever", "рычаг Жуковского"),
    "positions_plan": _t("", "", "", "the mechanism in its standard positions",
                         "план положений механизма"),
    "plan_length": _t("", "", "mm", "length on the drawing", "длина на чертеже"),
    # --- end plans ---
    # --- nom: task2 and aggregate (were render/nomenclature_ci.py), the engine's and the force
    # analysis's plot labels (were inline in render/plots_engine.py, render/plots_forces.py).
    # Names may be templates with {fields} (name(key, lang, **fields) fills them); text handed
    # to rich in a table title keeps its square brackets escaped (\\[). Keys the table above
    # already had for another meaning carry the prefix t2_ (task 2's row labels).
    # -- quantities of task 2 ----------------------------------------------------------------
    "t2_J": _ci("J", "kg·m²", "J (reduced inertia)", "J_пр (приведённый момент инерции)", "J_пр"),
    "omega0": _ci("ω0", "rad/s", "ω0 (at φ = 0)", "ω0 (при φ = 0)"),
    "t2_omega_mean": _ci("ω_ср", "rad/s", "ω_ср = (ω_max + ω_min)/2", "ω_ср = (ω_max + ω_min)/2"),
    "t2_delta": _ci("δ", "", "δ = (ω_max − ω_min)/ω_ср",
                      "δ = (ω_max − ω_min)/ω_ср, коэффициент неравномерности"),
    "t2_delta_T_max": _ci("ΔT_нб", "J", "ΔT_нб = A_max − A_min", "ΔT_нб = A_max − A_min"),
    "t2_P": _ci("P", "W", "power = mean M_D · ω_ср", "мощность = среднее M_Д · ω_ср"),
    "t2_J_required": _ci("J", "kg·m²", "J for δ = {delta}", "J_пр для δ = {delta}", "J_пр"),
    "t2_J_required_how": _ci("", "", "ΔT_нб/(δ·ω_ср²)", "ΔT_нб/(δ·ω_ср²)"),
    "rim_mass": _ci("m", "kg", "rim mass at R = {R} m", "масса обода при R = {R} м"),
    "rim_mass_how": _ci("", "", "m = J/R²", "m = J_пр/R²"),
    "t2_M_D": _ci("M_D", "N·m", "M_D", "M_Д", "M_Д"),
    "t2_M_C": _ci("M_C", "N·m", "M_C", "M_С", "M_С"),
    "t2_A": _ci("A", "J", "A", "A"),
    "t2_omega": _ci("ω", "rad/s", "ω", "ω"),
    "t2_phi_deg": _ci("φ°", "deg", "φ°", "φ°"),
    "phi_pi": _ci("φ/π", "", "φ/π", "φ/π"),
    "rpm": _ci("n", "rpm", "{n} rpm", "{n} об/мин"),
    "rpm_at": _ci("", "", "{n} rpm at {angle}", "{n} об/мин при {angle}"),
    "angle": _ci("φ", "deg", "φ = {deg}° ({pi}π rad)", "φ = {deg}° ({pi}π рад)"),
    "angle_unknown": _ci("", "", "(angle not given)", "(угол не задан)"),
    # --- flywheel (task2's designed rim; were in render/nomenclature_ci.py) ---
    "rim_design": _ci("", "", "rim (share {share} of J, b/t = {ratio})",
                      "обод (доля {share} от J_пр, b/t = {ratio})"),
    "rim_design_dims": _ci("", "m", "D_mean = {D}, t = {t}, b = {b} m; m = {m} kg",
                           "D_ср = {D}, t = {t}, b = {b} м; m = {m} кг"),
    "rim_design_how": _ci("", "", "v = {v} m/s ({src}), σ = ρ·v² = {sigma} MPa; m = share·J/R²",
                          "v = {v} м/с ({src}), σ = ρ·v² = {sigma} МПа; m = доля·J_пр/R²"),
    "rim_from_stress": _ci("", "", "from σ_allow", "по σ_доп"),
    "rim_from_given": _ci("", "", "given", "задана"),
    # -- task 2: headings and sentences -------------------------------------------------------
    "t2_seed_title": _ci("", "", "«Задача 2», {profile} resistance moment",
                           "Задача 2, момент сопротивления — {profile}"),
    "t2_seed_source": _ci("", "", "textbook task «Задача 2» (steady motion under given moment "
                            "graphs, table 27)", "задача «Задача 2» (установившееся движение "
                            "при заданных графиках моментов, табл. 27)"),
    "triangle": _ci("", "", "triangle", "треугольник"),
    "rectangle": _ci("", "", "rectangle", "прямоугольник"),
    "t2_balance": _ci("", "", "cycle balance ∮M_D dφ = ∮M_C dφ gives {name} = {value} N·m "
                                "(work per cycle {work} J)",
                        "баланс работ за цикл ∮M_Д dφ = ∮M_С dφ даёт {name} = {value} Н·м "
                        "(работа за цикл {work} Дж)"),
    "t2_given": _ci("", "", "M_D = {M_D} N·m, M_C = {M_C} N·m (given)",
                      "M_Д = {M_D} Н·м, M_С = {M_C} Н·м (заданы)"),
    "t2_unsteady": _ci("", "", "[yellow]the motion is not steady:[/yellow] the work over the cycle "
                                 "is {work} J, so ω after one cycle is {omega_end} rad/s "
                                 "(ω0 = {omega0} rad/s)",
                         "[yellow]движение не установившееся:[/yellow] работа за цикл {work} Дж, "
                         "поэтому ω в конце цикла {omega_end} рад/с (ω0 = {omega0} рад/с)"),
    "t2_segments": _ci("", "", "Segments: ½·J·(ω² − ω0²) = A(φ) = ∫(M_D − M_C) dφ\n"
                                 "φ \\[deg], M \\[N·m], A \\[J], ω \\[rad/s]",
                         "Участки: ½·J_пр·(ω² − ω0²) = A(φ) = ∫(M_Д − M_С) dφ\n"
                         "φ, °; M, Н·м; A, Дж; ω, рад/с"),
    "point": _ci("", "", "point", "точка"),
    "crossing_MD_MC": _ci("", "", "M_D = M_C", "M_Д = M_С"),
    "crossing": _ci("", "", "crossing", "пересечение"),
    "bound": _ci("", "", "bound", "граница"),
    "results": _ci("", "", "Results", "Результаты"),
    "quantity": _ci("", "", "quantity", "величина"),
    "value": _ci("", "", "value", "значение"),
    "unit": _ci("", "", "unit", "ед."),
    # -- task 2: angular acceleration and time (shown with --epsilon or --at) -------------------
    "t2_motion": _ci("", "", "Acceleration and time: ε(φ) = (M_D − M_C)/J, t(φ) = ∫₀^φ dφ/ω",
                       "Угловое ускорение и время: ε(φ) = (M_Д − M_С)/J_пр, t(φ) = ∫₀^φ dφ/ω"),
    "t2_epsilon": _ci("ε", "rad/s²", "ε", "ε"),
    "t2_epsilon_max": _ci("ε_max", "rad/s²", "ε_max (largest over the cycle)",
                         "ε_max (наибольшее за цикл)"),
    "t2_epsilon_min": _ci("ε_min", "rad/s²", "ε_min (smallest over the cycle)",
                         "ε_min (наименьшее за цикл)"),
    "t2_cycle_time": _ci("T_ц", "s", "cycle time ∫₀^Φ dφ/ω", "время цикла ∫₀^Φ dφ/ω"),
    "t2_energy_fluctuation_coefficient": _ci("C_E", "", "C_E = ΔT_нб / work per cycle",
                                               "C_E = ΔT_нб / работа за цикл"),
    "at_angle": _ci("", "", "at {angle}", "при {angle}"),
    "t2_phases": _ci("", "", "Phases between the extremes of ω (crossings and jumps of M_D − M_C)",
                       "Участки между экстремумами ω (пересечения и скачки M_Д − M_С)"),
    "phi_from": _ci("φ", "deg", "from φ°", "от φ°"),
    "phi_to": _ci("φ", "deg", "to φ°", "до φ°"),
    "trend": _ci("", "", "speed", "скорость"),
    "trend_up": _ci("", "", "rises (M_D > M_C)", "растёт (M_Д > M_С)"),
    "trend_down": _ci("", "", "falls (M_D < M_C)", "падает (M_Д < M_С)"),
    "trend_steady": _ci("", "", "constant (M_D = M_C)", "постоянна (M_Д = M_С)"),
    "t_start": _ci("t", "s", "t at start \\[s]", "t в начале \\[с]"),
    "duration": _ci("Δt", "s", "duration \\[s]", "длительность \\[с]"),
    "t2_at": _ci("", "", "At the asked angles", "В заданных положениях"),
    "t2_t": _ci("t", "s", "t \\[s]", "t \\[с]"),
    "phi_col": _ci("φ", "deg", "φ°", "φ°"),
    "omega_col": _ci("ω", "rad/s", "ω \\[rad/s]", "ω, рад/с"),
    "epsilon_col": _ci("ε", "rad/s²", "ε \\[rad/s²]", "ε \\[рад/с²]"),
    "t2_flywheel_mass": _ci("m", "kg", "mass at k = {k} m", "масса при k = {k} м"),
    "flywheel_mass_how": _ci("", "", "m = J/k²", "m = J_пр/k²"),
    "t2_power": _ci("", "", "mean power P = {P} W at ω_ср: mean {name} = P/ω_ср = {T} N·m",
                      "средняя мощность P = {P} Вт при ω_ср: среднее {name} = P/ω_ср = {T} Н·м"),
    # -- task 2: the plot ----------------------------------------------------------------------
    "t2_plot_epsilon": _ci("ε", "rad/s²", "ε(φ) = (M_D − M_C)/J", "ε(φ) = (M_Д − M_С)/J_пр"),
    "t2_plot_epsilon_axis": _ci("ε", "rad/s²", "ε [rad/s²]", "ε, рад/с²"),
    "t2_plot_epsilon_max": _ci("ε_max", "rad/s²", "ε_max = {value} rad/s² at {deg}°",
                                 "ε_max = {value} рад/с² при {deg}°"),
    "t2_plot_epsilon_min": _ci("ε_min", "rad/s²", "ε_min = {value} rad/s² at {deg}°",
                                 "ε_min = {value} рад/с² при {deg}°"),
    "t2_plot_MD": _ci("M_D", "N·m", "M_D (driving)", "M_Д (движущий)", "M_Д"),
    "t2_plot_MC": _ci("M_C", "N·m", "M_C (resistance)", "M_С (сопротивления)", "M_С"),
    "t2_plot_moment": _ci("M", "N·m", "moment [N·m]", "момент, Н·м"),
    "t2_plot_A": _ci("A", "J", "A(φ) = ∫(M_D − M_C) dφ", "A(φ) = ∫(M_Д − M_С) dφ"),
    "t2_plot_A_axis": _ci("A", "J", "A [J]", "A, Дж"),
    "t2_plot_omega": _ci("ω", "rad/s", "ω(φ)", "ω(φ)"),
    "t2_plot_A_areas": _ci("", "", "energy at the crossings", "энергия в точках пересечения"),
    "t2_plot_omega_areas": _ci("", "", "ω at the crossings", "ω в точках пересечения"),
    "t2_plot_omega_mean": _ci("ω_ср", "rad/s", "ω_ср", "ω_ср"),
    "t2_plot_omega_axis": _ci("ω", "rad/s", "ω [rad/s]", "ω, рад/с"),
    "t2_plot_phi_axis": _ci("φ", "deg", "φ [deg]", "φ, °"),
    "t2_plot_crossing_no": _ci("", "", "crossing number", "номер пересечения"),
    "t2_plot_title": _ci("", "", "task 2: δ = {delta}, ΔT_нб = {dT} J",
                           "задача 2: δ = {delta}, ΔT_нб = {dT} Дж"),
    "plot_written": _ci("", "", "plot written to {path}", "график записан в {path}"),
    # -- aggregate: the model ------------------------------------------------------------------
    "ag_rotors": _ci("", "", "Rotors reduced to shaft I (J·u², u = ω/ω_I)",
                       "Массы, приведённые к валу I (J·u², u = ω/ω_I)"),
    "rotor": _ci("", "", "rotor", "масса"),
    "J_reduced": _ci("J", "kg·m²", "J_reduced [kg·m²]", "J_пр, кг·м²", "J_пр"),
    "u": _ci("u", "", "u", "u"),
    "ag_connections": _ci("", "", "Connections reduced to shaft I (c·u²)",
                            "Упругие связи, приведённые к валу I (c·u²)"),
    "between": _ci("", "", "between", "между"),
    "c": _ci("c", "N·m/rad", "c [N·m/rad]", "жёсткость c, Н·м/рад"),
    "damping": _ci("b", "N·m·s/rad", "damping [N·m·s/rad]", "демпфирование, Н·м·с/рад"),
    "rotor_motor": _ci("", "", "motor J_Д", "двигатель J_Д"),
    "rotor_machine": _ci("", "", "machine J_пр.I", "машина J_пр.I"),
    "ag_equations": _ci("", "", "Equations (9.24): Σ_j a_ij·q̈_j + Σ_j c_ij·q_j = Q_i, "
                                  "q1 = φ1, q_(k+1) = φ_(k+1) − φ_k",
                          "Уравнения (9.24): Σ_j a_ij·q̈_j + Σ_j c_ij·q_j = Q_i, обобщённые "
                          "координаты q1 = φ1, q_(k+1) = φ_(k+1) − φ_k"),
    "a_ij": _ci("a_ij", "kg·m²", "inertia coefficients a_ij", "инерционные коэффициенты a_ij"),
    "c_ij": _ci("c_ij", "N·m/rad", "stiffness coefficients c_ij", "коэффициенты жёсткости c_ij"),
    "matrix_j": _ci("", "", "j = {j}", "j = {j}"),
    "matrix_i": _ci("", "", "i = {i}", "i = {i}"),
    "ag_equations_fixed": _ci("", "", "Equations: Σ_j a_ij·φ̈_j + Σ_j c_ij·φ_j = 0 in the rotors' "
                                        "absolute angles (a shaft fixed to the frame: no rigid "
                                        "rotation; a = M, c = K)",
                                "Уравнения: Σ_j a_ij·φ̈_j + Σ_j c_ij·φ_j = 0 в абсолютных углах масс "
                                "(вал заделан в стойку: вращения как твёрдого тела нет; a = M, c = K)"),
    "ag_equations_tree": _ci("", "", "Equations (9.24): Σ_j a_ij·q̈_j + Σ_j c_ij·q_j = Q_i, "
                                       "q1 = φ of the first rotor, q_(k+1) = φ_to − φ_from of shaft k",
                               "Уравнения (9.24): Σ_j a_ij·q̈_j + Σ_j c_ij·q_j = Q_i, обобщённые "
                               "координаты q1 = φ первой массы, q_(k+1) = φ_to − φ_from вала k"),
    "frame": _ci("", "", "frame", "стойка"),
    # -- aggregate: modes, nodes and shafts (shown with --modes) -------------------------------
    "ag_mode_nodes": _ci("", "", "Modes: frequencies and nodes (points that stand still)",
                           "Формы колебаний: частоты и узлы (неподвижные точки)"),
    "rpm_col": _ci("n", "rpm", "n [vib/min]", "n [кол/мин]"),
    "nodes": _ci("", "", "nodes", "узлы"),
    "node_shaft": _ci("", "", "shaft {a}–{b}: {dist}{frac} % of its compliance from {a}",
                        "вал {a}–{b}: {dist}{frac} % податливости от {a}"),
    "node_dist": _ci("", "m", "{d} m from {a}, ", "{d} м от {a}, "),
    "node_rotor": _ci("", "", "rotor {name} stands still", "масса {name} неподвижна"),
    "node_frame": _ci("", "", "the fixed end {name}", "заделка {name}"),
    "ag_shafts": _ci("", "", "Shafts: stiffness and equivalent length (uniform shaft of the first "
                               "piece's diameter)",
                       "Валы: жёсткость и приведённая длина (гладкий вал диаметра первого участка)"),
    "gear_ratio": _ci("i", "", "gear i", "передача i"),
    "c_input": _ci("c", "N·m/rad", "c (input side) [N·m/rad]", "c (со стороны входа), Н·м/рад"),
    "length": _ci("L", "m", "length [m]", "длина [м]"),
    "equivalent_length": _ci("L_eq", "m", "L_eq [m]", "L_прив [м]"),
    "d_ref": _ci("d", "m", "at d [m]", "при d [м]"),
    # -- aggregate: natural frequencies, resonance -----------------------------------------------
    "ag_modes": _ci("", "", "Natural frequencies (K·x = ω²·M·x)",
                      "Собственные частоты (K·x = ω²·M·x)"),
    "mode": _ci("", "", "mode", "№ формы"),
    "omega_n": _ci("ω", "rad/s", "ω [rad/s]", "ω, рад/с"),
    "f_n": _ci("f", "Hz", "f [Hz]", "f, Гц"),
    "shape": _ci("", "", "shape (φ, largest = 1)", "форма колебаний (φ, наибольшая = 1)"),
    "rigid_body": _ci("", "", "rigid body", "твёрдое тело"),
    "ag_no_motor": _ci("", "", "no [motor]: natural frequencies only",
                         "нет [motor]: только собственные частоты"),
    "ag_forcing": _ci("", "", "forcing ω_III = {w} rad/s ({f} Hz) at the steady speed "
                                "ω_I = {omega} rad/s ({n} rev/min)",
                        "вынуждающая частота ω_III = {w} рад/с ({f} Гц) при установившейся скорости "
                        "ω_I = {omega} рад/с ({n} об/мин)"),
    "ag_resonance": _ci("", "", "Resonance margins", "Отстройка от резонанса"),
    "f_n_col": _ci("f_n", "Hz", "f_n [Hz]", "f_n, Гц"),
    "ratio": _ci("", "", "ω_forcing/ω_n", "ω_вын/ω_n"),
    "margin": _ci("", "", "margin |1 − ω_f/ω_n|", "отстройка |1 − ω_вын/ω_n|"),
    # -- aggregate: steady state and start-up ------------------------------------------------------
    "ag_steady": _ci("", "", "Steady state (closed form; solve_ivp check on the periodic orbit)",
                       "Установившийся режим (точное решение; проверка solve_ivp на периодической "
                       "траектории)"),
    "solve_ivp": _ci("", "", "solve_ivp", "solve_ivp"),
    "twist_mean": _ci("q2", "rad", "twist q2 = φ2 − φ1, mean",
                        "угол закручивания q2 = φ2 − φ1, среднее"),
    "twist_amp": _ci("q2", "rad", "twist q2, amplitude", "угол закручивания q2, амплитуда"),
    "moment_mean": _ci("M_у", "N·m", "elastic moment c·(φ1 − φ2) = −c·q2, mean",
                         "упругий момент c·(φ1 − φ2) = −c·q2, среднее"),
    "moment_amp": _ci("M_у", "N·m", "elastic moment −c·q2, amplitude",
                        "упругий момент −c·q2, амплитуда"),
    "omega_motor": _ci("ω1", "rad/s", "ω1 (motor) min … max", "ω1 (двигатель) min … max"),
    "delta_motor": _ci("δ", "", "δ motor", "δ двигателя"),
    "omega_machine": _ci("ω2", "rad/s", "ω2 (machine, own shaft) min … max",
                           "ω2 (машина, на своём валу) min … max"),
    "delta_machine": _ci("δ", "", "δ machine", "δ машины"),
    "startup_peak": _ci("", "N·m", "start-up: peak elastic moment",
                          "пуск: наибольший упругий момент"),
    "startup_over": _ci("", "s", "over {t} s", "за {t} с"),
    "startup_time": _ci("t", "s", "start-up: time to 95 % of ω1", "пуск: время до 95 % ω1"),
    "note": _ci("", "", "note: {note}", "примечание: {note}"),
    "note_radau": _ci("", "", "solve_ivp check: 5 forcing periods are {fast:.4g} periods of the "
                                "highest natural frequency {f_top:.6g} Hz, more than the explicit "
                                "method's {limit}: integrated with the implicit Radau method and the "
                                "constant Jacobian, which follows the forced motion but damps that "
                                "mode's own oscillation",
                        "проверка solve_ivp: 5 периодов возмущения — это {fast:.4g} периодов высшей "
                        "собственной частоты {f_top:.6g} Гц, больше предела явного метода ({limit}): "
                        "интегрирование неявным методом Radau с постоянной матрицей Якоби, который "
                        "следует вынужденному движению, но гасит собственные колебания этой формы"),
    "note_cap_linear": _ci("", "", "start-up: integrated over {t_end:.4g} s = {limit} periods of the "
                                     "highest natural frequency {f_top:.6g} Hz (the cap), not the "
                                     "default {wanted:.4g} s (the longer of five time constants and 20 "
                                     "forcing periods); --t-end sets the duration",
                             "пуск: проинтегрирован за {t_end:.4g} с = {limit} периодов высшей "
                             "собственной частоты {f_top:.6g} Гц (предел), а не {wanted:.4g} с по "
                             "умолчанию (большее из пяти постоянных времени и 20 периодов "
                             "возмущения); длительность задаёт --t-end"),
    "note_cap_constant": _ci("", "", "start-up: integrated over {t_end:.4g} s = {limit} periods of "
                                       "the highest natural frequency {f_top:.6g} Hz (the cap), not the "
                                       "default {wanted:.4g} s (20 forcing periods); --t-end sets the "
                                       "duration",
                               "пуск: проинтегрирован за {t_end:.4g} с = {limit} периодов высшей "
                               "собственной частоты {f_top:.6g} Гц (предел), а не {wanted:.4g} с по "
                               "умолчанию (20 периодов возмущения); длительность задаёт --t-end"),
    # -- aggregate: the plot ---------------------------------------------------------------------
    "ag_plot_startup": _ci("", "", "start-up", "пуск"),
    "ag_plot_steady": _ci("", "", "steady state", "установившийся режим"),
    "ag_plot_omega1": _ci("ω1", "rad/s", "ω1, {name}", "ω1, {name}"),
    "ag_plot_omegaN": _ci("ω", "rad/s", "ω{n}, {name} (reduced to shaft I)",
                            "ω{n}, {name} (приведена к валу I)"),
    "ag_plot_omega_axis": _ci("ω", "rad/s", "ω [rad/s]", "ω, рад/с"),
    "ag_plot_moment": _ci("M_у", "N·m", "elastic moment c·(φ1 − φ2) = −c·q2",
                            "упругий момент c·(φ1 − φ2) = −c·q2"),
    "ag_plot_moment_axis": _ci("M", "N·m", "moment [N·m]", "момент, Н·м"),
    "ag_plot_t_axis": _ci("t", "s", "t [s]", "t, с"),
    "ag_plot_title": _ci("", "", "machine aggregate", "машинный агрегат"),
    # -- the four-stroke indicator diagram (render/plots_engine.py) ---------------------------
    "engine_intake": _ci("", "", "intake", "впуск"),
    "engine_compression": _ci("", "", "compression", "сжатие"),
    "engine_expansion": _ci("", "", "expansion", "расширение"),
    "engine_exhaust": _ci("", "", "exhaust", "выпуск"),
    "engine_table": _ci("", "", "{k}: table", "{k}: таблица"),
    "engine_s_axis": _ci("s", "", "relative piston travel s from the head",
                         "относительное перемещение поршня s от головки"),
    "engine_p_axis": _ci("p/p_max", "", "p / p_max", "p / p_max"),
    "engine_p_MPa": _ci("p", "MPa", "p, MPa (gauge)", "p, МПа (избыточное)"),
    "engine_phi": _ci("φ", "deg", "crank angle φ [deg]", "угол поворота кривошипа φ, °"),
    "engine_title": _ci("", "", "{t}: four-stroke indicator diagram, cylinder {c}",
                        "{t}: индикаторная диаграмма четырёхтактного цилиндра {c}"),
    "engine_fires": _ci("", "deg", "fires at {a:.1f}°", "воспламенение при {a:.1f}°"),
    # -- the force analysis's plots (render/plots_forces.py) ------------------------------------
    "forces_plot_reactions": _ci("", "", r"reactions in the joints $|R_{ij}|(\varphi)$, $R_{ij}$: the "
                                 "force of link i on link j",
                                 r"реакции в кинематических парах $|R_{ij}|(\varphi)$, $R_{ij}$ — "
                                 "сила действия звена i на звено j"),
    "forces_plot_moment": _ci("", "", r"balancing moment on the crank $M_y(\varphi)$, three ways",
                              r"уравновешивающий момент на кривошипе $M_у(\varphi)$, три способа"),
    "forces_plot_moment_steady": _ci("", "", r"balancing moment on the crank $M_y(\varphi)$, "
                                     "steady motion $\\omega$ = {w:.5g} rad/s",
                                     r"уравновешивающий момент на кривошипе $M_у(\varphi)$, "
                                     "равномерное вращение ω = {w:.5g} рад/с"),
    "forces_plot_M_const": _ci("", "", "{s} = {v:.6g} {u} (constant, from the cycle balance)",
                               "{s} = {v:.6g} {u} (постоянный, из условия цикла)"),
    "forces_plot_hodographs": _ci("", "", "polar diagrams (hodographs) of the loads over the cycle",
                                  "полярные диаграммы (годографы) нагрузок за цикл"),
    "forces_plot_pin": _ci("", "", "load on the crank pin, in the crank's axes",
                           "нагрузка на шатунную шейку в осях кривошипа"),
    "forces_plot_bearing": _ci("", "", r"load on the main bearing $R_{10}$",
                               r"нагрузка на коренной подшипник $R_{10}$"),
    "forces_plot_shaking": _ci("", "", "shaking force on the frame", "сила, действующая на стойку"),
    "forces_plot_curve": _ci("", "", "over the cycle, labels: φ [deg]", "за цикл, подписи: φ, °"),
    "forces_plot_origin": _ci("", "", "origin (zero force)", "начало координат (нулевая сила)"),
    # --- mut ---
    "note_lsoda": _ci("", "", "start-up: stiff (the fastest decay rate of the system {rho:.4g} 1/s, "
                              "from the motor's slope or a damper): integrated with LSODA and the "
                              "constant Jacobian, steps of at most 1/8 of the period of the highest "
                              "natural frequency {f_top:.6g} Hz",
                      "пуск: жёсткая система (наибольшая скорость затухания {rho:.4g} 1/с — от "
                      "наклона характеристики двигателя или демпфера): интегрирование методом "
                      "LSODA с постоянной матрицей Якоби, шаг не больше 1/8 периода высшей "
                      "собственной частоты {f_top:.6g} Гц"),
}

# the load names inside "M {load}": "gas HP", "gravity 2", "force punch", "couple c", "moment m"
LOAD_KINDS = {"gas": ("gas {x}", "газ {x}"), "gravity": ("gravity, link {x}", "сила тяжести звена {x}"),
              "force": ("force {x}", "сила {x}"), "couple": ("couple {x}", "пара сил {x}"),
              "moment": ("moment {x}", "момент {x}")}

# the sliders' dead centres in the standard positions' labels ("90° = 5 outer d.c."), as
# dynamics.grid.standard_positions writes them in English
DEAD_CENTRES = {"outer": ("outer", "внешняя"), "inner": ("inner", "внутренняя")}
DEAD_CENTRE_LABEL = ("{s} {kind} d.c.", "ползун {s}: {kind} мёртвая точка")

# the flywheel's materials (case [flywheel] material)
MATERIALS = {"steel": ("steel", "сталь"), "cast-iron": ("cast iron", "чугун")}

# -- units ----------------------------------------------------------------------------------------
_UNIT_RU = {"m": "м", "kg": "кг", "s": "с", "rad": "рад", "N": "Н", "J": "Дж", "Pa": "Па",
            "MPa": "МПа", "W": "Вт", "kW": "кВт", "deg": "°", "rpm": "об/мин", "min": "мин",
            "Hz": "Гц", "h": "ч", "rev": "об", "mm": "мм"}
_UNIT_EN_PRINT = {"deg": "°"}


def unit(u: str, lang: str = "en") -> str:
    """The unit as printed in ``lang``: SI tokens translated ("kg·m²/rad" → "кг·м²/рад"),
    "-" (dimensionless) as "–", degrees as "°"; "" (a record, a text) stays ""."""
    if u == "-":
        return "–"
    table = _UNIT_RU if lang == "ru" else _UNIT_EN_PRINT
    return re.sub(r"[A-Za-z]+", lambda m: table.get(m.group(0), m.group(0)), u)


# -- lookup ---------------------------------------------------------------------------------------
_FAMILIES = [(re.compile("^" + re.escape(k).replace(r"\{", "{").replace(r"\}", "}")
                         .replace("{point}", "(?P<x>.+)").replace("{link}", "(?P<x>.+)")
                         .replace("{cylinder}", "(?P<x>.+)").replace("{load}", "(?P<x>.+)")
                         + "$"), k) for k in TERMS if "{" in k]


def term(key: str) -> tuple[Term, str]:
    """(the term, the family member) of a concrete key: "J_II" → (J_II, ""), "x_B" → (x_{point},
    "B"), "M gas HP" → (M {load}, "gas HP"). KeyError if the table has no such quantity."""
    if key in TERMS:
        return TERMS[key], ""
    for rx, k in _FAMILIES:
        m = rx.match(key)
        if m:
            return TERMS[k], m.group("x")
    raise KeyError(f"{key!r} is not in the nomenclature (render/nomenclature.py)")


def load_name(x: str, lang: str = "en") -> str:
    """A load's name in ``lang``: "gas HP" → "газ HP", "gravity 2" → "gravity, link 2"; a name
    of no known kind as it is.

    >>> load_name("gravity 2", "ru")
    'сила тяжести звена 2'
    """
    kind, _, rest = x.partition(" ")
    if kind in LOAD_KINDS and rest:
        return LOAD_KINDS[kind][lang == "ru"].format(x=rest)
    return x


def member(key: str, lang: str = "en") -> str:
    """The family member of ``key`` in ``lang`` ("M gas HP" → "газ HP", "x_B" → "B"; "" for a
    key that is not a family's)."""
    return load_name(term(key)[1], lang)


def name(key: str, lang: str = "en", **fields) -> str:
    """The quantity's name in ``lang`` ("reduced moment: gas HP"); a template's ``{fields}``
    filled from ``fields`` (none given: the name as it is).

    >>> name("t2_balance", "ru", name="M_С", value="60", work="94.2478")
    'баланс работ за цикл ∮M_Д dφ = ∮M_С dφ даёт M_С = 60 Н·м (работа за цикл 94.2478 Дж)'
    >>> name("omega_max"), name("t2_J", "ru")
    ('ω_max', 'J_пр (приведённый момент инерции)')
    """
    t, x = term(key)
    template = t.ru if lang == "ru" else t.en
    if x:
        fields = {"x": load_name(x, lang), **fields}
    return template.format(**fields) if fields else template


def rotor_name(rotor: str, lang: str = "en") -> str:
    """A rotor's name in ``lang`` (`flywheel aggregate`): the two-mass model's own names
    translate, a user's stay."""
    if lang != "ru":
        return rotor
    for key in ("rotor_motor", "rotor_machine"):
        if rotor == TERMS[key].en:
            return TERMS[key].ru
    return rotor


def symbol(key: str, lang: str = "en") -> str:
    """The plain-text symbol in ``lang`` (ω_m in English, ω_ср in Russian)."""
    return term(key)[0].sym(lang)


def tex(key: str, lang: str = "en") -> str:
    """The mathtext symbol in ``lang``, for plots ("$\\omega_m$" in English, "$\\omega_{ср}$" in
    Russian)."""
    return term(key)[0].tex(lang)


def unit_of(key: str, lang: str = "en") -> str:
    """The unit of ``key`` as printed in ``lang``."""
    return unit(term(key)[0].unit, lang)


def si_unit(key: str) -> str:
    """The unit of ``key`` as CSV headers and JSON write it (SI, English): "kg·m²"."""
    return term(key)[0].unit


def with_unit(label: str, u: str, lang: str = "en") -> str:
    """A figure's label and its unit in the figures' one style per language: Russian as the
    course writes it, "ω, рад/с"; English as the text tables and CSV headers do, "ω [rad/s]"
    (tests/test_nomenclature.py holds every figure to it); ``u`` as printed in ``lang`` already."""
    if lang == "ru":
        return f"{label}, {u}"
    return f"{label} [{'deg' if u == '°' else u}]"


def axis(key: str, lang: str = "en", si: str | None = None) -> str:
    """A plot axis label as the course writes it: mathtext symbol, comma, unit ("$J_{II}$, кг·м²");
    ``si`` another unit of the same quantity ("MPa" for a pressure drawn in MPa)."""
    return with_unit(tex(key, lang), unit(si or si_unit(key), lang), lang)


def heading(key: str, lang: str = "en", si: str | None = None, label: str | None = None) -> str:
    """A column heading of a text table (the summary, the report, `flywheel check`): the
    symbol and its unit, "J_II [kg·m²]" in English (the unit as the CSV headers write it),
    "J_II, кг·м²" in Russian (the course's style); a dimensionless quantity by its symbol
    alone. ``si``: another unit of the same quantity; ``label``: another text than the symbol
    (a load's name: "gas HP [N·m]").

    >>> heading("omega", "en"), heading("omega", "ru"), heading("M gas HP", "ru", label="газ HP")
    ('ω [rad/s]', 'ω, рад/с', 'газ HP, Н·м')
    """
    u = si or si_unit(key)
    sym = symbol(key, lang) if label is None else label
    if u in ("-", ""):
        return sym
    return f"{sym}, {unit(u, lang)}" if lang == "ru" else f"{sym} [{u}]"


def legend(key: str, lang: str = "en") -> str:
    """A legend entry: the mathtext symbol and the name without its trailing symbol
    ("$A_D$: work of the driving forces")."""
    t, _ = term(key)
    nm = name(key, lang)
    sym = t.sym(lang)
    if sym and nm.endswith(" " + sym):
        nm = nm[: -len(sym) - 1]
    return f"{t.tex(lang)}: {nm}"


def name_tex(key: str, lang: str = "en") -> str:
    """The name with its trailing plain symbol typeset (a figure's title: "reduced moment of
    inertia of the second group $J_{II}$")."""
    t, _ = term(key)
    nm = name(key, lang)
    sym = t.sym(lang)
    if sym and nm.endswith(" " + sym):
        return nm[: -len(sym)] + t.tex(lang)
    return nm


def material(m: str, lang: str = "en") -> str:
    """A flywheel material's name in ``lang`` ("cast-iron" → "cast iron", "чугун")."""
    return MATERIALS[m][lang == "ru"] if m in MATERIALS else m


def position_label(position, lang: str = "en") -> str:
    """A standard position's label in ``lang`` (a :class:`flywheel.dynamics.results.Position`):
    "0° = 3 outer d.c." → "0° = ползун 3: внешняя мёртвая точка"; the angle, a table's
    "2 (30°)" as they are.

    >>> from flywheel.dynamics.results import DeadCentre, Position
    >>> position_label(Position(phi=1.5708, standard_deg=90, dead_centres=(DeadCentre("5", "inner"),)), "ru")
    '90° = ползун 5: внутренняя мёртвая точка'
    """
    return " = ".join(p if isinstance(p, str) else DEAD_CENTRE_LABEL[lang == "ru"].format(
        s=p.slider, kind=DEAD_CENTRES[p.kind][lang == "ru"]) for p in position.parts())


def csv_header(key: str) -> str:
    """A CSV column header: ``name [unit]`` with the SI unit ("J_II [kg·m²]")."""
    return f"{key} [{si_unit(key)}]"


# --- report: messages ---
# The warnings and notes of the computation (errors.Notice: the English text with a code and
# its parameters) in Russian, and the CLI's line prefixes. English is the Notice's own text.
MESSAGES_RU = {
    "no_net_work": ("нагрузки не совершают работы за цикл: уравновешивающий момент равен 0 "
                    "(маховик лишь сглаживает периодическую часть нагрузок)"),
    "forces_massless": ("силовой анализ: ни у одного звена нет массы или J_S, поэтому реакции "
                        "создают одни заданные силы (сил инерции нет)"),
    "tabulated_negative_J": ("таблица: интерполяция ({kind}) доли звена {link} в J_II опускается "
                             "ниже нуля ({J:.3g} кг·м² при φ = {phi_deg:.1f}°): задайте больше "
                             "положений вблизи этого угла"),
    "cylinder_negative_p": ("цилиндр {cylinder}: интерполяция ({kind}) его индикаторной таблицы "
                            "даёт отрицательное давление, до {p:.4g} МПа при φ = {phi_deg:.1f}° "
                            "(интерполяция 'pchip' не даёт выбросов)"),
    "startup_stall": ("разгон: двигатель не может разогнать машину, она останавливается при "
                      "φ = {phi_deg:.1f}°"),
    "startup_not_steady": ("разгон: установившийся режим не достигнут за {cycles_ru} "
                           "({t:.4g} с); средняя скорость последнего цикла {omega:.5g} рад/с, "
                           "установившаяся скорость по характеристике двигателя {target}"),
    "duty_motor_alone": ("двигатель один даёт операции её энергию (P·t_оп ≥ E): маховик не "
                         "отдаёт ничего, ΔE = 0"),
    "duty_motor_idles": ("двигатель сильнее, чем нужно операциям: он работает {t_work:.6g} с "
                         "из каждого цикла {t_cycle:.6g} с и {t_idle:.6g} с идёт вхолостую при "
                         "ω_max (его момент там принят равным нулю)"),
    "power_mismatch": ("machine.power: P = {power:.6g} Вт при ω_ср = {omega:.6g} рад/с означает "
                       "средний момент P/ω_ср = {M_power:.6g} Н·м, но нагрузки случая "
                       "уравновешиваются моментом {M_loads:.6g} Н·м ({P_loads:.6g} Вт, "
                       "{pct:+.3g} %): проверьте нагрузки или мощность"),
    "duty_delta_large": "δ = {delta:.4g}: скорость колеблется больше чем на 30 % от средней",
    "crank_short": ("crank.length: {length:g} м — необычно короткий кривошип (кривошипы: "
                    "5 мм … 2 м); длины задаются в метрах"),
    "delta_unusual": ("machine.delta: δ = {delta:g} вне обычных 1/300 … 1/5 ({lo:.4f} … "
                      "{hi:.1f}; по таблице Артоболевского: прессы 1/5 … 1/20, двигатели "
                      "1/80 … 1/150, генераторы 1/200 … 1/300)"),
    "rpm_unusual": ("machine: частота вращения кривошипа {rpm:.6g} об/мин вне обычных 1 … "
                    "20 000 об/мин"),
    "cylinder_vacuum": ("{where}: p/p_max опускается до {low:g} ({p:.4g} МПа избыточного, "
                        "разрежение): таблицы задают избыточное давление в долях p_max; "
                        "проверьте знак"),
    "no_flywheel_needed": ("первая группа уже имеет {J_first:.6g} кг·м² ≥ J_I = "
                           "{J_required:.6g} кг·м²: маховик не нужен"),
    "rim_speed": ("маховик в виде {shape_ru}: окружная скорость {v:.1f} м/с больше допускаемой "
                  "{limit:.1f} м/с = √(σ/ρ) тонкого вращающегося кольца (окружное напряжение "
                  "σ = ρ·v², Тимошенко, «Сопротивление материалов», ч. II) для материала "
                  "{material_ru}: σ = {sigma:g} МПа, ρ = {rho:g} кг/м³ (задайте "
                  "flywheel.allowable_stress или более широкий маховик: width_ratio)"),
    "out_kept": "{target}: оставлены файлы, изменённые вами после прошлого запуска: {files}",
    "out_removed": ("{target}: удалены файлы прошлого запуска, которые этот запуск не пишет "
                    "({n}): {files_ru}"),
}
#: the CLI's line prefixes ("warning: …") and its last line ("written: DIR/ (…)")
PREFIXES = {"warning": ("warning", "предупреждение"), "note": ("note", "примечание"),
            "written": ("written", "записано")}


#: functions (code, params) -> params that add the Russian words a block's templates need;
#: each block of templates below appends its own (the order they are appended is the order run)
_PARAM_HOOKS: list = []


def _ru_params(code: str, p: dict) -> dict:
    """Parameters of a Notice that need words of their own in Russian."""
    p = _msgs2_ru_params(code, _msgs_ru_params(p))
    for hook in _PARAM_HOOKS:
        p = hook(code, p)
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


def message(text: str, lang: str = "en") -> str:
    """A warning or note in ``lang``: a Notice (errors.Notice) with a Russian template is said
    in Russian, anything else (English, or a plain string) as it is.

    >>> from flywheel.errors import Notice
    >>> message(Notice("δ = 0.5: the speed swings by more than 30 % of the mean",
    ...                "duty_delta_large", delta=0.5), "ru")
    'δ = 0.5: скорость колеблется больше чем на 30 % от средней'
    """
    code = getattr(text, "code", "")
    if lang != "ru" or code not in MESSAGES_RU:
        return str(text)
    lead = getattr(text, "lead", "").replace(": (top level): ", ": (верхний уровень): ")
    return lead + MESSAGES_RU[code].format(**_ru_params(code, text.params))


def prefix(key: str, lang: str = "en") -> str:
    """A CLI line prefix ("warning", "note", "written") in ``lang``."""
    return PREFIXES[key][lang == "ru"]


# --- msgs ---
# The errors of a user's input (cli/guard.py's `error:` line) in Russian: a FlywheelError or a
# schema error raised with an errors.Notice says it in the user's --lang. Rare errors stay English.
PREFIXES["error"] = ("error", "ошибка")
#: what a file was expected to be (io/toml.py's "is a folder, expected …")
_FILE_KINDS_RU = {"a TOML case file": "файл случая TOML", "a TOML template": "шаблон TOML"}
#: the case kinds (cases/__init__.py NAMES) for "this is …, not …"
_CASE_KINDS_RU = {"run": "случай для flywheel run",
                  "task2": "случай задачи 2 (заданные графики моментов)",
                  "aggregate": "случай агрегата (упругие муфты)",
                  "variants": "шаблон вариантов",
                  "duty_cycle": "случай рабочего цикла (пресс, клёпальная машина, ножницы)"}
MESSAGES_RU.update({
    # io/toml.py
    "no_such_file": "{path}: нет такого файла",
    "is_a_folder": "{path}: это папка, а нужен {what_ru}",
    "not_utf8": "{path}: текст не в кодировке UTF-8 ({reason} в байте {byte})",
    "toml_syntax": "{path}: синтаксическая ошибка TOML: {detail_ru}",
    # cases/__init__.py
    "wrong_kind": "{source}: это {kind_ru}, а не {expected_ru}: используйте `{command}`",
    # io/schema.py: the field path is the Notice's lead
    "missing": "не задано обязательное поле",
    "unknown_key": "неизвестный ключ{hint_ru} (допустимы: {allowed})",
    "out_of_range": "{x:g}{unit_ru} вне допустимого диапазона ({lo:g} … {hi:g}{unit_ru})",
    "not_a_table": "должно быть таблицей ключей, например {{ ключ = значение, … }}{got_ru}",
    "not_finite_number": "должно быть конечным числом{got_ru}",
    "pydantic_float_type": "должно быть числом{got_ru}",
    "pydantic_int_type": "должно быть целым числом{got_ru}",
    "pydantic_int_from_float": "должно быть целым числом, а не дробным{got_ru}",
    "pydantic_string_type": "должно быть строкой{got_ru}",
    "pydantic_bool_type": "должно быть логическим значением (true или false){got_ru}",
    "pydantic_list_type": "должно быть списком [ … ]{got_ru}",
    "pydantic_tuple_type": "должно быть списком [ … ]{got_ru}",
    "pydantic_greater_than": "должно быть больше {gt:g}{got_ru}",
    "pydantic_greater_than_equal": "должно быть не меньше {ge:g}{got_ru}",
    "pydantic_less_than": "должно быть меньше {lt:g}{got_ru}",
    "pydantic_less_than_equal": "должно быть не больше {le:g}{got_ru}",
    "pydantic_literal_error": "должно быть одним из: {expected}{got_ru}",
    "pydantic_too_short": ("слишком мало элементов: нужно не меньше {min_length}, задано "
                           "{actual_length}"),
    "pydantic_too_long": ("слишком много элементов: допустимо не больше {max_length}, задано "
                          "{actual_length}"),
    # cases/run.py
    "cycle_not_whole": ("{cycle:g}° — не целое число оборотов (допустимо: 360, 720, 1080 … "
                        "{top}°)"),
    # linkage/solve.py: the group, what would assemble it
    "dyad_rrr": "группа {name} (RRR, звенья {a}–{b})",
    "dyad_in_line": "{what_ru} (звенья на одной прямой: мёртвое положение)",
    "dyad_rrp": "группа {name} (RRP, шатун {rod})",
    "dyad_rrp_perpendicular": "группа {name} (RRP, шатун {rod} перпендикулярен направляющей)",
    "dyad_rpr": "группа {name} (RPR, кулиса {rocker})",
    "cannot_assemble": "{what_ru} не собирается при угле кривошипа φ = {deg:.2f}°",
    "cannot_assemble_need": "{what_ru} не собирается при угле кривошипа φ = {deg:.2f}°: {need_ru}",
    "need_base": "{a} и {b} совпадают: у группы нет базы (переместите опору)",
    "need_in_line": ("расстояние {a}–{b} достигает {edge} м: звенья ложатся на одну прямую "
                     "(мёртвое положение; измените длину так, чтобы расстояние оставалось "
                     "строго между {lo:.6g} и {hi:.6g} м)"),
    "need_reach": ("расстояние {a}–{b} меняется в пределах {dmin:.6g} … {dmax:.6g} м, а звенья "
                   "({la:.6g} и {lb:.6g} м) достают лишь {lo:.6g} … {hi:.6g} м"),
    "need_rod": ("шатун ({rod_length:.6g} м) должен быть не короче {reach:.6g} м — наибольшего "
                 "расстояния точки {origin} от направляющей за цикл"),
    "need_rod_dead": ("мёртвое положение: сделайте шатун длиннее наибольшего расстояния точки "
                      "{origin} от направляющей"),
    "need_offset": ("смещение линии ползуна ({offset:.6g} м) должно быть меньше расстояния "
                    "{pivot}–{origin}, которое падает до {dmin:.6g} м"),
    "singular_rpr": ("{what_ru} имеет особое положение вблизи угла кривошипа φ = {deg:.2f}°: "
                     "{origin} проходит через опору кулисы {pivot}, где направление кулисы не "
                     "определено (сместите {pivot} с траектории {origin} или измените смещение "
                     "линии ползуна)"),
    # teaching/variants.py
    "checked_as": "{detail_ru} [проверено как {as_kind_ru}]",
    "template_not_analysed": "{source}: сам шаблон не удаётся рассчитать: {detail_ru}",
    # io/output.py
    "out_is_a_file": "--out {target}: {file} — это файл, а не папка",
    "out_not_ours": ("--out {target}: папка существует, не пуста и записана не командой flywheel "
                     "(нет {manifest}); укажите новую или пустую папку (в папке, записанной "
                     "flywheel, повторный запуск заменяет только свои файлы)"),
    # the command-line options
    "points_range": ("--points: {n} вне допустимого диапазона (допустимо: 36 … {top}; результаты "
                     "сходятся гораздо раньше: {default} по умолчанию отличается от сетки в 4 раза "
                     "мельче не более чем на 1e-4)"),
    "option_not_finite": "{option} должно быть конечным числом (задано {got})",
    "option_not_positive": "{option} должно быть положительным (задано {v:g} {unit_ru})",
    "option_delta": "--delta должно лежать между 0 и 2 (задано {delta:g})",
    "option_from_to": "--from ({start:g}°) должно быть меньше --to ({end:g}°)",
    # teaching/grading.py: a sheet's problems ("file, row 3: …"), the grade command
    "sheet_problem": "{where_ru}: {detail_ru}",
    "sheet_bad_bom": "начинается с метки порядка байтов {enc}, но не является текстом {enc}",
    "sheet_binary": "двоичные данные, а не текстовый файл CSV",
    "sheet_no_encoding": ("двоичные данные, а не текстовый файл CSV (не подходит ни одна "
                          "кодировка: UTF-8, UTF-16, cp1251, cp866, koi8-r)"),
    "sheet_too_large": ("{mb:.0f} МБ — слишком большой файл для листа ответов (допустимо: до "
                        "{top:.0f} МБ)"),
    "sheet_folder_empty": "папка без файлов *.csv",
    "sheet_missing": "нет такого файла или папки",
    "sheet_unreadable": "не удаётся прочитать ({reason})",
    "sheet_empty": "пустой файл (ожидается заголовок student,variant,…)",
    "sheet_not_csv": "не читается как файл CSV ({detail})",
    "sheet_no_column": ("нет столбца {columns} (заголовок должен быть student,variant,<ответы…>; "
                        "задано {header})"),
    "sheet_unknown_columns": ("столбцы {columns} не являются ответами ключа (пропущены; ответы: "
                              "{answers})"),
    "sheet_absent_columns": "нет столбца для {columns}: эти ответы считаются не данными",
    "row_no_student": "нет имени студента; строка пропущена",
    "row_variant": "{student!r}: {what_variant} (допустимы: {allowed}); строка пропущена",
    "row_not_a_number": "{student!r}: не число: {bad}; строка пропущена",
    "row_again": ("{student!r} встречается снова (впервые: {file}, строка {row}): засчитана "
                  "более поздняя строка, ранняя не проверяется"),
    "run_rows_reached": ("не проверено: за один запуск проверено уже {top} строк студентов "
                         "(проверяйте листы по частям)"),
    "run_rows_cut": ("эта строка и {n} после неё не проверены: не больше {top} строк студентов "
                     "за один запуск (проверяйте листы по частям)"),
    "nothing_graded": "нечего проверить (замечаний: {n}; первое: {detail_ru})",
    # teaching/variants.py, teaching/sheets.py
    "variants_repeat": ("различных вариантов возможно лишь {possible}; запрошено {count}, поэтому "
                        "некоторые повторяются"),
    "sheet_no_drawing_tabulated": ("кинематика задана таблицей ([tabulated]): на листе задания "
                                   "нет чертежа механизма"),
    "sheet_no_drawing_areas": ("задача задана диаграммой площадей, а не графиками моментов: на "
                               "листе задания нет чертежа"),
    # --transients (dynamics/stages.py, timedomain.py): why there is no start-up or run-down
    "startup_no_motor": ("в задании нет раздела [motor]: при постоянном движущем моменте работа "
                         "за цикл равна нулю при любой скорости, установившегося режима разгона "
                         "нет"),
    "rundown_no_work": ("работа нагрузок за цикл равна нулю, без привода машина "
                        "продолжает вращаться"),
    "rundown_positive_work": ("нагрузки совершают за цикл положительную работу ({work:+.3g} Дж: "
                              "они движут машину, как газ в двигателе), без постоянного "
                              "сопротивления машина разгоняется"),
    # the command-line options (cli/guard.py choice, needs_out; cli/*.py)
    "option_choice": "{option}: {got} — недопустимое значение (допустимы: {allowed})",
    "option_not_allowed": "{option}: {got} — недопустимое значение (допустимо: {allowed})",
    "option_range": "{option}: {got} вне допустимого диапазона (допустимо: {lo} … {hi})",
    "option_not_positive_number": "{option}: должно быть положительным числом (задано {got})",
    "report_needs_out": "--report пишет в папку вывода: укажите также --out DIR",
    # dynamics/stages.py: the cycle balance; constant_inertia/solve.py: a speed that falls to 0
    "balance_driving": ("нагрузки совершают за цикл работу {work:+.6g} Дж: постоянный движущий "
                        "момент должен был бы быть {M:.6g} Н·м ≤ 0 (допустимо: силы сопротивления "
                        "должны поглощать работу; для двигателя задайте machine.balance = "
                        "\"resistance\")"),
    "balance_resistance": ("нагрузки совершают за цикл работу {work:+.6g} Дж: постоянный момент "
                           "сопротивления должен был бы быть {M:.6g} Н·м ≤ 0 (допустимо: движущие "
                           "силы должны совершать работу; для компрессора или пресса задайте "
                           "machine.balance = \"driving\")"),
    "machine_stops": ("машина останавливается {where_ru}: кинетической энергии ½·J·ω0² = "
                      "{T0:.6g} Дж не хватает, чтобы покрыть недостаток работы {deficit:.6g} Дж"),
    # cases/run.py: the checks across tables
    "crank_or_tabulated": ("задайте что-то одно: [crank] (механизм) или [tabulated] (кинематика "
                           "таблицей)"),
    "delta_and_given_flywheel": ("задайте что-то одно: machine.delta (маховик подбирается под "
                                 "него) или заданный маховик (flywheel.J, mass с "
                                 "radius_of_gyration, given_disk или given_rim), но не оба"),
    "delta_missing": ("не задано: укажите machine.delta (маховик подбирается под него) или "
                      "заданный маховик (flywheel.J, mass с radius_of_gyration, given_disk или "
                      "given_rim)"),
    "motor_too_slow": "{n0:g} об/мин — не больше средней скорости {n:g} об/мин",
    # teaching (the template's and the key's numbers), cases/task2.py
    "not_positive_number": "должно быть положительным числом{got_ru}",
    "not_positive_relative": "должно быть положительным числом, относительным{got_ru}",
    "delta_0_2": "должно лежать между 0 и 2 (задано {delta:g})",
})
_MSGS_DERIVED = {"where_ru", "what_variant", "detail_ru", "as_kind_ru", "what_ru", "need_ru", "kind_ru", "expected_ru", "hint_ru", "unit_ru", "got_ru"}


def _msgs_ru_params(p: dict) -> dict:
    """The Russian words of an error's parameters: a parameter that is itself a Notice (the
    group in "… cannot be assembled") said in Russian, the kinds of file and case, the unit."""
    p = dict(p)
    for k in ("what", "need", "detail"):
        if k in p:
            p[k + "_ru"] = message(p[k], "ru")
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


# --- msgs2 ---
# The cross-field checks of the case files (cases/*.py), the duty cycle's limits, in Russian.
MESSAGES_RU.update({
    # cases/run.py
    "speed_rps_or_rpm": "задайте что-то одно: speed_rps или speed_rpm",
    "point_to_or_distance": "задайте что-то одно: `to` (с fraction) или `distance` (с angle_deg)",
    "link_mass_centroid": "у звена с массой должен быть задан `centroid`",
    "strictly_increasing": "значения должны строго возрастать",
    "values_per_s": "нужно {n_values_ru}, по одному на каждое s (задано {count})",
    "strokes_do_not_meet": ("начинается с p/p_max = {p_begin:g} при s = {at:g}, где {end} "
                            "кончается на {p_end:g}: такты не смыкаются (скачок {jump:.4g}; "
                            "допустимо: не больше join_tolerance = {tol:g}; подъём при вспышке "
                            "задаётся в таблице расширения, сразу после s = 0)"),
    "rim_inner_above_outer": "{inner:g} м — не меньше D = {D:g} м",
    "rim_share_twice": ("при [flywheel.rim] доля задаётся как flywheel.rim.share (укажите её "
                        "там)"),
    "given_flywheel_forms": ("заданный маховик — что-то одно из: J, mass с radius_of_gyration, "
                             "given_disk, given_rim (задано {forms})"),
    "mass_radius_missing": "не задано: mass и radius_of_gyration задаются вместе (J = m·k²)",
    "crank_length_missing": "не задано: укажите crank.length или design.mean_piston_speed",
    "point_twice": "имя точки {name!r} уже занято",
    "link_twice": "имя звена {name!r} уже занято",
    "point_used_before": "точка {name!r} используется раньше, чем задана (заданы: {so_far})",
    "link_not_defined": "звено {name!r} не задано (звенья: {links})",
    "point_never_defined": "точка {name!r} нигде не задана",
    "no_link_named": "нет звена {name!r} (звенья: {links})",
    "point_not_defined": "точка {name!r} не задана",
    "not_a_slider_of": "{name!r} — не ползун группы RRP (ползуны: {sliders_ru})",
    "pressure_above_p_max": ("p/p_max = {high:g} больше 1: p_max = {p_max:g} Па — наибольшее "
                             "давление диаграммы (допустимо: −0.101325 МПа/p_max … 1; чтобы "
                             "поднять выше, увеличьте p_max)"),
    "pressure_below_vacuum": ("p/p_max = {low:g} даёт {mpa:.4g} МПа избыточного давления, ниже "
                              "абсолютного вакуума (допустимо: p ≥ −0.101325 МПа избыточного)"),
    "not_a_slider": "{name!r} — не ползун группы RRP",
    "s_range": "должно быть 0 ≤ from < to ≤ 1 (задано {lo}, {hi})",
    "no_link": "нет звена {name!r}",
    "load_twice": "имя нагрузки {name!r} встречается дважды",
    "pin_twice": ("{angle:g}° ставит шейку {pin!r} туда, где уже {whom_ru} {name!r} (тот же "
                  "угол и радиус): шейки под одним углом — одна шейка с одним именем (допустимо: "
                  "присоедините шатуны к {name!r} или задайте другой угол)"),
    "four_stroke_cycle": ("четырёхтактная диаграмма занимает 720° угла кривошипа, а цикл машины "
                          "— {cycle:g}° (допустимо: machine.cycle_deg = 720 или кратное 720)"),
    "firing_order_missing": ("нет цилиндра {name!r} (порядок работы перечисляет каждый "
                             "четырёхтактный цилиндр один раз: {four})"),
    "dyad_kind": "kind должно быть одним из: RRP, RRR, RPR",
    # cases/rim.py
    "rim_share": "{share:g} — не доля J маховика (допустимо: 0 < share ≤ 1)",
    "rim_width_or_ratio": "задайте что-то одно: width или width_to_thickness",
    "rim_speed_stress": ("{speed:g} м/с даёт окружное напряжение ρ·v² = {stress:.6g} МПа больше "
                         "допускаемого {allowable:.6g} МПа ({material_ru}, ρ = {density:g} "
                         "кг/м³) при любом диаметре (допустимо: не больше √(σ/ρ) = {top:.6g} "
                         "м/с)"),
    # cases/task2.py
    "amount_word": "должно быть числом, \"balance\" или \"power\" (задано {value})",
    "must_be_positive": "должно быть положительным (задано {v:g}{unit_sp_ru})",
    "task2_speed_one_of": ("задайте что-то одно: omega0, omega0_rpm, mean, mean_rpm или пределы "
                           "max и min (или max_rpm и min_rpm){given_ru}"),
    "task2_J_or_mass": "задайте что-то одно: J или mass с radius_of_gyration",
    "mass_radius_together": "mass и radius_of_gyration задаются вместе (J = m·k²)",
    "task2_delta_or_percent": "задайте что-то одно: delta или fluctuation_percent",
    "diagram_or_graphs": "задайте что-то одно: [diagram] или [driving] и [resistance]",
    "balance_once": ("\"balance\" может заменять лишь одно значение (другое уже задано так: "
                     "{other})"),
    "points_go_back": "угол {at:g}° идёт после {before:g}°: углы не должны убывать",
    "points_third_value": ("третье значение при {at:g}°: у скачка их два (значение до и значение "
                           "после него)"),
    "points_span": "должно охватывать цикл 0…{cycle:g}° (охвачено {first:g}…{last:g}°)",
    "from_to_deg": "нужно 0 ≤ from_deg < to_deg ≤ {cycle:g} (задано {start:g}, {end:g})",
    "trapezoid_top": "нужно from_deg ≤ top_from_deg ≤ top_to_deg ≤ to_deg",
    "orders_for_terms": "задано порядков гармоник: {orders}, а членов ряда: {terms}",
    "areas_do_not_close": ("сумма {total:.6g}, а не 0: за цикл площади над средней линией и под "
                           "ней должны быть равны"),
    # cases/tabulated.py
    "positions_increase": "{at:g}° после {before:g}°: положения должны возрастать",
    "values_per_position": ("нужно {n_values_ru}, по одному на каждое положение positions_deg "
                            "(задано {count})"),
    "analogues_missing": ("аналогов скоростей точки {name!r} нет в [tabulated.points] (строки: "
                          "{rows})"),
    # cases/aggregate.py
    "coupling_c_or_dL": "задайте что-то одно: c или d и L (с G)",
    "shaft_G": ("не задано: с d и L нужен модуль сдвига G (например, 8.0e10 Па для стали)"),
    "motor_J_missing": "не задано обязательное поле (J_Д, момент инерции ротора двигателя, кг·м²)",
    "motor_torque_one_of": ("задайте что-то одно: starting_torque или rated_torque с "
                            "rated_slip"),
    "chain_or_two_mass": ("случай — либо двухмассовый агрегат ([coupling], [machine]), либо "
                          "цепочка ([[rotors]], [[shafts]]), но не то и другое"),
    "two_mass_needs": "не задано: двухмассовому агрегату нужны [motor], [coupling] и [machine]",
    "J_III_missing": ("не задано: укажите J_III (J_пр.III, кг·м²) или J_III_0 с "
                      "J_III_positions"),
    "i21_missing": "не задано: маховику на валу II нужно i21 = ω_II/ω_I",
    "fixed_end_shafts": ("не задано: неподвижный конец rotors[{k}] связан валом с ротором; "
                         "задайте [[shafts]] (N роторам нужно N − 1 валов)"),
    "aggregate_form": ("не задано: задайте двухмассовый агрегат ([motor], [coupling], [machine]) "
                       "или цепочку ([[rotors]] и [[shafts]])"),
    "two_rotors": "цепочке нужно не меньше двух роторов (задано {count})",
    "shafts_count": "роторов: {rotors}, поэтому валов между ними нужно {shafts_ru} (задано {count})",
    "rotor_names": "имена роторов должны различаться",
    "load_needs_motor": "не задано: для [load] нужен [motor] на первом роторе",
    # cases/duty_cycle.py, duty_cycle/solve.py
    "duty_out_of_range": ("{x:g}{unit_ru} вне допустимого диапазона{why_ru} (допустимо: {left} "
                          "значение {right}{unit_ru})"),
    "speed_not_below": "{v:g} — не меньше {other} = {vo:g} (допустимо: {allowed})",
    "duty_flywheel_small": ("маховик слишком мал: чтобы отдать {need:.6g} Дж (ΔE) на каждую "
                            "операцию, его скорость упала бы до нуля ({energy} = не больше "
                            "{top:.6g} Дж); возьмите маховик больше"),
})
MESSAGES_RU.update({
    # the non-finite policy (cli/guard.py not_finite; constant_inertia/solve.py's details)
    "not_finite": ("{who_ru}{quantity_ru} — не конечное число ({detail_ru}): значения выходят за "
                   "пределы двойной точности (числа слишком велики или слишком малы)"),
    "nf_power_moment": "средняя мощность даёт {which_ru} {x} Н·м",
    "nf_balance_moment": "баланс работ за цикл даёт {which_ru} {x} Н·м",
    "nf_work": "работа A(φ) = {x} Дж",
    # the command-line options
    "at_not_finite": "--at: {a} — не конечный угол в градусах",
    "t_end_range": ("--t-end: {t:g} с вне допустимого диапазона (допустимо: 0 … {top:g} с; разгон "
                    "длится от секунд до минуты, а время интегрирования растёт вместе с ним)"),
    "too_many_steps": ("{cause}{task_ru} потребовал бы около {steps:.3g} шагов интегрирования "
                       "({t_end:.4g} с; наибольшая скорость процессов системы {rate:.4g} 1/с), "
                       "больше предела {top}: {fix_ru}"),
    "plot_needs_motor": "--plot требует [motor]: у цепочки без двигателя нет движения во времени",
    "plot_is_a_folder": "--plot {plot}: это папка, а нужен файл изображения",
    "plot_cannot_write": "--plot {plot}: не удаётся записать изображение ({reason_ru})",
    "case_drops_options": "--case берёт данные из файла; уберите {used}",
    "profile_choice": "--profile должно быть triangle или rectangle (задано {value})",
    "from_to_cycle": "from и to должны лежать в пределах 0…360° (задано {start:g}°, {end:g}°)",
    "points_too_few": "--points: {n} — слишком мало (допустимо: 36 и больше)",
})
MESSAGES_RU.update({
    # teaching/variants.py: the template's paths, ranges and answers
    "path_not_in": ("{name!r} нет в {here_ru} (там есть: {keys_ru}){hint_ru} — изменяемое поле "
                    "должно иметь значение в шаблоне"),
    "positive_got": "должно быть положительным{got_ru}",
    "max_below_min": "max ({hi}) меньше min ({lo})",
    "spec_not_table": ("должно быть таблицей {{ values = [...] }} или {{ min = …, max = …, "
                       "step = … }}{got_ru}"),
    "nonempty_array": "должно быть непустым списком{got_ru}",
    "answers_missing": ("не задано (ключи результатов для ключа ответов, например answers = "
                        "[\"J_required\", \"delta_T_max\"])"),
    "answers_empty": "должно быть непустым списком имён результатов{got_ru}",
    "not_an_answer": "не является одним из ответов (допустимы: {allowed})",
    "not_a_result": "{name!r} {what_ru} (числовые результаты: {names}){hint_ru}",
    "no_variants_table": ("нет таблицы [variants] (в ней сказано, что менять и какие результаты "
                          "служат ответами; см. docs/teacher.md)"),
    "draws_failed": ("вариант {number}: {failed} попыток подряд не прошли проверку или расчёт; "
                     "сузьте диапазоны в [variants] (последняя ошибка: {detail_ru})"),
    # teaching/grading.py: the answer key; cli/teaching.py, io/output.py: the files written
    "key_not_object": "должно быть объектом JSON {{вариант: {{ответ: значение}}}} (задано {type})",
    "key_no_variants": "{where_ru}: должно быть непустым объектом {{вариант: {{ответ: значение}}}}",
    "key_tolerances": "должно быть объектом {{ответ: положительное число}}{got_ru}",
    "key_is_a_folder": "{path}: это папка, а нужен answers.json команды flywheel variants",
    "not_json": "{path}: не JSON: {msg} (строка {line}, столбец {col})",
    "option_is_a_folder": "{option} {path}: это папка, а нужно {expected_ru}",
    "csv_folder_missing": ("{option} {path}: папки {parent} не существует (допустимо: имя файла "
                           "CSV в существующей папке)"),
    "no_student_rows": ("{files}: нечего проверить: нет заполненных строк студентов (в строке "
                        "нужны имя студента и вариант)"),
})
MESSAGES_RU.update({
    # dynamics/sizing.py, dynamics/stages.py: the designed rim, a given flywheel, --transients
    "rim_no_hole": ("flywheel.rim: обод получается толщиной {t:.4g} м при среднем диаметре "
                    "{D:.4g} м, и отверстия не остаётся (допустимо: толщина < среднего диаметра: "
                    "больше окружная скорость обода, шире обод или меньше доля)"),
    "with_flywheel_J": "{detail_ru} (J маховика на его валу = {J:.6g} кг·м²)",
    "given_flywheel_small": ("заданный маховик (J = {J:.6g} кг·м²) слишком мал для этих "
                             "нагрузок: изменение энергии за цикл, {swing:.4g} Дж, останавливает "
                             "машину раньше, чем она наберёт среднюю скорость ω_m = {omega:.6g} "
                             "рад/с — установившегося движения нет (допустимо: J_I + J_II не "
                             "меньше примерно {need:.4g} кг·м² на валу кривошипа: больше "
                             "flywheel.J или меньше нагрузки)"),
    "startup_too_long": ("motor: разгон для --transients занял бы около {n:.3g} циклов "
                         "(ω̄·τ·(ln(50/δ) − 1)/Φ с постоянной времени τ = J̄·ω_x/M_п), больше "
                         "предела {top} циклов: двигатель (motor.starting_torque, "
                         "motor.no_load_speed_rpm) слишком слаб для этих масс; запустите без "
                         "--transients"),
    "rundown_too_long": ("выбег для --transients занял бы около {n:.3g} циклов (кинетическая "
                         "энергия ½·J·ω² на работу нагрузок за цикл, {work:.3g} Дж), больше "
                         "предела {top} циклов: нагрузки очень малы для этих масс; запустите без "
                         "--transients"),
    "animate_tabulated": ("--animate: {case} задаёт кинематику таблицей ([tabulated]): "
                          "анимировать нечего, механизма нет (допустимо: случай с [crank] и "
                          "[[dyads]])"),
    "graph_kind": "{tag_ru}{hint_ru} (допустимы: {allowed})",
})
MESSAGES_RU["firing_order_fit"] = (
    "machine.firing_order: {order} не укладывается в один цикл 720°: цилиндр {name} (позиция "
    "{position}) сработал бы при {at}, не раньше, чем цилиндр {first} сработает снова при "
    "{again} (допустимо: порядок, в котором каждый цилиндр приходит в верхнюю мёртвую точку "
    "после предыдущего, всё в пределах 720°; верхние мёртвые точки: {heads_ru})")
MESSAGES_RU.update({
    # cases/duty_cycle.py: the operation, the cycle, the flywheel
    "one_of_keys": "задайте что-то одно из: {keys}{given_ru}",
    "duty_work_one_way": ("задайте работу одним способом: energy, или energy_per_area с площадью "
                          "среза, или force (или shear_strength) с thickness и shape (задано "
                          "{given})"),
    "duty_work_missing": ("не задано: укажите работу одной операции (energy, energy_per_area с "
                          "площадью среза или force с thickness и shape) или delta_E"),
    "duty_thickness_missing": "не задано: работу определяет путь силы (толщина листа)",
    "duty_shape_missing": ("не задано: укажите, как сила меняется на пути (допустимо: constant, "
                           "falling, triangle)"),
    "duty_cycle_missing": ("не задано: укажите [cycle] (как часто) или мощность либо момент "
                           "двигателя, чтобы найти наибольший темп, который он выдержит"),
    "duty_J_or_mass": "задайте что-то одно: J или mass",
})
_MSGS2_DERIVED = {"heads_ru", "unit_sp_ru", "tag_ru", "here_ru", "keys_ru", "what_ru", "expected_ru", "who_ru", "quantity_ru", "which_ru", "task_ru", "fix_ru", "sliders_ru", "whom_ru", "material_ru", "given_ru", "shafts", "why_ru"}
_MSGS_DERIVED |= _MSGS2_DERIVED
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
                            "a file name": "имя файла"}.get(p["expected"], p["expected"])
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
MESSAGES_RU.update({
    "usage_no_such_option": "нет такого параметра: {option}{possible_ru}",
    "usage_needs_value": "параметру {option} нужно {count_ru}",
    "usage_takes_no_value": "параметр {option} не принимает значения",
    "usage_missing": "не задан {kind_ru} {name}",
    "usage_bad_value": "{hint}: должно быть {value_kind_ru}{got_ru}",
    "usage_no_such_command": "нет такой команды: {command!r}",
    "usage_extra_arguments": "лишние аргументы: {args}",
    "usage_missing_command": "не задана команда",
    "stopped_interrupted": "прервано (Ctrl-C)",
    "stopped_terminated": "остановлено (SIGTERM)",
    "internal_error": ("внутренняя ошибка flywheel {version} (ошибка программы, а не ваших "
                       "данных): {what}; пожалуйста, сообщите о ней, приложив команду и её "
                       "входные файлы{debug_ru}"),
})
_MSGS_DERIVED |= {"possible_ru", "count_ru", "kind_ru", "value_kind_ru", "debug_ru"}


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


_PARAM_HOOKS.append(_msgs_cli_ru_params)


# --- msgs_duty ---
# The duty cycle's case checks and solution (cases/duty_cycle.py, duty_cycle/solve.py), the
# variants template (teaching/variants.py) and the answer key (teaching/grading.py) in Russian.
MESSAGES_RU.update({
    # cases/duty_cycle.py: the operation
    "dc_goes_with": "задаётся только вместе с {a} или {b}",
    "dc_area_thickness": "не задано: для {key} нужна толщина листа (A = {area})",
    "dc_stroke_thickness": ("не задано: ход задаёт долю цикла t/(2·s), и для неё нужна толщина "
                            "листа t"),
    "dc_stroke_short": ("{stroke:g} м — меньше половины толщины {thickness:g} м: доля t/(2·s) "
                        "превысила бы 1 (допустимо: stroke ≥ {half:g} м)"),
    "dc_delta_E_above_E": ("{delta_E:g} Дж — больше работы операции E = {E:.6g} Дж (допустимо: "
                           "ΔE ≤ E)"),
    "dc_needs_work": ("требует работы одной операции (operation.energy, energy_per_area или "
                      "force); при одном delta_E подбирается только маховик"),
    # cases/duty_cycle.py: the flywheel and its speeds
    "dc_speed_units": "задайте скорости в одних единицах{given_ru}",
    "dc_given_one_speed": ("при заданном маховике задайте одну скорость (max, mean или min) и не "
                           "задавайте неравномерность: остальное программа найдёт сама"
                           "{given_ru}"),
    "dc_mass_radius": "нужен радиус (radius_of_gyration, rim_radius или rim_diameter): J = m·k²",
    "dc_J_radius": "при скоростях на радиусе (м/с) задайте и радиус",
    "dc_two_speeds": ("задайте две скорости (две из max, min, mean), или одну скорость и "
                      "неравномерность (percent, total_percent, delta, drop_percent), или "
                      "заданный маховик (J или mass) и одну скорость{given_ru}"),
    "dc_shaft_speed": ("нужна скорость вала: при скоростях на радиусе (м/с) задайте и радиус "
                       "маховика или задайте скорости в об/мин"),
    "dc_max_mean": ("{v:g} при {mean_key} = {mean:g} даёт min = 2·mean − max = {low:g} "
                    "(допустимо: {mean:g} < {key} < {top:g})"),
    "dc_drop_needs_max": ("это падение от наибольшей скорости: задайте его вместе с max_rpm, "
                          "max_omega или max_rim_speed"),
    "dc_double_precision": "значения слишком велики или слишком малы для двойной точности",
    "dc_result_not_finite": ("{result} — не конечное число: значения слишком велики или слишком "
                             "малы для двойной точности"),
    # duty_cycle/solve.py: the solution
    "dc_no_drop": ("пределы скорости {w1:.17g} и {w2:.17g} не дают её падения (допустимо: "
                   "ω_max > ω_min > 0)"),
    "dc_motor_weak": ("{have_ru} меньше средней мощности операций E/T_c = {need:.6g} Вт: "
                      "маховик никогда не восстановит скорость (допустимо: не меньше "
                      "{need:.6g} Вт)"),
    "dc_torque_weak": ("момент двигателя {T:.6g} Н·м меньше среднего момента операций "
                       "E/(2π·k) = {need:.6g} Н·м: маховик никогда не восстановит скорость "
                       "(допустимо: не меньше {need:.6g} Н·м)"),
    "dc_operation_too_long": ("операция длится {t_op:.6g} с — дольше цикла T_c = {Tc:.6g} с "
                              "(допустимо: не дольше цикла)"),
    # teaching/variants.py: the template's paths and ranges
    "var_not_an_index": "{array} — массив; {name!r} — не индекс (допустимо: 0…{last})",
    "var_index_range": ("в {array} элементов: {n}; индекс {i} вне допустимого диапазона "
                        "(допустимо: 0…{last})"),
    "var_inside_a_value": ("{value} — значение, а не таблица; внутри него нет ничего с именем "
                           "{name!r}"),
    "var_grid_missing": "не задано {key} (задайте min, max и step или values)",
    "var_grid_too_many": ("значений сетки {n} — слишком много (допустимо: не больше 100000; "
                          "возьмите шаг больше)"),
    "var_unknown_key": "неизвестный ключ {key!r} (допустимы: values или min, max, step)",
    "var_values_or_grid": "задайте что-то одно: values или min, max, step",
    "var_values_tables": "таблицы нельзя выбирать целиком (меняйте их поля)",
    "var_grid_needs_number": ("для min/max/step в шаблоне нужно число (там {current}); задайте "
                              "values = [...]"),
    "var_answer_twice": "{name!r} указан дважды",
    "var_answer_csv": ("{name!r} содержит символ, недопустимый в имени столбца CSV (, ; \" или "
                       "перевод строки)"),
    "var_tolerances_table": "должно быть таблицей {{ ответ = допуск }}{got_ru}",
    "var_not_a_table": "должно быть таблицей{got_ru}",
    "var_vary_variants": "нельзя менять саму таблицу [variants]",
    "var_path_is_table": "это таблица; меняйте её поля по одному",
    "var_nothing_to_vary": ("нечего менять (добавьте, например, \"machine.speed_rps\" = "
                            "{{ values = [8, 10, 12] }})"),
    "var_overlap": "пересекается с {other}",
    "var_no_new_combination": ("вариант {number}: за {draws_ru} не найдено новой "
                               "комбинации; расширьте диапазоны или запросите меньше вариантов"),
    # teaching/grading.py: the answer key, a student's number
    "grade_answers_object": "должно быть объектом {{ответ: значение}}{got_ru}",
    "grade_answers_list": "должно быть списком имён ответов{got_ru}",
    "grade_key_unreadable": "{path}: не удаётся прочитать ({reason_ru})",
    "grade_not_finite": "{value!r} — не конечное число",
})


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


_PARAM_HOOKS.append(_msgs_duty_ru_params)
_MSGS_DERIVED |= {"have_ru", "reason_ru"}


# --- msgs_tabulated ---
# The checks of a [tabulated] section (cases/tabulated.py) in Russian.
MESSAGES_RU.update({
    "tab_no_positions": ("нет положений (допустимо: {min} или больше различных углов в пределах "
                         "0 … {cycle:g})"),
    "tab_outside_cycle": "{a:g}° вне цикла (допустимо: 0 … {cycle:g}{cycle_note_ru})",
    "tab_duplicated": "угол {a:g}° повторяется (положения {i} и {j})",
    "tab_too_few": "различных положений {n} — слишком мало (допустимо: {min} или больше)",
    "tab_gap": ("положения не покрывают цикл: между {a:g}° и {b:g}° нет ни одного (промежуток "
                "{gap:g}°; допустимо: не больше {max_gap:g}° между соседними, 0 … "
                "{cycle:g}{cycle_note_ru})"),
    "tab_negative_analogue": ("{v:g} < 0: аналоги скоростей — модули |V_q| ≥ 0 (направление "
                              "задаёт angle_deg силы)"),
    "tab_not_closed": ("значение при {cycle:g}° ({last:g}) должно повторять значение при 0° "
                       "({first:g}): цикл замкнут"),
    "tab_mass_no_point": ("у звена {link} масса {mass:g} кг, но нет аналогов скоростей: задайте "
                          "point — строку [tabulated.points] (строки: {rows_ru})"),
    "tab_J_no_omega_q": ("у звена {link} J = {J:g} кг·м², но в [tabulated.omega_q] нет строки "
                         "{key!r} (строки: {rows_ru})"),
    "tab_inertia_overflow": ("m·V_q² + J·ω_q² переполняется в положении {k} ({a:g}°): значения "
                             "вне допустимого диапазона (допустимо: единицы СИ, м и кг·м²)"),
    "tab_moment_overflow": ("приведённый момент нагрузки «{load_ru}» переполняется в положении {k} ({a:g}°): "
                            "значения вне допустимого диапазона (допустимо: единицы СИ, Н и м)"),
})
_MSGS_DERIVED |= {"cycle_note_ru", "rows_ru", "load_ru"}


def _msgs_tabulated_ru_params(code: str, p: dict) -> dict:
    """The Russian words of the [tabulated] checks' parameters."""
    if "own_cycle" in p:
        p["cycle_note_ru"] = ", цикл machine.cycle_deg" if p["own_cycle"] else ""
    if code in ("tab_mass_no_point", "tab_J_no_omega_q"):
        p["rows_ru"] = "нет" if p["rows"] == "none" else p["rows"]
    if code == "tab_moment_overflow":
        p["load_ru"] = load_name(p["load"], "ru")
    return p


_PARAM_HOOKS.append(_msgs_tabulated_ru_params)


# --- progress ---
#: the stages of the long computations as the progress bar names them (cli/progress.py)
STAGES = {"start-up": ("start-up", "разгон"), "run-down": ("run-down", "выбег"),
          "steady check": ("steady check", "проверка установившегося режима"),
          "variants": ("variants", "варианты"), "task sheets": ("sheets", "листы заданий"),
          "answer sheets": ("sheets", "листы ответов")}


def stage_name(stage: str, lang: str = "en") -> str:
    """A progress bar's stage ("start-up") in ``lang``; an unknown stage as it is."""
    return STAGES[stage][lang == "ru"] if stage in STAGES else stage


# --- msgs_aggregate ---
# The errors of `flywheel aggregate` in Russian: the case's checks across fields
# (cases/aggregate.py), the chain reduced to shaft I (elastic/chain.py), the steady state
# (elastic/forced.py), the natural frequencies (elastic/modes.py), the integration
# (elastic/timedomain.py).
_AG_REVERSAL_TAIL = ("так что машина останавливалась бы и вращалась в обратную сторону каждый "
                     "период: установившегося движения у этой модели нет (увеличьте скорость, "
                     "добавьте инерции или маховик либо уменьшите M_amplitude)")
MESSAGES_RU.update({
    # cases/aggregate.py: shafts and couplings
    "ag_stiffness_twice": ("задайте что-то одно: жёсткость прямо (c или d и L) или отрезками "
                           "segments"),
    "ag_no_segments": "нужен хотя бы один отрезок вала",
    "ag_c_or_dL_missing": "не задано: задайте c или d и L (с G)",
    "ag_coupling_gear": ("муфта соединяет двигатель с валом I: зубчатой пары в ней нет (передачи "
                         "машины — i21, i31)"),
    "ag_coupling_between": ("муфта соединяет двигатель с машиной: between задаётся только для "
                            "валов цепочки"),
    # cases/aggregate.py: the motor
    "ag_chain_motor_J": "в цепочке двигатель — это первый ротор: задайте его J в rotors[0]",
    "ag_only_constant": ("только при characteristic = \"constant\" (двигатель с линейной "
                         "характеристикой сам находит свою скорость)"),
    "ag_only_linear": "только при characteristic = \"linear\"",
    "ag_omega_x_missing": "не задано: линейной характеристике нужна синхронная скорость ω_x",
    "ag_slip_missing": "не задано: нужно вместе с rated_torque (M_п = M_н/s_н)",
    "ag_slip_only_rated": "задаётся только вместе с rated_torque",
    "ag_motor_too_weak": ("двигатель не может привести машину в движение: M_п = {M_start:g} Н·м "
                          "не больше среднего момента сопротивления, приведённого к валу I, "
                          "{M0:g} Н·м"),
    "ag_speed_missing": ("не задано: двигателю с постоянным моментом нужна установившаяся "
                         "скорость вала I"),
    # cases/aggregate.py: the two-mass aggregate
    "ag_two_mass_motor": "не задано: двухмассовому агрегату нужен [motor] с J (J_Д)",
    "ag_J_III_twice": "задайте что-то одно: J_III или J_III_0 с J_III_positions",
    "ag_no_positions": "нужно хотя бы одно значение",
    "ag_J_III_zero": "J_пр.III получается равным нулю: должен быть положительным",
    # cases/aggregate.py: the chain, its fixed ends and branches
    "ag_fixed_J": "неподвижный конец (fixed = true) — это стойка: момента инерции у него нет",
    "ag_rotor_J_missing": ("не задано обязательное поле (момент инерции, кг·м²; или fixed = true "
                           "для стойки)"),
    "ag_motor_needs_line": ("{ag_why}: [motor] (и [load]) требуют свободной неразветвлённой "
                            "цепочки; для этой системы находятся лишь собственные частоты и формы "
                            "колебаний"),
    "ag_between_all_or_none": ("не задано: задайте between для каждого вала или ни для одного "
                               "(тогда вал k соединяет роторы k и k + 1)"),
    "ag_between_two": "нужны имена двух роторов, первым — со стороны входа (задано {count})",
    "ag_unknown_rotor": "нет ротора {name!r} (роторы: {rotors})",
    "ag_shaft_to_itself": "соединяет ротор {name!r} с ним самим",
    "ag_fixed_one_shaft": ("неподвижный конец — конец системы: к нему подходит один вал (задано "
                           "{count})"),
    "ag_all_fixed": "все роторы неподвижны: хотя бы один должен вращаться",
    "ag_not_connected": ("роторы и валы должны образовывать одну связную систему без замкнутых "
                         "контуров: {name!r} не соединён с {first!r}"),
    "ag_frame_damping": ("вал к стойке: его демпфирование в модели не учитывается (только "
                         "собственные частоты)"),
    # elastic/chain.py: the chain reduced to shaft I (J·u², c·u² overflow or underflow)
    "ag_ground_not_finite": ("ротор {name}: жёсткость связи со стойкой, приведённая к валу I, "
                             "должна быть конечной и неотрицательной (получено {v:g} Н·м/рад)"),
    "ag_ground_zero": "системе, закреплённой в стойке, нужен вал к стойке",
    "ag_reduced_not_finite": ("{ag_where}: приведённое к валу I значение {ag_quantity} — не "
                              "конечное число (получено {v:g}{ag_unit}){ag_overflow}"),
    "ag_J_not_positive": ("ротор {name}: момент инерции должен быть положительным (получено "
                          "{v:g} кг·м²)"),
    "ag_c_not_positive": ("соединение {connection}: жёсткость должна быть положительной "
                          "(получено {v:g} Н·м/рад)"),
    # elastic/forced.py, elastic/modes.py, elastic/timedomain.py
    "ag_resonance": ("частота возмущения {w:.6g} рад/с ({hz:.6g} Гц) совпадает с собственной "
                     "частотой {wn:.6g} рад/с крутильной формы {mode} (с точностью {tol:g}), и "
                     "её ничто не демпфирует: амплитуда установившихся колебаний неограниченна "
                     "(задайте демпфирование муфты, линейную характеристику двигателя или "
                     "измените скорость)"),
    "ag_amplitudes_not_finite": ("амплитуды установившихся колебаний не конечны при частоте "
                                 "возмущения {w:.6g} рад/с: гармоническое решение выходит за "
                                 "пределы двойной точности"),
    "ag_reversal_rigid": ("частота возмущения {w:.6g} рад/с намного ниже низшей собственной "
                          "частоты {wn:.6g} рад/с, поэтому нагрузка раскачивает всю машину как "
                          "жёсткое тело (форма с ω = 0, {ag_held}): скорость колебалась бы на "
                          "±{amp:.6g} рад/с около средней {mean:.6g} рад/с, " + _AG_REVERSAL_TAIL),
    "ag_reversal_rotor": ("скорость ротора {name} колебалась бы на ±{amp:.6g} рад/с около средней "
                          "{mean:.6g} рад/с (δ = {delta:.4g}), " + _AG_REVERSAL_TAIL),
    "ag_eigen_not_finite": ("собственные частоты не конечны: задача K·x = ω²·M·x выходит за "
                            "пределы двойной точности (жёсткость до {c:g} Н·м/рад при моменте "
                            "инерции от {J:g} кг·м², c/J = {ratio:g} 1/с²)"),
    "ag_solve_ivp_failed": ("solve_ivp ({method}) не справился на отрезке 0 … {t_end:.4g} с: "
                            "{ag_reason}"),
})
_AG_QUANTITIES_RU = {"moment of inertia": "момента инерции", "speed ratio": "передаточного "
                     "отношения", "stiffness": "жёсткости", "damping": "демпфирования"}
_MSGS_DERIVED |= {"ag_why", "ag_where", "ag_quantity", "ag_unit", "ag_overflow", "ag_held",
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


_PARAM_HOOKS.append(_msgs_aggregate_ru_params)


# --- sheets ---
# The task sheets of `flywheel variants … --sheets` (render/sheets.py, which adds only the
# sentence templates and the typesetting): the labels of a case file's input fields and the
# answers worded as a task.

#: input fields of a case file: a dotted-path pattern (``#`` an array index, ``*`` a name) →
#: (English, Russian) label; ``{x}`` is the element's name (a link, a cylinder, a point);
#: "@key" takes the name of the term ``key`` (the same quantity in the same words)
SHEET_FIELDS: list[tuple[str, str, str]] = [
    ("machine.speed_rps", "@crank_speed", ""),          # "@key": the nomenclature's name
    ("machine.speed_rpm", "@crank_speed", ""),
    ("machine.delta", "coefficient of speed fluctuation δ", "коэффициент неравномерности хода δ"),
    ("machine.gravity", "gravity g (x, y)", "ускорение свободного падения g (x, y)"),
    ("machine.cycle_deg", "cycle Φ", "цикл Φ"),
    ("machine.first_group.*", "J of the {x} (reduced to the crank)",
     "момент инерции: {x} (приведён к кривошипу)"),
    ("design.mean_piston_speed", "mean piston speed V_m", "средняя скорость поршня V_ср"),
    ("design.rod_to_crank", "rod to crank length ratio k", "отношение длин шатуна и кривошипа k"),
    ("crank.length", "@crank_length", ""),
    ("crank.pivot_at", "crank pivot (x, y)", "координаты опоры кривошипа (x, y)"),
    ("crank.start_angle_deg", "crank angle at φ = 0, from +x",
     "положение кривошипа при φ = 0 (от оси x)"),
    ("dyads.#.rod_length", "rod length, joint {x}", "длина шатуна, шарнир {x}"),
    ("dyads.#.length_from", "first link length, joint {x}", "длина первого звена, шарнир {x}"),
    ("dyads.#.length_to", "second link length, joint {x}", "длина второго звена, шарнир {x}"),
    ("dyads.#.offset", "slide line offset, joint {x}", "смещение линии ползуна, шарнир {x}"),
    ("dyads.#.guide.through", "guide of {x}: a point (x, y)", "направляющая {x}: точка (x, y)"),
    ("dyads.#.guide.angle_deg", "guide of {x}: angle from +x", "направляющая {x}: угол к оси x"),
    ("dyads.#.guide.offset", "guide of {x}: offset", "направляющая {x}: смещение"),
    ("points.*.fraction", "point {x}: share of its link's length",
     "точка {x}: доля длины звена"),
    ("points.*.distance", "point {x}: distance along its link", "точка {x}: расстояние по звену"),
    ("points.*.across", "point {x}: offset across its link", "точка {x}: смещение поперёк звена"),
    ("links.*.mass", "mass of link {x} m_{x}", "масса звена {x} m_{x}"),
    ("links.*.J_S", "moment of inertia of link {x} about its centroid J_S{x}",
     "момент инерции звена {x} относительно центра масс J_S{x}"),
    ("cylinders.#.bore", "bore of cylinder {x} d", "диаметр цилиндра {x} d"),
    ("cylinders.#.p_max", "maximum pressure in cylinder {x} p_max",
     "максимальное давление в цилиндре {x} p_max"),
    ("cylinders.#.s", "cylinder {x}: relative piston travel s",
     "цилиндр {x}: относительное перемещение поршня s"),
    ("cylinders.#.towards_head", "cylinder {x}: p/p_max, piston moving to the head",
     "цилиндр {x}: p/p_max при движении поршня к головке"),
    ("cylinders.#.away_from_head", "cylinder {x}: p/p_max, piston moving from the head",
     "цилиндр {x}: p/p_max при движении поршня от головки"),
    ("forces.#.magnitude", "force {x}: magnitude F", "сила {x}: модуль F"),
    ("forces.#.s_range", "force {x}: where it acts (relative travel)",
     "сила {x}: участок действия (отн. перемещение)"),
    ("flywheel.density", "density of the flywheel material ρ", "плотность материала маховика ρ"),
    ("flywheel.width_ratio", "flywheel width to diameter b/D",
     "отношение ширины маховика к диаметру b/D"),
    ("flywheel.inner_ratio", "rim inner to outer diameter D1/D",
     "отношение диаметров обода D₁/D"),
    ("flywheel.speed_ratio", "@flywheel_speed_ratio", ""),
    # --- audit: engines (issue 13), a given flywheel and its rim (issues 13, 14) ---
    ("machine.power", "mean power P", "средняя мощность P"),
    ("crank.pins.#.angle_deg", "crank pin {x}: angle to the crank",
     "шатунная шейка {x}: угол к кривошипу"),
    ("crank.pins.#.length", "crank pin {x}: throw", "шатунная шейка {x}: радиус кривошипа"),
    ("ground.*", "fixed point {x} (x, y)", "неподвижная точка {x} (x, y)"),
    ("cylinders.#.fires_at_deg", "cylinder {x}: fires at φ", "цилиндр {x}: воспламенение при φ"),
    ("cylinders.#.strokes.intake", "cylinder {x}: p/p_max on the intake stroke",
     "цилиндр {x}: p/p_max на такте впуска"),
    ("cylinders.#.strokes.compression", "cylinder {x}: p/p_max on the compression stroke",
     "цилиндр {x}: p/p_max на такте сжатия"),
    ("cylinders.#.strokes.expansion", "cylinder {x}: p/p_max on the expansion stroke",
     "цилиндр {x}: p/p_max на такте расширения"),
    ("cylinders.#.strokes.exhaust", "cylinder {x}: p/p_max on the exhaust stroke",
     "цилиндр {x}: p/p_max на такте выпуска"),
    ("cylinders.#.diagram.s", "cylinder {x}: indicator diagram, travel s",
     "цилиндр {x}: индикаторная диаграмма, перемещение s"),
    ("cylinders.#.diagram.p", "cylinder {x}: indicator diagram, p/p_max",
     "цилиндр {x}: индикаторная диаграмма, p/p_max"),
    ("flywheel.mass", "flywheel mass m", "масса маховика m"),
    ("flywheel.radius_of_gyration", "radius of gyration of the flywheel k",
     "радиус инерции маховика k"),
    ("flywheel.allowable_stress", "allowable stress of the rim [σ]",
     "допускаемое напряжение обода [σ]"),
    ("flywheel.rim.share", "share of J carried by the rim", "доля J, приходящаяся на обод"),
    ("flywheel.rim.width_to_thickness", "rim width to thickness b/t",
     "отношение ширины обода к толщине b/t"),
    ("flywheel.rim.width", "rim width b", "ширина обода b"),
    ("flywheel.rim.speed", "rim speed v", "окружная скорость обода v"),
    # task2 («Задача 2»)
    ("cycle_deg", "cycle Φ", "цикл Φ"),
    ("speed.omega0", "angular velocity at φ = 0, ω0", "угловая скорость при φ = 0, ω₀"),
    ("speed.mean", "mean angular velocity ω_m", "средняя угловая скорость ω_ср"),
    # flywheel.J means two things (docs/case-format.md, docs/task2.md): "run:" and "task2:" below
    ("flywheel.delta", "coefficient of speed fluctuation asked δ",
     "заданный коэффициент неравномерности хода δ"),
    ("driving.value", "driving moment M_D", "движущий момент M_Д"),
    ("driving.peak", "driving moment M_D, peak", "движущий момент M_Д, наибольший"),
    ("resistance.value", "resistance moment M_C", "момент сопротивления M_С"),
    ("resistance.peak", "resistance moment M_C, peak", "момент сопротивления M_С, наибольший"),
    ("driving.from_deg", "M_D: start of its graph", "M_Д: начало участка"),
    ("driving.to_deg", "M_D: end of its graph", "M_Д: конец участка"),
    ("resistance.from_deg", "M_C: start of its graph", "M_С: начало участка"),
    ("resistance.to_deg", "M_C: end of its graph", "M_С: конец участка"),
    ("resistance.apex_deg", "M_C: angle of its peak", "M_С: угол вершины"),
    ("resistance.base", "M_C outside its graph", "M_С вне участка"),
    ("driving.base", "M_D outside its graph", "M_Д вне участка"),
    # --- audit: task2 fields of the bundled cases (issue 14) ---
    ("power", "mean power P", "средняя мощность P"),
    ("at_deg", "angles asked φ", "заданные углы φ"),
    ("speed.omega0_rpm", "speed at φ = 0, n0", "частота вращения при φ = 0, n₀"),
    ("speed.mean_rpm", "mean speed n_m", "средняя частота вращения n_ср"),
    ("speed.max_rpm", "greatest speed n_max", "наибольшая частота вращения n_max"),
    ("speed.min_rpm", "least speed n_min", "наименьшая частота вращения n_min"),
    ("flywheel.fluctuation_percent", "speed fluctuation ± % of the mean",
     "колебание скорости, ± % от средней"),
    ("flywheel.rim_radius", "rim radius R", "радиус обода R"),
    ("diagram.areas", "areas of the turning-moment diagram", "площади диаграммы моментов"),
    ("diagram.moment_scale", "diagram: moment scale", "диаграмма: масштаб моментов"),
    ("diagram.angle_scale_deg", "diagram: angle scale", "диаграмма: масштаб углов"),
    ("diagram.delta_E", "maximum fluctuation of energy ΔE", "наибольшее изменение энергии ΔE"),
    ("diagram.energy_fluctuation_coefficient", "coefficient of fluctuation of energy C_E",
     "коэффициент колебания энергии C_E"),
    ("diagram.work_per_cycle", "work per cycle A", "работа за цикл A"),
    # --- sheets: the fields of one case kind ("kind:path"; a run's "run,i:" when the flywheel
    # is on a shaft of its own, speed ratio i ≠ 1), the given flywheel's forms, the text fields ---
    ("task2:flywheel.J", "reduced moment of inertia J", "приведённый момент инерции J_пр"),
    ("run,i:flywheel.J", "moment of inertia of the given flywheel on its own shaft J_M/i²",
     "момент инерции заданного маховика на его валу J_М/i²"),
    ("run:flywheel.J", "moment of inertia of the given flywheel J_M",
     "момент инерции заданного маховика J_М"),
    ("flywheel.given_disk.D", "given flywheel, a solid disk: outer diameter D",
     "заданный маховик — сплошной диск: наружный диаметр D"),
    ("flywheel.given_disk.b", "given flywheel, a solid disk: width b",
     "заданный маховик — сплошной диск: ширина b"),
    ("flywheel.given_rim.D", "given flywheel, a rim: outer diameter D",
     "заданный маховик — обод: наружный диаметр D"),
    ("flywheel.given_rim.D_inner", "given flywheel, a rim: inner diameter D1",
     "заданный маховик — обод: внутренний диаметр D₁"),
    ("flywheel.given_rim.b", "given flywheel, a rim: width b",
     "заданный маховик — обод: ширина b"),
    ("machine.firing_order", "firing order of the cylinders", "порядок работы цилиндров"),
    ("machine.balance", "the constant moment, found from the cycle balance",
     "постоянный момент, определяемый из условия цикла"),
    ("crank.rotation", "direction of the crank's rotation", "направление вращения кривошипа"),
    ("cylinders.#.head", "cylinder {x}: dead centre at the head",
     "цилиндр {x}: мёртвая точка у головки"),
    ("flywheel.material", "@flywheel_material", ""),
    ("forces.#.reference", "force {x}: its travel s measured from the dead centre",
     "сила {x}: мёртвая точка начала отсчёта перемещения s"),
    ("forces.#.stroke", "force {x}: acts while the slider moves",
     "сила {x}: действует при движении ползуна"),
] + [entry for graph, en, ru in (("driving", "M_D", "M_Д"), ("resistance", "M_C", "M_С"))
     for entry in (
         (f"{graph}.points", f"{en}: points (φ, M)", f"{ru}: точки графика (φ, M)"),
         (f"{graph}.scale", f"{en}: scale of the graph", f"{ru}: масштаб графика"),
         (f"{graph}.a0", f"{en}: constant term a_0", f"{ru}: постоянная составляющая a_0"),
         (f"{graph}.a", f"{en}: sine coefficients a_k", f"{ru}: коэффициенты при sin kφ a_k"),
         (f"{graph}.b", f"{en}: cosine coefficients b_k", f"{ru}: коэффициенты при cos kφ b_k"),
         (f"{graph}.orders", f"{en}: harmonic orders k", f"{ru}: порядки гармоник k"),
         (f"{graph}.top_from_deg", f"{en}: start of the top", f"{ru}: начало верхнего участка"),
         (f"{graph}.top_to_deg", f"{en}: end of the top", f"{ru}: конец верхнего участка"))]

#: the answers as a task: key → (English, Russian) object of "Determine …" (the symbol and
#: the unit are the term's; "{kind}:key" entries, of one case kind, first)
SHEET_ANSWERS: dict[str, tuple[str, str]] = {
    "run:J_required": ("the required moment of inertia of the first group",
                       "необходимый момент инерции первой группы звеньев"),
    "task2:J_required": ("the moment of inertia that gives the asked δ,",
                         "приведённый момент инерции, обеспечивающий заданный δ,"),
    "task2:delta": ("the coefficient of speed fluctuation", "коэффициент неравномерности хода"),
    "driving_moment": ("the driving moment that balances the cycle",
                       "приведённый движущий момент из условия цикла"),
    "delta_T_max": ("the largest fluctuation of kinetic energy",
                    "наибольшее изменение кинетической энергии"),
    "J_flywheel": ("the moment of inertia of the flywheel", "момент инерции маховика"),
    "flywheel_disk.D": ("the outer diameter of the flywheel as a solid disk",
                        "наружный диаметр маховика в виде сплошного диска"),
    "flywheel_disk.b": ("the width of the flywheel as a solid disk",
                        "ширину маховика в виде сплошного диска"),
    "flywheel_disk.mass": ("the mass of the flywheel as a solid disk",
                           "массу маховика в виде сплошного диска"),
    "flywheel_rim.D": ("the outer diameter of the flywheel's rim", "наружный диаметр обода маховика"),
    "flywheel_rim.mass": ("the mass of the flywheel's rim", "массу обода маховика"),
    "M_C": ("the resistance moment", "момент сопротивления"),
    "M_D": ("the driving moment", "движущий момент"),
    "omega_max": ("the greatest angular velocity", "наибольшую угловую скорость"),
    "omega_min": ("the least angular velocity", "наименьшую угловую скорость"),
    "omega_mean": ("the mean angular velocity", "среднюю угловую скорость"),
    "cycle_work_resistance": ("the work of the resistance over a cycle",
                              "работу сил сопротивления за цикл"),
    "balancing_moment": ("the constant moment that balances the cycle (with its sign)",
                         "постоянный момент из условия цикла (со знаком)"),
    "flywheel_J_on_its_shaft": ("the moment of inertia of the flywheel on its own shaft",
                                "момент инерции маховика на его валу"),
}
#: answers whose symbol differs between the two kinds (J_I of a run, J_пр of task2)
SHEET_SYMBOLS = {"task2:J_required": ("J", "J_пр"), "task2:delta": ("δ", "δ")}


def _sheet_pattern(p: str) -> re.Pattern:
    rx = re.escape(p).replace("\\#", r"(?P<i>\d+)").replace("\\*", r"(?P<x>[^.]+)")
    return re.compile("^" + rx + "$")


_SHEET_FIELD_RX = [(_sheet_pattern(p), en, ru) for p, en, ru in SHEET_FIELDS]


def field_label(path: str, lang: str = "en", names: dict[str, str] | None = None,
                kinds: tuple[str, ...] = ()) -> str:
    """The label of a case file's input field on a task sheet ("links.2.mass" → "масса звена 2
    m_2"); ``names``: the element name of an indexed path ("cylinders.0" → "HP"), else the
    element's number from 1; ``kinds``: the case kind's entries to try first, in order ("run",
    "task2"; "run,i" for a flywheel on a shaft of its own); an unknown field by its dotted path
    as the case file spells it.

    >>> field_label("cylinders.0.bore", "ru", {"cylinders.0": "HP"}), field_label("crank.length")
    ('диаметр цилиндра HP d', 'crank length l1')
    >>> field_label("flywheel.J", "ru", kinds=("run",)), field_label("flywheel.J", "ru")
    ('момент инерции заданного маховика J_М', 'flywheel.J')
    """
    for key in (*(f"{k}:{path}" for k in kinds), path):
        for rx, en, ru in _SHEET_FIELD_RX:
            m = rx.match(key)
            if m:
                if en.startswith("@"):
                    return name(en[1:], lang)
                d = m.groupdict()
                x = d.get("x") or ""
                if not x and d.get("i") is not None:
                    x = (names or {}).get(path[:m.end("i") - len(key) + len(path)]) or \
                        str(int(d["i"]) + 1)
                return (ru if lang == "ru" else en).format(x=x)
    return path


#: the words of a case file's text fields on a task sheet: path pattern → value → (English,
#: Russian); a value not listed is printed as it is
SHEET_VALUES: dict[str, dict[str, tuple[str, str]]] = {
    "machine.balance": {"driving": ("the driving moment M_D", "движущий момент M_Д"),
                        "resistance": ("the resistance moment M_C", "момент сопротивления M_С")},
    "crank.rotation": {"cw": ("clockwise", "по часовой стрелке"),
                       "ccw": ("counter-clockwise", "против часовой стрелки")},
    "cylinders.#.head": {"outer": ("outer (farther from the crank axis)",
                                   "внешняя (дальняя от оси кривошипа)"),
                         "inner": ("inner (nearer to the crank axis)",
                                   "внутренняя (ближняя к оси кривошипа)")},
    "flywheel.material": MATERIALS,
    "forces.#.reference": {"outer": ("outer (farther from the crank axis)",
                                     "внешняя (дальняя от оси кривошипа)"),
                           "inner": ("inner (nearer to the crank axis)",
                                     "внутренняя (ближняя к оси кривошипа)")},
    "forces.#.stroke": {"towards": ("towards that dead centre", "к этой мёртвой точке"),
                        "away": ("away from that dead centre", "от этой мёртвой точки"),
                        "both": ("either way", "в обе стороны")},
}
_SHEET_VALUE_RX = [(_sheet_pattern(p), words) for p, words in SHEET_VALUES.items()]


def field_value(path: str, value, lang: str = "en") -> str:
    """A text field's value as a task sheet prints it: the words of :data:`SHEET_VALUES`
    ("crank.rotation" "cw" → "по часовой стрелке"), an array of names as a sequence ("1-3-4-2",
    a firing order; ", " between names that hold a hyphen themselves), any other text as it is.

    >>> field_value("machine.firing_order", ("1", "3", "4", "2"))
    '1-3-4-2'
    >>> field_value("crank.rotation", "cw", "ru")
    'по часовой стрелке'
    """
    if isinstance(value, (list, tuple)):
        items = [field_value(path, v, lang) for v in value]
        return (", " if any("-" in v for v in items) else "-").join(items)
    for rx, words in _SHEET_VALUE_RX:
        if rx.match(path):
            return words[value][lang == "ru"] if value in words else value
    return value


def answer_words(kind: str, key: str, lang: str = "en") -> tuple[str, str, str]:
    """(what, symbol, unit) of an answer of a ``kind`` ("run", "task2") case as a task sheet
    asks it: the object of "Determine …", the symbol and the unit as printed ("" where the
    quantity has none; the result key itself if it is no term).

    >>> answer_words("run", "J_flywheel", "ru")
    ('момент инерции маховика', 'J_М', 'кг·м²')
    """
    last = key.rsplit(".", 1)[-1]
    words = SHEET_ANSWERS.get(f"{kind}:{key}") or SHEET_ANSWERS.get(key)
    try:
        sym, u = symbol(last, lang), unit_of(last, lang)
        label = name(key if key in TERMS else last, lang)
    except KeyError:
        sym, u, label = "", "", key
    if f"{kind}:{key}" in SHEET_SYMBOLS:
        sym = SHEET_SYMBOLS[f"{kind}:{key}"][lang == "ru"]
    what = words[lang == "ru"] if words else label
    if sym and what.endswith(sym):          # a name that ends with its symbol: not twice
        what = what[:-len(sym)].rstrip(" ,")
    return what, sym, "" if u in ("–", "") else u


# --- msgs_task2 ---
# The errors of flywheel task2 (cases/task2.py's cross-field checks, constant_inertia's solvers,
# cli/task2.py's --at) in Russian.
MESSAGES_RU.update({
    # cases/task2.py: [speed], [flywheel], at_deg
    "t2_limits_pair": "не задано: пределы скорости задаются парой ({first} с {other})",
    "t2_limit_below": "должно быть меньше {limit} (задано {v:g} {unit_ru}, а {limit} = {vo:g} "
                      "{unit_ru})",
    "t2_limits_give_delta": ("пределы скорости уже дают δ = (max − min)/ω_ср: задайте что-то "
                             "одно"),
    "t2_flywheel_missing": ("задайте J, или mass и radius_of_gyration, или требуемое delta (или "
                            "fluctuation_percent, или пределы скорости)"),
    "t2_at_in_cycle": "должно лежать в пределах цикла 0…{cycle:g}° (задано {x:g})",
    # cases/task2.py: the graphs and the mean power
    "t2_graphs_missing": "не задано: задайте графики [driving] и [resistance] или [diagram]",
    "t2_power_once": ("\"power\" может заменять лишь одно значение (другое уже задано так: "
                      "{other})"),
    "t2_power_needs_P": ("для \"power\" нужна средняя мощность: задайте power [Вт] на верхнем "
                         "уровне"),
    "t2_power_needs_mean": ("для \"power\" (средний момент M_ср = P/ω_ср) нужна средняя скорость: "
                            "задайте speed.mean, mean_rpm или пределы max/min"),
    "t2_power_unused": ("используется только значением графика \"power\" (M_ср = P/ω_ср), а "
                        "ни одно значение графика не равно \"power\""),
    "t2_points_two": "нужно не меньше двух точек [угол, момент]",
    "t2_apex_within": "должно лежать в пределах {start:g}…{end:g}° (задано {apex:g})",
    # cases/task2.py: [diagram]
    "t2_diagram_at": ("у диаграммы, заданной площадями, нет моментов между точками пересечения "
                      "со средней линией: для ε, ω и t при заданном угле нужны графики [driving] "
                      "и [resistance]"),
    "t2_efc_needs_work": ("нужна работа за цикл: задайте diagram.work_per_cycle [Дж] или среднюю "
                          "мощность (power верхнего уровня [Вт]) вместе со средней скоростью"),
    "t2_work_needs_mean": ("для работы за цикл P·Φ/ω_ср нужна средняя скорость: задайте "
                           "speed.mean, mean_rpm или пределы max/min"),
    "t2_power_unused_diagram": ("используется только значением графика \"power\" или "
                                "[diagram] energy_fluctuation_coefficient без work_per_cycle; "
                                "здесь её ничто не использует"),
    "t2_diagram_form": ("задайте что-то одно: areas (с moment_scale и angle_scale_deg), "
                        "energies, delta_E или energy_fluctuation_coefficient{given_ru}"),
    "t2_work_only_efc": "задаётся только вместе с energy_fluctuation_coefficient",
    "t2_only_areas": "задаётся только с areas или energies (а не с {form})",
    "t2_areas_scales": "не задано: для площадей нужны масштабы чертежа",
    "t2_two_areas": "нужно не меньше двух площадей",
    "t2_crossings_count": ("углов должно быть на один больше, чем площадей: {n} (задано "
                           "{count})"),
    "t2_angles_increase": "углы должны возрастать",
    "t2_crossings_within": "должны лежать в пределах 0…{cycle:g}°",
    # cli/task2.py
    "t2_at_option": "--at {x:g}: должно лежать в пределах цикла 0…{cycle:g}°",
    "t2_at_diagram": ("--at: {case} задаёт диаграмму площадями, у неё нет моментов между точками "
                      "пересечения со средней линией: для ε, ω и t при заданном угле нужны "
                      "графики"),
    # constant_inertia/graphs.py, preset.py (angles that coincide only after the conversion
    # to radians)
    "t2_graph_angles_back": ("углы графика не должны убывать: точка {i} при {at:g}° идёт после "
                             "{before:g}°"),
    "t2_graph_interval": ("интервал графика {start:g}…{end:g}° должен удовлетворять 0 ≤ from < "
                          "to ≤ {cycle:g}°"),
    "t2_from_below_to": "from ({start:g}°) должно быть меньше to ({end:g}°)",
    # constant_inertia/solve.py: the mean power, the cycle balance, the motion
    "t2_power_no_change": ("значение {t2_which_gen} не меняет его работу: по средней мощности "
                           "его не найти"),
    "t2_power_negative": ("средняя мощность {power:.6g} Вт требует отрицательного значения "
                          "{t2_which_gen} ({x:.6g}): одна лишь постоянная часть графика "
                          "совершает больше работы, чем P·Φ/ω_ср = {target:.6g} Дж"),
    "t2_balance_no_change": ("неизвестное значение {t2_which_gen} не меняет его работу: по "
                             "балансу работ за цикл его не найти"),
    "t2_balance_negative": ("баланс работ за цикл требует отрицательного {t2_which_gen} "
                            "({x:.6g} Н·м): {t2_balance_why}"),
    "t2_J_too_small": ("J = {J:.6g} кг·м² слишком мал для средней скорости {omega:.6g} рад/с: "
                       "колебание энергии {dT:.6g} Дж остановило бы машину"),
    "t2_delta_needs_mean": "чтобы найти J по δ, задайте среднюю скорость, а не ω0",
    "t2_no_fluctuation": "энергия не колеблется: при любом J δ = 0",
    "t2_mean_needs_steady": ("средняя скорость требует установившегося движения (работа за цикл "
                             "{work:.6g} Дж, а не 0): задайте ω0"),
    "t2_delta_0_2": "δ должно лежать между 0 и 2 (задано {delta:g})",
    "t2_time_law": ("время t(φ) = ∫dφ/ω не удаётся найти на {a:.6g}…{b:.6g}°: интеграл не "
                    "сходится (скорость слишком близка к нулю)"),
    "t2_areas_sum": ("сумма площадей {total:.6g}, а не 0: за цикл установившегося движения "
                     "площади над средней линией и под ней равны"),
    "t2_crossings_increase": "углы пересечений со средней линией должны возрастать",
    # constant_inertia/solve.py python_detail: what Python's arithmetic said (not_finite's detail)
    "t2_python_error": "{t2_python_ru}",
})
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


_PARAM_HOOKS.append(_msgs_task2_ru_params)
_MSGS_DERIVED |= {"t2_which_gen", "t2_balance_why", "t2_python_ru"}


# --- msgs_run ---
# The run case's cylinders, points and firing order, the dynamics' and the force analysis's
# errors, files that cannot be read or written (cases/run.py, dynamics/*.py, io/*.py) in Russian.
MESSAGES_RU.update({
    # cases/run.py: [points]
    "run_point_fraction_with_distance": "`fraction` и `across` задаются с `to`, а не с `distance`",
    "run_point_angle_with_to": "`angle_deg` задаётся с `distance`, а не с `to`",
    "run_point_not_on_link": "точка {point!r} не лежит на звене {link} (его точки: {points}){placed_ru}",
    "run_rod_length_missing": "не задано: укажите rod_length или design.rod_to_crank",
    "run_not_with_tabulated": ("не допускается вместе с [tabulated]: задайте массы и нагрузки в "
                               "[tabulated] (docs/tabulated.md)"),
    # cases/run.py: [[cylinders]], a four-stroke diagram over the cycle
    "run_diagram_too_short": "нужно не меньше 5 значений (0, 1, 0, 1, 0: четыре такта)",
    "run_s_outside": "{v:g} выходит за пределы хода (допустимо: 0 … 1)",
    "run_diagram_start": ("{s0:g}: диаграмма начинается в верхней мёртвой точке, где происходит "
                          "вспышка в цилиндре (допустимо: 0)"),
    "run_diagram_step": ("p/p_max меняется скачком с {p0:g} до {p1:g} при s = {at:g}, где такт "
                         "{end_ru} кончается, а такт {begin_ru} {begins_ru}: такты не смыкаются "
                         "(скачок {jump:.4g}; допустимо: не больше join_tolerance = {tol:g})"),
    "run_diagram_ends_inside": ("обрывается внутри такта {stroke_ru} (допустимо: s проходит "
                                "0 → 1 → 0 → 1 → 0 за такты расширения, выпуска, впуска и "
                                "сжатия)"),
    "run_diagram_direction": "{b:g} после {a:g}: на такте {stroke_ru} s должно {way_ru} до {target:g}",
    "run_diagram_goes_on": ("продолжается после того, как такт сжатия замкнул цикл при s = 0 "
                            "(допустимо: четыре такта)"),
    "run_diagram_or_tables": ("задайте что-то одно: diagram (одна таблица на весь цикл) или s с "
                              "её таблицами"),
    "run_s_missing": ("не задано обязательное поле (или задайте diagram: одну таблицу на весь "
                      "четырёхтактный цикл)"),
    "run_s_too_short": "нужно не меньше 2 значений",
    "run_s_span": "должно охватывать [0, 1] (задано {first} … {last})",
    "run_two_tables_missing": ("не задано: укажите towards_head и away_from_head или strokes "
                               "(четырёхтактную диаграмму)"),
    "run_fires_at_needs_strokes": ("задаётся только со strokes (четырёхтактной диаграммой): "
                                   "цилиндр с двумя таблицами повторяет цикл каждый оборот"),
    "run_two_tables_or_strokes": ("задайте что-то одно: towards_head и away_from_head "
                                  "(компрессор, двухтактный двигатель) или strokes "
                                  "(четырёхтактный двигатель)"),
    # cases/run.py, dynamics/engine.py, dynamics/grid.py: the firing order, the dead centres
    "run_firing_no_cylinder": "нет цилиндра {name!r} (четырёхтактные цилиндры: {four_ru})",
    "run_firing_not_four_stroke": ("у цилиндра {name!r} нет четырёхтактной диаграммы (strokes): "
                                   "в порядке работы участвуют только четырёхтактные цилиндры "
                                   "(четырёхтактные цилиндры: {four_ru})"),
    "run_firing_twice": ("цилиндр {name!r} уже есть в порядке работы (каждый срабатывает один "
                         "раз за цикл)"),
    "run_fires_at_with_order": ("machine.firing_order задаёт, где срабатывает цилиндр {name!r} "
                                "(допустимо: fires_at_deg только у первого цилиндра порядка, "
                                "{first!r})"),
    "run_fires_far": ("{deg:g}° отстоит на {gap:.4g}° от ближайшей верхней мёртвой точки поршня "
                      "{piston} ({h1}, {h2}): вспышка в цилиндре происходит в верхней мёртвой "
                      "точке (допустимо: не дальше 90° от неё)"),
    "run_no_dead_centres": "у {role_ru} {slider} нет пары мёртвых положений",
    # dynamics/forces.py, dynamics/stages.py
    "run_link_named_frame": ("силовой анализ: звено названо {frame!r}, а это имя стойки в "
                             "реакциях (допустимо: любое другое имя)"),
    "run_no_inertia": ("у машины нет инерции: нагрузки не вызывают колебаний энергии (ΔT_нб = 0, "
                       "поэтому маховик не подбирается), ни одно звено не имеет массы и на валу "
                       "кривошипа ничего нет, так что ω(φ) не определена (допустимо: массы в "
                       "[links] или machine.first_group)"),
    "run_overflow": ("результаты переполняются: значения случая вне допустимого диапазона "
                     "(допустимо: единицы СИ — м, кг, Н, Па)"),
    "run_given_no_inertia": ("у машины нет инерции (допустимо: flywheel.J > 0, массы в [links] "
                             "или machine.first_group)"),
    "run_given_no_fluctuation": ("заданный маховик (J = {J:.6g} кг·м²) не проверить: скорость "
                                 "не колеблется вовсе (δ = 0: нагрузки не совершают работы и "
                                 "массы звеньев не движутся, кинетическая энергия постоянна) "
                                 "(допустимо: случай с нагрузками или массами)"),
    "run_given_delta": ("заданный маховик (J = {J:.6g} кг·м²) слишком мал: коэффициент "
                        "неравномерности хода δ = {delta:.6g} (допустимо: больший flywheel.J)"),
    # io/output.py, io/toml.py: the system's refusal (its words by errno, else as it said them)
    "run_cannot_write": "{option} {path}: не удаётся записать ({reason_ru})",
    "run_cannot_read": "{path}: не удаётся прочитать ({reason_ru})",
    "run_out_folder_in_the_way": "--out {target}: {rel} — папка, а flywheel записывает туда файл",
})
#: the strokes of a four-stroke cycle in the genitive («такт расширения»)
_STROKES_RU = {"expansion": "расширения", "exhaust": "выпуска", "intake": "впуска",
               "compression": "сжатия"}
#: what a slider is to the load on it, in the genitive («у поршня 3»)
_ROLES_RU = {"piston": "поршня", "slider": "ползуна"}
#: the system's reasons (OSError.strerror) by errno
_OS_REASONS_RU = {"ENOENT": "нет такого файла или папки", "EACCES": "нет доступа",
                  "EPERM": "операция не разрешена", "ENOTDIR": "часть пути — не папка",
                  "EISDIR": "это папка", "ENAMETOOLONG": "слишком длинное имя файла",
                  "EROFS": "файловая система только для чтения",
                  "ENOSPC": "на устройстве нет места", "EDQUOT": "превышена дисковая квота",
                  "EEXIST": "файл уже существует", "EIO": "ошибка ввода-вывода",
                  "ELOOP": "слишком много символических ссылок", "EBUSY": "устройство занято",
                  "ETXTBSY": "файл занят", "EINVAL": "недопустимый аргумент",
                  "EFBIG": "файл слишком велик", "EMFILE": "открыто слишком много файлов"}


def os_reason_ru(code: int | None, reason: str) -> str:
    """The system's reason (OSError.strerror) in Russian by its errno; another as it said it."""
    return _OS_REASONS_RU.get(errno.errorcode.get(code, ""), reason) if code else reason


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


_PARAM_HOOKS.append(_msgs_run_ru_params)
_MSGS_DERIVED |= {"placed_ru", "end_ru", "begin_ru", "begins_ru", "stroke_ru", "way_ru",
                  "four_ru", "role_ru", "reason_ru"}


# --- msgs_rim ---
# The designed rim's plausibility warning (dynamics/stages.py with_rim_speeds) in Russian.
MESSAGES_RU["rim_thin"] = (
    "flywheel.rim: спроектированный обод толщиной {t_mm:.3g} мм при среднем диаметре {D:.4g} м "
    "(t/D = {ratio:.2g}, меньше {least:g}) — обруч, а не обод маховика; его окружная скорость "
    "{v:.4g} м/с ({from_ru}) слишком велика для такого медленного вала: задайте "
    "flywheel.rim.speed (около {v_aim:.3g} м/с даёт t/D = {aim:g})")
_MSGS_DERIVED |= {"from_ru"}


def _msgs_rim_ru_params(code: str, p: dict) -> dict:
    if code == "rim_thin":
        p["from_ru"] = "задана" if p["given"] else "наибольшая, какую допускает напряжение"
    return p


_PARAM_HOOKS.append(_msgs_rim_ru_params)


# --- msgs_libraries ---
# The words of the libraries and of the system inside an error line, in Russian: tomllib's
# (Python 3.11's tomllib/_parser.py, every message it raises), json's, matplotlib's savefig and
# the system's reasons (os_reason_ru); a message not listed (another version's wording) keeps
# its English words.
_TOML_RU = [
    (r"Invalid statement", "недопустимая инструкция"),
    (r"Expected newline or end of document after a statement",
     "после инструкции ожидается перевод строки или конец документа"),
    (r"Expected (?P<x>'.*')", "ожидается {x}"),
    (r"Found invalid character (?P<x>'.*')", "недопустимый символ {x}"),
    (r"Cannot declare (?P<x>.+) twice", "таблица {x} объявлена дважды"),
    (r"Cannot overwrite a value", "значение нельзя перезаписать"),
    (r"Expected '\]' at the end of a table declaration",
     "в конце объявления таблицы ожидается ']'"),
    (r"Expected '\]\]' at the end of an array declaration",
     "в конце объявления массива таблиц ожидается ']]'"),
    (r"Cannot mutate immutable namespace (?P<x>.+)",
     "нельзя изменить уже заданную таблицу {x}"),
    (r"Cannot redefine namespace (?P<x>.+)", "нельзя переопределить таблицу {x}"),
    (r"Expected '=' after a key in a key/value pair", "после ключа ожидается '='"),
    (r"Invalid initial character for a key part", "недопустимый первый символ ключа"),
    (r"Unclosed array", "массив не закрыт"),
    (r"Duplicate inline table key (?P<x>'.*')", "ключ {x} встроенной таблицы повторяется"),
    (r"Unclosed inline table", "встроенная таблица не закрыта"),
    (r"Unescaped '\\' in a string", "неэкранированный '\\' в строке"),
    (r"Invalid hex value", "недопустимое шестнадцатеричное значение"),
    (r"Escaped character is not a Unicode scalar value",
     "экранированный символ — не скалярное значение Unicode"),
    (r"Unterminated string", "строка не закрыта"),
    (r"Illegal character (?P<x>'.*')", "недопустимый символ {x}"),
    (r"Invalid date or datetime", "недопустимая дата или дата и время"),
    (r"Invalid value", "недопустимое значение"),
]


def _toml_detail_ru(detail: str) -> str:
    """tomllib's message "<what> (at line N, column M)" in Russian, its place «(строка N,
    столбец M)»; a message not in _TOML_RU keeps its words."""
    m = re.fullmatch(r"(?P<what>.*?)(?P<place> \(at line \d+, column \d+\)| \(at end of document\))?",
                     detail, re.S)
    what, place = _said_ru(m.group("what"), _TOML_RU), m.group("place") or ""
    place = re.sub(r"\(at line (\d+), column (\d+)\)", r"(строка \1, столбец \2)", place)
    return what + place.replace("(at end of document)", "(в конце документа)")


#: json's own words (Python's json/decoder.py, every message it raises) in Russian
_JSON_RU = [
    (r"Expecting value", "ожидается значение"),
    (r"Expecting property name enclosed in double quotes",
     "ожидается имя свойства в двойных кавычках"),
    (r"Expecting ',' delimiter", "ожидается разделитель ','"),
    (r"Expecting ':' delimiter", "ожидается разделитель ':'"),
    (r"Extra data", "лишние данные после документа"),
    (r"Unterminated string starting at", "незакрытая строка, её начало"),
    (r"Invalid control character at", "недопустимый управляющий символ"),
    (r"Invalid control character (?P<x>'.*') at", "недопустимый управляющий символ {x}"),
    (r"Invalid \\escape", "недопустимая escape-последовательность"),
    (r"Invalid \\escape: (?P<x>'.*')", "недопустимая escape-последовательность {x}"),
    (r"Invalid \\uXXXX escape", "недопустимая последовательность \\uXXXX"),
]


def _said_ru(text: str, table: list) -> str:
    """A library's fixed message in Russian from ``table`` (regex, template); as it is when
    no entry matches."""
    for rx, ru in table:
        hit = re.fullmatch(rx, text)
        if hit:
            return ru.format(**hit.groupdict())
    return text


#: matplotlib's reasons an image cannot be saved (savefig's ValueError)
_MATPLOTLIB_RU = [
    (r"Format '(?P<x>.*)' is not supported \(supported formats: (?P<y>.*)\)",
     "формат '{x}' не поддерживается (поддерживаются: {y})"),
]


def _msgs_libraries_ru_params(code: str, p: dict) -> dict:
    if code == "plot_cannot_write":
        p["reason_ru"] = (os_reason_ru(p["errno"], p["strerror"]) if p.get("strerror")
                          else _said_ru(p["reason"], _MATPLOTLIB_RU))
    elif code == "toml_syntax":
        p["detail_ru"] = _toml_detail_ru(p["detail"])
    elif code == "not_json":
        p["msg"] = _said_ru(p["msg"], _JSON_RU)
    return p


_PARAM_HOOKS.append(_msgs_libraries_ru_params)



# --- msgs_plural ---
# Russian numerals agree with their noun (1 цикл, 2 цикла, 5 циклов): the counts of the
# templates above, with their noun in the form the number asks for.


def ru_count(n: int, one: str, few: str, many: str) -> str:
    """``n`` with its noun in the form Russian gives it after that number: 1, 21 → ``one``;
    2–4, 22–24 → ``few``; 0, 5–20, 25 … → ``many``.

    >>> [ru_count(k, "вал", "вала", "валов") for k in (1, 2, 5, 11, 21, 112)]
    ['1 вал', '2 вала', '5 валов', '11 валов', '21 вал', '112 валов']
    """
    n = int(n)
    tens, last = n % 100, n % 10
    word = (many if 11 <= tens <= 14 else one if last == 1 else few if 2 <= last <= 4 else many)
    return f"{n} {word}"


_VALUES = ("значение", "значения", "значений")


def _msgs_plural_ru_params(code: str, p: dict) -> dict:
    if code == "startup_not_steady":
        p["cycles_ru"] = ru_count(p["cycles"], "цикл", "цикла", "циклов")
    elif code in ("values_per_s", "values_per_position"):
        p["n_values_ru"] = ru_count(p["n"], *_VALUES)
    elif code == "shafts_count":
        p["shafts_ru"] = ru_count(p["shafts"], "вал", "вала", "валов")
    elif code == "var_no_new_combination":
        p["draws_ru"] = ru_count(p["draws"], "попытку", "попытки", "попыток")
    return p


_PARAM_HOOKS.append(_msgs_plural_ru_params)
_MSGS_DERIVED |= {"cycles_ru", "n_values_ru", "shafts_ru", "draws_ru"}


# --- msgs_safe_out ---
# io/output.py: output folders that cannot reach outside themselves (issue 23, item 1).
MESSAGES_RU.update({
    "out_manifest_untrusted": ("{target}: {manifest} — не тот, что flywheel записал для этой "
                               "папки (изменён, написан вручную или прежней версией flywheel): "
                               "перечисленные в нём файлы считаются вашими, ни один не заменён "
                               "и не удалён"),
    "out_user_kept": "{target}: ваши файлы там, куда этот запуск пишет свои, сохранены: {files_ru}",
    "out_restored": ("{target}: папка восстановлена такой, какой была до запуска, прерванного "
                     "посреди замены файлов"),
    "out_restore_failed": ("--out {target}: запуск, прерванный посреди замены файлов, оставил "
                           "прежние файлы в {tmp}, и вернуть их не удаётся ({reason_ru}); "
                           "верните их вручную или укажите другую папку"),
})


def _msgs_safe_out_ru_params(code: str, p: dict) -> dict:
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


_PARAM_HOOKS.append(_msgs_safe_out_ru_params)
_MSGS_DERIVED |= {"files_ru", "reason_ru"}

# --- msgs_safe_grade ---
# flywheel grade's refusals of issue 23 (teaching/grading.py, cli/teaching.py) in Russian: an
# output over an input, --tolerance too large, a key nested too deep or with too long a number,
# a sheet whose encoding cannot be trusted; and variants' --sheets-format without --sheets.
_GRADE_INPUTS_RU = {"the answer key": "ключ ответов", "the answer sheet": "лист ответов"}
MESSAGES_RU.update({
    "grade_output_is_input": ("{option} {path}: это {what_ru} {given} (flywheel grade никогда не "
                              "записывает поверх своих входных файлов; допустимо: другое имя "
                              "файла)"),
    "grade_outputs_same": ("{option} {path} и {other} {there}: один и тот же файл (допустимо: "
                           "два разных имени файла)"),
    "grade_tolerance_too_large": ("--tolerance: {got} — слишком большой допуск (допустимо: "
                                  "0 < допуск ≤ 1, относительная погрешность: 0,01 — это 1 %)"),
    "sheets_format_without_sheets": ("--sheets-format {got}: задан без --sheets (он задаёт "
                                     "формат листов заданий; допустимо: --sheets "
                                     "--sheets-format ФОРМАТ или ни то, ни другое)"),
    "key_too_deep": ("{path}: слишком глубокая вложенность [] и {{}}: уровней — {depth} "
                     "(допустимо: не более {top})"),
    "key_too_deep_at": ("{path}: слишком глубокая вложенность [] и {{}} (допустимо: не более "
                        "{top} уровней)"),
    "key_number_too_long": ("{path}: слишком длинное число: цифр — {digits} (допустимо: не "
                            "более {top})"),
    "sheet_stray_byte": ("текст в кодировке Windows-1251 с лишним байтом {byte} на позиции "
                         "{at} (такого символа в Windows-1251 нет: лист прочитался бы искажённым "
                         "или не прочитался бы вовсе; допустимо: лист, заново сохранённый "
                         "в UTF-8 или Windows-1251)"),
    "run_problems_cut": ("… и ещё замечаний до этого листа включительно, не перечисленных: {n} "
                         "(не более {top} за один запуск; проверяйте листы частями)"),
    "sheet_undecodable": ("не текст в кодировке {codec} на позиции {at} (кодировка определена "
                          "по началу листа; допустимо: одна кодировка на весь лист: UTF-8, "
                          "Windows-1251, cp866, koi8-r)"),
})


def _msgs_safe_grade_ru_params(code: str, p: dict) -> dict:
    if code == "grade_output_is_input":
        p["what_ru"] = _GRADE_INPUTS_RU.get(p["what"], p["what"])
    return p


_PARAM_HOOKS.append(_msgs_safe_grade_ru_params)
_MSGS_DERIVED |= {"what_ru"}

# --- msgs_bounds ---
# The limits of the work (issue 23) in Russian: too many items, text too long, nesting too deep,
# integers too long, cycles and orders that do not repeat, report angles out of range.
_BOUNDS_ITEMS_RU = {"points": ("точку", "точки", "точек"), "terms": ("член", "члена", "членов"),
                    "orders": ("порядок", "порядка", "порядков"),
                    "angles": ("угол", "угла", "углов"),
                    "areas": ("площадь", "площади", "площадей"),
                    "energies": ("энергию", "энергии", "энергий")}


def _bounds_num_ru(x) -> str:
    """A number as a Russian line writes it: decimal comma, true minus (−1e+06 → −1e+06)."""
    text = f"{x:g}" if isinstance(x, float) else str(x)
    return text.replace(".", ",").replace("-", "−")


MESSAGES_RU.update({
    "too_many_items": "{count_items_ru} — слишком много (допустимо не больше {most})",
    "pydantic_string_too_long": ("слишком длинная строка: допустимо не больше {max_length} "
                                 "символов{got_ru}"),
    "doc_too_deep": ("{path}: {where_at_ru}таблицы и массивы вложены слишком глубоко "
                     "(допустимо не больше {most} уровней)"),
    "doc_number_too_long": ("{path}: {where_at_ru}слишком длинное целое число (допустимо: "
                            "{lo_ru} … {hi_ru}, 64-битные целые TOML; большее число запишите "
                            "как дробное, например 1e30)"),
    "cycle_out_of_range": ("{cycle_ru}° вне допустимого диапазона (допустимо: 360, 720, 1080 … "
                           "{top}°)"),
    "t2_cycle_not_whole": ("{cycle_ru}° — ни целое число оборотов, ни целая доля оборота "
                           "(допустимо: 360, 720, 1080 … 36000° или 180, 120, 90 … — диаграмма, "
                           "повторяющаяся за оборот)"),
    "t2_order_not_periodic": ("порядок {k_ru} не повторяется за цикл {cycle_ru}° (допустимо: "
                              "целые кратные 360/cycle_deg = {step_ru})"),
    "nf_moment_size": "размер момента ∮|M| dφ переполняется",
    "t2_graphs_too_big": ("вместе с графиком движущего момента: {pieces} участков × {terms} "
                          "гармоник — слишком большая работа (допустимо: участки × (1 + "
                          "гармоники) ≤ {most_ru}; задайте меньше точек или меньше гармоник)"),
    "at_too_many": "--at: {count_angles_ru} — слишком много (допустимо не больше {most})",
    "at_out_of_range": ("--at: {a_ru}° вне допустимого диапазона (допустимо: {lo_ru} … {hi_ru}°, "
                        "угол берётся по модулю цикла)"),
})


def _msgs_bounds_ru_params(code: str, p: dict) -> dict:
    if code == "too_many_items":
        p["count_items_ru"] = ru_count(p["count"], *_BOUNDS_ITEMS_RU.get(
            p["items"], ("элемент", "элемента", "элементов")))
    elif code == "at_too_many":
        p["count_angles_ru"] = ru_count(p["count"], *_BOUNDS_ITEMS_RU["angles"])
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


_PARAM_HOOKS.append(_msgs_bounds_ru_params)
_MSGS_DERIVED |= {"count_items_ru", "count_angles_ru", "where_at_ru", "cycle_ru", "k_ru", "most_ru",
                  "step_ru", "a_ru", "lo_ru", "hi_ru"}
