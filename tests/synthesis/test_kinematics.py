"""Vectorised kinematics against the engine's solver, and the corner bound of ratio ranges.

Reference: every library transmission's gear ratios from the general solver
(Transmission.ratio, Willis equation per set, Queitsch eq. 12) — an independent
code path (QR/least-squares solve of the full shift state) from the
determinant formula used here (Cramer's rule).  Tolerance 1e-9 relative: both
are exact up to round-off.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from epicyclic.synthesis.candidate import Candidate
from epicyclic.synthesis.kinematics import combination_determinants, corner_points, gear_ratios, ratio_ranges
from epicyclic.synthesis.mechanisms import Mechanism
from epicyclic.transmission.library import build


@pytest.mark.parametrize("key", ["simpson_c4", "zf_8hp70", "ravigneaux_aod"])
def test_gear_ratios_match_the_solver(key):
    t = build(key)
    c = Candidate.from_transmission(t)
    i0 = np.array([[p.stationary_ratio for p in sorted(t.train.planetary_sets, key=lambda p: p.stationary_ratio > 0)]])
    ratios = gear_ratios(c.mechanism, i0, np.array(c.schedule), c.input, c.output)[0]
    assert ratios == pytest.approx(list(c.ratios), rel=1e-9)


def test_housing_members_are_outside_the_space():
    from epicyclic.synthesis import SynthesisError

    with pytest.raises(SynthesisError, match="tied to the housing"):
        Candidate.from_transmission(build("lepelletier_6hp26"))


def test_no_gear_gives_nan():
    m = Mechanism(("simple",), (0, 1, 2))
    # brake on the sun with sun as input: the input cannot turn -> no gear
    assert np.isnan(gear_ratios(m, np.array([[-2.0]]), np.array([[0]]), 0, 2)[0, 0])


@settings(max_examples=60, deadline=None)
@given(st.lists(st.floats(0.0, 1.0), min_size=8, max_size=8), st.integers(0, 9))
def test_ratio_range_from_corners_bounds_every_interior_point(fractions, combo):
    """A multilinear fraction has its extremes at the corners of a box (no pole inside)."""
    t = build("zf_8hp70")
    c = Candidate.from_transmission(t)
    low, high = np.full(4, -3.0), np.full(4, -1.8)
    combos = np.array(c.schedule)
    det = combination_determinants(c.mechanism, corner_points(low, high), combos)
    valid, lo, hi = ratio_ranges(det[..., c.input], det[..., c.output])
    point = low + (high - low) * np.array(fractions[:4])
    r = gear_ratios(c.mechanism, point[None, :], combos, c.input, c.output)[0]
    k = combo % len(combos)
    if valid[k]:
        assert lo[k] * (1 - 1e-9) - 1e-12 <= r[k] <= hi[k] * (1 + 1e-9) + 1e-12 or \
            lo[k] * (1 + 1e-9) - 1e-12 <= r[k] <= hi[k] * (1 - 1e-9) + 1e-12


def test_determinants_are_multilinear_in_the_stationary_ratios():
    """det[L; E; e_x] is affine in each i0: the midpoint value is the mean of the end values."""
    c = Candidate.from_transmission(build("zf_8hp70"))
    combos = np.array(c.schedule)
    a = np.array([-2.0, -2.0, -1.6, -3.7])
    for k in range(4):
        lo, hi = a.copy(), a.copy()
        lo[k], hi[k] = -1.5, -4.0
        d = combination_determinants(c.mechanism, np.stack([lo, (lo + hi) / 2, hi]), combos)
        assert d[1] == pytest.approx((d[0] + d[2]) / 2, rel=1e-9, abs=1e-9)


def test_four_engaged_cofactors_by_laplace_expansion_equal_lu_determinants():
    """The k = 4 cofactors (Laplace expansion along two rows) equal numpy's LU determinants of each minor."""
    import itertools

    from epicyclic.synthesis.kinematics import _cofactors

    funcs = np.random.default_rng(0).normal(size=(3, 12, 5))
    combos = np.array(list(itertools.combinations(range(12), 4)))
    picked = funcs[:, combos, :]
    expected = np.stack([(-1) ** (i + 4) * np.linalg.det(picked[..., [j for j in range(5) if j != i]])
                         for i in range(5)], axis=-1)
    assert np.allclose(_cofactors(funcs, combos), expected, rtol=0, atol=1e-12 * np.abs(expected).max())


