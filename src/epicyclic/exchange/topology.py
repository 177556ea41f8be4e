"""Which REXS bodies turn as one: the members (shafts) of a train, read from couplings and assemblies.

A REXS gearbox is built of many bodies — shafts, planet pins, carrier side
plates, the casing — joined by relations.  Bodies joined rigidly turn as one
member of our train:

* a ``coupling`` in a ``side`` relation joins its inner and outer part;
* a ``planet_carrier`` and the parts assembled into it (plates, pins) are one
  body, together with the ``planet_carrier_shaft`` shafts of its stage;
* everything joined to the ``gear_casing`` is the housing.

Bearings (``concept_bearing``, ``rolling_bearing_*``) let the parts they
join turn against each other: they join nothing.  A ``switchable_coupling``
is a clutch (between two members) or a brake (against the casing), not a
join.  :class:`Members` finds the members (a union–find over component ids)
and names each after one of its shafts.

References
----------
REXS 1.7 relation types ``side``, ``assembly``, ``planet_carrier_shaft``
(``rexs_schema_1.7.xml``, FVA GmbH, github.com/fva-net/rexs-api-java, Apache-2.0).
"""

from __future__ import annotations

from ..limits import MAX_NAME_CHARS
from ..model import HOUSING
from .rexs_model import Component, RexsModel

__all__ = ["BEARING_TYPES", "GEAR_TYPES", "Members", "element_name"]

GEAR_TYPES = ("cylindrical_gear", "ring_gear")
BEARING_TYPES = ("concept_bearing", "rolling_bearing_with_catalog_geometry", "rolling_bearing_with_detailed_geometry",
                 "fluid_film_bearing", "bearing")
_BODY_TYPES = ("shaft", "side_plate", "planet_carrier", "gear_casing", "assembly_group")


def element_name(component: Component, taken: set[str]) -> str:
    """A valid, unique name for ``component``: its REXS name (cut to the name limit), else type and id.

    Parameters
    ----------
    component : Component
        The REXS component the element or shaft comes from.
    taken : set of str
        Names already used; the new one is added.

    Returns
    -------
    str
        Printable, at most :data:`~epicyclic.limits.MAX_NAME_CHARS` characters, not ``housing`` in any
        spelling, unique (the component id appended where needed).
    """
    name = "".join(ch if ch.isprintable() else " " for ch in component.name).strip()
    name = " ".join(name.split())
    if not name:
        name = f"{component.type.replace('_', ' ')} {component.id}"
    if name.casefold() == HOUSING:
        name = f"{name} {component.id}"
    if len(name) > MAX_NAME_CHARS:
        name = name[: MAX_NAME_CHARS - 12].rstrip() + f" … [{component.id}]"
    base, k = name, 2
    while name in taken:
        suffix = f" #{component.id}" if k == 2 else f" #{component.id}.{k}"
        name = base[: MAX_NAME_CHARS - len(suffix)] + suffix
        k += 1
    taken.add(name)
    return name


class Members:
    """The members of a REXS model: rigidly joined bodies, each named.

    Parameters
    ----------
    model : RexsModel

    Attributes
    ----------
    gear_shaft : dict gear id → shaft id
        The shaft each gear is assembled on.
    used : set of int
        Component ids the members are made of (couplings included), for the summary of what was ignored.
    """

    def __init__(self, model: RexsModel):
        self.model = model
        self.parent: dict[object, object] = {}
        self.used: set[int] = set()
        self.gear_shaft: dict[int, int] = {}
        casings = [c.id for c in model.of_type("gear_casing")]
        for cid in casings[1:]:
            self.union(casings[0], cid)
        self.casing = casings[0] if casings else None
        self.used.update(casings)
        stage_carrier: dict[int, int] = {}
        for relation in model.relations_of("assembly"):
            whole = model.components.get(relation.role("assembly"))
            part = model.components.get(relation.role("part"))
            if whole is None or part is None:
                continue
            if whole.type == "planet_carrier":
                self.union(whole.id, part.id)
                self.used.update((whole.id, part.id))
            elif whole.type == "planetary_stage" and part.type == "planet_carrier":
                stage_carrier[whole.id] = part.id
                self.used.add(part.id)
            elif whole.type in ("shaft", "gear_casing") and part.type in GEAR_TYPES:
                self.gear_shaft[part.id] = whole.id  # a ring gear may sit in the casing itself
        for relation in model.relations_of("planet_carrier_shaft"):
            stage, shaft = relation.role("planetary_stage"), relation.role("shaft")
            if stage is None or shaft is None:
                continue
            self.union(("carrier", stage), shaft)
            if stage in stage_carrier:
                self.union(("carrier", stage), stage_carrier[stage])
            self.used.add(shaft)
        for relation in model.relations_of("side"):
            joint = model.components.get(relation.role("assembly"))
            inner, outer = relation.role("inner_part"), relation.role("outer_part")
            if joint is not None and joint.type == "coupling" and inner is not None and outer is not None:
                self.union(inner, outer)
                self.used.update((joint.id, inner, outer))
        self.names: dict[object, str] = {}
        #: Shafts whose name a member takes first (those carrying a load or a given speed).
        self.preferred: list[int] = []

    # ---- union-find
    def find(self, key: object) -> object:
        """The representative of the body ``key`` (a component id)."""
        root = key
        while self.parent.get(root, root) != root:
            root = self.parent[root]
        while self.parent.get(key, key) != root:  # path compression
            self.parent[key], key = root, self.parent[key]
        return root

    def union(self, a: object, b: object) -> None:
        """Join the bodies ``a`` and ``b``."""
        ra, rb = self.find(a), self.find(b)
        if ra != rb:
            self.parent[rb] = ra

    def is_housing(self, cid: int) -> bool:
        """Whether the body ``cid`` is joined to the casing."""
        return self.casing is not None and self.find(cid) == self.find(self.casing)

    def shafts_of(self, cid: int) -> list[int]:
        """The REXS shafts of the member of ``cid``, by id."""
        root = self.find(cid)
        return [c.id for c in self.model.of_type("shaft") if self.find(c.id) == root]

    # ---- names
    def name(self, cid: int) -> str:
        """The member name of the body ``cid``: ``housing``, or the name of one of its shafts
        (one of :attr:`preferred` first).

        Parameters
        ----------
        cid : int
            A body of the member.
        """
        if self.is_housing(cid):
            return HOUSING
        root = self.find(cid)
        if root not in self.names:
            shafts = self.shafts_of(cid) or [cid]
            pick = next((s for s in self.preferred if s in shafts), shafts[0])
            component = self.model.components.get(pick)
            taken = set(self.names.values())
            self.names[root] = element_name(component, taken) if component else f"shaft {pick}"
        return self.names[root]
