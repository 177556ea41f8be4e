"""One mesh: closed-form scalings (hypothesis), vectorised = per case, bad input, JSON."""

import json
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from epicyclic.geometry import BasicRack, GearGeometry, MeshGeometry
from epicyclic.rating import MeshInput, RatingError, RatingSpec, material, rate_mesh

RACK = BasicRack(4.0)
PAIR = MeshGeometry(GearGeometry(19, RACK, 0.5), GearGeometry(104, RACK, 0.15)).with_tip_shortening()
RING = MeshGeometry(GearGeometry(24, BasicRack(2.0), 0.2), GearGeometry(72, BasicRack(2.0), 0.2, internal=True))


def spec(**kw):
    base = {"material": "18CrNiMo7-6", "flank_roughness": 3.0, "root_roughness": 10.0, "viscosity_40": 100.0,
            "K_Hbeta": 1.2, "application_factor": 1.0}
    base.update(kw)
    return RatingSpec(**base)


def rated(torque, width=48.0, mesh=PAIR, speed=1e-3, **kw):
    return rate_mesh(MeshInput("pair", mesh, width, ("pinion", "wheel"), spec(**kw)), torque, speed)


def test_the_independent_implementation_shares_the_nominal_values():
    # hanslhansl/din3990 tests/test_1.py: P = 55 kW at 980 1/min, b = 48.64 mm: F_t = 14103.4187 N, v = 3.8998 m/s
    r = rated(55000 / (980 * math.pi / 30), 48.64, speed=980)
    assert r["F_t"] == pytest.approx(14103.41869503906, rel=1e-12)
    assert r["v"] == pytest.approx(3.89976368065613, rel=1e-12)
    assert r["Z_H"] == pytest.approx(2.3959406670899934, rel=1e-12)


@settings(max_examples=20, deadline=None)
@given(st.floats(2000.0, 20000.0), st.floats(1.2, 4.0))
def test_pitting_safety_scales_with_one_over_root_torque(torque, factor):
    # K_v = 1 (at rest), K_Hβ given, K_Hα at its lower limit 1 at these loads: S_H ∝ 1/√T, S_F ∝ 1/T
    a, b = rated(torque), rated(torque * factor)
    for ga, gb in zip(a.gears, b.gears):
        assert gb.S_H == pytest.approx(ga.S_H / math.sqrt(factor), rel=1e-6)
        assert gb.S_F == pytest.approx(ga.S_F / factor, rel=1e-6)


@pytest.mark.parametrize("mesh", [PAIR, RING], ids=["external", "internal"])
def test_doubling_the_face_width_halves_the_root_stress(mesh):
    narrow, wide = rated(3000.0, 30.0, mesh), rated(3000.0, 60.0, mesh)
    for gn, gw in zip(narrow.gears, wide.gears):
        assert gw["sigma_F0"] == pytest.approx(gn["sigma_F0"] / 2, rel=1e-12)
        assert 0.45 < gw["sigma_F"] / gn["sigma_F"] < 0.55
        assert gw["sigma_H"] / gn["sigma_H"] == pytest.approx(1 / math.sqrt(2), rel=0.03)


def test_vectorised_cases_equal_the_per_case_loop():
    inp = MeshInput("pair", PAIR, 48.0, ("pinion", "wheel"), spec(K_Hbeta=None, application_factor=1.25))
    torques, speeds = np.linspace(200.0, 4000.0, 7), np.linspace(10.0, 6000.0, 7)
    batch = rate_mesh(inp, torques, speeds)
    for k, (t, n) in enumerate(zip(torques, speeds)):
        one = rate_mesh(inp, t, n)
        for symbol, f in one.factors.items():
            assert np.asarray(batch.factors[symbol].value).reshape(-1)[k if np.ndim(batch.factors[symbol].value)
                                                                     else 0] == pytest.approx(f.value, rel=1e-12)
        for gb, go in zip(batch.gears, one.gears):
            assert gb.S_H[k] == pytest.approx(go.S_H, rel=1e-12) and gb.S_F[k] == pytest.approx(go.S_F, rel=1e-12)


