"""Ranking by what decides a layout: weighted criteria, the Pareto front, explanations.

Published case: the Simpson three-speed (Ford C4 ratios 2.46, 1.46, 1.00, R −2.18; 'Ford C4
transmission', Wikipedia; train ``examples/simpson_c4_3speed.toml``).  Over the whole two-set space
its arrangement ranks first with the default weights, and rank 1 circulates no power (issue 22:
rank 1 used to circulate 0.87 × P_in in first gear, the Simpson came tenth).
"""

from __future__ import annotations

import json
import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from epicyclic.synthesis import SynthesisError, SynthesisSpec, synthesize_spec
from epicyclic.synthesis.candidate import Candidate
from epicyclic.synthesis.ranking import CRITERIA, pareto_front
from epicyclic.transmission.library import build

SIMPSON = SynthesisSpec.create([2.46, 1.46, 1.0, -2.18], 2, {"brakes": 2, "clutches": 2}, {"tolerance": 0.01})


@pytest.fixture(scope="module")
def result():
    return synthesize_spec(SIMPSON, workers=1, announce=False)


def test_the_simpson_ranks_first_and_rank_one_circulates_nothing(result):
    simpson = Candidate.from_transmission(build("simpson_c4")).architecture_key
    assert result.best.architecture_key == simpson
    assert result.best.metrics["circulating_power_max"] == pytest.approx(0.0, abs=1e-9)
    assert result.standings[0].pareto
    # candidates that circulate power are there, and rank behind
    assert any(c.metrics["circulating_power_max"] > 0.8 for c in result.candidates)


def test_score_is_the_sum_of_weighted_terms(result):
    for st_ in result.standings:
        assert st_.score == pytest.approx(sum(st_.terms.values()), rel=1e-12)
        for c in CRITERIA:
            assert st_.terms[c.name] == pytest.approx(c.weight * st_.values[c.name] / c.scale, rel=1e-12)
    scores = [s.score for s in result.standings]
    assert scores == sorted(scores)


def test_element_capacity_and_slip_are_recomputed_from_the_solver(result):
    """Independent: each element's largest torque over the gears, summed; the largest forward slip."""
    for cand in result.candidates[:4]:
        analysis = cand.transmission().analyze_all()
        largest = {}
        for g in analysis.gears:
            for name, torque in g.element_torques.items():
                largest[name] = max(largest.get(name, 0.0), abs(torque))
        assert cand.metrics["element_capacity"] == pytest.approx(sum(largest.values()), rel=1e-12)
        slip = max(abs(v) for g in analysis.gears[:cand.forward] for v in g.slip_speeds.values())
        assert cand.metrics["slip_speed_max"] == pytest.approx(slip, rel=1e-12)
        circulating = max(g.circulating_power_ratio or 0.0 for g in analysis.gears)
        assert cand.metrics["circulating_power_max"] == pytest.approx(circulating, rel=1e-12)


def test_weights_change_the_order_without_a_new_search(result):
    # planet speed alone: the slowest planets go first (the Simpson's are 2.48 × n_in, others' 1.7)
    planets = result.rerank({c.name: 0.0 for c in CRITERIA} | {"planet_speed": 1.0})
    assert planets.best.metrics["planet_speed_max"] == min(c.metrics["planet_speed_max"] for c in result.candidates)
    assert planets.best.architecture_key != result.best.architecture_key
    assert all(s.pareto for s in planets.standings if s.values["planet_speed"] == planets.standings[0].values[
        "planet_speed"])
    # circulating power weighted 0: it no longer counts against a candidate
    free = result.rerank({"circulating_power": 0.0})
    assert all(s.terms["circulating_power"] == 0 for s in free.standings)
    assert sorted(c.key for c in free.candidates) == sorted(c.key for c in result.candidates)


def test_explanations_name_what_differs(result):
    text = result.explain()
    lines = text.splitlines()
    assert lines[0].startswith("#1: score") and "on the Pareto front" in lines[0]
    behind = next(line for line in lines if "largest circulating power 0.868 × P_in vs 0 × P_in" in line)
    assert "behind on" in behind
    assert result.explain(2).startswith("#2: score") and "against #1" in result.explain(2)
    with pytest.raises(SynthesisError, match="rank must lie"):
        result.explain(99)
    assert "why:" in result.table() and "score = Σ weight" in result.table()


def test_json_holds_standings_and_no_infinities(result):
    data = json.loads(json.dumps(result.to_dict(), allow_nan=False))
    first = data["candidates"][0]
    assert first["rank"] == 1 and first["pareto"] is True and set(first["criteria"]) == {c.name for c in CRITERIA}
    assert data["pareto_front"][0] == 1


@pytest.mark.parametrize("weights, match", [({"speed": 1.0}, "unknown criterion"),
                                            ({"planet_speed": -1.0}, "finite number >= 0"),
                                            ({"planet_speed": math.inf}, "finite number >= 0")])
def test_bad_weights_are_refused(result, weights, match):
    with pytest.raises(SynthesisError, match=match):
        result.rerank(weights)
    with pytest.raises(SynthesisError, match=f"key 'constraints.weights.{next(iter(weights))}': .*{match}"):
        SynthesisSpec.create([2.0, 1.0], 2, None, {"weights": weights})


def test_ranking_table_in_the_spec_file(tmp_path):
    path = tmp_path / "s.toml"
    path.write_text("[targets]\nforward = [2.0, 1.0]\n[ranking]\nplanet_speed = 3\nmodule = 2.5\n")
    spec = SynthesisSpec.from_file(path)
    assert dict(spec.weights) == {"planet_speed": 3.0} and spec.module == 2.5
    path.write_text("[targets]\nforward = [2.0, 1.0]\n[ranking]\nplanet_sped = 3\n")
    with pytest.raises(SynthesisError, match=r"\[ranking\], key 'planet_sped': unknown criterion"):
        SynthesisSpec.from_file(path)


vectors = st.lists(st.lists(st.integers(0, 3), min_size=3, max_size=3), min_size=1, max_size=12)


@settings(max_examples=40, deadline=None)
@given(vectors)
def test_pareto_front_members_are_undominated(rows):
    front = pareto_front(rows)
    def dominates(a, b):
        return all(x <= y for x, y in zip(a, b)) and any(x < y for x, y in zip(a, b))
    for k, who in enumerate(front):
        if who is None:
            assert not any(dominates(other, rows[k]) for other in rows)
        else:
            assert dominates(rows[who], rows[k]) and not any(dominates(o, rows[k]) for o in rows[:who])
    assert any(w is None for w in front)  # a finite set always has a non-dominated member
