"""Operating points of a REXS model: shaft speeds, external loads, load spectra, the lubricant.

* A ``shaft`` with ``defines_speed = true`` gives its ``rotational_speed``
  (1/min) → ``[operating_point] speeds``.
* An ``external_load`` on a shaft (``assembly`` relation) with
  ``defines_torque = true`` gives ``torque_around_u_axis`` (N·m) →
  ``torques``, or ``power`` (kW) → ``powers``; one with only
  ``transmits_torque = true`` is where the torque goes out (or comes in):
  the member that takes the reaction.  Loads that transmit no torque
  (radial and axial forces) are counted as ignored.
* Roles: a defining load whose torque has the sign of its shaft's speed puts
  power in (``drives``), the opposite sign takes it out (``loads``); the
  reacting members get the other role.  Where the speed at that shaft is not
  given the defining load is taken as the drive, and a note says so.
* Each ``load_case`` of a ``load_spectrum`` overrides these attributes for
  its components: one operating point per load case, with its share of the
  time (``operating_time_fraction`` of the ``gear_unit``, %, or Bearinx's
  ``load_duration_fraction``) and its lubricant
  temperature (``temperature_lubricant`` of the ``gear_casing``).
* The ``lubricant``'s kinematic viscosities at 40 and 100 °C give the
  viscosity at the casing's lubricant temperature by Ubbelohde–Walther
  (ASTM D341): lg lg(ν + 0.7) = A − B lg T; times the density (from
  ``density_at_15_degree_celsius`` with a thermal expansion of 6.5·10⁻⁴ /K,
  the mean of the ASTM D1250 volume correction of lubricating oils) it is
  the dynamic viscosity of ``[lubricant] viscosity`` (mPa·s).

References
----------
ASTM D341-20, *Viscosity–temperature equations and charts for liquid petroleum products* (Walther 1931);
ASTM D1250-19 / API MPMS 11.1, volume correction of lubricating oils;
REXS 1.7 attribute database (``rexs_schema_1.7.xml``, FVA GmbH, Apache-2.0).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any

from ..model import HOUSING, OperatingPoint
from .rexs_model import Component, RexsModel
from .topology import Members

__all__ = ["OIL_EXPANSION", "OperatingMapper", "RexsLoadCase", "walther_viscosity"]

#: Volume expansion of a lubricating oil per kelvin (ASTM D1250: 6–7·10⁻⁴ /K for lubricating oils).
OIL_EXPANSION = 6.5e-4

_ROLE = "custom_epicyclic_role"
_LUBRICANT = "custom_epicyclic_element"


def walther_viscosity(nu_40: float, nu_100: float, temperature: float) -> float:
    """Kinematic viscosity (mm²/s) at ``temperature`` (°C) from ν40 and ν100 by Ubbelohde–Walther.

    Parameters
    ----------
    nu_40, nu_100 : float
        Kinematic viscosities at 40 °C and 100 °C, mm²/s (ν40 > ν100 > 0).
    temperature : float
        °C, above −50.

    Returns
    -------
    float
        ν(T) in mm²/s; exactly ``nu_40`` at 40 °C and ``nu_100`` at 100 °C.

    References
    ----------
    ASTM D341-20, eq. (1)–(2): lg lg(ν + 0.7) = A − B lg T, T in kelvin.

    Examples
    --------
    >>> round(walther_viscosity(100.0, 11.0, 40.0), 9), round(walther_viscosity(100.0, 11.0, 100.0), 9)
    (100.0, 11.0)
    """
    w40, w100 = (math.log10(math.log10(nu + 0.7)) for nu in (nu_40, nu_100))
    t40, t100 = math.log10(313.15), math.log10(373.15)
    b = (w40 - w100) / (t100 - t40)
    a = w40 + b * t40
    return 10 ** (10 ** (a - b * math.log10(temperature + 273.15))) - 0.7


@dataclass(frozen=True)
class RexsLoadCase:
    """One operating point of a REXS model (a load case of its load spectrum, or the model's own).

    Attributes
    ----------
    id : int
        The load case id (0: the model's components, no load spectrum).
    spectrum : int
        The load spectrum id (0 without one).
    operating_point : mapping
        The ``[operating_point]`` table: ``speeds``, ``torques``, ``powers`` with units, ``drives``, ``loads``.
    duration_fraction : float or None
        The share of the load case in the spectrum's time (``operating_time_fraction``, 0 … 1).
    lubricant_temperature : float or None
        °C, the casing's ``temperature_lubricant`` in this load case.
    gear : str or None
        The gear of the ``[transmission]`` schedule the load case runs in (the ``gear_unit``'s
        ``gear_shift_index`` in the load case), or None where it gives none.
    """

    id: int
    spectrum: int
    operating_point: Mapping[str, Any]
    duration_fraction: float | None = None
    lubricant_temperature: float | None = None
    gear: str | None = None

    def to_operating_point(self) -> OperatingPoint:
        """The load case as an :class:`~epicyclic.model.OperatingPoint` (core units: 1/min, N·m, W).

        Returns
        -------
        OperatingPoint
        """
        table = self.operating_point
        return OperatingPoint(dict(table.get("speeds", {})), dict(table.get("torques", {})),
                              dict(table.get("powers", {})), drives=table.get("drives", ()),
                              loads=table.get("loads", ()))


def _number(value: float) -> str:
    return f"{value:.12g}"


class OperatingMapper:
    """Reads speeds, loads and load cases of ``model`` onto the members of ``members``.

    Parameters
    ----------
    model : RexsModel
    members : Members
    used : set of int
        Component ids read (the loads, shafts and lubricant read are added).
    notes : list of str
        Assumptions made are appended.
    """

    def __init__(self, model: RexsModel, members: Members, used: set[int], notes: list[str]):
        self.model, self.members, self.used, self.notes = model, members, used, notes
        self.load_on: dict[int, int] = {}  # external_load id → shaft id
        for relation in model.relations_of("assembly"):
            whole = model.components.get(relation.role("assembly"))
            part = model.components.get(relation.role("part"))
            if whole is not None and part is not None and part.type == "external_load" and whole.type == "shaft":
                self.load_on[part.id] = whole.id
        self.lubricant_data: Mapping[str, Any] | None = None

    def preferred_shafts(self) -> list[int]:
        """Shafts carrying a torque-transmitting load or a given speed (their names name the members)."""
        model = self.model
        out = [self.load_on[load.id] for load in model.of_type("external_load") if load.id in self.load_on
               and model.boolean(load, "transmits_torque", default=True)]
        out += [s.id for s in model.of_type("shaft") if model.boolean(s, "defines_speed", default=False)]
        return out

    def load_cases(self, known: set[str]) -> list[RexsLoadCase]:
        """One load case per ``load_case`` of the file, else one from the components (none without speeds).

        Parameters
        ----------
        known : set of str
            The members the train's elements name (speeds and loads elsewhere are skipped).
        """
        model = self.model
        unit = next(iter(model.of_type("gear_unit")), None)
        casing = next(iter(model.of_type("gear_casing")), None)
        cases = []
        for case in model.load_cases or ():
            table = self.point(case.components, known, f"load case {case.id}")
            fraction = temperature = None
            for share in ("operating_time_fraction", "load_duration_fraction"):  # REXS 1.4+; Bearinx's name
                if unit is not None and model.has(unit, share, case.components.get(unit.id)):
                    fraction = model.number(unit, share, "fraction", case.components.get(unit.id))
                    break
            if casing is not None and model.has(casing, "temperature_lubricant", case.components.get(casing.id)):
                temperature = model.number(casing, "temperature_lubricant", "temperature",
                                           case.components.get(casing.id))
            gear = None
            if unit is not None and "gear_shift_index" in case.components.get(unit.id, {}):
                gear = str(model.integer(unit, "gear_shift_index", case.components.get(unit.id)))
            if table is not None:
                cases.append(RexsLoadCase(case.id, case.spectrum, MappingProxyType(table), fraction, temperature,
                                          gear))
        if not model.load_cases:
            table = self.point({}, known, "")
            if table is not None:
                temperature = (model.number(casing, "temperature_lubricant", "temperature")
                               if casing is not None and model.has(casing, "temperature_lubricant") else None)
                cases.append(RexsLoadCase(0, 0, MappingProxyType(table), None, temperature))
        return cases

    def point(self, overrides: Mapping[int, Mapping], known: set[str], case: str) -> dict[str, Any] | None:
        """The ``[operating_point]`` table of the model with a load case's ``overrides``, or None."""
        model, members = self.model, self.members
        speeds: dict[str, float] = {}
        shafts = model.of_type("shaft")
        flagged = any("defines_speed" in s.attributes or "defines_speed" in overrides.get(s.id, {}) for s in shafts)
        if not flagged:  # no shaft says which speed is given: the first shaft of the train with a speed
            first = next((s for s in shafts if model.has(s, "rotational_speed", overrides.get(s.id))
                          and members.name(s.id) in known), None)
            shafts = [first] if first is not None else []
            if first is not None:
                note = (f"{model.source}: no shaft has defines_speed; the speed of {first.label} is read as the "
                        "given one")
                if note not in self.notes:
                    self.notes.append(note)
        for shaft in shafts:
            extra = overrides.get(shaft.id)
            if flagged and not model.boolean(shaft, "defines_speed", default=False, overrides=extra):
                continue
            if not model.has(shaft, "rotational_speed", extra):
                if case and not model.has(shaft, "rotational_speed"):
                    continue  # this load case does not give it
                raise model.error(shaft, "rotational_speed", "defines_speed is true, but the file gives no speed.")
            speed = model.number(shaft, "rotational_speed", "speed", extra)
            self.used.add(shaft.id)
            name = members.name(shaft.id)
            if name == HOUSING or name not in known:
                continue
            if name in speeds and abs(speeds[name] - speed) > 1e-9 * max(1.0, abs(speed)):
                raise model.error(shaft, "rotational_speed", f"{speed:g} 1/min contradicts {speeds[name]:g} 1/min "
                                                             f"given for another shaft of member {name!r}.")
            speeds[name] = speed
        given: list[tuple[str, str, float, Component]] = []   # (member, torque|power, value, load)
        reacting: list[tuple[str, Component]] = []
        for load in model.of_type("external_load"):
            extra = overrides.get(load.id)
            if load.id not in self.load_on:
                continue
            if not model.boolean(load, "transmits_torque", default=True, overrides=extra):
                continue
            self.used.add(load.id)
            name = members.name(self.load_on[load.id])
            if name == HOUSING or name not in known:
                continue
            has_torque = model.has(load, "torque_around_u_axis", extra)
            has_power = model.has(load, "power", extra)
            if model.boolean(load, "defines_torque", default=has_torque or has_power, overrides=extra):
                if has_torque:
                    given.append((name, "torques", model.number(load, "torque_around_u_axis", "torque", extra), load))
                elif has_power:
                    given.append((name, "powers", model.number(load, "power", "power", extra), load))
                else:
                    raise model.error(load, "torque_around_u_axis", "defines_torque is true, but the file gives "
                                      "neither torque_around_u_axis nor power" + (f" (in {case})" if case else "")
                                      + ".")
            else:
                reacting.append((name, load))
        if not speeds and not given:
            return None
        table: dict[str, Any] = {}
        if speeds:
            table["speeds"] = {k: f"{_number(v)} 1/min" for k, v in speeds.items()}
        drives, loads = [], []
        for name, group, value, load in given:
            role = model.text(load, _ROLE)
            if role == "none":  # a torque or power at a shaft that is neither drive nor load: signed
                shown = value if group == "torques" else value / 1000.0
                table.setdefault(group, {})[name] = f"{_number(shown)} {'N*m' if group == 'torques' else 'kW'}"
                continue
            if role not in ("drive", "load"):
                if name in speeds and value * speeds[name] != 0:
                    role = "drive" if value * speeds[name] > 0 else "load"
                else:
                    role = "drive"
                    self.notes.append(f"{model.source}: {load.label}: the speed of its shaft is not given, so the "
                                      "sign of its torque cannot tell whether power enters; read as the drive")
            unit = "N*m" if group == "torques" else "kW"
            shown = abs(value) if group == "torques" else abs(value) / 1000.0
            table.setdefault(group, {})[name] = f"{_number(shown)} {unit}"
            (drives if role == "drive" else loads).append(name)
        for name, load in reacting:
            role = model.text(load, _ROLE) or ("load" if drives or not loads else "drive")
            if role == "none":
                continue
            target = drives if role == "drive" else loads
            if name not in drives + loads:
                target.append(name)
        if drives:
            table["drives"] = list(dict.fromkeys(drives))
        if loads:
            table["loads"] = list(dict.fromkeys(loads))
        return table

    def lubricant(self, custom: Mapping[str, Any] | None) -> dict[str, Any] | None:
        """The ``[lubricant]`` table: epicyclic's own (written by it), else from ν40, ν100, ρ15 at the casing's
        lubricant temperature; None without a lubricant or a temperature."""
        model = self.model
        found = next(iter(model.of_type("lubricant")), None)
        if found is None:
            return dict(custom) if custom else None
        self.used.add(found.id)
        data: dict[str, Any] = {"name": model.text(found, "name") or found.name}
        for key, attribute, quantity in (("viscosity_40", "viscosity_at_40_degree_celsius", "kinematic viscosity"),
                                         ("viscosity_100", "viscosity_at_100_degree_celsius", "kinematic viscosity"),
                                         ("density_15", "density_at_15_degree_celsius", "density")):
            if model.has(found, attribute):
                data[key] = model.number(found, attribute, quantity)
        casing = next(iter(model.of_type("gear_casing")), None)
        if casing is not None and model.has(casing, "temperature_lubricant"):
            data["temperature"] = model.number(casing, "temperature_lubricant", "temperature")
        self.lubricant_data = MappingProxyType(data)
        if custom:
            return dict(custom)
        table = {key: data[key] for key in ("viscosity_40", "viscosity_100") if key in data}  # the rating's
        if not all(k in data for k in ("viscosity_40", "viscosity_100", "density_15", "temperature")):
            return table or None
        nu40, nu100 = data["viscosity_40"], data["viscosity_100"]
        if not nu40 > nu100 > 0:
            raise model.error(found, "viscosity_at_100_degree_celsius", f"expected 0 < ν100 < ν40, got ν40 = "
                                                                        f"{nu40:g}, ν100 = {nu100:g} mm^2/s.")
        temperature = data["temperature"]
        nu = walther_viscosity(nu40, nu100, temperature)
        density = data["density_15"] * (1.0 - OIL_EXPANSION * (temperature - 15.0))
        return {"viscosity": round(nu * density, 6), **table}


def standard_cases(duty: Any, cases: list[RexsLoadCase]) -> Any:
    """epicyclic's custom copy of ``[duty_cycle]`` with each case's speeds and loads from the REXS load case.

    Parameters
    ----------
    duty : mapping
        The ``duty_cycle`` of ``custom_epicyclic_document`` (names, gears, hours).
    cases : list of RexsLoadCase
        The file's load cases, one per case of ``duty``, in order.

    Returns
    -------
    mapping
        ``duty`` with ``speeds``, ``torques``, ``powers``, ``drives``, ``loads`` of each case replaced by the
        load case's (the standard attributes win over the custom copy).
    """
    if not isinstance(duty, dict) or not isinstance(duty.get("case"), list):
        return duty
    out = dict(duty)
    merged = []
    for table, case in zip(duty["case"], cases):
        if not isinstance(table, dict):
            return duty
        kept = {k: v for k, v in table.items() if k not in ("speeds", "torques", "powers", "drives", "loads")}
        merged.append({**kept, **{k: v for k, v in dict(case.operating_point).items() if v}})
    out["case"] = merged
    return out
