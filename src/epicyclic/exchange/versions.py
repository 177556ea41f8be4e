"""REXS versions: which are read and written, and the translation between 1.7 and 2.0.0.

The reader understands the attribute ids of REXS 1.0–1.7 (the 1.x databases only add and
rename within what it reads in compatible ways); a REXS 2.0.0 file is translated back to the
1.7 ids on reading, and a file to be written as 2.0.0 is translated forward, from the FVA's
own changelog ``rexs_changelog_1.7_to_2.0.0.xml`` (``schema/rexs_1.7_to_2.0.0.json`` holds its
attribute renames, unit changes and enum-value renames):

* 306 attributes renamed, e.g. ``averaged_peak_to_valley_height_flank`` →
  ``mean_peak_to_valley_roughness_flank_iso_4287_1997`` (R_z of the flank);
* units: 2.0.0 has no ``°`` (angles are ``deg``, which 1.7 also knows), writes ``MPa`` where
  1.7 wrote ``N / mm^2`` (89 attributes) and ``K`` where 1.7 wrote ``C`` (4 flash temperatures);
* enum values ``biologic-degradable``/``food-grade`` of a lubricant's ``basis`` become
  ``biologic_degradable``/``food_grade``;
* the ``version`` of a 2.0.0 model is ``"2.0.0"`` (``"2.0"`` is read as the same).

An unknown version is refused with the versions that are read.

References
----------
FVA GmbH, REXS database ``rexs_schema_1.7.xml`` and ``rexs_schema_2.0.0.xml`` and the changelog
``rexs_changelog_1.7_to_2.0.0.xml`` (github.com/fva-net/rexs-api-java, ``api/src/main/resources/info/rexs``,
Apache-2.0); ``RexsStandardVersions.V2_0_0`` (model version ``"2.0.0"``) of the same repository.
"""

from __future__ import annotations

import json
from functools import lru_cache
from pathlib import Path
from typing import Any

from .rexs_model import RexsValueError

__all__ = ["READ_VERSIONS", "WRITE_VERSIONS", "DEFAULT_WRITE_VERSION", "RexsVersionError", "check_version",
           "check_write_version", "written_attribute", "read_attribute", "is_2", "model_as_read"]

#: The REXS model versions the reader accepts.
READ_VERSIONS = ("1.0", "1.1", "1.2", "1.3", "1.4", "1.5", "1.6", "1.7", "2.0.0")
#: The versions the writer writes (``epicyclic convert --rexs-version``).
WRITE_VERSIONS = ("1.7", "2.0.0")
#: Written unless another is asked for.  2.0.0 becomes the default once the FVA publishes 2.0.0
#: reference models to round-trip against (none were public when this was written).
DEFAULT_WRITE_VERSION = "1.7"

_TABLE = Path(__file__).parent / "schema" / "rexs_1.7_to_2.0.0.json"


class RexsVersionError(RexsValueError):
    """A REXS file of a version the reader does not know, or a version the writer does not write."""


def check_version(version: object, source: str) -> str:
    """The file's REXS ``version``, normalised (``"2.0"`` → ``"2.0.0"``); refused when unknown.

    Parameters
    ----------
    version : str
        The ``version`` of the file's ``<model>``.
    source : str
        The file, for the message.

    Returns
    -------
    str

    Raises
    ------
    RexsVersionError
        Not one of :data:`READ_VERSIONS`.

    Examples
    --------
    >>> check_version("2.0", "m.rexs"), check_version("1.4", "m.rexs")
    ('2.0.0', '1.4')
    >>> check_version("3.1", "m.rexs")
    Traceback (most recent call last):
    ...
    epicyclic.exchange.versions.RexsVersionError: m.rexs: REXS version '3.1' is not read by epicyclic; it reads 1.0 … 1.7 and 2.0.0 (the model's version attribute).

    References
    ----------
    REXS file format (``rexs-file.xsd``: ``version`` required); ``RexsStandardVersions`` (fva-net/rexs-api-java).
    """
    text = str(version).strip() if isinstance(version, (str, int, float)) else ""
    if text in ("2.0", "2.0.0"):
        return "2.0.0"
    if text in READ_VERSIONS:
        return text
    shown = text[:20] if text else "(none)"
    raise RexsVersionError(f"{source}: REXS version {shown!r} is not read by epicyclic; it reads 1.0 … 1.7 and 2.0.0 "
                           "(the model's version attribute).", source)


def check_write_version(version: object) -> str:
    """A version the writer writes (``"2.0"`` → ``"2.0.0"``), else :class:`RexsVersionError` naming the choices.

    Examples
    --------
    >>> check_write_version("2.0")
    '2.0.0'
    """
    text = str(version).strip() if isinstance(version, str) else ""
    text = "2.0.0" if text == "2.0" else text
    if text not in WRITE_VERSIONS:
        raise RexsVersionError(f"--rexs-version: epicyclic writes REXS {' or '.join(WRITE_VERSIONS)}, "
                               f"got {str(version)[:20]!r}.", "")
    return text


