"""The [duty_cycle] and [planetary.bearings.*] tables of a train file: reading and every error path."""

from __future__ import annotations

import pytest

from epicyclic.errors import EpicyclicError
from epicyclic.io import load_train_file, loads_train_file
from epicyclic.io.source import InputFileError
from epicyclic.transmission.errors import UnknownGearError

BASE = """
[[planetary]]
name = "P"
sun = "in"
ring = "r"
carrier = "out"
teeth = { sun = 30, planet = 24, ring = 78 }
[planetary.geometry]
module = 2.0
[planetary.losses]
bearing = { bore = 20.0, type = "needle roller" }
[planetary.bearings.planet]
dynamic_load_rating = "12 kN"
[[brake]]
name = "B"
shaft = "r"
[operating_point]
speeds = { in = 3000 }
torques = { in = 100 }
drives = ["in"]
loads = ["out"]
"""
CYCLE = """
[duty_cycle]
hours = 1000
[[duty_cycle.case]]
name = "a"
share = 0.25
speeds = { in = "3000 rpm" }
torques = { in = "100 N*m" }
[[duty_cycle.case]]
name = "b"
share = 0.75
speeds = { in = 1500 }
torques = { in = 200 }
"""


def test_reads_bearings_and_cycle():
    f = loads_train_file(BASE + CYCLE)
    rating = f.bearings["P"]["planet"]
    assert rating.type == "needle roller" and rating.dynamic_load_rating == 12e3  # type from losses.bearing
    cycle = f.duty_cycle
    assert cycle.total_hours == 1000.0 and cycle.hours.tolist() == [250.0, 750.0]
    op = cycle.cases[0].operating_point
    assert op.drives == ("in",) and op.loads == ("out",) and op.speeds["in"] == 3000.0  # roles of [operating_point]


def test_modified_life_inputs_with_units():
    text = BASE.replace('dynamic_load_rating = "12 kN"', 'dynamic_load_rating = "12 kN"\nfatigue_load_limit = 1500\n'
                        'pitch_diameter = "2.4 cm"\nviscosity = "12 mm^2/s"\ncontamination = 0.5\nreliability = 99')
    r = loads_train_file(text).bearings["P"]["planet"]
    assert (r.fatigue_load_limit, r.pitch_diameter, r.viscosity, r.reliability) == pytest.approx((1500, 24, 12, 99))


@pytest.mark.parametrize("change, match", [
    (('dynamic_load_rating = "12 kN"', 'fatigue_load_limit = "1 kN"'), "missing key 'dynamic_load_rating'"),
    (('dynamic_load_rating = "12 kN"', 'dynamic_load_rating = "12 kN*m"'), "key 'dynamic_load_rating': expected"),
    (('dynamic_load_rating = "12 kN"', 'dynamic_load_rating = -3'), "dynamic_load_rating C must be a positive"),
    (('[planetary.bearings.planet]', '[planetary.bearings.sun]'), "missing key 'type'"),
    (('[planetary.bearings.planet]', '[planetary.bearings.pin]'), "unknown key 'pin'"),
    (('dynamic_load_rating = "12 kN"', 'dynamic_load_rating = "12 kN"\ntype = "roller"'), "key 'type': expected"),
    (('dynamic_load_rating = "12 kN"', 'dynamic_load_rating = "12 kN"\nC = 3'), "unknown key 'C'"),
    (('dynamic_load_rating = "12 kN"', 'dynamic_load_rating = "12 kN"\ncontamination = 0.5'),
     "fatigue_load_limit, pitch_diameter, viscosity missing"),
])
def test_bearing_errors_name_the_key(change, match):
    # InputFileError, or the rating's own error located in the file (same message start: file, table)
    with pytest.raises(EpicyclicError, match=r"^<string>: \[\[planetary\]\] #1 'P', (table 'bearings\.\w+'|key 'bearings').*" + match):
        loads_train_file(BASE.replace(*change))


def test_bearings_need_geometry():
    text = BASE.replace("[planetary.geometry]\nmodule = 2.0\n[planetary.losses]\nbearing = { bore = 20.0, type = "
                        "\"needle roller\" }\n", "")
    with pytest.raises(InputFileError, match="add a 'geometry' table"):
        loads_train_file(text.replace('dynamic_load_rating', 'type = "needle roller"\ndynamic_load_rating'))


@pytest.mark.parametrize("change, error, match", [
    (("share = 0.75", "share = 0.5"), EpicyclicError, r"\[duty_cycle\]: the time shares sum to 0.75, not 1"),
    (("share = 0.25", "hours = -5"), InputFileError, "give 'hours' or 'share'|hours|expected a duration >= 0"),
    (("share = 0.25", "share = 0.25\nhours = 3"), InputFileError, "not both"),
    (('name = "a"\nshare = 0.25', 'name = "a"\nshare = 0.25\ngear = "1"'), InputFileError,
     r"needs a \[transmission\]"),
    (("torques = { in = 200 }", "torques = { inn = 200 }"), Exception, "unknown shaft 'inn'"),
    (("[[duty_cycle.case]]\nname = \"a\"", "[[duty_cycle.case]]\nname = \"a\"\nspeed = 3"), InputFileError,
     "unknown key 'speed'"),
])
def test_cycle_errors_name_the_key(change, error, match):
    with pytest.raises(error, match=match):
        loads_train_file(BASE + CYCLE.replace(*change))


def test_negative_hours_and_total_twice():
    hours = CYCLE.replace("hours = 1000\n", "").replace("share = 0.25", "hours = -5").replace("share = 0.75",
                                                                                           "hours = 5")
    with pytest.raises(InputFileError, match="key 'hours': expected a duration >= 0, got -5"):
        loads_train_file(BASE + hours)
    with pytest.raises(InputFileError, match="gives the total 'hours' already"):
        loads_train_file(BASE + CYCLE.replace("share = 0.25", "hours = 250"))


def test_unknown_gear_is_an_unknown_gear_error_located_in_the_file(tmp_path):
    from pathlib import Path

    text = (Path(__file__).resolve().parents[2] / "examples" / "zf_8hp70_geometry.toml").read_text()
    path = tmp_path / "t.toml"
    path.write_text(text.replace('gear = "R"\nshare = 0.02', 'gear = "9"\nshare = 0.02'))
    with pytest.raises(UnknownGearError, match=r"t.toml: \[\[duty_cycle.case\]\] #12 'reverse', key 'gear': .*"
                                               r"no gear '9'"):
        load_train_file(path)
