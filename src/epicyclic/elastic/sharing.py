"""Static load sharing among the planets: mesh loads from manufacturing errors, K_γ (one-sided contact).

The static part of the lumped model (:mod:`~epicyclic.elastic.lumped`) with the sun driven by a
torque T > 0, the ring and the carrier held in rotation (the reactions), every member held in
translation by its support stiffness (0 = floating) and each planet by its bearing and pin
(k_p, a flexible pin is a low k_p).  Errors, in micrometres:

* pin position errors e_r,n (radial) and e_t,n (tangential; a carrier pitch error) shift the rest
  position of the planet bearing springs;
* a planet tooth thickness deviation Δs_n (+ thicker) closes both meshes of the planet by
  Δs_n/2 · cos α (the flank moves Δs/2 along the pitch circle);
* a run-out (eccentricity) e of the sun or ring toothing at the angle φ in the carrier frame
  closes mesh n by e sin(φ − ψ_sn) (ψ_rn for the ring).

Tooth contacts carry load only in compression (k max(δ, 0)), so the load shares follow from a
complementarity problem, solved with :func:`~epicyclic.elastic.contact.solve_contact`.  The
load-sharing factor is K_γ = max_n F_n / mean F_n of the sun-mesh forces F_n (equal to the
ring-mesh forces, a planet turns freely on its pin; ρ times them for a stepped planet).  Without errors and with equally spaced
planets the set is solved in its symmetric subspace, so every planet's share is the same number.

References
----------
A. Kahraman, "Load sharing characteristics of planetary transmissions", Mech. Mach. Theory 29
(1994) 1151–1165 (pin position errors, floating sun, three planets share equally);
A. Singh, Mech. Mach. Theory 45 (2010) 511–530 (one-sided contact, K_γ falls as the load grows);
J. Lin, R. G. Parker, J. Vib. Acoust. 121 (1999) 316–321 (the model).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .contact import solve_contact
from .errors import ElasticError, finite, non_negative
from .lumped import PlanetaryLumpedModel
from .sharing_results import PlanetLoads, SharingStudy

__all__ = ["PlanetErrors", "Tolerances", "load_sharing", "sharing_over_torque", "sharing_over_revolution",
           "monte_carlo_sharing"]

_KEEP_DROP = (2, 5)  # carrier and ring rotation: held (the reactions)
_UM = 1e-6


def _per_planet(values, n: int, key: str) -> tuple[float, ...]:
    if values is None:
        return (0.0,) * n
    values = tuple(values)
    if len(values) != n:
        raise ElasticError(f"{key}: give one value per planet ({n}), got {len(values)}.")
    return tuple(finite(v, key) for v in values)


@dataclass(frozen=True)
class PlanetErrors:
    """Manufacturing errors of a set, µm (one value per planet where a tuple).

    Attributes
    ----------
    pin_radial, pin_tangential : tuple of float
        Pin position errors e_r,n (outward +), e_t,n (in the sense of ψ +).
    tooth_thickness : tuple of float
        Planet tooth thickness deviations Δs_n (thicker +).
    sun_runout, ring_runout : float
        Eccentricity of the toothing, µm (≥ 0).
    sun_runout_angle, ring_runout_angle : float
        Its direction in the carrier frame, degrees.
    """

    pin_radial: tuple[float, ...] | None = None
    pin_tangential: tuple[float, ...] | None = None
    tooth_thickness: tuple[float, ...] | None = None
    sun_runout: float = 0.0
    sun_runout_angle: float = 0.0
    ring_runout: float = 0.0
    ring_runout_angle: float = 0.0

    def __post_init__(self) -> None:
        for key in ("pin_radial", "pin_tangential", "tooth_thickness"):
            value = getattr(self, key)
            if value is not None:
                object.__setattr__(self, key, tuple(finite(v, key) for v in value))
        for key in ("sun_runout", "ring_runout"):
            object.__setattr__(self, key, non_negative(getattr(self, key), key))
        for key in ("sun_runout_angle", "ring_runout_angle"):
            object.__setattr__(self, key, finite(getattr(self, key), key))

    def arrays(self, n: int) -> dict[str, np.ndarray]:
        """The errors as arrays of one case (shape (1, n) or (1,)), µm and degrees."""
        return {"pin_radial": np.array([_per_planet(self.pin_radial, n, "pin_radial")]),
                "pin_tangential": np.array([_per_planet(self.pin_tangential, n, "pin_tangential")]),
                "tooth_thickness": np.array([_per_planet(self.tooth_thickness, n, "tooth_thickness")]),
                "sun_runout": np.array([self.sun_runout]), "sun_runout_angle": np.array([self.sun_runout_angle]),
                "ring_runout": np.array([self.ring_runout]), "ring_runout_angle": np.array([self.ring_runout_angle])}

    def is_zero(self) -> bool:
        """Whether there is no error at all."""
        return all(not any(v or ()) for v in (self.pin_radial, self.pin_tangential, self.tooth_thickness)) \
            and self.sun_runout == 0.0 and self.ring_runout == 0.0


@dataclass(frozen=True)
class Tolerances:
    """Tolerances of a set for Monte-Carlo draws, µm: each error uniform within them.

    Attributes
    ----------
    pin_position : float
        Radial and tangential pin position errors each uniform in ± this.
    tooth_thickness : float
        Planet tooth thickness deviation uniform in ± this.
    sun_runout, ring_runout : float
        Eccentricity uniform in [0, this] at a uniform angle.
    """

    pin_position: float = 0.0
    tooth_thickness: float = 0.0
    sun_runout: float = 0.0
    ring_runout: float = 0.0

    def __post_init__(self) -> None:
        for key in ("pin_position", "tooth_thickness", "sun_runout", "ring_runout"):
            object.__setattr__(self, key, non_negative(getattr(self, key), key))

    def draw(self, n: int, draws: int, rng: np.random.Generator) -> dict[str, np.ndarray]:
        """``draws`` cases of errors for ``n`` planets.

        Parameters
        ----------
        n : int
            Planets.
        draws : int
            Cases.
        rng : numpy.random.Generator
            The source of the draws.

        Returns
        -------
        dict
            Arrays as :meth:`PlanetErrors.arrays`, one row per draw.
        """
        u = lambda tol, shape: rng.uniform(-tol, tol, shape) if tol else np.zeros(shape)  # noqa: E731
        return {"pin_radial": u(self.pin_position, (draws, n)), "pin_tangential": u(self.pin_position, (draws, n)),
                "tooth_thickness": u(self.tooth_thickness, (draws, n)),
                "sun_runout": rng.uniform(0.0, self.sun_runout, draws) if self.sun_runout else np.zeros(draws),
                "sun_runout_angle": rng.uniform(0.0, 360.0, draws),
                "ring_runout": rng.uniform(0.0, self.ring_runout, draws) if self.ring_runout else np.zeros(draws),
                "ring_runout_angle": rng.uniform(0.0, 360.0, draws)}


def _static(model: PlanetaryLumpedModel):
    """The static springs with the held rotations (carrier, ring) and the free planet rotations eliminated.

    A planet turning freely on its pin carries F_s = ρ F_r (the same force in both meshes for a
    simple planet, ρ = 1): minimising the energy over u_n joins them into one contact of stiffness
    k_s k_r/(k_s + ρ² k_r) along ρ w_s + w_r (u_n cancels) with gap ρ g_s + g_r, carrying F_r.
    """
    if not isinstance(model, PlanetaryLumpedModel):
        raise ElasticError(f"load sharing needs a PlanetaryLumpedModel, got {type(model).__name__}.")
    if model.size != 9 + 3 * model.planets:
        raise ElasticError("load sharing is modelled for simple and stepped planets; a double-planet set is not "
                           "(its modes are: natural_modes).")
    names, k, v = model.springs()
    n = model.planets
    drop = set(_KEEP_DROP) | {11 + 3 * i for i in range(n)}
    keep = [i for i in range(model.size) if i not in drop]
    linear = [i for i, nm in enumerate(names) if nm.startswith(("bearing", "support"))]
    sun = [names.index(f"sun-planet {i + 1}") for i in range(n)]
    ring = [names.index(f"ring-planet {i + 1}") for i in range(n)]
    rho = model.step_ratio                            # a stepped planet: F_s r_p,sun = F_r r_p,ring
    w = rho * v[sun] + v[ring]
    k_pair = k[sun] * k[ring] / (k[sun] + rho * rho * k[ring])
    return names, k[linear], v[linear][:, keep], [names[i] for i in linear], k_pair, w[:, keep], keep


def _solve(model: PlanetaryLumpedModel, torque: np.ndarray, err: dict[str, np.ndarray]):
    """Sun-mesh and ring-mesh forces (B, N) of every case (the same: a planet turns freely)."""
    _, k_lin, v_lin, lin_names, k_pair, w, keep = _static(model)
    n, cases = model.planets, len(torque)
    psi = np.asarray(model.planet_angles)
    e_lin = np.zeros((cases, len(lin_names)))
    for i in range(n):
        radial, tangential = (j for j, nm in enumerate(lin_names) if nm == f"bearing planet {i + 1}")
        e_lin[:, radial] = err["pin_radial"][:, i] * _UM
        e_lin[:, tangential] = err["pin_tangential"][:, i] * _UM
    a_s, a_r = model.sun_pressure_angle, model.ring_pressure_angle
    phi_s = np.radians(err["sun_runout_angle"])[:, None]
    phi_r = np.radians(err["ring_runout_angle"])[:, None]
    close_s = err["tooth_thickness"] / 2 * math.cos(a_s) + err["sun_runout"][:, None] * np.sin(phi_s - (psi - a_s))
    close_r = err["tooth_thickness"] / 2 * math.cos(a_r) + err["ring_runout"][:, None] * np.sin(phi_r - (psi + a_r))
    rho = model.step_ratio
    g = -(rho * close_s + close_r) * _UM
    f = np.zeros((cases, len(keep)))
    f[:, keep.index(8)] = torque / model.sun.radius
    _, deflection = solve_contact(k_lin, v_lin, e_lin, k_pair, w, g, f)
    ring = k_pair * np.maximum(deflection, 0.0)
    return rho * ring, ring


def _symmetric(model: PlanetaryLumpedModel, torque: float):
    """Forces of an error-free, equally spaced set from its symmetric subspace (the same number per planet)."""
    _, k_lin, v_lin, _, k_pair, w, keep = _static(model)
    n = model.planets
    basis = np.zeros((len(keep), 3))                 # u_s, and ξ, η alike on every planet
    basis[keep.index(8), 0] = 1.0
    for i in range(n):
        p = keep.index(9 + 3 * i)
        basis[p:p + 2, 1:] += np.eye(2)
    lin, con = v_lin @ basis, w @ basis
    a = (lin.T * k_lin) @ lin + (con.T * k_pair) @ con
    rhs = np.array([torque / model.sun.radius, 0.0, 0.0])
    q_r = np.linalg.solve(a, rhs)
    deflection = (con * q_r).sum(axis=1)             # rows alike for every planet: the same sum
    if np.any(deflection <= 0.0):
        raise ElasticError("load sharing: a mesh opens under the torque; the sun torque must drive the set (> 0).")
    ring = (k_pair * deflection)[None]
    return model.step_ratio * ring, ring


def _repeat(errors: PlanetErrors, planets: int, cases: int) -> dict[str, np.ndarray]:
    if not isinstance(errors, PlanetErrors):
        raise ElasticError(f"errors must be PlanetErrors, got {type(errors).__name__}.")
    return {key: np.repeat(value, cases, axis=0) for key, value in errors.arrays(planets).items()}


def _torques(values) -> np.ndarray:
    t = np.atleast_1d(np.asarray(values, dtype=float))
    if t.ndim != 1 or not np.all(np.isfinite(t)) or np.any(t <= 0.0) or len(t) > 1_000_000:
        raise ElasticError("torque must be finite sun torques > 0 in N m (the sun drives; at most 1e6 cases).")
    return t


def load_sharing(model: PlanetaryLumpedModel, torque: float, errors: PlanetErrors | None = None) -> PlanetLoads:
    """Mesh load of every planet and K_γ of ``model`` under the sun torque ``torque`` (N m).

    Parameters
    ----------
    model : PlanetaryLumpedModel
    torque : float
        Sun torque, N m (> 0).
    errors : PlanetErrors, optional
        None: an error-free set.

    Returns
    -------
    PlanetLoads

    Raises
    ------
    ElasticError
        A torque ≤ 0, errors of the wrong length, no equilibrium.

    References
    ----------
    Kahraman 1994; Singh 2010 (module docstring).

    Examples
    --------
    >>> from epicyclic.elastic.lumped import Body, PlanetaryLumpedModel, equally_spaced
    >>> b = Body(1.0, 0.01, 0.05)
    >>> m = PlanetaryLumpedModel(b, Body(1.0, 0.01, 0.15), b, Body(0.5, 0.002, 0.05), equally_spaced(4),
    ...                          5e8, 5e8, 1e8, supports={"carrier": (1e9, 0), "ring": (1e9, 0), "sun": (1e9, 0)})
    >>> load_sharing(m, 500.0).k_gamma
    1.0
    >>> round(load_sharing(m, 500.0, PlanetErrors(pin_tangential=(20, 0, 0, 0))).k_gamma, 3)
    1.096
    """
    t = float(_torques(torque)[0])
    errors = errors or PlanetErrors()
    if not isinstance(errors, PlanetErrors):
        raise ElasticError(f"errors must be PlanetErrors, got {type(errors).__name__}.")
    err = errors.arrays(model.planets)
    if errors.is_zero() and model.equally_spaced():
        sun, ring = _symmetric(model, t)
    else:
        sun, ring = _solve(model, np.array([t]), err)
    return PlanetLoads(model.planets, t, model.sun.radius, sun[0], ring[0], errors)


def sharing_over_torque(model: PlanetaryLumpedModel, torques, errors: PlanetErrors) -> SharingStudy:
    """K_γ and the planet loads over sun torques (N m), the errors fixed.

    Parameters
    ----------
    model : PlanetaryLumpedModel
    torques : array_like
        Sun torques > 0, N m.
    errors : PlanetErrors

    Returns
    -------
    SharingStudy

    References
    ----------
    Singh 2010 (K_γ falls towards 1 as the load grows: the errors matter less against the deflections).
    """
    t = _torques(torques)
    err = _repeat(errors, model.planets, len(t))
    sun, ring = _solve(model, t, err)
    return SharingStudy("sun torque", "N m", t, sun, ring, t / model.sun.radius)


def sharing_over_revolution(model: PlanetaryLumpedModel, torque: float, errors: PlanetErrors, angles,
                            *, sun_turns: float, ring_turns: float) -> SharingStudy:
    """Planet loads over carrier angles: the run-outs of sun and ring turn against the carrier.

    Parameters
    ----------
    model : PlanetaryLumpedModel
    torque : float
        Sun torque > 0, N m.
    errors : PlanetErrors
        The run-out angles are those at carrier angle 0.
    angles : array_like
        Carrier angles, degrees.
    sun_turns, ring_turns : float
        Turns of sun and ring relative to the carrier per carrier turn, (n_s − n_c)/n_c and
        (n_r − n_c)/n_c (ring fixed: z_r/z_s and −1).

    Returns
    -------
    SharingStudy

    References
    ----------
    Kahraman 1994 (load sharing over a carrier revolution with run-out errors).
    """
    t = float(_torques(torque)[0])
    theta = np.atleast_1d(np.asarray(angles, dtype=float))
    if theta.ndim != 1 or not np.all(np.isfinite(theta)) or len(theta) > 1_000_000:
        raise ElasticError("angles must be finite carrier angles in degrees (at most 1e6).")
    s_turns, r_turns = finite(sun_turns, "sun_turns"), finite(ring_turns, "ring_turns")
    err = _repeat(errors, model.planets, len(theta))
    err["sun_runout_angle"] = err["sun_runout_angle"] + s_turns * theta
    err["ring_runout_angle"] = err["ring_runout_angle"] + r_turns * theta
    sun, ring = _solve(model, np.full(len(theta), t), err)
    return SharingStudy("carrier angle", "deg", theta, sun, ring, np.full(len(theta), t / model.sun.radius))


def monte_carlo_sharing(model: PlanetaryLumpedModel, torque: float, tolerances: Tolerances, draws: int = 10_000,
                        seed: int = 0) -> SharingStudy:
    """K_γ over ``draws`` sets with errors drawn uniformly within ``tolerances`` (numpy PCG64, ``seed``).

    Parameters
    ----------
    model : PlanetaryLumpedModel
    torque : float
        Sun torque > 0, N m.
    tolerances : Tolerances
    draws : int, default 10000
        1 … 1 000 000.
    seed : int, default 0
        Seed of ``numpy.random.default_rng`` (stated in the result).

    Returns
    -------
    SharingStudy
        With ``seed`` and the 95th percentile of K_γ (:meth:`SharingStudy.percentile`).

    References
    ----------
    Kahraman 1994; Singh 2010.
    """
    t = float(_torques(torque)[0])
    if not isinstance(tolerances, Tolerances):
        raise ElasticError(f"tolerances must be Tolerances, got {type(tolerances).__name__}.")
    if isinstance(draws, bool) or not isinstance(draws, int) or not 1 <= draws <= 1_000_000:
        raise ElasticError(f"draws must be a whole number 1 ... 1000000, got {draws!r}.")
    if isinstance(seed, bool) or not isinstance(seed, int) or seed < 0:
        raise ElasticError(f"seed must be a whole number >= 0, got {seed!r}.")
    err = tolerances.draw(model.planets, draws, np.random.default_rng(seed))
    sun, ring = _solve(model, np.full(draws, t), err)
    return SharingStudy("draw", "", np.arange(1.0, draws + 1), sun, ring, np.full(draws, t / model.sun.radius),
                        seed=seed, tolerances=tolerances)

