"""The task sheets' labels (`flywheel variants … --sheets`, render/sheets.py, which adds only
the sentence templates and the typesetting): the labels of a case file's input fields, the
words of their values and the answers worded as a task, by the field's dotted path. A field that
is a quantity of the nomenclature takes its name from there ("@key").
"""
from __future__ import annotations

import re

from flywheel.io.text import in_language
from flywheel.render.catalogue import words
from flywheel.render.mathfmt import point_name
from flywheel.dynamics.loads import LoadKey
from flywheel.render.nomenclature import (MATERIALS, TERMS, bare_name, load_name, name, symbol,
                                          unit_of)


#: input fields of a case file: a dotted-path pattern (``#`` an array index, ``*`` a name) →
#: (English, Russian) label; ``{x}`` is the element's name (a link, a cylinder, a point);
#: "@key" takes the name of the term ``key`` (the same quantity in the same words)
SHEET_FIELDS: list[tuple[str, str, str]] = [
    ("machine.speed_rps", "@crank_speed", ""),          # "@key": the nomenclature's name
    ("machine.speed_rpm", "@crank_speed", ""),
    ("machine.delta", "coefficient of speed fluctuation δ", "коэффициент неравномерности хода δ"),
    ("machine.gravity", "gravity g (x, y)", "ускорение свободного падения g (x; y)"),
    ("machine.cycle_deg", "cycle Φ", "цикл Φ"),
    ("machine.first_group.*", "J of the {x} (reduced to the crank)",
     "момент инерции {x} (приведённый к кривошипу)"),
    ("design.mean_piston_speed", "mean piston speed V_m", "средняя скорость поршня V_ср"),
    ("design.rod_to_crank", "rod to crank length ratio k", "отношение длин шатуна и кривошипа k"),
    ("crank.length", "@crank_length", ""),
    ("crank.pivot_at", "crank pivot (x, y)", "координаты опоры кривошипа (x; y)"),
    ("crank.start_angle_deg", "crank angle at φ = 0, from +x",
     "положение кривошипа при φ = 0 (от оси x)"),
    ("dyads.#.rod_length", "rod length, joint {x}", "длина шатуна, шарнир {x}"),
    ("dyads.#.length_from", "first link length, joint {x}", "длина первого звена, шарнир {x}"),
    ("dyads.#.length_to", "second link length, joint {x}", "длина второго звена, шарнир {x}"),
    ("dyads.#.offset", "slide line offset, joint {x}", "смещение линии ползуна, шарнир {x}"),
    ("dyads.#.guide.through", "guide of the slider at {x}: a point (x, y)",
     "направляющая ползуна в шарнире {x}: точка (x; y)"),
    ("dyads.#.guide.angle_deg", "guide of the slider at {x}: angle from +x",
     "направляющая ползуна в шарнире {x}: угол к оси x"),
    ("dyads.#.guide.offset", "guide of the slider at {x}: offset",
     "направляющая ползуна в шарнире {x}: смещение"),
    ("points.*.fraction", "point {x}: share of its link's length",
     "точка {x}: доля длины звена"),
    ("points.*.distance", "point {x}: distance along its link", "точка {x}: расстояние по звену"),
    ("points.*.across", "point {x}: offset across its link", "точка {x}: смещение поперёк звена"),
    ("links.*.mass", "mass of link {x} m_{x}", "масса звена {x} m_{x}"),
    ("links.*.J_S", "moment of inertia of link {x} about its centroid J_S{x}",
     "момент инерции звена {x} относительно центра масс J_S{x}"),
    # each cylinder's own symbols (seed 000: d2, p_max2 of cylinder 2): two cylinders' d and
    # p_max on one sheet are two quantities
    ("cylinders.#.bore", "bore of cylinder {x} d_{x}", "диаметр цилиндра {x} d_{x}"),
    ("cylinders.#.p_max", "maximum pressure in cylinder {x} p_max,{x}",
     "максимальное давление в цилиндре {x} p_max,{x}"),
    ("cylinders.#.s", "cylinder {x}: relative piston travel s",
     "цилиндр {x}: относительное перемещение поршня s"),
    ("cylinders.#.towards_head", "cylinder {x}: p/p_max, piston moving to the head",
     "цилиндр {x}: p/p_max при движении поршня к головке"),
    ("cylinders.#.away_from_head", "cylinder {x}: p/p_max, piston moving from the head",
     "цилиндр {x}: p/p_max при движении поршня от головки"),
    ("forces.#.magnitude", "force {x}: magnitude F", "сила {x}: модуль F"),
    ("forces.#.s_range", "force {x}: where it acts (relative travel)",
     "сила {x}: участок действия (отн. перемещение)"),
    # --- issue 24: loads over a part of the cycle, at points, springs ---
    ("forces.#.phi_range_deg", "force {x}: acts for φ from … to", "сила {x}: действует при φ от … до"),
    ("forces.#.angle_deg", "force {x}: direction from +x", "сила {x}: направление от оси x"),
    ("forces.#.table", "force {x}: table of F", "сила {x}: таблица F"),
    ("couples.#.moment", "couple {x}: moment M", "пара сил {x}: момент M"),
    ("couples.#.phi_range_deg", "couple {x}: acts for φ from … to",
     "пара сил {x}: действует при φ от … до"),
    ("couples.#.table", "couple {x}: table of M against φ", "пара сил {x}: таблица M по φ"),
    ("springs.#.stiffness", "spring {x}: stiffness c", "пружина {x}: жёсткость c"),
    ("springs.#.free_length", "spring {x}: free length L0", "пружина {x}: длина в свободном состоянии L0"),
    ("springs.#.preload", "spring {x}: preload (tension > 0)",
     "пружина {x}: предварительное усилие (растяжение > 0)"),
    ("springs.#.preload_at_deg", "spring {x}: preload at φ", "пружина {x}: предварительное усилие при φ"),
    ("springs.#.free_angle_deg", "spring {x}: free angle of its link θ0",
     "пружина {x}: угол звена в свободном состоянии θ0"),
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
    ("ground.*", "fixed point {x} (x, y)", "неподвижная точка {x} (x; y)"),
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
    # --- issue 24: a measured indicator diagram ---
    ("cylinders.#.indicator.tdc_offset_deg", "cylinder {x}: angle of the firing dead centre "
     "in the pressure trace", "цилиндр {x}: угол мёртвой точки вспышки в записи давления"),
    ("cylinders.#.indicator.atmosphere", "atmospheric pressure", "атмосферное давление"),
    ("cylinders.#.indicator.x", "cylinder {x}: indicator diagram, crank angle, volume or travel",
     "цилиндр {x}: индикаторная диаграмма, угол, объём или перемещение"),
    ("cylinders.#.indicator.p", "cylinder {x}: indicator diagram, pressure p",
     "цилиндр {x}: индикаторная диаграмма, давление p"),
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
    ("flywheel.delta", "allowed coefficient of speed fluctuation [δ]",
     "допускаемый коэффициент неравномерности хода [δ]"),
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

#: the answers as a task: key → (English, Russian) name, the Russian in the nominative
#: (answer_words makes it the object of «Определить»: object_form); the symbol and the unit
#: are the term's; "{kind}:key" entries, of one case kind, first
SHEET_ANSWERS: dict[str, tuple[str, str]] = {
    "run:J_required": ("the required moment of inertia of the first group",
                       "необходимый момент инерции первой группы звеньев"),
    "task2:J_required": ("the reduced moment of inertia required for [δ]",
                         "необходимый приведённый момент инерции при [δ]"),
    "task2:delta": ("the coefficient of speed fluctuation", "коэффициент неравномерности хода"),
    "driving_moment": ("the driving moment that balances the cycle",
                       "приведённый движущий момент из условия цикла"),
    "delta_T_max": ("the largest fluctuation of kinetic energy",
                    "наибольшее изменение кинетической энергии"),
    "J_flywheel": ("the moment of inertia of the flywheel", "момент инерции маховика"),
    "flywheel_disk.D": ("the outer diameter of the flywheel as a solid disk",
                        "наружный диаметр маховика в виде сплошного диска"),
    "flywheel_disk.b": ("the width of the flywheel as a solid disk",
                        "ширина маховика в виде сплошного диска"),
    "flywheel_disk.mass": ("the mass of the flywheel as a solid disk",
                           "масса маховика в виде сплошного диска"),
    "flywheel_rim.D": ("the outer diameter of the flywheel's rim", "наружный диаметр обода маховика"),
    "flywheel_rim.mass": ("the mass of the flywheel's rim", "масса обода маховика"),
    "M_C": ("the resistance moment", "момент сопротивления"),
    "M_D": ("the driving moment", "движущий момент"),
    "omega_max": ("the greatest angular velocity", "наибольшая угловая скорость"),
    "omega_min": ("the least angular velocity", "наименьшая угловая скорость"),
    "omega_mean": ("the mean angular velocity", "средняя угловая скорость"),
    "cycle_work_resistance": ("the work of the resistance over a cycle",
                              "работа сил сопротивления за цикл"),
    "balancing_moment": ("the constant moment that balances the cycle (with its sign)",
                         "постоянный момент из условия цикла (со знаком)"),
    "flywheel_J_on_its_shaft": ("the moment of inertia of the flywheel on its own shaft",
                                "момент инерции маховика на его валу"),
    # task2's masses: their names are templates of the radius they are taken at
    "task2:flywheel_mass": ("the mass of the flywheel", "масса маховика"),
    "task2:rim_mass": ("the mass of the flywheel's rim", "масса обода маховика"),
    "delta_T_I_max": ("the greatest change of the first group's kinetic energy",
                      "наибольшее изменение кинетической энергии первой группы"),
    "delta_T_I_min": ("the least change of the first group's kinetic energy",
                      "наименьшее изменение кинетической энергии первой группы"),
    "phi_delta_T_I_max_deg": ("the crank angle of the greatest ΔT_I",
                              "угол поворота кривошипа при наибольшем ΔT_I"),
    "phi_delta_T_I_min_deg": ("the crank angle of the least ΔT_I",
                              "угол поворота кривошипа при наименьшем ΔT_I"),
    "phi_omega_max_deg": ("the crank angle of the greatest angular velocity",
                          "угол поворота кривошипа при наибольшей угловой скорости"),
    "phi_omega_min_deg": ("the crank angle of the least angular velocity",
                          "угол поворота кривошипа при наименьшей угловой скорости"),
}
#: answers whose symbol differs between the two kinds (J_I of a run, J_пр of task2)
SHEET_SYMBOLS = {"task2:J_required": ("J_req", "J_треб"), "task2:delta": ("δ", "δ")}


#: the usual names of the first group's parts (machine.first_group's keys), said in a document's
#: language; a name not here is printed as the case writes it
PART = words("part", {
    "crankshaft": "crankshaft", "crank": "crank", "crank_gear": "crank gear",
    "gearbox": "gearbox", "gear": "gear", "rotor": "rotor", "motor": "motor rotor",
    "coupling": "coupling", "pulley": "pulley", "counterweights": "counterweights",
    "camshaft": "camshaft", "flywheel": "flywheel",
})


#: the same parts as a field's label names them: «момент инерции коленчатого вала» (Russian's
#: genitive; English as PART)
PART_OF = words("part_of", {
    "crankshaft": "crankshaft", "crank": "crank", "crank_gear": "crank gear",
    "gearbox": "gearbox", "gear": "gear", "rotor": "rotor", "motor": "motor rotor",
    "coupling": "coupling", "pulley": "pulley", "counterweights": "counterweights",
    "camshaft": "camshaft", "flywheel": "flywheel",
})
#: the course's symbols of the first group's parts (seed 000: J_10 the crankshaft's, J_ред the
#: gearbox's reduced to the crank), as the formula J_М = J_I − (J_10 + J_ред) names them
PART_SYMBOL = {"crankshaft": ("J_10", "J_10"), "gearbox": ("J_red", "J_ред")}


def part_name(key: str, lang: str) -> str:
    """A first-group part's name in ``lang`` (:data:`PART`: "crank_gear" → "crank gear",
    «кривошипное колесо»), else the case's own key."""
    return PART[lang].get(key, key)


def _patterns(patterns) -> dict[str, int]:
    """A table's dotted-path patterns → their rank (the first of two that match a path wins)."""
    rank: dict[str, int] = {}
    for k, p in enumerate(patterns):
        rank.setdefault(p, k)
    return rank


def _matched(key: str, rank: dict[str, int]) -> tuple[int, str, str, int] | None:
    """The first pattern of ``rank`` (:func:`_patterns`) that the dotted ``key`` matches, a
    pattern's one wildcard standing for a whole segment — ``#`` an index (digits), ``*`` a name
    — as (its rank, the name ``*`` stood for, the index ``#`` stood for, the length of the key
    up to that index); None for none. A path is looked up, not matched against every pattern:
    no regular expression to build (this module is imported with every record)."""
    segs = key.split(".")
    found = [(rank[key], "", "", 0)] if key in rank else []
    for j, seg in enumerate(segs):
        if not seg:
            continue
        head, tail = ".".join(segs[:j]), ".".join(segs[j + 1:])
        for wild in ("*", "#") if seg.isdecimal() else ("*",):
            p = f"{head}.{wild}" if head else wild
            p = f"{p}.{tail}" if tail else p
            if p in rank:
                end = len(".".join(segs[:j + 1]))
                found.append((rank[p], seg if wild == "*" else "", seg if wild == "#" else "",
                              end))
    return min(found) if found else None


_SHEET_FIELD_RANK = _patterns(p for p, _, _ in SHEET_FIELDS)


def field_kinds(kind: str, speed_ratio=1) -> tuple[str, ...]:
    """The kinds :func:`field_label` tries for a case of ``kind`` ("run", "task2"): a run's
    flywheel on a shaft of its own (``speed_ratio`` i ≠ 1) first as "run,i" (its J is J_M/i²).

    >>> field_kinds("run", 3), field_kinds("run"), field_kinds("task2")
    (('run,i', 'run'), ('run',), ('task2',))
    """
    return ("run,i", "run") if kind == "run" and speed_ratio != 1 else (kind,)


#: a point on its link, where the case says the joints it is measured from (and to), as the
#: записка's input table words it (render/document.py "share", "distance")
POINT_LABELS = {"fraction": ("point {p} of link {x}: share of {ab} l_{a}{n}/l_{ab}",
                             "точка {p} звена {x}: доля длины {ab} l_{a}{n}/l_{ab}"),
                "distance": ("point {p} of link {x}: distance from {a} l_{a}{n}",
                             "точка {p} звена {x}: расстояние от {a} l_{a}{n}")}


def _point_label(path: str, lang: str, names: dict) -> str:
    """The label of a point's share or distance along its link («точка S₂ звена 2: доля длины
    AB l_AS2/l_AB») where ``names`` has its link and joints (teaching/sheets.element_names);
    "" otherwise (the plain «точка S₂: доля длины звена»)."""
    parts = path.split(".")
    if len(parts) != 3 or parts[0] != "points" or parts[2] not in POINT_LABELS:
        return ""
    n, what = parts[1], parts[2]
    a, b, x = (names.get(f"points.{n}.{k}", "") for k in ("from", "to", "link"))
    if not a or not x or (what == "fraction" and not b):
        return ""
    return POINT_LABELS[what][lang == "ru"].format(p=point_name(n), x=x, a=a, n=n, ab=a + b)


def as_printed(value, si: str):
    """(value, unit) of a datum as the sheets and the list of drawn values print it: a pressure
    in MPa as the course gives it (seed 000: p_max2 = 0.882 MPa; «880 000 Па» is hard to read),
    the case's pascals over 10⁶, an array's each; any other as it is.

    >>> as_printed(882000.0, "Pa"), as_printed((0.5, 1.0), "m")
    ((0.882, 'MPa'), ((0.5, 1.0), 'm'))
    """
    from flywheel.units import PA_PER_MPA

    if si != "Pa":
        return value, si

    def mpa(v):
        return tuple(mpa(x) for x in v) if isinstance(v, tuple) else (
            v / PA_PER_MPA if isinstance(v, (int, float)) and not isinstance(v, bool) else v)

    return mpa(value), "MPa"


def field_label(path: str, lang: str = "en", names: dict[str, str] | None = None,
                kinds: tuple[str, ...] = ()) -> str:
    """The label of a case file's input field on a task sheet ("links.2.mass" → "масса звена 2
    m_2"); ``names``: the element name of an indexed path ("cylinders.0" → "HP", or a
    cylinder's label: an io.text.Text, "ВД" in Russian), else the element's number from 1; ``kinds``: the case kind's entries to try first, in order ("run",
    "task2"; "run,i" for a flywheel on a shaft of its own); an unknown field by its dotted path
    as the case file spells it.

    >>> field_label("cylinders.0.bore", "ru", {"cylinders.0": "HP"}), field_label("crank.length")
    ('диаметр цилиндра HP d_HP', 'crank length l1')
    >>> field_label("flywheel.J", "ru", kinds=("run",)), field_label("flywheel.J", "ru")
    ('момент инерции заданного маховика J_М', 'flywheel.J')
    >>> field_label("machine.first_group.gearbox", "ru")
    'момент инерции редуктора (приведённый к кривошипу) J_ред'
    """
    point = _point_label(path, lang, names or {})
    if point:
        return point
    for key in (*(f"{k}:{path}" for k in kinds), path):
        m = _matched(key, _SHEET_FIELD_RANK)
        if m is None:
            continue
        k, x, i, end = m
        _, en, ru = SHEET_FIELDS[k]
        if en.startswith("@"):
            return name(en[1:], lang)
        if x and key.endswith(f"first_group.{x}"):   # a part: «коленчатого вала J_10»
            sym = PART_SYMBOL.get(x, ("", ""))[lang == "ru"]
            label = (ru if lang == "ru" else en).format(x=PART_OF[lang].get(x, x))
            return f"{label} {sym}" if sym else label
        elif x and key.startswith(("points.", "ground.")):   # a point: S₂
            x = point_name(x)
        if not x and i:
            x = in_language((names or {}).get(path[:end - len(key) + len(path)])
                            or str(int(i) + 1), lang)
        return (ru if lang == "ru" else en).format(x=x)
    return path


#: the case files' ways of joining a table's points (cylinders, [tabulated]): English keeps the
#: case file's spelling, Russian says it in words
INTERPOLATIONS = {"linear": ("linear", "линейная"),
                  "pchip": ("pchip", "монотонная кубическая (PCHIP)"),
                  "natural-spline": ("natural-spline", "естественный кубический сплайн"),
                  "periodic-spline": ("periodic-spline", "периодический кубический сплайн"),
                  "finite-differences": ("finite-differences", "конечные разности")}
#: the words of a case file's text fields on a task sheet and in `check`: path pattern → value
#: → (English, Russian); a value not listed is printed as it is
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
    "cylinders.#.interpolation": INTERPOLATIONS,
    "tabulated.interpolation": INTERPOLATIONS,
    "tabulated.forces.#.interpolation": INTERPOLATIONS,
    "tabulated.moments.#.interpolation": INTERPOLATIONS,
}
_SHEET_VALUE_RANK = _patterns(SHEET_VALUES)
_SHEET_VALUE_WORDS = list(SHEET_VALUES.values())


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
    m = _matched(path, _SHEET_VALUE_RANK)
    if m is not None:
        said = _SHEET_VALUE_WORDS[m[0]]
        return said[value][lang == "ru"] if value in said else value
    return value


