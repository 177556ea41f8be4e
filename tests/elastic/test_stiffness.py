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


@pytest.mark.parametrize("eps", [1.2, 1.45, 1.6, 1.9])
def test_mesh_stiffness_over_the_cycle(eps):
    # ISO 6336-1, 9.3: c' single, c_γα = c'(0.75 ε_α + 0.25) mean; the wave's mean is c_γα b and its harmonics are
    # the Fourier lines of the sampled rectangular wave
    import numpy as np

    v = stiffness.mesh_stiffness_variation(14.0, eps, 25.0, harmonics=6)
    c_ga = stiffness.mesh_stiffness(14.0, eps, 500.0)[1]
    samples = 20000
    phase = (np.arange(samples) + 0.5) / samples
    wave = np.where((phase < (eps - 1) / 2) | (phase > 1 - (eps - 1) / 2), v["double"], v["single"])
    assert wave.mean() == pytest.approx(v["mean"], rel=1e-3)
    assert v["mean"] == pytest.approx(stiffness.lumped_mesh_stiffness(c_ga, 25.0), rel=1e-12)
    lines = 2 * np.abs(np.fft.rfft(wave)) / samples
    assert v["harmonics"] == pytest.approx(lines[1:7], rel=2e-3, abs=1e-4 * v["single"])
