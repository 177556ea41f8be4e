"""Per-gear efficiency of the ZF 8HP 70 at η0 = 0.98 and 0.97 per set, against the published table.

Published: Wikipedia, 'ZF 8HP transmission', 'In-Depth Analysis With Assessment' table,
row 8HP 70 (2008), line 'Efficiency' (two values per gear: η0 = 0.98 and 0.97 per
planetary set; 1st gear 0.9843 = (1 + (85/23)·0.98)/(1 + 85/23) confirms that reading).
Tolerance: 0.6 units of the 4th decimal (printed to 4 digits) where we agree.

Two published values disagree with the solver; the hand calculations below decide.
"""

from __future__ import annotations

import numpy as np
import pytest

from epicyclic.transmission.library import build

PUBLISHED = {  # gear: (η at η0 = 0.98, η at η0 = 0.97)
    "R": (0.9460, 0.9195), "1": (0.9843, 0.9764), "2": (0.9776, 0.9664), "3": (0.9896, 0.9843),
    "4": (0.9867, 0.9802), "5": (0.9903, 0.9854), "6": (1.0000, 1.0000), "7": (0.9947, 0.9920),
    "8": (0.9932, 0.9898),
}
DISAGREE = {"3", "5"}


@pytest.fixture(scope="module")
def analyses():
    return {eta: build("zf_8hp70", eta).analyze_all() for eta in (0.98, 0.97)}


@pytest.mark.parametrize("gear", [g for g in PUBLISHED if g not in DISAGREE])
@pytest.mark.parametrize("k, eta0", [(0, 0.98), (1, 0.97)])
def test_efficiency_matches_published(analyses, gear, k, eta0):
    assert analyses[eta0][gear].efficiency_drive == pytest.approx(PUBLISHED[gear][k], abs=0.6e-4)


def _third_gear_by_hand(eta0: float, k1: float = 2.0, k4: float = 85 / 23) -> float:
    """3rd gear (B, C, E): P2, P3 locked (S12 = S4 = input), P1 sun in / ring held / carrier → R4,
    P4 sums sun (input) and ring (n_in/3) into the carrier (output); both suns drive relative to
    their carriers (w = +1), so with k1 = 2, k4 = 85/23 and output torque 1:
    T_s4 = 1/(1 + k4·η0), T_r4 = k4·η0·T_s4, T_s1 = T_r4/(1 + k1·η0), T_in = T_s4 + T_s1,
    i = 3(1 + k4)/(3 + k4) = 2.10390, η = 1/(T_in·i).
    η0 = 0.98: T_s4 = 0.216369, T_r4 = 0.783631, T_s1 = 0.264740, T_in = 0.481109, η = 0.98794.
    η0 = 0.97: T_in = 0.484060, η = 0.98192.  Published 0.9896 / 0.9843 would need losses of
    1.04 % / 1.57 % of the input power, but the two rolling sets alone pass 0.3680 + 0.2351 =
    0.603 × P_in of rolling power, i.e. ≥ 0.603·(1 − η0) = 1.21 % / 1.81 %: the table is wrong.
    Other tooth counts (the GM 8L 90): k1 = z_ring/z_sun of P1, k4 of P4, i = (1 + k1)(1 + k4)/(1 + k1 + k4).
    """
    t_s4 = 1 / (1 + k4 * eta0)
    t_r4 = k4 * eta0 * t_s4
    t_s1 = t_r4 / (1 + k1 * eta0)
    ratio = (1 + k1) * (1 + k4) / (1 + k1 + k4)
    return 1 / ((t_s4 + t_s1) * ratio)


