"""The public REXS models (FVA-Workbench planetary stage, Bearinx two-stage gearbox) read and solved.

Sources (tests/exchange/fixtures/README.md, Apache-2.0):

* FVA planetary stage, minus gearing — github.com/fva-net/rexs-api-java,
  api/src/test/resources/FVA_Planetary_stage_-_Minus_gearing_1.1.rexs (FVA-Workbench 5.5, REXS 1.1).
* FVA industrial gearbox, two stages — github.com/BearinxSimulationSuite/REXSapi,
  test/example_models/FVA-Industriegetriebe_2stufig_1-4.rexs (Bearinx 12, REXS 1.4).

Every expected number is worked out by hand from the file's tooth counts, module, speed and torque
(Willis: i = 1 + z_ring/z_sun for a minus set with the ring held; a fixed-axis chain of two external
meshes: i = (z2/z1)(z4/z3)); none is taken from the program.
"""

from __future__ import annotations

import io
import math
import zipfile
from pathlib import Path

import pytest

from epicyclic.errors import EpicyclicError
from epicyclic.exchange import load_rexs_document
from epicyclic.exchange.container import read_model
from epicyclic.io import InputFileError, load_train_file
from epicyclic.io.geometry_report import geometry_results

FIXTURES = Path(__file__).parent / "fixtures"
EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "rexs"
PLANETARY = EXAMPLES / "FVA_Planetary_stage_-_Minus_gearing_1.1.rexs"
GEARBOX = EXAMPLES / "FVA-Industriegetriebe_2stufig_1-4.rexs"


def _json_variant(source: Path, tmp_path: Path) -> Path:
    """The XML model re-written in the REXS JSON container (types from the XML text), by our serializer."""
    from epicyclic.exchange.serialize import RexsBuilder

    model = read_model(source.read_bytes(), str(source))
    builder = RexsBuilder("test", "1")

    def kind(value):
        if isinstance(value, list):
            inner = {kind(v)[0] for v in value} or {"floating_point"}
            base = inner.pop() if len(inner) == 1 else "string"
            return base + "_array", [convert(v, base) for v in value]
        if value in ("true", "false"):
            return "boolean", value == "true"
        try:
            return "floating_point", float(value)
        except ValueError:
            return "string", value

    def convert(value, base):
        return value == "true" if base == "boolean" else float(value) if base == "floating_point" else value

    ids = {}
    for cid, c in sorted(model.components.items()):
        attributes = [(a.id, *kind(a.value), a.unit) for a in c.attributes.values()]
        builder._next = cid  # keep the file's ids
        ids[cid] = builder.component(c.type, c.name, attributes)
    for r in model.relations:
        builder.relation(r.type, [(ref.id, ref.role) for ref in r.refs], r.order)
    for case in model.load_cases:
        builder.load_case([(cid, [(a.id, *kind(a.value), a.unit) for a in attrs.values()])
                           for cid, attrs in case.components.items()])
    target = tmp_path / (source.stem + ".rexsj")
    target.write_text(builder.json())
    return target


def _zip_variant(source: Path, tmp_path: Path, member: str) -> Path:
    target = tmp_path / (source.stem + "-" + Path(member).suffix[1:] + ".rexsz")
    with zipfile.ZipFile(target, "w", zipfile.ZIP_DEFLATED) as archive:
        archive.writestr(member, source.read_bytes())
    return target


# ---------------------------------------------------------------------- the FVA planetary stage
def test_planetary_stage_maps_onto_a_simple_set():
    doc = load_rexs_document(PLANETARY)
    (p,) = doc.data["planetary"]
    assert p["teeth"] == {"sun": 17, "planet": 22, "ring": 61}
    assert p["planets"] == 3
    assert p["geometry"]["module"] == 4.0 and p["geometry"]["pressure_angle"] == 20.0
    assert p["geometry"]["face_width"] == {"sun": 50.0, "planet": 50.0, "ring": 50.0}
    assert p["geometry"]["dedendum"] == 1.25  # the rack tool's addendum 1.25 is the gear's dedendum
    assert (p["sun"], p["ring"], p["carrier"]) == ("Sonnenwelle [34]", "Hohlradwelle [62]", "Steg 1 [4]")
    # the two switchable couplings in parallel hold the ring: one brake
    assert doc.data["brake"] == [{"name": "Koppelung [65]", "shaft": "Hohlradwelle [62]", "engaged": True}]
    assert "switchable_coupling 66" in doc.origins["brake.Koppelung [65]"]
    assert doc.ignored.startswith("ignored: 11 shaft sections, 10 concept bearings")
    assert doc.materials["Planetenstufe [9].sun"] == "18CrNiMo7-6"


