"""A damaged REXS file never gives a traceback: every outcome is a train or an EpicyclicError.

The FVA planetary stage (examples/rexs, fva-net/rexs-api-java, Apache-2.0) with random damage: a value
replaced, a piece cut out, an id changed, in XML and in JSON.
"""

from __future__ import annotations

import json
from pathlib import Path

from hypothesis import HealthCheck, given, settings, strategies as st

from epicyclic.errors import EpicyclicError
from epicyclic.exchange.reading import loads_rexs_document
from epicyclic.io.toml_format import read_document

XML = (Path(__file__).resolve().parents[2] / "examples" / "rexs" / "FVA_Planetary_stage_-_Minus_gearing_1.1.rexs"
       ).read_bytes()
JUNK = st.sampled_from(["", "-1", "0", "1e400", "nan", "true", "x", "99999", "17.5", "<", "&amp;", "[]", "{}", '"'])


def outcome(data: bytes) -> None:
    try:
        train_file = read_document(loads_rexs_document(data, "damaged.rexs"))
        if train_file.operating_point is not None:
            train_file.solve()
    except EpicyclicError:
        pass  # a clear error: fine


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(at=st.integers(0, len(XML) - 1), cut=st.integers(0, 40), junk=JUNK)
def test_damaged_xml(at, cut, junk):
    outcome(XML[:at] + junk.encode() + XML[at + cut:])


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data())
def test_damaged_values(data):
    values = [p for p in XML.split(b">") if p and not p.startswith(b"<") and b"<" in p]
    piece = data.draw(st.sampled_from(values))
    junk = data.draw(JUNK).encode()
    outcome(XML.replace(piece, junk + piece[piece.index(b"<"):], 1))


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data())
def test_damaged_json(data):
    from epicyclic.exchange.container import read_model
    from epicyclic.exchange.serialize import RexsBuilder

    model = read_model(XML, "x")
    builder = RexsBuilder("t", "1")
    for cid, c in sorted(model.components.items()):
        builder._next = cid
        builder.component(c.type, c.name, [(a.id, "string", a.value if isinstance(a.value, str) else json.dumps(a.value),
                                            a.unit) for a in c.attributes.values()])
    for r in model.relations:
        builder.relation(r.type, [(ref.id, ref.role) for ref in r.refs], r.order)
    document = json.loads(builder.json())
    components = document["model"]["components"]
    victim = data.draw(st.sampled_from(components))
    field = data.draw(st.sampled_from(["id", "type", "attributes"]))
    victim[field] = data.draw(st.sampled_from([None, -1, "x", [], {}, 1.5, True]))
    outcome(json.dumps(document).encode())


@settings(max_examples=20, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data())
def test_a_relation_or_component_removed(data):
    import re

    blocks = [m.group() for m in re.finditer(rb"<relation [^>]*>.*?</relation>|<component [^>]*>.*?</component>",
                                             XML, re.DOTALL)]
    victim = data.draw(st.sampled_from(blocks))
    outcome(XML.replace(victim, b"", 1))
