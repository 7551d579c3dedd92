"""The pipeline: case → kinematics → loads → reduction → energy → sizing → motion → Results.

Reads the validated case and calls the pure stage functions in order (design.md §1); the
stages themselves know nothing of case files. Report angles, the 12 standard positions and
the dead centres are inserted into the φ grid, so their values are computed, not interpolated.
"""
from __future__ import annotations

import math

import numpy as np

from flywheel.dynamics import energy, loads, motion, reduction, sizing
from flywheel.errors import InputError
from flywheel.linkage import solve
from flywheel.linkage.deadcentres import dead_centres, guide_frame, slider_dyad
from flywheel.dynamics.results import Column, CylinderResult, Results

DEFAULT_POINTS = 3600


def _grid(n_points: int, extra: list[float]) -> np.ndarray:
    """Closed grid over [0, 2π]: n_points uniform intervals plus the extra angles [rad]."""
    base = np.linspace(0.0, 2 * np.pi, n_points + 1)
    extra = np.mod(np.asarray(extra, float), 2 * np.pi)
    phi = np.union1d(base, extra)
    # merge nodes closer than 1e-9 rad (an extra angle that is already a node)
    keep = np.concatenate([[True], np.diff(phi) > 1e-9])
    phi = phi[keep]
    phi[-1] = 2 * np.pi
    return phi


MAX_POINTS = 100_000      # ≈ 0.5 GB of arrays; far past convergence (tests/test_dynamics.py)


def grid_options(case, n_points: int, at_deg: list[float] | None) -> list[float]:
    """Check --points and --at; the report angles [deg] (default: the case's output.at_deg)."""
    if not 36 <= n_points <= MAX_POINTS:
        raise InputError(f"--points: {n_points} is out of range (allowed: 36 … {MAX_POINTS}; "
                         f"results converge well before: the default {DEFAULT_POINTS} is within "
                         f"1e-4 of a 4× finer grid)")
    at_deg = list(case.output.at_deg if at_deg is None else at_deg)
    for a in at_deg:
        if not math.isfinite(a):
            raise InputError(f"--at: {a} is not a finite angle in degrees")
    return at_deg


def _slider_frame(mech, dcs: dict, slider: str, near: str, what: str) -> tuple:
    """(dyad, guide unit vector u, guide base point, near dead centre, far dead centre) of a
    slider: ``near`` ('outer' or 'inner') names the dead centre that s is measured from (a
    cylinder's head, a force's reference). ``what`` names the load in the error."""
    d = slider_dyad(mech, slider)
    u, base = guide_frame(d)
    kinds = {dc.kind: dc for dc in dcs[slider]}
    if set(kinds) != {"outer", "inner"}:
        raise InputError(f"{what} {slider} has no pair of dead centres")
    a, b = kinds["outer"], kinds["inner"]
    return (d, u, base, a, b) if near == "outer" else (d, u, base, b, a)


def _force_switch_angles(case, mech, dcs, phi: np.ndarray, kin) -> list[float]:
    """Crank angles [rad] where a technological force's slider reaches the ends of its s_range
    (the force switches on or off): found in the grid's intervals, refined by Newton's method
    on x(φ) with the exact analogue x' (4 steps: quadratic convergence from h ≤ 2π/36)."""
    out: list[float] = []
    for f in case.forces:
        d, u, base, ref, other = _slider_frame(mech, dcs, f.slider, f.reference, f"forces {f.name}: slider")
        x = (kin.points[d.joint].r - base) @ u
        for s_b in f.s_range:
            if not 0.0 < s_b < 1.0:
                continue                    # the dead centres are nodes already
            x_b = ref.x + s_b * (other.x - ref.x)
            i = loads.travel_crossings(x, x_b)
            if i.size == 0:
                continue
            a = 0.5 * (phi[i] + phi[i + 1])
            for _ in range(4):
                k = solve(mech, a)
                xa = (k.points[d.joint].r - base) @ u
                a = np.clip(a - (xa - x_b) / (k.points[d.joint].v_q @ u), phi[i], phi[i + 1])
            out += [float(v) for v in a]
    return out


