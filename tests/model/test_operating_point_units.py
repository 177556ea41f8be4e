"""The Python API takes units wherever files do: unit strings and pint quantities in OperatingPoint.

Converted at the boundary by epicyclic.units.to_core (one converter for files, the CLI and the API);
errors are UnitError naming the field.  Reference values: DIN 1301 (PS = 735.49875 W),
Brandenberger 1952 (cm kg = kp·cm, U/min), 30/π for rad/s → 1/min.
"""

from __future__ import annotations

import math

import numpy as np
import pint
import pytest

from epicyclic import Brake, GearTrain, OperatingPoint, PlanetarySet, solve
from epicyclic.units import UnitError

USER = pint.UnitRegistry()  # a user's own registry, with pint's defaults (rpm = 2π rad/min there)


@pytest.mark.parametrize(
    ("group", "given", "core"),
    [
        ("speeds", "1500 U/min", 1500.0),
        ("speeds", "1500 rpm", 1500.0),
        ("speeds", "25 1/s", 1500.0),
        ("speeds", f"{50 * math.pi} rad/s", 1500.0),
        ("speeds", USER.Quantity(1500, "rpm"), 1500.0),
        ("speeds", USER.Quantity(50 * math.pi, "rad/s"), 1500.0),
        ("speeds", USER.Quantity(25, "Hz"), 1500.0),
        ("torques", "143.24 cm*kg", 143.24 * 0.0980665),
        ("torques", "100 N*m", 100.0),
        ("torques", USER.Quantity(1, "kN*m"), 1000.0),
        ("torques", 100 * USER.newton * USER.meter, 100.0),
        ("powers", "3 PS", 3 * 735.49875),
        ("powers", "30 kW", 30_000.0),
        ("powers", USER.Quantity(30, "kW"), 30_000.0),
        ("powers", np.float64(250.0), 250.0),
        ("powers", np.int64(250), 250.0),
    ],
)
def test_values_with_units_are_converted_to_core_units(group, given, core):
    op = OperatingPoint(**{group: {"x": given}})
    assert getattr(op, group)["x"] == pytest.approx(core, rel=1e-12)
    assert type(getattr(op, group)["x"]) is float


@pytest.mark.parametrize(
    ("group", "given", "match"),
    [
        ("speeds", "3 kW", r"operating_point\.speeds\.in: '3 kW' is not a speed"),
        ("torques", USER.Quantity(3, "m"), r"operating_point\.torques\.in: .* is not a torque"),
        ("powers", "fast", r"operating_point\.powers\.in: cannot read 'fast' as a power"),
        ("powers", USER.Quantity(np.array([1.0, 2.0]), "kW"), r"operating_point\.powers\.in: expected one power"),
        ("speeds", "nan rpm", r"operating_point\.speeds\.in"),
        ("speeds", {"value": 3}, r"operating_point\.speeds\.in: expected a number or a string"),
    ],
)
def test_bad_units_name_the_field(group, given, match):
    with pytest.raises(UnitError, match=match) as info:
        OperatingPoint(**{group: {"in": given}})
    assert info.value.field == f"operating_point.{group}.in"


def test_solving_with_units_equals_solving_in_core_units():
    train = GearTrain([PlanetarySet.simple("P", sun="in", ring="ring", carrier="out", z_sun=30, z_planet=24,
                                           z_ring=78, stationary_efficiency=0.98), Brake("B", "ring")])
    plain = solve(train, OperatingPoint(speeds={"in": 3000}, powers={"in": 10_000}, drives=["in"], loads=["out"]))
    with_units = solve(train, OperatingPoint(speeds={"in": USER.Quantity(3000, "rpm")}, powers={"in": "10 kW"},
                                             drives=["in"], loads=["out"]))
    assert with_units.speed("out") == pytest.approx(plain.speed("out"), rel=1e-15)
    assert with_units.efficiency == pytest.approx(plain.efficiency, rel=1e-15)
