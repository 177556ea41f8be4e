"""Shared fixtures of the synthesis tests."""

from __future__ import annotations

import pytest


@pytest.fixture(scope="session")
def simpson_with_teeth():
    """The Simpson arrangement of the Ford C4 (``examples/simpson_c4_3speed.toml``) with tooth counts a
    synthesis chose for its ratios 2.46, 1.46, 1.00, R −2.18 (39/23/85 × 4 and 34/20/74 × 3; the published
    33/72 have no whole planet)."""
    from epicyclic import Brake, Clutch, GearTrain, PlanetarySet
    from epicyclic.transmission import Transmission

    train = GearTrain([
        PlanetarySet.simple("front", sun="sun", ring="front_ring", carrier="out", z_sun=39, z_planet=23, z_ring=85,
                            planets=4),
        PlanetarySet.simple("rear", sun="sun", ring="out", carrier="rear_carrier", z_sun=34, z_planet=20, z_ring=74,
                            planets=3),
        Clutch("forward", "in", "front_ring"), Clutch("high_reverse", "in", "sun"), Brake("intermediate", "sun"),
        Brake("low_reverse", "rear_carrier")])
    return Transmission(train, {"1": ["forward", "low_reverse"], "2": ["forward", "intermediate"],
                                "3": ["forward", "high_reverse"], "R": ["high_reverse", "low_reverse"]}, "in", "out")
