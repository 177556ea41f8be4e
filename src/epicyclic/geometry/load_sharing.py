"""The load-sharing (mesh load) factor K_γ of a planetary set by number of planets and mounting.

K_γ is the share of the most loaded planet over the mean share: the design
force of a mesh is K_γ F_t/N.  Rating standards tabulate it by the number of
planets where no measured value is known:

* **IEC 61400-4:2012** (wind turbine gearboxes) and **AGMA 6123-B06** (enclosed
  epicyclic drives) for a set with a floating member (a floating sun):
  N = 3, 4, 5, 6, 7 → K_γ = 1.10, 1.25, 1.35, 1.44, 1.47, as the table is quoted
  in the secondary literature; one or two planets with a floating member share
  exactly (K_γ = 1).  Flexible (Flexpin) pins improve the sharing; the standards
  leave the lower value to measurement, so the table value is returned as the
  upper bound and the source says so.
* **ABS rules** (marine gears, as tabulated in the FVA-Workbench documentation,
  attribute PMID 6051): up to 3 planets 1.0, 4 → 1.2, 5 → 1.3, 6 and more 1.4
  (:func:`default_load_sharing`, the library's default since before this table).

Beyond the tables no value is invented: the caller gives a measured K_γ.

References
----------
IEC 61400-4:2012, *Wind turbines — Part 4: Design requirements for wind turbine
gearboxes* (load sharing factor K_γ); ANSI/AGMA 6123-B06, *Design Manual for
Enclosed Epicyclic Gear Drives* (planet load share factor K_γ); FVA-Workbench
documentation, attribute "Load sharing factor Kγ" (PMID 6051, ABS rules).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from .errors import GeometryError

__all__ = ["MOUNTINGS", "LoadSharing", "load_sharing_factor", "tabulated_load_sharing", "default_load_sharing"]

#: Mountings the tables distinguish.
MOUNTINGS = ("floating_sun", "flexible_pins", "abs")

#: IEC 61400-4 / AGMA 6123 (floating member), planets → K_γ.
_IEC = {1: 1.0, 2: 1.0, 3: 1.10, 4: 1.25, 5: 1.35, 6: 1.44, 7: 1.47}

_SOURCES = {
    "floating_sun": "IEC 61400-4:2012 / AGMA 6123-B06, floating central member",
    "flexible_pins": "IEC 61400-4:2012 / AGMA 6123-B06 table value (an upper bound for flexible pins; a lower value "
                     "needs measurement)",
    "abs": "ABS rules (FVA-Workbench PMID 6051)",
}


def default_load_sharing(planets: int) -> float:
    """Default load-sharing (mesh load) factor K_γ by number of planets (ABS rules).

    ===========  =====
    planets      K_γ
    ===========  =====
    up to 3      1.0
    4            1.2
    5            1.3
    6 and more   1.4
    ===========  =====

    Parameters
    ----------
    planets : int
        Number of planets, ≥ 1.

    Returns
    -------
    float

    Raises
    ------
    GeometryError
        ``planets`` is no whole number ≥ 1.

    >>> [default_load_sharing(n) for n in (3, 4, 5, 6, 8)]
    [1.0, 1.2, 1.3, 1.4, 1.4]

    References
    ----------
    ABS (American Bureau of Shipping) rules as tabulated in the FVA-Workbench
    documentation, attribute "Load sharing factor Kγ" (PMID 6051). Use a measured or
    AGMA 6123 / IEC 61400-4 value (:func:`load_sharing_factor`) where one applies.
    """
    if isinstance(planets, bool) or not isinstance(planets, int) or planets < 1:
        raise GeometryError(f"default_load_sharing: planets must be a whole number >= 1, got {planets!r}.")
    return 1.0 if planets <= 3 else {4: 1.2, 5: 1.3}.get(planets, 1.4)


@dataclass(frozen=True)
class LoadSharing:
    """A tabulated K_γ with its source.

    Attributes
    ----------
    value : float
        K_γ ≥ 1.
    planets : int
    mounting : str
        One of :data:`MOUNTINGS`.
    source : str
        The standard and table row.
    """

    value: float
    planets: int
    mounting: str
    source: str

    def to_dict(self) -> dict[str, Any]:
        """``value``, ``planets``, ``mounting``, ``source``."""
        return {"value": self.value, "planets": self.planets, "mounting": self.mounting, "source": self.source}

    def __str__(self) -> str:
        return f"K_gamma = {self.value:g} ({self.source}, {self.planets} planets)"


def tabulated_load_sharing(planets: int, mounting: str = "floating_sun") -> LoadSharing:
    """K_γ from the tables with its source (see the module docstring).

    Parameters
    ----------
    planets : int
        Number of planets, ≥ 1.
    mounting : {"floating_sun", "flexible_pins", "abs"}, default "floating_sun"
        ``floating_sun`` / ``flexible_pins``: the IEC 61400-4 / AGMA 6123 table
        (1 … 7 planets); ``abs``: the ABS rules (any number).

    Returns
    -------
    LoadSharing

    Raises
    ------
    GeometryError
        An unknown mounting, a bad number of planets, or more planets than the table covers.

    Examples
    --------
    >>> str(tabulated_load_sharing(4))
    'K_gamma = 1.25 (IEC 61400-4:2012 / AGMA 6123-B06, floating central member, 4 planets)'

    References
    ----------
    IEC 61400-4:2012; ANSI/AGMA 6123-B06; FVA-Workbench PMID 6051 (ABS).
    """
    if mounting not in MOUNTINGS:
        raise GeometryError(f"tabulated_load_sharing: mounting must be one of {', '.join(map(repr, MOUNTINGS))}, "
                            f"got {mounting!r}.")
    if isinstance(planets, bool) or not isinstance(planets, int) or planets < 1:
        raise GeometryError(f"tabulated_load_sharing: planets must be a whole number >= 1, got {planets!r}.")
    if mounting == "abs":
        return LoadSharing(default_load_sharing(planets), planets, mounting, _SOURCES[mounting])
    if planets not in _IEC:
        raise GeometryError(f"tabulated_load_sharing: IEC 61400-4 / AGMA 6123 tabulate K_gamma for 1 … {max(_IEC)} planets, "
                            f"not {planets}; give a measured load_sharing (K_gamma) or mounting='abs'.")
    return LoadSharing(_IEC[planets], planets, mounting, _SOURCES[mounting])


def load_sharing_factor(planets: int, mounting: str = "floating_sun") -> float:
    """K_γ from the tables by number of planets and mounting (the value of :func:`tabulated_load_sharing`).

    Parameters
    ----------
    planets : int
        Number of planets, ≥ 1.
    mounting : {"floating_sun", "flexible_pins", "abs"}, default "floating_sun"
        Which table row (module docstring).

    Returns
    -------
    float
        K_γ ≥ 1.

    Raises
    ------
    GeometryError
        As :func:`tabulated_load_sharing`.

    Examples
    --------
    >>> [load_sharing_factor(n) for n in (3, 4, 5, 6, 7)]
    [1.1, 1.25, 1.35, 1.44, 1.47]

    References
    ----------
    IEC 61400-4:2012; ANSI/AGMA 6123-B06.
    """
    return tabulated_load_sharing(planets, mounting).value
