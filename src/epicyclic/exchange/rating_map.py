"""The ``[rating]`` table of a REXS model: every ISO 6336 input its standard attributes give.

Read from the REXS 1.4–1.7 attribute database (FVA GmbH):

==============================  =====================================================================
rating key                      REXS attribute (component)
==============================  =====================================================================
``material``                    ``material_designation`` (``material``, via a ``reference``); with the
                                file's ``heat_treated_material_type_iso_6336_2019``/``_2006``,
                                ``surface_hardness_vickers``/``_brinell``/``_rockwell`` (HV/HB/HRC, with
                                its scale: the line's where given),
                                ``allowable_stress_number_contact_iso_6336_2016`` (σ_Hlim) and
                                ``allowable_stress_number_tooth_root_iso_6336_2016`` (σ_Flim) — REXS
                                1.4 writes ``endurance_limit_flank``/``_root`` on material or gear —,
                                ``elastic_modulus``, ``poisson_ratio`` a ``[rating.materials]`` entry
``flank_roughness``/``root_..``  ``averaged_peak_to_valley_height_flank``/``_root`` (gear), R_z
``application_factor``          ``application_factor_iso_6336_2019``/``_2006`` (``cylindrical_stage``)
``K_v``, ``K_Hbeta``            ``dynamic_factor_iso_6336_2019``/``_2006``,
                                ``face_load_factor_contact_stress_iso_6336_2019``/``_2006``
``K_Fbeta``, ``K_Halpha``,      ``face_load_factor_root_stress_…``,
``K_Falpha``                    ``transverse_load_factor_contact_stress_…``/``_root_stress_…``
``load_sharing``                ``mesh_load_factor_iso_6336_2019``/``_2006`` (K_γ)
``accuracy_grade``              ``tolerance_class_according_to_iso_1328_2013`` (per gear)
``cutter``                      ``cutter_wheel_tool`` of an internal gear: ``number_of_teeth``,
                                ``addendum_modification_coefficient``,
                                ``addendum_coefficient_reference_profile``, ``tip_radius_factor``
``life``                        ``operating_time`` (``gear_unit``), h
==============================  =====================================================================

A factor is one value where every mesh gives the same, else one per rating mesh (``"P:sun-planet"``);
the planets' meshes of one rating mesh that differ are taken at their largest and said so in a note.
What the rating cannot use but that changes a safety — crowning (``profile_crowning``,
``helix_crowning``, ``helix_slope``), a separate K_A of the root — is listed in the table's ``ignored`` (the report
prints it).  The table is complete (and so becomes the model's ``[rating]``) when every gear has a
material and both roughnesses and the lubricant a ``viscosity_40``; otherwise it is kept as the
partial inputs that a side file (``epicyclic rate MODEL.rexs --rating RATING.toml``) completes.

References
----------
ISO 6336-1:2019 (K_A, K_v, K_Hβ, K_γ); ISO 6336-2:2019, eq. (25) (R_z); ISO 6336-5:2016 (materials);
ISO 1328-1:2013 (tolerance class); REXS 1.7 attribute database (``rexs_schema_1.7.xml``, FVA GmbH,
github.com/fva-net/rexs-api-java, Apache-2.0).
"""

from __future__ import annotations

from typing import Any

from ..errors import EpicyclicError
from .rexs_model import Component, RexsModel

__all__ = ["MESH_FACTORS", "SIGMA_ATTRIBUTES", "TREATMENT_ENUM", "rating_table"]

