"""Hostile REXS files: XXE, billion laughs, zip bombs, deep nesting, too many components, bad numbers.

Each is refused before the work it would cause, with one clear error naming the file (and the component
and attribute where there is one); nothing is expanded, fetched or half-written.
"""

from __future__ import annotations

import io
import json
import random
import time
import zipfile

import pytest

from epicyclic import limits
from epicyclic.exchange.container import read_model
from epicyclic.exchange.reading import loads_rexs_document
from epicyclic.io import InputFileError, load_train_file

HEAD = '<model version="1.7" applicationId="t" applicationVersion="1" date="2026-01-01T00:00:00+00:00">'

#: A minimal planetary stage (sun 30, planet 24, ring 78; ring held by a coupling to the casing).
STAGE = HEAD + """
<relations>
 <relation id="1" type="central_shaft"><ref id="1" role="planetary_stage"/><ref id="2" role="shaft"/></relation>
 <relation id="2" type="central_shaft"><ref id="1" role="planetary_stage"/><ref id="3" role="shaft"/></relation>
 <relation id="3" type="planet_carrier_shaft"><ref id="1" role="planetary_stage"/><ref id="4" role="shaft"/></relation>
 <relation id="4" type="planet_shaft"><ref id="1" role="planetary_stage"/><ref id="5" role="shaft"/></relation>
 <relation id="5" type="assembly"><ref id="2" role="assembly"/><ref id="10" role="part"/></relation>
 <relation id="6" type="assembly"><ref id="3" role="assembly"/><ref id="11" role="part"/></relation>
 <relation id="7" type="assembly"><ref id="5" role="assembly"/><ref id="12" role="part"/></relation>
 <relation id="8" type="assembly"><ref id="1" role="assembly"/><ref id="20" role="part"/></relation>
 <relation id="9" type="assembly"><ref id="1" role="assembly"/><ref id="21" role="part"/></relation>
 <relation id="10" type="stage"><ref id="20" role="stage"/><ref id="10" role="gear_1"/><ref id="12" role="gear_2"/></relation>
 <relation id="11" type="stage"><ref id="21" role="stage"/><ref id="12" role="gear_1"/><ref id="11" role="gear_2"/></relation>
 <relation id="12" type="side"><ref id="30" role="assembly"/><ref id="3" role="inner_part"/><ref id="40" role="outer_part"/></relation>
 <relation id="13" type="assembly"><ref id="2" role="assembly"/><ref id="50" role="part"/></relation>
 <relation id="14" type="assembly"><ref id="4" role="assembly"/><ref id="51" role="part"/></relation>
</relations>
<components>
 <component id="1" type="planetary_stage" name="P"/>
 <component id="2" type="shaft" name="sun shaft">
  <attribute id="defines_speed" unit="none">true</attribute>
  <attribute id="rotational_speed" unit="1 / min">SPEED</attribute>
 </component>
 <component id="3" type="shaft" name="ring shaft"/>
 <component id="4" type="shaft" name="carrier"/>
 <component id="5" type="shaft" name="planet"/>
 <component id="10" type="cylindrical_gear" name="sun"><attribute id="number_of_teeth" unit="none">30</attribute></component>
 <component id="11" type="ring_gear" name="ring"><attribute id="number_of_teeth" unit="none">78</attribute></component>
 <component id="12" type="cylindrical_gear" name="planet gear"><attribute id="number_of_teeth" unit="none">24</attribute></component>
 <component id="20" type="cylindrical_stage" name="m1"/>
 <component id="21" type="cylindrical_stage" name="m2"/>
 <component id="30" type="coupling" name="ring fixed"/>
 <component id="40" type="gear_casing" name="casing"/>
 <component id="50" type="external_load" name="in">
  <attribute id="defines_torque" unit="none">true</attribute>
  <attribute id="torque_around_u_axis" unit="N m">10</attribute>
 </component>
 <component id="51" type="external_load" name="out"><attribute id="transmits_torque" unit="none">true</attribute></component>
</components>
</model>
"""


def stage(speed: str = "3000") -> bytes:
    return STAGE.replace("SPEED", speed).encode()


def test_the_minimal_stage_solves():
    # Willis, ring held: n_carrier = n_sun / (1 + 78/30) = 3000/3.6
    from epicyclic.io.toml_format import read_document

    f = read_document(loads_rexs_document(stage(), "s.rexs"))
    assert f.solve().speed("carrier") == pytest.approx(3000 / 3.6)
    assert f.train.shafts[-1] == "housing" or "housing" in f.train.shafts


def test_billion_laughs_is_refused_unexpanded():
    bomb = ('<?xml version="1.0"?><!DOCTYPE model [<!ENTITY a "aaaaaaaaaa">'
            + "".join(f'<!ENTITY {chr(98 + k)} "{("&" + chr(97 + k) + ";") * 10}">' for k in range(8))
            + ']><model version="&i;"/>').encode()
    start = time.perf_counter()
    with pytest.raises(InputFileError, match="declares a document type or entities"):
        read_model(bomb, "bomb.rexs")
    assert time.perf_counter() - start < 1.0


