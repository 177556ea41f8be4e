"""Set kinds and stages the bundled examples do not hold, through REXS and back.

Double-planet set (i0 = +z_ring/z_sun = +3: carrier held, n_ring = n_sun/3), two suns (Brandenberger's
Bild 1 kind), a stage given only by its ratio, an internal mesh, and a ring that is the housing.
"""

from __future__ import annotations

import pytest

from epicyclic.exchange.convert import rexs_text
from epicyclic.exchange.reading import loads_rexs_document
from epicyclic.io import loads_train_file
from epicyclic.io.source import parse_toml
from epicyclic.io.toml_format import read_document

OP = """
[operating_point]
speeds = {{ s = 1000 }}
torques = {{ s = 10 }}
drives = ["s"]
loads = ["{load}"]
"""
CASES = {
    "double": ("""
[[planetary]]
name = "D"
sun = "s"
ring = "r"
carrier = "c"
teeth = { kind = "double", sun = 30, planet_sun = 18, planet_ring = 18, ring = 90 }
planets = 3
stationary_efficiency = 0.96
[planetary.geometry]
module = 2.0
face_width = 12.0
[[brake]]
name = "B"
shaft = "c"
""", "r", {"r": 1000 / 3}),
    "two suns": ("""
[[planetary]]
name = "T"
sun = "s"
ring = "r"
carrier = "c"
teeth = { kind = "two_suns", first = 30, planet_first = 20, planet_second = 25, second = 25 }
[[brake]]
name = "B"
shaft = "r"
""", "c", {"c": 3000.0}),   # i0 = (25*20)/(30*25) = 2/3: n_c = n_s/(1 - i0) = 3000
    "ratio, internal mesh, ring is the housing": ("""
[[planetary]]
name = "P"
sun = "s"
ring = "housing"
carrier = "c"
teeth = { sun = 30, planet = 24, ring = 78 }
[[gear]]
name = "G"
first = "c"
second = "o"
ratio = "-2/3"
efficiency = 0.97
[[gear]]
name = "H"
first = "o"
second = "p"
meshes = [[20, 60, "internal"]]
""", "p", {"c": 1000 / 3.6, "o": -1000 / 3.6 * 1.5, "p": -1000 / 3.6 * 1.5 / 3}),
}


@pytest.mark.parametrize("case", CASES, ids=list(CASES))
@pytest.mark.parametrize("kind", ["xml", "json"])
def test_kind_round_trips(case, kind):
    text, load, speeds = CASES[case]
    text += OP.format(load=load)
    original = loads_train_file(text)
    back = read_document(loads_rexs_document(rexs_text(original, kind, document=parse_toml(text)).encode(), "t.rexs"))
    a, b = original.solve(), back.solve()
    for shaft, speed in speeds.items():
        assert a.speed(shaft) == pytest.approx(speed, rel=1e-12)   # the hand value
        assert b.speed(shaft) == pytest.approx(speed, rel=1e-12)   # survives the round trip
    assert b.efficiency == pytest.approx(a.efficiency, rel=1e-12)
    assert back.train.shafts == original.train.shafts
    assert back.exchange.ignored == ""