def is_2(version: str) -> bool:
    """Whether ``version`` is a REXS 2.x model version."""
    return version.startswith("2.")


@lru_cache(maxsize=1)
def _tables() -> dict[str, Any]:
    data = json.loads(_TABLE.read_text(encoding="utf-8"))
    data["attribute_ids_back"] = {new: old for old, new in data["attribute_ids"].items()}
    data["enum_values_back"] = {a: {new: old for old, new in m.items()} for a, m in data["enum_values"].items()}
    return data


#: Unit spellings of 1.7 that 2.0.0 replaces by a unit of the same size (no value changes).
_SAME_SIZE = {"°": "deg", "N / mm^2": "MPa"}


def written_attribute(attribute: str, unit: str, value: Any, version: str) -> tuple[str, str, Any]:
    """An attribute the writer builds with 1.7 ids and units, as ``version`` writes it.

    Parameters
    ----------
    attribute, unit : str
        The 1.7 id and unit.
    value
        The value (converted when the unit changes size: ``C`` → ``K`` adds 273.15).
    version : str
        ``"1.7"`` or ``"2.0.0"``.

    Returns
    -------
    (str, str, value)

    Examples
    --------
    >>> written_attribute("averaged_peak_to_valley_height_flank", "mum", 3.2, "2.0.0")
    ('mean_peak_to_valley_roughness_flank_iso_4287_1997', 'mum', 3.2)
    >>> written_attribute("normal_pressure_angle", "°", 20.0, "2.0.0")
    ('normal_pressure_angle', 'deg', 20.0)

    References
    ----------
    ``rexs_changelog_1.7_to_2.0.0.xml`` (FVA GmbH).
    """
    if not is_2(version):
        return attribute, unit, value
    tables = _tables()
    new = tables["attribute_ids"].get(attribute, attribute)
    change = tables["units"].get(new)
    if change is not None and change[0] == unit:
        if (unit, change[1]) == ("C", "K") and isinstance(value, (int, float)) and not isinstance(value, bool):
            value = value + 273.15
        unit = change[1]
    unit = _SAME_SIZE.get(unit, unit)
    enum = tables["enum_values"].get(new)
    if enum and isinstance(value, str):
        value = enum.get(value, value)
    return new, unit, value


def read_attribute(attribute: str, value: Any, version: str) -> tuple[str, Any]:
    """A 2.0.0 attribute id (and enum value) as the reader's 1.7 id; 1.x unchanged.

    The unit stays as the file gives it: the reader converts every unit it knows
    (:mod:`epicyclic.exchange.units`).

    Examples
    --------
    >>> read_attribute("mean_peak_to_valley_roughness_root_iso_4287_1997", 6.0, "2.0.0")
    ('averaged_peak_to_valley_height_root', 6.0)

    References
    ----------
    ``rexs_changelog_1.7_to_2.0.0.xml`` (FVA GmbH).
    """
    if not is_2(version):
        return attribute, value
    tables = _tables()
    enum = tables["enum_values_back"].get(attribute)
    if enum and isinstance(value, str):
        value = enum.get(value, value)
    return tables["attribute_ids_back"].get(attribute, attribute), value


def model_as_read(model):
    """A parsed :class:`~epicyclic.exchange.rexs_model.RexsModel` with its version checked and, for 2.0.0,
    its attribute ids (components and load cases) translated to the reader's 1.7 ids.

    Parameters
    ----------
    model : RexsModel

    Returns
    -------
    RexsModel
        ``version`` normalised (``"2.0"`` → ``"2.0.0"``).

    Raises
    ------
    RexsVersionError
        An unknown version.

    References
    ----------
    ``rexs_changelog_1.7_to_2.0.0.xml`` (FVA GmbH).
    """
    from dataclasses import replace

    from .rexs_model import Attribute, Component, LoadCase

    version = check_version(model.version, model.source)
    if not is_2(version):
        return replace(model, version=version) if version != model.version else model

    def attributes(found):
        out = {}
        for a in found.values():
            aid, value = read_attribute(a.id, a.value, version)
            out[aid] = Attribute(aid, value, a.unit)
        return out

    components = {cid: Component(c.id, c.type, c.name, attributes(c.attributes)) for cid, c in model.components.items()}
    cases = tuple(LoadCase(case.id, case.spectrum, {cid: attributes(found) for cid, found in case.components.items()})
                  for case in model.load_cases)
    return replace(model, version=version, components=components, load_cases=cases)
