"""Render a Solution as plain data, a text table or an HTML table.

Rendering never computes: it reads the result object.  Numbers are in the core
units (1/min, N·m, W) unless a table is asked for in other units (the sources'
U/min, kp·cm, PS: :class:`epicyclic.units.Units`).  This module
knows the result only by its attributes (it imports nothing from
:mod:`epicyclic.results.solution`, which imports it).

Schema versions of :func:`solution_to_dict`: 1 had ``circulating_power``
(largest port power ÷ input power); 2 replaces it by ``circulation``
(circulating power per loop and in total, and the largest element power, in W
and as a multiple of the input; null values where the torque split is
statically indeterminate).
"""

from __future__ import annotations

import html
from typing import Any

from ..units import Units, as_units

__all__ = ["solution_to_dict", "solution_table", "solution_html", "port_labels", "SCHEMA_VERSION"]

#: Version of the JSON layout produced by :func:`solution_to_dict`.
SCHEMA_VERSION = 2

UNITS = {"speed": "1/min", "torque": "N*m", "power": "W"}


def port_labels(sol: Any, state: Any) -> dict[str, str]:
    """Each port of an element's result named as the element's arrangement says it.

    The solver names a set's ports ``sun``, ``ring`` and ``carrier`` whatever its
    gears; a set with two rings (Wolfrom) or two suns calls its central members
    ``first`` and ``second``, as its file's ``teeth`` table does
    (:meth:`epicyclic.model.Teeth.label`).  Every other element keeps the solver's
    port names.  Reports use these labels; the result objects keep the solver's.

    Parameters
    ----------
    sol : Solution
        The solution that ``state`` belongs to (its train knows the element).
    state : ElementState
        One element's result (``sol.elements[name]``).

    Returns
    -------
    dict
        Port (solver's name) → label, in the order of ``state.ports``.

    Examples
    --------
    >>> from epicyclic import GearTrain, OperatingPoint, PlanetarySet, solve
    >>> wolfrom = PlanetarySet.two_rings("W", first="r1", second="out", carrier="c", z_first=81,
    ...                                  z_planet_first=27, z_planet_second=24, z_second=78)
    >>> sol = solve(GearTrain([wolfrom], name="t"), OperatingPoint(speeds={"c": 750, "r1": 0}))
    >>> port_labels(sol, sol.elements["W"])
    {'sun': 'first', 'ring': 'second', 'carrier': 'carrier'}
    """
    teeth = getattr(sol.train.element(state.name), "teeth", None)
    return {p: p if teeth is None else teeth.label(p) for p in state.ports}


def _labelled(mapping: Any, labels: dict[str, str]) -> dict[str, Any]:
    return {labels.get(k, k): v for k, v in mapping.items()}


def solution_to_dict(sol: Any) -> dict[str, Any]:
    """JSON-ready dictionary of a solution (stable layout, units stated).

    Ports are named by :func:`port_labels` (``first``/``second`` for a set with
    two rings or two suns).

    Parameters
    ----------
    sol : Solution
        The solution (speeds 1/min, torques N·m, powers W).

    Returns
    -------
    dict
        ``schema``, ``train``, ``units``, ``shafts``, ``elements``, the powers,
        ``efficiency``, ``self_locking``, ``circulation``, ``degrees_of_freedom``,
        ``warnings`` (layout in ``docs/file-format.md``).
    """
    labels = {e.name: port_labels(sol, e) for e in sol.elements.values()}
    return {
        "schema": SCHEMA_VERSION,
        "train": sol.train.name,
        "units": dict(UNITS),
        "shafts": {
            s.name: {"speed": s.speed, "torque": s.torque, "power": s.power, "role": s.role}
            for s in sol.shafts.values()
        },
        "elements": {
            e.name: {
                "kind": e.kind,
                "status": e.status,
                "ports": _labelled(e.ports, labels[e.name]),
                "torques": _labelled(e.torques, labels[e.name]),
                "speeds": _labelled(e.speeds, labels[e.name]),
                "rolling_power": e.rolling_power,
                "coupling_power": e.coupling_power,
                "loss": e.loss,
                "loss_direction": e.loss_direction,
                "efficiency_factor": e.efficiency_factor,
                "engaged": e.engaged,
                "slip_speed": e.slip_speed,
                "planet_speeds": list(e.planet_speeds),
                "planet_speeds_relative": list(e.planet_speeds_relative),
                "loss_sources": dict(e.loss_sources),
            }
            for e in sol.elements.values()
        },
        "input_power": sol.input_power,
        "output_power": sol.output_power,
        "loss": sol.loss,
        "efficiency": sol.efficiency,
        "self_locking": None
        if sol.self_locking is None
        else {
            "message": sol.self_locking.message,
            "cause": sol.self_locking.cause,
            "formal_efficiency": sol.self_locking.formal_efficiency,
            "thresholds": dict(sol.self_locking.thresholds),
        },
        "circulation": sol.circulation.to_dict(),
        "degrees_of_freedom": sol.degrees_of_freedom,
        "warnings": list(sol.warnings),
        **({"housing_loss_sources": dict(sol.housing_loss_sources)} if sol.housing_loss_sources else {}),
        **({"oil_temperature": sol.oil_temperature} if sol.oil_temperature is not None else {}),
    }


