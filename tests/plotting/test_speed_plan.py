"""Speed plan (Kutzbach) and Brandenberger's range diagram: geometry checked numerically."""

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from epicyclic import Brake, GearTrain, OperatingPoint, PlanetarySet, solve
from epicyclic.plotting import PlottingError
from epicyclic.plotting.speed_plan import (
    RPM_TO_RAD_S,
    plot_speed_plan,
    range_diagram,
    set_layout,
    speed_plan,
)


def _three_shaft(pset, n_sun=1200.0, n_carrier=-300.0):
    """A lone set with two given speeds and a given sun torque (three-shaft operation)."""
    train = GearTrain([pset], name=pset.name)
    op = OperatingPoint(speeds={pset.sun: n_sun, pset.carrier: n_carrier}, torques={pset.sun: 50.0},
                        drives=[pset.sun], connected=[pset.ring, pset.carrier])
    return solve(train, op)


SETS = {
    "simple": PlanetarySet.simple("S", sun="s", ring="r", carrier="c", z_sun=30, z_planet=24, z_ring=78),
    "simple shifted": PlanetarySet.simple("S", sun="s", ring="r", carrier="c", z_sun=17, z_planet=31, z_ring=80),
    "stepped external": PlanetarySet.stepped("S", sun="s", ring="r", carrier="c", z_sun=50, z_planet_sun=24,
                                             z_planet_ring=30, z_ring=42, ring_internal=False),
    "stepped internal": PlanetarySet.stepped("S", sun="s", ring="r", carrier="c", z_sun=20, z_planet_sun=30,
                                             z_planet_ring=18, z_ring=86),
    "double planet": PlanetarySet.double_planet("S", sun="s", ring="r", carrier="c", z_sun=30, z_planet_sun=17,
                                                z_planet_ring=19, z_ring=90),
    "i0 -2.6": PlanetarySet("S", "s", "r", "c", -2.6),
    "i0 -1 (differential)": PlanetarySet("S", "s", "r", "c", -1.0),
    "i0 -0.4": PlanetarySet("S", "s", "r", "c", -0.4),
    "i0 +1.49": PlanetarySet("S", "s", "r", "c", 1.49),
    "i0 +0.3": PlanetarySet("S", "s", "r", "c", 0.3),
}


def _collinear(points, slope=None, scale=1.0):
    """Max distance of the points from the line through the first two (and its slope)."""
    (r0, v0), (r1, v1) = points[0], points[1]
    k = (v1 - v0) / (r1 - r0)
    dev = max(abs(v - (v0 + k * (r - r0))) for r, v in points)
    return dev / scale, k


@pytest.mark.parametrize("name", list(SETS))
def test_planet_points_are_collinear_with_the_planet_line(name):
    # Queitsch Bild 5: the velocity endpoints of the meshes and the carrier lie on one line, whose
    # slope is the planet's absolute angular speed.  Tolerance 1e-12 relative to the largest speed.
    pset = SETS[name]
    plan = speed_plan(_three_shaft(pset))
    for body in plan.layout.bodies:
        points = list(plan.planet_points(body).values())
        line = plan.planet_line(body)
        scale = max(abs(v) for _, v in points + list(line))
        dev, slope = _collinear(list(line) + points, scale=scale)
        assert dev < 1e-12
        factor = 1e-3 if plan.layout.radius_unit == "mm" else 1.0
        assert slope == pytest.approx(plan.planet_omegas[body.index] * factor, rel=1e-12)
        assert len(points) >= 2  # a mesh point and the axis at least


def test_made_up_layout_reproduces_i0():
    # With the carrier held, n_sun/n_ring = i0 follows from the mesh radii alone.
    for name, pset in SETS.items():
        lay = set_layout(pset)
        body = lay.bodies[0] if len(lay.bodies) == 1 else None
        if body is None or lay.from_teeth:
            continue
        (rs, _), (rr, _) = lay.central["sun"], lay.central["ring"]
        # planet relative speed from the sun mesh, then the ring: (ω_r·r_r)/(r_r − a) = (ω_s·r_s)/(r_s − a)
        ratio = (rs / (rs - body.axis)) / (rr / (rr - body.axis))  # ω_s/ω_r with carrier held
        assert 1 / ratio == pytest.approx(pset.stationary_ratio, rel=1e-12), name


