"""Read a REXS file in any of its containers, safely: XML (``.rexs``), JSON (``.rexsj``), zip (``.rexsz``).

The container is chosen by content, not by suffix (:func:`sniff`): the zip
signature ``PK\\x03\\x04``, else the first character that is not white space
(a byte-order mark skipped): ``<`` is XML, ``{`` is JSON.  A TOML train file
starts with neither.  Limits (``docs/limits.md``), each checked before the
work it guards:

* the file, and the model inside a zip, at most
  :func:`~epicyclic.limits.max_rexs_bytes` (16 MiB by default);
* XML is parsed by :mod:`defusedxml`: a document type declaration, entity
  declarations and external references are refused (no billion laughs, no
  XXE); elements nest at most :data:`~epicyclic.limits.MAX_NESTING` deep
  (REXS needs 7), found while parsing;
* JSON nests at most :data:`~epicyclic.limits.MAX_NESTING` deep (found by a
  linear scan before :mod:`json` recurses), ``NaN``/``Infinity`` are refused;
* at most :data:`~epicyclic.limits.MAX_REXS_COMPONENTS` components,
  :data:`~epicyclic.limits.MAX_REXS_RELATIONS` relations and
  :data:`~epicyclic.limits.MAX_REXS_ARRAY_VALUES` values in one array;
* a zip holds exactly one ``.rexs`` or ``.rexsj`` model (other files, such as
  the gear data files the standard allows beside it, are skipped), expands at
  most :data:`~epicyclic.limits.MAX_ZIP_RATIO` times its compressed size and
  is read only up to the size limit, so a zip bomb is refused unexpanded.

Examples
--------
>>> read_model(b'<model version="1.7" applicationId="x" applicationVersion="1" date="d"/>', "m.rexs").version
'1.7'
>>> read_model(b'<!DOCTYPE m [<!ENTITY a "b">]><model/>', "m.rexs")
Traceback (most recent call last):
...
epicyclic.exchange.rexs_model.RexsValueError: m.rexs: the XML declares a document type or entities (DTDForbidden); REXS has none, and they are refused (entity expansion, external references).

References
----------
REXS file formats: ``rexs-schema.xsd`` and ``rexs-schema.json`` (FVA GmbH 2020,
github.com/BearinxSimulationSuite/REXSapi ``models/``, Apache-2.0); the zip container
as written by FVA-Workbench (github.com/fva-net/rexs-api-java, ``api/src/test/resources``).
"""

from __future__ import annotations

import base64
import io
import json
import re
import struct
import zipfile
from pathlib import Path
from typing import Any

from ..io.source import sniff
from ..limits import (
    MAX_NESTING,
    MAX_REXS_ARRAY_VALUES,
    MAX_REXS_COMPONENTS,
    MAX_REXS_RELATIONS,
    MAX_ZIP_RATIO,
    max_rexs_bytes,
)
from ..text import short
from .rexs_model import (
    Attribute,
    Component,
    LoadCase,
    Ref,
    Relation,
    RexsModel,
    RexsValueError,
)

__all__ = ["REXS_SUFFIXES", "parse_model", "read_model", "sniff"]

REXS_SUFFIXES = (".rexs", ".rexsj", ".rexsz")


def _size(n: int) -> str:
    return f"{n / 1048576:.3g} MiB ({n:,} bytes)" if n >= 1048576 else f"{n:,} bytes"


def read_model(data: bytes, source: str) -> RexsModel:
    """The REXS model in the bytes ``data`` of the file ``source`` (container by :func:`sniff`).

    Parameters
    ----------
    data : bytes
        The whole file (already read within the size limit).
    source : str
        The file name, the start of every message.

    Returns
    -------
    RexsModel

    Raises
    ------
    RexsValueError
        Not a REXS file, malformed, or past a limit; the message names the file and what is wrong.
    """
    kind = sniff(data)
    if kind is None:
        raise RexsValueError(f"{source}: not a REXS file: it starts with neither '<' (XML), '{{' (JSON) nor a zip "
                             "signature.", source)
    limit = max_rexs_bytes()
    if len(data) > limit:
        raise RexsValueError(f"{source}: the file is {_size(len(data))}; at most {_size(limit)} of REXS are read "
                             "(see docs/limits.md; raise the limit with EPICYCLIC_MAX_FILE_BYTES).", source)
    if kind == "zip":
        inner, member = _unzip(data, source)
        kind = sniff(inner)
        if kind is None:
            raise RexsValueError(f"{source}: the zip member {member!r} is neither REXS XML nor JSON.", source)
        return parse_model(inner, source, kind, "zip/")
    return parse_model(data, source, kind)


