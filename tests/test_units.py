"""Units at the edges (epicyclic.units): the sources' units and pint's traps."""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from epicyclic.errors import EpicyclicError
from epicyclic.units import UnitError, Units, from_core, to_core, unit_factor

# Brandenberger 1952, text to eq. (2): M = 71620·N/n cm kg (N in PS, n in U/min), so
# 3 PS at 1500 U/min is 143.24 cm kg; 1 PS = 75 kp·m/s = 735.49875 W (DIN 1301); 1 kp = 9.80665 N.
# hp = 745.69987 W (mechanical), lbf·ft = 1.3558179 N·m (NIST SP 811). Relative tolerance 1e-9.
CASES = [
    ("3 PS", "power", 3 * 735.49875),
    ("1 hp", "power", 745.6998715822702),
    ("2.5 kW", "power", 2500.0),
    ("1500 U/min", "speed", 1500.0),
    ("1500 1/min", "speed", 1500.0),
    ("1500 rpm", "speed", 1500.0),
    ("25 1/s", "speed", 1500.0),
    ("1 rad/s", "speed", 30 / math.pi),  # explicit factor, never through Hz
    ("360 deg/s", "speed", 60.0),
    ("143.24 kp*cm", "torque", 143.24 * 0.0980665),
    ("143.24 cm*kg", "torque", 143.24 * 0.0980665),  # Brandenberger's "cm kg" is kp·cm
    ("2 kp*m", "torque", 2 * 9.80665),
    ("1 lbf*ft", "torque", 1.3558179483314004),
    ("10 N*m", "torque", 10.0),
    ("0.01 kN*m", "torque", 10.0),
]


@pytest.mark.parametrize("text, quantity, expected", CASES)
def test_to_core_reads_the_sources_units(text, quantity, expected):
    assert to_core(text, quantity) == pytest.approx(expected, rel=1e-9)


def test_brandenberger_input_torque_from_ps_and_u_per_min():
    # Brandenberger 1952: M_An' = 71620·3/1500 = 143.24 cm kg (printed to 2 decimals).
    power = to_core("3 PS", "power")
    omega = to_core("1500 U/min", "speed") * math.pi / 30
    assert from_core(power / omega, "torque", "kp*cm") == pytest.approx(143.24, abs=0.005)


def test_plain_numbers_use_the_default_unit_or_the_core_unit():
    assert to_core(3, "power") == 3.0
    assert to_core(3, "power", default_unit="PS") == pytest.approx(2206.49625)
    assert to_core("3", "power", default_unit="kW") == 3000.0


@pytest.mark.parametrize(
    "value, quantity, match",
    [
        ("3 m", "power", r"powers\.II: '3 m' is not a power.*\[length\]"),
        ("1500 N*m", "speed", "is not a speed"),
        ("3 PS", "torque", "is not a torque"),
        ("3 furlongs_per_fortnight", "power", "cannot read"),
        ("3 PS/", "power", "cannot read"),
        ("", "power", "empty string"),
        (True, "power", "boolean"),
        ([3], "power", "expected a number or a string"),
        (float("nan"), "speed", "finite"),
        ("1e999 W", "power", "finite"),
        ("x" * 300, "power", "too long"),
    ],
)
def test_bad_values_name_the_field(value, quantity, match):
    with pytest.raises(UnitError, match=match) as info:
        to_core(value, quantity, field="powers.II")
    assert isinstance(info.value, EpicyclicError) and isinstance(info.value, ValueError)
    assert info.value.field == "powers.II"


def test_unknown_quantity_and_bad_unit():
    with pytest.raises(UnitError, match="unknown quantity 'energy'"):
        to_core("3 J", "energy")
    with pytest.raises(UnitError, match="units.power.*is not a power"):
        Units(power="U/min")
    with pytest.raises(UnitError, match="non-empty string"):
        unit_factor("", "speed")


def test_ps_is_not_petasiemens_and_u_is_not_enzyme_units():
    # pint's default registry reads PS as petasiemens and U as enzyme units.
    assert unit_factor("PS", "power") == 735.49875
    assert unit_factor("U/min", "speed") == 1.0


