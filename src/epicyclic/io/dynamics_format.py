"""The transient inputs of a train file: ``[dynamics]``, ``[engine]`` and every element's ``capacity`` table.

Read from the same TOML file as the train (after the same ``--set`` overrides); every error names the
file, the table and the key.  Units: SI (m, m², kg, kg·m², N, N·m, s, J/K) except speeds in 1/min and
pressures in bar, as a transmission's data sheets give them.  Defaults are stated in
``docs/file-format.md`` and repeated in every result's assumptions.

Examples
--------
>>> text = open("examples/dynamics/zf_8hp70_shift.toml").read()
>>> from epicyclic.io import loads_train_file
>>> from epicyclic.transmission import Transmission
>>> t = Transmission.from_train_file(loads_train_file(text))
>>> spec = dynamics_spec(text, "zf_8hp70_shift.toml", t)
>>> spec.duration, sorted(spec.elements)
(1.0, ['A', 'B', 'C', 'D', 'E'])
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from ..errors import EpicyclicError
from .overrides import OverrideError, apply_overrides
from .reader import TableReader, at_key, kind_of
from .source import parse_toml

__all__ = ["dynamics_spec", "DYNAMICS_KEYS", "ENGINE_KEYS", "CAPACITY_KEYS", "DEFAULT_SHAFT_INERTIA"]

DYNAMICS_KEYS = {"input_speed", "duration", "step", "line_pressure", "load", "output_torque", "grade",
                 "shaft_inertia", "inertia", "planets", "controller", "vehicle", "launch_element", "launch_ramp"}
ENGINE_KEYS = {"full_load", "motoring", "inertia", "throttle"}
CAPACITY_KEYS = {"kind", "reverse", "piston_area", "faces", "mean_radius", "friction", "return_spring",
                 "friction_area", "heat_capacity", "pressure"}
_CONTROLLER_KEYS = {"command_time", "fill_time", "torque_phase", "inertia_phase", "boost_time"}
_VEHICLE_KEYS = {"mass", "wheel_radius", "axle_ratio", "rolling_coefficient", "drag_area", "air_density",
                 "rotating_mass_factor", "axle_efficiency"}
_PLANET_KEYS = {"set", "count", "inertia", "mass", "orbit_radius", "spin_ratio"}
#: kg·m² of a shaft the file gives no inertia (stated).
DEFAULT_SHAFT_INERTIA = 0.005
#: °C at which open-clutch drag is evaluated when the file's oil temperature is found by a thermal balance.
DRAG_TEMPERATURE = 80.0


class _Reader(TableReader):
    def num(self, table, key, where, default=None, low=None, high=None):
        if key not in table:
            if default is None:
                raise self.error(where, f"missing key {key!r}.")
            return default
        value = self.number(table[key], key, where)
        if (low is not None and value < low) or (high is not None and value > high):
            raise self.error(at_key(where, key), f"expected a value in [{low:g}, {high:g}], got {value!r}.")
        return value

    def rows(self, table, key, where, unit: str) -> tuple[tuple[float, float], ...]:
        value = self.require(table, key, where)
        if not isinstance(value, list) or not value or not all(isinstance(r, list) and len(r) == 2 for r in value):
            raise self.error(at_key(where, key), f"expected a list of [x, y] pairs ({unit}), got {kind_of(value)}.")
        return tuple((self.number(x, key, where), self.number(y, key, where)) for x, y in value)


def dynamics_spec(text: str, source: str, transmission, overrides: Sequence[str] = ()) -> Any:
    """The :class:`~epicyclic.dynamics.shift.DynamicsSpec` of a train file's text.

    Parameters
    ----------
    text : str
        The file's TOML.
    source : str
        Its name (first word of every message).
    transmission : Transmission
        The file's transmission (its spin losses give the open elements' drag).
    overrides : sequence of str
        ``--set KEY=VALUE`` as for the train.

    Returns
    -------
    DynamicsSpec

    Raises
    ------
    InputFileError
        A missing ``[dynamics]`` table, an unknown or bad key (the message names table and key).
    """
    from ..dynamics import (
        DynamicsError,
        Engine,
        Freewheel,
        FrictionCapacity,
        HeldSpeed,
        Inertias,
        OutputTorque,
        PlanetInertia,
        PressureProfile,
        VehicleLoad,
        WetElement,
    )
    from ..dynamics.shift import DEFAULT_LINE_PRESSURE, DynamicsSpec, ShiftController
    from ..transmission import Vehicle

    r = _Reader(source)
    data = parse_toml(text, source)
    if overrides:
        try:
            data = apply_overrides(data, overrides)
        except OverrideError as exc:
            raise OverrideError(f"{source}: {exc}") from None
    if "dynamics" not in data:
        raise r.error("top level", "no [dynamics] table: add one (input_speed, duration, load, inertia; see "
                                   "docs/dynamics.md) to simulate shifts and launches.")
    dyn = r.table(data["dynamics"], "[dynamics]")
    r.check_keys(dyn, DYNAMICS_KEYS, "[dynamics]")
    assumed: list[str] = []
    where = "[dynamics]"
    try:
        moving = transmission.train.moving_shafts
        default_inertia = r.num(dyn, "shaft_inertia", where, DEFAULT_SHAFT_INERTIA, 0.0, 1e3)
        given = r.table(dyn.get("inertia", {}), "[dynamics.inertia]")
        for shaft in given:
            if shaft not in moving:
                raise r.error(f"[dynamics.inertia], key {shaft!r}", f"no such moving shaft; shafts are "
                                                                   f"{', '.join(moving)}.")
        shafts = {s: _inertia(r, given, s, default_inertia) for s in moving}
        missing = [s for s in moving if s not in given]
        if missing:
            assumed.append(f"shaft inertia {default_inertia:g} kg m^2 for {', '.join(missing)} ([dynamics] "
                           "shaft_inertia)")
        planets = []
        for k, p in enumerate(dyn.get("planets", [])):
            w = f"[[dynamics.planets]] #{k + 1}"
            p = r.table(p, w)
            r.check_keys(p, _PLANET_KEYS, w)
            planets.append(PlanetInertia(r.string(p, "set", w), int(r.integer(r.require(p, "count", w), "count", w)),
                                         r.num(p, "inertia", w), r.num(p, "mass", w, 0.0),
                                         r.num(p, "orbit_radius", w, 0.0),
                                         r.num(p, "spin_ratio", w) if "spin_ratio" in p else None))
        inertias = Inertias(shafts, tuple(planets))
        assumed.extend(_ignored(transmission))
        elements, pressures = _elements(r, data, transmission, FrictionCapacity, WetElement, Freewheel,
                                        PressureProfile, assumed)
        drive = _engine(r, data, Engine, assumed)
        load_kind = dyn.get("load", "vehicle")
        if load_kind not in ("vehicle", "held", "torque"):
            raise r.error(at_key(where, "load"), f"expected 'vehicle', 'held' or 'torque', got {load_kind!r:.40}.")
        if load_kind == "held":
            load = HeldSpeed()
        elif load_kind == "torque":
            load = OutputTorque(((0.0, r.num(dyn, "output_torque", where)),))
        else:
            vw = "[dynamics.vehicle]"
            vt = r.table(dyn.get("vehicle", {}), vw)
            r.check_keys(vt, _VEHICLE_KEYS, vw)
            if "mass" not in vt:
                raise r.error(vw, "missing key 'mass' (kg); or set [dynamics] load = 'held' or 'torque'.")
            vehicle = Vehicle(r.num(vt, "wheel_radius", vw), r.num(vt, "axle_ratio", vw), mass=r.num(vt, "mass", vw),
                              **{k: r.num(vt, k, vw) for k in ("rolling_coefficient", "drag_area", "air_density",
                                                               "rotating_mass_factor", "axle_efficiency") if k in vt})
            load = VehicleLoad(vehicle, r.num(dyn, "grade", where, 0.0, -1.0, 1.0))
        cw = "[dynamics.controller]"
        ct = r.table(dyn.get("controller", {}), cw)
        r.check_keys(ct, _CONTROLLER_KEYS, cw)
        controller = ShiftController(**{k: r.num(ct, k, cw) for k in _CONTROLLER_KEYS if k in ct})
        spec = DynamicsSpec(
            inertias, elements, drive, load, input_speed=r.num(dyn, "input_speed", where, 2500.0, -1e5, 1e5),
            duration=r.num(dyn, "duration", where, 1.0, 1e-6, 600.0), step=r.num(dyn, "step", where, 1e-3, 1e-6, 10.0),
            line_pressure=r.num(dyn, "line_pressure", where, DEFAULT_LINE_PRESSURE / 1e5, 1e-3, 100.0) * 1e5,
            controller=controller, pressures=pressures,
            launch_element=r.string(dyn, "launch_element", where) if "launch_element" in dyn else None,
            launch_ramp=r.num(dyn, "launch_ramp", where, 0.6, 0.0, 600.0), assumptions=tuple(assumed))
    except DynamicsError as exc:
        raise r.error(where, str(exc)) from None
    except EpicyclicError:
        raise
    return spec


def _ignored(transmission) -> list[str]:
    """The file's loss models the transient does not use, each said (it uses η0 per set and the clutch drag)."""
    out = []
    if getattr(transmission, "losses", None):
        out.append("ignored in the transient: the loss models of " + ", ".join(sorted(transmission.losses))
                   + " (each set or stage transmits with its stationary efficiency η0 by the direction of power flow)")
    spin = getattr(transmission, "spin", None)
    if spin is not None:
        parts = [name for name, present in (("oil pump", spin.pump), ("churning", spin.churning),
                                            ("windage", spin.windage), ("seals", spin.seals)) if present]
        if parts:
            out.append("ignored in the transient: " + ", ".join(parts) + " (only the open elements' drag acts)")
    return out


