"""Sub-tables of ``[rating]`` for the failure modes beyond pitting and root.

::

    [rating.micropitting]                 # ISO/TS 6336-22:2018 Method B; see docs/rating.md
    oil_temperature = 70.0                # θ_oil, degC (required)
    load_stage = 9                        # FZG GF-C/8.3/90 failure load stage SKS, or:
    # lambda_GFP = 0.21                   # the permissible specific film thickness, given
    edition = "ISO/TS 6336-22:2018"       # or "ISO/TR 15144-1:2014"
    lubricant_type = "mineral"            # pao, pag, pag_water_soluble
    roughness = 0.5                       # R_a, µm, or per gear { sun = 0.4, ring = 0.8 } (default R_z/6)
    lubrication = "dip"                   # spray, submerged (X_S)
    profile_modification = "none"         # pinion, wheel, both (tip relief designed for the load)
    bulk_temperature = 85.0               # θ_M given (default ISO/TR 15144-1 eq. (84))
    density = 895.0                       # ρ_15 of the oil, kg/m³ (default from ν_40)
    material_factor = 1.0                 # W_W (1 for case-carburised gears)
    S_lambda_min = 1.0
    points = 25

References
----------
ISO/TS 6336-22:2018; ``docs/file-format.md``.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from ..errors import EpicyclicError
from ..rating.micropitting import MicropittingSpec
from .reader import at_key

__all__ = ["MICROPITTING_KEYS", "read_micropitting"]

MICROPITTING_KEYS = {"oil_temperature", "load_stage", "lambda_GFP", "edition", "lubricant_type", "roughness",
                     "lubrication", "profile_modification", "bulk_temperature", "density", "material_factor",
                     "S_lambda_min", "points"}
_NUMBERS = ("oil_temperature", "lambda_GFP", "bulk_temperature", "density", "material_factor", "S_lambda_min")
_STRINGS = ("edition", "lubricant_type", "lubrication", "profile_modification")


def read_micropitting(reader, value: object, where: str = "[rating.micropitting]") -> MicropittingSpec:
    """The :class:`~epicyclic.rating.micropitting.MicropittingSpec` of a ``[rating.micropitting]`` table.

    Parameters
    ----------
    reader : TableReader
        The file's reader (messages name the file and the key).
    value : mapping
        The parsed table.
    where : str
        Its place in the file, for messages.

    Returns
    -------
    MicropittingSpec

    Raises
    ------
    InputFileError
        An unknown key, a value of the wrong kind, a missing oil temperature or permissible film.

    References
    ----------
    ISO/TS 6336-22:2018; ``docs/file-format.md``.
    """
    table = reader.table(value, where)
    reader.check_keys(table, MICROPITTING_KEYS, where)
    values: dict[str, Any] = {k: reader.number(table[k], k, where) for k in _NUMBERS if k in table}
    values.update({k: reader.string(table, k, where) for k in _STRINGS if k in table})
    for key in ("load_stage", "points"):
        if key in table:
            values[key] = reader.integer(table[key], key, where)
    if isinstance(table.get("roughness"), Mapping):
        r_where = at_key(where, "roughness")
        values["roughness"] = {k: reader.number(v, k, r_where) for k, v in reader.table(table["roughness"],
                                                                                          r_where).items()}
    elif "roughness" in table:
        values["roughness"] = reader.number(table["roughness"], "roughness", where)
    try:
        return MicropittingSpec(**values)
    except EpicyclicError as exc:
        raise reader.wrap(where, exc) from None
