"""Tooth flank fracture and the hardened layer (epicyclic.rating.flank_fracture).

The text of ISO/TS 6336-4:2019 (its local equivalent stress, clause 6.2; residual stresses, 6.3;
the hardness-to-strength conversion and the calibration constant c_1, clause 7) was not reachable
to this package, nor a published calculation report that prints A_FF: no published A_FF is
reproduced here.  The tests check instead against independent closed forms:

* the Hertzian line contact along the depth (K. L. Johnson, Contact Mechanics, CUP 1985, §4.2 and
  §4.6): σ_x = σ_y = −p_0 at the surface, τ_1,max = 0.300 p_0 at y = 0.786 b, τ_1 → p_0 b/(2y) far
  below, b = √(8 w ρ / (π E_r)) for the load w per unit length;
* the case hardness depth at 550 HV (ISO 2639:2002): the profile passes through it, falls
  monotonically from the surface to the core hardness, and stretching it moves CHD alone;
* A_FF,max = τ_1,max / (K_τ,per HV_s) + c_1 where the case is deep enough for the hardness to be
  the surface hardness wherever the stress peaks; A_FF = c_1 at the surface (τ_1 = 0 there), the
  maximum below the surface and, for a shallow case, deeper than the stress peak;
* at the required case depth S_FF = S_FFmin, and ok ⇔ CHD ≥ CHD_req (A_FF,max falls with CHD);
* hypothesis: S_FF positive, finite and falling with torque; vectorised cases = the per-case loop;
* the validity ranges of ISO/TS 6336-4:2019 clause 1 (case-carburised only; p_H 500 … 3000 N/mm²,
  ρ_red 5 … 150 mm, CHD 0.3 … 4.5 mm, as secondary sources quote them) warn naming the clause.
"""

import json
import math
import warnings
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from epicyclic.cli.main import app
from epicyclic.errors import EpicyclicError
from epicyclic.geometry import BasicRack, GearGeometry, MeshGeometry
from epicyclic.io import loads_train_file
from epicyclic.rating import (
    MeshInput,
    RatingError,
    RatingSpec,
    RatingWarning,
    rate_mesh,
)
from epicyclic.rating.flank_fracture import (
    DEFAULT_SHEAR_STRENGTH_FACTOR,
    FlankFractureSpec,
    HardnessProfile,
    axis_stresses,
    half_width,
    material_exposure,
    principal_shear,
    principal_shear_peak,
)
from epicyclic.rating.lubricant_film import reduced_modulus

RACK = BasicRack(4.0)
PAIR = MeshGeometry(GearGeometry(19, RACK, 0.5), GearGeometry(104, RACK, 0.15)).with_tip_shortening()
E_R = reduced_modulus(206000.0, 0.3, 206000.0, 0.3)
EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "rating" / "flank_fracture.toml"
TEXT = EXAMPLE.read_text(encoding="utf-8")
runner = CliRunner()


def ff(**kw):
    base = {"case_depth": 0.8, "surface_hardness": 700.0, "core_hardness": 400.0}
    base.update(kw)
    return FlankFractureSpec(**base)


def rated(torque, speed=1500.0, mesh=PAIR, material="18CrNiMo7-6", **kw):
    spec = RatingSpec(material=material, flank_roughness=3.0, root_roughness=10.0, viscosity_40=220.0,
                      K_Hbeta=1.2, flank_fracture=ff(**kw))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RatingWarning)
        return rate_mesh(MeshInput("pair", mesh, 40.0, ("pinion", "wheel"), spec), torque, speed)


# ---------------------------------------------------------------- Hertzian line contact (Johnson 1985)
def test_principal_shear_peak_is_0_30_p0_at_0_786_b():
    tau, depth = principal_shear_peak()
    assert tau == pytest.approx(0.300, abs=5e-4) and depth == pytest.approx(0.786, abs=5e-4)
    # the stationary point of ζ − ζ²/√(1 + ζ²) in closed form: d/dζ = 1 − (2ζ + ζ³)/(1 + ζ²)^1.5 = 0
    assert 1 - (2 * depth + depth ** 3) / (1 + depth ** 2) ** 1.5 == pytest.approx(0.0, abs=1e-7)


def test_axis_stresses_surface_far_field_and_tau_1():
    sx, sy = axis_stresses(0.0, 1200.0, 0.4)
    assert float(sx) == pytest.approx(-1200.0) and float(sy) == pytest.approx(-1200.0)
    y = np.linspace(0.0, 3.0, 31)
    sx, sy = axis_stresses(y, 1200.0, 0.4)
    assert np.allclose(principal_shear(y, 1200.0, 0.4), 0.5 * (sx - sy))
    assert float(principal_shear(400.0, 1.0, 1.0)) == pytest.approx(1.0 / 800.0, rel=1e-5)   # p b / (2y)