#: the tables a template may ask (teaching/tables.py): name → (English, Russian) title
SHEET_TABLES: dict[str, tuple[str, str]] = {
    "analogues": ("Velocity analogues at the positions of the mechanism",
                  "Аналоги скоростей в положениях механизма"),
    "delta_T": ("Work and kinetic energy at the positions of the mechanism",
                "Работа и кинетическая энергия в положениях механизма"),
    "reactions": ("Reactions in the kinematic pairs at φ = {a:g}°",
                  "Реакции в кинематических парах при φ = {a:g}°"),
}
#: a table's short name in a list of answers (`grade`'s report): (English, Russian)
TABLE_NAMES = {"analogues": ("analogues", "аналоги скоростей"),
               "delta_T": ("delta_T", "работа и энергия"),
               "reactions": ("reactions", "реакции в парах")}
#: what a table's row is (teaching/tables.py's ``row_label``)
TABLE_ROWS = {"analogues": "position", "delta_T": "position", "reactions": "joint"}
#: what a table's row is: (English, Russian)
SHEET_ROWS = {"position": ("position", "положение"), "joint": ("pair", "кинематическая пара"),
              "at": ("at position {row}", "в положении {row}"), "pair": ("pair", "пара")}


def table_title(table: str, phi_deg: float, lang: str = "en") -> str:
    """A table's title on the task sheet (``reactions``: at its angle ``phi_deg``)."""
    return SHEET_TABLES[table][lang == "ru"].format(a=phi_deg)


