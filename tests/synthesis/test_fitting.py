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
