"""The [elastic] table: units (N/µm → N/m), "floating", errors, tolerances, ranges; bad values name the key."""

import pytest

from epicyclic.io import load_train_file
from epicyclic.errors import EpicyclicError

BASE = """
[[planetary]]
name = "P"
sun = "in"
ring = "ring"
carrier = "out"
teeth = { sun = 21, planet = 43, ring = 108 }
[planetary.geometry]
module = 1.75
face_width = 38.0
"""


def _read(tmp_path, text):
    path = tmp_path / "f.toml"
    path.write_text(BASE + text, encoding="utf-8")
    return load_train_file(path)


def test_values_and_units(tmp_path):
    f = _read(tmp_path, """
[elastic]
planet_bearing = 250.0
sun_support = "floating"
ring_torsion = 2e7
speed_range = [0, 8000]
draws = 500
seed = 3
[elastic.errors]
pin_tangential = [10.0, 0.0, -5.0]
ring_runout = 8.0
[elastic.tolerances]
pin_position = 12.0
""")
    e = f.elastic
    assert e.spec.planet_bearing == 250e6 and e.spec.sun_support == 0.0 and e.spec.ring_torsion == 2e7
    assert e.spec.sun_mesh is None                         # left to the ISO 6336-1 default
    assert e.speed_range == (0.0, 8000.0) and (e.draws, e.seed) == (500, 3)
    assert e.errors.pin_tangential == (10.0, 0.0, -5.0) and e.errors.ring_runout == 8.0
    assert e.tolerances.pin_position == 12.0


def test_a_file_without_the_table(tmp_path):
    assert _read(tmp_path, "").elastic is None


@pytest.mark.parametrize("text, fragment", [
    ("[elastic]\nplanet_bearing = 0\n", "key 'planet_bearing'"),
    ("[elastic]\nseed = -1\n", "key 'seed'"),
    ("[elastic]\nmasses = { moon = [1, 1] }\n", "unknown member"),
    ("[elastic]\nmasses = { sun = [1, -1] }\n", "masses"),
    ("[elastic]\noperating_range = [1, 2, 3]\n", "operating_range"),
    ("[elastic.errors]\nsun_runout = -2\n", "sun_runout"),
    ("[elastic]\ndefaults = 'maybe'\n", "key 'defaults'"),
])
def test_bad_values_name_the_key(tmp_path, text, fragment):
    with pytest.raises(EpicyclicError, match=fragment) as caught:
        _read(tmp_path, text)
    assert "f.toml" in str(caught.value) and "[elastic]" in str(caught.value)
