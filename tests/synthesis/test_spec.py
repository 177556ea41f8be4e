"""Synthesis specification: parsing, ratio progressions and every error path."""

from __future__ import annotations

import math

import pytest

from hypothesis import given, settings
from hypothesis import strategies as st

from epicyclic.synthesis.spec import SynthesisError, SynthesisSpec, progression_range, progressive_ratios


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


def test_progressive_ratios_do_not_overflow():
    """In logarithms: 16 gears at the largest progression allowed stay finite (φ2^105 was computed directly)."""
    low, high = progression_range(1e6, 16)
    r = progressive_ratios(1e6, 16, 1e3, progression=high * 0.999)
    assert all(math.isfinite(v) and v > 0 for v in r) and r[0] / r[-1] == pytest.approx(1e6, rel=1e-9)


@settings(max_examples=30, deadline=None)
@given(spread=st.floats(1.05, 50.0), gears=st.integers(3, 16), inside=st.floats(0.0, 0.999), up=st.booleans())
def test_progression_range_is_where_every_step_exceeds_one(spread, gears, inside, up):
    """Inside the range every step φ_k > 1; at its ends the smallest step is exactly 1 (Naunheimer eq. 6.9)."""
    low, high = progression_range(spread, gears)
    prog = math.exp(inside * math.log(high if up else low))
    r = progressive_ratios(spread, gears, 4.0, prog)
    assert all(a > b for a, b in zip(r, r[1:]))
    edge = progressive_ratios(spread, gears, 4.0, high if up else low)
    assert min(a / b for a, b in zip(edge, edge[1:])) == pytest.approx(1.0, rel=1e-9)


@pytest.mark.parametrize("targets, match", [
    ({"spread": 7.0, "gears": 80, "first": 4.7, "progression": 1.1}, "key 'targets.gears': expected at most 16"),
    ({"spread": 7.0, "gears": 10**9, "first": 4.7}, "key 'targets.gears': expected at most 16"),
    ({"spread": 7.0, "gears": 8, "first": 4.7, "progression": 1e-10}, "key 'targets.progression': .*must lie in"),
    ({"spread": 7.0, "gears": 8, "first": 4.7, "progression": 1e10}, "key 'targets.progression': .*must lie in"),
    ({"spread": 1e300, "gears": 3, "first": 4.7}, "key 'targets.first': .*outside 1e-6"),
    ({"forward": [2.0] * 10**6}, "key 'targets.forward': at most 16 target ratios, got 1000000"),
])
def test_hostile_targets_are_refused_before_any_ratio_is_built(targets, match):
    with pytest.raises(SynthesisError, match=match):
        SynthesisSpec.create(targets, 2, {"brakes": 2, "clutches": 2})


@pytest.mark.parametrize("engaged, match", [([2, 2], "2 is listed twice"), ([], "a list of 1 to 4 numbers"),
                                            ("2", "a list of 1 to 4 numbers")])
def test_engaged_is_a_set_of_numbers(engaged, match):
    with pytest.raises(SynthesisError, match=f"key 'elements.engaged': .*{match}"):
        SynthesisSpec.create([2.46, 1.46, 1.0, -2.18], 2, {"brakes": 2, "clutches": 2, "engaged": engaged})


def test_spread_spec():
    s = SynthesisSpec.create({"spread": 4.0, "gears": 3, "first": 4.0, "reverse": [-3.0]}, 2,
                             {"brakes": 2, "clutches": 2})
    assert s.forward == pytest.approx((4.0, 2.0, 1.0)) and s.reverse == (-3.0,)