def test_ratio_functions_of_one_set_are_the_willis_ratio_and_its_slope():
    """Closed form (Queitsch eq. 12): ring held, sun in, carrier out: n_sun/n_carrier = 1 − i0, slope −1."""
    from epicyclic.synthesis.kinematics import RatioFunctions

    m = Mechanism(("simple",), (0, 1, 2))
    f = RatioFunctions.of(m, np.array([-4.0]), np.array([-1.5]), np.array([[1]]), 0, 2)
    for i0 in (-4.0, -3.3, -2.0, -1.5):
        ratio, jacobian = f.with_jacobian(np.array([i0]))
        assert ratio[0] == pytest.approx(1.0 - i0, rel=1e-12)
        assert jacobian[0, 0] == pytest.approx(-1.0, rel=1e-12)
        assert f(np.array([[i0]]))[0, 0] == pytest.approx(1.0 - i0, rel=1e-12)


@settings(max_examples=40, deadline=None)
@given(st.integers(0, 10 ** 6), st.integers(2, 4))
def test_ratio_functions_equal_the_general_path_with_exact_derivatives(seed, engaged):
    """The fit's fast path (multilinear interpolation of corner determinants) equals gear_ratios.

    Same NaN pattern (no gear), values to 1e-9 relative, and derivatives equal to the central
    difference of the general path (an independent computation: null-space solve at two points).
    """
    from epicyclic.synthesis.fitting import combinations_of_elements
    from epicyclic.synthesis.kinematics import RatioFunctions, element_count

    rng = np.random.default_rng(seed)
    mechs = _mechanisms(engaged)
    m = mechs[rng.integers(len(mechs))]
    elements = rng.choice(element_count(m.shafts), 6, replace=False)
    combos = combinations_of_elements(tuple(int(e) for e in elements), engaged)
    a, b = (int(v) for v in rng.choice(m.shafts, 2, replace=False))
    low, high = np.full(4, -4.0), np.full(4, -1.5)
    f = RatioFunctions.of(m, low, high, combos, a, b)
    points = np.vstack([rng.uniform(low, high, (8, 4)), corner_points(low, high)[:3]])
    fast, general = f(points), gear_ratios(m, points, combos, a, b)
    assert np.array_equal(np.isnan(fast), np.isnan(general))
    ok = ~np.isnan(general)
    assert fast[ok] == pytest.approx(general[ok], rel=1e-9, abs=1e-12)
    x = points[0]
    ratio, jacobian = f.with_jacobian(x)
    assert np.array_equal(np.isnan(ratio), np.isnan(general[0]))
    h = 1e-6
    for k in range(4):
        step = np.zeros(4)
        step[k] = h
        central = (gear_ratios(m, (x + step)[None], combos, a, b)[0] - gear_ratios(m, (x - step)[None], combos, a, b)[0]) / (2 * h)
        finite = np.isfinite(central) & np.isfinite(jacobian[:, k])
        assert jacobian[finite, k] == pytest.approx(central[finite], rel=1e-4, abs=1e-6 * (1 + np.abs(ratio[finite]).max(initial=0)))


_MECHANISMS: dict[int, tuple] = {}


def _mechanisms(engaged: int) -> tuple:
    from epicyclic.synthesis import enumerate_mechanisms

    if engaged not in _MECHANISMS:
        _MECHANISMS[engaged] = enumerate_mechanisms(("simple",) * 4, engaged + 1)
    return _MECHANISMS[engaged]


@pytest.mark.parametrize("shape", [(16, 3, 9), (16, 40000, 9), (3, 1, 1)])  # one block, several blocks, tiny
def test_cleaning_in_place_equals_clean_array_bit_for_bit(shape):
    """The determinants' zero rule written in place, in blocks: the same bytes as clean_array (signed zeros too)."""
    from epicyclic.results.zero import clean_array
    from epicyclic.synthesis.kinematics import _clean_in_place

    rng = np.random.default_rng(7)
    values = rng.normal(size=shape) * 10.0 ** rng.integers(-14, 3, size=shape)
    values.flat[::7] = -0.0
    values.flat[1::11] = np.nan
    values.flat[2::13] = -np.inf
    scale = 10.0 ** rng.integers(-3, 3, size=shape[:2] + (1,))
    expected = clean_array(values, scale)
    got = _clean_in_place(values.copy(), scale)
    assert got.tobytes() == expected.tobytes()
