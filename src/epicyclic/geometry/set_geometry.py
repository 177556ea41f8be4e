"""Geometry of a planetary set: its gears and meshes from tooth counts and a basic rack.

A :class:`~epicyclic.model.PlanetarySet` keeps only tooth counts (its
:class:`~epicyclic.model.Teeth`); :class:`SetGeometry` adds module, pressure
angle, helix angle, tooth-height factors and profile shifts and derives every
gear (:class:`~epicyclic.geometry.gear.GearGeometry`) and mesh
(:class:`~epicyclic.geometry.gear.MeshGeometry`) of the set.

Meshes by kind of set (``Teeth.kind``):

* ``simple``: sun–planet (external), planet–ring (internal);
* ``double``: sun–planet1, planet1–planet2 (external), planet2–ring (internal);
* ``stepped``: sun–planet_sun, planet_ring–ring; each central gear is
  external or internal (``Teeth.sun_internal``, ``Teeth.ring_internal``:
  sun + ring, two suns, or two rings as in the Wolfrom set).  The ring mesh
  may have its own module (``ring_module``), as stepped planets often do.
  A set with two suns or two rings names its gears as its file does
  (:func:`gear_label`): first–planet_first, planet_second–second.

References
----------
Queitsch, Formelzeichen (m, r_0, r_b, r_g, a, a_0, α_0, α_b); ISO 21771:2007.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field, replace
from types import MappingProxyType
from typing import Any

from ..model.planetary import PlanetarySet, Teeth
from ..model.teeth import TWO_CENTRAL_NAMES
from ._render import html_table, text_table
from .errors import GeometryError
from .contact import mesh_data, micrometres
from .tolerances import parse_center_distance_tolerance
from .gear import SHIFT_CONVENTIONS, BasicRack, GearGeometry, MeshGeometry, iso_profile_shift

__all__ = ["SetGeometry", "planet_names", "gear_label", "TWO_CENTRAL_NAMES"]


def gear_label(teeth: Teeth, name: str) -> str:
    """A gear's (or port's) name as a user of this arrangement says it, the names of the file's ``teeth`` table.

    A set with two rings or two suns calls its central gears ``first`` and ``second`` and
    its planet gears ``planet_first`` and ``planet_second``; every other set keeps
    ``sun``, ``ring``, ``planet``, ... .  Mesh names, fitting messages and force tables
    use these labels (:meth:`~epicyclic.model.Teeth.label`).

    >>> gear_label(Teeth("stepped", 81, 78, (27, 24), sun_internal=True), "sun")
    'first'
    >>> gear_label(Teeth("simple", 30, 78, (24,)), "sun")
    'sun'
    """
    return teeth.label(name)


def planet_names(teeth: Teeth) -> tuple[str, ...]:
    """Names of the planet gears of a set: ``planet`` / ``planet1, planet2`` / ``planet_sun, planet_ring``."""
    if teeth.kind == "simple":
        return ("planet",)
    if teeth.kind == "double":
        return ("planet1", "planet2")
    return ("planet_sun", "planet_ring")


@dataclass(frozen=True)
class SetGeometry:
    """Gear geometry of one planetary set.

    Parameters
    ----------
    planetary_set : PlanetarySet
        A set built from tooth counts (``planetary_set.teeth`` is not None).
    rack : BasicRack
        Module (normal module), pressure angle, helix angle, addendum and
        dedendum factors.
    x_sun, x_ring : float, default 0
        Profile-shift coefficients of the central gears, in the sign of
        ``internal_shift_convention`` for an internal gear (ISO 21771: a negative x
        of a ring enlarges its tip circle).
    x_planet : float or sequence of float, default 0
        Profile shift of the planet gear(s), one per planet gear of the kind
        (a single number is used for all).
    ring_module : float, optional
        Normal module of the ring mesh of a stepped set (default: ``rack.module``).
    tip_shortening : bool or mapping gear → float, default True
        Shorten the tips of external pairs by k m_n (ISO 21771) to keep the
        standard tip clearance at the shifted centre distance; or the tip-shortening
        coefficient k of each gear as built (missing gears 0).
    face_width : float or mapping gear → float, optional
        Face width b in mm, one for all gears or one per gear name (``sun``,
        ``planet``, ``ring``, ...); a mesh's width is the smaller of its two
        gears'.  Needed for mesh losses (load per face width).
    load_sharing : float or str, optional
        Load-sharing factor K_γ ≥ 1 for the design forces, or a mounting
        (``"floating_sun"``, ``"flexible_pins"``, ``"abs"``) for the tabulated value
        (:func:`~epicyclic.geometry.load_sharing.tabulated_load_sharing`); default by number
        of planets, :func:`~epicyclic.geometry.load_sharing.default_load_sharing`.
    internal_shift_convention : {"iso", "khk"}, default "iso"
        The sign in which an internal gear's profile shift is given: ``"iso"``
        (ISO 21771, DIN 3960, KISSsoft, REXS) or ``"khk"`` (KHK / SDP-SI handbooks,
        x_KHK = −x_ISO).  :attr:`gears` always hold the ISO value; reports state it.
    center_distance_tolerance : float or str, optional
        The housing's centre-distance allowance for the coaxiality check: ± mm, or an
        ISO 286 js field such as ``"js7"`` (DIN 3964).  Default: the effect of the
        shifts' printed digits (:func:`~epicyclic.geometry.coaxiality.coaxiality_tolerance`).
    center_distance : float, optional
        The carrier's centre distance as built, mm (simple and stepped sets): both meshes
        run at it (α_wt from it) and get the backlash their shifts and allowances leave
        (:attr:`MeshGeometry.backlash`; < 0 is a jam, an error of :func:`check_fitting`).
    thickness_allowance : float or mapping gear → float, optional
        Tooth-thickness allowance A_sn ≤ 0 of every gear (one number) or per gear, mm.

    References
    ----------
    ISO 21771:2007; lecad "Analysis of Planetary Transmissions" test run
    (profile-shifted simple set 21/43/108, m = 1.75: a = 56.8 mm).

    Examples
    --------
    >>> from epicyclic import PlanetarySet
    >>> p = PlanetarySet.simple("P", sun="s", ring="r", carrier="c", z_sun=21, z_planet=43, z_ring=108)
    >>> g = SetGeometry.create(p, module=1.75, x_sun=0.438, x_planet=0.0426)
    >>> [round(m.center_distance, 2) for m in g.meshes]
    [56.8, 56.8]
    >>> round(g.gears["sun"].tip_diameter, 3)
    41.701
    """

    planetary_set: PlanetarySet
    rack: BasicRack
    x_sun: float = 0.0
    x_ring: float = 0.0
    x_planet: tuple[float, ...] | float = 0.0
    ring_module: float | None = None
    tip_shortening: bool = True
    face_width: float | Mapping[str, float] | None = None
    load_sharing: float | None = None
    internal_shift_convention: str = "iso"
    center_distance_tolerance: float | str | None = None
    center_distance: float | None = None
    thickness_allowance: float | Mapping[str, float] | None = None
    gears: Mapping[str, GearGeometry] = field(init=False, repr=False, compare=False)
    meshes: tuple[MeshGeometry, ...] = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        pset = self.planetary_set
        if not isinstance(pset, PlanetarySet):
            raise GeometryError(f"SetGeometry: planetary_set must be a PlanetarySet, got {type(pset).__name__}.")
        owner = f"SetGeometry of {pset.name!r}"
        if pset.teeth is None:
            raise GeometryError(
                f"{owner}: the set has no tooth counts (it was built from a ratio). "
                "Build it with PlanetarySet.simple / .double_planet / .stepped."
            )
        if not isinstance(self.rack, BasicRack):
            raise GeometryError(f"{owner}: rack must be a BasicRack, got {type(self.rack).__name__}.")
        teeth = pset.teeth
        names = planet_names(teeth)
        xp = self.x_planet
        if isinstance(xp, (int, float)) and not isinstance(xp, bool):
            xp = (float(xp),) * len(names)
        else:
            xp = tuple(xp)  # type: ignore[arg-type]
            if len(xp) != len(names):
                raise GeometryError(
                    f"{owner}: x_planet needs {len(names)} value(s) for a {teeth.kind} set "
                    f"({', '.join(names)}), got {len(xp)}."
                )
        object.__setattr__(self, "x_planet", xp)
        ring_rack = self.rack
        if self.ring_module is not None:
            if teeth.kind != "stepped":
                raise GeometryError(
                    f"{owner}: ring_module applies to stepped sets only; a {teeth.kind} set has one module."
                )
            ring_rack = self.rack.with_module(self.ring_module)

        planet_racks = [self.rack] * len(names)
        if teeth.kind == "stepped":
            planet_racks[1] = ring_rack
        convention = self.internal_shift_convention
        iso_profile_shift(0.0, False, convention)  # raises on an unknown convention

        def central(x, internal: bool) -> float:
            if isinstance(x, bool) or not isinstance(x, (int, float)):
                return x  # GearGeometry names the bad value
            return iso_profile_shift(x, internal, convention)

        all_names = ("sun", *names, "ring")
        allowance = _per_gear(self.thickness_allowance, all_names, "thickness_allowance", owner, 0.0)
        gears: dict[str, GearGeometry] = {
            "sun": GearGeometry(teeth.sun, self.rack, central(self.x_sun, teeth.sun_internal),
                                internal=teeth.sun_internal, thickness_allowance=allowance["sun"])}
        for name, z, x, rk in zip(names, teeth.planet, xp, planet_racks):
            gears[name] = GearGeometry(z, rk, x, thickness_allowance=allowance[name])
        gears["ring"] = GearGeometry(teeth.ring, ring_rack, central(self.x_ring, teeth.ring_internal),
                                     internal=teeth.ring_internal, thickness_allowance=allowance["ring"])

        a_given = self.center_distance
        if a_given is not None and teeth.kind == "double":
            raise GeometryError(f"{owner}: center_distance applies to simple and stepped sets (one carrier radius); "
                                "a double-planet set has three centre distances.")
        pairs = _mesh_pairs(teeth.kind, names)
        meshes = [_mesh(gears, a, b, teeth, a_given) for a, b in pairs]
        if isinstance(self.tip_shortening, Mapping):
            k_given = _per_gear(dict(self.tip_shortening), all_names, "tip_shortening", owner, 0.0)
            gears = {n: replace(g, tip_shortening=k_given[n]) for n, g in gears.items()}
            meshes = [_mesh(gears, a, b, teeth, a_given) for a, b in pairs]
        elif self.tip_shortening:
            k: dict[str, float] = {}
            for (a, b), mesh in zip(pairs, meshes):
                for g in (a, b):
                    k[g] = max(k.get(g, 0.0), mesh.tip_shortening)
            gears = {n: replace(g, tip_shortening=k.get(n, 0.0)) if not g.internal else g for n, g in gears.items()}
            meshes = [_mesh(gears, a, b, teeth, a_given) for a, b in pairs]
        object.__setattr__(self, "gears", MappingProxyType(gears))
        object.__setattr__(self, "meshes", tuple(meshes))
        object.__setattr__(self, "face_width", _face_widths(self.face_width, tuple(gears), owner))
        if self.center_distance_tolerance is not None:
            try:
                object.__setattr__(self, "center_distance_tolerance",
                                   parse_center_distance_tolerance(self.center_distance_tolerance))
            except GeometryError as exc:
                raise GeometryError(f"{owner}: {exc}") from None
        k_gamma = self.load_sharing
        if isinstance(k_gamma, str):
            from .load_sharing import MOUNTINGS

            if k_gamma not in MOUNTINGS:
                raise GeometryError(f"{owner}: load_sharing must be a number >= 1 or one of "
                                    f"{', '.join(map(repr, MOUNTINGS))} (tabulated K_gamma), got {k_gamma!r}.")
        elif k_gamma is not None and (isinstance(k_gamma, bool) or not isinstance(k_gamma, (int, float))
                                    or not math.isfinite(k_gamma) or k_gamma < 1.0):
            raise GeometryError(f"{owner}: load_sharing (K_gamma) must be a number >= 1, got {k_gamma!r}.")

    # ------------------------------------------------------------------ constructors
    @classmethod
    def create(
        cls,
        planetary_set: PlanetarySet,
        module: float,
        *,
        pressure_angle: float = 20.0,
        helix_angle: float = 0.0,
        addendum: float = 1.0,
        dedendum: float = 1.25,
        x_sun: float = 0.0,
        x_planet: float | Sequence[float] = 0.0,
        x_ring: float = 0.0,
        ring_module: float | None = None,
        tip_shortening: bool = True,
        face_width: float | Mapping[str, float] | None = None,
        load_sharing: float | None = None,
        internal_shift_convention: str = "iso",
        center_distance_tolerance: float | str | None = None,
        center_distance: float | None = None,
        thickness_allowance: float | Mapping[str, float] | None = None,
    ) -> SetGeometry:
        """Build the geometry from plain numbers (module and face width in mm, angles in degrees).

        Parameters
        ----------
        planetary_set : PlanetarySet
            A set made from tooth counts.
        module : float
            Normal module m_n, mm (0.001 … 100).
        pressure_angle, helix_angle : float
            α_n in (0, 45) and β in [0, 45) degrees of the basic rack (ISO 53: 20, spur: 0).
        addendum, dedendum : float
            h_a* and h_f* of the basic rack (1.0 and 1.25).
        x_sun, x_planet, x_ring : float
            Profile-shift coefficients; ``x_planet`` one value per planet gear (a
            double or stepped set has two).
        ring_module : float, optional
            Stepped sets: module of the second mesh, mm.
        tip_shortening : bool or mapping gear → float, default True
            Shorten the tips of external pairs to keep the tip clearance, or k per gear.
        face_width : float or mapping gear → float, optional
            Face width b, mm (needed for mesh losses).
        load_sharing : float, optional
            K_γ ≥ 1 for the design forces (default by number of planets).
        internal_shift_convention : {"iso", "khk"}, default "iso"
            Sign of an internal gear's profile shift as given (ISO 21771 or KHK).
        center_distance_tolerance : float or str, optional
            ± mm or a js field (``"js7"``) for the coaxiality check.
        center_distance : float, optional
            The carrier's centre distance as built, mm (both meshes run at it).
        thickness_allowance : float or mapping gear → float, optional
            A_sn ≤ 0 per gear, mm.

        Returns
        -------
        SetGeometry

        Raises
        ------
        GeometryError
            A value out of range, a set without tooth counts, profile shifts that do not fit.

        References
        ----------
        ISO 21771:2007 (cylindrical gear geometry); ISO 53 (basic rack).

        Examples
        --------
        >>> from epicyclic import PlanetarySet
        >>> p = PlanetarySet.simple("P", sun="s", ring="r", carrier="c", z_sun=39, z_planet=49, z_ring=137)
        >>> SetGeometry.create(p, module=2.0)
        SetGeometry(simple 'P', m_n=2.0, sun-planet a_w=88.000, planet-ring a_w=88.000)
        """
        rack = BasicRack(module, pressure_angle, helix_angle, addendum, dedendum)
        return cls(planetary_set, rack, x_sun, x_ring, x_planet, ring_module, tip_shortening,  # type: ignore[arg-type]
                   face_width, load_sharing, internal_shift_convention, center_distance_tolerance,
                   center_distance, thickness_allowance)

    # ------------------------------------------------------------------ properties
    @property
    def kind(self) -> str:
        """``simple``, ``double`` or ``stepped``."""
        return self.planetary_set.teeth.kind  # type: ignore[union-attr]

    @property
    def planet_gear_names(self) -> tuple[str, ...]:
        return planet_names(self.planetary_set.teeth)  # type: ignore[arg-type]

    def mesh(self, name: str) -> MeshGeometry:
        """The mesh called ``name`` (e.g. ``"sun-planet"``, ``"first-planet_first"`` for two rings)."""
        for m in self.meshes:
            if m.name == name:
                return m
        raise GeometryError(
            f"SetGeometry: no mesh {name!r}; the set has {', '.join(repr(m.name) for m in self.meshes)}."
        )

    @property
    def sun_mesh(self) -> MeshGeometry:
        """The mesh of the sun with its planet gear."""
        return self.meshes[0]

    @property
    def ring_mesh(self) -> MeshGeometry:
        """The mesh of the second central gear (ring) with its planet gear."""
        return self.meshes[-1]

    def mesh_face_width(self, mesh: MeshGeometry | str) -> float:
        """Face width of a mesh, mm: the smaller of its two gears' widths.

        Raises
        ------
        GeometryError
            No face width was given.
        """
        name = mesh if isinstance(mesh, str) else mesh.name
        widths = self.face_width
        if widths is None:
            raise GeometryError(
                f"SetGeometry of {self.planetary_set.name!r}: no face width is given; mesh losses need the load "
                "per face width: give face_width (mm)."
            )
        a, b = self.mesh_gears(name)
        return min(widths[a], widths[b])  # type: ignore[index]

    def mesh_gears(self, mesh: MeshGeometry | str) -> tuple[str, str]:
        """The keys of :attr:`gears` (``sun``, ``planet_sun``, ...) of a mesh's two gears, in its name's order.

        Mesh names use :meth:`gear_label` (``first-planet_first`` for a set with two rings);
        this gives the gears behind them.
        """
        name = mesh if isinstance(mesh, str) else mesh.name
        for pair, m in zip(_mesh_pairs(self.kind, self.planet_gear_names), self.meshes):
            if m.name == name:
                return pair
        self.mesh(name)  # raises the error naming the meshes
        raise AssertionError(name)  # pragma: no cover

    @property
    def carrier_radius(self) -> float:
        """Radius of the planet (first planet gear) axes on the carrier = sun-mesh centre distance, mm."""
        return self.sun_mesh.center_distance

    @property
    def outer_planet_radius(self) -> float:
        """Radius of the axes of the planet gears meshing the ring (= carrier radius unless double), mm."""
        return self.ring_mesh.center_distance

    def to_dict(self) -> dict[str, Any]:
        """Plain data (mm, degrees)."""
        return {
            "set": self.planetary_set.name,
            "kind": self.kind,
            "rack": {
                "module": self.rack.module,
                "pressure_angle": self.rack.pressure_angle,
                "helix_angle": self.rack.helix_angle,
                "addendum": self.rack.addendum,
                "dedendum": self.rack.dedendum,
                "ring_module": self.ring_module,
            },
            "internal_shift_convention": self.internal_shift_convention,
            "profile_shift_sign": SHIFT_CONVENTIONS["iso"] + " (gears' profile_shift; the input was "
                                  + self.internal_shift_convention.upper() + ")",
            "gears": {n: g.to_dict() for n, g in self.gears.items()},
            "meshes": [mesh_data(m, b) for m, b in zip(self.meshes, self.mesh_face_widths())],
        }

    def gear_label(self, name: str) -> str:
        """The gear's name as a user of this arrangement says it: ``first``/``second`` for two suns or rings."""
        return gear_label(self.planetary_set.teeth, name)  # type: ignore[arg-type]

    def _rows(self) -> tuple[list[str], list[list[object]]]:
        headers = ["gear", "z", "x", "d [mm]", "d_b [mm]", "d_a [mm]", "d_f [mm]"]
        rows = [
            [self.gear_label(n) + (" (internal)" if g.internal else ""), g.teeth, g.profile_shift, g.reference_diameter,
             g.base_diameter, g.tip_diameter, g.root_diameter]
            for n, g in self.gears.items()
        ]
        return headers, rows

    def mesh_face_widths(self) -> tuple[float | None, ...]:
        """The face width of each mesh (mm), None for all without face widths."""
        if self.face_width is None:
            return (None,) * len(self.meshes)
        return tuple(self.mesh_face_width(m) for m in self.meshes)

    def _mesh_rows(self) -> tuple[list[str], list[list[object]]]:
        from .contact import overlap_ratio

        headers = ["mesh", "a [mm]", "a_w [mm]", "alpha_wt [deg]", "beta_w [deg]", "d_w1 [mm]", "d_w2 [mm]",
                   "eps_alpha", "eps_beta", "eps_gamma", "j_bn [um]"]
        rows = []
        for m, b in zip(self.meshes, self.mesh_face_widths()):
            eps_b = overlap_ratio(m, b) if b is not None else (0.0 if m.rack.helix_angle == 0 else None)
            rows.append([m.name, m.reference_center_distance, m.center_distance, m.operating_pressure_angle,
                         m.operating_helix_angle, *m.operating_pitch_diameters, m.contact_ratio,
                         "-" if eps_b is None else eps_b, "-" if eps_b is None else m.contact_ratio + eps_b,
                         micrometres(m.backlash)])
        return headers, rows

    @property
    def shift_convention_note(self) -> str:
        """One line on the sign of the internal gears' profile shifts in the tables (ISO 21771) and as given."""
        given = "" if self.internal_shift_convention == "iso" else " (given as KHK, x_ISO = -x_KHK)"
        return f"x: ISO 21771 sign, an internal gear's x < 0 enlarges its tip circle{given}"

    def table(self) -> str:
        """Gears and meshes as a text table (mm, degrees)."""
        title = (
            f"{self.planetary_set.teeth.arrangement} set {self.planetary_set.name!r}: m_n = {self.rack.module} mm, "
            f"alpha_n = {self.rack.pressure_angle} deg, beta = {self.rack.helix_angle} deg; "
            f"{self.shift_convention_note}"
        )
        return text_table(*self._rows(), title=title) + "\n\n" + text_table(*self._mesh_rows())

    def _repr_html_(self) -> str:
        return html_table(*self._rows(), title=f"set {self.planetary_set.name} ({self.shift_convention_note})") \
            + html_table(*self._mesh_rows())

    def __repr__(self) -> str:
        centres = ", ".join(f"{m.name} a_w={m.center_distance:.3f}" for m in self.meshes)
        return f"SetGeometry({self.kind} {self.planetary_set.name!r}, m_n={self.rack.module}, {centres})"