def _fifth_gear_by_hand(eta0: float, i0=(-2.0, -2.0, -111 / 69, -85 / 23),
                        ratio: float = 1.2845291806141765) -> float:
    """5th gear (B, C, D): all four sets roll.  Sun torques t1..t4, T_ring = −i0·η0^w·T_sun,
    T_carrier = −(T_sun + T_ring); loss directions w = (+1, −1, −1, +1) from the lossless
    rolling powers (+0.204, −0.164, −0.101, +0.026 × P_in).  Balances of the internal shafts:
    S12: t1 + t2 = 0;  C1/R4: T_c1 + T_r4 = 0;  R2/S3: T_r2 + t3 = 0;
    input (+S4, R3 by clutch C): T_c2 + T_r3 + t4 = 1.  Output (C3 + C4 by clutch D) carries
    M_out = T_c3 + T_c4.  Result η0 = 0.98: |M_out| = 1.27191 ('specific torque', published
    1.2720), η = 1.27191/1.28453 = 0.99018 (published 0.9903); η0 = 0.97: 1.26570 (published
    1.2658), η = 0.98534 (published 0.9854).  The published values are high by ≈ 1e-4; the
    balance below, written independently of the solver, agrees with the solver to 1e-9.
    """
    i0 = np.array(i0)
    f = i0 * eta0 ** np.array([1, -1, -1, 1])  # T_ring = -f T_sun, T_carrier = -(1 - f) T_sun
    a = np.array([
        [1, 1, 0, 0],
        [-(1 - f[0]), 0, 0, -f[3]],
        [0, -f[1], 1, 0],
        [0, -(1 - f[1]), -f[2], 1],
    ])
    t = np.linalg.solve(a, [0, 0, 0, 1.0])
    m_out = -(1 - f[2]) * t[2] - (1 - f[3]) * t[3]
    return -m_out / ratio  # ratio from the Willis rows (tested in test_library.py)


@pytest.mark.parametrize("k, eta0", [(0, 0.98), (1, 0.97)])
def test_third_gear_hand_calculation_decides(analyses, k, eta0):
    hand = _third_gear_by_hand(eta0)
    assert analyses[eta0]["3"].efficiency_drive == pytest.approx(hand, abs=1e-9)
    assert abs(hand - PUBLISHED["3"][k]) > 1e-3  # the published value is off by > 0.1 %


@pytest.mark.parametrize("k, eta0", [(0, 0.98), (1, 0.97)])
def test_fifth_gear_hand_calculation_decides(analyses, k, eta0):
    hand = _fifth_gear_by_hand(eta0)
    assert analyses[eta0]["5"].efficiency_drive == pytest.approx(hand, abs=1e-9)
    assert 0.5e-4 < PUBLISHED["5"][k] - hand < 2e-4


def test_rolling_power_signs_of_fifth_gear(analyses):
    """The loss directions used by the hand calculation are the solver's."""
    rolling = analyses[0.98]["5"].rolling_power
    assert [np.sign(rolling[p]) for p in ("P1", "P2", "P3", "P4")] == [1, -1, -1, 1]


def test_coast_differs_from_drive_and_is_below_one(analyses):
    a = analyses[0.97]
    for g in a.gears:
        assert 0.9 < g.efficiency_coast <= 1.0
    assert a["R"].efficiency_coast != pytest.approx(a["R"].efficiency_drive, abs=1e-4)


def test_losses_equal_rolling_power_times_loss_factor(analyses):
    """Energy check per gear: P_in − P_out = Σ over sets of (1 − η0) × driving-side rolling power."""
    for g in analyses[0.98].gears:
        sol = g.drive
        expected = 0.0
        for name in ("P1", "P2", "P3", "P4"):
            state = sol.elements[name]
            pw = state.rolling_power
            expected += pw * (1 - 0.98) if pw > 0 else -pw * (1 / 0.98 - 1)
        assert sol.input_power - sol.output_power == pytest.approx(expected, rel=1e-9, abs=1e-9)



