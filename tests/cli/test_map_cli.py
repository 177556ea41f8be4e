"""``epicyclic map``: the summary, the files it writes, and what it says when a map cannot mean much."""

from __future__ import annotations

import csv
import io
import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from epicyclic.cli.main import app

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
runner = CliRunner()


def _map(*args: str):
    return runner.invoke(app, ["map", *map(str, args)])


def test_summary_of_a_file_with_loss_models():
    result = _map(EXAMPLES / "geometry_simple_set.toml", "--speed", "1000..3000:3", "--torque", "20..60:3")
    assert result.exit_code == 0, result.output
    # ring held, sun drives the carrier: 1 + 108/21 (Willis equation)
    assert "(drive, ratio 6.143)" in result.output and "3 values" in result.output
    assert "mesh" in result.output and "bearing" in result.output and "drag" in result.output
    assert "note:" not in result.output


def test_a_file_without_loss_tables_says_why_the_map_is_flat(tmp_path):
    # η0 typed in: η is the same at every point. The map says so instead of showing a flat map silently.
    result = _map(EXAMPLES / "brandenberger_1952.toml", "--speed", "500..1500:3", "--torque", "10..30:3")
    assert result.exit_code == 0, result.output
    assert "0.8494 .. 0.8494" in result.output
    assert "note: the file has no loss tables" in result.output
    result = _map(EXAMPLES / "brandenberger_1952.toml", "--speed", "500..1500:3", "--torque", "10..30:3",
                  "-o", tmp_path / "flat.csv")
    assert result.exit_code == 0 and "note: the file has no loss tables" in result.output


def test_writes_csv_json_and_a_figure(tmp_path):
    args = (EXAMPLES / "zf_8hp70_geometry.toml", "--gear", "3", "--speed", "1000..4000:4", "--torque", "50..300:3")
    assert _map(*args, "-o", tmp_path / "g3.csv").exit_code == 0
    rows = list(csv.DictReader(io.StringIO((tmp_path / "g3.csv").read_text())))
    assert len(rows) == 12 and all(0.9 < float(r["efficiency"]) < 1 for r in rows)
    assert _map(*args, "-o", tmp_path / "g3.json").exit_code == 0
    data = json.loads((tmp_path / "g3.json").read_text())
    assert data["gear"] == "3" and data["ratio"] == pytest.approx(2.1039, abs=5e-5)  # published 8HP 70 3rd gear
    assert _map(*args, "-o", tmp_path / "g3.png").exit_code == 0
    assert (tmp_path / "g3.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


@pytest.mark.parametrize("example, says", [
    # a transmission file without an operating-point gear: which gear? (it said "[operating_point], key 'speeds'"
    # although the file has no [operating_point])
    ("zf_8hp70_8speed.toml", "pick one (--gear on the command line, gear= in Python): '1', '2'"),
    # two degrees of freedom: the input speed alone does not fix the train (it blamed the operating point's speeds)
    ("three_shaft_power_split.toml", "the speed of 'generator', 'output' is still free"),
])
def test_a_map_that_cannot_be_drawn_says_why(example, says):
    result = _map(EXAMPLES / example, "--speed", "1000", "--torque", "10")
    assert result.exit_code == 2
    assert says in result.output and "[operating_point]" not in result.output