def test_planetary_stage_solves_to_the_hand_numbers():
    f = load_train_file(PLANETARY)
    s = f.solve()
    ratio = 1 + 61 / 17                       # Willis, ring held: i = 1 + z_ring/z_sun = 4.588235
    assert s.speed("Sonnenwelle [34]") == pytest.approx(1500.0)
    assert s.speed("Steg 1 [4]") == pytest.approx(1500.0 / ratio, rel=1e-12)     # 326.923 1/min
    torque_in = 250e3 / (1500 * math.pi / 30)                                  # the file's 1591.549 N*m = 250 kW
    assert s.torque("Sonnenwelle [34]") == pytest.approx(torque_in, rel=1e-9)
    assert s.torque("Steg 1 [4]") == pytest.approx(-torque_in * ratio, rel=1e-9)  # -7302.4 N*m, lossless
    assert s.power("Steg 1 [4]") == pytest.approx(-250e3, rel=1e-9)
    # tooth force per planet at the sun: F_t = T_sun / (N r_sun), r_sun = m z / 2 = 34 mm
    (result,) = geometry_results(f.geometry, s)
    assert result.forces.design_tangential["sun-planet"] == pytest.approx(torque_in / (3 * 0.034), rel=1e-9)


def test_planetary_stage_lubricant_at_80_degrees():
    # ISO VG 100 (nu40 = 100, nu100 = 11 mm^2/s, rho15 = 0.88 kg/dm^3) at the casing's 80 degC
    from epicyclic.exchange.operating import OIL_EXPANSION, walther_viscosity

    doc = load_rexs_document(PLANETARY)
    nu = walther_viscosity(100.0, 11.0, 80.0)
    assert 18.0 < nu < 21.0  # ISO 3448 viscosity-temperature charts: VG 100 with VI ~ 95 reads about 19 at 80 degC
    assert doc.data["lubricant"]["viscosity"] == pytest.approx(nu * 0.88 * (1 - OIL_EXPANSION * 65), rel=1e-6)
    assert (doc.data["lubricant"]["viscosity_40"], doc.data["lubricant"]["viscosity_100"]) == (100.0, 11.0)


@pytest.mark.parametrize("container", ["xml", "json", "zip/xml", "zip/json", "published zip"])
def test_planetary_stage_containers_give_identical_results(container, tmp_path):
    reference = load_train_file(PLANETARY).solve()
    path = {"xml": PLANETARY, "published zip": FIXTURES / (PLANETARY.stem + ".rexsz")}.get(container)
    if container == "json":
        path = _json_variant(PLANETARY, tmp_path)
    elif container == "zip/xml":
        path = _zip_variant(PLANETARY, tmp_path, "model.rexs")
    elif container == "zip/json":
        path = _zip_variant(_json_variant(PLANETARY, tmp_path), tmp_path, "model.rexsj")
    f = load_train_file(path)
    assert f.exchange.container == (container if container != "published zip" else "zip/xml")
    s = f.solve()
    for shaft in ("Sonnenwelle [34]", "Steg 1 [4]", "Hohlradwelle [62]"):
        assert s.speed(shaft) == pytest.approx(reference.speed(shaft), abs=1e-9)
        assert s.torque(shaft) == pytest.approx(reference.torque(shaft), abs=1e-9)


def test_published_json_has_the_ring_couplings_open():
    # In the 1.1 JSON as published, is_engaged is `false` (the XML: [true]): the ring turns freely, and
    # the solver says so, naming the REXS shaft behind the ring.
    f = load_train_file(FIXTURES / (PLANETARY.stem + ".rexsj"))
    assert f.train.elements[1].engaged is False
    with pytest.raises(EpicyclicError, match=r"'Hohlradwelle \[62\]', 'Steg 1 \[4\]' is still free") as caught:
        f.solve()
    assert "(REXS: 'Hohlradwelle [62]' is shaft 62 'Hohlradwelle [62]'" in str(caught.value)


def test_workbench_7_export_gives_the_power_instead_of_the_torque():
    f = load_train_file(FIXTURES / (PLANETARY.stem + "_vers2.rexsj"))  # REXS 1.4, 100 kW at the sun
    s = f.solve()
    assert s.speed("Plate [4]") == pytest.approx(1500.0 / (1 + 61 / 17), rel=1e-12)
    assert s.power("Sun gear shaft [34]") == pytest.approx(100e3)
    assert s.torque("Sun gear shaft [34]") == pytest.approx(100e3 / (1500 * math.pi / 30))


