"""JSON report with a documented, stable schema, in the user's units.

The report is :meth:`Solution.to_dict() <epicyclic.results.Solution.to_dict>`
(core units) with every dimensioned number converted into the chosen
:class:`~epicyclic.units.Units`, wrapped with metadata.  Layout (schema
``"epicyclic-report/3"``, documented in ``docs/file-format.md``)::

    {
      "schema": "epicyclic-report/3",
      "generator": "epicyclic 0.1.0",
      "title": str, "source": str | null,
      "units": {"speed": str, "torque": str, "power": str},
      "solution": {                      # Solution.to_dict(), converted
        "shafts": {name: {"speed", "torque", "power", "role"}},
        "elements": {name: {"kind", "status", "ports", "torques", "speeds", "rolling_power",
                            "coupling_power", "loss", "loss_direction", "efficiency_factor",
                            "engaged", "slip_speed", "planet_speeds", "planet_speeds_relative",
                            "loss_sources"}},
        "input_power", "output_power", "loss", "efficiency", "self_locking",
        "circulation": {"power", "ratio", "loops": [{"path", "power", "ratio"}],
                        "largest_element_power", "largest_element_ratio", "indeterminate"},
        "degrees_of_freedom", "warnings", "ratio",
        "housing_loss_sources": {source: power},   # only with spin losses (pump, seals)
        "oil_temperature": degC                    # only with spin losses
      },
      "ideal": {... same as "solution", lossless ...} | null,
      "geometry": {element: {"kind", "geometry", "fitting", "forces"}}   # only with geometry; mm, deg, N, N*m
    }

Efficiencies, ratios (the circulation's ``ratio`` and ``largest_element_ratio``
are multiples of the input power) and ``loss_direction`` (w) are
dimensionless.  Schema 1 had ``circulating_power`` (largest port power ÷ input
power); schema 2 replaces it by ``circulation``: the power that flows around
closed loops (Blindleistung) per loop and in total, and the largest element
power, each null where the torque split is statically indeterminate.  Schema 3
adds ``geometry`` and each element's ``loss_sources`` (the loss by source in
the power unit: ``mesh``, ``bearing``, ``drag``; see ``docs/losses.md``).

Examples
--------
>>> from epicyclic.io import loads_train_file
>>> f = loads_train_file('''
... [units]
... power = "kW"
... [[planetary]]
... name = "P"
... sun = "in"
... ring = "ring"
... carrier = "out"
... stationary_ratio = -2
... [[brake]]
... name = "B"
... shaft = "ring"
... [operating_point]
... speeds = { in = 3000 }
... powers = { in = 10 }
... drives = ["in"]
... loads = ["out"]
... ''')
>>> report = report_dict(f.solve(), f.units)
>>> report["units"]["power"], round(report["solution"]["output_power"], 6)
('kW', 10.0)
"""

from __future__ import annotations

import json
import math
from typing import Any

from ..results.solution import Solution
from ..units import Units

__all__ = ["SCHEMA", "report_dict", "report_data", "json_report"]

#: Identifier of the layout; bumped on any incompatible change.
SCHEMA = "epicyclic-report/3"


def _convert_solution(data: dict[str, Any], units: Units) -> dict[str, Any]:
    speed, torque, power = units.speed_from_core, units.torque_from_core, units.power_from_core
    out = dict(data)
    out.pop("schema", None)
    out.pop("train", None)
    out["units"] = units.to_dict()
    out["shafts"] = {
        name: {**s, "speed": speed(s["speed"]), "torque": torque(s["torque"]), "power": power(s["power"])}
        for name, s in data["shafts"].items()
    }
    elements = {}
    for name, e in data["elements"].items():
        converted = dict(e)
        converted["torques"] = {p: torque(t) for p, t in e["torques"].items()}
        converted["speeds"] = {p: speed(n) for p, n in e["speeds"].items()}
        for key in ("rolling_power", "coupling_power", "loss"):
            converted[key] = power(e[key])
        if e.get("slip_speed") is not None:
            converted["slip_speed"] = speed(e["slip_speed"])
        converted["planet_speeds"] = [speed(n) for n in e["planet_speeds"]]
        converted["planet_speeds_relative"] = [speed(n) for n in e["planet_speeds_relative"]]
        converted["loss_sources"] = {k: power(v) for k, v in e.get("loss_sources", {}).items()}
        elements[name] = converted
    out["elements"] = elements
    for key in ("input_power", "output_power", "loss"):
        out[key] = power(data[key])
    if "housing_loss_sources" in data:  # pump, seals (spin losses, docs/losses.md)
        out["housing_loss_sources"] = {k: power(v) for k, v in data["housing_loss_sources"].items()}
    circ = dict(data["circulation"])
    for key in ("power", "largest_element_power"):
        circ[key] = None if circ[key] is None else power(circ[key])
    circ["loops"] = [{**loop, "power": power(loop["power"])} for loop in circ["loops"]]
    out["circulation"] = circ
    return out


def _finite(value: Any) -> Any:
    """Replace non-finite floats (not valid JSON) by None, recursively."""
    if isinstance(value, float) and not math.isfinite(value):
        return None
    if isinstance(value, dict):
        return {k: _finite(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_finite(v) for v in value]
    return value


def report_dict(
    solution: Solution,
    units: Units | None = None,
    *,
    title: str | None = None,
    source: str | None = None,
    geometry: dict[str, Any] | None = None,
) -> dict[str, Any]:
    """The report as plain data (JSON-ready), numbers in ``units``.

    Parameters
    ----------
    solution : Solution
    units : Units, optional
        Output units; core units (1/min, N·m, W) by default.
    title, source : str, optional
        Title (default: the train's name) and input file.
    geometry : dict, optional
        The ``"geometry"`` section (:func:`~epicyclic.io.geometry_report.geometry_dict`):
        gears, meshes, fitting and forces of the elements with a geometry table, in
        mm, degrees, N and N·m; the key is left out without one.

    Returns
    -------
    dict
        See the module docstring for the layout.
    """
    return _finite(report_data(solution, units, title=title, source=source, geometry=geometry))


def report_data(solution: Solution, units: Units | None = None, *, title: str | None = None,
                source: str | None = None, geometry: dict[str, Any] | None = None) -> dict[str, Any]:
    """:func:`report_dict` before non-finite numbers become null (to check them: ``check_finite``)."""
    from .. import __version__

    units = units or Units()
    body = _convert_solution(solution.to_dict(), units)
    body["ratio"] = solution.ratio
    ideal = None
    if solution.ideal is not None:
        ideal = _convert_solution(solution.ideal.to_dict(), units)
        ideal["ratio"] = solution.ideal.ratio
    report = {
        "schema": SCHEMA,
        "generator": f"epicyclic {__version__}",
        "title": title or solution.train.name,
        "source": source,
        "units": units.to_dict(),
        "solution": body,
        "ideal": ideal,
    }
    if geometry is not None:  # only for files with geometry tables
        report["geometry"] = geometry
    return report


def json_report(solution: Solution, units: Units | None = None, *, title: str | None = None,
                source: str | None = None, indent: int = 2, geometry: dict[str, Any] | None = None) -> str:
    """The report as JSON text (see :func:`report_dict`)."""
    return json.dumps(report_dict(solution, units, title=title, source=source, geometry=geometry), indent=indent,
                      ensure_ascii=False) + "\n"