# --- GM 8L 90: the same gearset concept, another published table --------------------------
# Wikipedia, 'GM 8L transmission', 'In-Depth Analysis With Assessment', row 8L 90 / 8L 80, line
# 'Efficiency' (η0 = 0.98 and 0.97 per set; 1st gear 0.9844 = (1 + (89/25)·0.98)/(1 + 89/25)).
# Tolerance 0.6 units of the printed 4th decimal where we agree.  The table's own pairs decide
# where we do not: with the loss directions fixed, every set's loss is its rolling power times
# (1 − η0^w), so the loss at η0 = 0.97 is 1.5 times the loss at 0.98 (to O(1 − η0)); the published
# pairs of 3rd, 4th, 5th and 7th gear give 2.30, 2.17, 2.01 and 1.06, those we reproduce 1.49–1.50.
PUBLISHED_8L90 = {
    "R": (0.9469, 0.9209), "1": (0.9844, 0.9766), "2": (0.9774, 0.9662), "3": (0.9896, 0.9761),
    "4": (0.9866, 0.9709), "5": (0.9869, 0.9737), "6": (1.0000, 1.0000), "7": (0.9948, 0.9945),
    "8": (0.9929, 0.9893),
}
AGREE_8L90 = {0.98: ("R", "1", "2", "4", "6", "7", "8"), 0.97: ("R", "1", "2", "6", "8")}


@pytest.fixture(scope="module")
def analyses_8l90():
    return {eta: build("gm_8l90", eta).analyze_all() for eta in (0.98, 0.97)}


@pytest.mark.parametrize("eta0, gear", [(e, g) for e, gears in AGREE_8L90.items() for g in gears])
def test_gm_8l90_efficiency_matches_published(analyses_8l90, eta0, gear):
    k = 0 if eta0 == 0.98 else 1
    assert analyses_8l90[eta0][gear].efficiency_drive == pytest.approx(PUBLISHED_8L90[gear][k], abs=0.6e-4)


def _loss_ratio(pair):
    return (1 - pair[1]) / (1 - pair[0])


@pytest.mark.parametrize("gear", [g for g in PUBLISHED_8L90 if g != "6"])
def test_gm_8l90_losses_scale_with_one_minus_eta0(analyses_8l90, gear):
    """Ours scale by 1.5 ± 0.03 from η0 = 0.98 to 0.97; a published pair that does not is not
    self-consistent, and exactly those are the pairs we do not reproduce."""
    ours = (analyses_8l90[0.98][gear].efficiency_drive, analyses_8l90[0.97][gear].efficiency_drive)
    assert 1.47 < _loss_ratio(ours) < 1.53
    consistent = 1.45 < _loss_ratio(PUBLISHED_8L90[gear]) < 1.55
    assert consistent == (gear in AGREE_8L90[0.97])


@pytest.mark.parametrize("eta0", [0.98, 0.97])
def test_gm_8l90_third_and_fifth_gear_by_hand(analyses_8l90, eta0):
    """The closed form of 3rd gear and the independent balance of 5th (above), with the 8L 90's
    teeth in the 8HP's places (P1 37/73, P2 46/86, P3 41/79, P4 25/89), give the solver's values;
    the published 0.9896 in 3rd is the 8HP 70's figure (other teeth), 0.9869 in 5th would need a
    loss 1.4 times the one its rolling power allows."""
    third = _third_gear_by_hand(eta0, k1=73 / 37, k4=89 / 25)
    fifth = _fifth_gear_by_hand(eta0, i0=(-73 / 37, -86 / 46, -79 / 41, -89 / 25),
                                ratio=build("gm_8l90").ratio("5"))
    assert analyses_8l90[eta0]["3"].efficiency_drive == pytest.approx(third, abs=1e-9)
    assert analyses_8l90[eta0]["5"].efficiency_drive == pytest.approx(fifth, abs=1e-9)
    rolling = analyses_8l90[eta0]["5"].rolling_power
    assert [np.sign(rolling[p]) for p in ("P1", "P2", "P3", "P4")] == [1, -1, -1, 1]
