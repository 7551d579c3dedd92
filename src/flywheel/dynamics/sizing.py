"""Flywheel sizing for a coefficient of speed fluctuation δ, and its dimensions."""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from flywheel.units import PA_PER_MPA


def J_required_merzalov(delta_T_max: float, omega_mean: float, delta: float) -> float:
    """J_I = ΔT_нб/(ω_m²·δ) [kg·m²] (seed 000 §4: J_PRI := ΔT_нб/(ω_1ср²·δ1); Merzalov)."""
    return delta_T_max / (omega_mean**2 * delta)


def J_required_exact(A: np.ndarray, J_II: np.ndarray, omega_mean: float, delta: float) -> tuple[float, float]:
    """Exact J_I [kg·m²] and the initial total kinetic energy T0 [J] (Wittenbauer's energy–mass
    diagram, done numerically; design.md §2).

    With T(φ) = T0 + A(φ) = ½(J_I + J_II(φ))·ω², ω_max = ω_m(1 + δ/2) and ω_min = ω_m(1 − δ/2)
    require T0 + A ≤ k₊(J_I + J_II) and T0 + A ≥ k₋(J_I + J_II), k± = ω_m²(1 ± δ/2)²/2, with
    equality somewhere: J_I = [max(A − k₊J_II) − min(A − k₋J_II)]/(k₊ − k₋),
    T0 = k₊·J_I − max(A − k₊J_II).

    >>> A = np.array([0.0, 10.0, 0.0]); J = np.zeros(3)   # constant inertia: J = ΔT/(δ·ω_m²)
    >>> round(J_required_exact(A, J, 10.0, 0.1)[0], 12)   # ΔT/(δ·ω_m²) = 10/(0.1·100)
    1.0
    """
    k_plus, k_minus = tangent_slopes(omega_mean, delta)
    top = np.max(A - k_plus * J_II)
    bottom = np.min(A - k_minus * J_II)
    J_I = (top - bottom) / (k_plus - k_minus)
    return float(J_I), float(k_plus * J_I - top)


def tangent_slopes(omega_mean: float, delta: float) -> tuple[float, float]:
    """k± = ω_m²(1 ± δ/2)²/2 = ω_max²/2, ω_min²/2 [J/(kg·m²)]: the slopes of the two tangents
    to the energy–mass curve (:func:`J_required_exact`).

    >>> tangent_slopes(10.0, 0.2)
    (60.50000000000001, 40.5)
    """
    return omega_mean**2 * (1 + delta / 2) ** 2 / 2, omega_mean**2 * (1 - delta / 2) ** 2 / 2


def tangency_points(A: np.ndarray, J_II: np.ndarray, omega_mean: float, delta: float) -> tuple[int, int]:
    """Grid indices of the points where the tangents of :func:`J_required_exact` touch the
    energy–mass curve (A against J_II): the maximum of A − k₊·J_II (ψ_max) and the minimum of
    A − k₋·J_II (ψ_min)."""
    k_plus, k_minus = tangent_slopes(omega_mean, delta)
    return int(np.argmax(A - k_plus * J_II)), int(np.argmin(A - k_minus * J_II))


def disk(J: float, density: float = 7800.0, width_ratio: float = 0.2) -> dict:
    """Solid disk of diameter D, width b = w·D: J = π·ρ·b·D⁴/32, so
    D = (32·J/(π·ρ·w))^(1/5), mass = ρ·π·D²·b/4 = 8·J/D².
    Steel ρ = 7800, w = 0.2 gives the seed's D = 0.366·J^(1/5) (seed 000, last block).

    >>> round((32 / (math.pi * 7800 * 0.2)) ** 0.2, 3)
    0.366
    """
    if J <= 0:
        return {"D": 0.0, "b": 0.0, "mass": 0.0}
    D = (32 * J / (math.pi * density * width_ratio)) ** 0.2
    b = width_ratio * D
    return {"D": D, "b": b, "mass": density * math.pi * D**2 * b / 4}


