"""The rating travels with the design: ISO 6336 inputs read from and written to REXS standard attributes.

The FVA planetary stage exported by FVA-Workbench 7.1 (``FVA_Planetary_stage_-_Minus_gearing_1.1_vers2.rexsj``,
github.com/fva-net/rexs-api-java, Apache-2.0; REXS 1.4) gives on every ``cylindrical_stage``
``application_factor_iso_6336_2006 = 1.25`` and ``mesh_load_factor_iso_6336_2019 = 1.0``; on the gears
``endurance_limit_flank``/``_root`` (sun and planets 1500/461 N/mm², ring 740.64/306 N/mm²), R_z 5/20 µm; on the
materials ``surface_hardness_vickers = 750``; on the gear unit ``operating_time = 100 000 h``; and a helix and a
profile crowning of 5 µm on the sun's flanks.  Attribute names: REXS 1.7 database (``rexs_schema_1.7.xml``).
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest
from typer.testing import CliRunner

from epicyclic.cli.main import app
from epicyclic.exchange import loads_rexs_document
from epicyclic.exchange.convert import rexs_text
from epicyclic.exchange.validate import validate_rexs
from epicyclic.io import InputFileError, load_train_file
from epicyclic.io.rating_format import side_rating

FIXTURES = Path(__file__).parent / "fixtures"
ROOT = Path(__file__).resolve().parents[2]
VERS2 = FIXTURES / "FVA_Planetary_stage_-_Minus_gearing_1.1_vers2.rexsj"
STAGE = ROOT / "examples" / "rexs" / "FVA_Planetary_stage_-_Minus_gearing_1.1.rexs"
DATE = "2026-01-01T00:00:00+00:00"


def _rate(*argv):
    result = CliRunner().invoke(app, ["rate", *[str(a) for a in argv]])
    return result


def test_the_files_application_factor_is_used():
    # defect: K_A = 1.25 on every mesh was rated with K_A = 1.0 "(given)"
    result = _rate(VERS2, "-f", "json")
    data = json.loads(result.stdout)
    assert data["inputs"]["application_factor"] == 1.25
    for mesh in data["ratings"][0]["meshes"]:
        assert mesh["factors"]["K_A"]["value"] == 1.25


def test_the_files_materials_are_used_not_the_table():
    # defect: the file's hardness and sigma_Flim were replaced by the data file's values (700 HV, 425 N/mm^2)
    spec = load_train_file(VERS2).rating
    sun, ring = spec.material_of("Planetary stage [9]", "sun"), spec.material_of("Planetary stage [9]", "ring")
    # with sigma_Hlim and sigma_Flim given, the hardness serves Z_W, which takes HB: the file's surface_hardness_brinell
    assert (sun.treatment, sun.hardness, sun.hardness_scale, sun.sigma_Hlim, sun.sigma_Flim, sun.E) == (
        "Eh", 693.5, "HB", 1500.0, 461.0, 210000.0)
    assert (ring.treatment, ring.hardness, ring.hardness_scale, ring.sigma_Hlim, ring.sigma_Flim) == (
        "V", 266.0, "HB", 740.64, 306.0)
    assert spec.life == 100000.0 and spec.load_sharing == 1.0


def test_crowning_is_listed_as_ignored():
    # defect: the crowning was dropped silently while K_Hbeta came from method C
    result = _rate(VERS2)
    assert "Inputs given but not used" in result.stdout
    assert "helix crowning" in result.stdout and "helix_crowning_amount_datum_face = 5 µm" in result.stdout
    data = json.loads(_rate(VERS2, "-f", "json").stdout)
    assert any("profile crowning" in item for item in data["inputs"]["ignored"])


def test_k_a_scales_the_stresses_as_the_standard_says(tmp_path):
    # closed form (ISO 6336-2:2019, eq. (1); -3, eq. (3)): sigma_H / sqrt(K_A K_v K_Hbeta K_Halpha) and
    # sigma_F / (K_A K_v K_Fbeta K_Falpha) do not depend on K_A
    side = tmp_path / "rating.toml"
    side.write_text("[rating]\napplication_factor = 1.0\n", encoding="utf-8")
    f = load_train_file(VERS2)
    from epicyclic.rating.train import rate_solution

    def stresses(spec):
        out = []
        for m in rate_solution(f.solve(), f.geometry, spec).meshes:
            k = {key: float(m.factors[key].value) for key in ("K_A", "K_v", "K_Hbeta", "K_Halpha", "K_Fbeta",
                                                            "K_Falpha")}
            for g in m.gears:
                h, r = float(g.factors["sigma_H"].value), float(g.factors["sigma_F"].value)
                out.extend((h / math.sqrt(k["K_A"] * k["K_v"] * k["K_Hbeta"] * k["K_Halpha"]),
                            r / (k["K_A"] * k["K_v"] * k["K_Fbeta"] * k["K_Falpha"])))
        return out

    given, unit = stresses(f.rating), stresses(side_rating(f, side).rating)
    assert side_rating(f, side).rating.application_factor == 1.0
    assert given == pytest.approx(unit, rel=1e-9)


def test_standard_attributes_win_over_the_custom_copy():
    f = load_train_file(ROOT / "examples" / "rating" / "simple_set.toml")
    text = rexs_text(f, "xml", DATE)
    assert validate_rexs(text, "xml") == []
    assert 'id="application_factor_iso_6336_2019" unit="none">1.25<' in text
    assert 'id="allowable_stress_number_tooth_root_iso_6336_2016"' in text
    edited = text.replace('id="application_factor_iso_6336_2019" unit="none">1.25<',
                          'id="application_factor_iso_6336_2019" unit="none">1.5<')
    doc = loads_rexs_document(edited.encode(), "edited.rexs")
    assert doc.data["rating"]["application_factor"] == 1.5
    assert any("application_factor" in n and "standard attributes are used" in n for n in doc.notes)


def test_written_rating_reads_back_the_same():
    f = load_train_file(ROOT / "examples" / "rating" / "simple_set.toml")
    for kind in ("xml", "json"):
        text = rexs_text(f, kind, DATE)
        assert validate_rexs(text, kind) == []
        doc = loads_rexs_document(text.encode(), f"written.{kind}")
        assert doc.rating_inputs["application_factor"] == f.rating.application_factor
        assert doc.rating_inputs["flank_roughness"] == f.rating.flank_roughness
        assert doc.rating_inputs["accuracy_grade"] == f.rating.accuracy_grade
        assert doc.rating_inputs["material"]["P:ring"] == "42CrMo4"
        assert doc.rating_inputs["tool_tip_radius"] == f.rating.tool_tip_radius
        assert doc.rating_inputs["cutter"]["teeth"] == f.rating.cutter.teeth == 25  # the ring's cutter_wheel_tool
        from epicyclic.io.toml_format import read_document

        assert read_document(doc).rating.cutter == f.rating.cutter


def test_a_model_without_rating_inputs_is_rated_with_a_side_file(tmp_path):
    result = _rate(STAGE)
    assert result.exit_code == 2 and "--rating RATING.toml" in result.stderr
    side = tmp_path / "rating.toml"
    side.write_text('[rating]\nmaterial = "18CrNiMo7-6"\nflank_roughness = 4.0\nroot_roughness = 12.0\n',
                    encoding="utf-8")
    result = _rate(STAGE, "--rating", side)
    assert result.exit_code == 0, result.stderr
    assert "Planetenstufe [9]" in result.stdout


def test_a_side_file_without_rating_is_refused(tmp_path):
    side = tmp_path / "rating.toml"
    side.write_text('[lubricant]\nviscosity_40 = 100.0\n', encoding="utf-8")
    with pytest.raises(InputFileError, match=r"rating\.toml: \[rating\]: the side file has no \[rating\] table"):
        side_rating(load_train_file(STAGE), side)
    side.write_text('[rating]\nmaterial = "18CrNiMo7-6"\nflank_roughnes = 4.0\n', encoding="utf-8")
    with pytest.raises(InputFileError, match="did you mean 'flank_roughness'"):
        side_rating(load_train_file(STAGE), side)


def test_a_toml_duty_cycle_is_written_as_a_load_spectrum():
    from epicyclic.exchange.container import read_model
    from epicyclic.io.duty_format import analyse_file_duty_cycle

    f = load_train_file(ROOT / "examples" / "rating" / "simple_set_duty_cycle.toml")
    text = rexs_text(f, "xml", DATE)
    assert validate_rexs(text, "xml") == []
    model = read_model(text.encode(), "cycle.rexs")
    assert len(model.load_cases) == 4  # one load_case per [[duty_cycle.case]]
    doc = loads_rexs_document(text.encode(), "cycle.rexs")
    assert [c.duration_fraction for c in doc.load_cases] == pytest.approx([0.05, 0.25, 0.5, 0.2])
    assert doc.data["operating_point"]["torques"] == {"in": "600 N*m"}  # the file's point, not the first case
    back = analyse_file_duty_cycle(load_train_file_from(doc))
    given = analyse_file_duty_cycle(f)
    assert back.to_dict()["cycle"] == given.to_dict()["cycle"]
    assert [d["D_H"] for d in back.to_dict()["damage"]] == pytest.approx([d["D_H"] for d in given.to_dict()["damage"]])


def test_the_load_cases_win_over_the_custom_duty_cycle():
    f = load_train_file(ROOT / "examples" / "rating" / "simple_set_duty_cycle.toml")
    text = rexs_text(f, "xml", DATE)
    peak = 'id="torque_around_u_axis" unit="N m">750.0<'
    assert peak in text
    doc = loads_rexs_document(text.replace(peak, 'id="torque_around_u_axis" unit="N m">900.0<', 1).encode(), "e.rexs")
    assert doc.data["duty_cycle"]["case"][0]["name"] == "peak"
    assert "900" in json.dumps(doc.data["duty_cycle"]["case"][0]["torques"])


def load_train_file_from(doc):
    from epicyclic.io.toml_format import read_document

    return read_document(doc)


def test_factors_that_differ_between_meshes_are_read_per_mesh():
    f = load_train_file(ROOT / "examples" / "rating" / "simple_set.toml")
    data = json.loads(rexs_text(f, "json", DATE))
    for c in data["model"]["components"]:
        if c["type"] == "cylindrical_stage" and c["name"].endswith("-ring"):
            for a in c["attributes"]:
                if a["id"] == "application_factor_iso_6336_2019":
                    a["floating_point"] = 1.5
    doc = loads_rexs_document(json.dumps(data).encode(), "meshes.rexsj")
    assert doc.data["rating"]["application_factor"] == {"P:sun-planet": 1.25, "P:planet-ring": 1.5}
    from epicyclic.io.toml_format import read_document
    from epicyclic.rating.train import rate_solution

    g = read_document(doc)
    rating = rate_solution(g.solve(), g.geometry, g.rating)
    assert {m.mesh: float(m.factors["K_A"].value) for m in rating.meshes} == {"sun-planet": 1.25, "planet-ring": 1.5}


def test_planet_bearings_travel_as_catalogue_bearings():
    from epicyclic.exchange.container import read_model
    from epicyclic.io.toml_format import read_document

    f = load_train_file(ROOT / "examples" / "rating" / "simple_set_duty_cycle.toml")
    text = rexs_text(f, "xml", DATE)
    bearings = [c for c in read_model(text.encode(), "b.rexs").components.values()
                if c.type == "rolling_bearing_with_catalog_geometry"]
    assert len(bearings) == 3  # one per planet
    assert float(bearings[0].attributes["radial_dynamic_load_rating"].value) == 120.0  # kN
    assert bearings[0].attributes["bearing_type"].value == "radial_roller_bearing"
    doc = loads_rexs_document(text.encode(), "b.rexs")
    planet = doc.data["planetary"][0]["bearings"]["planet"]
    # the same REXS enum as the set's losses.bearing type: that (finer) type stays the planet bearing's
    assert planet["dynamic_load_rating"] == 120000.0 and "type" not in planet
    assert read_document(doc).bearings["P"]["planet"].type == "cylindrical roller full complement"
    edited = text.replace('id="radial_dynamic_load_rating" unit="kN">120.0<', 'id="radial_dynamic_load_rating" unit="kN">'
                          '90.0<')
    doc = loads_rexs_document(edited.encode(), "b.rexs")
    assert doc.data["planetary"][0]["bearings"]["planet"]["dynamic_load_rating"] == 90000.0
    assert read_document(doc).bearings["P"]["planet"].dynamic_load_rating == 90000.0
