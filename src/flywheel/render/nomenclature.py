"""The nomenclature: every quantity flywheel prints, once — key → symbol, unit, English and
Russian name. CSV headers, plot axes and legends, the rich summary and the report take their
names from here; the renderers keep only sentence templates.

The commands other than ``run`` (task2, aggregate) and the plots take their row labels and
headings from the same table (the block marked ``--- nom``); their labels and sentences that
have no symbol and no unit are entries of the catalogue (locale/ru/LC_MESSAGES/flywheel.po,
msgctxt "term:<key>") that :func:`term` finds like the others. A name may be a template with
``{fields}`` that :func:`name` fills. Every other sentence (warnings, errors, prefixes) is the
catalogue's too (render/messages.py).

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

import re
from dataclasses import dataclass

from flywheel.dynamics.loads import LoadKey
from flywheel.io.text import in_language
from flywheel.render.numbers import typeset_params


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
    "cycle_time": _t("T_ц", r"$T_ц$", "s", "cycle time", "время цикла", "T_c", r"$T_c$"),
    # loads and works
    "cycle_work_resistance": _t("A_С", r"$A_С$", "J", "work of the resistance over a cycle A_C",
                                "работа сил сопротивления за цикл A_С", "A_C", "$A_C$"),
    "driving_moment": _t("M_Д", r"$M_Д$", "N·m", "driving moment M_D (cycle mean)",
                         "приведённый движущий момент M_Д", "M_D", "$M_D$"),
    "M_C": _t("M_С", r"$M_С$", "N·m", "reduced moment of the resistance M_C",
              "приведённый момент сил сопротивления M_С", "M_C", "$M_C$"),
    "cycle_work_driving": _t("A_Д", r"$A_Д$", "J", "work of the driving forces over a cycle A_D",
                             "работа движущих сил за цикл A_Д", "A_D", "$A_D$"),
    "resistance_moment": _t("M_С", r"$M_С$", "N·m",
                            "moment of the resistance M_C (constant, from the cycle condition)",
                            "приведённый момент сил сопротивления M_С (постоянный, из условия "
                            "цикла)", "M_C", "$M_C$"),
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
    # the course's ΔT_нб («наибольшее»); English writes its subscript in English, ΔT_max
    "delta_T_max": _t("ΔT_нб", r"$\Delta T_{нб}$", "J", "largest energy fluctuation ΔT_max",
                      "наибольшее изменение кинетической энергии ΔT_нб", "ΔT_max",
                      r"$\Delta T_{max}$"),
    "delta_T_I_max": _t("ΔT_I max", r"$\Delta T_{I\,max}$", "J", "ΔT_I, greatest",
                        "ΔT_I, наибольшее"),
    "delta_T_I_min": _t("ΔT_I min", r"$\Delta T_{I\,min}$", "J", "ΔT_I, least", "ΔT_I, наименьшее"),
    "phi_delta_T_I_max_deg": _t("φ", r"$\varphi$", "deg", "φ of ΔT_I max", "φ при ΔT_I max"),
    "phi_delta_T_I_min_deg": _t("φ", r"$\varphi$", "deg", "φ of ΔT_I min", "φ при ΔT_I min"),
    "T0": _t("T₀", "$T_0$", "J", "total kinetic energy at φ = 0",
             "полная кинетическая энергия при φ = 0", "T0"),
    # flywheel
    "delta": _t("δ", r"$\delta$", "-", "target δ", "заданный коэффициент неравномерности δ"),
    "J_first_group": _t("J_10 + J_ред", r"$J_{10} + J_{ред}$", "kg·m²", "already on the crank shaft",
                        "уже на валу кривошипа (J_10 + J_ред)", "J_10 + J_red", r"$J_{10} + J_{red}$"),
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
    "flywheel_material_density": _t("ρ", r"$\rho$", "kg/m³", "density of the flywheel material",
                                    "плотность материала маховика"),
    "flywheel_rim_speed_limit": _t("v_доп", r"$v_{доп}$", "m/s", "rim speed ≤",
                                   "окружная скорость ≤", "v_max", r"$v_{max}$"),
    "D": _t("D", "$D$", "m", "outer diameter", "наружный диаметр"),
    "D_inner": _t("D₁", "$D_1$", "m", "inner diameter of the rim", "внутренний диаметр обода",
                  "D1"),
    "b": _t("b", "$b$", "m", "width", "ширина"),
    "mass": _t("m", "$m$", "kg", "mass", "масса"),
    "rim_speed": _t("v", "$v$", "m/s", "rim speed", "окружная скорость обода"),
    "disk_speed": _t("v", "$v$", "m/s", "peripheral speed", "окружная скорость на наружном диаметре"),
    # true motion
    "omega": _t("ω", r"$\omega$", "rad/s", "crank angular velocity ω",
                "угловая скорость звена приведения ω"),
    "epsilon": _t("ε", r"$\varepsilon$", "rad/s²", "crank angular acceleration ε",
                  "угловое ускорение звена приведения ε"),
    "omega_exact": _t("ω", r"$\omega$", "rad/s", "ω with the exact flywheel size",
                      "ω при точном моменте инерции маховика"),
    "omega_max": _t("ω_max", r"$\omega_{max}$", "rad/s", "greatest angular velocity ω_max",
                    "наибольшая угловая скорость ω_max"),
    "omega_min": _t("ω_min", r"$\omega_{min}$", "rad/s", "least angular velocity ω_min",
                    "наименьшая угловая скорость ω_min"),
    "phi_omega_max_deg": _t("φ", r"$\varphi$", "deg", "φ of ω_max", "φ при ω_max"),
    "phi_omega_min_deg": _t("φ", r"$\varphi$", "deg", "φ of ω_min", "φ при ω_min"),
    "t": _t("t", "$t$", "s", "time t(φ)", "время t(φ)"),
    # --transients (summary.json results.time_domain)
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
    "vq_signed": _t("v_q", r"$|v_q|$, ползуны $v_q$ (+ от внешней м. т.)", "m/rad",
                    "|v_q| of the points, v_q of the sliders signed",
                    "аналоги скорости точек |v_q| и ползунов v_q со знаком", "v_q",
                    r"$|v_q|$, sliders $v_q$ (+ from outer d. c.)"),
    "aq_signed": _t("a_q", r"$|a_q|$, ползуны $a_q$ (+ от внешней м. т.)", "m/rad²",
                    "|a_q| of the points, a_q of the sliders signed",
                    "аналоги ускорения точек |a_q| и ползунов a_q со знаком", "a_q",
                    r"$|a_q|$, sliders $a_q$ (+ from outer d. c.)"),
    "aqx_{point}": _t("a_qx", "$a_{qx}$", "m/rad²", "a_qx of {x}", "a_qx точки {x}"),
    "aqy_{point}": _t("a_qy", "$a_{qy}$", "m/rad²", "a_qy of {x}", "a_qy точки {x}"),
    "theta_{link}": _t("θ", r"$\theta$", "deg", "angle of link {x}", "угол звена {x}"),
    "omega_q_{link}": _t("ω_q", r"$\omega_q$", "-", "ω_q of link {x}",
                         "аналог угловой скорости звена {x}"),
    "eps_q_{link}": _t("ε_q", r"$\varepsilon_q$", "1/rad", "ε_q of link {x}",
                       "аналог углового ускорения звена {x}"),
    # at a report angle (summary.json results.at[])
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
    "M_y_groups": _t("M_угр", r"$M_{угр}$", "N·m",
                     "balancing moment of the Assur groups M_y,gr (without the first group's "
                     "inertia)", "уравновешивающий момент групп Ассура M_угр (без инерции первой "
                     "группы)", "M_y,gr", r"$M_{y,gr}$"),
    "first_group_torque": _t("−J_I·ε", r"$-J_I\varepsilon$", "N·m",
                             "inertia torque of the first group (flywheel) −J_I·ε",
                             "момент сил инерции первой группы (маховика) −J_I·ε"),
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
    # issue 24: a motion from rest ([start]) and ε at a stated angle and speed (--snapshot)
    "start": _t("", "", "-", "motion from a stated state ([start])",
                "движение из заданного состояния ([start])"),
    "snapshots": _t("", "", "-", "angular acceleration at a stated angle and speed",
                    "угловое ускорение при заданных угле и скорости"),
    "at_travel": _t("", "", "-", "crank angles of a stated slider travel",
                    "углы кривошипа при заданном перемещении ползуна"),
    "roots": _t("", "", "-", "crank angles where a quantity changes sign",
                "углы кривошипа, при которых величина меняет знак"),
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
    # the output link of the last group (results.output_link; linkage/output_link.py)
    "output_link": _t("", "", "-", "output link: extreme positions, time ratio, transmission angle",
                      "выходное звено: крайние положения, коэффициент K, угол передачи"),
    "swing_deg": _t("ψ", r"$\psi$", "deg", "swing of the rocker", "угол размаха коромысла"),
    "output_stroke": _t("H", "$H$", "m", "stroke of the slider", "ход ползуна"),
    "time_ratio_K": _t("K", "$K$", "-", "time ratio (working/return stroke crank angles)",
                       "коэффициент изменения средней скорости хода"),
    "transmission_angle_min_deg": _t("γ_min", r"$\gamma_{min}$", "deg",
                                     "least transmission angle", "наименьший угол передачи"),
    "phi_transmission_angle_min_deg": _t("φ", r"$\varphi$", "deg",
                                         "crank angle of the least transmission angle",
                                         "угол поворота кривошипа при наименьшем угле передачи"),
    # the kinematics alone (dynamics/kinematics_only.py): true values on the grid at ω_m
    "v_{point}": _t("v", "$v$", "m/s", "velocity of {x}", "скорость точки {x}"),
    "a_{point}": _t("a", "$a$", "m/s²", "acceleration of {x}", "ускорение точки {x}"),
    "omega_{link}": _t("ω", r"$\omega$", "rad/s", "angular velocity of link {x}",
                       "угловая скорость звена {x}"),
    "eps_{link}": _t("ε", r"$\varepsilon$", "rad/s²", "angular acceleration of link {x}",
                     "угловое ускорение звена {x}"),
    "analysis": _t("", "", "", "what was computed", "что рассчитано"),
    # --- flywheel ---  (the designed rim, [flywheel.rim]: results.flywheel_rim)
    "D_mean": _t("D_ср", r"$D_{ср}$", "m", "mean diameter of the rim", "средний диаметр обода",
                 "D_m", "$D_m$"),
    "thickness": _t("t", "$t$", "m", "radial thickness of the rim", "толщина обода"),
    "width": _t("b", "$b$", "m", "width of the rim", "ширина обода"),
    "stress": _t("σ", r"$\sigma$", "Pa", "hoop stress of the rim ρ·v²",
                 "напряжение в ободе ρ·v²"),
    "share": _t("k_об", r"$k_{об}$", "-", "share of J carried by the rim", "доля J на ободе",
                "k_rim", r"$k_{rim}$"),
    "rim_area": _t("A", "$A$", "m²", "cross-section of the rim b·t",
                   "площадь сечения обода b·t"),
    "rim_mass_designed": _t("m_об", r"$m_{об}$", "kg", "mass of the rim k_rim·J/R²",
                            "масса обода k_об·J/R²", "m_rim", r"$m_{rim}$"),
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
    "plan_length": _t("", "", "mm", "length on the drawing", "длина на чертеже"),
    # --- end plans ---
    # --- nom: task2 and aggregate (were render/nomenclature_ci.py), the engine's and the force
    # analysis's plot labels (were inline in render/plots_engine.py, render/plots_forces.py).
    # Names may be templates with {fields} (name(key, lang, **fields) fills them); text handed
    # to rich in a table title keeps its square brackets escaped (\\[). Keys the table above
    # already had for another meaning carry the prefix t2_ (task 2's row labels).
    # -- quantities of task 2 ----------------------------------------------------------------
    "t2_J": _ci("J", "kg·m²", "reduced moment of inertia J", "приведённый момент инерции J_пр",
                "J_пр"),
    "omega0": _ci("ω₀", "rad/s", "initial angular velocity ω₀ (at φ = 0)",
                  "начальная угловая скорость ω₀ (при φ = 0)"),
    # English subscripts in English (ω_m, ΔT_max, T_c), as the run's; Russian the course's
    "t2_omega_mean": _ci("ω_m", "rad/s", "mean angular velocity ω_m = (ω_max + ω_min)/2",
                         "средняя угловая скорость ω_ср = (ω_max + ω_min)/2", "ω_ср"),
    "t2_delta": _ci("δ", "", "coefficient of speed fluctuation δ = (ω_max − ω_min)/ω_m",
                    "коэффициент неравномерности хода δ = (ω_max − ω_min)/ω_ср"),
    "t2_delta_T_max": _ci("ΔT_max", "J", "greatest change of kinetic energy ΔT_max = A_max − A_min",
                          "наибольшее изменение кинетической энергии ΔT_нб = A_max − A_min",
                          "ΔT_нб"),
    "t2_P": _ci("P", "W", "power = mean M_D · ω_m", "мощность = среднее M_Д · ω_ср"),
    "t2_J_required": _ci("J", "kg·m²", "J for δ = {delta}", "J_пр для δ = {delta}", "J_пр"),
    "rim_mass": _ci("m", "kg", "rim mass at R = {R} m", "масса обода при R = {R} м"),
    "t2_M_D": _ci("M_D", "N·m", "M_D", "M_Д", "M_Д"),
    "t2_M_C": _ci("M_C", "N·m", "M_C", "M_С", "M_С"),
    "t2_A": _ci("A", "J", "A", "A"),
    "t2_omega": _ci("ω", "rad/s", "ω", "ω"),
    "t2_phi_deg": _ci("φ°", "deg", "φ°", "φ, °"),
    "phi_pi": _ci("φ/π", "", "φ/π", "φ/π"),
    "row_no": _ci("", "", "#", "№"),      # a terminal table's row number (a record's: «№»)
    "rpm": _ci("n", "rpm", "{n} rpm", "{n} об/мин"),
    "angle": _ci("φ", "deg", "φ = {deg}° ({pi} rad)", "φ = {deg}° ({pi} рад)"),
    # --- flywheel (task2's designed rim; were in render/nomenclature_ci.py) ---
    "rim_design_dims": _ci("", "m", "D_mean = {D}, t = {t}, b = {b} m; m = {m} kg",
                           "D_ср = {D}, t = {t}, b = {b} м; m = {m} кг"),
    # -- task 2: angular acceleration and time (shown with --epsilon or --at) -------------------
    "t2_epsilon": _ci("ε", "rad/s²", "ε", "ε"),
    "t2_epsilon_max": _ci("ε_max", "rad/s²", "ε_max (largest over the cycle)",
                         "ε_max (наибольшее за цикл)"),
    "t2_epsilon_min": _ci("ε_min", "rad/s²", "ε_min (smallest over the cycle)",
                         "ε_min (наименьшее за цикл)"),
    "t2_cycle_time": _ci("T_c", "s", "cycle time ∫₀^Φ dφ/ω", "время цикла ∫₀^Φ dφ/ω", "T_ц"),
    "t2_energy_fluctuation_coefficient": _ci("C_E", "", "C_E = ΔT_max / work per cycle",
                                               "C_E = ΔT_нб / работа за цикл"),
    "phi_from": _ci("φ", "deg", "from φ°", "от φ, °"),
    "phi_to": _ci("φ", "deg", "to φ°", "до φ, °"),
    "t_start": _ci("t", "s", "t at start \\[s]", "t в начале, с"),
    "duration": _ci("Δt", "s", "duration \\[s]", "длительность, с"),
    "t2_t": _ci("t", "s", "t \\[s]", "t, с"),
    "phi_col": _ci("φ", "deg", "φ°", "φ, °"),
    "omega_col": _ci("ω", "rad/s", "ω \\[rad/s]", "ω, рад/с"),
    "epsilon_col": _ci("ε", "rad/s²", "ε \\[rad/s²]", "ε, рад/с²"),
    "t2_flywheel_mass": _ci("m", "kg", "mass at k = {k} m", "масса при k = {k} м"),
    # -- task 2: the plot ----------------------------------------------------------------------
    "t2_plot_epsilon": _ci("ε", "rad/s²", "ε(φ) = (M_D − M_C)/J", "ε(φ) = (M_Д − M_С)/J_пр"),
    "t2_plot_epsilon_axis": _ci("ε", "rad/s²", "ε [rad/s²]", "ε, рад/с²"),
    "t2_plot_epsilon_max": _ci("ε_max", "rad/s²", "ε_max = {value} rad/s² at {deg}°",
                                 "ε_max = {value} рад/с² при {deg}°"),
    "t2_plot_epsilon_min": _ci("ε_min", "rad/s²", "ε_min = {value} rad/s² at {deg}°",
                                 "ε_min = {value} рад/с² при {deg}°"),
    "t2_plot_omega_max": _ci("ω_max", "rad/s", "ω_max = {value} rad/s at {deg}°",
                               "ω_max = {value} рад/с при {deg}°"),
    "t2_plot_omega_min": _ci("ω_min", "rad/s", "ω_min = {value} rad/s at {deg}°",
                               "ω_min = {value} рад/с при {deg}°"),
    "t2_plot_MD": _ci("M_D", "N·m", "M_D (driving)", "M_Д (движущий)", "M_Д"),
    "t2_plot_MC": _ci("M_C", "N·m", "M_C (resistance)", "M_С (сопротивления)", "M_С"),
    "t2_plot_moment": _ci("M", "N·m", "moment [N·m]", "момент, Н·м"),
    "t2_plot_A": _ci("A", "J", "A(φ) = ∫(M_D − M_C) dφ", "A(φ) = ∫(M_Д − M_С) dφ"),
    "t2_plot_A_axis": _ci("A", "J", "A [J]", "A, Дж"),
    "t2_plot_omega": _ci("ω", "rad/s", "ω(φ)", "ω(φ)"),
    "t2_plot_omega_mean": _ci("ω_ср", "rad/s", "ω_ср", "ω_ср"),
    "t2_plot_omega_axis": _ci("ω", "rad/s", "ω [rad/s]", "ω, рад/с"),
    "t2_plot_phi_axis": _ci("φ", "deg", "φ [deg]", "φ, °"),
    # -- aggregate: the model ------------------------------------------------------------------
    "J_reduced": _ci("J", "kg·m²", "J_reduced [kg·m²]", "J_пр, кг·м²", "J_пр"),
    "u": _ci("u", "", "u", "u"),
    "c": _ci("c", "N·m/rad", "c [N·m/rad]", "жёсткость c, Н·м/рад"),
    "damping": _ci("b", "N·m·s/rad", "damping [N·m·s/rad]", "демпфирование, Н·м·с/рад"),
    "a_ij": _ci("a_ij", "kg·m²", "inertia coefficients a_ij", "инерционные коэффициенты a_ij"),
    "c_ij": _ci("c_ij", "N·m/rad", "stiffness coefficients c_ij", "коэффициенты жёсткости c_ij"),
    # -- aggregate: modes, nodes and shafts (shown with --modes) -------------------------------
    "rpm_col": _ci("n", "rpm", "n [vib/min]", "n [кол/мин]"),
    "node_dist": _ci("", "m", "{d} m from {a}, ", "{d} м от {a}, "),
    "gear_ratio": _ci("i", "", "gear i", "передача i"),
    "c_input": _ci("c", "N·m/rad", "c (input side) [N·m/rad]", "c (со стороны входа), Н·м/рад"),
    "length": _ci("L", "m", "length [m]", "длина [м]"),
    "equivalent_length": _ci("L_eq", "m", "L_eq [m]", "L_прив [м]"),
    "d_ref": _ci("d", "m", "at d [m]", "при d [м]"),
    # -- aggregate: natural frequencies, resonance -----------------------------------------------
    "omega_n": _ci("ω", "rad/s", "ω [rad/s]", "ω, рад/с"),
    "f_n": _ci("f", "Hz", "f [Hz]", "f, Гц"),
    "f_n_col": _ci("f_n", "Hz", "f_n [Hz]", "f_n, Гц"),
    # -- aggregate: steady state and start-up ------------------------------------------------------
    "twist_mean": _ci("q2", "rad", "twist q2 = φ2 − φ1, mean",
                        "угол закручивания q2 = φ2 − φ1, среднее"),
    "twist_amp": _ci("q2", "rad", "twist q2, amplitude", "угол закручивания q2, амплитуда"),
    "moment_mean": _ci("M_у", "N·m", "elastic moment c·(φ1 − φ2) = −c·q2, mean",
                         "упругий момент c·(φ1 − φ2) = −c·q2, среднее"),
    "moment_amp": _ci("M_у", "N·m", "elastic moment −c·q2, amplitude",
                        "упругий момент −c·q2, амплитуда"),
    "omega_motor": _ci("ω1", "rad/s", "ω1 (motor) min … max",
                         "ω1 двигателя, наименьшая … наибольшая"),
    "delta_motor": _ci("δ", "", "δ motor", "δ двигателя"),
    "omega_machine": _ci("ω2", "rad/s", "ω2 (machine, own shaft) min … max",
                           "ω2 машины (на своём валу), наименьшая … наибольшая"),
    "delta_machine": _ci("δ", "", "δ machine", "δ машины"),
    "startup_peak": _ci("", "N·m", "start-up: peak elastic moment",
                          "пуск: наибольший упругий момент"),
    "startup_over": _ci("", "s", "over {t} s", "за {t} с"),
    "startup_time": _ci("t", "s", "start-up: time to 95 % of ω1", "пуск: время до 95 % ω1"),
    # -- aggregate: the plot ---------------------------------------------------------------------
    "ag_plot_omega1": _ci("ω1", "rad/s", "ω1, {name}", "ω1, {name}"),
    "ag_plot_omegaN": _ci("ω", "rad/s", "ω{n}, {name} (reduced to shaft I)",
                            "ω{n}, {name} (приведена к валу I)"),
    "ag_plot_omega_axis": _ci("ω", "rad/s", "ω [rad/s]", "ω, рад/с"),
    "ag_plot_moment": _ci("M_у", "N·m", "elastic moment c·(φ1 − φ2) = −c·q2",
                            "упругий момент c·(φ1 − φ2) = −c·q2"),
    "ag_plot_moment_axis": _ci("M", "N·m", "moment [N·m]", "момент, Н·м"),
    "ag_plot_t_axis": _ci("t", "s", "t [s]", "t, с"),
    # -- the four-stroke indicator diagram (render/plots_engine.py) ---------------------------
    "engine_s_axis": _ci("s", "", "relative piston travel s from the head",
                         "относительное перемещение поршня s от головки"),
    "engine_p_axis": _ci("p/p_max", "", "p / p_max", "p / p_max"),
    "engine_p_MPa": _ci("p", "MPa", "p, MPa (gauge)", "p, МПа (избыточное)"),
    "engine_phi": _ci("φ", "deg", "crank angle φ [deg]", "угол поворота кривошипа φ, °"),
    "engine_fires": _ci("", "deg", "fires at {a:.1f}°", "воспламенение при {a:.1f}°"),
    # (the labels and sentences without a symbol or a unit: the catalogue, "term:<key>", below)
}

# the load names inside "M {load}": "gas HP", "gravity 2", "force punch", "couple c", "moment m",
# "spring s"
LOAD_KINDS = {"gas": ("gas {x}", "газ {x}"), "gravity": ("gravity, link {x}", "сила тяжести звена {x}"),
              "force": ("force {x}", "сила {x}"), "couple": ("couple {x}", "пара сил {x}"),
              "moment": ("moment {x}", "момент {x}"), "spring": ("spring {x}", "пружина {x}")}

# the kinds of Assur groups of class II by their pairs: R revolute, P prismatic; in Russian
# В (вращательная) and П (поступательная), as Артоболевский, «Теория механизмов и машин», ч. 2
DYAD_KINDS = {"RRR": ("RRR", "ВВВ"), "RRP": ("RRP", "ВВП"), "RPR": ("RPR", "ВПВ")}


def dyad_kind(kind: str, lang: str = "en") -> str:
    """An Assur group's kind in ``lang``: "RRP" → «ВВП» in Russian; a kind not listed as it
    is."""
    return DYAD_KINDS[kind][lang == "ru"] if kind in DYAD_KINDS else kind


# the sliders' dead centres in the standard positions' labels ("90° = 5 outer d.c."), as
# dynamics.grid.standard_positions writes them in English
DEAD_CENTRES = {"outer": ("outer", "внешняя"), "inner": ("inner", "внутренняя")}

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


def load_name(x, lang: str = "en", titles=None, labels=None) -> str:
    """A load's name in ``lang`` from its key (:class:`~flywheel.dynamics.loads.LoadKey`, or its
    text "kind name" as a column's family member gives it): gas HP → "газ HP", gravity 2 →
    "gravity, link 2"; a key of no known kind as its text; a load the case titles (``titles``:
    LoadsResult.titles) by its title; a cylinder the case labels (``labels``:
    LoadsResult.labels) by its label, gas HP → "газ ВД".

    >>> load_name(LoadKey("gravity", "2"), "ru")
    'сила тяжести звена 2'
    """
    key = x if isinstance(x, LoadKey) else LoadKey.parse(x)
    if titles and key in titles:              # the case's own title of the load (LoadsResult.titles)
        return in_language(titles[key], lang)
    if key.kind in LOAD_KINDS and key.name:
        called = in_language(labels[key], lang) if labels and key in labels else key.name
        return LOAD_KINDS[key.kind][lang == "ru"].format(x=called)
    return str(x)


def member(key: str, lang: str = "en", titles=None, labels=None) -> str:
    """The family member of ``key`` in ``lang`` ("M gas HP" → "газ HP", "x_B" → "B"; "" for a
    key that is not a family's); a titled load by its title (``titles``: LoadsResult.titles), a
    labelled cylinder's gas by its label (``labels``: LoadsResult.labels)."""
    return load_name(term(key)[1], lang, titles, labels)


def indicator_stem(name: str) -> str:
    """The file stem of cylinder ``name``'s indicator diagram (plots/indicator_HP.png): the
    name's ASCII letters and digits, any other character '_'."""
    return "indicator_" + ("".join(ch if ch.isalnum() and ch.isascii() else "_" for ch in name)
                           or "cylinder")


def cylinder_label(cylinder, lang: str = "en") -> str:
    """A cylinder's short name in ``lang`` ("ВД" in «цилиндр ВД»): the case's ``label`` (a
    CylinderSpec's or a CylinderResult's), else its name."""
    return in_language(cylinder.label, lang) if cylinder.label else cylinder.name


def name(key: str, lang: str = "en", **fields) -> str:
    """The quantity's name in ``lang`` ("reduced moment: gas HP"); a template's ``{fields}``
    filled from ``fields`` (none given: the name as it is).

    >>> name("t2_balance", "ru", name="M_С", value="60", work="94.2478")
    'баланс работ за цикл ∮M_Д dφ = ∮M_С dφ даёт M_С = 60 Н·м (работа за цикл 94.2478 Дж)'
    >>> name("omega_max"), name("t2_J", "ru")
    ('greatest angular velocity ω_max', 'приведённый момент инерции J_пр')
    """
    t, x = term(key)
    template = t.ru if lang == "ru" else t.en
    if x:
        fields = {"x": load_name(x, lang), **fields}
    # within Russian typography (render/numbers.py) a real field as the one formatter writes it
    return template.format(**typeset_params(fields)) if fields else template


#: the two-mass model's rotors as English writes them (their names in summary.json keep the
#: course's J_Д and J_пр.I, cases/aggregate.py)
ROTORS_EN = {"rotor_motor": "motor J_D", "rotor_machine": "machine J_red.I"}


def rotor_name(rotor: str, lang: str = "en") -> str:
    """A rotor's name in ``lang`` (`flywheel aggregate`): the two-mass model's own names
    translate (English subscripts in English), a user's stay."""
    for key in ("rotor_motor", "rotor_machine"):
        if rotor == TERMS[key].en:
            return TERMS[key].ru if lang == "ru" else ROTORS_EN[key]
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
    (tests/render/test_nomenclature.py holds every figure to it); ``u`` as printed in ``lang`` already."""
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
    return f"{term(key)[0].tex(lang)}: {bare_name(key, lang)}"


def bare_name(key: str, lang: str = "en") -> str:
    """The name without its trailing symbol, for a table that prints the symbol in a column
    of its own («площадь среза» beside «A»; "work of the driving forces").

    >>> bare_name("energy_per_area", "ru"), bare_name("omega_max")
    ('удельная работа на единицу площади среза', 'greatest angular velocity')
    """
    nm = name(key, lang)
    sym = term(key)[0].sym(lang)
    return nm[: -len(sym) - 1] if sym and nm.endswith(" " + sym) else nm


def name_tex(key: str, lang: str = "en") -> str:
    """The name with its trailing plain symbol typeset (a figure's title: "reduced moment of
    inertia of the second group $J_{II}$")."""
    t, _ = term(key)
    nm, bare = name(key, lang), bare_name(key, lang)
    return f"{bare} {t.tex(lang)}" if bare != nm else nm


def material(m: str, lang: str = "en") -> str:
    """A flywheel material's name in ``lang`` ("cast-iron" → "cast iron", "чугун")."""
    return MATERIALS[m][lang == "ru"] if m in MATERIALS else m


def csv_header(key: str) -> str:
    """A CSV column header: ``name [unit]`` with the SI unit ("J_II [kg·m²]")."""
    return f"{key} [{si_unit(key)}]"


# -- the labels and sentences without a symbol or a unit: the catalogue -----------------------------
# (locale/ru/LC_MESSAGES/flywheel.po, msgctxt "term:<key>": English the msgid, Russian the msgstr)
def _catalogue_terms() -> dict[str, Term]:
    from flywheel.render.catalogue import _english, compiled_msgstrs

    russian = compiled_msgstrs("ru", "term:")
    return {ctx[5:]: Term("", "", "", en, russian[ctx])
            for ctx, en in _english().items() if ctx.startswith("term:")}


TERMS.update(_catalogue_terms())

#: what moved out of this module (the sentences: render/messages.py and the catalogue; the task
#: sheets' labels: render/sheet_labels.py), still found here by the old names
_MOVED = {"message": "messages", "prefix": "messages", "stage_name": "messages",
          "field_label": "sheet_labels", "field_value": "sheet_labels",
          "answer_words": "sheet_labels", "SHEET_VALUES": "sheet_labels",
          "SHEET_FIELDS": "sheet_labels", "SHEET_ANSWERS": "sheet_labels",
          "position_label": "positions", "position_cells": "positions"}


def __getattr__(attr: str):
    if attr in _MOVED:
        import importlib

        return getattr(importlib.import_module(f"flywheel.render.{_MOVED[attr]}"), attr)
    raise AttributeError(f"module {__name__!r} has no attribute {attr!r}")