# ---------------------------------------------------------------------- the Bearinx two-stage gearbox
def test_two_stage_gearbox_maps_onto_one_chain_of_meshes():
    doc = load_rexs_document(GEARBOX)
    (g,) = doc.data["gear"]
    assert g["meshes"] == [[27, 51, "external"], [23, 34, "external"]]
    assert (g["first"], g["second"]) == ("Shaft [6]", "Shaft [42]")
    assert g["geometry"]["module"] == [4.5, 6.5]
    assert g["geometry"]["helix_angle"] == [21.0, 10.0]
    assert g["geometry"]["profile_shift"] == [[0.231415, 0.231415], [0.15074, 0.15074]]
    assert "shaft_section" not in doc.summary or "12 shaft sections" in doc.summary


def test_two_stage_gearbox_load_spectrum():
    f = load_train_file(GEARBOX)
    cases = f.load_cases
    assert [c.id for c in cases] == [1, 2, 3, 4]
    assert [c.duration_fraction for c in cases] == pytest.approx([0.20, 0.30, 0.35, 0.15])
    assert [c.lubricant_temperature for c in cases] == [70.0] * 4
    ratio = (51 / 27) * (34 / 23)                                       # 2.792271
    for case, (n, t) in zip(cases, [(543, 567), (3456, 345), (1234, 456), (789, 789)]):
        s = load_train_file(GEARBOX).train  # the same train for every case
        from epicyclic import solve

        solution = solve(s, case.to_operating_point(), lossless=True)
        assert solution.speed("Shaft [6]") == pytest.approx(n)
        assert solution.speed("Shaft [42]") == pytest.approx(n / ratio, rel=1e-12)
        assert solution.torque("Shaft [42]") == pytest.approx(-t * ratio, rel=1e-12)
    assert f.operating_point.speeds == cases[0].to_operating_point().speeds


def test_two_stage_gearbox_forces_by_hand():
    f = load_train_file(GEARBOX)
    s = f.solve()
    (result,) = geometry_results(f.geometry, s)
    # the profile shifts of the file make both stages run at the REXS centre distance a = 190 mm
    assert [m.center_distance for m in result.geometry.meshes] == pytest.approx([190.0, 190.0], abs=1e-5)
    # F_t = T / r_w with the working pitch radius r_w1 = a z1 / (z1 + z2) of each pinion
    mesh1, mesh2 = result.forces.to_dict()["meshes"]
    assert mesh1["torque"] == pytest.approx(567.0)
    assert mesh2["torque"] == pytest.approx(567.0 * 51 / 27)                       # 1071 N*m on the countershaft
    assert mesh1["tangential"] == pytest.approx(567.0 / (190 * 27 / 78 / 1000), rel=1e-6)   # 8621.05 N
    assert mesh2["tangential"] == pytest.approx(1071.0 / (190 * 23 / 57 / 1000), rel=1e-6)  # 13969.56 N


@pytest.mark.parametrize("variant", ["xml", "json", "our json", "zip"])
def test_two_stage_gearbox_containers_agree(variant, tmp_path):
    path = {"xml": GEARBOX, "json": FIXTURES / (GEARBOX.stem + ".rexsj")}.get(variant)
    if variant == "our json":
        path = _json_variant(GEARBOX, tmp_path)
    elif variant == "zip":
        path = _zip_variant(GEARBOX, tmp_path, "m.rexs")
    f = load_train_file(path)
    s = f.solve()
    assert s.speed("Shaft [42]") == pytest.approx(543 * 27 * 23 / (51 * 34), rel=1e-12)
    assert len(f.load_cases) == 4


def test_not_a_rexs_zip():
    data = io.BytesIO()
    with zipfile.ZipFile(data, "w") as archive:
        archive.writestr("gde_file.gde", "")
    with pytest.raises(InputFileError, match="exactly one .rexs or .rexsj model"):
        read_model(data.getvalue(), "x.rexsz")


def test_a_centre_distance_the_profile_shifts_do_not_give_is_noted(tmp_path):
    # a = m (z_sun + z_planet) / 2 = 4 (17 + 22) / 2 = 78 mm with x = 0 (ISO 21771); the file altered to 79 mm
    altered = tmp_path / "a79.rexs"
    altered.write_bytes(PLANETARY.read_bytes().replace(b'unit="mm">78.0<', b'unit="mm">79.0<'))
    notes = load_rexs_document(altered).notes
    assert len(notes) == 2  # sun-planet and planet-ring, once for the three planets
    assert "REXS gives the centre distance a = 79 mm, its profile shifts give a_w = 78.0000 mm" in notes[0]
    assert load_rexs_document(PLANETARY).notes == ()


