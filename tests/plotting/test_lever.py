"""Lever diagrams: node heights reproduce i0 and the gear ratios; speeds lie on one line."""

import pytest

from epicyclic import Brake, Clutch, GearTrain, OperatingPoint, PlanetarySet, solve
from epicyclic.plotting import PlottingError
from epicyclic.plotting.lever import compound_lever, lever_diagram


def _simpson():
    """Simpson-type train: common sun S, front ring = input, front carrier = rear ring = output."""
    return GearTrain([
        PlanetarySet.simple("front", sun="S", ring="IN", carrier="OUT", z_sun=30, z_planet=24, z_ring=78),
        PlanetarySet.simple("rear", sun="S", ring="OUT", carrier="C2", z_sun=33, z_planet=21, z_ring=75),
        Brake("B1", "C2"), Brake("B2", "S"), Clutch("K", "IN", "S"),
    ], name="Simpson")


def _ratio(lever, a, b, c):
    return (lever.position(a) - lever.position(c)) / (lever.position(b) - lever.position(c))


def test_each_lever_reproduces_its_ratio(brandenberger):
    # Brandenberger 1952, Beispiel: a/b·c/d = 50/24·30/42, so i0 (I→II) = (24/50)(42/30) = 0.672;
    # fixed stage e/f·g/h = 40/44·20/64 = 0.284, so n_III/n_II = 3.52.  Tolerance 1e-12.
    d = lever_diagram(brandenberger)
    planetary, stage = d.levers
    assert _ratio(planetary, "sun", "ring", "carrier") == pytest.approx(0.672, rel=1e-12)
    assert _ratio(stage, "first", "second", "housing") == pytest.approx((44 / 40) * (64 / 20), rel=1e-12)
    # plus set: the carrier node lies outside sun–ring; minus set: between (Benford–Leising)
    assert planetary.position("carrier") in (0.0, 1.0)


def test_minus_set_node_spacing_is_tooth_counts(simple):
    # Benford–Leising: sun–carrier : carrier–ring = z_ring : z_sun = 78 : 30.
    lever = lever_diagram(simple).levers[0]
    sc = abs(lever.position("sun") - lever.position("carrier"))
    cr = abs(lever.position("carrier") - lever.position("ring"))
    assert sc / cr == pytest.approx(78 / 30, rel=1e-12)


def test_compound_lever_of_brandenberger_train(brandenberger):
    d = lever_diagram(brandenberger)
    c = d.compound
    assert set(c.positions) == {"I", "II", "III", "housing"}
    # every element's ratio holds on the compound heights too
    assert (c.positions["I"] - c.positions["III"]) / (c.positions["II"] - c.positions["III"]) == pytest.approx(0.672)
    # speeds: one straight line (tolerance 1e-9 of the largest speed) through n = 0 at the housing
    alpha, beta = c.speed_line()
    for shaft, y in c.positions.items():
        assert alpha + beta * y == pytest.approx(c.speeds[shaft], abs=1e-9 * 5280)
    # gear ratio n_II/n_I from the heights = 1500/2740 (paper: n1 = 2740 for n2 = 1500)
    h = c.positions["housing"]
    assert (c.positions["II"] - h) / (c.positions["I"] - h) == pytest.approx(1500 / brandenberger.speed("I"), rel=1e-9)


@pytest.mark.parametrize("engaged", [["B1"], ["B2"], ["K"]])
def test_shift_states_of_a_compound_train(engaged):
    train = _simpson().with_engaged(engaged)
    sol = solve(train, OperatingPoint(speeds={"IN": 1000.0}, torques={"IN": 100.0}, drives=["IN"], loads=["OUT"]))
    d = lever_diagram(sol)
    c = d.compound
    assert c is not None
    alpha, beta = c.speed_line()
    for shaft, y in c.positions.items():
        assert alpha + beta * y == pytest.approx(c.speeds[shaft], abs=1e-9 * 1000)
    # the gear ratio of the shift state read from the lever: rotate about the held node
    if engaged == ["K"]:
        # direct drive: the whole lever turns as one, the speed line is vertical (β = 0)
        assert sol.ratio == pytest.approx(1.0, rel=1e-12)
        assert beta == pytest.approx(0.0, abs=1e-9 * 1000)
    else:
        held = "C2" if engaged == ["B1"] else "S"
        assert c.positions[held] == pytest.approx(c.positions["housing"], abs=1e-12)
        ratio = (c.positions["IN"] - c.positions[held]) / (c.positions["OUT"] - c.positions[held])
        assert ratio == pytest.approx(sol.ratio, rel=1e-9)


