"""Results of the load-sharing calculation: the loads of one set, and a study over torque, angle or draws."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ._render import Tabular, number
from .errors import ElasticError

__all__ = ["PlanetLoads", "SharingStudy", "k_gamma"]


def k_gamma(forces: np.ndarray) -> np.ndarray:
    """K_γ = max_n F_n / mean F_n along the last axis (exactly 1 where all F_n are equal, at most N).

    >>> float(k_gamma(np.array([1.0, 1.0, 2.0])))
    1.5
    """
    forces = np.asarray(forces, dtype=float)
    top, low = forces.max(axis=-1), forces.min(axis=-1)
    ratio = top / forces.mean(axis=-1)
    # 1 <= K_γ <= N exactly (all equal / one planet carrying it all); round-off kept inside
    return np.where(top == low, 1.0, np.clip(ratio, 1.0, forces.shape[-1]))


@dataclass(frozen=True)
class PlanetLoads(Tabular):
    """Mesh loads of every planet of one set under one torque.

    Attributes
    ----------
    planets : int
    torque : float
        Sun torque, N m.
    sun_radius : float
        Base radius of the sun, m (the total tangential force is T/r_bs).
    sun_mesh, ring_mesh : ndarray
        Force in each sun–planet and ring–planet mesh along the line of action, N.
    errors : object
        The :class:`~epicyclic.elastic.sharing.PlanetErrors` it was computed with.
    """

    planets: int
    torque: float
    sun_radius: float
    sun_mesh: np.ndarray
    ring_mesh: np.ndarray
    errors: Any = None

    @property
    def shares(self) -> np.ndarray:
        """F_n / mean F_n."""
        return self.sun_mesh / self.sun_mesh.mean()

    @property
    def k_gamma(self) -> float:
        """K_γ = max share."""
        return float(k_gamma(self.sun_mesh))

    @property
    def total(self) -> float:
        """Σ F_n, N (= T/r_bs)."""
        return float(self.sun_mesh.sum())

    def _rows(self) -> tuple[list[str], list[list[str]]]:
        headers = ["planet", "sun mesh N", "ring mesh N", "share"]
        rows = [[str(i + 1), number(float(s), 6), number(float(r), 6), f"{float(x):.4f}"]
                for i, (s, r, x) in enumerate(zip(self.sun_mesh, self.ring_mesh, self.shares))]
        return headers, rows

    def _title(self) -> str:
        return f"Planet loads at sun torque {self.torque:g} N m: K_gamma = {self.k_gamma:.4f}"


    def __repr__(self) -> str:
        return f"PlanetLoads({self.planets} planets, T {self.torque:g} N m, K_gamma {self.k_gamma:.4f})"

    def to_dict(self) -> dict[str, Any]:
        """JSON data: torque (N m), forces (N), shares, K_γ."""
        return {"torque_Nm": self.torque, "sun_mesh_N": self.sun_mesh.tolist(), "ring_mesh_N": self.ring_mesh.tolist(),
                "shares": self.shares.tolist(), "k_gamma": self.k_gamma}


@dataclass(frozen=True)
class SharingStudy(Tabular):
    """Planet loads over many cases: torques, carrier angles or Monte-Carlo draws.

    Attributes
    ----------
    parameter, unit : str
        What varies (``sun torque`` N m, ``carrier angle`` deg, ``draw``).
    values : ndarray
        Its values (B,).
    sun_mesh, ring_mesh : ndarray
        Mesh forces (B, N), N.
    total : ndarray
        T/r_bs of each case, N.
    seed : int or None
        Monte Carlo: the seed of ``numpy.random.default_rng``.
    tolerances : object
        Monte Carlo: the :class:`~epicyclic.elastic.sharing.Tolerances` drawn from.
    """

    parameter: str
    unit: str
    values: np.ndarray
    sun_mesh: np.ndarray
    ring_mesh: np.ndarray
    total: np.ndarray
    seed: int | None = None
    tolerances: Any = None

    @property
    def k_gamma(self) -> np.ndarray:
        """K_γ of every case."""
        return k_gamma(self.sun_mesh)

    @property
    def shares(self) -> np.ndarray:
        """F_n / mean F_n of every case (B, N)."""
        return self.sun_mesh / self.sun_mesh.mean(axis=1, keepdims=True)

    def percentile(self, q: float = 95.0) -> float:
        """The ``q``-th percentile of K_γ (numpy's linear interpolation)."""
        if not 0.0 <= q <= 100.0:
            raise ElasticError(f"percentile q must lie in 0 ... 100, got {q!r}.")
        return float(np.percentile(self.k_gamma, q))

    def _rows(self, limit: int = 12) -> tuple[list[str], list[list[str]]]:
        if self.seed is not None:
            kg = self.k_gamma
            headers = ["statistic", "K_gamma"]
            rows = [["draws", str(len(kg))], ["seed", str(self.seed)], ["mean", f"{kg.mean():.4f}"],
                    ["median", f"{self.percentile(50):.4f}"], ["95th percentile", f"{self.percentile(95):.4f}"],
                    ["max", f"{kg.max():.4f}"]]
            return headers, rows
        n = self.sun_mesh.shape[1]
        headers = [f"{self.parameter} {self.unit}".strip(), "K_gamma"] + [f"F{i + 1} N" for i in range(n)]
        step = max(1, len(self.values) // limit)
        rows = [[number(float(self.values[b]), 6), f"{float(self.k_gamma[b]):.4f}"]
                + [number(float(x), 5) for x in self.sun_mesh[b]] for b in range(0, len(self.values), step)]
        return headers, rows

    def _title(self) -> str:
        if self.seed is not None:
            return f"K_gamma over {len(self.values)} Monte-Carlo draws (seed {self.seed}, errors uniform)"
        return f"Planet loads over {self.parameter} ({len(self.values)} cases)"


    def __repr__(self) -> str:
        return (f"SharingStudy({self.parameter}, {len(self.values)} cases, K_gamma {self.k_gamma.min():.4f} … "
                f"{self.k_gamma.max():.4f})")

    def to_dict(self) -> dict[str, Any]:
        """JSON data: the parameter, its values, K_γ and forces per case (Monte Carlo: statistics, seed)."""
        out: dict[str, Any] = {"parameter": self.parameter, "unit": self.unit}
        if self.seed is not None:
            kg = self.k_gamma
            out.update({"draws": len(kg), "seed": self.seed, "distribution": "uniform within the tolerances",
                        "tolerances_um": vars(self.tolerances) if self.tolerances is not None else None,
                        "k_gamma_mean": float(kg.mean()), "k_gamma_p50": self.percentile(50),
                        "k_gamma_p95": self.percentile(95), "k_gamma_max": float(kg.max())})
        else:
            out.update({"values": self.values.tolist(), "k_gamma": self.k_gamma.tolist(),
                        "sun_mesh_N": self.sun_mesh.tolist()})
        return out
