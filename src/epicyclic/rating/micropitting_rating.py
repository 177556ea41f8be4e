"""The micropitting rating of one mesh of a train: Method B from the mesh's rating inputs and load factors.

:func:`rate_micropitting` takes the :class:`~epicyclic.rating.mesh_rating.MeshInput` (geometry, face
width, materials, roughness, lubricant) and the :class:`~epicyclic.rating.results.MeshRating` of the
same load (F_t, K_A, K_γ, K_v, K_Hβ, K_Hα) and returns a
:class:`~epicyclic.rating.mode_results.ModeRating` with S_λ = λ_GF,min / λ_GFP (see
:mod:`~epicyclic.rating.micropitting` for the formulas), vectorised over load cases.

References
----------
ISO/TS 6336-22:2018, clauses 1 and 5–8; ISO/TR 15144-1:2014.
"""

from __future__ import annotations

import math

import numpy as np

from .contact_path import contact_path
from .errors import RatingError, warn_validity
from .lubricant_film import OilProperties, reduced_modulus
from .micropitting import (
    MicropittingSpec,
    film_state,
    permissible_film_thickness,
    tip_relief_factor,
)
from .mode_results import ModeRating
from .results import Factor

__all__ = ["rate_micropitting"]


def _validity(inp, v, clause: str) -> None:
    mesh, rack = inp.mesh, inp.mesh.rack
    where = f"{inp.element} {mesh.name}"
    if mesh.internal:
        warn_validity(f"{where}: the document is written for external gears; the internal mesh is rated with "
                      "the same formulas (the ring's flank concave)", f"{clause}, clause 1")
    if not 3.0 <= rack.module <= 11.0:
        warn_validity(f"{where}: m_n = {rack.module:g} mm outside the 3 ... 11 mm the method was developed for",
                      f"{clause}, clause 1")
    v_min, v_max = float(np.min(v)), float(np.max(v))
    if v_min < 2.0 or v_max > 60.0:
        warn_validity(f"{where}: pitch line velocity {v_min:.3g} ... {v_max:.3g} m/s outside 2 ... 60 m/s",
                      f"{clause}, clause 1")
    if rack.pressure_angle > 25.0 or rack.helix_angle > 25.0:
        warn_validity(f"{where}: α_n = {rack.pressure_angle:g}°, β = {rack.helix_angle:g}° beyond 25°",
                      f"{clause}, clause 1")
    beta_b = math.asin(math.sin(rack.beta) * math.cos(rack.alpha_n))
    if mesh.contact_ratio / math.cos(beta_b) ** 2 >= 2.5:
        warn_validity(f"{where}: virtual contact ratio ε_αn ≥ 2.5", f"{clause}, clause 1")


