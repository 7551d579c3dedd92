"""The stages that every route shares: reduction sums → energy → sizing → motion → time domain.

A route (the linkage :mod:`~flywheel.dynamics.pipeline`, the table
:mod:`~flywheel.dynamics.tabulated`) supplies the loads (:class:`LoadsResult`) and the links'
shares of J_II on a closed φ grid; these functions take it from there. They read only the
case's [machine], [flywheel] and [motor] sections, never a case file. Each returns a typed,
frozen result (:mod:`flywheel.dynamics.results`) whose ``warnings`` say what the user should
know; input that cannot be analysed raises :class:`~flywheel.errors.InputError`.
"""
from __future__ import annotations

from dataclasses import replace

import numpy as np

from flywheel.dynamics import energy, motion, reduction, sizing
from flywheel.dynamics.results import (EnergyResult, FlywheelShape, ForceResult, LoadsResult,
                                       MotionResult, ReductionResult, Rundown, SizingResult,
                                       StartupNotComputed, StartupRun, StartupStalled,
                                       TimeDomainResult, Verification)
from flywheel.errors import InputError, Notice, said
from flywheel.units import PA_PER_MPA, SECONDS_PER_MINUTE, TWO_PI


POWER_RTOL = 0.01
"""machine.power and the power of the case's loads, |M_const|·ω_m, may differ by this share
before a warning says so (a textbook rounds its power to three digits)."""


def reduced_inertia(phi: np.ndarray, J_parts: dict[str, np.ndarray],
                    dJ_parts: dict[str, np.ndarray], warnings=()) -> ReductionResult:
    """J_II and dJ_II/dφ as the sums of the links' shares (seed 000 §3.1), with J_II's cycle
    mean (1/Φ)·∮J_II dφ over the closed grid's cycle Φ (trapezoid rule) and extremes. J_parts
    [kg·m²], dJ_parts [kg·m²/rad] by link."""
    if J_parts:
        J_II, dJ_II = reduction.reduced_inertia({k: (J_parts[k], dJ_parts[k]) for k in J_parts})
    else:
        J_II, dJ_II = np.zeros_like(phi), np.zeros_like(phi)
    return ReductionResult(
        J_parts=J_parts, dJ_parts=dJ_parts, J_II=J_II, dJ_II=dJ_II,
        J_II_mean=float(energy.cumulative_work(J_II, phi)[-1] / (phi[-1] - phi[0])),
        J_II_min=float(np.min(J_II)), J_II_max=float(np.max(J_II)), warnings=tuple(warnings))


