"""Inputs of the scuffing rating: errors naming the key and the value commonly taken, the TOML table."""

from __future__ import annotations

from pathlib import Path

import pytest

from epicyclic.errors import EpicyclicError
from epicyclic.io import loads_train_file
from epicyclic.io.reader import InputFileError
from epicyclic.rating import RatingError
from epicyclic.rating.scuffing import ScuffingSpec

EXAMPLE = Path(__file__).resolve().parents[3] / "examples" / "rating" / "helical_stage_scuffing.toml"
BASE = {"oil_temperature": 80.0, "roughness_Ra": 0.6, "load_stage": 12}


@pytest.mark.parametrize(("missing", "message"), [
    ("oil_temperature", "oil_temperature is missing.*oil_temperature = 80.0"),
    ("roughness_Ra", "roughness_Ra is missing.*roughness_Ra = 0.5"),
    ("load_stage", "load_stage is missing.*load_stage = 12"),
])
def test_missing_required_key(missing, message):
    with pytest.raises(RatingError, match=message):
        ScuffingSpec(**{k: v for k, v in BASE.items() if k != missing})


@pytest.mark.parametrize(("key", "value", "message"), [
    ("load_stage", 15, "1 ... 12"), ("load_stage", 0, "1 ... 12"), ("oil_type", "castor", "oil_type must be one of"),
    ("lubrication", "mist", "lubrication must be one of"), ("driving", "sun", "driving must be"),
    ("edition", "2030", "edition must be one of"), ("oil_temperature", float("nan"), "oil_temperature must be"),
    ("roughness_Ra", -0.1, "roughness_Ra must be"), ("S_Smin", 0.0, "S_Smin must be"),
    ("scuffing_temperature", 50.0, "scuffing_temperature must be a number > 80"), ("run_in", 1.5, "run_in must be"),
])
def test_bad_values(key, value, message):
    with pytest.raises(RatingError, match=message):
        ScuffingSpec(**(BASE | {key: value}))


def test_temperatures_instead_of_a_load_stage_and_per_gear_roughness():
    spec = ScuffingSpec(oil_temperature=80.0, roughness_Ra={"sun": 0.4, "ring": 0.9},
                        integral_scuffing_temperature=400.0, scuffing_temperature=420.0)
    assert spec.load_stage is None and spec.roughness_of("P", "ring") == 0.9
    with pytest.raises(RatingError, match="no entry for gear 'planet'"):
        spec.roughness_of("P", "planet")
    assert spec.clauses == ("ISO/TS 6336-20:2017", "ISO/TS 6336-21:2017")
    assert ScuffingSpec(**(BASE | {"edition": "2000"})).clauses[1] == "ISO/TR 13989-2:2000"
    assert spec.to_dict()["roughness_Ra"] == {"sun": 0.4, "ring": 0.9}


def test_the_toml_table():
    """[rating.scuffing] is read into RatingSpec.scuffing; unknown keys and bad values name the file's key."""
    text = EXAMPLE.read_text(encoding="utf-8")
    tf = loads_train_file(text, EXAMPLE)
    assert tf.rating.scuffing.load_stage == 12 and tf.rating.scuffing.driving == "gear1"
    assert tf.rating.to_dict()["scuffing"]["oil_density"] == 890.0
    with pytest.raises(InputFileError, match=r"rating.scuffing.*colour"):
        loads_train_file(text.replace("load_stage = 12", "load_stage = 12\ncolour = 1"), EXAMPLE)
    with pytest.raises(EpicyclicError, match=r"helical_stage_scuffing.toml: \[rating.scuffing\].*load_stage"):
        loads_train_file(text.replace("load_stage = 12", "load_stage = 15"), EXAMPLE)
    with pytest.raises(EpicyclicError, match=r"oil_temperature is missing"):
        loads_train_file(text.replace("oil_temperature = 80.0", ""), EXAMPLE)
