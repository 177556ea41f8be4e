"""The ``[rating]`` table of a train file: inputs of the ISO 6336 tooth load capacity rating.

::

    [rating]                              # every key optional; defaults in docs/rating.md
    standard = "2019"                     # ISO 6336 edition: "2006" or "2019"
    application_factor = 1.25             # K_A
    life = 20000                          # required life, h
    S_Hmin = 1.0
    S_Fmin = 1.4
    accuracy_grade = 6                    # ISO 1328-1, or per gear: { sun = 5, ring = 7 }
    accuracy_standard = "1995"            # ISO 1328-1 edition: "1995" or "2013" (default: ISO 6336's)
    flank_roughness = 3.0                 # R_z, µm (required); or per gear: { sun = 3.0, ring = 6.0 }
    root_roughness = 10.0                 # R_z, µm (required); or per gear
    material = "18CrNiMo7-6"              # or { sun = "...", planet = "...", ring = "42CrMo4", "P1:ring" = "..." }
    quality = "MQ"                        # ML, MQ or ME (ISO 6336-5)
    K_Hbeta = 1.3                         # given; otherwise method C with shaft_deflection (µm)
    K_v = { "sun-planet" = 1.05, "planet-ring" = 1.08 }   # per mesh ("P1:sun-planet", mesh, element, all)
    K_Fbeta = 1.25                        # given; otherwise K_Hbeta^N_F
    K_Halpha = 1.1                        # given (K_Falpha too, else = K_Halpha); otherwise method B
    f_pb = { sun = 8.0, ring = 12.0 }     # measured deviations per gear, µm (also f_falpha, f_Hbeta)
    load_sharing = 1.15                   # K_γ of every set (default: the set geometry's, else by planets)
    cutter = { teeth = 24, profile_shift = 0.0, addendum = 1.25, tip_radius = 0.25 }   # internal gears
    rim_thickness = { ring = 12.0 }       # s_R below the root, mm (Y_B); others solid
    tool = { ring = { teeth = 36, tip_radius = 0.3 }, sun = { tip_radius = 0.38 } }   # the tool per gear:
                                          # teeth → pinion-type cutter (z0, profile_shift, addendum, tip_radius),
                                          # else rack-type tool (addendum, tip_radius, protuberance, protuberance_angle)
    long_life = "standard"                # or "optimum"
    ignored = ["..."]                     # inputs given but not used (the REXS reader lists them), reported
    [rating.scuffing]                     # scuffing (flash and integral temperature): io/scuffing_format.py
    load_stage = 12
    [rating.lubricant]
    viscosity_40 = 35.0                   # mm²/s (or in the top-level [lubricant])
    viscosity_100 = 7.0
    [rating.flank_fracture]               # tooth flank fracture: io/flank_fracture_format.py
    case_depth = 1.0
    [rating.micropitting]                 # ISO/TS 6336-22 (see failure_modes_format)
    oil_temperature = 70.0
    load_stage = 9
    [rating.materials.MySteel]            # a user material, then material = "MySteel"
    treatment = "Eh"                      # ISO 6336-5 symbol
    sigma_Hlim = 1550.0
    sigma_Flim = 480.0
    hardness = 300.0                      # with its scale: "HB", "HV" or "HRC" (Z_W takes HB)
    hardness_scale = "HV"

References
----------
ISO 6336-1:2019, ISO 6336-2:2019, ISO 6336-3:2019, ISO 6336-5:2016; ``docs/file-format.md``.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from ..errors import EpicyclicError
from ..geometry.tooth_generation import PinionCutter, RackTool
from ..rating.materials import DEFAULT_QUALITY, Material, material, material_names
from ..rating.spec import RatingSpec
from ..rating.tooth_form import Cutter
from .failure_modes_format import read_micropitting
from .reader import at_key

__all__ = ["RATING_KEYS", "read_rating", "side_rating"]

RATING_KEYS = {"standard", "application_factor", "life", "S_Hmin", "S_Fmin", "accuracy_grade", "flank_roughness",
               "root_roughness", "material", "quality", "K_Hbeta", "K_v", "shaft_deflection", "load_sharing",
               "tool_tip_radius", "cutter", "long_life", "pitting_permitted", "tip_relief", "lubricant", "materials",
               "rim_thickness", "micropitting", "scuffing", "flank_fracture", "tool", "ignored", "notes",
               "accuracy_standard", "K_Fbeta", "K_Halpha", "K_Falpha", "f_pb", "f_falpha", "f_Hbeta"}
_NUMBERS = ("life", "S_Hmin", "S_Fmin", "shaft_deflection", "tool_tip_radius", "tip_relief")
#: Given per mesh (a table by mesh) or per gear (a table by gear), or one number for all.
_TABLES = ("application_factor", "K_Hbeta", "K_v", "load_sharing", "K_Fbeta", "K_Halpha", "K_Falpha", "f_pb",
           "f_falpha", "f_Hbeta", "flank_roughness", "root_roughness")
#: The fixed unit of a [rating] number (the others are pure numbers).
_UNITS = {"life": "h", "shaft_deflection": "µm", "tip_relief": "µm", "flank_roughness": "µm", "root_roughness": "µm",
          "f_pb": "µm", "f_falpha": "µm", "f_Hbeta": "µm"}
_CUTTER_KEYS = {"teeth", "profile_shift", "addendum", "tip_radius"}
_RACK_TOOL_KEYS = {"addendum", "tip_radius", "protuberance", "protuberance_angle"}
_USER_MATERIAL = {"treatment", "sigma_Hlim", "sigma_Flim", "hardness", "hardness_scale", "E", "poisson", "density",
                  "yield_strength"}


def _plain(reader, value, key: str, where: str, table_key: str) -> float:
    """A number of a key whose unit is fixed: its own unit may be written ("3 um"); another is refused naming it."""
    unit = _UNITS.get(table_key)
    if isinstance(value, str) and any(c.isalpha() for c in value):
        bare = value.strip()
        for spelled in ((unit, "um") if unit == "µm" else (unit,)) if unit else ():
            if bare.endswith(spelled):
                return reader.number(bare[: -len(spelled)], key, where)
        label = f"{unit} (R_z)" if table_key.endswith("roughness") else unit or "1 (a factor)"
        example = "12.0" if unit else "1.1"
        raise reader.error(at_key(where, key), f"takes a plain number in {label}, without a unit; got {value!r} "
                                               f"(e.g. {key} = {example}).")
    return reader.number(value, key, where)


def _user_materials(reader, table, where: str, quality: str) -> dict[str, Material]:
    out = {}
    for name, entry in table.items():
        w = f"{where}.{name}"
        entry = reader.table(entry, w)
        reader.check_keys(entry, _USER_MATERIAL, w)
        values = {k: reader.number(entry[k], k, w) for k in entry if k not in ("treatment", "hardness_scale")}
        if "hardness_scale" in entry:
            values["hardness_scale"] = reader.string(entry, "hardness_scale", w)
        for key in ("sigma_Hlim", "sigma_Flim"):
            reader.require(entry, key, w)
        treatment = reader.string(entry, "treatment", w)
        try:
            out[name] = Material(name, treatment, quality=quality, **values)
        except EpicyclicError as exc:
            raise reader.wrap(w, exc) from None
    return out


def _material(reader, value, users, quality, where: str) -> Material:
    if not isinstance(value, str):
        raise reader.error(where, f"expected a material name, got {value!r}; names are "
                                  f"{', '.join(material_names() + tuple(users))}.")
    if value in users:
        return users[value]
    try:
        return material(value, quality=quality)
    except EpicyclicError as exc:
        raise reader.wrap(where, exc) from None


def _tool(reader, value, where: str) -> RackTool | PinionCutter:
    """One gear's tool: a pinion-type cutter where ``teeth`` is given, else a rack-type tool (hob)."""
    entry = reader.table(value, where)
    cutter = "teeth" in entry
    if not cutter and "profile_shift" in entry:
        raise reader.error(where, "profile_shift is the x0 of a pinion-type cutter: give its teeth = z0 too "
                                  "(a rack-type tool has no profile shift).")
    reader.check_keys(entry, _CUTTER_KEYS if cutter else _RACK_TOOL_KEYS, where)
    numbers = {k: reader.number(entry[k], k, where) for k in entry if k != "teeth"}
    try:
        if cutter:
            return PinionCutter(reader.integer(entry["teeth"], "teeth", where), **numbers)
        return RackTool(**numbers)
    except EpicyclicError as exc:
        raise reader.wrap(where, exc) from None


