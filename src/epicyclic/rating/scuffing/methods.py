"""The integral and the flash temperature method of one mesh, vectorised over load cases.

:class:`ScuffingInput` holds what does not change with the load (geometry factors, the oil at
θ_oil, the permissible temperatures); :func:`integral_temperature` and
:func:`flash_temperature` evaluate a :class:`ScuffingLoad` (one value per load case)::

    w_Bt   = K_A K_γ K_v K_Bβ K_Bα F_t / b                    (K_Bβ = K_Hβ, K_Bα = K_Hα)
    μ_mC   = 0.045 (w_Bt K_Bγ / (v_ΣC ρ_redC))^0.2 η_oil^-0.05 X_R X_L,  v_ΣC = 2 v_w sin α_wt = 2 ω1 ρ_C1

  integral temperature method (ISO/TS 6336-21:2017; ISO/TR 13989-2:2000):

    θ_flaE   = μ_mC X_M X_BE X_αβ (K_Bγ w_Bt)^0.75 v^0.5 / a^0.25 · X_E / (X_Q X_Ca)
    (X_E = 1 + (1 − φ_E) 30 R_a/ρ_redC; X_Ca = 1 for accuracy grades coarser than 6; μ_mC with
    w_Bt ≥ 150 N/mm and v ≤ 50 m/s)
    θ_flaint = θ_flaE X_ε,   θ_M = θ_oil + C_1 X_mp θ_flaint,   θ_int = θ_M + C_2 θ_flaint
    (C_1 = 0.7, C_2 = 1.5; θ_M with X_S as well)
    θ_intS   = θ_MT + X_WrelT C_2 θ_flaintT,  θ_MT = 80 + 0.23 T_1T X_L,
               θ_flaintT = 0.2 T_1T (100/ν_40)^0.02 X_L   (T_1T = 3.726 S_FZG², the FZG load stage)
    S_intS   = θ_intS / θ_int,   S_SL = (θ_intS − θ_oil) / (θ_int − θ_oil)

  flash temperature method (ISO/TS 6336-20:2017; ISO/TR 13989-1:2000), along the path Γ_A … Γ_E:

    θ_fl(Γ) = μ_m X_M X_J X_G(Γ) (X_Γ w_Bt)^0.75 v^0.5 / a^0.25,  X_G = X_αβ X_BE(Γ),
    X_J = 1 + (C_eff − C_a)/50 (|Γ|/(Γ_E − Γ_A))³ in the approach (the driven gear's tip), else 1
    θ_M     = θ_oil + 0.47 X_S X_mp θ_flm   (θ_flm the mean of θ_fl over the path)
    θ_B     = θ_M + θ_fl,   θ_S = 80 + (0.85 + 1.4 X_W) X_L' S_FZG²,  X_L' = X_L η_oil^-0.05
    S_B     = (θ_S − θ_oil) / (θ_B,max − θ_oil)

v is the pitch line velocity at the reference circle (relative to the carrier), a the centre
distance, F_t the nominal tangential force at the reference circle per planet.

References
----------
ISO/TS 6336-21:2017 (integral temperature), ISO/TS 6336-20:2017 (flash temperature), their 2022
revisions; ISO/TR 13989-1, -2:2000; DIN 3990-4:1987; Blok, H.: *Theoretical study of temperature
rise at surfaces of actual contact under oiliness lubricating conditions*, Proc. General
Discussion on Lubrication, IMechE (1937) 222–235.  X_L' of θ_S as the KISSsoft report of the
tests applies ISO/TR 13989-1 (its printed X_L = η_oil^-0.05); μ_m of the flash method is taken
as μ_mC (see docs/rating.md, Scuffing).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..contact_path import ContactPath
from ..errors import RatingError, warn_validity
from . import factors
from .spec import LUBRICATION_FACTORS, ScuffingSpec

__all__ = ["C_1", "C_2", "FRICTION_LOAD_FLOOR", "FRICTION_SPEED_LIMIT", "approach_factor_path", "ScuffingInput", "ScuffingLoad", "flash_temperature", "integral_temperature"]

#: Weighting factors of the integral temperature method (ISO/TS 6336-21:2017).
C_1, C_2 = 0.7, 1.5
#: Weight of the mean flash temperature in the bulk temperature of the flash method.
C_FLASH = 0.47
#: The friction formula's range: w_Bt below 150 N/mm is taken as 150, v above 50 m/s as 50 (ISO/TR 13989-2, 5.1).
FRICTION_LOAD_FLOOR, FRICTION_SPEED_LIMIT = 150.0, 50.0
#: Tip relief is credited in X_Ca for ISO 1328 accuracy grades up to this one (ISO/TR 13989-2, X_Ca).
TIP_RELIEF_GRADE = 6


@dataclass(frozen=True)
class ScuffingLoad:
    """The load of a mesh in each load case (numbers or arrays of one shape).

    Parameters
    ----------
    tangential_force : float or ndarray
        F_t at the reference circle per planet, N.
    velocity : float or ndarray
        v at the reference circle, m/s.
    K_A, K_gamma, K_v, K_Bbeta, K_Balpha : float or ndarray
        Load factors (K_Bβ = K_Hβ, K_Bα = K_Hα of ISO 6336-1).
    mesh_stiffness : float or ndarray
        c_γα, N/(mm µm), for C_eff.
    tip_relief : float
        C_a, µm.
    """

    tangential_force: object
    velocity: object
    K_A: object = 1.0
    K_gamma: object = 1.0
    K_v: object = 1.0
    K_Bbeta: object = 1.0
    K_Balpha: object = 1.0
    mesh_stiffness: object = 20.0
    tip_relief: float = 0.0

    def line_load(self, face_width: float) -> np.ndarray:
        """w_Bt = K_A K_γ K_v K_Bβ K_Bα F_t / b, N/mm."""
        product = np.asarray(self.tangential_force, dtype=float)
        for k in (self.K_A, self.K_gamma, self.K_v, self.K_Bbeta, self.K_Balpha):
            product = product * np.asarray(k, dtype=float)
        return product / face_width


@dataclass(frozen=True)
class ScuffingInput:
    """The load-independent part of a mesh's scuffing rating.

    Parameters
    ----------
    path : ContactPath
        The mesh's path of contact (Γ, X_Γ).
    spec : ScuffingSpec
    viscosity_40 : float
        ν_40, mm²/s.
    viscosity : float
        η_oil at θ_oil, mPa·s.
    roughness : float
        R_a, the mean of both flanks, µm.
    thermo_elastic : float
        X_M.
    multiple_meshing : float, default 1
        X_mp.
    points : int, default 41
        Points of the flash temperature along the path.

    Raises
    ------
    RatingError
        ε_1 ≤ 0 or ε_α out of the methods' range.

    References
    ----------
    ISO/TS 6336-21:2017; ISO/TS 6336-20:2017.
    """

    path: ContactPath
    spec: ScuffingSpec
    viscosity_40: float
    viscosity: float
    roughness: float
    thermo_elastic: float
    multiple_meshing: float = 1.0
    points: int = 41
    derived: dict = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        p, s = self.path, self.spec
        rack = p.mesh.rack
        u, a = p.u, p.mesh.center_distance
        eps_1 = p.points["E"] * p.rho_c1 / p.base_pitch
        eps_2 = -p.points["A"] * p.rho_c1 / p.base_pitch
        if eps_2 <= 0.0:
            raise RatingError(f"scuffing of {p.mesh.name or 'mesh'}: the tip of gear 2 does not reach the pitch point "
                              f"(ε_2 = {eps_2:.4f}); the methods need contact on both sides of C.")
        x_ab = factors.angle_factor(rack.alpha_n, p.alpha_t, p.alpha_wt, rack.beta)
        eps_gamma = p.eps_alpha + p.eps_beta
        gam = p.gammas(self.points)
        x_q = 1.0
        if s.driving == "gear1":
            x_q = factors.approach_factor(eps_2, eps_1)
        elif s.driving == "gear2":
            x_q = factors.approach_factor(eps_1, eps_2)
        x_l = factors.LUBRICANT_FACTORS[s.oil_type]
        flash_clause, integral_clause = s.clauses
        if s.load_stage is not None and s.load_stage > 12:
            warn_validity(f"FZG A/8.3/90 load stage {s.load_stage} lies beyond the test's 12 stages (ISO 14635-1): "
                          "θ_S and θ_intS are extrapolated from the formulas of the test", integral_clause)
        if s.integral_scuffing_temperature is not None:
            theta_ints = s.integral_scuffing_temperature
            t_1t = None
        else:
            t_1t = factors.fzg_torque(s.load_stage)
            theta_mt = 80.0 + 0.23 * t_1t * x_l
            theta_flaint_t = 0.2 * t_1t * (100.0 / self.viscosity_40) ** 0.02 * x_l
            theta_ints = theta_mt + s.structural_factor * C_2 * theta_flaint_t
        if theta_ints <= s.oil_temperature:
            warn_validity(f"the permissible integral temperature θ_intS = {theta_ints:.1f} °C is not above the oil "
                          f"temperature {s.oil_temperature:g} °C: the oil scuffs at any load (S_SL = 0)",
                          integral_clause)
        x_l_flash = x_l * self.viscosity ** -0.05
        theta_s = (s.scuffing_temperature if s.scuffing_temperature is not None else
                   80.0 + (0.85 + 1.4 * s.structural_factor) * x_l_flash * s.load_stage ** 2)
        if theta_s <= s.oil_temperature:
            warn_validity(f"the scuffing temperature θ_S = {theta_s:.1f} °C is not above the oil temperature "
                          f"{s.oil_temperature:g} °C: the oil scuffs at any load (S_B = 0)", flash_clause)
        rho_c = factors.pitch_point_radius(u, a, p.alpha_wt, p.beta_b, p.internal)
        object.__setattr__(self, "derived", {
            "X_E": 1.0 + (1.0 - s.run_in) * 30.0 * self.roughness / rho_c, "u": u, "a": a, "eps_1": eps_1, "eps_2": eps_2, "eps_gamma": eps_gamma, "X_alphabeta": x_ab,
            "X_BE": factors.geometry_factor(p.points["E"], u, p.internal),
            "X_epsilon": factors.contact_ratio_factor(eps_1, eps_2, integral_clause),
            "K_Bgamma": factors.helical_load_factor(eps_gamma),
            "rho_redC": rho_c,
            "X_Q": x_q, "X_L": x_l, "X_L_flash": x_l_flash, "X_S": LUBRICATION_FACTORS[s.lubrication],
            "T_1T": t_1t, "theta_intS": theta_ints, "theta_S": theta_s, "gamma": gam,
            "X_G": x_ab * factors.geometry_factor(gam, u, p.internal), "X_Gamma": p.load_sharing(gam),
        })

    def __getitem__(self, key: str):
        return self.derived[key]


def _friction(si: ScuffingInput, load: ScuffingLoad, w_bt) -> np.ndarray:
    """μ_mC with the friction formula's range: w_Bt at least 150 N/mm, v at most 50 m/s."""
    d, p = si.derived, si.path
    v = np.minimum(np.asarray(load.velocity, dtype=float), FRICTION_SPEED_LIMIT)
    # v_ΣC = 2 ω1 ρ_C1 = 2 v_w sin α_wt: the sum velocity at the pitch point (v_w at the operating pitch circle)
    v_sum = 2.0 * v * math.tan(p.alpha_wt) * math.cos(p.alpha_t)
    w = np.maximum(np.asarray(w_bt, dtype=float), FRICTION_LOAD_FLOOR)
    return factors.mean_friction(w * d["K_Bgamma"], v_sum, d["rho_redC"], si.viscosity, si.roughness, d["X_L"])


