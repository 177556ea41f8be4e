"""A REXS model as it stands in the file: components, relations, load cases, typed on access.

The three containers (XML, JSON, zip) are read into these value objects by
:mod:`epicyclic.exchange.container`; :mod:`epicyclic.exchange.mapping` maps
them onto a train description.  Attribute values stay as the file holds them
(XML: text; JSON: typed values) and are typed when read, so that one
malformed value is reported naming the file, the component id and name and
the attribute — and only when it is needed.

Examples
--------
>>> c = Component(7, "cylindrical_gear", "Sun", {"number_of_teeth": Attribute("number_of_teeth", "17", "")})
>>> m = RexsModel("t.rexs", "1.7", {7: c}, ())
>>> m.integer(c, "number_of_teeth")
17
>>> m.number(Component(8, "shaft", "S", {"rotational_speed": Attribute("rotational_speed", "fast", "1 / min")}),
...          "rotational_speed", "speed")
Traceback (most recent call last):
...
epicyclic.exchange.rexs_model.RexsValueError: t.rexs: component 8 (shaft 'S'), attribute 'rotational_speed': expected a number, got 'fast'.

References
----------
REXS file format (``rexs-schema.xsd``, ``rexs-schema.json``, FVA GmbH 2020,
github.com/BearinxSimulationSuite/REXSapi, Apache-2.0).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any

from ..io.source import InputFileError
from ..text import short
from .units import RexsUnitError, to_file_unit

__all__ = ["Attribute", "Component", "LoadCase", "Ref", "Relation", "RexsModel", "RexsValueError"]


class RexsValueError(InputFileError):
    """A REXS value that is malformed, missing or of the wrong kind; the message names the component and
    attribute."""


@dataclass(frozen=True)
class Attribute:
    """One attribute of a component: its id, raw value (XML text, or a typed JSON value) and REXS unit."""

    id: str
    value: Any
    unit: str = ""


@dataclass(frozen=True)
class Component:
    """A REXS component: id, type (``"cylindrical_gear"``, ...), name and attributes by id."""

    id: int
    type: str
    name: str
    attributes: Mapping[str, Attribute] = field(default_factory=dict)

    def __post_init__(self) -> None:
        object.__setattr__(self, "attributes", MappingProxyType(dict(self.attributes)))

    @property
    def label(self) -> str:
        """``component 9 (planetary_stage 'Planetenstufe [9]')`` for messages."""
        return f"component {self.id} ({self.type}" + (f" {short(self.name, 60)})" if self.name else ")")


@dataclass(frozen=True)
class Ref:
    """One end of a relation: the component id and its role (``"gear_1"``, ``"inner_part"``, ...)."""

    id: int
    role: str
    hint: str = ""


@dataclass(frozen=True)
class Relation:
    """A REXS relation: id, type (``"stage"``, ``"side"``, ...), optional order, its refs."""

    id: int
    type: str
    refs: tuple[Ref, ...]
    order: int | None = None

    def role(self, role: str) -> int | None:
        """The id of the component in ``role`` (the first if several), or None."""
        return next((r.id for r in self.refs if r.role == role), None)


@dataclass(frozen=True)
class LoadCase:
    """One load case of a load spectrum: attributes by component id that override the model's."""

    id: int
    spectrum: int
    components: Mapping[int, Mapping[str, Attribute]]