def test_simple_set_radii_and_queitsch_eq7(simple):
    # Unit module: r = z/2 (Queitsch eq. 10: r4 = r2 + 2 r3; eq. 11: r5 = (r2 + r4)/2).
    plan = speed_plan(simple)
    assert plan.layout.central["sun"] == (15.0, False)
    assert plan.layout.central["ring"] == (39.0, True)
    body = plan.layout.bodies[0]
    assert body.axis == 27.0
    # Queitsch eq. 7: v51 − v41 = v21 − v51 (carrier speed at the axis is the mean of the mesh speeds).
    p = plan.planet_points(body)
    assert p["carrier"][1] == pytest.approx((p["sun"][1] + p["ring"][1]) / 2, rel=1e-12)
    # ring held: its mesh point has zero speed; sun: v = ω r = 3600·π/30·15 mm = 5.655 m/s.
    assert abs(p["ring"][1]) < 1e-12
    assert p["sun"][1] == pytest.approx(3600 * math.pi / 30 * 0.015, rel=1e-12)


def test_module_scales_radii_not_speeds_of_rotation(simple):
    a, b = speed_plan(simple), speed_plan(simple, module=2.5)
    assert b.layout.central["ring"][0] == pytest.approx(2.5 * a.layout.central["ring"][0])
    assert b.planet_omegas == a.planet_omegas


def test_brandenberger_range_7_and_ratio(brandenberger):
    # Brandenberger 1952, text to Bild 10: n3 > n2 > n1, "so dass … der Bereich 7 in Betracht
    # kommt", all three speeds negative in his sign convention; a/b·c/d = 1.49 (printed, 3 digits).
    d = range_diagram(brandenberger)
    assert d.operating_range == 7
    assert d.ports == ("sun", "ring", "carrier")  # II (ring) is the faster one with the carrier held
    assert all(v < 0 for v in d.speeds_at(d.x_operating))
    assert round(d.offsets[1] / d.offsets[0], 2) == 1.49
    # the three lines cut the operating vertical at the actual speeds (n1 = 2740, n2 = 1500, n3 = 5280)
    n = [-v for v in d.speeds_at(d.x_operating)]
    assert [round(v, -1) for v in n] == [2740, 1500, 5280]


def test_range_numbering_single_cases(brandenberger):
    # Cases 2, 4, 6: one shaft stands still (carrier, I, II for a plus set with n2' > n1' > 0).
    d = range_diagram(brandenberger)
    n1, n2, _ = d.offsets
    assert [d.range_of(x) for x in (1.0, 0.0, -n1 / 2, -n1, -(n1 + n2) / 2, -n2, -n2 - 1)] == [1, 2, 3, 4, 5, 6, 7]


@pytest.mark.parametrize(("held", "load", "expected"), [("III", "II", 2), ("I", "III", 4), ("II", "III", 6)])
def test_two_shaft_operation_lands_on_a_single_case(held, load, expected):
    # A plus set (i0 = 0.672, Brandenberger's example) with one shaft held sits on the single case
    # where that shaft's line crosses zero: carrier 2, I 4, II 6.
    pset = PlanetarySet("P", "I", "II", "III", 0.672)
    drive = "II" if held == "I" else "I"
    train = GearTrain([pset, Brake("B", held)])
    sol = solve(train, OperatingPoint(speeds={drive: 1000.0}, torques={drive: 10.0}, drives=[drive], loads=[load]))
    assert range_diagram(sol).operating_range == expected


def test_locked_set_has_no_range():
    pset = PlanetarySet.simple("P", sun="s", ring="r", carrier="c", z_sun=30, z_planet=24, z_ring=78)
    sol = _three_shaft(pset, n_sun=500.0, n_carrier=500.0)
    assert range_diagram(sol).operating_range is None


@settings(max_examples=25, deadline=None)
@given(zs=st.integers(12, 60), zp=st.integers(12, 60), n_s=st.floats(-5000, 5000), n_c=st.floats(-5000, 5000))
def test_collinearity_for_random_simple_sets(zs, zp, n_s, n_c):
    pset = PlanetarySet.simple("P", sun="s", ring="r", carrier="c", z_sun=zs, z_planet=zp, z_ring=zs + 2 * zp)
    plan = speed_plan(_three_shaft(pset, n_s, n_c))
    body = plan.layout.bodies[0]
    points = list(plan.planet_points(body).values())
    scale = max(1e-9, *(abs(v) for _, v in points))
    assert _collinear(points, scale=scale)[0] < 1e-9


