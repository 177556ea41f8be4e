"""The ``[rating.flank_fracture]`` table of a train file: inputs of the tooth flank fracture rating.

::

    [rating.flank_fracture]               # ISO/TS 6336-4:2019 (simplified); see docs/rating.md
    case_depth = 1.0                      # CHD at 550 HV, mm; or per gear { sun = 0.8, planet = 0.8 }
    surface_hardness = 700.0              # HV_s (or per gear)
    core_hardness = 400.0                 # HV_c (or per gear)
    # hardness_profile = { ring = [[0.0, 680], [0.4, 640], [0.8, 560], [1.2, 470], [2.5, 380]] }
    #                                     # measured [depth mm, HV] pairs (per gear or for all)
    shear_strength_factor = 0.83          # K_τ,per, N/mm² per HV (default 0.831, an assumption)
    calibration_factor = 0.0              # c_1 of the material exposure
    S_FFmin = 1.0                         # minimum of S_FF = 1 / A_FF,max
    points = 25                           # contact points along the path
    depths_per_decade = 115               # depths per decade below each point (every 2 %)

References
----------
ISO/TS 6336-4:2019; ISO 2639:2002; ``docs/file-format.md``.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from ..errors import EpicyclicError
from ..rating.flank_fracture.spec import FlankFractureSpec
from .reader import at_key

__all__ = ["FLANK_FRACTURE_KEYS", "read_flank_fracture"]

FLANK_FRACTURE_KEYS = {"case_depth", "surface_hardness", "core_hardness", "hardness_profile",
                       "shear_strength_factor", "calibration_factor", "S_FFmin", "points", "depths_per_decade"}
_PER_GEAR = ("case_depth", "surface_hardness", "core_hardness")
_NUMBERS = ("shear_strength_factor", "calibration_factor", "S_FFmin")


def _pairs(reader, value, where: str) -> list[list[float]]:
    if not isinstance(value, list):
        raise reader.error(where, "expected a list of [depth mm, HV] pairs, e.g. [[0.0, 700], [0.8, 600], "
                                  "[1.2, 520], [3.0, 400]].")
    out = []
    for i, pair in enumerate(value):
        if not isinstance(pair, list) or len(pair) != 2:
            raise reader.error(f"{where}[{i}]", "expected a pair [depth mm, HV].")
        out.append([reader.number(pair[0], "depth", f"{where}[{i}]"), reader.number(pair[1], "HV", f"{where}[{i}]")])
    return out


def read_flank_fracture(reader, table: Mapping[str, Any]) -> FlankFractureSpec:
    """The :class:`~epicyclic.rating.flank_fracture.FlankFractureSpec` of a ``[rating.flank_fracture]`` table.

    Parameters
    ----------
    reader : TableReader
        The file's reader (messages name the file and the key).
    table : mapping
        The parsed table.

    Returns
    -------
    FlankFractureSpec

    Raises
    ------
    InputFileError
        An unknown key, a value of the wrong kind, missing case depth and hardness.

    References
    ----------
    ISO/TS 6336-4:2019; ``docs/file-format.md``.
    """
    where = "[rating.flank_fracture]"
    table = reader.table(table, where)
    reader.check_keys(table, FLANK_FRACTURE_KEYS, where)
    values: dict[str, Any] = {k: reader.number(table[k], k, where) for k in _NUMBERS if k in table}
    for key in ("points", "depths_per_decade"):
        if key in table:
            values[key] = reader.integer(table[key], key, where)
    for key in _PER_GEAR:
        if isinstance(table.get(key), Mapping):
            k_where = at_key(where, key)
            values[key] = {g: reader.number(v, g, k_where) for g, v in reader.table(table[key], k_where).items()}
        elif key in table:
            values[key] = reader.number(table[key], key, where)
    if "hardness_profile" in table:
        h_where = at_key(where, "hardness_profile")
        prof = table["hardness_profile"]
        values["hardness_profile"] = ({g: _pairs(reader, v, at_key(h_where, g)) for g, v in prof.items()}
                                      if isinstance(prof, Mapping) else _pairs(reader, prof, h_where))
    try:
        return FlankFractureSpec(**values)
    except EpicyclicError as exc:
        raise reader.wrap(where, exc) from None
