"""Lever diagrams: node heights reproduce i0 and the gear ratios; speeds lie on one line."""

from pathlib import Path

import pytest

from epicyclic import Brake, Clutch, GearTrain, OperatingPoint, PlanetarySet, solve
from epicyclic.plotting import PlottingError
from epicyclic.plotting.lever import compound_lever, free_levers, lever_diagram


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


# --- published levers -------------------------------------------------------------------------
# Benford & Leising 1981 (SAE 810102) build a gearset's lever from its tooth counts: a simple set is a
# lever sun–carrier–ring with sun–carrier : carrier–ring = z_ring : z_sun; a dual-pinion set has the ring
# between carrier and sun with carrier–ring : ring–sun = z_sun : (z_ring − z_sun); sets sharing two
# members combine into one lever.  The heights below are that construction by hand; the code finds
# them from the null space of the Willis equations.  Tolerance 1e-12 (both exact for these teeth).

def _relative(positions, zero, one):
    """Heights as fractions of the distance from node ``zero`` to node ``one`` (orientation-free)."""
    span = positions[one] - positions[zero]
    return {s: (y - positions[zero]) / span for s, y in positions.items()}


def test_simpson_ford_c4_lever_is_benford_leising():
    # Ford C4: sun 33, ring 72 in both sets (sources in examples/simpson_c4_3speed.toml).  Front set on
    # its own: sun 0, front carrier (output) at z_r = 72, front ring at z_r + z_s = 105.  Rear set scaled
    # to share sun and output: rear carrier at 72·72/105, output (its ring) at 72.
    from epicyclic.io import load_train_file

    train = load_train_file(EXAMPLES / "simpson_c4_3speed.toml").train
    (lever,) = lever_diagram(train=train).free
    got = _relative(lever.positions, "sun", "front_ring")
    expected = {"sun": 0.0, "rear_carrier": 72 * 72 / 105 / 105, "out": 72 / 105, "front_ring": 1.0}
    assert got == pytest.approx(expected, abs=1e-12)
    # and the published ratios follow by turning it about the held node: 1st (rear carrier held) 2.46,
    # 2nd (sun held) 1.46, reverse (input at the sun, rear carrier held) −2.18 (C4 sources in the file)
    h = got["rear_carrier"]
    assert (1 - h) / (got["out"] - h) == pytest.approx(2.46, abs=0.005)
    assert 1 / got["out"] == pytest.approx(1.46, abs=0.005)
    assert (0 - h) / (got["out"] - h) == pytest.approx(-2.18, abs=0.005)


def test_ravigneaux_ford_aod_lever_is_benford_leising():
    # Ford AOD: forward sun 30 (dual pinion), reverse sun 36 (long pinion only), ring 72 (ATRA TSB 89-30).
    # Reverse set: reverse sun 0, carrier 72, ring 108.  Dual-pinion set: carrier–ring : ring–forward sun
    # = 30 : 42, scaled to carrier–ring = 36: forward sun at 108 + 50.4 = 158.4.
    from epicyclic.io import load_train_file

    train = load_train_file(EXAMPLES / "ravigneaux_ford_aod_4speed.toml").train
    (lever,) = lever_diagram(train=train).free
    got = _relative(lever.positions, "reverse_sun", "forward_sun")
    expected = {"reverse_sun": 0.0, "carrier": 72 / 158.4, "ring": 108 / 158.4, "forward_sun": 1.0}
    assert got == pytest.approx(expected, abs=1e-12)
    # ATRA TSB 89-30: 1st = z_ring/z_forward_sun = 2.4 (carrier held, forward sun in, ring out)
    c = got["carrier"]
    assert (1 - c) / (got["ring"] - c) == pytest.approx(72 / 30, rel=1e-12)


def test_prius_gen2_lever_gives_the_published_speed_relation():
    # Toyota Prius Gen 2 (NHW20): power-split set sun 30 (MG1), carrier (engine), ring 78 on MG2.
    # Published: "MG1 = 3.6 x ICE - 2.6 x MG2" (G. Davies, prius.ecrostech.com; quoted at
    # cap-lore.com/Hardware/Prius.html).  On the lever every speed is n = α + β·Y, so
    # n_MG1 = a·n_engine + (1 − a)·n_MG2 with a = (Y_MG1 − Y_MG2)/(Y_engine − Y_MG2).
    psd = PlanetarySet.simple("PSD", sun="mg1", ring="mg2", carrier="engine", z_sun=30, z_planet=23, z_ring=78)
    (lever,) = free_levers(GearTrain([psd]))
    y = lever.positions
    a = (y["mg1"] - y["mg2"]) / (y["engine"] - y["mg2"])
    assert (a, 1 - a) == pytest.approx((3.6, -2.6), abs=1e-12)
    # the same relation in a solved state: engine 2000, MG2 3000 → MG1 = 7200 − 7800 = −600 1/min
    sol = solve(GearTrain([psd]), OperatingPoint(speeds={"engine": 2000.0, "mg2": 3000.0}, torques={"engine": 100.0},
                                                 drives=["engine"], connected=["mg1", "mg2"]))
    assert sol.speed("mg1") == pytest.approx(-600.0, abs=1e-9)


