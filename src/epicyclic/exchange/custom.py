"""epicyclic's own data in a REXS file: ``custom_epicyclic_*`` attributes holding JSON objects.

REXS lets a program add attributes whose id starts with ``custom_``; epicyclic
writes what REXS has no attribute for (efficiencies, loss models, the
schedule's gear names, the title) as a JSON object in one string attribute per
component, and reads it back (:func:`custom`).  Other programs keep and ignore
them.

Examples
--------
>>> from epicyclic.exchange.rexs_model import Attribute, Component, RexsModel
>>> c = Component(9, "planetary_stage", "P", {CUSTOM_ELEMENT: Attribute(CUSTOM_ELEMENT, '{"stationary_efficiency": 0.98}')})
>>> custom(RexsModel("t.rexs", "1.7", {9: c}, ()), c, CUSTOM_ELEMENT)
{'stationary_efficiency': 0.98}

References
----------
REXS 1.7 specification, custom attributes (``custom_`` prefix), FVA GmbH, rexs.info.
"""

from __future__ import annotations

import json
from typing import Any

from ..limits import MAX_STRING_CHARS
from .rexs_model import Component, RexsModel

__all__ = ["CUSTOM_ELEMENT", "CUSTOM_DOCUMENT", "SPIN_TABLES", "custom"]

#: The train file's spin-loss tables (pump, housing, seals, churning, windage; docs/losses.md): REXS has no
#: attribute for them, so they travel in the document's custom attribute.
SPIN_TABLES = ("pump", "housing", "seal", "churning", "windage", "defaults")

#: Custom attribute (a JSON string) with an element's keys that REXS has no attribute for.
CUSTOM_ELEMENT = "custom_epicyclic_element"
#: Custom attribute of the ``gear_unit`` with the document's keys that REXS has no attribute for.
CUSTOM_DOCUMENT = "custom_epicyclic_document"


def _no_constant(name: str):
    raise ValueError(f"{name} is not a JSON number")


def custom(model: RexsModel, component: Component | None, attribute: str) -> dict[str, Any]:
    """The JSON object of a ``custom_epicyclic_*`` string attribute ({} where there is none).

    Parameters
    ----------
    model : RexsModel
    component : Component or None
    attribute : str
        :data:`CUSTOM_ELEMENT` or :data:`CUSTOM_DOCUMENT`.

    Raises
    ------
    RexsValueError
        The attribute is not a JSON object of at most :data:`~epicyclic.limits.MAX_STRING_CHARS` characters.
    """
    if component is None or attribute not in component.attributes:
        return {}
    text = component.attributes[attribute].value
    if not isinstance(text, str) or len(text) > MAX_STRING_CHARS:
        raise model.error(component, attribute, f"expected a JSON object of at most {MAX_STRING_CHARS:,} "
                                                "characters.")
    try:
        value = json.loads(text, parse_constant=_no_constant)
    except (ValueError, RecursionError) as exc:
        raise model.error(component, attribute, f"not a JSON object ({str(exc)[:60]}).") from None
    if not isinstance(value, dict):
        raise model.error(component, attribute, "expected a JSON object.")
    return value