def _safety(limit, value, base):
    limit, value = np.broadcast_arrays(np.asarray(limit, dtype=float), np.asarray(value, dtype=float))
    rise = value - base
    margin = np.maximum(limit - base, 0.0)  # a limit at or below θ_oil: nothing can be transmitted
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(rise > 0, margin / np.where(rise > 0, rise, 1.0), np.where(margin > 0, np.inf, 0.0))


def integral_temperature(si: ScuffingInput, load: ScuffingLoad) -> dict[str, object]:
    """θ_flaint, θ_M, θ_int, θ_intS, S_intS, S_SL and the load-dependent factors (numbers or arrays).

    Parameters
    ----------
    si : ScuffingInput
    load : ScuffingLoad

    Returns
    -------
    dict
        ``w_Bt``, ``mu_mC``, ``C_eff``, ``X_Ca``, ``theta_flaE``, ``theta_flaint``, ``theta_M``,
        ``theta_int``, ``S_intS``, ``S_SL``.

    References
    ----------
    ISO/TS 6336-21:2017 (ISO/TR 13989-2:2000): flash temperature at the pinion tip, mean flash
    temperature, bulk and integral temperature, safeties.
    """
    d, s, p = si.derived, si.spec, si.path
    b = p.face_width
    w_bt = load.line_load(b)
    mu = _friction(si, load, w_bt)
    c_eff = factors.effective_tip_relief(np.asarray(load.K_A, dtype=float), load.tangential_force, b,
                                         load.mesh_stiffness)
    x_ca = (factors.tip_relief_factor(load.tip_relief, c_eff, max(d["eps_1"], d["eps_2"]))
            if p.accuracy_grade <= TIP_RELIEF_GRADE else np.ones(np.shape(c_eff)))
    v = np.asarray(load.velocity, dtype=float)
    theta_flae = (mu * si.thermo_elastic * d["X_BE"] * d["X_alphabeta"] * (d["K_Bgamma"] * w_bt) ** 0.75
                  * np.sqrt(v) / d["a"] ** 0.25 * d["X_E"] / (d["X_Q"] * x_ca))
    theta_flaint = theta_flae * d["X_epsilon"]
    theta_m = s.oil_temperature + C_1 * d["X_S"] * si.multiple_meshing * theta_flaint
    theta_int = theta_m + C_2 * theta_flaint
    with np.errstate(divide="ignore", invalid="ignore"):
        s_ints = np.where(theta_int > 0, d["theta_intS"] / np.where(theta_int > 0, theta_int, 1.0), np.inf)
    return {"w_Bt": w_bt, "mu_mC": mu, "C_eff": c_eff, "X_Ca": x_ca, "theta_flaE": theta_flae,
            "theta_flaint": theta_flaint, "theta_M": theta_m, "theta_int": theta_int, "S_intS": s_ints,
            "S_SL": _safety(d["theta_intS"], theta_int, s.oil_temperature)}