def rate_micropitting(inp, rating, torque, speed, spec: MicropittingSpec | None = None) -> ModeRating:
    """S_λ of one mesh at the load of ``rating`` (torque on gear 1 per planet, N·m; speed of gear 1, 1/min).

    Parameters
    ----------
    inp : MeshInput
    rating : MeshRating
        The ISO 6336 rating of the same load (its F_t and load factors are used).
    torque, speed : float or array_like
        As given to :func:`~epicyclic.rating.mesh_rating.rate_mesh`.
    spec : MicropittingSpec, optional
        Default ``inp.spec.micropitting``.

    Returns
    -------
    ModeRating
        ``mode = "micropitting"``, safety ``S_lambda``.

    Raises
    ------
    RatingError
        No micropitting inputs, ν_100 missing, a mesh that does not turn.

    References
    ----------
    ISO/TS 6336-22:2018, eq. (1) and clauses 5–8; ISO/TR 15144-1:2014.
    """
    spec = spec if spec is not None else getattr(inp.spec, "micropitting", None)
    if spec is None:
        raise RatingError("micropitting: give the [rating.micropitting] table (oil_temperature and load_stage or "
                          "lambda_GFP).")
    s, rspec, mesh = inp.static, inp.spec, inp.mesh
    clause = spec.edition
    if rspec.viscosity_100 is None:
        raise RatingError("rating.viscosity_100 is missing (ν at 100 degC in mm^2/s, for the viscosity at the bulk "
                          "and contact temperatures of the micropitting rating); give it in [lubricant].")
    oil = OilProperties(rspec.required("viscosity_40"), rspec.viscosity_100, spec.lubricant_type, spec.density)
    mats = s["materials"]
    e_r = reduced_modulus(mats[0].E, mats[0].poisson, mats[1].E, mats[1].poisson)
    notes = []
    ras = []
    for name in inp.gears:
        ra, note = spec.roughness_of(inp.element, name, rspec.roughness_of("flank_roughness", inp.element, name))
        ras.append(ra)
        if note:
            notes.append(note)
    ra = 0.5 * (ras[0] + ras[1])
    path = contact_path(mesh, inp.face_width, accuracy_grade=rspec.accuracy_grade,
                        tip_relief=spec.profile_modification)
    x_ca = tip_relief_factor(path, spec.profile_modification, rspec.accuracy_grade)
    load = rating["K_A"] * rating["K_gamma"] * np.asarray(rating["K_v"]) * np.asarray(rating["K_Hbeta"]) * \
        np.asarray(rating["K_Halpha"])
    _validity(inp, rating["v"], clause)
    state = film_state(path, oil, E_r=e_r, roughness=ra, speed1=speed, force=rating["F_t"], load_factor=load,
                       oil_temperature=spec.oil_temperature, bulk_temperature=spec.bulk_temperature,
                       lubrication=spec.lubrication, x_ca=x_ca, points=spec.points)
    lam_min = state.lambda_min
    if spec.lambda_GFP is not None:
        lam_p, lam_t, source = spec.lambda_GFP, None, "given"
    else:
        treatments = {m.treatment for m in mats}
        w_w = spec.material_factor
        if w_w is None:
            w_w = 1.0
            if treatments != {"Eh"}:
                notes.append("micropitting: W_W = 1 (case-carburised) taken for a pair with "
                             f"{', '.join(sorted(treatments))}; give material_factor")
        test = permissible_film_thickness(oil, spec.load_stage, w_w)
        lam_p, lam_t = test["lambda_GFP"], test["lambda_GFT"]
        source = f"FZG GF-C/8.3/90, SKS {spec.load_stage}"
    with np.errstate(divide="ignore"):
        safety = np.asarray(lam_min, dtype=float) / lam_p
    sc = state.scalars
    where = f"{clause}, Method B"

    def eq(number: str) -> str:  # the equation numbers are those of ISO/TR 15144-1:2014
        return f"ISO/TR 15144-1:2014, {number}" if clause.startswith("ISO/TR") else \
            f"{clause} (ISO/TR 15144-1:2014, {number})"
    f = [
        Factor("theta_oil", spec.oil_temperature, "degC", where, "oil temperature"),
        Factor("theta_M", sc["theta_M"], "degC", eq("eq. (84)") if spec.bulk_temperature is None else "given",
               "bulk temperature"),
        Factor("mu_m", sc["mu_m"], "1", eq("eq. (86)"), "mean coefficient of friction"),
        Factor("X_R", sc["X_R"], "1", eq("eq. (87)"), "roughness factor (friction)"),
        Factor("X_L", sc["X_L"], "1", eq("Table 3"), f"lubricant factor ({spec.lubricant_type})"),
        Factor("K_Bgamma", sc["K_Bgamma"], "1", eq("eqs. (88)-(90)"), "helical load factor"),
        Factor("H_V", sc["H_V"], "1", eq("eq. (91)"), "load losses factor"),
        Factor("X_S", sc["X_S"], "1", eq("eq. (84)"), f"lubrication factor ({spec.lubrication})"),
        Factor("X_Ca", sc["X_Ca"], "1", eq("eq. (100)"), "tip relief factor"),
        Factor("E_r", e_r, "N/mm^2", eq("eq. (6)"), "reduced modulus of elasticity"),
        Factor("eta_M", sc["eta_M"], "N*s/m^2", eq("eq. (16)"), "dynamic viscosity at theta_M"),
        Factor("alpha_M", sc["alpha_M"], "m^2/N", eq("eq. (8)"), "pressure-viscosity coefficient at theta_M"),
        Factor("G_M", sc["G_M"], "1", eq("eq. (5)"), "material parameter"),
        Factor("R_a", ra, "um", eq("eq. (3)"), "effective arithmetic mean roughness"),
        Factor("lambda_GF_min", lam_min, "1", eq("eq. (2)"),
               f"minimum specific lubricant film thickness (at {state.lambda_min_at})"),
    ]
    if lam_t is not None:
        f.append(Factor("lambda_GFT", lam_t, "1", eq("Annex A"), "limiting film thickness of the test"))
    f += [Factor("lambda_GFP", lam_p, "1", eq("Annex A") if lam_t is not None else "given",
                 f"permissible specific film thickness ({source})"),
          Factor("S_lambda", float(safety) if safety.ndim == 0 else safety, "1", eq("eq. (1)"),
                 "safety factor against micropitting"),
          Factor("S_lambda_min", spec.S_lambda_min, "1", "agreed (ISO/TS 6336-22 names none)", "minimum safety")]
    p = state.path
    profile = {"gamma": p["gamma"], "X_Y": p["X"], "rho_n": p["rho_n"], "v_sum": p["v_sum"], "v_g": p["v_slide"],
               "p_dyn": p["p_dyn"], "theta_fl": p["theta_fl"], "theta_B": p["theta_B"], "h": p["h"],
               "lambda_GF": p["lambda"], "points": {k: float(p["gamma"][i]) for k, i in state.points.items()}}
    return ModeRating("micropitting", "Micropitting", f"{clause}, method B", {x.symbol: x for x in f}, "S_lambda",
                      spec.S_lambda_min,
                      gears=tuple(inp.gears), profile=_profile(profile), notes=tuple(notes))


def _profile(profile):
    out = {}
    for key, value in profile.items():
        out[key] = value if isinstance(value, dict) else np.asarray(value)
    return out
