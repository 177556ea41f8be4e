"""Speed plans: the Kutzbach diagram and Brandenberger's speed diagram of a set.

Kutzbach diagram (Queitsch, Bild 5, "Geschwindigkeitsplan"): for a planetary
set, every member's peripheral speed ``v = ω·r`` is drawn over the radius.  A
member turning about the central axis is a straight line through the origin;
a planet is a straight line through its mesh points and, at its axis, through
the carrier's line — the endpoints of the velocity vectors lie on one line
(Queitsch, eq. 7: ``v51 − v41 = v21 − v51``).

Radii are the *operating* pitch radii of each mesh.  A set with a geometry
table (:class:`~epicyclic.geometry.SetGeometry`: module, profile shifts, a
stepped planet's second module) is drawn at its own; otherwise they come
from the tooth counts (unit module 1 mm unless given): with centre distance ``a`` of a planet
axis, ``r_sun = a·z_s/(z_s + z_p)``, an internal ring ``r = a·z_r/(z_r − z_p)``
and an external second central gear ``r = a·z_d/(z_d + z_c)``.  For a set
known only by ``i0`` a layout with the same ``i0`` is made up (radii relative
to the sun's): a simple set for a minus set with ``|i0| ≥ 1.5`` or
``|i0| ≤ 2/3``, a stepped planet with an internal ring otherwise, and a stepped
planet with two external central gears (Brandenberger's Bild 1) for a plus set.

Brandenberger's speed diagram of the same set (ranges 1–7) is in :mod:`.ranges`.

References
----------
Queitsch, Bild 5 and eqs. 7–12; Brandenberger 1952, eq. 1 and Bild 3–5
(text: "je vier verschiedene Bereiche 1, 3, 5, 7 … neben drei Einzelfällen
2, 4, 6"); tec-science, "Willis-Gleichung" (Geschwindigkeitsverteilung am Planetenrad).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import TYPE_CHECKING, Any

from ..model.planetary import PlanetarySet, Teeth
from ._common import RPM_TO_RAD_S, SHAFT_COLOURS, PlottingError, figure_svg, planetary_set, pyplot
from ._labels import finish
from .context import FigureContext
from .ranges import RangeDiagram, range_diagram
from .schematic import DrawnSet, drawn_set
from .values import Scales, clean, fmt, scale_of

if TYPE_CHECKING:  # pragma: no cover
    from ..results.solution import Solution

__all__ = ["PlanetBody", "SetLayout", "set_layout", "SpeedPlan", "speed_plan", "RangeDiagram",
           "range_diagram", "plot_speed_plan"]  # RangeDiagram, range_diagram: from .ranges

@dataclass(frozen=True)
class PlanetBody:
    """One planet body (gears on one planet shaft, one speed).

    Attributes
    ----------
    label : str
    axis : float
        Radius of the planet axis from the central axis (the carrier arm).
    extent : tuple of float
        Innermost and outermost radius of its gears.
    contacts : mapping port → radius
        Radius of the mesh point with the central member ``"sun"`` or ``"ring"``.
    index : int
        Which entry of ``ElementState.planet_speeds`` is this body's speed.
    """

    label: str
    axis: float
    extent: tuple[float, float]
    contacts: Mapping[str, float]
    index: int = 0


@dataclass(frozen=True)
class SetLayout:
    """Radii of a planetary set's members for the Kutzbach diagram.

    Attributes
    ----------
    radius_unit : str
        ``"mm"``: radii from tooth counts and the module.
    central : mapping port → (radius, internal)
        The two central members at their mesh radius; ``internal`` for an
        internal ring gear.
    bodies : tuple of PlanetBody
    from_teeth : bool
        The set's own tooth counts (False: a schematic set reproducing i0).
    schematic : bool
    drawn : DrawnSet
        The tooth counts drawn and which drawn gear is which port.
    note : str
        What the radii rest on, when it is the set's geometry (else empty).
    """

    set_name: str
    radius_unit: str
    central: Mapping[str, tuple[float, bool]]
    bodies: tuple[PlanetBody, ...]
    from_teeth: bool
    schematic: bool = False
    drawn: DrawnSet | None = None
    stationary_ratio: float = float("nan")
    note: str = ""


def _pitch(a: float, z: float, z_partner: float, internal: bool) -> float:
    """Operating pitch radius of gear z meshing z_partner at centre distance a."""
    return a * z / (z - z_partner) if internal else a * z / (z + z_partner)


def set_layout(pset: PlanetarySet, module: float = 1.0, geometry: Any = None) -> SetLayout:
    """The radii of ``pset`` for the speed plan (see the module text).

    A set given by i0 alone is drawn with the schematic tooth counts of
    :func:`~epicyclic.plotting.schematic.drawn_set`; where those reproduce i0
    only approximately, the second central gear's operating pitch radius is
    set so that the layout reproduces i0 exactly.

    Parameters
    ----------
    pset : PlanetarySet
    module : float, default 1.0
        Gear module in mm.
    geometry : SetGeometry, optional
        The set's gear geometry: the radii are its meshes' operating pitch radii
        (profile shifts, a stepped planet's second module), ``module`` is not used.

    Examples
    --------
    >>> from epicyclic import PlanetarySet
    >>> lay = set_layout(PlanetarySet.simple("P", sun="s", ring="r", carrier="c",
    ...                                      z_sun=30, z_planet=24, z_ring=78))
    >>> lay.central["sun"], lay.central["ring"], lay.bodies[0].axis
    ((15.0, False), (39.0, True), 27.0)
    """
    from dataclasses import replace

    if not (isinstance(module, (int, float)) and not isinstance(module, bool) and module > 0):
        raise PlottingError(f"speed plan: module must be a positive number of mm, got {module!r}.")
    drawn = drawn_set(pset)
    if geometry is not None and pset.teeth is not None and geometry.planetary_set.teeth == pset.teeth:
        return replace(_layout_from_geometry(pset.name, geometry), drawn=drawn, stationary_ratio=pset.stationary_ratio)
    layout = _layout_from_teeth(pset.name, drawn.teeth, float(module))
    layout = replace(layout, from_teeth=not drawn.schematic, schematic=drawn.schematic, drawn=drawn,
                     stationary_ratio=pset.stationary_ratio)
    if drawn.swapped:  # the set's "sun" port is the larger, internal gear of the drawing
        central = {"sun": layout.central["ring"], "ring": layout.central["sun"]}
        bodies = tuple(replace(b, contacts=MappingProxyType({drawn.roles.get(k, k): r for k, r in b.contacts.items()}))
                       for b in layout.bodies)
        layout = replace(layout, central=MappingProxyType(central), bodies=bodies)
    if drawn.schematic and len(layout.bodies) == 1:
        layout = _exact(layout, pset.stationary_ratio)
    return layout


def _exact(layout: SetLayout, i0: float) -> SetLayout:
    """Set the ring-side radius so that the layout's i0 equals ``i0`` (operating pitch radius)."""
    from dataclasses import replace

    body = layout.bodies[0]
    a, rs = body.axis, body.contacts["sun"]
    c = i0 * rs / (rs - a)  # ω_sun/ω_ring = i0 with the carrier held; rr/(rr − a) = c
    rr = c * a / (c - 1.0)
    internal = layout.central["ring"][1]
    extent = (min(body.extent[0], rr, 2 * a - rr if not internal else rr),
              max(body.extent[1], rr, 2 * a - rr if not internal else rr))
    body = replace(body, contacts=MappingProxyType({**body.contacts, "ring": rr}), extent=extent)
    return replace(layout, central=MappingProxyType({**layout.central, "ring": (rr, internal)}), bodies=(body,))


def _layout_from_teeth(name: str, teeth: Teeth, m: float) -> SetLayout:
    zs, zr, zp = teeth.sun, teeth.ring, teeth.planet
    if teeth.kind == "simple":
        a = m * (zs + zp[0]) / 2
        return _layout(name, teeth, a, a, _pitch(a, zs, zp[0], False), _pitch(a, zr, zp[0], True))
    if teeth.kind == "stepped":
        zb, zc = zp
        sun_internal = getattr(teeth, "sun_internal", False)  # the first ring of a Wolfrom set
        a = m * (zs - zb if sun_internal else zs + zb) / 2
        return _layout(name, teeth, a, a, _pitch(a, zs, zb, sun_internal), _pitch(a, zr, zc, teeth.ring_internal))
    z1, z2 = zp
    return _layout(name, teeth, m * (zs + z1) / 2, m * (zr - z2) / 2, m * zs / 2, m * zr / 2)


def _layout_from_geometry(name: str, geometry: Any) -> SetLayout:
    """The layout at the geometry's operating pitch radii and centre distances (mm)."""
    def pitch_radius(mesh: Any, gear: str) -> float:  # gear 1 of a mesh is its external gear (SetGeometry)
        a, b = geometry.mesh_gears(mesh)
        first = b if geometry.gears[a].internal else a
        return mesh.operating_pitch_diameters[0 if gear == first else 1] / 2

    teeth = geometry.planetary_set.teeth
    layout = _layout(name, teeth, geometry.carrier_radius, geometry.outer_planet_radius,
                     pitch_radius(geometry.sun_mesh, "sun"), pitch_radius(geometry.ring_mesh, "ring"))
    rack = geometry.rack
    modules = f"m_n {fmt(rack.module)} mm" + (f", ring mesh {fmt(geometry.ring_module, 4)} mm"
                                              if geometry.ring_module is not None else "")
    shifted = any(x != 0 for x in (geometry.x_sun, geometry.x_ring, *geometry.x_planet))
    note = f"the file's geometry: {modules}" + (", profile-shifted" if shifted else "")
    from dataclasses import replace

    return replace(layout, note=note)


def _layout(name: str, teeth: Teeth, a1: float, a2: float, rs: float, rr: float) -> SetLayout:
    """The layout from the planet axes' radii (a1 of the sun-side planet, a2 of the ring-side one) and the
    operating pitch radii rs, rr of the two central gears, mm."""
    sun_internal, ring_internal = getattr(teeth, "sun_internal", False), teeth.ring_internal
    central = MappingProxyType({"sun": (rs, sun_internal), "ring": (rr, ring_internal)})
    if teeth.kind == "simple":
        body = PlanetBody("planet", a1, (rs, rr), MappingProxyType({"sun": rs, "ring": rr}))
        return SetLayout(name, "mm", central, (body,), True)
    if teeth.kind == "stepped":
        a = a1
        extent = (min(rs, 2 * a - rs, 2 * a - rr, rr), max(2 * a - rs, rs, rr, 2 * a - rr))
        body = PlanetBody("stepped planet", a, extent, MappingProxyType({"sun": rs, "ring": rr}))
        return SetLayout(name, "mm", central, (body,), True)
    # double planet: planet 1 meshes the sun, planet 2 the ring; their common
    # mesh lies off the radial lines, so each body is drawn on its own radial line.
    b1 = PlanetBody("planet 1", a1, (rs, 2 * a1 - rs), MappingProxyType({"sun": rs}), 0)
    b2 = PlanetBody("planet 2", a2, (2 * a2 - rr, rr), MappingProxyType({"ring": rr}), 1)
    return SetLayout(name, "mm", central, (b1, b2), True)


@dataclass(frozen=True)
class SpeedPlan:
    """Kutzbach diagram of one planetary set at a solved operating point.

    Attributes
    ----------
    layout : SetLayout
    omegas : mapping port → rad/s
        Angular velocities of sun, ring and carrier.
    planet_omegas : tuple of float
        Absolute angular velocity of each planet body, rad/s.
    shafts : mapping port → shaft name
    velocity_unit : str
        ``"m/s"`` with radii in mm, else ``"rad/s·r_sun"``.

    References
    ----------
    Queitsch, Bild 5 and eq. 7.
    """

    layout: SetLayout
    omegas: Mapping[str, float]
    planet_omegas: tuple[float, ...]
    shafts: Mapping[str, str]
    velocity_unit: str = field(default="m/s")
    module: float = 1.0
    context: FigureContext = field(default_factory=FigureContext)
    speed_scale: float = 0.0

    def _v(self, omega: float, r: float) -> float:
        return omega * r / 1000.0 if self.layout.radius_unit == "mm" else omega * r

    def member_points(self, port: str) -> tuple[tuple[float, float], tuple[float, float]]:
        """((r, v), (r, v)) of a central member or the carrier: origin and its outer point."""
        if port == "carrier":
            r = max(b.axis for b in self.layout.bodies)
        else:
            r = self.layout.central[port][0]
        return (0.0, 0.0), (r, self._v(self.omegas[port], r))

    def planet_line(self, body: PlanetBody) -> tuple[tuple[float, float], tuple[float, float]]:
        """Endpoints (r, v) of a planet body's line over its extent.

        v(r) = ω_c·a + ω_p·(r − a): the carrier carries the axis, the planet
        turns about it at its absolute speed ω_p.
        """
        wp = self.planet_omegas[body.index]
        wc = self.omegas["carrier"]
        return tuple((r, self._v(wc, body.axis) + self._v(wp, r - body.axis)) for r in body.extent)  # type: ignore[return-value]

    def planet_points(self, body: PlanetBody) -> dict[str, tuple[float, float]]:
        """The points a planet's line must pass through, each from its own member.

        ``"carrier"`` at the axis (ω_c·a) and every mesh point with a central
        member (ω_member·r_contact): collinear with the planet's line when the
        kinematics is right.
        """
        points = {"carrier": (body.axis, self._v(self.omegas["carrier"], body.axis))}
        for port, r in body.contacts.items():
            points[port] = (r, self._v(self.omegas[port], r))
        return points

    def to_dict(self) -> dict[str, Any]:
        """Plain data: radii, speeds and the lines (units stated)."""
        return {
            "set": self.layout.set_name,
            "radius_unit": self.layout.radius_unit,
            "velocity_unit": self.velocity_unit,
            "members": {p: {"shaft": self.shafts[p], "points": self.member_points(p)} for p in self.omegas},
            "planets": [{"label": b.label, "line": self.planet_line(b), "points": self.planet_points(b)}
                        for b in self.layout.bodies],
        }

    def _repr_html_(self) -> str:
        return figure_svg(self.plot().figure)

    def __repr__(self) -> str:
        speeds = ", ".join(f"{p} {fmt(w / RPM_TO_RAD_S)}" for p, w in self.omegas.items())
        return f"<SpeedPlan {self.layout.set_name!r}: {speeds} 1/min, {len(self.layout.bodies)} planet body/ies>"

    def assumptions(self) -> str:
        """What the radii rest on: the file's geometry, the module (given or assumed) and, for a schematic set,
        its teeth."""
        if self.layout.note:
            return self.layout.note
        text = f"module {fmt(self.module)} mm" + ("" if self.module_given else " assumed")
        drawn = self.layout.drawn
        if self.layout.schematic and drawn is not None:
            t = drawn.teeth
            teeth = "/".join(str(z) for z in (t.sun, *t.planet, t.ring))
            how = "" if drawn.exact else ", nearest drawable"
            text = (f"schematic {t.kind} set {teeth} (the file gives i0 only{how}; "
                    f"radii reproduce i0 = {fmt(self.i0, 5)}), " + text)
        return text

    @property
    def module_given(self) -> bool:
        return self.module != 1.0

    @property
    def i0(self) -> float:
        """The set's stationary ratio, which the layout's radii reproduce."""
        return self.layout.stationary_ratio

    def plot(self, ax: Any = None) -> Any:
        """Draw the diagram (radius up, peripheral speed across) on ``ax``; return ax."""
        plt = pyplot()
        if ax is None:
            _, ax = plt.subplots(figsize=(6, 5))
        ctx = self.context
        colours = dict(zip(("sun", "ring", "carrier"), SHAFT_COLOURS))
        names = {"sun": "sun", "ring": "ring" if self.layout.central["ring"][1] else "2nd central", "carrier": "carrier"}
        teeth = self.layout.drawn.teeth if self.layout.drawn is not None and not self.layout.schematic else None
        if teeth is not None and teeth.arrangement in ("two rings", "two suns"):  # as the set's file names them
            names.update(sun="first", ring="second")
        top = max(self.speed_scale * RPM_TO_RAD_S, scale_of((*self.omegas.values(), *self.planet_omegas)))

        def speed(w: float) -> str:  # in the figure's unit, round-off (a held member) shown as 0
            return f"{fmt(ctx.convert(clean(w, top) / RPM_TO_RAD_S, 'speed'), 5)} {ctx.unit('speed')}"

        for port in ("sun", "ring", "carrier"):
            (r0, v0), (r1, v1) = self.member_points(port)
            ax.plot([v0, v1], [r0, r1], color=colours[port], lw=2,
                    label=f"{names[port]} ({self.shafts[port]}): {speed(self.omegas[port])}")
        for k, body in enumerate(self.layout.bodies):
            (r0, v0), (r1, v1) = self.planet_line(body)
            ax.plot([v0, v1], [r0, r1], color=SHAFT_COLOURS[3 + k], lw=3.5, alpha=0.8,
                    label=f"{body.label}: {speed(self.planet_omegas[body.index])}")
            for name, (r, v) in self.planet_points(body).items():
                ax.plot([v], [r], "o", color=colours[name], ms=7, mec="black", zorder=5)
                ax.annotate(names[name] if name != "carrier" else "axis", (v, r), textcoords="offset points",
                            xytext=(6, -4), fontsize=8)
        ax.axvline(0, color="black", lw=0.8)
        ax.axhline(0, color="black", lw=0.8)
        own = self.layout.schematic or self.layout.note  # said in the title, not beside the axis
        ax.set_ylabel("radius r in mm" if own else f"radius r in mm ({self.assumptions()})")
        ax.set_xlabel(f"peripheral speed v in {self.velocity_unit}")
        title = f"Speed plan (Kutzbach) of set {self.layout.set_name!r}"
        if own:
            title += "\n" + self.assumptions()
        ax.set_title(title, fontsize=10)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8, loc="best")
        return ax


