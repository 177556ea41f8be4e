"""Transmission model: validation, degrees of freedom per gear, rendering, invariants."""

from __future__ import annotations

import json

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from epicyclic import Brake, Clutch, GearTrain, PlanetarySet
from epicyclic.errors import EpicyclicError, ModelError
from epicyclic.transmission import GearFreedomError, ShiftScheduleError, Transmission
from epicyclic.transmission.library import build


def _two_speed():
    return GearTrain([PlanetarySet("P", "in", "ring", "out", -2.0, 0.98), Brake("B", "ring"),
                      Clutch("C", "in", "ring"), Brake("Bout", "out")])


def test_two_speed_ratios_and_efficiency():
    """Ring held, sun in, carrier out: i = 1 − i0 = 3, η = (1 − i0·η0)/(1 − i0) (Brandenberger 1952, eq. 7)."""
    t = Transmission(_two_speed(), {"1": ["B"], "2": ["C"]}, "in", "out")
    assert t.ratio("1") == pytest.approx(3.0)
    g = t.analyze("1")
    assert g.efficiency_drive == pytest.approx((1 + 2 * 0.98) / 3, rel=1e-12)
    assert g.kind == "reduction" and t.analyze("2").kind == "direct"


@pytest.mark.parametrize("schedule, match", [
    ({}, "non-empty mapping"),
    ({"1": "B"}, "must be a list"),
    ({"1": ["B", "B"]}, "names an element twice"),
    ({"1": ["X"]}, "'X', which is not a clutch or brake"),
    ({"": ["B"]}, "non-empty strings"),
])
def test_schedule_errors(schedule, match):
    with pytest.raises(ShiftScheduleError, match=match):
        Transmission(_two_speed(), schedule, "in", "out")


@pytest.mark.parametrize("inp, out, match", [
    ("nope", "out", "input must be a moving shaft"),
    ("in", "housing", "output must be a moving shaft"),
    ("in", "in", "different shafts"),
])
def test_shaft_errors(inp, out, match):
    with pytest.raises(ShiftScheduleError, match=match):
        Transmission(_two_speed(), {"1": ["B"]}, inp, out)


def test_gear_with_two_degrees_of_freedom_names_gear_and_free_shafts():
    with pytest.raises(GearFreedomError, match=r"gear 'N' .* leaves 2 degrees of freedom.*'ring'") as info:
        Transmission(_two_speed(), {"1": ["B"], "N": []}, "in", "out")
    assert info.value.gear == "N" and info.value.degrees_of_freedom == 2 and "ring" in info.value.free
    assert isinstance(info.value, (EpicyclicError, ValueError))


def test_gear_that_locks_the_train():
    with pytest.raises(GearFreedomError, match="locks the whole train"):
        Transmission(_two_speed(), {"tie-up": ["B", "C"]}, "in", "out")


def test_gear_that_holds_the_output():
    train = GearTrain([PlanetarySet("P", "in", "ring", "out", -2.0), Brake("Bout", "out")])
    with pytest.raises(GearFreedomError, match="output 'out' stands still"):
        Transmission(train, {"P": ["Bout"]}, "in", "out")


def test_gear_that_holds_the_input():
    """A brake on the input shaft once gave "leaves 1 degrees of freedom, expected 1" (validation pass)."""
    train = GearTrain([PlanetarySet("P", "in", "ring", "out", -2.0), Brake("Bin", "in")])
    with pytest.raises(GearFreedomError, match=r"gear 'X' \(engaged: Bin\) holds the input 'in' still.*'ring', 'out'"):
        Transmission(train, {"X": ["Bin"]}, "in", "out")


def test_train_type_and_unknown_gear():
    with pytest.raises(ShiftScheduleError, match="must be a GearTrain"):
        Transmission("train", {"1": ["B"]}, "in", "out")  # type: ignore[arg-type]
    t = Transmission(_two_speed(), {"1": ["B"]}, "in", "out")
    with pytest.raises(ShiftScheduleError, match="no gear '9'"):
        t.ratio("9")


@pytest.mark.parametrize("kwargs, match", [
    ({"input_speed": 0.0}, "input_speed"),
    ({"input_speed": float("nan")}, "input_speed"),
    ({"input_torque": -5.0}, "input_torque"),
])
def test_analyze_bad_levels(kwargs, match):
    t = Transmission(_two_speed(), {"1": ["B"]}, "in", "out")
    with pytest.raises(EpicyclicError, match=match):  # nan: a UnitError from the unit converter
        t.analyze("1", **kwargs)


def test_with_efficiency_per_set_and_errors():
    t = build("zf_8hp70")
    assert t.with_efficiency({"P4": 0.9}).analyze("1").efficiency_drive == pytest.approx(
        (1 + 85 / 23 * 0.9) / (1 + 85 / 23), rel=1e-12)
    with pytest.raises(ModelError, match="'P9', which is not a planetary set"):
        t.with_efficiency({"P9": 0.9})