def approach_factor_path(gamma, effective, tip_relief: float, driving: str | None):
    """X_J along the path: 1 + (C_eff − C_a)/50 · (|Γ|/(Γ_E − Γ_A))³ where the driven gear's tip enters, ≥ 1.

    The driven gear's tip meets the driving flank in the approach: Γ < 0 when gear 1 drives, Γ > 0
    when gear 2 does; without ``driving`` both ends (on the safe side).

    Parameters
    ----------
    gamma : ndarray
        Γ of the points, from Γ_A to Γ_E.
    effective : float or ndarray
        C_eff, µm (one per load case, broadcast against ``gamma``).
    tip_relief : float
        C_a, µm.
    driving : {"gear1", "gear2", None}

    Returns
    -------
    ndarray

    References
    ----------
    ISO/TR 13989-1:2000 and ISO/TS 6336-20:2017 (approach factor X_J); DIN 3990-4:1987.
    """
    gam = np.asarray(gamma, dtype=float)
    span = gam[-1] - gam[0]
    rise = np.maximum(np.asarray(effective, dtype=float) - tip_relief, 0.0) / 50.0
    approach = np.zeros(gam.shape, dtype=bool)
    if driving in ("gear1", None):
        approach |= gam < 0.0
    if driving in ("gear2", None):
        approach |= gam > 0.0
    return np.where(approach, 1.0 + rise * (np.abs(gam) / span) ** 3, 1.0)


