"""Tooth-count search: vectorised vs loop reference, modes, ranking, errors."""

from __future__ import annotations

import math

import pytest

from epicyclic.geometry.errors import GeometryError
from epicyclic.geometry.fitting import check_fitting
from epicyclic.geometry.search import search_teeth, search_teeth_loops, two_shaft_ratio
from epicyclic.geometry.set_geometry import SetGeometry


@pytest.mark.parametrize(
    ("i0", "held", "driver", "driven", "expected"),
    [
        # Queitsch Tafel 1 with s = i0: 1 - s, 1 - 1/s, s and reciprocals
        (-2.6, "ring", "sun", "carrier", 3.6),
        (-2.6, "ring", "carrier", "sun", 1 / 3.6),
        (-2.6, "sun", "ring", "carrier", 1 - 1 / -2.6),
        (-2.6, "carrier", "sun", "ring", -2.6),
    ],
)
def test_two_shaft_ratio(i0, held, driver, driven, expected):
    assert two_shaft_ratio(i0, held, driver, driven) == pytest.approx(expected)


@pytest.mark.parametrize(
    ("target", "mode"),
    [(4.0, ("ring", "sun", "carrier")), (1.35, ("sun", "ring", "carrier")), (-2.8, ("carrier", "sun", "ring"))],
)
def test_vectorised_equals_loops(target, mode):
    held, driver, driven = mode
    kw = dict(held=held, driver=driver, driven=driven, tolerance=0.02, z_sun=(12, 34), z_planet=(12, 34),
              planets=(3, 4, 5), module=1.5, min_clearance=1.0)
    fast, slow = search_teeth(target, **kw), search_teeth_loops(target, **kw)
    assert len(fast) > 0
    assert [c.key() for c in fast.candidates] == [c.key() for c in slow.candidates]


def _tiers(res):
    """Each candidate's tier in the ranking: 0 the first of its family (the counts over their common factor),
    1 a repeat (a scaled copy, the same counts with other N)."""
    seen, tiers = set(), []
    for c in res.candidates:
        g = math.gcd(c.z_sun, c.z_planet)
        family = (c.z_sun // g, c.z_planet // g)
        tiers.append(1 if family in seen else 0)
        seen.add(family)
    return tiers


def test_candidates_fit_and_are_ranked():
    res = search_teeth(4.0, tolerance=0.03, z_sun=(12, 40), z_planet=(12, 40), planets=(3, 4, 5), module=2.0)
    tiers = _tiers(res)
    assert tiers == sorted(tiers)  # distinct sets, then the repeats
    for tier in set(tiers):  # within a tier: smallest error first
        errors = [round(c.error, 12) for c, t in zip(res.candidates, tiers) if t == tier]
        assert errors == sorted(errors)
    assert max(c.error for c in res.candidates) <= 0.03
    for c in res.candidates[:10]:
        report = check_fitting(SetGeometry.create(c.planetary_set(), module=2.0))
        assert report.passed and all(ch.passed for ch in report.checks)
    exact = [c for c, t in zip(res.candidates, tiers) if c.error == 0.0 and t == 1]
    sizes = [c.z_ring for c in exact]
    assert sizes == sorted(sizes)
    assert "tooth-count sets" in res.table() and "<table>" in res._repr_html_()
    assert res.to_dict()["candidates"][0]["z_ring"] == res.best.z_ring and "ToothSearch" in repr(res)


def test_hunting_tooth_preferred_on_ties():
    res = search_teeth(4.5, tolerance=0.05, z_sun=(14, 40), z_planet=(14, 50), planets=(3,))
    for a, b in zip(res.candidates, res.candidates[1:]):
        if round(a.error, 12) == round(b.error, 12) and a.z_ring == b.z_ring:
            assert a.hunting >= b.hunting


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"target_ratio": 0}, "target_ratio must be a finite non-zero"),
        ({"target_ratio": 4, "tolerance": 2}, "tolerance is a relative deviation"),
        ({"target_ratio": 4, "z_sun": (2, 10)}, "z_sun must be"),
        ({"target_ratio": 4, "planets": (0,)}, "planets must be whole numbers"),
        ({"target_ratio": 4, "held": "sun", "driver": "sun"}, "must be 'sun', 'ring', 'carrier'"),
    ],
)
def test_search_errors(kwargs, match):
    with pytest.raises(GeometryError, match=match):
        search_teeth(**kwargs)


def test_ratio_4_lists_hunting_and_distinct_sets_before_scaled_copies():
    """Issue 30: at ratio 4 (ring held, sun drives carrier) only z_s = z_p meets the target exactly, so ranking by
    error alone listed twenty scaled copies of 1/1/3 (21/21/63 … 40/40/120) and no hunting set. The page's
    defaults: tolerance 1 %, planets 3..5, teeth 12..80."""
    res = search_teeth(4.0, tolerance=0.01, z_sun=(12, 80), z_planet=(12, 80), planets=(3, 4, 5))
    first = res.candidates[:20]
    assert first[0].key() == (21, 21, 63, 3) and first[0].error == 0.0  # the smallest exact set, once
    assert all(c.hunting for c in first[1:]) and all(abs(c.ratio / 4 - 1) <= 0.01 for c in first)
    families = {(c.z_sun // math.gcd(c.z_sun, c.z_planet), c.z_planet // math.gcd(c.z_sun, c.z_planet))
                for c in first}
    assert len(families) >= 10  # distinct sets, not copies of one
    copies = [c for c in first if c.z_sun == c.z_planet]
    assert len(copies) <= 1  # one 1/1/3 set (the exact ratio), not twenty
