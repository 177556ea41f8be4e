"""``epicyclic size``: module, face width and profile shifts of a set that can be built and carries the load."""

from __future__ import annotations

import json
from pathlib import Path

from typer.testing import CliRunner

from epicyclic.cli.main import app

ROOT = Path(__file__).resolve().parents[2]
SIMPLE = ROOT / "examples" / "rating" / "simple_set.toml"


def _size(*argv):
    return CliRunner().invoke(app, ["size", *[str(a) for a in argv]])


def _set_19_17_56(tmp_path: Path) -> Path:
    text = SIMPLE.read_text(encoding="utf-8")
    text = text.replace("teeth = { sun = 21, planet = 39, ring = 99 }", "teeth = { sun = 19, planet = 17, ring = 56 }")
    text = text.replace("profile_shift = { sun = 0.25, planet = 0.1, ring = -0.45 }", "")
    path = tmp_path / "set.toml"
    path.write_text(text, encoding="utf-8")
    return path


def test_the_bound_is_stated_before_the_result():
    result = _size(SIMPLE)
    assert result.exit_code == 0, result.stderr
    assert result.stderr.startswith("size: searching 41 ISO 54 modules 0.5 ... 50 mm for set 'P', b = 0.5 d_sun")
    assert "normal module" in result.stdout and "fitting conditions" in result.stdout and "pass" in result.stdout


def test_json_gives_module_width_shifts_and_fitting():
    data = json.loads(_size(SIMPLE, "--shifts", "balanced", "-f", "json").stdout)
    assert data["schema"] == "epicyclic-size/1" and data["fitting"]["passed"] is True
    assert data["face_width"] == 0.5 * 21 * data["module"]
    assert data["profile_shifts"]["sun"] == data["shift_choice"]["x_sun"]
    assert data["rating"]["ok"] is True


def test_a_set_that_cannot_be_built_is_refused_and_balanced_shifts_build_it(tmp_path):
    path = _set_19_17_56(tmp_path)
    refused = _size(path)
    assert refused.exit_code == 2 and "coaxiality" in refused.stderr and "--shifts balanced" in refused.stderr
    built = _size(path, "--shifts", "balanced", "-f", "markdown")
    assert built.exit_code == 0, built.stderr
    assert "| normal module |" in built.stdout


def test_bad_options_name_the_option_and_the_default(tmp_path):
    result = _size(SIMPLE, "--shifts", "even")
    assert result.exit_code == 2 and "--shifts must be 'given' or 'balanced', got 'even' (default 'given')" in \
        result.stderr
    result = _size(SIMPLE, "--face-width", "30", "--face-width-ratio", "0.5")
    assert result.exit_code == 2 and "not both" in result.stderr
    result = _size(SIMPLE, "--element", "Q")
    assert result.exit_code == 2 and "no planetary set 'Q'" in result.stderr
