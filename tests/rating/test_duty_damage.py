"""Damage sums of the teeth over a duty cycle (ISO 6336-6 Palmgren–Miner on the rating's S–N curves)."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import pytest

from epicyclic.io import load_train_file
from epicyclic.rating import DutyCycle, LoadCase, analyse_duty_cycle
from epicyclic.rating.train import rate_solution

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "rating" / "simple_set.toml"


def _run(f, hours, op=None):
    duty = DutyCycle((LoadCase("design point", op or f.operating_point, hours=hours),))
    return analyse_duty_cycle(f.train, duty, losses=f.losses, geometry=f.geometry, rating=f.rating)


def test_one_case_for_the_required_life_matches_the_safety():
    # one case at the rating's own operating point for its required life L_h: n = N_L of the rating, and
    # N_fail from Z_NT(N_fail) = sigma_H / sigma_ref with sigma_ref = sigma_HG / Z_NT(N_L) (ISO 6336-2, eq. (4));
    # S_H > 1 means D < 1 (the rating at one point, rate_solution, is the independent path)
    f = load_train_file(EXAMPLE)
    res = _run(f, f.rating.life)
    single = rate_solution(f.solve(), f.geometry, f.rating)
    for d in res.damage:
        gear = single.mesh(d.element, d.mesh).gears[[g.gear for g in single.mesh(d.element, d.mesh).gears]
                                                    .index(d.gear)]
        fac = gear.factors
        assert d.cycles[0] == pytest.approx(fac["N_L"].value, rel=1e-9)
        ratio = fac["sigma_H"].value / (fac["sigma_HG"].value / fac["Z_NT"].value)
        expected = fac["N_L"].value / d.flank_curve.cycles_to_failure(ratio)
        assert d.flank_damage == pytest.approx(expected, rel=1e-9)
        assert (d.flank_damage < 1) == (fac["S_H"].value > 1)
        assert (d.root_damage < 1) == (fac["S_F"].value > 1)


def test_damage_is_linear_in_hours_and_grows_with_torque():
    f = load_train_file(EXAMPLE)
    short, long = _run(f, 1000.0), _run(f, 3000.0)
    for a, b in zip(short.damage, long.damage):
        assert b.flank_damage == pytest.approx(3 * a.flank_damage, rel=1e-9)
        assert b.root_damage == pytest.approx(3 * a.root_damage, rel=1e-9)
    op = f.operating_point
    heavier = _run(f, 1000.0, replace(op, torques={k: 1.5 * v for k, v in op.torques.items()}))
    assert all(h.flank_damage > a.flank_damage and h.root_damage > a.root_damage
               for h, a in zip(heavier.damage, short.damage))


def test_a_cycle_of_shares_runs_for_the_rating_life():
    f = load_train_file(EXAMPLE)
    by_share = analyse_duty_cycle(f.train, DutyCycle((LoadCase("a", f.operating_point, share=1.0),)),
                                  geometry=f.geometry, rating=f.rating)
    by_hours = _run(f, f.rating.life)
    assert [d.flank_damage for d in by_share.damage] == pytest.approx([d.flank_damage for d in by_hours.damage])
    assert "Palmgren-Miner damage sums" in by_share.table()
    assert by_share.to_dict()["damage"][0]["D_H"] == pytest.approx(by_share.damage[0].flank_damage)