def row_word(row_label: str, lang: str = "en") -> str:
    return SHEET_ROWS[row_label][lang == "ru"]


def pair_label(joint: str) -> str:
    """A reaction's row as the sheet prints it: ``O:0->1`` → «O (0→1)», the force of link 0
    on link 1 at O."""
    point, _, links = joint.partition(":")
    return f"{point} ({links.replace('->', '→')})" if links else joint


def row_text(table: str, row: str) -> str:
    """A table's row label as the sheet prints it: a position's number, a pair «O (0→1)»."""
    return pair_label(row) if TABLE_ROWS.get(table) == "joint" else row


def table_name(table: str, lang: str = "en") -> str:
    """A table's short name in `grade`'s lists: the key in English, «аналоги скоростей» in
    Russian."""
    return TABLE_NAMES[table][lang == "ru"] if table in TABLE_NAMES else table


def _cell_parts(key: str) -> tuple[str, str, str] | None:
    """(table, row, column) of a table's cell ``table.row.column``, None for another answer."""
    table, _, rest = key.partition(".")
    if table not in SHEET_TABLES or rest.count(".") < 1:
        return None
    row, _, column = rest.rpartition(".")
    return table, row, column


def column_heading(table: str, column: str, lang: str = "en") -> str:
    """A table's column head: the symbol, its point or link, the unit («v_q(B), м/рад»,
    "R_x [N]")."""
    sym = column_symbol(table, column, lang)
    u = unit_of(f"{column}_O" if table == "reactions" else column, lang)
    if u in ("–", "-", ""):
        return sym
    return f"{sym}, {u}" if lang == "ru" else f"{sym} [{u}]"


