"""Duty-cycle machines in time (punching, riveting, shearing presses, stamping): the work of an
operation (:mod:`.work`) and the flywheel, motor and timing of the cycle (:mod:`.solve`).
Pure functions on plain floats; the case format is :mod:`flywheel.cases.duty_cycle`, the
command ``flywheel duty-cycle`` (docs/duty-cycle.md)."""
