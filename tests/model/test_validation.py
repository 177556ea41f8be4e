"""Bad model input gives a clear EpicyclicError (also ValueError) naming the field and the fix."""

import pytest

from epicyclic import (
    Brake,
    Clutch,
    EfficiencyError,
    EpicyclicError,
    GearStage,
    GearTrain,
    ModelError,
    OperatingPoint,
    OperatingPointError,
    PlanetarySet,
    ToothCountError,
    TopologyError,
)
from epicyclic.units import UnitError


def simple(**kw):
    args = dict(sun="s", ring="r", carrier="c", z_sun=30, z_planet=24, z_ring=78)
    args.update(kw)
    return PlanetarySet.simple("P1", **args)


@pytest.mark.parametrize(
    ("make", "error", "match"),
    [
        (lambda: simple(z_ring=20), ToothCountError, r"ring must have more teeth than the sun.*z_ring=20"),
        # regression: a ring smaller than the sun is named as such, not as a negative planet
        (lambda: simple(z_ring=20, z_planet=-5), ToothCountError, r"ring must have more teeth than the sun"),
        (lambda: simple(z_planet=40), ToothCountError, r"cannot mesh coaxially.*78 - 30 - 2\*40 = -32.*z_planet=24"),
        (lambda: simple(z_planet=2), ToothCountError, r"z_planet must be at least 3 teeth, got 2"),
        (lambda: simple(z_sun=30.5), ToothCountError, r"z_sun must be a whole number of teeth, got 30.5"),
        (lambda: simple(stationary_efficiency=1.2), EfficiencyError, r"stationary_efficiency must lie in \(0, 1\].*1.2"),
        (lambda: simple(stationary_efficiency=0.0), EfficiencyError, r"must lie in \(0, 1\]"),
        (lambda: simple(stationary_efficiency=97), EfficiencyError, r"not a percentage"),
        (lambda: simple(mesh_efficiencies=(0.99,)), ModelError, r"mesh_efficiencies must have 2 values"),
        (lambda: simple(mesh_efficiencies=(0.99, -1)), EfficiencyError, r"mesh_efficiencies\[1\]"),
        (lambda: simple(ring="s"), ModelError, r"three different shafts"),
        (lambda: PlanetarySet("P", "a", "b", "c", 1.0), ModelError, r"must not be 0 or 1"),
        (lambda: PlanetarySet("P", "a", "b", "c", float("nan")), ModelError, r"finite number"),
        (lambda: PlanetarySet("P", "a", "b", "c", -2.0, planets=0), ModelError, r"planets must be a whole number >= 1"),
        (lambda: PlanetarySet("", "a", "b", "c", -2.0), ModelError, r"name must be a non-empty"),
        (lambda: GearStage("G", "a", "a", 2.0), ModelError, r"different shafts"),
        (lambda: GearStage("G", "a", "b", 0.0), ModelError, r"finite, non-zero"),
        (lambda: GearStage("G", "a", "housing", 2.0), TopologyError, r"use a Brake"),
        (lambda: GearStage.from_teeth("G", "a", "b", [(20, 1)]), ToothCountError, r"z_driven must be a whole number of at least 3"),
        (lambda: GearStage.from_teeth("G", "a", "b", [(20, 40, "spiral")]), ModelError, r"'external' or 'internal'"),
        (lambda: Brake("B", "housing"), TopologyError, r"brake on the housing holds nothing"),
        (lambda: Clutch("C", "a", "housing"), TopologyError, r"is a brake; use Brake\('C', 'a'\)"),
        (lambda: GearTrain([]), ModelError, r"at least one element"),
        (lambda: GearTrain([Brake("B", "a"), Brake("B", "b")]), ModelError, r"'B' is used twice"),
        (lambda: GearTrain(["not an element"]), ModelError, r"must be a PlanetarySet, GearStage, Clutch or Brake"),
        (lambda: OperatingPoint(speeds={"a": float("inf")}), OperatingPointError, r"speeds\['a'\] must be finite"),
        (lambda: OperatingPoint(speeds={"a": "fast"}), UnitError, r"operating_point\.speeds\.a: cannot read 'fast'"),
        (lambda: OperatingPoint(speeds={"a": [1500]}), UnitError, r"operating_point\.speeds\.a: expected a number"),
        (lambda: OperatingPoint(drives=["a"], loads=["a"]), OperatingPointError, r"both as drive and as load"),
        (lambda: OperatingPoint(torques={"a": 1}, powers={"a": 1}), OperatingPointError, r"not both"),
        # regressions (Python API pass): each was a bare TypeError/ValueError from deep inside, or silent
        (lambda: GearTrain(Brake("B", "a")), ModelError, r"elements must be a list of elements, got one Brake 'B'"),
        (lambda: GearTrain(5), ModelError, r"elements must be a list, got int 5"),
        (lambda: GearTrain([Brake("B", "a")], shafts=3), ModelError, r"shafts must be a list, got int 3"),
        (lambda: OperatingPoint(speeds="sun"), OperatingPointError, r"speeds must be a mapping shaft → value, e\.g\."),
        (lambda: OperatingPoint(speeds=["ab"]), OperatingPointError, r"speeds must be a mapping"),
        (lambda: OperatingPoint(drives=["a", 3]), OperatingPointError, r"drives must be shaft names.*got 3"),
        (lambda: OperatingPoint(loads=None), OperatingPointError, r"loads must be shaft names.*got None"),
    ],
)
def test_bad_model_input(make, error, match):
    with pytest.raises(error, match=match) as info:
        make()
    assert isinstance(info.value, EpicyclicError) and isinstance(info.value, ValueError)


