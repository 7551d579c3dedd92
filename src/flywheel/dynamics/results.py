"""The results of one analysis: arrays on the φ grid, scalars, and the report angles.

One object that renderers read; it computes nothing. Every column carries its unit and
a description, so CSV headers, plot labels and the summary name a quantity the same way.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np


@dataclass(frozen=True)
class Column:
    """An array on the grid with its unit and description (English, Russian)."""

    values: np.ndarray
    unit: str
    label: str
    label_ru: str = ""


@dataclass
class CylinderResult:
    """One cylinder on the grid: relative travel s, whether the piston moves towards the head,
    pressure p [Pa], force F [N], reduced moment M [N·m], and its indicator tables."""

    name: str
    piston: str
    s: np.ndarray
    towards_head: np.ndarray
    p: np.ndarray
    F: np.ndarray
    M: np.ndarray
    table_s: np.ndarray
    table_towards: np.ndarray
    table_away: np.ndarray
    p_max: float
    head_phi: float


@dataclass
class Results:
    """Everything one run computed (SI units, angles in radians)."""

    title: str
    source: str
    phi: np.ndarray
    kinematics: object                      # flywheel.linkage.Kinematics
    columns: dict[str, Column]              # table.csv, in order
    scalars: dict                           # summary.json "results" (JSON-ready)
    at: list[dict]                          # summary.json "results.at"
    position_angles: list[tuple[str, float]]  # (label, φ) of the standard positions
    J_parts: dict[str, np.ndarray]
    dJ_parts: dict[str, np.ndarray]
    M_parts: dict[str, np.ndarray]
    cylinders: list[CylinderResult]
    links_drawn: list[tuple[str, list[str]]]  # (link, its points) for the kinematic scheme
    warnings: list[str] = field(default_factory=list)
    time_domain: dict | None = None           # --transients: checks and histories (t, ω)

    def index_of(self, phi: float) -> int:
        """Grid index of the node at angle ``phi`` [rad] (report angles are grid nodes)."""
        return int(np.argmin(np.abs(self.phi - phi)))

    def summary(self) -> dict:
        """The summary.json document."""
        return {
            "title": self.title,
            "source": self.source,
            "units": "SI (m, kg, s, rad, N, N·m, J, kg·m²); angles *_deg in degrees",
            "results": {**self.scalars, "at": self.at},
            "warnings": list(self.warnings),
        }
