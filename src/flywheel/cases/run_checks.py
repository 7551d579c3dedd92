"""The checks of a run case across its tables (names unique and defined before use, pins,
engines and firing orders) and the plausibility warnings: each takes a validated
:class:`flywheel.cases.run.Case` (never imported here: run.py calls these)."""
from __future__ import annotations

from flywheel.errors import Notice
from flywheel.io.schema import FieldError
from flywheel.cases.run_linkage import RRPSpec, RRRSpec
from flywheel.cases.run_loads import check_loads
from flywheel.units import PA_PER_MPA, RPM_PER_RAD_S, SECONDS_PER_MINUTE, TWO_PI


def _check_references(case) -> None:
    """Names are unique and defined before use; lengths can be derived."""
    if (case.crank is None) == (case.tabulated is None):
        raise FieldError((), Notice.of(
            "crank_or_tabulated", "give exactly one of [crank] (a linkage) and [tabulated] "
            "(kinematics from a table)"))
    if case.tabulated is not None and case.machine.analysis == "kinematics":
        raise FieldError(("machine", "analysis"), Notice.of(
            "kinematics_tabulated", "\"kinematics\" needs a linkage ([crank] and [[dyads]]); a "
            "[tabulated] case has no positions to compute (allowed: \"dynamics\")"))
    given = case.flywheel.given_J is not None
    if given and case.machine.delta is not None:
        raise FieldError(("machine", "delta"), Notice.of(
            "delta_and_given_flywheel", "give exactly one of machine.delta (the flywheel is sized "
            "for it) and a given flywheel (flywheel.J, mass with radius_of_gyration, given_disk "
            "or given_rim), not both"))
    if not given and case.machine.delta is None and not case.kinematics_only:
        raise FieldError(("machine", "delta"), Notice.of(
            "delta_missing", "missing: give machine.delta (the flywheel is sized for it) or a "
            "given flywheel (flywheel.J, mass with radius_of_gyration, given_disk or given_rim)"))
    if case.motor is not None and case.motor.no_load_speed_rpm * TWO_PI / SECONDS_PER_MINUTE <= case.machine.omega_mean:
        raise FieldError(("motor", "no_load_speed_rpm"), Notice.of(
            "motor_too_slow", "{n0:g} rpm is not above the mean speed {n:g} rpm",
            n0=case.motor.no_load_speed_rpm, n=case.machine.omega_mean * RPM_PER_RAD_S))
    if case.tabulated is not None:   # no linkage: masses and loads live in [tabulated]
        for key in ("ground", "dyads", "points", "links", "cylinders", "forces", "couples", "springs"):
            if getattr(case, key):
                raise FieldError((key,), Notice.of(
                    "run_not_with_tabulated", "not allowed with [tabulated]: give masses and "
                    "loads in [tabulated] (docs/tabulated.md)"))
        return
    if case.crank.length is None and case.design.mean_piston_speed is None:
        raise FieldError(("crank", "length"), Notice.of(
            "crank_length_missing", "missing: give crank.length or design.mean_piston_speed"))
    points: set[str] = set()
    links: set[str] = set()

    def new_point(name: str, loc: tuple) -> None:
        if name in points:
            raise FieldError(loc, Notice.of(
                "point_twice", "point name {name!r} is already defined", name=name))
        points.add(name)

    def new_link(name: str, loc: tuple) -> None:
        if name in links:
            raise FieldError(loc, Notice.of(
                "link_twice", "link name {name!r} is already defined", name=name))
        links.add(name)

    def known(name: str, loc: tuple) -> None:
        if name not in points:
            raise FieldError(loc, Notice.of(
                "point_used_before", "point {name!r} is used before it is defined (defined so "
                "far: {so_far})", name=name, so_far=", ".join(sorted(points))))

    for name in case.ground:
        new_point(name, ("ground", name))
    new_point(case.crank.pivot, ("crank", "pivot"))
    new_point(case.crank.tip, ("crank", "tip"))
    _check_pins(case)
    for i, pin in enumerate(case.crank.pins):
        new_point(pin.name, ("crank", "pins", i, "name"))
    new_link(case.crank.name, ("crank", "name"))
    on: dict[str, set[str]] = {case.crank.name: {case.crank.pivot, case.crank.tip}  # link → its points
                               | {pin.name for pin in case.crank.pins}}
    pending = dict(case.points)
    sliders: set[str] = set()

    def place_points() -> None:
        progress = True
        while progress:
            progress = False
            for name, p in list(pending.items()):
                if p.link in links and p.from_ in points and (p.to is None or p.to in points):
                    for key, q in (("from", p.from_), ("to", p.to)):
                        if q is not None and q not in on[p.link]:
                            raise FieldError(("points", name, key),
                                             _not_on_link(q, p.link, on[p.link], placed=True))
                    new_point(name, ("points", name))
                    on[p.link].add(name)
                    del pending[name]
                    progress = True

    place_points()
    for i, d in enumerate(case.dyads):
        place_points()
        known(d.from_, ("dyads", i, "from"))
        if isinstance(d, RRPSpec):
            if d.rod_length is None and case.design.rod_to_crank is None:
                raise FieldError(("dyads", i, "rod_length"), Notice.of(
                    "run_rod_length_missing", "missing: give rod_length or design.rod_to_crank"))
            new_link(d.rod, ("dyads", i, "rod"))
            new_link(d.slider, ("dyads", i, "slider"))
            new_point(d.joint, ("dyads", i, "joint"))
            sliders.add(d.slider)
            on[d.rod], on[d.slider] = {d.from_, d.joint}, {d.joint}
        elif isinstance(d, RRRSpec):
            known(d.to, ("dyads", i, "to"))
            new_link(d.link_from, ("dyads", i, "link_from"))
            new_link(d.link_to, ("dyads", i, "link_to"))
            new_point(d.joint, ("dyads", i, "joint"))
            on[d.link_from], on[d.link_to] = {d.from_, d.joint}, {d.to, d.joint}
        else:
            known(d.pivot, ("dyads", i, "pivot"))
            new_link(d.rocker, ("dyads", i, "rocker"))
            new_link(d.slider, ("dyads", i, "slider"))
            on[d.rocker], on[d.slider] = {d.pivot}, {d.from_}
    place_points()
    for name, p in pending.items():
        if p.link not in links:
            raise FieldError(("points", name, "link"), Notice.of(
                "link_not_defined", "link {name!r} is not defined (links: {links})", name=p.link,
                links=", ".join(sorted(links))))
        missing = p.from_ if p.from_ not in points else p.to
        raise FieldError(("points", name), Notice.of(
            "point_never_defined", "point {name!r} is never defined", name=missing))
    for name, link in case.links.items():
        if name not in links:
            raise FieldError(("links", name), Notice.of(
                "no_link_named", "no link named {name!r} (links: {links})", name=name,
                links=", ".join(sorted(links))))
        if link.centroid is not None and link.centroid not in points:
            raise FieldError(("links", name, "centroid"), Notice.of(
                "point_not_defined", "point {name!r} is not defined", name=link.centroid))
        if link.centroid is not None and link.centroid not in on[name]:
            raise FieldError(("links", name, "centroid"),
                             _not_on_link(link.centroid, name, on[name]))
    for i, c in enumerate(case.cylinders):
        if c.piston not in sliders:
            raise FieldError(("cylinders", i, "piston"), Notice.of(
                "not_a_slider_of", "{name!r} is not the slider of an RRP dyad (sliders: "
                "{sliders_or_none})", name=c.piston, sliders=", ".join(sorted(sliders)),
                sliders_or_none=', '.join(sorted(sliders)) or 'none'))
    for i, c in enumerate(case.cylinders):
        for key, values in c.tables().items():
            low, high = min(values), max(values)
            if not high <= 1 + 1e-9:          # (mut) 1e300 here overflowed the energy silently
                raise FieldError(("cylinders", i) + c.table_loc(key),
                                 Notice.of(
                                     "pressure_above_p_max", "p/p_max = {high:g} is above 1: "
                                     "p_max = {p_max:g} Pa is the largest pressure of the diagram "
                                     "(allowed: −0.101325 MPa/p_max … 1; to go higher, raise "
                                     "p_max)", high=high, p_max=c.p_max))
            if low * c.p_max < -ATM:
                raise FieldError(("cylinders", i) + c.table_loc(key),
                                 Notice.of(
                                     "pressure_below_vacuum", "p/p_max = {low:g} gives {mpa:.4g} "
                                     "MPa gauge, below absolute vacuum (allowed: p ≥ −0.101325 "
                                     "MPa gauge)", low=low, mpa=low * c.p_max / PA_PER_MPA))
    _check_engine(case)
    fixed = set(case.ground) | {case.crank.pivot}
    check_loads(case, points, links, on, sliders, fixed)
    names = ([(("cylinders", i, "name"), c.name) for i, c in enumerate(case.cylinders)]
             + [(("forces", i, "name"), f.name) for i, f in enumerate(case.forces)]
             + [(("couples", i, "name"), c.name) for i, c in enumerate(case.couples)]
             + [(("springs", i, "name"), c.name) for i, c in enumerate(case.springs)])
    seen: set[str] = set()
    for loc, n in names:
        if n in seen:
            raise FieldError(loc, Notice.of(
                "load_twice", "load name {name!r} is used twice", name=n))
        seen.add(n)


