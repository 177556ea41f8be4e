"""The manufacturing data sheet of a set's or stage's gears: test dimensions with allowances, and the backlash.

Per gear: the tooth-thickness allowances (upper A_sne = the gear's
``thickness_allowance``, lower A_sni = A_sne − T_sn with the tolerance T_sn given),
the span measurement W_k over k teeth (external gears), the dimension over or between
balls M_d, the chordal tooth thickness at the reference circle and the constant chord,
each nominal and at both allowances (:mod:`epicyclic.geometry.measurement`).  Per mesh:
the normal backlash j_bn, nominal and its least and largest value over the thickness
allowances of both gears and the centre-distance allowance ±A_a (the set's
``center_distance_tolerance``, DIN 3964), each computed exactly from the shifts
(:attr:`~epicyclic.geometry.gear.MeshGeometry.backlash`), and the circumferential
backlash j_wt = j_bn / (cos α_wt cos β_b).  With an accuracy grade, each gear's flank
tolerances of ISO 1328-1:2013 or :1995 (:mod:`epicyclic.geometry.accuracy`, at its d, m_n and
face width).

References
----------
ISO 21771:2007, clause 5 and eqs. (62), (63) (backlash); DIN 3960:1987; DIN 3967:1978
(tooth-thickness allowances and backlash); DIN 3964:1980 (centre-distance allowances);
ISO 1328-1:1995 and ISO 1328-1:2013 (flank tolerances).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, replace
from typing import Any

from ._render import html_table, text_table
from .accuracy import FlankTolerances, flank_tolerances
from .errors import GeometryError
from .gear import GearGeometry, MeshGeometry
from .measurement import (ChordalThickness, PinMeasurement, SpanMeasurement, chordal_measurement, nominal_thickness,
                          pin_measurement, span_measurement)

__all__ = ["GearDataSheet", "MeshBacklash", "DataSheet", "data_sheet", "mesh_backlash"]


@dataclass(frozen=True)
class GearDataSheet:
    """The test dimensions of one gear (mm).

    Attributes
    ----------
    name : str
    gear : GearGeometry
    lower_allowance : float
        A_sni, mm (= A_sne when no tolerance was given).
    span : SpanMeasurement or None
        None for an internal gear.
    pins : PinMeasurement
    chordal : ChordalThickness
    tolerance_given : bool
        Whether T_sn was given (without it the limits equal the upper allowance).
    accuracy : FlankTolerances or None
        The ISO 1328-1 flank tolerances at the grade asked for (None: no grade, or no face width).
    """

    name: str
    gear: GearGeometry
    lower_allowance: float
    span: SpanMeasurement | None
    pins: PinMeasurement
    chordal: ChordalThickness
    tolerance_given: bool
    accuracy: FlankTolerances | None = None

    def to_dict(self) -> dict[str, Any]:
        """Plain data, mm."""
        g = self.gear
        span = None if self.span is None else {
            "teeth_spanned": self.span.teeth_spanned, "nominal": self.span.nominal, "upper": self.span.upper,
            "lower": self.span.lower, "measuring_diameter": self.span.measuring_diameter}
        p, c = self.pins, self.chordal
        return {
            "name": self.name, "teeth": g.teeth, "internal": g.internal, "module": g.rack.module,
            "profile_shift": g.profile_shift, "thickness": {
                "nominal": nominal_thickness(g), "upper_allowance": g.thickness_allowance,
                "lower_allowance": self.lower_allowance, "tolerance_given": self.tolerance_given},
            "span": span,
            "pins": {"pin_diameter": p.pin_diameter, "nominal": p.nominal, "upper": p.upper, "lower": p.lower,
                     "contact_diameter": p.contact_diameter, "teeth_even": p.even,
                     "measured": "between balls" if p.internal else "over balls"},
            "chordal": {"nominal": c.nominal, "upper": c.upper, "lower": c.lower, "height": c.height,
                        "constant_chord": c.constant_chord, "constant_chord_height": c.constant_chord_height},
            "accuracy": None if self.accuracy is None else self.accuracy.to_dict(),
        }


@dataclass(frozen=True)
class MeshBacklash:
    """Normal backlash of a pair, mm: nominal (upper allowances, centre distance as built) and its range."""

    name: str
    nominal: float
    least: float
    largest: float
    center_distance: float
    center_distance_allowance: float
    circumferential_factor: float

    @property
    def circumferential(self) -> tuple[float, float]:
        """(least, largest) circumferential backlash j_wt = j_bn / (cos α_wt cos β_b), mm."""
        return self.least * self.circumferential_factor, self.largest * self.circumferential_factor

    def to_dict(self) -> dict[str, Any]:
        """Plain data, mm."""
        lo, hi = self.circumferential
        return {"name": self.name, "normal_backlash": self.nominal, "normal_backlash_least": self.least,
                "normal_backlash_largest": self.largest, "circumferential_backlash_least": lo,
                "circumferential_backlash_largest": hi, "center_distance": self.center_distance,
                "center_distance_allowance": self.center_distance_allowance}


def mesh_backlash(mesh: MeshGeometry, lower1: float, lower2: float, allowance: float = 0.0) -> MeshBacklash:
    """Least and largest normal backlash of a pair over its thickness and centre-distance allowances.

    Parameters
    ----------
    mesh : MeshGeometry
        Built with the upper allowances (the gears' ``thickness_allowance``) at its centre distance.
    lower1, lower2 : float
        Lower thickness allowances A_sni of gear 1 and gear 2, mm.
    allowance : float, default 0
        Centre-distance allowance ±A_a, mm (≥ 0).

    Returns
    -------
    MeshBacklash

    Examples
    --------
    Two gears 60 µm thinner each at the backlash-free distance: j_bn = 2 · 0.06 cos 20° (spur):

    >>> from epicyclic.geometry.gear import BasicRack
    >>> r = BasicRack(2.0)
    >>> m = MeshGeometry(GearGeometry(20, r, thickness_allowance=-0.06), GearGeometry(40, r, thickness_allowance=-0.06),
    ...                  working_center_distance=60.0)
    >>> round(mesh_backlash(m, -0.1, -0.1).nominal / math.cos(r.alpha_n), 6)
    0.12

    References
    ----------
    ISO 21771:2007, eqs. (62), (63); DIN 3967:1978 (backlash from the thickness and centre-distance
    allowances).
    """
    if not (isinstance(allowance, (int, float)) and math.isfinite(allowance) and allowance >= 0):
        raise GeometryError(f"backlash: the centre-distance allowance must be a number of mm >= 0, got {allowance!r}.")
    a = mesh.center_distance
    values = []
    for a_w in (a - allowance, a + allowance):
        for low in (False, True):
            g1 = replace(mesh.gear1, thickness_allowance=lower1) if low else mesh.gear1
            g2 = replace(mesh.gear2, thickness_allowance=lower2) if low else mesh.gear2
            values.append(MeshGeometry(g1, g2, mesh.name, working_center_distance=a_w).backlash)
    rack = mesh.rack
    cos_bb = math.sqrt(1.0 - (math.sin(rack.beta) * math.cos(rack.alpha_n)) ** 2)
    factor = 1.0 / (math.cos(mesh.alpha_wt) * cos_bb)
    return MeshBacklash(mesh.name, mesh.backlash, min(values), max(values), a, float(allowance), factor)


@dataclass(frozen=True)
class DataSheet:
    """The manufacturing data sheet of one element (gears and meshes), mm; renders itself."""

    element: str
    gears: tuple[GearDataSheet, ...]
    meshes: tuple[MeshBacklash, ...]
    accuracy_note: str = ""

    _GEAR_HEAD = ["gear", "z", "A_sne [um]", "A_sni [um]", "k", "W_k [mm]", "W_k max", "W_k min", "D_M [mm]",
                  "M_d [mm]", "M_d max", "M_d min", "s_n chord [mm]", "h_a chord [mm]"]
    _MESH_HEAD = ["mesh", "a_w [mm]", "+-A_a [mm]", "j_bn [um]", "j_bn min [um]", "j_bn max [um]",
                  "j_wt min [um]", "j_wt max [um]"]

    def _gear_rows(self) -> list[list[object]]:
        rows = []
        for s in self.gears:
            span = [s.span.teeth_spanned, s.span.nominal, s.span.upper, s.span.lower] if s.span else ["-"] * 4
            rows.append([s.name, s.gear.teeth, round(s.gear.thickness_allowance * 1000, 1),
                         round(s.lower_allowance * 1000, 1), *span, s.pins.pin_diameter, s.pins.nominal,
                         max(s.pins.upper, s.pins.lower), min(s.pins.upper, s.pins.lower), s.chordal.nominal,
                         s.chordal.height])
        return rows

    def _mesh_rows(self) -> list[list[object]]:
        def um(value: float) -> float:
            return round(value * 1000, 1) + 0.0  # no "-0.0"

        return [[m.name, m.center_distance, m.center_distance_allowance, um(m.nominal), um(m.least), um(m.largest),
                 *(um(v) for v in m.circumferential)] for m in self.meshes]

    _ACCURACY_SYMBOLS = ("f_pt", "F_p", "F_alpha", "f_falpha", "f_Halpha", "F_beta", "f_fbeta", "f_Hbeta", "F_r")

    def _accuracy_rows(self) -> list[list[object]]:
        return [[s.name, s.accuracy.standard, s.accuracy.grade, *(f"{getattr(s.accuracy, k):g}"
                                                              for k in self._ACCURACY_SYMBOLS)]
                for s in self.gears if s.accuracy is not None]

    @property
    def _accuracy_head(self) -> list[str]:
        return ["gear", "standard", "grade", *(f"{k} [um]" for k in self._ACCURACY_SYMBOLS)]

    def _notes(self) -> list[str]:
        notes = ["W_k/M_d max belong to the upper allowance A_sne, min to the lower A_sni (internal gear: M_d "
                 "between balls, a thinner tooth reads larger); chordal thickness at the reference circle."]
        if self.accuracy_note:
            notes.append(self.accuracy_note)
        missing = [s.name for s in self.gears if not s.tolerance_given]
        if missing:
            notes.append(f"no tooth-thickness tolerance T_sn given for {', '.join(missing)}: the limits equal the "
                         "upper allowance (give thickness_tolerance).")
        return notes

    def table(self) -> str:
        """Plain-text tables: gears, then meshes."""
        parts = [text_table(self._GEAR_HEAD, self._gear_rows(), title=f"data sheet of {self.element!r}: gears")]
        if self.meshes:
            parts.append(text_table(self._MESH_HEAD, self._mesh_rows(), title="backlash"))
        if self._accuracy_rows():
            parts.append(text_table(self._accuracy_head, self._accuracy_rows(), title="flank tolerances"))
        return "\n\n".join(parts + self._notes())

    def markdown(self) -> str:
        """Markdown tables."""
        def md(head, rows):
            from ._render import _cell
            return "\n".join(["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
                             + ["| " + " | ".join(_cell(v) for v in row) + " |" for row in rows])
        out = [f"### Data sheet of {self.element}", "", md(self._GEAR_HEAD, self._gear_rows())]
        if self.meshes:
            out += ["", md(self._MESH_HEAD, self._mesh_rows())]
        if self._accuracy_rows():
            out += ["", md(self._accuracy_head, self._accuracy_rows())]
        return "\n".join(out + [""] + [f"* {n}" for n in self._notes()]) + "\n"

    def _repr_html_(self) -> str:
        import html

        out = html_table(self._GEAR_HEAD, self._gear_rows(), title=f"data sheet of {self.element}")
        if self.meshes:
            out += html_table(self._MESH_HEAD, self._mesh_rows(), title="backlash")
        if self._accuracy_rows():
            out += html_table(self._accuracy_head, self._accuracy_rows(), title="flank tolerances")
        return out + "".join(f"<p>{html.escape(n)}</p>" for n in self._notes())

    def to_dict(self) -> dict[str, Any]:
        """Plain data, mm."""
        return {"element": self.element, "gears": [g.to_dict() for g in self.gears],
                "meshes": [m.to_dict() for m in self.meshes], "notes": self._notes()}

    def __repr__(self) -> str:
        return f"DataSheet({self.element!r}, {len(self.gears)} gear(s), {len(self.meshes)} mesh(es))"


def _per_gear(value, names, key: str) -> dict[str, float | None]:
    if value is None or isinstance(value, (int, float)) and not isinstance(value, bool):
        return dict.fromkeys(names, value)
    if not isinstance(value, Mapping):
        raise GeometryError(f"data sheet: {key} must be a number of mm or a mapping gear → mm, got {value!r}.")
    unknown = sorted(set(value) - set(names))
    if unknown:
        raise GeometryError(f"data sheet: {key}: no gear {unknown[0]!r}; gears are {', '.join(names)}.")
    return {n: value.get(n) for n in names}


def _face_widths(geometry) -> dict[int, float]:
    """Face width by ``id`` of the gear object, mm (sets: per gear; stages: the mesh's, the larger for an idler)."""
    from .set_geometry import SetGeometry

    out: dict[int, float] = {}
    if isinstance(geometry, SetGeometry):
        if geometry.face_width is not None:
            out = {id(g): geometry.face_width[n] for n, g in geometry.gears.items()}  # type: ignore[index]
        return out
    for mesh, b in zip(geometry.meshes, geometry.mesh_face_widths()):
        if b is not None:
            for g in (mesh.gear1, mesh.gear2):
                out[id(g)] = max(b, out.get(id(g), 0.0))
    return out


def _gears_of(geometry) -> tuple[dict[str, GearGeometry], list[tuple[MeshGeometry, str, str]], float]:
    from .set_geometry import SetGeometry
    from .tolerances import center_distance_allowance

    if isinstance(geometry, SetGeometry):
        gears = {geometry.gear_label(n): g for n, g in geometry.gears.items()}
        label = {n: geometry.gear_label(n) for n in geometry.gears}
        meshes = []
        for mesh in geometry.meshes:
            a, b = geometry.mesh_gears(mesh)
            meshes.append((mesh, label[a], label[b]))
        tol = geometry.center_distance_tolerance
        allowance = 0.0
        if isinstance(tol, str):
            allowance = center_distance_allowance(tol, geometry.meshes[0].center_distance)
        elif tol is not None:
            allowance = float(tol)
        return gears, meshes, allowance
    gears, meshes = {}, []
    for i, mesh in enumerate(geometry.meshes, 1):
        name = mesh.name or f"mesh {i}"
        names = []
        for j, g in ((1, mesh.gear1), (2, mesh.gear2)):
            same = next((n for n, h in gears.items() if h is g), None)  # an idler is one gear in two meshes
            names.append(same or f"{name}:{j}")
            gears.setdefault(names[-1], g)
        meshes.append((mesh, names[0], names[1]))
    return gears, meshes, 0.0


def data_sheet(geometry, element: str = "", *, thickness_tolerance: float | Mapping[str, float] | None = None,
               pin_diameter: float | Mapping[str, float] | None = None, accuracy_grade: int | None = None,
               accuracy_edition: str = "2013") -> DataSheet:
    """The data sheet of a :class:`SetGeometry` or :class:`StageGeometry`.

    Parameters
    ----------
    geometry : SetGeometry or StageGeometry
    element : str, optional
        The name shown (default the set's or stage's).
    thickness_tolerance : float or mapping gear → float, optional
        Tooth-thickness tolerance T_sn ≥ 0 per gear (or one for all), mm: A_sni = A_sne − T_sn.
    pin_diameter : float or mapping gear → float, optional
        Ball diameter D_M per gear, mm (default the standard ball,
        :func:`~epicyclic.geometry.measurement.standard_pin_diameter`).
    accuracy_grade : int, optional
        ISO 1328-1 accuracy grade (1995: 0 … 12) or flank tolerance class (2013: 1 … 11) of every
        gear: its flank tolerances are listed (a gear without face width is named in a note).
    accuracy_edition : {"2013", "1995"}, default "2013"

    Returns
    -------
    DataSheet

    Raises
    ------
    GeometryError
        A negative tolerance, an unknown gear name, a ball that does not rest on the flanks.

    References
    ----------
    ISO 21771:2007, clause 5; DIN 3960:1987; DIN 3967:1978.
    """
    gears, meshes, allowance = _gears_of(geometry)
    names = tuple(gears)
    tolerances = _per_gear(thickness_tolerance, names, "thickness_tolerance")
    pins = _per_gear(pin_diameter, names, "pin_diameter")
    widths = _face_widths(geometry)
    sheets, lower, no_width = [], {}, []
    for name, gear in gears.items():
        t = tolerances[name]
        if t is not None and not (math.isfinite(t) and t >= 0):
            raise GeometryError(f"data sheet: thickness_tolerance of {name!r} must be a number of mm >= 0 "
                                f"(T_sn = A_sne - A_sni), got {t!r}.")
        low = gear.thickness_allowance - (t or 0.0)
        lower[name] = low
        accuracy = None
        if accuracy_grade is not None:
            if id(gear) in widths:
                accuracy = flank_tolerances(accuracy_grade, gear.reference_diameter, gear.rack.module,
                                            widths[id(gear)], accuracy_edition)
            else:
                no_width.append(name)
        try:
            span = None if gear.internal else span_measurement(gear, low)
            sheets.append(GearDataSheet(name, gear, low, span, pin_measurement(gear, pins[name], low),
                                        chordal_measurement(gear, low), t is not None, accuracy))
        except GeometryError as exc:
            raise GeometryError(f"data sheet, gear {name!r}: {exc}") from None
    backlash = tuple(mesh_backlash(m, lower[a], lower[b], allowance) for m, a, b in meshes)
    if not element:
        element = getattr(getattr(geometry, "planetary_set", None), "name", None) or geometry.stage.name
    note = (f"no flank tolerances for {', '.join(no_width)}: ISO 1328-1 needs the face width (give face_width)."
            if no_width else "")
    return DataSheet(element, tuple(sheets), backlash, note)
