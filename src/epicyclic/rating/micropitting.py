"""Micropitting load capacity, ISO/TS 6336-22:2018 Method B (and ISO/TR 15144-1:2014).

The safety against micropitting compares the thinnest specific lubricant film along the path of
contact with the permissible one::

    S_λ = λ_GF,min / λ_GFP                                         (ISO/TS 6336-22, eq. (1))
    λ_GF,Y = h_Y / R_a,   R_a = (R_a1 + R_a2)/2                   (eqs. (2), (3))

h_Y by Dowson–Higginson (:mod:`~epicyclic.rating.lubricant_film`) at the points A, AB, B, C,
D, DE, E of the path (:mod:`~epicyclic.rating.contact_path`), with the viscosity at the bulk
temperature θ_M and the sliding parameter S_GF from the local contact temperature
θ_B,Y = θ_M + θ_fl,Y::

    μ_m = 0.045 (K_A K_γ K_v K_Hα K_Hβ F_bt K_Bγ / (b v_Σ,C ρ_n,C))^0.2 η_oil^−0.05 X_R X_L   (eq. (86))
    X_R = 2.2 (R_a / ρ_n,C)^0.25;  K_Bγ = 1, 1 + 0.2 √((ε_γ − 2)(5 − ε_γ)), 1.3   (eqs. (87)–(90))
    θ_M = θ_oil + 7400 (P μ_m H_V / (a b))^0.72 X_S / (1.2 X_Ca)                    (eq. (84))
    H_V = (ε_1² + ε_2² + 1 − ε_α)(1/z1 ± 1/z2) π / cos β_b   (ε_α < 2)               (eq. (91))
    θ_fl,Y = (√π/2) μ_m p_dyn,Y v_g,Y / (B_M1 √v_r1,Y + B_M2 √v_r2,Y) · √(8 ρ_n,Y p_dyn,Y / (1000 E_r))   (eq. (80))

(P in kW, a and b in mm, p in Pa in eq. (80), B_M = √(λ_M ρ_M c_M) = 12 420 N/(m s^0.5 K) for
steel, X_S = 1.2 spray, 1.0 dip, 0.2 submerged; X_Ca = 1 + 0.24 ε_max + 0.71 ε_max² with a tip
relief and accuracy grade ≤ 6, else 1; eq. (80) is Jaeger's band source of the mean Hertzian
pressure.)

The permissible film λ_GFP is given, or follows from the failure load stage SKS of the FZG
micropitting test GF-C/8.3/90 (FVA 54/7; DIN ISO 14635 gear type C: z = 16/24, m = 4.5 mm,
a = 91.5 mm, b = 14 mm, R_a = 0.5 µm, v = 8.3 m/s, θ_oil = 90 °C, the pinion torque of the load
stage): λ_GFT is λ_GF,min of the test gears at that stage, computed by the same method, and
λ_GFP = 1.4 W_W λ_GFT with the material factor W_W (1 for case-carburised steel).

Validity (warnings naming the clause): external gears (clause 1; an internal mesh is rated
with the same formulas, the ring's flank concave), modules 3 … 11 mm, pitch line velocities
2 … 60 m/s (developed for 8 … 60 m/s), α_n ≤ 25°, β ≤ 25°, ε_αn < 2.5.

References
----------
ISO/TS 6336-22:2018, clauses 1, 5–8 and Annex A (λ_GFT from the FZG test); ISO/TR 15144-1:2014
(the same Method B; the equation numbers above are that edition's); DIN ISO 14635-1:2006 (FZG
test, pinion torques of the load stages); FVA information sheet 54/7 (GF-C/8.3/90); Dowson and
Higginson (1966).  The standards' texts were not reachable when this was written: the formulas
follow their published structure and are tested against closed forms (see tests).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from functools import lru_cache
from types import MappingProxyType
from typing import Any

import numpy as np

from ..geometry.gear import BasicRack, GearGeometry, MeshGeometry
from .contact_path import POINTS, TIP_RELIEF, ContactPath, contact_path
from .errors import RatingError, warn_validity
from .lubricant_film import (
    LUBRICANT_TYPES,
    OilProperties,
    film_thickness,
    reduced_modulus,
)

__all__ = [
    "EDITIONS",
    "FZG_TORQUES",
    "MicropittingSpec",
    "film_state",
    "fzg_c_path",
    "helical_load_factor",
    "permissible_film_thickness",
]

#: Editions of Method B that can be named (the same formulas here).
EDITIONS = ("ISO/TS 6336-22:2018", "ISO/TR 15144-1:2014")
#: Pinion torque of the FZG load stages, N·m (DIN ISO 14635-1:2006, Table 1).
FZG_TORQUES = MappingProxyType({1: 3.3, 2: 13.7, 3: 35.3, 4: 60.8, 5: 94.1, 6: 135.5, 7: 183.4, 8: 239.3,
                                9: 302.0, 10: 372.6, 11: 450.1, 12: 534.5})
#: X_S of the lubrication (ISO/TR 15144-1:2014, eq. (84); ISO/TR 13989-1:2000, 8.2).
LUBRICATION = MappingProxyType({"spray": 1.2, "dip": 1.0, "submerged": 0.2})
#: Highest contact temperature the oil's formulas are taken to (α_θ of eq. (8) falls to 0 at 510 °C), °C.
OIL_LIMIT = 350.0
#: B_M = √(λ_M ρ_M c_M) of steel (45 W/(m K), 7800 kg/m³, 440 J/(kg K)), N/(m s^0.5 K).
STEEL_THERMAL = math.sqrt(45.0 * 7800.0 * 440.0)


def _number(value, key: str, low: float | None = None, high: float | None = None):
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) or \
            (low is not None and value <= low) or (high is not None and value > high):
        bounds = f" in ({low:g}, {high:g}]" if high is not None else (f" > {low:g}" if low is not None else "")
        raise RatingError(f"rating.micropitting.{key} must be a number{bounds}, got {value!r}.")
    return float(value)


@dataclass(frozen=True)
class MicropittingSpec:
    """Inputs of the micropitting rating (the ``[rating.micropitting]`` table).

    Parameters
    ----------
    oil_temperature : float
        θ_oil, °C (required).
    edition : str, default "ISO/TS 6336-22:2018"
        Or ``"ISO/TR 15144-1:2014"`` (older reports; the same formulas here).
    bulk_temperature : float, optional
        θ_M, °C, given (otherwise eq. (84)).
    lubricant_type : str, default "mineral"
        ``mineral``, ``pao``, ``pag``, ``pag_water_soluble``.
    density : float, optional
        ρ_15 of the oil, kg/m³.
    load_stage : int, optional
        Failure load stage SKS of the FZG test GF-C/8.3/90 (5 … 10).
    lambda_GFP : float, optional
        Permissible specific film thickness, given (replaces ``load_stage``).
    material_factor : float, optional
        W_W (default 1 for case-carburised gears; required for others when λ_GFP comes from the test).
    roughness : float or mapping gear → float, optional
        R_a of the flanks, µm (default R_z/6 of ``flank_roughness``, listed in the notes).
    lubrication : str, default "dip"
        ``dip``, ``spray`` or ``submerged`` (X_S).
    profile_modification : str, default "none"
        ``none``, ``pinion``, ``wheel``, ``both``: tips with a tip relief designed for the load (X_Y, X_Ca).
    S_lambda_min : float, default 1.0
        Minimum safety (ISO/TS 6336-22 names none; to be agreed).
    points : int, default 25
        Points of the path besides A … E for the film profile.

    References
    ----------
    ISO/TS 6336-22:2018, clauses 5–8, Annex A.
    """

    oil_temperature: float | None = None
    edition: str = EDITIONS[0]
    bulk_temperature: float | None = None
    lubricant_type: str = "mineral"
    density: float | None = None
    load_stage: int | None = None
    lambda_GFP: float | None = None
    material_factor: float | None = None
    roughness: float | Mapping[str, float] | None = None
    lubrication: str = "dip"
    profile_modification: str = "none"
    S_lambda_min: float = 1.0
    points: int = 25

    def __post_init__(self) -> None:
        if self.edition not in EDITIONS:
            raise RatingError(f"rating.micropitting.edition must be one of {', '.join(EDITIONS)}, got "
                              f"{self.edition!r}.")
        object.__setattr__(self, "oil_temperature", _number(self.oil_temperature, "oil_temperature", -40.0, 200.0))
        object.__setattr__(self, "bulk_temperature", _number(self.bulk_temperature, "bulk_temperature", -40.0, 250.0))
        object.__setattr__(self, "density", _number(self.density, "density", 0.0))
        object.__setattr__(self, "lambda_GFP", _number(self.lambda_GFP, "lambda_GFP", 0.0))
        object.__setattr__(self, "material_factor", _number(self.material_factor, "material_factor", 0.0))
        object.__setattr__(self, "S_lambda_min", _number(self.S_lambda_min, "S_lambda_min", 0.0))
        if self.lubricant_type not in LUBRICANT_TYPES:
            raise RatingError(f"rating.micropitting.lubricant_type must be one of {', '.join(LUBRICANT_TYPES)}, "
                              f"got {self.lubricant_type!r}; the default is 'mineral'.")
        if self.lubrication not in LUBRICATION:
            raise RatingError(f"rating.micropitting.lubrication must be one of {', '.join(LUBRICATION)}, got "
                              f"{self.lubrication!r}; the default is 'dip'.")
        if self.profile_modification not in TIP_RELIEF:
            raise RatingError(f"rating.micropitting.profile_modification must be one of {', '.join(TIP_RELIEF)}, "
                              f"got {self.profile_modification!r}; the default is 'none'.")
        s = self.load_stage
        if s is not None and (isinstance(s, bool) or not isinstance(s, int) or s not in FZG_TORQUES):
            raise RatingError(f"rating.micropitting.load_stage must be a whole FZG load stage 1 ... 12, got {s!r}.")
        if s is None and self.lambda_GFP is None:
            raise RatingError("rating.micropitting needs the permissible film: give load_stage (the failure load "
                              "stage SKS of the oil in the FZG test GF-C/8.3/90, e.g. 9) or lambda_GFP.")
        if self.oil_temperature is None:
            raise RatingError("rating.micropitting.oil_temperature is missing (θ_oil in degC, e.g. 70).")
        if isinstance(self.roughness, Mapping):
            object.__setattr__(self, "roughness", MappingProxyType(
                {k: _number(v, f"roughness.{k}", 0.0) for k, v in self.roughness.items()}))
        elif self.roughness is not None:
            object.__setattr__(self, "roughness", _number(self.roughness, "roughness", 0.0))
        n = self.points
        if isinstance(n, bool) or not isinstance(n, int) or not 2 <= n <= 1000:
            raise RatingError(f"rating.micropitting.points must be a whole number 2 ... 1000, got {n!r}.")

    def roughness_of(self, element: str, gear: str, rz: float) -> tuple[float, str | None]:
        """(R_a in µm, a note when it is taken as R_z/6) of ``gear`` of ``element``."""
        given = self.roughness
        if isinstance(given, Mapping):
            for key in (f"{element}:{gear}", gear, "all"):
                if key in given:
                    return given[key], None
        elif given is not None:
            return given, None
        return rz / 6.0, f"micropitting: R_a of {gear} taken as R_z/6 = {rz / 6.0:.3g} um (give roughness)"

    def to_dict(self) -> dict[str, Any]:
        """Plain data."""
        out = {k: getattr(self, k) for k in ("edition", "oil_temperature", "bulk_temperature", "lubricant_type",
                                             "density", "load_stage", "lambda_GFP", "material_factor",
                                             "lubrication", "profile_modification", "S_lambda_min", "points")}
        out["roughness"] = dict(self.roughness) if isinstance(self.roughness, Mapping) else self.roughness
        return out


def helical_load_factor(eps_gamma: float) -> float:
    """K_Bγ of the mean coefficient of friction (ISO/TR 15144-1:2014, eqs. (88)–(90); ISO/TR 13989-2).

    Examples
    --------
    >>> helical_load_factor(1.6), round(helical_load_factor(2.5), 4), helical_load_factor(4.0)
    (1.0, 1.2236, 1.3)
    """
    if eps_gamma <= 2.0:
        return 1.0
    if eps_gamma < 3.5:
        return 1.0 + 0.2 * math.sqrt((eps_gamma - 2.0) * (5.0 - eps_gamma))
    return 1.3


def _loss_factor(path: ContactPath) -> float:
    """H_V of Ohlendorf (ISO/TR 15144-1:2014, eqs. (91), (92))."""
    mesh = path.mesh
    e1 = path.rho_c1 * path.points["E"] / path.base_pitch
    e2 = -path.rho_c1 * path.points["A"] / path.base_pitch
    inv = 1.0 / mesh.gear1.teeth + (-1.0 if path.internal else 1.0) / mesh.gear2.teeth
    core = e1 ** 2 + e2 ** 2 + 1.0 - path.eps_alpha if path.eps_alpha < 2.0 else 0.5 * path.eps_alpha
    return core * inv * math.pi / math.cos(path.beta_b)


def tip_relief_factor(path: ContactPath, modification: str, grade: int) -> float:
    """X_Ca of the bulk temperature (ISO/TR 15144-1:2014, eqs. (100), (101)): 1 without tip relief or above grade 6."""
    if modification == "none" or grade > 6:
        return 1.0
    e1 = path.rho_c1 * path.points["E"] / path.base_pitch
    e2 = -path.rho_c1 * path.points["A"] / path.base_pitch
    e = max(e1, e2)
    return 1.0 + 0.24 * e + 0.71 * e ** 2


@dataclass(frozen=True)
class FilmState:
    """Method B along the path for one or more load cases (arrays ``cases + (points,)``).

    Attributes
    ----------
    scalars : mapping
        μ_m, θ_M, X_R, K_Bγ, H_V, X_Ca, X_S, X_L, E_r, G_M, η_M, α_M, R_a (numbers or per case).
    path : mapping
        Γ, X_Y, ρ_n, v_Σ, v_g, p_dyn, θ_fl, θ_B, S_GF, h, λ along the path.
    points : mapping name → index
        Index of A, AB, B, C, D, DE, E in the path arrays.
    """

    scalars: Mapping[str, Any]
    path: Mapping[str, np.ndarray]
    points: Mapping[str, int] = field(default_factory=dict)

    @property
    def lambda_min(self):
        """λ_GF,min over the points A … E of Method B (number or one per case)."""
        idx = [self.points[k] for k in POINTS]
        out = np.min(self.path["lambda"][..., idx], axis=-1)
        return float(out) if np.ndim(out) == 0 else out

    @property
    def lambda_min_at(self) -> str:
        """The point of λ_GF,min (of the first case)."""
        lam = np.atleast_2d(self.path["lambda"])[0]
        return min(POINTS, key=lambda k: lam[self.points[k]])


def film_state(path: ContactPath, oil: OilProperties, *, E_r: float, roughness: float, speed1, force,
               load_factor, oil_temperature: float, bulk_temperature: float | None = None,
               lubrication: str = "dip", x_ca: float = 1.0, thermal=(STEEL_THERMAL, STEEL_THERMAL),
               points: int = 25) -> FilmState:
    """λ_GF along the path of ``path`` for gear 1 at ``speed1`` (1/min) under F_t = ``force`` (N).

    Parameters
    ----------
    path : ContactPath
    oil : OilProperties
    E_r : float
        Reduced modulus, N/mm².
    roughness : float
        R_a = (R_a1 + R_a2)/2, µm.
    speed1, force, load_factor : float or array_like
        n1 (1/min), F_t at the reference circle (N), K_A K_γ K_v K_Hα K_Hβ; one per load case.
    oil_temperature : float
        θ_oil, °C.
    bulk_temperature : float, optional
        θ_M given, °C (otherwise eq. (84)).
    lubrication : str, default "dip"
    x_ca : float, default 1
        X_Ca (:func:`tip_relief_factor`).
    thermal : (float, float)
        B_M1, B_M2, N/(m s^0.5 K).
    points : int, default 25

    Returns
    -------
    FilmState

    References
    ----------
    ISO/TS 6336-22:2018, clause 7 (Method B); ISO/TR 15144-1:2014, eqs. (2)–(33), (79)–(92).
    """
    speed = np.abs(np.asarray(speed1, dtype=float))
    ft = np.asarray(force, dtype=float)
    kf = np.asarray(load_factor, dtype=float)
    speed, ft, kf = np.broadcast_arrays(speed, ft, kf)
    if np.any(speed <= 0):
        raise RatingError("micropitting: the mesh must turn (speed of gear 1 > 0 1/min) for a lubricant film.")
    gamma = path.gammas(points)
    st = path.state(gamma, speed, ft, math.sqrt(E_r / (2.0 * math.pi)), load_factor=kf)
    c = int(np.argmin(np.abs(gamma)))
    rho_c = float(path.relative_radius(0.0))
    v_sum_c = st.v_sum[..., c]
    eta_oil = oil.dynamic_viscosity(oil_temperature)
    x_r = 2.2 * (roughness / rho_c) ** 0.25
    k_bg = helical_load_factor(path.eps_alpha + path.eps_beta)
    f_bt = ft / math.cos(path.alpha_t)
    with np.errstate(divide="ignore"):
        mu_m = 0.045 * (kf * f_bt * k_bg / (path.face_width * v_sum_c * rho_c)) ** 0.2 * \
            (1e3 * eta_oil) ** -0.05 * x_r * oil.lubricant_factor
    h_v = _loss_factor(path)
    x_s = LUBRICATION[lubrication]
    if bulk_temperature is None:
        v_t = math.pi * path.mesh.gear1.reference_diameter * speed / 60000.0
        power = ft * v_t / 1000.0
        theta_m = oil_temperature + 7400.0 * (power * mu_m * h_v / (path.mesh.center_distance * path.face_width)) \
            ** 0.72 * x_s / (1.2 * x_ca)
    else:
        theta_m = np.full(speed.shape, float(bulk_temperature))
    theta_m_b = theta_m[..., None] if np.ndim(theta_m) else theta_m
    mu_b = mu_m[..., None] if np.ndim(mu_m) else mu_m
    theta_m_oil = np.minimum(theta_m_b, OIL_LIMIT)
    eta_m, alpha_m = oil.dynamic_viscosity(theta_m_oil), oil.pressure_viscosity(theta_m_oil)
    p_pa = st.p_H * 1e6
    denominator = thermal[0] * np.sqrt(st.v_r1) + thermal[1] * np.sqrt(st.v_r2)
    theta_fl = math.sqrt(math.pi) / 2.0 * mu_b * p_pa * st.v_slide / denominator * \
        np.sqrt(8.0 * st.rho_rel * st.p_H / (1000.0 * E_r))
    theta_b = theta_m_b + theta_fl
    hottest = float(np.max(theta_b))
    if hottest > OIL_LIMIT or float(np.max(theta_m)) > OIL_LIMIT:
        warn_validity(f"contact temperature up to {hottest:.0f} degC beyond the {OIL_LIMIT:g} degC the oil's "
                      "formulas are taken to (the mesh scuffs first); the lubricant is taken at that limit there",
                      "ISO/TS 6336-22:2018, 7 (ISO/TR 15144-1:2014, eqs. (8), (27))")
    theta_b_oil = np.minimum(theta_b, OIL_LIMIT)
    s_gf = oil.pressure_viscosity(theta_b_oil) * oil.dynamic_viscosity(theta_b_oil) / (alpha_m * eta_m)
    g_m = 1e6 * alpha_m * E_r
    u = eta_m * st.v_sum / (2000.0 * E_r * st.rho_rel)
    w = 2.0 * math.pi * st.p_H ** 2 / E_r ** 2
    h = film_thickness(st.rho_rel, g_m, u, w, s_gf)
    lam = h / roughness
    index = {k: int(np.argmin(np.abs(gamma - path.points[k]))) for k in POINTS}

    def out(x):
        x = np.asarray(x, dtype=float)
        return float(x) if x.ndim == 0 else x

    scalars = {"mu_m": out(mu_m), "theta_M": out(theta_m), "X_R": x_r, "K_Bgamma": k_bg, "H_V": h_v,
               "X_Ca": x_ca, "X_S": x_s, "X_L": oil.lubricant_factor, "E_r": E_r,
               "G_M": out(np.squeeze(g_m, -1) if np.ndim(g_m) else g_m),
               "eta_M": out(np.squeeze(eta_m, -1) if np.ndim(eta_m) else eta_m),
               "alpha_M": out(np.squeeze(alpha_m, -1) if np.ndim(alpha_m) else alpha_m),
               "eta_oil": float(eta_oil), "R_a": roughness, "rho_nC": rho_c}
    profile = {"gamma": gamma, "X": st.X, "rho_n": st.rho_rel, "v_sum": st.v_sum, "v_slide": st.v_slide,
               "p_dyn": st.p_H, "theta_fl": theta_fl, "theta_B": theta_b, "S_GF": s_gf, "h": h, "lambda": lam}
    return FilmState(MappingProxyType(scalars), MappingProxyType(profile), MappingProxyType(index))


def fzg_c_path() -> ContactPath:
    """The path of contact of the FZG gear type C (z = 16/24, m = 4.5 mm, a = 91.5 mm, b = 14 mm).

    x = 0.1817 / 0.1715, d_a = 82.46 / 118.36 mm (DIN ISO 14635-1:2006; FVA 54/7).

    References
    ----------
    DIN ISO 14635-1:2006, test gear type C; FVA information sheet 54/7 (micropitting test GF-C/8.3/90).
    """
    rack = BasicRack(4.5)
    g1 = GearGeometry(16, rack, 0.1817)
    g2 = GearGeometry(24, rack, 0.1715)
    # tip shortening to the test gears' tip diameters d_a = d + 2 m (1 + x − k)
    k1 = (g1.tip_diameter - 82.46) / (2 * 4.5)
    k2 = (g2.tip_diameter - 118.36) / (2 * 4.5)
    mesh = MeshGeometry(GearGeometry(16, rack, 0.1817, tip_shortening=k1),
                        GearGeometry(24, rack, 0.1715, tip_shortening=k2), "FZG C", working_center_distance=91.5)
    return contact_path(mesh, 14.0, accuracy_grade=5)


def permissible_film_thickness(oil: OilProperties, load_stage: int, material_factor: float = 1.0) -> dict[str, float]:
    """λ_GFT of the FZG test GF-C/8.3/90 at the failure load stage and λ_GFP = 1.4 W_W λ_GFT.

    Parameters
    ----------
    oil : OilProperties
    load_stage : int
        Failure load stage SKS (1 … 12; the test runs 5 … 10).
    material_factor : float, default 1
        W_W.

    Returns
    -------
    dict
        ``lambda_GFT``, ``lambda_GFP``, ``theta_M`` of the test gears, ``torque`` (pinion, N·m).

    References
    ----------
    ISO/TS 6336-22:2018, Annex A; ISO/TR 15144-1:2014, A.1 (λ_GFP = 1.4 W_W λ_GFT); DIN ISO 14635-1:2006.
    """
    if load_stage not in FZG_TORQUES:
        raise RatingError(f"micropitting: FZG load stage must be 1 ... 12, got {load_stage!r}.")
    if not 5 <= load_stage <= 10:
        warn_validity(f"FZG failure load stage {load_stage} lies outside the test's stages 5 ... 10; λ_GFT is "
                      "computed at that stage's torque all the same", "ISO/TS 6336-22:2018, Annex A")
    lam_t, theta = _test_film(oil.oil.viscosity_40, oil.oil.viscosity_100, oil.lubricant_type, oil.density_15,
                              load_stage)
    return {"lambda_GFT": lam_t, "lambda_GFP": 1.4 * material_factor * lam_t, "theta_M": theta,
            "torque": FZG_TORQUES[load_stage]}


@lru_cache(maxsize=64)
def _test_film(nu40: float, nu100: float, kind: str, density: float, load_stage: int) -> tuple[float, float]:
    """(λ_GF,min, θ_M) of the FZG C test gears at ``load_stage`` with this oil (once per oil and stage)."""
    oil = OilProperties(nu40, nu100, kind, density)
    path = fzg_c_path()
    torque = FZG_TORQUES[load_stage]
    d_w1 = path.mesh.operating_pitch_diameters[0]
    speed = 8.3 * 60000.0 / (math.pi * d_w1)
    force = 2000.0 * torque / path.mesh.gear1.reference_diameter
    state = film_state(path, oil, E_r=reduced_modulus(206000.0, 0.3, 206000.0, 0.3), roughness=0.5, speed1=speed,
                       force=force, load_factor=1.0, oil_temperature=90.0, lubrication="dip")
    return float(state.lambda_min), float(state.scalars["theta_M"])