def test_external_entity_is_never_fetched(tmp_path):
    secret = tmp_path / "secret.txt"
    secret.write_text("the secret")
    xxe = (f'<?xml version="1.0"?><!DOCTYPE m [<!ENTITY x SYSTEM "file://{secret}">]>'
           '<model version="&x;"/>').encode()
    with pytest.raises(InputFileError) as caught:
        read_model(xxe, "xxe.rexs")
    assert "the secret" not in str(caught.value)


def test_zip_bomb_is_refused_unexpanded():
    data = io.BytesIO()
    with zipfile.ZipFile(data, "w", zipfile.ZIP_DEFLATED) as archive:
        archive.writestr("model.rexs", b"<model " + b" " * (8 << 20) + b"/>")  # 8 MiB of spaces: ~1000:1
    with pytest.raises(InputFileError, match="zip bomb"):
        read_model(data.getvalue(), "bomb.rexsz")


def test_zip_member_beyond_the_size_limit(monkeypatch):
    monkeypatch.setenv(limits.FILE_BYTES_VARIABLE, "4096")  # REXS limit 16 x 4 KiB = 64 KiB
    data = io.BytesIO()
    with zipfile.ZipFile(data, "w", zipfile.ZIP_DEFLATED) as archive:  # random hex: compresses 2:1, no bomb
        archive.writestr("model.rexs", b"<model>" + random.Random(1).randbytes(50_000).hex().encode() + b"</model>")
    assert len(data.getvalue()) < 65536
    with pytest.raises(InputFileError, match="expands to"):
        read_model(data.getvalue(), "big.rexsz")


def test_deep_xml_nesting():
    deep = (HEAD + "<a>" * 200 + "</a>" * 200 + "</model>").encode()
    with pytest.raises(InputFileError, match="nested more than 16 levels"):
        read_model(deep, "deep.rexs")


def test_deep_json_nesting():
    deep = ('{"model": {"version": "1.7", "components": ' + "[" * 5000 + "]" * 5000 + "}}").encode()
    with pytest.raises(InputFileError, match="nested more than 16 levels"):
        read_model(deep, "deep.rexsj")


def test_json_nan_is_refused():
    with pytest.raises(InputFileError, match="not valid JSON.*NaN"):
        read_model(b'{"model": {"version": "1.7", "x": NaN}}', "nan.rexsj")


def test_too_many_components(monkeypatch):
    monkeypatch.setattr("epicyclic.exchange.container.MAX_REXS_COMPONENTS", 10)
    components = "".join(f'<component id="{k}" type="shaft"/>' for k in range(20))
    with pytest.raises(InputFileError, match="more than 10 components"):
        read_model((HEAD + f"<components>{components}</components></model>").encode(), "many.rexs")


@pytest.mark.parametrize("speed, message", [
    ("fast", "expected a number, got 'fast'"),
    ("nan", "expected a finite number"),
    ("1e999", "expected a finite number"),
    ("", "defines_speed is true, but the file gives no speed"),
])
def test_malformed_number_names_file_component_and_attribute(speed, message):
    with pytest.raises(InputFileError) as caught:
        from epicyclic.io.toml_format import read_document

        read_document(loads_rexs_document(stage(speed), "bad.rexs")).solve()
    text = str(caught.value)
    assert text.startswith("bad.rexs: component 2 (shaft 'sun shaft'), attribute 'rotational_speed'")
    assert message in text


def test_unit_of_the_wrong_quantity():
    bad = stage().replace(b'unit="1 / min">3000', b'unit="mm">3000')
    with pytest.raises(InputFileError, match="the unit 'mm' is not a speed"):
        loads_rexs_document(bad, "unit.rexs")


def test_a_missing_tooth_count_names_the_gear():
    bad = stage().replace(b'<attribute id="number_of_teeth" unit="none">78</attribute>', b"")
    with pytest.raises(InputFileError, match=r"component 11 \(ring_gear 'ring'\), attribute 'number_of_teeth': missing"):
        loads_rexs_document(bad, "teeth.rexs")


def test_a_relation_to_an_unknown_component():
    bad = stage().replace(b'<ref id="12" role="gear_2"/>', b'<ref id="99" role="gear_2"/>')
    with pytest.raises(InputFileError, match="names component 99, which the file does not have"):
        loads_rexs_document(bad, "ref.rexs")


def test_a_duplicate_component_id():
    bad = stage().replace(b'<component id="5" type="shaft"', b'<component id="4" type="shaft"')
    with pytest.raises(InputFileError, match="component id 4 is used twice"):
        loads_rexs_document(bad, "dup.rexs")


def test_rexs_content_with_a_toml_suffix_is_read_as_rexs(tmp_path):
    path = tmp_path / "looks_like.toml"
    path.write_bytes(stage())
    assert load_train_file(path).exchange.container == "xml"


def test_no_gears_at_all_is_a_clear_error():
    with pytest.raises(InputFileError, match="holds no planetary_stage and no cylindrical_stage"):
        loads_rexs_document((HEAD + "<components/></model>").encode(), "empty.rexs")


