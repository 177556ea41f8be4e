"""Face load distribution of a mesh: a slice model along the face width → w(y), K_Hβ, K_Fβ.

The face width b is cut into S slices, each a tooth-contact spring c_γβ b/S (N/µm) that pushes
and never pulls.  Slice i at y_i (0 at the end where the torque enters) starts with the gap

    g_i = F_βx (y_i/b − ½) − f_c (y_i/b − ½) + 4 C_β (y_i/b − ½)² + C_I max(0, 1 − y_i/L_I, 1 − (b − y_i)/L_I)

(misalignment F_βx, a helix slope correction f_c against it, crowning C_β at both ends, end relief
C_I over L_I at both ends; µm).  Optionally the pinion body twists under the torque it carries
(a solid shaft of diameter d, shear modulus G): the twist between the input end and slice i adds
r_b² /(G J) Σ_j F_j min(y_i, y_j) to its gap (the torque at y is what the slices beyond y carry).
The mesh approach δ and the slice forces F_i ≥ 0 satisfy F_i/k_i + Σ_j A_ij F_j = δ − g_i on the
contacting slices, Σ F_i = F_total: a linear complementarity problem, solved exactly by an active-set
method (at most 4 S steps, else an error).  K_Hβ = max w/mean w, K_Fβ = K_Hβ^N_F with
N_F = (b/h)²/(1 + b/h + (b/h)²).

For a rigid body and a linear gap this reproduces ISO 6336-1 method C: K_Hβ = 1 + F_βy c_γβ/(2 F_m/b)
while the whole face carries, √(2 F_βy c_γβ/(F_m/b)) otherwise.

References
----------
ISO 6336-1:2006, 7.6 (eqs. (41)–(42): the linear spring-bed model of method C), 7.7 (eq. (45), K_Fβ);
ISO 6336-1:2006, annex E (face load distribution, slice models with body deflections);
ISO/TR 22849:2011 (the slice model of planetary meshes with torsion and bending).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from ._render import Tabular, number
from .errors import ElasticError, finite, non_negative, positive

__all__ = ["HelixModification", "FaceLoad", "face_load", "best_crowning"]


@dataclass(frozen=True)
class HelixModification:
    """Flank line modifications, µm (and mm for the relief length).

    Attributes
    ----------
    crowning : float
        C_β: the ends stand back by this from the middle (parabola).
    end_relief : float
        C_I at each end, falling linearly to 0 over ``end_relief_length``.
    end_relief_length : float
        L_I, mm.
    slope_correction : float
        f_c: a helix slope correction that takes back this much of the misalignment.
    """

    crowning: float = 0.0
    end_relief: float = 0.0
    end_relief_length: float = 0.0
    slope_correction: float = 0.0

    def __post_init__(self) -> None:
        for key in ("crowning", "end_relief", "end_relief_length"):
            object.__setattr__(self, key, non_negative(getattr(self, key), key))
        object.__setattr__(self, "slope_correction", finite(self.slope_correction, "slope_correction"))
        if self.end_relief > 0.0 and self.end_relief_length <= 0.0:
            raise ElasticError("end_relief needs end_relief_length > 0 (mm over which it runs out).")


@dataclass(frozen=True)
class FaceLoad(Tabular):
    """Load per unit face width of a mesh.

    Attributes
    ----------
    positions : ndarray
        Slice centres y, mm from the torque input end.
    line_load : ndarray
        w(y), N/mm.
    force : float
        Total tangential force along the line of action, N.
    face_width : float
        mm.
    k_hbeta, k_fbeta : float
        K_Hβ = max w/mean w and K_Fβ = K_Hβ^N_F.
    contact_width : float
        The part of the face that carries, mm.
    """

    positions: np.ndarray
    line_load: np.ndarray
    force: float
    face_width: float
    k_hbeta: float
    k_fbeta: float
    contact_width: float

    def _rows(self) -> tuple[list[str], list[list[str]]]:
        step = max(1, len(self.positions) // 10)
        rows = [[number(float(y), 4), number(float(w), 5)] for y, w in
                zip(self.positions[::step], self.line_load[::step])]
        return ["y mm", "w N/mm"], rows

    def _title(self) -> str:
        return (f"Face load: K_Hbeta {self.k_hbeta:.4f}, K_Fbeta {self.k_fbeta:.4f}, contact "
                f"{self.contact_width:.4g} of {self.face_width:g} mm")

    def __repr__(self) -> str:
        return f"FaceLoad(K_Hbeta {self.k_hbeta:.4f}, {len(self.positions)} slices, F {self.force:g} N)"

    def to_dict(self) -> dict[str, Any]:
        """JSON data: positions (mm), line load (N/mm), K_Hβ, K_Fβ, contact width."""
        return {"positions_mm": self.positions.tolist(), "line_load_N_per_mm": self.line_load.tolist(),
                "force_N": self.force, "face_width_mm": self.face_width, "k_hbeta": self.k_hbeta,
                "k_fbeta": self.k_fbeta, "contact_width_mm": self.contact_width}


def _solve(k: np.ndarray, a: np.ndarray, g: np.ndarray, total: float, limit: int) -> np.ndarray:
    """Slice forces F ≥ 0 with F/k + A F = δ − g where F > 0, ≥ where F = 0, Σ F = total."""
    n = len(k)
    active = np.ones(n, dtype=bool)
    for _ in range(limit):
        idx = np.flatnonzero(active)
        m = np.zeros((len(idx) + 1, len(idx) + 1))
        m[:-1, :-1] = np.diag(1.0 / k[idx]) + a[np.ix_(idx, idx)]
        m[:-1, -1], m[-1, :-1] = -1.0, 1.0
        rhs = np.concatenate([-g[idx], [total]])
        sol = np.linalg.solve(m, rhs)
        force = np.zeros(n)
        force[idx], delta = sol[:-1], sol[-1]
        pulling = idx[force[idx] < 0.0]
        if pulling.size:
            active[pulling] = False                    # slices that would pull open
            continue
        approach = delta - g - a @ force               # what an open slice would be pressed by
        closing = ~active & (approach > 1e-12 * max(abs(delta), 1e-30))
        if not closing.any():
            return force
        active[closing] = True
    raise ElasticError(f"face load: no contact solution within {limit} active-set steps.")


def face_load(force: float, face_width: float, c_gamma_beta: float, *, misalignment: float = 0.0,
              modification: HelixModification | None = None, slices: int = 40, tooth_height: float | None = None,
              torsion: tuple[float, float, float] | None = None) -> FaceLoad:
    """The load distribution w(y) along the face width of one mesh.

    Parameters
    ----------
    force : float
        Tangential force F_m (with K_A K_v as the rating takes it), N (> 0).
    face_width : float
        b, mm.
    c_gamma_beta : float
        Mesh stiffness per unit face width c_γβ, N/(mm µm).
    misalignment : float, default 0
        F_βx (effective, after running-in: F_βy), µm: the gap at the far end relative to the input end.
    modification : HelixModification, optional
    slices : int, default 40
        S (4 … 400).
    tooth_height : float, optional
        h, mm, for K_Fβ (b/h below 3 taken as 3); without it K_Fβ = K_Hβ.
    torsion : (diameter mm, base radius mm, shear modulus N/mm²), optional
        The pinion body twisting under its torque (torque enters at y = 0).

    Returns
    -------
    FaceLoad

    Raises
    ------
    ElasticError
        Non-positive force, width or stiffness, slices out of range.

    References
    ----------
    ISO 6336-1:2006, 7.6 eqs. (41)–(42) (the rigid, linear case), 7.7 eq. (45); annex E.

    Examples
    --------
    An aligned, unmodified, rigid mesh: uniform load.

    >>> face_load(10000.0, 50.0, 15.0).k_hbeta
    1.0
    >>> round(face_load(10000.0, 50.0, 15.0, misalignment=10.0).k_hbeta, 4)  # 1 + 10*15/(2*200) at the centres
    1.3656
    """
    f = positive(force, "force")
    b = positive(face_width, "face_width")
    c = positive(c_gamma_beta, "c_gamma_beta")
    fx = finite(misalignment, "misalignment")
    mod = modification or HelixModification()
    if not isinstance(mod, HelixModification):
        raise ElasticError(f"modification must be a HelixModification, got {type(mod).__name__}.")
    if isinstance(slices, bool) or not isinstance(slices, int) or not 4 <= slices <= 400:
        raise ElasticError(f"slices must be a whole number 4 ... 400, got {slices!r}.")
    width = b / slices
    y = (np.arange(slices) + 0.5) * width
    s = y / b - 0.5
    gap = (fx - mod.slope_correction) * s + 4.0 * mod.crowning * s * s
    if mod.end_relief > 0.0:
        length = mod.end_relief_length
        gap = gap + mod.end_relief * np.maximum.reduce([np.zeros_like(y), 1 - y / length, 1 - (b - y) / length])
    gap = gap - gap.min()
    k = np.full(slices, c * width)                       # N/µm per slice
    a = np.zeros((slices, slices))
    if torsion is not None:
        d, r_b, shear = (positive(v, key) for v, key in zip(torsion, ("torsion diameter", "base radius",
                                                                        "shear modulus")))
        polar = math.pi * d ** 4 / 32                    # mm⁴
        a = r_b ** 2 / (shear * polar) * np.minimum.outer(y, y) * 1e3   # mm per N → µm per N
    if torsion is None and not np.any(gap):
        forces = np.full(slices, f / slices)             # no gap, rigid bodies: the exact solution is uniform
    else:
        forces = _solve(k, a, gap, f, 4 * slices)
    w = forces / width
    top, low = float(w.max()), float(w.min())
    k_h = 1.0 if top == low else max(top / float(w.mean()), 1.0)
    if tooth_height is not None:
        bh = max(b / positive(tooth_height, "tooth_height"), 3.0)
        k_f = k_h ** (bh * bh / (1.0 + bh + bh * bh))
    else:
        k_f = k_h
    return FaceLoad(y, w, f, b, k_h, k_f, float(np.count_nonzero(forces > 0.0) * width))


def best_crowning(force: float, face_width: float, c_gamma_beta: float, misalignment: float, *,
                  target: float | None = None, steps: int = 81, slices: int = 40) -> tuple[float, FaceLoad]:
    """The crowning C_β (µm) that gives the lowest K_Hβ — or the least that reaches ``target`` — of a mesh.

    The search is bounded before it runs: ``steps`` values of C_β evenly from 0 to
    |F_βx| + 20 µm (a crowning beyond the misalignment and 20 µm only narrows the contact).

    Parameters
    ----------
    force, face_width, c_gamma_beta, misalignment : float
        As :func:`face_load`.
    target : float, optional
        A K_Hβ to reach; None: the least K_Hβ.
    steps : int, default 81
        2 … 1000.
    slices : int, default 40

    Returns
    -------
    tuple
        (C_β µm, its FaceLoad); with an unreachable target, the best one found.

    References
    ----------
    ISO 6336-1:2006, annex E (helix modifications).
    """
    if isinstance(steps, bool) or not isinstance(steps, int) or not 2 <= steps <= 1000:
        raise ElasticError(f"steps must be a whole number 2 ... 1000, got {steps!r}.")
    grid = np.linspace(0.0, abs(finite(misalignment, "misalignment")) + 20.0, steps)
    loads = [face_load(force, face_width, c_gamma_beta, misalignment=misalignment,
                       modification=HelixModification(crowning=float(cb)), slices=slices) for cb in grid]
    values = np.array([x.k_hbeta for x in loads])
    if target is not None:
        reached = np.flatnonzero(values <= finite(target, "target"))
        if reached.size:
            return float(grid[reached[0]]), loads[reached[0]]
    best = int(np.argmin(values))
    return float(grid[best]), loads[best]
