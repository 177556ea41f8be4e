"""The operating-point form and the TOML text: written with tomlkit, read back by the loader unchanged."""

from __future__ import annotations

import tomllib

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from epicyclic.io import loads_train_file
from epicyclic.web.examples import bundled_examples
from epicyclic.web.state import (FormError, PageState, ShaftRow, clean_text, operating_rows,
                                 write_operating_point)

SIMPLE = bundled_examples()["simple_set_ring_held_sun_drives"].text


@settings(max_examples=60, deadline=None)
@given(speed=st.floats(min_value=-1e6, max_value=1e6, allow_nan=False).filter(lambda v: abs(v) > 1e-3),
       torque=st.floats(min_value=1e-3, max_value=1e6, allow_nan=False))
def test_form_values_reach_the_operating_point_unchanged(speed, torque):
    """Invariant: a plain number in the form is the file's value, read back exactly (core units here)."""
    rows = (ShaftRow("sun", "drive", repr(speed), "torque", repr(torque)), ShaftRow("ring"),
            ShaftRow("carrier", "load"))
    text = write_operating_point(SIMPLE, rows, "")
    op = loads_train_file(text).operating_point
    assert op.speeds == {"sun": speed} and op.torques == {"sun": torque} and not op.powers
    assert op.drives == ("sun",) and op.loads == ("carrier",)
    assert operating_rows(tomllib.loads(text), ["sun", "ring", "carrier"])[0].speed == repr(speed).removesuffix(".0")


def test_comments_and_other_tables_survive():
    rows = (ShaftRow("sun", "drive", "2000 rpm", "power", "5 kW"), ShaftRow("carrier", "load"))
    text = write_operating_point(SIMPLE, rows, "")
    assert text.startswith("# A simple (minus) set") and "[[brake]]" in text
    solution = loads_train_file(text).solve()
    assert solution.speed("sun") == pytest.approx(2000) and solution.power("sun") == pytest.approx(5000)


def test_names_that_need_quotes_and_a_file_without_operating_point():
    text = '[[planetary]]\nname = "P"\nsun = "a b"\nring = "r.1"\ncarrier = "c"\nstationary_ratio = -2\n'
    rows = (ShaftRow("a b", "drive", "100", "torque", "1"), ShaftRow("r.1", "", "0"), ShaftRow("c", "load"))
    written = write_operating_point(text, rows, "")
    op = loads_train_file(written).operating_point
    assert op.speeds == {"a b": 100.0, "r.1": 0.0} and op.drives == ("a b",)


def test_invalid_toml_is_left_to_the_loader():
    with pytest.raises(tomllib.TOMLDecodeError):
        write_operating_point("[[planetary]\n", (), "")


class Form(dict):
    """A mapping with ``getlist`` and ``multi_items`` like Starlette's FormData."""

    def getlist(self, key):
        value = super().get(key, [])
        return value if isinstance(value, list) else [value]

    def get(self, key, default=None):
        value = super().get(key, default)
        return value[0] if isinstance(value, list) and value else value

    def multi_items(self):
        return [(k, v) for k, vs in self.items() for v in (vs if isinstance(vs, list) else [vs])]


def test_page_state_from_form():
    state = PageState.from_form(Form(toml="x = 1", shaft=["a", "b"], role=["drive", ""], speed=["1", ""],
                                     moment=["torque", "power"], value=["2", ""], units="si", lang="de",
                                     tool_fit_module="2", gear="R"), max_text=100)
    assert state.rows[1] == ShaftRow("b", "", "", "power", "") and state.units == "si" and state.gear == "R"
    assert state.extra == {"tool_fit_module": "2"}


@pytest.mark.parametrize("fields, message", [
    (dict(toml="x" * 101), "at most 100"),
    (dict(shaft=["a"], role=[]), "every shaft row"),
    (dict(shaft=["a"], role=["boss"], speed=[""], moment=["torque"], value=[""]), "role of shaft 'a'"),
    (dict(shaft=["a"], role=[""], speed=[""], moment=["force"], value=[""]), "expected 'torque' or 'power'"),
    (dict(units="imperial"), "units must be one of"),
    (dict(lang="fr"), "language must be one of"),
])
def test_page_state_errors(fields, message):
    with pytest.raises(FormError, match=message):
        PageState.from_form(Form({"toml": "", **fields}), max_text=100)


def test_clean_text_drops_control_characters():
    assert clean_text("a\x00b\u202ec\n", "f", 10) == "abc"
    assert clean_text("a\nb", "f", 10, single_line=False) == "a\nb"
    assert clean_text(None, "f", 1) == ""


@pytest.mark.parametrize("key", ["zf_8hp70_8speed", "zf_8hp70_geometry", "simpson_c4_3speed"])
def test_texts_for_every_gear_at_once_are_the_texts_of_each_gear(key):
    """The texts drawn ahead (one parse) are exactly what the form writes for each gear (one parse each)."""
    from epicyclic.web.state import default_operating_rows, write_operating_points

    text = bundled_examples()[key].text
    train_file = loads_train_file(text)
    spec = train_file.transmission
    rows = (operating_rows(tomllib.loads(text), train_file.train.moving_shafts) if train_file.operating_point
            else default_operating_rows(train_file.train.moving_shafts, spec.input, spec.output))
    gears = list(spec.gears)[::-1]
    assert write_operating_points(text, rows, gears) == tuple(write_operating_point(text, rows, g) for g in gears)
