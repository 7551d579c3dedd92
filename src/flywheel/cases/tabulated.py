"""The [tabulated] section of a run case (docs/tabulated.md; seed 004, the press course
project): kinematics and loads as tables read off velocity plans, validated.

The analysis of such a case is :mod:`flywheel.dynamics.tabulated`.
"""
from __future__ import annotations

from typing import Annotated, Literal

import numpy as np
from pydantic import Field, PrivateAttr, ValidationInfo, model_validator

from flywheel.errors import Notice
from flywheel.io.schema import MAX_TEXT, FieldError, StrictModel, TitleText, title_field, within

MIN_POSITIONS = 6
MAX_GAP_DEG = 360.0 / MIN_POSITIONS      # the widest allowed gap between neighbouring positions
CYCLE_DEG = 360.0                        # the cycle when the validation context gives none
_TOL = 1e-9

Row = list[float]
Name = Annotated[str, Field(min_length=1, max_length=MAX_TEXT)]




class TableError(FieldError):
    """An error in the [tabulated] section; ``loc`` is the field path inside it (the run case's
    loader puts ``tabulated.`` in front and the file name before it)."""




class TabLink(StrictModel):
    """Mass data of one link and the table rows it uses: J share = mass·V_q² + J·ω_q²."""

    # the same ranges as a [links] entry of a mechanism (cases/run.py Mass, Inertia)
    mass: Annotated[float, Field(gt=0), within(0.0, 1e6, "kg")] = Field(
        0.0, description="mass m [kg], > 0, at `point` (leave it out for a link that only turns)")
    point: str | None = Field(None, description="row of [tabulated.points] whose |V_q| the mass "
                                                "moves with (its centroid, or the point the "
                                                "course uses for it)")
    J: Annotated[float, Field(ge=0), within(0.0, 1e6, "kg·m²")] = Field(
        0.0, description="moment of inertia [kg·m²] multiplied by ω_q²: about the centroid for "
                         "a link in plane motion (with its mass at the centroid), about the fixed "
                         "pivot for a link that only turns (then no mass)")
    omega_q: str | None = Field(None, description="row of [tabulated.omega_q] (default: the link's "
                                                  "own name)")


class TabForce(StrictModel):
    """A force at a tabulated point: its reduced moment is M = F·|V_q|·cos α (positive when it
    drives the crank)."""

    name: Name
    title: TitleText = title_field(description="its name in the documents and figures: a string, or { ru = …, en = … } "
                                                  "(default: its kind and name, as 'force cutting')")
    point: Name = Field(description="row of [tabulated.points] where the force acts")
    magnitude: float | Row = Field(description="F [N]: one number, or one per position")
    angle_deg: float | Row = Field(description="α [deg] between the force and the point's "
                                               "velocity: one number, or one per position "
                                               "(180 for a resistance opposing the motion)")
    interpolation: Literal["linear", "periodic-spline"] = Field(
        "linear", description="how the per-position reduced moments are joined: 'linear' (the "
                              "trapezoidal rule of graphical integration; safe for a force that "
                              "switches on and off) or 'periodic-spline' (smooth loads)")


class TabMoment(StrictModel):
    """A reduced moment given outright per position (e.g. read off another calculation)."""

    name: Name
    title: TitleText = title_field(description="its name in the documents and figures: a string, or { ru = …, en = … } "
                                                  "(default: its kind and name, as 'force cutting')")
    values: Row = Field(description="reduced moment [N·m] per position, positive when it drives")
    interpolation: Literal["linear", "periodic-spline"] = Field(
        "linear", description="'linear' or 'periodic-spline' (see forces)")


