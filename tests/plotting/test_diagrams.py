"""Torque bars and power rectangles (Brandenberger 1952, Bild 5, 8, 9): areas checked numerically."""

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from epicyclic import GearTrain, OperatingPoint, PlanetarySet, solve
from epicyclic.demo import KP_CM
from epicyclic.plotting.diagrams import RPM_TO_RAD_S, power_diagram, torque_diagram

CASES = ["brandenberger", "simple", "simple_reversed"]


@pytest.mark.parametrize("case", CASES)
def test_loss_rectangle_area_equals_solver_loss(case, request):
    # Brandenberger Bild 8/9: the heavy rectangle is the loss.  Tolerance: 1e-9 relative.
    sol = request.getfixturevalue(case)
    diagram = power_diagram(sol)
    for element in diagram.actual:
        assert element.loss_rect is not None
        assert element.loss_rect.area == pytest.approx(sol.elements[element.element].loss, rel=1e-9)
        assert element.loss_rect.area == pytest.approx(element.loss, rel=1e-9)
    # total: the loss rectangles add up to input − output
    total = sum(e.loss_rect.area for e in diagram.actual)
    assert total == pytest.approx(sol.input_power - sol.output_power, rel=1e-9)


@pytest.mark.parametrize("case", CASES)
def test_port_rectangles_are_the_powers_and_balance(case, request):
    # Area of each port rectangle = |M·n|·π/30; drives − loads = loss (eq. 3 with friction).
    sol = request.getfixturevalue(case)
    for element in power_diagram(sol).actual:
        state = sol.elements[element.element]
        for rect, port in zip(element.rects, state.ports):
            assert rect.area == pytest.approx(abs(state.port_powers[port]), rel=1e-12, abs=1e-9)
            assert rect.height == pytest.approx(abs(state.torques[port]), rel=1e-12)
            assert rect.width == pytest.approx(state.speeds[port], rel=1e-12)
        assert element.drive_power - element.load_power == pytest.approx(element.loss, rel=1e-9)


def test_ideal_side_has_no_loss_rectangle(brandenberger):
    # Without friction (Bild 5): drive area equals load area, no loss.
    for element in power_diagram(brandenberger).ideal:
        assert element.loss_rect is None
        assert element.drive_power == pytest.approx(element.load_power, rel=1e-9)


def test_brandenberger_bild8_situation(brandenberger):
    # Text to Bild 10: system I drives relative to the carrier (eq. 7), so the case is Bild 8:
    # the ring (II) torque is reduced, the loss rectangle has width n2 − n3 = 1500 − 5280.
    planetary = power_diagram(brandenberger).actual[0]
    assert planetary.loss_direction == +1
    assert planetary.loss_rect.label.startswith("loss: ΔM_ring")
    assert planetary.loss_rect.width == pytest.approx(1500 - 5280, rel=1e-9)
    assert planetary.loss_rect.x0 == pytest.approx(5280, rel=1e-9)
    # Tabelle 2 signs: I delivers (load of the set), II and III feed in.
    roles = [r.role for r in planetary.rects]
    assert roles == ["load", "drive", "drive"]


def test_simple_reversed_is_bild9(simple_reversed):
    element = power_diagram(simple_reversed).actual[0]
    assert element.loss_direction == -1
    assert element.loss_rect.label.startswith("loss: ΔM_sun")


def test_loss_rectangle_does_not_move_with_the_speed_level():
    # Brandenberger: "Dieses Rechteck ist unabhängig von der jeweils gewählten Stelle A" — adding the
    # same speed to all three shafts changes neither width nor height (tolerance 1e-9 relative).
    pset = PlanetarySet("P", "I", "II", "III", 1.49, stationary_efficiency=0.9)
    train = GearTrain([pset])
    rects = []
    for shift in (0.0, -4000.0, 2500.0):
        op = OperatingPoint(speeds={"I": 1000.0 + shift, "III": shift}, torques={"I": 20.0},
                            connected=["I", "II", "III"])
        rect = power_diagram(solve(train, op)).actual[0].loss_rect
        rects.append((rect.width, rect.height, rect.area))
    for other in rects[1:]:
        assert other == pytest.approx(rects[0], rel=1e-9)


