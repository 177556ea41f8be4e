"""Speed plans: the Kutzbach diagram and Brandenberger's speed diagram of a set.

Kutzbach diagram (Queitsch, Bild 5, "Geschwindigkeitsplan"): for a planetary
set, every member's peripheral speed ``v = ω·r`` is drawn over the radius.  A
member turning about the central axis is a straight line through the origin;
a planet is a straight line through its mesh points and, at its axis, through
the carrier's line — the endpoints of the velocity vectors lie on one line
(Queitsch, eq. 7: ``v51 − v41 = v21 − v51``).

Radii come from the tooth counts with the *operating* pitch radii of each
mesh (unit module 1 mm unless given): with centre distance ``a`` of a planet
axis, ``r_sun = a·z_s/(z_s + z_p)``, an internal ring ``r = a·z_r/(z_r − z_p)``
and an external second central gear ``r = a·z_d/(z_d + z_c)``.  For a set
known only by ``i0`` a layout with the same ``i0`` is made up (radii relative
to the sun's): a simple set for a minus set with ``|i0| ≥ 1.5`` or
``|i0| ≤ 2/3``, a stepped planet with an internal ring otherwise, and a stepped
planet with two external central gears (Brandenberger's Bild 1) for a plus set.

Brandenberger's speed diagram (Bild 3 and 4): at ``x = 0`` the speeds of the
central members with the carrier held, ``n1' = n1 − n3`` and
``n2' = n2 − n3``, are marked, and parallel 45° lines drawn through ``0``,
``n1'`` and ``n2'``.  A vertical line at ``x`` cuts them at three speeds that
belong together (all shafts given the extra turn ``x``); the actual operating
point is ``x = n3``.  The three points where a line crosses zero (one shaft
stands still: cases 2, 4, 6) split the axis into the four ranges 1, 3, 5, 7,
numbered from the right.  Speeds are scaled by ±1 so that the faster central
member with the carrier held (Brandenberger's system II) turns positively.

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

from ..model.planetary import PlanetarySet
from ._common import RPM_TO_RAD_S, SHAFT_COLOURS, PlottingError, figure_svg, fmt, planetary_set, pyplot

if TYPE_CHECKING:  # pragma: no cover
    from ..results.solution import Solution

__all__ = ["PlanetBody", "SetLayout", "set_layout", "SpeedPlan", "speed_plan", "RangeDiagram",
           "range_diagram", "plot_speed_plan"]

#: |i0| between these bounds is drawn with a stepped planet when no teeth are known.
_SIMPLE_LAYOUT_BOUNDS = (2.0 / 3.0, 1.5)


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
        ``"mm"`` (from tooth counts and module) or ``"r_sun"`` (made up from i0).
    central : mapping port → (radius, internal)
        The two central members at their mesh radius; ``internal`` for an
        internal ring gear.
    bodies : tuple of PlanetBody
    from_teeth : bool
    """

    set_name: str
    radius_unit: str
    central: Mapping[str, tuple[float, bool]]
    bodies: tuple[PlanetBody, ...]
    from_teeth: bool


def _pitch(a: float, z: float, z_partner: float, internal: bool) -> float:
    """Operating pitch radius of gear z meshing z_partner at centre distance a."""
    return a * z / (z - z_partner) if internal else a * z / (z + z_partner)


