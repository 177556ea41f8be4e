"""The ``[rating.scuffing]`` table of a train file: inputs of the scuffing rating.

::

    [rating.scuffing]
    load_stage = 12                       # FZG A/8.3/90 failure load stage of the oil (ISO 14635-1)
    oil_temperature = 80.0                # θ_oil, °C
    roughness_Ra = 0.6                    # R_a of the flanks, µm; or per gear { sun = 0.5, ring = 1.0 }
    oil_type = "mineral"                  # X_L: mineral, polyalphaolefin, polyglycol, ...
    oil_density = 890.0                   # kg/m³ at 15 °C
    lubrication = "dip"                   # X_S: dip, spray, immersed
    structural_factor = 1.0               # X_W
    contact_coefficient = 13.78           # B_M, N/(mm s^½ K)
    run_in = 1.0                          # φ_E of X_E: 1 well run in, 0 new
    driving = "gear1"                     # X_Q (without: 1)
    S_Smin = 1.8                          # integral temperature
    S_Bmin = 2.0                          # flash temperature
    edition = "2017"                      # "2017", "2022" (ISO/TS 6336-20/-21) or "2000" (ISO/TR 13989)

The lubricant's ν_40 and ν_100 come from ``[lubricant]`` or ``[rating.lubricant]``.

References
----------
ISO/TS 6336-20:2017; ISO/TS 6336-21:2017; ISO 14635-1:2000; ``docs/file-format.md``.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from ..errors import EpicyclicError
from ..rating.scuffing.spec import ScuffingSpec
from .reader import at_key

__all__ = ["SCUFFING_KEYS", "read_scuffing"]

SCUFFING_KEYS = {"load_stage", "oil_temperature", "roughness_Ra", "oil_type", "oil_density", "lubrication",
                 "structural_factor", "contact_coefficient", "run_in", "driving", "multiple_meshing",
                 "S_Smin", "S_Bmin", "edition", "integral_scuffing_temperature", "scuffing_temperature"}
_NUMBERS = ("oil_temperature", "oil_density", "structural_factor", "contact_coefficient", "run_in",
            "multiple_meshing", "S_Smin", "S_Bmin", "integral_scuffing_temperature", "scuffing_temperature")


def read_scuffing(reader, table: Mapping[str, Any]) -> ScuffingSpec:
    """The :class:`~epicyclic.rating.scuffing.ScuffingSpec` of a ``[rating.scuffing]`` table.

    Parameters
    ----------
    reader : TableReader
        The file's reader (messages name the file and the key).
    table : mapping
        The parsed table.

    Returns
    -------
    ScuffingSpec

    Raises
    ------
    InputFileError
        An unknown key, a value of the wrong kind, a missing required key (named with the value
        commonly taken).

    References
    ----------
    ISO/TS 6336-20:2017; ISO/TS 6336-21:2017; ``docs/file-format.md``.
    """
    where = "[rating.scuffing]"
    table = reader.table(table, where)
    reader.check_keys(table, SCUFFING_KEYS, where)
    values: dict[str, Any] = {k: reader.number(table[k], k, where) for k in _NUMBERS if k in table}
    if "load_stage" in table:
        values["load_stage"] = reader.integer(table["load_stage"], "load_stage", where)
    for key in ("oil_type", "lubrication", "driving"):
        if key in table:
            values[key] = reader.string(table, key, where)
    if "edition" in table:
        values["edition"] = str(table["edition"])
    if isinstance(table.get("roughness_Ra"), Mapping):
        r_where = at_key(where, "roughness_Ra")
        values["roughness_Ra"] = {k: reader.number(v, k, r_where)
                                  for k, v in reader.table(table["roughness_Ra"], r_where).items()}
    elif "roughness_Ra" in table:
        values["roughness_Ra"] = reader.number(table["roughness_Ra"], "roughness_Ra", where)
    try:
        return ScuffingSpec(**values)
    except EpicyclicError as exc:
        raise reader.wrap(where, exc) from None