def test_figure_has_labelled_axes_and_legend(brandenberger):
    fig = plot_speed_plan(brandenberger)
    kutzbach, ranges = fig.axes[:2]
    assert "radius" in kutzbach.get_ylabel() and "mm" in kutzbach.get_ylabel()
    assert "m/s" in kutzbach.get_xlabel()
    assert "1/min" in ranges.get_xlabel() and "1/min" in ranges.get_ylabel()
    assert kutzbach.get_legend() is not None and ranges.get_legend() is not None
    assert "range 7" in " ".join(t.get_text() for t in ranges.get_legend().get_texts())


def test_speed_plan_dict_and_repr(simple):
    plan = speed_plan(simple)
    data = plan.to_dict()
    assert data["radius_unit"] == "mm" and data["members"]["sun"]["shaft"] == "sun"
    assert "SpeedPlan 'P'" in repr(plan)
    assert plan.omegas["sun"] == pytest.approx(3600 * RPM_TO_RAD_S)


def test_errors(simple):
    with pytest.raises(PlottingError, match="no planetary set named 'X'; planetary sets are 'P'"):
        speed_plan(simple, "X")
    with pytest.raises(PlottingError, match="module must be a positive number of mm, got -1"):
        speed_plan(simple, module=-1)
    from epicyclic import GearStage

    stage_only = GearTrain([GearStage("G", "a", "b", -2.0)])
    sol = solve(stage_only, OperatingPoint(speeds={"a": 100.0}, torques={"a": 1.0}, drives=["a"], loads=["b"]))
    with pytest.raises(PlottingError, match="has no planetary set"):
        range_diagram(sol)
    with pytest.raises(PlottingError, match="has no planetary set"):
        plot_speed_plan(sol)


@pytest.mark.parametrize("case", ["brandenberger", "simple"])
def test_torques_are_distances_between_the_other_lines(case, request):
    # Brandenberger 1952, text to Bild 3/4: a torque equals (in size) the distance between the lines
    # of the two other systems.  Compared with the frictionless port torques; tolerance 1e-9.
    sol = request.getfixturevalue(case)
    d = range_diagram(sol)
    name = d.set_name
    torques = sol.ideal.elements[name].torques
    graphical = d.graphical_torques()
    scale = abs(torques[d.ports[0]]) / graphical[0]
    for port, g in zip(d.ports, graphical):
        assert abs(torques[port]) == pytest.approx(scale * g, rel=1e-9)


def test_a_file_with_geometry_draws_its_own_radii():
    """The speed plan of a file with a geometry table uses its operating pitch radii (ISO 21771 a_w, d_w),
    not a unit module: lecad's profile-shifted 21/43/108, m 1.75 (a_w = 56.8 mm, d_w1 = 2·56.8·21/64);
    the stepped example's two modules (a_w = 50 mm both, ring 91·2·50/70/2 = 65 mm)."""
    from pathlib import Path

    from epicyclic.io import load_train_file
    from epicyclic.plotting.subject import figure_subject

    examples = Path(__file__).resolve().parents[2] / "examples"
    simple = figure_subject(load_train_file(examples / "geometry_simple_set.toml"))
    plan = speed_plan(simple.solution, "P", context=simple.context)
    a_w = plan.layout.bodies[0].axis
    assert a_w == pytest.approx(56.8, abs=1e-4)
    assert plan.layout.central["sun"][0] == pytest.approx(a_w * 21 / 64, rel=1e-9)  # d_w1 = 2 a_w z1/(z1 + z2)
    assert plan.assumptions() == "the file's geometry: m_n 1.75 mm, profile-shifted" and plan.module == 1.75
    # the sun's peripheral speed v = ω r_w at 3000 1/min
    assert plan.member_points("sun")[1][1] == pytest.approx(3000 * math.pi / 30 * a_w * 21 / 64 / 1000, rel=1e-9)
    stepped = figure_subject(load_train_file(examples / "geometry_stepped_set.toml"))
    plan = speed_plan(stepped.solution, "S", context=stepped.context)
    assert plan.layout.bodies[0].axis == pytest.approx(50.0, abs=1e-9)
    assert plan.layout.central["sun"][0] == pytest.approx(20.0) and plan.layout.central["ring"][0] == pytest.approx(65.0)
    assert "ring mesh 1.429 mm" in plan.assumptions()
    # the lines still meet: the planet's line passes through its mesh points and the carrier at its axis
    body = plan.layout.bodies[0]
    (r0, v0), (r1, v1) = plan.planet_line(body)
    for r, v in plan.planet_points(body).values():
        assert v == pytest.approx(v0 + (v1 - v0) * (r - r0) / (r1 - r0), abs=1e-9)
    # without the file's geometry: the unit module, said so
    bare = speed_plan(stepped.solution, "S")
    assert "module 1 mm assumed" in bare.assumptions()