def _extremes(x: np.ndarray) -> tuple[float, float]:
    return float(np.min(x)), float(np.max(x))


def analyze(case, n_points: int = DEFAULT_POINTS, at_deg: list[float] | None = None,
            transients: bool = False) -> Results:
    """Run the whole dynamic analysis of a validated case (:class:`flywheel.cases.run.Case`).

    n_points: uniform intervals over the cycle (the report angles, standard positions and dead
    centres are added as nodes); at_deg: report angles [deg] (default: the case's
    output.at_deg); transients: also integrate the equation of motion in time (a check of
    ω(φ), start-up with the case's motor, run-down; imports scipy). Raises FlywheelError subclasses for input that cannot be analysed.
    """
    if case.tabulated is not None:
        from flywheel.dynamics.tabulated import analyze_tabulated

        return analyze_tabulated(case, n_points, at_deg, transients)
    from flywheel.cases.run import to_mechanism

    at_deg = grid_options(case, n_points, at_deg)
    mech = to_mechanism(case)
    machine = case.machine
    warnings: list[str] = []

    # -- standard positions: every 30° and the dead centres of every slider ---------------------
    sliders = [d.slider for d in mech.dyads if hasattr(d, "guide")]
    dcs = {s: dead_centres(mech, s) for s in sliders}
    positions = [(f"{k * 30}°", math.radians(k * 30)) for k in range(12)]
    for s, lst in dcs.items():
        for dc in lst:
            label = f"{s} {dc.kind} d.c."
            same = [i for i, (_, ph) in enumerate(positions) if abs(ph - dc.phi) < 1e-9]
            if same:     # a dead centre on a standard position: one row, both names
                i = same[0]
                positions[i] = (f"{positions[i][0]} = {label}", positions[i][1])
            else:
                positions.append((label, dc.phi))
    positions.sort(key=lambda p: p[1])
    extra = [p[1] for p in positions] + [math.radians(a) for a in at_deg]
    phi = _grid(n_points, extra)
    kin = solve(mech, phi)
    if case.forces:     # where a technological force switches on or off: nodes of the grid
        switch = _force_switch_angles(case, mech, dcs, phi, kin)
        if switch:
            phi = _grid(n_points, extra + switch)
            kin = solve(mech, phi)
    P, L = kin.points, kin.links

    # -- loads --------------------------------------------------------------------------------
    M_parts: dict[str, np.ndarray] = {}
    W_parts: dict[str, np.ndarray] = {}      # exact cumulative works, where the trapezoid is not
    cyl_results: list[CylinderResult] = []
    columns: dict[str, Column] = {}
    for cy in case.cylinders:
        d, u, base, head, far = _slider_frame(mech, dcs, cy.piston, cy.head, f"cylinders {cy.name}: piston")
        x = (P[d.joint].r - base) @ u
        x_dot = P[d.joint].v_q @ u
        s_tab = np.asarray(cy.s, float)
        up, down = np.asarray(cy.towards_head, float), np.asarray(cy.away_from_head, float)
        p, F, s = loads.gas_force(x, x_dot, head.x, far.x, s_tab, up, down, cy.p_max, cy.bore,
                                  cy.interpolation)
        M = loads.gas_moment(F, x_dot, head.x, far.x)
        if np.min(p) < 0:
            i = int(np.argmin(p))
            warnings.append(f"cylinder {cy.name}: the {cy.interpolation} interpolation of its "
                            f"indicator table gives negative pressure, down to {p[i] / 1e6:.4g} MPa "
                            f"at φ = {math.degrees(phi[i]):.1f}° (use 'pchip' to avoid overshoot)")
        M_parts[f"gas {cy.name}"] = M
        towards = x_dot * (head.x - far.x) > 0
        cyl_results.append(CylinderResult(cy.name, cy.piston, s, towards, p, F, M, s_tab, up, down,
                                          cy.p_max, head.phi))
        columns[f"s_{cy.name}"] = Column(s, "-", f"relative piston travel from the head, {cy.name}",
                                         f"относительное перемещение поршня {cy.name}")
        columns[f"p_{cy.name}"] = Column(p, "Pa", f"gas pressure, {cy.name}", f"давление {cy.name}")
        columns[f"F_{cy.name}"] = Column(F, "N", f"gas force on piston {cy.piston}",
                                         f"сила давления газа на поршень {cy.piston}")
    for f in case.forces:
        d, u, base, ref, other = _slider_frame(mech, dcs, f.slider, f.reference, f"forces {f.name}: slider")
        x = (P[d.joint].r - base) @ u
        x_dot = P[d.joint].v_q @ u
        F, M = loads.technological_moment(x, x_dot, ref.x, other.x, f.magnitude, tuple(f.s_range), f.stroke)
        M_parts[f"force {f.name}"] = M
        W_parts[f"force {f.name}"] = loads.technological_work(x, ref.x, other.x, f.magnitude,
                                                              tuple(f.s_range), f.stroke)
        columns[f"F_{f.name}"] = Column(F, "N", f"technological force {f.name}", f"сила {f.name}")
    g = np.asarray(machine.gravity, float)
    for name, lk in case.links.items():
        if lk.mass > 0 and np.any(g != 0):
            M_parts[f"gravity {name}"] = loads.gravity_moment(lk.mass, g, P[lk.centroid].v_q)
    for c in case.couples:
        M_parts[f"couple {c.name}"] = c.moment * L[c.link].omega_q

    # -- reduction of masses ---------------------------------------------------------------------
    J_parts, dJ_parts = {}, {}
    for name, lk in case.links.items():
        if lk.mass == 0 and lk.J_S == 0:
            continue
        c = P[lk.centroid] if lk.centroid else None
        v = c.v_q if c is not None else np.zeros((phi.size, 2))
        a = c.a_q if c is not None else np.zeros((phi.size, 2))
        lm = L[name]
        J, dJ = reduction.link_inertia(lk.mass, lk.J_S, v, a, lm.omega_q, lm.eps_q)
        J_parts[name], dJ_parts[name] = J, dJ

    dyn = dynamics(phi, J_parts, dJ_parts, M_parts, case.machine, case.flywheel, warnings, W_parts)
    J_II, dJ_II, M_sum, M_known, omega, eps = (dyn[k] for k in ("J_II", "dJ_II", "M_sum", "M_known",
                                                             "omega", "epsilon"))
    J_I, driving_moment = dyn["J_I"], dyn["scalars"]["driving_moment"]

    # -- table columns -----------------------------------------------------------------------------------
    cols: dict[str, Column] = {"phi_deg": Column(np.degrees(phi), "deg", "crank angle φ", "угол φ")}
    for name, pm in P.items():
        if np.all(pm.v_q == 0) and np.all(pm.a_q == 0):
            continue
        cols[f"x_{name}"] = Column(pm.r[:, 0], "m", f"x of {name}", f"x точки {name}")
        cols[f"y_{name}"] = Column(pm.r[:, 1], "m", f"y of {name}", f"y точки {name}")
        cols[f"vq_{name}"] = Column(np.hypot(*pm.v_q.T), "m/rad", f"|v_q| of {name}",
                                    f"аналог скорости {name}")
        cols[f"vqx_{name}"] = Column(pm.v_q[:, 0], "m/rad", f"v_qx of {name}", f"v_qx {name}")
        cols[f"vqy_{name}"] = Column(pm.v_q[:, 1], "m/rad", f"v_qy of {name}", f"v_qy {name}")
        cols[f"aq_{name}"] = Column(np.hypot(*pm.a_q.T), "m/rad²", f"|a_q| of {name}",
                                    f"аналог ускорения {name}")
        cols[f"aqx_{name}"] = Column(pm.a_q[:, 0], "m/rad²", f"a_qx of {name}", f"a_qx {name}")
        cols[f"aqy_{name}"] = Column(pm.a_q[:, 1], "m/rad²", f"a_qy of {name}", f"a_qy {name}")
    for name, lm in L.items():
        if name == mech.crank.name or (np.all(lm.omega_q == 0) and np.all(lm.eps_q == 0)):
            continue
        cols[f"theta_{name}"] = Column(np.degrees(lm.theta), "deg", f"angle of link {name}",
                                       f"угол звена {name}")
        cols[f"omega_q_{name}"] = Column(lm.omega_q, "-", f"ω_q of link {name}", f"аналог угл. скорости {name}")
        cols[f"eps_q_{name}"] = Column(lm.eps_q, "1/rad", f"ε_q of link {name}",
                                       f"аналог угл. ускорения {name}")
    cols.update(columns)
    cols.update(dyn["columns"])

    # -- report angles -----------------------------------------------------------------------------------------
    at_list = []
    for a in at_deg:
        i = int(np.argmin(np.abs(phi - math.radians(a) % (2 * np.pi))))
        w, e = float(omega[i]), float(eps[i])
        pts = {}
        for name, pm in P.items():
            v_vec = pm.v_q[i] * w
            a_vec = pm.a_q[i] * w**2 + pm.v_q[i] * e
            pts[name] = {
                "x": float(pm.r[i, 0]), "y": float(pm.r[i, 1]),
                "v_q": float(np.hypot(*pm.v_q[i])), "a_q": float(np.hypot(*pm.a_q[i])),
                "v": float(np.hypot(*v_vec)), "a": float(np.hypot(*a_vec)),
                "v_x": float(v_vec[0]), "v_y": float(v_vec[1]),
                "a_x": float(a_vec[0]), "a_y": float(a_vec[1]),
            }
        lks = {}
        for name, lm in L.items():
            lks[name] = {
                "omega_q": float(lm.omega_q[i]), "epsilon_q": float(lm.eps_q[i]),
                "omega": float(lm.omega_q[i] * w),
                "epsilon": float(lm.eps_q[i] * w**2 + lm.omega_q[i] * e),
            }
        at_list.append({
            "phi_deg": float(a), "omega": w, "epsilon": e,
            "J_II": float(J_II[i]), "dJ_II": float(dJ_II[i]), "M_sum": float(M_sum[i]),
            "moments": {k: float(v[i]) for k, v in M_parts.items()},
            "forces": {**{c.name: float(c.F[i]) for c in cyl_results},     # gas, then technological
                       **{f.name: float(columns[f"F_{f.name}"].values[i]) for f in case.forces}},
            "points": pts, "links": lks,
        })

    scalars = {"crank_length": float(mech.crank.length), **dyn["scalars"]}
    links_drawn = [(mech.crank.name, [mech.crank.pivot, mech.crank.tip])]
    for d in mech.dyads:
        if hasattr(d, "guide"):
            links_drawn.append((d.rod, [d.origin, d.joint]))
        elif hasattr(d, "rocker"):
            links_drawn.append((d.rocker, [d.pivot, d.origin]))
        else:
            links_drawn.append((d.link_a, [d.point_a, d.joint]))
            links_drawn.append((d.link_b, [d.point_b, d.joint]))
    time_domain = None
    if transients:
        time_domain = _transients(case, phi, J_I + J_II, dJ_II, M_sum, M_known, omega, driving_moment,
                                  warnings)
        scalars["time_domain"] = {k: v for k, v in time_domain.items() if k != "histories"}
    for p in mech.points:               # centroids and other points drawn on their links
        for link, pts in links_drawn:
            if link == p.link and p.name not in pts:
                pts.append(p.name)
    return Results(
        time_domain=time_domain,
        title=case.title, source=case.source, phi=phi, kinematics=kin, columns=cols,
        scalars=scalars, at=at_list, position_angles=positions, J_parts=J_parts,
        dJ_parts=dJ_parts, M_parts=M_parts, cylinders=cyl_results, links_drawn=links_drawn,
        warnings=warnings,
    )