def test_units_object_converts_and_serialises():
    u = Units(speed="U/min", torque="kp*cm", power="PS")
    assert u.to_dict() == {"speed": "U/min", "torque": "kp*cm", "power": "PS"}
    assert u.convert(None, "power") is None
    assert u.torque_from_core(9.80665) == pytest.approx(100.0)
    assert u.speed_from_core(1500.0) == 1500.0


UNITS = {"speed": ["1/min", "U/min", "rpm", "1/s", "rad/s"], "torque": ["N*m", "kp*cm", "cm*kg", "lbf*ft"],
         "power": ["W", "kW", "PS", "hp"]}


@given(st.sampled_from(sorted(UNITS)).flatmap(lambda q: st.tuples(st.just(q), st.sampled_from(UNITS[q]))),
       st.floats(min_value=-1e6, max_value=1e6, allow_nan=False))
def test_round_trip_through_any_unit(quantity_unit, value):
    quantity, unit = quantity_unit
    back = to_core(from_core(value, quantity, unit), quantity, default_unit=unit)
    assert back == pytest.approx(value, rel=1e-12, abs=1e-9)


# ---- hostile strings: the grammar answers at once, with a value or a UnitError, never pint's evaluation
_PIECES = ["9", "**", "^", "10", "e308", "e-400", "1e309", " ", "*", "/", "·", "rpm", "W", "kW", "PS", "m", "s",
           "(", ")", "nan", "inf", "-", "+", ".", ",", "__import__", "U/min", "2", "²", "³", "kp", "cm", "kg",
           "'", '"', "\x1b", "0", "1/", "min", "Ys", "lbf", "ft"]


@given(st.lists(st.sampled_from(_PIECES), max_size=30).map("".join) | st.text(max_size=250))
def test_any_string_is_a_finite_value_or_a_unit_error_at_once(text):
    import time

    for quantity in ("speed", "torque", "power"):
        start = time.monotonic()
        try:
            value = to_core(text, quantity, field="f", default_unit="rpm" if quantity == "speed" else None)
        except UnitError as exc:
            assert str(exc).startswith("f:") or str(exc).startswith("units")
        else:
            assert math.isfinite(value)
        assert time.monotonic() - start < 0.5


@pytest.mark.parametrize("text", ["9**9**9 rpm", "10**10**10 W", "2**2**2**2**2 W", "9^9^9 rpm", "(9**9)**9 W"])
def test_towers_of_powers_are_refused_without_evaluation(text):
    import time

    start = time.monotonic()
    with pytest.raises(UnitError, match="cannot read"):
        to_core(text, "power" if text.endswith("W") else "speed", field="speeds.sun")
    assert time.monotonic() - start < 0.1


@pytest.mark.parametrize("unit, match", [("0 rpm", "not a unit"), ("1000 rpm", "not a unit"), ("-rpm", "not a unit"),
                                         ("1/Ys", "degenerate"), ("rpm**0", "power 0"), ("rpm/rpm", "not a speed")])
def test_degenerate_units_are_refused(unit, match):
    with pytest.raises(UnitError, match=match):
        Units(speed=unit)


@pytest.mark.parametrize("text, quantity, expected", [
    ("2 m²·kg/s³", "power", 2.0), ("2 m^2*kg*s^-3", "power", 2.0), ("3*PS", "power", 3 * 735.49875),
    ("143.24 cm kg", "torque", 143.24 * 0.0980665), ("3 Nm", "torque", 3.0), ("1500rpm", "speed", 1500.0),
    ("3/min", "speed", 3.0), ("1 U/min/min*min", "speed", 1.0),
])
def test_the_grammar_reads_products_powers_and_spaces(text, quantity, expected):
    # exact factors: W = kg·m²/s³, PS = 735.49875 W (DIN 1301), kp = 9.80665 N; relative 1e-12
    assert to_core(text, quantity) == pytest.approx(expected, rel=1e-12)


# ---- the known units: read without pint, equal to the registry (issue 11, fast start)
from epicyclic import units as _units  # noqa: E402