def work_and_energy(phi: np.ndarray, loads: LoadsResult, red: ReductionResult,
                    machine) -> EnergyResult:
    """The constant moment that balances the cycle, the works A_D, A_C, A, and ΔT_I(φ) with its
    global extremes (Merzalov; seed 000 §3.2.7, §4). ``machine``: the case's [machine]
    (ω_m, balance). The cycle Φ is the closed grid's (2π, or 4π for a four-stroke engine):
    M = −(1/Φ)·∮ M_known dφ. Raises InputError if the loads' work has the wrong sign for the
    balance; loads that do no net work (weights only) need no constant moment whichever the
    balance: M = 0 and a warning."""
    omega_m = machine.omega_mean
    cycle = phi[-1] - phi[0]
    zero = np.zeros_like(phi)
    M_parts, W_parts = loads.M_parts, loads.W_parts
    warnings: list[str] = []
    M_known = sum(M_parts.values()) if M_parts else zero.copy()
    A_known = energy.cumulative_work(sum((M for k, M in M_parts.items() if k not in W_parts),
                                         zero.copy()), phi) + sum(W_parts.values(), zero.copy())
    work_known = float(A_known[-1])
    M_const = energy.balancing_moment(A_known, phi)
    if abs(work_known) <= 1e-9 * float(energy.cumulative_work(np.abs(M_known), phi)[-1]):
        # only conservative loads (gravity, say): nothing to balance, round-off aside
        M_const, work_known = 0.0, 0.0
        warnings.append(Notice.of(
            "no_net_work", "the loads do no net work over a cycle: the balancing moment is 0 (the "
            "flywheel only smooths the loads' periodic part)"))
    elif machine.balance == "driving" and not M_const > 0:
        raise InputError(Notice.of(
            "balance_driving", "the loads do {work:+.6g} J of work over a cycle: a constant "
            "driving moment would have to be {M:.6g} N·m ≤ 0 (allowed: resistance must absorb "
            "work; for an engine set machine.balance = \"resistance\")", work=work_known,
            M=M_const))
    elif machine.balance == "resistance" and not M_const < 0:
        raise InputError(Notice.of(
            "balance_resistance", "the loads do {work:+.6g} J of work over a cycle: a constant "
            "resistance moment would have to be {M:.6g} N·m ≤ 0 (allowed: driving forces must "
            "supply work; for a compressor or press set machine.balance = \"driving\")",
            work=work_known, M=-M_const))
    A_const = M_const * phi
    A = A_known + A_const
    if machine.balance == "driving":
        A_D, A_C = A_const, A_known
        cycle_work_resistance = work_known
        driving_moment = M_const
    else:
        A_D, A_C = A_known, A_const
        cycle_work_resistance = M_const * cycle
        driving_moment = work_known / cycle
    power = getattr(machine, "power", None)
    power_moment = power_from_loads = None
    if power is not None:   # the mean power at ω_m: M = P/ω_m against the balance's moment
        power_moment = power / omega_m
        mean_moment = abs(float(M_const))   # mean driving (or resistance) moment [N·m]
        power_from_loads = mean_moment * omega_m
        if abs(power_from_loads - power) > POWER_RTOL * power:
            which = "driving" if machine.balance == "driving" else "resistance"
            warnings.append(Notice.of(
                "power_mismatch", "machine.power: P = {power:.6g} W at ω_m = {omega:.6g} rad/s "
                "means a mean {which} moment P/ω_m = {M_power:.6g} N·m, but the case's loads "
                "balance with {M_loads:.6g} N·m ({P_loads:.6g} W, {pct:+.3g} %): check the loads "
                "or the power", power=power, omega=omega_m, driving=which == "driving",
                M_power=power_moment, M_loads=mean_moment, P_loads=power_from_loads,
                pct=(power_from_loads / power - 1) * 100, which=which))
    T_II, dT_I = energy.first_group_energy_change(A, red.J_II, omega_m)
    phi_max, dT_max = energy.extreme(dT_I, phi, "max")
    phi_min, dT_min = energy.extreme(dT_I, phi, "min")
    return EnergyResult(
        balance=machine.balance, M_known=M_known, balancing_moment=float(M_const),
        M_sum=M_known + M_const, A_D=A_D, A_C=A_C, A=A,
        cycle_work_resistance=float(cycle_work_resistance), driving_moment=float(driving_moment),
        T_II=T_II, dT_I=dT_I, delta_T_I_max=float(dT_max), phi_delta_T_I_max=phi_max,
        delta_T_I_min=float(dT_min), phi_delta_T_I_min=phi_min,
        delta_T_max=float(dT_max - dT_min), power=power, power_moment=power_moment,
        power_from_loads=power_from_loads, warnings=tuple(warnings))


