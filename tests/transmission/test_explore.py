"""Exploration of all shift states: every one-DOF drive with its ratio."""

from __future__ import annotations

import json
import time

import pytest

from epicyclic import Brake, Clutch, GearTrain, PlanetarySet
from epicyclic.transmission import ShiftScheduleError, explore
from epicyclic.transmission.library import build, build_train


def test_8hp_exploration_finds_every_scheduled_gear():
    t = build("zf_8hp70")
    ex = explore(t)
    assert ex.states == 32
    named = {c.gear: c.ratio for c in ex.combinations if c.gear}
    assert set(named) == set(t.gears)
    for gear, ratio in named.items():
        assert ratio == pytest.approx(t.ratio(gear), rel=1e-12)
    # ZF's schedule uses every one-DOF state of the five elements: 9 drives, no duplicates
    assert len(ex) == 9 and len(ex.distinct_ratios) == 9 and ex.held == 0
    assert [c.kind for c in ex.combinations].count("overdrive") == 2


def test_simpson_exploration_lists_ratios_without_schedule():
    train = build_train("simpson_c4")
    ex = explore(train, "in", "out")
    assert ex.find(["forward", "low_reverse"]).ratio == pytest.approx(2 + 33 / 72, rel=1e-12)
    assert ex.find(["forward", "low_reverse"]).gear is None
    assert ex.find(["intermediate", "low_reverse"]) is None  # output held / no drive


def test_duplicates_and_redundant_states():
    """Two clutches joining the same shafts: each alone gives direct drive (duplicates);
    both together are redundant and listed only on request."""
    train = GearTrain([PlanetarySet("P", "in", "ring", "out", -2.0), Brake("B", "ring"),
                       Clutch("C1", "in", "ring"), Clutch("C2", "ring", "in")])
    ex = explore(train, "in", "out")
    assert ex.find(["C1"]).duplicates == (("C2",),) and ex.find(["C1", "C2"]) is None
    full = explore(train, "in", "out", include_redundant=True)
    assert full.find(["C1", "C2"]).redundant and full.states == 2 ** 3
    assert full.distinct_ratios == pytest.approx((3.0, 1.0))


def test_rendering():
    ex = explore(build("ravigneaux_aod"))
    assert "drives from 'in' to 'ring'" in ex.table()
    assert "| engaged |" in ex.markdown() and "<table>" in ex._repr_html_()
    json.dumps(ex.to_dict())
    assert repr(ex).startswith("<Exploration")


def test_four_sets_six_elements_is_interactive():
    """4 sets and 6 elements (8HP plus one extra clutch): 64 states well under 0.5 s."""
    train = build_train("zf_8hp70")
    bigger = GearTrain(train.elements + (Clutch("F", "s12", "c3", engaged=False),), name="8HP + F")
    start = time.perf_counter()
    ex = explore(bigger, "in", "out")
    assert time.perf_counter() - start < 0.5
    assert ex.states == 64 and len(ex) > 9


@pytest.mark.parametrize("kwargs, match", [
    ({"input": "nope"}, "input must be a moving shaft"),
    ({"output": "in"}, "must differ"),
    ({"elements": ["A", "Z"]}, "'Z' is not a clutch or brake"),
])
def test_errors(kwargs, match):
    with pytest.raises(ShiftScheduleError, match=match):
        explore(build("zf_8hp70"), **kwargs)


def test_errors_with_bare_train():
    with pytest.raises(ShiftScheduleError, match="give input and output"):
        explore(build_train("zf_8hp70"))
    with pytest.raises(ShiftScheduleError, match="expected a Transmission or GearTrain"):
        explore("8hp")  # type: ignore[arg-type]