def column_symbol(table: str, column: str, lang: str = "en") -> str:
    """A table's column symbol as its head prints it, with its point or link («v_q(B)»,
    «ΔT_I», «R_x»)."""
    sym = symbol(f"{column}_O" if table == "reactions" else column, lang)
    m = re.fullmatch(r"(?:vq|omega_q)_(.+)", column)
    return f"{sym}({m.group(1)})" if m else sym


def cell_name(key: str, lang: str = "en") -> str | None:
    """A table's cell as `grade`'s Russian report lists it: its column's symbol and its row
    («T_II, положение 4», «R, пара O (0→1)»); in English the key; None if ``key`` is no
    cell."""
    parts = _cell_parts(key)
    if parts is None:
        return None
    if lang != "ru":
        return key
    table, row, column = parts
    word = SHEET_ROWS["pair" if TABLE_ROWS.get(table) == "joint" else "position"][1]
    return f"{column_symbol(table, column, lang)}, {word} {row_text(table, row)}"


def cell_words(key: str, lang: str = "en") -> tuple[str, str, str] | None:
    """(what, symbol, unit) of a table's cell (``analogues.3.vq_B``: «аналог скорости точки B
    в положении 3», v_q, м/рад), None if ``key`` is no cell."""
    parts = _cell_parts(key)
    if parts is None:
        return None
    table, row, column = parts
    term = f"{column}_{pair_label(row)}" if table == "reactions" else column
    try:
        what, sym, u = name(term, lang), symbol(term, lang), unit_of(term, lang)
    except KeyError:
        return None
    if sym and what.endswith(sym):
        what = what[:-len(sym)].rstrip(" ,")
    if table != "reactions":
        what = f"{what} {SHEET_ROWS['at'][lang == 'ru'].format(row=row)}"
    return (object_form(what) if lang == "ru" else what), sym, "" if u in ("–", "-", "") else u