def _not_on_link(point: str, link: str, its: set[str], placed: bool = False) -> Notice:
    """The error of a point named on a link that does not carry it; ``placed``: the point is
    one the case places on that link (``[points]``)."""
    return Notice.of(
        "run_point_not_on_link", "point {point!r} is not on link {link} (its points: "
        "{points}){placed_note}", point=point, link=link, points=", ".join(sorted(its)),
        placed=placed,
        placed_note=": a point fixed on a link is placed from that link's own points" if placed else '')


def _check_pins(case) -> None:
    """Two pins of one crankshaft at the same angle and throw are one point of the plane
    mechanism: they must have one name (rods of an in-line engine's cylinders 1 and 4 share a
    pin), so a second name there is refused."""
    seen = [((0.0, case.crank_length), case.crank.tip, "the crank's tip")]
    for i, pin in enumerate(case.crank.pins):
        where = (pin.angle_deg % 360.0, pin.length if pin.length is not None else case.crank_length)
        for (angle, length), name, what in seen:
            gap = abs((where[0] - angle + 180.0) % 360.0 - 180.0)
            if gap < 1e-9 and abs(where[1] - length) <= 1e-12 * length:
                raise FieldError(("crank", "pins", i, "angle_deg"),
                                 Notice.of(
                                     "pin_twice", "{angle:g}° puts pin {pin!r} where {whom} "
                                     "{name!r} is (same angle and throw): pins at the same angle "
                                     "are one pin with one name (allowed: attach the rods to "
                                     "{name!r}, or give another angle)", angle=pin.angle_deg,
                                     pin=pin.name, whom=what, name=name))
        seen.append((where, pin.name, f"pin (crank.pins[{i}])"))


