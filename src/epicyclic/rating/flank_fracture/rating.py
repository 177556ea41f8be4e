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
1/S_FFmin, searched between 0.05 and 10 mm (a bisection on log CHD, all load cases at once; A_FF,max falls as
the case deepens).

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


def depths(deepest: float, per_decade: int) -> np.ndarray:
    """The depths evaluated, mm: 0, then 1 µm · 10^(i/per_decade) up to ``deepest`` (and one beyond).

    The grid does not depend on the load, so a case rated in a batch meets the same depths as alone.

    Parameters
    ----------
    deepest : float
        The depth to reach, mm.
    per_decade : int
        Depths per decade (115: every 2 %).

    Returns
    -------
    ndarray

    References
    ----------
    Johnson 1985, §4.6.
    """
    n = math.ceil(per_decade * math.log10(max(deepest, 1e-3) / 1e-3))
    return np.concatenate([[0.0], 1e-3 * 10.0 ** (np.arange(n + 1) / per_decade)])


def depth_bound(pressure, b, profiles) -> float:
    """A depth below which A_FF cannot have its maximum, mm (over all cases and the gears' profiles).

    τ_1 ≤ p_0 b/(2y) at every depth (Johnson's closed form falls to it from below), and A_FF at
    0.786 b under the largest pressure is at least 0.300 p_max/(K_τ,per HV_max); so below
    y = max(p b)/p_max · HV_max/(0.6 HV_min) every A_FF is smaller.

    References
    ----------
    Johnson 1985, §4.6.
    """
    p = np.atleast_2d(np.asarray(pressure, dtype=float))
    pb = np.max(p * np.atleast_2d(np.asarray(b, dtype=float)), axis=-1)
    p_max = np.max(p, axis=-1)
    ratio = max(prof.hardness_range[0] / prof.hardness_range[1] for prof in profiles)
    with np.errstate(divide="ignore", invalid="ignore"):
        y = np.where(p_max > 0, pb / np.where(p_max > 0, p_max, 1.0), 0.0)
    return float(np.max(y)) * ratio / 0.6 * 1.05


def stress_envelope(depth, pressure, b) -> np.ndarray:
    """max over the contact points of τ_eff at each depth: shape ``pressure.shape[:-1] + depth.shape``.

    Parameters
    ----------
    depth : ndarray
        y, mm (1-d).
    pressure, b : ndarray
        p_dyn and b_H of the contact points (last axis), N/mm² and mm.

    Returns
    -------
    ndarray

    References
    ----------
    Johnson 1985, §4.6.
    """
    p = np.asarray(pressure, dtype=float)[..., None]
    b = np.asarray(b, dtype=float)[..., None]
    loaded = b > 0
    tau = np.where(loaded, principal_shear(depth, p, np.where(loaded, b, 1.0)), 0.0)
    return np.max(tau, axis=-2)


def required_case_depth(profile: HardnessProfile, depth, envelope, spec: FlankFractureSpec, steps: int = 40):
    """CHD_req of each load case: the smallest CHD (mm) at which A_FF,max = 1/S_FFmin (inf: none ≤ 10 mm).

    A_FF,max(CHD) = max_y τ_env(y) / (K_τ,per HV(y; CHD)) + c_1 with the stress envelope of the
    contact points (it does not depend on CHD) and the profile stretched to CHD; it falls as CHD
    grows, and a bisection on log CHD over :data:`CHD_BOUNDS` (``steps`` halvings, all cases at
    once) finds where it meets 1/S_FFmin.

    Parameters
    ----------
    profile : HardnessProfile
    depth : ndarray
        y, mm (1-d), reaching :func:`depth_bound` (:func:`depths`).
    envelope : ndarray
        :func:`stress_envelope` at ``depth``, shape (m,) or (k, m).
    spec : FlankFractureSpec
    steps : int, default 40

    Returns
    -------
    float or ndarray
        One per case: :data:`CHD_BOUNDS` [0] where even that meets the limit; ``inf`` where 10 mm
        does not.

    References
    ----------
    ISO/TS 6336-4:2019, 5.2; ISO 2639:2002.
    """
    env = np.atleast_2d(np.asarray(envelope, dtype=float))
    target = 1.0 / spec.S_FFmin

    def exposure(chd):
        hv = profile(depth[None, :], case_depth=chd[:, None])
        return np.max(env / (spec.K_tau_per * hv), axis=-1) + spec.calibration_factor
    lo = np.full(env.shape[0], CHD_BOUNDS[0])
    hi = np.full(env.shape[0], CHD_BOUNDS[1])
    none, enough = exposure(hi) > target, exposure(lo) <= target
    for _ in range(steps):
        mid = np.sqrt(lo * hi)
        over = exposure(mid) > target
        lo, hi = np.where(over, mid, lo), np.where(over, hi, mid)
    out = np.where(none, math.inf, np.where(enough, CHD_BOUNDS[0], hi))
    return float(out[0]) if np.ndim(envelope) == 1 else out


