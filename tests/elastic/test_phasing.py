"""Mesh phasing against a direct computation of the summed mesh forces (Parker & Lin 2004).

The direct computation knows nothing of the phase formula: the mesh state at planet n is the
position of the nearest sun tooth relative to the planet's direction, (θ − ψ_n) modulo the
tooth pitch 2π/z_s, put into a random periodic mesh-force waveform; the net torque and the net
force (along the lines of action, turning with ψ_n) are summed over the planets and
Fourier-analysed over one revolution of the sun relative to the carrier.
"""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from elastic_cases import lin_parker_1999
from epicyclic.elastic import ElasticError, equally_spaced, natural_modes
from epicyclic.elastic.phasing import mesh_phasing

ALPHA = math.radians(22.0)


def _summed_forces(z_s, angles, harmonics, phases, samples):
    theta = 2 * np.pi * np.arange(samples) / samples
    pitch = 2 * np.pi / z_s
    torque = np.zeros(samples)
    force = np.zeros(samples, complex)
    for psi in angles:
        state = np.mod(theta - psi, pitch) / pitch * 2 * np.pi       # nearest tooth relative to the planet
        f = sum(np.cos(l_ * state + phases[l_ - 1]) for l_ in range(1, harmonics + 1))
        torque += f
        force += f * np.exp(1j * (psi - ALPHA + np.pi / 2))              # along the line of action
    return np.fft.fft(torque) / samples, np.fft.fft(force) / samples


@settings(max_examples=40, deadline=None)
@given(z_s=st.integers(9, 60), planets=st.integers(3, 8), equal=st.booleans(),
       jitter=st.lists(st.floats(-0.4, 0.4), min_size=8, max_size=8), seed=st.integers(0, 2**16))
def test_weights_are_the_fourier_lines_of_the_summed_forces(z_s, planets, equal, jitter, seed):
    angles = list(equally_spaced(planets))
    if not equal:
        angles = [a + (j if i else 0.0) for i, (a, j) in enumerate(zip(angles, jitter))]
    harmonics = 4
    phases = np.random.default_rng(seed).uniform(0, 2 * np.pi, harmonics)
    samples = 8 * z_s * harmonics
    torque, force = _summed_forces(z_s, angles, harmonics, phases, samples)
    phasing = mesh_phasing(z_s, 3 * z_s, angles)
    for l_ in range(1, harmonics + 1):
        h = l_ * z_s
        w = phasing.weights(l_)
        scale = planets / 2
        assert abs(torque[h]) / scale == pytest.approx(w["rotational"], abs=1e-9)
        assert abs(force[h]) / scale == pytest.approx(w["translational+"], abs=1e-9)
        assert abs(force[-h]) / scale == pytest.approx(w["translational-"], abs=1e-9)


@settings(max_examples=60, deadline=None)
@given(z_s=st.integers(9, 80), planets=st.integers(3, 9), l_=st.integers(1, 6))
def test_equally_spaced_rules(z_s, planets, l_):
    # Parker & Lin 2004, Table 1: l z_s/N integer -> rotational; (l z_s ± 1)/N integer -> translational;
    # otherwise planet modes.
    rule = []
    if (l_ * z_s) % planets == 0:
        rule.append("rotational")
    if (l_ * z_s + 1) % planets == 0 or (l_ * z_s - 1) % planets == 0:
        rule.append("translational")
    if not rule:
        rule.append("planet")
    z_r = z_s + 40 + (-(2 * z_s + 40) % planets)  # assembles: (z_s + z_r)/N integer
    assert mesh_phasing(z_s, z_r, equally_spaced(planets)).excited(l_) == tuple(rule)


@pytest.mark.parametrize("planets", [3, 4, 5, 6])
@pytest.mark.parametrize("z_s", [17, 20, 23, 30, 31])
def test_modal_forces_of_the_lumped_model_follow_the_rules(planets, z_s):
    # The harmonic mesh forces of sun and ring meshes (ring phases e^{i l z_r psi_n} with an assembling
    # z_r, (z_s + z_r)/N integer) projected on the modes of the Lin & Parker 1999 model.
    z_r = z_s + 2 * 20 + (-(2 * z_s + 40) % planets)
    assert (z_s + z_r) % planets == 0
    model = lin_parker_1999(planets)
    modes = natural_modes(model)
    names, _, v = model.springs()
    psi = np.asarray(model.planet_angles)
    sun = np.array([i for i, n in enumerate(names) if n.startswith("sun-planet")])
    ring = np.array([i for i, n in enumerate(names) if n.startswith("ring-planet")])
    phasing = mesh_phasing(z_s, z_r, model.planet_angles)
    for l_ in range(1, 5):
        c_sun = np.exp(-1j * l_ * z_s * psi)
        c_ring = 0.7 * np.exp(0.3j) * np.exp(1j * l_ * z_r * psi)
        generalised = v[sun].T @ c_sun + v[ring].T @ c_ring          # force vector in the coordinates
        modal = np.abs(modes.shapes.T @ generalised)
        excited = set(phasing.excited(l_))
        for kind in ("rotational", "translational", "planet"):
            idx = [i for i, k in enumerate(modes.kinds) if k == kind and modes.frequencies[i] > 0]
            if not idx:
                continue
            size = float(np.max(modal[idx]))
            if kind in excited:
                assert size > 1e-3
            else:
                assert size < 1e-9


def test_renders_and_bad_input():
    p = mesh_phasing(31, 69, equally_spaced(5))
    assert "translational" in p.table() and "| harmonic |" in p.markdown() and "<table>" in p._repr_html_()
    assert p.to_dict()["harmonics"][0]["excites"] == ["translational"]
    assert p.sun_phases[1] == pytest.approx((31 / 5) % 1)
    with pytest.raises(ElasticError, match="sun_teeth"):
        mesh_phasing(0, 69, equally_spaced(5))
    with pytest.raises(ElasticError, match="harmonic"):
        p.weights(0)
