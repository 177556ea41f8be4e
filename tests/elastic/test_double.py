"""Double-planet sets: consistent mesh kinematics and the mode structure of Kiracofe & Parker 2007.

A rigid rotation of the whole set strains no spring (every line of action and rotation sign consistent
with rolling); with the sun and carrier torsionally free the set has a rigid-body mode; equally spaced
pairs give 9 rotational modes, 9 double translational frequencies and 6 planet-mode frequencies of
multiplicity N − 3 (Kiracofe & Parker, J. Vib. Acoust. 129 (2007) 1–16).
"""

import math

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from epicyclic.elastic import Body, ElasticError, equally_spaced, load_sharing, natural_modes
from epicyclic.elastic.double import DoublePlanetModel


def _double(planets, scale=(1.0,) * 8, free=True, alpha=math.radians(21.0)):
    s = scale
    r_bs, r_ba, r_bb, r_br = 0.030 * s[0], 0.022 * s[1], 0.024 * s[2], 0.110 * s[3]
    r_a = (r_bs + r_ba) / math.cos(alpha)
    r_b = (r_br - r_bb) / math.cos(alpha)
    a_ab = (r_ba + r_bb) / math.cos(alpha)
    if not abs(r_b - r_a) < a_ab < r_a + r_b:
        return None
    phi = math.acos((r_a ** 2 + r_b ** 2 - a_ab ** 2) / (2 * r_a * r_b))
    body = lambda m, r: Body(m, 0.5 * m * r * r, r)  # noqa: E731
    return DoublePlanetModel(
        Body(4.0 * s[4], 0.02, r_a), body(2.0, r_br), body(0.5 * s[5], r_bs), body(0.3 * s[6], r_ba),
        equally_spaced(planets), 4e8, 5e8, 1e8 * s[7],
        supports={"carrier": (1e8, 0.0 if free else 1e6), "ring": (1e8, 1e9 * r_br ** 2), "sun": (1e8, 0.0)},
        sun_pressure_angle=alpha, ring_pressure_angle=alpha, outer_planet=body(0.35, r_bb), planet_mesh=4.5e8,
        planet_pressure_angle=alpha, outer_planet_radius=r_b, outer_planet_angle=phi)


def test_a_rigid_rotation_strains_nothing():
    model = _double(4)
    q = np.zeros(model.size)
    theta = 1e-3
    q[2], q[5], q[8] = model.carrier.radius * theta, model.ring.radius * theta, model.sun.radius * theta
    for n in range(4):
        a, b = 9 + 6 * n, 12 + 6 * n
        q[a + 1], q[a + 2] = model.carrier.radius * theta, model.planet.radius * theta
        q[b + 1], q[b + 2] = model.outer_planet_radius * theta, model.outer_planet.radius * theta
    names, k, v = model.springs()
    strain = v @ q
    moving = [i for i, n in enumerate(names) if not n.startswith("torsion")]
    assert np.max(np.abs(strain[moving])) < 1e-15
    assert len(model.labels()) == model.size == 9 + 24


@settings(max_examples=25, deadline=None)
@given(planets=st.integers(3, 6), scale=st.lists(st.floats(0.8, 1.25), min_size=8, max_size=8),
       free=st.booleans())
def test_structure_of_double_planet_sets(planets, scale, free):
    model = _double(planets, scale, free)
    assume(model is not None)        # the three centre distances close a triangle
    modes = natural_modes(model)
    assert modes.count("rotational") + modes.count("rigid-body") == 9
    assert modes.count("rigid-body") == (1 if free else 0)
    assert modes.count("translational") == 18
    assert modes.count("planet") == 6 * (planets - 3)
    assert modes.count("mixed") == 0


def test_load_sharing_says_it_is_not_modelled():
    with pytest.raises(ElasticError, match="double-planet"):
        load_sharing(_double(3), 100.0)