def _grid(headers: list[str], rows: list[list[str]]) -> str:
    widths = [max(len(h), *(len(r[k]) for r in rows)) if rows else len(h) for k, h in enumerate(headers)]
    line = "  ".join(h.ljust(w) for h, w in zip(headers, widths))
    rule = "  ".join("-" * w for w in widths)
    body = ["  ".join(c.rjust(w) if k else c.ljust(w) for k, (c, w) in enumerate(zip(r, widths))) for r in rows]
    return "\n".join([line, rule, *body])


def _num(value: float | None, digits: int = 6) -> str:
    return "—" if value is None else f"{value:.{digits}g}"


def _shaft_rows(sol: Any, u: Units) -> list[list[str]]:
    return [[s.name, _num(u.speed_from_core(s.speed)), _num(u.torque_from_core(s.torque)),
             _num(u.power_from_core(s.power)), s.role] for s in sol.shafts.values()]


def _element_rows(sol: Any, u: Units) -> list[list[str]]:
    rows = []
    for e in sol.elements.values():
        labels = port_labels(sol, e)
        torques = " / ".join(f"{labels.get(p, p)} {_num(u.torque_from_core(t), 5)}" for p, t in e.torques.items())
        rows.append([e.name, e.kind, e.status, torques, _num(u.power_from_core(e.rolling_power)),
                     _num(u.power_from_core(e.coupling_power)), _num(u.power_from_core(e.loss))])
    return rows


def _summary(sol: Any, u: Units) -> list[str]:
    """Summary lines, labels aligned: powers, loss, efficiency, circulation, warnings."""
    power = u.power_from_core
    pairs = [("input power", f"{power(sol.input_power):.6g} {u.power}"),
             ("output power", f"{power(sol.output_power):.6g} {u.power}"),
             ("total loss", f"{power(sol.loss):.6g} {u.power}")]
    if sol.self_locking is not None:
        label = sol.self_locking.label
        pairs += [("efficiency", f"— ({label})"), (label, sol.self_locking.message)]
    else:
        pairs.append(("efficiency", _num(sol.efficiency)))
    pairs += _circulation_pairs(sol.circulation, u)
    pairs += [("warning", w) for w in sol.warnings]
    width = max(len(label) for label, _ in pairs)
    return [f"{label.ljust(width)}  {value}" for label, value in pairs]


def _circulation_pairs(circulation: Any, u: Units) -> list[tuple[str, str]]:
    if circulation.indeterminate:
        return [("circulating power", "— (" + circulation.describe() + ")")]
    if circulation.loops:
        pairs = [("circulating power", f"{_num(u.convert(circulation.power, 'power'))} {u.power}"
                  + (f" = {_num(circulation.ratio, 4)} × input" if circulation.ratio is not None else ""))]
        pairs += [("circulating loop", f"{loop.describe()}: {_num(u.convert(loop.power, 'power'))} {u.power}")
                  for loop in circulation.loops]
    else:
        pairs = [("circulating power", "none")]
    if circulation.largest_element_ratio is not None:
        pairs.append(("largest element power", f"{_num(circulation.largest_element_ratio, 4)} × input"))
    return pairs


def _shaft_headers(u: Units) -> list[str]:
    return ["shaft", f"speed [{u.speed}]", f"torque [{u.torque}]", f"power [{u.power}]", "role"]


def _element_headers(u: Units) -> list[str]:
    return ["element", "kind", "state", f"port torques [{u.torque}]", f"rolling power [{u.power}]",
            f"coupling power [{u.power}]", f"loss [{u.power}]"]


def solution_table(sol: Any, units: Any = None) -> str:
    """Plain-text report: shafts, elements, summary; in ``units`` (see :func:`epicyclic.units.as_units`)."""
    u = as_units(units)
    return "\n\n".join([
        f"{sol.train.name}",
        _grid(_shaft_headers(u), _shaft_rows(sol, u)),
        _grid(_element_headers(u), _element_rows(sol, u)),
        "\n".join(_summary(sol, u)),
    ])


def _html_table(headers: list[str], rows: list[list[str]]) -> str:
    head = "".join(f"<th>{html.escape(h)}</th>" for h in headers)
    body = "".join("<tr>" + "".join(f"<td>{html.escape(c)}</td>" for c in r) + "</tr>" for r in rows)
    return f"<table><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>"


def solution_html(sol: Any) -> str:
    """HTML fragment (for notebooks and reports)."""
    u = Units()
    summary = "".join(f"<li>{html.escape(line)}</li>" for line in _summary(sol, u))
    return (
        f"<div class='epicyclic-solution'><h4>{html.escape(sol.train.name)}</h4>"
        + _html_table(_shaft_headers(u), _shaft_rows(sol, u))
        + _html_table(_element_headers(u), _element_rows(sol, u))
        + f"<ul>{summary}</ul></div>"
    )
