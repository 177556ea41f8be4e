"""The TOML train description (epicyclic.io.toml_format)."""

from __future__ import annotations

import pytest

from epicyclic import Brake, Clutch, GearStage, PlanetarySet
from epicyclic.errors import ModelError, ToothCountError, UnknownShaftError
from epicyclic.io import InputFileError, loads_train_file
from epicyclic.units import UnitError

SET = """
[[planetary]]
name = "P"
sun = "in"
ring = "ring"
carrier = "out"
teeth = { sun = 30, planet = 24, ring = 78 }
stationary_efficiency = 0.98
"""


def test_every_element_kind_and_the_units_table():
    f = loads_train_file("""
title = "all kinds"
description = "one of each"
[units]
speed = "U/min"
torque = "kp*cm"
power = "PS"
[[planetary]]
name = "S"
sun = "a"
ring = "b"
carrier = "c"
teeth = { kind = "stepped", sun = 50, planet_sun = 24, planet_ring = 30, ring = 42, ring_internal = false }
mesh_efficiencies = [0.95, 0.95]
planets = 4
[[planetary]]
name = "D"
sun = "a"
ring = "d"
carrier = "e"
teeth = { kind = "double", sun = 30, planet_sun = 18, planet_ring = 18, ring = 90 }
[[planetary]]
name = "R"
sun = "d"
ring = "f"
carrier = "g"
stationary_ratio = "-(78/30)"
mesh_efficiencies = [0.99, 0.99]
[[gear]]
name = "G"
first = "c"
second = "b"
ratio = "(44/40)*(64/20)"
efficiency = 0.9
[[gear]]
name = "H"
first = "g"
second = "f"
meshes = [[20, 40], [15, 45, "internal"]]
[[clutch]]
name = "C1"
first = "e"
second = "f"
engaged = false
[[brake]]
name = "B1"
shaft = "d"
""")
    train = f.train
    assert f.title == "all kinds" and f.description == "one of each"
    assert f.units.power == "PS" and f.operating_point is None and f.transmission is None
    s, d, r, g, h, c1, b1 = train.elements
    assert isinstance(s, PlanetarySet) and s.stationary_ratio == pytest.approx(0.672)
    assert s.stationary_efficiency == pytest.approx(0.9025) and s.planets == 4
    assert d.stationary_ratio == pytest.approx(3.0) and d.teeth.kind == "double"
    assert r.stationary_ratio == pytest.approx(-2.6) and r.stationary_efficiency == pytest.approx(0.9801)
    assert isinstance(g, GearStage) and g.ratio == pytest.approx(3.52) and g.efficiency == 0.9
    assert h.ratio == pytest.approx(1 / ((-20 / 40) * (15 / 45)))
    assert isinstance(c1, Clutch) and not c1.engaged
    assert isinstance(b1, Brake) and b1.engaged


def test_operating_point_is_converted_to_core_units():
    f = loads_train_file("""
[units]
speed = "U/min"
power = "PS"
""" + SET + """
[[brake]]
name = "B"
shaft = "ring"
[operating_point]
speeds = { in = 1500 }
powers = { in = "2 kW" }
drives = "in"
loads = ["out"]
""")
    op = f.operating_point
    assert op.speeds["in"] == 1500.0 and op.powers["in"] == 2000.0
    assert op.drives == ("in",) and op.loads == ("out",)


TRANSMISSION = SET + """
[[brake]]
name = "B"
shaft = "ring"
[[clutch]]
name = "C"
first = "in"
second = "ring"
[transmission]
input = "in"
output = "out"
[transmission.schedule]
"1" = ["B"]
"2" = ["C"]
"""


def test_transmission_without_operating_point_loads():
    f = loads_train_file(TRANSMISSION)
    assert f.operating_point is None
    assert f.transmission.gears == ("1", "2") and f.transmission.schedule["2"] == ("C",)
    second = f.transmission.train_in_gear(f.train, "2")
    assert second.element("C").engaged and not second.element("B").engaged
    with pytest.raises(InputFileError, match=r"no \[operating_point\] table"):
        f.solve()
    with pytest.raises(ModelError, match="no gear '3'"):
        f.transmission.train_in_gear(f.train, "3")


def test_operating_point_in_a_gear():
    f = loads_train_file(TRANSMISSION + """
[operating_point]
gear = "1"
speeds = { in = 3000 }
torques = { in = 10 }
drives = ["in"]
loads = ["out"]
""")
    assert f.gear == "1"
    assert f.solve().speed("out") == pytest.approx(3000 / 3.6)