def size_flywheel(phi: np.ndarray, en: EnergyResult, red: ReductionResult, machine,
                  fw, delta: float | None = None, J_given: float | None = None) -> SizingResult:
    """J_I for δ by Merzalov and exactly (the energy–mass diagram, with its tangents and
    tangency points), the flywheel on its shaft (seed 003, eqs. 9.21–9.23) and its disk and rim
    dimensions. ``machine``, ``fw``: the case's [machine] and [flywheel]. Rim speeds come after
    the motion (:func:`with_rim_speeds`).

    A given flywheel (``J_given`` [kg·m²] on its own shaft, :func:`given_flywheel_delta`): no
    sizing — J_I = J_first_group + J_given·i² is what the crank shaft carries (J_required),
    ``delta`` is the δ it gives, and the exact J_I and the tangents are those of that δ (they
    come back to J_I: a check of the energy–mass diagram against the motion)."""
    omega_m = machine.omega_mean
    delta = machine.delta if delta is None else delta
    warnings: list[str] = []
    J_first = float(sum(machine.first_group.values()))
    if J_given is None:
        J_req = sizing.J_required_merzalov(en.delta_T_max, omega_m, delta)
    else:
        J_req = J_first + J_given * fw.speed_ratio ** 2
    J_fly = J_req - J_first if J_given is None else J_given * fw.speed_ratio ** 2
    if J_given is None and J_fly <= 0:
        warnings.append(Notice.of(
            "no_flywheel_needed", "the first group already has {J_first:.6g} kg·m² ≥ J_required = "
            "{J_required:.6g} kg·m²: no flywheel is needed", J_first=J_first, J_required=J_req))
    J_exact, T0_exact = sizing.J_required_exact(en.A, red.J_II, omega_m, delta)
    k_plus, k_minus = sizing.tangent_slopes(omega_m, delta)
    i_max, i_min = sizing.tangency_points(en.A, red.J_II, omega_m, delta)
    J_shaft = (max(J_fly, 0.0) / fw.speed_ratio**2          # seed 003, eqs. 9.21–9.23
               if J_given is None else J_given)
    if fw.formulas == "course":
        disk, rim = sizing.disk_course(J_shaft), sizing.rim_course(J_shaft * fw.rim_share)
    else:
        disk = sizing.disk(J_shaft, fw.rho, fw.width_ratio)
        rim = sizing.rim(J_shaft * fw.rim_share, fw.rho, fw.width_ratio, fw.inner_ratio)
    rim_spec = getattr(fw, "rim", None)
    designed = None
    if rim_spec is not None:          # [flywheel.rim]: the rim as engineers finish it
        try:
            designed = rim_spec.design(J_shaft, omega_m * fw.speed_ratio, fw.rho, fw.sigma)
        except InputError as exc:
            raise InputError(Notice.of(
                "with_flywheel_J", "{detail} (the flywheel's J = {J:.6g} kg·m² on its shaft)",
                detail=said(exc), J=J_shaft)) from None
    return SizingResult(
        omega_mean=float(omega_m), delta=float(delta), J_required=float(J_req),
        J_first_group=J_first, J_flywheel=float(J_fly), J_required_exact=float(J_exact),
        J_flywheel_exact=float(J_exact - J_first), T0_exact=T0_exact, k_plus=k_plus,
        k_minus=k_minus, T_k=k_plus * J_exact - T0_exact, T_l=k_minus * J_exact - T0_exact,
        i_tangent_max=i_max, i_tangent_min=i_min, speed_ratio=float(fw.speed_ratio),
        J_on_its_shaft=float(J_shaft), rim_share=float(fw.rim_share),
        disk=FlywheelShape(**disk), rim=FlywheelShape(**rim), material=fw.material,
        material_density=float(fw.rho),
        rim_speed_limit=float(sizing.rim_speed_limit(fw.sigma, fw.rho)), formulas=fw.formulas,
        rim_design=designed, flywheel_given=J_given is not None,
        J_flywheel_given=None if J_given is None else float(J_given), warnings=tuple(warnings))


def _overflow() -> Notice:
    """The error of results beyond double precision."""
    return Notice.of(
        "run_overflow", "the results overflow: the case's values are out of range (allowed: SI "
        "units, m, kg, N, Pa)")


def true_motion(phi: np.ndarray, en: EnergyResult, red: ReductionResult,
                sz: SizingResult) -> MotionResult:
    """ω(φ), ε(φ), t(φ) with J_I = max(J_required, J_first_group) on the crank shaft, and ω(φ)
    with the exact J_I (the energy equation; seed 000 §4). Raises InputError if there is no
    inertia at all or the numbers overflow."""
    A, J_II = en.A, red.J_II
    J_I = max(sz.J_required, sz.J_first_group)            # what is really on the crank shaft
    if not J_I + float(J_II.min()) > 0:
        raise InputError(Notice.of(
            "run_no_inertia", "the machine has no inertia: the loads cause no fluctuation of "
            "energy (ΔT_max = 0, so no flywheel is sized), no link carries mass and nothing is on "
            "the crank shaft, so ω(φ) is undefined (allowed: masses in [links] or "
            "machine.first_group)"))
    if not all(np.isfinite(x) for x in (J_I, en.delta_T_max, float(np.max(np.abs(J_II))),
                                          float(np.max(np.abs(A))))):
        raise InputError(_overflow())
    T0 = motion.T0_for_mean_speed(A, J_I, J_II, sz.omega_mean)
    omega = motion.omega_from_energy(T0, A, J_I, J_II)
    if not np.all(np.isfinite(omega)):    # finite energies, but ½·J·ω² beyond double precision
        raise InputError(_overflow())
    w_max, w_min, _, delta_ach = motion.speed_fluctuation(omega)
    eps = motion.angular_acceleration(en.M_sum, omega, J_I + J_II, red.dJ_II)
    t = motion.time_law(omega, phi)
    omega_exact = motion.omega_from_energy(sz.T0_exact, A, sz.J_required_exact, J_II)
    i_wmax, i_wmin = int(np.argmax(omega)), int(np.argmin(omega))
    return MotionResult(
        J_I=J_I, T0=float(T0), omega=omega, epsilon=eps, t=t, omega_exact=omega_exact,
        omega_max=w_max, phi_omega_max=float(phi[i_wmax]), omega_min=w_min,
        phi_omega_min=float(phi[i_wmin]), delta_achieved=float(delta_ach),
        delta_achieved_exact=float(motion.speed_fluctuation(omega_exact)[3]),
        cycle_time=float(t[-1]))


