"""Overlap and total contact ratio of a helical mesh: ε_β = b sin β / (π m_n), ε_γ = ε_α + ε_β.

References
----------
ISO 21771:2007 (overlap ratio ε_β, total contact ratio ε_γ).
"""

from __future__ import annotations

import math

from .gear import MeshGeometry

__all__ = ["overlap_ratio"]


def overlap_ratio(mesh: MeshGeometry, face_width: float) -> float:
    """ε_β = b sin β / (π m_n) of a mesh of face width b (mm).

    Parameters
    ----------
    mesh : MeshGeometry
        The mesh.
    face_width : float
        The common face width b, mm.

    Returns
    -------
    float
        ε_β (0 for spur gears).

    Examples
    --------
    m_n = 8 mm, β = 15.8°, b = 100 mm: ε_β = 100 sin 15.8° / (8π) = 1.0834

    >>> from epicyclic.geometry.gear import BasicRack, GearGeometry
    >>> rack = BasicRack(8.0, helix_angle=15.8)
    >>> round(overlap_ratio(MeshGeometry(GearGeometry(17, rack, 0.145), GearGeometry(103, rack)), 100.0), 4)
    1.0834

    References
    ----------
    ISO 21771:2007, ε_β = b sin β / (π m_n).
    """
    return face_width * math.sin(mesh.rack.beta) / (math.pi * mesh.rack.module)