def test_editions_differ_only_where_the_standard_does():
    helical = MeshGeometry(GearGeometry(23, BasicRack(3.0, helix_angle=15), 0.0),
                           GearGeometry(61, BasicRack(3.0, helix_angle=15), 0.0)).with_tip_shortening()
    old, new = (rated(800.0, 40.0, helical, standard=s) for s in ("2006", "2019"))
    assert new["Y_beta"] == pytest.approx(old["Y_beta"] / math.cos(math.radians(15)) ** 3)
    assert new.gears[0].S_H == pytest.approx(old.gears[0].S_H, rel=1e-12)
    assert new.gears[0].S_F < old.gears[0].S_F
    assert old.standard == "ISO 6336:2006" and new.factors["Y_beta"].clause.startswith("ISO 6336-3:2019")


def test_zero_load_has_unbounded_safety_and_clean_json():
    r = rated(0.0)
    assert math.isinf(r.gears[0].S_H)
    text = json.dumps(r.to_dict(), allow_nan=False)
    assert '"S_H": {"value": null' in text


@pytest.mark.parametrize(("missing", "message"), [
    ("material", r"rating\.material is missing .* '18CrNiMo7-6'"),
    ("flank_roughness", r"rating\.flank_roughness is missing .* 3\.0"),
    ("root_roughness", r"rating\.root_roughness is missing .* 10\.0"),
    ("viscosity_40", r"rating\.viscosity_40 is missing .*viscosity_40 = 100\.0"),
])
def test_missing_input_names_the_key_and_the_default(missing, message):
    with pytest.raises(RatingError, match=message):
        MeshInput("pair", PAIR, 48.0, ("pinion", "wheel"), spec(**{missing: None}))


def test_material_per_gear_and_bad_values():
    s = spec(material={"pinion": "18CrNiMo7-6", "wheel": "42CrMo4"})
    r = rate_mesh(MeshInput("pair", PAIR, 48.0, ("pinion", "wheel"), s), 2000.0, 500.0)
    assert r.gears[1]["sigma_Hlim"] < r.gears[0]["sigma_Hlim"] and r["Z_W"] > 1.0
    # Z_W raises the softer (through-hardened) wheel only, never the case-carburised pinion (ISO 6336-2, 12)
    assert r.gears[1]["Z_W"] == r["Z_W"] and r.gears[0]["Z_W"] == 1.0
    hard = r.gears[0]
    assert hard["sigma_HG"] == pytest.approx(hard["sigma_Hlim"] * hard["Z_NT"] * r["Z_L"] * r["Z_v"] * r["Z_R"],
                                             rel=1e-12)
    with pytest.raises(RatingError, match="no entry for gear 'wheel'"):
        MeshInput("pair", PAIR, 48.0, ("pinion", "wheel"), spec(material={"pinion": material("16MnCr5")}))
    with pytest.raises(RatingError, match="standard"):
        spec(standard="1996")
    with pytest.raises(RatingError, match="S_Fmin"):
        spec(S_Fmin=0)


def test_a_thin_ring_rim_raises_the_root_stress():
    solid = rated(500.0, 30.0, RING)
    thin = rated(500.0, 30.0, RING, rim_thickness={"wheel": 5.0})            # s_R/m_n = 2.5
    assert thin.gears[1]["Y_B"] == pytest.approx(1.15 * math.log(8.324 / 2.5))
    assert thin.gears[1]["sigma_F"] == pytest.approx(solid.gears[1]["sigma_F"] * thin.gears[1]["Y_B"], rel=1e-12)
    assert thin.gears[0]["Y_B"] == 1.0 and thin.gears[0]["sigma_F"] == solid.gears[0]["sigma_F"]


def test_internal_mesh_uses_the_difference_of_curvatures():
    r = rated(500.0, 30.0, RING)
    assert r.internal and r.gears[1]["Z_D"] == 1.0
    assert r.gears[1].factors["Y_F"].name.endswith("(rack (basic rack), no tool given)")