#: ISO 6336 heat-treatment enum of REXS → the ISO 6336-5 symbol of the material data.
TREATMENT_ENUM = {
    "case_hardened_wrought_steel": "Eh", "through_hardened_wrought_steel": "V",
    "through_hardened_cast_steel": "V(cast)", "normalized_wrought_low_carbon_steel": "St",
    "normalized_cast_steel": "St(cast)", "nitrided_steel": "NT", "nitrided_through_hardened_steel": "NV",
    "nitrocaburized_wrought_steel": "NV(nitrocar)", "flame_or_induction_hardened_steel": "IF",
    "grey_cast_iron": "GG", "nodular_cast_iron_ferritic_structure": "GGG(ferr)",
    "nodular_cast_iron_perlitic_or_bainitic_structure": "GGG(perl)", "black_malleable_cast_iron": "GTS",
}
#: rating key → the REXS attributes of σ_Hlim and σ_Flim, the first present wins (1.7 first).
SIGMA_ATTRIBUTES = {
    "sigma_Hlim": ("allowable_stress_number_contact_iso_6336_2016", "allowable_stress_number_contact_iso_6336_2003",
                   "endurance_limit_flank"),
    "sigma_Flim": ("allowable_stress_number_tooth_root_iso_6336_2016",
                   "allowable_stress_number_tooth_root_iso_6336_2003", "endurance_limit_root"),
}
_HARDNESS = {"HV": "surface_hardness_vickers", "HB": "surface_hardness_brinell", "HRC": "surface_hardness_rockwell"}
#: rating key → the ``cylindrical_stage`` attributes of a given factor (2019 edition first).
MESH_FACTORS = {
    "application_factor": ("application_factor_iso_6336_2019", "application_factor_iso_6336_2006"),
    "K_v": ("dynamic_factor_iso_6336_2019", "dynamic_factor_iso_6336_2006"),
    "K_Hbeta": ("face_load_factor_contact_stress_iso_6336_2019", "face_load_factor_contact_stress_iso_6336_2006"),
    "load_sharing": ("mesh_load_factor_iso_6336_2019", "mesh_load_factor_iso_6336_2006"),
    "K_Fbeta": ("face_load_factor_root_stress_iso_6336_2019", "face_load_factor_root_stress_iso_6336_2006"),
    "K_Halpha": ("transverse_load_factor_contact_stress_iso_6336_2019",
                 "transverse_load_factor_contact_stress_iso_6336_2006"),
    "K_Falpha": ("transverse_load_factor_root_stress_iso_6336_2019", "transverse_load_factor_root_stress_iso_6336_2006"),
}
#: Given factors the rating has no input for (listed as ignored where a file gives them).
_NOT_GIVEN = ("application_factor_tooth_root_iso_6336_2019", "application_factor_tooth_root_iso_6336_2006")
_MODIFICATIONS = {"profile_crowning": "profile crowning", "helix_crowning": "helix crowning",
                  "helix_slope": "helix slope (helix angle modification)"}


