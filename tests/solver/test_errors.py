"""Underdetermined and contradictory operating points name the shafts concerned."""

import pytest

from epicyclic import (
    Brake,
    ContradictionError,
    GearStage,
    GearTrain,
    OperatingPoint,
    OperatingPointError,
    PlanetarySet,
    UnderdeterminedError,
    UnknownShaftError,
    solve,
)


def single_set(held=True):
    elements = [PlanetarySet("P", "sun", "ring", "carrier", -2.0, 0.98)]
    if held:
        elements.append(Brake("B", "ring"))
    return GearTrain(elements)


def test_free_speeds_are_named():
    train = single_set(held=False)  # two degrees of freedom, one speed given
    op = OperatingPoint(speeds={"sun": 1000}, torques={"sun": 1}, drives=["sun"], loads=["carrier"])
    with pytest.raises(UnderdeterminedError, match=r"speed of shaft\(s\) 'ring', 'carrier' is still free.*2 degree") as info:
        solve(train, op)
    assert info.value.free == ("ring", "carrier") and info.value.quantity == "speed"


def test_no_speed_given():
    op = OperatingPoint(torques={"sun": 1}, drives=["sun"], loads=["carrier"])
    with pytest.raises(UnderdeterminedError, match="no speed given"):
        solve(single_set(), op)


def test_contradictory_speeds_are_named_with_implied_value():
    op = OperatingPoint(speeds={"sun": 900, "carrier": 250}, torques={"sun": 1}, drives=["sun"], loads=["carrier"])
    with pytest.raises(ContradictionError, match=r"n\[sun\] = 900 1/min is given, but .* imply n\[sun\] = 750") as info:
        solve(single_set(), op)
    assert set(info.value.conflicting) == {"sun", "carrier"}


def test_speed_at_held_shaft_contradicts_the_brake():
    op = OperatingPoint(speeds={"sun": 900, "ring": 100}, torques={"sun": 1}, drives=["sun"], loads=["carrier"])
    with pytest.raises(ContradictionError, match=r"n\[ring\] = 100 1/min is given, but the train .*n\[ring\] = 0") as info:
        solve(single_set(), op)
    assert info.value.conflicting == ("ring",)


def test_housing_speed_must_be_zero():
    op = OperatingPoint(speeds={"sun": 900, "housing": 5}, torques={"sun": 1}, drives=["sun"], loads=["carrier"])
    with pytest.raises(ContradictionError, match="housing .* stands still"):
        solve(single_set(), op)


def test_no_torque_given_names_the_free_torques():
    op = OperatingPoint(speeds={"sun": 900}, drives=["sun"], loads=["carrier"])
    with pytest.raises(UnderdeterminedError, match=r"torques at shaft\(s\) .*'sun'.*not determined.*no torque or power") as info:
        solve(single_set(), op)
    assert info.value.quantity == "torque" and "housing" not in info.value.free


def test_contradictory_torques():
    op = OperatingPoint(speeds={"sun": 900}, torques={"sun": 1, "carrier": 10}, drives=["sun"], loads=["carrier"])
    with pytest.raises(ContradictionError, match=r"given torques/powers contradict.*'sun', 'carrier'") as info:
        solve(single_set(), op)
    assert info.value.quantity == "torque"


def test_torque_with_no_reaction():
    op = OperatingPoint(speeds={"sun": 900}, torques={"sun": 1})
    with pytest.raises(ContradictionError, match="cannot be balanced.*Name the shafts where power leaves"):
        solve(single_set(), op)


@pytest.mark.parametrize(
    ("op", "match"),
    [
        (OperatingPoint(speeds={"Sun": 900}, torques={"sun": 1}, drives=["sun"], loads=["carrier"]),
         r"unknown shaft 'Sun'.*Did you mean 'sun'\?"),
        (OperatingPoint(speeds={"sun": 900}, torques={"sun": 1}, drives=["sun"], loads=["output"]),
         r"unknown shaft 'output'; the train has shafts 'sun', 'ring', 'carrier', 'housing'"),
    ],
)
def test_unknown_shafts(op, match):
    with pytest.raises(UnknownShaftError, match=match):
        solve(single_set(), op)


def test_power_at_standstill():
    op = OperatingPoint(speeds={"sun": 900}, powers={"ring": 100}, drives=["sun"], loads=["carrier"])
    with pytest.raises(OperatingPointError, match=r"powers\['ring'\].*stands still.*give torques\['ring'\]"):
        solve(single_set(), op)


def test_housing_cannot_be_a_drive():
    op = OperatingPoint(speeds={"sun": 900}, torques={"sun": 1}, drives=["housing"])
    with pytest.raises(OperatingPointError, match="housing cannot be one of the drives"):
        solve(single_set(), op)


def test_redundant_locking_is_a_warning_not_an_error():
    # A set locked by two clutches at once: the split of torque between the set and the clutches
    # is statically indeterminate, but every external torque, speed and loss is determined.
    from epicyclic import Clutch

    train = GearTrain([
        PlanetarySet("P", "sun", "ring", "carrier", -2.0, 0.98),
        Clutch("C1", "sun", "carrier"), Clutch("C2", "ring", "carrier"),
    ])
    op = OperatingPoint(speeds={"sun": 1000}, torques={"sun": 10}, drives=["sun"], loads=["ring"])
    sol = solve(train, op)
    assert sol.speed("ring") == pytest.approx(1000)
    assert sol.torque("ring") == pytest.approx(-10)
    assert sol.efficiency == pytest.approx(1.0)
    assert any("statically indeterminate" in w for w in sol.warnings)


@pytest.mark.parametrize("train_arg, op_arg, error, words", [
    ("dict", "op", "ModelError", "first argument must be a GearTrain, got dict"),
    ("list", "op", "ModelError", "got list"),
    ("train", "dict", "OperatingPointError", "must be an OperatingPoint, got dict"),
    ("train", "None", "OperatingPointError", "got NoneType"),
])
def test_wrong_argument_types_are_named(train_arg, op_arg, error, words):
    """solve(train, dict) and the like: an error naming the argument and how to build it, not an
    AttributeError from inside the solver."""
    import epicyclic

    train = single_set()
    op = OperatingPoint(speeds={"sun": 1000}, torques={"sun": 10}, drives=["sun"], loads=["carrier"])
    args = {"train": train, "op": op, "dict": {"speeds": {"sun": 1000}}, "list": [train], "None": None}
    with pytest.raises(getattr(epicyclic.errors, error), match=words):
        solve(args[train_arg], args[op_arg])