def set_layout(pset: PlanetarySet, module: float = 1.0) -> SetLayout:
    """The radii of ``pset`` for the speed plan (see the module text).

    Parameters
    ----------
    pset : PlanetarySet
    module : float, default 1.0
        Gear module in mm (used only with tooth counts).

    Examples
    --------
    >>> from epicyclic import PlanetarySet
    >>> lay = set_layout(PlanetarySet.simple("P", sun="s", ring="r", carrier="c",
    ...                                      z_sun=30, z_planet=24, z_ring=78))
    >>> lay.central["sun"], lay.central["ring"], lay.bodies[0].axis
    ((15.0, False), (39.0, True), 27.0)
    """
    if not (isinstance(module, (int, float)) and not isinstance(module, bool) and module > 0):
        raise PlottingError(f"speed plan: module must be a positive number of mm, got {module!r}.")
    teeth = pset.teeth
    if teeth is None:
        return _layout_from_ratio(pset)
    m = float(module)
    zs, zr, zp = teeth.sun, teeth.ring, teeth.planet
    if teeth.kind == "simple":
        a = m * (zs + zp[0]) / 2
        rs, rr = _pitch(a, zs, zp[0], False), _pitch(a, zr, zp[0], True)
        body = PlanetBody("planet", a, (rs, rr), MappingProxyType({"sun": rs, "ring": rr}))
        return SetLayout(pset.name, "mm", MappingProxyType({"sun": (rs, False), "ring": (rr, True)}), (body,), True)
    if teeth.kind == "stepped":
        zb, zc = zp
        sun_internal = getattr(teeth, "sun_internal", False)  # the first ring of a Wolfrom set
        a = m * (zs - zb if sun_internal else zs + zb) / 2
        rs = _pitch(a, zs, zb, sun_internal)
        rd = _pitch(a, zr, zc, teeth.ring_internal)
        extent = (min(rs, 2 * a - rs, 2 * a - rd, rd), max(2 * a - rs, rs, rd, 2 * a - rd))
        body = PlanetBody("stepped planet", a, extent, MappingProxyType({"sun": rs, "ring": rd}))
        return SetLayout(pset.name, "mm", MappingProxyType({"sun": (rs, sun_internal),
                                                           "ring": (rd, teeth.ring_internal)}), (body,), True)
    # double planet: planet 1 meshes the sun, planet 2 the ring; their common
    # mesh lies off the radial lines, so each body is drawn on its own radial line.
    z1, z2 = zp
    a1, a2 = m * (zs + z1) / 2, m * (zr - z2) / 2
    rs, rr = m * zs / 2, m * zr / 2
    b1 = PlanetBody("planet 1", a1, (rs, 2 * a1 - rs), MappingProxyType({"sun": rs}), 0)
    b2 = PlanetBody("planet 2", a2, (2 * a2 - rr, rr), MappingProxyType({"ring": rr}), 1)
    return SetLayout(pset.name, "mm", MappingProxyType({"sun": (rs, False), "ring": (rr, True)}), (b1, b2), True)


