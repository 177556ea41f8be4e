"""The gear train: a graph of named shafts joined by elements.

Shafts are nodes; planetary sets, gear stages, clutches and brakes are the
edges (hyperedges) that join them.  The frame is the shaft ``"housing"`` with
speed zero.  A train is immutable; a shift state is a new train made with
:meth:`GearTrain.with_engaged`.

References
----------
Queitsch, eq. 12 (one Willis equation per set); Brandenberger 1952, Bild 10 (a closed train as a graph of sets and stages).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from typing import Union

from ..errors import ModelError, UnknownShaftError, closest
from ..limits import MAX_ELEMENTS, MAX_SHAFTS, MAX_TITLE_CHARS
from .elements import HOUSING, Brake, Clutch, GearStage
from .planetary import PlanetarySet, check_name

__all__ = ["GearTrain", "Element", "ShiftElement"]

Element = Union[PlanetarySet, GearStage, Clutch, Brake]
ShiftElement = Union[Clutch, Brake]


def _sequence(value: object, field_name: str, example: str) -> tuple:
    """``value`` as a tuple if it is an iterable of items (not one element), else a ModelError naming the field."""
    if isinstance(value, (PlanetarySet, GearStage, Clutch, Brake)):
        raise ModelError(f"gear train: {field_name} must be a list of elements, got one {type(value).__name__} "
                         f"{value.name!r}; put it in a list: {example}.")
    try:
        return tuple(value)  # type: ignore[arg-type]
    except TypeError:
        raise ModelError(f"gear train: {field_name} must be a list, got {type(value).__name__} {value!r:.40}; "
                         f"e.g. {example}.") from None


@dataclass(frozen=True)
class GearTrain:
    """A gear train of elements joining named shafts.

    Parameters
    ----------
    elements : iterable of PlanetarySet, GearStage, Clutch, Brake
        The elements; names must be unique.
    shafts : iterable of str, optional
        Extra shaft names (shafts not joined to any element); every shaft an
        element names is added automatically, and so is ``"housing"``.
    name : str, optional
        A title for reports.

    Examples
    --------
    >>> from epicyclic import PlanetarySet, Brake
    >>> train = GearTrain([
    ...     PlanetarySet.simple("P", sun="in", ring="ring", carrier="out",
    ...                         z_sun=30, z_planet=24, z_ring=78),
    ...     Brake("B", "ring")])
    >>> train.shafts
    ('in', 'ring', 'out', 'housing')
    """

    elements: tuple[Element, ...]
    shafts: tuple[str, ...] = field(default=())
    name: str = "gear train"

    def __hash__(self) -> int:  # the solver's caches are keyed by the train: hashed once, then kept
        value = self.__dict__.get("_hash")
        if value is None:
            value = self.__dict__["_hash"] = hash((self.elements, self.shafts, self.name))
        return value

    def __getstate__(self) -> dict:  # string hashes differ between processes: not pickled
        return {k: v for k, v in self.__dict__.items() if k != "_hash"}

    def __post_init__(self) -> None:
        elements = _sequence(self.elements, "elements", "GearTrain([PlanetarySet(...), Brake(...)])")
        if not elements:
            raise ModelError("gear train: elements must contain at least one element, got none.")
        if len(elements) > MAX_ELEMENTS:
            raise ModelError(f"gear train: {len(elements)} elements given; at most {MAX_ELEMENTS} are accepted.")
        if not isinstance(self.name, str) or len(self.name) > MAX_TITLE_CHARS:
            raise ModelError(f"gear train: name must be a string of at most {MAX_TITLE_CHARS} characters, "
                             f"got {self.name!r:.40}.")
        names: set[str] = set()
        for k, element in enumerate(elements):
            if not isinstance(element, (PlanetarySet, GearStage, Clutch, Brake)):
                raise ModelError(
                    f"gear train: elements[{k}] must be a PlanetarySet, GearStage, Clutch or Brake, "
                    f"got {type(element).__name__}."
                )
            if element.name in names:
                raise ModelError(f"gear train: element name {element.name!r} is used twice; names must be unique.")
            names.add(element.name)
        ordered: list[str] = []
        extra = (self.shafts,) if isinstance(self.shafts, str) else _sequence(self.shafts, "shafts", "shafts=['out']")
        for shaft in extra:
            check_name(shaft, "shafts", "gear train")
            if shaft not in ordered:
                ordered.append(shaft)
        for element in elements:
            for shaft in element.shafts:
                if shaft not in ordered and shaft != HOUSING:
                    ordered.append(shaft)
        ordered = [s for s in ordered if s != HOUSING] + [HOUSING]
        if len(ordered) > MAX_SHAFTS:
            raise ModelError(f"gear train: {len(ordered)} shafts; at most {MAX_SHAFTS} are accepted.")
        object.__setattr__(self, "elements", elements)
        object.__setattr__(self, "shafts", tuple(ordered))

    # ------------------------------------------------------------------ look-ups
    def _repr_html_(self) -> str:
        """Jupyter: the elements and shafts of the train (:mod:`epicyclic.model.html`)."""
        from .html import train_html

        return train_html(self)

    def element(self, name: str) -> Element:
        """The element called ``name``."""
        for element in self.elements:
            if element.name == name:
                return element
        names = [e.name for e in self.elements]
        close = closest(name, names)
        raise ModelError(
            f"gear train: no element named {name!r:.70}; elements are {', '.join(repr(n) for n in names)}."
            + (f" Did you mean {close!r}?" if close else "")
        )

    def check_shaft(self, name: str, where: str = "operating point") -> str:
        """Return ``name`` if the train has that shaft, else raise UnknownShaftError.

        Parameters
        ----------
        name : str
            A shaft name (the housing is ``"housing"``).
        where : str, default "operating point"
            What named the shaft, the prefix of the message (e.g. ``"plot --shaft"``).

        Returns
        -------
        str
            ``name``.

        Raises
        ------
        UnknownShaftError
            The train has no such shaft; the message lists its shafts and the likely
            misspelt one.

        Examples
        --------
        >>> from epicyclic.demo import brandenberger_1952
        >>> train = brandenberger_1952()[0]
        >>> train.check_shaft("III")
        'III'
        """
        if name not in self.shafts:
            raise UnknownShaftError(name, self.shafts, where)
        return name

    @property
    def planetary_sets(self) -> tuple[PlanetarySet, ...]:
        return tuple(e for e in self.elements if isinstance(e, PlanetarySet))

    @property
    def gear_stages(self) -> tuple[GearStage, ...]:
        return tuple(e for e in self.elements if isinstance(e, GearStage))

    @property
    def shift_elements(self) -> tuple[ShiftElement, ...]:
        """Clutches and brakes, engaged or not."""
        return tuple(e for e in self.elements if isinstance(e, (Clutch, Brake)))

    @property
    def moving_shafts(self) -> tuple[str, ...]:
        """All shafts but the housing."""
        return self.shafts[:-1]

    # ------------------------------------------------------------------ shift states
    def with_engaged(self, engaged: Iterable[str] | Mapping[str, bool]) -> GearTrain:
        """A copy with exactly the named clutches and brakes engaged (all others open).

        ``engaged`` may also be a mapping name → bool that changes only the
        elements it names.
        """
        from dataclasses import replace

        shift_names = {e.name for e in self.shift_elements}
        if isinstance(engaged, Mapping):
            wanted = {name: bool(v) for name, v in engaged.items()}
        else:
            names = list(engaged)
            wanted = {name: (name in names) for name in shift_names}
            for name in names:
                wanted.setdefault(name, True)
        for name in wanted:
            if name not in shift_names:
                raise ModelError(
                    f"shift state: {name!r} is not a clutch or brake of this train; shift elements are "
                    f"{', '.join(sorted(shift_names)) or 'none'}."
                )
        elements = tuple(
            replace(e, engaged=wanted[e.name]) if e.name in wanted else e for e in self.elements
        )
        return GearTrain(elements, self.shafts, self.name)