def parse_model(data: bytes, source: str, kind: str, container: str = "") -> RexsModel:
    """The model of REXS XML (``kind="xml"``) or JSON (``kind="json"``) bytes.

    Parameters
    ----------
    data : bytes
        The XML or JSON document.
    source : str
        The file name, for messages.
    kind : str
        ``"xml"`` or ``"json"``.
    container : str, default ""
        ``"zip/"`` for a model read from a zip (recorded in :attr:`RexsModel.container`).

    Raises
    ------
    RexsValueError
        Malformed, or past a limit; :class:`~epicyclic.exchange.versions.RexsVersionError` for a
        version that is not read (1.0 … 1.7 and 2.0.0 are).
    """
    from .versions import model_as_read

    model = _parse_xml(data, source) if kind == "xml" else _parse_json(data, source)
    return model_as_read(RexsModel(model["source"], model["version"], model["components"], model["relations"],
                                   model["load_cases"], model["application"], container + kind))


# ---------------------------------------------------------------------- zip
def _unzip(data: bytes, source: str) -> tuple[bytes, str]:
    try:
        archive = zipfile.ZipFile(io.BytesIO(data))
    except (zipfile.BadZipFile, ValueError, OSError) as exc:
        raise RexsValueError(f"{source}: not a readable zip file ({short(str(exc), 60)}).", source) from None
    with archive:
        infos = archive.infolist()
        if len(infos) > 1000:
            raise RexsValueError(f"{source}: the zip holds {len(infos):,} files; a .rexsz holds one model and a "
                                 "few gear data files.", source)
        models = [i for i in infos if not i.is_dir() and Path(i.filename).suffix.lower() in (".rexs", ".rexsj")
                  and not Path(i.filename).name.startswith("._") and "__MACOSX" not in i.filename]
        if len(models) != 1:
            found = ", ".join(repr(i.filename[:60]) for i in models[:3]) or "none"
            raise RexsValueError(f"{source}: a .rexsz must hold exactly one .rexs or .rexsj model; found {found}.",
                                 source)
        info = models[0]
        limit = max_rexs_bytes()
        if info.file_size > limit:
            raise RexsValueError(f"{source}: the model {info.filename[:60]!r} expands to {_size(info.file_size)}; at "
                                 f"most {_size(limit)} are read (see docs/limits.md).", source)
        if info.file_size > MAX_ZIP_RATIO * max(info.compress_size, 1) and info.file_size > 65536:
            raise RexsValueError(f"{source}: the model {info.filename[:60]!r} expands {info.file_size / max(info.compress_size, 1):,.0f} "
                                 f"times (at most {MAX_ZIP_RATIO}): a zip bomb, refused unexpanded.", source)
        try:
            with archive.open(info) as handle:
                inner = handle.read(limit + 1)  # the header's size may lie: never read past the limit
        except (zipfile.BadZipFile, NotImplementedError, RuntimeError, OSError, EOFError) as exc:
            raise RexsValueError(f"{source}: cannot expand {info.filename[:60]!r} ({short(str(exc), 60)}).",
                                 source) from None
        if len(inner) > limit or len(inner) > MAX_ZIP_RATIO * max(info.compress_size, 1) + 65536:
            raise RexsValueError(f"{source}: the model {info.filename[:60]!r} expands beyond its declared size or "
                                 f"{MAX_ZIP_RATIO} times its compressed size: a zip bomb, refused.", source)
        return inner, info.filename