@pytest.mark.parametrize("targets, sets, elements, constraints, match", [
    ([], 2, None, None, "key 'targets': expected a non-empty list"),
    ([2.0, 0.0], 2, None, None, "key 'targets': a target ratio of 0"),
    ([2.0, math.nan], 2, None, None, "key 'targets': expected a finite number"),
    (["2"], 2, None, None, "key 'targets': expected a finite number"),
    ({"reverse": [-2.0]}, 2, None, None, "key 'targets.forward': give at least one forward"),
    ({"forward": [2.0], "bogus": 1}, 2, None, None, "key 'targets': unknown key"),
    ({"spread": 4.0, "gears": 3}, 2, None, None, "key 'targets.first': missing"),
    ({"spread": 0.5, "gears": 3, "first": 2.0}, 2, None, None, "key 'targets.spread': expected a number > 1"),
    ({"forward": 2.0}, 2, None, None, "key 'targets.forward': expected a list of ratios"),
    ([2.0, 1.0], 0, None, None, "key 'sets': expected a whole number >= 1"),
    ([2.0, 1.0], {"simple": 5}, None, None, "key 'sets': give 1 to 4 planetary sets"),
    ([2.0, 1.0], 2, {"brakes": 4, "clutches": 5}, None, "key 'elements': at most 8 shift elements"),
    ([float(k) for k in range(20, 3, -1)], 2, {"brakes": 4, "clutches": 4}, None, "at most 16 target ratios"),
    ([2.0, 1.0], {"ring": 1}, None, None, "key 'sets': unknown key"),
    ([2.0, 1.0], 2, {"brakes": 1, "clutches": 0}, None, "key 'elements': 1 shift elements cannot give 2 gears"),
    ([3.0, 2.0, 1.0, -2.0], 2, {"brakes": 2, "clutches": 2, "engaged": 4}, None,
     "key 'elements.engaged': .* fewer than the 4 gears"),
    ([2.0, 1.0], 2, {"brakes": 2, "clutches": 2, "gears": 3}, None, "key 'elements': unknown key"),
    ([2.0, 1.0], 2, {"brakes": -1}, None, "key 'elements.brakes': expected a whole number >= 0"),
    ([2.0, 1.0], 2, None, {"tolerance": 5}, r"key 'constraints.tolerance': .*\(0, 0.2\]"),
    ([2.0, 1.0], 2, None, {"stationary_ratio": [0.5, 3.0]}, "key 'constraints.stationary_ratio': .*must exceed 1"),
    ([2.0, 1.0], 2, None, {"stationary_ratio": [3.0, 2.0]}, "key 'constraints.stationary_ratio': .*low <= high"),
    ([2.0, 1.0], 2, None, {"sun": [2, 40]}, "key 'constraints.sun': expected a whole number >= 3"),
    ([2.0, 1.0], 2, None, {"stationary_efficiency": 1.5}, r"key 'constraints.stationary_efficiency': .*\(0, 1\]"),
    ([2.0, 1.0], 2, None, {"free_input": "yes"}, "key 'constraints.free_input': expected true or false"),
    ([2.0, 1.0], 2, None, {"levels": 9}, "key 'constraints.levels': expected at most 4"),
    ([2.0, 1.0], 2, None, {"colour": "red"}, "key 'constraints.colour': unknown constraint"),
])
def test_bad_specs_raise_clear_errors(targets, sets, elements, constraints, match):
    """The Python call: each message starts with `synthesize: key '<argument>.<key>':`, as file errors do."""
    with pytest.raises(SynthesisError, match=match) as info:
        SynthesisSpec.create(targets, sets, elements, constraints)
    assert str(info.value).startswith("synthesize: key '")


@pytest.mark.parametrize("text, where", [
    ("[targets]\nforward = [2.0, 1.0]\ntolerance = 5\n", "[targets], key 'tolerance': the tolerance is relative"),
    ("[targets]\nforward = [2.0, 1.0]\n[bounds]\nsun = [2, 40]\n", "[bounds], key 'sun': expected a whole number"),
    ("[targets]\nforward = [2.0, 1.0]\n[bounds]\ntolerance = 0.5\n", "[bounds], key 'tolerance':"),
    ("[targets]\nforward = [2.0, 1.0]\n[search]\nlevels = 9\n", "[search], key 'levels': expected at most 4"),
    ("[targets]\nforward = [2.0, 1.0]\n[search]\nspeed = 3\n", "[search], key 'speed': unknown constraint"),
    ("[targets]\nforward = [2.0, 1.0]\n[sets]\nsimple = 5\n", "[sets]: give 1 to 4 planetary sets"),
    ("[targets]\nforward = [2.0, 1.0]\n[sets]\nsimple = 'two'\n", "[sets], key 'simple': expected a whole"),
    ("[targets]\nforward = [2.0, 1.0]\n[elements]\nbrakes = 2\nclutches = 2\nengaged = 4\n",
     "[elements], key 'engaged':"),
    ("[targets]\nforward = [2.0, 0.0]\n", "[targets], key 'forward': forward ratios must be > 0"),
    ("[targets]\nforward = ['fast']\n", "[targets], key 'forward': expected a finite number, got 'fast'"),
    ("[targets]\nspread = 4.0\ngears = 3\n", "[targets], key 'first': missing"),
    ("[targets]\nfoward = [2.0]\n", "[targets]: unknown key(s) 'foward'"),
])
def test_file_errors_name_the_file_table_and_key(tmp_path, text, where):
    """A specification file: `<file>: [table], key 'name': ...` (io.reader.at_key, as train files say it)."""
    path = tmp_path / "spec.toml"
    path.write_text(text)
    with pytest.raises(SynthesisError) as info:
        SynthesisSpec.from_file(path)
    assert str(info.value).startswith(f"{path}: {where}")


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
    messages = {"missing.toml": "no such file", "bad.toml": "not valid TOML", "table.toml": "key 'targets': expected a table",
                "unknown.toml": "unknown table", "notargets.toml": r"missing \[targets\]"}
    for name, text in cases.items():
        path = tmp_path / name
        if text is not None:
            path.write_text(text)
        with pytest.raises(SynthesisError, match=messages[name]) as info:
            SynthesisSpec.from_file(path)
        assert name in str(info.value)


