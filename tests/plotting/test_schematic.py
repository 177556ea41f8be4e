"""Schematic sets for sets given by i0 alone: drawable, and their layout reproduces i0."""

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from epicyclic import Brake, GearTrain, OperatingPoint, PlanetarySet, solve
from epicyclic.plotting.animation import planetary_animation
from epicyclic.plotting.schematic import drawn_set, schematic_teeth
from epicyclic.plotting.speed_plan import set_layout


@pytest.mark.parametrize(("i0", "kind", "teeth"), [
    # the library's ratios have small exact tooth counts (Queitsch eq. 4: i0 = −z_ring/z_sun)
    (-96 / 48, "simple", (16, 8, 32)), (-111 / 69, "simple", (46, 14, 74)), (-85 / 23, "simple", (23, 31, 85)),
    (72 / 30, "double", (20, 8, 8, 48)), (-1.0, "stepped", (30, 10, 20, 60)),
])
def test_schematic_teeth_reproduce_i0_exactly(i0, kind, teeth):
    t, roles, exact = schematic_teeth(i0)
    assert exact and t.kind == kind and (t.sun, *t.planet, t.ring) == teeth
    assert t.stationary_ratio == pytest.approx(i0, rel=1e-12)


@settings(max_examples=60, deadline=None)
@given(i0=st.one_of(st.floats(-8.0, -0.125), st.floats(0.125, 8.0)).filter(lambda v: abs(v - 1) > 0.02),
       planets=st.integers(3, 5))
def test_schematic_layout_reproduces_any_i0_and_is_drawable(i0, planets):
    # With the carrier held, ω_sun/ω_ring from the layout's radii equals i0 (tolerance 1e-9), whether
    # or not small teeth give it exactly; neighbouring planets do not overlap.
    pset = PlanetarySet("P", "s", "r", "c", i0, planets=planets)
    layout = set_layout(pset)
    drawn = drawn_set(pset)
    assert layout.schematic and drawn.schematic
    if len(layout.bodies) == 1:
        body = layout.bodies[0]
        rs, rr = body.contacts["sun"], body.contacts["ring"]
        ratio = (rs / (rs - body.axis)) / (rr / (rr - body.axis))
        assert 1 / ratio == pytest.approx(i0, rel=1e-9)
        t = drawn.teeth
        big = max(abs(rs - body.axis), abs(rr - body.axis))  # the larger planet gear
        module = 2 * abs(rs - body.axis) / (t.planet[0])
        assert 2 * body.axis * math.sin(math.pi / planets) > 2 * big + module  # tips clear
    else:
        assert drawn.teeth.kind == "double" and drawn.exact


@pytest.mark.parametrize("i0", [-0.4, 72 / 30, 1.49])
def test_willis_phases_add_up_for_schematic_sets(i0):
    # tec-science, "Willis-Gleichung": the three superposed motions add up to the real one, also for
    # a swapped simple set (sun port drawn as the ring), a double planet and a stepped set.
    pset = PlanetarySet("P", "s", "r", "c", i0)
    sol = solve(GearTrain([pset, Brake("B", "r")]),
                OperatingPoint(speeds={"s": 1000.0}, torques={"s": 10.0}, drives=["s"], loads=["c"]))
    willis = planetary_animation(sol, willis=True, frames=48)
    real = planetary_animation(sol, frames=48)
    assert willis.angles(3 * willis.phase_frames) == pytest.approx(real.angles(willis.phase_frames), abs=1e-9)
    assert "schematic" in willis.schematic
