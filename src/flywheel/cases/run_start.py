"""The `[start]` table of a run case: a motion from rest (or from a given speed) under a constant
driving moment or the case's [motor], integrated in time (issue 24 item 5; the format:
docs/case-format.md, [start]; the computation: :mod:`flywheel.dynamics.start`)."""
from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field, model_validator

from flywheel.errors import Notice
from flywheel.io.schema import FieldError, StrictModel, at_most, within
from flywheel.cases.run_fields import Angle, Moment

MAX_START_TIMES = 1000       # reported instants
T_END_MAX = 1e4              # [s]


class StartSpec(StrictModel):
    """A motion from (φ0, ω0) to t_end, reported at ``times``."""

    phi0_deg: Angle = Field(0.0, description="initial crank angle φ0 [deg]")
    omega0: Annotated[float, within(-1e4, 1e4, "rad/s")] = Field(
        0.0, description="initial crank speed ω0 [rad/s] (0: from rest)")
    driver: Literal["moment", "motor"] = Field(
        "moment", description="the driving moment: a constant (moment) or the [motor]'s "
                              "characteristic M_Д(ω)")
    moment: Moment | None = Field(None, description="the constant driving moment [N·m], added "
                                                    "to the loads' (driver = \"moment\")")
    t_end: Annotated[float, Field(gt=0), within(0.0, T_END_MAX, "s")] = Field(
        description="the end of the motion [s]")
    times: Annotated[list[float], at_most(MAX_START_TIMES, "times"), within(0.0, T_END_MAX, "s")] = Field(
        description="the instants at which φ, ω, ε are reported [s], increasing, within 0 … t_end")
    rtol: Annotated[float, within(1e-12, 1e-3, "")] = Field(
        1e-9, description="solve_ivp's relative tolerance (1e-12 … 1e-3)")
    atol: Annotated[float, within(1e-14, 1.0, "")] = Field(
        1e-9, description="solve_ivp's absolute tolerance (1e-14 … 1)")

    @model_validator(mode="after")
    def _check(self):
        if self.driver == "moment" and self.moment is None:
            raise FieldError(("moment",), Notice.of(
                "start_moment_missing", "missing: give the constant driving moment [N·m], or "
                "driver = \"motor\""))
        if self.driver == "motor" and self.moment is not None:
            raise FieldError(("moment",), Notice.of(
                "start_moment_with_motor", "goes with driver = \"moment\" (the motor drives)"))
        if not self.times:
            raise FieldError(("times",), Notice.of(
                "start_no_times", "needs at least one instant [s]"))
        for i, (a, b) in enumerate(zip(self.times, self.times[1:]), start=1):
            if not b > a:
                raise FieldError(("times", i), Notice.of(
                    "start_times_increasing", "{b:g} s after {a:g} s (allowed: strictly "
                    "increasing)", a=a, b=b))
        if self.times[-1] > self.t_end:
            raise FieldError(("times", len(self.times) - 1), Notice.of(
                "start_time_after_end", "{t:g} s is after t_end = {t_end:g} s (allowed: 0 … "
                "t_end)", t=self.times[-1], t_end=self.t_end))
        return self