class _Reader:
    def __init__(self, model: RexsModel):
        self.model = model
        self.ignored: list[str] = []
        self.notes: list[str] = []

    def ignore(self, item: str) -> None:
        if item not in self.ignored:
            self.ignored.append(item)

    def label(self, c: Component) -> str:
        return f"{c.type} {c.id}" + (f" {c.name!r}" if c.name else "")

    def first(self, c: Component | None, attributes, quantity: str = "number") -> tuple[str, float] | None:
        for attribute in attributes:
            if c is not None and self.model.has(c, attribute):
                return attribute, self.model.number(c, attribute, quantity)
        return None

    def factor(self, key: str, meshes: list[tuple[str, Component, str | None]]) -> float | dict | None:
        """One value where every mesh gives the same, else one per rating mesh (``"P:sun-planet"``); the
        planets' meshes of one rating mesh (or of an element whose meshes are not named) at their largest."""
        found: dict[str, set[float]] = {}
        for element, stage, mesh in meshes:
            hit = self.first(stage, MESH_FACTORS[key])
            if hit is not None:
                found.setdefault(f"{element}:{mesh}" if mesh else element, set()).add(hit[1])
        if not found:
            return None
        for where, values in found.items():
            if len(values) > 1:
                self.notes.append(f"{key}: the planets' meshes of {where} give "
                                  f"{', '.join(f'{v:g}' for v in sorted(values))}; the largest, {max(values):g}, is used")
        table = {where: max(values) for where, values in found.items()}
        distinct = set(table.values())
        return distinct.pop() if len(distinct) == 1 else table

    def material(self, element: str, role: str, data) -> dict[str, Any] | None:
        """The gear's material: its designation and the values the file gives (None without one)."""
        model = self.model
        found = model.components.get(data.material_id) if data.material_id is not None else None
        out: dict[str, Any] = {"name": data.material}
        for key, attributes in SIGMA_ATTRIBUTES.items():
            hit = self.first(data.component, attributes, "stress") or self.first(found, attributes, "stress")
            if hit is not None:
                out[key] = hit[1]
        if found is None:
            return out if data.material else None
        for attribute in ("heat_treated_material_type_iso_6336_2019", "heat_treated_material_type_iso_6336_2006"):
            if model.has(found, attribute):
                value = found.attributes[attribute].value
                if isinstance(value, str) and value in TREATMENT_ENUM:
                    out["treatment"] = TREATMENT_ENUM[value]
                    break
        for scale, attribute in _HARDNESS.items():
            if model.has(found, attribute):
                out.setdefault("hardnesses", {})[scale] = model.number(found, attribute, "hardness")
        if model.has(found, "elastic_modulus"):
            out["E"] = model.number(found, "elastic_modulus", "stress")
        if model.has(found, "poisson_ratio"):
            out["poisson"] = model.number(found, "poisson_ratio")
        return out

    def modifications(self, element: str, role: str, data) -> None:
        model = self.model
        owners = {data.component.id, *data.flanks}
        for relation in model.relations_of("reference"):
            target = model.components.get(relation.role("referenced"))
            if relation.role("origin") in owners and target is not None and target.type in _MODIFICATIONS:
                amounts = ", ".join(f"{a} = {model.number(target, a, 'length') * 1000:g} µm"
                                    for a in sorted(target.attributes)
                                    if "amount" in a or a.startswith("profile_crowning_at"))
                self.ignore(f"{element}:{role}: {_MODIFICATIONS[target.type]} ({self.label(target)}"
                                    + (f": {amounts}" if amounts else "") + ") - not used: K_Hbeta by method C "
                                    "and the contact without flank modifications")


def _user_material(entry: dict[str, Any], reader: _Reader, where: str) -> tuple[str, dict | None]:
    """(name, [rating.materials] entry or None where the data file's material is the file's)."""
    from ..rating.materials import _data

    name = entry.get("name") or where
    known = _data()["material"].get(name)
    treatment = entry.get("treatment") or (known or {}).get("treatment")
    if treatment is None:
        raise EpicyclicError(f"material {name!r} of {where}: no ISO 6336 heat treatment "
                             "(heat_treated_material_type_iso_6336_2019) and not a material of the data file")
    unit = _data()["treatment"].get(treatment, {}).get("hardness_unit")
    values: dict[str, Any] = {}
    hardnesses = entry.get("hardnesses", {})
    # with sigma_Hlim and sigma_Flim given only Z_W needs the hardness, in HB; otherwise the ISO 6336-5 line, in
    # its unit: that scale first where the file gives it (the rating converts the others by ASTM E140)
    first = "HB" if "sigma_Hlim" in entry and "sigma_Flim" in entry else unit
    scale = first if first in hardnesses else next((k for k in (unit, "HV", "HB", "HRC") if k in hardnesses), None)
    if scale is not None:
        values["hardness"], values["hardness_scale"] = hardnesses[scale], scale
        others = {k: v for k, v in hardnesses.items() if k != scale}
        if others:
            reader.notes.append(f"{where}: surface hardness {hardnesses[scale]:g} {scale} used; the file also gives "
                                + ", ".join(f"{v:g} {k}" for k, v in others.items()))
    for key in ("sigma_Hlim", "sigma_Flim", "E", "poisson"):
        if key in entry:
            values[key] = entry[key]
    if known is not None:
        from ..rating.materials import material

        table = material(name).to_dict()
        if known["treatment"] == treatment and all(
                table.get(k) == v if isinstance(v, str) else abs(float(table[k]) - float(v)) <= 1e-9 * max(
                    1.0, abs(float(v))) for k, v in values.items()):
            return name, None
        fill = {"hardness": known["hardness"], "hardness_scale": unit, "E": known["E"], "poisson": known["poisson"],
                "density": known["density"], "yield_strength": known["yield_strength"]}
        values = {**fill, **values}
        if "sigma_Hlim" not in values or "sigma_Flim" not in values:
            from ..rating.hardness import convert_hardness

            line = material(name, hardness=convert_hardness(values["hardness"], values["hardness_scale"], unit)
                            if values["hardness_scale"] != unit else values["hardness"])
            values.setdefault("sigma_Hlim", line.sigma_Hlim)
            values.setdefault("sigma_Flim", line.sigma_Flim)
    if "sigma_Hlim" not in values or "sigma_Flim" not in values:
        raise EpicyclicError(f"material {name!r} of {where}: the file gives no allowable stress numbers "
                             "(allowable_stress_number_contact_iso_6336_2016 and _tooth_root_) and the data file "
                             "has no such material")
    return name, {"treatment": treatment, **values}


