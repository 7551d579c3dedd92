"""The analysis of a case: mechanism → grid → kinematics → loads → reduction → energy → sizing →
motion → report angles → force analysis → plans at the report angles → (time domain) → Results.

:func:`analyze` reads the validated case and calls the stages in order (design.md §1). This
module is the linkage route: the case's mechanism gives the kinematics, and its cylinders,
forces, weights and couples the loads. A case whose kinematics are a table goes the tabulated
route (:mod:`flywheel.dynamics.tabulated`) into the same shared stages
(:mod:`flywheel.dynamics.stages`). Report angles, the standard positions and the dead centres
are nodes of the φ grid (:mod:`flywheel.dynamics.grid`), so their values are computed, not
interpolated.
"""
from __future__ import annotations

import math

import numpy as np

from flywheel.dynamics import applied as A
from flywheel.dynamics import loads as L
from flywheel.dynamics import plans, reduction, stages
from flywheel.dynamics.columns import linkage_columns
from flywheel.dynamics.engine import firing_angles, four_stroke_cylinder, gas_work
from flywheel.dynamics.asks import with_start
from flywheel.dynamics.grid import (DEFAULT_POINTS, grid_options, linkage_grid, report_index,
                                    slider_frame, standard_positions)
from flywheel.dynamics.results import (AtAngle, CylinderResult, EnergyResult, LinkAt, LoadsResult,
                                       PointAt, ReductionResult, Results,
                                       warnings_of, with_forces)
from flywheel.errors import InputError, Notice
from flywheel.linkage.drawing import describe, links_drawn
from flywheel.linkage.output_link import output_link
from flywheel.units import PA_PER_MPA


def analyze(case, n_points: int = DEFAULT_POINTS, at_deg: list[float] | None = None,
            transients: bool = False, motion: str | None = None, progress=None) -> Results:
    """Run the whole dynamic analysis of a validated case (:class:`flywheel.cases.run.Case`).

    n_points: uniform intervals over the cycle (the report angles, standard positions and dead
    centres are added as nodes); at_deg: report angles [deg] (default: the case's
    output.at_deg); transients: also integrate the equation of motion in time (a check of
    ω(φ), start-up with the case's motor, run-down; imports scipy); motion: the crank's
    motion in the force analysis, "true" or "steady" (default: the case's
    force_analysis.motion); progress: a plain callable ``progress(stage, fraction)`` for the
    time integrations of ``transients`` (:func:`stages.time_domain`). Raises FlywheelError
    subclasses for input that cannot be analysed.
    """
    motion = force_motion(case, motion)
    if case.tabulated is not None:
        from flywheel.dynamics.tabulated import analyze_tabulated

        return with_start(analyze_tabulated(case, n_points, at_deg, transients, motion, progress),
                          case)
    at_deg = grid_options(case, n_points, at_deg)
    mech = case.mechanism()
    positions, dcs = standard_positions(mech, case.machine.cycle)
    phi, kin = linkage_grid(case, mech, dcs, n_points,
                            [p.phi for p in positions] + [math.radians(a) for a in at_deg])
    ld = linkage_loads(case, mech, dcs, kin)
    red = linkage_reduction(case, kin)
    en, sz, mo = stages.dynamics(phi, ld, red, case.machine, case.flywheel)
    fl = force_loads(case, mech, dcs, kin, ld, mo.J_I)
    fo = stages.force_analysis(phi, red, en, mo, case.machine.omega_mean, motion, mech, kin, fl)
    at = report_angles(at_deg, kin, ld, red, en, fo.omega, fo.epsilon)   # the motion used
    pl = plans.plan_sets(mech, kin, fo.analysis, fl, at_deg)     # drawn at the report angles
    td = stages.time_domain(case, phi, red, en, mo, progress) if transients else None
    return with_start(Results(
        title=case.title, source=case.source, phi=phi, kinematics=kin, loads=ld, reduction=red,
        energy=en, sizing=sz, motion=mo,
        columns=linkage_columns(phi, kin, mech.crank.name, ld, red, en, mo),
        at=with_forces(at, fo, phi),
        position_angles=tuple(positions), links_drawn=links_drawn(mech),
        crank_length=float(mech.crank.length), time_domain=td, forces=fo, plans=pl,
        drawing=describe(mech, kin), output_link=output_link(mech),
        warnings=tuple(case.plausibility_warnings()) + warnings_of(ld, red, en, sz, mo, fo, td)),
        case)                                           # [start]: a motion from rest