def speed_plan(solution: Solution, element: str | None = None, *, module: float = 1.0,
               context: FigureContext | None = None) -> SpeedPlan:
    """The Kutzbach diagram of a planetary set of a solved train.

    Parameters
    ----------
    solution : Solution
    element : str, optional
        Name of the planetary set (default: the first).
    module : float, default 1.0
        Module in mm for radii from tooth counts (a set with geometry in
        ``context.geometry`` is drawn at its own operating pitch radii).
    context : FigureContext, optional
        Title, units, gear, notes and the file's geometry.

    Returns
    -------
    SpeedPlan

    Raises
    ------
    PlottingError
        No such planetary set.

    References
    ----------
    Queitsch, Bild 5 and eq. 7; tec-science, "Willis-Gleichung" (planet speed,
    n_P z_P = n_T (z_P + z_S) − n_S z_S).

    Examples
    --------
    >>> from epicyclic.demo import brandenberger_1952
    >>> from epicyclic import solve
    >>> plan = speed_plan(solve(*brandenberger_1952()))
    >>> round(plan.planet_omegas[0] / RPM_TO_RAD_S)   # stepped planet, 1/min
    10572
    """
    pset = planetary_set(solution, element)
    state = solution.elements[pset.name]
    layout = set_layout(pset, module, (context.geometry if context is not None else {}).get(pset.name))
    if layout.note:
        module = (context.geometry[pset.name].rack.module if context is not None else module)
    omegas = {p: state.speeds[p] * RPM_TO_RAD_S for p in ("sun", "ring", "carrier")}
    if state.planet_speeds:
        planet = tuple(n * RPM_TO_RAD_S for n in state.planet_speeds)
    else:  # a schematic set: the drawn planets' speeds
        assert layout.drawn is not None
        planet = tuple(n * RPM_TO_RAD_S for n in layout.drawn.planet_speeds(state.speeds))
    return SpeedPlan(layout, MappingProxyType(omegas), planet, MappingProxyType(dict(state.ports)), "m/s",
                     float(module), context or FigureContext(), Scales.of(solution).speed)


