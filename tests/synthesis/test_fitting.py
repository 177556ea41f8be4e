"""Ratio fitting and schedule assignment."""

from __future__ import annotations

import numpy as np
import pytest

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
