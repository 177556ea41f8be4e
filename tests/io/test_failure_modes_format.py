"""The ``[rating.micropitting]`` table (epicyclic.io.failure_modes_format) and its section in ``epicyclic rate``."""

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from epicyclic.cli.main import app
from epicyclic.errors import EpicyclicError
from epicyclic.io import loads_train_file

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "rating" / "micropitting.toml"
TEXT = EXAMPLE.read_text(encoding="utf-8")
runner = CliRunner()


def test_the_table_is_read():
    spec = loads_train_file(TEXT).rating.micropitting
    assert (spec.oil_temperature, spec.load_stage, spec.roughness, spec.lubricant_type) == (70.0, 9, 0.5, "mineral")
    per_gear = loads_train_file(TEXT.replace("roughness = 0.5 ", "roughness = { sun = 0.4, planet = 0.5, ring = 0.8 } "))
    assert dict(per_gear.rating.micropitting.roughness) == {"sun": 0.4, "planet": 0.5, "ring": 0.8}


@pytest.mark.parametrize(("change", "message"), [
    (("load_stage = 9 ", "load_stge = 9 "), "load_stge"),
    (("load_stage = 9 ", "load_stage = 13 "), "load_stage must be"),
    (("load_stage = 9 ", "lubrication = 'mist'\nload_stage = 9 "), "lubrication must be one of"),
    (("oil_temperature = 70.0 ", "oil_temperature = 'hot' "), "oil_temperature"),
    (("oil_temperature = 70.0 ", "# "), "oil_temperature is missing"),
    (("load_stage = 9 ", "# "), "load_stage .* or lambda_GFP"),
])
def test_bad_input_names_the_key(change, message):
    with pytest.raises(EpicyclicError, match=message):          # located: the file and the table are named
        loads_train_file(TEXT.replace(*change))
    with pytest.raises(EpicyclicError, match=r"\[rating.micropitting\]"):
        loads_train_file(TEXT.replace(*change))


def test_rate_prints_the_micropitting_section_in_every_format():
    table = runner.invoke(app, ["rate", str(EXAMPLE)])
    assert table.exit_code == 0, table.output
    assert "Failure modes beyond pitting and root" in table.output and "λ_GFmin" in table.output
    data = json.loads(runner.invoke(app, ["rate", str(EXAMPLE), "-f", "json"]).stdout)
    section = data["ratings"][0]["meshes"][0]["modes"]["micropitting"]
    assert section["safety"] == "S_lambda" and section["value"] > 0 and section["ok"] is True
    assert data["inputs"]["micropitting"]["load_stage"] == 9
    assert any("ISO/TS 6336-22:2018, clause 1" in w for w in data["warnings"])      # the internal mesh
    assert "#### Micropitting" in runner.invoke(app, ["rate", str(EXAMPLE), "-f", "markdown"]).output
    assert "<h4>Micropitting" in runner.invoke(app, ["rate", str(EXAMPLE), "-f", "html"]).output


def test_a_micropitting_shortfall_is_marked_and_named():
    given = str(EXAMPLE) + ""
    result = runner.invoke(app, ["rate", given, "--set", "rating.micropitting.lambda_GFP=3.0", "-f", "html"])
    assert result.exit_code == 0, result.output
    assert "<h4 class='below'" in result.output
    text = runner.invoke(app, ["rate", given, "--set", "rating.micropitting.lambda_GFP=3.0"])
    assert "S_λ" in text.output and " !" in text.output and "below minimum safety" in text.output
