"""The scuffing rating of a mesh and of every mesh of a train, beside its ISO 6336 rating.

:func:`scuffing_input` builds the load-independent :class:`~.methods.ScuffingInput` of a
:class:`~epicyclic.rating.mesh_rating.MeshInput` (its path of contact from
:mod:`epicyclic.rating.contact_path`, the oil at θ_oil, X_M, X_mp); :func:`rate_scuffing` takes the
load of the mesh from its :class:`~epicyclic.rating.results.MeshRating` (F_t, v, K_A, K_γ, K_v,
K_Hβ = K_Bβ, K_Hα = K_Bα, c_γα, C_a: the same factors, per load case) and evaluates both methods;
:func:`rate_train_scuffing` does so for every mesh of a :class:`~epicyclic.rating.results.TrainRating`.

Defaults taken (and said in the notes): gear 1 of the mesh in the role of the pinion (the planet of
a ring mesh); without ``driving`` X_Q = 1 and the approach factor X_J at both ends of the path; the
multiple meshing factor X_mp = (1 + n_p)/2 with n_p the meshes of the busiest gear of the mesh (a sun or ring with N
planets: N, a planet between sun and ring: 2); the load sharing X_Γ of unmodified profiles.

References
----------
ISO/TS 6336-20:2017; ISO/TS 6336-21:2017; ISO/TR 13989-1, -2:2000; DIN 3990-4:1987 (X_mp).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np

from ...losses.errors import LossModelError
from ...losses.oil import Oil
from ..contact_path import contact_path
from ..errors import RatingError
from ..results import Factor, MeshRating, TrainRating
from . import factors
from .methods import C_1, C_2, C_FLASH, ScuffingInput, ScuffingLoad, flash_temperature, integral_temperature
from .results import ScuffingRating
from .spec import ScuffingSpec

__all__ = ["multiple_meshing_factor", "rate_scuffing", "rate_train_scuffing", "scuffing_input", "scuffing_modes"]


def multiple_meshing_factor(inp) -> float:
    """X_mp = (1 + n_p)/2, n_p the number of meshes of the busiest gear of ``inp``.

    A central gear meshing N planets has N, a planet between sun and ring (reversed bending) 2,
    any other gear 1.

    References
    ----------
    DIN 3990-4:1987 and ISO/TR 13989-2:2000 (multiple meshing factor X_mp).
    """
    meshes = [c if c > 1 else (2.0 if r else 1.0) for c, r in zip(inp.contacts, inp.reversed_bending)]
    return (1.0 + max(meshes)) / 2.0


def scuffing_input(inp, scuffing: ScuffingSpec | None = None, *, points: int = 41) -> ScuffingInput:
    """The load-independent scuffing data of ``inp`` (its spec's ``scuffing`` unless given).

    Parameters
    ----------
    inp : MeshInput
        The mesh (:class:`~epicyclic.rating.mesh_rating.MeshInput`).
    scuffing : ScuffingSpec, optional
    points : int, default 41
        Points of the flash temperature along the path.

    Returns
    -------
    ScuffingInput

    Raises
    ------
    RatingError
        No scuffing inputs, no ν_100 (the oil at θ_oil), θ_oil outside the oil's range.

    References
    ----------
    ISO/TS 6336-20:2017; ISO/TS 6336-21:2017.
    """
    spec = inp.spec
    sspec = scuffing if scuffing is not None else getattr(spec, "scuffing", None)
    if sspec is None:
        raise RatingError("rating.scuffing is missing: give [rating.scuffing] with load_stage, oil_temperature "
                          "and roughness_Ra (see docs/rating.md, Scuffing).")
    nu40 = spec.required("viscosity_40")
    if spec.viscosity_100 is None:
        raise RatingError("rating.lubricant.viscosity_100 is missing (ν at 100 degC in mm^2/s, for the oil's "
                          "viscosity at the oil temperature of the scuffing rating); give it - e.g. "
                          "viscosity_100 = 19.0 for an ISO VG 220 mineral oil.")
    try:
        oil = Oil(nu40, spec.viscosity_100, density=sspec.oil_density)
        eta = float(oil.dynamic_viscosity(sspec.oil_temperature))
    except LossModelError as exc:
        raise RatingError(f"rating.scuffing: {exc}") from None
    m1, m2 = spec.material_of(inp.element, inp.gears[0]), spec.material_of(inp.element, inp.gears[1])
    x_m = factors.thermo_elastic_factor(m1.E, m1.poisson, m2.E, m2.poisson, sspec.contact_coefficient)
    ra = 0.5 * sum(sspec.roughness_of(inp.element, g) for g in inp.gears)
    x_mp = sspec.multiple_meshing if sspec.multiple_meshing is not None else multiple_meshing_factor(inp)
    path = contact_path(inp.mesh, float(inp.face_width), accuracy_grade=min(spec.accuracy_grade, 12))
    return ScuffingInput(path, sspec, nu40, eta, ra, x_m, x_mp, points)


def _factor(symbol, value, unit, clause, name):
    array = np.asarray(value, dtype=float)
    return Factor(symbol, float(array) if array.ndim == 0 else array, unit, clause, name)


def rate_scuffing(si: ScuffingInput, rating: MeshRating, *, element: str = "", gears=("gear 1", "gear 2"),
                  notes: Sequence[str] = ()) -> ScuffingRating:
    """Both scuffing methods for the load of ``rating`` (one value per load case where it has several).

    Parameters
    ----------
    si : ScuffingInput
    rating : MeshRating
        The ISO 6336 rating of the same mesh (its F_t, v, K_A, K_γ, K_v, K_Hβ, K_Hα, c_γα, C_a).
    element : str, optional
        Defaults to the rating's.
    gears : (str, str)
        Names of gear 1 and gear 2.
    notes : sequence of str
        Carried into the result.

    Returns
    -------
    ScuffingRating

    References
    ----------
    ISO/TS 6336-21:2017 (integral temperature); ISO/TS 6336-20:2017 (flash temperature).
    """
    s, d, p = si.spec, si.derived, si.path
    fl, it = s.clauses
    stiffness = rating["c_gamma_alpha"] if p.eps_beta > 0 else rating["c_prime"]  # C_eff: c_γ helical, c' spur
    load = ScuffingLoad(rating["F_t"], rating["v"], rating["K_A"], rating["K_gamma"], rating["K_v"],
                        rating["K_Hbeta"], rating["K_Halpha"], stiffness, float(rating["C_a"]))
    r = integral_temperature(si, load)
    f = flash_temperature(si, load)
    t_1t = d["T_1T"]
    given_int = s.integral_scuffing_temperature is not None
    integral = [
        _factor("theta_oil", s.oil_temperature, "°C", it, "oil temperature"),
        _factor("w_Bt", r["w_Bt"], "N/mm", it, "transverse unit load K_A K_gamma K_v K_Bbeta K_Balpha F_t/b"),
        _factor("K_Bgamma", d["K_Bgamma"], "1", it, "helical load factor"),
        _factor("X_M", si.thermo_elastic, "K·N^-3/4·s^1/2·m^-1/2·mm", it,
                f"thermo-elastic factor (B_M = {s.contact_coefficient:g} N/(mm·s^0.5·K))"),
        _factor("X_BE", d["X_BE"], "1", it, "geometry factor at the tip of gear 1"),
        _factor("X_alphabeta", d["X_alphabeta"], "1", it, "angle factor"),
        _factor("epsilon_1", d["eps_1"], "1", it, "addendum contact ratio of gear 1"),
        _factor("epsilon_2", d["eps_2"], "1", it, "addendum contact ratio of gear 2"),
        _factor("X_epsilon", d["X_epsilon"], "1", it, "contact ratio factor"),
        _factor("C_eff", r["C_eff"], "µm", it, "effective tip relief K_A F_t/(b c_gamma) (c' of a spur pair)"),
        _factor("C_a", load.tip_relief, "µm", it, "tip relief (as in K_v)"),
        _factor("X_Ca", r["X_Ca"], "1", it, "tip relief factor"),
        _factor("X_E", d["X_E"], "1", it, f"running-in factor (phi_E = {s.run_in:g})"),
        _factor("X_Q", d["X_Q"], "1", it, "approach factor" + ("" if s.driving else " (no driving gear given: 1)")),
        _factor("rho_redC", d["rho_redC"], "mm", it, "relative radius of curvature at the pitch point"),
        _factor("eta_oil", si.viscosity, "mPa·s", it, f"dynamic viscosity at {s.oil_temperature:g} °C"),
        _factor("R_a", si.roughness, "µm", it, "mean arithmetic roughness of the flanks"),
        _factor("X_L", d["X_L"], "1", it, f"lubricant factor ({s.oil_type} oil)"),
        _factor("mu_mC", r["mu_mC"], "1", it, "mean coefficient of friction"),
        _factor("theta_flaE", r["theta_flaE"], "K", it, "flash temperature at the tip of gear 1"),
        _factor("theta_flaint", r["theta_flaint"], "K", it, "mean flash temperature"),
        _factor("X_S", d["X_S"], "1", it, f"lubrication factor ({s.lubrication})"),
        _factor("X_mp", si.multiple_meshing, "1", it, "multiple meshing factor"),
        _factor("theta_M", r["theta_M"], "°C", it, f"bulk temperature theta_oil + {C_1} X_S X_mp theta_flaint"),
        _factor("theta_int", r["theta_int"], "°C", it, f"integral temperature theta_M + {C_2} theta_flaint"),
        _factor("X_WrelT", s.structural_factor, "1", it, "relative structural factor"),
        *([_factor("T_1T", t_1t, "N·m", "ISO 14635-1:2000, Table 2",
                   f"FZG A/8.3/90 pinion torque of load stage {s.load_stage}")] if t_1t is not None else []),
        _factor("theta_intS", d["theta_intS"], "°C", it,
                "permissible integral temperature" + (" (given)" if given_int else " from the FZG load stage")),
        _factor("S_intS", r["S_intS"], "1", it, "safety factor for scuffing (integral temperature)"),
        _factor("S_SL", r["S_SL"], "1", it, "safety for the transmittable torque"),
    ]
    flash = [
        _factor("mu_m", f["mu_m"], "1", fl, "mean coefficient of friction (as mu_mC)"),
        _factor("X_J", f["X_J_max"], "1", fl, "approach factor at the highest contact temperature"),
        _factor("theta_flm", f["theta_flm"], "K", fl, "mean flash temperature along the path"),
        _factor("theta_M", f["theta_M"], "°C", fl, f"bulk temperature theta_oil + {C_FLASH} X_S X_mp theta_flm"),
        _factor("theta_flmax", np.max(f["theta_fl"], axis=-1), "K", fl, "highest flash temperature"),
        _factor("theta_Bmax", f["theta_Bmax"], "°C", fl, "highest contact temperature theta_M + theta_fl"),
        _factor("Gamma_max", f["gamma_max"], "1", fl, "parameter Gamma of the highest contact temperature"),
        _factor("X_Gamma", f["X_Gamma_max"], "1", fl, "load sharing factor there"),
        _factor("X_L_S", d["X_L_flash"], "1", fl, "lubricant factor of theta_S, X_L eta_oil^-0.05"),
        _factor("X_W", s.structural_factor, "1", fl, "structural factor"),
        _factor("theta_S", d["theta_S"], "°C", fl, "scuffing temperature" + (
            " (given)" if s.scuffing_temperature is not None else f" of FZG load stage {s.load_stage}")),
        _factor("S_B", f["S_B"], "1", fl, "safety factor for scuffing (flash temperature)"),
    ]
    path = {"gamma": d["gamma"], "X_Gamma": d["X_Gamma"], "theta_fl": f["theta_fl"], "theta_B": f["theta_B"]}
    base = ["mu_m of the flash method = mu_mC (the integral method's)",
            "X_Gamma of unmodified profiles (ISO/TS 6336-20 load sharing without designed tip relief)"]
    if not s.driving:
        base.append("no driving gear given: X_Q = 1 and X_J at both ends of the path (on the safe side)")
    if np.any(np.asarray(load.velocity) > 50.0) or np.any(np.asarray(r["w_Bt"]) < 150.0):
        base.append("mu_mC evaluated at w_Bt >= 150 N/mm and v <= 50 m/s, the friction formula's range")
    if p.accuracy_grade > 6:
        base.append(f"accuracy grade {p.accuracy_grade} coarser than 6: no tip relief credited (X_Ca = 1)")
    if np.any(load.tip_relief > np.asarray(r["C_eff"])):
        base.append(f"C_a = {load.tip_relief:g} µm above C_eff (down to {_low(r['C_eff']):.3g} µm): X_Ca with "
                    "C_a = C_eff, as the standard limits it")
    return ScuffingRating(element or rating.element, rating.mesh, tuple(gears), it, fl,
                          {x.symbol: x for x in integral}, {x.symbol: x for x in flash}, path, s.S_Smin, s.S_Bmin,
                          tuple(notes) + tuple(base))


def _low(value) -> float:
    return float(np.min(np.asarray(value, dtype=float)))


def rate_train_scuffing(planned, rating: TrainRating, scuffing: ScuffingSpec | None = None,
                        inputs=None) -> tuple[ScuffingRating, ...]:
    """The scuffing rating of every mesh of ``rating`` (``planned`` from :func:`~epicyclic.rating.mesh_inputs`).

    Parameters
    ----------
    planned : sequence of PlannedMesh, or the (planned, skipped) pair of mesh_inputs
        The meshes ``rating`` was rated from, in its order.
    rating : TrainRating
    scuffing : ScuffingSpec, optional
        Defaults to the meshes' spec's ``scuffing``.
    inputs : sequence of ScuffingInput, optional
        Built already (reuse across gears).

    Returns
    -------
    tuple of ScuffingRating

    Raises
    ------
    RatingError
        The meshes do not match the rating, missing scuffing inputs.

    References
    ----------
    ISO/TS 6336-20:2017; ISO/TS 6336-21:2017.
    """
    if len(planned) == 2 and isinstance(planned[1], Mapping):  # mesh_inputs' (planned, skipped)
        planned = planned[0]
    if len(planned) != len(rating.meshes):
        raise RatingError(f"scuffing: {len(planned)} planned meshes but the rating has {len(rating.meshes)}.")
    inputs = inputs if inputs is not None else [scuffing_input(p.input, scuffing) for p in planned]
    out = []
    for item, si, mesh in zip(planned, inputs, rating.meshes):
        if (item.input.element, item.input.mesh.name) != (mesh.element, mesh.mesh):
            raise RatingError(f"scuffing: planned mesh {item.input.element} {item.input.mesh.name} does not match "
                              f"the rating's {mesh.element} {mesh.mesh}.")
        out.append(rate_scuffing(si, mesh, element=mesh.element, gears=item.input.gears))
    return tuple(out)



def scuffing_modes(inp, rating: MeshRating) -> tuple:
    """The two :class:`~epicyclic.rating.mode_results.ModeRating` s of a mesh (integral, flash) for ``rate_mesh``.

    Parameters
    ----------
    inp : MeshInput
        With ``spec.scuffing``.
    rating : MeshRating
        The ISO 6336 rating of the same load.

    Returns
    -------
    tuple of ModeRating
        ``scuffing_integral`` (S_intS) and ``scuffing_flash`` (S_B).

    References
    ----------
    ISO/TS 6336-21:2017; ISO/TS 6336-20:2017.
    """
    return rate_scuffing(scuffing_input(inp), rating, element=inp.element, gears=inp.gears).modes()