def _layout_from_ratio(pset: PlanetarySet) -> SetLayout:
    i0 = pset.stationary_ratio
    k = abs(i0)
    if i0 < 0 and not (_SIMPLE_LAYOUT_BOUNDS[0] < k < _SIMPLE_LAYOUT_BOUNDS[1]):
        # simple set: i0 = -r_ring/r_sun; the larger central gear is the internal one
        a = (1.0 + k) / 2
        body = PlanetBody("planet", a, (min(1.0, k), max(1.0, k)), MappingProxyType({"sun": 1.0, "ring": k}))
        central = {"sun": (1.0, k < 1.0), "ring": (k, k > 1.0)}
    elif i0 < 0:
        # stepped planet, internal ring: |i0| = r_d·ρ_b/(ρ_c·r_a) with ρ_c = 0.8·a
        rho_b = k / 2.25
        a = 1.0 + rho_b
        rho_c = 0.8 * a
        rd = a + rho_c
        body = PlanetBody("stepped planet", a, (1.0, rd), MappingProxyType({"sun": 1.0, "ring": rd}))
        central = {"sun": (1.0, False), "ring": (rd, True)}
    else:
        # stepped planet, two external central gears (Brandenberger Bild 1): i0 = r_d/ρ_c
        a = 2.0
        rho_c = 2.0 / (1.0 + i0)
        rd = a - rho_c
        body = PlanetBody("stepped planet", a, (min(1.0, rd), max(3.0, a + rho_c)),
                          MappingProxyType({"sun": 1.0, "ring": rd}))
        central = {"sun": (1.0, False), "ring": (rd, False)}
    return SetLayout(pset.name, "r_sun", MappingProxyType(central), (body,), False)


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

    def plot(self, ax: Any = None) -> Any:
        """Draw the diagram (radius up, peripheral speed across) on ``ax``; return ax."""
        plt = pyplot()
        if ax is None:
            _, ax = plt.subplots(figsize=(6, 5))
        colours = dict(zip(("sun", "ring", "carrier"), SHAFT_COLOURS))
        names = {"sun": "sun", "ring": "ring" if self.layout.central["ring"][1] else "2nd central", "carrier": "carrier"}
        top = max(abs(w) for w in (*self.omegas.values(), *self.planet_omegas)) or 1.0

        def rpm(w: float) -> str:  # round-off (a held member) shown as 0
            return fmt(0.0 if abs(w) <= 1e-9 * top else w / RPM_TO_RAD_S, 6)

        for port in ("sun", "ring", "carrier"):
            (r0, v0), (r1, v1) = self.member_points(port)
            ax.plot([v0, v1], [r0, r1], color=colours[port], lw=2,
                    label=f"{names[port]} ({self.shafts[port]}): {rpm(self.omegas[port])} 1/min")
        for k, body in enumerate(self.layout.bodies):
            (r0, v0), (r1, v1) = self.planet_line(body)
            ax.plot([v0, v1], [r0, r1], color=SHAFT_COLOURS[3 + k], lw=3.5, alpha=0.8,
                    label=f"{body.label}: {rpm(self.planet_omegas[body.index])} 1/min")
            for name, (r, v) in self.planet_points(body).items():
                ax.plot([v], [r], "o", color=colours[name], ms=7, mec="black", zorder=5)
                ax.annotate(name if name != "carrier" else "axis", (v, r), textcoords="offset points",
                            xytext=(6, -4), fontsize=8)
        ax.axvline(0, color="black", lw=0.8)
        ax.axhline(0, color="black", lw=0.8)
        unit = "mm" if self.layout.radius_unit == "mm" else "relative to sun radius"
        ax.set_ylabel(f"radius r in {unit}")
        ax.set_xlabel(f"peripheral speed v in {self.velocity_unit}")
        ax.set_title(f"Speed plan (Kutzbach) of set {self.layout.set_name!r}")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8, loc="best")
        return ax