#: a report angle's record of summary.json (``at.N.…``) as a task asks it: its group and the
#: nomenclature's term; a point's or a link's quantity names its point or link
_AT_GROUPS = {("balancing_moment", "kinetostatic"): "M_y",
              ("balancing_moment", "zhukovsky"): "M_y_zhukovsky",
              ("balancing_moment", "groups"): "M_y_groups",
              ("balancing_moment", "power"): "M_y_power"}
_AT_LOADS = ("crank_pin_load", "main_bearing_load", "shaking_force")   # the loads' own terms
_COMPONENT = {"F": ("", ""), "Fx": (": x component", ": проекция на ось x"),
              "Fy": (": y component", ": проекция на ось y")}
#: a force's or a reaction's further numbers at a report angle (summary.json's ``angle_deg``,
#: a prismatic pair's ``normal`` and ``offset``): (English, Russian, symbol, unit) of ``{of}``, the
#: force in the genitive (:data:`_OF_FORCE`)
_FORCE_MORE = {"angle_deg": ("the direction of {of}, from the x axis",
                             "направление {of}, угол от оси x", "α", "deg"),
               "normal": ("the component of {of} along the slide's normal",
                          "составляющая {of} по нормали к линии скольжения", "R", "N"),
               "offset": ("the offset of the line of action of {of} along the slide",
                          "смещение линии действия {of} вдоль линии скольжения", "h", "m")}
