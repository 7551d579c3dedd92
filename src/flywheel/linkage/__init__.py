"""Planar-linkage kinematics by Assur groups (design.md §3).

A mechanism is a driving crank followed by two-link groups (dyads), each placed by points
already known. Positions are closed-form; velocity and acceleration analogues (d/dφ, d²/dφ²)
come from the differentiated closure equations, exactly, vectorized over the φ grid.
"""
from flywheel.linkage.mechanism import (
    Crank,
    CrankPin,
    Guide,
    LinkPoint,
    Mechanism,
    RPR,
    RRP,
    RRR,
)
from flywheel.linkage.solve import Kinematics, LinkMotion, PointMotion, solve

__all__ = [
    "Crank", "CrankPin", "Guide", "LinkPoint", "Mechanism", "RPR", "RRP", "RRR",
    "Kinematics", "LinkMotion", "PointMotion", "solve",
]
