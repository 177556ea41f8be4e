"""The geometry and losses tables of a train file, the [lubricant] table and the new tooth-count kinds."""

from __future__ import annotations

import pytest

from epicyclic.errors import ModelError, ToothCountError
from epicyclic.geometry import SetGeometry, StageGeometry, check_fitting
from epicyclic.io import InputFileError, loads_train_file
from epicyclic.losses import ConstantFriction, ElementLosses, SchlenkFriction

# lecad "Analysis of Planetary Transmissions" test run: 21/43/108, m = 1.75, x = 0.438/0.0426/0, 3 planets,
# face widths sun 39.75, planet 38, ring 41.5 mm; printed a = 56.8 mm, d_a sun 41.7008, planet 78.8170.
LECAD = """
title = "lecad test run"
[lubricant]
viscosity = 26.0
lubricant_factor = 1.0
[[planetary]]
name = "P"
sun = "in"
ring = "ring"
carrier = "out"
teeth = { sun = 21, planet = 43, ring = 108 }
planets = 3
[planetary.geometry]
module = 1.75
profile_shift = { sun = 0.438, planet = 0.0426 }
face_width = { sun = 39.75, planet = 38.0, ring = 41.5 }
[planetary.losses]
friction = "schlenk"
roughness = 0.4
bearing = { bore = 25.0, type = "needle roller" }
drag = [{ member = "carrier", coefficients = [0.0, 1e-5] }]
[[brake]]
name = "B"
shaft = "ring"
"""


def test_set_geometry_and_losses_from_the_file():
    f = loads_train_file(LECAD)
    g = f.geometry["P"]
    assert isinstance(g, SetGeometry)
    assert [round(m.center_distance, 2) for m in g.meshes] == [56.8, 56.8]
    assert g.gears["sun"].tip_diameter == pytest.approx(41.7008, abs=2e-4)
    assert g.gears["planet"].tip_diameter == pytest.approx(78.8170, abs=3e-4)
    assert g.mesh_face_width("sun-planet") == 38.0 and g.mesh_face_width("planet-ring") == 38.0
    assert check_fitting(g).passed
    model = f.losses["P"]
    assert isinstance(model, ElementLosses) and isinstance(model.friction, SchlenkFriction)
    assert model.friction.lubricant.viscosity == 26.0 and 0.99 < model.bearing_efficiency < 1.0
    assert model.drag[0].member == "carrier" and len(model.meshes) == 2


def test_stage_geometry_and_constant_friction():
    f = loads_train_file("""
[[gear]]
name = "G"
first = "a"
second = "b"
meshes = [[40, 44], [20, 64]]
[gear.geometry]
module = [2.0, 2.5]
face_width = [20.0, 25.0]
profile_shift = [[0.1, -0.1], [0.0, 0.0]]
[gear.losses]
friction = 0.05
drag = { member = "first", coefficients = [0.01] }
""")
    g = f.geometry["G"]
    assert isinstance(g, StageGeometry) and [m.rack.module for m in g.meshes] == [2.0, 2.5]
    assert g.meshes[0].center_distance == pytest.approx(84.0) and g.mesh_face_width(1) == 25.0
    assert isinstance(f.losses["G"].friction, ConstantFriction) and len(f.losses["G"].meshes) == 2


def test_wolfrom_and_two_suns_kinds_and_geometry_planets():
    f = loads_train_file("""
[[planetary]]
name = "W"
sun = "r1"
ring = "r2"
carrier = "c"
teeth = { kind = "two_rings", first = 81, planet_first = 27, planet_second = 24, second = 78 }
[planetary.geometry]
module = 2.0
planets = 4
[[planetary]]
name = "B"
sun = "I"
ring = "II"
carrier = "III"
teeth = { kind = "two_suns", first = 50, planet_first = 24, planet_second = 30, second = 42 }
""")
    w, b = f.train.elements
    assert w.stationary_ratio == pytest.approx(78 * 27 / (81 * 24)) and w.teeth.arrangement == "two rings"
    assert w.planets == 4 and f.geometry["W"].planetary_set.planets == 4
    assert b.stationary_ratio == pytest.approx(0.672)


def _file(extra_set="", extra_top="", teeth="{ sun = 21, planet = 43, ring = 108 }", element="planetary"):
    return f"""
{extra_top}
[[planetary]]
name = "P"
sun = "in"
ring = "ring"
carrier = "out"
teeth = {teeth}
{extra_set}
"""


