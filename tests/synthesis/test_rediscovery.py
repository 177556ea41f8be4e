"""Rediscovery: from published ratios back to the published transmission.

ZF 8HP 70 (pilot series 2008): ratios 4.6957, 3.1304, 2.1039, 1.6667, 1.2845, 1.0000, 0.8392,
0.6667, R −3.2968 ('ZF 8HP transmission', 'In-Depth Analysis With Assessment' table, row 8HP 70;
connections: US patent 8,016,708 B2 and the Jeep 8HP75 service information — see
``epicyclic/transmission/library.py``).  The search gets only the ratios, 4 simple sets,
2 brakes and 3 clutches with 3 engaged per gear, and a designer's space: ties join pairs of
members, input and output are carriers.  That space holds 915 tie patterns and about 1.3·10^8
architectures (input, output, brake and clutch placements); all are screened, none is named.
The published architecture must come out among the first five, with tooth counts that give
the published ratios to their four printed decimals.

The search runs on a LocalCluster with two real worker processes (the one test that does).
"""

from __future__ import annotations

import pytest

from epicyclic.synthesis import synthesize
from epicyclic.synthesis.candidate import Candidate
from epicyclic.transmission.library import build, entry


@pytest.fixture(scope="module")
def zf8():
    published = entry("zf_8hp70").published_ratios
    result = synthesize(list(published.values()), sets=4, elements={"brakes": 2, "clutches": 3, "engaged": 3},
                        constraints={"tolerance": 0.01, "max_members_per_shaft": 2, "free_input": False,
                                     "input_members": ["carrier"], "output_members": ["carrier"], "top": 10},
                        workers=2, processes=True)
    return published, result


def test_8hp_architecture_and_teeth_are_among_the_top_candidates(zf8):
    published, result = zf8
    assert result.stats["workers"] == 2 and result.stats["mechanisms"] == 915
    assert result.stats["architectures"] > 10**8
    key = Candidate.from_transmission(build("zf_8hp70")).architecture_key
    ranks = [k for k, c in enumerate(result.candidates[:5]) if c.architecture_key == key]
    assert ranks, [c.describe() for c in result.candidates[:5]]
    found = result.candidates[ranks[0]]
    ratios = dict(zip(found.gears, found.ratios))
    for gear, value in published.items():  # to the four printed decimals
        assert round(ratios[gear], 4) == pytest.approx(value, abs=1e-9), gear
    # the same schedule as ZF's (1 ABC, 2 ABE, ... R ABD), element names aside
    assert found.metrics["double_shifts"] == 0


def test_8hp_candidate_file_reproduces_its_ratios(zf8, tmp_path):
    from epicyclic.transmission import Transmission

    published, result = zf8
    paths = result.write_toml(tmp_path, count=3)
    for cand, path in zip(result.candidates, paths):
        t = Transmission.from_file(path)
        assert list(t.ratios.values()) == pytest.approx(list(cand.ratios), rel=1e-12)


def test_ravigneaux_aod_is_found_with_a_plus_set():
    """Ford AOD: 2.40, 1.47, 1.00, 0.67, R −2.00 (ATRA TSB 89-30; compass-at.com), one simple and one
    double-planet set, 2 brakes, 3 clutches, 2 engaged: the Ravigneaux arrangement (sets sharing ring
    and carrier, separate input with three clutches) is among the candidates of the full space."""
    published = entry("ravigneaux_aod").published_ratios
    result = synthesize(list(published.values()), sets={"simple": 1, "plus": 1},
                        elements={"brakes": 2, "clutches": 3, "engaged": 2}, constraints={"tolerance": 0.01},
                        workers=1, processes=False)
    key = Candidate.from_transmission(build("ravigneaux_aod")).architecture_key
    found = [c for c in result.candidates if c.architecture_key == key]
    assert found
    assert all(abs(r / t - 1) <= 0.01 for r, t in zip(found[0].ratios, found[0].targets))
    assert found[0].teeth[1].kind == "plus" and found[0].teeth[1].stationary_ratio > 0
