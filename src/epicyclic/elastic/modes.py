"""Natural frequencies and modes of a planetary set: classification and modal strain energy.

* Free vibration at rest: K φ = ω² M φ (``scipy.linalg.eigh``), φ mass-normalised.
* Classification (Lin & Parker 1999, section 3, for equally spaced planets): a *rotational* mode
  has no translation of the central members (multiplicity 1), a *translational* mode no rotation
  of them (multiplicity 2), a *planet* mode no motion of them at all (multiplicity N − 3); a
  rotational mode at ω = 0 is the *rigid-body* mode of a set with a free member.  Modes of sets
  with unequally spaced planets that fit none of these are *mixed*.
* Modal strain energy of an element (mesh, bearing, support): k (vᵀφ)² / (φᵀKφ), its share of
  the mode's strain energy (the shares of a mode add up to 1).
* At a carrier speed Ω (rad/s), with gyroscopic and centripetal terms: the quadratic eigenvalue
  problem M q̈ + Ω G q̇ + (K − Ω² K_Ω) q = 0 in first-order form, vectorised over speeds
  (:func:`frequencies_at_speeds`).

References
----------
J. Lin, R. G. Parker, J. Vib. Acoust. 121 (1999) 316–321, section 3 (the three mode types and
their multiplicities) and Table 2 (natural frequencies of the example system);
C. G. Cooley, R. G. Parker, J. Vib. Acoust. 134 (2012) 061014 (gyroscopic terms).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
import scipy.linalg

from ._render import Tabular, number
from .errors import ElasticError
from .lumped import PlanetaryLumpedModel

__all__ = ["NaturalModes", "natural_modes", "frequencies_at_speeds", "kinds_at_speed", "KINDS"]

#: Mode types.
KINDS = ("rigid-body", "rotational", "translational", "planet", "mixed")

_TRANSLATION = np.array([0, 1, 3, 4, 6, 7])
_ROTATION = np.array([2, 5, 8])


def _kind(group: np.ndarray, zero: bool, tolerance: float) -> str:
    """The type of the eigenspace spanned by the columns of ``group``."""
    scale = np.max(np.abs(group), axis=0)
    central = np.max(np.abs(group[:9]), axis=0) / scale
    translation = np.max(np.abs(group[_TRANSLATION]), axis=0) / scale
    rotation = np.max(np.abs(group[_ROTATION]), axis=0) / scale
    if np.all(central <= tolerance):
        return "planet"
    if np.all(translation <= tolerance):
        return "rigid-body" if zero else "rotational"
    if np.all(rotation <= tolerance):
        return "translational"
    return "mixed"


@dataclass(frozen=True)
class NaturalModes(Tabular):
    """Natural frequencies and modes of a planetary set at rest.

    Attributes
    ----------
    model : PlanetaryLumpedModel
    frequencies : ndarray
        Natural frequencies f = ω/2π, Hz, ascending (a rigid-body mode is 0).
    shapes : ndarray
        Mass-normalised mode shapes, one column per frequency (coordinates as ``model.labels()``).
    kinds : tuple of str
        One of :data:`KINDS` per mode.
    multiplicities : tuple of int
        How many modes share each mode's frequency.
    elements : tuple of str
        The spring elements (meshes, bearings, supports).
    strain_energy : ndarray
        Share of each mode's strain energy in each element (modes × elements; rows add up to 1,
        rigid-body rows 0).
    """

    model: PlanetaryLumpedModel
    frequencies: np.ndarray
    shapes: np.ndarray
    kinds: tuple[str, ...]
    multiplicities: tuple[int, ...]
    elements: tuple[str, ...]
    strain_energy: np.ndarray

    def __len__(self) -> int:
        return len(self.frequencies)

    def distinct(self) -> list[tuple[float, str, int]]:
        """(frequency Hz, kind, multiplicity) of each distinct frequency, ascending."""
        out: list[tuple[float, str, int]] = []
        i = 0
        while i < len(self):
            out.append((float(self.frequencies[i]), self.kinds[i], self.multiplicities[i]))
            i += self.multiplicities[i]
        return out

    def count(self, kind: str) -> int:
        """How many modes (with multiplicity) are of ``kind``."""
        if kind not in KINDS:
            raise ElasticError(f"kind must be one of {', '.join(KINDS)}, got {kind!r}.")
        return sum(1 for k in self.kinds if k == kind)

    def _rows(self) -> tuple[list[str], list[list[str]]]:
        headers = ["mode", "f Hz", "type", "multiplicity", "most strain energy in"]
        rows, i = [], 0
        while i < len(self):
            shares = self.strain_energy[i]
            top = np.argsort(shares)[::-1][:2]
            where = ", ".join(f"{self.elements[k]} {shares[k]:.0%}" for k in top if shares[k] > 0.005) or "—"
            label = str(i + 1) if self.multiplicities[i] == 1 else f"{i + 1}-{i + self.multiplicities[i]}"
            rows.append([label, number(float(self.frequencies[i]), 6), self.kinds[i], str(self.multiplicities[i]),
                         where])
            i += self.multiplicities[i]
        return headers, rows

    def _title(self) -> str:
        return f"Natural frequencies of a {self.model.planets}-planet set ({len(self)} modes)"


    def __repr__(self) -> str:
        shown = ", ".join(f"{f:.5g} Hz {k} x{m}" for f, k, m in self.distinct()[:6])
        return f"NaturalModes({self.model.planets} planets: {shown}{', …' if len(self.distinct()) > 6 else ''})"

    def to_dict(self) -> dict[str, Any]:
        """JSON data: the model's inputs and, per mode, frequency (Hz), type, multiplicity, strain energy."""
        return {"model": self.model.to_dict(), "elements": list(self.elements),
                "modes": [{"frequency_Hz": float(f), "type": k, "multiplicity": m,
                           "strain_energy": {e: float(s) for e, s in zip(self.elements, row) if s > 0.0}}
                          for f, k, m, row in zip(self.frequencies, self.kinds, self.multiplicities,
                                                  self.strain_energy)]}


