"""Errors located in the input file (epicyclic.io.located)."""

from __future__ import annotations

import pytest

from epicyclic.errors import (ContradictionError, ModelError, OperatingPointError, ToothCountError,
                              UnderdeterminedError)
from epicyclic.io import loads_train_file
from epicyclic.io.located import NonFiniteResultError, check_finite, locate_error, located
from epicyclic.transmission import GearFreedomError

SET = """
[[planetary]]
name = "P"
sun = "in"
ring = "ring"
carrier = "out"
stationary_ratio = -2
[[brake]]
name = "B"
shaft = "ring"
[operating_point]
speeds = { in = 3000 }
torques = { in = 10 }
drives = ["in"]
loads = ["out"]
"""


def test_located_keeps_class_and_fields_and_never_prefixes_twice():
    exc = UnderdeterminedError("planetary set 'P': the speed of 'x' is still free.", ["x"], "speed")
    once = located(exc, "t.toml", "[[planetary]] #1 'P'", owner="planetary set 'P'")
    assert type(once) is UnderdeterminedError and once.free == ("x",) and once.quantity == "speed"
    assert str(once) == "t.toml: [[planetary]] #1 'P': the speed of 'x' is still free."
    assert located(once, "t.toml", "elsewhere") is once
    assert str(located(ModelError("t.toml: no table."), "t.toml")) == "t.toml: no table."


@pytest.mark.parametrize(
    "exc, where",
    [
        (UnderdeterminedError("m", ["ring"], "speed"), "[operating_point], key 'speeds'"),
        (UnderdeterminedError("m", ["out"], "torque"), "[operating_point], key 'torques' or 'powers'"),
        (ContradictionError("m", ["in", "out"], "speed"), "[operating_point], keys 'speeds.in', 'speeds.out'"),
        (ContradictionError("m", ["out"], "torque"), "[operating_point], key 'torques.out'"),
        (OperatingPointError("m", group="powers", shafts=["x"]), "[operating_point], key 'powers.x'"),
        (OperatingPointError("m", group="drives"), "[operating_point], key 'drives'"),
        (GearFreedomError("m", "3", 2, ["x"]), "[transmission], key 'schedule.3'"),
        (ModelError("m"), ""),
    ],
)
def test_structured_fields_become_keys(exc, where):
    message = str(locate_error(exc, "t.toml"))
    assert message == (f"t.toml: {where}: m" if where else "t.toml: m")


def test_solver_stage_errors_name_the_file_and_key():
    cases = [
        (SET.replace('[[brake]]\nname = "B"\nshaft = "ring"\n', ""), UnderdeterminedError, "key 'speeds'"),
        (SET.replace("speeds = { in = 3000 }", "speeds = { in = 3000, out = 1 }"), ContradictionError,
         "keys 'speeds.in', 'speeds.out'"),
        (SET.replace("torques = { in = 10 }", "torques = { in = 10, out = 1 }"), ContradictionError,
         "'torques.out'"),
        (SET.replace('loads = ["out"]', "loads = []"), ContradictionError, "key 'torques.in'"),
        (SET.replace("torques = { in = 10 }", "powers = { ring = 10 }"), OperatingPointError,
         "key 'powers.ring'"),
        (SET.replace("torques = { in = 10 }", "torques = { out = 1 }\npowers = { in = 3 }")
         .replace('loads = ["out"]', 'loads = ["out"]'), ContradictionError, "[operating_point], key"),
    ]
    for text, error, key in cases:
        with pytest.raises(error) as info:
            loads_train_file(text, "t.toml").solve()
        assert str(info.value).startswith("t.toml: [operating_point]") and key in str(info.value), str(info.value)


def test_file_errors_keep_model_classes():
    with pytest.raises(ToothCountError, match=r"t.toml: \[\[planetary\]\] #1 'P', key 'teeth': z_planet"):
        loads_train_file(SET.replace("stationary_ratio = -2", "teeth = { sun = 30, planet = 2, ring = 78 }"),
                         "t.toml")
    with pytest.raises(ModelError, match=r"key 'stationary_ratio': '1/0' divides by zero\.$"):
        loads_train_file(SET.replace("-2", "'1/0'"), "t.toml")


def test_check_finite_names_the_first_non_finite_quantity():
    check_finite({"a": [1.0, {"b": 2.0}], "c": None, "d": "x"}, "t.toml")
    with pytest.raises(NonFiniteResultError, match=r"t.toml: result 'a\[1\]\.b' is nan") as info:
        check_finite({"a": [1.0, {"b": float("nan")}], "z": float("inf")}, "t.toml")
    assert info.value.quantity == "a[1].b"


def test_gears_names_the_gear_a_solver_error_comes_from(monkeypatch):
    from pathlib import Path

    from typer.testing import CliRunner

    from epicyclic.cli.main import app
    from epicyclic.transmission import Transmission

    original = Transmission.analyze

    def analyze(self, gear, **kwargs):
        if gear == "2":
            raise UnderdeterminedError("the torques at 'x' are not determined.", ["x"], "torque")
        return original(self, gear, **kwargs)

    monkeypatch.setattr(Transmission, "analyze", analyze)
    path = Path(__file__).resolve().parents[2] / "examples" / "simpson_c4_3speed.toml"
    result = CliRunner().invoke(app, ["gears", str(path)])
    assert result.exit_code == 2
    assert result.stderr == f"error: {path}: [transmission], key 'schedule.2': the torques at 'x' are not determined.\n"
