"""Public functions refuse NaN, infinity and overflow with the project's own error naming the argument (issue 30).

Before: ``ClutchDrag.torque(s, nan, 850)`` and ``steady_temperature`` with a NaN loss returned NaN;
``DragTorque('carrier', [0]*399 + [1]).loss(3000)`` returned inf and ``.loss(nan)`` NaN;
``max_planets(nan, 50)``, ``min_profile_shift(nan)`` and ``search_teeth(5, min_clearance=nan)`` returned;
``inv_inverse(-1)`` raised a bare ValueError; ``Housing`` refused emissivity 0 (convection only).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from epicyclic.errors import EpicyclicError
from epicyclic.geometry.errors import GeometryError
from epicyclic.geometry.fitting import max_planets
from epicyclic.geometry.involute import inv_inverse
from epicyclic.geometry.search import search_teeth
from epicyclic.geometry.undercut import min_profile_shift
from epicyclic.losses import LossModelError
from epicyclic.losses.clutch_drag import ClutchDrag
from epicyclic.losses.drag import DragTorque
from epicyclic.losses.thermal import Housing, steady_temperature

NAN = float("nan")
CLUTCH = ClutchDrag("K1", gaps=6, inner_radius=70.0, outer_radius=90.0, clearance=0.2, supply=2.0)


@pytest.mark.parametrize("call, error, names", [
    (lambda: CLUTCH.torque(1000.0, NAN, 850.0), LossModelError, "viscosity"),
    (lambda: CLUTCH.torque(NAN, 10.0, 850.0), LossModelError, "slip"),
    (lambda: CLUTCH.loss(1000.0, 10.0, -850.0), LossModelError, "density"),
    (lambda: DragTorque("carrier", [0.0] * 399 + [1.0]).loss(3000.0), LossModelError, "overflows"),
    (lambda: DragTorque("carrier", [0.05, 1e-4]).loss(NAN), LossModelError, "speed"),
    (lambda: DragTorque("carrier", [1e300]).loss(1e10), LossModelError, "overflows"),
    (lambda: max_planets(NAN, 50.0), GeometryError, "tip_diameter"),
    (lambda: max_planets(30.0, math.inf), GeometryError, "center_distance"),
    (lambda: max_planets(30.0, 50.0, NAN), GeometryError, "min_clearance"),
    (lambda: min_profile_shift(NAN), GeometryError, "teeth"),
    (lambda: min_profile_shift(12.5), GeometryError, "whole number"),
    (lambda: search_teeth(5.0, min_clearance=NAN), GeometryError, "min_clearance"),
    (lambda: inv_inverse(-1.0), GeometryError, "inv_inverse"),
    (lambda: steady_temperature(Housing(1.0), lambda t: np.full(np.shape(t), NAN), (2,)), LossModelError,
     "not finite"),
])
def test_public_functions_refuse_non_finite_input_naming_it(call, error, names):
    with pytest.raises(error, match=names) as caught:
        call()
    assert isinstance(caught.value, EpicyclicError)


def test_finite_inputs_still_give_the_published_values():
    # max_planets: Drivetrain Hub standard example (5 planets); min_profile_shift: machinecalcs.com (0.298)
    assert max_planets(104 / 3, 104 / 3) == 5
    assert round(min_profile_shift(12), 3) == 0.298
    assert round(min_profile_shift(12.0), 3) == 0.298  # a whole float counts as a tooth count


def test_clutch_drag_in_blocks_equals_one_evaluation():
    # 2^16-point blocks keep the mist's (points, nodes) temporaries small (10^7 slips peaked at 4.1 GB);
    # the blocks give the one-shot values to round-off (the film edge's Newton stop is per call).
    slip = np.linspace(0.0, 6000.0, 3 * (1 << 16) + 17)
    whole = CLUTCH.torque(slip, 10.0, 850.0)
    pieces = np.concatenate([CLUTCH.torque(slip[i:i + 5000], 10.0, 850.0) for i in range(0, slip.size, 5000)])
    assert whole.shape == slip.shape
    np.testing.assert_allclose(whole, pieces, rtol=1e-13, atol=0.0)


def test_a_housing_that_only_convects():
    # ε = 0: no radiation; h A Δϑ = P: 300 W on 1 m² at 10 W/(m² K) → Δϑ = 30 K exactly
    housing = Housing(1.0, ambient=20.0, heat_transfer=10.0, emissivity=0.0)
    t = steady_temperature(housing, lambda temperature: np.full(np.shape(temperature), 300.0), (2,))
    np.testing.assert_allclose(t, 50.0, atol=1e-6)
    with pytest.raises(LossModelError, match=r"\[0, 1\]"):
        Housing(1.0, emissivity=1.5)