def read_rating(reader, table: Mapping[str, Any], lubricant: Mapping[str, Any] | None) -> RatingSpec:
    """The :class:`~epicyclic.rating.spec.RatingSpec` of a ``[rating]`` table.

    Parameters
    ----------
    reader : TableReader
        The file's reader (messages name the file and the key).
    table : mapping
        The parsed ``[rating]`` table.
    lubricant : mapping or None
        The top-level ``[lubricant]`` table (its ``viscosity_40`` and ``viscosity_100``, mm²/s).

    Returns
    -------
    RatingSpec

    Raises
    ------
    InputFileError
        An unknown key, a value of the wrong kind, an unknown material.

    References
    ----------
    ISO 6336-1:2019; ISO 6336-5:2016 (materials); ``docs/file-format.md``.
    """
    where = "[rating]"
    table = reader.table(table, where)
    reader.check_keys(table, RATING_KEYS, where)
    values: dict[str, Any] = {k: reader.number(table[k], k, where, _UNITS.get(k, "1")) for k in _NUMBERS if k in table}
    for key in _TABLES:  # one value, or one per mesh / per gear: { sun = 4.8, ring = 8.0 }
        if isinstance(table.get(key), Mapping):
            k_where = at_key(where, key)
            values[key] = {k: _plain(reader, v, k, k_where, key) for k, v in reader.table(table[key], k_where).items()}
        elif key in table:
            values[key] = _plain(reader, table[key], key, where, key)
    if "standard" in table:
        values["standard"] = str(table["standard"])
    if isinstance(table.get("accuracy_grade"), Mapping):
        g_where = at_key(where, "accuracy_grade")
        values["accuracy_grade"] = {k: reader.integer(v, k, g_where)
                                    for k, v in reader.table(table["accuracy_grade"], g_where).items()}
    elif "accuracy_grade" in table:
        values["accuracy_grade"] = reader.integer(table["accuracy_grade"], "accuracy_grade", where)
    if "accuracy_standard" in table:
        values["accuracy_standard"] = reader.string(table, "accuracy_standard", where)
    if "long_life" in table:
        values["long_life"] = reader.string(table, "long_life", where)
    if "pitting_permitted" in table:
        values["pitting_permitted"] = reader.boolean(table, "pitting_permitted", where, False)
    quality = reader.string(table, "quality", where, default=DEFAULT_QUALITY)
    users = _user_materials(reader, reader.table(table.get("materials", {}), "[rating.materials]"),
                            "[rating.materials]", quality)
    if "material" in table:
        given = table["material"]
        if isinstance(given, dict):
            values["material"] = {k: _material(reader, v, users, quality, at_key(where, f"material.{k}"))
                                  for k, v in given.items()}
        else:
            values["material"] = _material(reader, given, users, quality, at_key(where, "material"))
    if "cutter" in table:
        c_where = at_key(where, "cutter")
        ct = reader.table(table["cutter"], c_where)
        reader.check_keys(ct, {"teeth", "profile_shift", "addendum", "tip_radius"}, c_where)
        kwargs = {k: reader.number(ct[k], k, c_where) for k in ("profile_shift", "addendum", "tip_radius") if k in ct}
        try:
            values["cutter"] = Cutter(reader.integer(reader.require(ct, "teeth", c_where), "teeth", c_where), **kwargs)
        except EpicyclicError as exc:
            raise reader.wrap(c_where, exc) from None
    if "rim_thickness" in table:
        r_where = at_key(where, "rim_thickness")
        rims = reader.table(table["rim_thickness"], r_where)
        values["rim_thickness"] = {k: reader.number(v, k, r_where, "mm") for k, v in rims.items()}
    if "micropitting" in table:  # the failure modes beyond pitting and root: their own sub-tables
        values["micropitting"] = read_micropitting(reader, table["micropitting"])
    if "scuffing" in table:
        from .scuffing_format import read_scuffing

        values["scuffing"] = read_scuffing(reader, table["scuffing"])
    if "flank_fracture" in table:
        from .flank_fracture_format import read_flank_fracture

        values["flank_fracture"] = read_flank_fracture(reader, table["flank_fracture"])
    if "tool" in table:
        t_where = at_key(where, "tool")
        tools = reader.table(table["tool"], t_where)
        values["tools"] = {k: _tool(reader, v, at_key(where, f"tool.{k}")) for k, v in tools.items()}
    for key in ("ignored", "notes"):  # what a REXS file gave that the rating does not use; the reader's notes
        if key in table:
            items = table[key]
            if not isinstance(items, list) or not all(isinstance(i, str) for i in items):
                raise reader.error(at_key(where, key), f"expected a list of strings, got {items!r:.60}.")
            values[key] = tuple(items)
    oil = dict(lubricant or {})
    if "lubricant" in table:
        own = reader.table(table["lubricant"], "[rating.lubricant]")
        reader.check_keys(own, {"viscosity_40", "viscosity_100"}, "[rating.lubricant]")
        oil.update(own)
    for key in ("viscosity_40", "viscosity_100"):
        if key in oil:
            values[key] = reader.number(oil[key], key, "[lubricant]")
    try:
        return RatingSpec(**values)
    except EpicyclicError as exc:
        raise reader.wrap(where, exc) from None


