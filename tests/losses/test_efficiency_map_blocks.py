"""An efficiency map is solved in blocks of torque rows (issue 30: the documented maximum of 10^6 points
needed about 3.3 GB in one batch solve, past a page worker's 2 GiB): the blocks give the numbers of one solve."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import epicyclic.losses.efficiency_map as maps  # noqa: F401 - the module (its function shadows the name)
from epicyclic.io import load_train_file

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
MODULE = __import__("sys").modules["epicyclic.losses.efficiency_map"]


@pytest.mark.parametrize(("name", "gear", "direction"), [("zf_8hp70_geometry.toml", "3", "drive"),
                                                         ("zf_8hp70_spin_losses.toml", "5", "coast")])
def test_blocks_give_the_numbers_of_one_solve(monkeypatch, name, gear, direction):
    train_file = load_train_file(EXAMPLES / name)
    speeds, torques = np.linspace(600, 5000, 7), np.linspace(20, 400, 9)
    whole = MODULE.efficiency_map(train_file, speeds, torques, gear=gear, direction=direction)
    monkeypatch.setattr(MODULE, "MAP_BLOCK_POINTS", 15)  # two torque rows (7 speeds) a block, the last one short
    blocked = MODULE.efficiency_map(train_file, speeds, torques, gear=gear, direction=direction)
    for field in ("efficiency", "input_power", "output_power", "loss", "self_locking"):
        np.testing.assert_allclose(getattr(blocked, field), getattr(whole, field), rtol=1e-12, atol=1e-9)
    assert set(blocked.losses) == set(whole.losses)
    for source in whole.losses:
        np.testing.assert_allclose(blocked.losses[source], whole.losses[source], rtol=1e-12, atol=1e-9)
    if whole.oil_temperature is not None:
        np.testing.assert_allclose(np.broadcast_to(blocked.oil_temperature, whole.loss.shape),
                                   np.broadcast_to(whole.oil_temperature, whole.loss.shape))


def test_a_block_is_bounded():
    assert MODULE.MAP_BLOCK_POINTS * 3.3e3 < 0.5 * 2**30  # a block's temporaries well within 2 GiB