def _validity(inp, mats, p_max, rho, profiles) -> None:
    where = f"{inp.element} {inp.mesh.name}"
    clause = f"{TS}, clause 1"
    for name, mat, prof in zip(inp.gears, mats, profiles):
        if prof is not None and mat.treatment != "Eh":
            warn_validity(f"{where}: {name} ({mat.name}, {mat.treatment}) is not case-carburised; the method is "
                          "written for case-carburised gears (rated with the same formulas)", clause)
    lo, hi = float(np.min(p_max)), float(np.max(p_max))
    if lo < 500.0 or hi > 3000.0:
        warn_validity(f"{where}: p_dyn,max {lo:.0f} ... {hi:.0f} N/mm^2 outside 500 ... 3000 N/mm^2", clause)
    if float(np.min(rho)) < 5.0 or float(np.max(rho)) > 150.0:
        warn_validity(f"{where}: rho_red {float(np.min(rho)):.3g} ... {float(np.max(rho)):.3g} mm outside "
                      "5 ... 150 mm", clause)
    for name, prof in zip(inp.gears, profiles):
        if prof is not None and not 0.3 <= prof.case_depth <= 4.5:
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
    if all(prof is None for prof in profiles):
        g1, g2 = inp.gears
        raise RatingError(f"rating.flank_fracture: no case_depth or hardness_profile for {inp.element} {g1} or "
                          f"{g2}; give them for all gears or per gear (e.g. case_depth = {{ {g1} = 1.0 }}), or "
                          "leave the table out.")
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
    cap = depth_bound(cases[0], cases[1], [prof for prof in profiles if prof is not None])
    y_req = depths(cap, spec.depths_per_decade)
    envelope = stress_envelope(y_req, cases[0], cases[1])           # (cases, depths), the same for both gears
    gear_factors, curves = [], {}
    for name, prof in zip(inp.gears, profiles):
        if prof is None:
            gear_factors.append({})
            continue
        y = depths(max(cap, 3.0 * prof.case_depth), spec.depths_per_decade)
        hv = prof(y)
        a, tau = material_exposure(y, p, b, hv, spec.K_tau_per, spec.calibration_factor)
        flat = a.reshape(-1, a.shape[-2] * a.shape[-1])
        at = np.argmax(flat, axis=-1)
        a_max = flat[np.arange(flat.shape[0]), at]
        cp, depth = np.unravel_index(at, a.shape[-2:])
        req = required_case_depth(prof, y_req, envelope, spec)
        k = int(np.argmax(a_max))
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
        if prof is None:
            notes.append(f"flank fracture: {name} not rated (no case_depth or hardness_profile given for it)")
        elif prof.points is None:
            notes.append(f"flank fracture: hardness profile of {name} estimated from HV_s, HV_c and CHD (this "
                         "package's curve); give hardness_profile where measured")
    req = {n: np.asarray(g["CHD_req"].value) for n, g in zip(inp.gears, gear_factors) if g}
    inf_gears = [n for n, r in req.items() if not np.all(np.isfinite(r))]
    low_gears = [n for n, r in req.items() if np.any(r <= CHD_BOUNDS[0])]
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
