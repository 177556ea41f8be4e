"""A lumped model from a set's geometry: radii, ISO 6336-1 mesh stiffness, disc masses, stated and refused defaults."""

import math

import numpy as np

import pytest

from epicyclic import PlanetarySet
from epicyclic.elastic import ElasticError
from epicyclic.elastic.from_geometry import ElasticSpec, lumped_model
from epicyclic.elastic.stiffness import single_stiffness
from epicyclic.geometry.set_geometry import SetGeometry


def _geometry(**kw):
    p = PlanetarySet.simple("P", sun="s", ring="r", carrier="c", z_sun=21, z_planet=43, z_ring=108, planets=3)
    return SetGeometry.create(p, module=1.75, x_sun=0.438, x_planet=0.0426, face_width=38.0, **kw)


def test_radii_angles_and_discs():
    g = _geometry()
    model, taken = lumped_model(g)
    assert model.sun.radius == pytest.approx(21 * 1.75 * math.cos(math.radians(20)) / 2e3)
    assert model.carrier.radius == pytest.approx(g.carrier_radius / 1e3)
    assert math.degrees(model.sun_pressure_angle) == pytest.approx(g.sun_mesh.operating_pressure_angle)
    sun = g.gears["sun"]
    d_m = (sun.tip_diameter + sun.root_diameter) / 2
    mass = 7850e-9 * math.pi / 4 * d_m ** 2 * 38.0
    assert model.sun.mass == pytest.approx(mass) and model.sun.inertia == pytest.approx(mass * d_m ** 2 / 8 * 1e-6)
    assert len(taken) == 10 and any("ISO 6336-1" in t for t in taken)


def test_mesh_stiffness_is_c_gamma_alpha_times_b():
    # ISO 6336-1, 9.3: spur, so z_n = z; c_γα = c' (0.75 ε_α + 0.25), k = c_γα b (N/(mm µm) · mm = 1e6 N/m)
    g = _geometry()
    model, _ = lumped_model(g)
    c_prime = single_stiffness(21, 43, 0.438, 0.0426, 0.0)
    expected = c_prime * (0.75 * g.sun_mesh.contact_ratio + 0.25) * 38.0 * 1e6
    assert model.sun_mesh == pytest.approx(expected, rel=1e-12)


def test_given_values_replace_the_defaults():
    spec = ElasticSpec(sun_mesh=3e8, ring_mesh=4e8, planet_bearing=2e8, sun_support=0.0, ring_support=1e9,
                       carrier_support=1e9, sun_torsion=0.0, ring_torsion=1e6, carrier_torsion=0.0, density=7800.0,
                       masses={"sun": (1.0, 0.001)}, planet_angles=(0.0, 100.0, 240.0))
    model, taken = lumped_model(_geometry(), spec)
    assert taken == []
    assert (model.sun_mesh, model.ring_mesh, model.planet_bearing) == (3e8, 4e8, 2e8)
    assert model.supports["sun"] == (0.0, 0.0) and model.sun.mass == 1.0
    assert math.degrees(model.planet_angles[1]) == pytest.approx(100.0)


def test_refused_defaults_and_bad_sets():
    with pytest.raises(ElasticError, match="refuses defaults"):
        lumped_model(_geometry(), ElasticSpec(refuse_defaults=True))
    with pytest.raises(ElasticError, match="planet_angles"):
        lumped_model(_geometry(), ElasticSpec(planet_angles=(0.0, 90.0)))
    with pytest.raises(ElasticError, match="face_width"):
        p = PlanetarySet.simple("P", sun="s", ring="r", carrier="c", z_sun=21, z_planet=43, z_ring=108, planets=3)
        lumped_model(SetGeometry.create(p, module=1.75, x_sun=0.438, x_planet=0.0426))
    with pytest.raises(ElasticError, match="elastic.sun_mesh"):
        ElasticSpec(sun_mesh=-1.0)


def test_a_stepped_set():
    # examples/geometry_stepped_set.toml: sun 20 (m 2) - planet 30 | planet 21 (m 2*50/70) - ring 91
    p = PlanetarySet.stepped("S", sun="s", ring="r", carrier="c", z_sun=20, z_planet_sun=30, z_planet_ring=21,
                             z_ring=91, planets=3)
    g = SetGeometry.create(p, module=2.0, ring_module=2 * 50 / 70, face_width=20.0, x_sun=0.2, x_planet=(-0.2, 0.0))
    model, _ = lumped_model(g)
    assert model.step_ratio == pytest.approx((21 * 2 * 50 / 70) / (30 * 2.0))
    assert model.planet.mass > lumped_model(g)[0].sun.mass


def test_a_double_planet_set():
    # sun 30, planets 15 and 16, ring 78, m = 2 (tests/geometry/test_fitting.py: it assembles with 3 pairs)
    from epicyclic.elastic import natural_modes
    from epicyclic.elastic.double import DoublePlanetModel

    p = PlanetarySet.double_planet("D", sun="s", ring="r", carrier="c", z_sun=30, z_planet_sun=15, z_planet_ring=16,
                                   z_ring=78, planets=3)
    g = SetGeometry.create(p, module=2.0, face_width=20.0)
    model, taken = lumped_model(g)
    assert isinstance(model, DoublePlanetModel) and model.size == 9 + 18
    a, b, c = (m.center_distance for m in g.meshes)
    # the outer planet stands where the three centre distances close their triangle
    gap = model.outer_planet_radius * 1e3 * np.array([math.cos(model.outer_planet_angle),
                                                       math.sin(model.outer_planet_angle)]) - np.array([a, 0.0])
    assert np.hypot(*gap) == pytest.approx(b, rel=1e-12) and model.outer_planet_radius * 1e3 == pytest.approx(c)
    modes = natural_modes(model)
    assert modes.count("translational") == 18 and modes.count("rigid-body") == 1
    assert any("planet-planet" in t for t in taken)