_OF_FORCE = {"joints": ("the reaction in pair {x}", "реакции в кинематической паре {x}"),
             "crank_pin_load": ("the load on the crank pin", "нагрузки на шатунную шейку"),
             "main_bearing_load": ("the load on the main bearing", "нагрузки на коренной подшипник"),
             "shaking_force": ("the shaking force on the frame", "неуравновешенной силы на стойку")}
#: an engine's firing angle (summary.json's firing_deg.<cylinder>): (English, Russian)
_FIRING = ("crank angle where cylinder {c} fires", "угол вспышки в цилиндре {c}")
#: a slider-crank's crank-pin components at a report angle (summary.json's slider_crank.S.…):
#: the term of its symbol and unit
_PIN_XY = {"crank_pin_x": "crank_pin_Fx", "crank_pin_y": "crank_pin_Fy"}
#: a link's quantities at a report angle: (English, Russian, symbol) with the link's name
_AT_LINK = {"omega": ("angular velocity of link {L}", "угловая скорость звена {L}", "ω_{L}", "rad/s"),
            "epsilon": ("angular acceleration of link {L}", "угловое ускорение звена {L}", "ε_{L}",
                        "rad/s²"),
            "omega_q": ("angular velocity analogue of link {L}", "аналог угловой скорости звена {L}",
                        "ω_q{L}", "-"),
            "epsilon_q": ("angular acceleration analogue of link {L}",
                          "аналог углового ускорения звена {L}", "ε_q{L}", "1/rad")}


