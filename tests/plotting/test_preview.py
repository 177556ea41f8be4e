"""Notebook previews of descriptions (epicyclic.plotting.preview, registered by epicyclic.notebook)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from epicyclic import GearTrain, PlanetarySet
from epicyclic.io import load_train_file
from epicyclic.notebook import PREVIEWS, register
from epicyclic.plotting.preview import set_html, train_html, transmission_html
from epicyclic.transmission import Transmission

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def _cells(html: str) -> list[str]:
    return re.findall(r"<td[^>]*>([^<]*)</td>", html)


def test_a_set_shows_its_gears_and_key_figures():
    pset = PlanetarySet.simple("P", sun="in", ring="ring", carrier="out", z_sun=30, z_planet=24, z_ring=78,
                               stationary_efficiency=0.98, planets=4)
    html = set_html(pset)
    assert html.count("<svg") == 1 and "animateTransform" not in html  # drawn still
    cells = _cells(html)
    assert cells[cells.index("stationary ratio i0") + 1] == "-2.6"  # i0 = -z_ring/z_sun (Queitsch eq. 4)
    assert cells[cells.index("teeth (sun/planet/ring)") + 1] == "30/24/78"
    assert cells[cells.index("planets") + 1] == "4"
    assert html.count('fill-rule="evenodd"') == 1 and html.count("translate(") == 4  # the ring; four planets


def test_a_set_given_by_i0_is_drawn_schematic_and_says_so():
    pset = load_train_file(EXAMPLES / "plus_set_reduction.toml").train.planetary_sets[0]
    cells = _cells(set_html(pset))
    assert "plus set" in cells
    assert any(c.startswith("schematic teeth ") and "given by i0 alone" in c for c in cells)


def test_a_train_shows_its_lever_diagram_and_elements():
    train = load_train_file(EXAMPLES / "brandenberger_1952.toml").train
    html = train_html(train)
    assert "<svg" in html and "lever diagram" in html
    assert "i0 0.672, η0 0.9" in html  # Brandenberger 1952, Bild 10: i0 = (24·42)/(50·30) = 0.672
    assert "ratio 3.52, η 0.9" in html


def test_a_transmission_shows_its_schedule_with_ratios_steps_and_spread():
    t = Transmission.from_file(EXAMPLES / "zf_8hp70_8speed.toml")
    html = transmission_html(t)
    rows = re.findall(r"<tr><td[^>]*>([^<]*)</td><td[^>]*>([^<]*)</td><td[^>]*>([^<]*)</td><td[^>]*>([^<]*)</td></tr>",
                      html)
    ratios = {gear: float(ratio) for gear, _, ratio, _ in rows}
    # ZF 8HP 70 published ratios (ZF press kit 2008: 4.696 ... 0.667, R -3.297)
    assert ratios["1"] == pytest.approx(4.696, abs=5e-4) and ratios["8"] == pytest.approx(0.667, abs=5e-4)
    assert ratios["R"] == pytest.approx(-3.297, abs=5e-4)
    steps = {gear: step for gear, _, _, step in rows}
    assert float(steps["1"]) == pytest.approx(ratios["1"] / ratios["2"], rel=1e-3) and steps["8"] == ""
    assert "spread 7.04" in html


def test_names_are_escaped():
    pset = PlanetarySet.simple("<b>P</b>", sun="<i>s</i>", ring="r", carrier="c", z_sun=30, z_planet=24, z_ring=78)
    html = train_html(GearTrain([pset], name="<script>x</script>"))
    assert "<script>x" not in html and "<b>P" not in html and "&lt;script&gt;" in html


class _Formatter:
    def __init__(self):
        self.printers = {}

    def for_type_by_name(self, module, name, function):
        self.printers[(module, name)] = function


class _Shell:
    def __init__(self):
        self.display_formatter = type("DisplayFormatter", (), {})()
        self.display_formatter.formatters = {"text/html": _Formatter()}


def test_register_hands_ipython_one_preview_per_type():
    shell = _Shell()
    assert register(shell) is True
    printers = shell.display_formatter.formatters["text/html"].printers
    assert set(printers) == {(module, name) for module, name, _ in PREVIEWS}
    pset = PlanetarySet.simple("P", sun="s", ring="r", carrier="c", z_sun=30, z_planet=24, z_ring=78)
    assert printers[("epicyclic.model.planetary", "PlanetarySet")](pset) == set_html(pset)
    for module, name, _ in PREVIEWS:  # the names IPython looks the types up by are the real ones
        assert getattr(__import__(module, fromlist=[name]), name).__name__ == name


def test_without_ipython_nothing_is_registered(monkeypatch):
    import sys

    monkeypatch.delitem(sys.modules, "IPython", raising=False)
    assert register() is False