def force_motion(case, motion: str | None) -> str:
    """The motion of the force analysis: ``motion`` if given (``run --motion``), else the
    case's force_analysis.motion; "true" or "steady" (InputError otherwise)."""
    motion = motion if motion is not None else case.force_analysis.motion
    if motion not in stages.MOTIONS:
        raise InputError(Notice.of(
            "option_choice", "{option}: {got} is not {what} (allowed: {allowed})",
            option="--motion", got=repr(motion), what="a motion",
            allowed=", ".join(stages.MOTIONS)))
    return motion


def force_loads(case, mech, dcs: dict, kin, ld: LoadsResult, J_I: float):
    """The case's loads as the force analysis takes them (:class:`forces.Loads`), the same
    loads whose reduced moments :func:`linkage_loads` gives: each gas force F (ld.cylinders) pushes
    its piston away from the cylinder head along the guide, (F·sign(x_far − x_head))·u, whose
    moment F·v_q is L.gas_moment; each technological force opposes its slider's velocity,
    −F·sign(x′)·u, moment −F·|x′| (L.technological_moment); weights m·g at the centroids;
    the couples; the links' masses; J_I [kg·m²] on the crank shaft (the first group as the
    dynamics sized it)."""
    from flywheel.dynamics import forces

    pf = []
    for cy, cr in zip(case.cylinders, ld.cylinders):
        d, u, _, head, far = slider_frame(mech, dcs, cy.piston, cy.head, f"cylinders {cy.name}: piston")
        F = cr.F * np.sign(far.x - head.x)
        # named by the cylinder's label (F_ВД), else by its piston's link (F₃ on piston 3, as
        # G₃ and Φ₃ are: its cylinder's name may be a number of another link, cylinder 2 on 5)
        pf.append(forces.PointForce(cy.name, cy.piston, d.joint, F[:, None] * u,
                                    label=cy.label or cy.piston))
    applied = A.applied_loads(case, mech, kin)
    for f in case.forces:
        if f.slider is None:
            pf += [forces.PointForce(f.name, lk, p, F, on, f.label)
                   for lk, p, F, on in applied[L.LoadKey("force", f.name)].vectors]
            continue
        d, u, _, _, _ = slider_frame(mech, dcs, f.slider, f.reference, f"forces {f.name}: slider")
        F = -ld.forces[f.name] * np.sign(kin.points[d.joint].v_q @ u)
        pf.append(forces.PointForce(f.name, f.slider, d.joint, F[:, None] * u, label=f.label))
    couples = tuple(forces.Couple(c.name, lk, M, on, c.label)
                    for c in case.couples for lk, M, on in (
                        applied[L.LoadKey("couple", c.name)].couples if A.is_new_couple(c)
                        else ((c.link, c.moment, True),)))
    for sp in case.springs:
        ap = applied[L.LoadKey("spring", sp.name)]
        pf += [forces.PointForce(sp.name, lk, p, F, on, sp.label) for lk, p, F, on in ap.vectors]
        couples += tuple(forces.Couple(sp.name, lk, M, on, sp.label) for lk, M, on in ap.couples)
    return forces.Loads(dict(case.links), tuple(pf), couples, tuple(case.machine.gravity), J_I)


