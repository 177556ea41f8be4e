"""Hardness with its scale: Z_W takes HB (ISO 6336-2:2006, clause 12), converted by ASTM E140-12b, Table 1.

Defect of issue 28: Z_W took a Vickers hardness as Brinell (a 300 HV through-hardened 42CrMo4 ring gave
Z_W = 1.2 − (300 − 130)/1700 = 1.100 instead of the 284 HB it is).
"""

import pytest
from hypothesis import given
from hypothesis import strategies as st

from epicyclic.rating import RatingError, flank, material
from epicyclic.rating.hardness import convert_hardness
from epicyclic.rating.materials import Material

# ASTM E140-12b, Table 1 (non-austenitic steels) rows: HRC, HV, HBW
ROWS = [(20, 238, 226), (30, 302, 286), (40, 392, 371), (50, 513, 481)]


@pytest.mark.parametrize(("hrc", "hv", "hb"), ROWS)
def test_table_rows(hrc, hv, hb):
    assert convert_hardness(hv, "HV", "HB") == hb and convert_hardness(hrc, "HRC", "HV") == hv
    assert convert_hardness(hb, "HB", "HRC") == hrc


def test_z_w_takes_a_vickers_hardness_as_brinell_no_more():
    ring = material("42CrMo4")  # the data file's 300 HV (the ISO 6336-5 line of "V" is drawn in HV)
    assert (ring.hardness, ring.hardness_scale) == (300.0, "HV")
    hb = 253 + (300 - 266) / (302 - 266) * (286 - 253)  # E140 Table 1 between 25 and 30 HRC: 284.2 HBW
    assert flank.work_hardening_factor(material("18CrNiMo7-6"), ring) == pytest.approx(1.2 - (hb - 130) / 1700)
    assert flank.work_hardening_factor(material("18CrNiMo7-6"), ring) != pytest.approx(1.1)
    brinell = Material("34CrNiMo6", "V", 700, 290, hardness=240, hardness_scale="HB")
    assert flank.work_hardening_factor(material("18CrNiMo7-6"), brinell) == pytest.approx(1.2 - 110 / 1700)


@pytest.mark.parametrize(("kwargs", "message"), [
    ({"hardness": 240}, "hardness 240 has no scale; give hardness_scale = 'HB'"),
    ({}, "no hardness is given"),
    ({"hardness": 700, "hardness_scale": "HV"}, "outside the conversion table of ASTM E140"),
])
def test_a_hardness_without_scale_or_table_is_refused(kwargs, message):
    soft = Material("MySteel", "V", 700, 290, **kwargs)
    with pytest.raises(RatingError, match=message):
        flank.work_hardening_factor(material("18CrNiMo7-6"), soft)


def test_unknown_scale():
    with pytest.raises(RatingError, match="hardness_scale must be one of HB, HV, HRC"):
        Material("MySteel", "V", 700, 290, hardness=240, hardness_scale="HBW")


@given(st.floats(238, 697), st.floats(0, 100))
def test_conversion_is_monotone_and_invertible(hv, step):
    hb = convert_hardness(hv, "HV", "HB")
    assert convert_hardness(hb, "HB", "HV") == pytest.approx(hv)
    assert convert_hardness(min(hv + step, 697), "HV", "HB") >= hb


def test_a_user_material_in_a_file_needs_its_scale(tmp_path):
    from pathlib import Path

    from typer.testing import CliRunner

    from epicyclic.cli.main import app

    text = (Path(__file__).resolve().parents[2] / "examples" / "rating" / "simple_set.toml").read_text()
    text = text.replace('ring = "42CrMo4" }', 'ring = "MySteel" }')
    user = '\n[rating.materials.MySteel]\ntreatment = "V"\nsigma_Hlim = 760.0\nsigma_Flim = 310.0\nhardness = 300.0\n'
    text = text.replace("\n[operating_point]", user + "\n[operating_point]")
    path = tmp_path / "user.toml"
    path.write_text(text)
    result = CliRunner().invoke(app, ["rate", str(path)])
    assert result.exit_code == 2 and "hardness 300 has no scale; give hardness_scale" in result.output
    path.write_text(text.replace("hardness = 300.0\n", 'hardness = 300.0\nhardness_scale = "HV"\n'))
    assert CliRunner().invoke(app, ["rate", str(path)]).exit_code == 0
