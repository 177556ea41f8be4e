"""Tooth flank fracture of one mesh: the material exposure along the depth and the hardened layer.

:func:`rate_flank_fracture` follows the structure of ISO/TS 6336-4:2019 — at each contact point
CP of the path of contact, the local Hertzian pressure p_dyn,CP (with K_A K_γ K_v K_Hβ K_Hα), the
radius of relative curvature ρ_red,CP and the half width b_H,CP = 4 ρ_red p_dyn / E_r; below it,
at the depth y, the local stress τ_eff,CP(y), the local permissible stress from the hardness
τ_per(y) = K_τ,per HV(y) and the material exposure (clause 5.3)::

    A_FF,CP(y) = τ_eff,CP(y) / τ_per(y) + c_1,        A_FF,max = max over CP and y   (clause 5.2)

and this package's safety S_FF = 1 / A_FF,max against S_FFmin.  What differs from the TS, because
its text was not reachable (see ``docs/rating.md``):

* τ_eff,CP(y) is the principal shear stress τ_1 below the centre of the Hertzian line contact
  (Johnson 1985, §4.6: 0.300 p_dyn at 0.786 b_H), not the TS's fitted local equivalent stress
  (clause 6.2); friction is not included;
* quasi-stationary residual stresses (clause 6.3) are not taken into account (the compressive
  residual stress of the case and the tensile one of the core both are left out);
* K_τ,per and c_1 default to stated assumptions (:mod:`.spec`); the hardness profile is measured or
  the assumed curve of :mod:`.hardness`.

The hardened-layer check gives, per gear, the required case hardness depth CHD_req: the smallest
CHD (the profile stretched along the depth, surface and core hardness kept) at which A_FF,max =
1/S_FFmin, searched between 0.05 and 10 mm (scipy's brentq; A_FF,max falls as the case deepens).

References
----------
ISO/TS 6336-4:2019, clauses 1 (scope), 5.2, 5.3, 6.2 (the material strength: its clause not located); K. L. Johnson, Contact Mechanics, CUP
1985, §4.6; I. Boiadjiev, J. Witzig, T. Tobie, K. Stahl, "Tooth flank fracture — basic principles
and calculation model for a sub-surface-initiated fatigue failure mode of case-hardened gears",
Gear Technology, August 2015; ISO 2639:2002.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq

from ..contact_path import contact_path
from ..errors import RatingError, warn_validity
from ..lubricant_film import reduced_modulus
from ..mode_results import ModeRating
from ..results import Factor
from .hardness import HardnessProfile
from .spec import FlankFractureSpec
from .subsurface import half_width, principal_shear

__all__ = ["CHD_BOUNDS", "material_exposure", "rate_flank_fracture", "required_case_depth"]

TS = "ISO/TS 6336-4:2019"
CHD_BOUNDS = (0.05, 10.0)
"""The search interval of the required case hardness depth, mm."""


def material_exposure(depth, pressure, b, hardness, K_tau_per: float, c_1: float = 0.0):
    """(A_FF, τ_eff) at ``depth`` (m,) below contact points of pressure and half width (..., n).

    Parameters
    ----------
    depth : ndarray
        y, mm (1-d).
    pressure, b : ndarray
        p_dyn (N/mm²) and b_H (mm) of the contact points; b = 0 where a point carries no load.
    hardness : ndarray
        HV at ``depth``.
    K_tau_per : float
        N/mm² per HV.
    c_1 : float, default 0
        Calibration constant.

    Returns
    -------
    (ndarray, ndarray)
        Both of shape ``pressure.shape + depth.shape``.

    References
    ----------
    ISO/TS 6336-4:2019, 5.3 (A_FF,CP(y)); Johnson 1985, §4.6 (τ_1).
    """
    p = np.asarray(pressure, dtype=float)[..., None]
    b = np.asarray(b, dtype=float)[..., None]
    loaded = b > 0
    tau = np.where(loaded, principal_shear(depth, p, np.where(loaded, b, 1.0)), 0.0)
    return tau / (K_tau_per * np.asarray(hardness, dtype=float)) + c_1, tau


def _grid(b_max: float, chd: float, n: int) -> np.ndarray:
    return np.linspace(0.0, max(4.0 * b_max, 3.0 * chd), n)


def _max_exposure(profile: HardnessProfile, chd: float, p, b, spec: FlankFractureSpec) -> float:
    y = _grid(float(np.max(b)), chd, spec.depth_points)
    a, _ = material_exposure(y, p, b, profile(y, case_depth=chd), spec.K_tau_per, spec.calibration_factor)
    return float(np.max(a))


def required_case_depth(profile: HardnessProfile, pressure, b, spec: FlankFractureSpec) -> float:
    """CHD_req: the smallest CHD (mm) at which A_FF,max = 1/S_FFmin for one load case (inf: none ≤ 10 mm).

    Parameters
    ----------
    profile : HardnessProfile
        Stretched along the depth to each trial CHD.
    pressure, b : ndarray
        p_dyn and b_H of the contact points of the case, shape (n,).
    spec : FlankFractureSpec

    Returns
    -------
    float
        :data:`CHD_BOUNDS` [0] where even that meets the limit; ``inf`` where 10 mm does not.

    References
    ----------
    ISO/TS 6336-4:2019, 5.2; ISO 2639:2002.
    """
    target = 1.0 / spec.S_FFmin
    lo, hi = CHD_BOUNDS

    def excess(chd):
        return _max_exposure(profile, chd, pressure, b, spec) - target
    if excess(hi) > 0:
        return math.inf
    if excess(lo) <= 0:
        return lo
    return float(brentq(excess, lo, hi, xtol=1e-4))


def _validity(inp, mats, p_max, rho, profiles) -> None:
    where = f"{inp.element} {inp.mesh.name}"
    clause = f"{TS}, clause 1"
    for name, mat in zip(inp.gears, mats):
        if mat.treatment != "Eh":
            warn_validity(f"{where}: {name} ({mat.name}, {mat.treatment}) is not case-carburised; the method is "
                          "written for case-carburised gears (rated with the same formulas)", clause)
    lo, hi = float(np.min(p_max)), float(np.max(p_max))
    if lo < 500.0 or hi > 3000.0:
        warn_validity(f"{where}: p_dyn,max {lo:.0f} ... {hi:.0f} N/mm^2 outside 500 ... 3000 N/mm^2", clause)
    if float(np.min(rho)) < 5.0 or float(np.max(rho)) > 150.0:
        warn_validity(f"{where}: rho_red {float(np.min(rho)):.3g} ... {float(np.max(rho)):.3g} mm outside "
                      "5 ... 150 mm", clause)
    for name, prof in zip(inp.gears, profiles):
        if not 0.3 <= prof.case_depth <= 4.5:
            warn_validity(f"{where}: {name} CHD {prof.case_depth:g} mm outside 0.3 ... 4.5 mm", clause)


def rate_flank_fracture(inp, rating, torque, speed, spec: FlankFractureSpec | None = None) -> ModeRating:
    """A_FF,max, S_FF and CHD_req of both gears of one mesh at the load of ``rating``.

    Parameters
    ----------
    inp : MeshInput
    rating : MeshRating
        The ISO 6336 rating of the same load (F_t and the load factors are used).
    torque, speed : float or array_like
        As given to :func:`~epicyclic.rating.mesh_rating.rate_mesh` (one per load case).
    spec : FlankFractureSpec, optional
        Default ``inp.spec.flank_fracture``.

    Returns
    -------
    ModeRating
        ``mode = "flank_fracture"``, safety ``S_FF`` per gear.

    Raises
    ------
    RatingError
        No inputs, a gear without case depth or hardness.

    References
    ----------
    ISO/TS 6336-4:2019, clauses 5.2, 5.3, 6.2; Johnson 1985, §4.6.
    """
    spec = spec if spec is not None else getattr(inp.spec, "flank_fracture", None)
    if spec is None:
        raise RatingError("flank fracture: give the [rating.flank_fracture] table (case_depth, surface_hardness, "
                          "core_hardness or hardness_profile).")
    mats = inp.static["materials"]
    profiles = [spec.profile_of(inp.element, name) for name in inp.gears]
    e_r = reduced_modulus(mats[0].E, mats[0].poisson, mats[1].E, mats[1].poisson)
    path = contact_path(inp.mesh, inp.face_width, accuracy_grade=inp.spec.accuracy_grade)
    gammas = path.gammas(spec.points)
    load = rating["K_A"] * rating["K_gamma"] * np.asarray(rating["K_v"]) * np.asarray(rating["K_Hbeta"]) * \
        np.asarray(rating["K_Halpha"])
    state = path.state(gammas, speed, rating["F_t"], math.sqrt(e_r / (2.0 * math.pi)), load_factor=load)
    p = np.asarray(state.p_H, dtype=float)
    rho = np.broadcast_to(np.asarray(state.rho_rel, dtype=float), p.shape)
    b = half_width(p, rho, e_r)
    cases = p.reshape(-1, p.shape[-1]), b.reshape(-1, b.shape[-1])
    p_max = np.max(cases[0], axis=-1)
    _validity(inp, mats, p_max, state.rho_rel, profiles)
    shape = p.shape[:-1]
    gear_factors, curves, worst = [], {}, (-1.0, None)
    for name, prof in zip(inp.gears, profiles):
        y = _grid(float(np.max(b)), prof.case_depth, spec.depth_points)
        hv = prof(y)
        a, tau = material_exposure(y, p, b, hv, spec.K_tau_per, spec.calibration_factor)
        flat = a.reshape(-1, a.shape[-2] * a.shape[-1])
        at = np.argmax(flat, axis=-1)
        a_max = flat[np.arange(flat.shape[0]), at]
        cp, depth = np.unravel_index(at, a.shape[-2:])
        req = np.array([required_case_depth(prof, pc, bc, spec) for pc, bc in zip(*cases)])
        k = int(np.argmax(a_max))
        if a_max[k] > worst[0]:
            worst = (float(a_max[k]), k)
        curves[name] = {"y": y, "HV": hv, "tau_per": spec.K_tau_per * hv,
                        "tau_eff": tau.reshape(-1, *a.shape[-2:])[k, cp[k]],
                        "A_FF": a.reshape(-1, *a.shape[-2:])[k, cp[k]]}

        def per_case(values):
            v = np.asarray(values, dtype=float).reshape(shape)
            return float(v) if v.ndim == 0 else v
        src = f"{prof.source} profile"
        gear_factors.append({
            "HV_surface": Factor("HV_surface", prof.surface, "HV", src, "surface hardness"),
            "HV_core": Factor("HV_core", prof.core, "HV", src, "core hardness"),
            "CHD": Factor("CHD", prof.case_depth, "mm", "ISO 2639:2002 (550 HV)", "case hardness depth"),
            "A_FF_max": Factor("A_FF_max", per_case(a_max), "1", f"{TS}, 5.2", "maximum material exposure"),
            "y_A_FF_max": Factor("y_A_FF_max", per_case(y[depth]), "mm", f"{TS}, 5.2", "depth of A_FF,max"),
            "Gamma_A_FF_max": Factor("Gamma_A_FF_max", per_case(gammas[cp]), "1", f"{TS}, 3.3",
                                     "contact point of A_FF,max (path parameter)"),
            "CHD_req": Factor("CHD_req", per_case(req), "mm", f"{TS}, 5.2 (this package's search)",
                              f"required case hardness depth for S_FF = S_FFmin ({CHD_BOUNDS[0]:g} ... "
                              f"{CHD_BOUNDS[1]:g} mm)"),
            "S_FF": Factor("S_FF", per_case(1.0 / a_max), "1", "1 / A_FF,max",
                           "safety against tooth flank fracture")})
    b_crit = cases[1][np.arange(cases[1].shape[0]), np.argmax(cases[0], axis=-1)]

    def mesh_value(values):
        v = np.asarray(values, dtype=float).reshape(shape)
        return float(v) if v.ndim == 0 else v
    mesh_factors = [
        Factor("E_r", e_r, "N/mm^2", f"{TS}, 6.2.3", "reduced modulus of elasticity"),
        Factor("p_dyn_max", mesh_value(p_max), "N/mm^2", f"{TS}, 6.2.4",
               "largest local Hertzian contact stress on the path"),
        Factor("b_H", mesh_value(b_crit), "mm", "Johnson 1985, §4.2", "half Hertzian contact width at p_dyn,max"),
        Factor("y_tau_max", mesh_value(0.786 * b_crit), "mm", "Johnson 1985, §4.6",
               "depth of the largest shear stress at p_dyn,max (0.786 b_H)"),
        Factor("K_tau_per", spec.K_tau_per, "N/mm^2/HV", "given" if spec.shear_strength_factor is not None else
               "assumed (0.45 x 3.2 / sqrt 3)", "hardness to shear strength factor"),
        Factor("c_1", spec.calibration_factor, "1", f"{TS}, 5.3 (given)" if spec.calibration_factor else
               "assumed 0", "material exposure calibration constant"),
        Factor("S_FFmin", spec.S_FFmin, "1", "agreed", "minimum safety")]
    notes = [("flank fracture: tau_eff is the Hertzian principal shear stress below the contact centre (Johnson "
              "1985) in place of the local equivalent stress of ISO/TS 6336-4 6.2; residual stresses (6.3) are "
              "not taken into account")]
    if spec.shear_strength_factor is None:
        notes.append(f"flank fracture: K_tau,per = {spec.K_tau_per:.3f} N/mm^2 per HV assumed (not the value of "
                     "ISO/TS 6336-4); give shear_strength_factor")
    for name, prof in zip(inp.gears, profiles):
        if prof.points is None:
            notes.append(f"flank fracture: hardness profile of {name} estimated from HV_s, HV_c and CHD (this "
                         "package's curve); give hardness_profile where measured")
    inf_gears = [n for n, g in zip(inp.gears, gear_factors) if not np.all(np.isfinite(g["CHD_req"].value))]
    low_gears = [n for n, g in zip(inp.gears, gear_factors) if np.any(np.asarray(g["CHD_req"].value) <= CHD_BOUNDS[0])]
    if low_gears:
        notes.append(f"flank fracture: CHD_req = {CHD_BOUNDS[0]:g} mm for {', '.join(low_gears)} means "
                     f"{CHD_BOUNDS[0]:g} mm or less (the lower end of the search)")
    if inf_gears:
        notes.append(f"flank fracture: no case depth up to {CHD_BOUNDS[1]:g} mm reaches S_FFmin for "
                     f"{', '.join(inf_gears)} (the surface hardness or the load is the limit)")
    return ModeRating("flank_fracture", "Tooth flank fracture and hardened layer", f"{TS} (simplified, see notes)",
                      {f.symbol: f for f in mesh_factors}, "S_FF", spec.S_FFmin,
                      gear_factors=tuple(gear_factors), gears=tuple(inp.gears),
                      profile={"gamma": gammas, **{f"{key}": {n: c[key] for n, c in curves.items()}
                                                   for key in ("y", "HV", "tau_per", "tau_eff", "A_FF")}},
                      notes=tuple(notes))