def with_rim_speeds(sz: SizingResult, mo: MotionResult, fw) -> SizingResult:
    """The sizing with the disk's and the rim's peripheral speeds at ω_max, and a warning for
    each above the limit √(σ/ρ) of a thin rotating ring (hoop stress σ = ρ·v²)."""
    warnings = list(sz.warnings)
    shapes = {}
    for shape, dims in (("disk", sz.disk), ("rim", sz.rim)):
        v = mo.omega_max * sz.speed_ratio * dims.D / 2
        shapes[shape] = replace(dims, rim_speed=v)
        if shape == "rim" and sz.rim_design is not None:
            continue                  # the designed rim replaces this one
        if v > sz.rim_speed_limit:
            material = fw.material if fw.density is None and fw.allowable_stress is None \
                else "the given material"
            warnings.append(Notice.of(
                "rim_speed", "flywheel as a {shape}: rim speed {v:.1f} m/s exceeds the safe "
                "{limit:.1f} m/s = √(σ/ρ) of a thin rotating ring (hoop stress σ = ρ·v², "
                "Timoshenko, Strength of Materials, part II) for {material}: σ = {sigma:g} MPa, ρ "
                "= {rho:g} kg/m³ (set flywheel.allowable_stress, or a wider flywheel: width_ratio)",
                shape=shape, v=v, limit=sz.rim_speed_limit, material=material,
                sigma=fw.sigma / PA_PER_MPA, rho=fw.rho))
    designed = sz.rim_design
    if designed is not None:          # its hoop stress at ω_max, ρ·(ω_max·i·D_mean/2)²
        designed = designed.at_top_speed(mo.omega_max * sz.speed_ratio)
        thin = sizing.thin_rim_notice(designed)
        if thin is not None:
            warnings.append(thin)
    return replace(sz, disk=shapes["disk"], rim=shapes["rim"], rim_design=designed,
                   warnings=tuple(warnings))


def given_flywheel_delta(en: EnergyResult, red: ReductionResult, machine, J_given: float,
                         speed_ratio: float) -> float:
    """The δ a given flywheel gives: J_I = J_first_group + J_given·i² [kg·m²] on the crank
    shaft, ω(φ) from the energy equation ½(J_I + J_II)·ω² = T0 + A with (ω_max + ω_min)/2 = ω_m
    (:func:`true_motion`'s motion), δ = (ω_max − ω_min)/ω_m. Raises InputError if there is no
    inertia at all."""
    J_I = float(sum(machine.first_group.values())) + J_given * speed_ratio ** 2
    if not J_I + float(red.J_II.min()) > 0:
        raise InputError(Notice.of(
            "run_given_no_inertia", "the machine has no inertia (allowed: a flywheel.J > 0, masses "
            "in [links] or machine.first_group)"))
    T0 = motion.T0_for_mean_speed(en.A, J_I, red.J_II, machine.omega_mean)
    _, _, wm, delta = motion.speed_fluctuation(motion.omega_from_energy(T0, en.A, J_I, red.J_II))
    if not abs(wm - machine.omega_mean) <= 1e-6 * machine.omega_mean:
        # ω_min → 0 and still (ω_max + ω_min)/2 > ω_m: no steady motion at this mean speed
        swing, need = float(np.ptp(en.A)), float(np.ptp(en.A)) / (2 * machine.omega_mean ** 2)
        raise InputError(Notice.of(
            "given_flywheel_small", "the given flywheel (J = {J:.6g} kg·m²) is too small for these "
            "loads: the energy change over the cycle, {swing:.4g} J, stops the machine before it "
            "can average ω_m = {omega:.6g} rad/s — no steady motion exists (allowed: a J_I + J_II "
            "of at least about {need:.4g} kg·m² on the crank shaft: a larger flywheel.J, or "
            "smaller loads)", J=J_given, swing=swing, omega=machine.omega_mean, need=need))
    return float(delta)