#: the force analysis's extremes over the cycle (summary.json results.force_analysis): key →
#: (English, Russian, the nomenclature's term of its symbol and unit)
_FORCE_ANALYSIS = {
    "balancing_moment_max": ("the greatest balancing moment over the cycle",
                             "наибольший уравновешивающий момент за цикл", "M_y"),
    "balancing_moment_min": ("the least balancing moment over the cycle",
                             "наименьший уравновешивающий момент за цикл", "M_y"),
    "balancing_moment_cycle_mean": ("the mean of the balancing moment over the cycle",
                                    "среднее за цикл значение уравновешивающего момента", "M_y"),
    "crank_pin_load_max": ("the greatest load on the crank pin over the cycle",
                           "наибольшая нагрузка на шатунную шейку за цикл", "crank_pin_load"),
    "main_bearing_load_max": ("the greatest load on the main bearing over the cycle",
                              "наибольшая нагрузка на коренной подшипник за цикл",
                              "main_bearing_load"),
    "shaking_force_max": ("the greatest shaking force on the frame over the cycle",
                          "наибольшая неуравновешенная сила на стойку за цикл", "shaking_force"),
    "shaking_moment_max": ("the greatest shaking moment on the frame over the cycle",
                           "наибольший неуравновешенный момент на стойку за цикл",
                           "shaking_moment"),
}


def _at_words(key: str, lang: str, loads: tuple = ({}, {})) -> tuple[str, str, str] | None:
    """(what, symbol, unit) of a report angle's quantity ``at.N.…`` without its angle, of a
    force analysis's extreme over the cycle (``force_analysis.…_max``) or of the output link's
    stroke and extreme positions (``output_link.stroke``, ``output_link.extremes_phi_deg.N``);
    a load by its title or its cylinder's label (``loads``: LoadsResult.titles, .labels);
    None for another key or one not worded here."""
    from flywheel.render.nomenclature import unit

    parts = key.split(".")
    if parts[0] == "output_link" and len(parts) == 2 and parts[1] == "stroke":
        return name("output_stroke", lang), symbol("output_stroke", lang), unit_of("output_stroke",
                                                                                 lang)
    if parts[:2] == ["output_link", "extremes_phi_deg"] and len(parts) == 3 and parts[2].isdigit():
        k = int(parts[2]) + 1
        return ((f"угол поворота кривошипа в крайнем положении {k} выходного звена" if
                 lang == "ru" else f"crank angle of the output link's extreme position {k}"),
                "φ", unit_of("phi_deg", lang))
    if len(parts) == 2 and parts[0] == "force_analysis" and parts[1] in _FORCE_ANALYSIS:
        en, r, term = _FORCE_ANALYSIS[parts[1]]
        return (r if lang == "ru" else en), symbol(term, lang), unit_of(term, lang)
    ru = lang == "ru"
    if parts[0] == "firing_deg" and len(parts) == 2:       # an engine's cylinder fires at
        return (_FIRING[ru].format(c=parts[1]), symbol("firing_deg", lang),
                unit_of("firing_deg", lang))
    if len(parts) < 3 or parts[0] != "at" or not parts[1].isdigit():
        return None
    group, rest = parts[2], parts[3:]
    if group in ("moments", "forces") and len(rest) == 1:  # a load's reduced moment, a force
        titles, labels = loads
        if group == "moments":
            term = f"M {rest[0]}"
            what = name(term, lang, x=load_name(rest[0], lang, titles, labels))
        else:       # a cylinder's gas force or a force: by its title where the case gives one
            term = f"F_{rest[0]}"
            titled = [k for k in (LoadKey("force", rest[0]), LoadKey("gas", rest[0]))
                      if k in titles]
            what = in_language(titles[titled[0]], lang) if titled else name(term, lang)
        return what, symbol(term, lang), unit_of(term, lang)
    if group == "slider_crank" and len(rest) == 2:          # by the slider of the rod
        slider, q = rest
        if f"{q}_{{link}}" in TERMS:
            t = f"{q}_{slider}"
            return name(t, lang), symbol(t, lang), unit_of(t, lang)
        if q in _PIN_XY:
            t = _PIN_XY[q]
            return (name(t, lang) + (f" от шатуна ползуна {slider}" if ru else
                                     f" from the rod of slider {slider}"),
                    symbol(t, lang), unit_of(t, lang))
    more = rest[-1] if rest and rest[-1] in _FORCE_MORE else None
    if more and (group == "joints" and len(rest) == 2 or group in _AT_LOADS and len(rest) == 1):
        en, r, sym, u = _FORCE_MORE[more]
        of = _OF_FORCE[group][ru].format(x=pair_label(rest[0]))
        return (r if ru else en).format(of=of), sym, unit(u, lang)
    if group == "crank_pin_load" and rest in (["tangential"], ["radial"]):
        t = f"crank_pin_{rest[0]}"
        return name(t, lang), symbol(t, lang), unit_of(t, lang)
    if group == "points" and len(rest) == 2 and rest[1] in TERMS:
        point, q = rest
        what = name(q, lang)
        tail = (" точки" if ru else " of a point")
        what = (what[:-len(tail)] if what.endswith(tail) else what) + (
            f" точки {point}" if ru else f" of point {point}")
        return what, symbol(q, lang), unit_of(q, lang)
    if group == "links" and len(rest) == 2 and rest[1] in _AT_LINK:
        en, r, sym, u = _AT_LINK[rest[1]]
        return (r if ru else en).format(L=rest[0]), sym.format(L=rest[0]), unit(u, lang)
    if group == "joints" and len(rest) == 2 and rest[1] in ("F", "Fx", "Fy"):
        column = {"F": "R", "Fx": "Rx", "Fy": "Ry"}[rest[1]]
        return cell_words(f"reactions.{rest[0]}.{column}", lang)
    term = _AT_GROUPS.get((group, rest[0])) if len(rest) == 1 else None
    if term is None and group in _AT_LOADS and len(rest) == 1 and rest[0] in _COMPONENT:
        return name(group, lang) + _COMPONENT[rest[0]][ru], symbol(group, lang), unit_of(group,
                                                                                          lang)
    if term is None and not rest and group in TERMS:
        term = group
    if term is None:
        return None
    sym = symbol(term, lang)     # named once: not in the middle (M_у (кинетостатика)), not last
    return bare_name(term, lang).replace(f" {sym} ", " ", 1), sym, unit_of(term, lang)