_BLANK_KEYS = {"diameter", "face_width", "bore", "density", "rim_diameter", "web_width"}


def _inertia(r, given, shaft: str, default: float) -> float:
    """kg·m² of a shaft: a number, or a list of gear blanks on it (solid, or rimmed with rim_diameter and web_width)."""
    from ..dynamics import rimmed_blank_inertia, solid_blank_inertia
    from ..dynamics.inertia import STEEL_DENSITY

    where = "[dynamics.inertia]"
    value = given.get(shaft, default)
    if not isinstance(value, list):
        return r.num(given, shaft, where, default, 0.0, 1e3)
    total = 0.0
    for k, blank in enumerate(value):
        w = f"{where}, key {shaft!r}, blank #{k + 1}"
        blank = r.table(blank, w)
        r.check_keys(blank, _BLANK_KEYS, w)
        d, b = r.num(blank, "diameter", w), r.num(blank, "face_width", w)
        bore, rho = r.num(blank, "bore", w, 0.0), r.num(blank, "density", w, STEEL_DENSITY)
        if "rim_diameter" in blank or "web_width" in blank:
            total += rimmed_blank_inertia(d, b, r.num(blank, "rim_diameter", w), r.num(blank, "web_width", w),
                                          bore=bore, density=rho)
        else:
            total += solid_blank_inertia(d, b, bore=bore, density=rho)
    return total


