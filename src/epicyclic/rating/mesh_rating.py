"""The ISO 6336 Method B rating of one mesh, vectorised over load cases.

:class:`MeshInput` gathers what does not change with the load — the mesh geometry
(:class:`~epicyclic.geometry.MeshGeometry`), face width, materials, the tooth forms
(:mod:`~epicyclic.rating.tooth_form`), Z_H, Z_E, Z_ε, Z_B/Z_D, mesh stiffness,
deviations, Z_L, Z_R, Y_δrelT, Y_RrelT, Y_X — and :func:`rate_mesh` evaluates the
load-dependent part for one torque and speed or for arrays of them (one per load
case) in one pass::

    F_t = 2000 T1 / d1                                   (ISO 6336-1, 6.1: at the reference circle)
    σ_H0 = Z_H Z_E Z_ε Z_β √(F_t/(d1 b) (u ± 1)/u)       (ISO 6336-2, eq. (2); − internal)
    σ_H1,2 = Z_B,D σ_H0 √(K_A K_γ K_v K_Hβ K_Hα)         (eq. (1))
    σ_HG = σ_Hlim Z_NT Z_L Z_v Z_R Z_W Z_X,  σ_HP = σ_HG / S_Hmin,  S_H = σ_HG / σ_H   (eqs. (3), (4);
        Z_W of the softer gear only, 1 for the harder: ISO 6336-2, clause 12)
    σ_F0 = F_t/(b m_n) Y_F Y_S Y_β Y_B Y_DT               (ISO 6336-3, eq. (3))
    σ_F = σ_F0 K_A K_γ K_v K_Fβ K_Fα                     (eq. (2))
    σ_FG = σ_Flim Y_ST Y_NT Y_δrelT Y_RrelT Y_X Y_M,  σ_FP = σ_FG / S_Fmin,  S_F = σ_FG / σ_F

T1 is the torque on gear 1 per planet (the design torque K_γ T1 is the load of the
most loaded planet); n1 its speed relative to the carrier; the load cycles of gear i
over the required life L_h are N_L = 60 L_h |n_i| · contacts per revolution (a sun or
ring meshing p planets: p; a planet: 1 per mesh, its bending reversed where it meshes on
both flanks, Y_M = 0.7).

References
----------
ISO 6336-1:2019, 6.1 and clauses 6–9; ISO 6336-2:2019, eqs. (1)–(4); ISO 6336-3:2019,
eqs. (1)–(5) and Annex B (Y_M).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from ..geometry.gear import MeshGeometry
from . import flank, load_factors, root
from ..geometry.accuracy import base_pitch_deviation
from .errors import RatingError
from .given_factors import COMPUTED, DEFAULT, GEAR_DEVIATIONS, GIVEN, MESH_FACTORS, FactorValue
from .life_factors import bending_curve, pitting_curve
from .materials import Material
from .results import Factor, GearRating, MeshRating
from .spec import RatingSpec
from .standard import clause
from .tooth_form import ToothForm, external_tooth_form, internal_tooth_form

__all__ = ["MeshInput", "rate_mesh"]


def _running_in_alpha(m: Material, deviation: float, velocity):
    """y_α (or y_f with f_fα) by material, with the limits of the pitch line velocity (ISO 6336-1, 8.3.4)."""
    v = np.asarray(velocity, dtype=float)
    if m.surface_hardened:
        return np.full(v.shape, min(0.075 * deviation, 3.0))
    if m.treatment in ("GG", "GGG(ferr)"):
        y = 0.275 * deviation
        return np.where(v > 10.0, min(y, 11.0), np.where(v > 5.0, min(y, 22.0), y))
    y = 160.0 / m.sigma_Hlim * deviation
    return np.where(v > 10.0, min(y, 6400.0 / m.sigma_Hlim), np.where(v > 5.0, min(y, 12800.0 / m.sigma_Hlim), y))


def _running_in_beta(m: Material, f_beta, velocity):
    """y_β by material, with the limits of the pitch line velocity (ISO 6336-1, 7.6.3)."""
    v = np.asarray(velocity, dtype=float)
    if m.surface_hardened:
        return np.minimum(0.15 * f_beta, 6.0)
    if m.treatment in ("GG", "GGG(ferr)"):
        y = 0.55 * f_beta
        return np.where(v > 10.0, np.minimum(y, 22.0), np.where(v > 5.0, np.minimum(y, 45.0), y))
    y = 320.0 / m.sigma_Hlim * f_beta
    return np.where(v > 10.0, np.minimum(y, 12800.0 / m.sigma_Hlim),
                    np.where(v > 5.0, np.minimum(y, 25600.0 / m.sigma_Hlim), y))


@dataclass(frozen=True)
class MeshInput:
    """The load-independent part of a mesh's rating.

    Parameters
    ----------
    element : str
        The set or stage.
    mesh : MeshGeometry
        Gear 1 external; gear 2 external or internal.
    face_width : float
        b, mm.
    gears : (str, str)
        Names of gear 1 and gear 2 (``sun``, ``planet``, ``ring`` ...).
    spec : RatingSpec
    contacts : (float, float), default (1, 1)
        Load cycles of each gear per revolution relative to the carrier in this mesh.
    reversed_bending : (bool, bool), default (False, False)
        Gear carries fully reversed bending (an idler planet): Y_M = 0.7.
    load_sharing : float, default 1
        K_γ.
    planets : int, default 0
        Planets meshing the central gear of this mesh (for m_red of a sun mesh).
    planet_index : int, default -1
        Which gear (0 or 1) is the planet of a planetary mesh, −1 for a stage.
    load_sharing_source : str, default "given"
        Where ``load_sharing`` comes from (``"given"``, ``"default"``, a table's name ...).

    Raises
    ------
    RatingError
        A material, roughness or viscosity missing; an impossible tooth form.

    References
    ----------
    ISO 6336-1:2019, clauses 6–9; ISO 6336-2:2019; ISO 6336-3:2019.
    """

    element: str
    mesh: MeshGeometry
    face_width: float
    gears: tuple[str, str]
    spec: RatingSpec
    contacts: tuple[float, float] = (1.0, 1.0)
    reversed_bending: tuple[bool, bool] = (False, False)
    load_sharing: float = 1.0
    planets: int = 0
    planet_index: int = -1
    load_sharing_source: str = GIVEN
    static: dict[str, Any] = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        if not isinstance(self.mesh, MeshGeometry):
            raise RatingError(f"rating of {self.element!r}: mesh must be a MeshGeometry.")
        if not (isinstance(self.face_width, (int, float)) and self.face_width > 0):
            raise RatingError(f"rating of {self.element!r}: face width must be > 0 mm, got {self.face_width!r}; "
                              "give geometry.face_width.")
        object.__setattr__(self, "static", _static(self))

    @property
    def name(self) -> str:
        """The mesh's name."""
        return self.mesh.name


def _static(inp: MeshInput) -> dict[str, Any]:
    spec, mesh, b = inp.spec, inp.mesh, float(inp.face_width)
    year = spec.standard
    g1, g2 = mesh.gear1, mesh.gear2
    rack = mesh.rack
    mats = (spec.material_of(inp.element, inp.gears[0]), spec.material_of(inp.element, inp.gears[1]))
    rz_flank = [spec.roughness_of("flank_roughness", inp.element, name) for name in inp.gears]
    rz_root = [spec.roughness_of("root_roughness", inp.element, name) for name in inp.gears]
    nu40 = spec.required("viscosity_40")
    an, beta, at, awt = rack.alpha_n, rack.beta, rack.alpha_t, mesh.alpha_wt
    beta_b = math.asin(math.sin(beta) * math.cos(an))
    eps_a = mesh.contact_ratio
    eps_b = b * math.sin(beta) / (math.pi * rack.module)
    eps_g = eps_a + eps_b
    z1, z2 = g1.teeth, g2.teeth
    u = z2 / z1
    s: dict[str, Any] = {"materials": mats, "eps_alpha": eps_a, "eps_beta": eps_b, "eps_gamma": eps_g, "u": u,
                         "d1": g1.reference_diameter, "beta_b": beta_b}
    forms: list[ToothForm] = []
    for g in (g1, g2):
        common = (g.teeth, g.profile_shift, rack.module, an, beta, g.tip_diameter, eps_a)
        if g.internal:
            forms.append(internal_tooth_form(*common, dedendum=rack.dedendum, tip_radius=spec.tool_tip_radius,
                                             cutter=spec.cutter))
        else:
            forms.append(external_tooth_form(*common, dedendum=rack.dedendum, tip_radius=spec.tool_tip_radius))
    s["forms"] = forms
    s["Z_H"] = flank.zone_factor(at, awt, beta_b)
    s["Z_E"] = flank.elasticity_factor(mats[0].E, mats[0].poisson, mats[1].E, mats[1].poisson)
    s["Z_eps"] = flank.contact_ratio_factor(eps_a, eps_b)
    s["Z_beta"] = flank.helix_factor(beta)
    s["Z_B"], s["Z_D"] = flank.single_pair_factors(
        g1.tip_diameter / 2, g1.base_diameter / 2, z1, g2.tip_diameter / 2, g2.base_diameter / 2, z2, awt,
        mesh.center_distance, eps_a, eps_b, mesh.internal)
    hlim = min(m.sigma_Hlim for m in mats)
    s["Z_L"] = flank.lubricant_factor(nu40, hlim)
    rho1, rho2 = flank.pitch_curvature(g1.base_diameter / 2, g2.base_diameter / 2, awt, mesh.internal)
    s["Z_R"] = flank.roughness_factor(rz_flank[0], rz_flank[1], rho1, rho2, mesh.internal, hlim)
    s["Z_W"] = flank.work_hardening_factor(*mats)
    # Z_W raises the strength of the softer, through-hardened gear only (ISO 6336-2, 12); the hard gear: 1
    s["Z_W_gears"] = [s["Z_W"] if (other.surface_hardened and not m.surface_hardened) else 1.0
                      for m, other in ((mats[0], mats[1]), (mats[1], mats[0]))]
    s["sigma_Hlim_pair"] = hlim
    # C_a of B_k in K_v: the designed tip relief, else what running-in wears off (C_ay)
    s["C_a"] = (load_factors.running_in_tip_relief(mats[0].sigma_Hlim, mats[1].sigma_Hlim)
                if spec.tip_relief is None else spec.tip_relief)
    # stiffness (the pinion is the gear with fewer teeth), deviations, running-in
    zn = [g.teeth / (math.cos(beta_b) ** 2 * math.cos(beta)) for g in (g1, g2)]
    xs = [g1.profile_shift, g2.profile_shift]
    order = (0, 1) if (mesh.internal or z1 <= z2) else (1, 0)
    s["c_prime_th"] = load_factors.single_stiffness(
        zn[order[0]], zn[order[1]], xs[order[0]], xs[order[1]], beta, dedendum=rack.dedendum,
        pressure_angle_deg=rack.pressure_angle, internal=mesh.internal)
    s["grades"] = [spec.grade_of(inp.element, name) for name in inp.gears]
    given = {key: [spec.deviation_of(key, inp.element, name) for name in inp.gears] for key in GEAR_DEVIATIONS}
    dev = []
    for i, (q, g) in enumerate(zip(s["grades"], (g1, g2))):
        if all(given[key][i] is not None for key in GEAR_DEVIATIONS):  # all measured: no grade needed
            dev.append({key: given[key][i] for key in GEAR_DEVIATIONS})
            continue
        d = load_factors.deviations(q, g.reference_diameter, rack.module, b, spec.accuracy_standard)
        dev.append({**d, "f_pb": base_pitch_deviation(d["f_pt"], at)})
    for key in GEAR_DEVIATIONS:  # measured per gear, else from the grade; the mesh takes the larger
        s[key] = max(d[key] if v is None else v for v, d in zip(given[key], dev))
        s[key + "_source"] = _sources(given[key])
    d_m = [(g.tip_diameter + g.root_diameter) / 2 for g in (g1, g2)]
    s["m_red"] = load_factors.reduced_mass(
        d_m[0], g1.base_diameter, d_m[1], g2.base_diameter, mats[0].density, mats[1].density,
        internal=mesh.internal, planets=inp.planets if inp.planet_index >= 0 else 0,
        gear1_is_planet=inp.planet_index == 0)
    s["tooth_height"] = max(abs(g.root_diameter - g.tip_diameter) / 2 for g in (g1, g2))
    # root factors per gear
    s["Y_beta"] = root.helix_factor(beta, eps_b, year)
    eps_an = eps_a / math.cos(beta_b) ** 2
    s["Y_DT"] = root.deep_tooth_factor(eps_an, max(s["grades"]))
    s["Y_B"] = [root.rim_factor(spec.rim_of(inp.element, name), abs(g.root_diameter - g.tip_diameter) / 2,
                                rack.module, g.internal) for name, g in zip(inp.gears, (g1, g2))]
    s["Y_delta"] = [root.relative_notch_sensitivity(f.q_s, m.treatment, m.yield_strength) for f, m in zip(forms, mats)]
    s["Y_R"] = [root.relative_surface_factor(rz, m.treatment) for rz, m in zip(rz_root, mats)]
    s["Y_X"] = [root.size_factor(rack.module, m.treatment) for m in mats]
    s["Y_M"] = [root.REVERSED_BENDING if r else 1.0 for r in inp.reversed_bending]
    s["Z_curves"] = [pitting_curve(m.treatment, pitting_permitted=spec.pitting_permitted,
                                   long_life=spec.long_life, edition=year) for m in mats]
    s["Y_curves"] = [bending_curve(m.treatment, long_life=spec.long_life, edition=year) for m in mats]
    return s


def _sources(given) -> str:
    """"given", "computed", or which gear's deviation is given."""
    if all(v is None for v in given):
        return COMPUTED
    if all(v is not None for v in given):
        return GIVEN
    return f"{GIVEN} (gear {1 if given[0] is not None else 2}), {COMPUTED} (gear {2 if given[0] is not None else 1})"


def _factor(symbol: str, value, given: FactorValue | None, computed_clause: str, name: str, given_clause: str) -> Factor:
    """The Factor row of a load factor: the given FactorValue's source and clause, or computed by the clause."""
    if given is None:
        return Factor(symbol, _out(value), "1", computed_clause, name, COMPUTED)
    return Factor(symbol, _out(value), "1", given.clause or given_clause, name, given.source)


def _deviation_clause(source: str, from_grade: str) -> str:
    if source == GIVEN:
        return "ISO 6336-1, 6.3 and 8.3 (measured, given)"
    return from_grade if source == COMPUTED else f"{from_grade}; measured (given)"


def _safety(strength, stress):
    stress = np.asarray(stress, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(stress > 0, np.asarray(strength, dtype=float) / np.where(stress > 0, stress, 1.0), np.inf)


def _out(value):
    array = np.asarray(value, dtype=float)
    return float(array) if array.ndim == 0 else array


def rate_mesh(inp: MeshInput, torque, speed, *, hours: float | None = None) -> MeshRating:
    """Rate one mesh at torque ``torque`` on gear 1 (N·m, per planet) and speed ``speed`` (1/min).

    Parameters
    ----------
    inp : MeshInput
        The mesh and its load-independent data.
    torque : float or array_like
        Torque on gear 1 per planet (per load path), N·m; one per load case for an array.
    speed : float or array_like
        Speed of gear 1 relative to the carrier (to the housing for a stage), 1/min.
    hours : float, optional
        Required life the life factors are for (default ``inp.spec.life``), h.

    Returns
    -------
    MeshRating
        Factors as numbers, or arrays of the cases' shape.

    Raises
    ------
    RatingError
        Torque or speed not finite.

    References
    ----------
    ISO 6336-1:2019, 6.1; ISO 6336-2:2019, eqs. (1)–(4); ISO 6336-3:2019, eqs. (1)–(5).
    """
    s, spec, mesh = inp.static, inp.spec, inp.mesh
    year = spec.standard
    t1 = np.abs(np.asarray(torque, dtype=float))
    n1 = np.abs(np.asarray(speed, dtype=float))
    if not (np.all(np.isfinite(t1)) and np.all(np.isfinite(n1))):
        raise RatingError(f"rating of {inp.element!r} {mesh.name}: torque and speed must be finite numbers.")
    t1, n1 = np.broadcast_arrays(t1, n1)
    hours = spec.life if hours is None else hours
    b, d1, rack = float(inp.face_width), s["d1"], mesh.rack
    p1, p2, p3 = (lambda w: clause(1, year, w)), (lambda w: clause(2, year, w)), (lambda w: clause(3, year, w))
    given = {key: spec.given_factor(key, inp.element, mesh.name) for key in MESH_FACTORS}
    ka_f = given["application_factor"] or FactorValue(1.0, DEFAULT, p1("6.2, uniform driver and load (default)"))
    kg_f = given["load_sharing"] or FactorValue(float(inp.load_sharing), inp.load_sharing_source, p1("6.5.9"))
    ka, kg = ka_f.value, kg_f.value
    f_t = 2000.0 * t1 / d1
    v = math.pi * d1 * n1 / 60000.0
    line = ka * kg * f_t / b
    mats = s["materials"]
    y_a = 0.5 * (_running_in_alpha(mats[0], s["f_pb"], v) + _running_in_alpha(mats[1], s["f_pb"], v))
    y_f = 0.5 * (_running_in_alpha(mats[0], s["f_falpha"], v) + _running_in_alpha(mats[1], s["f_falpha"], v))
    f_pb_eff, f_f_eff = np.maximum(0.0, s["f_pb"] - y_a), np.maximum(0.0, s["f_falpha"] - y_f)
    c_p, c_ga, c_gb = load_factors.mesh_stiffness(s["c_prime_th"], s["eps_alpha"], line)
    k_v, resonance, _ = load_factors.dynamic_factor(
        n1, mesh.gear1.teeth, c_ga, c_p, s["m_red"], line, f_pb_eff, f_f_eff, s["eps_gamma"], s["C_a"])
    if given["K_v"] is not None:
        k_v = np.full(np.shape(k_v), given["K_v"].value)
    f_m = line * k_v
    f_bx = np.maximum.reduce([np.full(f_m.shape, 1.33 * spec.shaft_deflection + s["f_Hbeta"]), 0.005 * f_m,
                              np.full(f_m.shape, 0.5 * s["f_Hbeta"])])
    y_b = 0.5 * (_running_in_beta(mats[0], f_bx, v) + _running_in_beta(mats[1], f_bx, v))
    k_hb_given = None if given["K_Hbeta"] is None else given["K_Hbeta"].value
    k_hb, k_fb = load_factors.face_load_factors(k_hb_given, f_m, c_gb, f_bx, y_b, b, s["tooth_height"])
    if given["K_Fbeta"] is not None:
        k_fb = np.full(np.shape(k_hb), given["K_Fbeta"].value)
    k_ha, k_fa = load_factors.transverse_load_factors(f_m * k_hb, c_ga, f_pb_eff, s["eps_alpha"],
                                                       s["eps_gamma"], s["Z_eps"], year)
    if given["K_Halpha"] is not None:
        k_ha = np.full(np.shape(k_ha), given["K_Halpha"].value)
        if given["K_Falpha"] is None:  # K_Fα = K_Hα (ISO 6336-1, 8.3): the given one for both
            given["K_Falpha"] = replace(given["K_Halpha"], clause=p1("8.3, K_Falpha = K_Halpha (given)"))
    if given["K_Falpha"] is not None:
        k_fa = np.full(np.shape(k_fa), given["K_Falpha"].value)
    u = s["u"]
    ratio = (u - 1.0) / u if mesh.internal else (u + 1.0) / u
    sigma_h0 = s["Z_H"] * s["Z_E"] * s["Z_eps"] * s["Z_beta"] * np.sqrt(f_t / (d1 * b) * ratio)
    load_h = ka * kg * k_v * k_hb * k_ha
    z_v = flank.speed_factor(v, s["sigma_Hlim_pair"])
    speeds = (n1, n1 * mesh.gear1.teeth / mesh.gear2.teeth)
    m_n = rack.module
    gears = []
    for i, (name, mat) in enumerate(zip(inp.gears, mats)):
        cycles = np.maximum(60.0 * hours * speeds[i] * inp.contacts[i], 1.0)
        z_nt = s["Z_curves"][i].factor(cycles)
        y_nt = s["Y_curves"][i].factor(cycles)
        z_bd = s["Z_B"] if i == 0 else s["Z_D"]
        sigma_h = z_bd * sigma_h0 * np.sqrt(load_h)
        sigma_hg = mat.sigma_Hlim * z_nt * s["Z_L"] * z_v * s["Z_R"] * s["Z_W_gears"][i] * 1.0
        form = s["forms"][i]
        sigma_f0 = f_t / (b * m_n) * form.Y_F * form.Y_S * s["Y_beta"] * s["Y_B"][i] * s["Y_DT"]
        sigma_f = sigma_f0 * ka * kg * k_v * k_fb * k_fa
        sigma_fg = (mat.sigma_Flim * root.Y_ST * y_nt * s["Y_delta"][i] * s["Y_R"][i] * s["Y_X"][i]
                    * s["Y_M"][i])
        f = [
            Factor("N_L", _out(cycles), "1", "ISO 6336-2/-3, 60 L_h n contacts", "load cycles over the life"),
            Factor("Z_B" if i == 0 else "Z_D", z_bd, "1", p2("6.2"), "single pair tooth contact factor"),
            Factor("sigma_H", _out(sigma_h), "N/mm^2", p2("eq. (1)"), "contact stress"),
            Factor("Z_NT", _out(z_nt), "1", p2("10, Table 2"), "life factor (pitting)"),
            Factor("sigma_Hlim", mat.sigma_Hlim, "N/mm^2", "ISO 6336-5:2016, Table 1", "allowable stress number"),
            Factor("Z_W", s["Z_W_gears"][i], "1", p2("12"), "work hardening factor (1 for the harder gear)"),
            Factor("sigma_HG", _out(sigma_hg), "N/mm^2", p2("eq. (4)"), "pitting stress limit"),
            Factor("sigma_HP", _out(sigma_hg / spec.S_Hmin), "N/mm^2", p2("eq. (3)"), "permissible contact stress"),
            Factor("S_H", _out(_safety(sigma_hg, sigma_h)), "1", p2("eq. (4)"), "safety factor for pitting"),
            Factor("Y_F", form.Y_F, "1", p3("6.2" if not mesh.gear2.internal or i == 0 else "6.3"),
                   f"tooth form factor ({form.method})"),
            Factor("Y_S", form.Y_S, "1", p3("7.2, eq. (41)"), "stress correction factor"),
            Factor("Y_B", s["Y_B"][i], "1", p3("7.4"), "rim thickness factor"),
            Factor("s_Fn", form.s_Fn, "mm", p3("eq. (12)"), "tooth root chord at the critical section"),
            Factor("h_Fe", form.h_Fe, "mm", p3("eq. (20)"), "bending moment arm"),
            Factor("rho_F", form.rho_F, "mm", p3("eq. (13)"), "root fillet radius at the critical section"),
            Factor("sigma_F0", _out(sigma_f0), "N/mm^2", p3("eq. (3)"), "nominal tooth root stress"),
            Factor("sigma_F", _out(sigma_f), "N/mm^2", p3("eq. (2)"), "tooth root stress"),
            Factor("Y_NT", _out(y_nt), "1", p3("12, Table 3"), "life factor (root)"),
            Factor("Y_deltarelT", s["Y_delta"][i], "1", p3("13.2"), "relative notch sensitivity factor"),
            Factor("Y_RrelT", s["Y_R"][i], "1", p3("14.2"), "relative surface factor"),
            Factor("Y_X", s["Y_X"][i], "1", p3("15, Table 6"), "size factor (root)"),
            Factor("Y_M", s["Y_M"][i], "1", "ISO 6336-5:2016, 5.4; ISO 6336-3 Annex B", "mean stress factor"),
            Factor("Y_ST", root.Y_ST, "1", p3("11"), "stress correction factor of the test gear"),
            Factor("sigma_Flim", mat.sigma_Flim, "N/mm^2", "ISO 6336-5:2016, Table 1", "nominal stress number"),
            Factor("sigma_FG", _out(sigma_fg), "N/mm^2", p3("eq. (5)"), "tooth root stress limit"),
            Factor("sigma_FP", _out(sigma_fg / spec.S_Fmin), "N/mm^2", p3("eq. (4)"), "permissible root stress"),
            Factor("S_F", _out(_safety(sigma_fg, sigma_f)), "1", p3("eq. (5)"), "safety factor for bending"),
        ]
        gears.append(GearRating(name, {x.symbol: x for x in f}, spec.S_Hmin, spec.S_Fmin, s["Z_curves"][i],
                                s["Y_curves"][i], float(hours)))
    accuracy = f"ISO 1328-1:{spec.accuracy_standard}, grade {'/'.join(map(str, sorted(set(s['grades']))))}"
    mesh_factors = [
        Factor("F_t", _out(f_t), "N", p1("6.1"), "nominal tangential force at the reference circle"),
        Factor("v", _out(v), "m/s", p1("6.1"), "pitch line velocity (relative to the carrier)"),
        Factor("u", u, "1", p2("eq. (2)"), "gear ratio z2/z1"),
        Factor("b", b, "mm", p2("eq. (2)"), "face width"),
        Factor("d_1", d1, "mm", "ISO 21771:2007", "reference diameter of gear 1"),
        Factor("m_n", m_n, "mm", "ISO 21771:2007", "normal module"),
        Factor("epsilon_alpha", s["eps_alpha"], "1", "ISO 21771:2007", "transverse contact ratio"),
        Factor("epsilon_beta", s["eps_beta"], "1", "ISO 21771:2007", "overlap ratio"),
        _factor("K_A", ka, ka_f, "", "application factor", p1("6.2 (given)")),
        _factor("K_gamma", kg, kg_f, "", "load sharing factor of the planets", p1("6.5.9 (given)")),
        Factor("c_prime", _out(c_p), "N/(mm*µm)", p1("9.3.1"), "single stiffness"),
        Factor("c_gamma_alpha", _out(c_ga), "N/(mm*µm)", p1("9.3.2"), "mesh stiffness"),
        Factor("m_red", s["m_red"], "kg/mm", p1("6.5.9"), "reduced mass per face width"),
        Factor("N", _out(resonance), "1", p1("6.3, eq. (13)"), "resonance ratio"),
        Factor("C_a", s["C_a"], "µm", p1("6.3" if spec.tip_relief is not None else "6.3 (C_ay, running-in)"),
               "tip relief in K_v", GIVEN if spec.tip_relief is not None else COMPUTED),
        _factor("K_v", k_v, given["K_v"], p1("6.3 (method B)"), "dynamic factor", p1("6 (given)")),
        Factor("f_pb", s["f_pb"], "µm", _deviation_clause(s["f_pb_source"], f"{accuracy}, f_pb = f_pt cos α_t"),
               "transverse base pitch deviation", s["f_pb_source"]),
        Factor("f_falpha", s["f_falpha"], "µm", _deviation_clause(s["f_falpha_source"], accuracy),
               "profile form deviation", s["f_falpha_source"]),
        Factor("f_Hbeta", s["f_Hbeta"], "µm", _deviation_clause(s["f_Hbeta_source"], accuracy),
               "helix slope deviation", s["f_Hbeta_source"]),
        Factor("y_alpha", _out(y_a), "µm", p1("8.3.4"), "running-in allowance (pitch)"),
        Factor("y_f", _out(y_f), "µm", p1("6.3 and 8.3.4"), "running-in allowance (profile form)"),
        Factor("F_betax", _out(f_bx), "µm", p1("7.6 (method C)"), "initial equivalent misalignment"),
        _factor("K_Hbeta", k_hb, given["K_Hbeta"], p1("7.6 (method C)"), "face load factor (contact)",
                p1("7 (given)")),
        _factor("K_Fbeta", k_fb, given["K_Fbeta"], p1("7.7, eq. (45)"), "face load factor (root)", p1("7.7 (given)")),
        _factor("K_Halpha", k_ha, given["K_Halpha"], p1("8.3 (method B)"), "transverse load factor (contact)",
                p1("8 (given)")),
        _factor("K_Falpha", k_fa, given["K_Falpha"], p1("8.3 (method B)"), "transverse load factor (root)",
                p1("8 (given)")),
        Factor("Z_H", s["Z_H"], "1", p2("6.1, eq. (9)"), "zone factor"),
        Factor("Z_E", s["Z_E"], "sqrt(N/mm^2)", p2("7, eq. (10)"), "elasticity factor"),
        Factor("Z_epsilon", s["Z_eps"], "1", p2("8, eq. (13)"), "contact ratio factor"),
        Factor("Z_beta", s["Z_beta"], "1", p2("9, eq. (14)"), "helix angle factor (pitting)"),
        Factor("sigma_H0", _out(sigma_h0), "N/mm^2", p2("eq. (2)"), "nominal contact stress"),
        Factor("Z_L", s["Z_L"], "1", p2("11.2"), "lubricant factor"),
        Factor("Z_v", _out(z_v), "1", p2("11.3"), "velocity factor"),
        Factor("Z_R", s["Z_R"], "1", p2("11.4"), "roughness factor"),
        Factor("Z_W", s["Z_W"], "1", p2("12"), "work hardening factor of the softer gear of the pair"),
        Factor("Z_X", 1.0, "1", p2("13"), "size factor (pitting)"),
        Factor("Y_beta", s["Y_beta"], "1", p3("7.3"), "helix angle factor (root)"),
        Factor("Y_DT", s["Y_DT"], "1", p3("7.5"), "deep tooth factor"),
    ]
    method_c = (f"K_Hbeta by method C from F_betax = 1.33 f_sh + f_Hbeta "
                f"(f_Hbeta = {s['f_Hbeta']:.1f} µm, {s['f_Hbeta_source']})")
    notes = tuple(spec.notes) + ((method_c,) if given["K_Hbeta"] is None else ())
    return MeshRating(inp.element, mesh.name, f"ISO 6336:{year}", "B", {x.symbol: x for x in mesh_factors},
                      (gears[0], gears[1]), mesh.internal, notes)