def linkage_loads(case, mech, dcs: dict, kin) -> LoadsResult:
    """The case's loads on the grid of ``kin``: gas forces of the cylinders (indicator tables),
    technological forces (with their exact works), weights, couples — each as its reduced
    moment, by name (seed 000 §3.2; design.md §2). ``dcs``: the sliders' dead centres."""
    phi, P, Lk = kin.phi, kin.points, kin.links
    M_parts: dict[L.LoadKey, np.ndarray] = {}
    W_parts: dict[L.LoadKey, np.ndarray] = {}      # exact cumulative works, where the trapezoid is not
    cylinders: list[CylinderResult] = []
    forces: dict[str, np.ndarray] = {}
    tensions: dict[str, np.ndarray] = {}
    warnings: list[str] = []
    fires_at = firing_angles(case, mech, dcs) if any(c.four_stroke for c in case.cylinders) else {}
    for cy in case.cylinders:
        if cy.four_stroke:
            cylinders.append(four_stroke_cylinder(cy, mech, dcs, kin, fires_at[cy.name]))
            M_parts[L.LoadKey("gas", cy.name)] = cylinders[-1].M
            if (W := gas_work(cy, mech, dcs, kin, cylinders[-1])) is not None:
                W_parts[L.LoadKey("gas", cy.name)] = W   # exact for linear tables
            continue
        d, u, base, head, far = slider_frame(mech, dcs, cy.piston, cy.head, f"cylinders {cy.name}: piston")
        x = (P[d.joint].r - base) @ u
        x_dot = P[d.joint].v_q @ u
        s_tab = np.asarray(cy.s, float)
        up, down = np.asarray(cy.towards_head, float), np.asarray(cy.away_from_head, float)
        p, F, s = L.gas_force(x, x_dot, head.x, far.x, s_tab, up, down, cy.p_max, cy.bore,
                              cy.interpolation)
        M = L.gas_moment(F, x_dot, head.x, far.x)
        if np.min(p) < 0:
            i = int(np.argmin(p))
            p_mpa, at = float(p[i]) / PA_PER_MPA, math.degrees(phi[i])
            warnings.append(Notice.of(
                "cylinder_negative_p", "cylinder {cylinder}: the {kind} interpolation of its "
                "indicator table gives negative pressure, down to {p:.4g} MPa at φ = "
                "{phi_deg:.1f}° (use 'pchip' to avoid overshoot)",
                cylinder=cy.label or cy.name, kind=cy.interpolation, p=p_mpa, phi_deg=at))
        M_parts[L.LoadKey("gas", cy.name)] = M
        towards = x_dot * (head.x - far.x) > 0
        cylinders.append(CylinderResult(cy.name, cy.piston, s, towards, p, F, M, s_tab, up, down,
                                        cy.p_max, head.phi, label=cy.label))
        if (W := gas_work(cy, mech, dcs, kin, cylinders[-1])) is not None:
            W_parts[L.LoadKey("gas", cy.name)] = W       # exact for linear tables
    applied = A.applied_loads(case, mech, kin)
    for f in case.forces:
        key = L.LoadKey("force", f.name)
        if f.slider is None:                  # a force at a point (dynamics.applied)
            M_parts[key], W_parts[key], forces[f.name] = applied[key].M, applied[key].W, applied[key].F
            continue
        d, u, base, ref, other = slider_frame(mech, dcs, f.slider, f.reference, f"forces {f.name}: slider")
        x = (P[d.joint].r - base) @ u
        x_dot = P[d.joint].v_q @ u
        F, M = L.technological_moment(x, x_dot, ref.x, other.x, f.magnitude, tuple(f.s_range), f.stroke)
        W = L.technological_work(x, ref.x, other.x, f.magnitude, tuple(f.s_range), f.stroke)
        if f.phi_range_deg is not None:       # and only over a part of the cycle
            rng, cycle = tuple(math.radians(a) for a in f.phi_range_deg), case.machine.cycle
            on = A.nodes_on(phi, rng, cycle)
            F, M = np.where(on, F, 0.0), np.where(on, M, 0.0)
            W = np.concatenate([[0.0], np.cumsum(np.diff(W) * A.intervals_on(phi, rng, cycle))])
        M_parts[key], W_parts[key], forces[f.name] = M, W, F
    g = np.asarray(case.machine.gravity, float)
    for name, lk in case.links.items():
        if lk.mass > 0 and np.any(g != 0):
            M_parts[L.LoadKey("gravity", name)] = L.gravity_moment(lk.mass, g, P[lk.centroid].v_q)
    for c in case.couples:
        key = L.LoadKey("couple", c.name)
        if A.is_new_couple(c):                # over a range, or a table (dynamics.applied)
            M_parts[key], W_parts[key] = applied[key].M, applied[key].W
        else:
            M_parts[key] = c.moment * Lk[c.link].omega_q
    for sp in case.springs:                   # −dU/dφ, and the exact work −ΔU
        key = L.LoadKey("spring", sp.name)
        M_parts[key], W_parts[key] = applied[key].M, applied[key].W
        if applied[key].F is not None:
            tensions[sp.name] = applied[key].F
    titles = {L.LoadKey(kind, x.name): x.title for kind, given in (
        ("gas", case.cylinders), ("force", case.forces), ("couple", case.couples),
        ("spring", case.springs)) for x in given if x.title}
    return LoadsResult(M_parts=M_parts, W_parts=W_parts, cylinders=tuple(cylinders),
                       forces=forces, warnings=tuple(warnings), tensions=tensions, titles=titles)


