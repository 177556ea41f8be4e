"""Module and face width of each set of a candidate: ISO 6336 pitting and root, in every gear.

Every synthesised candidate gets real geometry, so that its train file passes
``epicyclic fit``, ``analyze`` and ``rate``.  For each simple set the module is the
smallest ISO 54 module (series I and II) at which every mesh of the set meets S_Hmin
(pitting, ISO 6336-2) and S_Fmin (tooth root, ISO 6336-3) **in every gear** that
loads it, found by the rating's own search :func:`~epicyclic.rating.sizing.smallest_module`:

* the gears are solved at the sizing point (``[sizing] input_torque``, default 300 N·m,
  and ``input_speed``, default 1000 1/min: the operating point of the train file);
* the gear with the largest sun torque is sized first; every other loaded gear is then
  rated at that module and raises it where a mesh falls short (the search resumes at the
  module reached, so each further gear costs one rating when the module holds);
* a last pass rates every loaded gear at the final module and keeps the lowest S_H and
  S_F over gears and meshes (what the candidate's ``rate --gear all`` reports);
* the face width grows with the module, b = ``face_width_ratio`` · d_sun (b/d1, default
  0.5), the gears are unshifted (x = 0) with the ISO 53 A basic rack, and the set must fit at the
  module (:func:`~epicyclic.geometry.check_fitting`'s error-level conditions, which the search enforces);
* the rating inputs are the spec's ``[rating]`` table (material, R_z of flank and root,
  ν_40, life, minimum safeties, K_A), by default case-carburised 18CrNiMo7-6, R_z 3 / 10 µm,
  ν_40 = 100 mm²/s, 20 000 h, S_Hmin 1.0, S_Fmin 1.4, K_A 1.0 (stated in
  :data:`RATING_DEFAULTS`); the written train file carries the same table, so ``rate`` rates
  with what sized it.

A set that no module of the series up to 50 mm can carry raises
:class:`~epicyclic.rating.errors.RatingError` (the candidate is dropped, never written
unsized).  A gear in which a set carries no torque (below 10⁻⁹ of the input torque) or
whose members all turn together (locked: the teeth do not roll, no load cycles) does not
size it.  Double-planet sets have no planet tooth counts yet, so no geometry.

References
----------
ISO 54:1996 (modules); ISO 6336-1:2019, -2:2019 eq. (4) (S_H), -3:2019 eq. (5) (S_F);
ISO 6336-5:2016 (materials); ISO 21771:2007 (d = m·z).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any

__all__ = ["RATING_DEFAULTS", "RATING_KEYS", "SetSize", "check_rating", "rating_spec", "size_sets"]

#: The rating inputs of the sizing when the spec's ``[rating]`` table leaves them out.
RATING_DEFAULTS: Mapping[str, Any] = MappingProxyType({
    "material": "18CrNiMo7-6", "flank_roughness": 3.0, "root_roughness": 10.0, "viscosity_40": 100.0,
    "life": 20000.0, "S_Hmin": 1.0, "S_Fmin": 1.4, "application_factor": 1.0})
#: Keys a synthesis spec's ``[rating]`` table may give.
RATING_KEYS = tuple(RATING_DEFAULTS)

#: Torque below which (× the input torque) a set is idle in a gear.
_IDLE = 1e-9


@dataclass(frozen=True)
class SetSize:
    """Module and face width of one set, and the ratings they come from.

    Attributes
    ----------
    module, face_width : float
        mm.
    gear : str
        The gear whose load set the module (the last one to raise it).
    sun_torque : float
        Largest |T_sun| over the gears at the sizing point, N·m.
    safety_pitting, safety_bending : float
        Lowest S_H and S_F over the loaded gears and the set's meshes at this module.
    """

    module: float
    face_width: float
    gear: str
    sun_torque: float
    safety_pitting: float
    safety_bending: float

    def to_dict(self) -> dict:
        """``module`` and ``face_width`` (mm), ``gear``, ``sun_torque`` (N·m), ``safety_pitting``, ``safety_bending``."""
        return {"module": self.module, "face_width": self.face_width, "gear": self.gear,
                "sun_torque": self.sun_torque, "safety_pitting": self.safety_pitting,
                "safety_bending": self.safety_bending}


def rating_spec(values: Mapping[str, Any] | Sequence[tuple[str, Any]] = ()):
    """The :class:`~epicyclic.rating.RatingSpec` of the sizing: ``values`` over :data:`RATING_DEFAULTS`.

    Parameters
    ----------
    values : mapping or sequence of (key, value)
        Keys of :data:`RATING_KEYS` (the spec's ``[rating]`` table).

    Returns
    -------
    RatingSpec

    Raises
    ------
    RatingError
        A value out of range or an unknown material.

    >>> rating_spec({"life": 5000}).life, rating_spec().material.name
    (5000.0, '18CrNiMo7-6')
    """
    from ..rating import RatingSpec

    merged = {**RATING_DEFAULTS, **dict(values)}
    return RatingSpec(**merged)


def check_rating(given: Any, error: Any) -> tuple[tuple[str, Any], ...]:
    """Validated rating inputs of the sizing: known keys, values the rating accepts (checked by building it).

    Parameters
    ----------
    given : mapping
        The spec's ``[rating]`` table.
    error : callable (key, message) → Exception
        Builds the error naming the key (the spec's place).

    Returns
    -------
    tuple of (str, value)
    """
    import re

    from ..errors import EpicyclicError
    from ..text import short

    if not isinstance(given, Mapping):
        raise error("rating", f"expected a table of rating inputs, got {short(given)}.")
    for key, value in given.items():
        if key not in RATING_KEYS:
            raise error(str(key), f"unknown rating input; use {', '.join(RATING_KEYS)}.")
        if key == "material" and not isinstance(value, str):
            raise error(key, f"expected a material name such as \"18CrNiMo7-6\", got {short(value)}.")
        if key != "material" and (isinstance(value, bool) or not isinstance(value, (int, float))):
            raise error(key, f"expected a number, got {short(value)}.")
    try:
        rating_spec(given)
    except EpicyclicError as exc:
        named = re.match(r"rating\.(\w+)", str(exc))  # the rating's messages start with the key
        raise error(named.group(1) if named and named.group(1) in given else next(iter(given)), str(exc)) from None
    return tuple((str(k), v if k == "material" else float(v)) for k, v in given.items())


def _loaded(state, input_torque: float) -> bool:
    """The set carries torque and its members do not all turn together."""
    torques, speeds = state.torques, state.speeds
    if abs(torques["sun"]) <= _IDLE * max(abs(input_torque), 1.0):
        return False
    spread = max(speeds.values()) - min(speeds.values())
    return spread > 1e-9 * max(1.0, *(abs(v) for v in speeds.values()))


def size_sets(solutions: Mapping[str, Any], set_names: Sequence[str | None], spec, face_width_ratio: float = 0.5,
              input_torque: float = 1.0) -> tuple[SetSize | None, ...]:
    """The smallest ISO 54 module of each set meeting S_Hmin and S_Fmin in every gear that loads it.

    Parameters
    ----------
    solutions : mapping gear → Solution
        Every gear solved at the sizing point (drive).
    set_names : sequence of str or None
        The planetary sets to size (None: a set without tooth counts, left unsized).
    spec : RatingSpec
        Materials, roughness, lubricant, life, minimum safeties (:func:`rating_spec`).
    face_width_ratio : float, default 0.5
        b / d_sun.
    input_torque : float, default 1
        N·m at the sizing point (the idle threshold is relative to it).

    Returns
    -------
    tuple of SetSize or None
        One per name.

    Raises
    ------
    RatingError
        A set that no module up to 50 mm can carry in some gear.

    References
    ----------
    ISO 54:1996; ISO 6336-2:2019, eq. (4); ISO 6336-3:2019, eq. (5).
    """
    from ..rating import smallest_module

    out: list[SetSize | None] = []
    for name in set_names:
        if name is None:
            out.append(None)
            continue
        loaded = [(g, s) for g, s in solutions.items() if _loaded(s.elements[name], input_torque)]
        if not loaded:
            out.append(None)
            continue
        loaded.sort(key=lambda gs: -abs(gs[1].elements[name].torques["sun"]))
        module, gear, result = 0.0, loaded[0][0], None
        for _ in range(8):  # passes until no gear raises the module (stable after one, but bounded)
            raised = False
            lowest_h = lowest_f = float("inf")
            for g, solution in loaded:
                result = smallest_module(solution, name, spec, face_width_ratio=face_width_ratio,
                                         min_module=module or 0.5)
                if result.module > module:
                    raised = raised or module > 0
                    module, gear = result.module, g
                    lowest_h = lowest_f = float("inf")  # restart the minima at the new module
                _, s_h, s_f = result.tried[-1]
                lowest_h, lowest_f = min(lowest_h, s_h), min(lowest_f, s_f)
            if not raised:
                break
        sun_torque = max(abs(s.elements[name].torques["sun"]) for _, s in loaded)
        out.append(SetSize(module, result.face_width, gear, sun_torque, lowest_h, lowest_f))
    return tuple(out)