def _elements(r, data, transmission, FrictionCapacity, WetElement, Freewheel, PressureProfile, assumed):
    drags = {}
    spin = getattr(transmission, "spin", None)
    if spin is not None and spin.oil is not None:
        temperature = spin.temperature if spin.temperature is not None else DRAG_TEMPERATURE
        if spin.temperature is None and spin.clutch_drag:
            assumed.append(f"open-clutch drag at {DRAG_TEMPERATURE:g} degC (the file's oil temperature is found by "
                           "a thermal balance the transient does not run)")
        viscosity, density = float(spin.oil.dynamic_viscosity(temperature)), float(spin.oil.density_at(temperature))
        drags = {d.element: WetElement.drag_function(d, viscosity, density) for d in spin.clutch_drag}
    elements, pressures = {}, {}
    for kind in ("clutch", "brake"):
        for k, table in enumerate(data.get(kind, []) if isinstance(data.get(kind, []), list) else []):
            if not isinstance(table, dict) or "capacity" not in table:
                continue
            name = table.get("name", f"#{k + 1}")
            w = f"[[{kind}]] #{k + 1} {name!r} [{kind}.capacity]"
            cap = r.table(table["capacity"], w)
            r.check_keys(cap, CAPACITY_KEYS, w)
            element_kind = cap.get("kind", "wet")
            if element_kind == "one_way":
                elements[name] = Freewheel(name, r.boolean(cap, "reverse", w, False))
                continue
            if element_kind != "wet":
                raise r.error(at_key(w, "kind"), f"expected 'wet' or 'one_way', got {element_kind!r:.40}.")
            friction = cap.get("friction")
            if isinstance(friction, list):
                friction = r.rows(cap, "friction", w, "slip 1/min, mu")
            else:
                friction = r.num(cap, "friction", w)
            faces = r.integer(r.require(cap, "faces", w), "faces", w)
            capacity = FrictionCapacity(
                r.num(cap, "piston_area", w), faces, r.num(cap, "mean_radius", w), friction,
                r.num(cap, "return_spring", w, 0.0), r.num(cap, "friction_area", w) if "friction_area" in cap else None,
                r.num(cap, "heat_capacity", w) if "heat_capacity" in cap else None)
            elements[name] = WetElement(name, capacity, drags.get(name))
            if "pressure" in cap:
                rows = r.rows(cap, "pressure", w, "s, bar")
                pressures[name] = PressureProfile(tuple((t, p * 1e5) for t, p in rows), name)
    return elements, pressures


def _engine(r, data, Engine, assumed):
    if "engine" not in data:
        raise r.error("top level", "no [engine] table: give full_load = [[speed 1/min, torque N*m], ...] (and "
                                   "inertia, throttle) for the drive.")
    w = "[engine]"
    e = r.table(data["engine"], w)
    r.check_keys(e, ENGINE_KEYS, w)
    if "inertia" not in e:
        assumed.append("engine inertia 0.15 kg m^2 ([engine] inertia)")
    if "motoring" not in e:
        assumed.append("no engine braking at part throttle ([engine] motoring)")
    return Engine(r.rows(e, "full_load", w, "1/min, N*m"), r.num(e, "inertia", w, 0.15, 0.0, 100.0),
                  r.rows(e, "motoring", w, "1/min, N*m") if "motoring" in e else ((0.0, 0.0),),
                  r.num(e, "throttle", w, 1.0, 0.0, 1.0))
