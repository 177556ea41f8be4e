"""The size of a search before it runs: counting formulas checked against enumeration, the bound enforced.

Independent check: the dynamic programme of :func:`labelled_patterns` against brute-force enumeration of
the restricted-growth numberings (the mechanisms' own generator), and the per-mechanism bound against the
architectures the screening actually examines.
"""

from __future__ import annotations

import math
import time

import pytest

from epicyclic.synthesis import SynthesisError, SynthesisSpec, synthesize_spec
from epicyclic.synthesis.estimate import architectures_per_mechanism, count, estimate, labelled_patterns
from epicyclic.synthesis.mechanisms import _partitions, enumerate_mechanisms
from epicyclic.synthesis.search import plan

SIMPSON = SynthesisSpec.create([2.46, 1.46, 1.0, -2.18], 2, {"brakes": 2, "clutches": 2}, {"tolerance": 0.01})
EIGHT = [4.6957, 3.1304, 2.1039, 1.6667, 1.2845, 1.0, 0.8392, 0.6667, -3.2968]


@pytest.mark.parametrize("sets, shafts, cap", [(1, 3, None), (2, 3, None), (2, 4, None), (2, 5, None), (3, 5, None),
                                               (3, 6, 2), (3, 7, None), (4, 6, 3), (4, 8, 2), (4, 9, None)])
def test_labelled_patterns_match_brute_force(sets, shafts, cap):
    assert labelled_patterns(sets, shafts, cap) == sum(1 for _ in _partitions(sets, shafts, cap or sets))


def test_labelled_patterns_closed_form_without_cap():
    """Without a cap: surjective colourings with distinct colours per set, by inclusion–exclusion, over m!."""
    for sets, m in [(2, 4), (3, 6), (4, 7)]:
        closed = sum((-1) ** j * math.comb(m, j) * ((m - j) * (m - j - 1) * (m - j - 2)) ** sets
                     for j in range(m - 2)) // math.factorial(m)
        assert labelled_patterns(sets, m) == closed


def test_estimate_is_close_to_the_enumerated_count():
    """Mechanisms up to isomorphism lie between labelled/|G| (Burnside) and labelled (connected ones fewer)."""
    spec = SynthesisSpec.create(EIGHT, 4, {"brakes": 2, "clutches": 3, "engaged": 3},
                                {"max_members_per_shaft": 2, "free_input": False})
    guess = estimate(spec)
    actual = len(enumerate_mechanisms(("simple",) * 4, 4, max_members_per_shaft=2))
    assert actual == 915 and 0.8 * guess.mechanisms <= actual <= labelled_patterns(4, 8, 2)


def test_the_bound_holds_for_what_the_screening_examines():
    result = synthesize_spec(SIMPSON, workers=1, announce=False)
    bound = count(SIMPSON, (m for t in plan(SIMPSON) for m in t.mechanisms))
    assert 0 < result.stats["architectures"] <= bound.architectures == result.stats["bound"]["architectures"]
    assert bound.architectures <= estimate(SIMPSON).architectures * 2


def test_per_mechanism_bound():
    # free input: 3 outputs on 4 shafts; brakes on the 2 others, C(2, 2); clutches among 6 pairs, C(6, 2)
    assert architectures_per_mechanism(4, True, 2, 2) == 3 * 1 * 15


def test_every_search_announces_its_bound_before_it_starts():
    lines = []
    synthesize_spec(SIMPSON, workers=1, announce=lines.append)
    assert len(lines) == 1 and lines[0].startswith("synthesize: at most ")
    assert "architectures on 41 mechanisms" in lines[0]


def test_four_sets_eight_elements_nine_ratios_is_refused_at_once():
    spec = SynthesisSpec.create(EIGHT, 4, {"brakes": 4, "clutches": 4})
    start = time.perf_counter()
    with pytest.raises(SynthesisError, match=r"\[search\], key 'max_architectures'.*more than the bound of 1e\+10"):
        synthesize_spec(spec, workers=1, announce=False)
    assert time.perf_counter() - start < 1.0  # refused from the formulas, before any enumeration


def test_a_raised_bound_is_the_users_decision():
    spec = SynthesisSpec.create([2.46, 1.46, 1.0, -2.18], 2, {"brakes": 2, "clutches": 2},
                                {"max_architectures": 1000})
    with pytest.raises(SynthesisError, match="max_architectures"):
        synthesize_spec(spec, workers=1, announce=False)


def test_time_limit_stops_and_says_incomplete():
    spec = SynthesisSpec.create([2.46, 1.46, 1.0, -2.18], 2, {"brakes": 2, "clutches": 2}, {"time_limit": 1e-9})
    result = synthesize_spec(spec, workers=1, announce=False)
    assert result.stats["complete"] is False and result.stats["tasks_done"] < result.stats["tasks"]
    assert "INCOMPLETE: stopped at the time limit" in result.table()


@pytest.mark.parametrize("workers", [0, 257, 2.5, True])
def test_workers_out_of_range_are_refused(workers):
    with pytest.raises(SynthesisError, match="workers must be a whole number in 1 … 256"):
        synthesize_spec(SIMPSON, workers=workers, announce=False)


def test_the_ten_speed_spec_is_bounded_and_split_finely():
    """Ford 10R80 ratios ('Ford–GM 10-speed automatic transmission', Wikipedia): 4 simple sets,
    2 brakes + 4 clutches, 4 engaged, carriers in and out.  Stated before it runs: within the default
    bound, one mechanism per task (about 10^7 architectures each), so the time limit, progress and the
    checkpoint act every few seconds."""
    from pathlib import Path

    path = Path(__file__).resolve().parents[2] / "examples" / "synthesis" / "ten_speed_10r80.toml"
    spec = SynthesisSpec.from_file(path)
    assert spec.forward[0] == 4.696 and spec.reverse == (-4.866,) and spec.gears == 11
    tasks = plan(spec)
    size = count(spec, (m for t in tasks for m in t.mechanisms))
    assert size.mechanisms == 321 and 10**9 < size.architectures <= spec.max_architectures
    assert all(len(t.mechanisms) == 1 for t in tasks)
    guess = estimate(spec)
    assert 0.3 <= guess.architectures / size.architectures <= 3  # the formula estimate is of the right size


@pytest.mark.parametrize("chunk", [0, -3, 1.5])
def test_chunk_out_of_range_is_refused(chunk):
    with pytest.raises(SynthesisError, match="chunk must be a whole number"):
        synthesize_spec(SIMPSON, workers=1, announce=False, chunk=chunk)
