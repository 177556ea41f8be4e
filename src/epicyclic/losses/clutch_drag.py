"""Drag of an open wet multi-plate clutch or brake: the oil film sheared between its plates.

Each of the ``gaps`` oil films between a friction plate and a steel plate
(clearance h, plates from r_i to r_o) carries the Couette shear of the slip
speed ω; the torque of a full film is (Newton's law integrated over the
annulus)

.. math:: T_{full} = \\frac{\\pi \\eta \\omega}{2 h} (r_o^4 - r_i^4)

At low slip the oil fed at the inner radius fills every gap.  The rotating
plate pumps the oil outward (centrifugal term of the thin-film equations); with
ambient pressure at the inner radius and at the edge r_e of the film, the flow
a gap passes is (Yuan et al. 2007, eq. 9 without the surface tension term)

.. math:: Q(r_e) = \\frac{\\pi \\rho \\omega^2 h^3 (r_e^2 - r_i^2)}{40 \\eta \\ln(r_e / r_i)}

Once that exceeds the oil supplied per gap (Q_s = supply / gaps) the coherent
film cannot reach the outer radius: it ends at the r_e where Q(r_e) = Q_s
(aeration).  Outside r_e the gap holds an oil mist (a suspension of oil in
air, Iqbal et al. 2013), which still shears: the drag is the sum of the film's
and the mist's (Iqbal et al. 2013, the ATF film plus the mist film)

.. math::

    T = N_{gaps}\\, f_g \\left[\\frac{\\pi \\eta \\omega}{2 h} (r_e^4 - r_i^4)
        + \\frac{2 \\pi \\omega}{h} \\int_{r_e}^{r_o} \\eta_m(r)\\, r^3\\, dr\\right]

with the mist's viscosity the volume-weighted mean of oil and air (the
homogeneous two-phase model, Dukler, Wicks & Cleveland 1964),
η_m = α η + (1 − α) η_air, and the oil's volume share α(r) = Q_s / Q(r) ≤ 1 by
continuity: the mist carries the supply Q_s outward where a full film would
carry Q(r) (α = 1 at r_e, so the drag is continuous at the peak).  Once even
Q(r_i) = π ρ ω² h³ r_i² / (20 η) exceeds the supply no coherent film is left
(r_e = r_i) and the whole gap holds mist.  The mist keeps a residual drag that
falls about as 1/ω (α ∝ 1/ω²) towards the air shear (∝ ω); ``mist=False`` gives
the film alone (Yuan et al. 2007), whose drag drops to zero at about 1.1 … 1.3 ×
the peak slip.  The groove factor f_g ∈ (0, 1] is the share of the plate that
shears a film (1 for plain plates; 1 − groove area share for grooved ones,
Kitabayashi et al. 2003).  The drag peaks near the slip where Q(r_o) equals the
supply.

Validity (stated by the sources): a thin laminar film, h ≪ r_o (h/r_o < 0.01)
and the Reynolds number ρ ω r_o h / η below about 2000 (Couette flow stays
laminar); plates parallel and not in contact; surface tension and the second
rise of the drag at very high slip (plate wobble and the gap closing, Pan &
Zhou 2019) are left out.  Without a given supply the film is taken full (no
aeration): an upper bound.  Whatever the slip, the drag lies between the air
shear and the full film's drag (for oil more viscous than air).

References
----------
Yuan, Y., Liu, E. A., Hill, J., Zou, Q.: *An improved hydrodynamic model for open wet transmission
clutches*, ASME J. Fluids Eng. 129 (2007) 333–337, eqs. (5)–(9);
Kitabayashi, H., Li, C. Y., Hiraki, H.: *Analysis of the various factors affecting drag torque in
multiple-plate wet clutches*, SAE 2003-01-1973;
Iqbal, S., Al-Bender, F., Pluymers, B., Desmet, W.: *Model for predicting drag torque in open
multi-disks wet clutches*, ASME J. Fluids Eng. 136 (2014) 021103 (first published 2013);
Iqbal, S., Al-Bender, F., Pluymers, B., Desmet, W.: *Mathematical model and experimental evaluation
of drag torque in disengaged wet clutches*, ISRN Tribology 2013, 206539 (drag = ATF film + mist film);
Dukler, A. E., Wicks, M., Cleveland, R. G.: *Frictional pressure drop in two-phase flow: B. An
approach through similarity analysis*, AIChE J. 10 (1964) 44–51 (homogeneous mixture viscosity);
Incropera, F. P., DeWitt, D. P.: *Fundamentals of Heat and Mass Transfer*, 6th ed. (2007), Table A.4
(air at 300 K: μ = 184.6·10⁻⁷ N·s/m²);
Pahlovy, S. A., Mahmud, S. F., Ogawa, M., Kubota, M., Takakura, M.: *Multiphase drag modeling for
prediction of the drag torque characteristics in disengaged wet clutches*, SAE Int. J. Commer. Veh.
7 (2014) / SAE 2016-01-1145.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from ..limits import MAX_PLATE_GAPS
from ..results.solution import RPM_TO_RAD_S
from ._checks import finite_array, positive, positive_array
from .errors import LossModelError

__all__ = ["ClutchDrag", "LAMINAR_REYNOLDS", "AIR_VISCOSITY", "MIST_NODES"]

#: Reynolds number ρ ω r_o h / η up to which the film is laminar (Couette flow).
LAMINAR_REYNOLDS = 2000.0
#: Dynamic viscosity of air at 300 K, mPa·s (Incropera & DeWitt 2007, Table A.4: 184.6e-7 N·s/m²).
AIR_VISCOSITY = 0.01846
#: Gauss–Legendre nodes of the mist integral over r_e … r_o (its integrand is smooth: 8 nodes give it
#: to about 1e-12 relative for plates up to r_o/r_i = 4, tested against adaptive quadrature).
MIST_NODES = 8
_NODES, _WEIGHTS = np.polynomial.legendre.leggauss(MIST_NODES)
_BLOCK = 1 << 16  # points evaluated at once: the mist's (points, nodes) temporaries stay at a few MB
#: Most Newton steps for the film edge (from above on a convex function: monotone, quadratic near the root).
_NEWTON_STEPS = 60


def _log_edge_ratio(k: np.ndarray) -> np.ndarray:
    """u = ln (r_e/r_i)² > 0 with (e^u − 1)/u = k > 1, by Newton's method from above.

    h(u) = (e^u − 1)/u is increasing and convex with h ≥ 1 + u/2 and h ≥ e^(u/2) (Jensen), so the
    root lies below min(2 (k − 1), 2 ln k), where the steps start; Newton's steps on a convex
    increasing function started above the root fall monotonically onto it.  Equivalent to
    u = −W₋₁(−e^(−1/k)/k) − 1/k (Lambert's W, lower branch), without importing scipy.special
    (0.3 s at start-up, most of a drive cycle's import time).
    """
    u = np.minimum(2.0 * (k - 1.0), 2.0 * np.log(k))
    for _ in range(_NEWTON_STEPS):
        e = np.expm1(u)
        with np.errstate(divide="ignore", invalid="ignore"):
            h = np.where(u > 1e-8, e / u, 1.0 + 0.5 * u)
            slope = np.where(u > 1e-4, (u * (e + 1.0) - e) / (u * u), 0.5 + u / 3.0 + u * u / 8.0)
        step = (h - k) / slope
        u = np.maximum(u - step, 0.0)
        if np.all(np.abs(step) <= 1e-15 * np.maximum(u, 1e-300) + 1e-300):
            break
    return u


@dataclass(frozen=True)
class ClutchDrag:
    """The drag model of one open wet multi-plate clutch or brake.

    Parameters
    ----------
    element : str
        Name of the clutch or brake in the train.
    gaps : int
        Number of oil films (friction surfaces), e.g. 2 per friction plate.
    inner_radius, outer_radius : float
        Of the friction lining, mm.
    clearance : float
        Oil film thickness per gap when open, mm (total free travel / gaps).
    supply : float or None, default None
        Oil flow fed to the pack, l/min; None: the gaps stay full (no aeration).
    groove_factor : float, default 1.0
        Share of the plate area that shears a film, (0, 1].
    mist : bool, default True
        Past the peak, the oil mist outside the film edge shears too (Iqbal et al. 2013); False: the
        film alone (Yuan et al. 2007), no drag once it has collapsed.

    Examples
    --------
    >>> drag = ClutchDrag("C", gaps=8, inner_radius=65.0, outer_radius=80.0, clearance=0.2)
    >>> round(float(drag.torque(1000.0, 10.0, 850.0)), 3)  # N·m at 1000 1/min slip, 10 mPa·s
    1.521
    """

    element: str
    gaps: int
    inner_radius: float
    outer_radius: float
    clearance: float
    supply: float | None = None
    groove_factor: float = 1.0
    mist: bool = True

    def __post_init__(self) -> None:
        owner = f"clutch drag of {self.element!r}"
        if isinstance(self.gaps, bool) or not isinstance(self.gaps, int) or not 1 <= self.gaps <= MAX_PLATE_GAPS:
            raise LossModelError(f"{owner}: gaps must be a whole number of oil films in 1 ... {MAX_PLATE_GAPS} "
                                 f"(see docs/limits.md), got {self.gaps!r}.")
        r_i = positive(self.inner_radius, "inner_radius (mm)", owner)
        r_o = positive(self.outer_radius, "outer_radius (mm)", owner)
        if not r_o > r_i:
            raise LossModelError(f"{owner}: outer_radius must exceed inner_radius, got {r_o!r} and {r_i!r}.")
        h = positive(self.clearance, "clearance (mm)", owner)
        if h > 0.05 * r_o:
            raise LossModelError(f"{owner}: clearance {h!r} mm is no thin film on plates of radius {r_o!r} mm "
                                 "(the model needs h < 0.05 r_o; typical: 0.1 ... 0.3 mm).")
        supply = None if self.supply is None else positive(self.supply, "supply (l/min)", owner, allow_zero=True)
        groove = positive(self.groove_factor, "groove_factor", owner)
        if groove > 1.0:
            raise LossModelError(f"{owner}: groove_factor is the share of the plate that shears oil, in (0, 1]; "
                                 f"got {groove!r}.")
        if not isinstance(self.mist, bool):
            raise LossModelError(f"{owner}: mist must be true or false (the oil mist past the film edge shears), "
                                 f"got {self.mist!r}.")
        for name, value in (("inner_radius", r_i), ("outer_radius", r_o), ("clearance", h), ("supply", supply),
                            ("groove_factor", groove)):
            object.__setattr__(self, name, value)

    # ---------------------------------------------------------------- the model
    @property
    def _owner(self) -> str:
        return f"ClutchDrag of {self.element!r}"

    def _si(self):
        return self.inner_radius * 1e-3, self.outer_radius * 1e-3, self.clearance * 1e-3

    def film_flow(self, slip, viscosity, density, film_radius=None):
        """Flow one gap passes with the film out to ``film_radius`` (default r_o), l/min.

        Parameters
        ----------
        slip : float or array_like
            Slip speed, 1/min.
        viscosity : float or array_like
            Dynamic viscosity η, mPa·s.
        density : float or array_like
            ρ, kg/m³.
        film_radius : float or array_like, optional
            r_e, mm (r_i < r_e ≤ r_o).

        Returns
        -------
        ndarray
            Q(r_e) = π ρ ω² h³ (r_e² − r_i²) / (40 η ln(r_e/r_i)), l/min.

        References
        ----------
        Yuan et al. 2007, eq. (9) without the surface tension term.
        """
        r_i, r_o, h = self._si()
        r_e = r_o if film_radius is None else np.asarray(film_radius, dtype=float) * 1e-3
        omega = np.abs(np.asarray(slip, dtype=float)) * RPM_TO_RAD_S
        eta = np.asarray(viscosity, dtype=float) * 1e-3
        ratio = np.asarray(r_e / r_i, dtype=float)
        with np.errstate(divide="ignore", invalid="ignore"):  # (r_e² − r_i²)/ln(r_e/r_i) → 2 r_i² at r_e = r_i
            shape = np.where(ratio > 1.0 + 1e-12, (r_e ** 2 - r_i ** 2) / np.log(ratio), 2.0 * r_i ** 2)
        q = np.pi * np.asarray(density, dtype=float) * omega ** 2 * h ** 3 * shape / (40.0 * eta)
        return q * 6e4  # m³/s → l/min

    def film_radius(self, slip, viscosity, density):
        """Outer edge r_e of the oil film, mm: r_o while the supply fills the gap, less once it aerates.

        Parameters
        ----------
        slip : float or array_like
            Slip speed, 1/min.
        viscosity : float or array_like
            η, mPa·s.
        density : float or array_like
            ρ, kg/m³.

        Returns
        -------
        ndarray
            r_e, mm (Q(r_e) = supply: x = (r_e/r_i)² with (x − 1)/ln x = k, Lambert's W₋₁ in closed form,
            solved by Newton's method; vectorised over points).

        References
        ----------
        Yuan et al. 2007, eq. (9); Iqbal et al. 2013 (film shrinkage by aeration).
        """
        slip, viscosity, density = np.broadcast_arrays(*(np.asarray(v, dtype=float)
                                                         for v in (slip, viscosity, density)))
        full = np.full(slip.shape, self.outer_radius)
        if self.supply is None:
            return full
        per_gap = self.supply / self.gaps
        short = self.film_flow(slip, viscosity, density) > per_gap
        if not np.any(short):
            return full
        # Q(r_e) = 2 A r_i² (x − 1)/ln x with x = (r_e/r_i)², A = π ρ ω² h³/(40 η): (x − 1)/ln x = k,
        # x = e^u (Lambert's W₋₁ in closed form; solved by Newton's method, _log_edge_ratio)
        r_i = self.inner_radius * 1e-3
        a = (np.pi * density[short] * (np.abs(slip[short]) * RPM_TO_RAD_S) ** 2 * (self.clearance * 1e-3) ** 3
             / (40.0 * viscosity[short] * 1e-3))
        k = per_gap / 6e4 / (2.0 * a * r_i ** 2)
        edge = np.full(k.shape, self.inner_radius)
        film = k > 1.0 + 1e-12  # else not even Q(r_i) is supplied: no coherent film
        edge[film] = np.minimum(self.inner_radius * np.exp(0.5 * _log_edge_ratio(k[film])), self.outer_radius)
        full[short] = edge
        return full

    def mist_fraction(self, slip, viscosity, density, radius):
        """Oil's volume share α of the mist at ``radius`` (mm) outside the film edge: Q_s / Q(r), at most 1.

        Parameters
        ----------
        slip : float or array_like
            Slip speed, 1/min.
        viscosity : float or array_like
            η, mPa·s.
        density : float or array_like
            ρ, kg/m³.
        radius : float or array_like
            r, mm (r_i ≤ r ≤ r_o).

        Returns
        -------
        ndarray
            α ∈ [0, 1] (1 without a supply: the gap stays full).

        References
        ----------
        Continuity of the supplied oil through the aerated zone, with Q(r) of Yuan et al. 2007, eq. (9).
        """
        if self.supply is None:
            return np.ones(np.broadcast(*(np.asarray(v) for v in (slip, viscosity, density, radius))).shape)
        flow = self.film_flow(slip, viscosity, density, radius)
        per_gap = self.supply / self.gaps
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(flow > per_gap, per_gap / flow, 1.0)

    def _parts(self, slip, viscosity, density) -> tuple[np.ndarray, np.ndarray]:
        """(film drag, mist drag), N·m, with the film edge found once."""
        slip, viscosity, density = np.broadcast_arrays(
            finite_array(slip, "slip (1/min)", self._owner), positive_array(viscosity, "viscosity (mPa*s)", self._owner),
            positive_array(density, "density (kg/m^3)", self._owner))
        if slip.size > _BLOCK:  # the mist's (points, nodes) temporaries stay within a few MB
            flat = [v.ravel() for v in (slip, viscosity, density)]
            parts = [self._parts(*(v[i:i + _BLOCK] for v in flat)) for i in range(0, slip.size, _BLOCK)]
            return tuple(np.concatenate([p[k] for p in parts]).reshape(slip.shape) for k in (0, 1))
        r_i, _, h = self._si()
        omega = np.abs(slip) * RPM_TO_RAD_S
        edge = self.film_radius(slip, viscosity, density)
        scale = self.gaps * self.groove_factor * np.pi * omega / h
        film = scale * viscosity * 1e-3 * ((edge * 1e-3) ** 4 - r_i ** 4) / 2.0 + 0.0
        mist = np.zeros(slip.shape)
        aerated = edge < self.outer_radius
        if not self.mist or self.supply is None or not np.any(aerated):
            return film, mist
        r_e = edge[aerated][:, None]
        half = 0.5 * (self.outer_radius - r_e)
        radius = r_e + half * (_NODES + 1.0)  # mm, (points, nodes)
        n, eta, rho = (v[aerated][:, None] for v in (slip, viscosity, density))
        alpha = self.mist_fraction(n, eta, rho, radius)
        mixture = (alpha * eta + (1.0 - alpha) * AIR_VISCOSITY) * 1e-3  # Pa·s
        integral = (half[:, 0] * 1e-3) * np.sum(_WEIGHTS * mixture * (radius * 1e-3) ** 3, axis=1)
        mist[aerated] = 2.0 * scale[aerated] * integral
        return film, mist

    def mist_torque(self, slip, viscosity, density):
        """Drag of the mist between the film edge r_e and r_o, N·m (0 while the film is full or ``mist=False``).

        Parameters
        ----------
        slip : float or array_like
            1/min.
        viscosity : float or array_like
            η, mPa·s.
        density : float or array_like
            ρ, kg/m³.

        Returns
        -------
        ndarray
            N_gaps f_g (2π ω / h) ∫ [α η + (1 − α) η_air] r³ dr over r_e … r_o (Gauss–Legendre,
            :data:`MIST_NODES` nodes).

        References
        ----------
        Iqbal et al. 2013 (drag of the mist film); Dukler et al. 1964 (homogeneous mixture viscosity).
        """
        return self._parts(slip, viscosity, density)[1]

    def film_torque(self, slip, viscosity, density):
        """Drag of the coherent film from r_i to r_e, N·m: N_gaps f_g π η ω (r_e⁴ − r_i⁴) / (2 h).

        Parameters
        ----------
        slip : float or array_like
            1/min.
        viscosity : float or array_like
            η, mPa·s.
        density : float or array_like
            ρ, kg/m³.

        Returns
        -------
        ndarray

        References
        ----------
        Yuan et al. 2007, eqs. (5)–(9); Kitabayashi et al. 2003 (groove factor).
        """
        return self._parts(slip, viscosity, density)[0]

    def torque(self, slip, viscosity, density):
        """Drag torque magnitude, N·m, at slip speed ``slip`` (1/min) and the oil's η (mPa·s), ρ (kg/m³).

        Parameters
        ----------
        slip : float or array_like
            Speed difference across the element, 1/min (its sign does not matter).
        viscosity : float or array_like
            η at the oil temperature, mPa·s.
        density : float or array_like
            ρ at the oil temperature, kg/m³.

        Returns
        -------
        ndarray
            The film's drag plus the mist's (:meth:`film_torque` + :meth:`mist_torque`), ≥ 0.

        References
        ----------
        Yuan et al. 2007, eqs. (5)–(9); Iqbal et al. 2013 (film + mist); Kitabayashi et al. 2003
        (groove factor).
        """
        film, mist = self._parts(slip, viscosity, density)
        return film + mist

    def loss(self, slip, viscosity, density):
        """Power lost, W: T |ω_slip| ≥ 0.

        Parameters
        ----------
        slip : float or array_like
            1/min.
        viscosity : float or array_like
            η, mPa·s.
        density : float or array_like
            ρ, kg/m³.

        Returns
        -------
        ndarray
        """
        return self.torque(slip, viscosity, density) * np.abs(np.asarray(slip, dtype=float)) * RPM_TO_RAD_S

    def peak_slip(self, viscosity: float, density: float) -> float:
        """Slip speed (1/min) where the film starts to aerate: the gap's pumped flow Q(r_o) equals the supply.

        The film's drag is largest there; with the mist (``mist=True``) the maximum lies slightly
        above it (a few per cent in slip and torque), and the drag falls gradually past it.

        Parameters
        ----------
        viscosity : float
            η, mPa·s.
        density : float
            ρ, kg/m³.

        Returns
        -------
        float
            1/min; infinite without a supply (the full film's drag grows without bound).
        """
        if self.supply is None:
            return float("inf")
        unit = float(self.film_flow(1.0, viscosity, density))  # Q ∝ ω²
        return float(np.sqrt(self.supply / self.gaps / unit))

    def reynolds(self, slip, viscosity, density):
        """ρ ω r_o h / η of the film (laminar below :data:`LAMINAR_REYNOLDS`).

        Parameters
        ----------
        slip, viscosity, density : float or array_like
            1/min, mPa·s, kg/m³.

        Returns
        -------
        ndarray
        """
        _, r_o, h = self._si()
        return (np.asarray(density, dtype=float) * np.abs(np.asarray(slip, dtype=float)) * RPM_TO_RAD_S * r_o * h
                / (np.asarray(viscosity, dtype=float) * 1e-3))