def _face_widths(value, names: tuple[str, ...], owner: str) -> Mapping[str, float] | None:
    """Face width per gear name (mm) from one number or a mapping; None stays None."""
    if value is None:
        return None
    if isinstance(value, Mapping):
        unknown = [k for k in value if k not in names]
        missing = [n for n in names if n not in value]
        if unknown or missing:
            raise GeometryError(
                f"{owner}: face_width needs one value per gear {', '.join(names)}"
                + (f"; unknown {', '.join(map(repr, unknown))}" if unknown else "")
                + (f"; missing {', '.join(missing)}" if missing else "") + "."
            )
        widths = dict(value)
    else:
        widths = {n: value for n in names}
    for n, b in widths.items():
        if isinstance(b, bool) or not isinstance(b, (int, float)) or not math.isfinite(b) or b <= 0:
            raise GeometryError(f"{owner}: face_width of {n} must be a positive number of mm, got {b!r}.")
    return MappingProxyType({n: float(b) for n, b in widths.items()})


def _mesh(gears: Mapping[str, GearGeometry], a: str, b: str, teeth: Teeth,
          center_distance: float | None = None) -> MeshGeometry:
    """The mesh of gears ``a`` and ``b``, named ``"a-b"`` by their labels, with the internal gear (if any) second."""
    first, second = (gears[b], gears[a]) if gears[a].internal else (gears[a], gears[b])
    return MeshGeometry(first, second, f"{gear_label(teeth, a)}-{gear_label(teeth, b)}", center_distance)


def _per_gear(value, names: tuple[str, ...], key: str, owner: str, default: float) -> dict[str, float]:
    """One number for every gear, or a mapping gear → number (missing gears ``default``); None → ``default``."""
    if value is None:
        return {n: default for n in names}
    if isinstance(value, Mapping):
        unknown = [k for k in value if k not in names]
        if unknown:
            raise GeometryError(f"{owner}: {key} names unknown gear {unknown[0]!r}; the gears are {', '.join(names)}.")
        return {n: value.get(n, default) for n in names}
    return {n: value for n in names}


def _mesh_pairs(kind: str, names: tuple[str, ...]) -> list[tuple[str, str]]:
    if kind == "simple":
        return [("sun", names[0]), (names[0], "ring")]
    if kind == "double":
        return [("sun", names[0]), (names[0], names[1]), (names[1], "ring")]
    return [("sun", names[0]), (names[1], "ring")]



