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
    # largest edge has MAX_WIDTH (data units).
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


def test_power_around_a_closed_loop_is_marked_in_bild_11():
    # Brandenberger, text to Bild 11/12: power circulates through the coupling stage.  The edges of
    # the closed loop I → stage → III → planetary → I are marked, and only they; at shaft I the
    # input and the power coming back around the loop add up to what enters the stage.
    sol = _bild11()
    flow = power_flow(sol)
    assert sol.self_locking is None
    loop = {(e.source, e.target) for e in flow.edges if e.circulating}
    assert loop == {("I", "stage"), ("stage", "III"), ("III", "planetary"), ("planetary", "I")}
    power = {(e.source, e.target): e.power for e in flow.edges}
    assert power[("I", "stage")] == pytest.approx(sol.input_power + power[("planetary", "I")], rel=1e-9)
    assert power[("I", "stage")] / sol.input_power == pytest.approx(sol.circulation.largest_element_ratio, rel=1e-9)
    assert sol.circulation.power == pytest.approx(power[("planetary", "I")], rel=1e-9)  # what comes back
    assert flow.crossings == 0
    fig = flow.plot()
    assert "closed loop" in fig._suptitle.get_text()


def test_figure_and_data(brandenberger):
    flow = power_flow(brandenberger)
    fig = flow.plot()
    ax = fig.axes[0]
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    assert any("band width ∝ power" in t for t in labels) and "W" in fig._suptitle.get_text()
    data = flow.to_dict()
    assert data["units"]["power"] == "W" and len(data["edges"]) == len(flow.edges)
    assert "× input" in repr(flow)


def _fewest_crossings(layout):
    """The fewest crossings any order of the layers gives (every permutation of every layer).

    The crossings are a sum over adjacent layers, so the minimum over all orders is found exactly layer by
    layer (dynamic programming over each layer's permutations) instead of over their product, which grows
    as the product of the layers' factorials (the 8HP with spin losses in 6th gear: hours).
    """
    from itertools import permutations

    from epicyclic.plotting._layered import count_crossings

    best = {order: 0 for order in permutations(layout.layers[0])}
    for layer in layout.layers[1:]:
        best = {order: min(value + count_crossings(previous, order, layout.links) for previous, value in best.items())
                for order in permutations(layer)}
    return min(best.values())


def _gears():
    from pathlib import Path

    from epicyclic.io import load_train_file

    for path in sorted((Path(__file__).resolve().parents[2] / "examples").glob("*.toml")):
        spec = load_train_file(path)
        for gear in (list(spec.transmission.schedule) if spec.transmission else [None]):
            yield pytest.param(spec, gear, id=f"{path.stem}-{gear or 'as given'}")


@pytest.mark.parametrize(("spec", "gear"), list(_gears()))
def test_no_avoidable_crossing(spec, gear):
    # The layout's crossing count is the least any order of its layers gives (checked by trying every
    # order: the graphs are small), in every example and every gear of every transmission.
    from epicyclic.plotting import figure_subject
    from epicyclic.plotting._layered import layered_layout

    flow = power_flow(figure_subject(spec, gear).solution)
    kinds = {n.name: n.kind for n in flow.nodes}
    edges = [(e.source, e.target) for e in flow.edges if e.kind != "loss"]
    names = list(dict.fromkeys(n for e in edges for n in e))
    layout = layered_layout(names, edges, first=[n for n in names if kinds[n] == "source"],
                            last=[n for n in names if kinds[n] == "sink"])
    assert layout.crossings == flow.crossings
    assert flow.crossings == _fewest_crossings(layout)
