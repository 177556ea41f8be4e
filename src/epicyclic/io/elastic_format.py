"""The ``[elastic]`` table of a train file: stiffnesses, errors and tolerances of the planetary sets' elastic models.

Units: stiffnesses in N/µm (1 N/µm = 10⁶ N/m), torsional stiffnesses in N m/rad, errors and
tolerances in µm, angles in degrees, speeds in 1/min.  Every key is optional; a missing one takes
the default of :data:`epicyclic.elastic.from_geometry.DEFAULTS` (listed in the reports), or, with
``defaults = "refuse"``, is an error naming it.  See ``docs/file-format.md`` and ``docs/elastic.md``.

References
----------
J. Lin, R. G. Parker, J. Vib. Acoust. 121 (1999) 316–321 (the model and its default magnitudes);
ISO 6336-1:2006, 9.3 (the default mesh stiffness).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Mapping

from ..text import short
from .reader import TableReader, at_key

__all__ = ["ElasticInputs", "read_elastic", "ELASTIC_KEYS"]

_STIFF = ("sun_mesh", "ring_mesh", "planet_bearing", "sun_support", "ring_support", "carrier_support")
_TORSION = ("sun_torsion", "ring_torsion", "carrier_torsion")
_FACE_KEYS = {"misalignment", "crowning", "end_relief", "end_relief_length", "slope_correction", "sun_torsion",
              "slices"}
ELASTIC_KEYS = {"defaults", "set", *_STIFF, *_TORSION, "density", "masses", "planet_angles", "errors", "tolerances",
                "draws", "seed", "speed_range", "operating_range", "face", "rating"}
_ERROR_KEYS = {"pin_radial", "pin_tangential", "tooth_thickness", "sun_runout", "sun_runout_angle", "ring_runout",
               "ring_runout_angle"}
_TOLERANCE_KEYS = {"pin_position", "tooth_thickness", "sun_runout", "ring_runout"}
_WHERE = "[elastic]"


@dataclass(frozen=True)
class ElasticInputs:
    """What ``[elastic]`` says.

    Attributes
    ----------
    spec : ElasticSpec
        Stiffnesses, masses, planet angles (SI) for :func:`~epicyclic.elastic.from_geometry.lumped_model`.
    set_name : str or None
        The set it is for (None: every simple set with geometry).
    errors : PlanetErrors or None
    tolerances : Tolerances or None
    draws, seed : int
        Monte Carlo (default 10000 draws, seed 0).
    speed_range : tuple of float or None
        Sun speeds of the Campbell diagram, 1/min.
    operating_range : tuple of float or None
        Sun speeds whose crossings are listed, 1/min.
    face : dict or None
        ``[elastic.face]``: ``misalignment``, ``modification`` (HelixModification), ``sun_torsion``
        (bool), ``slices`` for the face load distribution of the most loaded planet's meshes.
    rating : tuple of str
        The factors ``epicyclic rate`` takes from the elastic model (``load_sharing``, ``K_Hbeta``).
    """

    spec: Any
    set_name: str | None = None
    errors: Any = None
    tolerances: Any = None
    draws: int = 10_000
    seed: int = 0
    speed_range: tuple[float, float] | None = None
    operating_range: tuple[float, float] | None = None
    face: Any = None
    rating: tuple[str, ...] = ()


def _numbers(reader: TableReader, value: object, key: str, where: str) -> tuple[float, ...]:
    if not isinstance(value, list) or not value or len(value) > 64:
        raise reader.error(at_key(where, key), f"expected an array of 1 … 64 numbers, got {short(value)}.")
    return tuple(reader.number(v, key, where) for v in value)


def _range(reader: TableReader, table: Mapping[str, Any], key: str) -> tuple[float, float] | None:
    if key not in table:
        return None
    low, *rest = _numbers(reader, table[key], key, _WHERE)
    if len(rest) != 1 or not 0.0 <= low < rest[0] <= 1e6:
        raise reader.error(at_key(_WHERE, key), f"expected [low, high] sun speeds in 1/min with 0 <= low < high <= "
                                                f"1e6, got {short(table[key])}.")
    return low, rest[0]


def _whole(reader: TableReader, table: Mapping[str, Any], key: str, default: int, low: int, high: int) -> int:
    value = reader.integer(table.get(key, default), key, _WHERE)
    if not low <= value <= high:
        raise reader.error(at_key(_WHERE, key), f"expected a whole number {low} … {high}, got {value}.")
    return value


def read_elastic(reader: TableReader, value: object) -> ElasticInputs:
    """Parse ``[elastic]``; errors name the key and what is expected.

    Parameters
    ----------
    reader : TableReader
        The file's reader (messages name its source).
    value : object
        The parsed table.

    Returns
    -------
    ElasticInputs

    References
    ----------
    ``docs/file-format.md``, section ``[elastic]``.
    """
    from ..elastic.errors import ElasticError
    from ..elastic.from_geometry import ElasticSpec
    from ..elastic.sharing import PlanetErrors, Tolerances

    table = reader.table(value, _WHERE)
    reader.check_keys(table, ELASTIC_KEYS, _WHERE)
    defaults = table.get("defaults", "use")
    if defaults not in ("use", "refuse"):
        raise reader.error(at_key(_WHERE, "defaults"), f"expected \"use\" (the stated defaults) or \"refuse\" (every "
                                                       f"stiffness given), got {short(defaults)}.")
    values: dict[str, Any] = {}
    for key in _STIFF:
        if key in table:
            raw = table[key]
            if key.endswith("support") and raw == "floating":
                values[key] = 0.0
                continue
            number = reader.number(raw, key, _WHERE)
            if number < 0 or (number == 0 and not key.endswith("support")):
                bound = '>= 0 (or "floating")' if key.endswith("support") else "> 0"
                raise reader.error(at_key(_WHERE, key), f"expected a stiffness in N/um {bound}, got {short(raw)}.")
            values[key] = number * 1e6
    for key in _TORSION:
        if key in table:
            number = reader.number(table[key], key, _WHERE)
            if number < 0:
                raise reader.error(at_key(_WHERE, key), f"expected a torsional stiffness in N m/rad >= 0 (0 = free), "
                                                        f"got {short(table[key])}.")
            values[key] = number
    if "density" in table:
        values["density"] = reader.number(table["density"], "density", _WHERE)
    masses = {}
    if "masses" in table:
        where = at_key(_WHERE, "masses")
        for name, pair in reader.table(table["masses"], where).items():
            if name not in ("sun", "planet", "ring", "carrier"):
                raise reader.error(where, f"unknown member {short(name)}; expected sun, planet, ring or carrier.")
            numbers = _numbers(reader, pair, name, where)
            if len(numbers) != 2 or min(numbers) <= 0:
                raise reader.error(at_key(where, name), "expected [mass kg, polar inertia kg m2], both > 0.")
            masses[name] = numbers
    angles = _numbers(reader, table["planet_angles"], "planet_angles", _WHERE) if "planet_angles" in table else None
    try:
        spec = ElasticSpec(**values, masses=masses, planet_angles=angles, refuse_defaults=defaults == "refuse")
        errors = tolerances = None
        if "errors" in table:
            where = f"{_WHERE} errors"
            err = reader.table(table["errors"], where)
            reader.check_keys(err, _ERROR_KEYS, where)
            errors = PlanetErrors(**{k: (_numbers(reader, v, k, where) if isinstance(v, list)
                                         else reader.number(v, k, where)) for k, v in err.items()})
        if "tolerances" in table:
            where = f"{_WHERE} tolerances"
            tol = reader.table(table["tolerances"], where)
            reader.check_keys(tol, _TOLERANCE_KEYS, where)
            tolerances = Tolerances(**{k: reader.number(v, k, where) for k, v in tol.items()})
        face = _face(reader, table["face"]) if "face" in table else None
    except ElasticError as exc:
        raise reader.wrap(_WHERE, exc, "elastic") from None
    except TypeError as exc:  # a list where a number belongs, or the reverse
        raise reader.error(_WHERE, f"a value has the wrong kind: {exc}; see docs/file-format.md, [elastic].") from None
    name = reader.name(table, "set", _WHERE) if "set" in table else None
    rating = reader.names(table.get("rating", []), "rating", _WHERE)
    unknown = [r for r in rating if r not in ("load_sharing", "K_Hbeta")]
    if unknown:
        raise reader.error(at_key(_WHERE, "rating"), f"the elastic model computes load_sharing and K_Hbeta for the "
                                                     f"rating, not {short(unknown[0])}.")
    return ElasticInputs(spec, name, errors, tolerances, _whole(reader, table, "draws", 10_000, 1, 1_000_000),
                         _whole(reader, table, "seed", 0, 0, 2 ** 63 - 1), _range(reader, table, "speed_range"),
                         _range(reader, table, "operating_range"), face, rating)


def _face(reader: TableReader, value: object) -> dict[str, Any]:
    """``[elastic.face]``: misalignment and helix modifications (µm, mm), sun torsion (bool), slices."""
    from ..elastic.face_load import HelixModification

    where = f"{_WHERE} face"
    face = reader.table(value, where)
    reader.check_keys(face, _FACE_KEYS, where)
    mod = {k: reader.number(face[k], k, where) for k in ("crowning", "end_relief", "end_relief_length",
                                                         "slope_correction") if k in face}
    return {"misalignment": reader.number(face.get("misalignment", 0.0), "misalignment", where),
            "modification": HelixModification(**mod),
            "sun_torsion": reader.boolean(face, "sun_torsion", where, True),
            "slices": _whole(reader, face, "slices", 40, 4, 400)}
