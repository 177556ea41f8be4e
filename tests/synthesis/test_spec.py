"""Synthesis specification: parsing, ratio progressions and every error path."""

from __future__ import annotations

import math

import pytest

from epicyclic.synthesis.spec import SynthesisError, SynthesisSpec, progressive_ratios


def test_plain_list_splits_forward_and_reverse():
    s = SynthesisSpec.create([1.0, 2.46, -2.18, 1.46], 2, {"brakes": 2, "clutches": 2})
    assert s.forward == (2.46, 1.46, 1.0) and s.reverse == (-2.18,)
    assert s.engaged == (1, 2, 3)  # C(4, k) >= 4 gears
    assert s.kinds == ("simple", "simple") and s.gears == 4


def test_engaged_given_and_constraints():
    s = SynthesisSpec.create({"forward": [4.7, 3.1], "reverse": [-3.3], "tolerance": 0.005},
                             {"simple": 3, "plus": 1}, {"brakes": 2, "clutches": 3, "engaged": 3},
                             {"stationary_ratio": [1.6, 3.8], "planets": 4, "max_members_per_shaft": 2,
                              "free_input": False, "levels": 2, "top": 5})
    assert s.engaged == (3,) and s.tolerance == 0.005 and s.kinds == ("simple",) * 3 + ("plus",)
    assert s.stationary_ratio == (1.6, 3.8) and s.planets == (4,) and s.max_members_per_shaft == 2


def test_geometric_progression_closed_form():
    """φ2 = 1: geometric steps, i_k = i_1 / spread^((k-1)/(z-1)) (Naunheimer et al. 2011, eq. 6.9)."""
    r = progressive_ratios(7.0, 8, 4.7)
    assert r[0] == 4.7 and r[-1] == pytest.approx(4.7 / 7.0, rel=1e-12)
    steps = [a / b for a, b in zip(r, r[1:])]
    assert all(s == pytest.approx(7.0 ** (1 / 7), rel=1e-12) for s in steps)


def test_progressive_steps_grow_towards_first_gear():
    r = progressive_ratios(6.0, 6, 4.0, progression=1.05)
    steps = [a / b for a, b in zip(r, r[1:])]
    assert r[0] / r[-1] == pytest.approx(6.0, rel=1e-12)
    assert all(s1 / s2 == pytest.approx(1.05, rel=1e-12) for s1, s2 in zip(steps, steps[1:]))


def test_spread_spec():
    s = SynthesisSpec.create({"spread": 4.0, "gears": 3, "first": 4.0, "reverse": [-3.0]}, 2,
                             {"brakes": 2, "clutches": 2})
    assert s.forward == pytest.approx((4.0, 2.0, 1.0)) and s.reverse == (-3.0,)


@pytest.mark.parametrize("targets, sets, elements, constraints, match", [
    ([], 2, None, None, "non-empty list"),
    ([2.0, 0.0], 2, None, None, "must be a finite number|> 0"),
    ([2.0, math.nan], 2, None, None, "finite number"),
    (["2"], 2, None, None, "finite number"),
    ({"reverse": [-2.0]}, 2, None, None, "at least one forward"),
    ({"forward": [2.0], "bogus": 1}, 2, None, None, "unknown targets key"),
    ({"spread": 4.0, "gears": 3}, 2, None, None, "targets.first"),
    ({"spread": 0.5, "gears": 3, "first": 2.0}, 2, None, None, "spread must be > 1"),
    ([2.0, 1.0], 0, None, None, "sets must be a whole number >= 1"),
    ([2.0, 1.0], {"simple": 5}, None, None, "1 to 4 planetary sets"),
    ([2.0, 1.0], 2, {"brakes": 4, "clutches": 5}, None, "at most 8 shift elements"),
    ([float(k) for k in range(20, 3, -1)], 2, {"brakes": 4, "clutches": 4}, None, "at most 16 target ratios"),
    ([2.0, 1.0], {"ring": 1}, None, None, "unknown sets key"),
    ([2.0, 1.0], 2, {"brakes": 1, "clutches": 0}, None, "cannot give 2 gears|fewer than"),
    ([3.0, 2.0, 1.0, -2.0], 2, {"brakes": 2, "clutches": 2, "engaged": 4}, None, "fewer than the 4 gears"),
    ([2.0, 1.0], 2, {"brakes": 2, "clutches": 2, "gears": 3}, None, "unknown elements key"),
    ([2.0, 1.0], 2, None, {"tolerance": 5}, r"\(0, 0.2\]"),
    ([2.0, 1.0], 2, None, {"stationary_ratio": [0.5, 3.0]}, "must exceed 1"),
    ([2.0, 1.0], 2, None, {"stationary_ratio": [3.0, 2.0]}, "low <= high"),
    ([2.0, 1.0], 2, None, {"sun": [2, 40]}, "whole number >= 3"),
    ([2.0, 1.0], 2, None, {"stationary_efficiency": 1.5}, r"\(0, 1\]"),
    ([2.0, 1.0], 2, None, {"free_input": "yes"}, "true or false"),
    ([2.0, 1.0], 2, None, {"levels": 9}, "at most 4"),
    ([2.0, 1.0], 2, None, {"colour": "red"}, "unknown constraint"),
])
def test_bad_specs_raise_clear_errors(targets, sets, elements, constraints, match):
    with pytest.raises(SynthesisError, match=match):
        SynthesisSpec.create(targets, sets, elements, constraints)


def test_from_file_and_its_errors(tmp_path):
    good = tmp_path / "s.toml"
    good.write_text('title = "t"\n[targets]\nforward = [2.46, 1.46, 1.0]\nreverse = [-2.18]\n'
                    '[sets]\nsimple = 2\n[elements]\nbrakes = 2\nclutches = 2\n[search]\nlevels = 2\n')
    s = SynthesisSpec.from_file(good)
    assert s.title == "t" and s.levels == 2 and s.brakes == 2
    cases = {
        "missing.toml": None,
        "bad.toml": "[targets\n",
        "table.toml": "targets = 3\n",
        "unknown.toml": "[targets]\nforward=[2.0]\n[gears]\nx=1\n",
        "notargets.toml": "[sets]\nsimple = 2\n",
    }
    messages = {"missing.toml": "no such file", "bad.toml": "not valid TOML", "table.toml": "must be a table",
                "unknown.toml": "unknown table", "notargets.toml": r"missing \[targets\]"}
    for name, text in cases.items():
        path = tmp_path / name
        if text is not None:
            path.write_text(text)
        with pytest.raises(SynthesisError, match=messages[name]) as info:
            SynthesisSpec.from_file(path)
        assert name in str(info.value)