def side_rating(train_file, path):
    """``train_file`` with the ``[rating]`` of the side file ``path`` over its own rating inputs.

    The side file's ``[rating]`` (and ``[lubricant]``) keys replace those a REXS model's standard
    attributes give (:attr:`~epicyclic.exchange.mapping.RexsDocument.rating_inputs`); its ``ignored``
    list joins the model's.  For a TOML train file the side file's ``[rating]`` replaces the file's.

    Parameters
    ----------
    train_file : TrainFile
    path : str or Path
        A TOML file with a ``[rating]`` table.

    Returns
    -------
    TrainFile

    Raises
    ------
    InputFileError
        The side file cannot be read, is not TOML, has no ``[rating]`` table or a bad key (the message
        names the side file and the key).

    References
    ----------
    ``docs/rating.md`` (the side file); ISO 6336-1:2019.
    """
    from dataclasses import replace

    from .reader import TableReader
    from .source import parse_toml, read_source

    source = str(path)
    reader = TableReader(source)
    side = parse_toml(read_source(path), source)
    reader.check_keys(side, {"rating", "lubricant"}, "the side file")
    if "rating" not in side:
        raise reader.error("[rating]", "the side file has no [rating] table; give material, flank_roughness, "
                                       "root_roughness (and [lubricant] viscosity_40) there (see docs/rating.md).")
    document = getattr(train_file.exchange, "data", None) or {}
    base = dict(getattr(train_file.exchange, "rating_inputs", None) or document.get("rating") or {})
    table = {**base, **reader.table(side["rating"], "[rating]")}
    for key in ("ignored", "notes"):
        if key in base and key in side["rating"]:
            table[key] = list(base[key]) + [i for i in side["rating"][key] if i not in base[key]]
    lubricant = {**(document.get("lubricant") or {}), **reader.table(side.get("lubricant", {}), "[lubricant]")}
    return replace(train_file, rating=read_rating(reader, table, {k: v for k, v in lubricant.items()
                                                                  if k in ("viscosity_40", "viscosity_100")}))