def test_rendering_of_analysis():
    a = build("zf_8hp70", 0.98).analyze_all()
    text = a.table()
    assert "spread 7.043" in text and "mean step 1.322" in text
    assert a.spread == pytest.approx(4.6957 / 0.6667, rel=1e-3)
    assert list(a.steps)[0] == "1→2" and a.steps["1→2"] == pytest.approx(1.5, rel=1e-12)
    assert "| gear |" in a.markdown() and "<table>" in a._repr_html_()
    json.dumps(a.to_dict())
    assert repr(a).startswith("<TransmissionAnalysis") and "ratio 4.6957" in repr(a["1"])
    assert "gear 1 (reduction)" in a["1"].table() and "<pre>" in a["1"]._repr_html_()
    assert "x" in build("simpson_c4").shift_table()
    assert repr(build("simpson_c4")).startswith("<Transmission 'Ford C4")
    assert set(a.progression) and all(v > 0 for v in a.progression.values())


@settings(max_examples=25, deadline=None)
@given(eta0=st.floats(0.9, 1.0), gear=st.sampled_from(["1", "2", "3", "4", "5", "6", "7", "8", "R"]))
def test_efficiency_bounds_and_ratio_independent_of_losses(eta0, gear):
    t = build("zf_8hp70", eta0)
    g = t.analyze(gear)
    assert g.ratio == pytest.approx(build("zf_8hp70").ratio(gear), rel=1e-12)
    assert 0.0 < g.efficiency_drive <= 1.0 + 1e-12
    assert g.efficiency_drive >= eta0 ** 4 - 0.05  # at most four sets in series, plus circulation
    assert sum(g.set_losses.values()) == pytest.approx(1 - g.efficiency_drive, abs=1e-9)


@settings(max_examples=20, deadline=None)
@given(speed=st.floats(10.0, 8000.0), torque=st.floats(1.0, 1000.0))
def test_results_are_level_independent(speed, torque):
    """Losses depend on rolling power only: multiples do not change with the operating level."""
    t = build("lepelletier_6hp26", 0.97)
    a, b = t.analyze("2"), t.analyze("2", input_speed=speed, input_torque=torque)
    assert b.efficiency_drive == pytest.approx(a.efficiency_drive, rel=1e-9)
    for name, value in a.element_torques.items():
        assert b.element_torques[name] == pytest.approx(value, rel=1e-9, abs=1e-12)


def test_input_speed_and_torque_take_units_like_a_file():
    # regression: "2000 U/min" or "15 kp*m" raised a bare TypeError from numpy, a pint speed a
    # DimensionalityError in speeds(); the file reader takes them, so the Python API does too
    import pint

    ureg = pint.UnitRegistry()
    t = build("simpson_c4", stationary_efficiency=0.97)
    plain = t.analyze("1", input_speed=2000.0, input_torque=9.80665 * 15)
    for speed, torque in (("2000 U/min", "15 kp*m"), (2000 * ureg.rpm, 15 * ureg("kgf*m")),
                          (f"{2000 * 3.141592653589793 / 30!r} rad/s", "147.09975 N*m")):
        result = t.analyze("1", input_speed=speed, input_torque=torque)
        assert result.drive.speed("in") == pytest.approx(2000.0, rel=1e-12)
        assert result.drive.torque("in") == pytest.approx(plain.drive.torque("in"), rel=1e-12)
        assert t.speeds("1", input_speed=speed)["in"] == pytest.approx(2000.0, rel=1e-12)
    assert t.analyze_all(input_speed="1500 rpm")["2"].drive.speed("in") == 1500.0


@pytest.mark.parametrize(("kwargs", "match"), [
    ({"input_speed": "3000 N"}, r"input_speed: '3000 N' is not a speed"),
    ({"input_torque": "10 kW"}, r"input_torque: '10 kW' is not a torque"),
    ({"input_speed": "fast"}, r"input_speed: cannot read 'fast'"),
])
def test_a_wrong_unit_names_the_argument(kwargs, match):
    with pytest.raises(EpicyclicError, match=match):
        build("simpson_c4").analyze("1", **kwargs)


def test_an_unknown_gear_is_named_with_the_gears_also_as_a_key_error():
    # regression: analysis["9"] raised a bare KeyError('9'); a number for a gear name was "no gear 3"
    from epicyclic.transmission import UnknownGearError

    t = build("simpson_c4")
    analysis = t.analyze_all()
    with pytest.raises(UnknownGearError, match=r"no gear '9'; gears are '1', '2', '3', 'R'\.$") as info:
        analysis["9"]
    assert isinstance(info.value, KeyError) and isinstance(info.value, EpicyclicError)
    with pytest.raises(KeyError, match=r"no gear 'r'.*Did you mean 'R'\?"):
        analysis["r"]
    with pytest.raises(ShiftScheduleError, match=r"no gear 3 \(gear names are strings\)"):
        t.analyze(3)