def test_with_engaged_rejects_unknown_element():
    train = GearTrain([PlanetarySet("P", "a", "b", "c", -2.0), Brake("B", "b", engaged=False)])
    assert train.with_engaged(["B"]).element("B").engaged is True
    assert train.with_engaged([]).element("B").engaged is False
    with pytest.raises(ModelError, match="'X' is not a clutch or brake"):
        train.with_engaged(["X"])


def test_values_are_frozen():
    s = simple()
    with pytest.raises(AttributeError):
        s.stationary_ratio = 3.0


@pytest.mark.parametrize(
    ("factory", "expected"),
    [
        # Simple set: i0 = −z_ring/z_sun (tec-science, "Willis-Gleichung", "Festgestellter Steg").
        (lambda: simple(), -78 / 30),
        # Double planet: sun–p1–p2–ring, two external meshes and one internal: i0 = +z_ring/z_sun.
        (lambda: PlanetarySet.double_planet("D", sun="s", ring="r", carrier="c", z_sun=30, z_planet_sun=18,
                                            z_planet_ring=19, z_ring=90), 90 / 30),
        # Stepped planet with two suns (Brandenberger 1952, Bild 1): i0 = (b·d)/(a·c) = 24·42/(50·30).
        (lambda: PlanetarySet.stepped("S", sun="s", ring="r", carrier="c", z_sun=50, z_planet_sun=24,
                                      z_planet_ring=30, z_ring=42, ring_internal=False), 24 * 42 / (50 * 30)),
        # Stepped planet with a ring: i0 = −(z_ring·z_b)/(z_c·z_sun).
        (lambda: PlanetarySet.stepped("S", sun="s", ring="r", carrier="c", z_sun=20, z_planet_sun=40,
                                      z_planet_ring=20, z_ring=80), -80 * 40 / (20 * 20)),
    ],
)
def test_stationary_ratio_from_teeth(factory, expected):
    assert factory().stationary_ratio == pytest.approx(expected, rel=1e-15)


def test_mesh_efficiencies_combine_by_product():
    # Brandenberger 1952: the set's efficiency is the product η1·η2 of its two meshes.
    s = simple(mesh_efficiencies=(0.99, 0.98))
    assert s.stationary_efficiency == pytest.approx(0.99 * 0.98)


def test_one_extra_shaft_is_a_name_not_its_letters():
    assert GearTrain([Brake("B", "a")], shafts="spare").shafts == ("spare", "a", "housing")


def test_an_operating_point_hashes_by_value():
    # regression: hash() raised "unhashable type: 'mappingproxy'" (a frozen value as a cache key)
    a = OperatingPoint(speeds={"in": 3000}, powers={"in": "10 kW"}, drives=["in"], loads="out")
    b = OperatingPoint(speeds={"in": "3000 rpm"}, powers={"in": 10_000}, drives="in", loads=["out"])
    assert a == b and hash(a) == hash(b) and len({a, b}) == 1
    assert hash(a) != hash(OperatingPoint(speeds={"in": 3001}, powers={"in": 10_000}, drives="in", loads="out"))


@pytest.mark.parametrize(("name", "hint"), [("sunn", "'sun'"), ("Ring", "'ring'"), ("carier", "'carrier'")])
def test_an_unknown_shaft_suggests_the_close_name(name, hint):
    from epicyclic import UnknownShaftError, solve

    train = GearTrain([simple(sun="sun", ring="ring", carrier="carrier"), Brake("B", "ring")])
    op = OperatingPoint(speeds={name: 3000}, torques={"sun": 10}, drives=["sun"], loads=["carrier"])
    with pytest.raises(UnknownShaftError, match=f"unknown shaft '{name}'.*Did you mean {hint}"):
        solve(train, op)


def test_a_shaft_that_is_no_string_is_named_as_such():
    from epicyclic import UnknownShaftError, solve

    train = GearTrain([simple(sun="sun", ring="ring", carrier="carrier"), Brake("B", "ring")])
    sol = solve(train, OperatingPoint(speeds={"sun": 3000}, torques={"sun": 10}, drives=["sun"], loads=["carrier"]))
    with pytest.raises(UnknownShaftError, match="a shaft is named by a string, got int 1"):  # was AttributeError
        sol.speed(1)
    with pytest.raises(ModelError, match="no element named 'p1'.*Did you mean 'P1'"):
        train.element("p1")