@dataclass(frozen=True)
class RexsModel:
    """A REXS model read from a file (any container), its values typed on access.

    Attributes
    ----------
    source : str
        The file, the start of every message.
    version : str
        The REXS version the file declares (``"1.1"`` ... ``"1.7"``).
    components : mapping id → Component
    relations : tuple of Relation
    load_cases : tuple of LoadCase
        Of every load spectrum, in file order.
    application : str
        ``applicationId`` and ``applicationVersion`` of the writing program.
    container : str
        ``"xml"``, ``"json"``, ``"zip/xml"`` or ``"zip/json"``.
    """

    source: str
    version: str
    components: Mapping[int, Component]
    relations: tuple[Relation, ...]
    load_cases: tuple[LoadCase, ...] = ()
    application: str = ""
    container: str = "xml"

    def __post_init__(self) -> None:
        # A relation that names a component the file does not have (one deleted, a typo) is an error here,
        # before any mapping: read past, it makes another train (a planet read as a fixed-axis stage).
        for relation in self.relations:
            for ref in relation.refs:
                if ref.id not in self.components:
                    what = f"relation {relation.id} ({relation.type}), role {ref.role!r}"
                    raise RexsValueError(f"{self.source}: {what} names component {ref.id}, which the file does not "
                                         "have; restore the component or delete the relation.", self.source, what)

    # ---- messages
    def error(self, component: Component | None, attribute: str | None, message: str) -> RexsValueError:
        """A :class:`RexsValueError` ``"<file>: component <id> (<type> '<name>'), attribute '<a>': <message>"``."""
        where = ", ".join(p for p in (component.label if component else "",
                                      f"attribute {attribute!r}" if attribute else "") if p)
        return RexsValueError(f"{self.source}: {where}: {message}" if where else f"{self.source}: {message}",
                              self.source, where)

    # ---- typed values
    def has(self, component: Component, attribute: str, overrides: Mapping[str, Attribute] | None = None) -> bool:
        """Whether ``component`` (or the load case's ``overrides``) gives ``attribute`` with a value."""
        found = (overrides or {}).get(attribute) or component.attributes.get(attribute)
        return found is not None and found.value not in (None, "", [])

    def _raw(self, component, attribute, overrides):
        found = (overrides or {}).get(attribute) or component.attributes.get(attribute)
        if found is None or found.value in (None, "", []):
            raise self.error(component, attribute, "missing; the file must give it for epicyclic to read the "
                                                   "component.")
        return found

    def number(self, component: Component, attribute: str, quantity: str = "number",
               overrides: Mapping[str, Attribute] | None = None) -> float:
        """A finite number in the train file's unit of ``quantity`` (see :mod:`epicyclic.exchange.units`).

        Parameters
        ----------
        component : Component
        attribute : str
            The attribute id.
        quantity : str, default "number"
            ``"length"``, ``"angle"``, ``"speed"``, ``"torque"``, ... (:data:`~epicyclic.exchange.units.FILE_UNITS`).
        overrides : mapping, optional
            A load case's attributes of this component, read first.

        Raises
        ------
        RexsValueError
            Missing, not a number, not finite, or in a unit of another quantity.
        """
        found = self._raw(component, attribute, overrides)
        value = found.value
        if isinstance(value, list) and len(value) == 1:
            value = value[0]
        if isinstance(value, bool):
            raise self.error(component, attribute, f"expected a number, got the boolean {value!r}.")
        if isinstance(value, str):
            try:
                value = float(value.strip())
            except ValueError:
                raise self.error(component, attribute, f"expected a number, got {short(value)}.") from None
        if not isinstance(value, (int, float)):
            raise self.error(component, attribute, f"expected a number, got {short(value)}.")
        try:
            value = float(value)
        except OverflowError:
            raise self.error(component, attribute, "the number is beyond double precision.") from None
        if not math.isfinite(value):
            raise self.error(component, attribute, f"expected a finite number, got {value!r}.")
        try:
            return to_file_unit(value, found.unit, quantity, f"{self.source}: {component.label}, attribute "
                                                             f"{attribute!r}")
        except RexsUnitError as exc:
            raise RexsValueError(str(exc), self.source, component.label) from None

    def integer(self, component: Component, attribute: str,
                overrides: Mapping[str, Attribute] | None = None) -> int:
        """A whole number (``17``, ``"17"`` or ``17.0`` as FVA-Workbench's JSON writes it).

        Parameters
        ----------
        component : Component
        attribute : str
        overrides : mapping, optional
            A load case's attributes of this component, read first.

        Raises
        ------
        RexsValueError
            Missing or not a whole number.
        """
        value = self.number(component, attribute, "number", overrides)
        if value != int(value) or abs(value) > 2**53:
            raise self.error(component, attribute, f"expected a whole number, got {value!r}.")
        return int(value)

    def boolean(self, component: Component, attribute: str, default: bool | None = None,
                overrides: Mapping[str, Attribute] | None = None) -> bool:
        """A boolean (``true``/``false`` in XML, a JSON boolean); ``default`` where the file has none.

        Parameters
        ----------
        component : Component
        attribute : str
        default : bool, optional
            Returned when the attribute is missing; None makes a missing attribute an error.
        overrides : mapping, optional
            A load case's attributes of this component, read first.

        Raises
        ------
        RexsValueError
            Missing (without ``default``) or not a boolean.
        """
        if default is not None and not self.has(component, attribute, overrides):
            return default
        value = self._raw(component, attribute, overrides).value
        if isinstance(value, list) and len(value) == 1:
            value = value[0]
        if isinstance(value, str) and value.strip().lower() in ("true", "false"):
            return value.strip().lower() == "true"
        if isinstance(value, bool):
            return value
        raise self.error(component, attribute, f"expected true or false, got {short(value)}.")

    def booleans(self, component: Component, attribute: str) -> tuple[bool, ...]:
        """A boolean array (``is_engaged`` of a switchable coupling, one value per gear).

        Parameters
        ----------
        component : Component
        attribute : str

        Raises
        ------
        RexsValueError
            Missing, or a value that is not true/false.
        """
        value = self._raw(component, attribute, None).value
        items = value if isinstance(value, list) else [value]
        out = []
        for item in items:
            if isinstance(item, str) and item.strip().lower() in ("true", "false"):
                out.append(item.strip().lower() == "true")
            elif isinstance(item, bool):
                out.append(item)
            else:
                raise self.error(component, attribute, f"expected an array of true/false, got {short(item)}.")
        return tuple(out)

    def text(self, component: Component, attribute: str, default: str = "") -> str:
        """A string or enum value (``default`` where the file has none or gives another kind of value).

        Parameters
        ----------
        component : Component
        attribute : str
        default : str, default ""
        """
        found = component.attributes.get(attribute)
        return found.value.strip() if found is not None and isinstance(found.value, str) else default

    # ---- structure
    def of_type(self, *types: str) -> list[Component]:
        """The components of the given types, by id."""
        return [c for _, c in sorted(self.components.items()) if c.type in types]

    def relations_of(self, *types: str) -> list[Relation]:
        """The relations of the given types, in file order."""
        return [r for r in self.relations if r.type in types]

    def component(self, cid: int | None, relation: Relation | None = None) -> Component:
        """The component with id ``cid`` (a relation naming an unknown id is an error naming it).

        Parameters
        ----------
        cid : int or None
            The id a relation names.
        relation : Relation, optional
            The relation, for the message.

        Raises
        ------
        RexsValueError
            No component has that id.
        """
        if cid is None or cid not in self.components:
            what = f"relation {relation.id} ({relation.type})" if relation else "a relation"
            raise RexsValueError(f"{self.source}: {what} names component {cid}, which the file does not have.",
                                 self.source, what)
        return self.components[cid]
