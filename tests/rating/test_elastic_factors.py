"""K_γ and K_Hβ of `epicyclic rate` computed by the elastic model where [elastic] rating asks for them."""

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from epicyclic.cli.main import app
from epicyclic.elastic import HelixModification, PlanetErrors, face_load, load_sharing
from epicyclic.elastic.from_geometry import lumped_model
from epicyclic.io import load_train_file
from epicyclic.rating.elastic_factors import with_elastic_factors
from epicyclic.rating.errors import RatingError

BASE = (Path(__file__).resolve().parents[2] / "examples" / "rating" / "simple_set.toml").read_text(encoding="utf-8")
ELASTIC = """
[elastic]
rating = ["load_sharing", "K_Hbeta"]
sun_support = 100.0
[elastic.errors]
pin_tangential = [15.0, 0.0, -5.0]
[elastic.face]
misalignment = 10.0
crowning = 5.0
sun_torsion = false
"""


def _file(tmp_path, text):
    path = tmp_path / "rate.toml"
    path.write_text(text, encoding="utf-8")
    return path


def test_rate_takes_the_computed_factors_with_their_source(tmp_path):
    path = _file(tmp_path, BASE.replace("load_sharing = 1.0", "") + ELASTIC)
    result = CliRunner().invoke(app, ["rate", str(path), "--format", "json"])
    assert result.exit_code == 0, result.output
    meshes = json.loads(result.stdout)["ratings"][0]["meshes"]
    # the same numbers straight from the elastic model at the file's sun torque
    f = load_train_file(path)
    geometry = f.geometry["P"]
    model, _ = lumped_model(geometry, f.elastic.spec)
    torque = abs(f.solve().elements["P"].torques["sun"])
    loads = load_sharing(model, torque, PlanetErrors(pin_tangential=(15.0, 0.0, -5.0)))
    k_a = f.rating.application_factor
    for mesh, k, force in zip(meshes, (model.sun_mesh, model.ring_mesh),
                              (loads.sun_mesh.max(), loads.ring_mesh[loads.sun_mesh.argmax()])):
        assert mesh["factors"]["K_gamma"]["value"] == pytest.approx(loads.k_gamma, rel=1e-12)
        assert mesh["factors"]["K_gamma"]["source"] == "computed by the elastic model"
        b = geometry.mesh_face_width(geometry.sun_mesh if mesh["mesh"] == "sun-planet" else geometry.ring_mesh)
        expected = face_load(force * k_a, b, 0.85 * k / (b * 1e6), misalignment=10.0,
                             modification=HelixModification(crowning=5.0)).k_hbeta
        assert mesh["factors"]["K_Hbeta"]["value"] == pytest.approx(expected, rel=1e-12)
        assert mesh["factors"]["K_Hbeta"]["source"] == "computed by the elastic model"
        assert expected > 1.0


def test_error_free_set_shares_equally(tmp_path):
    path = _file(tmp_path, BASE.replace("load_sharing = 1.0", "") + '[elastic]\nrating = ["load_sharing"]\n')
    f = load_train_file(path)
    spec = with_elastic_factors(f.rating, f.geometry, f.elastic, f.solve(), f.elastic.rating)
    assert spec.load_sharing["P"].value == 1.0 and spec.K_Hbeta is None


def test_given_and_asked_is_refused(tmp_path):
    path = _file(tmp_path, BASE + '[elastic]\nrating = ["load_sharing"]\n')
    f = load_train_file(path)
    with pytest.raises(RatingError, match="give one of them"):
        with_elastic_factors(f.rating, f.geometry, f.elastic, f.solve(), f.elastic.rating)
    result = CliRunner().invoke(app, ["rate", str(path)])
    assert result.exit_code == 2 and "give one of them" in result.stderr