def rating_table(model: RexsModel, gears: list[tuple[str, str, Any]], meshes: list[tuple[str, Component]],
                 lubricant: dict | None) -> tuple[dict[str, Any], bool]:
    """The ``[rating]`` inputs of the gears ``(element, gear name, GearData)`` and meshes ``(element,
    cylindrical_stage)``, and whether they are complete.

    Parameters
    ----------
    model : RexsModel
    gears : list of (str, str, GearData)
        Every gear of the model's planetary sets.
    meshes : list of (str, Component)
        Their ``cylindrical_stage`` meshes.
    lubricant : dict or None
        The document's ``[lubricant]`` (its ``viscosity_40`` is needed).

    Returns
    -------
    (dict, bool)
        The table (with ``ignored`` and ``notes`` lists where there are any) and whether it holds
        every required input.
    """
    reader = _Reader(model)
    table: dict[str, Any] = {}
    materials: dict[str, str] = {}
    users: dict[str, dict] = {}
    complete = bool(gears)
    for element, role, data in gears:
        where = f"{element}:{role}"
        entry = reader.material(element, role, data)
        reader.modifications(element, role, data)
        if entry is None:
            complete = False
            continue
        try:
            name, user = _user_material(entry, reader, where)
        except EpicyclicError as exc:
            reader.notes.append(str(exc))
            complete = False
            continue
        if user is not None:
            same = [n for n, u in users.items() if u == user]
            if same:
                name = same[0]
            elif name in users:
                name = f"{name} ({where})"
            users[name] = user
        materials[where] = name
    if materials:
        distinct = set(materials.values())
        table["material"] = distinct.pop() if len(distinct) == 1 and complete else materials
    if users:
        table["materials"] = users
    for key in ("flank_roughness", "root_roughness"):
        values = {f"{e}:{r}": getattr(d, key) for e, r, d in gears if getattr(d, key) is not None}
        if len(values) < len(gears) or not gears:
            complete = False
        if values:
            table[key] = next(iter(values.values())) if len(set(values.values())) == 1 and len(values) == len(
                gears) else values
    for key in MESH_FACTORS:
        value = reader.factor(key, meshes)
        if value is not None:
            table[key] = value
    for element, stage, _ in meshes:
        for attribute in _NOT_GIVEN:
            if model.has(stage, attribute):
                reader.ignored.append(f"{element} {reader.label(stage)}: {attribute} = "
                                      f"{model.number(stage, attribute):g} - not used: the rating computes it")
    grades = {f"{e}:{r}": int(str(d.component.attributes["tolerance_class_according_to_iso_1328_2013"].value))
              for e, r, d in gears if model.has(d.component, "tolerance_class_according_to_iso_1328_2013")}
    if grades:  # one ISO 1328 class, or one per gear
        table["accuracy_grade"] = next(iter(grades.values())) if len(set(grades.values())) == 1 else grades
    cutters = set()
    for _, _, data in gears:
        for tid in data.tools if data.internal else ():
            tool = model.components.get(tid)
            if tool is not None and tool.type == "cutter_wheel_tool" and model.has(tool, "number_of_teeth"):
                cutter = {"teeth": model.integer(tool, "number_of_teeth")}
                for key, attribute in (("profile_shift", "addendum_modification_coefficient"),
                                       ("addendum", "addendum_coefficient_reference_profile"),
                                       ("tip_radius", "tip_radius_factor")):
                    if model.has(tool, attribute):
                        cutter[key] = model.number(tool, attribute)
                if cutter.get("tip_radius", 0.25) <= 0.0:  # a sharp corner: the rack approximation's rho_F = 0
                    reader.ignore(f"{reader.label(tool)}: z0 = {cutter['teeth']}, tip_radius_factor = 0 - not used: "
                                  "a sharp cutter tip (rho_a0* = 0) leaves the rack-shaped root without a fillet "
                                  "radius; the root is rated with the basic rack's tool_tip_radius (give [rating] "
                                  "cutter to rate with a cutter)")
                    continue
                cutters.add(tuple(sorted(cutter.items())))
    if len(cutters) == 1:
        table["cutter"] = dict(next(iter(cutters)))
    elif cutters:
        reader.ignored.append(f"cutter_wheel_tool: {len(cutters)} different cutters - not used: the rating takes "
                              "one cutter for every internal gear (give [rating] cutter)")
    radii = {model.number(tool, "tip_radius_factor") for _, _, d in gears if not d.internal for tool in
             (model.components.get(t) for t in d.tools) if tool is not None and tool.type == "rack_shaped_tool"
             and model.has(tool, "tip_radius_factor")}
    if radii:  # one rho_fP* per file: the smallest (the sharpest fillet, the largest Y_S)
        table["tool_tip_radius"] = min(radii)
        if len(radii) > 1:
            reader.notes.append(f"tool_tip_radius: the racks give {sorted(radii)}; the smallest is used")
    unit = next(iter(model.of_type("gear_unit")), None)
    if unit is not None and model.has(unit, "operating_time"):
        table["life"] = model.number(unit, "operating_time", "time")
    if not (lubricant or {}).get("viscosity_40"):
        complete = False
    if reader.ignored:
        table["ignored"] = reader.ignored
    if reader.notes:
        table["notes"] = reader.notes
    return table, complete


