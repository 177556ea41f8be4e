"""Fixed-axis gear stages, clutches and brakes.

A fixed-axis stage is a planetary set whose carrier is the housing
(Queitsch, Bild 3): the solver treats both with one rule.  A clutch joins two
shafts when engaged; a brake joins a shaft to the housing.

References
----------
Queitsch, Bild 3 (the stationary gear train as a set with the
carrier held).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from ..errors import ModelError, ToothCountError, TopologyError
from ..limits import MAX_MESHES, MIN_TEETH
from .planetary import check_efficiency, check_name, check_teeth, finite_float

__all__ = ["GearStage", "Clutch", "Brake", "HOUSING", "Mesh"]

#: The name of the frame; its speed is zero.
HOUSING = "housing"

#: One mesh of a fixed-axis stage: (z_driving, z_driven, kind) with kind
#: "external" (reverses direction) or "internal" (keeps it).
Mesh = tuple[int, int, str]


@dataclass(frozen=True)
class GearStage:
    """A fixed-axis gear stage between two shafts.

    Parameters
    ----------
    name : str
        Element name.
    first, second : str
        The two shafts; the ratio is n_first / n_second.
    ratio : float
        Signed speed ratio n_first/n_second (negative for one external mesh).
    efficiency : float, default 1.0
        Efficiency of the stage in (0, 1]; applied in the direction in which
        power actually flows.
    meshes : tuple of Mesh, optional
        The tooth counts the ratio came from.

    References
    ----------
    Brandenberger 1952, eqs. 5 and 9.

    Examples
    --------
    >>> stage = GearStage.from_teeth("V", "II", "III", [(40, 44, "external"), (20, 64, "external")])
    >>> round(1 / stage.ratio, 4)  # n_II = n_III (40/44)(20/64), Brandenberger eq. 5
    0.2841
    """

    name: str
    first: str
    second: str
    ratio: float
    efficiency: float = 1.0
    meshes: tuple[Mesh, ...] = ()

    def __post_init__(self) -> None:
        owner = f"gear stage {self.name!r}"
        check_name(self.name, "name", "gear stage")
        check_name(self.first, "first", owner)
        check_name(self.second, "second", owner)
        if self.first == self.second:
            raise ModelError(f"{owner}: first and second must be different shafts, got {self.first!r} twice.")
        if HOUSING in (self.first, self.second):
            raise TopologyError(
                f"{owner}: a gear stage cannot join the housing (its gears turn on axes fixed in the "
                "housing already); use a Brake to hold a shaft."
            )
        r = self.ratio
        if finite_float(r) is None or r == 0:
            raise ModelError(f"{owner}: ratio must be a finite, non-zero number n_first/n_second, got {r!r}.")
        object.__setattr__(self, "ratio", float(r))
        object.__setattr__(self, "efficiency", check_efficiency(self.efficiency, "efficiency", owner))

    @classmethod
    def from_teeth(
        cls,
        name: str,
        first: str,
        second: str,
        meshes: Sequence[Mesh],
        efficiency: float = 1.0,
    ) -> GearStage:
        """A stage (or chain of meshes) from tooth counts.

        n_second = n_first · Π (∓ z_driving/z_driven): an external mesh reverses the
        direction of rotation, an internal one keeps it; the stage's ``ratio`` is
        n_first/n_second.

        Parameters
        ----------
        name : str
            Element name (unique in the train).
        first, second : str
            The shafts at the two ends of the chain (not the housing).
        meshes : sequence of tuple
            ``(z_driving, z_driven)`` or ``(z_driving, z_driven, "external" | "internal")``
            for each mesh, in order from ``first`` to ``second`` (default external);
            tooth counts are whole numbers ≥ 3; at most 32 meshes.
        efficiency : float, default 1.0
            Efficiency of the whole stage in (0, 1], applied in the direction power flows.

        Returns
        -------
        GearStage

        Raises
        ------
        ToothCountError
            No mesh, too many meshes, a mesh that is not two or three items, or a
            tooth count that is not a whole number in range.
        ModelError
            A mesh kind other than ``"external"``/``"internal"``, or ``first`` equal to ``second``.
        TopologyError
            ``first`` or ``second`` is the housing (hold a shaft with a Brake).
        EfficiencyError
            ``efficiency`` outside (0, 1].

        References
        ----------
        Brandenberger 1952, eq. 5: n2 = n3 (e/f)(g/h) for the fixed-axis stage of Bild 10.

        Examples
        --------
        >>> stage = GearStage.from_teeth("V", "II", "III", [(40, 44), (20, 64)], efficiency=0.9)
        >>> round(stage.ratio, 4), stage.meshes[0]
        (3.52, (40, 44, 'external'))
        """
        owner = f"gear stage {name!r}"
        if not meshes:
            raise ToothCountError(f"{owner}: give at least one mesh (z_driving, z_driven, kind).")
        if len(meshes) > MAX_MESHES:
            raise ToothCountError(f"{owner}: {len(meshes)} meshes given; at most {MAX_MESHES} are accepted.")
        speed_ratio = 1.0  # n_second / n_first
        checked = []
        for k, mesh in enumerate(meshes):
            if len(mesh) == 2:
                mesh = (*mesh, "external")
            if len(mesh) != 3:
                raise ToothCountError(f"{owner}: mesh {k} must be (z_driving, z_driven, kind), got {mesh!r}.")
            z1, z2, kind = mesh
            for label, z in (("z_driving", z1), ("z_driven", z2)):
                if isinstance(z, bool) or not isinstance(z, int) or z < MIN_TEETH:
                    raise ToothCountError(f"{owner}: mesh {k} {label} must be a whole number of at least {MIN_TEETH} "
                                          f"teeth, got {z!r:.40}.")
                check_teeth(z, f"mesh {k} {label}", owner)
            if kind not in ("external", "internal"):
                raise ModelError(f"{owner}: mesh {k} kind must be 'external' or 'internal', got {kind!r:.40}.")
            sign = -1.0 if kind == "external" else 1.0
            speed_ratio *= sign * z1 / z2
            checked.append((z1, z2, kind))
        return cls(name, first, second, 1.0 / speed_ratio, efficiency, tuple(checked))

    @property
    def shafts(self) -> tuple[str, str]:
        """The joined shafts (first, second)."""
        return (self.first, self.second)


@dataclass(frozen=True)
class Clutch:
    """A clutch that joins two shafts when engaged (ideal: no slip, no drag).

    Parameters
    ----------
    name : str
    first, second : str
        The shafts it joins.
    engaged : bool, default True
    """

    name: str
    first: str
    second: str
    engaged: bool = True

    def __post_init__(self) -> None:
        owner = f"clutch {self.name!r}"
        check_name(self.name, "name", "clutch")
        check_name(self.first, "first", owner)
        check_name(self.second, "second", owner)
        if self.first == self.second:
            raise ModelError(f"{owner}: a clutch joins two different shafts, got {self.first!r} twice.")
        if HOUSING in (self.first, self.second):
            raise TopologyError(
                f"{owner}: a clutch to the housing is a brake; use Brake({self.name!r}, "
                f"{(self.second if self.first == HOUSING else self.first)!r})."
            )
        if not isinstance(self.engaged, bool):
            raise ModelError(f"{owner}: engaged must be True or False, got {self.engaged!r}.")

    @property
    def shafts(self) -> tuple[str, str]:
        return (self.first, self.second)


@dataclass(frozen=True)
class Brake:
    """A brake that holds a shaft against the housing when engaged.

    Parameters
    ----------
    name : str
    shaft : str
        The shaft it holds; must not be the housing.
    engaged : bool, default True
    """

    name: str
    shaft: str
    engaged: bool = True

    def __post_init__(self) -> None:
        owner = f"brake {self.name!r}"
        check_name(self.name, "name", "brake")
        check_name(self.shaft, "shaft", owner)
        if self.shaft == HOUSING:
            raise TopologyError(
                f"{owner}: a brake on the housing holds nothing; give the shaft it holds "
                "(e.g. shaft='ring')."
            )
        if not isinstance(self.engaged, bool):
            raise ModelError(f"{owner}: engaged must be True or False, got {self.engaged!r}.")

    @property
    def first(self) -> str:
        return self.shaft

    @property
    def second(self) -> str:
        return HOUSING

    @property
    def shafts(self) -> tuple[str, str]:
        return (self.shaft, HOUSING)
