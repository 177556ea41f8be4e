"""Result objects of a tooth load capacity rating: factors, gears, meshes, a train.

* :class:`Factor` — one ISO 6336 quantity: symbol, value (a number, or one per load
  case), unit, the clause it comes from;
* :class:`GearRating` — one gear of a mesh: flank (σ_H, σ_HP, S_H) and root (σ_F,
  σ_FP, S_F) with their factors and the load cycles N_L;
* :class:`MeshRating` — one mesh: the load factors and the two gears, the lowest
  safeties, whether they meet S_Hmin / S_Fmin;
* :class:`TrainRating` — every mesh of every rated element of a train at one
  operating point (or over load cases).

Each renders itself (``table()``, ``to_dict()``, ``_repr_html_``); ``to_dict`` keys
are the ISO symbols (``S_H``, ``sigma_HP``, ``K_Hbeta``, ``Y_F`` ...) each as
``{"value", "unit", "clause"}``, never NaN or infinity (an unbounded safety is
``None`` with a note).

References
----------
ISO 6336-1:2019, clause 4 (symbols and units); ISO 6336-2:2019; ISO 6336-3:2019.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any

import numpy as np

__all__ = ["Factor", "GearRating", "MeshRating", "TrainRating", "json_value"]


def json_value(value):
    """A number or array as JSON data: floats, lists of floats, ``None`` for NaN/±inf.

    Parameters
    ----------
    value : float, int, bool, str or numpy.ndarray
        The value to convert.

    Returns
    -------
    float, list, str, bool or None

    References
    ----------
    RFC 8259, section 6 (JSON numbers have no NaN or infinity).

    Examples
    --------
    >>> json_value(float("inf")), json_value(np.array([1.0, 2.0]))
    (None, [1.0, 2.0])
    """
    if isinstance(value, (bool, str)) or value is None:
        return value
    array = np.asarray(value, dtype=float)
    if array.ndim == 0:
        number = float(array)
        return number if math.isfinite(number) else None
    return [json_value(v) for v in array]


@dataclass(frozen=True)
class Factor:
    """One quantity of the rating with its unit and source.

    Parameters
    ----------
    symbol : str
        ISO symbol in ASCII (``K_v``, ``Z_H``, ``sigma_H``, ``S_F``).
    value : float or numpy.ndarray
        The value, or one per load case.
    unit : str
        ``"1"`` for a factor, ``"N/mm^2"``, ``"mm"``, ``"N"``, ``"m/s"``, ...
    clause : str
        Where the standard defines it, e.g. ``"ISO 6336-2:2019, 6.1"``.
    name : str
        What it is in words.
    source : str, default ""
        Where a factor's value comes from: ``"given"`` (an input), ``"computed"`` (by the clause),
        or another named source (``"computed by the elastic model"``).  Left empty, a factor
        (``K_``, ``Z_``, ``Y_``, ``S_`` of unit 1) is ``"computed"``, σ_Hlim and σ_Flim are
        ``"material"``, data and stresses have none.

    References
    ----------
    ISO 6336-1:2019, clause 4.
    """

    symbol: str
    value: Any
    unit: str = "1"
    clause: str = ""
    name: str = ""
    source: str = ""

    def __post_init__(self) -> None:
        if not self.source:
            if self.symbol in ("sigma_Hlim", "sigma_Flim"):
                object.__setattr__(self, "source", "material")
            elif self.unit == "1" and self.symbol[:2] in ("K_", "Z_", "Y_", "S_"):
                object.__setattr__(self, "source", "computed")

    def to_dict(self) -> dict[str, Any]:
        """``{"value", "unit", "clause", "name"}`` and ``source`` where it has one (JSON-safe)."""
        out = {"value": json_value(self.value), "unit": self.unit, "clause": self.clause, "name": self.name}
        if self.source:
            out["source"] = self.source
        return out


def _short(value) -> str:
    array = np.asarray(value, dtype=float)
    return f"{float(np.min(array)):.3f}" if array.size else "-"


def _factors(factors: Mapping[str, Factor]) -> Mapping[str, Factor]:
    return MappingProxyType(dict(factors))


@dataclass(frozen=True)
class GearRating:
    """Flank and root of one gear of a mesh.

    Attributes
    ----------
    gear : str
        The gear's name in its set or stage (``sun``, ``planet``, ``ring``, ``gear 1``).
    factors : mapping symbol → Factor
        Y_F, Y_S, Y_β, ..., sigma_F0, sigma_F, sigma_FP, S_F, Z_NT, sigma_H, sigma_HP, S_H, N_L ...
    S_Hmin, S_Fmin : float
        The minimum safeties it is checked against.
    pitting_curve, bending_curve : SNCurve, optional
        The Z_NT and Y_NT curves of its material (for :meth:`damage`).
    life_hours : float, default 0
        The required life N_L is counted over, h.
    """

    gear: str
    factors: Mapping[str, Factor]
    S_Hmin: float
    S_Fmin: float
    pitting_curve: Any = None
    bending_curve: Any = None
    life_hours: float = 0.0

    def __post_init__(self) -> None:
        object.__setattr__(self, "factors", _factors(self.factors))

    def __getitem__(self, symbol: str):
        return self.factors[symbol].value

    @property
    def S_H(self):
        """Safety against pitting of the flank (number or one per case)."""
        return self.factors["S_H"].value

    @property
    def S_F(self):
        """Safety against tooth-root breakage (number or one per case)."""
        return self.factors["S_F"].value

    @property
    def ok(self) -> bool:
        """Whether S_H ≥ S_Hmin and S_F ≥ S_Fmin (in every case)."""
        return bool(np.all(np.asarray(self.S_H) >= self.S_Hmin) and np.all(np.asarray(self.S_F) >= self.S_Fmin))

    def damage(self, hours) -> tuple[float, float]:
        """Palmgren–Miner damage (D_H of the flank, D_F of the root) over the rated load cases.

        Parameters
        ----------
        hours : float or array_like
            Hours spent in each load case (one per case of the rating, or one number).

        Returns
        -------
        tuple of float
            (D_H, D_F); the gear is expected to last while both are below 1 (∞ where a case
            exceeds the static strength).

        Raises
        ------
        ValueError
            The rating has no S–N curves or no life (not made by :func:`~epicyclic.rating.rate_mesh`).

        References
        ----------
        ISO 6336-6:2019, clause 5 (Palmgren–Miner); the life factors of ISO 6336-2, -3.
        """
        from .life_factors import miner_damage

        if self.pitting_curve is None or self.bending_curve is None or not self.life_hours > 0:
            raise ValueError("damage: this GearRating has no S-N curves or life; rate it with rate_mesh.")
        n_l = np.atleast_1d(np.asarray(self["N_L"], dtype=float))
        h = np.broadcast_to(np.asarray(hours, dtype=float), n_l.shape)
        cycles = n_l / self.life_hours * h
        out = []
        for stress, limit, factor, curve in (("sigma_H", "sigma_HG", "Z_NT", self.pitting_curve),
                                              ("sigma_F", "sigma_FG", "Y_NT", self.bending_curve)):
            sigma = np.broadcast_to(np.asarray(self[stress], dtype=float), n_l.shape)
            reference = np.broadcast_to(np.asarray(self[limit], dtype=float) / np.asarray(self[factor]), n_l.shape)
            total = 0.0
            for s_i, r_i, n_i in zip(sigma, reference, cycles):
                total += miner_damage([(float(s_i), float(n_i))], curve, float(r_i))
            out.append(total)
        return out[0], out[1]

    def to_dict(self) -> dict[str, Any]:
        """Each factor by its symbol, ``S_Hmin``, ``S_Fmin`` and ``ok``."""
        out: dict[str, Any] = {s: f.to_dict() for s, f in self.factors.items()}
        out.update(S_Hmin=self.S_Hmin, S_Fmin=self.S_Fmin, ok=self.ok)
        return out


@dataclass(frozen=True)
class MeshRating:
    """The rating of one mesh: load factors, both gears, the lowest safeties.

    Attributes
    ----------
    element : str
        The set or stage the mesh belongs to.
    mesh : str
        The mesh's name (``sun-planet``, ``planet-ring``, ``mesh 1 (20/40)``).
    standard : str
        ``"ISO 6336:2006"`` or ``"ISO 6336:2019"``.
    method : str
        ``"B"`` (factors by method B; K_Hβ by method C or given, stated in its factor).
    factors : mapping symbol → Factor
        The mesh's own factors and data: F_t, v, u, K_A, K_gamma, K_v, K_Hbeta, K_Fbeta,
        K_Halpha, K_Falpha, Z_H, Z_E, Z_epsilon, Z_beta, sigma_H0, Z_L, Z_v, Z_R ...
    gears : tuple of GearRating
        Gear 1 (the external pinion or planet) and gear 2.
    internal : bool
        Gear 2 is internal (a ring).
    notes : tuple of str
        What the rating assumed (defaults taken, clamps applied).
    """

    element: str
    mesh: str
    standard: str
    method: str
    factors: Mapping[str, Factor]
    gears: tuple[GearRating, GearRating]
    internal: bool = False
    notes: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        object.__setattr__(self, "factors", _factors(self.factors))

    def __getitem__(self, symbol: str):
        return self.factors[symbol].value

    def __repr__(self) -> str:
        return (f"MeshRating({self.element}: {self.mesh}, {self.standard}, S_H {_short(self.S_H)}, "
                f"S_F {_short(self.S_F)}, ok {self.ok})")

    @property
    def S_H(self):
        """Lowest pitting safety of the two gears (number or one per case)."""
        return np.minimum(self.gears[0].S_H, self.gears[1].S_H)

    @property
    def S_F(self):
        """Lowest root safety of the two gears (number or one per case)."""
        return np.minimum(self.gears[0].S_F, self.gears[1].S_F)

    @property
    def ok(self) -> bool:
        """Whether both gears meet their minimum safeties."""
        return all(g.ok for g in self.gears)

    def to_dict(self) -> dict[str, Any]:
        """JSON data: element, mesh, standard, method, factors by ISO symbol, gears, ok, notes."""
        return {"element": self.element, "mesh": self.mesh, "standard": self.standard, "method": self.method,
                "internal": self.internal, "factors": {s: f.to_dict() for s, f in self.factors.items()},
                "gears": {g.gear: g.to_dict() for g in self.gears},
                "S_H": json_value(self.S_H), "S_F": json_value(self.S_F), "ok": self.ok, "notes": list(self.notes)}

    def table(self) -> str:
        """This mesh's factors as a plain-text table (a safety below its minimum ends in ``!``)."""
        from .report import text_report

        return text_report(TrainRating((self,), standard=self.standard))

    def _repr_html_(self) -> str:
        from .report import html_section

        return html_section(TrainRating((self,), standard=self.standard))

    def explain(self, gear: int = 0) -> str:
        """The worked rating of this mesh, equation by equation (:func:`~epicyclic.rating.worked.worked_rating`)."""
        from .worked import worked_rating

        return worked_rating(self, gear)


