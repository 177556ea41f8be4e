"""Per-mesh friction inputs and the per-mesh loss table (issue 19)."""

from __future__ import annotations

import json
import math

import pytest
from typer.testing import CliRunner

from epicyclic.cli.main import app
from epicyclic.io import InputFileError, loads_train_file
from epicyclic.losses import ConstantFriction, SchlenkFriction
from epicyclic.losses.mesh_table import mesh_loss_table

FILE = """
title = "per-mesh friction"
[lubricant]
viscosity = 26.0
[[planetary]]
name = "P"
sun = "in"
ring = "ring"
carrier = "out"
teeth = {{ sun = 21, planet = 43, ring = 108 }}
planets = 3
[planetary.geometry]
module = 1.75
profile_shift = {{ sun = 0.438, planet = 0.0426 }}
face_width = 38.0
[planetary.losses]
{losses}
[[brake]]
name = "B"
shaft = "ring"
[operating_point]
speeds = {{ in = 3000 }}
torques = {{ in = 100 }}
drives = ["in"]
loads = ["out"]
"""

PER_MESH = 'friction = { "sun-planet" = "schlenk", "planet-ring" = 0.04 }\nroughness = { "sun-planet" = 0.4 }'


def test_friction_per_mesh_from_the_file():
    f = loads_train_file(FILE.format(losses=PER_MESH))
    model = f.losses["P"]
    sun, ring = model.meshes
    assert isinstance(sun.friction, SchlenkFriction) and sun.friction.roughness == 0.4
    assert isinstance(ring.friction, ConstantFriction) and ring.friction.value == 0.04
    listed = loads_train_file(FILE.format(losses='friction = [0.05, 0.04]')).losses["P"]
    assert [m.friction.value for m in listed.meshes] == [0.05, 0.04]
    rough = loads_train_file(FILE.format(losses='friction = "schlenk"\nroughness = [0.4, 0.8]')).losses["P"]
    assert [m.friction.roughness for m in rough.meshes] == [0.4, 0.8]


@pytest.mark.parametrize(("losses", "says"), [
    ('friction = { "sun-planet" = 0.05, "planet-sun" = 0.04 }', r"unknown mesh 'planet-sun'; the meshes are"),
    ('friction = [0.05]', r"expected one value per mesh \(2"),
    ('friction = { "sun-planet" = 0.05 }', r"missing mesh 'planet-ring'"),
    ('friction = { "sun-planet" = "schlenk", "planet-ring" = 0.04 }', r"needs the flank roughness"),
])
def test_bad_per_mesh_friction(losses, says):
    with pytest.raises(InputFileError, match=says):
        loads_train_file(FILE.format(losses=losses))


def test_mesh_table_adds_up_to_the_element_loss():
    f = loads_train_file(FILE.format(losses=PER_MESH))
    solution = f.solve()
    table = mesh_loss_table(solution, f.losses)
    sun, ring = table.rows
    assert sun.model.startswith("Schlenk") and ring.model == "mu = 0.04" and ring.friction == 0.04
    assert ring.efficiency == pytest.approx(1 - 0.04 * ring.loss_factor)
    # rolling power of the sun mesh: |T_sun (n_sun - n_c)| pi/30
    state = solution.elements["P"]
    assert sun.rolling_power == pytest.approx(abs(state.torques["sun"] * (state.speeds["sun"] - state.speeds["carrier"]))
                                              * math.pi / 30)
    # the meshes' losses make the element's mesh loss (eta0 = eta_1 eta_2 on the rolling power: second order apart)
    assert sun.power_loss + ring.power_loss == pytest.approx(state.loss_sources["mesh"], rel=2e-3)
    assert all(r.power_loss >= 0 and 0 < r.efficiency <= 1 for r in table.rows)


def test_analyze_and_forces_report_the_mesh_table(tmp_path):
    path = tmp_path / "p.toml"
    path.write_text(FILE.format(losses=PER_MESH), encoding="utf-8")
    runner = CliRunner()
    data = json.loads(runner.invoke(app, ["analyze", str(path), "-f", "json"]).output)
    rows = data["geometry"]["P"]["mesh_losses"]
    assert [r["mesh"] for r in rows] == ["sun-planet", "planet-ring"]
    assert {"mu", "H_V", "H_V_method", "eps_alpha", "eps_beta", "power_loss_W", "efficiency", "model"} <= set(rows[0])
    html = runner.invoke(app, ["analyze", str(path), "-f", "html"]).output
    assert "mesh losses" in html and "Ohlendorf closed form" in html
    text = runner.invoke(app, ["forces", str(path)]).output
    assert "mesh losses (mu H_V of the rolling power)" in text
