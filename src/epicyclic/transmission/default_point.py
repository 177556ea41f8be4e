"""The operating point a transmission is shown at when its file gives none.

A transmission file often has a ``[transmission]`` table and no
``[operating_point]``: its ratios, steps and spread do not depend on a load,
but its efficiencies do as soon as the losses come from loss models (mesh
friction by Niemann/Winter, bearing and drag losses: the load-dependent part
grows with the torque, the load-independent part with the speed; ISO/TR
14179-2, 2001, sec. 5).  Every output of such a file (``epicyclic gears``,
``plot``, ``analyze``, the page) is solved at the same stated default: the
input driven at :data:`DEFAULT_INPUT_SPEED` with :data:`DEFAULT_INPUT_TORQUE`,
the output loaded; coast (engine braking) drives the output with the input
torque times the ratio.  1000 1/min and 100 N·m is a light part-load point
of a passenger-car automatic transmission (about 10.5 kW; the ZF 8HP70 is
rated 700 N·m), a realistic level for the losses, not unit input.

Examples
--------
>>> point = default_operating_point("in", "out")
>>> dict(point.speeds), dict(point.torques), point.drives, point.loads
({'in': 1000.0}, {'in': 100.0}, ('in',), ('out',))
>>> default_point_note()
'no operating point in the file: the default n_in = 1000 1/min, T_in = 100 N·m at the input'

References
----------
ISO/TR 14179-2:2001, Gears — Thermal capacity — Part 2: load-dependent and load-independent power
losses (sec. 5); ZF Friedrichshafen AG, 8HP70 data sheet (input torque up to 700 N·m).
"""

from __future__ import annotations

from ..model.operating_point import OperatingPoint

__all__ = ["DEFAULT_INPUT_SPEED", "DEFAULT_INPUT_TORQUE", "default_operating_point", "default_point_note"]

#: Input speed of the default operating point, 1/min.
DEFAULT_INPUT_SPEED = 1000.0
#: Input torque of the default operating point, N·m.
DEFAULT_INPUT_TORQUE = 100.0


def default_operating_point(input: str, output: str, *, speed: float = DEFAULT_INPUT_SPEED,
                            torque: float = DEFAULT_INPUT_TORQUE) -> OperatingPoint:
    """The default operating point of a transmission: ``input`` driven, ``output`` loaded.

    Parameters
    ----------
    input, output : str
        The transmission's input and output shafts.
    speed : float, default :data:`DEFAULT_INPUT_SPEED`
        Input speed, 1/min.
    torque : float, default :data:`DEFAULT_INPUT_TORQUE`
        Input torque, N·m.

    Returns
    -------
    OperatingPoint

    References
    ----------
    ISO/TR 14179-2:2001, sec. 5 (losses depend on load and speed, so the point is stated).
    """
    return OperatingPoint(speeds={input: speed}, torques={input: torque}, drives=[input], loads=[output])


def default_point_note(units=None) -> str:
    """The sentence an output at the default point carries (in the file's units where they differ).

    Parameters
    ----------
    units : epicyclic.units.Units, optional
        The file's units; numbers in other units than 1/min and N·m are added in brackets.

    References
    ----------
    ISO/TR 14179-2:2001, sec. 5.
    """
    text = (f"no operating point in the file: the default n_in = {DEFAULT_INPUT_SPEED:g} 1/min, "
            f"T_in = {DEFAULT_INPUT_TORQUE:g} N·m at the input")
    if units is not None and (units.speed, units.torque) != ("1/min", "N*m"):
        speed = units.speed_from_core(DEFAULT_INPUT_SPEED)
        torque = units.torque_from_core(DEFAULT_INPUT_TORQUE)
        text += f" ({speed:.4g} {units.speed}, {torque:.4g} {units.torque.replace('*', '·')})"
    return text
