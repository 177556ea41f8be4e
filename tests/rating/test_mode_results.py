"""ModeRating (epicyclic.rating.mode_results): a failure mode's safety, minimum, rendering and JSON."""

import json

import numpy as np
import pytest

from epicyclic.rating.mode_results import ModeRating, mode_rows
from epicyclic.rating.results import Factor


def mode(values, minimum=1.0, per_gear=False):
    f = {"lambda": Factor("lambda", 0.3, "1", "somewhere, eq. (2)", "a quantity")}
    gears = None
    if per_gear:
        gears = ({"S_X": Factor("S_X", values[0], "1", "eq. (1)", "safety")},
                 {"S_X": Factor("S_X", values[1], "1", "eq. (1)", "safety")})
    else:
        f["S_X"] = Factor("S_X", values, "1", "eq. (1)", "safety")
    return ModeRating("test", "Test mode", "a method", f, "S_X", minimum, gear_factors=gears,
                      profile={"gamma": np.array([-0.5, 0.0, 0.5]), "points": {"A": -0.5}}, notes=("a note",))


def test_safety_ok_and_below_minimum():
    good, bad = mode(1.5), mode(np.array([1.5, 0.8]))
    assert good.ok and good.below_minimum() is None and good.value == 1.5
    assert not bad.ok and bad.below_minimum() == "S_X 0.8 < 1"
    pair = mode((1.4, 1.2), per_gear=True)
    assert pair.value == 1.2 and pair.ok
    assert not mode((1.4, 0.9), per_gear=True).ok


def test_rendering_marks_the_shortfall():
    bad = mode(0.8)
    rows = mode_rows(bad)
    assert rows[-2][3] == "0.8 !" and rows[0][1] == "λ"
    assert rows[-1][1:4] == ["S_Xmin", "1", "1"]  # the minimum beside the safety
    assert "Test mode" in bad.table() and "0.8 !" in bad.table()
    assert "class='below'" in bad.html() and "a note" in bad.html() and bad._repr_html_() == bad.html()
    assert bad.markdown().startswith("#### Test mode") and "*note: a note*" in bad.markdown()
    assert "class='below'" not in mode(1.5).html()
    per_gear = mode_rows(mode((1.4, 0.9), per_gear=True))
    assert per_gear[-2][3:5] == ["1.4", "0.9 !"] and per_gear[-1][3:5] == ["1", "1"]


def test_json_is_strict():
    data = json.loads(json.dumps(mode(np.array([np.inf, 1.2])).to_dict(), allow_nan=False))
    assert data["value"] == [None, 1.2] and data["profile"]["points"] == {"A": -0.5}
    assert data["factors"]["S_X"]["clause"] == "eq. (1)" and data["notes"] == ["a note"]
    with pytest.raises(KeyError):
        mode(1.0)["missing"]