def rim(J: float, density: float = 7800.0, width_ratio: float = 0.2, inner_ratio: float = 0.8) -> dict:
    """Rim (hub and spokes neglected) of outer diameter D, inner D1 = c·D, width b = w·D:
    J = π·ρ·b·(D⁴ − D1⁴)/32, so D = (32·J/(π·ρ·w·(1 − c⁴)))^(1/5), mass = ρ·π·(D² − D1²)·b/4.
    Steel with w = 0.2, c = 0.8 gives the seed's D = 0.406·J^(1/5) and its mass constant
    6123 ≈ ρπ/4 = 6126.1 (seed 000, last block).

    >>> round((32 / (math.pi * 7800 * 0.2 * (1 - 0.8**4))) ** 0.2, 3)
    0.406
    """
    if J <= 0:
        return {"D": 0.0, "D_inner": 0.0, "b": 0.0, "mass": 0.0}
    D = (32 * J / (math.pi * density * width_ratio * (1 - inner_ratio**4))) ** 0.2
    D1 = inner_ratio * D
    b = width_ratio * D
    return {"D": D, "D_inner": D1, "b": b, "mass": density * math.pi * (D**2 - D1**2) * b / 4}


def disk_course(J: float) -> dict:
    """The course's empirical disk rule (seed 000, last block): D = 0.366·J^(1/5),
    m = 8·J/D², b = 0.2·D (steel; the constant is (32/(π·7800·0.2))^(1/5) rounded)."""
    if J <= 0:
        return {"D": 0.0, "b": 0.0, "mass": 0.0}
    D = 0.366 * J**0.2
    return {"D": D, "b": 0.2 * D, "mass": 8 * J / D**2}


def rim_course(J: float) -> dict:
    """The course's empirical rim rule (seed 000, last block): D = 0.406·J^(1/5), b = 0.2·D,
    D1 = 0.8·D, m = 6123·(D² − D1²)·b (6123 ≈ ρπ/4 for steel, rounded)."""
    if J <= 0:
        return {"D": 0.0, "D_inner": 0.0, "b": 0.0, "mass": 0.0}
    D = 0.406 * J**0.2
    D1, b = 0.8 * D, 0.2 * D
    return {"D": D, "D_inner": D1, "b": b, "mass": 6123 * (D**2 - D1**2) * b}


def rim_speed_limit(allowable_stress: float, density: float) -> float:
    """Largest peripheral speed of a rotating rim [m/s]: the hoop stress of a thin ring is
    σ = ρ·v², so v_max = √(σ_allow/ρ) (the thin rotating ring; e.g. Timoshenko, Strength of
    Materials, part II, rotating rings). σ_allow = 7 MPa for cast iron and 20 MPa for steel give
    the customary limits of about 30 and 50 m/s."""
    return math.sqrt(allowable_stress / density)


RIM_SHARE_DEFAULT = 0.9
"""The share of the flywheel's J carried by a designed rim when none is given: the hub and arms
carry the rest (Khurmi & Gupta, «Theory of Machines», ch. 16, "Dimensions of the flywheel rim":
the rim is usually taken to give about 90 % of the flywheel effect; their worked examples use
0.92, 0.95)."""

WIDTH_TO_THICKNESS_DEFAULT = 2.0
"""The rim's width b over its radial thickness t when neither is given (b = 2·t, as in Khurmi &
Gupta's Examples 16.16 and 16.23)."""


