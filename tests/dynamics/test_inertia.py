"""Inertias: gear blanks against the closed form of a thick-walled tube, planets against their kinetic energy.

Meriam & Kraige, *Engineering Mechanics: Dynamics*, 7th ed. (2012), Appendix D, Table D/4:
J = ½ m (r_o² + r_i²) of a hollow circular cylinder; the planet's absolute spin ω_c + ρ (ω_s − ω_c)
(Müller 1982, ch. 2).
"""

import math

import numpy as np
import pytest

from epicyclic import Brake, GearTrain, PlanetarySet
from epicyclic.dynamics import (
    DynamicsError,
    Inertias,
    PlanetInertia,
    rimmed_blank_inertia,
    solid_blank_inertia,
)


def test_solid_blank_is_a_tube():
    d, b, bore, rho = 0.12, 0.025, 0.03, 7850.0
    m = rho * math.pi * ((d / 2) ** 2 - (bore / 2) ** 2) * b
    assert solid_blank_inertia(d, b, bore=bore) == pytest.approx(0.5 * m * ((d / 2) ** 2 + (bore / 2) ** 2), rel=1e-15)


def test_rimmed_blank_is_rim_plus_web_and_lighter_than_solid():
    full = solid_blank_inertia(0.2, 0.03, bore=0.04)
    rimmed = rimmed_blank_inertia(0.2, 0.03, 0.15, 0.01, bore=0.04)
    rim = solid_blank_inertia(0.2, 0.03, bore=0.15)
    web = solid_blank_inertia(0.15, 0.01, bore=0.04)
    assert rimmed == pytest.approx(rim + web, rel=1e-14)
    assert rimmed < full
    assert rimmed_blank_inertia(0.2, 0.03, 0.15, 0.03, bore=0.04) == pytest.approx(full, rel=1e-14)


@pytest.mark.parametrize("bad", [dict(diameter=0.1, face_width=0.02, bore=0.1), dict(diameter=-1, face_width=0.02)])
def test_blank_errors_name_the_field(bad):
    with pytest.raises(DynamicsError, match="bore|diameter"):
        solid_blank_inertia(**bad)


def test_planets_couple_sun_and_carrier_as_their_kinetic_energy_says():
    train = GearTrain([PlanetarySet.simple("P", sun="s", ring="r", carrier="c", z_sun=30, z_planet=24, z_ring=78),
                       Brake("B", "r")])
    inertias = Inertias({"s": 0.01, "c": 0.02}, (PlanetInertia("P", 3, 0.002, mass=1.5, orbit_radius=0.05),))
    j = inertias.matrix(train)
    w = np.array([300.0, 0.0, -80.0])  # s, r, c (train order)
    index = {s: k for k, s in enumerate(train.moving_shafts)}
    ws, wc = w[index["s"]], w[index["c"]]
    planet = wc + (-30 / 24) * (ws - wc)
    direct = 0.5 * (0.01 * ws ** 2 + 0.02 * wc ** 2 + 3 * (0.002 * planet ** 2 + 1.5 * 0.05 ** 2 * wc ** 2))
    assert 0.5 * w @ j @ w == pytest.approx(direct, rel=1e-14)
    assert np.allclose(j, j.T)


def test_unknown_shaft_or_set_is_named():
    train = GearTrain([Brake("B", "x")])
    with pytest.raises(DynamicsError, match="'y' is not a moving shaft"):
        Inertias({"y": 1.0}).matrix(train)
    with pytest.raises(DynamicsError, match="no such planetary set"):
        Inertias({}, (PlanetInertia("Q", 3, 0.001),)).matrix(train)


def test_blanks_from_the_file():
    from epicyclic.io import loads_train_file
    from epicyclic.io.dynamics_format import dynamics_spec
    from epicyclic.transmission import Transmission

    path = "examples/dynamics/zf_8hp70_shift.toml"
    text = open(path, encoding="utf-8").read().replace(
        "s12 = 0.012", "s12 = [{diameter = 0.1, face_width = 0.02}, {diameter = 0.2, face_width = 0.03, "
                       "rim_diameter = 0.15, web_width = 0.01, bore = 0.04}]")
    t = Transmission.from_train_file(loads_train_file(text, path))
    spec = dynamics_spec(text, path, t)
    expected = solid_blank_inertia(0.1, 0.02) + rimmed_blank_inertia(0.2, 0.03, 0.15, 0.01, bore=0.04)
    assert spec.inertias.shafts["s12"] == pytest.approx(expected, rel=1e-15)