# ---------------------------------------------------------------------- XML
def _parse_xml(data: bytes, source: str) -> dict[str, Any]:
    from xml.etree.ElementTree import ParseError

    from defusedxml import DTDForbidden, EntitiesForbidden, ExternalReferenceForbidden
    from defusedxml.ElementTree import iterparse

    depth, count, root = 0, 0, None
    try:
        for event, element in iterparse(io.BytesIO(data), events=("start", "end"), forbid_dtd=True):
            if event == "start":
                depth += 1
                count += 1
                if root is None:
                    root = element
                if depth > MAX_NESTING:
                    raise RexsValueError(f"{source}: XML elements are nested more than {MAX_NESTING} levels deep; "
                                         "REXS needs 7 (see docs/limits.md).", source)
                if count > 4 * (MAX_REXS_COMPONENTS + MAX_REXS_RELATIONS) * 10:
                    raise RexsValueError(f"{source}: the file holds more than {count:,} XML elements (see "
                                         "docs/limits.md).", source)
            else:
                depth -= 1
    except (DTDForbidden, EntitiesForbidden, ExternalReferenceForbidden) as exc:
        raise RexsValueError(f"{source}: the XML declares a document type or entities ({type(exc).__name__}); "
                             "REXS has none, and they are refused (entity expansion, external references).",
                             source) from None
    except ParseError as exc:
        raise RexsValueError(f"{source}: not well-formed XML ({short(str(exc), 80)}).", source) from None
    if root is None or root.tag != "model":
        raise RexsValueError(f"{source}: the XML root element is {short(getattr(root, 'tag', None))}, not <model>: "
                             "not a REXS file.", source)
    version = root.get("version", "")
    application = " ".join(p for p in (root.get("applicationId", ""), root.get("applicationVersion", "")) if p)
    components: dict[int, Component] = {}
    relations: list[Relation] = []
    load_cases: list[LoadCase] = []
    for part in root:
        if part.tag == "components":
            for element in part:
                if element.tag == "component":
                    _add_component(components, _xml_component(element, source), source)
        elif part.tag == "relations":
            for element in part:
                if element.tag == "relation":
                    relations.append(_xml_relation(element, source))
                    _count(len(relations), MAX_REXS_RELATIONS, "relations", source)
        elif part.tag == "load_spectrum":
            spectrum = _integer(part.get("id", "0"), source, "load_spectrum", "id")
            for case in part:
                if case.tag == "load_case":
                    cid = _integer(case.get("id"), source, f"load_spectrum {spectrum}, load_case", "id")
                    overrides = {}
                    for element in case:
                        if element.tag == "component":
                            comp = _xml_component(element, source)
                            overrides[comp.id] = dict(comp.attributes)
                    load_cases.append(LoadCase(cid, spectrum, overrides))
    return {"source": source, "version": version, "application": application, "components": components,
            "relations": tuple(relations), "load_cases": tuple(load_cases)}


def _xml_component(element, source: str) -> Component:
    cid = _integer(element.get("id"), source, "component", "id")
    ctype = element.get("type") or ""
    attributes = {}
    for a in element:
        if a.tag != "attribute" or not a.get("id"):
            continue
        children = list(a)
        if children:
            value = _xml_array(children[0], source, f"component {cid}, attribute {a.get('id')!r}")
        else:
            value = (a.text or "").strip()
        attributes[a.get("id")] = Attribute(a.get("id"), value, a.get("unit") or "")
    return Component(cid, ctype, (element.get("name") or "").strip(), attributes)


def _xml_array(element, source: str, where: str):
    code = element.get("code")
    if element.tag == "array":
        if code:
            return _decode(element.text or "", code, source, where)
        values = [(c.text or "").strip() for c in element if c.tag == "c"]
        _count(len(values), MAX_REXS_ARRAY_VALUES, "array values", source)
        return values
    if element.tag == "matrix":
        rows = [[(c.text or "").strip() for c in r] for r in element if r.tag == "r"]
        _count(sum(len(r) for r in rows), MAX_REXS_ARRAY_VALUES, "matrix values", source)
        return rows
    if element.tag == "array_of_arrays":
        return [_xml_array(child, source, where) for child in element]
    return (element.text or "").strip()