def linkage_reduction(case, kin) -> ReductionResult:
    """Each link's share of J_II and dJ_II/dφ from its mass, J_S and the analogues of its
    centroid and its turning (seed 000 §3.1), summed by :func:`stages.reduced_inertia`."""
    phi, P, Lk = kin.phi, kin.points, kin.links
    J_parts, dJ_parts = {}, {}
    for name, lk in case.links.items():
        if lk.mass == 0 and lk.J_S == 0:
            continue
        c = P[lk.centroid] if lk.centroid else None
        v = c.v_q if c is not None else np.zeros((phi.size, 2))
        a = c.a_q if c is not None else np.zeros((phi.size, 2))
        lm = Lk[name]
        J_parts[name], dJ_parts[name] = reduction.link_inertia(lk.mass, lk.J_S, v, a, lm.omega_q, lm.eps_q)
    return stages.reduced_inertia(phi, J_parts, dJ_parts)


def report_angles(at_deg: list[float], kin, ld: LoadsResult, red: ReductionResult,
                  en: EnergyResult, omega: np.ndarray, epsilon: np.ndarray) -> tuple[AtAngle, ...]:
    """summary.json's "at" (without the force analysis: :func:`results.with_forces`): at each
    report angle [deg] the crank's ω and ε, J_II, the moments and forces, and every point's and
    link's true velocity and acceleration (v = v_q·ω, a = a_q·ω² + v_q·ε; ω_i = ω_q·ω,
    ε_i = ε_q·ω² + ω_q·ε). ``omega`` [rad/s], ``epsilon`` [rad/s²]: the crank's motion on the
    grid as the force analysis takes it (ω(φ), ε(φ) of the dynamics, or ω_m and 0 with
    ``--motion steady``), so both describe the same motion."""
    out = []
    for a in at_deg:
        i = report_index(kin.phi, a)
        w, e = float(omega[i]), float(epsilon[i])
        pts = {}
        for name, pm in kin.points.items():
            v_vec = pm.v_q[i] * w
            a_vec = pm.a_q[i] * w**2 + pm.v_q[i] * e
            pts[name] = PointAt(
                x=float(pm.r[i, 0]), y=float(pm.r[i, 1]),
                v_q=float(np.hypot(*pm.v_q[i])), a_q=float(np.hypot(*pm.a_q[i])),
                v=float(np.hypot(*v_vec)), a=float(np.hypot(*a_vec)),
                v_x=float(v_vec[0]), v_y=float(v_vec[1]),
                a_x=float(a_vec[0]), a_y=float(a_vec[1]))
        lks = {}
        for name, lm in kin.links.items():
            lks[name] = LinkAt(
                omega_q=float(lm.omega_q[i]), epsilon_q=float(lm.eps_q[i]),
                omega=float(lm.omega_q[i] * w),
                epsilon=float(lm.eps_q[i] * w**2 + lm.omega_q[i] * e))
        out.append(AtAngle(
            phi_deg=float(a), omega=w, epsilon=e,
            J_II=float(red.J_II[i]), dJ_II=float(red.dJ_II[i]), M_sum=float(en.M_sum[i]),
            moments={str(k): float(v[i]) for k, v in ld.M_parts.items()},
            forces={**{c.name: float(c.F[i]) for c in ld.cylinders},     # gas, then technological
                    **{k: float(F[i]) for k, F in ld.forces.items()},
                    **{k: float(T[i]) for k, T in ld.tensions.items()}},     # then springs
            points=pts, links=lks))
    return tuple(out)


