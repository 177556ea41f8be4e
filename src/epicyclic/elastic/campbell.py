"""Campbell diagram of a planetary set: natural frequencies against mesh and shaft orders over speed.

Over a range of input speeds n (1/min) with the members turning at fixed ratios to it
(n_j = ratio_j n, e.g. from the kinematics of the train), the set's

* mesh frequency is f_m = z_s |n_s − n_c|/60 (= z_r |n_r − n_c|/60 for a simple set; a stepped set's
  ring meshes get their own lines, ``ring mesh xl``), and its harmonics l f_m;
* shaft orders are k n_j/60 for the carrier, ring and sun;
* natural frequencies follow from :func:`~epicyclic.elastic.modes.frequencies_at_speeds` at the
  carrier speed Ω = 2π n_c/60 (gyroscopic terms; or the frequencies at rest).

A crossing is a speed at which an excitation line meets a natural-frequency curve (the sign of
their difference changes between two grid speeds; the speed is interpolated linearly).  Each
mesh-harmonic crossing says whether the mesh phasing lets that harmonic excite the mode's type
(:mod:`~epicyclic.elastic.phasing`; the type from the mode shape at the crossing's speed,
:func:`~epicyclic.elastic.modes.kinds_at_speed`).

References
----------
Cooley & Parker 2012, J. Vib. Acoust. 134, 061014 (natural frequencies over carrier speed);
Parker & Lin 2004, J. Mech. Des. 126, 365–370 (which harmonics excite which modes);
ISO 6336-1:2006, 6.5 (mesh frequency of a planetary set from the speeds relative to the carrier).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from ._render import Tabular, number
from .errors import ElasticError, finite
from .lumped import CENTRAL, PlanetaryLumpedModel
from .modes import frequencies_at_speeds, kinds_at_speed, natural_modes
from .phasing import mesh_phasing

__all__ = ["CampbellDiagram", "Crossing", "campbell_diagram", "crossings"]


@dataclass(frozen=True)
class Crossing:
    """One excitation line meeting one natural-frequency curve.

    Attributes
    ----------
    order : str
        ``"mesh x2"`` (second mesh harmonic) or ``"sun x1"`` (first order of the sun speed) …
    mode : int
        Rank of the natural frequency (1 = lowest).
    kind : str
        The type of that mode at the crossing's speed.
    speed : float
        Input speed of the crossing, 1/min.
    frequency : float
        Hz.
    excited : bool or None
        Mesh harmonics: whether the phasing lets the harmonic excite that type; shaft orders: None.
    """

    order: str
    mode: int
    kind: str
    speed: float
    frequency: float
    excited: bool | None

    def to_dict(self) -> dict[str, Any]:
        """JSON data (speed in 1/min, frequency in Hz)."""
        return {"order": self.order, "mode": self.mode, "type": self.kind, "speed_rpm": self.speed,
                "frequency_Hz": self.frequency, "excited": self.excited}


def crossings(speeds: np.ndarray, natural: np.ndarray, lines: np.ndarray) -> list[tuple[int, int, float, float]]:
    """(line, mode, speed, frequency) where ``lines[:, i]`` crosses ``natural[:, j]`` over ``speeds``.

    Parameters
    ----------
    speeds : ndarray
        Grid, ascending, shape (S,).
    natural : ndarray
        Shape (S, M), Hz.
    lines : ndarray
        Shape (S, L), Hz.

    Returns
    -------
    list of tuple
        Linearly interpolated between the grid points where the difference changes sign (a
        touch at a grid point counts once).

    Examples
    --------
    >>> s = np.array([0.0, 1.0, 2.0])
    >>> crossings(s, np.array([[1.0], [1.0], [1.0]]), np.array([[0.0], [0.5], [1.5]]))
    [(0, 0, 1.5, 1.0)]
    """
    diff = lines[:, :, None] - natural[:, None, :]                       # S × L × M
    a, b = diff[:-1], diff[1:]
    hit = ((a < 0) & (b >= 0)) | ((a > 0) & (b <= 0))
    out = []
    for s, i, j in zip(*np.nonzero(hit)):
        t = a[s, i, j] / (a[s, i, j] - b[s, i, j])
        speed = speeds[s] + t * (speeds[s + 1] - speeds[s])
        freq = lines[s, i] + t * (lines[s + 1, i] - lines[s, i])
        out.append((int(i), int(j), float(speed), float(freq)))
    return sorted(out, key=lambda c: (c[2], c[0], c[1]))


@dataclass(frozen=True)
class CampbellDiagram(Tabular):
    """Natural frequencies and excitation orders of a set over a speed range.

    Attributes
    ----------
    speeds : ndarray
        Input speeds, 1/min.
    natural : ndarray
        Natural frequencies, Hz, shape (speeds, modes).
    orders : tuple of str
        Names of the excitation lines.
    lines : ndarray
        Their frequencies, Hz, shape (speeds, orders).
    kinds : tuple of str
        Type of each mode at rest.
    crossings : tuple of Crossing
        Within ``operating`` (all speeds when it is None).
    operating : tuple of float or None
        The operating speed range (1/min) the crossings are listed for.
    gyroscopic : bool
    """

    speeds: np.ndarray
    natural: np.ndarray
    orders: tuple[str, ...]
    lines: np.ndarray
    kinds: tuple[str, ...]
    crossings: tuple[Crossing, ...]
    operating: tuple[float, float] | None
    gyroscopic: bool

    def _rows(self) -> tuple[list[str], list[list[str]]]:
        headers = ["order", "mode", "type", "speed 1/min", "f Hz", "excited"]
        rows = [[c.order, str(c.mode), c.kind, number(c.speed, 6), number(c.frequency, 6),
                 "—" if c.excited is None else ("yes" if c.excited else "no (phasing)")] for c in self.crossings]
        return headers, rows

    def _title(self) -> str:
        span = f"{self.operating[0]:g} … {self.operating[1]:g}" if self.operating else \
            f"{self.speeds[0]:g} … {self.speeds[-1]:g}"
        return f"Campbell diagram crossings, input speed {span} 1/min ({len(self.crossings)})"


    def __repr__(self) -> str:
        return (f"CampbellDiagram({len(self.speeds)} speeds {self.speeds[0]:g}…{self.speeds[-1]:g} 1/min, "
                f"{self.natural.shape[1]} modes, {len(self.orders)} orders, {len(self.crossings)} crossings)")

    def to_dict(self) -> dict[str, Any]:
        """JSON data: the grid, natural frequencies, lines and crossings."""
        return {"speeds_rpm": self.speeds.tolist(), "natural_Hz": self.natural.tolist(),
                "orders": list(self.orders), "lines_Hz": self.lines.tolist(), "types": list(self.kinds),
                "operating_rpm": list(self.operating) if self.operating else None, "gyroscopic": self.gyroscopic,
                "crossings": [c.to_dict() for c in self.crossings]}


def campbell_diagram(model: PlanetaryLumpedModel, sun_teeth: int, ring_teeth: int, ratios: dict[str, float],
                     speeds, *, mesh_harmonics: int = 3, shaft_orders: int = 1, operating=None,
                     gyroscopic: bool = True) -> CampbellDiagram:
    """The Campbell diagram of ``model`` over input ``speeds`` (1/min).

    Parameters
    ----------
    model : PlanetaryLumpedModel
    sun_teeth, ring_teeth : int
        z_s, z_r (mesh frequency and phasing).
    ratios : mapping
        Speed of ``carrier``, ``ring``, ``sun`` per unit input speed (a member not given stands).
    speeds : array_like
        Input speeds, 1/min, ascending (at most 100 000 points).
    mesh_harmonics : int, default 3
        Mesh harmonics l = 1 … drawn.
    shaft_orders : int, default 1
        Orders k = 1 … of each turning member's speed.
    operating : (float, float), optional
        The operating range the crossings are listed for, 1/min.
    gyroscopic : bool, default True
        Natural frequencies at the carrier speed (else at rest, flat lines).

    Returns
    -------
    CampbellDiagram

    Raises
    ------
    ElasticError
        Unknown member, non-finite ratio or speed, speeds not ascending, bad counts.

    References
    ----------
    Cooley & Parker 2012; Parker & Lin 2004, Table 1.

    Examples
    --------
    >>> from epicyclic.elastic.lumped import Body, PlanetaryLumpedModel, equally_spaced
    >>> b = Body(1.0, 0.01, 0.1)
    >>> m = PlanetaryLumpedModel(b, b, b, Body(0.5, 0.002, 0.05), equally_spaced(3), 5e8, 5e8, 1e8,
    ...                          supports={"ring": (1e8, 1e6), "carrier": (1e8, 1e4), "sun": (1e8, 1e4)})
    >>> c = campbell_diagram(m, 30, 90, {"sun": 1.0, "carrier": 0.25}, np.linspace(0, 20000, 201))
    >>> c.orders[:2], len(c.crossings) > 0
    (('mesh x1', 'mesh x2'), True)
    """
    for name, value in ratios.items():
        if name not in CENTRAL:
            raise ElasticError(f"ratios: unknown member {name!r}; use carrier, ring or sun.")
        finite(value, f"ratios.{name}")
    ratio = {name: float(ratios.get(name, 0.0)) for name in CENTRAL}
    grid_ = np.asarray(speeds, dtype=float)
    if grid_.ndim != 1 or len(grid_) < 2 or len(grid_) > 100_000 or not np.all(np.isfinite(grid_)) \
            or np.any(np.diff(grid_) <= 0) or np.any(np.abs(grid_) > 1e6):
        raise ElasticError("speeds must be 2 … 100000 finite, ascending input speeds in 1/min (|n| <= 1e6).")
    for key, value in (("mesh_harmonics", mesh_harmonics), ("shaft_orders", shaft_orders)):
        if isinstance(value, bool) or not isinstance(value, int) or not 0 <= value <= 50:
            raise ElasticError(f"{key} must be a whole number 0 ... 50, got {value!r}.")
    phasing = mesh_phasing(sun_teeth, ring_teeth, model.planet_angles)
    rest = natural_modes(model)
    if gyroscopic:
        natural = frequencies_at_speeds(model, 2 * math.pi * ratio["carrier"] * grid_ / 60.0)
    else:
        natural = np.broadcast_to(rest.frequencies, (len(grid_), len(rest.frequencies))).copy()
    mesh = sun_teeth * np.abs(ratio["sun"] - ratio["carrier"]) * np.abs(grid_) / 60.0
    ring_mesh = ring_teeth * np.abs(ratio["ring"] - ratio["carrier"]) * np.abs(grid_) / 60.0
    orders = [f"mesh x{l_}" for l_ in range(1, mesh_harmonics + 1)]
    columns = [l_ * mesh for l_ in range(1, mesh_harmonics + 1)]
    if not np.allclose(ring_mesh, mesh, rtol=1e-9, atol=1e-9):  # a stepped set: the ring meshes have their own
        orders += [f"ring mesh x{l_}" for l_ in range(1, mesh_harmonics + 1)]
        columns += [l_ * ring_mesh for l_ in range(1, mesh_harmonics + 1)]
    for name in CENTRAL:
        if ratio[name] != 0.0:
            for k in range(1, shaft_orders + 1):
                orders.append(f"{name} x{k}")
                columns.append(k * abs(ratio[name]) * np.abs(grid_) / 60.0)
    lines = np.stack(columns, axis=1) if columns else np.zeros((len(grid_), 0))
    band = None
    if operating is not None:
        low, high = (finite(v, "operating") for v in operating)
        if high < low:
            raise ElasticError(f"operating must be (low, high) in 1/min with low <= high, got {operating!r}.")
        band = (low, high)
    found = []
    for i, j, speed, freq in crossings(grid_, natural, lines):
        if freq <= 0.0 or (band and not band[0] <= speed <= band[1]):
            continue
        # the mode's type at the crossing's carrier speed (the ranks of the curves may change with speed)
        kind = kinds_at_speed(model, 2 * math.pi * ratio["carrier"] * speed / 60.0)[1][j] if gyroscopic \
            else rest.kinds[j]
        excited = None
        if "mesh" in orders[i]:
            which = "ring" if orders[i].startswith("ring") else "sun"
            harmonic = int(orders[i].rsplit("x", 1)[1])
            excited = ("rotational" if kind == "rigid-body" else kind) in phasing.excited(harmonic, which) \
                or kind == "mixed"
        found.append(Crossing(orders[i], j + 1, kind, speed, freq, excited))
    return CampbellDiagram(grid_, natural, tuple(orders), lines, rest.kinds, tuple(found), band, gyroscopic)
