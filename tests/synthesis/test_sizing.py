"""Lewis pre-dimensioning of the sets: the formula against Shigley's worked example, the module chosen.

Budynas & Nisbett, *Shigley's Mechanical Engineering Design*, Example 14-1: a 16-tooth spur gear,
diametral pitch P = 8 teeth/in, face F = 1.5 in, Y = 0.296 (Table 14-2), allowable 10 kpsi (30 kpsi
yield over a design factor of 3), velocity factor K_v = 1.524 at 628 ft/min: W_t = F·Y·σ/(K_v·P) = 364 lbf.
"""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from epicyclic.synthesis.sizing import (MODULES, lewis_form_factor, lewis_stress, minimum_module, size_set)


def test_lewis_stress_reproduces_shigley_example_14_1():
    # in inch units the module is 1/P; σ = K_v · W_t / (F · m · Y)
    stress = 1.524 * lewis_stress(364.2, 1.5, 1 / 8, 0.296)
    assert stress == pytest.approx(10_000.0, rel=1e-3)
    assert lewis_form_factor(16) == 0.296


@pytest.mark.parametrize("teeth, y", [(12, 0.245), (17, 0.303), (20, 0.322), (50, 0.409), (400, 0.480), (1000, 0.480)])
def test_form_factor_table_rows(teeth, y):
    assert lewis_form_factor(teeth) == pytest.approx(y)


def test_form_factor_needs_twelve_teeth():
    with pytest.raises(ValueError, match="starts at 12 teeth"):
        lewis_form_factor(11)


@settings(max_examples=30, deadline=None)
@given(torque=st.floats(1.0, 5000.0), z_sun=st.integers(17, 80), z_planet=st.integers(17, 80),
       planets=st.integers(3, 6), stress=st.floats(100.0, 600.0), k=st.floats(6.0, 16.0))
def test_the_module_is_the_smallest_of_the_series_that_holds(torque, z_sun, z_planet, planets, stress, k):
    size = size_set(torque, z_sun, z_planet, planets, stress, k)
    assert size.stress <= stress * (1 + 1e-9) and size.face_width == pytest.approx(k * size.module)
    exact = minimum_module(torque, z_sun, z_planet, planets, stress, k)
    assert size.module >= exact * (1 - 1e-9)
    smaller = [m for m in MODULES if m < size.module]
    if smaller:  # one step down would be over the allowable stress
        assert smaller[-1] < exact * (1 + 1e-9)


def test_a_torque_past_the_series_is_an_error():
    with pytest.raises(ValueError, match="needs a module above 50 mm"):
        size_set(1e9, 17, 17, 3)


def test_hunting_teeth_asked_for_are_what_every_candidate_gets():
    """gcd(z_sun, z_planet) = gcd(z_planet, z_ring) = 1 on every simple set of every candidate."""
    from math import gcd

    from epicyclic.synthesis import SynthesisSpec, synthesize_spec

    spec = SynthesisSpec.create([2.46, 1.46, 1.0, -2.18], 2, {"brakes": 2, "clutches": 2, "engaged": 2},
                                {"tolerance": 0.01, "hunting": True})
    result = synthesize_spec(spec, workers=1, announce=False)
    assert len(result) > 0
    for cand in result.candidates:
        for t in cand.teeth:
            assert gcd(t.z_sun, t.z_planet) == 1 and gcd(t.z_planet, t.z_ring) == 1
        assert all(s is not None and s.module > 0 for s in cand.sizes)