def dynamics(phi: np.ndarray, J_parts: dict, dJ_parts: dict, M_parts: dict, machine, fw,
             warnings: list[str], W_parts: dict | None = None) -> dict:
    """Energy → sizing → motion, shared by every route that yields J_II's parts and the reduced
    moments on a closed φ grid (linkage kinematics, tabulated kinematics).

    J_parts, dJ_parts: link name → J share [kg·m²], dJ/dφ share; M_parts: load name → reduced
    moment [N·m]; machine, fw: the case's [machine] and [flywheel]. Returns a dict with the
    arrays (J_II, dJ_II, M_known, M_sum, A, omega, epsilon, …), "J_I", "columns" (for
    table.csv) and "scalars" (for summary.json). Appends warnings.
    """
    omega_m = machine.omega_mean
    zero = np.zeros_like(phi)
    if J_parts:
        J_II, dJ_II = reduction.reduced_inertia({k: (J_parts[k], dJ_parts[k]) for k in J_parts})
    else:
        J_II, dJ_II = zero.copy(), zero.copy()

    # -- energy --------------------------------------------------------------------------------------
    M_known = sum(M_parts.values()) if M_parts else zero.copy()
    W_parts = W_parts or {}
    A_known = energy.cumulative_work(sum((M for k, M in M_parts.items() if k not in W_parts),
                                         zero.copy()), phi) + sum(W_parts.values(), zero.copy())
    work_known = float(A_known[-1])
    M_const = energy.balancing_moment(A_known, phi)
    if abs(work_known) <= 1e-9 * float(energy.cumulative_work(np.abs(M_known), phi)[-1]):
        # only conservative loads (gravity, say): nothing to balance, round-off aside
        M_const, work_known = 0.0, 0.0
        warnings.append("the loads do no net work over a cycle: the balancing moment is 0 "
                        "(the flywheel only smooths the loads' periodic part)")
    elif machine.balance == "driving" and not M_const > 0:
        raise InputError(
            f"the loads do {work_known:+.6g} J of work over a cycle: a constant driving moment "
            f"would have to be {M_const:.6g} N·m ≤ 0 (allowed: resistance must absorb work; "
            f"for an engine set machine.balance = \"resistance\")")
    if machine.balance == "resistance" and not M_const < 0:
        raise InputError(
            f"the loads do {work_known:+.6g} J of work over a cycle: a constant resistance moment "
            f"would have to be {-M_const:.6g} N·m ≤ 0 (allowed: driving forces must supply work; "
            f"for a compressor or press set machine.balance = \"driving\")")
    M_sum = M_known + M_const
    A_const = M_const * phi
    A = A_known + A_const
    if machine.balance == "driving":
        A_D, A_C = A_const, A_known
        cycle_work_resistance = work_known
        driving_moment = M_const
    else:
        A_D, A_C = A_known, A_const
        cycle_work_resistance = M_const * 2 * np.pi
        driving_moment = work_known / (2 * np.pi)
    T_II, dT_I = energy.first_group_energy_change(A, J_II, omega_m)
    phi_max, dT_max = energy.extreme(dT_I, phi, "max")
    phi_min, dT_min = energy.extreme(dT_I, phi, "min")
    delta_T_max = dT_max - dT_min

    # -- sizing ----------------------------------------------------------------------------------------
    delta = machine.delta
    J_req = sizing.J_required_merzalov(delta_T_max, omega_m, delta)
    J_first = float(sum(machine.first_group.values()))
    J_fly = J_req - J_first
    if J_fly <= 0:
        warnings.append(f"the first group already has {J_first:.6g} kg·m² ≥ J_required = {J_req:.6g} "
                        f"kg·m²: no flywheel is needed")
    J_exact, T0_exact = sizing.J_required_exact(A, J_II, omega_m, delta)
    J_shaft = max(J_fly, 0.0) / fw.speed_ratio**2          # seed 003, eqs. 9.21–9.23
    if fw.formulas == "course":
        disk, rim = sizing.disk_course(J_shaft), sizing.rim_course(J_shaft * fw.rim_share)
    else:
        disk = sizing.disk(J_shaft, fw.rho, fw.width_ratio)
        rim = sizing.rim(J_shaft * fw.rim_share, fw.rho, fw.width_ratio, fw.inner_ratio)

    # -- motion ----------------------------------------------------------------------------------------
    J_I = max(J_req, J_first)            # what is really on the crank shaft
    if not J_I + float(J_II.min()) > 0:
        raise InputError("the machine has no inertia: the loads cause no fluctuation of energy "
                         "(ΔT_нб = 0, so no flywheel is sized), no link carries mass and nothing "
                         "is on the crank shaft, so ω(φ) is undefined (allowed: masses in [links] "
                         "or machine.first_group)")
    if not all(np.isfinite(x) for x in (J_I, delta_T_max, float(np.max(np.abs(J_II))),
                                          float(np.max(np.abs(A))))):
        raise InputError("the results overflow: the case's values are out of range (allowed: SI "
                         "units, m, kg, N, Pa)")
    T0 = motion.T0_for_mean_speed(A, J_I, J_II, omega_m)
    omega = motion.omega_from_energy(T0, A, J_I, J_II)
    w_max, w_min, w_mean, delta_ach = motion.speed_fluctuation(omega)
    eps = motion.angular_acceleration(M_sum, omega, J_I + J_II, dJ_II)
    t = motion.time_law(omega, phi)
    omega_exact = motion.omega_from_energy(T0_exact, A, J_exact, J_II)
    delta_ach_exact = motion.speed_fluctuation(omega_exact)[3]
    i_wmax, i_wmin = int(np.argmax(omega)), int(np.argmin(omega))

    v_limit = sizing.rim_speed_limit(fw.sigma, fw.rho)
    for shape, dims in (("disk", disk), ("rim", rim)):
        dims["rim_speed"] = w_max * fw.speed_ratio * dims["D"] / 2
        if dims["rim_speed"] > v_limit:
            material = fw.material if fw.density is None and fw.allowable_stress is None \
                else "the given material"
            warnings.append(f"flywheel as a {shape}: rim speed {dims['rim_speed']:.1f} m/s exceeds "
                            f"the safe {v_limit:.1f} m/s = √(σ/ρ) of a thin rotating ring (hoop "
                            f"stress σ = ρ·v², Timoshenko, Strength of Materials, part II) for "
                            f"{material}: σ = {fw.sigma / 1e6:g} MPa, ρ = {fw.rho:g} kg/m³ (set "
                            f"flywheel.allowable_stress, or a wider flywheel: width_ratio)")

    cols: dict[str, Column] = {}
    for name, J in J_parts.items():
        cols[f"J_{name}"] = Column(J, "kg·m²", f"link {name}'s share of J_II", f"вклад звена {name} в J_II")
    for name, dJ in dJ_parts.items():
        cols[f"dJ_{name}"] = Column(dJ, "kg·m²/rad", f"link {name}'s share of dJ_II/dφ",
                                    f"вклад звена {name} в dJ_II/dφ")
    cols["J_II"] = Column(J_II, "kg·m²", "reduced inertia of the second group J_II",
                          "приведённый момент инерции II группы")
    cols["dJ_II"] = Column(dJ_II, "kg·m²/rad", "dJ_II/dφ", "производная J_II")
    for name, M in M_parts.items():
        cols[f"M {name}"] = Column(M, "N·m", f"reduced moment: {name}", f"приведённый момент: {name}")
    cols["M_known"] = Column(M_known, "N·m", "sum of the given loads' reduced moments",
                             "суммарный приведённый момент заданных сил")
    cols["M_sum"] = Column(M_sum, "N·m", "total reduced moment M_Σ", "суммарный приведённый момент")
    cols["A_D"] = Column(A_D, "J", "work of the driving moment A_D", "работа движущих сил")
    cols["A_C"] = Column(A_C, "J", "work of the resistance A_C", "работа сил сопротивления")
    cols["A"] = Column(A, "J", "total work A", "суммарная работа")
    cols["T_II"] = Column(T_II, "J", "kinetic energy of the second group T_II", "кин. энергия II группы")
    cols["dT_I"] = Column(dT_I, "J", "change of kinetic energy of the first group ΔT_I",
                          "изменение кин. энергии I группы")
    cols["omega"] = Column(omega, "rad/s", "crank angular velocity ω", "угловая скорость звена приведения")
    cols["epsilon"] = Column(eps, "rad/s²", "crank angular acceleration ε", "угловое ускорение")
    cols["omega_exact"] = Column(omega_exact, "rad/s", "ω with the exact flywheel size",
                                 "ω при точном моменте инерции маховика")
    cols["t"] = Column(t, "s", "time t(φ)", "время")

    scalars = {
        "omega_mean": float(omega_m),
        "n_points": int(phi.size),
        "cycle_work_resistance": float(cycle_work_resistance),
        "driving_moment": float(driving_moment),
        "balancing_moment": float(M_const),
        "balance": machine.balance,
        "delta": float(delta),
        "delta_T_max": float(delta_T_max),
        "delta_T_I_max": float(dT_max), "phi_delta_T_I_max_deg": math.degrees(phi_max),
        "delta_T_I_min": float(dT_min), "phi_delta_T_I_min_deg": math.degrees(phi_min),
        "J_II_mean": float(energy.cumulative_work(J_II, phi)[-1] / (2 * np.pi)),
        "J_II_min": _extremes(J_II)[0], "J_II_max": _extremes(J_II)[1],
        "J_first_group": J_first,
        "J_required": float(J_req),
        "J_required_exact": float(J_exact),
        "J_flywheel": float(J_fly),
        "J_flywheel_exact": float(J_exact - J_first),
        "delta_achieved": float(delta_ach),
        "delta_achieved_exact": float(delta_ach_exact),
        "omega_max": w_max, "phi_omega_max_deg": math.degrees(phi[i_wmax]),
        "omega_min": w_min, "phi_omega_min_deg": math.degrees(phi[i_wmin]),
        "T0": float(T0),
        "cycle_time": float(t[-1]),
        "flywheel_disk": disk,
        "flywheel_rim": rim,
        "flywheel_material": fw.material,
        "flywheel_material_density": float(fw.rho),
        "flywheel_speed_ratio": float(fw.speed_ratio),
        "flywheel_J_on_its_shaft": float(J_shaft),
        "flywheel_rim_share": float(fw.rim_share),
        "flywheel_rim_speed_limit": float(v_limit),
        "flywheel_formulas": fw.formulas,
    }
    return {"J_II": J_II, "dJ_II": dJ_II, "M_known": M_known, "M_sum": M_sum, "A": A,
            "omega": omega, "epsilon": eps, "J_I": J_I, "columns": cols, "scalars": scalars}


