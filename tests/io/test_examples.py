"""Every file in examples/ loads, and solves where it has an operating point.

Published numbers: Brandenberger 1952 (Beispiel zu Bild 10), Queitsch Tafel 1 (two-shaft ratios),
Brandenberger 1952, eq. 7 and text to Bild 9 (plus set i0 = 1.02, η0 = 0.95: η = 0.2714 one way, self-locking the other way).
"""

from __future__ import annotations

from pathlib import Path

import pytest

from epicyclic.io import load_train_file

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
FILES = sorted(EXAMPLES.glob("*.toml"))


def test_there_are_examples():
    assert len(FILES) >= 10


@pytest.mark.parametrize("path", FILES, ids=[p.name for p in FILES])
def test_every_example_loads_and_solves(path):
    assert path.read_text(encoding="utf-8").lstrip().startswith("#"), "each example starts with a comment header"
    train_file = load_train_file(path)
    assert train_file.train.elements
    if train_file.operating_point is None:
        assert train_file.transmission is not None or train_file.train  # loads without an operating point
        return
    solution = train_file.solve()
    assert solution.input_power > 0
    assert solution.loss >= -1e-9 * solution.input_power
    if solution.self_locking is None:
        assert 0 < solution.efficiency <= 1 + 1e-12


def test_brandenberger_in_original_units():
    # Brandenberger 1952: n1 = 2740, n3 = 5280 U/min, M_An' = 143.24 cm kg, η' = 0.85, N1' = 2.55 PS,
    # without friction N1 = 3 PS. Printed digits: rounded to those digits.
    f = load_train_file(EXAMPLES / "brandenberger_1952.toml")
    s = f.solve()
    u = f.units
    assert round(u.speed_from_core(s.speed("I"))) == 2740
    assert round(u.speed_from_core(s.speed("III"))) == 5280
    assert round(u.torque_from_core(s.torque("II")), 2) == 143.24
    assert round(s.efficiency, 2) == 0.85
    assert round(u.power_from_core(s.output_power), 2) == 2.55
    assert round(u.power_from_core(s.ideal.output_power), 2) == 3.00


S, ETA0 = -78 / 30, 0.98
# Closed forms of Brandenberger's loss rule for a minus set (Brandenberger 1952, eq. 7 gives the first; the others
# follow from the same rule, eq. 7, with the roles of the shafts exchanged). Ratios: Queitsch Tafel 1.
MODES = [
    ("simple_set_ring_held_sun_drives.toml", "sun", "carrier", 1 - S, (1 - S * ETA0) / (1 - S)),
    ("simple_set_ring_held_carrier_drives.toml", "carrier", "sun", 1 / (1 - S), (1 - S) / (1 - S / ETA0)),
    ("simple_set_sun_held_ring_drives.toml", "ring", "carrier", (1 - S) / -S, (1 - ETA0 / S) / (1 - 1 / S)),
    ("simple_set_sun_held_carrier_drives.toml", "carrier", "ring", -S / (1 - S), (1 - 1 / S) / (1 - 1 / (S * ETA0))),
    ("simple_set_carrier_held_sun_drives.toml", "sun", "ring", S, ETA0),
    ("simple_set_carrier_held_ring_drives.toml", "ring", "sun", 1 / S, ETA0),
    ("simple_set_direct_drive.toml", "sun", "carrier", 1.0, 1.0),
]


@pytest.mark.parametrize("name, drive, load, ratio, efficiency", MODES, ids=[m[0] for m in MODES])
def test_two_shaft_mode_files(name, drive, load, ratio, efficiency):
    # tolerance: 1e-9 relative (exact arithmetic on both sides)
    s = load_train_file(EXAMPLES / name).solve()
    assert s.speed(drive) / s.speed(load) == pytest.approx(ratio, rel=1e-9)
    assert s.efficiency == pytest.approx(efficiency, rel=1e-9)


def test_plus_set_files():
    # Brandenberger 1952, eq. 7: i0 = 1.02, η0 = 0.95, ring held: carrier → sun η = 0.2714; sun → carrier self-locks
    # (formal η = −1.55), threshold η0 = 1/i0.
    reduction = load_train_file(EXAMPLES / "plus_set_reduction.toml").solve()
    assert round(reduction.efficiency, 4) == 0.2714
    locked = load_train_file(EXAMPLES / "plus_set_self_locking.toml").solve()
    assert locked.self_locking is not None and locked.efficiency is None
    assert round(locked.self_locking.formal_efficiency, 2) == -1.55
    assert locked.self_locking.thresholds["plus"] == pytest.approx(1 / 1.02, rel=1e-6)


def test_power_split_file():
    # Ideal torque split M_s : M_r : M_c = 1 : −i0 : −(1 − i0) (Queitsch eqs. 26–29), i0 = −78/30.
    f = load_train_file(EXAMPLES / "three_shaft_power_split.toml")
    s = f.solve()
    ideal = s.ideal
    i0 = -78 / 30
    assert ideal.torque("output") / ideal.torque("generator") == pytest.approx(-i0, rel=1e-9)
    assert ideal.torque("engine") / ideal.torque("generator") == pytest.approx(-(1 - i0), rel=1e-9)
    assert s.speed("generator") == pytest.approx(i0 * 1500 + (1 - i0) * 2000, rel=1e-12)
    assert s.shafts["generator"].power < 0 and s.shafts["output"].power < 0  # both are loads
    assert 0.97 < s.efficiency < 1