@pytest.mark.parametrize(("example", "levers"), [
    # free state: the sets merge where they share two members, and only there
    ("simpson_c4_3speed", [("front", "rear")]),
    ("ravigneaux_ford_aod_4speed", [("Pfwd", "Prev")]),
    ("lepelletier_zf_6hp26_6speed", [("P1",), ("P2", "P3")]),
    ("zf_8hp70_8speed", [("P1",), ("P2",), ("P3",), ("P4",)]),
    ("toyota_prius_power_split", [("PSD",), ("MSR", "counter", "final")]),
    ("brandenberger_1952", [("planetary", "stage")]),
])
def test_free_state_levers_from_the_kinematics(example, levers):
    from epicyclic.io import load_train_file

    train = load_train_file(EXAMPLES / f"{example}.toml").train
    assert [c.elements for c in free_levers(train)] == levers


@pytest.mark.parametrize("gear", ["1", "2", "3", "4", "5", "6", "7", "8", "R"])
def test_8hp_reduced_lever_in_every_gear(gear):
    # ZF 8HP 70: the free state has four levers, but every gear (three shift elements engaged) has one
    # reduced lever holding every shaft; the ratio read from it is the published one (4 decimals).
    from epicyclic.transmission.library import build, entry

    t = build("zf_8hp70")
    lever = compound_lever(t.gear_train(gear))
    if gear == "6":  # direct drive, no brake: the whole train turns as one block, the lever shrinks to a point
        assert lever is None and list(t.speeds(gear).values()) == pytest.approx([1.0] * (len(t.train.shafts) - 1) + [0.0])
        return
    assert lever is not None and set(lever.positions) == set(t.train.shafts)
    p = lever.positions
    ratio = (p["in"] - p["housing"]) / (p["out"] - p["housing"])
    assert ratio == pytest.approx(entry("zf_8hp70").published_ratios[gear], abs=5e-5)


@pytest.mark.parametrize("gear", ["1", "3", "R"])
def test_lever_names_stand_clear_of_the_nodes_and_inside_the_frame(gear):
    """Each lever's name (``P1: i0 -2``) is drawn under its lever inside the axes, not over a node marker
    or across the frame."""
    import matplotlib.pyplot as plt

    from epicyclic.transmission.library import build

    t = build("zf_8hp70")
    fig = lever_diagram(train=t.gear_train(gear), transmission=t, gear=gear).plot()
    try:
        fig.canvas.draw()
        renderer = fig.canvas.get_renderer()
        ax = fig.axes[0]
        frame = ax.get_window_extent(renderer)
        names = [text for text in ax.texts if ": i0 " in text.get_text()]
        assert len(names) == 4
        markers = [line for line in ax.lines if line.get_marker() == "o"]
        for text in names:
            box = text.get_window_extent(renderer)
            assert frame.y0 <= box.y0 and box.y1 <= frame.y1, f"{text.get_text()!r} crosses the frame"
            for line in markers:
                for x, y in ax.transData.transform(line.get_xydata()):
                    radius = line.get_markersize() / 2 * fig.dpi / 72
                    inside_x = box.x0 - radius < x < box.x1 + radius
                    inside_y = box.y0 - radius < y < box.y1 + radius
                    assert not (inside_x and inside_y), f"{text.get_text()!r} covers a node marker"
    finally:
        plt.close(fig)


def test_a_mesh_below_its_minimum_safety_is_drawn_red():
    """ISO 6336 (docs/rating.md): at 3000 N·m the rating example's meshes fall below S_Hmin/S_Fmin, and the
    lever diagram draws the set red and says which mesh and safety; at the file's 600 N·m it is drawn black."""
    import matplotlib.pyplot as plt
    from matplotlib.colors import to_hex

    from epicyclic.io import load_train_file
    from epicyclic.plotting import figure_subject
    from epicyclic.plotting._lever_draw import UNSAFE
    from epicyclic.rating.train import rate_solution

    path = Path(__file__).resolve().parents[2] / "examples" / "rating" / "simple_set.toml"
    for torque, red in (("600 N*m", False), ("3000 N*m", True)):
        f = load_train_file(path, overrides=[f'operating_point.torques.in="{torque}"'])
        subject = figure_subject(f)
        rating = rate_solution(subject.solution, f.geometry, f.rating)
        assert (not rating.ok) == red and bool(subject.context.warnings) == red
        fig = lever_diagram(subject.solution, context=subject.context).plot()
        try:
            ax = fig.axes[0]
            lever = max(ax.lines, key=lambda line: line.get_linewidth())  # the set's lever, 3.5 pt
            assert (to_hex(lever.get_color()) == UNSAFE.lower()) == red
            names = [t for t in ax.texts if t.get_text().startswith("P: i0")]
            assert len(names) == 1 and ("below minimum safety" in names[0].get_text()) == red
            if red:
                s_f = min(float(g.S_F) for m in rating.meshes if m.mesh == "sun-planet" for g in m.gears)
                assert f"S_F {s_f:.3f} < 1.4" in names[0].get_text()  # the mesh's lowest root safety, printed
                assert subject.context.warnings["P"] == rating.below_minimum()["P"]
        finally:
            plt.close(fig)
