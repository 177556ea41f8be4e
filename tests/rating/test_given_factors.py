"""Load factors given per mesh or computed, the deviations per gear, and where each value comes from.

Defects of issue 28 each checked here (they failed before the change): one K_v and one K_Hβ per file
while the sun–planet and planet–ring meshes of a planetary stage differ; no way to give K_Hα or the
pitch and profile deviations; K_A 1.0 labelled "given" where nothing was given.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from epicyclic.cli.main import app
from epicyclic.geometry import BasicRack, GearGeometry, MeshGeometry
from epicyclic.rating import MeshInput, RatingError, RatingSpec, rate_mesh
from epicyclic.rating.given_factors import FactorValue, check_given, mesh_factor

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "rating" / "simple_set.toml"
BASE = EXAMPLE.read_text(encoding="utf-8")
runner = CliRunner()
PAIR = MeshGeometry(GearGeometry(19, BasicRack(4.0), 0.5), GearGeometry(104, BasicRack(4.0), 0.15)).with_tip_shortening()


def _rate(tmp_path, extra: str, *, drop: str = "") -> dict:
    text = BASE.replace("load_sharing = 1.0        # K_gamma: three planets with a floating sun",
                        "load_sharing = 1.0\n" + extra)
    if drop:
        text = text.replace(drop, "")
    path = tmp_path / "rated.toml"
    path.write_text(text, encoding="utf-8")
    result = runner.invoke(app, ["rate", str(path), "-f", "json"])
    assert result.exit_code == 0, result.output
    return {m["mesh"]: m for m in json.loads(result.stdout)["ratings"][0]["meshes"]}


def _bad(tmp_path, extra: str) -> str:
    text = BASE.replace("load_sharing = 1.0        # K_gamma: three planets with a floating sun", extra)
    path = tmp_path / "bad.toml"
    path.write_text(text, encoding="utf-8")
    result = runner.invoke(app, ["rate", str(path)])
    assert result.exit_code == 2, result.output
    return result.output


def test_dynamic_and_face_load_factors_per_mesh(tmp_path):
    meshes = _rate(tmp_path, 'K_v = { "sun-planet" = 1.05, "planet-ring" = 1.08 }\nK_Hbeta = { "planet-ring" = 1.3 }')
    sun, ring = meshes["sun-planet"]["factors"], meshes["planet-ring"]["factors"]
    assert (sun["K_v"]["value"], ring["K_v"]["value"]) == (1.05, 1.08)
    assert sun["K_v"]["source"] == ring["K_v"]["source"] == "given" and "(given)" in sun["K_v"]["clause"]
    assert ring["K_Hbeta"]["value"] == 1.3 and ring["K_Hbeta"]["source"] == "given"
    assert sun["K_Hbeta"]["source"] == "computed" and "7.6 (method C)" in sun["K_Hbeta"]["clause"]
    assert ring["K_Fbeta"]["source"] == "computed" and ring["K_Fbeta"]["value"] < 1.3  # K_Hβ^N_F of the given one


def test_every_load_factor_says_given_or_computed(tmp_path):
    meshes = _rate(tmp_path, "", drop="application_factor = 1.25\n")
    factors = meshes["sun-planet"]["factors"]
    assert factors["K_A"] == {**factors["K_A"], "value": 1.0, "source": "default"}  # not "given": nothing was
    assert factors["K_gamma"]["source"] == "given"  # load_sharing = 1.0 of [rating]
    for symbol in ("K_v", "K_Hbeta", "K_Fbeta", "K_Halpha", "K_Falpha", "f_pb", "f_falpha", "f_Hbeta"):
        assert factors[symbol]["source"] == "computed", symbol
    assert "ISO 1328-1:2013, grade 6" in factors["f_pb"]["clause"] and factors["f_pb"]["unit"] == "µm"
    assert factors["Z_H"]["source"] == "computed" and "source" not in factors["F_t"]  # data carry none
    sun = meshes["sun-planet"]["gears"]["sun"]
    assert sun["S_H"]["source"] == "computed" and sun["sigma_Hlim"]["source"] == "material"


def test_transverse_load_factors_given(tmp_path):
    meshes = _rate(tmp_path, 'K_Halpha = { "sun-planet" = 1.2 }\nK_Falpha = { "planet-ring" = 1.15 }')
    sun, ring = meshes["sun-planet"]["factors"], meshes["planet-ring"]["factors"]
    assert sun["K_Halpha"]["value"] == sun["K_Falpha"]["value"] == 1.2  # K_Fα = K_Hα where only K_Hα is given
    assert "K_Falpha = K_Halpha" in sun["K_Falpha"]["clause"]
    assert ring["K_Falpha"]["value"] == 1.15 and ring["K_Halpha"]["source"] == "computed"


def test_measured_deviations_per_gear_raise_k_v(tmp_path):
    plain = _rate(tmp_path, "")["planet-ring"]["factors"]
    rough = _rate(tmp_path, "f_pb = { ring = 25.0 }\nf_falpha = 20.0")["planet-ring"]["factors"]
    assert rough["f_pb"]["value"] == 25.0 and rough["f_pb"]["source"].startswith("given (gear 2)")
    assert rough["f_falpha"]["source"] == "given"
    assert rough["K_v"]["value"] > plain["K_v"]["value"]


def test_accuracy_edition_and_grade_per_gear(tmp_path):
    old = _rate(tmp_path, 'accuracy_standard = "1995"\naccuracy_grade = { sun = 5, all = 7 }',
                drop="accuracy_grade = 6\n")["sun-planet"]["factors"]
    assert "ISO 1328-1:1995, grade 5/7" in old["f_pb"]["clause"]


@pytest.mark.parametrize(("extra", "message"), [
    ('K_v = { "sun-plnet" = 1.05 }', "rating.K_v: 'sun-plnet' names no mesh of the rated train; accepted keys"),
    ("K_Hbeta = 0.9", "rating.K_Hbeta must be a number >= 1"),
    ('K_v = { "planet-ring" = 0.95 }', "rating.K_v.planet-ring must be a number >= 1"),
    ("f_pb = -3.0", "rating.f_pb must be a number >= 0 (a deviation in µm)"),
    ('accuracy_standard = "1997"', "rating.accuracy_standard must be one of '1995', '2013'"),
    ("f_pb = { moon = 8.0 }", "rating.f_pb: 'moon' names no gear"),
    ("K_Halfa = 1.1", "unknown key 'K_Halfa'"),
    ('K_v = "fast"', "K_v"),
    ('f_pb = "12 um"', "key 'f_pb': takes a plain number in µm, without a unit"),
    ('K_v = { "sun-planet" = "1.05 N" }', "takes a plain number in 1 (a factor)"),
])
def test_bad_factors_name_the_key_and_what_is_accepted(tmp_path, extra, message):
    assert message in _bad(tmp_path, extra)


def test_a_third_source_plugs_in():
    # an elastic model of the carrier computes K_Hβ of one mesh: its value, source and clause travel unchanged
    elastic = FactorValue(1.23, "computed by the elastic model", "ISO 6336-1:2019, 7.3 (method A)")
    spec = RatingSpec(K_Hbeta={"P:planet-ring": elastic, "all": 1.1})
    assert spec.given_factor("K_Hbeta", "P", "planet-ring") is elastic
    assert spec.given_factor("K_Hbeta", "P", "sun-planet").value == 1.1
    assert spec.given_factor("K_v", "P", "sun-planet") is None
    with pytest.raises(RatingError, match="source must name"):
        FactorValue(1.2, "")


@settings(max_examples=20, deadline=None)
@given(st.floats(1.0, 3.0), st.floats(0.0, 0.5))
def test_safety_falls_as_a_given_factor_rises(k, step):
    def rated(k_hbeta):
        spec = RatingSpec(material="18CrNiMo7-6", flank_roughness=3.0, root_roughness=10.0, viscosity_40=100.0,
                          K_Hbeta=k_hbeta)
        return rate_mesh(MeshInput("pair", PAIR, 30.0, ("pinion", "wheel"), spec), 400.0, 1500.0)

    low, high = rated(k), rated(k + step)
    assert high.S_H <= low.S_H and high.S_F <= low.S_F


def test_mesh_lookup_order():
    table = check_given({"P:sun-planet": 1.3, "sun-planet": 1.2, "P": 1.1, "all": 1.05}, "K_v")
    assert [mesh_factor(table, e, m).value for e, m in
            (("P", "sun-planet"), ("Q", "sun-planet"), ("P", "planet-ring"), ("Q", "planet-ring"))] == [
        1.3, 1.2, 1.1, 1.05]


@settings(max_examples=20, deadline=None)
@given(st.floats(0.0, 60.0), st.floats(0.0, 30.0))
def test_k_v_rises_with_a_measured_base_pitch_deviation(f_pb, step):
    def k_v(value):
        spec = RatingSpec(material="18CrNiMo7-6", flank_roughness=3.0, root_roughness=10.0, viscosity_40=100.0,
                          K_Hbeta=1.2, f_pb=value)
        return rate_mesh(MeshInput("pair", PAIR, 30.0, ("pinion", "wheel"), spec), 400.0, 3000.0)["K_v"]

    assert k_v(f_pb + step) >= k_v(f_pb) - 1e-12


def test_measured_deviations_need_no_grade_where_the_grade_has_no_tolerance():
    # m_n = 0.3 mm lies outside ISO 1328-1 (0.5 ... 70 mm): from the grade an error naming the key; all three
    # deviations measured: rated
    small = MeshGeometry(GearGeometry(20, BasicRack(0.3), 0.0), GearGeometry(40, BasicRack(0.3), 0.0))
    base = {"material": "18CrNiMo7-6", "flank_roughness": 3.0, "root_roughness": 10.0, "viscosity_40": 100.0}
    with pytest.raises(RatingError, match="rating.accuracy_grade: accuracy: the normal module 0.3 mm lies outside"):
        MeshInput("pair", small, 3.0, ("pinion", "wheel"), RatingSpec(**base))
    spec = RatingSpec(**base, f_pb=3.0, f_falpha=3.0, f_Hbeta=4.0)
    rating = rate_mesh(MeshInput("pair", small, 3.0, ("pinion", "wheel"), spec), 0.5, 3000.0)
    assert rating.factors["f_pb"].source == "given" and rating["f_Hbeta"] == 4.0