def _groups(omega: np.ndarray, rtol: float) -> list[list[int]]:
    scale = max(float(omega[-1]), 1.0)
    groups: list[list[int]] = []
    for i, w in enumerate(omega):
        if groups and abs(w - omega[groups[-1][0]]) <= rtol * max(w, 1e-3 * scale):
            groups[-1].append(i)
        else:
            groups.append([i])
    return groups


def natural_modes(model: PlanetaryLumpedModel, *, rtol: float = 1e-7) -> NaturalModes:
    """Natural frequencies, mode shapes, types and strain energies of ``model`` at rest.

    Parameters
    ----------
    model : PlanetaryLumpedModel
    rtol : float, default 1e-7
        Frequencies closer than ``rtol`` (relative) count as one repeated frequency.

    Returns
    -------
    NaturalModes

    Raises
    ------
    ElasticError
        A model that is not a :class:`PlanetaryLumpedModel`.

    References
    ----------
    Lin & Parker 1999, section 3 (mode types and multiplicities), Table 2.

    Examples
    --------
    >>> from epicyclic.elastic.lumped import Body, PlanetaryLumpedModel, equally_spaced
    >>> b = Body(1.0, 0.01, 0.1)
    >>> m = PlanetaryLumpedModel(b, b, b, Body(0.5, 0.002, 0.05), equally_spaced(4), 5e8, 5e8, 1e8,
    ...                          supports={"ring": (1e8, 1e6), "carrier": (1e8, 0.0), "sun": (1e8, 0.0)})
    >>> modes = natural_modes(m)
    >>> modes.count("rigid-body"), modes.count("translational"), modes.count("planet")
    (1, 12, 3)
    """
    if not isinstance(model, PlanetaryLumpedModel):
        raise ElasticError(f"natural_modes needs a PlanetaryLumpedModel, got {type(model).__name__}.")
    names, k, v = model.springs()
    m = model.mass_matrix()
    stiffness = (v.T * k) @ v
    eigenvalues, shapes = scipy.linalg.eigh(stiffness, m)
    top = max(float(eigenvalues[-1]), 1.0)
    eigenvalues = np.where(eigenvalues < 1e-10 * top, 0.0, eigenvalues)
    omega = np.sqrt(eigenvalues)
    elements = tuple(dict.fromkeys(names))
    member = np.array([elements.index(n) for n in names])
    energy = k[:, None] * (v @ shapes) ** 2              # springs × modes
    per_element = np.zeros((len(elements), len(omega)))
    np.add.at(per_element, member, energy)
    total = per_element.sum(axis=0)
    shares = np.divide(per_element, total, out=np.zeros_like(per_element), where=eigenvalues > 0.0).T
    kinds: list[str] = []
    multiplicities: list[int] = []
    for group in _groups(omega, rtol):
        kind = _kind(shapes[:, group], omega[group[0]] == 0.0, 1e-6)
        kinds += [kind] * len(group)
        multiplicities += [len(group)] * len(group)
    return NaturalModes(model, omega / (2.0 * math.pi), shapes, tuple(kinds), tuple(multiplicities), elements,
                        shares)


