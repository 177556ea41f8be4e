"""The scuffing rating of every mesh of a train, beside its ISO 6336 rating."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from epicyclic import Brake, GearTrain, OperatingPoint, PlanetarySet, solve
from epicyclic.geometry import SetGeometry
from epicyclic.io import load_train_file
from epicyclic.rating import RatingError, RatingSpec, mesh_inputs, rate_solution
from epicyclic.rating.scuffing import ScuffingSpec, rate_train_scuffing, scuffing_input
from epicyclic.rating.scuffing.rating import multiple_meshing_factor

EXAMPLE = Path(__file__).resolve().parents[3] / "examples" / "rating" / "helical_stage_scuffing.toml"
SCUFFING = ScuffingSpec(oil_temperature=90.0, roughness_Ra={"sun": 0.5, "planet": 0.5, "ring": 0.8}, load_stage=10)


def _planetary(torque=600.0, scuffing=SCUFFING):
    p = PlanetarySet.simple("P", sun="in", ring="r", carrier="out", z_sun=21, z_planet=39, z_ring=99)
    sol = solve(GearTrain([p, Brake("B", "r")]),
                OperatingPoint(speeds={"in": 1500}, torques={"in": torque}, drives=["in"], loads=["out"]))
    geometry = {"P": SetGeometry.create(p, 3.0, face_width=40.0, x_sun=0.25, x_planet=0.1, x_ring=-0.45)}
    spec = RatingSpec(material="18CrNiMo7-6", flank_roughness=3.0, root_roughness=10.0, viscosity_40=220.0,
                      viscosity_100=19.0, application_factor=1.25, scuffing=scuffing)
    return sol, geometry, spec


def test_every_mesh_of_a_planetary_set():
    """Both meshes rated; the ring mesh (internal, little sliding) runs cooler than the sun mesh."""
    sol, geometry, spec = _planetary()
    planned, _ = mesh_inputs(geometry, spec)
    rating = rate_solution(sol, geometry, spec, planned=(planned, {}))
    sun, ring = rate_train_scuffing(planned, rating)
    assert (sun.mesh, ring.mesh) == ("sun-planet", "planet-ring")
    assert ring.flash["theta_Bmax"].value < sun.flash["theta_Bmax"].value
    assert ring.integral["theta_int"].value < sun.integral["theta_int"].value
    for r in (sun, ring):
        assert r.ok and 0 < r.S_intS < math.inf and 0 < r.S_B < math.inf
        assert r.integral["X_mp"].value == 2.0  # the sun meets three planets: (1 + 3)/2
        assert r.integral["mu_mC"].value == r.flash["mu_m"].value
    assert "S_intS" in repr(sun) and "<table>" in sun._repr_html_() and "ϑ_intS" in sun.table()
    # rate_mesh carries the same as the mesh's failure modes
    mesh = rating.mesh("P", "sun-planet")
    assert mesh.mode("scuffing_flash").value == pytest.approx(sun.S_B)
    assert mesh.mode("scuffing_integral").value == pytest.approx(sun.S_intS)
    assert mesh.mode("scuffing_flash").profile["theta_B"] is not None


def test_multiple_meshing_factor():
    """X_mp = (1 + n_p)/2 of the busiest gear: a sun with N planets, a planet between sun and ring (DIN 3990-4)."""
    _, geometry, spec = _planetary()
    planned, _ = mesh_inputs(geometry, spec)
    assert [multiple_meshing_factor(p.input) for p in planned] == [2.0, 2.0]
    given = ScuffingSpec(oil_temperature=90.0, roughness_Ra=0.5, load_stage=10, multiple_meshing=1.0)
    assert scuffing_input(planned[0].input, given).multiple_meshing == 1.0


def test_safety_falls_with_the_torque_and_a_short_one_is_named():
    """Raising the torque lowers S_intS and S_B; below the minimum the result says what falls short."""
    low, high = [], []
    for torque, out in ((300.0, low), (6000.0, high)):
        sol, geometry, spec = _planetary(torque)
        planned, _ = mesh_inputs(geometry, spec)
        out.extend(rate_train_scuffing(planned, rate_solution(sol, geometry, spec, planned=(planned, {}))))
    assert high[0].S_intS < low[0].S_intS and high[0].S_B < low[0].S_B
    strict = ScuffingSpec(oil_temperature=90.0, roughness_Ra=0.5, load_stage=10, S_Smin=50.0, S_Bmin=50.0)
    sol, geometry, spec = _planetary(scuffing=strict)
    planned, _ = mesh_inputs(geometry, spec)
    short = rate_train_scuffing(planned, rate_solution(sol, geometry, spec, planned=(planned, {})))[0]
    assert not short.ok and short.below_minimum()[0].startswith("S_intS ")


def test_missing_inputs_name_the_key():
    """No scuffing table, no ν_100: errors naming the key and the value commonly taken."""
    sol, geometry, spec = _planetary(scuffing=None)
    planned, _ = mesh_inputs(geometry, spec)
    with pytest.raises(RatingError, match=r"rating.scuffing is missing"):
        scuffing_input(planned[0].input)
    _, geometry, spec = _planetary()
    spec = RatingSpec(material="18CrNiMo7-6", flank_roughness=3.0, root_roughness=10.0, viscosity_40=220.0,
                      scuffing=SCUFFING)
    planned, _ = mesh_inputs(geometry, spec)
    with pytest.raises(RatingError, match=r"viscosity_100 is missing.*viscosity_100 = 19.0"):
        scuffing_input(planned[0].input)


def test_example_file_rates_the_stage_like_the_report():
    """The example (the KISSsoft stage's inputs, ISO 6336 factors computed here) lands near the report.

    With K_v, K_Hα and c_γα of this package's method B (not the report's) and the oil's viscosity by
    ASTM D341, θ_int is within 1.5 % of the report's 115.75 °C (see test_methods for the exact check).
    """
    tf = load_train_file(EXAMPLE)
    from epicyclic.cli.rate import rate_file

    (_, rating), = rate_file(tf, EXAMPLE, [None])
    integral, flash = rating.meshes[0].mode("scuffing_integral"), rating.meshes[0].mode("scuffing_flash")
    assert integral["theta_int"] == pytest.approx(115.75, rel=0.015)
    assert np.asarray(flash.profile["theta_B"]).shape == np.asarray(flash.profile["gamma"]).shape


def test_load_cases_at_once_equal_the_per_case_ratings():
    """Over a BatchSolution every quantity is an array, equal to rating each case alone."""
    from epicyclic.rating import rate_batch
    from epicyclic.solver.batch import solve_batch

    sol, geometry, spec = _planetary()
    train = GearTrain([PlanetarySet.simple("P", sun="in", ring="r", carrier="out", z_sun=21, z_planet=39, z_ring=99),
                       Brake("B", "r")])
    torques, speeds = np.array([200.0, 600.0, 1500.0]), np.array([3000.0, 1500.0, 500.0])
    batch = solve_batch(train, speeds={"in": speeds}, torques={"in": torques}, drives=["in"], loads=["out"])
    planned = mesh_inputs(geometry, spec)
    many = rate_train_scuffing(planned, rate_batch(batch, geometry, spec, planned=planned))
    for k in range(3):
        one = solve(train, OperatingPoint(speeds={"in": speeds[k]}, torques={"in": torques[k]}, drives=["in"],
                                          loads=["out"]))
        single = rate_train_scuffing(planned, rate_solution(one, geometry, spec, planned=planned))
        for a, b in zip(many, single):
            assert a.S_intS[k] == pytest.approx(b.S_intS, rel=1e-9)
            assert a.S_B[k] == pytest.approx(b.S_B, rel=1e-9)
            np.testing.assert_allclose(a.path["theta_B"][k], b.path["theta_B"], rtol=1e-9)
    assert many[0].to_dict()["S_B"] == [float(x) for x in many[0].S_B]