def test_a_json_array_where_an_object_belongs():
    with pytest.raises(InputFileError, match="a component is 3, not an object"):
        read_model(json.dumps({"model": {"version": "1.7", "components": [3]}}).encode(), "arr.rexsj")


def test_a_large_toml_file_keeps_the_toml_limit(tmp_path):
    path = tmp_path / "large.toml"
    path.write_text('title = "x"\n' + "# padding\n" * 200_000)  # 2 MB: over 1 MiB, under the REXS 16 MiB
    with pytest.raises(InputFileError, match="at most 1 MiB"):
        load_train_file(path)


def test_a_large_rexs_file_gets_the_rexs_limit(tmp_path):
    from epicyclic.exchange.topology import Members  # noqa: F401  (the package imports)

    path = tmp_path / "large.rexs"
    path.write_bytes(stage().replace(b"</model>", b"<!--" + b" " * (2 << 20) + b"--></model>"))
    assert load_train_file(path).solve().speed("carrier") == pytest.approx(3000 / 3.6)


def test_without_defines_speed_the_first_speed_is_the_given_one():
    from epicyclic.io.toml_format import read_document

    unflagged = stage().replace(b'<attribute id="defines_speed" unit="none">true</attribute>', b"")
    f = read_document(loads_rexs_document(unflagged, "s.rexs"))
    assert f.solve().speed("carrier") == pytest.approx(3000 / 3.6)
    assert "no shaft has defines_speed" in f.exchange.notes[0]
    assert repr(f.exchange).startswith('RexsDocument("s.rexs: REXS 1.7 (xml, t 1): 1 planetary; 1 note(s)')


def test_a_ring_gear_in_the_casing_is_held():
    # some exporters assemble a fixed ring gear into the gear_casing instead of a shaft held by a coupling
    from epicyclic.io.toml_format import read_document

    casing_ring = (stage().replace(b'<relation id="6" type="assembly"><ref id="3" role="assembly"/>',
                                   b'<relation id="6" type="assembly"><ref id="40" role="assembly"/>')
                   .replace(b'<relation id="2" type="central_shaft"><ref id="1" role="planetary_stage"/>'
                            b'<ref id="3" role="shaft"/></relation>', b""))
    f = read_document(loads_rexs_document(casing_ring, "casing.rexs"))
    assert f.train.elements[0].ring == "housing"
    assert f.solve().speed("carrier") == pytest.approx(3000 / 3.6)


def test_a_relation_to_a_deleted_planetary_stage_is_an_error():
    # issue 30: with the planetary_stage component deleted and its relations left, convert exited 0 and
    # read the planets as fixed-axis [[gear]] stages: a different train.
    bad = stage().replace(b' <component id="1" type="planetary_stage" name="P"/>\n', b"")
    with pytest.raises(InputFileError, match=r"relation 1 \(central_shaft\), role 'planetary_stage' names component "
                                             r"1, which the file does not have"):
        loads_rexs_document(bad, "deleted.rexs")


def test_control_characters_in_the_model_convert_to_toml_or_are_refused(tmp_path):
    # issue 30: <model version="banana\x7f"> made `convert -o out.toml` fail with tomlkit's
    # "Comment cannot contain control character" (exit 1).  An unknown version is now refused naming the
    # attribute; the program's name (applicationId), written into a comment, is written without them.
    from epicyclic.exchange.convert import toml_text
    from epicyclic.exchange.versions import RexsVersionError

    bad_version = tmp_path / "v.rexs"
    bad_version.write_bytes(stage().replace(b'version="1.7"', b'version="banana\x7f"'))
    with pytest.raises(RexsVersionError, match="the model's version attribute"):
        load_train_file(bad_version)
    path = tmp_path / "a.rexs"
    path.write_bytes(stage().replace(b'applicationId="t"', b'applicationId="t\x7f\xc2\x85x"'))  # DEL, NEL
    text = toml_text(load_train_file(path))
    assert "\x7f" not in text and "\x85" not in text and "(REXS 1.7," in text


@pytest.mark.parametrize("call, says", [
    (lambda: loads_rexs_document("<model/>"), "loads_rexs_document: data must be the file's bytes, got str"),
    (lambda: loads_rexs_document(None), "got NoneType"),
    (lambda: loads_rexs_document(5), "got int"),
])
def test_api_calls_with_a_wrong_type_get_a_clear_error(call, says):
    # issue 30: these were AttributeError/TypeError tracebacks
    from epicyclic.errors import ModelError

    with pytest.raises(ModelError, match=says):
        call()


def test_api_writers_refuse_what_is_not_a_train_file():
    from epicyclic.errors import ModelError
    from epicyclic.exchange.convert import rexs_text, toml_text
    from epicyclic.exchange.reading import is_rexs

    with pytest.raises(ModelError, match="is_rexs: data must be the file's bytes, got str"):
        is_rexs("<model/>")
    for writer in (rexs_text, toml_text):
        with pytest.raises(ModelError, match=f"{writer.__name__}: train_file must be a train file"):
            writer(None)
    with pytest.raises(ModelError, match="kind must be 'xml' or 'json', got 'yaml'"):  # quietly returned JSON
        rexs_text(load_train_file("examples/brandenberger_1952.toml"), kind="yaml")