def test_damage_over_cases_is_miner_on_the_life_factor_curves():
    inp = MeshInput("pair", PAIR, 48.0, ("pinion", "wheel"), spec())
    r = rate_mesh(inp, np.array([400.0, 700.0]), np.array([500.0, 500.0]), hours=1000.0)
    g = r.gears[0]
    d_h, d_f = g.damage([400.0, 600.0])
    expected = 0.0
    for k, hours in enumerate((400.0, 600.0)):
        ratio = g["sigma_H"][k] / (g["sigma_HG"][k] / g["Z_NT"][k])
        expected += g["N_L"][k] / 1000.0 * hours / g.pitting_curve.cycles_to_failure(ratio)
    assert 0 < d_h < math.inf and d_h == pytest.approx(expected, rel=1e-12) and 0 < d_f < math.inf
    # the whole required life at one case: D = 1 exactly where S_H = 1 ... and D < 1 where S_H > 1
    one = rate_mesh(inp, 700.0, 500.0, hours=1000.0).gears[0]
    assert (one.damage(1000.0)[0] < 1.0) == (one.S_H > 1.0)


@pytest.mark.parametrize("mesh", [PAIR, RING], ids=["external", "internal"])
def test_stresses_and_safeties_are_the_products_of_their_factors(mesh):
    # ISO 6336-2 eqs. (1)-(4), ISO 6336-3 eqs. (1)-(5), factor by factor from the reported values
    r = rate_mesh(MeshInput("pair", mesh, 30.0, ("pinion", "wheel"), spec(K_Hbeta=None, application_factor=1.4),
                            load_sharing=1.15), 800.0, 2500.0)
    m = r.factors
    f = {k: v.value for k, v in m.items()}
    u = f["u"]
    ratio = (u - 1) / u if mesh.internal else (u + 1) / u
    assert f["F_t"] == pytest.approx(2000 * 800 / mesh.gear1.reference_diameter)
    sigma_h0 = f["Z_H"] * f["Z_E"] * f["Z_epsilon"] * f["Z_beta"] * math.sqrt(f["F_t"] / (f["d_1"] * f["b"]) * ratio)
    assert f["sigma_H0"] == pytest.approx(sigma_h0, rel=1e-12)
    load_h = f["K_A"] * f["K_gamma"] * f["K_v"] * f["K_Hbeta"] * f["K_Halpha"]
    load_f = f["K_A"] * f["K_gamma"] * f["K_v"] * f["K_Fbeta"] * f["K_Falpha"]
    assert f["K_gamma"] == 1.15 and f["K_A"] == 1.4
    for g, zbd in zip(r.gears, ("Z_B", "Z_D")):
        q = {k: v.value for k, v in g.factors.items()}
        assert q["sigma_H"] == pytest.approx(q[zbd] * sigma_h0 * math.sqrt(load_h), rel=1e-12)
        limit_h = q["sigma_Hlim"] * q["Z_NT"] * f["Z_L"] * f["Z_v"] * f["Z_R"] * q["Z_W"] * f["Z_X"]
        assert q["S_H"] == pytest.approx(limit_h / q["sigma_H"], rel=1e-12)
        assert q["sigma_HP"] == pytest.approx(limit_h / g.S_Hmin, rel=1e-12)
        sigma_f0 = f["F_t"] / (f["b"] * f["m_n"]) * q["Y_F"] * q["Y_S"] * f["Y_beta"] * q["Y_B"] * f["Y_DT"]
        assert q["sigma_F"] == pytest.approx(sigma_f0 * load_f, rel=1e-12)
        limit_f = (q["sigma_Flim"] * q["Y_ST"] * q["Y_NT"] * q["Y_deltarelT"] * q["Y_RrelT"] * q["Y_X"]
                   * q["Y_M"])
        assert q["S_F"] == pytest.approx(limit_f / q["sigma_F"], rel=1e-12)
        assert q["sigma_FP"] == pytest.approx(limit_f / g.S_Fmin, rel=1e-12)