@pytest.mark.parametrize(
    ("text", "error", "match"),
    [
        (_file("[planetary.geometry]\nmodule = -1"), InputFileError,
         r"<string>: \[\[planetary\]\] #1 'P', table 'geometry', key 'geometry.module': expected a positive normal module"),
        (_file("[planetary.geometry]\nmodul = 2"), InputFileError, r"unknown key 'modul'.*did you mean 'module'"),
        (_file("[planetary.geometry]\npressure_angle = 20"), InputFileError, r"table 'geometry': missing key 'module'"),
        (_file("[planetary.geometry]\nmodule = 2\nprofile_shift = { son = 0.1 }"), InputFileError,
         r"key 'geometry.profile_shift': unknown gear 'son'.*did you mean 'sun'"),
        (_file("[planetary.geometry]\nmodule = 2\nface_width = { sun = 20 }"), InputFileError,
         r"key 'geometry.face_width': missing gear 'planet'"),
        (_file("[planetary.geometry]\nmodule = 2\nring_module = 2.5"), InputFileError,
         r"only stepped sets have a second module"),
        (_file("planets = 3\n[planetary.geometry]\nmodule = 2\nplanets = 4"), InputFileError,
         r"4 planets, but the element's 'planets' says 3; give the number once"),
        (_file("[planetary.geometry]\nmodule = 2\nload_sharing = 0.5"), InputFileError, r"K_gamma >= 1"),
        (_file("[planetary.geometry]\nmodule = 2\nhelix_angle = 50"), ModelError,
         r"table 'geometry': BasicRack: helix_angle must lie in \[0, 45\)"),
        (_file("[planetary.losses]\nfriction = \"schlenk\"\nroughness = 0.4\n[planetary.geometry]\nmodule = 2\n"
               "face_width = 20"), InputFileError, r"needs the oil: add a top-level \[lubricant\] table"),
        (_file("[planetary.losses]\nfriction = \"schlenk\"\n[planetary.geometry]\nmodule = 2\nface_width = 20",
               "[lubricant]\nviscosity = 30"), InputFileError, r"needs the flank roughness: add 'roughness'"),
        (_file("[planetary.losses]\nfriction = 0.05\n[planetary.geometry]\nmodule = 2"), InputFileError,
         r"needs the load per face width: add 'face_width'"),
        (_file("[planetary.losses]\nfriction = 0.05"), InputFileError, r"needs the gear geometry"),
        (_file("stationary_efficiency = 0.98\n[planetary.losses]\nfriction = 0.05\n[planetary.geometry]\n"
               "module = 2\nface_width = 20"), InputFileError,
         r"remove the element's 'stationary_efficiency'"),
        (_file("[planetary.losses]\nfriction = \"coulomb\""), InputFileError,
         r"expected a coefficient such as 0.05 or \"schlenk\""),
        (_file("[planetary.losses]\nfriction = 1.5"), InputFileError, r"expected a coefficient of friction in \[0, 1\)"),
        (_file("[planetary.losses]\ndrag = [{ member = \"planet\", coefficients = [0.1] }]"), ModelError,
         r"table 'losses': losses of 'P': a drag torque acts on 'planet', which is not a member"),
        (_file("[planetary.losses]\ndrag = [{ member = \"carrier\", coefficients = [-0.1] }]"), ModelError,
         r"coefficients\[0\] must be a number >= 0"),
        (_file("[planetary.losses]\nbearing = { bore = 20, type = \"plain\" }\n[planetary.geometry]\nmodule = 2"),
         ModelError, r"unknown bearing type 'plain'"),
        (_file("[planetary.losses]\nbearing = { bore = 20 }"), InputFileError, r"takes the bearing loads from the "
                                                                                 r"tooth forces"),
        (_file("", "[lubricant]\nviscosity = -3"), InputFileError, r"\[lubricant\], key 'viscosity': expected a "
                                                                    r"positive number \(mPa\*s\)"),
        (_file("", "", "{ kind = \"two_rings\", first = 81, planet_first = 27, planet_second = 16, second = 78 }"),
         ToothCountError, r"\[\[planetary\]\] #1 'P', key 'teeth': the stepped planet cannot be coaxial"),
        (_file("", "", "{ kind = \"stepped\", sun = 20, planet_sun = 30, planet_ring = 18, ring = 86 }"),
         ToothCountError, r"cannot be coaxial.*module_ratio = 0\.735"),
        (_file("", "", "{ kind = \"wolfrom\", first = 81 }"), InputFileError, r"'two_rings' for a Wolfrom set"),
    ],
)
def test_bad_geometry_and_losses_name_file_element_key(text, error, match):
    with pytest.raises(error, match=match):
        loads_train_file(text)


def test_stepped_module_ratio_from_the_geometry():
    # 20 + 30 = 50 teeth of module 2 and 86 - 18 = 68 teeth of module 2·50/68: coaxial
    f = loads_train_file(_file("[planetary.geometry]\nmodule = 2.0\nring_module = 1.4705882352941178", "",
                               "{ kind = \"stepped\", sun = 20, planet_sun = 30, planet_ring = 18, ring = 86 }"))
    assert check_fitting(f.geometry["P"], planets=3).checks[0].passed
