"""Write a REXS model as XML (``.rexs``) or JSON (``.rexsj``), the layouts of the official schemas.

:class:`RexsBuilder` collects components (with typed attributes), relations
and load cases; :meth:`RexsBuilder.xml` and :meth:`RexsBuilder.json` write
them so that they validate against ``rexs-schema.xsd`` and
``rexs-schema.json`` (shipped in ``epicyclic/exchange/schema/``; the tests
validate every file written).  Non-finite numbers are never written.

Examples
--------
>>> b = RexsBuilder("epicyclic", "0.1", date="2026-01-01T00:00:00+00:00")
>>> unit = b.component("gear_unit", "Gear unit", [("number_of_gears", "integer", 1, "none")])
>>> print(b.xml().splitlines()[1])
<model version="1.7" applicationId="epicyclic" applicationVersion="0.1" date="2026-01-01T00:00:00+00:00" applicationLanguage="en">

References
----------
``rexs-schema.xsd``, ``rexs-schema.json`` (FVA GmbH 2020, github.com/BearinxSimulationSuite/REXSapi ``models/``,
Apache-2.0).
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass, field
from datetime import datetime, timezone
from typing import Any
from xml.sax.saxutils import escape, quoteattr

__all__ = ["REXS_VERSION", "RexsBuilder"]

#: The REXS version written (the newest 1.x release of the FVA database, ``rexs_schema_1.7.xml``).
REXS_VERSION = "1.7"

_KINDS = ("floating_point", "integer", "boolean", "string", "enum", "boolean_array", "floating_point_array",
          "integer_array", "string_array", "reference_component")


@dataclass
class _Component:
    id: int
    type: str
    name: str
    attributes: list[tuple[str, str, Any, str]] = field(default_factory=list)


class RexsBuilder:
    """A REXS model under construction.

    Parameters
    ----------
    application : str
        ``applicationId``.
    version : str
        ``applicationVersion``.
    date : str, optional
        ISO 8601 with offset (``2026-01-01T00:00:00+00:00``); default now (UTC).
    """

    def __init__(self, application: str, version: str, date: str | None = None):
        self.application, self.version = application, version
        self.date = date or datetime.now(timezone.utc).replace(microsecond=0).isoformat()
        self.components: list[_Component] = []
        self.relations: list[tuple[int, str, int | None, list[tuple[int, str, str]]]] = []
        self.load_cases: list[tuple[int, list[tuple[int, list[tuple[str, str, Any, str]]]]]] = []
        self._next = 1

    def _id(self) -> int:
        self._next += 1
        return self._next - 1

    def component(self, ctype: str, name: str, attributes: list[tuple[str, str, Any, str]] = ()) -> int:
        """Add a component; returns its id.

        Parameters
        ----------
        ctype : str
            The REXS component type (``"shaft"``, ``"cylindrical_gear"``, ...).
        name : str
        attributes : list of (id, kind, value, unit)
            ``kind`` one of ``floating_point``, ``integer``, ``boolean``, ``string``, ``boolean_array``, ...;
            an attribute whose value is None is left out.
        """
        for _, kind, value, _ in attributes:
            self._check(kind, value)
        c = _Component(self._id(), ctype, name, [a for a in attributes if a[2] is not None])
        self.components.append(c)
        return c.id

    def add(self, cid: int, attributes: list[tuple[str, str, Any, str]]) -> None:
        """Add attributes to the component ``cid``.

        Parameters
        ----------
        cid : int
        attributes : list of (id, kind, value, unit)
        """
        for _, kind, value, _ in attributes:
            self._check(kind, value)
        target = next(c for c in self.components if c.id == cid)
        target.attributes.extend(a for a in attributes if a[2] is not None)

    def relation(self, rtype: str, refs: list[tuple[int, str]], order: int | None = None) -> None:
        """Add a relation of ``rtype`` between ``refs`` (component id, role).

        Parameters
        ----------
        rtype : str
        refs : list of (int, str)
        order : int, optional
        """
        hints = {c.id: c.type for c in self.components}
        self.relations.append((self._id(), rtype, order, [(cid, role, hints.get(cid, "")) for cid, role in refs]))

    def load_case(self, overrides: list[tuple[int, list[tuple[str, str, Any, str]]]]) -> None:
        """Add a load case: attributes by component id.

        Parameters
        ----------
        overrides : list of (int, list of (id, kind, value, unit))
        """
        merged: dict[int, list] = {}
        for cid, attributes in overrides:
            for _, kind, value, _ in attributes:
                self._check(kind, value)
            merged.setdefault(cid, []).extend(attributes)  # one entry per component
        self.load_cases.append((len(self.load_cases) + 1, list(merged.items())))

    @staticmethod
    def _check(kind: str, value: Any) -> None:
        if kind not in _KINDS:
            raise ValueError(f"unknown REXS value kind {kind!r}")
        values = value if isinstance(value, list) else [value]
        if any(isinstance(v, float) and not math.isfinite(v) for v in values):
            raise ValueError("REXS files never hold NaN or infinity")

    # ---- XML
    @staticmethod
    def _xml_value(kind: str, value: Any) -> str:
        if kind.endswith("_array"):
            return "<array>" + "".join(f"<c>{RexsBuilder._xml_value(kind[:-6], v)}</c>" for v in value) + "</array>"
        if kind == "boolean":
            return "true" if value else "false"
        if kind == "floating_point":
            return repr(float(value))
        return escape(str(value))

    @staticmethod
    def _as_written(attributes, rexs_version: str):
        """(id, kind, value, unit) in the ids and units of ``rexs_version`` (built with 1.7's)."""
        from .versions import written_attribute

        for aid, kind, value, unit in attributes:
            aid, unit, value = written_attribute(aid, unit, value, rexs_version)
            yield aid, kind, value, unit

    def _xml_attributes(self, attributes, indent: str, rexs_version: str = REXS_VERSION) -> list[str]:
        return [f"{indent}<attribute id={quoteattr(aid)} unit={quoteattr(unit)}>{self._xml_value(kind, value)}"
                "</attribute>" for aid, kind, value, unit in self._as_written(attributes, rexs_version)]

    def xml(self, rexs_version: str = REXS_VERSION) -> str:
        """The model as REXS XML text.

        Parameters
        ----------
        rexs_version : str, default "1.7"
            ``"1.7"`` or ``"2.0.0"`` (attribute ids and units translated,
            :func:`~epicyclic.exchange.versions.written_attribute`).

        Returns
        -------
        str
        """
        out = ['<?xml version="1.0" encoding="UTF-8"?>',
               f"<model version={quoteattr(rexs_version)} applicationId={quoteattr(self.application)} "
               f"applicationVersion={quoteattr(self.version)} date={quoteattr(self.date)} "
               'applicationLanguage="en">', "  <relations>"]
        for rid, rtype, order, refs in self.relations:
            extra = f' order="{order}"' if order is not None else ""
            out.append(f'    <relation id="{rid}" type={quoteattr(rtype)}{extra}>')
            out += [f'      <ref id="{cid}" role={quoteattr(role)} hint={quoteattr(hint)}/>' for cid, role, hint in refs]
            out.append("    </relation>")
        out.append("  </relations>")
        out.append("  <components>")
        for c in self.components:
            out.append(f'    <component id="{c.id}" type={quoteattr(c.type)} name={quoteattr(c.name)}>')
            out += self._xml_attributes(c.attributes, "      ", rexs_version)
            out.append("    </component>")
        out.append("  </components>")
        if self.load_cases:
            out.append('  <load_spectrum id="1">')
            for lid, overrides in self.load_cases:
                out.append(f'    <load_case id="{lid}">')
                for cid, attributes in overrides:
                    c = next(x for x in self.components if x.id == cid)
                    out.append(f'      <component id="{cid}" type={quoteattr(c.type)} name={quoteattr(c.name)}>')
                    out += self._xml_attributes(attributes, "        ", rexs_version)
                    out.append("      </component>")
                out.append("    </load_case>")
            out.append("  </load_spectrum>")
        out.append("</model>")
        return "\n".join(out) + "\n"

    # ---- JSON
    def _json_attributes(self, attributes, rexs_version: str = REXS_VERSION) -> list[dict[str, Any]]:
        return [{"id": aid, "unit": unit, kind: value}
                for aid, kind, value, unit in self._as_written(attributes, rexs_version)]

    def json(self, rexs_version: str = REXS_VERSION) -> str:
        """The model as REXS JSON text.

        Parameters
        ----------
        rexs_version : str, default "1.7"
            ``"1.7"`` or ``"2.0.0"``.

        Returns
        -------
        str
        """
        types = {c.id: c for c in self.components}
        model: dict[str, Any] = {
            "version": rexs_version, "applicationId": self.application, "applicationVersion": self.version,
            "date": self.date, "applicationLanguage": "en",
            "relations": [{"id": rid, "type": rtype, **({"order": order} if order is not None else {}),
                           "refs": [{"id": cid, "role": role, "hint": hint} for cid, role, hint in refs]}
                          for rid, rtype, order, refs in self.relations],
            "components": [{"id": c.id, "type": c.type, "name": c.name,
                            "attributes": self._json_attributes(c.attributes, rexs_version)}
                           for c in self.components],
        }
        if self.load_cases:
            model["load_spectrum"] = {"id": 1, "load_cases": [
                {"id": lid, "components": [{"id": cid, "type": types[cid].type, "name": types[cid].name,
                                            "attributes": self._json_attributes(attributes, rexs_version)}
                                           for cid, attributes in overrides]} for lid, overrides in self.load_cases]}
        return json.dumps({"model": model}, indent=1, ensure_ascii=False, allow_nan=False) + "\n"
