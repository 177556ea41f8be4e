"""The mesh stiffness of ISO 6336-1, 9.3 lives in epicyclic.elastic.stiffness; the rating takes it from there."""

import pytest

from epicyclic.elastic import stiffness
from epicyclic.rating import load_factors


def test_one_path():
    assert load_factors.single_stiffness is stiffness.single_stiffness
    assert load_factors.mesh_stiffness is stiffness.mesh_stiffness


def test_lumped_mesh_stiffness_from_c_gamma_alpha():
    # ISO 6336-1, 9.3.2: c_γα = c' (0.75 ε_α + 0.25); k = c_γα b (N/(mm µm) · mm = N/µm = 1e6 N/m)
    c, c_ga, _ = stiffness.mesh_stiffness(14.0, 1.6, 500.0)
    assert c_ga == pytest.approx(14.0 * 1.45)
    assert stiffness.lumped_mesh_stiffness(c_ga, 30.0) == pytest.approx(14.0 * 1.45 * 30.0 * 1e6)