class TabulatedSpec(StrictModel):
    """The kinematics and loads as tables aligned with ``positions_deg`` (docs/tabulated.md).

    The table covers the machine's cycle: 360°, or machine.cycle_deg (720° for a four-stroke
    engine or a press whose cycle is two revolutions), given to the validation as the context
    ``{"cycle_deg": …}`` by the run case's loader (:func:`cycle_context`)."""

    positions_deg: Row = Field(description="crank positions φ [deg], increasing, within the cycle "
                                           "[0, machine.cycle_deg] (360 unless given); a last "
                                           "position at the cycle's end repeats the first (0) "
                                           "and its values must equal those at 0")
    interpolation: Literal["periodic-spline", "finite-differences"] = Field(
        "periodic-spline",
        description="J_II(φ) and dJ_II/dφ: 'periodic-spline' (scipy CubicSpline, periodic; "
                    "dJ from the spline's derivative) or 'finite-differences' (J_II linear "
                    "between positions, dJ = (I_{i+1} − I_i)/(φ_{i+1} − φ_i) as in seed 004)")
    crank_length: float | None = Field(None, gt=0, description="l1 [m], reported only")
    points: dict[str, Row] = Field(default_factory=dict,
                                   description="point → |V_q| = V/ω1 per position [m]")
    omega_q: dict[str, Row] = Field(default_factory=dict,
                                    description="link → ω_q = ω_i/ω1 per position [-]")
    links: dict[str, TabLink] = Field(default_factory=dict)
    forces: list[TabForce] = Field(default_factory=list)
    moments: list[TabMoment] = Field(default_factory=list)

    _cycle_deg: float = PrivateAttr(CYCLE_DEG)

    @model_validator(mode="after")
    def _check(self, info: ValidationInfo):
        self._cycle_deg = (info.context or {}).get("cycle_deg", CYCLE_DEG)
        _validate(self, self._cycle_deg)
        return self

    # -- derived ------------------------------------------------------------------------------
    @property
    def cycle_deg(self) -> float:
        """The cycle the table covers [deg]: 360, or the machine's cycle_deg."""
        return self._cycle_deg

    @property
    def closed(self) -> bool:
        """True if the last position (the cycle's end, 360° or 720°) repeats the first (0°)."""
        p = self.positions_deg
        return abs(p[-1] - p[0] - self._cycle_deg) < _TOL

    @property
    def nodes_deg(self) -> np.ndarray:
        """The distinct positions [deg] (without a closing 360°)."""
        p = np.asarray(self.positions_deg, float)
        return p[:-1] if self.closed else p


def cycle_context(data) -> dict:
    """The validation context of a run case document: its machine.cycle_deg when that is a
    whole number of revolutions (else 360: the [machine] error is reported on its own)."""
    machine = data.get("machine") if isinstance(data, dict) else None
    c = machine.get("cycle_deg", CYCLE_DEG) if isinstance(machine, dict) else CYCLE_DEG
    ok = (isinstance(c, (int, float)) and not isinstance(c, bool) and 360.0 <= c <= 3600.0
          and abs(c / 360.0 - round(c / 360.0)) < 1e-9)
    return {"cycle_deg": float(c) if ok else CYCLE_DEG}


