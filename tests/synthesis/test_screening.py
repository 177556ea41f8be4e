"""Screening shortcuts are exact: the pruned, interpolated search returns exactly the reference's candidates.

* Multilinear interpolation: a combination determinant D_x(i0) = det[L(i0); E; e_x] is multilinear
  in the stationary ratios (each Willis row holds one i0, linearly; Queitsch eq. 12), so its values
  at the 2^S corners of a box fix it everywhere in the box.  Checked against the determinants solved
  at interior grid points.
* Rarest-target pruning of the first level (only element sets holding a combination that reaches
  the rarest target are examined): the same placements, in the same order, as the full scan.
* Matching pruning (Glover 1967, convex bipartite graphs): an architecture none of whose boxes admits
  one combination per target is dropped; every placement it drops is one the ratio fit rejects, and
  the placements it keeps carry the reference's boxes, so the whole search returns the same candidates
  in the same order (Simpson space; a sample of the 8HP space at the screening level).
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from epicyclic.synthesis import SynthesisSpec, enumerate_mechanisms, screening
from epicyclic.synthesis.fitting import combinations_of_elements, fit_ratios
from epicyclic.synthesis.kinematics import combination_determinants, element_rows
from epicyclic.synthesis.screening import _grid, layout, multilinear, screen
from epicyclic.synthesis.search import _mechanisms, bounds

EIGHT_FORWARD = np.array([4.6957, 3.1304, 2.1039, 1.6667, 1.2845, 1.0, 0.8392, 0.6667])  # ZF 8HP 70
EIGHT_REVERSE = np.array([-3.2968])


@settings(max_examples=25, deadline=None)
@given(st.lists(st.floats(-5, 5), min_size=8, max_size=8), st.integers(1, 3))
def test_interpolation_is_exact_for_multilinear_functions(coefficients, level):
    """f(t) = Σ_subsets c · Π t_k over three variables: interpolated grid values equal f there."""
    import itertools

    subsets = list(itertools.product((0, 1), repeat=3))

    def f(t):
        return sum(c * np.prod([t[k] for k in range(3) if s[k]]) for c, s in zip(coefficients, subsets))

    corners = np.array([f(np.array(b, float)) for b in itertools.product((0, 1), repeat=3)])
    cells = 2 ** level
    points = np.arange((cells + 1) ** 3)
    got = multilinear(corners, points, level, 3)
    for p, value in zip(points, got):
        digits = [(p // (cells + 1) ** (2 - k)) % (cells + 1) for k in range(3)]
        assert value == pytest.approx(f(np.array(digits) / cells), abs=1e-9)


def test_interpolated_determinants_equal_the_solved_ones():
    mech = enumerate_mechanisms(("simple",) * 3, 3)[7]
    lay = layout(mech.shafts, 2, 2, 2)
    low, high = np.full(3, -4.0), np.full(3, -1.5)
    corners, _ = _grid(low, high, 0)
    whole = combination_determinants(mech, corners, lay.combos, element_rows(mech.shafts))
    points, _ = _grid(low, high, 2)
    solved = combination_determinants(mech, points, lay.combos, element_rows(mech.shafts))
    interpolated = multilinear(whole, np.arange(len(points)), 2, 3)
    scale = np.abs(solved).max()
    assert np.max(np.abs(interpolated - solved)) <= 1e-12 * scale


def _both(mech, spec, engaged, levels, prune=True):
    lay = layout(mech.shafts, spec.brakes, spec.clutches, engaged)
    low, high = bounds(spec)
    args = (mech, lay, low, high, np.array(spec.forward), np.array(spec.reverse), spec.tolerance)
    fast = screen(*args, levels=levels, interpolate=True, prune=prune)
    reference = screen(*args, levels=levels, interpolate=False, prune=False)
    return fast, reference


def _dropped_fail_the_fit(mech, spec, engaged, levels, fast, reference):
    """Placements kept by the pruned screening are the reference's (same boxes, same order); the rest fail."""
    assert fast[1] == reference[1]
    kept = set(fast[0])
    assert [p for p in reference[0] if p in kept] == fast[0]
    low, high = bounds(spec)
    points, corners = _grid(low, high, levels)
    for p in reference[0]:
        if p not in kept:
            starts = points[corners[list(p.boxes)]].mean(axis=1)
            assert fit_ratios(mech, p.input, p.output, combinations_of_elements(p.elements, engaged), low, high,
                              np.array(spec.forward), np.array(spec.reverse), spec.tolerance, starts) is None, p
    return len(reference[0]) - len(kept)


