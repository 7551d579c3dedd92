"""The nomenclature: every quantity flywheel prints, once — key → symbol, unit, English and
Russian name. CSV headers, plot axes and legends, the rich summary and the report take their
names from here; the renderers keep only sentence templates.

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


@dataclass(frozen=True)
class Term:
    """One quantity: ``symbol`` (plain text, the course's), ``math`` (mathtext, for plots),
    ``unit`` (SI, English), ``en`` and ``ru`` (names; ``{x}`` stands for the family member),
    ``symbol_en`` (the English text's symbol where the course's subscript is Cyrillic)."""

    symbol: str
    math: str
    unit: str
    en: str
    ru: str
    symbol_en: str = ""

    def sym(self, lang: str) -> str:
        """The plain-text symbol in ``lang``."""
        return self.symbol_en if (lang == "en" and self.symbol_en) else self.symbol


def _t(symbol, math, unit, en, ru, symbol_en=""):
    return Term(symbol, math, unit, en, ru, symbol_en)


# -- the table ------------------------------------------------------------------------------------
TERMS: dict[str, Term] = {
    # crank, speed, cycle
    "phi_deg": _t("φ", r"$\varphi$", "deg", "crank angle φ", "угол поворота кривошипа φ"),
    "crank_length": _t("l₁", r"$l_1$", "m", "crank length l1", "длина кривошипа l₁", "l1"),
    "omega_mean": _t("ω_ср", r"$\omega_{ср}$", "rad/s", "mean angular velocity ω_m",
                     "средняя угловая скорость ω_ср", "ω_m"),
    "n_points": _t("N", "$N$", "-", "grid nodes over the cycle", "число узлов сетки по φ"),
    "cycle_time": _t("T_ц", r"$T_ц$", "s", "cycle time", "время цикла", "T_c"),
    # loads and works
    "cycle_work_resistance": _t("A_С", r"$A_С$", "J", "work of the resistance over a cycle A_C",
                                "работа сил сопротивления за цикл A_С", "A_C"),
    "driving_moment": _t("M_Д", r"$M_Д$", "N·m", "driving moment M_D (cycle mean)",
                         "приведённый движущий момент M_Д", "M_D"),
    "balancing_moment": _t("M_const", r"$M_{const}$", "N·m",
                           "constant moment from the cycle balance",
                           "постоянный момент из условия цикла"),
    "M_known": _t("M_изв", r"$M_{изв}$", "N·m", "sum of the given loads' reduced moments",
                  "суммарный приведённый момент заданных сил", "M_known"),
    "M_sum": _t("M_Σ", r"$M_\Sigma$", "N·m", "total reduced moment M_Σ",
                "суммарный приведённый момент M_Σ"),
    "M {load}": _t("M", "$M$", "N·m", "reduced moment: {x}", "приведённый момент: {x}"),
    "M_st": _t("M_ст", r"$M_{ст}$", "N·m", "static moment Мст = −Σ reduced moments of the "
               "loads (resisting positive)", "приведённый момент сил статического "
               "сопротивления M_ст"),
    "M_dyn": _t("M_дин", r"$M_{дин}$", "N·m", "dynamic moment Мдин = ω_m²/2·dJ_II/dφ",
                "динамический момент M_дин"),
    "A_D": _t("A_Д", r"$A_Д$", "J", "work of the driving moment A_D", "работа движущих сил A_Д",
              "A_D"),
    "A_C": _t("A_С", r"$A_С$", "J", "work of the resistance A_C", "работа сил сопротивления A_С",
              "A_C"),
    "A": _t("A", "$A$", "J", "total work A", "суммарная работа A"),
    "s_{cylinder}": _t("s", "$s$", "-", "relative piston travel from the head, {x}",
                       "относительное перемещение поршня от головки, {x}"),
    "p_{cylinder}": _t("p", "$p$", "Pa", "gas pressure, {x}", "давление газа, {x}"),
    "F_{load}": _t("F", "$F$", "N", "force {x}", "сила {x}"),
    # reduction of masses, energy
    "J_II": _t("J_II", r"$J_{II}$", "kg·m²", "reduced inertia of the second group J_II",
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
               "кинетическая энергия второй группы звеньев T_II"),
    "dT_I": _t("ΔT_I", r"$\Delta T_I$", "J", "change of kinetic energy of the first group ΔT_I",
               "изменение кинетической энергии первой группы звеньев ΔT_I"),
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
                     "момент инерции маховика J_М = J_I − (J_10 + J_ред)", "J_M"),
    "J_flywheel_exact": _t("J_М", "$J_М$", "kg·m²", "flywheel J_M, exact",
                           "момент инерции маховика J_М, точно", "J_M"),
    "delta_achieved": _t("δ", r"$\delta$", "-", "δ achieved with J_I (Merzalov)",
                         "достигнутый δ (Мерцалов)"),
    "delta_achieved_exact": _t("δ", r"$\delta$", "-", "δ achieved with the exact J_I",
                               "достигнутый δ (точный J_I)"),
    "flywheel_J_on_its_shaft": _t("J_М/i²", r"$J_М/i^2$", "kg·m²",
                                  "flywheel J on its own shaft, J_M/i²",
                                  "момент инерции маховика на его валу J_М/i²", "J_M/i²"),
    "flywheel_speed_ratio": _t("i", "$i$", "-", "flywheel shaft speed ratio i",
                               "передаточное отношение к валу маховика i"),
    "flywheel_rim_share": _t("k_об", r"$k_{об}$", "-", "rim share of J_M (hub and spokes the rest)",
                             "доля J_М на ободе (остальное — ступица и спицы)", "rim share"),
    "flywheel_material_density": _t("ρ", r"$\rho$", "kg/m³", "density of the flywheel material",
                                    "плотность материала маховика"),
    "flywheel_rim_speed_limit": _t("v_доп", r"$v_{доп}$", "m/s", "rim speed ≤",
                                   "окружная скорость ≤", "v_max"),
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
    # kinematics on the grid
    "x_{point}": _t("x", "$x$", "m", "x of {x}", "x точки {x}"),
    "y_{point}": _t("y", "$y$", "m", "y of {x}", "y точки {x}"),
    "vq_{point}": _t("v_q", "$v_q$", "m/rad", "|v_q| of {x}", "аналог скорости точки {x}"),
    "vqx_{point}": _t("v_qx", "$v_{qx}$", "m/rad", "v_qx of {x}", "v_qx точки {x}"),
    "vqy_{point}": _t("v_qy", "$v_{qy}$", "m/rad", "v_qy of {x}", "v_qy точки {x}"),
    "aq_{point}": _t("a_q", "$a_q$", "m/rad²", "|a_q| of {x}", "аналог ускорения точки {x}"),
    "aqx_{point}": _t("a_qx", "$a_{qx}$", "m/rad²", "a_qx of {x}", "a_qx точки {x}"),
    "aqy_{point}": _t("a_qy", "$a_{qy}$", "m/rad²", "a_qy of {x}", "a_qy точки {x}"),
    "theta_{link}": _t("θ", r"$\theta$", "deg", "angle of link {x}", "угол звена {x}"),
    "omega_q_{link}": _t("ω_q", r"$\omega_q$", "-", "ω_q of link {x}",
                         "аналог угловой скорости звена {x}"),
    "eps_q_{link}": _t("ε_q", r"$\varepsilon_q$", "1/rad", "ε_q of link {x}",
                       "аналог углового ускорения звена {x}"),
    # at a report angle (summary.json results.at[])
    "v_q": _t("v_q", "$v_q$", "m/rad", "velocity analogue", "аналог скорости"),
    "a_q": _t("a_q", "$a_q$", "m/rad²", "acceleration analogue", "аналог ускорения"),
    "v": _t("v", "$v$", "m/s", "velocity", "скорость"),
    "a": _t("a", "$a$", "m/s²", "acceleration", "ускорение"),
    "epsilon_q": _t("ε_q", r"$\varepsilon_q$", "1/rad", "angular acceleration analogue",
                    "аналог углового ускорения"),
    "omega_q": _t("ω_q", r"$\omega_q$", "-", "angular velocity analogue",
                  "аналог угловой скорости"),
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
    # end force analysis -----------------------------------------------------------------------
}

# the load names inside "M {load}": "gas HP", "gravity 2", "force punch", "couple c", "moment m"
LOAD_KINDS = {"gas": ("gas {x}", "газ {x}"), "gravity": ("gravity, link {x}", "сила тяжести звена {x}"),
              "force": ("force {x}", "сила {x}"), "couple": ("couple {x}", "пара сил {x}"),
              "moment": ("moment {x}", "момент {x}")}

# -- units ----------------------------------------------------------------------------------------
_UNIT_RU = {"m": "м", "kg": "кг", "s": "с", "rad": "рад", "N": "Н", "J": "Дж", "Pa": "Па",
            "MPa": "МПа", "W": "Вт", "kW": "кВт", "deg": "°", "rpm": "об/мин", "min": "мин",
            "Hz": "Гц", "h": "ч"}
_UNIT_EN_PRINT = {"deg": "°"}


def unit(u: str, lang: str = "en") -> str:
    """The unit as printed in ``lang``: SI tokens translated ("kg·m²/rad" → "кг·м²/рад"),
    "-" (dimensionless) as "–", degrees as "°"."""
    if u in ("-", ""):
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


def _member(x: str, lang: str) -> str:
    """A load's name in ``lang``: "gas HP" → "газ HP"; other members as they are."""
    kind, _, rest = x.partition(" ")
    if kind in LOAD_KINDS and rest:
        return LOAD_KINDS[kind][lang == "ru"].format(x=rest)
    return x


def name(key: str, lang: str = "en") -> str:
    """The quantity's name in ``lang`` ("reduced moment: gas HP")."""
    t, x = term(key)
    return (t.ru if lang == "ru" else t.en).format(x=_member(x, lang))


def symbol(key: str, lang: str = "en") -> str:
    """The plain-text symbol in ``lang`` (ω_m in English, ω_ср in Russian)."""
    return term(key)[0].sym(lang)


def unit_of(key: str, lang: str = "en") -> str:
    """The unit of ``key`` as printed in ``lang``."""
    return unit(term(key)[0].unit, lang)


def si_unit(key: str) -> str:
    """The unit of ``key`` as CSV headers and JSON write it (SI, English): "kg·m²"."""
    return term(key)[0].unit


def axis(key: str, lang: str = "en") -> str:
    """A plot axis label as the course writes it: mathtext symbol, comma, unit ("$J_{II}$, кг·м²")."""
    return f"{term(key)[0].math}, {unit_of(key, lang)}"


def csv_header(key: str) -> str:
    """A CSV column header: ``name [unit]`` with the SI unit ("J_II [kg·m²]")."""
    return f"{key} [{si_unit(key)}]"
