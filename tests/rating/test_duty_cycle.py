"""DutyCycle / LoadCase value objects: validation and the two ways of building them."""

from __future__ import annotations

import pytest

from epicyclic import OperatingPoint
from epicyclic.rating import DutyCycle, DutyCycleError, LoadCase

OP = OperatingPoint(speeds={"in": 2000.0}, torques={"in": 100.0}, drives=["in"], loads=["out"])


def test_hours_give_shares_and_total():
    cycle = DutyCycle((LoadCase("a", OP, hours=300.0), LoadCase("b", OP, hours=100.0)))
    assert cycle.shares.tolist() == [0.75, 0.25] and cycle.total_hours == 400.0
    assert cycle.hours.tolist() == [300.0, 100.0]


def test_shares_with_and_without_total():
    cycle = DutyCycle((LoadCase("a", OP, share=0.4), LoadCase("b", OP, share=0.6)), total_hours=1000.0)
    assert cycle.hours.tolist() == pytest.approx([400.0, 600.0])
    assert DutyCycle((LoadCase("a", OP, share=1.0),)).hours is None


def test_shares_that_do_not_sum_to_one_are_refused():
    with pytest.raises(DutyCycleError, match="sum to 0.8, not 1.*a: 0.5, b: 0.3"):
        DutyCycle((LoadCase("a", OP, share=0.5), LoadCase("b", OP, share=0.3)))


@pytest.mark.parametrize("kwargs, match", [
    ({"hours": -1.0}, "hours must be a number >= 0"),
    ({"share": 1.5}, r"share must lie in \[0, 1\]"),
    ({}, "got neither"),
    ({"hours": 1.0, "share": 1.0}, "not both"),
    ({"hours": float("nan")}, "hours must be a number >= 0"),
])
def test_bad_durations(kwargs, match):
    with pytest.raises(DutyCycleError, match=match):
        LoadCase("a", OP, **kwargs)


def test_cycle_errors():
    with pytest.raises(DutyCycleError, match="at least one LoadCase"):
        DutyCycle(())
    with pytest.raises(DutyCycleError, match="'a' used twice"):
        DutyCycle((LoadCase("a", OP, share=0.5), LoadCase("a", OP, share=0.5)))
    with pytest.raises(DutyCycleError, match="not a mix"):
        DutyCycle((LoadCase("a", OP, share=0.5), LoadCase("b", OP, hours=5.0)))
    with pytest.raises(DutyCycleError, match="sum to 400 h"):
        DutyCycle((LoadCase("a", OP, hours=300.0), LoadCase("b", OP, hours=100.0)), total_hours=500.0)
    with pytest.raises(DutyCycleError, match="sum to 0"):
        DutyCycle((LoadCase("a", OP, hours=0.0),))
    with pytest.raises(DutyCycleError, match="must be an OperatingPoint"):
        LoadCase("a", {"in": 3}, share=1.0)  # type: ignore[arg-type]


def test_from_operating_points_as_a_rexs_load_spectrum_maps():
    # a REXS load_spectrum becomes a list of operating points with durations (and gears)
    ops = [OperatingPoint(speeds={"in": n}, torques={"in": 50.0}, drives=["in"], loads=["out"]) for n in (1e3, 3e3)]
    cycle = DutyCycle.from_operating_points(ops, hours=[10.0, 30.0], gears=["1", "2"], names=["lc1", "lc2"])
    assert cycle.names == ("lc1", "lc2") and [c.gear for c in cycle.cases] == ["1", "2"]
    assert cycle.shares.tolist() == [0.25, 0.75]
    with pytest.raises(DutyCycleError, match="2 points but 1 durations"):
        DutyCycle.from_operating_points(ops, hours=[1.0])
    with pytest.raises(DutyCycleError, match="not both"):
        DutyCycle.from_operating_points(ops, hours=[1.0, 1.0], shares=[0.5, 0.5])
    assert cycle.to_dict()["cases"][1]["speeds"] == {"in": 3000.0}


def test_from_rexs_load_cases():
    # the shape of epicyclic.exchange.operating.RexsLoadCase (branch rexs): id, gear, duration_fraction,
    # to_operating_point(); REXS gives fractions of the gear unit's time, no hours
    from types import SimpleNamespace

    cases = [SimpleNamespace(id=k, gear=g, duration_fraction=f, to_operating_point=lambda: OP)
             for k, g, f in ((3, "1", 0.2), (7, "2", 0.8))]
    cycle = DutyCycle.from_load_cases(cases, total_hours=500.0)
    assert cycle.names == ("load case 3", "load case 7") and [c.gear for c in cycle.cases] == ["1", "2"]
    assert cycle.hours.tolist() == pytest.approx([100.0, 400.0])
    cases[1].duration_fraction = None
    with pytest.raises(DutyCycleError, match="load case\\(s\\) 7 give no load_duration_fraction"):
        DutyCycle.from_load_cases(cases)
    cases[1].duration_fraction = 0.5
    with pytest.raises(DutyCycleError, match="sum to 0.7"):
        DutyCycle.from_load_cases(cases)