@pytest.mark.parametrize("internal", [False, True])
def test_nominal_contact_stress_is_hertz_at_the_pitch_point(internal):
    # Hertz, two cylinders of radii ρ1, ρ2 (ρ2 concave for a ring): p = √(F_n E* / (π b R)),
    # 1/R = 1/ρ1 ± 1/ρ2, ρ = r sin α_t, F_n = F_t / cos α_t, 1/E* = Σ (1 − ν²)/E (Johnson, Contact Mechanics, 4.2)
    rack = BasicRack(3.0)
    mesh = (MeshGeometry(GearGeometry(25, rack), GearGeometry(75, rack, internal=True)) if internal
            else MeshGeometry(GearGeometry(25, rack), GearGeometry(50, rack)))
    r = rated(400.0, 30.0, mesh)
    alpha = math.radians(20)
    rho1, rho2 = (g.reference_diameter / 2 * math.sin(alpha) for g in (mesh.gear1, mesh.gear2))
    inv_r = 1 / rho1 - 1 / rho2 if internal else 1 / rho1 + 1 / rho2
    e_star = 1 / (2 * (1 - 0.3 ** 2) / 206000.0)
    f_n = 2000 * 400.0 / mesh.gear1.reference_diameter / math.cos(alpha)
    hertz = math.sqrt(f_n * e_star * inv_r / (math.pi * 30.0))
    assert r["sigma_H0"] / r["Z_epsilon"] == pytest.approx(hertz, rel=1e-12)


def test_a_given_dynamic_factor_replaces_method_b():
    # ISO 6336-1, 6: K_v may be given (measured, method A); σ_H ∝ √K_v, σ_F ∝ K_v otherwise unchanged
    computed = rated(3000.0, speed=3000.0)
    given = rated(3000.0, speed=3000.0, K_v=1.3)
    assert given["K_v"] == 1.3 and computed["K_v"] != 1.3
    assert given.factors["K_v"].clause.endswith("6 (given)")
    ratio = 1.3 / computed["K_v"]
    for a, b in zip(computed.gears, given.gears):
        assert b["sigma_H"] == pytest.approx(a["sigma_H"] * math.sqrt(ratio), rel=1e-9)
        assert b["sigma_F"] == pytest.approx(a["sigma_F"] * ratio, rel=1e-9)
    with pytest.raises(RatingError, match="K_v"):
        spec(K_v=0.5)


def test_without_a_tip_relief_k_v_takes_the_running_in_value():
    # ISO 6336-1:2006, 6.3: C_ay = (σ_Hlim/97 − 18.45)²/18 + 1.5 µm per gear, the pair's mean
    from epicyclic.rating.load_factors import running_in_tip_relief

    assert running_in_tip_relief(1500, 1500) == pytest.approx((1500 / 97 - 18.45) ** 2 / 18 + 1.5, rel=1e-12)
    assert running_in_tip_relief(1500, 700) == pytest.approx(0.5 * (1.99538 + 8.51063), abs=1e-5)
    default, none, given = (rated(3000.0, speed=3000.0, **kw) for kw in ({}, {"tip_relief": 0.0},
                                                                         {"tip_relief": 10.0}))
    assert default["C_a"] == pytest.approx(running_in_tip_relief(1500, 1500), rel=1e-12)
    assert none["C_a"] == 0.0 and given["C_a"] == 10.0
    # B_k = |1 − c' C_a/(K_A F_t/b)| falls with C_a here, and K_v with it
    assert given["K_v"] < default["K_v"] < none["K_v"]


def test_roughness_per_gear():
    # Z_R from the mean R_z of the pair (ISO 6336-2, eq. (28)); Y_RrelT from each gear's root R_z
    per_gear = rated(3000.0, flank_roughness={"pinion": 2.0, "wheel": 4.0}, root_roughness={"pinion": 5.0,
                                                                                              "all": 20.0})
    mean = rated(3000.0, flank_roughness=3.0, root_roughness=5.0)
    coarse = rated(3000.0, root_roughness=20.0)
    assert per_gear["Z_R"] == pytest.approx(mean["Z_R"], rel=1e-12)
    assert per_gear.gears[0]["Y_RrelT"] == mean.gears[0]["Y_RrelT"]
    assert per_gear.gears[1]["Y_RrelT"] == coarse.gears[1]["Y_RrelT"] < mean.gears[1]["Y_RrelT"]
    with pytest.raises(RatingError, match=r"flank_roughness has no entry for gear 'wheel'.*add wheel = 3.0"):
        rated(3000.0, flank_roughness={"pinion": 2.0})
    with pytest.raises(RatingError, match="root_roughness.pinion"):
        spec(root_roughness={"pinion": -1.0})