def speed_plan(solution: Solution, element: str | None = None, *, module: float = 1.0) -> SpeedPlan:
    """The Kutzbach diagram of a planetary set of a solved train.

    Parameters
    ----------
    solution : Solution
    element : str, optional
        Name of the planetary set (default: the first).
    module : float, default 1.0
        Module in mm for radii from tooth counts.

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
    layout = set_layout(pset, module)
    omegas = {p: state.speeds[p] * RPM_TO_RAD_S for p in ("sun", "ring", "carrier")}
    if state.planet_speeds:
        planet = tuple(n * RPM_TO_RAD_S for n in state.planet_speeds)
    else:
        # no tooth counts: the planet's speed from the made-up layout (rolling at the sun mesh)
        body = layout.bodies[0]
        rs = body.contacts["sun"]
        planet = (omegas["carrier"] + (omegas["sun"] - omegas["carrier"]) * rs / (rs - body.axis),)
    unit = "m/s" if layout.radius_unit == "mm" else "rad/s × r_sun"
    return SpeedPlan(layout, MappingProxyType(omegas), planet, MappingProxyType(dict(state.ports)), unit)


@dataclass(frozen=True)
class RangeDiagram:
    """Brandenberger's speed diagram of one set (Bild 3/4) with the operating point.

    Attributes
    ----------
    labels : tuple of str
        ("I", "II", "III") mapped to ports in ``ports``: II is the central
        member that is faster with the carrier held.
    ports : tuple of str
        Ports (sun/ring) of I and II, then "carrier".
    shafts : tuple of str
    offsets : tuple of float
        n1', n2', 0 in 1/min, after the sign scaling.
    sign : float
        +1 or −1: the factor applied to all speeds.
    x_operating : float
        sign·n3, the position of the operating point.
    zero_points : tuple of float
        x where each line crosses zero (cases 2, 4, 6 from the right).
    operating_range : int or None
        1…7 (None for a set without relative motion).

    References
    ----------
    Brandenberger 1952, eq. 1 and Bild 3–5.
    """

    set_name: str
    labels: tuple[str, str, str]
    ports: tuple[str, str, str]
    shafts: tuple[str, str, str]
    offsets: tuple[float, float, float]
    sign: float
    x_operating: float
    zero_points: tuple[float, float, float]
    operating_range: int | None

    def speeds_at(self, x: float) -> tuple[float, float, float]:
        """Scaled speeds of I, II, III at position x (the three lines)."""
        return tuple(o + x for o in self.offsets)  # type: ignore[return-value]

    def range_of(self, x: float) -> int:
        """The range number 1…7 of position x (2, 4, 6: a shaft stands still)."""
        p = self.zero_points
        tol = 1e-9 * max(1.0, *(abs(v) for v in p))
        for k, point in enumerate(p):
            if abs(x - point) <= tol:
                return 2 * k + 2
        return 1 + 2 * sum(x < point for point in p)

    def graphical_torques(self) -> tuple[float, float, float]:
        """Torque magnitudes of I, II, III read from the diagram (Bild 3), up to one factor.

        "Ein Drehmoment entspricht der Grösse nach dem Abstand der Geraden, durch
        welche die Drehzahlen der beiden anderen Systeme graphisch dargestellt
        werden": |M1| ∝ |n2' − 0|, |M2| ∝ |n1' − 0|, |M3| ∝ |n1' − n2'| (frictionless).
        """
        n1, n2, n3 = self.offsets
        return abs(n2 - n3), abs(n1 - n3), abs(n1 - n2)

    def to_dict(self) -> dict[str, Any]:
        return {"set": self.set_name, "labels": self.labels, "ports": self.ports, "shafts": self.shafts,
                "offsets": self.offsets, "sign": self.sign, "x_operating": self.x_operating,
                "zero_points": self.zero_points, "operating_range": self.operating_range}

    def _repr_html_(self) -> str:
        return figure_svg(self.plot().figure)

    def __repr__(self) -> str:
        return f"<RangeDiagram {self.set_name!r}: operating point in range {self.operating_range}>"

    def plot(self, ax: Any = None) -> Any:
        """Draw the parallel 45° lines, the ranges and the operating point."""
        plt = pyplot()
        if ax is None:
            _, ax = plt.subplots(figsize=(6, 5))
        p = self.zero_points
        span = max(abs(self.x_operating), *(abs(v) for v in p), 1.0)
        lo, hi = min(min(p), self.x_operating) - 0.35 * span, max(max(p), self.x_operating, 0.0) + 0.35 * span
        for k in range(3):
            ax.plot([lo, hi], [self.offsets[k] + lo, self.offsets[k] + hi], color=SHAFT_COLOURS[k], lw=2,
                    label=f"{self.labels[k]} = {self.ports[k]} ({self.shafts[k]})")
            ax.plot([0], [self.offsets[k]], "o", color=SHAFT_COLOURS[k], mec="black")
        edges = [hi, *p, lo]
        for k, point in enumerate(p):
            ax.axvline(point, color="grey", lw=0.8, ls=":")
            ax.annotate(str(2 * k + 2), (point, 0), textcoords="offset points", xytext=(3, 4), fontsize=9, color="grey")
        for k in range(4):
            mid = 0.5 * (edges[k] + edges[k + 1])
            ax.text(mid, 0.05, str(2 * k + 1), transform=ax.get_xaxis_transform(), ha="center", fontsize=12,
                    color="grey", weight="bold")
        # Bild 3: a torque is the distance between the lines of the other two shafts (at x = 0)
        tq = self.graphical_torques()
        total = sum(tq) or 1.0
        ax.plot([], [], " ", label="torques ∝ distance of the other two lines:\n"
                + " : ".join(f"M{lab} {t / total:.3f}" for lab, t in zip(self.labels, tq)))
        ys = self.speeds_at(self.x_operating)
        ax.plot([self.x_operating] * 2, [min(*ys, 0), max(*ys, 0)], color="black", lw=2.5,
                label=f"operating point (range {self.operating_range})")
        for k, y in enumerate(ys):
            ax.plot([self.x_operating], [y], "s", color=SHAFT_COLOURS[k], mec="black", ms=8, zorder=5)
        ax.axhline(0, color="black", lw=0.8)
        factor = "" if self.sign > 0 else " (all speeds × −1)"
        ax.set_xlabel(f"extra turn of all shafts = carrier speed n_III in 1/min{factor}")
        ax.set_ylabel(f"shaft speed n in 1/min{factor}")
        ax.set_title(f"Speed ranges 1–7 of set {self.set_name!r} (Brandenberger Bild 3/4)")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8, loc="upper left")
        return ax


def range_diagram(solution: Solution, element: str | None = None) -> RangeDiagram:
    """Brandenberger's speed diagram (ranges 1–7) of a set at the solved point.

    Parameters
    ----------
    solution : Solution
    element : str, optional
        Name of the planetary set (default: the first).

    Returns
    -------
    RangeDiagram

    References
    ----------
    Brandenberger 1952, eq. 1 and Bild 3–5.

    Examples
    --------
    >>> from epicyclic.demo import brandenberger_1952
    >>> from epicyclic import solve
    >>> range_diagram(solve(*brandenberger_1952())).operating_range  # Brandenberger: "Bereich 7"
    7
    """
    pset = planetary_set(solution, element)
    state = solution.elements[pset.name]
    n = state.speeds
    rel = {"sun": n["sun"] - n["carrier"], "ring": n["ring"] - n["carrier"]}
    i0 = pset.stationary_ratio
    if max(abs(v) for v in rel.values()) <= 1e-12 * max(1.0, *(abs(v) for v in n.values())):
        rel = {"sun": 1000.0 * i0, "ring": 1000.0}  # locked set: only the shape of the diagram
        locked = True
    else:
        locked = False
    first, second = ("sun", "ring") if abs(rel["ring"]) >= abs(rel["sun"]) else ("ring", "sun")
    sign = 1.0 if rel[second] > 0 else -1.0
    offsets = (sign * rel[first], sign * rel[second], 0.0)
    zero = tuple(sorted((-o for o in offsets), reverse=True))
    x_op = sign * n["carrier"]
    ports = (first, second, "carrier")
    diagram = RangeDiagram(pset.name, ("I", "II", "III"), ports, tuple(state.ports[p] for p in ports),  # type: ignore[arg-type]
                           offsets, sign, x_op, zero, None)  # type: ignore[arg-type]
    if locked:
        return diagram
    from dataclasses import replace

    return replace(diagram, operating_range=diagram.range_of(x_op))


def plot_speed_plan(solution: Solution, element: str | None = None, *, module: float = 1.0) -> Any:
    """Figure with the Kutzbach diagram and the range diagram of every (or one) set."""
    plt = pyplot()
    sets = [planetary_set(solution, element)] if element is not None else list(solution.train.planetary_sets)
    if not sets:
        planetary_set(solution, None)  # raises the clear error
    fig, axes = plt.subplots(len(sets), 2, figsize=(13, 5.2 * len(sets)), squeeze=False)
    for row, pset in zip(axes, sets):
        speed_plan(solution, pset.name, module=module).plot(row[0])
        range_diagram(solution, pset.name).plot(row[1])
    fig.suptitle(f"{solution.train.name}: speeds", fontsize=13)
    fig.tight_layout()
    return fig