def test_free_compound_train_combines_and_shows_links():
    # With every shift element open the two sets still form one 4-node lever (2 DOF).
    d = lever_diagram(train=_simpson().with_engaged([]))
    assert d.compound is not None and set(d.compound.positions) == {"S", "IN", "OUT", "C2"}
    assert ("S", 0, 1) in d.links and ("OUT", 0, 1) in d.links
    for lever in d.levers:
        a, b, c = (n.shaft for n in lever.nodes)
        p = d.compound.positions
        i0 = next(e.stationary_ratio for e in _simpson().elements if getattr(e, "name", "") == lever.element)
        assert (p[a] - p[c]) / (p[b] - p[c]) == pytest.approx(i0, rel=1e-12)


def test_three_free_speeds_give_no_compound_lever():
    # Two sets joined only through an open clutch: two levers, no common one.
    train = GearTrain([
        PlanetarySet("P1", "a", "b", "c", -2.0), PlanetarySet("P2", "d", "e", "f", -3.0), Clutch("K", "c", "d"),
    ])
    assert compound_lever(train) is None
    d = lever_diagram(train=train)
    assert [c.elements for c in d.free] == [("P1",), ("P2",)] and d.speed_levers == d.free
    fig = d.plot()
    assert len(fig.axes) == 1  # no speeds without a solution: the levers only


def test_figure_and_data(brandenberger):
    d = lever_diagram(brandenberger)
    fig = d.plot()
    left, right = fig.axes
    assert "1/min" in right.get_xlabel() and left.get_ylabel()
    labels = " ".join(t.get_text() for t in right.texts)
    assert "II (input): 1500 1/min" in labels and "I (output)" in labels
    assert d.to_dict()["compound"]["speeds"]["II"] == 1500.0
    assert "compound lever" in repr(d)


def test_errors():
    with pytest.raises(PlottingError, match="give a solution"):
        lever_diagram()


EXAMPLES = __import__("pathlib").Path(__file__).resolve().parents[2] / "examples"


@pytest.mark.parametrize(("example", "gear", "published"), [
    # Ford C4 (Simpson): "Ratios are 2.46 low, 1.46 second and direct high", reverse 2.18 (sources in the file).
    ("simpson_c4_3speed", "1", 2.46), ("simpson_c4_3speed", "2", 1.46), ("simpson_c4_3speed", "R", -2.18),
    # Ford AOD (Ravigneaux): ATRA TSB 89-30: 2.40, 1.47, 1.00, 0.67, R −2.00.
    ("ravigneaux_ford_aod_4speed", "1", 2.40), ("ravigneaux_ford_aod_4speed", "2", 1.47),
    ("ravigneaux_ford_aod_4speed", "4", 0.67), ("ravigneaux_ford_aod_4speed", "R", -2.00),
])
def test_gear_ratio_read_from_the_compound_lever(example, gear, published):
    # Rotate the compound lever about the held (housing) node: n_in/n_out = (Y_in − Y_h)/(Y_out − Y_h).
    # The published ratios are printed to 2 digits: tolerance 0.005.
    from epicyclic.io import load_train_file

    spec = load_train_file(EXAMPLES / f"{example}.toml")
    tr = spec.transmission
    lever = compound_lever(tr.train_in_gear(spec.train, gear))
    p = lever.positions
    ratio = (p[tr.input] - p["housing"]) / (p[tr.output] - p["housing"])
    assert ratio == pytest.approx(published, abs=0.005)