def answer_words(kind: str, key: str, lang: str = "en", at_deg: tuple = (),
                 loads: tuple = ({}, {}), asked: bool = True) -> tuple[str, str, str]:
    """(what, symbol, unit) of an answer of a ``kind`` ("run", "task2") case as a task sheet
    asks it: the object of "Determine …" (``asked``; else the name as a table's row names it,
    «наибольшая угловая скорость»), the symbol and the unit as printed ("" where the
    quantity has none; the result key itself if it is no term; a table's cell:
    :func:`cell_words`; a report angle's quantity ``at.N.…`` at ``at_deg[N]``, the variant's
    report angles, where given: «угловую скорость звена 3 при φ = 60°»; a load by its title
    or its cylinder's label of ``loads``, the variant's LoadsResult.titles and .labels).

    >>> answer_words("run", "J_flywheel", "ru")
    ('момент инерции маховика', 'J_М', 'кг·м²')
    >>> answer_words("task2", "omega_max", "ru")[0], answer_words("task2", "omega_max", "ru", asked=False)[0]
    ('наибольшую угловую скорость', 'наибольшая угловая скорость')
    """
    cell = cell_words(key, lang)
    if cell is not None:
        return cell
    at = _at_words(key, lang, loads)
    if at is not None:
        what, sym, u = at
    else:
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
        if sym and what.endswith(" " + sym):    # a name that ends with its symbol: not twice
            what = what[:-len(sym)].rstrip(" ,")
    parts = key.split(".")
    if (what != key and len(parts) > 2 and parts[0] == "at" and parts[1].isdigit()
            and int(parts[1]) < len(at_deg)):
        from flywheel.render.numbers import fmt     # the variant's report angle it is asked at

        what += (" при φ = " if lang == "ru" else " at φ = ") + fmt(at_deg[int(parts[1])],
                                                                    given=True) + "°"
    return (object_form(what) if lang == "ru" and asked else what), sym, \
        "" if u in ("–", "") else u


def object_form(phrase: str) -> str:
    """A Russian name as the object of «Определить»: its leading feminine adjectives and noun
    in the accusative («кинетическая энергия второй группы» → «кинетическую энергию второй
    группы», «реакция в паре» → «реакцию в паре»); a masculine or neuter name, one already
    in the accusative and a neuter noun in -мя (время) as they are.

    >>> object_form("суммарная работа в положении 4"), object_form("момент инерции маховика")
    ('суммарную работу в положении 4', 'момент инерции маховика')
    """
    words = phrase.split(" ")
    for i, w in enumerate(words):
        if re.fullmatch(r"[а-яё]+(ая|яя)", w):          # a feminine adjective
            words[i] = w[:-2] + ("ую" if w.endswith("ая") else "юю")
            continue
        if re.fullmatch(r"[а-яё]+[ая]", w) and not w.endswith("мя"):   # its noun
            words[i] = w[:-1] + ("у" if w.endswith("а") else "ю")
        break
    return " ".join(words)