def test_half_width_is_hertz_for_the_line_load():
    w, rho = 600.0, 18.0                                 # N/mm, mm
    p0 = math.sqrt(w * E_R / (2 * math.pi * rho))        # = Z_E √(w/ρ) of ISO 6336-2 with Z_E = √(E_r/2π)
    assert float(half_width(p0, rho, E_R)) == pytest.approx(math.sqrt(8 * w * rho / (math.pi * E_R)))
    assert 2 * w / (math.pi * float(half_width(p0, rho, E_R))) == pytest.approx(p0)   # w = π b p0 / 2


def test_tau_1_stays_below_its_far_field_bound():
    zeta = np.geomspace(1e-3, 1e3, 2000)            # τ_1/p_0 ≤ b/(2y): the bound depth_bound relies on
    assert np.all(principal_shear(zeta, 1.0, 1.0) * 2 * zeta <= 1.0)


# ---------------------------------------------------------------- hardness profile
def test_estimated_profile_passes_550_hv_at_chd_and_falls_to_the_core():
    prof = HardnessProfile(700.0, 400.0, 0.9)
    y = np.linspace(0.0, 5.0, 501)
    hv = prof(y)
    assert hv[0] == pytest.approx(700.0) and float(prof(0.9)) == pytest.approx(550.0)
    assert np.all(np.diff(hv) <= 1e-12) and hv[-1] == pytest.approx(400.0, abs=0.5)
    stretched = prof.with_case_depth(1.5)
    assert float(stretched(1.5)) == pytest.approx(550.0) and np.allclose(stretched(y * 1.5 / 0.9), hv)


def test_measured_profile_reads_chd_and_keeps_monotone_data_monotone():
    prof = HardnessProfile.measured([[0.0, 690], [0.4, 650], [0.8, 560], [1.2, 460], [2.5, 400]])
    assert prof.case_depth == pytest.approx(0.8 + 10 / 100 * 0.4)        # linear between 560 and 460
    assert (prof.surface, prof.core, prof.source) == (690.0, 400.0, "measured")
    hv = prof(np.linspace(0.0, 4.0, 400))
    assert np.all(np.diff(hv) <= 1e-9) and hv[-1] == 400.0                # PCHIP, held below the last point


@pytest.mark.parametrize(("points", "message"), [
    ([[0.0, 700]], "at least two"),
    ([[0.5, 700], [0.2, 400]], "increase"),
    ([[0.0, 700], [2.0, 600]], "fall below it"),
    ("deep", "at least two|pairs"),
])
def test_bad_profiles_are_named(points, message):
    with pytest.raises(RatingError, match=message):
        HardnessProfile.measured(points)


def test_profile_needs_a_case_above_and_a_core_below_550_hv():
    with pytest.raises(RatingError, match="550 HV"):
        HardnessProfile(520.0, 400.0, 1.0)
    with pytest.raises(RatingError, match="case_depth"):
        HardnessProfile(700.0, 400.0, -1.0)


# ---------------------------------------------------------------- material exposure
def test_exposure_is_c1_at_the_surface_and_peaks_below_it():
    y = np.linspace(0.0, 3.0, 601)
    prof = HardnessProfile(700.0, 400.0, 0.5)
    a, tau = material_exposure(y, np.array([1500.0]), np.array([0.4]), prof(y), 0.8, 0.04)
    a = a[0]
    assert a[0] == pytest.approx(0.04) and tau[0, 0] == 0.0
    peak = y[np.argmax(a)]
    assert peak > 0.786 * 0.4                 # the falling hardness moves the peak below the stress peak
    assert np.argmax(a) < len(y) - 1          # and it is not at the end of the grid


def test_deep_case_gives_the_closed_form():
    r = rated(800.0, case_depth=10.0, depths_per_decade=1000)
    mode = r.mode("flank_fracture")
    p_max = mode["p_dyn_max"]
    tau = principal_shear_peak()[0]
    expected = tau * p_max / (DEFAULT_SHEAR_STRENGTH_FACTOR * 700.0)
    a_max = mode.gear_factors[0]["A_FF_max"].value
    assert a_max == pytest.approx(expected, rel=2e-3)
    assert mode.gear_factors[0]["S_FF"].value == pytest.approx(1 / a_max)
    assert mode.gear_factors[0]["y_A_FF_max"].value == pytest.approx(mode["y_tau_max"], rel=0.01)


