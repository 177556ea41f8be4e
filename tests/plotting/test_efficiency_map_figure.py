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