@dataclass(frozen=True)
class RimDesign:
    """A flywheel rim of rectangular section designed as engineers finish a flywheel (Khurmi &
    Gupta, «Theory of Machines», ch. 16, "Dimensions of the flywheel rim"; :func:`design_rim`).

    Which formula each quantity uses: ``rim_speed`` v = ω·D_mean/2 at the mean speed ω of the
    flywheel's shaft [m/s]; ``stress`` σ = ρ·v², the hoop stress of a thin rotating ring [Pa]
    (Timoshenko, «Strength of Materials», part II, rotating rings); ``mass`` m = share·J/R²
    with R = D_mean/2 (thin ring: radius of gyration = mean radius) [kg]; the section from
    m = ρ·π·D_mean·b·t (exact for a rectangular annulus) with b = ratio·t or b given [m];
    ``J_rim_exact`` = m·(R² + t²/4), the same rim as a thick annulus, ½·m·(R_o² + R_i²)
    [kg·m²], which exceeds the thin-ring share·J by the factor 1 + (t/D_mean)²."""

    J: float                     # the flywheel's J on its own shaft, to be shared [kg·m²]
    share: float                 # share of J (and of the energy) carried by the rim [-]
    omega: float                 # the flywheel shaft's mean speed ω [rad/s]
    density: float               # ρ [kg/m³]
    allowable_stress: float      # σ_allow [Pa]
    speed_from: str              # "allowable stress" (v = √(σ_allow/ρ)) or "given"
    D_mean: float                # mean diameter 2·v/ω [m]
    rim_speed: float             # v at D_mean at the mean speed [m/s]
    stress: float                # thin-ring hoop stress ρ·v² [Pa]
    mass: float                  # share·J/R² [kg]
    thickness: float             # radial thickness t [m]
    width: float                 # axial width b [m]
    J_rim: float                 # thin ring m·R² = share·J [kg·m²]
    J_rim_exact: float           # thick annulus m·(R² + t²/4) [kg·m²]
    stress_at_omega_max: float | None = None   # ρ·(ω_max·R)² after the motion [Pa]
    width_given: bool = False    # b given (flywheel.rim.width), not b = ratio·t
    diameter_given: bool = False   # D_mean given (flywheel.rim.diameter), not from the speed
    thickness_given: bool = False  # t/R given (flywheel.rim.thickness_to_radius)

    DOCUMENT = ("D_mean", "thickness", "width", "mass", "rim_speed", "stress", "share", "D",
                "D_inner", "b", "allowable_stress", ("rim_speed_from", "speed_from"), "J_rim",
                "J_rim_exact", "stress_at_omega_max", "area")

    @property
    def area(self) -> float:
        """The rim's cross-section b·t [m²] (a rectangle; m = ρ·π·D_mean·b·t)."""
        return self.width * self.thickness

    @property
    def D(self) -> float:
        """Outer diameter D_mean + t [m]."""
        return self.D_mean + self.thickness

    @property
    def D_inner(self) -> float:
        """Inner diameter D_mean − t [m]."""
        return self.D_mean - self.thickness

    @property
    def b(self) -> float:
        """The width under the plain rim's name [m]."""
        return self.width

    def at_top_speed(self, omega_max: float) -> "RimDesign":
        """This rim with its hoop stress at the top speed ``omega_max`` [rad/s] of its shaft,
        ``stress_at_omega_max`` = ρ·(ω_max·D_mean/2)² [Pa] (thin rotating ring, as ``stress``)."""
        from dataclasses import replace

        v_top = omega_max * self.D_mean / 2
        return replace(self, stress_at_omega_max=self.density * v_top ** 2)

    def as_dict(self) -> dict:
        """summary.json's results.flywheel_rim (and ``task2 --json``'s flywheel_rim): the
        contract keys D_mean, thickness, width, mass, rim_speed, stress, share, then the outer
        and inner diameters and the width under the plain rim's names (D, D_inner, b)."""
        from flywheel.io.serialize import to_json

        return to_json(self)


#: t/D_mean below which a designed rim is too thin to make (a plausibility bound of flywheel's:
#: a rolled or cast rim of 1 % of its diameter is a hoop, no flywheel), and the t/D_mean the
#: hint's rim speed gives
THIN_RIM = 0.01
THIN_RIM_AIM = 0.05


