"""Stepped planets (two gears on one body): the mode structure survives, the planet carries F_s r_p,sun = F_r r_p,ring.

Kiracofe & Parker 2007 (J. Vib. Acoust. 129, 1–16) prove for compound planetary gears with equally
spaced planets the same three mode types as Lin & Parker 1999 for simple ones.
"""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from elastic_cases import lin_parker_1999
from epicyclic.elastic import PlanetErrors, PlanetaryLumpedModel, load_sharing, natural_modes


def _stepped(planets, rho, sun_support=1e8):
    m = lin_parker_1999(planets)
    return PlanetaryLumpedModel(m.carrier, m.ring, m.sun, m.planet, m.planet_angles, m.sun_mesh, m.ring_mesh,
                                m.planet_bearing, supports={"carrier": (1e8, 0.0), "ring": (1e8, 1e7),
                                                            "sun": (sun_support, 0.0)},
                                sun_pressure_angle=m.sun_pressure_angle, ring_pressure_angle=math.radians(21.0),
                                ring_planet_radius=rho * m.planet.radius)


def test_a_step_of_one_is_the_simple_set():
    m = lin_parker_1999(4)
    same = PlanetaryLumpedModel(m.carrier, m.ring, m.sun, m.planet, m.planet_angles, m.sun_mesh, m.ring_mesh,
                                m.planet_bearing, supports=m.supports, sun_pressure_angle=m.sun_pressure_angle,
                                ring_pressure_angle=m.ring_pressure_angle, ring_planet_radius=m.planet.radius)
    assert natural_modes(same).frequencies == pytest.approx(natural_modes(m).frequencies, rel=1e-12, abs=1e-9)


@settings(max_examples=25, deadline=None)
@given(planets=st.integers(3, 7), rho=st.floats(0.5, 2.0))
def test_structure_of_stepped_sets(planets, rho):
    modes = natural_modes(_stepped(planets, rho))
    assert modes.count("rotational") + modes.count("rigid-body") == 6
    assert modes.count("translational") == 12
    assert modes.count("planet") == 3 * (planets - 3)
    assert modes.count("mixed") == 0


@settings(max_examples=25, deadline=None)
@given(rho=st.floats(0.5, 2.0), errors=st.lists(st.floats(-20.0, 20.0), min_size=8, max_size=8),
       torque=st.floats(50.0, 2000.0))
def test_stepped_planet_balance(rho, errors, torque):
    model = _stepped(4, rho)
    loads = load_sharing(model, torque, PlanetErrors(pin_radial=errors[:4], pin_tangential=errors[4:]))
    assert loads.total == pytest.approx(torque / model.sun.radius, rel=1e-9)
    assert loads.sun_mesh == pytest.approx(rho * loads.ring_mesh, rel=1e-12)     # torque balance of the planet
    assert 1.0 <= loads.k_gamma <= 4


def test_stepped_linear_regime_is_the_linear_solution():
    # all contacts closed: the forces of the full stiffness matrix (with u_n) solved directly
    model = _stepped(4, 1.4)
    err = PlanetErrors(pin_tangential=(8.0, 0.0, -3.0, 0.0))
    loads = load_sharing(model, 900.0, err)
    names, k, v = model.springs()
    keep = [i for i in range(model.size) if i not in (2, 5)]
    use = [i for i, n in enumerate(names) if not n.startswith("torsion")]
    kk = (v[use][:, keep].T * k[use]) @ v[use][:, keep]
    rhs = np.zeros(len(keep))
    rhs[keep.index(8)] = 900.0 / model.sun.radius
    for n in range(4):
        rows = [i for i in use if names[i] == f"bearing planet {n + 1}"]
        rhs += k[rows[1]] * err.pin_tangential[n] * 1e-6 * v[rows[1], keep]
    q = np.linalg.solve(kk, rhs)
    sun = [i for i, n in enumerate(names) if n.startswith("sun-planet")]
    ring = [i for i, n in enumerate(names) if n.startswith("ring-planet")]
    assert loads.sun_mesh == pytest.approx(k[sun] * (v[sun][:, keep] @ q), rel=1e-9)
    assert loads.ring_mesh == pytest.approx(k[ring] * (v[ring][:, keep] @ q), rel=1e-9)
