"""The path of contact of a mesh: points A … E, radii of curvature, velocities, load sharing, pressure.

Everything the local ratings (micropitting, ISO/TS 6336-22; scuffing, ISO/TS 6336-20/21;
flank fracture, ISO/TS 6336-4) need along the line of action, from the mesh geometry
(:class:`~epicyclic.geometry.MeshGeometry`) and vectorised with numpy.

A point Y of the path is given by its parameter (ISO/TS 6336-20:2017, 5.x; ISO/TR 13989-1:2000)::

    Γ_Y = tan α_Y1 / tan α_wt − 1 = ρ_t1,Y / ρ_t1,C − 1,       ρ_t1,C = r_b1 tan α_wt

(Γ = 0 at the pitch point C, negative towards the pinion's root).  Its distance from A along
the line of action is g_Y (ISO/TS 6336-22:2018, 6.2, eqs. for g_A … g_E).  Then, in the
transverse plane::

    ρ_t1 = ρ_t1,C (1 + Γ)
    ρ_t2 = ρ_t1,C (u − Γ)                  external (u = z2/z1)
    ρ_t2 = ρ_t1,C (u + Γ)                  internal: the ring's concave flank, ρ_t2 = ρ_t1 + a_w sin α_wt
    ρ_n,i = ρ_t,i / cos β_b                normal section
    ρ_rel = ρ_n1 ρ_n2 / (ρ_n2 ± ρ_n1)       (+ external, − internal)
    v_r1 = ω1 ρ_t1,  v_r2 = ω2 ρ_t2        tangential velocities of the flanks (ISO/TS 6336-22, eqs. (14), (15))
    v_Σ = v_r1 + v_r2,  v_g = |v_r1 − v_r2|,  ζ1 = (v_r1 − v_r2)/v_r1,  ζ2 = (v_r2 − v_r1)/v_r2
    p_H,Y = Z_E √(F_t X_Y / (b ρ_n,rel cos α_t cos β_b)),  p_dyn,Y = p_H,Y √(K_A K_γ K_v K_Hα K_Hβ)

Points: A (tip of gear 2), B = E − p_bt and D = A + p_bt (single pair contact), C (pitch
point), E (tip of gear 1), AB and DE halfway in the double contact zones.

The load sharing factor X_Y (X_Γ) along the path:

* spur, unmodified profiles (ISO/TS 6336-22:2018, 6.3; ISO/TS 6336-20:2017): linear in the
  double contact zones from X_A = (Q − 2)/15 (Q the accuracy grade, not below 7: 1/3) to
  X_A + 1/3 at B, 1 in single contact B … D, falling from X_E + 1/3 at D to X_E at E;
* spur with tip relief designed for the load (``tip_relief`` ``"pinion"``, ``"wheel"``,
  ``"both"``): the relieved tip is unloaded (X = 0 at A for the wheel's tip, at E for the
  pinion's) and the pair opposite carries the rest (X(Γ) + X(Γ + p_bt) = 1), linear between —
  the idealised form of the standards' profile-modified cases;
* helical, ε_β ≥ 1: X = 1/ε_α along the path; 0 < ε_β < 1: (1 − ε_β) X_spur + ε_β/ε_α; both
  with the buttressing factor X_but near A and E (ΔΓ = 0.2 sin β_b, X_but = 1.3 for ε_β ≥ 1,
  1 + 0.3 ε_β below; ISO/TR 13989-1:2000, 9.5; ISO/TS 6336-20:2017, 5.4).

References
----------
ISO/TS 6336-22:2018, clause 6 (points and path of contact, load sharing factor X_Y, local
radii, velocities and contact stress; Method B); ISO/TR 15144-1:2014, eqs. (14), (15),
(24)–(25), (34)–(48); ISO/TS 6336-20:2017, clause 5 (parameter Γ, X_Γ, X_but); ISO/TR
13989-1:2000, 9 (X_Γ); ISO 21771:2007 (involute geometry).  The texts of the standards were
not reachable to this package; the formulas follow their published structure, and the
tests check them against independent closed forms (ISO 6336-2's σ_H0 at the pitch point,
the kinematics of rolling involutes).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType

import numpy as np

from ..geometry.gear import MeshGeometry
from .errors import RatingError, warn_validity

__all__ = ["POINTS", "TIP_RELIEF", "ContactPath", "PathState", "contact_path"]

#: The named points of the path, in order from A to E.
POINTS = ("A", "AB", "B", "C", "D", "DE", "E")
#: Tip relief cases of the load sharing factor.
TIP_RELIEF = ("none", "pinion", "wheel", "both")


def _positive(value, what: str) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) or value <= 0:
        raise RatingError(f"contact path: {what} must be a positive number, got {value!r}.")
    return float(value)


@dataclass(frozen=True)
class PathState:
    """Local quantities at points of the path for one or more load cases (arrays ``cases + (points,)``).

    Parameters
    ----------
    gamma : ndarray
        Γ_Y of the points (1-d).
    g : ndarray
        g_Y, distance from A along the line of action, mm.
    d_y1, d_y2 : ndarray
        Diameters of the contact point on gear 1 and gear 2, mm.
    rho_t1, rho_t2 : ndarray
        Transverse radii of curvature of the flanks, mm (ρ_t2 of a ring: its concave flank, > 0).
    rho_rel : ndarray
        Normal relative radius of curvature ρ_n,rel, mm.
    X : ndarray
        Load sharing factor X_Y.
    v_r1, v_r2, v_sum, v_slide : ndarray
        Tangential velocities of the flanks, their sum v_Σ and the sliding velocity v_g, m/s.
    zeta1, zeta2 : ndarray
        Specific sliding of gear 1 and gear 2.
    p_H : ndarray
        Local Hertzian pressure p_dyn,Y (with the load factors given), N/mm².
    """

    gamma: np.ndarray
    g: np.ndarray
    d_y1: np.ndarray
    d_y2: np.ndarray
    rho_t1: np.ndarray
    rho_t2: np.ndarray
    rho_rel: np.ndarray
    X: np.ndarray
    v_r1: np.ndarray
    v_r2: np.ndarray
    v_sum: np.ndarray
    v_slide: np.ndarray
    zeta1: np.ndarray
    zeta2: np.ndarray
    p_H: np.ndarray

    def __repr__(self) -> str:
        return (f"PathState({self.gamma.size} points, Γ {self.gamma[0]:.4f} … {self.gamma[-1]:.4f}, "
                f"max p_H {float(np.max(self.p_H)):.1f} N/mm^2)")


@dataclass(frozen=True)
class ContactPath:
    """The path of contact of one mesh (gear 1 external, gear 2 external or internal).

    Build it with :func:`contact_path`.

    Parameters
    ----------
    mesh : MeshGeometry
    face_width : float
        b, mm.
    accuracy_grade : int
        Q (ISO 1328-1) of X_A = X_E for unmodified profiles.
    tip_relief : str
        ``"none"``, ``"pinion"``, ``"wheel"`` or ``"both"``.
    buttressing : bool
        Apply X_but of helical gears near A and E.

    Attributes
    ----------
    rho_c1 : float
        ρ_t1,C = r_b1 tan α_wt, mm.
    u : float
        z2/z1.
    base_pitch : float
        p_bt = π d_b1 / z1, mm.
    eps_alpha, eps_beta : float
        ε_α, ε_β.
    beta_b, alpha_t, alpha_wt : float
        rad.
    points : mapping
        Γ of A, AB, B, C, D, DE, E.

    References
    ----------
    ISO/TS 6336-22:2018, clause 6; ISO/TS 6336-20:2017, clause 5.
    """

    mesh: MeshGeometry
    face_width: float
    accuracy_grade: int = 6
    tip_relief: str = "none"
    buttressing: bool = True
    rho_c1: float = field(init=False, repr=False, compare=False)
    u: float = field(init=False, repr=False, compare=False)
    base_pitch: float = field(init=False, repr=False, compare=False)
    eps_alpha: float = field(init=False, repr=False, compare=False)
    eps_beta: float = field(init=False, repr=False, compare=False)
    beta_b: float = field(init=False, repr=False, compare=False)
    alpha_t: float = field(init=False, repr=False, compare=False)
    alpha_wt: float = field(init=False, repr=False, compare=False)
    rb1: float = field(init=False, repr=False, compare=False)
    rb2: float = field(init=False, repr=False, compare=False)
    rho_a: float = field(init=False, repr=False, compare=False)
    points: Mapping[str, float] = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        if not isinstance(self.mesh, MeshGeometry):
            raise RatingError("contact path: mesh must be a MeshGeometry.")
        object.__setattr__(self, "face_width", _positive(self.face_width, "face width b (mm)"))
        if self.tip_relief not in TIP_RELIEF:
            raise RatingError(f"contact path: tip_relief must be one of {', '.join(TIP_RELIEF)}, "
                              f"got {self.tip_relief!r}; the default is 'none' (unmodified profiles).")
        q = self.accuracy_grade
        if isinstance(q, bool) or not isinstance(q, int) or not 1 <= q <= 12:
            raise RatingError(f"contact path: accuracy_grade must be a whole number 1 ... 12, got {q!r}.")
        mesh, rack = self.mesh, self.mesh.rack
        g1, g2 = mesh.gear1, mesh.gear2
        rb1, rb2 = g1.base_diameter / 2, g2.base_diameter / 2
        awt = mesh.alpha_wt
        rho_c1 = rb1 * math.tan(awt)
        common = mesh.center_distance * math.sin(awt)
        ra1, ra2 = g1.tip_diameter / 2, g2.tip_diameter / 2
        rho_e = math.sqrt(max(0.0, ra1 ** 2 - rb1 ** 2))
        path2 = math.sqrt(max(0.0, ra2 ** 2 - rb2 ** 2))
        rho_a = path2 - common if mesh.internal else common - path2
        name = mesh.name or ("internal mesh" if mesh.internal else "mesh")
        if rho_a <= 0.0:
            raise RatingError(f"contact path of {name}: the tip of gear 2 reaches below the base circle of gear 1 "
                              f"(ρ_A = {rho_a:.4f} mm): the teeth interfere; raise x1 or shorten gear 2's tips.")
        if not mesh.internal and rho_e >= common:
            raise RatingError(f"contact path of {name}: the tip of gear 1 reaches below the base circle of gear 2 "
                              f"(ρ_E = {rho_e:.4f} mm ≥ a_w sin α_wt = {common:.4f} mm): the teeth interfere; raise "
                              "x2 or shorten gear 1's tips.")
        p_bt = math.pi * g1.base_diameter / g1.teeth
        eps_a = mesh.contact_ratio  # = (ρ_E − ρ_A)/p_bt, ISO 21771
        if eps_a < 1.0:
            raise RatingError(f"contact path of {name}: transverse contact ratio ε_α = {eps_a:.4f} < 1, the mesh "
                              "cannot run; lengthen the tips or change the profile shifts.")
        beta = rack.beta
        beta_b = math.asin(math.sin(beta) * math.cos(rack.alpha_n))
        eps_b = self.face_width * math.sin(beta) / (math.pi * rack.module)
        u = g2.teeth / g1.teeth
        gam = lambda rho: rho / rho_c1 - 1.0
        rho_b, rho_d = rho_e - p_bt, rho_a + p_bt
        if eps_a >= 2.0:
            rho_b, rho_d = rho_d, rho_b  # no single contact: B, D swap; keep A ≤ B ≤ D ≤ E
        pts = {"A": gam(rho_a), "AB": gam((rho_a + rho_b) / 2), "B": gam(rho_b), "C": 0.0, "D": gam(rho_d),
               "DE": gam((rho_d + rho_e) / 2), "E": gam(rho_e)}
        derived = {"rho_c1": rho_c1, "u": u, "base_pitch": p_bt, "eps_alpha": eps_a, "eps_beta": eps_b,
                   "beta_b": beta_b, "alpha_t": rack.alpha_t, "alpha_wt": awt, "rb1": rb1, "rb2": rb2, "rho_a": rho_a}
        for key, value in derived.items():
            object.__setattr__(self, key, value)
        object.__setattr__(self, "points", MappingProxyType(pts))
        if eps_a >= 2.0 and eps_b == 0.0:
            warn_validity(f"ε_α = {eps_a:.3f} ≥ 2 for the spur mesh {name}: Method B is made for ε_α < 2; the load "
                          "sharing is taken as 1/⌊ε_α⌋ in the whole path (on the safe side)", "ISO/TS 6336-22:2018, 6.3")

    # ------------------------------------------------------------------ scalars
    @property
    def internal(self) -> bool:
        """Gear 2 internal."""
        return self.mesh.internal

    @property
    def length(self) -> float:
        """g_α = ε_α p_bt, the length of the path of contact, mm."""
        return self.eps_alpha * self.base_pitch

    # ------------------------------------------------------------------ geometry along Γ
    def gamma_of(self, g) -> np.ndarray:
        """Γ of the point at distance ``g`` (mm) from A along the line of action."""
        return (self.rho_a + np.asarray(g, dtype=float)) / self.rho_c1 - 1.0

    def g_of(self, gamma) -> np.ndarray:
        """g_Y, the distance from A of the point Γ, mm."""
        return self.rho_c1 * (1.0 + np.asarray(gamma, dtype=float)) - self.rho_a

    def radii(self, gamma) -> tuple[np.ndarray, np.ndarray]:
        """(ρ_t1, ρ_t2), the transverse radii of curvature of both flanks at Γ, mm.

        References
        ----------
        ISO/TS 6336-20:2017, eqs. for ρ_1,Γ and ρ_2,Γ; ISO/TS 6336-22:2018, 6.4.
        """
        gamma = np.asarray(gamma, dtype=float)
        rho1 = self.rho_c1 * (1.0 + gamma)
        rho2 = self.rho_c1 * (self.u + gamma if self.internal else self.u - gamma)
        return rho1, rho2

    def diameters(self, gamma) -> tuple[np.ndarray, np.ndarray]:
        """(d_Y1, d_Y2), the diameters of the contact point on both gears, mm (ISO/TS 6336-22, eqs. (41), (42))."""
        rho1, rho2 = self.radii(gamma)
        return 2.0 * np.hypot(self.rb1, rho1), 2.0 * np.hypot(self.rb2, rho2)

    def relative_radius(self, gamma) -> np.ndarray:
        """ρ_n,rel at Γ in the normal section, mm: ρ_n1 ρ_n2 / (ρ_n2 ± ρ_n1).

        References
        ----------
        ISO/TS 6336-22:2018, eqs. (43)–(45) (ρ_t,Y, ρ_n,Y = ρ_t,Y / cos β_b); ISO/TS 6336-20:2017, ρ_rel,Γ.
        """
        rho1, rho2 = self.radii(gamma)
        den = rho2 - rho1 if self.internal else rho2 + rho1
        return rho1 * rho2 / den / math.cos(self.beta_b)

    def velocities(self, gamma, speed1) -> tuple[np.ndarray, np.ndarray]:
        """(v_r1, v_r2): tangential velocities of the flanks at Γ for gear 1 at ``speed1`` (1/min), m/s.

        ``speed1`` may be an array of load cases: the result has shape ``speed1.shape + gamma.shape``.

        References
        ----------
        ISO/TS 6336-22:2018, eqs. (14), (15) (v_r,Y = ω r_Y sin α_Y = ω ρ_t,Y).
        """
        rho1, rho2 = self.radii(gamma)
        n1 = np.abs(np.asarray(speed1, dtype=float))[..., None] if np.ndim(speed1) else abs(float(speed1))
        w1 = 2.0 * math.pi * n1 / 60.0
        return w1 * rho1 / 1000.0, w1 / self.u * rho2 / 1000.0

    # ------------------------------------------------------------------ load sharing
    def _spur_sharing(self, gamma: np.ndarray) -> np.ndarray:
        p = self.points
        ga, gb, gd, ge = p["A"], p["B"], p["D"], p["E"]
        if self.eps_alpha >= 2.0:
            return np.full(gamma.shape, 1.0 / math.floor(self.eps_alpha))
        base = (max(self.accuracy_grade, 7) - 2.0) / 15.0
        x_a = 0.0 if self.tip_relief in ("wheel", "both") else base
        x_e = 0.0 if self.tip_relief in ("pinion", "both") else base
        if self.tip_relief == "none":
            x_b, x_d = base + 1.0 / 3.0, base + 1.0 / 3.0
        else:  # the pair opposite carries the rest: X(Γ) + X(Γ + p_bt) = 1
            x_b, x_d = 1.0 - x_e, 1.0 - x_a
        with np.errstate(divide="ignore", invalid="ignore"):
            rise = x_a + (x_b - x_a) * (gamma - ga) / (gb - ga) if gb > ga else np.ones(gamma.shape)
            fall = x_e + (x_d - x_e) * (ge - gamma) / (ge - gd) if ge > gd else np.ones(gamma.shape)
        x = np.where(gamma < gb, rise, np.where(gamma <= gd, 1.0, fall))
        return np.clip(x, 0.0, 1.0)

    def _buttressing(self, gamma: np.ndarray) -> np.ndarray:
        width = 0.2 * math.sin(self.beta_b)
        peak = 1.3 if self.eps_beta >= 1.0 else 1.0 + 0.3 * self.eps_beta
        if not self.buttressing or self.eps_beta == 0.0 or peak <= 1.0:  # (a β so small that X_but = 1)
            return np.ones(gamma.shape)
        ga, ge = self.points["A"], self.points["E"]
        near_a = peak - (gamma - ga) / width * (peak - 1.0)
        near_e = peak - (ge - gamma) / width * (peak - 1.0)
        return np.maximum.reduce([np.ones(gamma.shape), near_a, near_e])

    def load_sharing(self, gamma) -> np.ndarray:
        """X_Y (X_Γ), the share of the mesh load the tooth pair at Γ carries.

        References
        ----------
        ISO/TS 6336-22:2018, 6.3 (X_Y, spur and helical, with and without tip relief); ISO/TS
        6336-20:2017, 5.3–5.4 and ISO/TR 13989-1:2000, 9 (X_Γ, buttressing factor X_but).
        """
        gamma = np.asarray(gamma, dtype=float)
        eb = self.eps_beta
        if eb >= 1.0:
            x = np.full(gamma.shape, 1.0 / self.eps_alpha)
        else:
            x = (1.0 - eb) * self._spur_sharing(gamma) + eb / self.eps_alpha
        return x * self._buttressing(gamma)

    # ------------------------------------------------------------------ discretisation
    def gammas(self, n: int = 25) -> np.ndarray:
        """Γ of ``n`` equally spaced points from A to E together with the named points, sorted (1-d).

        Parameters
        ----------
        n : int, default 25
            Points of the even spacing (at least 2).

        Returns
        -------
        ndarray
        """
        if isinstance(n, bool) or not isinstance(n, int) or n < 2:
            raise RatingError(f"contact path: the number of points must be a whole number >= 2, got {n!r}.")
        p = self.points
        grid = np.linspace(p["A"], p["E"], n)
        return np.unique(np.concatenate([grid, np.array([p[k] for k in POINTS])]))

    def state(self, gamma, speed1, tangential_force, elasticity_factor: float, *,
              load_factor=1.0) -> PathState:
        """All local quantities at ``gamma`` for gear 1 at ``speed1`` (1/min) under F_t (N).

        Parameters
        ----------
        gamma : array_like
            Γ of the points (see :meth:`gammas`).
        speed1 : float or array_like
            Speed of gear 1 relative to the carrier (or housing), 1/min; one per load case.
        tangential_force : float or array_like
            F_t at the reference circle, N; one per load case.
        elasticity_factor : float
            Z_E, √(N/mm²).
        load_factor : float or array_like, default 1
            K_A K_γ K_v K_Hα K_Hβ (p_dyn,Y); one per load case.

        Returns
        -------
        PathState
            Arrays of shape ``cases + gamma.shape``.

        References
        ----------
        ISO/TS 6336-22:2018, eqs. (24), (25) (p_H,Y and p_dyn,Y), (13)–(15), (41)–(45).
        """
        gamma = np.atleast_1d(np.asarray(gamma, dtype=float))
        ft = np.asarray(tangential_force, dtype=float)
        kf = np.asarray(load_factor, dtype=float)
        if not (np.all(np.isfinite(ft)) and np.all(ft >= 0) and np.all(np.isfinite(kf)) and np.all(kf > 0)):
            raise RatingError("contact path: tangential force must be finite and >= 0 N, the load factor > 0.")
        rho1, rho2 = self.radii(gamma)
        d1, d2 = self.diameters(gamma)
        rho_rel = self.relative_radius(gamma)
        x = self.load_sharing(gamma)
        v1, v2 = self.velocities(gamma, speed1)
        v1, v2 = np.broadcast_arrays(v1, v2)
        with np.errstate(divide="ignore", invalid="ignore"):
            z1 = np.where(v1 > 0, (v1 - v2) / np.where(v1 > 0, v1, 1.0), -np.inf)
            z2 = np.where(v2 > 0, (v2 - v1) / np.where(v2 > 0, v2, 1.0), -np.inf)
        load = (ft * kf)[..., None] if (ft * kf).ndim else ft * kf
        cos_term = self.face_width * math.cos(self.alpha_t) * math.cos(self.beta_b)
        p_h = elasticity_factor * np.sqrt(load * x / (cos_term * rho_rel))
        return PathState(gamma, self.g_of(gamma), d1, d2, rho1, rho2, rho_rel, x, v1, v2, v1 + v2,
                         np.abs(v1 - v2), z1, z2, p_h)

    def __repr__(self) -> str:
        return (f"ContactPath({self.mesh.name or 'mesh'}: Γ_A {self.points['A']:.4f}, Γ_E {self.points['E']:.4f}, "
                f"ε_α {self.eps_alpha:.3f}, ε_β {self.eps_beta:.3f}, tip relief {self.tip_relief})")


def contact_path(mesh: MeshGeometry, face_width: float, *, accuracy_grade: int = 6, tip_relief: str = "none",
                 buttressing: bool = True) -> ContactPath:
    """The path of contact of ``mesh`` with face width ``face_width`` (mm).

    Parameters
    ----------
    mesh : MeshGeometry
        Gear 1 external, gear 2 external or internal.
    face_width : float
        b, mm.
    accuracy_grade : int, default 6
        ISO 1328-1 grade Q for X_A = (Q − 2)/15 (grades finer than 7 as 7).
    tip_relief : {"none", "pinion", "wheel", "both"}, default "none"
        Which tips carry a tip relief designed for the load.
    buttressing : bool, default True
        Apply the buttressing factor of helical gears near A and E.

    Returns
    -------
    ContactPath

    Raises
    ------
    RatingError
        ε_α < 1, interference (the tip of gear 2 below the base circle of gear 1), bad values.

    References
    ----------
    ISO/TS 6336-22:2018, clause 6; ISO/TS 6336-20:2017, clause 5.

    Examples
    --------
    A 20/40 spur pair, m = 4: the pitch point is Γ = 0, the single contact zone lies around it.

    >>> from epicyclic.geometry.gear import BasicRack, GearGeometry
    >>> rack = BasicRack(4.0)
    >>> path = contact_path(MeshGeometry(GearGeometry(20, rack), GearGeometry(40, rack)), 20.0)
    >>> path.points["B"] < path.points["C"] == 0.0 < path.points["D"]
    True
    >>> [round(float(x), 4) for x in path.load_sharing([path.points["A"], 0.0])]
    [0.3333, 1.0]
    """
    return ContactPath(mesh, face_width, accuracy_grade, tip_relief, buttressing)