def _validate(t: TabulatedSpec, cycle: float = CYCLE_DEG) -> None:
    p = t.positions_deg
    n = len(p)
    if n == 0:
        raise TableError(("positions_deg",), Notice.of(
            "tab_no_positions", "no positions (allowed: {min} or more distinct angles within 0 … "
            "{cycle:g})", min=MIN_POSITIONS, cycle=cycle))
    for i, a in enumerate(p):
        if not 0.0 <= a <= cycle:
            raise TableError(("positions_deg", i), Notice.of(
                "tab_outside_cycle", "{a:g}° is outside the cycle (allowed: 0 … "
                "{cycle:g}{cycle_note})", a=a, cycle=cycle, own_cycle=cycle != CYCLE_DEG,
                cycle_note=_cycle_note(cycle)))
    for i in range(1, n):
        if abs(p[i] - p[i - 1]) < _TOL:
            raise TableError(("positions_deg", i), Notice.of(
                "tab_duplicated", "duplicated angle {a:g}° (positions {i} and {j})", a=p[i], i=i,
                j=i + 1))
        if p[i] < p[i - 1]:
            raise TableError(("positions_deg", i), Notice.of(
                "positions_increase", "{at:g}° after {before:g}°: positions must increase", at=p[i],
                before=p[i - 1]))
    distinct = n - 1 if t.closed else n
    if distinct < MIN_POSITIONS:
        raise TableError(("positions_deg",), Notice.of(
            "tab_too_few", "{n} distinct positions are too few (allowed: {min} or more)",
            n=distinct, min=MIN_POSITIONS))
    nodes = np.asarray(p[:distinct], float)
    gaps = np.diff(np.append(nodes, nodes[0] + cycle))
    k = int(np.argmax(gaps))
    if gaps[k] > MAX_GAP_DEG + _TOL:
        end = nodes[(k + 1) % distinct]
        raise TableError(("positions_deg",), Notice.of(
            "tab_gap", "the positions do not cover the cycle: nothing between {a:g}° and {b:g}° "
            "({gap:g}° gap; allowed: {max_gap:g}° or less between neighbours, 0 … "
            "{cycle:g}{cycle_note})", a=float(nodes[k]), b=float(end), gap=float(gaps[k]),
            max_gap=MAX_GAP_DEG, cycle=cycle, own_cycle=cycle != CYCLE_DEG,
            cycle_note=_cycle_note(cycle)))

    def row(values, loc: tuple, nonneg: bool = False) -> None:
        if len(values) != n:
            raise TableError(loc, Notice.of(
                "values_per_position", "needs {n} values, one per position in positions_deg (got "
                "{count})", n=n, count=len(values)))
        if nonneg and min(values) < 0:
            i = int(np.argmin(values))
            raise TableError(loc + (i,), Notice.of(
                "tab_negative_analogue", "{v:g} < 0: velocity analogues are magnitudes |V_q| ≥ 0 "
                "(the direction is in a force's angle_deg)", v=values[i]))
        if t.closed and abs(values[-1] - values[0]) > _TOL * max(1.0, abs(values[0])):
            raise TableError(loc + (n - 1,), Notice.of(
                "tab_not_closed", "the value at {cycle:g}° ({last:g}) must repeat the value at 0° "
                "({first:g}): the cycle closes", cycle=cycle, last=values[-1], first=values[0]))

    for name, v in t.points.items():
        row(v, ("points", name), nonneg=True)
    for name, v in t.omega_q.items():
        row(v, ("omega_q", name))
    known_points = ", ".join(sorted(t.points)) or "none"
    for name, lk in t.links.items():
        if lk.mass > 0:
            if lk.point is None:
                raise TableError(("links", name, "point"), Notice.of(
                    "tab_mass_no_point", "link {link} has mass {mass:g} kg but no velocity "
                    "analogues: give point = a row of [tabulated.points] (rows: {rows})", link=name,
                    mass=lk.mass, rows=known_points))
        if lk.point is not None and lk.point not in t.points:
            raise TableError(("links", name, "point"), Notice.of(
                "analogues_missing", "velocity analogues of {name!r} are missing from "
                "[tabulated.points] (rows: {rows})", name=lk.point, rows=known_points))
        if lk.J > 0:
            key = lk.omega_q or name
            if key not in t.omega_q:
                raise TableError(("links", name, "omega_q"), Notice.of(
                    "tab_J_no_omega_q", "link {link} has J = {J:g} kg·m² but [tabulated.omega_q] "
                    "has no row {key!r} (rows: {rows})", link=name, J=lk.J, key=key,
                    rows=", ".join(sorted(t.omega_q)) or "none"))
    names: set[str] = set()
    for i, f in enumerate(t.forces):
        if f.point not in t.points:
            raise TableError(("forces", i, "point"), Notice.of(
                "analogues_missing", "velocity analogues of {name!r} are missing from "
                "[tabulated.points] (rows: {rows})", name=f.point, rows=known_points))
        for key in ("magnitude", "angle_deg"):
            v = getattr(f, key)
            if isinstance(v, list):
                row(v, ("forces", i, key))
        if f.name in names:
            raise TableError(("forces", i, "name"), Notice.of(
                "load_twice", "load name {name!r} is used twice", name=f.name))
        names.add(f.name)
    for i, m in enumerate(t.moments):
        row(m.values, ("moments", i, "values"))
        if m.name in names:
            raise TableError(("moments", i, "name"), Notice.of(
                "load_twice", "load name {name!r} is used twice", name=m.name))
        names.add(m.name)
    _check_finite(t)


def _cycle_note(cycle: float) -> str:
    return "" if cycle == CYCLE_DEG else ", the cycle of machine.cycle_deg"


def _check_finite(t: TabulatedSpec) -> None:
    """Finite inputs can still overflow (m·V_q² with V_q = 1e200): name the row and position."""
    from flywheel.dynamics.tabulated import link_inertia_at_positions, load_moments_at_positions

    with np.errstate(over="ignore", invalid="ignore"):
        for name, J in link_inertia_at_positions(t).items():
            if not np.all(np.isfinite(J)):
                i = int(np.argmin(np.isfinite(J)))
                raise TableError(("links", name), Notice.of(
                    "tab_inertia_overflow", "m·V_q² + J·ω_q² overflows at position {k} ({a:g}°): "
                    "the values are out of range (allowed: SI values, m and kg·m²)", k=i + 1,
                    a=t.positions_deg[i]))
        for name, M in load_moments_at_positions(t).items():
            if not np.all(np.isfinite(M)):
                i = int(np.argmin(np.isfinite(M)))
                raise TableError((), Notice.of(
                    "tab_moment_overflow", "the reduced moment of {load} overflows at position {k} "
                    "({a:g}°): the values are out of range (allowed: SI values, N and m)",
                    load=str(name), k=i + 1, a=t.positions_deg[i]))
