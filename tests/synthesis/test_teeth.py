"""The tooth choice trades ratio error against ring balance: against a brute force.

Small case: the Simpson arrangement (``examples/simpson_c4_3speed.toml``) with the tooth options the
tooth search offers for its two stationary ratios (up to 6 each, every one meeting fit, assembly and
neighbour conditions: hard constraints).  The brute force builds every combination as a train
(``Candidate.transmission``: the project's solver, not the vectorised kinematics of the search), keeps
those whose gear ratios meet every Ford C4 target within 1 % (2.46, 1.46, 1.00, R −2.18; 'Ford C4
transmission', Wikipedia), sizes each by ISO 6336 in every gear and computes
J = w_e · e/tol + w_b · (d_max/d_min − 1)/0.25 by hand; the synthesis' choice must have the least J.
"""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from epicyclic.synthesis import SynthesisSpec
from epicyclic.synthesis.candidate import Candidate, evaluate
from epicyclic.synthesis.fitting import combinations_of_elements
from epicyclic.synthesis.search import Arrangement, sized_candidate
from epicyclic.synthesis.teeth import choose_teeth, tooth_objective, tooth_options

TARGETS = [2.46, 1.46, 1.0, -2.18]


@pytest.fixture(scope="module")
def simpson(simpson_with_teeth):
    return Candidate.from_transmission(simpson_with_teeth)


@pytest.fixture(scope="module")
def brute(simpson):
    """Every combination of options built and solved as a train; the admissible ones ISO-sized."""
    c = simpson
    spec = SynthesisSpec.create(TARGETS, 2, {"brakes": 2, "clutches": 2, "engaged": 2}, {"tolerance": 0.01})
    options = [tooth_options(t.stationary_ratio, "simple", tolerance=0.01, sun=spec.sun, planet=spec.planet,
                             planets=spec.planets) for t in c.teeth]
    targets = np.array(TARGETS)
    out = []
    for row in itertools.product(*options):  # every combination, hard constraints met by each option
        trial = Candidate(c.mechanism, c.input, c.output, c.elements, c.schedule, row, c.ratios, tuple(TARGETS),
                          c.forward)
        ratios = np.array(list(trial.transmission().ratios.values()))
        error = float(np.max(np.abs(ratios / targets - 1)))
        if error > 0.01 * (1 + 1e-9):
            continue
        sized = evaluate(Candidate(c.mechanism, c.input, c.output, c.elements, c.schedule, row, tuple(ratios),
                                   tuple(TARGETS), c.forward), 300.0)
        rings = [z.module * t.z_ring for z, t in zip(sized.sizes, row)]
        out.append((error, max(rings) / min(rings) - 1, row))
    return options, out


@pytest.mark.parametrize("weights", [{}, {"ring_balance": 0.0}, {"ratio_error": 0.2, "ring_balance": 3.0}])
def test_the_choice_has_the_least_objective_of_every_admissible_combination(simpson, brute, weights):
    c = simpson
    options, admissible = brute
    spec = SynthesisSpec.create(TARGETS, 2, {"brakes": 2, "clutches": 2, "engaged": 2},
                                {"tolerance": 0.01, "tooth_weights": weights})
    w = {"ratio_error": 1.0, "ring_balance": 1.0, **weights}
    combos = combinations_of_elements(c.elements, 2)
    rows = tuple(int(np.flatnonzero((combos == np.array(s)).all(axis=1))[0]) for s in c.schedule)
    targets = np.array(TARGETS)
    chosen = choose_teeth(c.mechanism, c.input, c.output, combos, rows, targets, options, 0.01)
    picked = sized_candidate(spec, Arrangement(c.mechanism, c.input, c.output, c.elements, c.schedule), chosen,
                             targets)
    assert len(admissible) == len(chosen[0]) > 1  # the search admits exactly the brute force's combinations
    best = min(w["ratio_error"] * e / 0.01 + w["ring_balance"] * b / 0.25 for e, b, _ in admissible)
    rings = [z.module * t.z_ring for z, t in zip(picked.sizes, picked.teeth)]
    j = w["ratio_error"] * picked.metrics["ratio_error"] / 0.01 + w["ring_balance"] * (max(rings) / min(rings)
                                                                                        - 1) / 0.25
    assert j == pytest.approx(best, rel=1e-9, abs=1e-12)


def test_objective_formula():
    # e = 0.5 tol and rings 100 / 150 mm: 0.5 + 0.5 / 0.25
    assert tooth_objective(np.array([0.005]), np.array([[100.0, 150.0]]), 0.01).tolist() == pytest.approx([2.5])
    assert tooth_objective(np.array([0.005]), np.array([[100.0, np.nan]]), 0.01,
                           {"ring_balance": 5.0}).tolist() == pytest.approx([0.5])


def test_bad_tooth_weights_name_the_key():
    from epicyclic.synthesis.spec import SynthesisError

    with pytest.raises(SynthesisError, match="tooth_weights.ring_size"):
        SynthesisSpec.create(TARGETS, 2, {"brakes": 2, "clutches": 2}, {"tooth_weights": {"ring_size": 1.0}})
    with pytest.raises(SynthesisError, match=">= 0"):
        SynthesisSpec.create(TARGETS, 2, {"brakes": 2, "clutches": 2}, {"tooth_weights": {"ring_balance": -1}})