def dynamics(phi: np.ndarray, loads: LoadsResult, red: ReductionResult, machine,
             fw) -> tuple[EnergyResult, SizingResult, MotionResult]:
    """Energy → sizing → motion → rim speeds: everything that follows from the loads and J_II.
    A given flywheel (``fw.given_J``) is not sized: its δ comes from the motion
    (:func:`given_flywheel_delta`)."""
    with np.errstate(over="ignore", invalid="ignore"):  # an overflow: true_motion's one line
        en = work_and_energy(phi, loads, red, machine)
        J_given = getattr(fw, "given_J", None)
        if J_given is None:
            sz = size_flywheel(phi, en, red, machine, fw)
        else:
            delta = given_flywheel_delta(en, red, machine, J_given, fw.speed_ratio)
            if delta == 0:
                raise InputError(Notice.of(
                    "run_given_no_fluctuation", "the given flywheel (J = {J:.6g} kg·m²) is not "
                    "checked: the speed does not fluctuate at all (δ = 0: no load does work and no "
                    "link's mass moves, so the kinetic energy is constant) (allowed: a case with "
                    "loads or masses)", J=J_given))
            if not 0 < delta < 2:
                raise InputError(Notice.of(
                    "run_given_delta", "the given flywheel (J = {J:.6g} kg·m²) is too small: the "
                    "speed fluctuates by δ = {delta:.6g} (allowed: a larger flywheel.J)", J=J_given,
                    delta=delta))
            sz = size_flywheel(phi, en, red, machine, fw, delta=delta, J_given=J_given)
        mo = true_motion(phi, en, red, sz)
    return en, with_rim_speeds(sz, mo, fw), mo


MOTIONS = ("true", "steady")
"""The crank motions of the force analysis: ω(φ), ε(φ) of the dynamics, or ω_m with ε = 0."""


def force_analysis(phi: np.ndarray, red: ReductionResult, en: EnergyResult, mo: MotionResult,
                   omega_mean: float, motion: str = "true", mech=None, kin=None,
                   loads=None) -> ForceResult:
    """The force analysis (кинетостатика) of the run (design.md §9; docs/forces.md).

    motion: "true" — the crank's ω(φ), ε(φ) of the dynamics (``mo``) — or "steady" — ω = ω_m,
    ε = 0, "the crank turns uniformly" of textbook problems. With a linkage (``mech``, ``kin``
    and ``loads``, a :class:`flywheel.dynamics.forces.Loads` whose J_first_group is mo.J_I):
    :func:`~flywheel.dynamics.forces.kinetostatics` (every reaction, M_y), M_y again by
    Zhukovsky's lever and by the power balance, the total load on the crank pin. Without one
    (a tabulated case) only the power balance, from the reduced quantities:
    M_y = (J_I + J_II)·ε + ½·J_II′·ω² − M_known (:func:`reduced_balancing_moment`).

    The closure is always of the true motion: M_y = M_const (the constant moment of the
    dynamics) at every node, the equation of motion read backwards; reported as
    max|M_y − M_const|/|M_const| (relative to max|J_I·ε| if M_const = 0). A group singular at
    some node raises InputError naming the group and the angle (forces.kinetostatics)."""
    from flywheel.dynamics import forces as fo

    if motion not in MOTIONS:
        # library use only: no CLI input reaches this
        raise InputError(f"force analysis: motion {motion!r} (allowed: {', '.join(MOTIONS)})")
    true_w, true_e = mo.omega, mo.epsilon
    if motion == "true":
        w, e = true_w, true_e
    else:
        w, e = np.full_like(phi, omega_mean), np.zeros_like(phi)
    M_const = float(en.balancing_moment)
    J_eps = mo.J_I * np.abs(true_e)     # |J_I·ε|, the first-group couple's size

    def closure(M_true: np.ndarray) -> tuple[float, str]:
        return fo.closure_of(M_true, M_const, J_eps)

    def mean(M: np.ndarray) -> float:
        return float(np.sum(energy.trapezoid_areas(M, phi)) / (phi[-1] - phi[0]))

    if mech is None:
        J, dJ = mo.J_I + red.J_II, red.dJ_II
        M_power = reduced_balancing_moment(J, dJ, en.M_known, w, e)
        M_true = M_power if motion == "true" else reduced_balancing_moment(
            J, dJ, en.M_known, true_w, true_e)
        c, ref = closure(M_true)
        return ForceResult(
            motion=motion, omega=w, epsilon=e, analysis=None, M_y_zhukovsky=None,
            M_y_power=M_power, M_const=M_const, closure=c, closure_reference=ref,
            M_y_cycle_mean=mean(M_power), crank_pin_load=None, crank_pin_tangential=None,
            crank_pin_radial=None,
            note="joint reactions need a linkage: the kinematics are a table, so M_y is given by "
                 "the power balance only, M_y = (J_I + J_II)·ε + ½·dJ_II/dφ·ω² − M_known")
    fa = fo.kinetostatics(mech, kin, w, e, loads)
    fa_true = fa if motion == "true" else fo.kinetostatics(mech, kin, true_w, true_e, loads)
    warnings = []
    if not any(getattr(m, "mass", 0) or getattr(m, "J_S", 0) for m in loads.masses.values()):
        warnings.append(Notice.of(
            "forces_massless", "force analysis: no link has mass or J_S, so the reactions are "
            "those of the given forces alone (no inertia forces)"))
    P, Ft, Fr = crank_pin_load(mech, kin, fa)
    c, ref = closure(fa_true.balancing_moment)
    return ForceResult(
        motion=motion, omega=w, epsilon=e, analysis=fa,
        M_y_zhukovsky=fo.zhukovsky_moment(mech, kin, w, e, loads),
        M_y_power=fo.power_balance_moment(mech, kin, w, e, loads), M_const=M_const, closure=c,
        closure_reference=ref, M_y_cycle_mean=mean(fa.balancing_moment), crank_pin_load=P,
        crank_pin_tangential=Ft, crank_pin_radial=Fr, warnings=tuple(warnings))