def plot_speed_plan(solution: Solution, element: str | None = None, *, module: float = 1.0,
                    context: FigureContext | None = None) -> Any:
    """Figure with the Kutzbach diagram and the range diagram of every (or one) set.

    One row per planetary set: :func:`speed_plan` on the left,
    :func:`~epicyclic.plotting.ranges.range_diagram` on the right.

    Parameters
    ----------
    solution : Solution
        A solved train.
    element : str, optional
        Name of one planetary set (default: every set).
    module : float, default 1.0
        Module in mm for radii from tooth counts (sets in ``context.geometry``
        are drawn at their own operating pitch radii).
    context : FigureContext, optional
        Title, units, gear, notes and the file's geometry.

    Returns
    -------
    matplotlib.figure.Figure

    Raises
    ------
    PlottingError
        No such planetary set, or a train without one.

    References
    ----------
    Queitsch, Bild 5 (speed plan); Brandenberger 1952, Bild 3–5 (ranges 1–7).
    """
    plt = pyplot()
    context = context or FigureContext(title=solution.train.name)
    sets = [planetary_set(solution, element)] if element is not None else list(solution.train.planetary_sets)
    if not sets:
        planetary_set(solution, None)  # raises the clear error
    fig, axes = plt.subplots(len(sets), 2, figsize=(13, 5.2 * len(sets)), squeeze=False)
    for row, pset in zip(axes, sets):
        speed_plan(solution, pset.name, module=module, context=context).plot(row[0])
        range_diagram(solution, pset.name, context=context).plot(row[1])
    fig.suptitle(context.heading(solution.train, "speeds"), fontsize=12)
    return finish(fig, [t for ax in fig.axes for t in ax.texts])
