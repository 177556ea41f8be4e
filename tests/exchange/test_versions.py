"""REXS 2.0.0 (issue 31): written 2.0.0 validates and uses 2.0.0's ids and units; 1.7 → 2.0.0 → 1.7 is lossless.

The 2.0.0 ids and units are checked against the FVA's REXS 2.0.0 database
(``fixtures/rexs_2.0.0_database_excerpt.json``, from ``rexs_schema_2.0.0.xml``, fva-net/rexs-api-java);
the XML against the FVA's file schema of its 2.0 API (``rexs-file.xsd``). The FVA has published no
2.0.0 example models (fva-net/rexs-api-java holds 1.0–1.4 models only), so the public 1.x models are
upgraded here with the changelog's renames and read as 2.0.0.
"""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from epicyclic.exchange.container import read_model
from epicyclic.exchange.convert import convert, rexs_text
from epicyclic.exchange.validate import validate_rexs
from epicyclic.exchange.versions import RexsVersionError, check_version, written_attribute
from epicyclic.io import load_train_file

from .test_roundtrip import DATE, EXAMPLES, FIXTURES, ROOT, fingerprint, same

TABLE = json.loads((ROOT / "src" / "epicyclic" / "exchange" / "schema" / "rexs_1.7_to_2.0.0.json")
                   .read_text(encoding="utf-8"))
PICKED = [e for e in EXAMPLES if e.name in (
    "zf_8hp70_geometry.toml", "brandenberger_1952.toml", "wolfrom_drive.toml", "geometry_stepped_set.toml",
    "simple_set_duty_cycle.toml", "FVA-Industriegetriebe_2stufig_1-4.rexs",
    "FVA_Planetary_stage_-_Minus_gearing_1.1.rexs")]


@pytest.mark.parametrize("example", PICKED, ids=lambda p: p.name)
@pytest.mark.parametrize("kind, suffix", [("xml", ".rexs"), ("json", ".rexsj")])
def test_1_7_to_2_0_to_1_7_is_lossless(example, kind, suffix, tmp_path):
    first = load_train_file(example)
    text_17 = rexs_text(first, kind, DATE)
    path_17 = tmp_path / f"a{suffix}"
    path_17.write_text(text_17, encoding="utf-8")
    read_17 = load_train_file(path_17)
    text_20 = rexs_text(read_17, kind, DATE, rexs_version="2.0.0")
    assert validate_rexs(text_20, kind) == []
    path_20 = tmp_path / f"b{suffix}"
    path_20.write_text(text_20, encoding="utf-8")
    back = load_train_file(path_20)
    assert back.exchange.version == "2.0.0"
    # every byte of what the 1.7 file writes again as 1.7 (a TOML's kW -> W -> kW may move the last digit once)
    assert rexs_text(back, kind, DATE) == rexs_text(read_17, kind, DATE)
    same(fingerprint(first), fingerprint(back))


def _raw_attributes(text: str):
    """(component type, attribute id, unit) of an XML text, read with ElementTree (no translation)."""
    root = ET.fromstring(text)
    types = {c.get("id"): c.get("type") for c in root.iter("component")}
    for c in root.iter("component"):
        for a in c.iter("attribute"):
            yield types[c.get("id")], a.get("id"), a.get("unit")


@pytest.mark.parametrize("example", PICKED, ids=lambda p: p.name)
def test_written_2_0_uses_the_2_0_database(example):
    database = json.loads((FIXTURES / "rexs_2.0.0_database_excerpt.json").read_text(encoding="utf-8"))
    text = rexs_text(load_train_file(example), "xml", DATE, rexs_version="2.0")
    assert ET.fromstring(text).get("version") == "2.0.0"
    for ctype, aid, unit in _raw_attributes(text):
        if aid.startswith("custom_"):
            continue
        known = database["components"][ctype]
        assert aid in known, (ctype, aid)
        assert (unit if unit != "none" else "none") == known[aid][1], (ctype, aid, unit)
        assert unit != "°"
    root = ET.fromstring(text)
    for r in root.iter("relation"):
        assert {ref.get("role") for ref in r.iter("ref")} <= set(database["relations"][r.get("type")]), r.get("type")


