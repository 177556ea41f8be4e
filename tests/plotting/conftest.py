"""Plotting tests draw with the Agg backend (no display) and share a few solved trains."""

import matplotlib

matplotlib.use("Agg")

import pytest  # noqa: E402

from epicyclic import Brake, GearTrain, OperatingPoint, PlanetarySet, solve  # noqa: E402
from epicyclic.demo import brandenberger_1952  # noqa: E402


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    import matplotlib.pyplot as plt

    plt.close("all")


@pytest.fixture(scope="session")
def brandenberger():
    """Brandenberger 1952, Bild 10 example (3 PS at 1500 1/min into II)."""
    return solve(*brandenberger_1952())


def simple_train(eta0=0.98, **teeth):
    z = {"z_sun": 30, "z_planet": 24, "z_ring": 78, **teeth}
    return GearTrain([PlanetarySet.simple("P", sun="sun", ring="ring", carrier="carrier",
                                          stationary_efficiency=eta0, **z), Brake("B", "ring")], name="simple set")


@pytest.fixture(scope="session")
def simple():
    """Simple minus set 30/24/78, ring held, sun drives the carrier (reduction 3.6)."""
    op = OperatingPoint(speeds={"sun": 3600.0}, torques={"sun": 100.0}, drives=["sun"], loads=["carrier"])
    return solve(simple_train(), op)


@pytest.fixture(scope="session")
def simple_reversed():
    """The same set driven from the carrier (step-up): the sun is driven relative to the carrier (w = −1)."""
    op = OperatingPoint(speeds={"carrier": 1000.0}, torques={"carrier": 360.0}, drives=["carrier"], loads=["sun"])
    return solve(simple_train(), op)
