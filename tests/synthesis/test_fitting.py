"""Ratio fitting and schedule assignment."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from epicyclic.synthesis.candidate import Candidate
from epicyclic.synthesis.fitting import assign, combinations_of_elements, fit_ratios
from epicyclic.synthesis.kinematics import gear_ratios
from epicyclic.transmission.library import build


def test_assignment_is_monotone_and_optimal():
    ratios = np.array([1.0, 3.1, -3.0, 4.6, 2.0, np.nan, -1.0])
    cost, picks = assign(ratios, np.array([4.7, 3.1, 1.0]), np.array([-3.3]))
    assert picks == [3, 1, 0, 2]
    brute = min(sum((np.log(ratios[a] / t)) ** 2 for a, t in zip(p, (4.7, 3.1, 1.0)))
                for p in __import__("itertools").permutations([0, 1, 3, 4], 3))
    assert cost == pytest.approx(brute + np.log(3.0 / 3.3) ** 2)


def test_too_few_gears_cannot_be_assigned():
    assert assign(np.array([2.0, np.nan]), np.array([2.0, 1.0]), np.array([]))[0] == np.inf


def test_fit_recovers_the_8hp_stationary_ratios_from_its_published_ratios():
    """Published ratios (ZF 8HP 70, 4 decimals) → i0 = −96/48, −96/48, −111/69, −85/23 within 1e-3."""
    t = build("zf_8hp70")
    c = Candidate.from_transmission(t)
    combos = combinations_of_elements(c.elements, 3)
    fwd, rev = np.array(c.targets[:8]), np.array(c.targets[8:])
    low, high = np.full(4, -4.0), np.full(4, -1.5)
    starts = np.array([[-2.5, -2.5, -2.5, -2.5], [-2.2, -1.8, -1.8, -3.5]])
    fit = fit_ratios(c.mechanism, c.input, c.output, combos, low, high, fwd, rev, 0.002, starts)
    assert fit is not None and fit.error < 1e-3
    assert fit.stationary_ratios == pytest.approx([-2.0, -2.0, -111 / 69, -85 / 23], abs=1e-3)
    assert [tuple(combos[j]) for j in fit.schedule] == list(c.schedule)
    r = gear_ratios(c.mechanism, np.array([fit.stationary_ratios]), combos[list(fit.schedule)], c.input, c.output)
    assert r[0] == pytest.approx(fit.ratios, rel=1e-12)


def test_single_swaps_are_preferred_among_combinations_of_identical_ratio():
    """Ford 10R80 (examples/transmissions/ford_10r80_10speed.toml): first gear is 1 + 85/23 with A B C E,
    A B D E or A B E F (set 4's sun at input speed, its ring held); only A B C E and A B E F shift to second
    (A B C F) by one swap.  Given A B D E, the schedule takes an equivalent single-swap combination and keeps
    every ratio (Naunheimer et al. 2011, section 12.3)."""
    from pathlib import Path

    from epicyclic.synthesis.fitting import single_swap_schedule
    from epicyclic.transmission import Transmission

    path = Path(__file__).resolve().parents[2] / "examples" / "transmissions" / "ford_10r80_10speed.toml"
    t = Transmission.from_file(path)
    c = Candidate.from_transmission(t)
    combos = combinations_of_elements(c.elements, 4)
    rows = [int(np.flatnonzero((combos == np.array(s)).all(axis=1))[0]) for s in c.schedule]
    # the file's names of the elements, by the gears each is engaged in
    gears_of = {e: frozenset(k for k, s in enumerate(c.schedule) if e in s) for e in c.elements}
    order = list(t.ratios)  # the candidate's gear order is the file's: 1 … 10, R
    names = {n: next(e for e, g in gears_of.items() if g == frozenset(order.index(x) for x in order
                                                                         if n in t.schedule[x]))
             for n in "ABCDEF"}
    label = {e: n for n, e in names.items()}
    abde = tuple(sorted(names[n] for n in "ABDE"))
    rows[0] = int(np.flatnonzero((combos == np.array(abde)).all(axis=1))[0])
    i0 = np.array([[t.stationary_ratio for t in c.teeth], [-2.7, -1.9, -3.1, -2.2]])
    before = gear_ratios(c.mechanism, i0[:1], combos[rows], c.input, c.output)
    new = single_swap_schedule(c.mechanism, c.input, c.output, combos, tuple(rows), 10, i0)
    after = gear_ratios(c.mechanism, i0[:1], combos[list(new)], c.input, c.output)
    assert after == pytest.approx(before, rel=1e-12) and new[1:] == tuple(rows[1:])
    sets = [set(combos[j]) for j in new[:10]]
    assert all(len(a ^ b) == 2 for a, b in zip(sets, sets[1:]))  # one element out, one in, every shift
    assert {label[e] for e in combos[new[0]]} in ({"A", "B", "C", "E"}, {"A", "B", "E", "F"})


def _monotone_by_the_recurrence(values, targets):
    """Reference: the recurrence cost[i, j] = min(cost[i, j−1], cost[i−1, j−1] + (v_j − t_i)²), element by element."""
    n, m = targets.size, values.size
    if n == 0:
        return 0.0, []
    if m < n:
        return np.inf, []
    order = np.argsort(-values)
    v, t = np.log(values[order]), np.log(targets)
    cost = np.full((n + 1, m + 1), np.inf)
    cost[0, :] = 0.0
    for i in range(1, n + 1):
        for j in range(i, m + 1):
            d = v[j - 1] - t[i - 1]
            cost[i, j] = min(cost[i, j - 1], cost[i - 1, j - 1] + d * d)
    from epicyclic.synthesis.fitting import _backtrack

    return _backtrack(cost, order)  # the same table gives the same picks


@settings(max_examples=200, deadline=None)
@given(st.lists(st.floats(0.05, 20.0), max_size=20), st.lists(st.floats(0.05, 20.0), max_size=10),
       st.booleans())
def test_monotone_assignment_equals_its_recurrence(values, targets, tie):
    """The assignment's dynamic programme, a running minimum per row, equals the element-wise recurrence exactly."""
    from epicyclic.synthesis.fitting import _monotone

    values = np.array(values + values[:1] if tie else values, dtype=float)  # a tie: one ratio twice
    targets = np.sort(np.array(targets, dtype=float))[::-1]
    assert _monotone(values, targets) == _monotone_by_the_recurrence(values, targets)


class _GeneralPath:
    """The ratio functions by the general path: a null-space solve per point, central differences."""

    def __init__(self, mechanism, combos, input, output):
        self.args = (mechanism, combos, input, output)

    @classmethod
    def of(cls, mechanism, low, high, combos, input, output):
        return cls(mechanism, combos, input, output)

    def __call__(self, ratios):
        mechanism, combos, input, output = self.args
        return gear_ratios(mechanism, np.atleast_2d(ratios), combos, input, output)

    def with_jacobian(self, x):
        columns = []
        for k in range(x.size):
            step = np.zeros(x.size)
            step[k] = 1e-7 * (1 + abs(x[k]))
            columns.append((self(x + step)[0] - self(x - step)[0]) / (2 * step[k]))
        return self(x)[0], np.array(columns).T


def test_fit_with_exact_derivatives_decides_as_the_general_path(monkeypatch):
    """The fit's fast path (corner interpolation, exact Jacobian) fits exactly the placements the general path fits.

    Placements: the ZF 8HP 70's own (fits) and the first 40 that survive screening on random 4-set
    mechanisms with 2 brakes + 4 clutches and the 8HP targets (most do not fit).  Where both fit, both meet the tolerance.
    """
    from epicyclic.synthesis import enumerate_mechanisms, fitting
    from epicyclic.synthesis.boxes import _grid
    from epicyclic.synthesis.screening import layout, screen

    forward = np.array([4.6957, 3.1304, 2.1039, 1.6667, 1.2845, 1.0, 0.8392, 0.6667])  # ZF 8HP 70
    reverse = np.array([-3.2968])
    low, high = np.full(4, -4.0), np.full(4, -1.5)
    points, corners = _grid(low, high, 3)
    c = Candidate.from_transmission(build("zf_8hp70"))
    cases = [(c.mechanism, c.input, c.output, tuple(sorted({e for row in c.schedule for e in row})),
              ((low + high) / 2)[None, :])]
    mechs = enumerate_mechanisms(("simple",) * 4, 4, max_members_per_shaft=2)
    rng = np.random.default_rng(3)
    lay = layout(8, 2, 4, 3)
    for i in rng.choice(len(mechs), 30, replace=False):
        placements, _ = screen(mechs[i], lay, low, high, forward, reverse, 0.01, levels=3)
        cases += [(mechs[i], p.input, p.output, p.elements, points[corners[list(p.boxes)]].mean(axis=1))
                  for p in placements]
        if len(cases) > 40:
            break
    assert len(cases) > 20

    def fits():
        return [fitting.fit_ratios(m, a, b, combinations_of_elements(e, 3), low, high, forward, reverse, 0.01, s)
                for m, a, b, e, s in cases[:41]]

    fast = fits()
    monkeypatch.setattr(fitting, "RatioFunctions", _GeneralPath)
    general = fits()
    assert [f is None for f in fast] == [g is None for g in general]
    assert fast[0] is not None  # the 8HP itself
    for f, g in zip(fast, general):
        if f is not None:
            assert max(f.error, g.error) <= 0.01 * (1 + 1e-9)