def reduced_balancing_moment(J: np.ndarray, dJ: np.ndarray, M_known: np.ndarray, omega,
                             epsilon) -> np.ndarray:
    """M_y [N·m, in the direction of rotation] from the reduced quantities alone: the
    kinetic-energy theorem for the machine reduced to the crank, d(½·J·ω²)/dt = (M_y + M_known)·ω
    with J = J_I + J_II(φ) [kg·m²], J′ = dJ_II/dφ [kg·m²/rad] and dφ/dt = ω, gives
    J·ω·ε + ½·J′·ω³ = (M_y + M_known)·ω, so

        M_y = J·ε + ½·J′·ω² − M_known

    (Артоболевский, «Теория механизмов и машин», уравнение движения машины в
    дифференциальной форме; seed 004, eq. (5): Мдин = ω1²/2·dIпр/dφ + ε1·Iпр, with
    Мст = −M_known: M_y = Мст + Мдин + J_I·ε — in steady motion, ε = 0, M_y = Мст + Мдин).
    With the true motion, ε = (M_known + M_const − ½·J′·ω²)/J (motion.angular_acceleration),
    so M_y = M_const at every node.

    >>> float(reduced_balancing_moment(np.array([2.0]), np.array([0.5]), np.array([-3.0]), 4.0, 1.0)[0])
    9.0
    """
    return J * epsilon + 0.5 * dJ * np.asarray(omega) ** 2 - M_known


def crank_pin_load(mech, kin, fa) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The force [N] of every link on the crank pin, summed — (N, 2) in the case's frame — and
    its parts along the pin's velocity (tangential, positive drives) and along the crank towards
    the shaft axis (radial), as forces.SliderCrank has them for one rod (Khurmi & Gupta ch. 15):
    the reverse of the crank's reactions at its tip."""
    c = mech.crank
    px = np.zeros(kin.phi.size)
    py = np.zeros(kin.phi.size)
    for r in fa.joints.values():
        if r.joint == c.tip and r.by == c.name:
            px, py = px - r.x, py - r.y
        elif r.joint == c.tip and r.on == c.name:
            px, py = px + r.x, py + r.y
    A, O = kin.points[c.tip].r, kin.points[c.pivot].r
    cx, cy = (A[:, 0] - O[:, 0]) / c.length, (A[:, 1] - O[:, 1]) / c.length
    tangential = c.direction * (-px * cy + py * cx)
    radial = -(px * cx + py * cy)
    return np.stack([px, py], axis=1), tangential, radial