@pytest.mark.parametrize(
    "text, error, match",
    [
        ("title = ", InputFileError, "not valid TOML"),
        ("colour = 'red'\n" + SET, InputFileError, "top level: unknown key 'colour'"),
        (SET.replace("planets", "x") + "plantes = 3", InputFileError, "unknown key"),
        (SET + "planetz = 3", InputFileError, r"\[\[planetary\]\] #1 'P': unknown key 'planetz'.*did you mean 'planets'"),
        ("title = 'empty'", InputFileError, "describes no element"),
        ("[planetary]\nname = 'P'", InputFileError, r"write \[\[planetary\]\]"),
        (SET.replace("teeth = { sun = 30, planet = 24, ring = 78 }", ""), InputFileError, "got neither"),
        (SET.replace("sun = 30, planet = 24", "sun = 30, planet = 20"), ToothCountError, "'P'.*coaxially"),
        (SET.replace("planet = 24", "planet = 24.5"), InputFileError, r"key 'teeth.planet': expected a whole number"),
        (SET.replace("sun = 30,", "kind = 'weird', sun = 30,"), InputFileError, "'simple', 'double' or 'stepped'"),
        (SET.replace("0.98", "1.2"), InputFileError, r"expected an efficiency in \(0, 1\]"),
        (SET.replace("0.98", "'98 %'"), ModelError, "stationary_efficiency"),
        (SET + "[operating_point]\nspeeds = { inn = 3 }", UnknownShaftError, "unknown shaft 'inn'"),
        (SET + "[operating_point]\npowers = { in = '3 m' }", UnitError, r"key 'powers.in': '3 m' is not a power"),
        (SET + "[operating_point]\nspeed = { in = 3 }", InputFileError, "unknown key 'speed'.*did you mean 'speeds'"),
        (SET + "[operating_point]\ngear = '1'", InputFileError, r"needs a \[transmission\]"),
        (SET + "[units]\npower = 'm'", UnitError, r"\[units\].*is not a power"),
        (SET + "[transmission]\ninput = 'in'\noutput = 'out'\nschedule = { 1 = ['X'] }", InputFileError,
         "'X' is not a clutch or brake"),
        (SET.replace('stationary_efficiency = 0.98', "stationary_ratio = '1/0'"), InputFileError, "not both"),
        ("[[gear]]\nname = 'G'\nfirst = 'a'\nsecond = 'b'\nratio = 'a/b'", ModelError, "found a name"),
        ("[[gear]]\nname = 'G'\nfirst = 'a'\nsecond = 'b'\nmeshes = [[1, 40]]", ToothCountError, "at least 3 teeth"),
        ("[[gear]]\nname = 'G'\nfirst = 'a'\nsecond = 'b'\nmeshes = [40]", InputFileError, r"meshes\[0\]"),
        ("[[brake]]\nname = 'B'\nshaft = 'housing'", ModelError, "brake on the housing"),
        ("[[brake]]\nname = 'B'\nshaft = 's'\nengaged = 'yes'", InputFileError, "expected true or false"),
        ("[[clutch]]\nname = 'C'\nfirst = 's'", InputFileError, "missing key 'second'"),
    ],
)
def test_invalid_files_name_file_element_key(text, error, match):
    with pytest.raises(error, match=match) as info:
        loads_train_file(text, source="bad.toml")
    assert str(info.value).startswith("bad.toml")


def test_model_errors_keep_their_class_and_gain_the_location():
    with pytest.raises(ModelError, match=r"bad.toml: \[\[planetary\]\] #1 'P'.*mesh_efficiencies must have 2") as info:
        loads_train_file(SET.replace("stationary_efficiency = 0.98", "mesh_efficiencies = [0.9, 0.9, 0.9]"),
                         source="bad.toml")
    assert type(info.value) is ModelError


def test_load_train_file_reports_missing_and_unreadable_files(tmp_path):
    from epicyclic.io import load_train_file

    with pytest.raises(InputFileError, match="no such file"):
        load_train_file(tmp_path / "missing.toml")
    binary = tmp_path / "binary.toml"
    binary.write_bytes(b"\xff\xfe\x00")
    with pytest.raises(InputFileError, match="cannot read the file"):
        load_train_file(binary)


@pytest.mark.parametrize("override, says", [
    ("transmission.input_speed_range=[800]", r"expected \[lowest, highest\] rated input speed"),
    ("transmission.input_speed_range=[6000, 800]", "expected 0 <= lowest < highest speed"),
    ('transmission.input_speed_range=[800, "6 m"]', "not a speed"),
    ("transmission.max_input_torque=-5", "expected a positive torque"),
    ('transmission.max_input_torque="70 kW"', "not a torque"),
])
def test_the_rated_range_of_a_transmission_is_checked(override, says):
    from epicyclic.errors import EpicyclicError
    from epicyclic.io import load_train_file

    with pytest.raises(EpicyclicError, match=says) as caught:
        load_train_file("examples/zf_8hp70_8speed.toml", overrides=[override])
    assert "[transmission]" in str(caught.value)


def test_the_rated_range_reads_units():
    from epicyclic.io import load_train_file

    f = load_train_file("examples/zf_8hp70_8speed.toml", overrides=[
        'transmission.input_speed_range=["800 rpm", "6500 U/min"]', 'transmission.max_input_torque="70 kp*m"'])
    assert f.transmission.input_speed_range == (800.0, 6500.0)
    assert f.transmission.max_input_torque == pytest.approx(70 * 9.80665)
