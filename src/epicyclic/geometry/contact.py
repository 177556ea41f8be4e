"""Overlap and total contact ratio of a helical mesh: ε_β = b sin β / (π m_n), ε_γ = ε_α + ε_β.

References
----------
ISO 21771:2007 (overlap ratio ε_β, total contact ratio ε_γ).
"""

from __future__ import annotations

import math
from typing import Any

from .gear import MeshGeometry

__all__ = ["overlap_ratio", "mesh_data", "micrometres"]


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


def mesh_data(mesh: MeshGeometry, face_width: float | None) -> dict[str, Any]:
    """:meth:`MeshGeometry.to_dict` with ``overlap_ratio`` ε_β and ``total_contact_ratio`` ε_γ.

    Parameters
    ----------
    mesh : MeshGeometry
        The mesh.
    face_width : float or None
        Its face width b, mm; None leaves ε_β and ε_γ of a helical mesh unknown (None).

    Returns
    -------
    dict

    References
    ----------
    ISO 21771:2007 (ε_β, ε_γ = ε_α + ε_β).
    """
    data = mesh.to_dict()
    eps_b = overlap_ratio(mesh, face_width) if face_width is not None else (
        0.0 if mesh.rack.helix_angle == 0 else None)
    data["overlap_ratio"] = eps_b
    data["total_contact_ratio"] = None if eps_b is None else mesh.contact_ratio + eps_b
    return data


def micrometres(length_mm: float) -> float:
    """A length in µm for a table, round-off below 1 nm shown as 0 (no "-0.0000").

    >>> micrometres(-1e-13), micrometres(0.0301)
    (0.0, 30.1)
    """
    value = 1000.0 * length_mm
    return 0.0 if abs(value) < 1e-3 else round(value, 9)