def time_domain(case, phi: np.ndarray, red: ReductionResult, en: EnergyResult,
                mo: MotionResult, progress=None) -> TimeDomainResult:
    """--transients: the steady motion checked by time integration, start-up with the case's
    [motor] (if any), run-down (:mod:`flywheel.dynamics.timedomain`; imports scipy).

    The start-up and the run-down are estimated first (timedomain.startup_cycles,
    rundown_cycles); one longer than MAX_STARTUP_CYCLES or MAX_RUNDOWN_CYCLES cycles is refused
    (InputError) before any integration. ``progress(stage, fraction)``: a plain callable, stage
    "steady check", "start-up" or "run-down", fractions 0 … 1 non-decreasing per stage."""
    from flywheel.dynamics import timedomain

    machine = case.machine
    J, dJ = mo.J_I + red.J_II, red.dJ_II
    warnings: list[str] = []

    def stage(name: str):
        return None if progress is None else (lambda f: progress(name, f))

    motor = None
    delta = machine.delta if machine.delta is not None else mo.delta_achieved
    if case.motor is not None:
        w_x = case.motor.no_load_speed_rpm * TWO_PI / SECONDS_PER_MINUTE
        M_p = case.motor.starting_torque or en.driving_moment / (1 - machine.omega_mean / w_x)
        motor = timedomain.linear_motor(M_p, w_x)
        n_up = timedomain.startup_cycles(phi, J, en.M_known, motor, machine.omega_mean,
                                         delta)
        if n_up is not None and n_up > timedomain.MAX_STARTUP_CYCLES:
            raise InputError(Notice.of(
                "startup_too_long", "motor: the start-up of --transients would take about {n:.3g} "
                "cycles (ω̄·τ·(ln(50/δ) − 1)/Φ with the time constant τ = J̄·ω_x/M_п), more than "
                "the limit of {top} cycles: the motor (motor.starting_torque, "
                "motor.no_load_speed_rpm) is too weak for these masses; run without --transients",
                n=n_up, top=timedomain.MAX_STARTUP_CYCLES))
    n_down = timedomain.rundown_cycles(phi, J, en.M_known, float(mo.omega[0]))
    if n_down is not None and n_down > timedomain.MAX_RUNDOWN_CYCLES:
        work = 0.5 * float(J[0]) * float(mo.omega[0]) ** 2 / n_down
        raise InputError(Notice.of(
            "rundown_too_long", "the run-down of --transients would take about {n:.3g} cycles (the "
            "kinetic energy ½·J·ω² over the work the loads take per cycle, {work:.3g} J), more "
            "than the limit of {top} cycles: the loads are very small for the masses; run without "
            "--transients", n=n_down, work=work, top=timedomain.MAX_RUNDOWN_CYCLES))
    verification = timedomain.verify_steady(phi, J, dJ, en.M_sum, mo.omega,
                                            progress=stage("steady check"))
    histories, means = {}, None
    if motor is not None:
        st = timedomain.startup(phi, J, dJ, en.M_known, motor,
                                machine.omega_mean, delta, progress=stage("start-up"))
        scalars = {k: v for k, v in st.items() if not isinstance(v, np.ndarray)}
        startup = (StartupStalled if st["stalled"] else StartupRun)(
            **scalars, starting_torque=float(M_p), no_load_speed=float(w_x))
        if st.get("warning"):
            warnings.append(st["warning"])
        if "t" in st:
            histories["startup"] = (st["t"], st["omega"])
            means = timedomain.history_cycle_means(st["t"], st["omega"], float(phi[-1] - phi[0]))
    else:
        startup = StartupNotComputed(
            reason=Notice.of(
                "startup_no_motor", "no [motor] in the case: under a constant driving moment the "
                "work over a cycle is zero at any speed, so there is no start-up to a steady state"))
    rd = timedomain.rundown(phi, J, dJ, en.M_known, float(mo.omega[0]),
                            progress=stage("run-down"))
    histories["rundown"] = (rd["t"], rd["omega"])
    return TimeDomainResult(
        verification=Verification(**verification), startup=startup,
        rundown=Rundown(**{k: v for k, v in rd.items() if not isinstance(v, np.ndarray)}),
        histories=histories, startup_cycle_means=means, warnings=tuple(warnings))
