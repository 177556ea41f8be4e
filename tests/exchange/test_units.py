"""The REXS unit table against pint, and the lubricant's viscosity–temperature law.

Every factor of :data:`epicyclic.exchange.units.REXS_UNITS` is checked against pint's definition of the
same unit (pint spells ``mum`` as ``µm``, ``N m`` as ``N*m``, ``C`` as ``degC``); Ubbelohde–Walther
(ASTM D341-20, eq. 1–2) is checked at its two defining points and against its closed form.
"""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings, strategies as st

from epicyclic.exchange.operating import walther_viscosity
from epicyclic.exchange.units import FILE_UNITS, REXS_UNITS, RexsUnitError, to_file_unit
from epicyclic.unit_registry import registry

PINT = {"mum": "micrometer", "°": "degree", "deg": "degree", "1 / min": "1/minute", "1 / s": "1/second",
        "rad / s": "radian/second", "N m": "newton*meter", "N mm": "newton*millimeter", "kN m": "kilonewton*meter",
        "mm^2 / s": "millimeter**2/second", "kg / dm^3": "kilogram/decimeter**3", "mPa s": "millipascal*second",
        "%": "percent", "h": "hour"}
TARGET = {"length": "millimeter", "angle": "degree", "speed": "1/minute", "torque": "newton*meter", "power": "watt",
          "force": "newton", "kinematic viscosity": "millimeter**2/second", "density": "kilogram/decimeter**3",
          "dynamic viscosity": "millipascal*second", "fraction": "dimensionless", "time": "hour"}


@pytest.mark.parametrize("unit", [u for u, (q, _, _) in REXS_UNITS.items() if q in TARGET])
def test_factor_agrees_with_pint(unit):
    quantity, factor, _ = REXS_UNITS[unit]
    ureg = registry()
    if quantity == "speed":  # revolutions per minute: rad/s converts with 30/pi (one turn = 2 pi rad)
        expected = {"1 / min": 1.0, "1 / s": 60.0, "rad / s": 30.0 / math.pi}[unit]
    else:
        expected = ureg.Quantity(1.0, PINT.get(unit, unit)).to(TARGET[quantity]).magnitude
    assert factor == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize("unit, value, expected", [("C", 80.0, 80.0), ("K", 353.15, 80.0)])
def test_temperatures(unit, value, expected):
    assert to_file_unit(value, unit, "temperature", "w") == pytest.approx(expected)
    assert registry().Quantity(value, {"C": "degC", "K": "kelvin"}[unit]).to("degC").magnitude == pytest.approx(expected)


def test_every_quantity_has_a_file_unit():
    assert {q for q, _, _ in REXS_UNITS.values()} <= set(FILE_UNITS)


def test_unknown_unit_names_the_attribute():
    with pytest.raises(RexsUnitError, match="w: the unit 'furlong' is unknown to REXS; REXS writes lengths in mm"):
        to_file_unit(1.0, "furlong", "length", "w")


@settings(max_examples=30, deadline=None)
@given(nu40=st.floats(20, 1000), ratio=st.floats(4, 12), t=st.floats(0, 150))
def test_walther_is_monotone_and_exact_at_40_and_100(nu40, ratio, t):
    nu100 = nu40 / ratio
    assert walther_viscosity(nu40, nu100, 40.0) == pytest.approx(nu40, rel=1e-9)
    assert walther_viscosity(nu40, nu100, 100.0) == pytest.approx(nu100, rel=1e-9)
    # closed form: lg lg(nu + 0.7) is linear in lg T (ASTM D341 eq. 1)
    w = [math.log10(math.log10(walther_viscosity(nu40, nu100, x) + 0.7)) for x in (40.0, t, 100.0)]
    x = [math.log10(v + 273.15) for v in (40.0, t, 100.0)]
    assert (w[1] - w[0]) * (x[2] - x[0]) == pytest.approx((w[2] - w[0]) * (x[1] - x[0]), abs=1e-9)
    assert walther_viscosity(nu40, nu100, t + 1.0) < walther_viscosity(nu40, nu100, t)