def _xml_relation(element, source: str) -> Relation:
    rid = _integer(element.get("id"), source, "relation", "id")
    order = element.get("order")
    refs = tuple(Ref(_integer(r.get("id"), source, f"relation {rid}, ref", "id"), r.get("role") or "",
                     r.get("hint") or "") for r in element if r.tag == "ref")
    return Relation(rid, element.get("type") or "", refs,
                    _integer(order, source, f"relation {rid}", "order") if order is not None else None)


# ---------------------------------------------------------------------- JSON
_JSON_INTEREST = re.compile(r'[\[\]{}"]')
_JSON_STRING_REST = re.compile(r'(?:[^"\\]|\\.)*"', re.DOTALL)


def _check_json_nesting(text: str, source: str) -> None:
    depth, i = 0, 0
    while (match := _JSON_INTEREST.search(text, i)) is not None:
        char = match.group()
        if char == '"':
            rest = _JSON_STRING_REST.match(text, match.end())
            if rest is None:
                return  # an unterminated string: json reports it
            i = rest.end()
            continue
        depth += 1 if char in "[{" else -1
        if depth > MAX_NESTING:
            line = text.count("\n", 0, match.start()) + 1
            raise RexsValueError(f"{source}: line {line}: JSON arrays and objects are nested more than {MAX_NESTING} "
                                 "levels deep; REXS needs 8 (see docs/limits.md).", source)
        i = match.end()


def _reject_constant(name: str):
    raise ValueError(f"{name} is not a JSON number")


def _parse_json(data: bytes, source: str) -> dict[str, Any]:
    try:
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        raise RexsValueError(f"{source}: not UTF-8 text (byte 0x{data[exc.start]:02x} at {exc.start}).",
                             source) from None
    _check_json_nesting(text, source)
    try:
        document = json.loads(text, parse_constant=_reject_constant)
    except (ValueError, RecursionError) as exc:
        raise RexsValueError(f"{source}: not valid JSON ({short(str(exc), 80)}).", source) from None
    model = document.get("model") if isinstance(document, dict) else None
    if not isinstance(model, dict):
        raise RexsValueError(f"{source}: the JSON has no object \"model\": not a REXS file.", source)
    components: dict[int, Component] = {}
    for item in _list(model, "components", source):
        _add_component(components, _json_component(item, source, "component"), source)
    relations = []
    for item in _list(model, "relations", source):
        if not isinstance(item, dict):
            raise RexsValueError(f"{source}: a relation is {short(item)}, not an object.", source)
        rid = _integer(item.get("id"), source, "relation", "id")
        refs = []
        for ref in _list(item, "refs", source):
            if not isinstance(ref, dict):
                raise RexsValueError(f"{source}: relation {rid}: a ref is {short(ref)}, not an object.", source)
            refs.append(Ref(_integer(ref.get("id"), source, f"relation {rid}, ref", "id"), str(ref.get("role", "")),
                            str(ref.get("hint", "") or "")))
        order = item.get("order")
        relations.append(Relation(rid, str(item.get("type", "")), tuple(refs),
                                  None if order is None else _integer(order, source, f"relation {rid}", "order")))
        _count(len(relations), MAX_REXS_RELATIONS, "relations", source)
    load_cases = []
    spectra = model.get("load_spectrum", [])
    for spectrum in spectra if isinstance(spectra, list) else [spectra]:
        if not isinstance(spectrum, dict):
            continue
        sid = _integer(spectrum.get("id", 0), source, "load_spectrum", "id")
        for case in _list(spectrum, "load_cases", source):
            if not isinstance(case, dict):
                continue
            cid = _integer(case.get("id"), source, f"load_spectrum {sid}, load_case", "id")
            overrides = {}
            for item in _list(case, "components", source):
                comp = _json_component(item, source, f"load case {cid}, component")
                overrides[comp.id] = dict(comp.attributes)
            load_cases.append(LoadCase(cid, sid, overrides))
    application = " ".join(str(model.get(k, "")) for k in ("applicationId", "applicationVersion") if model.get(k))
    return {"source": source, "version": str(model.get("version", "")), "application": application,
            "components": components, "relations": tuple(relations), "load_cases": tuple(load_cases)}


