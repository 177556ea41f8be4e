"""A cold start of the 8HP example with open-clutch drag (issue 30).

At −20 °C the oil of ``examples/zf_8hp70_spin_losses.toml`` (ν given at 40 and 100 °C only) is
extrapolated by Walther's line to about 1000 mm²/s, and the open clutches' drag takes far more power
than the 15 N·m input gives.  Before: no word of the extrapolation, and every gear labelled
"self-locking" — a verdict about the gearing (Brandenberger 1952, text to Bild 9) that is false here.
"""

from __future__ import annotations

import json

import pytest

from epicyclic.io import load_train_file
from epicyclic.losses.oil import Oil
from epicyclic.transmission import Transmission
from epicyclic.transmission.input_point import input_point

FILE = "examples/zf_8hp70_spin_losses.toml"


@pytest.fixture(scope="module")
def cold():
    spec = load_train_file(FILE, overrides=["lubricant.temperature=-20"])
    transmission = Transmission.from_train_file(spec)
    point = input_point(transmission.input, spec.operating_point, speed="2379", torque="15", units=spec.units)
    return transmission.analyze_all(point=point)


def test_spin_losses_beyond_the_input_are_not_called_self_locking(cold):
    first = cold.gears[0]
    locked = first.drive.self_locking
    assert locked is not None and locked.cause == "no-load losses" and locked.label == "losses > input"
    assert "not a self-locking of the gearing" in locked.message and "self-locks" not in locked.message
    no_load = sum(v for e in first.drive.elements.values() for k, v in e.loss_sources.items()
                  if k not in ("mesh", "bearing")) + sum(first.drive.housing_loss_sources.values())
    assert no_load > first.drive.input_power  # the spin losses alone exceed the input: the verdict's reason
    table = cold.table()
    assert "losses > input" in table and "self-locking" not in table


def test_an_extrapolated_viscosity_is_warned(cold):
    warnings = cold.oil_warnings
    assert len(warnings) == 1 and "-20 degC lies outside the lubricant's viscosity data (40 ... 100 degC)" in warnings[0]
    assert warnings[0] in cold.table() and json.loads(json.dumps(cold.to_dict()))["warnings"] == list(warnings)


def test_within_the_data_there_is_no_warning_and_the_margin_is_stated():
    oil = Oil(29.5, 6.0)
    assert oil.extrapolation_warning(80.0) is None and oil.extrapolation_warning(20.0) is None
    assert oil.extrapolation_warning(19.0) is not None and oil.extrapolation_warning(121.0) is not None
    table = Oil.from_table([(-20.0, 1500.0), (40.0, 29.5), (100.0, 6.0)])
    assert table.data_range == (-20.0, 100.0) and table.extrapolation_warning(-20.0) is None


def test_a_real_self_locking_keeps_its_name():
    # Brandenberger's plus set driven from the wrong side self-locks whatever the input: no no-load losses
    from epicyclic.io import load_train_file as load

    solution = load("examples/plus_set_self_locking.toml").solve()
    assert solution.self_locking is not None and solution.self_locking.cause == "self-locking"
    assert solution.self_locking.label == "self-locking"
