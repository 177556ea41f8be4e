"""Wet clutch capacity T = μ z r_m (p A − F_s) (Naunheimer et al. 2011, §10.2; Budynas & Nisbett 2011, §16-5),
pressure profiles and freewheels."""

import math

import pytest

from epicyclic.dynamics import (
    DynamicsError,
    FrictionCapacity,
    PressureProfile,
    WetElement,
)


def test_capacity_closed_form_and_inverse():
    c = FrictionCapacity(piston_area=0.01, faces=8, mean_radius=0.07, friction=0.12, return_spring=500.0)
    assert c.capacity(5e5, 0.0) == pytest.approx(0.12 * 8 * 0.07 * (5e5 * 0.01 - 500.0), rel=1e-15)
    assert c.capacity(c.pressure_for(250.0), 0.0) == pytest.approx(250.0, rel=1e-14)
    assert c.capacity(4e4, 0.0) == 0.0  # below the return spring: open


def test_friction_table_interpolates_over_slip_in_rpm():
    c = FrictionCapacity(piston_area=0.01, faces=2, mean_radius=0.1, friction=((0, 0.14), (100, 0.12), (1000, 0.10)))
    assert c.static_mu == 0.14
    assert c.mu(50 * math.pi / 30) == pytest.approx(0.13, rel=1e-12)
    assert c.mu(-550 * math.pi / 30) == pytest.approx(0.11, rel=1e-12)
    assert c.mu(1e6) == 0.10


@pytest.mark.parametrize("friction, match", [(((0, 0.1), (0, 0.2)), "increase"), (1.5, "above 1"), ((), "at least one")])
def test_bad_friction_tables(friction, match):
    with pytest.raises(DynamicsError, match=match):
        FrictionCapacity(piston_area=0.01, faces=2, mean_radius=0.1, friction=friction)


def test_open_pack_carries_its_drag():
    c = FrictionCapacity(piston_area=0.01, faces=2, mean_radius=0.1, friction=0.12, return_spring=1000.0)
    element = WetElement("C", c, drag=lambda slip: 0.01 * slip)
    assert element.torque(0.0, 100.0) == pytest.approx(1.0)
    assert element.torque(2e5, 100.0) == pytest.approx(c.capacity(2e5, 100.0))


def test_pressure_ramps_and_errors():
    p = PressureProfile.ramps(0.0, [(0.05, 3e5), (0.05, 1e5), (0.2, 1.5e5)], t0=0.1)
    assert [round(p(t)) for t in (0.0, 0.125, 0.2, 0.3, 9.0)] == [0, 150000, 100000, 125000, 150000]
    with pytest.raises(DynamicsError, match="must not decrease"):
        PressureProfile(((0.2, 1.0), (0.1, 1.0)))
    with pytest.raises(DynamicsError, match="pressure in 0"):
        PressureProfile(((0.0, -1.0),))
