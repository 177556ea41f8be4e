"""The worked rating of one mesh: every equation of ISO 6336 Method B with its numbers.

``MeshRating.explain(gear)`` and ``epicyclic rate FILE --explain MESH`` show, for gear
``gear`` (0: gear 1, 1: gear 2) of a rated mesh, the chain from the tangential force to
both safeties, each line an equation, the numbers put in, the result and the clause.
Where the mesh was rated over several load cases, the case with the lowest pitting
safety is shown.

References
----------
ISO 6336-1:2019, 6.1; ISO 6336-2:2019, eqs. (1)–(4); ISO 6336-3:2019, eqs. (1)–(5).
"""

from __future__ import annotations

import numpy as np

__all__ = ["worked_rating"]


def _pick(value, index):
    array = np.asarray(value, dtype=float)
    return float(array.reshape(-1)[index]) if array.size > 1 else float(array.reshape(-1)[0])


def worked_rating(mesh, gear: int = 0) -> str:
    """The worked rating of gear ``gear`` of ``mesh`` as text.

    Parameters
    ----------
    mesh : MeshRating
        A rated mesh (:func:`~epicyclic.rating.mesh_rating.rate_mesh`).
    gear : int, default 0
        0 for gear 1, 1 for gear 2.

    Returns
    -------
    str

    Raises
    ------
    IndexError
        ``gear`` is not 0 or 1.

    References
    ----------
    ISO 6336-2:2019, eqs. (1)–(4); ISO 6336-3:2019, eqs. (1)–(5).
    """
    g = mesh.gears[gear]
    case = int(np.argmin(np.asarray(g.S_H, dtype=float).reshape(-1)))
    m = {k: _pick(f.value, case) for k, f in mesh.factors.items()}
    q = {k: _pick(f.value, case) for k, f in g.factors.items()}
    c = {**{k: f.clause for k, f in mesh.factors.items()}, **{k: f.clause for k, f in g.factors.items()}}
    zbd = "Z_B" if gear == 0 else "Z_D"
    sign = "−" if mesh.internal else "+"
    lines = [f"Worked rating of {g.gear} in mesh {mesh.mesh} of {mesh.element} ({mesh.standard}, method B)"
             + (f", load case {case + 1}" if np.asarray(g.S_H).size > 1 else ""), ""]

    def eq(text: str, value: float, unit: str, key: str) -> None:
        lines.append(f"  {text} = {value:.6g} {unit}".rstrip() + (f"    [{c.get(key, '')}]" if c.get(key) else ""))

    eq("F_t = 2000 T1 / d1", m["F_t"], "N", "F_t")
    eq("v = π d1 n1 / 60000", m["v"], "m/s", "v")
    eq(f"K_v = f(N = {m['N']:.4g}, B_p, B_f, B_k)  (c' = {m['c_prime']:.4g}, c_γα = {m['c_gamma_alpha']:.4g} "
       f"N/(mm µm), m_red = {m['m_red']:.4g} kg/mm)", m["K_v"], "", "K_v")
    eq(f"K_Hβ  (F_βx = {m['F_betax']:.4g} µm)", m["K_Hbeta"], "", "K_Hbeta")
    eq("K_Fβ = K_Hβ^N_F", m["K_Fbeta"], "", "K_Fbeta")
    eq("K_Hα", m["K_Halpha"], "", "K_Halpha")
    eq("K_Fα", m["K_Falpha"], "", "K_Falpha")
    lines.append("")
    lines.append("Pitting (ISO 6336-2)")
    eq(f"σ_H0 = Z_H Z_E Z_ε Z_β √(F_t/(d1 b) (u {sign} 1)/u) = {m['Z_H']:.4f} · {m['Z_E']:.2f} · "
       f"{m['Z_epsilon']:.4f} · {m['Z_beta']:.4f} · √({m['F_t']:.6g}/({m['d_1']:.4f} · {m['b']:g}) · "
       f"(u {sign} 1)/u), "
       f"u = {m['u']:.4f}", m["sigma_H0"], "N/mm²", "sigma_H0")
    eq(f"σ_H = {zbd} σ_H0 √(K_A K_γ K_v K_Hβ K_Hα) = {q[zbd]:.4f} · {m['sigma_H0']:.2f} · √({m['K_A']:.3f} · "
       f"{m['K_gamma']:.3f} · {m['K_v']:.4f} · {m['K_Hbeta']:.4f} · {m['K_Halpha']:.4f})", q["sigma_H"], "N/mm²",
       "sigma_H")
    eq(f"σ_HG = σ_Hlim Z_NT Z_L Z_v Z_R Z_W Z_X = {q['sigma_Hlim']:g} · {q['Z_NT']:.4f} · {m['Z_L']:.4f} · "
       f"{m['Z_v']:.4f} · {m['Z_R']:.4f} · {m['Z_W']:.4f} · {m['Z_X']:.4f}  (N_L = {q['N_L']:.4g})",
       q["sigma_HG"], "N/mm²", "sigma_HG")
    eq(f"σ_HP = σ_HG / S_Hmin = {q['sigma_HG']:.2f} / {g.S_Hmin:g}", q["sigma_HP"], "N/mm²", "sigma_HP")
    eq(f"S_H = σ_HG / σ_H = {q['sigma_HG']:.2f} / {q['sigma_H']:.2f}", q["S_H"],
       "(≥ S_Hmin {:g}: {})".format(g.S_Hmin, "yes" if q["S_H"] >= g.S_Hmin else "NO"), "S_H")
    lines.append("")
    lines.append("Tooth root (ISO 6336-3)")
    eq(f"Y_F = 6 (h_Fe/m_n) cos α_Fen / ((s_Fn/m_n)² cos α_n)  (s_Fn = {q['s_Fn']:.4f} mm, h_Fe = {q['h_Fe']:.4f} mm)",
       q["Y_F"], "", "Y_F")
    eq(f"Y_S = (1.2 + 0.13 L) q_s^(1/(1.21 + 2.3/L))  (ρ_F = {q['rho_F']:.4f} mm)", q["Y_S"], "", "Y_S")
    eq(f"σ_F0 = F_t/(b m_n) Y_F Y_S Y_β Y_B Y_DT = {m['F_t']:.6g}/({m['b']:g} · {m['m_n']:g}) · {q['Y_F']:.4f} · "
       f"{q['Y_S']:.4f} · {m['Y_beta']:.4f} · {q['Y_B']:.4f} · {m['Y_DT']:.4f}", q["sigma_F0"], "N/mm²", "sigma_F0")
    eq(f"σ_F = σ_F0 K_A K_γ K_v K_Fβ K_Fα = {q['sigma_F0']:.2f} · {m['K_A']:.3f} · {m['K_gamma']:.3f} · "
       f"{m['K_v']:.4f} · {m['K_Fbeta']:.4f} · {m['K_Falpha']:.4f}", q["sigma_F"], "N/mm²", "sigma_F")
    eq(f"σ_FG = σ_Flim Y_ST Y_NT Y_δrelT Y_RrelT Y_X Y_M = {q['sigma_Flim']:g} · {q['Y_ST']:g} · {q['Y_NT']:.4f} · "
       f"{q['Y_deltarelT']:.4f} · {q['Y_RrelT']:.4f} · {q['Y_X']:.4f} · {q['Y_M']:.2f}", q["sigma_FG"], "N/mm²",
       "sigma_FG")
    eq(f"σ_FP = σ_FG / S_Fmin = {q['sigma_FG']:.2f} / {g.S_Fmin:g}", q["sigma_FP"], "N/mm²", "sigma_FP")
    eq(f"S_F = σ_FG / σ_F = {q['sigma_FG']:.2f} / {q['sigma_F']:.2f}", q["S_F"],
       "(≥ S_Fmin {:g}: {})".format(g.S_Fmin, "yes" if q["S_F"] >= g.S_Fmin else "NO"), "S_F")
    return "\n".join(lines) + "\n"
