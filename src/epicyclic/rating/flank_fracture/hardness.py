"""The hardness of a case-carburised flank along the depth below the surface.

A :class:`HardnessProfile` gives the Vickers hardness HV(y) at the depth y (mm) below the flank,
either from a measured profile (depth–hardness pairs, interpolated shape-preserving by a PCHIP
spline and held at the last value below it) or, where only the surface hardness HV_s, the core
hardness HV_c and the case hardness depth CHD are known, by the smooth curve::

    HV(y) = HV_c + (HV_s − HV_c) exp(−k (y/CHD)²),    k = ln((HV_s − HV_c) / (HV_limit − HV_c))

which is HV_s at the surface with a horizontal tangent (the carburised case), passes through the
limit hardness HV_limit = 550 HV at y = CHD — the definition of the case hardness depth (ISO
2639:2002: the depth at which the hardness has fallen to 550 HV) — and falls monotonically to the
core hardness.  This curve is this package's assumption, not the estimated profile of ISO/TS
6336-4:2019 (whose text, and the profile formulas after Thomas 1998 and Lang 1979 that it is said
to use, were not reachable here): give a measured profile where one exists.

:meth:`HardnessProfile.with_case_depth` stretches a profile along the depth to another CHD (the
same surface and core hardness, the same shape): the hardened-layer check searches the CHD at
which the material exposure reaches its limit on it.

References
----------
ISO 2639:2002 (case hardness depth CHD, limit hardness 550 HV); ISO/TS 6336-4:2019
(the local material strength from the hardness profile); F. N. Fritsch, R. E. Carlson,
"Monotone piecewise cubic interpolation", SIAM J. Numer. Anal. 17 (1980) (PCHIP).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import RatingError

__all__ = ["LIMIT_HARDNESS", "HardnessProfile"]

LIMIT_HARDNESS = 550.0
"""The limit hardness that defines the case hardness depth of carburised parts, HV (ISO 2639:2002)."""


def _positive(value, what: str) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) or value <= 0:
        raise RatingError(f"{what} must be a positive number, got {value!r}.")
    return float(value)


@dataclass(frozen=True)
class HardnessProfile:
    """HV(y) of one flank.

    Parameters
    ----------
    surface : float
        HV_s, Vickers hardness at the surface (> 550 HV for a carburised case).
    core : float
        HV_c, core hardness (< 550 HV).
    case_depth : float
        CHD at 550 HV, mm.
    points : tuple of (depth mm, HV) pairs, optional
        A measured profile; then ``surface``, ``core`` and ``case_depth`` are read from it (pass
        them as :meth:`measured` does).

    References
    ----------
    ISO 2639:2002; ISO/TS 6336-4:2019 (local material strength).
    """

    surface: float
    core: float
    case_depth: float
    points: tuple[tuple[float, float], ...] | None = None

    def __post_init__(self) -> None:
        object.__setattr__(self, "surface", _positive(self.surface, "flank_fracture.surface_hardness"))
        object.__setattr__(self, "core", _positive(self.core, "flank_fracture.core_hardness"))
        object.__setattr__(self, "case_depth", _positive(self.case_depth, "flank_fracture.case_depth"))
        if self.points is None and not self.core < LIMIT_HARDNESS < self.surface:
            raise RatingError(f"flank_fracture: the case hardness depth is defined at 550 HV, so surface_hardness "
                              f"({self.surface:g} HV) must be above and core_hardness ({self.core:g} HV) below "
                              "550 HV (case-carburised gears: typically 58-62 HRC ~ 650-750 HV and 300-450 HV).")

    @classmethod
    def measured(cls, points) -> HardnessProfile:
        """A profile from measured (depth in mm, HV) pairs, depth increasing from the surface.

        Parameters
        ----------
        points : sequence of (float, float)
            At least two; the first depth ≥ 0, depths strictly increasing, the hardness must pass
            below 550 HV (the CHD is where it does).

        Returns
        -------
        HardnessProfile

        Raises
        ------
        RatingError
            Fewer than two points, depths not increasing, hardness not positive, no CHD.

        References
        ----------
        ISO 2639:2002.
        """
        try:
            arr = np.asarray(points, dtype=float)
        except (TypeError, ValueError):
            raise RatingError("flank_fracture.hardness_profile must be a list of [depth mm, HV] pairs, e.g. "
                              "[[0.0, 700], [0.5, 650], [1.0, 560], [1.5, 450], [3.0, 380]].") from None
        if arr.ndim != 2 or arr.shape[1] != 2 or arr.shape[0] < 2 or not np.all(np.isfinite(arr)):
            raise RatingError("flank_fracture.hardness_profile needs at least two finite [depth mm, HV] pairs.")
        y, hv = arr[:, 0], arr[:, 1]
        if y[0] < 0 or np.any(np.diff(y) <= 0) or np.any(hv <= 0):
            raise RatingError("flank_fracture.hardness_profile: depths must start at >= 0 mm and increase, "
                              "hardness values be positive HV.")
        below = np.nonzero(hv < LIMIT_HARDNESS)[0]
        if below.size == 0 or below[0] == 0:
            raise RatingError("flank_fracture.hardness_profile must start above 550 HV and fall below it (the "
                              "case hardness depth CHD, ISO 2639); extend it into the core.")
        i = int(below[0])
        chd = y[i - 1] + (hv[i - 1] - LIMIT_HARDNESS) * (y[i] - y[i - 1]) / (hv[i - 1] - hv[i])
        return cls(float(hv[0]), float(hv[-1]), float(chd), tuple((float(a), float(b)) for a, b in arr))

    def __call__(self, depth, case_depth: float | None = None) -> np.ndarray:
        """HV at ``depth`` (mm, ≥ 0), the profile stretched to ``case_depth`` where given."""
        y = np.asarray(depth, dtype=float)
        if case_depth is not None:
            y = y * (self.case_depth / case_depth)
        if self.points is None:
            k = math.log((self.surface - self.core) / (LIMIT_HARDNESS - self.core))
            return self.core + (self.surface - self.core) * np.exp(-k * (y / self.case_depth) ** 2)
        from scipy.interpolate import PchipInterpolator

        pts = np.asarray(self.points)
        inside = np.clip(y, pts[0, 0], pts[-1, 0])
        return PchipInterpolator(pts[:, 0], pts[:, 1])(inside)

    def with_case_depth(self, case_depth: float) -> HardnessProfile:
        """The same profile stretched along the depth to CHD = ``case_depth`` (mm)."""
        scale = case_depth / self.case_depth
        pts = None if self.points is None else tuple((a * scale, b) for a, b in self.points)
        return HardnessProfile(self.surface, self.core, case_depth, pts)

    @property
    def hardness_range(self) -> tuple[float, float]:
        """(the highest, the lowest) HV of the profile."""
        if self.points is None:
            return self.surface, self.core
        hv = [h for _, h in self.points]
        return max(hv), min(hv)

    @property
    def source(self) -> str:
        """``"measured"`` or ``"estimated"``."""
        return "measured" if self.points is not None else "estimated"

    def to_dict(self) -> dict:
        """Plain data."""
        return {"surface_hardness": self.surface, "core_hardness": self.core, "case_depth": self.case_depth,
                "hardness_profile": [list(p) for p in self.points] if self.points else None}

    def __repr__(self) -> str:
        return (f"HardnessProfile({self.source}: {self.surface:g} HV surface, {self.core:g} HV core, "
                f"CHD {self.case_depth:g} mm)")
