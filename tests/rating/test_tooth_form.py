"""Y_F, Y_S: 30° tangent (external) and rack-shaped tooth (internal), ISO 6336-3.

Cross-check: the independent DIN 3990 / ISO 6336 implementation hanslhansl/din3990
(tests/test_1.py, its printed intermediate values) for the pair z = 19/104, m_n = 4,
x = 0.5/0.15, rack h_fP* = 1.25, ρ_fP* = 0.25: ϑ, s_Fn, ρ_F (the same critical section
in methods B and C) and, with the load at the tip (ε_α − 1 → 0), h_Fa, α_Fan, Y_Fa, Y_Sa
(eqs. (19)–(27) with d_en = d_an).  s_Fn differs by 6e-5 relative (their E is 1.7e-5 mm
larger), so s_Fn-dependent values are compared to 2e-4.
"""

import math

import pytest

from epicyclic.rating import RatingError, RatingWarning
from epicyclic.rating.tooth_form import (
    Cutter,
    external_tooth_form,
    internal_tooth_form,
    stress_correction,
)

A20 = math.radians(20)


@pytest.mark.parametrize(("z", "x", "d_a", "theta", "s_fn", "rho_f", "h_fa", "alpha_fan", "y_fa", "y_sa"), [
    (19, 0.5, 88.0, 48.10260415904784, 8.748743355951145, 1.3161477577049423, 8.174657642839318,
     34.561848000666245, 2.246336378902072, 1.9147262565947287),
    (104, 0.15, 425.2, 56.99835389167487, 9.239504610725831, 1.325999192893118, 7.834245947926714,
     22.738705423178445, 2.1616566798058514, 2.008781657562889),
])
def test_critical_section_matches_independent_implementation(z, x, d_a, theta, s_fn, rho_f, h_fa, alpha_fan,
                                                             y_fa, y_sa):
    tip = external_tooth_form(z, x, 4.0, A20, 0.0, d_a, 1.0)   # ε_α = 1: load at the tip
    assert math.degrees(tip.theta) == pytest.approx(theta, abs=1e-3)
    assert tip.s_Fn == pytest.approx(s_fn, rel=1e-4)
    assert tip.rho_F == pytest.approx(rho_f, rel=1e-4)
    assert tip.h_Fe == pytest.approx(h_fa, rel=1e-5)
    assert math.degrees(tip.alpha_Fen) == pytest.approx(alpha_fan, abs=1e-6)
    assert tip.Y_F == pytest.approx(y_fa, rel=2e-4)
    assert tip.Y_S == pytest.approx(y_sa, rel=2e-4)


def test_single_contact_load_is_below_the_tip():
    tip = external_tooth_form(19, 0.5, 4.0, A20, 0.0, 88.0, 1.0)
    inner = external_tooth_form(19, 0.5, 4.0, A20, 0.0, 88.0, 1.5363)
    assert inner.h_Fe < tip.h_Fe and inner.Y_F < tip.Y_F and inner.Y_S > tip.Y_S
    assert inner.s_Fn == tip.s_Fn  # the critical section does not depend on the load point


def test_internal_rack_chord_closed_form():
    # s_Fn/m = 2 (π/4 + (h_fP − ρ_fP) tan α + ρ_fP/cos α − ρ_fP cos 30°) with h_fP = 1.25, ρ_fP = 0.25
    f = internal_tooth_form(96, 0.0, 1.5, A20, 0.0, 141.0, 1.7)
    expected = 2 * (math.pi / 4 + 1.0 * math.tan(A20) + 0.25 / math.cos(A20) - 0.25 * math.cos(math.pi / 6))
    assert f.s_Fn / 1.5 == pytest.approx(expected, rel=1e-12)
    assert f.rho_F == pytest.approx(0.25 * 1.5) and f.alpha_Fen == pytest.approx(A20)
    assert f.Y_F == pytest.approx(6 * (f.h_Fe / 1.5) / (f.s_Fn / 1.5) ** 2)


def test_cutter_equal_to_rack_depth_gives_the_rack_result():
    rack = internal_tooth_form(96, 0.0, 1.5, A20, 0.0, 141.0, 1.7)
    cut = internal_tooth_form(96, 0.0, 1.5, A20, 0.0, 141.0, 1.7, cutter=Cutter(24))
    assert cut.Y_F == pytest.approx(rack.Y_F, rel=1e-9) and cut.method == "rack (pinion-type cutter)"
    deeper = internal_tooth_form(96, 0.0, 1.5, A20, 0.0, 141.0, 1.7, cutter=Cutter(24, addendum=1.4))
    assert deeper.s_Fn > rack.s_Fn   # a deeper root widens the rack tooth's critical chord


def test_stress_correction_formula_and_range_warning():
    L, q = 8.0 / 6.0, 8.0 / 2.4
    assert stress_correction(8.0, 6.0, 1.2) == pytest.approx((1.2 + 0.13 * L) * q ** (1 / (1.21 + 2.3 / L)))
    with pytest.warns(RatingWarning, match="ISO 6336-3"):
        stress_correction(8.0, 6.0, 0.4)   # q_s = 10 > 8


def test_bad_tool_is_refused():
    with pytest.raises(RatingError, match="z0"):
        internal_tooth_form(30, 0.0, 1.5, A20, 0.0, 41.0, 1.5, cutter=Cutter(40))
    with pytest.raises(RatingError, match="teeth"):
        Cutter(3)