def thin_rim_notice(rim: RimDesign):
    """The warning (a Notice) for a designed rim thinner than :data:`THIN_RIM` of its mean
    diameter — a hoop, not a flywheel rim — with the advice that fits the keys the case gave:
    a ``thickness_to_radius`` given fixes t/D_mean = (t/R)/2 whatever the speed, so the advice is
    t/R = 2·:data:`THIN_RIM_AIM`; a ``diameter`` given, the mean diameter that gives t/D_mean =
    :data:`THIN_RIM_AIM` (:func:`rim_speed_for_thickness`, D = 2·v/ω); else the rim speed that
    gives it. None for a rim thick enough."""
    from flywheel.errors import Notice

    ratio = rim.thickness / rim.D_mean
    if not ratio < THIN_RIM:
        return None
    t_mm, D = rim.thickness * 1e3, rim.D_mean
    if rim.thickness_given:
        return Notice.of(
            "rim_thin_ratio", "flywheel.rim: the designed rim is {t_mm:.3g} mm thick on a mean "
            "diameter of {D:.4g} m (t/D = {ratio:.2g}, below {least:g}): a hoop, not a flywheel "
            "rim; its flywheel.rim.thickness_to_radius = {t_to_R:g} sets t/D = {ratio:.2g} "
            "whatever the speed: give flywheel.rim.thickness_to_radius about {aim_ratio:g} "
            "(t/D = {aim:g})",
            t_mm=t_mm, D=D, ratio=ratio, least=THIN_RIM, aim=THIN_RIM_AIM, t_to_R=2 * ratio,
            aim_ratio=2 * THIN_RIM_AIM)
    v_aim = rim_speed_for_thickness(rim)
    if rim.diameter_given:
        return Notice.of(
            "rim_thin_diameter", "flywheel.rim: the designed rim is {t_mm:.3g} mm thick on a "
            "mean diameter of {D:.4g} m (t/D = {ratio:.2g}, below {least:g}): a hoop, not a "
            "flywheel rim; its diameter is too large for its mass: give a smaller "
            "flywheel.rim.diameter (about {D_aim:.3g} m gives t/D = {aim:g})",
            t_mm=t_mm, D=D, ratio=ratio, least=THIN_RIM, aim=THIN_RIM_AIM,
            D_aim=D * v_aim / rim.rim_speed)
    return Notice.of(
        "rim_thin", "flywheel.rim: the designed rim is {t_mm:.3g} mm thick on a mean "
        "diameter of {D:.4g} m (t/D = {ratio:.2g}, below {least:g}): a hoop, not a "
        "flywheel rim; its rim speed {v:.4g} m/s ({speed_source}) is too high for a shaft "
        "this slow: give flywheel.rim.speed (about {v_aim:.3g} m/s gives t/D = {aim:g})",
        t_mm=t_mm, D=D, ratio=ratio, least=THIN_RIM, v=rim.rim_speed,
        given=rim.speed_from == "given", v_aim=v_aim, aim=THIN_RIM_AIM,
        speed_source=("given" if rim.speed_from == "given"
                      else "the largest the allowable stress allows"))


def rim_speed_for_thickness(rim: RimDesign, aim: float = THIN_RIM_AIM) -> float:
    """The rim speed [m/s] at which :func:`design_rim`'s rim (same J, share, ω, ρ and the same
    width rule) comes out with t/D_mean = ``aim``.

    From design_rim's own relations, with D = 2·v/ω and m = share·J/R² ∝ D⁻²: for b = ratio·t,
    t = √(m/(π·D·ratio·ρ)) ∝ D^(−3/2), so t/D ∝ D^(−5/2); for a given width b,
    t = m/(π·D·b·ρ) ∝ D⁻³, so t/D ∝ D⁻⁴. Hence v_aim = v·((t/D)/aim)^(1/k), k = 5/2 or 4.

    >>> r = design_rim(100.0, 5.0, 7200.0, 7e6, share=1.0, width_to_thickness=2.0)
    >>> round(r.thickness / r.D_mean, 5), round(r.D_mean, 3)   # a hoop 12.5 m across
    (0.00017, 12.472)
    >>> v = rim_speed_for_thickness(r, 0.05)
    >>> s = design_rim(100.0, 5.0, 7200.0, 7e6, share=1.0, speed=v, width_to_thickness=2.0)
    >>> round(s.thickness / s.D_mean, 12), round(s.D_mean, 3)
    (0.05, 1.287)
    """
    k = 4.0 if rim.width_given else 2.5
    return rim.rim_speed * (rim.thickness / rim.D_mean / aim) ** (1.0 / k)


