"""A train over a duty cycle: closed forms for energies and bearing loads, the batch against a per-case loop,
invariants (energy balance, loss >= 0, efficiency <= 1), bad input."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from epicyclic import Brake, GearTrain, OperatingPoint, PlanetarySet
from epicyclic.geometry import SetGeometry
from epicyclic.io import load_train_file
from epicyclic.losses import solve_with_losses
from epicyclic.rating import (
    BearingRating,
    DutyCycle,
    DutyCycleError,
    LoadCase,
    analyse_duty_cycle,
)
from epicyclic.rating.bearing_life import (
    basic_rating_life,
    rating_life_hours,
)
from epicyclic.transmission.errors import UnknownGearError

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
SET = PlanetarySet.simple("P", sun="in", ring="r", carrier="out", z_sun=30, z_planet=24, z_ring=78,
                          stationary_efficiency=1.0)
TRAIN = GearTrain([SET, Brake("B", "r")])
GEOMETRY = {"P": SetGeometry.create(SET, module=2.0)}


def _op(n, t):
    return OperatingPoint(speeds={"in": n}, torques={"in": t}, drives=["in"], loads=["out"])


def test_planet_bearing_load_and_speed_closed_form():
    # Queitsch part I, eq. (26): each planet bearing of a simple set carries 2 F_t, F_t = 2000 T_sun/(N d_sun)
    # (lossless, spur, d_sun = m z = 60 mm); it turns at n_p - n_c = -(z_s/z_p)(n_s - n_c), n_c = n_s/(1 + 78/30).
    # Over two cases of equal time: L10h = 1/Σ(q_i/L10h_i) (Palmgren-Miner, SKF Rolling bearings 2013: variable operating conditions).
    rating = BearingRating("needle roller", 15e3)
    cycle = DutyCycle((LoadCase("a", _op(3000.0, 100.0), hours=600.0), LoadCase("b", _op(1000.0, 250.0),
                                                                                 hours=600.0)))
    res = analyse_duty_cycle(TRAIN, cycle, geometry=GEOMETRY, bearings={"P": {"planet": rating}})
    assert len(res.bearings) == 3
    b = res.bearings[0]
    loads = [2 * 2000 * t / (3 * 60.0) for t in (100.0, 250.0)]
    speeds = [30 / 24 * (n - n / 3.6) for n in (3000.0, 1000.0)]
    assert b.radial == pytest.approx(loads, rel=1e-9)
    assert b.speeds == pytest.approx(speeds, rel=1e-9)
    per_case = [float(rating_life_hours(basic_rating_life(15e3, p, 10 / 3), n)) for p, n in zip(loads, speeds)]
    assert b.case_hours == pytest.approx(per_case, rel=1e-9)
    assert b.life_hours == pytest.approx(1 / (0.5 / per_case[0] + 0.5 / per_case[1]), rel=1e-9)
    assert b.life_hours == pytest.approx(1e6 * b.life / (60 * b.mean_speed), rel=1e-9)


def test_central_bearing_carries_the_external_load_only_with_equal_spacing():
    # equally spaced planets put no net force on the sun (central_forces = 0): the load is the given one
    rating = BearingRating("deep groove ball", 30e3, external_load=500.0)
    cycle = DutyCycle((LoadCase("a", _op(3000.0, 100.0), share=1.0),), total_hours=100.0)
    b = analyse_duty_cycle(TRAIN, cycle, geometry=GEOMETRY, bearings={"P": {"sun": rating}}).bearings[0]
    assert b.radial == pytest.approx([500.0], abs=1e-6) and b.speeds == pytest.approx([3000.0])
    assert b.life_hours == pytest.approx(1e6 * (30e3 / 500.0) ** 3 / (60 * 3000.0), rel=1e-6)


def test_energies_closed_form_and_cycle_efficiency():
    # ring held, sun driving: η = (1 - i0 η0)/(1 - i0) with i0 = -2.6 (Brandenberger 1952, η0 in the direction
    # of the rolling power); E = P t
    eta0 = 0.97
    pset = PlanetarySet.simple("P", sun="in", ring="r", carrier="out", z_sun=30, z_planet=24, z_ring=78,
                               stationary_efficiency=eta0)
    train = GearTrain([pset, Brake("B", "r")])
    cycle = DutyCycle((LoadCase("a", _op(3000.0, 100.0), hours=10.0), LoadCase("b", _op(1500.0, 200.0),
                                                                               hours=30.0)))
    res = analyse_duty_cycle(train, cycle)
    power = 100.0 * 3000.0 * math.pi / 30
    assert res.energy.input == pytest.approx([power * 10 / 1000, power * 30 / 1000], rel=1e-12)
    assert res.cycle_efficiency == pytest.approx((1 + 2.6 * eta0) / 3.6, rel=1e-12)
    assert res.lost_energy == pytest.approx(res.input_energy - res.output_energy, rel=1e-9)


def test_batch_equals_a_per_case_loop_on_the_8hp_example():
    f = load_train_file(EXAMPLES / "zf_8hp70_geometry.toml")
    res = analyse_duty_cycle(f.train, f.duty_cycle, schedule=f.transmission, losses=f.losses, geometry=f.geometry,
                             bearings=f.bearings)
    hours = f.duty_cycle.hours
    for k, case in enumerate(f.duty_cycle.cases):
        sol = solve_with_losses(f.transmission.train_in_gear(f.train, case.gear), case.operating_point, f.losses)
        assert res.energy.input[k] == pytest.approx(sol.input_power * hours[k] / 1000, rel=1e-9)
        assert res.energy.output[k] == pytest.approx(abs(sol.output_power) * hours[k] / 1000, rel=1e-9)
        for element, state in sol.elements.items():
            for source, loss in state.loss_sources.items():
                assert res.energy.lost[element][source][k] == pytest.approx(loss * hours[k] / 1000, rel=1e-7,
                                                                             abs=1e-9)
    # JSON: units everywhere, no NaN/Infinity
    text = json.dumps(res.to_dict(), allow_nan=False)
    assert '"unit": "kWh"' in text and '"L10h"' in text
    assert {b.element for b in res.bearings} == {"P1", "P2", "P3", "P4"}


def test_shared_planet_is_rated_once_with_the_whole_body_load():
    # Wolfrom drive: the planet gear meshing ring 1 belongs to both sets; its bearing carries the vector sum
    # of all meshes (share_planets; 763.9 N at 5 N·m lossless, see its doctest) and is rated once.
    s = PlanetarySet.simple("S", sun="in", ring="r1", carrier="c", z_sun=27, z_planet=27, z_ring=81)
    w = PlanetarySet.two_rings("W", first="r1", second="out", carrier="c", z_first=81, z_planet_first=27,
                               z_planet_second=24, z_second=78)
    train = GearTrain([s, w, Brake("B", "r1")])
    geo = {p.name: SetGeometry.create(p, module=2.0) for p in (s, w)}
    rating = BearingRating("needle roller", 5e3)
    cycle = DutyCycle((LoadCase("a", _op(3000.0, 5.0), share=1.0),))
    res = analyse_duty_cycle(train, cycle, geometry=geo, bearings={"S": {"planet": rating}, "W": {"planet": rating}})
    assert [b.element for b in res.bearings] == ["S", "S", "S"]
    assert res.bearings[0].radial[0] == pytest.approx(763.9, abs=0.05)


def test_bad_input():
    cycle = DutyCycle((LoadCase("a", _op(3000.0, 100.0), gear="9", share=1.0),))
    with pytest.raises(DutyCycleError, match="needs a \\[transmission\\]"):
        analyse_duty_cycle(TRAIN, cycle)
    f = load_train_file(EXAMPLES / "zf_8hp70_geometry.toml")
    with pytest.raises(UnknownGearError, match="no gear '9'"):
        analyse_duty_cycle(f.train, cycle, schedule=f.transmission)
    ok = DutyCycle((LoadCase("a", _op(3000.0, 100.0), share=1.0),))
    with pytest.raises(DutyCycleError, match="add a 'geometry' table"):
        analyse_duty_cycle(TRAIN, ok, bearings={"P": {"planet": BearingRating("needle roller", 1e4)}})
    with pytest.raises(DutyCycleError, match="unknown position 'pin'"):
        analyse_duty_cycle(TRAIN, ok, geometry=GEOMETRY, bearings={"P": {"pin": BearingRating("needle roller", 1e4)}})


def test_a_case_the_solver_refuses_is_named_and_keeps_its_error_class():
    from epicyclic.errors import ContradictionError

    bad = OperatingPoint(speeds={"in": 1000.0, "out": 1000.0}, torques={"in": 10.0}, drives=["in"], loads=["out"])
    cycle = DutyCycle((LoadCase("a", _op(3000.0, 100.0), share=0.5), LoadCase("b", bad, share=0.5)))
    with pytest.raises(ContradictionError, match="duty cycle, case 'b': .*contradict") as info:
        analyse_duty_cycle(TRAIN, cycle)
    assert info.value.duty_case == 1


def test_a_bearing_that_never_turns_has_no_life_number_in_json():
    cycle = DutyCycle((LoadCase("a", _op(3000.0, 100.0), share=1.0),))
    res = analyse_duty_cycle(TRAIN, cycle, geometry=GEOMETRY,
                             bearings={"P": {"ring": BearingRating("deep groove ball", 1e4)}})
    data = json.loads(json.dumps(res.to_dict(), allow_nan=False))
    assert data["bearings"][0]["L10h"]["value"] is None and "no fatigue" in data["bearings"][0]["notes"][0]
    assert data["per_cycle_hour"] is True and "kWh per cycle hour" in res.table()


@settings(max_examples=12, deadline=None)
@given(cases=st.lists(st.tuples(st.floats(100.0, 6000.0), st.floats(1.0, 500.0), st.floats(0.1, 100.0)),
                      min_size=1, max_size=5), eta0=st.floats(0.8, 1.0))
def test_energy_balance_and_bounds(cases, eta0):
    pset = PlanetarySet.simple("P", sun="in", ring="r", carrier="out", z_sun=30, z_planet=24, z_ring=78,
                               stationary_efficiency=eta0)
    train = GearTrain([pset, Brake("B", "r")])
    cycle = DutyCycle(tuple(LoadCase(f"c{k}", _op(n, t), hours=h) for k, (n, t, h) in enumerate(cases)))
    res = analyse_duty_cycle(train, cycle)
    assert np.all(res.energy.total_lost >= -1e-12 * res.energy.input)
    assert res.cycle_efficiency <= 1 + 1e-12
    assert res.energy.input - res.energy.output == pytest.approx(res.energy.total_lost, rel=1e-9, abs=1e-9)


def test_double_planet_bearings_turn_at_their_own_relative_speeds():
    # n_p - n_c = k (n_s - n_c) per planet gear: k = -z_s/z_p1 and +z_s/z_p2 (Teeth.planet_factors; Willis)
    pset = PlanetarySet.double_planet("P", sun="in", ring="out", carrier="c", z_sun=30, z_planet_sun=19,
                                      z_planet_ring=21, z_ring=90)
    train = GearTrain([pset, Brake("B", "c")])
    geometry = {"P": SetGeometry.create(pset, module=2.0)}
    cycle = DutyCycle((LoadCase("a", _op(3000.0, 50.0), share=1.0),))
    res = analyse_duty_cycle(train, cycle, geometry=geometry,
                             bearings={"P": {"planet": BearingRating("needle roller", 1e4)}})
    assert len(res.bearings) == 2 * pset.planets
    first, second = res.bearings[0], res.bearings[1]
    assert first.position.endswith("(planet1)") and second.position.endswith("(planet2)")
    assert first.speeds[0] == pytest.approx(30 / 19 * 3000.0, rel=1e-9)  # carrier held
    assert second.speeds[0] == pytest.approx(30 / 21 * 3000.0, rel=1e-9)
    assert first.radial[0] > 0 and second.radial[0] > 0


def test_renderings_escape_names():
    cycle = DutyCycle((LoadCase("a|<b>", _op(3000.0, 100.0), share=1.0),), total_hours=10.0)
    res = analyse_duty_cycle(TRAIN, cycle, geometry=GEOMETRY,
                             bearings={"P": {"planet": BearingRating("needle roller", 1e4)}})
    assert "a\\|&lt;b>" in res.markdown()
    assert "<b>" not in res._repr_html_() and "a|&lt;b&gt;" in res._repr_html_()
    assert res.html().startswith("<!DOCTYPE html>") and "a|<b>" in res.table()
    assert "DutyCycleResult" in repr(res) and "3 bearings" in repr(res)