def frequencies_at_speeds(model: PlanetaryLumpedModel, carrier_speeds) -> np.ndarray:
    """Natural frequencies (Hz) at each carrier speed Ω, with gyroscopic and centripetal terms.

    Parameters
    ----------
    model : PlanetaryLumpedModel
    carrier_speeds : float or array_like
        Ω, rad/s (the speed of the frame the coordinates turn with).

    Returns
    -------
    ndarray
        Shape (speeds, 9 + 3N): ascending frequencies |Im λ|/2π of the first-order system
        [[0, I], [−M⁻¹(K − Ω² K_Ω), −Ω M⁻¹ G]] at each speed (a mode that has lost its
        stiffness to the centripetal term shows 0).

    Raises
    ------
    ElasticError
        A speed that is not finite or above 10⁶ rad/s.

    References
    ----------
    Cooley & Parker 2012, eq. (1) and section 3 (the eigenvalue problem at speed).

    Examples
    --------
    At rest the result is :func:`natural_modes`' frequencies:

    >>> from epicyclic.elastic.lumped import Body, PlanetaryLumpedModel, equally_spaced
    >>> b = Body(1.0, 0.01, 0.1)
    >>> m = PlanetaryLumpedModel(b, b, b, Body(0.5, 0.002, 0.05), equally_spaced(3), 5e8, 5e8, 1e8,
    ...                          supports={"ring": (1e8, 1e6), "carrier": (1e8, 0.0), "sun": (1e8, 0.0)})
    >>> bool(np.allclose(frequencies_at_speeds(m, 0.0)[0], natural_modes(m).frequencies, rtol=1e-8, atol=1e-6))
    True
    """
    speeds = np.atleast_1d(np.asarray(carrier_speeds, dtype=float))
    if speeds.ndim != 1 or not np.all(np.isfinite(speeds)) or np.any(np.abs(speeds) > 1e6):
        raise ElasticError("carrier_speeds must be finite speeds in rad/s below 1e6 (one list).")
    n = model.size
    m_inv = 1.0 / np.diag(model.mass_matrix())
    k = model.stiffness_matrix()
    k_omega = np.diag(model.centripetal_matrix())
    g = model.gyroscopic_matrix()
    a = np.zeros((len(speeds), 2 * n, 2 * n))
    a[:, :n, n:] = np.eye(n)
    a[:, n:, :n] = -m_inv[None, :, None] * (k[None] - speeds[:, None, None] ** 2 * np.diag(k_omega)[None])
    a[:, n:, n:] = -speeds[:, None, None] * (m_inv[:, None] * g)[None]
    lam = np.linalg.eigvals(a)
    freq = np.sort(np.abs(lam.imag), axis=1)[:, 1::2] / (2.0 * math.pi)  # each ±iω pair once
    top = np.max(freq, axis=1, keepdims=True)
    return np.where(freq < 1e-6 * np.maximum(top, 1.0), 0.0, freq)



def kinds_at_speed(model: PlanetaryLumpedModel, carrier_speed: float) -> tuple[tuple[float, ...], tuple[str, ...]]:
    """Natural frequencies (Hz) and mode types at the carrier speed Ω, from the gyroscopic eigenvectors.

    Cooley & Parker (2012) show that the rotational, translational and planet modes of equally spaced
    planets keep their structure at speed (the translational pairs split); each complex mode shape is
    classified by which central-member coordinates move, as :func:`natural_modes` does at rest.

    Parameters
    ----------
    model : PlanetaryLumpedModel
    carrier_speed : float
        Ω, rad/s.

    Returns
    -------
    tuple
        (ascending frequencies Hz, their types as :data:`KINDS`).

    References
    ----------
    Cooley & Parker 2012, section 4 (the mode types at speed).

    Examples
    --------
    >>> from epicyclic.elastic.lumped import Body, PlanetaryLumpedModel, equally_spaced
    >>> b = Body(1.0, 0.01, 0.1)
    >>> m = PlanetaryLumpedModel(b, b, b, Body(0.5, 0.002, 0.05), equally_spaced(4), 5e8, 5e8, 1e8,
    ...                          supports={"ring": (1e8, 1e6), "carrier": (1e8, 1e4), "sun": (1e8, 1e4)})
    >>> _, kinds = kinds_at_speed(m, 300.0)
    >>> kinds.count("rotational"), kinds.count("translational"), kinds.count("planet")
    (6, 12, 3)
    """
    speed = float(np.asarray(carrier_speed, dtype=float))
    if not math.isfinite(speed) or abs(speed) > 1e6:
        raise ElasticError(f"carrier_speed must be a finite speed in rad/s below 1e6, got {carrier_speed!r}.")
    n = model.size
    m_inv = 1.0 / np.diag(model.mass_matrix())
    a = np.zeros((2 * n, 2 * n))
    a[:n, n:] = np.eye(n)
    a[n:, :n] = -m_inv[:, None] * (model.stiffness_matrix() - speed ** 2 * model.centripetal_matrix())
    a[n:, n:] = -speed * (m_inv[:, None] * model.gyroscopic_matrix())
    lam, vec = np.linalg.eig(a)
    order = np.argsort(np.abs(lam.imag), kind="stable")[1::2]   # one of each ±iω pair, ascending
    freq = np.abs(lam.imag[order]) / (2.0 * math.pi)
    top = max(float(freq.max()), 1.0)
    kinds = []
    for f, k in zip(freq, order):
        shape = np.abs(vec[:n, k])[:, None]
        kinds.append(_kind(shape, f < 1e-6 * top, 1e-6))
    return tuple(float(f) if f >= 1e-6 * top else 0.0 for f in freq), tuple(kinds)
