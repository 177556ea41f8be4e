"""--set KEY=VALUE: overrides applied to the parsed TOML before validation (messages name the key)."""

from __future__ import annotations

from pathlib import Path

import pytest

from epicyclic.io import InputFileError, OverrideError, apply_overrides, load_train_file
from epicyclic.io.overrides import parse_override
from epicyclic.units import UnitError

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
BRANDENBERGER = EXAMPLES / "brandenberger_1952.toml"


@pytest.mark.parametrize(
    ("text", "path", "value"),
    [
        ('operating_point.speeds.sun="2000 rpm"', ("operating_point", "speeds", "sun"), "2000 rpm"),
        ("operating_point.speeds.sun=2000 rpm", ("operating_point", "speeds", "sun"), "2000 rpm"),
        ("operating_point.speeds.sun=2000", ("operating_point", "speeds", "sun"), 2000),
        ("planetary.P1.stationary_efficiency=0.97", ("planetary", "P1", "stationary_efficiency"), 0.97),
        ('operating_point.drives=["in", "x"]', ("operating_point", "drives"), ["in", "x"]),
        ('transmission.schedule."1"=["A"]', ("transmission", "schedule", "1"), ["A"]),
        ("clutch.C.engaged=false", ("clutch", "C", "engaged"), False),
        (" title = My train ", ("title",), "My train"),
        ("title==x", ("title",), "=x"),
    ],
)
def test_parse_override(text, path, value):
    assert parse_override(text) == (path, value)


@pytest.mark.parametrize(
    ("text", "match"),
    [
        ("no-equals-sign", r"expected KEY=VALUE"),
        ("=3", r"expected KEY=VALUE"),
        ("a..b=3", r"is not one dotted key"),
        ("a b=3", r"is not one dotted key"),
    ],
)
def test_malformed_overrides(text, match):
    with pytest.raises(OverrideError, match=match):
        parse_override(text)


def test_overrides_pick_elements_by_name_or_number_and_leave_the_input_alone():
    data = {"planetary": [{"name": "P1", "stationary_efficiency": 0.9}, {"name": "P2"}],
            "operating_point": {"speeds": {"in": 1}}}
    result = apply_overrides(data, ["planetary.P2.stationary_efficiency=0.95", "planetary.1.planets=4",
                                    "operating_point.torques.in=10", "operating_point.speeds.in=2"])
    assert result["planetary"][1]["stationary_efficiency"] == 0.95
    assert result["planetary"][0]["planets"] == 4
    assert result["operating_point"] == {"speeds": {"in": 2}, "torques": {"in": 10}}
    assert data["operating_point"]["speeds"]["in"] == 1 and "planets" not in data["planetary"][0]  # a copy


@pytest.mark.parametrize(
    ("text", "match"),
    [
        ("planetary.P9.planets=4", r"no \[\[planetary\]\] named 'P9'; give a name \('P1'\) or a number from 1 to 1"),
        ("planetary.2.planets=4", r"no \[\[planetary\]\] named '2'"),
        ("planetary.P1=4", r"planetary is an array of tables; set a key of one element"),
        ("title.x=4", r"title is the value 'T', not a table"),
        ("operating_point.drives.x=1", r"operating_point.drives is an array of values, not of tables"),
    ],
)
def test_overrides_that_do_not_fit_the_file(text, match):
    data = {"title": "T", "planetary": [{"name": "P1"}], "operating_point": {"drives": ["in"]}}
    with pytest.raises(OverrideError, match=match):
        apply_overrides(data, [text])


def test_loading_with_overrides_changes_the_solution():
    base = load_train_file(BRANDENBERGER).solve()
    faster = load_train_file(BRANDENBERGER, overrides=['operating_point.speeds.II="3000 U/min"']).solve()
    assert faster.speed("I") == pytest.approx(2 * base.speed("I"), rel=1e-12)  # same power, twice the speed
    assert faster.efficiency == pytest.approx(base.efficiency, rel=1e-12)
    lossless = load_train_file(BRANDENBERGER, overrides=["planetary.planetary.stationary_efficiency=1",
                                                         "gear.stage.efficiency=1"]).solve()
    assert lossless.efficiency == pytest.approx(1.0, rel=1e-12)


def test_overridden_values_are_validated_like_the_file_and_named():
    with pytest.raises(UnitError, match=r"brandenberger_1952.toml: \[operating_point\], key 'speeds\.II': cannot read 'fast'"):
        load_train_file(BRANDENBERGER, overrides=["operating_point.speeds.II=fast"])
    with pytest.raises(InputFileError, match=r"\[\[planetary\]\] #1 'planetary', key 'stationary_efficiency': "
                                             r"expected an efficiency in \(0, 1\]"):
        load_train_file(BRANDENBERGER, overrides=["planetary.1.stationary_efficiency=1.5"])
    with pytest.raises(InputFileError, match=r"unknown key 'sped'.*did you mean 'speeds'"):
        load_train_file(BRANDENBERGER, overrides=["operating_point.sped.II=5"])
    with pytest.raises(OverrideError, match=r"brandenberger_1952.toml: --set 'planetary.x.planets=3'"):
        load_train_file(BRANDENBERGER, overrides=["planetary.x.planets=3"])


def test_a_key_of_sixty_thousand_parts_is_refused_at_once():
    # issue 30: `--set` with a dotted key of 60 000 parts hung past 20 s (tomllib on the whole key)
    import time

    start = time.perf_counter()
    with pytest.raises(OverrideError, match="the key has 60001 parts; keys nest at most"):
        parse_override("a." * 60000 + "b=1")
    assert time.perf_counter() - start < 2.0  # a linear scan; generous for a loaded 2-core machine
    assert parse_override('a."b.c".d=1') == (("a", "b.c", "d"), 1)  # dots inside a quoted part do not count
