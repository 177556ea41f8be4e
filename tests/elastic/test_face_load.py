"""Face load distribution: the slice model against ISO 6336-1 method C and an independent 1-D solve.

ISO 6336-1:2006, 7.6, eqs. (41)–(42) are the rigid linear spring bed: K_Hβ = 1 + F_βx c_γβ/(2 F_m/b)
while the whole face carries, √(2 F_βx c_γβ/(F_m/b)) otherwise (the peak at the face end; the slices
sample the centres of their strips, so the end value is approached as S grows).
"""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.optimize import brentq

from epicyclic.elastic import ElasticError
from epicyclic.elastic.face_load import HelixModification, best_crowning, face_load


def test_aligned_unmodified_rigid_mesh_is_uniform():
    load = face_load(8000.0, 40.0, 14.0)
    assert load.k_hbeta == 1.0 and load.k_fbeta == 1.0
    assert np.all(load.line_load == load.line_load[0])
    assert load.line_load.sum() * 40.0 / 40 == pytest.approx(8000.0)


@pytest.mark.parametrize("misalignment, expected", [
    (10.0, 1 + 10.0 * 15.0 / (2 * 200.0)),          # whole face carries: eq. (41)
    (60.0, (2 * 60.0 * 15.0 / 200.0) ** 0.5),       # part of the face: eq. (42)
])
def test_iso_6336_method_c(misalignment, expected):
    load = face_load(10000.0, 50.0, 15.0, misalignment=misalignment, slices=400)
    assert load.k_hbeta == pytest.approx(expected, rel=5e-3)


@settings(max_examples=30, deadline=None)
@given(fx=st.floats(0.0, 80.0), crown=st.floats(0.0, 30.0), force=st.floats(500.0, 50000.0),
       slices=st.integers(4, 60))
def test_rigid_body_equals_a_one_dimensional_solve(fx, crown, force, slices):
    # rigid bodies: the slices that carry are those whose gap is below the approach δ, F_i = k (δ − g_i);
    # δ from Σ F_i = F by a bracketing root finder (independent of the active-set method)
    b, c = 50.0, 15.0
    load = face_load(force, b, c, misalignment=fx, modification=HelixModification(crowning=crown), slices=slices)
    y = (np.arange(slices) + 0.5) * b / slices
    s = y / b - 0.5
    g = fx * s + 4 * crown * s * s
    g = g - g.min()
    k = c * b / slices
    delta = brentq(lambda d: np.sum(k * np.maximum(d - g, 0.0)) - force, 0.0, force / k + g.max() + 1.0,
                   xtol=1e-14, rtol=1e-14)
    assert load.line_load * b / slices == pytest.approx(k * np.maximum(delta - g, 0.0), rel=1e-9, abs=1e-9)
    assert load.line_load.sum() * b / slices == pytest.approx(force, rel=1e-12)
    assert load.k_hbeta >= 1.0


def test_crowning_lowers_the_peak_of_a_misaligned_mesh():
    plain = face_load(10000.0, 50.0, 15.0, misalignment=30.0)
    crowned = face_load(10000.0, 50.0, 15.0, misalignment=30.0, modification=HelixModification(crowning=10.0))
    assert crowned.line_load.max() < plain.line_load.max()
    cb, best = best_crowning(10000.0, 50.0, 15.0, 30.0)
    assert best.k_hbeta <= crowned.k_hbeta and 0.0 < cb < 50.0
    cb_target, hit = best_crowning(10000.0, 50.0, 15.0, 30.0, target=1.9)
    assert hit.k_hbeta <= 1.9 and cb_target <= cb


def test_slope_correction_and_end_relief():
    corrected = face_load(10000.0, 50.0, 15.0, misalignment=25.0,
                          modification=HelixModification(slope_correction=25.0))
    assert corrected.k_hbeta == 1.0                     # the correction takes the misalignment back
    relieved = face_load(10000.0, 50.0, 15.0, modification=HelixModification(end_relief=5.0,
                                                                              end_relief_length=5.0))
    assert relieved.line_load[0] < relieved.line_load[20]


def test_torsion_loads_the_input_end():
    load = face_load(10000.0, 50.0, 15.0, torsion=(40.0, 18.0, 80000.0), tooth_height=4.5)
    assert np.argmax(load.line_load) == 0 and load.k_hbeta > 1.0
    assert 1.0 < load.k_fbeta < load.k_hbeta           # K_Fβ = K_Hβ^N_F, N_F < 1
    assert load.line_load.sum() * 50.0 / 40 == pytest.approx(10000.0)
    assert "K_Hbeta" in load.table() and load.to_dict()["k_hbeta"] == load.k_hbeta


def test_bad_input():
    with pytest.raises(ElasticError, match="force"):
        face_load(-1.0, 50.0, 15.0)
    with pytest.raises(ElasticError, match="slices"):
        face_load(1.0, 50.0, 15.0, slices=2)
    with pytest.raises(ElasticError, match="end_relief_length"):
        HelixModification(end_relief=3.0)
