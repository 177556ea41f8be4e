"""Load factors given or computed: :class:`FactorValue` and the per-mesh and per-gear look-up of ``[rating]``.

A load factor of ISO 6336-1 (K_A, K_γ, K_v, K_Hβ, K_Fβ, K_Hα, K_Fα) is either *given* (by the
user, measured, from a REXS file) or *computed* by a method of the standard; a third source, such
as an elastic model of the carrier that computes K_γ or K_Hβ, is one more ``source`` string.  Each
factor of a rating carries its :class:`FactorValue` (value, source, clause), and the reports print
both.

In ``[rating]`` each factor is one number for every mesh, or a table by mesh::

    K_v = 1.05                                         # every mesh
    K_Hbeta = { "sun-planet" = 1.15, "planet-ring" = 1.25 }
    K_Hbeta = { "P1:sun-planet" = 1.2, P2 = 1.3, all = 1.1 }   # element:mesh, mesh, element, all

A mesh takes the first entry of ``element:mesh``, ``mesh``, ``element``, ``all``; a mesh without one
computes the factor (K_A without one is an error: it cannot be computed).  The measured deviations
``f_pb``, ``f_falpha``, ``f_Hbeta`` (µm) and the ``accuracy_grade`` are given per gear in the same
way (``element:gear``, ``gear``, ``all``).

References
----------
ISO 6336-1:2019, clause 4 and 6.2 (K_A "should be determined by ... measurement or experience"),
6.3 (K_v methods A/B), 7 (K_Hβ methods A/B/C), 8 (K_Hα methods A/B), 6.5.9 (K_γ).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType

from .errors import RatingError

__all__ = ["COMPUTED", "DEFAULT", "GEAR_DEVIATIONS", "GIVEN", "MESH_FACTORS", "FactorValue", "gear_value",
           "mesh_factor", "unmatched_keys"]

GIVEN, COMPUTED, DEFAULT = "given", "computed", "default"

#: ``[rating]`` key → ISO symbol of the load factors given per mesh.
MESH_FACTORS: Mapping[str, str] = MappingProxyType({
    "application_factor": "K_A", "load_sharing": "K_gamma", "K_v": "K_v", "K_Hbeta": "K_Hbeta",
    "K_Fbeta": "K_Fbeta", "K_Halpha": "K_Halpha", "K_Falpha": "K_Falpha"})
#: Deviations that may be given per gear instead of from the accuracy grade, µm.
GEAR_DEVIATIONS = ("f_pb", "f_falpha", "f_Hbeta")


@dataclass(frozen=True)
class FactorValue:
    """A factor's value and where it comes from.

    Parameters
    ----------
    value : float
        The factor (or deviation, in its unit).
    source : str, default "given"
        ``"given"``, ``"computed"``, ``"default"`` or another named source such as
        ``"computed by the elastic model"``.
    clause : str, default ""
        The clause of the standard it is given under or computed by, e.g.
        ``"ISO 6336-1:2006, 6.3.2 (method B)"``.

    Raises
    ------
    RatingError
        A value that is not a finite number, an empty source.

    References
    ----------
    ISO 6336-1:2019, clause 4.

    Examples
    --------
    >>> FactorValue(1.15, clause="ISO 6336-1:2019, 7 (given)")
    FactorValue(1.15, given, ISO 6336-1:2019, 7 (given))
    """

    value: float
    source: str = GIVEN
    clause: str = ""

    def __post_init__(self) -> None:
        v = self.value
        if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v):
            raise RatingError(f"FactorValue: value must be a finite number, got {v!r}.")
        if not isinstance(self.source, str) or not self.source.strip():
            raise RatingError(f"FactorValue: source must name where the value comes from, got {self.source!r}.")
        object.__setattr__(self, "value", float(v))

    def __float__(self) -> float:
        return self.value

    def __repr__(self) -> str:
        return f"FactorValue({self.value:g}, {self.source}{', ' + self.clause if self.clause else ''})"


def check_given(value, key: str, low: float = 1.0):
    """A given factor (number, FactorValue or table of them) checked: each ≥ ``low``; tables read-only.

    Parameters
    ----------
    value : float, FactorValue or mapping
        As written in ``[rating]`` or passed to :class:`~epicyclic.rating.spec.RatingSpec`.
    key : str
        The ``[rating]`` key (for the message).
    low : float, default 1
        The least value accepted (1 for a load factor, 0 for a deviation in µm).

    Returns
    -------
    float, FactorValue or mapping of str → float or FactorValue
        Plain numbers stay numbers (a FactorValue stays one).

    Raises
    ------
    RatingError
        A value below ``low``, not a number, or an empty table.

    References
    ----------
    ISO 6336-1:2019, clauses 6–8 (each load factor ≥ 1).
    """
    if isinstance(value, Mapping):
        if not value:
            raise RatingError(f"rating.{key} is an empty table; give a number, or entries such as "
                              f"{{ \"sun-planet\" = 1.1, all = 1.0 }}.")
        return MappingProxyType({str(k): check_given(v, f"{key}.{k}", low) for k, v in value.items()})
    factor = value if isinstance(value, FactorValue) else None
    number = factor.value if factor else value
    if isinstance(number, bool) or not isinstance(number, (int, float)) or not math.isfinite(number) or number < low:
        what = "a load factor" if low == 1.0 else "a deviation in µm"
        raise RatingError(f"rating.{key} must be a number >= {low:g} ({what}), got {number!r}.")
    return factor or float(number)


def _pick(given, names: tuple[str, ...]):
    if not isinstance(given, Mapping):
        return given
    for name in names:
        if name in given:
            return given[name]
    return None


def mesh_factor(given, element: str, mesh: str) -> FactorValue | None:
    """The given factor of ``mesh`` of ``element`` (``element:mesh``, ``mesh``, ``element``, ``all``), or None.

    Parameters
    ----------
    given : FactorValue, mapping or None
        A checked ``[rating]`` value (:func:`check_given`).
    element, mesh : str
        The set or stage and the mesh's name (``sun-planet``, ``planet-ring``, ``mesh 1 (20/40)``).

    Returns
    -------
    FactorValue or None
        None where nothing is given for this mesh (the factor is computed).

    Examples
    --------
    >>> given = check_given({"sun-planet": 1.1, "P2": 1.3}, "K_v")
    >>> mesh_factor(given, "P1", "sun-planet").value, mesh_factor(given, "P2", "planet-ring").value
    (1.1, 1.3)
    >>> mesh_factor(given, "P1", "planet-ring") is None
    True
    """
    value = _pick(given, (f"{element}:{mesh}", mesh, element, "all"))
    return FactorValue(value) if isinstance(value, (int, float)) and not isinstance(value, bool) else value


def gear_value(given, element: str, gear: str):
    """The entry of ``gear`` of ``element`` in a per-gear value (``element:gear``, ``gear``, ``all``), or None.

    Parameters
    ----------
    given : object or mapping
        One value for every gear, or a table by gear.
    element, gear : str
        The set or stage and the gear's name in it (``sun``, ``ring``, ``driving`` ...).

    Returns
    -------
    object or None

    Examples
    --------
    >>> gear_value({"ring": 8, "all": 6}, "P1", "ring"), gear_value({"ring": 8, "all": 6}, "P1", "sun")
    (8, 6)
    """
    return _pick(given, (f"{element}:{gear}", gear, "all"))


def unmatched_keys(given, names: set[str]) -> list[str]:
    """The keys of a per-mesh or per-gear table that name no mesh, gear or element of the train.

    Parameters
    ----------
    given : object or mapping
        A ``[rating]`` value.
    names : set of str
        Every name a key may take (``element:mesh``, ``mesh``, ``element``, ``element:gear``,
        ``gear``, ``all``).

    Returns
    -------
    list of str

    Examples
    --------
    >>> unmatched_keys({"sun-planet": 1.1, "sun-plnet": 1.2}, {"sun-planet", "all"})
    ['sun-plnet']
    """
    if not isinstance(given, Mapping):
        return []
    return [k for k in given if k not in names]