def test_from_text_names_the_source_it_is_given(tmp_path):
    text = '[targets]\nforward = [2.46, 1.46, 1.0]\n[sets]\nsimple = 2\n[elements]\nbrakes = 2\nclutches = 2\n'
    path = tmp_path / "s.toml"
    path.write_text(text)
    assert SynthesisSpec.from_text(text, "pasted spec") == SynthesisSpec.from_file(path)
    with pytest.raises(SynthesisError, match=r"^pasted spec: \[bounds\], key 'sun'"):
        SynthesisSpec.from_text(text + "[bounds]\nsun = [17]\n", "pasted spec")
    with pytest.raises(SynthesisError, match="^pasted spec: not valid TOML"):
        SynthesisSpec.from_text("[targets", "pasted spec")


@pytest.mark.parametrize("text, where", [
    ("[sizing]\nallowable_stress = 200\n", "[sizing], key 'allowable_stress': the Lewis pre-dimensioning was replaced"),
    ("[sizing]\nface_width_ratio = 5\n", "[sizing], key 'face_width_ratio': expected 0.05"),
    ("[rating]\nlife = -1\n", "[rating], key 'life'"),
    ("[rating]\nmaterial = 3\n", "[rating], key 'material': expected a material name"),
    ("[rating]\nmaterial = \"Unobtainium\"\n", "[rating], key 'material'"),
    ("[rating]\nhardness = 60\n", "[rating], key 'hardness': unknown rating input"),
    ("[teeth]\nring_balance = -1\n", "[teeth], key 'ring_balance': a weight is a finite number >= 0"),
    ("[teeth]\nrings = 1\n", "[teeth], key 'rings': unknown"),
])
def test_sizing_rating_and_teeth_tables_name_their_keys(tmp_path, text, where):
    path = tmp_path / "spec.toml"
    path.write_text("[targets]\nforward = [2.46, 1.46, 1.0]\nreverse = [-2.18]\n" + text)
    with pytest.raises(SynthesisError) as info:
        SynthesisSpec.from_file(path)
    assert str(info.value).startswith(f"{path}: ") and where in str(info.value)


def test_sizing_rating_and_teeth_values_are_kept():
    s = SynthesisSpec.create([2.46, 1.46, 1.0, -2.18], 2, {"brakes": 2, "clutches": 2},
                             {"face_width_ratio": 0.7, "input_speed": 2000, "rating": {"life": 5000, "S_Fmin": 1.6},
                              "tooth_weights": {"ring_balance": 2}})
    assert (s.face_width_ratio, s.input_speed) == (0.7, 2000.0)
    assert dict(s.rating) == {"life": 5000.0, "S_Fmin": 1.6} and dict(s.tooth_weights)["ring_balance"] == 2.0
    with pytest.raises(SynthesisError, match="key 'constraints.rating.life'"):
        SynthesisSpec.create([2.46, -2.18], 2, {"brakes": 2, "clutches": 2}, {"rating": {"life": 0}})