def test_required_case_depth_meets_the_minimum_exactly():
    mode = rated(1000.0, case_depth=0.3, S_FFmin=1.1).mode("flank_fracture")
    req = mode.gear_factors[0]["CHD_req"].value
    assert 0.3 < req < 10.0 and not mode.ok
    at_req = rated(1000.0, case_depth=req, S_FFmin=1.1).mode("flank_fracture")
    assert at_req.gear_factors[0]["S_FF"].value == pytest.approx(1.1, rel=2e-3)
    deeper = rated(1000.0, case_depth=req * 1.05, S_FFmin=1.1).mode("flank_fracture")
    assert deeper.gear_factors[0]["S_FF"].value >= 1.1


def test_no_case_depth_is_enough_when_the_surface_hardness_is_the_limit():
    mode = rated(4000.0).mode("flank_fracture")          # τ_1,max above K_τ,per HV_s
    assert mode.gear_factors[0]["CHD_req"].value == math.inf and not mode.ok
    assert any("no case depth" in n for n in mode.notes)
    data = json.loads(json.dumps(mode.to_dict(), allow_nan=False))
    assert data["gears"]["pinion"]["CHD_req"]["value"] is None and data["ok"] is False


@settings(max_examples=20, deadline=None)
@given(chd=st.floats(0.3, 3.0), factor=st.floats(1.05, 3.0), torque=st.floats(200.0, 2500.0))
def test_exposure_falls_as_the_case_deepens(chd, factor, torque):
    shallow = rated(torque, case_depth=chd).mode("flank_fracture").gear_factors[0]
    deep = rated(torque, case_depth=chd * factor).mode("flank_fracture").gear_factors[0]
    assert deep["A_FF_max"].value <= shallow["A_FF_max"].value * (1 + 1e-9)
    assert deep["CHD_req"].value == pytest.approx(shallow["CHD_req"].value, rel=1e-6)   # a property of the load


def test_given_constants_are_used_and_labelled():
    base = rated(800.0).mode("flank_fracture")
    given_ = rated(800.0, shear_strength_factor=0.5, calibration_factor=0.04).mode("flank_fracture")
    ratio = (given_.gear_factors[0]["A_FF_max"].value - 0.04) / base.gear_factors[0]["A_FF_max"].value
    assert ratio == pytest.approx(DEFAULT_SHEAR_STRENGTH_FACTOR / 0.5, rel=1e-9)
    assert given_.factors["K_tau_per"].clause == "given" and "assumed" in base.factors["K_tau_per"].clause
    assert not any("K_tau,per" in n for n in given_.notes) and any("K_tau,per" in n for n in base.notes)


@settings(max_examples=20, deadline=None)
@given(torque=st.floats(100.0, 3000.0), factor=st.floats(1.05, 3.0))
def test_safety_positive_finite_and_falling_with_torque(torque, factor):
    low = rated(torque).mode("flank_fracture").value
    high = rated(torque * factor).mode("flank_fracture").value
    assert 0 < high <= low * (1 + 1e-12) and math.isfinite(low)


def test_vectorised_cases_equal_the_loop():
    torques = np.array([300.0, 900.0, 1800.0])
    batch = rated(torques).mode("flank_fracture")
    for i, t in enumerate(torques):
        one = rated(float(t)).mode("flank_fracture")
        for key in ("A_FF_max", "CHD_req", "S_FF", "y_A_FF_max"):
            assert batch.gear_factors[1][key].value[i] == pytest.approx(one.gear_factors[1][key].value)


def test_rated_mesh_section_in_json_and_html():
    r = rated(800.0, case_depth={"pinion": 0.8, "wheel": 1.1})
    mode = r.mode("flank_fracture")
    assert [g["CHD"].value for g in mode.gear_factors] == [0.8, 1.1]
    data = json.loads(json.dumps(r.to_dict(), allow_nan=False))
    section = data["modes"]["flank_fracture"]
    assert section["safety"] == "S_FF" and set(section["profile"]["A_FF"]) == {"pinion", "wheel"}
    from epicyclic.rating.report_render import iso_symbol

    assert iso_symbol("A_FF_max") in mode.table() and iso_symbol("CHD_req") in mode._repr_html_() and "#### Tooth flank" in mode.markdown()


# ---------------------------------------------------------------- validity (ISO/TS 6336-4:2019, clause 1)
def test_validity_ranges_warn_naming_the_clause():
    spec = RatingSpec(material="42CrMo4", flank_roughness=3.0, root_roughness=10.0, viscosity_40=220.0,
                      flank_fracture=ff(case_depth=0.2))
    with pytest.warns(RatingWarning, match=r"ISO/TS 6336-4:2019, clause 1") as record:
        rate_mesh(MeshInput("pair", PAIR, 40.0, ("pinion", "wheel"), spec), 5.0, 1500.0)
    text = " ".join(str(w.message) for w in record)
    assert "not case-carburised" in text and "CHD 0.2 mm outside" in text and "outside 500 ... 3000" in text