def _transients(case, phi, J, dJ, M_sum, M_known, omega, driving_moment,
                warnings: list[str]) -> dict:
    """Time-domain stage: verification of ω(φ), start-up (with a motor), run-down. Appends a
    start-up that does not reach the steady state within its cap to ``warnings``."""
    from flywheel.dynamics import timedomain

    machine = case.machine
    out: dict = {"verification": timedomain.verify_steady(phi, J, dJ, M_sum, omega)}
    histories = {}
    if case.motor is not None:
        w_x = case.motor.no_load_speed_rpm * 2 * math.pi / 60
        M_p = case.motor.starting_torque or driving_moment / (1 - machine.omega_mean / w_x)
        st = timedomain.startup(phi, J, dJ, M_known, timedomain.linear_motor(M_p, w_x),
                                machine.omega_mean, machine.delta)
        out["startup"] = {k: v for k, v in st.items() if not isinstance(v, np.ndarray)}
        out["startup"]["starting_torque"] = float(M_p)
        out["startup"]["no_load_speed"] = float(w_x)
        if st.get("warning"):
            warnings.append(st["warning"])
        if "t" in st:
            histories["startup"] = (st["t"], st["omega"])
    else:
        out["startup"] = {"computed": False,
                          "reason": "no [motor] in the case: under a constant driving moment the work "
                                    "over a cycle is zero at any speed, so there is no start-up to a "
                                    "steady state"}
    rd = timedomain.rundown(phi, J, dJ, M_known, float(omega[0]))
    out["rundown"] = {k: v for k, v in rd.items() if not isinstance(v, np.ndarray)}
    histories["rundown"] = (rd["t"], rd["omega"])
    out["histories"] = histories
    return out
