"""Jupyter: planetary sets, gear trains and transmissions render themselves as HTML (a schematic and key figures)."""

from __future__ import annotations

import re

from epicyclic import Brake, Clutch, GearTrain, PlanetarySet
from epicyclic.transmission import Transmission
from epicyclic.transmission.library import build


def test_a_planetary_set_shows_a_front_view_and_its_key_figures():
    pset = PlanetarySet("P<1>", "s", "r", "c", -2.0, 0.98, planets=4)
    page = pset._repr_html_()
    assert page.count("<circle") == 2 + 4  # ring, sun and four planets
    assert "P&lt;1&gt;" in page and "<1>" not in page  # names are escaped
    assert "<td>-2</td>" in page and "<td>0.98</td>" in page


def test_a_train_lists_its_elements():
    train = GearTrain([PlanetarySet("P", "in", "ring", "out", -2.0, 0.98), Brake("B", "ring"),
                       Clutch("C", "in", "ring", engaged=False)])
    page = train._repr_html_()
    assert page.count("<tr>") == 1 + 3 and "PlanetarySet" in page and "<td>no</td>" in page


def test_a_transmission_shows_its_schedule_ratios_steps_and_spread():
    """Ford C4 (Simpson): published ratios 2.46, 1.46, 1.00, reverse 2.18."""
    page = build("simpson_c4")._repr_html_()
    ratios = [float(r) for r in re.findall(r"<td>(-?\d+\.\d{4})</td>", page)]
    assert [round(r, 2) for r in ratios] == [2.46, 1.46, 1.0, -2.18]
    transmission = build("simpson_c4")
    assert isinstance(transmission, Transmission)
    spread = float(re.search(r"spread (\d+\.\d{3})", page).group(1))
    assert spread == round(transmission.ratio("1") / transmission.ratio("3"), 3)  # first over top gear