def _check_engine(case) -> None:
    """A four-stroke diagram needs a cycle of 720° (or a multiple); a firing order names every
    four-stroke cylinder once and nothing else, and then sets where each fires."""
    cycle = case.machine.cycle_deg
    four = [c.name for c in case.cylinders if c.four_stroke]
    for i, c in enumerate(case.cylinders):
        if c.four_stroke and round(cycle) % 720:
            raise FieldError(("cylinders", i, "diagram" if c.diagram is not None else "strokes"),
                             Notice.of(
                                 "four_stroke_cycle", "a four-stroke diagram spans 720° of crank "
                                 "angle, the machine's cycle is {cycle:g}° (allowed: "
                                 "machine.cycle_deg = 720, or a multiple of 720)", cycle=cycle))
    order = case.machine.firing_order
    if order is None:
        return
    names = {c.name: c for c in case.cylinders}
    seen: set[str] = set()
    for k, name in enumerate(order):
        loc = ("machine", "firing_order", k)
        if name not in names:
            raise FieldError(loc, Notice.of(
                "run_firing_no_cylinder", "no cylinder named {name!r} (four-stroke cylinders: "
                "{four_or_none})", name=name, four=", ".join(four),
                four_or_none=', '.join(four) or 'none'))
        if not names[name].four_stroke:
            raise FieldError(loc, Notice.of(
                "run_firing_not_four_stroke", "cylinder {name!r} has no four-stroke diagram "
                "(strokes): only four-stroke cylinders fire in an order (four-stroke cylinders: "
                "{four_or_none})", name=name, four=", ".join(four),
                four_or_none=', '.join(four) or 'none'))
        if name in seen:
            raise FieldError(loc, Notice.of(
                "run_firing_twice", "cylinder {name!r} is already in the order (each fires once "
                "per cycle)", name=name))
        seen.add(name)
    missing = [n for n in four if n not in seen]
    if missing:
        raise FieldError(("machine", "firing_order"), Notice.of(
            "firing_order_missing", "cylinder {name!r} is missing (a firing order lists every "
            "four-stroke cylinder once: {four})", name=missing[0], four=", ".join(four)))
    for i, c in enumerate(case.cylinders):
        if c.fires_at_deg is not None and c.name != order[0]:
            raise FieldError(("cylinders", i, "fires_at_deg"), Notice.of(
                "run_fires_at_with_order", "machine.firing_order sets where cylinder {name!r} "
                "fires (allowed: fires_at_deg on the first cylinder of the order, {first!r}, only)",
                name=c.name, first=order[0]))