def test_sew_three_stage_gearbox_rexs_1_0():
    # SEW three-stage cylindrical gearbox (fva-net/rexs-api-java, SEW_3-stage_cylindrical_gearbox_1.0.rexs):
    # three external meshes 23/67, 13/76, 14/87: i = -(67/23)(76/13)(87/14) = -105.83 (three reversals)
    f = load_train_file(FIXTURES / "SEW_3-stage_cylindrical_gearbox_1.0.rexs")
    (g,) = f.exchange.data["gear"]
    assert g["meshes"] == [[23, 67, "external"], [13, 76, "external"], [14, 87, "external"]]
    s = f.solve()
    ratio = -(67 / 23) * (76 / 13) * (87 / 14)
    assert s.speed("ABW [54]") == pytest.approx(1400 / ratio, rel=1e-12)
    assert s.torque("ABW [54]") == pytest.approx(-s.torque("ANW [4]") * ratio, rel=1e-9)  # lossless: T_out = -i T_in
    assert s.torque("ABW [54]") == pytest.approx(500.0, rel=1e-9)  # the file gives 4.72456 N*m at the input: 500 N*m out
    assert f.exchange.ignored == "ignored: 33 shaft sections, 9 rolling bearing rows, 9 rolling bearings with catalog geometry"


def test_a_stage_of_other_gears_is_not_read():
    # the planetary stage with its external gears made worm gears: its meshes are skipped, and the stage
    # without meshes is a clear error naming it
    from epicyclic.exchange.reading import loads_rexs_document

    text = PLANETARY.read_bytes().replace(b'type="cylindrical_gear"', b'type="worm_gear"')
    with pytest.raises(InputFileError, match=r"component 9 \(planetary_stage 'Planetenstufe \[9\]'\): the stage has no "
                                             "cylindrical_stage meshes"):
        loads_rexs_document(text, "worm.rexs")


def test_two_stage_gearbox_load_spectrum_is_a_duty_cycle():
    # the four load cases become the file's [duty_cycle]: `epicyclic duty` on the REXS file; energy per cycle
    # hour of case k: E_k = T_k n_k (pi/30) share_k (W h per hour), from the file's torques, speeds, shares
    from epicyclic.io.duty_format import analyse_file_duty_cycle

    f = load_train_file(GEARBOX)
    assert [c.name for c in f.duty_cycle.cases] == ["load case 1", "load case 2", "load case 3", "load case 4"]
    result = analyse_file_duty_cycle(f).to_dict()
    for case, (n, t, share) in zip(result["cases"], [(543, 567, 0.20), (3456, 345, 0.30), (1234, 456, 0.35),
                                                     (789, 789, 0.15)]):
        assert case["energy_in"]["value"] == pytest.approx(t * n * math.pi / 30 * share / 1000, rel=1e-9)


def test_workbench_7_export_is_rated_as_it_is():
    # FVA-Workbench 7.1 gives each gear's material (18CrNiMo7-6 sun and planets, 42CrMo4 ring) and R_z
    # (flank 5 um, root 20 um), and the oil's nu_40 = 100 mm^2/s: a [rating] table, so `epicyclic rate` runs.
    # Hand check of its first line: F_t = T_sun / (N d_sun / 2) = (100 kW / (1500 pi/30)) / (3 * 0.034 m)
    # = 6241.4 N; v = pi d_sun (n_sun - n_carrier) / 60000 with n_carrier = 1500 / (1 + 61/17).
    from epicyclic.rating.train import rate_solution

    f = load_train_file(FIXTURES / (PLANETARY.stem + "_vers2.rexsj"))
    table = f.exchange.data["rating"]
    assert table["material"] == {"Planetary stage [9]:sun": "18CrNiMo7-6", "Planetary stage [9]:planet": "18CrNiMo7-6",
                                 "Planetary stage [9]:ring": "42CrMo4"}
    assert (table["flank_roughness"], table["root_roughness"]) == (5.0, 20.0)
    assert f.rating is not None
    assert load_rexs_document(PLANETARY).data.get("rating") is None  # the 1.1 file gives no roughness
    rating = rate_solution(f.solve(), f.geometry, f.rating).to_dict()
    first = rating["meshes"][0]["factors"]
    torque = 100e3 / (1500 * math.pi / 30)
    assert first["F_t"]["value"] == pytest.approx(torque / (3 * 0.034), rel=1e-9)                       # 6241.4 N
    assert first["v"]["value"] == pytest.approx(math.pi * 68 * (1500 - 1500 / (1 + 61 / 17)) / 60000, rel=1e-9)
    # with the file's K_A = 1.25, operating_time 100 000 h, the ring's sigma_Hlim = 740.64 N/mm^2 and 266 HB (Z_W
    # of the through-hardened ring against case-hardened planets) the ring's flank is the weakest, above S_Hmin = 1
    # (tests/exchange/test_rating_map.py has the inputs one by one)
    assert rating["ok"] is True