@pytest.mark.parametrize(("quantity", "unit"), [(q, u) for q, table in _units._KNOWN_FACTORS.items() for u in table])
def test_known_unit_factors_equal_the_registry(quantity, unit):
    # The table only saves building the registry; the registry (pint + the sources' definitions:
    # DIN 1301 PS, kp = 9.80665 N, U = one revolution) stays the reference.
    ureg = _units.registry()
    value = ureg.Quantity(1.0, unit)
    if quantity == "torque" and unit.endswith("kg"):
        value = value * ureg.Quantity(_units.G0, "N/kg")  # cm kg in the sources' sense: kp·cm
    reference = value.to(_units.CORE_UNITS[quantity]).magnitude
    assert _units._KNOWN_FACTORS[quantity][unit] == pytest.approx(reference, rel=1e-15)
    assert _units.to_core(f"2.5 {unit}", quantity) == pytest.approx(2.5 * reference, rel=1e-15)


def test_reading_the_sources_units_does_not_import_pint():
    import subprocess
    import sys

    code = ("import sys\nfrom epicyclic.io import load_train_file\n"
            "f = load_train_file('examples/brandenberger_1952.toml')\nf.units.convert(f.solve().loss, 'power')\n"
            "print('pint' in sys.modules)")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120,
                          cwd=__import__("pathlib").Path(__file__).resolve().parents[1])
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "False"


@pytest.mark.parametrize("value", [np.int64(1500), np.float32(1500.0), Fraction(3000, 2)])
def test_numpy_scalars_and_fractions_are_numbers(value):
    # regression: np.int64 / np.float32 (np.arange, float32 arrays) were "expected a number"
    assert to_core(value, "speed") == 1500.0
    assert to_core(value, "speed", default_unit="rad/s") == pytest.approx(1500.0 * 30 / np.pi, rel=1e-6)


def test_as_units_from_a_mapping():
    from epicyclic.units import as_units

    assert as_units(None) == Units() and as_units({"power": "PS"}) == Units(power="PS")
    with pytest.raises(UnitError, match=r"report: unknown quantity 'force'"):
        as_units({"force": "N"}, "report")
    with pytest.raises(UnitError, match=r"expected Units\(speed=\.\.\., torque=\.\.\., power=\.\.\.\) or a mapping"):
        as_units("rpm")


def test_pint_default_registry_misreadings_are_named():
    # regression: 10 * ureg.PS (pint's default registry: petasiemens) gave "is not a power: its unit
    # has the dimension [current] ** 2 ..." without saying why; the docs promised PS = metric horsepower
    import pint

    ureg = pint.UnitRegistry()
    with pytest.raises(UnitError, match=r"pint's default registry reads 'PS' as petasiemens; give the power as a "
                                        r"string \('10 PS'\) or in 'metric_horsepower'"):
        to_core(ureg.Quantity(10, "PS"), "power")
    with pytest.raises(UnitError, match=r"reads 'U' as enzyme_unit; give the speed as a string \('1500 U/min'\)"):
        to_core(ureg.Quantity(1500, "U/min"), "speed")
    assert to_core(ureg.Quantity(3, "metric_horsepower"), "power") == pytest.approx(2206.49625, rel=1e-12)


def test_a_list_of_pint_quantities_or_strings_beside_them_is_converted_one_by_one():
    """numpy cannot make an array of pint quantities (it asks them for a dimensionless number) nor of a
    string beside a quantity: each value is converted by its own unit, and a ragged list names its index."""
    import pint

    from epicyclic.units import to_core_array

    other = pint.UnitRegistry()
    assert to_core_array(["1000 rpm", 2000 * other("rpm")], "speed", field="speeds.sun").tolist() == [1000.0, 2000.0]
    converted = to_core_array([1000 * other("rpm"), 2000 * other("rad/s")], "speed", field="speeds.sun")
    assert converted.tolist() == pytest.approx([1000.0, 2000.0 * 30.0 / math.pi], rel=1e-15)
    with pytest.raises(UnitError, match=r"speeds\.sun\[0\]: .*not a speed"):
        to_core_array([1000 * other("N*m")], "speed", field="speeds.sun")
    with pytest.raises(UnitError, match=r"speeds\.sun\[0\]"):
        to_core_array([[1, 2], [3]], "speed", field="speeds.sun")
