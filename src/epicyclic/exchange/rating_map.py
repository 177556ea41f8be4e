"""The ``[rating]`` table of a REXS model: materials and roughness of its gears (ISO 6336 inputs).

Where every gear of the model's planetary sets references a ``material`` whose
designation (``material_designation``, else the component's name without its
``[id]``) is a material of epicyclic's data file (``docs/rating.md``), gives
the mean peak-to-valley roughness R_z of its flanks and root fillets
(``averaged_peak_to_valley_height_flank``/``_root``), and the lubricant its
viscosity at 40 °C, the model gets a ``[rating]`` table, so that
``epicyclic rate`` rates the REXS file as it is.  The roughness is the mean
over the gears (ISO 6336-2 uses the pair's mean); everything else keeps the
rating's defaults (K_A = 1, material quality MQ, ...).  Without all of them
there is no ``[rating]`` (``epicyclic rate`` then says which keys the table needs).

References
----------
ISO 6336-2:2019, eq. (25) (R_z10 of the pair); ISO 6336-5:2016 (materials); REXS 1.7 attribute
database (FVA GmbH, Apache-2.0).
"""

from __future__ import annotations

from typing import Any

from ..errors import EpicyclicError

__all__ = ["rating_table"]


def rating_table(gears: list[tuple[str, str, Any]], lubricant: dict | None) -> dict | None:
    """The ``[rating]`` table of the gears ``(element, gear name, GearData)``, or None.

    Parameters
    ----------
    gears : list of (str, str, GearData)
        Every gear of the model's planetary sets.
    lubricant : dict or None
        The document's ``[lubricant]`` (its ``viscosity_40`` is needed).

    Returns
    -------
    dict or None
    """
    if not gears:
        return None
    from ..rating.materials import material

    names = {}
    for element, role, data in gears:
        try:
            material(data.material or "")
        except EpicyclicError:
            names = None
            break
        names[f"{element}:{role}"] = data.material
    flank = [d.flank_roughness for _, _, d in gears]
    root = [d.root_roughness for _, _, d in gears]
    if names is None or None in flank or None in root or not (lubricant or {}).get("viscosity_40"):
        return None
    distinct = set(names.values())
    return {"material": distinct.pop() if len(distinct) == 1 else names,
            "flank_roughness": round(sum(flank) / len(flank), 6), "root_roughness": round(sum(root) / len(root), 6)}