# ---------------------------------------------------------------- bad input
def test_missing_values_are_named_with_a_typical_value():
    with pytest.raises(RatingError, match="core_hardness is missing for pair wheel"):
        rated(800.0, core_hardness={"pinion": 400.0})
    with pytest.raises(RatingError, match="case_depth .* surface_hardness"):
        FlankFractureSpec()
    with pytest.raises(RatingError, match="S_FFmin"):
        ff(S_FFmin=0.0)
    with pytest.raises(RatingError, match="flank_fracture must be"):
        RatingSpec(material="18CrNiMo7-6", flank_fracture={"case_depth": 1.0})


# ---------------------------------------------------------------- the train file and epicyclic rate
def test_the_table_is_read_and_bad_keys_are_named():
    spec = loads_train_file(TEXT).rating.flank_fracture
    assert dict(spec.case_depth) == {"sun": 0.6, "planet": 0.6, "ring": 0.8} and spec.surface_hardness == 700.0
    measured = loads_train_file(TEXT.replace("# hardness_profile", "hardness_profile")).rating.flank_fracture
    assert measured.profile_of("P", "ring").source == "measured"
    with pytest.raises(EpicyclicError, match=r"\[rating.flank_fracture\].*case_dept"):
        loads_train_file(TEXT.replace("case_depth = {", "case_dept = {"))
    with pytest.raises(EpicyclicError, match=r"\[rating.flank_fracture\].*550 HV"):
        loads_train_file(TEXT.replace("surface_hardness = 700.0", "surface_hardness = 500.0"))
    with pytest.raises(EpicyclicError, match="depth mm, HV"):
        loads_train_file(TEXT.replace("# hardness_profile = { ring = [[0.0, 690]", "hardness_profile = { ring = [[0.0]"))


def test_rate_prints_the_flank_fracture_section_in_every_format():
    table = runner.invoke(app, ["rate", str(EXAMPLE)])
    assert table.exit_code == 0, table.output
    assert "Tooth flank fracture and hardened layer" in table.output and "CHD_req" in table.output
    data = json.loads(runner.invoke(app, ["rate", str(EXAMPLE), "-f", "json"]).stdout)
    section = data["ratings"][0]["meshes"][0]["modes"]["flank_fracture"]
    assert section["safety"] == "S_FF" and section["value"] > 1 and section["ok"] is True
    assert data["inputs"]["flank_fracture"]["surface_hardness"] == 700.0
    assert "#### Tooth flank fracture" in runner.invoke(app, ["rate", str(EXAMPLE), "-f", "markdown"]).output
    assert "<h4>Tooth flank fracture" in runner.invoke(app, ["rate", str(EXAMPLE), "-f", "html"]).output


def test_a_flank_fracture_shortfall_is_marked_and_named():
    result = runner.invoke(app, ["rate", str(EXAMPLE), "--set", "rating.flank_fracture.S_FFmin=4.0"])
    assert result.exit_code == 0, result.output
    assert "S_FF" in result.output and " !" in result.output and "below minimum safety" in result.output


def test_the_table_travels_through_rexs_and_toml(tmp_path):
    from epicyclic.exchange.convert import convert
    from epicyclic.io import load_train_file

    original = loads_train_file(TEXT).rating.flank_fracture
    for suffix in (".rexs", ".toml"):
        out = tmp_path / ("ff" + suffix)
        convert(EXAMPLE, out)
        back = load_train_file(out).rating.flank_fracture
        assert back == original and back.shear_strength_factor is None      # the default stays a default


def test_a_gear_without_case_depth_is_not_rated_and_says_so():
    mode = rated(800.0, case_depth={"pinion": 0.8}).mode("flank_fracture")     # e.g. a nitrided wheel
    assert dict(mode.gear_factors[1]) == {} and mode.value == mode.gear_factors[0]["S_FF"].value
    assert any("wheel not rated" in n for n in mode.notes)
    rows = [line for line in mode.table().splitlines() if line.startswith("safety against")]
    assert len(rows) == 1 and f"{mode.value:.4f}".rstrip("0") in rows[0].split()
    data = json.loads(json.dumps(mode.to_dict(), allow_nan=False))
    assert data["gears"]["wheel"] == {} and data["gears"]["pinion"]["S_FF"]["value"] == pytest.approx(mode.value)
    with pytest.raises(RatingError, match="no case_depth or hardness_profile for pair pinion or wheel"):
        rated(800.0, case_depth={"ring": 0.8})