def test_pruned_screening_drops_only_what_the_fit_rejects_on_the_whole_simpson_space():
    spec = SynthesisSpec.create([2.46, 1.46, 1.0, -2.18], 2, {"brakes": 2, "clutches": 2}, {"tolerance": 0.01})
    kept = 0
    for engaged in spec.engaged:
        for mech in _mechanisms(spec, engaged):
            fast, reference = _both(mech, spec, engaged, spec.levels)
            assert _both(mech, spec, engaged, spec.levels, prune=False)[0] == reference, mech  # interpolation
            _dropped_fail_the_fit(mech, spec, engaged, spec.levels, fast, reference)
            kept += len(fast[0])
    assert kept > 0


def test_pruned_screening_drops_only_what_the_fit_rejects_on_a_sample_of_the_8hp_space():
    spec = SynthesisSpec.create([*EIGHT_FORWARD, *EIGHT_REVERSE], 4, {"brakes": 2, "clutches": 3, "engaged": 3},
                                {"max_members_per_shaft": 2, "free_input": False})
    mechs = enumerate_mechanisms(("simple",) * 4, 4, max_members_per_shaft=2)
    rng = np.random.default_rng(1)
    dropped = 0
    for k in rng.choice(len(mechs), size=3, replace=False):
        fast, reference = _both(mechs[k], spec, 3, 2)
        assert fast[1] > 10**5
        dropped += _dropped_fail_the_fit(mechs[k], spec, 3, 2, fast, reference)
    assert dropped > 0  # the matching test does prune here


def test_rarest_target_level_equals_the_full_scan():
    """prune=True at level 0 without the matching test: the same placements, in the same order."""
    spec = SynthesisSpec.create([*EIGHT_FORWARD, *EIGHT_REVERSE], 4, {"brakes": 2, "clutches": 3, "engaged": 3},
                                {"max_members_per_shaft": 2, "free_input": False})
    mechs = enumerate_mechanisms(("simple",) * 4, 4, max_members_per_shaft=2)
    lay = layout(8, 2, 3, 3)
    low, high = bounds(spec)
    for mech in mechs[::300]:
        args = (mech, lay, low, high, np.array(spec.forward), np.array(spec.reverse), spec.tolerance)
        with pytest.MonkeyPatch.context() as patch:
            patch.setattr(screening, "_matched", lambda masks, gears: np.ones(len(masks), dtype=bool))
            fast = screen(*args, levels=0, prune=True, kernel=False)
        assert fast == screen(*args, levels=0, prune=False) and fast[0], mech


def test_matching_rule_agrees_with_brute_force():
    """Glover's greedy rule against every assignment of distinct combinations (intervals of 4 targets)."""
    import itertools

    intervals = [0] + [(1 << stop) - (1 << first) for first in range(4) for stop in range(first + 1, 5)]
    rng = np.random.default_rng(3)
    rows = np.array([rng.choice(intervals, size=5) for _ in range(400)])
    expected = [any(all(row[c] >> j & 1 for j, c in enumerate(pick)) for pick in itertools.permutations(range(5), 4))
                for row in rows]
    assert screening._matched(rows, 4).tolist() == expected and 0 < sum(expected) < len(rows)


def test_pruned_search_returns_exactly_the_unpruned_candidates(monkeypatch):
    """The whole Simpson-space search, ranked: same candidates, same order, with and without the pruning."""
    import functools

    from epicyclic.synthesis import search, synthesize

    def run():
        res = synthesize([2.46, 1.46, 1.0, -2.18], sets=2, elements={"brakes": 2, "clutches": 2},
                         constraints={"tolerance": 0.01}, workers=1, announce=False)
        return [c.key for c in res.candidates], res.stats["screened"]

    pruned, screened = run()
    monkeypatch.setattr(search, "screen", functools.partial(screen, interpolate=False, prune=False))
    reference, reference_screened = run()
    assert pruned == reference and len(pruned) > 0
    assert screened <= reference_screened
