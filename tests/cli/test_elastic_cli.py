"""``epicyclic vibration`` and ``epicyclic sharing`` on the example file, in every format."""

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from epicyclic.cli.main import app

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "elastic_simple_set.toml"


@pytest.mark.parametrize("command", ["vibration", "sharing"])
@pytest.mark.parametrize("fmt", ["table", "json", "markdown", "html"])
def test_formats(command, fmt):
    result = CliRunner().invoke(app, [command, str(EXAMPLE), "--format", fmt])
    assert result.exit_code == 0, result.output
    if fmt == "json":
        data = json.loads(result.stdout)   # strict JSON: no NaN or Infinity
        assert "P" in data["sets"]
    elif fmt == "html":
        assert result.stdout.startswith("<!DOCTYPE html>")
    else:
        assert ("natural modes" if command == "vibration" else "planet loads") in result.stdout


def test_vibration_lists_defaults_and_phasing():
    result = CliRunner().invoke(app, ["vibration", str(EXAMPLE), "--format", "json"])
    data = json.loads(result.stdout)["sets"]["P"]
    assert data["defaults_taken"] == ["sun mesh c_gamma_alpha b (ISO 6336-1, 9.3)",
                                      "ring mesh c_gamma_alpha b (ISO 6336-1, 9.3)"]
    # z_s = 21 with 3 planets: every mesh harmonic is a pure torque (Parker & Lin 2004)
    assert all(h["excites"] == ["rotational"] for h in data["phasing"]["harmonics"])
    assert all(2500.0 <= c["speed_rpm"] <= 3500.0 for c in data["campbell"]["crossings"])
    kinds = [m["type"] for m in data["modes"]["modes"]]
    assert kinds.count("translational") == 12 and kinds.count("rigid-body") == 1


def test_sharing_reports_the_computed_and_the_table_value(tmp_path):
    out = tmp_path / "loads.svg"
    result = CliRunner().invoke(app, ["sharing", str(EXAMPLE), "--format", "json", "--plot", str(out)])
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout.split("\nwrote")[0] if "wrote" in result.stdout else result.stdout)["sets"]["P"]
    assert data["loads"]["k_gamma"] > 1.0
    assert sum(data["loads"]["sun_mesh_N"]) == pytest.approx(60.0 / (21 * 1.75 * 0.9396926207859084 / 2e3), rel=1e-3)
    assert data["monte_carlo"]["seed"] == 0 and data["monte_carlo"]["draws"] == 10000
    assert any("IEC 61400-4" in n for n in data["notes"])
    assert data["face_load"]["sun"]["k_hbeta"] > 1.0 and data["face_load"]["ring"]["k_hbeta"] > 1.0
    assert out.exists() and out.stat().st_size > 1000
    assert (tmp_path / "loads-face.svg").stat().st_size > 1000     # [elastic.face]: the face load too
