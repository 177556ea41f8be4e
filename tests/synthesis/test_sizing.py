"""ISO 6336 sizing of synthesised sets: the module is the smallest that holds in every gear.

Independent check: for each set, :func:`epicyclic.rating.smallest_module` run on its own in every
gear that loads the set (the full ISO 54 series from 0.5 mm, no resuming); the synthesis' module
must be the largest of those, and one module smaller must fail S_Hmin or S_Fmin in some gear
(ISO 6336-2:2019 eq. (4), ISO 6336-3:2019 eq. (5)).  The train: the Simpson arrangement of the
Ford C4 (``examples/simpson_c4_3speed.toml``) with tooth counts a synthesis chose for its ratios
(39/23/85 × 4 and 34/20/74 × 3; the published 33/72 have no whole planet).
"""

from __future__ import annotations

import pytest

from epicyclic.rating import RatingError, smallest_module
from epicyclic.rating.sizing import ISO_54_MODULES
from epicyclic.synthesis.sizing import RATING_DEFAULTS, rating_spec, size_sets


@pytest.fixture(scope="module")
def simpson(simpson_with_teeth):
    t = simpson_with_teeth
    analysis = t.analyze_all(input_torque=400.0)
    return t, {g.gear: g.drive for g in analysis.gears}


def test_rating_defaults_are_the_stated_ones():
    spec = rating_spec()
    assert spec.material.name == RATING_DEFAULTS["material"] == "18CrNiMo7-6"
    assert (spec.flank_roughness, spec.root_roughness, spec.viscosity_40) == (3.0, 10.0, 100.0)
    assert (spec.S_Hmin, spec.S_Fmin, spec.life, spec.application_factor) == (1.0, 1.4, 20000.0, 1.0)
    assert rating_spec({"S_Fmin": 2.0}).S_Fmin == 2.0


@pytest.mark.parametrize("ratio", [0.3, 0.6])
def test_module_is_the_largest_smallest_module_over_the_loaded_gears(simpson, ratio):
    t, solutions = simpson
    spec = rating_spec()
    names = [p.name for p in t.train.planetary_sets]
    sizes = size_sets(solutions, names, spec, ratio, 400.0)
    for name, size in zip(names, sizes):
        per_gear = {}
        for gear, sol in solutions.items():
            state = sol.elements[name]
            if abs(state.torques["sun"]) > 1e-6 and max(state.speeds.values()) - min(state.speeds.values()) > 1e-6:
                per_gear[gear] = smallest_module(sol, name, spec, face_width_ratio=ratio).module
        assert size.module == max(per_gear.values()) and per_gear[size.gear] == size.module
        assert size.face_width == pytest.approx(ratio * size.module * next(
            p.teeth.sun for p in t.train.planetary_sets if p.name == name))
        assert size.safety_pitting >= spec.S_Hmin and size.safety_bending >= spec.S_Fmin
        smaller = [m for m in ISO_54_MODULES if m < size.module][-1]
        with pytest.raises(RatingError):  # one module down fails in the gear that set it
            smallest_module(solutions[size.gear], name, spec, face_width_ratio=ratio, max_module=smaller)


def test_a_set_no_module_carries_is_an_error(simpson):
    t, _ = simpson
    huge = {g.gear: g.drive for g in t.analyze_all(input_torque=1e10).gears}  # N·m: past a 50 mm module
    with pytest.raises(RatingError, match="no module"):
        size_sets(huge, [t.train.planetary_sets[0].name], rating_spec(), 0.5, 1e10)


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
