"""The loss step of the worked solution: η0 at the point, μ and H_V per mesh, each spin-loss source.

:func:`loss_step` re-evaluates the loss models of a solved train at its state
(the element speeds and torques, the oil temperature) and writes out, equation
by equation with the numbers substituted:

* per element with a mesh model: H_V (Ohlendorf) and μ (given, or Schlenk's
  correlation of ISO/TR 14179-2) of every mesh, the mesh factor Π (1 − μ H_V),
  the bearing factor and η0 at the point; the drag torques Σ c_i |n|^i;
* the oil: ν by Walther's equation (ASTM D341), ρ, η = ρ ν at the temperature;
* per open clutch or brake: the film flow Q(r_o) against the supply, the film
  edge r_e and the drag T = N f_g π η ω (r_e⁴ − r_i⁴) / (2h) (Yuan et al. 2007);
* the pump T = V Δp / (2π η_hm), churning (Changenet & Velex 2007), windage,
  seals (7.69·10⁻⁶ d² n, ISO/TR 14179-2) and the heat balance P_Q = P_V
  (ISO/TR 14179-1);
* the sum P_V = Σ sources, equal to the solver's loss.

References
----------
Ohlendorf 1958 (H_V); ISO/TR 14179-2:2001 (μ_mZ, P_VD); ISO/TR 14179-1:2001 (P_Q = P_V);
ASTM D341-20; Yuan et al. 2007; Changenet & Velex 2007; see docs/losses.md.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from .io.tables import fmt
from .model import Clutch
from .model.elements import HOUSING

__all__ = ["loss_step", "LOSS_TEXT", "model_efficiency"]

RPM = math.pi / 30.0

LOSS_TEXT = {
    "en": {
        "title": "6. Losses by source (the loss models at this point)",
        "eta0": "η0 at the point = mesh factor · bearing factor = {mesh} · {bearing} = {eta0} (set {name!r})",
        "mesh": "mesh {mesh}: H_V = {hv} (Ohlendorf), μ = {mu} ({model}) → 1 − μ·H_V = 1 − {mu}·{hv} = {eta}",
        "schlenk": "Schlenk: μ = 0.048·(F_bt/b / (v_ΣC·ρ_C))^0.2·η_oil^−0.05·R_a^0.25·X_L, η_oil = {eta} mPa·s",
        "given_mu": "μ given",
        "own": "{name}: no mesh model; η0 = {eta0} as given",
        "bearing": "planet bearings: η_bearing = {eta} (SKF, M = 0.5·μ·P·d)",
        "drag": "drag torque on {member}: T = Σ c_i·|n|^i = {torque} N·m at n = {speed} 1/min → P = T·ω = {loss} W",
        "oil": "oil at ϑ = {t} °C: Walther (ASTM D341) log log(ν + 0.7) = A − B·log T → ν = {nu} mm²/s; "
               "ρ = ρ15·(1 − α·(ϑ − 15)) = {rho} kg/m³; η = ρ·ν = {eta} mPa·s",
        "clutch": "{name} open, slip Δn = {slip} 1/min (ω = {omega} rad/s): film flow Q(r_o) = π ρ ω² h³ (r_o² − "
                  "r_i²)/(40 η ln(r_o/r_i)) = {flow} l/min per gap, supply {supply} → film to r_e = {re} mm",
        "clutch_t": "    T = N·f_g·π·η·ω·(r_e⁴ − r_i⁴)/(2h) = {gaps}·{groove}·π·{eta}e-3·{omega}·({re}⁴ − {ri}⁴)e-12/"
                    "(2·{h}e-3) = {film} N·m film (Yuan et al. 2007) + {mist} N·m oil mist r_e … r_o (Iqbal et al. 2013) "
                    "= {torque} N·m → P = T·ω = {loss} W",
        "engaged": "{name} engaged: no drag",
        "pump": "pump on {shaft}: T = V·Δp/(2π·η_hm) = {v}e-6·{p}e5/(2π·{eta}) = {torque} N·m at n = {speed} "
                "1/min → P = {loss} W",
        "churning": "churning of the gear on {shaft}: C_m = {cm} (Changenet & Velex 2007, Re_c = {rec}), "
                    "T = ½ ρ ω² S_m R_p³ C_m = {torque} N·m → P = {loss} W",
        "windage": "windage of the gear on {shaft}: C_M = {cm} (free disc, Re = {re}), "
                   "T = ½ C_M ρ ω² R⁵ (1 + 2.3 b/R) = {torque} N·m → P = {loss} W",
        "seal": "seals on {shaft}: P = {count}·7.69e-6·d²·n = {count}·7.69e-6·{d}²·{speed} = {loss} W "
                "(ISO/TR 14179-2, Simrit)",
        "thermal": "heat balance (ISO/TR 14179-1): P_Q(ϑ) = A·[h_c·Δϑ + ε·σ·(T⁴ − T_a⁴)] + k_cool·(ϑ − ϑ_c) = {q} W "
                   "= P_V at ϑ = {t} °C",
        "sum": "P_V = {terms} = {total} W (solver: {solver} W)",
        "none": "no loss model: every loss is the typed-in η0's",
        "defaults": "defaults used (docs/file-format.md; refuse with defaults = \"refuse\"): ",
    },
    "de": {
        "title": "6. Verluste nach Quellen (die Verlustmodelle in diesem Betriebspunkt)",
        "eta0": "η0 im Betriebspunkt = Verzahnungsfaktor · Lagerfaktor = {mesh} · {bearing} = {eta0} (Satz {name!r})",
        "mesh": "Eingriff {mesh}: H_V = {hv} (Ohlendorf), μ = {mu} ({model}) → 1 − μ·H_V = 1 − {mu}·{hv} = {eta}",
        "schlenk": "Schlenk: μ = 0.048·(F_bt/b / (v_ΣC·ρ_C))^0.2·η_Öl^−0.05·R_a^0.25·X_L, η_Öl = {eta} mPa·s",
        "given_mu": "μ vorgegeben",
        "own": "{name}: kein Verzahnungsmodell; η0 = {eta0} wie vorgegeben",
        "bearing": "Planetenlager: η_Lager = {eta} (SKF, M = 0.5·μ·P·d)",
        "drag": "Schleppmoment an {member}: T = Σ c_i·|n|^i = {torque} N·m bei n = {speed} 1/min → P = T·ω = {loss} W",
        "oil": "Öl bei ϑ = {t} °C: Walther (ASTM D341) log log(ν + 0.7) = A − B·log T → ν = {nu} mm²/s; "
               "ρ = ρ15·(1 − α·(ϑ − 15)) = {rho} kg/m³; η = ρ·ν = {eta} mPa·s",
        "clutch": "{name} offen, Differenzdrehzahl Δn = {slip} 1/min (ω = {omega} rad/s): Filmstrom Q(r_o) = "
                  "π ρ ω² h³ (r_o² − r_i²)/(40 η ln(r_o/r_i)) = {flow} l/min je Spalt, Zufluss {supply} → Film bis "
                  "r_e = {re} mm",
        "clutch_t": "    T = N·f_g·π·η·ω·(r_e⁴ − r_i⁴)/(2h) = {gaps}·{groove}·π·{eta}e-3·{omega}·({re}⁴ − {ri}⁴)e-12/"
                    "(2·{h}e-3) = {film} N·m Film (Yuan et al. 2007) + {mist} N·m Ölnebel r_e … r_o (Iqbal et al. 2013) "
                    "= {torque} N·m → P = T·ω = {loss} W",
        "engaged": "{name} geschlossen: kein Schleppmoment",
        "pump": "Pumpe an {shaft}: T = V·Δp/(2π·η_hm) = {v}e-6·{p}e5/(2π·{eta}) = {torque} N·m bei n = {speed} "
                "1/min → P = {loss} W",
        "churning": "Planschen des Rades auf {shaft}: C_m = {cm} (Changenet & Velex 2007, Re_c = {rec}), "
                    "T = ½ ρ ω² S_m R_p³ C_m = {torque} N·m → P = {loss} W",
        "windage": "Ventilation des Rades auf {shaft}: C_M = {cm} (freie Scheibe, Re = {re}), "
                   "T = ½ C_M ρ ω² R⁵ (1 + 2.3 b/R) = {torque} N·m → P = {loss} W",
        "seal": "Dichtungen an {shaft}: P = {count}·7.69e-6·d²·n = {count}·7.69e-6·{d}²·{speed} = {loss} W "
                "(ISO/TR 14179-2, Simrit)",
        "thermal": "Wärmebilanz (ISO/TR 14179-1): P_Q(ϑ) = A·[α_K·Δϑ + ε·σ·(T⁴ − T_U⁴)] + k_Kühler·(ϑ − ϑ_K) = {q} W "
                   "= P_V bei ϑ = {t} °C",
        "sum": "P_V = {terms} = {total} W (Löser: {solver} W)",
        "none": "kein Verlustmodell: alle Verluste stammen aus dem vorgegebenen η0",
        "defaults": "verwendete Vorgabewerte (docs/file-format.md; ablehnen mit defaults = \"refuse\"): ",
    },
}


def model_efficiency(state) -> float | None:
    """η0 the solver applied to a set or stage (from its factor η0^w), None where no rolling power flows."""
    w = state.loss_direction
    if w == 0:
        return None
    return state.efficiency_factor if w == 1 else 1.0 / state.efficiency_factor


def loss_step(solution, losses: Mapping[str, Any] | None, spin, lang: str = "en", *, gear: str | None = None,
              input: str | None = None) -> tuple[str, tuple[str, ...]] | None:
    """The title and lines of the loss step, or None without any loss model.

    Parameters
    ----------
    solution : Solution
        Solved with the models (:func:`~epicyclic.losses.solve_with_losses`).
    losses : mapping element → ElementLosses or None
        The mesh, bearing and drag models.
    spin : SpinLosses or None
        The spin losses and the oil.
    lang : {"en", "de"}
    gear : str, optional
        The gear (a pump pressure by gear).
    input : str, optional
        The transmission's input (drives the pump by default).

    Returns
    -------
    tuple (str, tuple of str) or None

    References
    ----------
    Ohlendorf 1958; ISO/TR 14179-1, -2:2001; ASTM D341-20; Yuan et al. 2007; Changenet & Velex 2007.
    """
    losses = dict(losses or {})
    if not losses and spin is None:
        return None
    t = LOSS_TEXT[lang]
    lines: list[str] = []
    temperature = solution.oil_temperature
    viscosity = None
    if spin is not None and spin.oil is not None and temperature is not None:
        eta, nu, rho = (float(v) for v in spin.oil_state(temperature))
        viscosity = eta
        lines.append(t["oil"].format(t=fmt(temperature, 4), nu=fmt(nu, 5), rho=fmt(rho, 5), eta=fmt(eta, 5)))
    for name, model in losses.items():
        state = solution.elements[name]
        speeds = {p: np.array([state.speeds[p]]) for p in model.ports if p != HOUSING}
        torques = {p: np.array([state.torques[p]]) for p in model.ports if p != HOUSING}
        evaluated = model.evaluate(speeds, torques, viscosity)
        if model.friction is None:
            own = model.element.stationary_efficiency if hasattr(model.element, "stationary_efficiency") \
                else model.element.efficiency
            lines.append(t["own"].format(name=name, eta0=fmt(own, 6)))
        else:
            label = t["given_mu"] if not hasattr(model.friction, "roughness") else t["schlenk"].format(
                eta=fmt(viscosity if viscosity is not None else model.friction.lubricant.viscosity, 5))
            for mesh, mu in zip(model.meshes, evaluated.friction):
                mu_value = float(np.ravel(mu)[0])
                lines.append(t["mesh"].format(mesh=mesh.mesh.name, hv=fmt(mesh.loss_factor, 5), mu=fmt(mu_value, 4),
                                              model=label, eta=fmt(1.0 - mu_value * mesh.loss_factor, 6)))
            if model.bearing_efficiency != 1.0:
                lines.append("    " + t["bearing"].format(eta=fmt(model.bearing_efficiency, 6)))
            mesh_factor = float(np.ravel(evaluated.factors["mesh"])[0])
            lines.append("    " + t["eta0"].format(mesh=fmt(mesh_factor, 6), bearing=fmt(model.bearing_efficiency, 6),
                                                   eta0=fmt(mesh_factor * model.bearing_efficiency, 6), name=name))
        for term in model.drag:
            n_rel = state.speeds[term.member] - (state.speeds[term.relative_to] if term.relative_to != HOUSING else 0.0)
            lines.append(t["drag"].format(member=term.member, torque=fmt(float(term.torque(n_rel)), 5),
                                          speed=fmt(n_rel, 6), loss=fmt(float(term.loss(n_rel)), 5)))
    if spin is not None:
        lines.extend(_spin_lines(solution, spin, t, temperature, gear, input))
    totals = solution.loss_sources
    terms = " + ".join(f"{fmt(v, 5)} ({k})" for k, v in totals.items() if v)
    lines.append(t["sum"].format(terms=terms or "0", total=fmt(sum(totals.values()), 6), solver=fmt(solution.loss, 6)))
    return t["title"], tuple(lines)


def _spin_lines(solution, spin, t, temperature, gear, input) -> list[str]:
    lines: list[str] = []
    eta, nu, rho = spin.oil_state(temperature if temperature is not None else 80.0)
    speed = {s: st.speed for s, st in solution.shafts.items()}
    speed[HOUSING] = 0.0
    elements = {e.name: e for e in solution.train.elements}
    for drag in spin.clutch_drag:
        element = elements[drag.element]
        if element.engaged:
            lines.append(t["engaged"].format(name=drag.element))
            continue
        first, second = (element.first, element.second) if isinstance(element, Clutch) else (element.shaft, HOUSING)
        slip = speed[first] - speed[second]
        torque = float(drag.torque(slip, eta, rho))
        r_e = float(drag.film_radius(slip, eta, rho))
        supply = "—" if drag.supply is None else f"{fmt(drag.supply / drag.gaps, 4)} l/min"
        lines.append(t["clutch"].format(name=drag.element, slip=fmt(slip, 6), omega=fmt(abs(slip) * RPM, 5),
                                        flow=fmt(float(drag.film_flow(slip, eta, rho)), 4), supply=supply,
                                        re=fmt(r_e, 5)))
        lines.append(t["clutch_t"].format(gaps=drag.gaps, groove=fmt(drag.groove_factor, 3), eta=fmt(float(eta), 5),
                                          omega=fmt(abs(slip) * RPM, 5), re=fmt(r_e, 5), ri=fmt(drag.inner_radius, 5),
                                          h=fmt(drag.clearance, 4), torque=fmt(torque, 5),
                                          film=fmt(float(drag.film_torque(slip, eta, rho)), 5),
                                          mist=fmt(float(drag.mist_torque(slip, eta, rho)), 5),
                                          loss=fmt(torque * abs(slip) * RPM, 5)))
    if spin.pump is not None:
        shaft = spin.pump.shaft or input
        n = speed.get(shaft, 0.0)
        lines.append(t["pump"].format(shaft=shaft, v=fmt(spin.pump.displacement, 4), p=fmt(spin.pump.pressure_in(gear), 4),
                                      eta=fmt(spin.pump.efficiency, 3), torque=fmt(spin.pump.torque(gear), 5),
                                      speed=fmt(n, 6), loss=fmt(float(spin.pump.loss(n, gear)), 5)))
    for dipped in spin.churning:
        n = speed[dipped.shaft]
        rec = abs(n) * RPM * dipped.pitch_radius * dipped.face_width * 1e-6 / (float(nu) * 1e-6)
        lines.append(t["churning"].format(shaft=dipped.shaft, cm=fmt(float(dipped.coefficient(n, nu)), 4),
                                          rec=fmt(rec, 4), torque=fmt(float(dipped.torque(n, nu, rho)), 5),
                                          loss=fmt(float(dipped.loss(n, nu, rho)), 5)))
    for fast in spin.windage:
        n = speed[fast.shaft]
        re = abs(n) * RPM * (fast.radius * 1e-3) ** 2 / (fast.kinematic_viscosity * 1e-6)
        lines.append(t["windage"].format(shaft=fast.shaft, cm=fmt(float(fast.coefficient(n)), 4), re=fmt(re, 4),
                                         torque=fmt(float(fast.torque(n)), 5), loss=fmt(float(fast.loss(n)), 5)))
    for seal in spin.seals:
        n = speed[seal.shaft]
        lines.append(t["seal"].format(shaft=seal.shaft, count=seal.count, d=fmt(seal.diameter, 4), speed=fmt(n, 6),
                                      loss=fmt(float(seal.loss(n)), 5)))
    if spin.defaults:
        lines.append(t["defaults"] + "; ".join(spin.defaults))
    if spin.thermal and temperature is not None:
        lines.append(t["thermal"].format(q=fmt(float(spin.housing.dissipated(temperature)), 5),
                                         t=fmt(temperature, 4)))
    return lines