def flash_temperature(si: ScuffingInput, load: ScuffingLoad) -> dict[str, object]:
    """θ_fl along the path, θ_flm, θ_M, θ_B and its maximum, S_B (numbers or arrays).

    Parameters
    ----------
    si : ScuffingInput
    load : ScuffingLoad

    Returns
    -------
    dict
        ``mu_m``, ``theta_fl`` (cases + points), ``theta_flm``, ``theta_M``, ``theta_B`` (cases + points),
        ``theta_Bmax``, ``gamma_max`` (Γ of θ_B,max), ``X_Gamma_max`` (X_Γ there), ``S_B``.

    References
    ----------
    ISO/TS 6336-20:2017 (ISO/TR 13989-1:2000): local flash temperature (Blok), bulk and contact
    temperature, scuffing temperature, safety S_B.
    """
    d, s, p = si.derived, si.spec, si.path
    w_bt = load.line_load(p.face_width)
    mu = _friction(si, load, w_bt)
    gam, x_g, x_gam = d["gamma"], d["X_G"], d["X_Gamma"]
    scale = mu * si.thermo_elastic * np.sqrt(np.asarray(load.velocity, dtype=float)) / d["a"] ** 0.25
    w = np.asarray(w_bt, dtype=float)[..., None]
    c_eff = factors.effective_tip_relief(np.asarray(load.K_A, dtype=float), load.tangential_force, p.face_width,
                                         load.mesh_stiffness)
    x_j = approach_factor_path(gam, np.asarray(c_eff, dtype=float)[..., None], load.tip_relief, s.driving)
    theta_fl = np.asarray(scale, dtype=float)[..., None] * x_j * x_g * (x_gam * w) ** 0.75
    theta_flm = np.trapezoid(theta_fl, gam, axis=-1) / (gam[-1] - gam[0])
    theta_m = s.oil_temperature + C_FLASH * d["X_S"] * si.multiple_meshing * theta_flm
    theta_b = theta_m[..., None] + theta_fl
    k = np.argmax(theta_b, axis=-1)
    theta_bmax = np.take_along_axis(theta_b, np.asarray(k)[..., None], axis=-1)[..., 0]
    x_j_max = np.take_along_axis(np.broadcast_to(x_j, theta_b.shape), np.asarray(k)[..., None], axis=-1)[..., 0]
    out = {"w_Bt": w_bt, "mu_m": mu, "X_J_max": x_j_max, "theta_fl": theta_fl, "theta_flm": theta_flm, "theta_M": theta_m,
           "theta_B": theta_b, "theta_Bmax": theta_bmax, "gamma_max": gam[k], "X_Gamma_max": x_gam[k],
           "S_B": _safety(d["theta_S"], theta_bmax, s.oil_temperature)}
    return {key: (float(v) if isinstance(v, np.ndarray) and v.ndim == 0 else v) for key, v in out.items()}
