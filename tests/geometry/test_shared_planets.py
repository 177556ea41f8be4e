"""Bearing loads of planets that several sets share (Wolfrom, Ravigneaux) and of stepped planets.

Closed forms: the tooth forces of Queitsch part I, eqs. (23)–(26), (30) (F_t = 2000 T/(N d_w),
F_r = F_t tan α_wt) with the torques of a lossless train (Willis equation, tec-science
"Willis-Gleichung": the Wolfrom ratio 1 + z_r1/z_s times z_p1 z_r2/(z_p1 z_r2 − z_p2 z_r1) = 52).
Tolerance 1e-9 relative: the same arithmetic in another order.
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from epicyclic import Brake, GearTrain, OperatingPoint, PlanetarySet, solve
from epicyclic.geometry import SetGeometry, planetary_forces, share_planets
from epicyclic.geometry.forces import _cross
from epicyclic.io.geometry_report import geometry_results
from epicyclic.io.toml_format import load_train_file

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
TAN20 = math.tan(math.radians(20.0))


def _wolfrom(eta=1.0, torque=5.0):
    s = PlanetarySet.simple("S", sun="in", ring="r1", carrier="c", z_sun=27, z_planet=27, z_ring=81,
                            stationary_efficiency=eta)
    w = PlanetarySet.two_rings("W", first="r1", second="out", carrier="c", z_first=81, z_planet_first=27,
                               z_planet_second=24, z_second=78, stationary_efficiency=eta)
    sol = solve(GearTrain([s, w, Brake("B", "r1")]),
                OperatingPoint(speeds={"in": 3000.0}, torques={"in": torque}, drives=["in"], loads=["out"]))
    geo = {p.name: SetGeometry.create(p, module=2.0) for p in (s, w)}
    return sol, geo, {n: planetary_forces(sol, n, g) for n, g in geo.items()}


def test_wolfrom_planet_bearing_is_the_vector_sum_of_its_three_meshes():
    # 27/27-24/81/78, m = 2 mm, N = 3, T_in = 5 N*m, no losses: T_out = -52 T, ring 1 takes 51 T.
    # Per planet: sun F_s = 1000 T/(N 27 mm), ring 1 F_1 = 1000·51 T/(N 81 mm), ring 2 F_2 = 1000·52 T/(N 78 mm).
    # The carrier carries no torque: F_s + F_1 - F_2 = 0 tangentially; the sun pushes the planet out,
    # both rings push it in: bearing = tan 20° (F_1 + F_2 - F_s) = 763.89 N, pointing to the axis.
    t, n = 5.0, 3
    f_s, f_1, f_2 = 1000 * t / (n * 27), 1000 * 51 * t / (n * 81), 1000 * 52 * t / (n * 78)
    assert f_s + f_1 - f_2 == pytest.approx(0.0, abs=1e-9)
    expected = TAN20 * (f_1 + f_2 - f_s)
    assert expected == pytest.approx(763.89, abs=0.01)
    sol, geo, forces = _wolfrom()
    shared = share_planets(forces, geo)
    for name in ("S", "W"):
        for body in shared[name].bodies:
            assert body.bearing_load == pytest.approx(expected, rel=1e-9)
            centre = body.center
            radial = (body.bearing_force[0] * centre[0] + body.bearing_force[1] * centre[1]) / math.hypot(*centre)
            assert radial == pytest.approx(-expected, rel=1e-9)  # toward the axis: no tangential part
        assert shared[name].design_bearing_load == pytest.approx(expected, rel=1e-9)
    assert shared["S"].bodies[0].shared_with == ("W",) and shared["W"].bodies[0].shared_with == ("S",)
    planet = shared["S"].shared[0]
    by_name = {m.mesh: m for m in planet.meshes}
    assert set(by_name) == {"S: sun-planet", "S: planet-ring = W: first-planet_first", "W: planet_second-second"}
    assert by_name["S: sun-planet"].tangential == pytest.approx(f_s, rel=1e-9)
    ring1 = by_name["S: planet-ring = W: first-planet_first"]
    assert ring1.tangential == pytest.approx(f_1, rel=1e-9)  # one mesh, the two sets' shares added
    assert ring1.radial == pytest.approx(f_1 * TAN20, rel=1e-9)
    assert by_name["W: planet_second-second"].tangential == pytest.approx(f_2, rel=1e-9)
    # each set alone gives neither the load nor its direction: S 2 F_s, W tan 20° (F_1,W + F_2) ...
    assert forces["S"].bodies[0].bearing_load == pytest.approx(2 * f_s, rel=1e-9)
    assert forces["W"].bodies[0].bearing_load != pytest.approx(expected, rel=1e-3)


def test_wolfrom_with_losses_balances_the_whole_planet():
    sol, geo, forces = _wolfrom(eta=0.97, torque=20.0)
    shared = share_planets(forces, geo)
    for planet in shared["S"].shared:
        fx = sum(m.force_on_planet[0] for m in planet.meshes)
        fy = sum(m.force_on_planet[1] for m in planet.meshes)
        assert (fx, fy) == pytest.approx(planet.bearing_force, abs=1e-9)
        ring1 = next(m for m in planet.meshes if "=" in m.mesh)
        parts = [next(m for m in forces[s].bodies[planet.index].meshes if m.mesh == name)
                 for s, name in (("S", "planet-ring"), ("W", "first-planet_first"))]
        assert ring1.tangential == pytest.approx(sum(p.tangential for p in parts), rel=1e-12)  # same sense here
    # the carrier sees the pins of the whole planets: their tangential parts give its torque, 0 here,
    # apart from the friction moments (each set's, as in planetary_forces)
    friction = sum(b.friction_moment for f in forces.values() for b in f.bodies)
    arm_torque = sum(_cross(p.center, p.bearing_force) for p in shared["S"].shared) / 1000.0
    assert -arm_torque + friction == pytest.approx(sum(sol.elements[s].torques["carrier"] for s in "SW"), abs=1e-9)


def test_ravigneaux_long_planet_is_one_body():
    # double set (sun 30, planets 15/16, ring 78) and simple set (sun 46, long planet 16, ring 78) on one carrier:
    # the long planet meshes the short planet, the large sun and the ring; no losses: no net moment on it.
    double = PlanetarySet.double_planet("D", sun="s1", ring="r", carrier="c", z_sun=30, z_planet_sun=15,
                                        z_planet_ring=16, z_ring=78)
    simple = PlanetarySet.simple("L", sun="s2", ring="r", carrier="c", z_sun=46, z_planet=16, z_ring=78)
    sol = solve(GearTrain([double, simple, Brake("B", "s2")]),
                OperatingPoint(speeds={"s1": 3000.0}, torques={"s1": 50.0}, drives=["s1"], loads=["r"]))
    geo = {p.name: SetGeometry.create(p, module=2.0) for p in (double, simple)}
    shared = share_planets({n: planetary_forces(sol, n, g) for n, g in geo.items()}, geo)
    assert [b.shared_with for b in shared["D"].bodies[:2]] == [(), ("L",)]  # planet1 alone, planet2 shared
    for planet in shared["D"].shared:
        assert [m.mesh for m in planet.meshes] == ["D: planet1-planet2", "D: planet2-ring = L: planet-ring",
                                                   "L: sun-planet"]
        moment = sum(_cross((m.point[0] - planet.center[0], m.point[1] - planet.center[1]), m.force_on_planet)
                     for m in planet.meshes)
        assert moment == pytest.approx(0.0, abs=1e-9 * planet.bearing_load * 16)
        # the ring mesh carries the ring torque: T_r / (N r_r) with r_r = 78 mm
        ring = planet.meshes[1]
        assert ring.tangential == pytest.approx(abs(sol.elements["D"].torques["ring"] + sol.elements["L"].torques["ring"])
                                                * 1000 / (3 * 78), rel=1e-9)


def test_stepped_planet_bearing_sums_both_wheels():
    # examples/geometry_stepped_set.toml without losses: sun 20 (m 2), planet 30/21, ring 91 (m 2·50/70), N = 3,
    # T = 40 N*m. Sun mesh on wheel 30: F_1 = 1000·40/(3·20 mm) outward; ring mesh on wheel 21 (r = 15 mm):
    # F_2 = F_1·30/15 inward, same tangential sense (moment balance on the planet shaft): bearing
    # = hypot(F_1 + F_2, tan 20° (F_2 - F_1)) (both meshes at α_wt = 20°: the shifts +0.2/-0.2 add to zero).
    pset = PlanetarySet.stepped("S", sun="in", ring="ring", carrier="out", z_sun=20, z_planet_sun=30,
                                z_planet_ring=21, z_ring=91, module_ratio=50 / 70)
    geo = SetGeometry.create(pset, module=2.0, ring_module=2.0 * 50 / 70, x_sun=0.2, x_planet=(-0.2, 0.0))
    sol = solve(GearTrain([pset, Brake("B", "ring")]),
                OperatingPoint(speeds={"in": 2000.0}, torques={"in": 40.0}, drives=["in"], loads=["out"]))
    f1 = 1000 * 40 / (3 * 20)
    f2 = f1 * 30 / 15
    expected = math.hypot(f1 + f2, TAN20 * (f2 - f1))
    forces = planetary_forces(sol, "S", geo)
    for body in forces.bodies:
        assert [m.tangential for m in body.meshes] == pytest.approx([f1, f2], rel=1e-9)
        assert body.bearing_load == pytest.approx(expected, rel=1e-9)


def test_sets_that_share_no_planet_are_unchanged():
    # the simple-set example: forces as planetary_forces gives them, and Queitsch eq. (26): the planet
    # bearing carries 2 F_t (the radial forces cancel)
    train = load_train_file(EXAMPLES / "geometry_simple_set.toml")
    sol = solve(train.train, train.operating_point)
    (result,) = geometry_results(train.geometry, sol)
    assert result.forces == planetary_forces(sol, result.name, train.geometry[result.name])
    assert not result.forces.shared and not result.forces.bodies[0].shared_with
    body = result.forces.bodies[0]
    assert body.bearing_load == pytest.approx(2 * body.meshes[0].tangential, rel=1e-2)  # η0 < 1 shifts it by 0.8 %
    # two sets on one sun with equal teeth but their own carriers (as the 8HP's P1 and P2): two planets
    a = PlanetarySet.simple("A", sun="s", ring="housing", carrier="c", z_sun=30, z_planet=24, z_ring=78)
    b = PlanetarySet.simple("B", sun="s", ring="c", carrier="out", z_sun=30, z_planet=24, z_ring=78)
    sol = solve(GearTrain([a, b]), OperatingPoint(speeds={"s": 1000.0}, torques={"s": 10.0}, drives=["s"],
                                                  loads=["out"]))
    geo = {p.name: SetGeometry.create(p, module=2.0) for p in (a, b)}
    forces = {n: planetary_forces(sol, n, g) for n, g in geo.items()}
    assert share_planets(forces, geo) == forces


def test_wolfrom_example_report_names_the_rings_and_shares_the_planet():
    train = load_train_file(EXAMPLES / "wolfrom_drive.toml")
    sol = solve(train.train, train.operating_point)
    results = {r.name: r for r in geometry_results(train.geometry, sol)}
    w = results["W"].forces
    assert [m.mesh for m in w.bodies[0].meshes] == ["first-planet_first", "planet_second-second"]
    assert w.bodies[0].gear == "planet_first+planet_second"
    assert dict(w.members) == {"sun": ("first", "r1"), "ring": ("second", "out"), "carrier": ("carrier", "c")}
    text = w.table()
    title = text.splitlines()[0]
    assert "(torques first (r1) " in title and ", second (out) -" in title and "sun" not in title
    assert "planets shared with set 'S'" in text
    s = results["S"].forces
    assert "S: planet-ring = W: first-planet_first" in s.table()
    assert s.bodies[0].bearing_load == pytest.approx(w.bodies[0].bearing_load, rel=1e-12)
    assert s.to_dict()["shared_planets"][0]["sets"] == ["S", "W"]
