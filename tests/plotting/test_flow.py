"""Power-flow graph: arrow widths proportional to power, circulating power highlighted."""

import pytest

from epicyclic import GearStage, GearTrain, OperatingPoint, PlanetarySet, solve
from epicyclic.demo import PS
from epicyclic.plotting.flow import MAX_WIDTH, power_flow


def _bild11():
    """Brandenberger Bild 11: the set's systems I and III joined by a fixed stage, n1 = (e/f)(g/h)·n3."""
    train = GearTrain([
        PlanetarySet.stepped("planetary", sun="I", ring="II", carrier="III", z_sun=50, z_planet_sun=24,
                             z_planet_ring=30, z_ring=42, ring_internal=False, stationary_efficiency=0.9),
        GearStage.from_teeth("stage", "III", "I", [(40, 44, "external"), (20, 64, "external")], efficiency=0.9),
    ], name="Brandenberger Bild 11")
    # driven at I (driven at II it self-locks with η0 = 0.9)
    op = OperatingPoint(speeds={"I": 1500.0}, powers={"I": 3 * PS}, drives=["I"], loads=["II"])
    return solve(train, op)


@pytest.mark.parametrize("case", ["brandenberger", "simple", "simple_reversed"])
def test_widths_are_proportional_to_power(case, request):
    # One scale for every edge: width / power is the same (tolerance 1e-12 relative); the
    # largest edge has MAX_WIDTH points.
    flow = power_flow(request.getfixturevalue(case))
    ratios = [e.width / e.power for e in flow.edges]
    assert max(ratios) == pytest.approx(min(ratios), rel=1e-12)
    assert ratios[0] == pytest.approx(flow.width_per_watt, rel=1e-12)
    assert max(e.width for e in flow.edges) == pytest.approx(MAX_WIDTH, rel=1e-12)


def test_brandenberger_edges_are_the_solved_powers(brandenberger):
    flow = power_flow(brandenberger)
    drive = [e for e in flow.edges if e.kind == "drive"]
    load = [e for e in flow.edges if e.kind == "load"]
    # Paper: 3 PS in at II, 2.55 PS out at I (printed 3 digits)
    assert [e.target for e in drive] == ["II"] and drive[0].power / PS == pytest.approx(3.0, rel=1e-12)
    assert [e.source for e in load] == ["I"] and round(load[0].power / PS, 2) == 2.55
    losses = {e.source: e.power for e in flow.edges if e.kind == "loss"}
    assert losses == pytest.approx({n: brandenberger.elements[n].loss for n in ("planetary", "stage")}, rel=1e-12)
    assert flow.rolling["planetary"] == pytest.approx(brandenberger.elements["planetary"].rolling_power)
    # power balance at every shaft node: in = out (external edges included)
    for shaft in ("I", "II", "III"):
        inflow = sum(e.power for e in flow.edges if e.target == shaft)
        outflow = sum(e.power for e in flow.edges if e.source == shaft)
        assert inflow == pytest.approx(outflow, rel=1e-9)
    assert not any(e.circulating for e in flow.edges)  # Bild 10: no circulation


def test_circulating_power_is_highlighted_in_bild_11():
    # Brandenberger, text to Bild 11/12: in these arrangements power circulates in the coupling stage.
    # The red edges are exactly those of the loop around which it circulates (results.circulation).
    sol = _bild11()
    flow = power_flow(sol)
    assert sol.self_locking is None and sol.circulation.loops
    loop = sol.circulation.loops[0]
    circulating = [e for e in flow.edges if e.circulating]
    assert {(e.source, e.target) for e in circulating} == set(zip(loop.path, (*loop.path[1:], loop.path[0])))
    assert all(e.power >= loop.power * (1 - 1e-12) for e in circulating)  # the loop's bottleneck
    assert not any(e.circulating for e in flow.edges if e.kind != "port")
    assert max(e.power for e in flow.edges) / sol.input_power == pytest.approx(
        sol.circulation.largest_element_ratio, rel=1e-9)
    fig = flow.plot()
    assert "power circulates" in fig.axes[0].get_title()


def test_figure_and_data(brandenberger):
    flow = power_flow(brandenberger)
    fig = flow.plot()
    ax = fig.axes[0]
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    assert any("W per pt" in t for t in labels) and "W" in ax.get_title()
    data = flow.to_dict()
    assert data["units"]["power"] == "W" and len(data["edges"]) == len(flow.edges)
    assert "× input" in repr(flow)