def _upgrade(text: str) -> str:
    """A 1.x XML model as 2.0.0 by the FVA changelog's attribute renames, unit and enum changes."""
    root = ET.fromstring(text)
    root.set("version", "2.0.0")
    for a in root.iter("attribute"):
        new = TABLE["attribute_ids"].get(a.get("id"), a.get("id"))
        a.set("id", new)
        if a.get("unit") == "°":
            a.set("unit", "deg")
        if new in TABLE["enum_values"] and a.text in TABLE["enum_values"][new]:
            a.text = TABLE["enum_values"][new][a.text]
    return ET.tostring(root, encoding="unicode")


@pytest.mark.parametrize("name", ["FVA_Planetary_stage_-_Minus_gearing_1.1.rexs", "FVA-Industriegetriebe_2stufig_1-4.rexs",
                                  "SEW_3-stage_cylindrical_gearbox_1.0.rexs"])
def test_public_models_upgraded_to_2_0_read_the_same(name, tmp_path):
    source = next(p for p in (ROOT / "examples" / "rexs" / name, FIXTURES / name) if p.exists())
    original = load_train_file(source)
    upgraded = tmp_path / name
    text = _upgrade(source.read_text(encoding="utf-8"))
    upgraded.write_text(text, encoding="utf-8")
    again = load_train_file(upgraded)
    assert again.exchange.version == "2.0.0"
    if original.operating_point is not None:
        same(fingerprint(original), fingerprint(again))
    assert again.exchange.data == original.exchange.data


def test_renamed_roughness_and_unit_spelling():
    # rexs_changelog_1.7_to_2.0.0.xml: R_z flank/root renamed to the ISO 4287:1997 ids; no '°' in 2.0.0
    assert TABLE["attribute_ids"]["averaged_peak_to_valley_height_flank"] == \
        "mean_peak_to_valley_roughness_flank_iso_4287_1997"
    assert written_attribute("averaged_peak_to_valley_height_root", "mum", 6.0, "2.0.0")[0] == \
        "mean_peak_to_valley_roughness_root_iso_4287_1997"
    assert written_attribute("helix_angle_reference_diameter", "°", 12.0, "2.0.0") == \
        ("helix_angle_reference_diameter", "deg", 12.0)
    assert written_attribute("helix_angle_reference_diameter", "°", 12.0, "1.7")[1] == "°"
    flash = next(a for a, (old, new) in TABLE["units"].items() if (old, new) == ("C", "K"))
    assert written_attribute(flash, "C", 100.0, "2.0.0") == (flash, "K", pytest.approx(373.15))


@pytest.mark.parametrize("version", ["3.0", "1.8", "", "DEV", "2.1.0"])
def test_an_unknown_version_is_refused(version):
    text = f'<model version="{version}" applicationId="x" applicationVersion="1" date="d"/>'.encode()
    with pytest.raises(RexsVersionError, match="reads 1.0 … 1.7 and 2.0.0"):
        read_model(text, "m.rexs")
    assert check_version("2.0", "m") == "2.0.0"


def test_convert_rexs_version_option(tmp_path):
    source = ROOT / "examples" / "brandenberger_1952.toml"
    line = convert(source, tmp_path / "a.rexsj", DATE, rexs_version="2.0")
    assert "REXS 2.0.0 JSON" in line
    assert json.loads((tmp_path / "a.rexsj").read_text())["model"]["version"] == "2.0.0"
    with pytest.raises(Exception, match="REXS 1.7 or 2.0.0"):
        convert(source, tmp_path / "b.rexs", DATE, rexs_version="1.5")
    with pytest.raises(Exception, match="applies to .rexs"):
        convert(source, tmp_path / "b.toml", DATE, rexs_version="2.0")
