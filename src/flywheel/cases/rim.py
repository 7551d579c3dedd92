"""The flywheel's material and the designed rim, shared by the `run` and the `task2` case formats
(docs/case-format.md, docs/task2.md): ``[flywheel] material, density, allowable_stress`` and
``[flywheel.rim]`` (:func:`flywheel.dynamics.sizing.design_rim`)."""
from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field, model_validator

from flywheel.errors import Notice
from flywheel.io.schema import FieldError, StrictModel, within
from flywheel.units import PA_PER_MPA

MATERIALS = {  # density [kg/m³], allowable hoop stress of a rotating rim [Pa]
    "steel": (7800.0, 20e6),
    "cast-iron": (7200.0, 7e6),
}

Material = Literal["steel", "cast-iron"]
Density = Annotated[float, Field(gt=0), within(1.0, 1e5, "kg/m³")]
Stress = Annotated[float, Field(gt=0), within(1e3, 1e11, "Pa")]


class RimSpec(StrictModel):
    """``[flywheel.rim]``: design the flywheel's rim (Khurmi & Gupta, «Theory of Machines», ch. 16):
    its mean diameter from the rim speed (given, or the largest the allowable stress allows),
    the share of J it carries, its rectangular section."""

    speed: Annotated[float, Field(gt=0), within(1e-3, 1e4, "m/s")] | None = Field(
        None, description="rim speed at the mean diameter at the mean speed [m/s]; default: "
                          "the largest allowed, √(σ_allow/ρ)")
    share: float = Field(0.9, description="share of the flywheel's J (and of its energy) "
                                          "carried by the rim, 0 < share ≤ 1; hub and arms the "
                                          "rest")
    width_to_thickness: Annotated[float, Field(gt=0), within(1e-2, 100.0, "")] | None = Field(
        None, description="b/t of the rectangular section (default 2)")
    width: Annotated[float, Field(gt=0), within(1e-4, 100.0, "m")] | None = Field(
        None, description="the rim's axial width b [m] (instead of width_to_thickness)")
    diameter: Annotated[float, Field(gt=0), within(1e-3, 100.0, "m")] | None = Field(
        None, description="the rim's mean diameter D_mean [m] (instead of speed): its speed is "
                          "ω·D_mean/2")
    thickness_to_radius: Annotated[float, Field(gt=0), within(1e-3, 1.0, "")] | None = Field(
        None, description="t/R: the radial thickness as a share of the mean radius (instead of "
                          "width_to_thickness or width; the width follows from the mass)")

    @model_validator(mode="after")
    def _check(self):
        if not 0.0 < self.share <= 1.0:
            raise FieldError(("share",), Notice.of(
                "rim_share", "{share:g} is not a share of the flywheel's J (allowed: 0 < share ≤ 1)",
                share=self.share))
        if self.width is not None and self.width_to_thickness is not None:
            raise FieldError((), Notice.of(
                "rim_width_or_ratio", "give width or width_to_thickness, not both"))
        if self.thickness_to_radius is not None and (self.width is not None
                                                     or self.width_to_thickness is not None):
            raise FieldError(("thickness_to_radius",), Notice.of(
                "rim_thickness_or_width", "give thickness_to_radius, or width or "
                "width_to_thickness, not both (the section has one free dimension)"))
        if self.diameter is not None and self.speed is not None:
            raise FieldError(("diameter",), Notice.of(
                "rim_diameter_or_speed", "give diameter or speed, not both (the rim speed is "
                "ω·D_mean/2)"))
        return self

    def check_speed(self, density: float, allowable_stress: float, material: str) -> None:
        """The given rim speed's hoop stress ρ·v² within σ_allow, else a FieldError at
        rim.speed saying the largest speed allowed (no diameter helps: σ depends on v alone)."""
        if self.speed is None:
            return
        if density * self.speed ** 2 > allowable_stress * (1 + 1e-12):
            raise FieldError(("rim", "speed"),
                             Notice.of(
                                 "rim_speed_stress", "{speed:g} m/s gives the hoop stress ρ·v² = "
                                 "{stress:.6g} MPa above the allowable {allowable:.6g} MPa "
                                 "({material}, ρ = {density:g} kg/m³), whatever the diameter "
                                 "(allowed: at most √(σ/ρ) = {top:.6g} m/s)", speed=self.speed,
                                 stress=density * self.speed ** 2 / PA_PER_MPA,
                                 allowable=allowable_stress / PA_PER_MPA, material=material,
                                 density=density, top=(allowable_stress / density) ** 0.5))

    def design(self, J: float, omega: float, density: float, allowable_stress: float):
        """The rim (:class:`flywheel.dynamics.sizing.RimDesign`) for J [kg·m²] at ω [rad/s]."""
        from flywheel.dynamics.sizing import design_rim

        return design_rim(J, omega, density, allowable_stress, share=self.share,
                          speed=self.speed, width_to_thickness=self.width_to_thickness,
                          width=self.width, diameter=self.diameter,
                          thickness_to_radius=self.thickness_to_radius)
