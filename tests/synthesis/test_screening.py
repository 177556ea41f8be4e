"""Screening shortcuts are exact: the pruned, interpolated screening keeps exactly the reference's placements.

* Multilinear interpolation: a combination determinant D_x(i0) = det[L(i0); E; e_x] is multilinear
  in the stationary ratios (each Willis row holds one i0, linearly; Queitsch eq. 12), so its values
  at the 2^S corners of a box fix it everywhere in the box.  Checked against the determinants solved
  at interior grid points.
* Block pruning: a block of element sets with the same brakes engages only combinations with those
  brakes; when they miss a target no architecture in the block can pass.
* Whole searches on smaller spaces (every two-set mechanism of the Simpson spec; a sample of the 8HP
  space at two bisection levels) give the same placements with and without the shortcuts.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from epicyclic.synthesis import SynthesisSpec, enumerate_mechanisms
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


def _both(mech, spec, engaged, levels):
    lay = layout(mech.shafts, spec.brakes, spec.clutches, engaged)
    low, high = bounds(spec)
    args = (mech, lay, low, high, np.array(spec.forward), np.array(spec.reverse), spec.tolerance)
    fast = screen(*args, levels=levels, interpolate=True, prune=True)
    reference = screen(*args, levels=levels, interpolate=False, prune=False)
    return fast, reference


def test_pruned_equals_unpruned_on_the_whole_simpson_space():
    spec = SynthesisSpec.create([2.46, 1.46, 1.0, -2.18], 2, {"brakes": 2, "clutches": 2}, {"tolerance": 0.01})
    kept = 0
    for engaged in spec.engaged:
        for mech in _mechanisms(spec, engaged):
            fast, reference = _both(mech, spec, engaged, spec.levels)
            assert fast == reference, mech
            kept += len(fast[0])
    assert kept > 0


def test_pruned_equals_unpruned_on_a_sample_of_the_8hp_space():
    spec = SynthesisSpec.create([*EIGHT_FORWARD, *EIGHT_REVERSE], 4, {"brakes": 2, "clutches": 3, "engaged": 3},
                                {"max_members_per_shaft": 2, "free_input": False})
    mechs = enumerate_mechanisms(("simple",) * 4, 4, max_members_per_shaft=2)
    rng = np.random.default_rng(1)
    for k in rng.choice(len(mechs), size=3, replace=False):
        fast, reference = _both(mechs[k], spec, 3, 2)
        assert fast == reference and fast[1] > 10**5
