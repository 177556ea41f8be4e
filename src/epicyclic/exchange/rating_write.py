"""Write a train file's ``[rating]`` inputs as REXS standard attributes (the reader's map backwards).

Per gear of a planetary set: R_z of flank and root (``averaged_peak_to_valley_height_flank``/
``_root``, µm), the ISO 1328 tolerance class, and a ``reference`` to a ``material`` component
(``material_designation``, ``heat_treated_material_type_iso_6336_2019``, the surface hardness in
the scale of its ISO 6336-5 line, σ_Hlim and σ_Flim as ``allowable_stress_number_contact_iso_6336_2016``
and ``_tooth_root_``, ``elastic_modulus``, ``poisson_ratio``, ``density``); per mesh
(``cylindrical_stage``) K_A and the given K_v, K_Hβ, K_Fβ, K_Hα, K_Fα, K_γ in the attributes of the
rating's edition; the basic rack's tip radius ρ_fP* (``tip_radius_factor`` of a ``rack_shaped_tool``)
and the ring's pinion-type cutter (``cutter_wheel_tool``: ``number_of_teeth``,
``addendum_modification_coefficient``, ``addendum_coefficient_reference_profile``, ``tip_radius_factor``).
The attribute names are those :mod:`~epicyclic.exchange.rating_map` reads.

References
----------
REXS 1.7 attribute database (``rexs_schema_1.7.xml``, FVA GmbH, github.com/fva-net/rexs-api-java,
Apache-2.0); ISO 6336-1:2019; ISO 6336-5:2016; ISO 1328-1:2013.
"""

from __future__ import annotations

from typing import Any

from ..errors import EpicyclicError
from .rating_map import MESH_FACTORS, TREATMENT_ENUM

__all__ = ["RatingWriter"]

_ENUM = {symbol: value for value, symbol in TREATMENT_ENUM.items()}
_HARDNESS = {"HV": ("surface_hardness_vickers", "HV"), "HB": ("surface_hardness_brinell", "HB"),
             "HRC": ("surface_hardness_rockwell", "HRC")}


class RatingWriter:
    """The rating attributes of one train file's gears and meshes, written into a :class:`RexsBuilder`.

    Parameters
    ----------
    builder : RexsBuilder
    spec : RatingSpec or None
        The file's ``[rating]`` (nothing is written without one).
    """

    def __init__(self, builder, spec):
        self.b, self.spec = builder, spec
        self.materials: dict[Any, int] = {}
        self.flanks: dict[int, tuple[int, int]] = {}  # gear → its left and right flank
        self.tools: dict[int, list[tuple[int, str]]] = {}  # gear → (tool, type) in manufacturing order

    def tool(self, gid: int, tool: int, name: str, order: int) -> None:
        """Relate ``tool`` to both flanks of gear ``gid`` as manufacturing step ``order``."""
        settings = self.b.component("cylindrical_gear_manufacturing_settings", name)
        for flank_id in self.flanks[gid]:
            self.b.relation("manufacturing_step", [(flank_id, "workpiece"), (tool, "tool"),
                                                   (settings, "manufacturing_settings")], order=order)
        self.tools.setdefault(gid, []).append((tool, "rack" if order == 1 and not self.tools.get(gid) else "step"))

    def _tools(self, gid: int, internal: bool) -> None:
        """The rack's tip radius ρ_fP* on an external gear's rack tool; an internal gear's pinion-type cutter."""
        spec = self.spec
        if gid not in self.flanks:
            return
        made = self.tools.get(gid, [])
        if not internal:
            attrs = [("tip_radius_factor", "floating_point", float(spec.tool_tip_radius), "none")]
            if made:
                self.b.add(made[0][0], attrs)
            else:
                self.tool(gid, self.b.component("rack_shaped_tool", "rack-type tool", attrs), "rack manufacturing", 1)
            return
        cutter = spec.cutter
        if cutter is None:
            return
        attrs = [("number_of_teeth", "integer", int(cutter.teeth), "none"),
                 ("addendum_modification_coefficient", "floating_point", float(cutter.profile_shift), "none"),
                 ("tip_radius_factor", "floating_point", float(cutter.tip_radius), "none")]
        if made:  # the gear's dedendum is its rack tool's: the cutter's addendum may stand beside it
            attrs.append(("addendum_coefficient_reference_profile", "floating_point", float(cutter.addendum), "none"))
        tid = self.b.component("cutter_wheel_tool", "pinion-type cutter", attrs)
        self.tool(gid, tid, "cutter manufacturing", len(made) + 1)

    def _try(self, pick):
        try:
            return pick()
        except EpicyclicError:  # not given for this gear: nothing written
            return None

    def gear(self, gid: int, element: str, role: str) -> None:
        """Roughness, tolerance class and material of gear ``gid`` (``role`` of ``element``)."""
        spec = self.spec
        if spec is None:
            return
        attrs = []
        for key, attribute in (("flank_roughness", "averaged_peak_to_valley_height_flank"),
                               ("root_roughness", "averaged_peak_to_valley_height_root")):
            value = self._try(lambda key=key: spec.roughness_of(key, element, role))
            if value is not None:
                attrs.append((attribute, "floating_point", float(value), "mum"))
        grade = self._try(lambda: spec.grade_of(element, role))
        if grade is not None:
            attrs.append(("tolerance_class_according_to_iso_1328_2013", "enum", str(int(grade)), "none"))
        self.b.add(gid, attrs)
        material = self._try(lambda: spec.material_of(element, role))
        if material is not None:
            self.b.relation("reference", [(gid, "origin"), (self.material(material), "referenced")])
        self._tools(gid, role == "ring")

    def material(self, m) -> int:
        """The ``material`` component of ``m`` (one per distinct material)."""
        if m in self.materials:
            return self.materials[m]
        from ..rating.materials import _data

        attrs: list[tuple[str, str, Any, str]] = [("material_designation", "string", m.name, "none")]
        if m.treatment in _ENUM:
            attrs.append(("heat_treated_material_type_iso_6336_2019", "enum", _ENUM[m.treatment], "none"))
        unit = getattr(m, "hardness_scale", None) or _data()["treatment"].get(m.treatment, {}).get("hardness_unit")
        if unit in _HARDNESS and m.hardness > 0:
            attribute, symbol = _HARDNESS[unit]
            attrs.append((attribute, "floating_point", float(m.hardness), symbol))
        attrs += [("allowable_stress_number_contact_iso_6336_2016", "floating_point", m.sigma_Hlim, "N / mm^2"),
                  ("allowable_stress_number_tooth_root_iso_6336_2016", "floating_point", m.sigma_Flim, "N / mm^2"),
                  ("elastic_modulus", "floating_point", m.E, "N / mm^2"),
                  ("poisson_ratio", "floating_point", float(m.poisson), "none"),
                  ("density", "floating_point", m.density * 1e6, "kg / dm^3")]
        self.materials[m] = cid = self.b.component("material", m.name, attrs)
        return cid

    def mesh(self, sid: int, element: str, name: str) -> None:
        """K_A and the given factors of the mesh ``sid`` (``name`` of ``element``; the edition's attributes)."""
        spec = self.spec
        if spec is None:
            return
        index = 0 if spec.standard == "2019" else 1
        attrs = []
        for key, attributes in MESH_FACTORS.items():
            value = self._try(lambda key=key: spec.given_factor(key, element, name))
            if value is not None:
                attrs.append((attributes[index], "floating_point", float(value), "none"))
        self.b.add(sid, attrs)