_CODED = {"floating_point_array_coded", "integer_array_coded", "floating_point_matrix_coded"}


def _json_component(item, source: str, what: str) -> Component:
    if not isinstance(item, dict):
        raise RexsValueError(f"{source}: a {what} is {short(item)}, not an object.", source)
    cid = _integer(item.get("id"), source, what, "id")
    attributes = {}
    for a in _list(item, "attributes", source):
        if not isinstance(a, dict) or not isinstance(a.get("id"), str):
            raise RexsValueError(f"{source}: component {cid}: an attribute is {short(a)}, not an object with an "
                                 "\"id\".", source)
        kinds = [k for k in a if k not in ("id", "unit")]
        value = a[kinds[0]] if kinds else None
        if kinds and kinds[0] in _CODED and isinstance(value, dict):
            value = _decode(str(value.get("value", "")), str(value.get("code", "")), source,
                            f"component {cid}, attribute {a['id']!r}")
        elif isinstance(value, list):
            _count(len(value), MAX_REXS_ARRAY_VALUES, "array values", source)
        attributes[a["id"]] = Attribute(a["id"], value, str(a.get("unit", "") or ""))
    name = item.get("name")
    return Component(cid, str(item.get("type", "")), name.strip() if isinstance(name, str) else "", attributes)


def _list(table: dict, key: str, source: str) -> list:
    value = table.get(key, [])
    if value is None:
        return []
    if not isinstance(value, list):
        raise RexsValueError(f"{source}: \"{key}\" is {short(value)}, not an array.", source)
    return value


# ---------------------------------------------------------------------- shared
def _add_component(components: dict[int, Component], component: Component, source: str) -> None:
    if component.id in components:
        raise RexsValueError(f"{source}: component id {component.id} is used twice ({components[component.id].type} "
                             f"and {component.type}); ids must be unique.", source)
    components[component.id] = component
    _count(len(components), MAX_REXS_COMPONENTS, "components", source)


def _count(count: int, maximum: int, what: str, source: str) -> None:
    if count > maximum:
        raise RexsValueError(f"{source}: the file holds more than {maximum:,} {what} (see docs/limits.md).", source)


def _integer(value: object, source: str, what: str, key: str) -> int:
    if isinstance(value, bool):
        value = None
    if isinstance(value, str) and re.fullmatch(r"\s*-?\d{1,15}\s*", value):
        return int(value)
    if isinstance(value, int) and abs(value) < 10**15:
        return value
    if isinstance(value, float) and value.is_integer() and abs(value) < 1e15:
        return int(value)
    raise RexsValueError(f"{source}: {what}: {key!r} must be a whole number, got {short(value)}.", source)


def _decode(text: str, code: str, source: str, where: str) -> list:
    formats = {"float64": "d", "float32": "f", "int32": "i"}
    if code not in formats:
        raise RexsValueError(f"{source}: {where}: unknown array code {short(code)}; REXS codes are float64, float32 "
                             "and int32.", source)
    try:
        raw = base64.b64decode(text.strip(), validate=True)
    except ValueError:
        raise RexsValueError(f"{source}: {where}: the coded array is not base64.", source) from None
    size = struct.calcsize(formats[code])
    if len(raw) % size or len(raw) // size > MAX_REXS_ARRAY_VALUES:
        raise RexsValueError(f"{source}: {where}: the coded array holds {len(raw)} bytes, not a whole number of "
                             f"{code} values within {MAX_REXS_ARRAY_VALUES:,}.", source)
    return list(struct.unpack(f"<{len(raw) // size}{formats[code]}", raw))
