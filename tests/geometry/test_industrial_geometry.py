"""Industrial planetary geometry (issue 19): counts that do not add up, coaxiality tolerance, shift sign."""

from __future__ import annotations

import pytest

from epicyclic import PlanetarySet
from epicyclic.errors import EpicyclicError
from epicyclic.geometry import SetGeometry, check_coaxiality, check_fitting
from epicyclic.geometry.coaxiality import coaxiality_tolerance, shift_decimals
from epicyclic.geometry.errors import GeometryError
from epicyclic.geometry.tolerances import center_distance_allowance, standard_tolerance
from epicyclic.io import InputFileError, loads_train_file


def off_by_three(planets: int = 3) -> PlanetarySet:
    # z_ring - z_sun - 2 z_planet = 97 - 20 - 74 = +3: standard centre distances 57 and 60 modules apart
    return PlanetarySet.simple("P", sun="s", ring="r", carrier="c", z_sun=20, z_planet=37, z_ring=97,
                               planets=planets)


def test_counts_off_by_three_are_coaxial_by_profile_shift():
    geometry = SetGeometry.create(off_by_three(), module=2.0, x_sun=0.6, x_planet=0.3)
    check = check_coaxiality(geometry)
    assert not check.passed and "z_ring = z_sun + 2 z_planet = 94 (given 97)" in check.message
    fixed = SetGeometry.create(off_by_three(), module=2.0, x_sun=0.6, x_planet=0.3, x_ring=check.suggestion["x_ring"])
    coaxial = check_coaxiality(fixed)
    assert coaxial.passed
    a_s, a_r = coaxial.center_distances.values()
    assert a_s == pytest.approx(a_r, abs=1e-3) and a_s > 2.0 * 57 / 2 * 1.0  # the sun mesh spread by its shifts
    assert check_fitting(fixed).checks[0].passed


def test_suggestion_keeps_the_digits_given():
    four = check_coaxiality(SetGeometry.create(off_by_three(), module=2.0, x_sun=0.6, x_planet=0.3))
    assert round(four.suggestion["x_ring"], 4) == four.suggestion["x_ring"]
    five = check_coaxiality(SetGeometry.create(off_by_three(), module=2.0, x_sun=0.61234, x_planet=0.3))
    assert round(five.suggestion["x_ring"], 5) == five.suggestion["x_ring"] != round(five.suggestion["x_ring"], 4)
    assert shift_decimals([0.5, 0.0, -0.25]) == 4 and shift_decimals([1.5e-7]) == 8


@pytest.mark.parametrize(("x_sun", "x_planet"), [(0.61234567, 0.28712345), (0.55555, 0.33333),
                                                 (0.70004999, 0.30004999)])
def test_large_module_design_printed_to_four_decimals_passes(x_sun, x_planet):
    # a design made exactly coaxial, then written to 4 decimals as a calculation report prints it
    m = 25.0
    exact = check_coaxiality(SetGeometry.create(off_by_three(), module=m, x_sun=x_sun, x_planet=x_planet), 1e-12)
    x_ring = exact.suggestion["x_ring"]
    printed = SetGeometry.create(off_by_three(), module=m, x_sun=round(x_sun, 4), x_planet=round(x_planet, 4),
                                 x_ring=round(x_ring, 4))
    assert not check_coaxiality(printed, 1e-3).passed  # a fixed 1 µm refuses what was built
    check = check_coaxiality(printed)
    tolerance, basis = coaxiality_tolerance(printed)
    assert check.passed and check.tolerance == tolerance and "4 decimals at m_n = 25 mm" in basis
    # the tolerance is the rounding's effect: ±½ of the 4th decimal on each gear of both meshes, a few µm
    assert 1e-3 < tolerance < 1e-2


def test_iso_286_standard_tolerances():
    # ISO 286-1:2010, Table 1: IT7 50-80 mm = 30 µm, IT6 120-180 mm = 25 µm, IT5 <= 3 mm = 4 µm,
    # IT11 2500-3150 mm = 1350 µm, IT8 400-500 mm = 97 µm (a size on a range's upper limit belongs to it)
    assert standard_tolerance(7, 56.8) == 0.030
    assert standard_tolerance(6, 150.0) == 0.025
    assert standard_tolerance(5, 3.0) == 0.004
    assert standard_tolerance(11, 3150.0) == 1.350
    assert standard_tolerance(8, 500.0) == 0.097
    assert center_distance_allowance("js7", 56.8) == 0.015
    with pytest.raises(GeometryError, match="js5 … js11"):
        center_distance_allowance("h7", 56.8)
    with pytest.raises(GeometryError, match="IT5 … IT11"):
        standard_tolerance(4, 56.8)


FILE = """
[[planetary]]
name = "P"
sun = "in"
ring = "housing"
carrier = "out"
teeth = {{ sun = 20, planet = 37, ring = 97 }}
planets = 3
[planetary.geometry]
module = 2
profile_shift = {{ sun = 0.6, planet = 0.3, ring = {ring} }}
{extra}
"""


def test_file_center_distance_tolerance_js_field():
    geometry = loads_train_file(FILE.format(ring=0.31, extra='center_distance_tolerance = "js7"')).geometry["P"]
    check = check_coaxiality(geometry)
    # a = 58.64 mm: IT7 of 50-80 mm = 30 µm, js7 = ±15 µm; x_ring 0.31 instead of 0.3173 misses by more
    assert check.tolerance == 0.015 and "DIN 3964 field js7" in check.message and not check.passed
    with pytest.raises(InputFileError, match=r"key 'geometry.center_distance_tolerance': expected a positive number"):
        loads_train_file(FILE.format(ring=0.31, extra='center_distance_tolerance = "h7"'))
    with pytest.raises(InputFileError, match=r"center_distance_tolerance.*got -1"):
        loads_train_file(FILE.format(ring=0.31, extra="center_distance_tolerance = -1"))


def test_internal_shift_convention_khk_only_when_the_file_says_so():
    iso = loads_train_file(FILE.format(ring=0.3173, extra="")).geometry["P"]
    khk = loads_train_file(FILE.format(ring=-0.3173, extra='internal_shift_convention = "khk"')).geometry["P"]
    assert iso.gears["ring"].profile_shift == khk.gears["ring"].profile_shift == 0.3173
    assert [m.center_distance for m in iso.meshes] == [m.center_distance for m in khk.meshes]
    assert "ISO 21771 sign" in iso.table() and "given as KHK" in khk.table()
    assert iso.to_dict()["internal_shift_convention"] == "iso" and khk.to_dict()["internal_shift_convention"] == "khk"
    # the suggestion comes back in the file's own sign
    off = loads_train_file(FILE.format(ring=0.0, extra='internal_shift_convention = "khk"')).geometry["P"]
    assert check_coaxiality(off).suggestion["x_ring"] == -0.3173
    assert "KHK sign" in check_coaxiality(off).message
    with pytest.raises(InputFileError, match=r"internal_shift_convention': expected \"iso\""):
        loads_train_file(FILE.format(ring=0.0, extra='internal_shift_convention = "din"'))


def test_unknown_convention_in_python_is_refused():
    with pytest.raises(EpicyclicError, match="internal_shift_convention must be one of"):
        SetGeometry.create(off_by_three(), module=2.0, internal_shift_convention="agma")
