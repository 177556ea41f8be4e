"""Geometry of a fixed-axis gear stage: one :class:`MeshGeometry` per mesh of its chain.

A :class:`~epicyclic.model.GearStage` built from tooth counts keeps its meshes
``(z_driving, z_driven, "external" | "internal")`` from the first shaft to the
second; :class:`StageGeometry` adds the basic rack (one for all meshes or one per
mesh), profile shifts and face widths.  In an internal mesh the larger gear is
the internal one.

References
----------
ISO 21771:2007 (cylindrical gears); Brandenberger 1952, eq. 5 (a chain of meshes).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field, replace
from typing import Any

from ..model.elements import GearStage
from ._render import html_table, text_table
from .errors import GeometryError
from .gear import BasicRack, GearGeometry, MeshGeometry, iso_profile_shift
from .contact import mesh_data, micrometres

__all__ = ["StageGeometry"]


def _with_gear(mesh: MeshGeometry, gear: GearGeometry, tip: float) -> MeshGeometry:
    """``mesh`` with ``gear`` (its gear1 or gear2) given the tip shortening ``tip``."""
    which = "gear1" if mesh.gear1 is gear else "gear2"
    return replace(mesh, **{which: replace(gear, tip_shortening=tip)})


def _per_mesh(value, count: int, name: str, owner: str) -> tuple:
    if isinstance(value, (list, tuple)):
        if len(value) != count:
            raise GeometryError(f"{owner}: {name} needs {count} value(s), one per mesh, got {len(value)}.")
        return tuple(value)
    return (value,) * count


@dataclass(frozen=True)
class StageGeometry:
    """Gear geometry of one fixed-axis stage.

    Parameters
    ----------
    stage : GearStage
        A stage built from tooth counts (``stage.meshes`` not empty).
    rack : BasicRack or sequence of BasicRack
        One basic rack for all meshes, or one per mesh.
    profile_shifts : sequence of (float, float), optional
        (x_driving, x_driven) per mesh (default 0).
    face_width : float or sequence of float, optional
        Face width of each mesh, mm (one for all, or one per mesh).
    tip_shortening : bool or sequence of (float, float), default True
        Shorten the tips of external pairs by their k = Σx − y (ISO 21771), or the coefficients
        (k_driving, k_driven) per mesh as built (k m_n off each gear's tip).
    tip_diameter : sequence of (float or None, float or None), optional
        The tip diameters (d_a driving, d_a driven) per mesh as built, mm (an internal gear's the
        inner one; None keeps the gear's from ``tip_shortening``): they replace the tip shortening
        of those gears, k = (d_a,nominal − d_a)/(2 m_n) (internal: d_a − d_a,nominal).
    internal_shift_convention : {"iso", "khk"}, default "iso"
        Sign of an internal gear's profile shift as given (ISO 21771 or KHK, x_KHK = −x_ISO);
        the meshes hold ISO values.
    idlers : sequence of int, optional
        Mesh numbers k (1-based) whose driven gear is the next mesh's driving gear: one
        idler gear meshing twice.  It keeps one geometry in both meshes (same teeth, same
        profile shift, the larger tip shortening of the two).
    center_distance : float or sequence of float, optional
        Centre distance of each mesh as built, mm (one for all, or one per mesh; None
        entries keep the backlash-free one).

    Examples
    --------
    Brandenberger's fixed stage 40/44 · 20/64 with module 2:

    >>> from epicyclic import GearStage
    >>> stage = GearStage.from_teeth("V", "III", "II", [(40, 44, "external"), (20, 64, "external")])
    >>> g = StageGeometry(stage, BasicRack(2.0), face_width=20.0)
    >>> [round(m.center_distance, 3) for m in g.meshes]
    [84.0, 84.0]
    """

    stage: GearStage
    rack: BasicRack | Sequence[BasicRack]
    profile_shifts: Sequence[tuple[float, float]] = ()
    face_width: float | Sequence[float] | None = None
    tip_shortening: bool | Sequence[tuple[float, float]] = True
    internal_shift_convention: str = "iso"
    idlers: Sequence[int] = ()
    center_distance: float | Sequence[float | None] | None = None
    tip_diameter: Sequence[tuple[float | None, float | None]] | None = None
    meshes: tuple[MeshGeometry, ...] = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        stage = self.stage
        if not isinstance(stage, GearStage):
            raise GeometryError(f"StageGeometry: stage must be a GearStage, got {type(stage).__name__}.")
        owner = f"StageGeometry of {stage.name!r}"
        if not stage.meshes:
            raise GeometryError(
                f"{owner}: the stage has no tooth counts (it was built from a ratio); build it with "
                "GearStage.from_teeth (in a file: 'meshes' instead of 'ratio')."
            )
        count = len(stage.meshes)
        iso_profile_shift(0.0, False, self.internal_shift_convention)  # raises on an unknown convention
        racks = _per_mesh(self.rack, count, "rack", owner)
        if not all(isinstance(r, BasicRack) for r in racks):
            raise GeometryError(f"{owner}: rack must be a BasicRack or one per mesh.")
        shifts = tuple(self.profile_shifts) or ((0.0, 0.0),) * count
        if len(shifts) != count or not all(isinstance(x, (tuple, list)) and len(x) == 2 for x in shifts):
            raise GeometryError(
                f"{owner}: profile_shifts needs one pair (x_driving, x_driven) per mesh ({count}), got {shifts!r}."
            )
        widths = None
        if self.face_width is not None:
            widths = _per_mesh(self.face_width, count, "face_width", owner)
            for b in widths:
                if isinstance(b, bool) or not isinstance(b, (int, float)) or not math.isfinite(b) or b <= 0:
                    raise GeometryError(f"{owner}: face_width must be a positive number of mm, got {b!r}.")
            widths = tuple(float(b) for b in widths)
        idlers = self._idlers(stage, shifts, owner)
        centers = _per_mesh(self.center_distance, count, "center_distance", owner)
        meshes = []
        for k, ((z1, z2, kind), rack, (x1, x2)) in enumerate(zip(stage.meshes, racks, shifts)):
            name = f"mesh {k + 1} ({z1}/{z2})"
            if kind == "internal":
                small, large = ((z1, x1), (z2, x2)) if z1 < z2 else ((z2, x2), (z1, x1))
                x_large = large[1]
                if isinstance(x_large, (int, float)) and not isinstance(x_large, bool):
                    x_large = iso_profile_shift(x_large, True, self.internal_shift_convention)
                mesh = MeshGeometry(GearGeometry(small[0], rack, small[1]),
                                    GearGeometry(large[0], rack, x_large, internal=True), name, centers[k])
            else:
                mesh = MeshGeometry(GearGeometry(z1, rack, x1), GearGeometry(z2, rack, x2), name, centers[k])
                if self.tip_shortening is True:
                    mesh = mesh.with_tip_shortening()
            meshes.append(mesh)
        given = self._given_tips(meshes, owner)
        for k in idlers:  # one idler gear: the larger tip shortening of its two meshes on both
            first, second = meshes[k - 1], meshes[k]
            driven = first.gear2 if self.driving_is_gear1(k - 1) else first.gear1
            driving = second.gear1 if self.driving_is_gear1(k) else second.gear2
            if (k - 1, 1) in given and (k, 0) in given and driven.tip_shortening != driving.tip_shortening:
                raise GeometryError(f"{owner}: the idler of meshes {k} and {k + 1} is one gear with one tip, but its "
                                    f"given tips differ (k = {driven.tip_shortening:g} and "
                                    f"{driving.tip_shortening:g}); give the same tip in both meshes.")
            tip = max(driven.tip_shortening, driving.tip_shortening)
            meshes[k - 1] = _with_gear(first, driven, tip)
            meshes[k] = _with_gear(second, driving, tip)
        object.__setattr__(self, "rack", racks if isinstance(self.rack, (list, tuple)) else self.rack)
        object.__setattr__(self, "profile_shifts", tuple(tuple(float(v) for v in x) for x in shifts))
        object.__setattr__(self, "face_width", widths)
        object.__setattr__(self, "meshes", tuple(meshes))
        object.__setattr__(self, "idlers", idlers)
        if not isinstance(self.tip_shortening, bool):
            object.__setattr__(self, "tip_shortening", tuple(tuple(float(v) for v in p) for p in self.tip_shortening))
        if self.tip_diameter is not None:
            object.__setattr__(self, "tip_diameter", tuple(tuple(p) for p in self.tip_diameter))

    def _given_tips(self, meshes: list[MeshGeometry], owner: str) -> set[tuple[int, int]]:
        """Apply the given tip shortening and tip diameters per gear in place; the (mesh, 0 driving / 1 driven) set."""
        count = len(meshes)
        tips = () if isinstance(self.tip_shortening, bool) else tuple(self.tip_shortening)
        diameters = () if self.tip_diameter is None else tuple(self.tip_diameter)
        for name, values in (("tip_shortening", tips), ("tip_diameter", diameters)):
            if values and (len(values) != count or not all(isinstance(v, (tuple, list)) and len(v) == 2
                                                           for v in values)):
                raise GeometryError(f"{owner}: {name} needs one pair (driving, driven) per mesh ({count}), "
                                    f"got {values!r}.")
        given: set[tuple[int, int]] = set()
        for k, mesh in enumerate(meshes):
            order = (0, 1) if self.driving_is_gear1(k) else (1, 0)  # gear1/gear2 → driving/driven
            for gear_index, side in enumerate(order):
                gear = mesh.gear1 if gear_index == 0 else mesh.gear2
                k_tip = tips[k][side] if tips else None
                d_a = diameters[k][side] if diameters else None
                if d_a is not None:
                    if isinstance(d_a, bool) or not isinstance(d_a, (int, float)) or not d_a > 0:
                        raise GeometryError(f"{owner}: tip_diameter of mesh {k + 1} must be positive numbers of mm "
                                            f"or None, got {d_a!r}.")
                    nominal = replace(gear, tip_shortening=0.0).tip_diameter
                    step = (d_a - nominal) if gear.internal else (nominal - d_a)
                    k_tip = step / (2.0 * gear.rack.module)
                    if not -1e-9 <= k_tip <= 3.0:
                        raise GeometryError(f"{owner}: tip_diameter {d_a:g} mm of mesh {k + 1} "
                                            f"({'driving' if side == 0 else 'driven'}) lies beyond the uncut tip "
                                            f"{nominal:.3f} mm (or more than 3 m_n inside); give a tip within.")
                    k_tip = max(k_tip, 0.0)
                if k_tip is not None:
                    mesh = _with_gear(mesh, gear, k_tip)
                    given.add((k, side))
            meshes[k] = mesh
        return given

    def _idlers(self, stage: GearStage, shifts, owner: str) -> tuple[int, ...]:
        """The checked idler mesh numbers (1-based): same teeth and the same profile shift in both meshes."""
        out = []
        for k in self.idlers:
            if isinstance(k, bool) or not isinstance(k, int) or not 1 <= k < len(stage.meshes):
                raise GeometryError(f"{owner}: idlers holds mesh numbers 1 … {len(stage.meshes) - 1} (the driven "
                                    f"gear of mesh k drives mesh k + 1), got {k!r}.")
            z_driven, z_next = stage.meshes[k - 1][1], stage.meshes[k][0]
            if z_driven != z_next:
                raise GeometryError(f"{owner}: an idler is one gear, but mesh {k}'s driven gear has {z_driven} teeth "
                                    f"and mesh {k + 1}'s driving gear {z_next}.")
            x_driven, x_next = shifts[k - 1][1], shifts[k][0]
            if x_driven != x_next:
                raise GeometryError(f"{owner}: the idler of meshes {k} and {k + 1} is one gear with one profile "
                                    f"shift, got {x_driven!r} and {x_next!r}; give the same x in both meshes.")
            out.append(k)
        return tuple(sorted(set(out)))

    def mesh_face_width(self, index: int) -> float:
        """Face width of mesh ``index`` (0-based), mm."""
        if self.face_width is None:
            raise GeometryError(
                f"StageGeometry of {self.stage.name!r}: no face width is given; mesh losses need the load "
                "per face width: give face_width (mm)."
            )
        return self.face_width[index]  # type: ignore[index]

    def driving_is_gear1(self, index: int) -> bool:
        """Whether gear 1 of mesh ``index`` is its driving gear (the one on the side of the first shaft)."""
        z1, z2, kind = self.stage.meshes[index]
        return kind != "internal" or z1 < z2

    def to_dict(self) -> dict[str, Any]:
        """Plain data (mm, degrees)."""
        return {"stage": self.stage.name, "face_width": None if self.face_width is None else list(self.face_width),
                "internal_shift_convention": self.internal_shift_convention, "idlers": list(self.idlers),
                "meshes": [mesh_data(m, b) for m, b in zip(self.meshes, self.mesh_face_widths())]}

    def mesh_face_widths(self) -> tuple[float | None, ...]:
        """The face width of each mesh (mm), None for all without face widths."""
        return tuple(self.face_width) if self.face_width is not None else (None,) * len(self.meshes)

    def _rows(self) -> list[list[object]]:
        from .contact import overlap_ratio

        rows = []
        for m, b in zip(self.meshes, self.mesh_face_widths()):
            eps_b = overlap_ratio(m, b) if b is not None else (0.0 if m.rack.helix_angle == 0 else None)
            rows.append([m.name, m.gear1.teeth, m.gear2.teeth, m.rack.module, m.center_distance,
                         m.operating_pressure_angle, m.operating_helix_angle, m.contact_ratio,
                         "-" if eps_b is None else eps_b, "-" if eps_b is None else m.contact_ratio + eps_b,
                         micrometres(m.backlash)])
        return rows

    _HEAD = ["mesh", "z1", "z2", "m_n [mm]", "a_w [mm]", "alpha_wt [deg]", "beta_w [deg]", "eps_alpha", "eps_beta",
             "eps_gamma", "j_bn [um]"]

    def table(self) -> str:
        """The stage's meshes as a plain-text table: tooth counts, m_n, a_w, α_wt, ε_α.

        Lengths in mm, angles in degrees.

        Returns
        -------
        str
        """
        given = "" if self.internal_shift_convention == "iso" else " (given as KHK, x_ISO = -x_KHK)"
        return text_table(self._HEAD, self._rows(), title=f"stage {self.stage.name!r} (profile shift: ISO 21771 "
                                                          f"sign{given})")

    def _repr_html_(self) -> str:
        return html_table(self._HEAD, self._rows(), title=f"stage {self.stage.name}")

    def __repr__(self) -> str:
        return f"StageGeometry({self.stage.name!r}, {len(self.meshes)} mesh(es))"
