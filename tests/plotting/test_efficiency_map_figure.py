"""The efficiency-map picture: every η band its own colour."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from epicyclic.io import load_train_file
from epicyclic.losses import efficiency_map

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def test_every_efficiency_band_gets_its_own_colour():
    # The levels sit at quantiles of η, so the bands are unequal (the 8HP's 3rd gear: 0.967 … 0.9919 for the
    # drag-dominated corner, then bands of 0.0002). With a linear colour scale the bulk of the map was one
    # yellow; each band now takes the next colour of the map, from its bottom to its top.
    emap = efficiency_map(load_train_file(EXAMPLES / "zf_8hp70_geometry.toml"), np.linspace(500, 6000, 30),
                          np.linspace(10, 500, 30), gear="3")
    fig = emap.plot()
    filled = fig.axes[0].collections[0]
    levels = np.asarray(filled.levels)
    assert np.diff(levels).max() > 20 * np.diff(levels).min()  # unequal bands: the case that went wrong
    middles = (levels[:-1] + levels[1:]) / 2
    colours = filled.cmap(filled.norm(middles))
    assert len({tuple(np.round(c, 3)) for c in colours}) == len(middles)
    assert np.allclose(colours[0], filled.cmap(0.0)) and np.allclose(colours[-1], filled.cmap(filled.cmap.N - 1))


def test_a_small_drag_share_still_shows_its_variation():
    # The simple-set example: drag is 0.004 … 6.7 % of the loss (0.1 % summed over the map). On a fixed
    # 0 … 100 % scale the whole panel was one colour; the levels now span the share's own range (log scale,
    # it spans three decades), and the map uses most of the colour bands.
    emap = efficiency_map(load_train_file(EXAMPLES / "geometry_simple_set.toml"), np.linspace(500, 6000, 30),
                          np.linspace(10, 500, 30))
    share = 100 * emap.losses["drag"] / emap.loss
    assert share.max() < 10  # the case that was flat
    fig = emap.plot()
    filled = fig.axes[1].collections[0]  # axes: the two panels, then their colour bars
    levels = np.asarray(filled.levels)
    assert levels[0] == share.min() and levels[-1] == share.max()
    assert np.allclose(np.diff(np.log(levels)), np.log(levels[1] / levels[0]))  # logarithmic
    used = {int(np.searchsorted(levels, v, side="right")) for v in share.ravel()}
    assert len(used) >= len(levels) - 2  # nearly every band appears somewhere on the map
    assert "0.004 … 6.7 %" in fig.axes[1].get_title() and "log scale" in fig.axes[3].get_ylabel()


def test_share_levels_by_range():
    from epicyclic.plotting.efficiency_map import share_levels

    assert share_levels(np.array([20.0, 25.0, 30.0]))[0].tolist() == np.linspace(20, 30, 11).tolist()
    levels, scale = share_levels(np.array([5.0, 5.0]))
    assert scale == "5 % everywhere" and levels[0] < 5.0 < levels[-1]
    assert share_levels(np.array([0.0, 3.0]))[1] == "linear scale"  # zero drag somewhere: no log scale