def design_rim(J: float, omega: float, density: float, allowable_stress: float, *,
               share: float = RIM_SHARE_DEFAULT, speed: float | None = None,
               width_to_thickness: float | None = None,
               width: float | None = None,
               thickness_to_radius: float | None = None,
               diameter: float | None = None) -> RimDesign:
    """The rim carrying ``share`` of ``J`` [kg·m²] on a shaft turning at the mean speed
    ``omega`` [rad/s] (Khurmi & Gupta, «Theory of Machines», ch. 16, "Dimensions of the flywheel
    rim", Examples 16.14–16.18, 16.23):

    v = √(σ_allow/ρ) (hoop stress of a thin rotating ring σ = ρ·v²), the given ``speed``, or
    ω·D_mean/2 of the given mean ``diameter``;
    D_mean = 2·v/ω; m = share·J/R², R = D_mean/2 (thin ring, k = R); m = ρ·π·D_mean·b·t with
    b = ratio·t, t = √(m/(π·D_mean·ratio·ρ)), or b = ``width`` given, t = m/(π·D_mean·b·ρ), or
    t = ``thickness_to_radius``·R given, b = m/(π·D_mean·t·ρ).

    Raises InputError (naming the field) if the given speed's stress ρ·v² exceeds σ_allow
    (no diameter can help: the stress of a thin ring depends on v alone), if the share is not in
    (0, 1], or if the rim comes out thicker than its mean diameter (no hole left).

    >>> r = design_rim(100.0, 50.0, 7200.0, 7e6, share=1.0, width_to_thickness=2.0)
    >>> round(r.rim_speed ** 2 * 7200.0 / 7e6, 12), round(r.mass * (r.D_mean / 2) ** 2, 9)
    (1.0, 100.0)
    """
    from flywheel.errors import InputError, Notice

    if not 0.0 < share <= 1.0:
        # library use only: no CLI input reaches this
        raise InputError(f"flywheel.rim.share: {share:g} is not a share (allowed: 0 < share ≤ 1)")
    v_max = rim_speed_limit(allowable_stress, density)
    if diameter is not None:        # the mean diameter given: v = ω·D_mean/2
        speed = omega * diameter / 2
        if density * speed ** 2 > allowable_stress * (1 + 1e-12):
            raise InputError(Notice.of(
                "rim_diameter_stress", "flywheel.rim.diameter: {D:g} m turns at {speed:.6g} "
                "m/s, whose hoop stress ρ·v² = {stress:.6g} MPa is above the allowable "
                "{allowable:.6g} MPa (allowed: at most {top:.6g} m, at √(σ/ρ) = {v_top:.6g} "
                "m/s)", D=diameter, speed=speed, stress=density * speed ** 2 / PA_PER_MPA,
                allowable=allowable_stress / PA_PER_MPA, top=2 * v_max / omega, v_top=v_max))
    if speed is None:
        v, speed_from = v_max, "allowable stress"
    else:
        if density * speed ** 2 > allowable_stress * (1 + 1e-12):
            # library use only: no CLI input reaches this
            raise InputError(
                f"flywheel.rim.speed: {speed:g} m/s gives the hoop stress ρ·v² = "
                f"{density * speed ** 2 / PA_PER_MPA:.6g} MPa above the allowable "
                f"{allowable_stress / PA_PER_MPA:.6g} MPa, whatever the diameter (allowed: at most "
                f"√(σ/ρ) = {v_max:.6g} m/s for ρ = {density:g} kg/m³)")
        v, speed_from = speed, "given"
    D = diameter if diameter is not None else 2 * v / omega    # a given diameter kept exact
    R = D / 2
    J_rim = share * max(J, 0.0)
    m = J_rim / R ** 2
    if thickness_to_radius is not None:     # t = (t/R)·R given, b from m = ρ·π·D·b·t
        t = thickness_to_radius * R
        b = m / (math.pi * D * t * density)
    elif width is not None:
        b = width
        t = m / (math.pi * D * b * density)
    else:
        ratio = width_to_thickness if width_to_thickness is not None else WIDTH_TO_THICKNESS_DEFAULT
        t = math.sqrt(m / (math.pi * D * ratio * density))
        b = ratio * t
    if not t < D:
        raise InputError(Notice.of(
            "rim_no_hole", "flywheel.rim: the rim comes out {t:.4g} m thick on a mean diameter of "
            "{D:.4g} m, so it has no hole (allowed: thickness < mean diameter: a higher rim speed, "
            "a wider rim, or a smaller share)", t=t, D=D))
    return RimDesign(J=float(J), share=float(share), omega=float(omega), density=float(density),
                     allowable_stress=float(allowable_stress), speed_from=speed_from,
                     D_mean=D, rim_speed=v, stress=density * v ** 2, mass=m, thickness=t,
                     width=b, J_rim=m * R ** 2, J_rim_exact=m * (R ** 2 + t ** 2 / 4),
                     width_given=width is not None, diameter_given=diameter is not None,
                     thickness_given=thickness_to_radius is not None)
