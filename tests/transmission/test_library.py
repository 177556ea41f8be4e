"""Published ratios of the library transmissions, reproduced per gear to the printed digits.

Sources are cited per entry in epicyclic/transmission/library.py and in the
TOML files in examples/.  Tolerance: half a unit of the last printed digit.
"""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

from epicyclic import GearTrain, OperatingPoint, PlanetarySet, solve
from epicyclic.errors import ModelError
from epicyclic.io import load_train_file
from epicyclic.solver.assembly import matrices
from epicyclic.solver.kinematics import degrees_of_freedom
from epicyclic.transmission import Transmission
from epicyclic.transmission.library import LIBRARY, build, build_train, entry, to_toml

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
FILES = {
    "simpson_c4": "simpson_c4_3speed.toml",
    "ravigneaux_aod": "ravigneaux_ford_aod_4speed.toml",
    "lepelletier_6hp26": "lepelletier_zf_6hp26_6speed.toml",
    "zf_8hp70": "zf_8hp70_8speed.toml",
    "gm_8l90": "gm_8l90_8speed.toml",
    "prius_psd": "toyota_prius_power_split.toml",
}

CASES = [
    (key, gear, published, LIBRARY[key].printed_digits)
    for key in ("simpson_c4", "ravigneaux_aod", "lepelletier_6hp26", "zf_8hp70", "zf_8hp45", "gm_8l90", "gm_8l45")
    for gear, published in LIBRARY[key].published_ratios.items()
]


# Ford C4: Wikipedia 'Ford C4' (2.46, 1.46, 1.00) and ford-torino.de (R 2.18);
# Ford AOD: ATRA TSB 89-30 (2.4, 1.47, 1, 0.67) and compass-at.com (R -2.0);
# ZF 6HP 26: Wikipedia 'ZF 6HP transmission' (4.171 … 0.691, R -3.403);
# ZF 8HP 70: Wikipedia 'ZF 8HP transmission', in-depth table (4.6957 … 0.6667, R -3.2968);
# ZF 8HP 45 (1st gen.): same article, teeth 48/96 48/96 60/96 28/104, ratios 4.714 … 0.667, R -3.295;
# GM 8L 90 / 8L 45: Wikipedia 'GM 8L transmission', in-depth table (4.5600 … R -3.8176; 4.6154 … R -3.9278).
@pytest.mark.parametrize("key, gear, published, digits", CASES,
                         ids=[f"{k}-{g}" for k, g, _, _ in CASES])
def test_published_ratio_per_gear(key, gear, published, digits):
    ratio = build(key).ratio(gear)
    assert abs(ratio - published) <= 0.5 * 10 ** -digits + 1e-12


@pytest.mark.parametrize("key", list(FILES))
def test_toml_file_matches_library(key):
    """The example file is exactly what the library writes (data cannot drift)."""
    assert (EXAMPLES / FILES[key]).read_text() == to_toml(key)
    data = tomllib.loads((EXAMPLES / FILES[key]).read_text())
    assert [p["name"] for p in data["planetary"]] == [s.name for s in entry(key).sets]


@pytest.mark.parametrize("key", [k for k in FILES if k != "prius_psd"])
def test_file_loads_to_the_same_ratios(key):
    from_file = Transmission.from_file(EXAMPLES / FILES[key])
    built = build(key, 0.98)
    assert from_file.gears == built.gears
    for gear in built.gears:
        assert from_file.ratio(gear) == pytest.approx(built.ratio(gear), rel=1e-12)


def test_from_file_without_transmission_table():
    with pytest.raises(ModelError, match=r"no \[transmission\] table"):
        Transmission.from_file(EXAMPLES / FILES["prius_psd"])


# --- Toyota Prius (3rd gen.) power-split device --------------------------------------
# PriusChat post 1048061 (2010 Prius New Car Features): sun 30, pinion 23, ring 78; MG2
# reduction 22/18/58; counter 54/55; final 24/77; "Total Final Drive Ratio: 3.267:1".

def test_prius_is_two_degree_of_freedom():
    train = build_train("prius_psd")
    assert degrees_of_freedom(matrices(train, [])) == 2
    with pytest.raises(ModelError, match="no shift schedule"):
        build("prius_psd")


def test_prius_published_final_drive_ratio():
    train = build_train("prius_psd")
    sol = solve(train, OperatingPoint(speeds={"ring": 3267.0, "engine": 1000.0}), lossless=True)
    # (55/54)(77/24) = 3.26775: the post prints 3.267 (truncated; rounding gives 3.268)
    assert abs(sol.speed("ring") / sol.speed("wheels") - 3.267) < 1e-3


def test_prius_power_split_speeds():
    """Willis for the PSD: n_mg1 = n_engine (1 + 78/30) − n_ring (78/30)  (sun 30, ring 78)."""
    train = build_train("prius_psd")
    sol = solve(train, OperatingPoint(speeds={"engine": 2000.0, "wheels": 600.0}), lossless=True)
    ring = 600.0 * (55 / 54) * (77 / 24)
    assert sol.speed("ring") == pytest.approx(ring, rel=1e-12)
    assert sol.speed("mg1") == pytest.approx(2000.0 * 108 / 30 - ring * 78 / 30, rel=1e-12)
    # MG2 drives the ring through the reduction set with fixed carrier: n_mg2 = -(58/22) n_ring
    assert sol.speed("mg2") / sol.speed("ring") == pytest.approx(-58 / 22, rel=1e-12)
    # MG1 at rest: the engine drives the ring in overdrive 78/108 (= 1/1.3846)
    sol0 = solve(train, OperatingPoint(speeds={"engine": 1000.0, "mg1": 0.0}), lossless=True)
    assert sol0.speed("engine") / sol0.speed("ring") == pytest.approx(78 / 108, rel=1e-12)


def test_unknown_entry():
    with pytest.raises(ModelError, match="no entry 'zf_9hp'"):
        entry("zf_9hp")


def test_gm_8l_needs_gearsets_1_and_3_swapped():
    """Wikipedia: the GM 8L keeps the 8HP's gearset logic 'with gearsets 1 and 3 swapped'.  GM's
    S1/R1 41/79 in the 8HP's first place instead of its third gives 2.0575 in 3rd (published
    2.0751): the assignment of gm_8l90 is the only one of the two that reproduces the table."""
    from dataclasses import replace

    e = entry("gm_8l90")
    p1, p2, p3, p4 = e.sets
    unswapped = replace(e, sets=(replace(p1, z_sun=p3.z_sun, z_ring=p3.z_ring), p2,
                                 replace(p3, z_sun=p1.z_sun, z_ring=p1.z_ring), p4))
    train = GearTrain([s for s in build_train("gm_8l90").elements if not isinstance(s, PlanetarySet)]
                      + [PlanetarySet(s.name, s.sun, s.ring, s.carrier, float(s.stationary_ratio))
                         for s in unswapped.sets])
    ratio = Transmission(train, e.schedule, e.input, e.output).ratio("3")
    assert ratio == pytest.approx(2.0575, abs=5e-5)
    assert build("gm_8l90").ratio("3") == pytest.approx(2.0751, abs=5e-5)