def merge_rating(custom: Any, standard: dict[str, Any], notes: list[str]) -> Any:
    """epicyclic's custom copy of ``[rating]`` with the standard attributes' values over it.

    Parameters
    ----------
    custom : object
        The ``rating`` of ``custom_epicyclic_document`` (the table the file was written from).
    standard : dict
        :func:`rating_table` of the model's standard attributes.
    notes : list of str
        Gets a note for each key where the two differ (the standard attribute is used).

    Returns
    -------
    object
        The merged table (``custom`` unchanged where it is not a table).
    """
    if not isinstance(custom, dict):
        return custom
    merged = dict(custom)
    for key, value in standard.items():
        if key in ("ignored", "notes"):
            merged[key] = list(custom.get(key, [])) + [v for v in value if v not in custom.get(key, [])]
            continue
        if isinstance(value, dict) and isinstance(custom.get(key), dict) and key in ("cutter", "materials"):
            value = {**custom[key], **value}  # what the standard does not give (a cutter's addendum) stays
        if key in custom and custom[key] != value and _differs(key, custom[key], value, standard):
            notes.append(f"[rating] {key}: the REXS attributes give {value!r}, epicyclic's custom copy "
                         f"{custom[key]!r}; the standard attributes are used")
        merged[key] = value
    return merged


def _differs(key: str, custom: Any, value: Any, standard: dict[str, Any]) -> bool:
    """Whether the two are different inputs (a material given by name once and per gear is the same)."""
    if key == "material" and isinstance(custom, str) and isinstance(value, dict):
        return set(value.values()) != {custom}
    if key in ("flank_roughness", "root_roughness") and not isinstance(custom, dict) and isinstance(value, dict):
        return set(value.values()) != {custom}
    return True