@dataclass(frozen=True)
class TrainRating:
    """Every rated mesh of a train at one operating point (or over load cases).

    Attributes
    ----------
    meshes : tuple of MeshRating
    gear : str or None
        The transmission gear it was rated in.
    standard : str
    life_hours : float
        The required life the life factors are for, h.
    skipped : mapping element → reason
        Elements with geometry that could not be rated (and why).
    """

    meshes: tuple[MeshRating, ...]
    gear: str | None = None
    standard: str = ""
    life_hours: float = 0.0
    skipped: Mapping[str, str] = field(default_factory=lambda: MappingProxyType({}))

    @property
    def ok(self) -> bool:
        """Whether every mesh meets its minimum safeties."""
        return all(m.ok for m in self.meshes)

    def below_minimum(self) -> dict[str, str]:
        """Element → what falls short, for every element with a mesh below its minimum safety.

        Returns
        -------
        dict
            One line per failing mesh with the lowest safety of its two gears, e.g.
            ``{"P": "planet-ring: S_F 1.14 < 1.4"}`` (the lowest case where a rating holds several);
            empty where every mesh meets its minimums.
        """
        out: dict[str, list[str]] = {}
        for mesh in self.meshes:
            short = []
            for kind in ("S_H", "S_F"):
                value, minimum = min((float(np.min(getattr(g, kind))), getattr(g, kind + "min")) for g in mesh.gears)
                if any(float(np.min(getattr(g, kind))) < getattr(g, kind + "min") for g in mesh.gears):
                    short.append(f"{kind} {value:.3g} < {minimum:g}")
            if short:
                out.setdefault(mesh.element, []).append(f"{mesh.mesh}: {', '.join(short)}")
        return {element: "\n".join(items) for element, items in out.items()}

    def mesh(self, element: str, mesh: str | None = None) -> MeshRating:
        """The rating of ``mesh`` of ``element`` (its first mesh if ``mesh`` is None).

        Parameters
        ----------
        element : str
            The set or stage.
        mesh : str, optional
            The mesh's name (``sun-planet``, ``planet-ring``, ``mesh 1 (20/40)``).

        Returns
        -------
        MeshRating

        Raises
        ------
        RatingError
            No such mesh; the message lists the rated ones.
        """
        for m in self.meshes:
            if m.element == element and (mesh is None or m.mesh == mesh):
                return m
        known = ", ".join(f"{m.element}: {m.mesh}" for m in self.meshes)
        from .errors import RatingError

        raise RatingError(f"rating: no mesh {mesh!r} of {element!r}; rated meshes are {known or 'none'}.")

    def to_dict(self) -> dict[str, Any]:
        """JSON data: standard, gear, life, ok and one entry per mesh."""
        return {"standard": self.standard, "method": "B", "gear": self.gear, "life_hours": self.life_hours,
                "ok": self.ok, "meshes": [m.to_dict() for m in self.meshes], "skipped": dict(self.skipped)}

    def table(self) -> str:
        """The rating as plain text: a summary and every mesh's factors."""
        from .report import text_report

        return text_report(self)

    def _repr_html_(self) -> str:
        from .report import html_section

        return html_section(self)

    def __repr__(self) -> str:
        worst = min((float(np.min(m.S_H)) for m in self.meshes), default=float("nan"))
        worst_f = min((float(np.min(m.S_F)) for m in self.meshes), default=float("nan"))
        return (f"TrainRating({len(self.meshes)} meshes, {self.standard}, gear {self.gear}, "
                f"min S_H {worst:.3f}, min S_F {worst_f:.3f}, ok {self.ok})")

