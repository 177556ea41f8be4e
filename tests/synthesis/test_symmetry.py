"""Symmetries of mechanisms: one placement per orbit screened, every image written back, the same result.

* The automorphism groups are right: by the orbit–stabilizer theorem, a mechanism of S sets of one
  kind stands for S!/|Aut| labelled tie patterns, so Σ S!/|Aut| over the enumerated mechanisms must
  equal the number of connected labelled patterns counted directly (Harary & Palmer 1973, ch. 2).
* Exactness: ``screen(symmetry=True)`` returns exactly the placements (boxes and order included) of
  ``screen(symmetry=False)`` on the whole Simpson space, on every three-set mechanism with two
  brakes and two clutches, and on the symmetric mechanisms of a sample of the 8HP space; and the
  ranked Simpson search is unchanged.
"""

from __future__ import annotations

import functools
import math

import numpy as np
import pytest

from epicyclic.synthesis import SynthesisSpec, enumerate_mechanisms
from epicyclic.synthesis.mechanisms import Mechanism, _connected, _partitions
from epicyclic.synthesis.screening import layout, screen
from epicyclic.synthesis.search import _mechanisms, bounds
from epicyclic.synthesis.symmetry import automorphisms, box_images, box_order, element_map, element_set_images

EIGHT_FORWARD = np.array([4.6957, 3.1304, 2.1039, 1.6667, 1.2845, 1.0, 0.8392, 0.6667])  # ZF 8HP 70
EIGHT_REVERSE = np.array([-3.2968])


@pytest.mark.parametrize("sets, dof, free_input", [(2, 2, False), (2, 3, True), (3, 3, False), (3, 2, True),
                                                    (4, 5, False)])
def test_orbit_stabilizer_counts_the_labelled_patterns(sets, dof, free_input):
    kinds = ("simple",) * sets
    mechs = enumerate_mechanisms(kinds, dof, free_input=free_input)
    shafts = dof + sets - int(free_input)
    labelled = sum(_connected(p, sets) for p in _partitions(sets, shafts, sets))
    assert sum(math.factorial(sets) // (1 + len(automorphisms(m))) for m in mechs) == labelled
    assert any(automorphisms(m) for m in mechs)


def test_an_automorphism_maps_every_set_onto_a_set():
    for m in enumerate_mechanisms(("simple",) * 3, 3):
        for g in automorphisms(m):
            for j in range(3):
                assert tuple(g.shafts[x] for x in m.set_shafts(g.sets[j])) == m.set_shafts(j)


def test_the_box_must_be_kept():
    m = Mechanism(("simple", "simple"), (0, 1, 2, 0, 1, 3))  # common sun and ring: the two sets swap
    assert len(automorphisms(m)) == 1
    assert automorphisms(m, np.array([-4.0, -3.0]), np.array([-1.5, -1.5])) == ()


def test_element_set_images_are_a_permutation():
    m = Mechanism(("simple", "simple"), (0, 1, 2, 0, 1, 3), free_input=True)
    (g,) = automorphisms(m)
    lay = layout(m.shafts, 2, 2, 2)
    images = element_set_images(lay.element_sets, g.shafts)
    assert sorted(images) == list(range(len(lay.element_sets)))
    assert np.array_equal(images[images], np.arange(len(images)))  # an involution: applied twice, the identity
    mapped = np.sort(element_map(g.shafts)[lay.element_sets], axis=1)
    assert np.array_equal(lay.element_sets[images], mapped)


def test_box_images_and_order():
    boxes = np.arange(64)  # level 2, three sets
    assert sorted(box_images(boxes, 2, (2, 0, 1))) == list(range(64))
    assert np.array_equal(box_images(box_images(boxes, 2, (1, 0, 2)), 2, (1, 0, 2)), boxes)
    from epicyclic.synthesis.screening import _children

    visited = _children(_children(np.array([0]), 0, 3).ravel(), 1, 3).ravel()  # the bisection's order
    assert box_order(np.random.default_rng(0).permutation(visited), 2, 3).tolist() == visited.tolist()


def _compare(spec, mechs, engaged, levels):
    low, high = bounds(spec)
    kept = symmetric = 0
    for mech in mechs:
        lay = layout(mech.shafts, spec.brakes, spec.clutches, engaged)
        args = (mech, lay, low, high, np.array(spec.forward), np.array(spec.reverse), spec.tolerance)
        reduced = screen(*args, levels=levels, symmetry=True)
        assert reduced == screen(*args, levels=levels, symmetry=False), mech
        kept += len(reduced[0])
        symmetric += bool(automorphisms(mech, low, high)) and bool(reduced[0])
    return kept, symmetric


def test_symmetry_reduced_screening_is_exact_on_the_simpson_space():
    spec = SynthesisSpec.create([2.46, 1.46, 1.0, -2.18], 2, {"brakes": 2, "clutches": 2}, {"tolerance": 0.01})
    kept = sum(_compare(spec, _mechanisms(spec, k), k, spec.levels)[0] for k in spec.engaged)
    assert kept > 0


def test_symmetry_reduced_screening_is_exact_on_three_sets():
    """Every symmetric three-set mechanism, 2 brakes + 2 clutches, 2 engaged (a three-speed with reverse); the
    others take the unreduced path unchanged."""
    spec = SynthesisSpec.create([3.1, 1.75, 1.0, -2.6], 3, {"brakes": 2, "clutches": 2, "engaged": 2},
                                {"tolerance": 0.015})
    mechs = [m for m in _mechanisms(spec, 2) if automorphisms(m, *bounds(spec))]
    kept, symmetric = _compare(spec, mechs, 2, 2)
    assert len(mechs) == 57 and kept > 100 and symmetric > 5, (kept, symmetric)


@pytest.mark.parametrize("members", [(0, 1, 2, 0, 3, 4, 5, 2, 6, 7, 4, 6), (0, 1, 2, 1, 3, 4, 5, 2, 6, 7, 5, 3),
                                     (0, 1, 2, 0, 3, 4, 5, 1, 6, 5, 7, 4)])
def test_symmetry_reduced_screening_is_exact_on_symmetric_8hp_mechanisms(members):
    """Three of the 45 symmetric mechanisms of the 8HP space (ties in pairs) that keep placements."""
    spec = SynthesisSpec.create([*EIGHT_FORWARD, *EIGHT_REVERSE], 4, {"brakes": 2, "clutches": 3, "engaged": 3},
                                {"max_members_per_shaft": 2, "free_input": False})
    kept, symmetric = _compare(spec, [Mechanism(("simple",) * 4, members)], 3, 2)
    assert kept >= 2 and symmetric == 1


def test_ranked_search_is_unchanged(monkeypatch):
    from epicyclic.synthesis import search, synthesize

    def run():
        res = synthesize([2.46, 1.46, 1.0, -2.18], sets=2, elements={"brakes": 2, "clutches": 2},
                         constraints={"tolerance": 0.01}, workers=1, announce=False)
        return [c.key for c in res.candidates], res.stats["screened"]

    reduced = run()
    monkeypatch.setattr(search, "screen", functools.partial(screen, symmetry=False))
    assert run() == reduced and reduced[0]