# -- plausibility: allowed, but a careful engineer would look twice --------------------------------

ATM = 101_325.0          # Pa: a gauge pressure below −1 atm is below absolute vacuum
# δ of real machines (Артоболевский, «Теория механизмов и машин», table of δ: crushers and
# presses 1/5 … 1/20, pumps 1/5 … 1/30, machine tools 1/20 … 1/50, engines 1/80 … 1/150,
# generators 1/200 … 1/300)
DELTA_USUAL = (1 / 300, 1 / 5)


def plausibility_warnings(case) -> list[str]:
    """Warnings (one line each, with the value and the usual range) for values that are
    allowed but unusual enough to suspect a slip: a crank of less than 5 mm (units?), δ outside
    1/300 … 1/5, a speed outside 1 … 20 000 rpm, negative (vacuum) gauge pressures in an
    indicator table. Values that cannot be right are refused by the schema instead."""
    out = []
    if case.crank is not None and case.crank_length < 5e-3:
        out.append(Notice.of(
            "crank_short", "crank.length: {length:g} m is unusually short (cranks: 5 mm … 2 m); "
            "lengths are in metres", length=case.crank_length))
    d = case.machine.delta
    if d is not None and not DELTA_USUAL[0] <= d <= DELTA_USUAL[1]:
        out.append(Notice.of(
            "delta_unusual", "machine.delta: δ = {delta:g} is outside the usual 1/300 … 1/5 "
            "({lo:.4f} … {hi:.1f}; Артоболевский's table: presses 1/5 … 1/20, engines 1/80 … "
            "1/150, generators 1/200 … 1/300)", delta=d, lo=DELTA_USUAL[0], hi=DELTA_USUAL[1]))
    rpm = case.machine.omega_mean * RPM_PER_RAD_S
    if not 1.0 <= rpm <= 20_000.0:
        out.append(Notice.of(
            "rpm_unusual", "machine: the crank speed {rpm:.6g} rpm is outside the usual 1 … 20 "
            "000 rpm", rpm=rpm))
    for i, c in enumerate(case.cylinders):
        for key, values in c.tables().items():
            low = min(values)
            if low < 0 and key not in ("intake", "compression"):   # an engine draws its
                # charge below atmospheric pressure, and compresses it from there
                where = ".".join(c.table_loc(key))
                out.append(Notice.of(
                    "cylinder_vacuum", "{where}: p/p_max down to {low:g} ({p:.4g} MPa gauge, a "
                    "vacuum): the tables are gauge pressures relative to p_max; check the sign",
                    where=f"cylinders[{i}].{where}", low=low, p=low * c.p_max / PA_PER_MPA))
    return out

