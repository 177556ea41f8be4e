"""Mesh phasing of a planetary set: which mesh-frequency harmonics excite which modes (Parker & Lin 2004).

The sun–planet mesh of planet n goes through the same state as that of planet 1 a fraction
γ_sn = z_s ψ_n/2π (mod 1) of a mesh cycle later; the ring–planet meshes γ_rn = −z_r ψ_n/2π
(mod 1).  The l-th harmonic of the mesh forces acts on the set with the net weights

* rotational (torque on the central members): W₀ = (1/N) Σ_n e^{−2πi l γ_sn},
* translational (net force, the two senses of a rotating force): W± = (1/N) Σ_n e^{−2πi l γ_sn} e^{±iψ_n},

and what remains excites the planet modes.  For equally spaced planets this gives the rules of
Parker & Lin (2004): harmonic l excites only rotational modes where l z_s/N is an integer, only
translational modes where (l z_s ± 1)/N is an integer, and only planet modes otherwise.

References
----------
R. G. Parker, J. Lin, "Mesh phasing relationships in planetary and epicyclic gears", J. Mech.
Des. 126 (2004) 365–370, eqs. (14)–(15) (mesh phases) and Table 1 (the excitation rules);
R. G. Parker, "A physical explanation for the effectiveness of planet phasing to suppress
planetary gear vibration", J. Sound Vib. 236 (2000) 561–573.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from ._render import grid, html_table, markdown
from .errors import ElasticError, finite

__all__ = ["MeshPhasing", "mesh_phasing"]

_TOL = 1e-9


def _teeth(value: object, key: str) -> int:
    if isinstance(value, bool) or not isinstance(value, int) or value < 1:
        raise ElasticError(f"{key} must be a whole number of teeth >= 1, got {value!r}.")
    return value


@dataclass(frozen=True)
class MeshPhasing:
    """Mesh phases of a set and the mode types each mesh harmonic excites.

    Attributes
    ----------
    sun_teeth, ring_teeth : int
    planet_angles : tuple of float
        ψ_n, rad.
    sun_phases, ring_phases : tuple of float
        γ_sn, γ_rn in [0, 1): fractions of a mesh cycle.
    """

    sun_teeth: int
    ring_teeth: int
    planet_angles: tuple[float, ...]
    sun_phases: tuple[float, ...]
    ring_phases: tuple[float, ...]

    @property
    def planets(self) -> int:
        """N."""
        return len(self.planet_angles)

    @property
    def equally_spaced(self) -> bool:
        """Whether the planets stand 2π/N apart."""
        psi = np.asarray(self.planet_angles) - self.planet_angles[0]
        ideal = 2 * np.pi * np.arange(self.planets) / self.planets
        return bool(np.all(np.abs(np.angle(np.exp(1j * (psi - ideal)))) < 1e-9))

    def weights(self, harmonic: int, mesh: str = "sun") -> dict[str, float]:
        """|W₀|, |W₊|, |W₋| of harmonic l (module docstring), each 0 … 1.

        Parameters
        ----------
        harmonic : int
            l ≥ 1.
        mesh : {"sun", "ring"}, default "sun"
            The phases of the sun–planet or of the ring–planet meshes (the same rules for a simple
            set that assembles; a stepped set's ring meshes have their own frequency).

        Returns
        -------
        dict
            ``rotational``, ``translational+``, ``translational-`` and ``planet`` (the
            rest: √(1 − Σ |W|²) for equally spaced planets, the part of the unit phasors
            outside the rotational and translational patterns).
        """
        l_ = _teeth(harmonic, "harmonic")
        if mesh not in ("sun", "ring"):
            raise ElasticError(f"mesh must be 'sun' or 'ring', got {mesh!r}.")
        psi = np.asarray(self.planet_angles)
        phases = self.sun_phases if mesh == "sun" else self.ring_phases
        phasor = np.exp(-2j * np.pi * l_ * np.asarray(phases))
        n = self.planets
        w0 = abs(phasor.sum()) / n
        wp = abs((phasor * np.exp(1j * psi)).sum()) / n
        wm = abs((phasor * np.exp(-1j * psi)).sum()) / n
        # the projection of the phasors onto the span of 1, e^{iψ}, e^{−iψ} (orthogonal for equal spacing)
        basis = np.stack([np.ones(n), np.exp(1j * psi), np.exp(-1j * psi)], axis=1)
        coef, *_ = np.linalg.lstsq(basis, phasor, rcond=None)
        rest = float(np.linalg.norm(phasor - basis @ coef)) / math.sqrt(n)
        clean = lambda x: 0.0 if x < _TOL else float(x)  # noqa: E731
        return {"rotational": clean(w0), "translational+": clean(wp), "translational-": clean(wm),
                "planet": clean(rest)}

    def excited(self, harmonic: int, mesh: str = "sun") -> tuple[str, ...]:
        """The mode types harmonic l of the ``mesh`` (sun or ring) meshes excites.

        Parameters
        ----------
        harmonic : int
            l ≥ 1.
        mesh : {"sun", "ring"}, default "sun"

        Returns
        -------
        tuple of str
            Some of ``rotational``, ``translational``, ``planet`` (empty: the harmonic cancels).
        """
        w = self.weights(harmonic, mesh)
        out = []
        if w["rotational"] > 0.0:
            out.append("rotational")
        if w["translational+"] > 0.0 or w["translational-"] > 0.0:
            out.append("translational")
        if w["planet"] > 0.0:
            out.append("planet")
        return tuple(out)

    def _rows(self, harmonics: int) -> tuple[list[str], list[list[str]]]:
        headers = ["harmonic", "rotational", "translational", "planet", "excites"]
        rows = []
        for l_ in range(1, harmonics + 1):
            w = self.weights(l_)
            rows.append([str(l_), f"{w['rotational']:.3f}", f"{max(w['translational+'], w['translational-']):.3f}",
                         f"{w['planet']:.3f}", ", ".join(self.excited(l_)) or "nothing"])
        return headers, rows

    def _title(self) -> str:
        spacing = "equally spaced" if self.equally_spaced else "unequally spaced"
        return f"Mesh phasing: z_s {self.sun_teeth}, z_r {self.ring_teeth}, {self.planets} planets {spacing}"

    def table(self, harmonics: int = 6) -> str:
        """Weights and excited mode types of the first ``harmonics`` mesh harmonics."""
        return grid(*self._rows(harmonics), title=self._title())

    def markdown(self, harmonics: int = 6) -> str:
        """:meth:`table` as Markdown."""
        return markdown(*self._rows(harmonics), title=self._title())

    def _repr_html_(self) -> str:
        return html_table(*self._rows(6), title=self._title())

    def __repr__(self) -> str:
        return (f"MeshPhasing(z_s {self.sun_teeth}, z_r {self.ring_teeth}, {self.planets} planets: "
                + "; ".join(f"{l_}: {'/'.join(self.excited(l_)) or 'nothing'}" for l_ in range(1, 4)) + ")")

    def to_dict(self, harmonics: int = 6) -> dict[str, Any]:
        """JSON data: tooth counts, planet angles (deg), phases and per harmonic weights and excited types."""
        return {"sun_teeth": self.sun_teeth, "ring_teeth": self.ring_teeth,
                "planet_angles_deg": [math.degrees(a) for a in self.planet_angles],
                "equally_spaced": self.equally_spaced,
                "sun_phases": list(self.sun_phases), "ring_phases": list(self.ring_phases),
                "harmonics": [{"harmonic": l_, "weights": self.weights(l_), "excites": list(self.excited(l_))}
                              for l_ in range(1, harmonics + 1)]}


def mesh_phasing(sun_teeth: int, ring_teeth: int, planet_angles) -> MeshPhasing:
    """Mesh phases γ_sn = z_s ψ_n/2π, γ_rn = −z_r ψ_n/2π (mod 1) of a set.

    Parameters
    ----------
    sun_teeth, ring_teeth : int
        z_s, z_r.
    planet_angles : sequence of float
        ψ_n, rad (the first planet is the reference).

    Returns
    -------
    MeshPhasing

    Raises
    ------
    ElasticError
        Tooth counts that are not whole numbers ≥ 1, no planet, a non-finite angle.

    References
    ----------
    Parker & Lin 2004, eqs. (14)–(15) and Table 1.

    Examples
    --------
    Equally spaced planets: z_s = 30 with 5 planets, 30/5 integer: the first harmonic is a pure torque:

    >>> from epicyclic.elastic.lumped import equally_spaced
    >>> mesh_phasing(30, 70, equally_spaced(5)).excited(1)
    ('rotational',)
    >>> mesh_phasing(31, 69, equally_spaced(5)).excited(1)   # (31 - 1)/5 integer
    ('translational',)
    >>> mesh_phasing(32, 68, equally_spaced(5)).excited(1)
    ('planet',)
    """
    z_s, z_r = _teeth(sun_teeth, "sun_teeth"), _teeth(ring_teeth, "ring_teeth")
    angles = tuple(finite(a, "planet_angles") for a in planet_angles)
    if not angles:
        raise ElasticError("planet_angles: give at least one planet angle.")
    psi = np.asarray(angles) - angles[0]
    frac = lambda x: tuple(float(v) for v in np.mod(np.round(x, 12), 1.0))  # noqa: E731
    return MeshPhasing(z_s, z_r, angles, frac(z_s * psi / (2 * np.pi)), frac(-z_r * psi / (2 * np.pi)))