def test_torque_bars_match_solution_and_sum_to_zero(brandenberger):
    d = torque_diagram(brandenberger)
    assert d.groups == ("external", "planetary", "stage")
    # Brandenberger eq. (2): M1 + M2 + M3 = 0 on the set, with and without friction.
    for group in ("planetary", "stage"):
        bars = d.group(group)
        assert sum(b.actual for b in bars) == pytest.approx(0.0, abs=1e-12)
        assert sum(b.ideal for b in bars) == pytest.approx(0.0, abs=1e-12)
    external = {b.label: b for b in d.group("external")}
    # Paper: input torque M_An = 71620·3/1500 = 143.24 cm·kg at II (tolerance 0.005 cm·kg).
    assert external["II"].actual / KP_CM == pytest.approx(143.24, abs=0.005)
    assert external["II"].role == "drive" and external["I"].role == "load"
    assert external["I"].actual == brandenberger.torque("I")
    assert external["I"].ideal == brandenberger.ideal.torque("I")


def test_power_diagram_units_and_figure(brandenberger):
    diagram = power_diagram(brandenberger)
    data = diagram.to_dict()
    assert data["units"] == {"x": "1/min", "y": "N*m", "power": "W"}
    fig = diagram.plot()
    assert len(fig.axes) == 4  # two elements × (without, with friction)
    for ax in fig.axes:
        assert "1/min" in ax.get_xlabel() and "N·m" in ax.get_ylabel()
        assert ax.get_legend() is not None
    assert "without friction" in fig.axes[0].get_title() and "with friction" in fig.axes[1].get_title()
    assert "loss" in repr(diagram)


def test_torque_figure(brandenberger):
    fig = torque_diagram(brandenberger).plot()
    *panels, legend_ax = fig.axes
    assert all("N·m" in ax.get_ylabel() for ax in panels)
    labels = [t.get_text() for t in legend_ax.get_legend().get_texts()]
    assert labels == ["without friction (outline)", "load (power out)", "drive (power in)", "no power"]
    assert RPM_TO_RAD_S == pytest.approx(0.10471975511965977)


def test_report_svg_is_self_contained(brandenberger):
    # The HTML report forbids external or internal references (url(, href=, src=): hatching is drawn
    # as lines, markers are inlined, clip paths dropped.
    import re
    import xml.etree.ElementTree as ET

    from epicyclic.plotting import report_figures

    figures = report_figures(brandenberger)
    assert len(figures) == 6
    for title, svg in figures:
        assert svg.startswith("<svg"), title
        assert not re.search(r"<link|<script|\bsrc=|\bhref=|url\(|@import", svg), title
        ET.fromstring(svg)  # well-formed


@settings(max_examples=30, deadline=None)
@given(i0=st.floats(-6, 6).filter(lambda v: abs(v) > 0.05 and abs(v - 1) > 0.05), eta0=st.floats(0.5, 1.0),
       n_sun=st.floats(-4000, 4000).map(lambda v: 0.0 if abs(v) < 1e-6 else v),
       n_carrier=st.floats(-4000, 4000).map(lambda v: 0.0 if abs(v) < 1e-6 else v), torque=st.floats(1, 500))
def test_loss_rectangle_equals_loss_for_random_sets(i0, eta0, n_sun, n_carrier, torque):
    # Invariant: for any set, speeds and torque, the loss rectangle's area is the solver's loss. Speeds are 0
    # or at least 1e-6 1/min: at 1e-307 1/min the powers underflow and the solver refuses them with a
    # NonFiniteResultError by design (tests/solver/test_conditioning.py), no picture to compare.
    assume(abs(n_sun - n_carrier) > 1.0)
    train = GearTrain([PlanetarySet("P", "a", "b", "c", i0, stationary_efficiency=eta0)])
    op = OperatingPoint(speeds={"a": n_sun, "c": n_carrier}, torques={"a": torque}, connected=["a", "b", "c"])
    sol = solve(train, op)
    element = power_diagram(sol).actual[0]
    loss = sol.elements["P"].loss
    area = element.loss_rect.area if element.loss_rect is not None else 0.0
    assert area == pytest.approx(loss, rel=1e-9, abs=1e-9 * max(1.0, abs(sol.elements["P"].rolling_power)))


def test_every_picture_renders_itself_in_a_notebook(brandenberger):
    # _repr_html_ gives inline SVG (Jupyter shows it), with no url( or href references.
    from epicyclic import plotting

    objects = [plotting.speed_plan(brandenberger), plotting.range_diagram(brandenberger),
               plotting.torque_diagram(brandenberger), plotting.power_diagram(brandenberger),
               plotting.lever_diagram(brandenberger), plotting.power_flow(brandenberger),
               plotting.planetary_animation(brandenberger)]
    for obj in objects:
        html = obj._repr_html_()
        assert html.startswith("<svg") and "url(" not in html, type(obj).__name__
