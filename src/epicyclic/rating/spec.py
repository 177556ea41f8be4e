"""What a rating needs besides geometry and loads: :class:`RatingSpec` (the file's ``[rating]``).

Defaults (stated here and in ``docs/rating.md``):

======================  ==========================  =============================================
key                     default                     meaning
======================  ==========================  =============================================
standard                ``"2019"``                  ISO 6336 edition (``"2006"`` or ``"2019"``)
application_factor      1.0 (``default``)           K_A (uniform driver and load); one number or per mesh
life                    20000                       required life, h
S_Hmin / S_Fmin         1.0 / 1.4                   minimum safeties
accuracy_grade          6                           ISO 1328-1 flank tolerance class
accuracy_standard       1995 for ISO 6336:2006,     ISO 1328-1 edition of the grade (``"1995"`` or
                        2013 for :2019              ``"2013"``)
K_Hbeta, K_Fbeta        method C, K_Hβ^N_F          a given K_Hβ (K_Fβ), or F_βx from f_Hβ (+ 1.33 f_sh)
K_v                     method B                    a given dynamic factor
K_Halpha, K_Falpha      method B                    given transverse load factors (K_Fα = K_Hα if only
                                                    K_Hα is given)
f_pb, f_falpha, f_Hbeta from the accuracy grade     measured deviations per gear, µm
shaft_deflection        0                           f_sh for method C, µm
load_sharing            of the geometry, else by    K_γ (AGMA 6123/ISO values may be given)
                        number of planets
tool_tip_radius         0.25                        ρ_fP* of the basic rack (ISO 53 C; A: 0.38)
long_life               ``"standard"``              Z_NT, Y_NT 0.85 at 10^10 (``"optimum"``: 1.0)
pitting_permitted       False                       Z_NT curve without pitting (5·10^7)
tip_relief              running-in C_ay             C_a for K_v, µm (without one: C_ay of the pair)
rim_thickness           none (solid gears)          s_R per gear for Y_B, mm
micropitting            none (not rated)            :class:`~.micropitting.MicropittingSpec`
scuffing                none (not rated)            :class:`~epicyclic.rating.scuffing.ScuffingSpec`
flank_fracture          none (not rated)            :class:`~epicyclic.rating.flank_fracture.FlankFractureSpec`
tool                    none (ISO's closed form)    the tool per gear: the tooth form it generates
======================  ==========================  =============================================

Every load factor is one number for all meshes or a table by mesh (``element:mesh``, ``mesh``,
``element``, ``all``; :mod:`~epicyclic.rating.given_factors`); deviations and ``accuracy_grade``
one value or a table by gear (``element:gear``, ``gear``, ``all``).

Required (an error names the key and the value it would suggest): ``material`` (a
name of the data file, or per gear), ``flank_roughness`` and ``root_roughness`` (R_z,
µm), the lubricant's ``viscosity_40`` (mm²/s; from ``[lubricant]`` or
``[rating.lubricant]``).

References
----------
ISO 6336-1:2019, clause 4 and Annex (minimum safeties are agreed between customer and
supplier; 1.0 / 1.4 are the values commercial tools propose); ISO 6336-5:2016.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any

from ..geometry.tooth_generation import PinionCutter, RackTool
from ..geometry.accuracy import EDITIONS as ACCURACY_EDITIONS
from .errors import RatingError
from .given_factors import GEAR_DEVIATIONS, MESH_FACTORS, FactorValue, check_given, gear_value, mesh_factor
from .materials import Material, material
from .micropitting import MicropittingSpec
from .standard import DEFAULT_EDITION, edition
from .tooth_form import Cutter

__all__ = ["DEFAULTS", "SUGGESTED", "RatingSpec"]

DEFAULTS: Mapping[str, Any] = MappingProxyType({
    "standard": DEFAULT_EDITION, "application_factor": 1.0, "life": 20000.0, "S_Hmin": 1.0, "S_Fmin": 1.4,
    "accuracy_grade": 6, "shaft_deflection": 0.0, "tool_tip_radius": 0.25, "long_life": "standard",
    "pitting_permitted": False, "tip_relief": None,
})
#: The values an error for a missing required key proposes (never taken silently).
SUGGESTED: Mapping[str, Any] = MappingProxyType({
    "material": "18CrNiMo7-6", "flank_roughness": 3.0, "root_roughness": 10.0, "viscosity_40": 100.0,
})


def _number(value: object, key: str, low: float = 0.0, *, strict: bool = True) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) or (
            value <= low if strict else value < low):
        raise RatingError(f"rating.{key} must be a number {'>' if strict else '>='} {low:g}, got {value!r}.")
    return float(value)


def _per_gear(given: Mapping[str, Any], key: str, element: str, gear: str, suggestion: str):
    """The entry of ``gear`` of ``element`` in a per-gear mapping (``"P1:ring"``, ``"ring"``, ``"all"``)."""
    for name in (f"{element}:{gear}", gear, "all"):
        if name in given:
            return given[name]
    raise RatingError(f"rating.{key} has no entry for gear {gear!r} of {element!r} (keys "
                      f"{', '.join(map(repr, given)) or 'none'}); add {gear} = {suggestion} or '{element}:{gear}'.")


def _plain(value):
    return dict(value) if isinstance(value, Mapping) else value


def _missing(key: str, meaning: str) -> RatingError:
    return RatingError(f"rating.{key} is missing ({meaning}); give it in [rating] - e.g. {key} = "
                       f"{SUGGESTED[key]!r}, the value commonly taken.")


@dataclass(frozen=True)
class RatingSpec:
    """Inputs of an ISO 6336 rating that the geometry and the loads do not give.

    Parameters
    ----------
    material : Material or mapping gear → Material, optional
        One material for every gear, or one per gear name (``sun``, ``planet``, ``ring``,
        ``planet1`` ..., ``driving``/``driven`` for stages; an ``element:gear`` key such
        as ``"P1:ring"`` for one element).  Required.
    flank_roughness, root_roughness : float or mapping gear → float, optional
        R_z of flanks and root fillets, µm: one value for every gear, or one per gear name
        (keys as for ``material``: ``"P1:ring"``, ``"ring"``, ``"all"``).  Required.
    viscosity_40 : float, optional
        Kinematic viscosity of the oil at 40 °C, mm²/s.  Required.
    viscosity_100 : float, optional
        At 100 °C, mm²/s (kept for the report).
    standard : str, default "2019"
    application_factor : float, FactorValue or mapping mesh → float, optional
        K_A for every mesh or per mesh (default 1.0, a uniform driver and load, reported as
        ``default``).
    life : float, default 20000
        Required life, h.
    S_Hmin, S_Fmin : float, default 1.0, 1.4
    accuracy_grade : int or mapping gear → int, default 6
    accuracy_standard : str, optional
        ISO 1328-1 edition the grade is read in, ``"1995"`` or ``"2013"``; by default the one the
        ISO 6336 edition refers to (2006: ISO 1328-1:1995, 2019: ISO 1328-1:2013).
    K_Hbeta : float, FactorValue or mapping mesh → float, optional
        Given face load factor; otherwise method C.
    K_Fbeta : float or mapping mesh → float, optional
        Given face load factor of the root; otherwise K_Hβ^N_F (ISO 6336-1, 7.7).
    K_v : float or mapping mesh → float, optional
        Given dynamic factor (from measurement or a method A analysis, ISO 6336-1, 6.3); otherwise
        method B.
    K_Halpha, K_Falpha : float or mapping mesh → float, optional
        Given transverse load factors; otherwise method B (ISO 6336-1, 8.3).  K_Fα = K_Hα where only
        K_Hα is given.
    f_pb, f_falpha, f_Hbeta : float or mapping gear → float, optional
        Measured transverse base pitch, profile form and helix slope deviations, µm; otherwise from
        the accuracy grade (ISO 1328-1).
    shaft_deflection : float, default 0
        f_sh, µm (method C).
    load_sharing : float or mapping mesh → float, optional
        K_γ for every planetary set or per mesh (default: the set geometry's, else by number of
        planets).
    tool_tip_radius : float, default 0.25
        ρ_fP* of the basic rack.
    cutter : Cutter, optional
        Pinion-type cutter of the internal gears (rack approximation without).
    long_life : str, default "standard"
    pitting_permitted : bool, default False
    tip_relief : float, optional
        C_a, µm.  Without one, the running-in tip relief C_ay of the pair (ISO 6336-1:2006, 6.3,
        the mean of C_ay = (σ_Hlim/97 − 18.45)²/18 + 1.5 of both gears), as ISO 6336-1 prescribes
        for gears without a designed tip relief; give 0 for none at all.
    notes : tuple of str, default ()
        Remarks carried into every mesh rating.
    rim_thickness : mapping gear → float, optional
        Rim thickness s_R below the root per gear name (``ring``, ``"P1:ring"``), mm, for Y_B;
        gears not named are solid (Y_B = 1).
    micropitting : MicropittingSpec, optional
        Rate micropitting (ISO/TS 6336-22 Method B) with these inputs.
    scuffing : ScuffingSpec, optional
        Inputs of the scuffing rating (``[rating.scuffing]``); without, scuffing is not rated.
    flank_fracture : FlankFractureSpec, optional
        Inputs of the tooth flank fracture rating (``[rating.flank_fracture]``); without, not rated.
    tools : mapping gear → RackTool or PinionCutter, optional
        The tool that cuts each gear (keys as for ``material``): Y_F, Y_S from the root fillet it
        generates (:mod:`~epicyclic.rating.generated_form`).  Gears without one: ISO's closed form
        with the basic rack (``tool_tip_radius``), internal gears the ``cutter`` if given.
    ignored : tuple of str, default ()
        Inputs the source gave that the rating does not use although they change a safety (a REXS
        file's crowning, ...): listed in the report, never dropped silently.

    Raises
    ------
    RatingError
        A value of the wrong kind or out of range.

    References
    ----------
    ISO 6336-1:2019 (K_A, K_γ, accuracy); ISO 6336-2:2019, 11 (ν_40, R_z); ISO 6336-3:2019, 14 (R_z root).
    """

    material: Material | Mapping[str, Material] | None = None
    flank_roughness: float | Mapping[str, float] | None = None
    root_roughness: float | Mapping[str, float] | None = None
    viscosity_40: float | None = None
    viscosity_100: float | None = None
    standard: str = DEFAULT_EDITION
    application_factor: Any = None
    life: float = 20000.0
    S_Hmin: float = 1.0
    S_Fmin: float = 1.4
    accuracy_grade: int = 6
    accuracy_standard: str | None = None
    K_Hbeta: Any = None
    K_v: Any = None
    shaft_deflection: float = 0.0
    load_sharing: Any = None
    tool_tip_radius: float = 0.25
    cutter: Cutter | None = None
    long_life: str = "standard"
    pitting_permitted: bool = False
    tip_relief: float | None = None
    notes: tuple[str, ...] = field(default=(), compare=False)
    rim_thickness: Mapping[str, float] | None = None
    micropitting: MicropittingSpec | None = None
    scuffing: Any = None
    flank_fracture: Any = None
    tools: Mapping[str, RackTool | PinionCutter] | None = None
    ignored: tuple[str, ...] = field(default=(), compare=False)
    K_Fbeta: Any = None
    K_Halpha: Any = None
    K_Falpha: Any = None
    f_pb: Any = None
    f_falpha: Any = None
    f_Hbeta: Any = None

    def __post_init__(self) -> None:
        object.__setattr__(self, "standard", edition(self.standard))
        object.__setattr__(self, "life", _number(self.life, "life"))
        for key in ("S_Hmin", "S_Fmin", "tool_tip_radius"):
            object.__setattr__(self, key, _number(getattr(self, key), key))
        for key in ("flank_roughness", "root_roughness"):
            value = getattr(self, key)
            if isinstance(value, Mapping):
                object.__setattr__(self, key, MappingProxyType({k: _number(v, f"{key}.{k}") for k, v in value.items()}))
            elif value is not None:
                object.__setattr__(self, key, _number(value, key))
        for key in ("viscosity_40", "viscosity_100"):
            if getattr(self, key) is not None:
                object.__setattr__(self, key, _number(getattr(self, key), key))
        object.__setattr__(self, "shaft_deflection", _number(self.shaft_deflection, "shaft_deflection", strict=False))
        if self.tip_relief is not None:
            object.__setattr__(self, "tip_relief", _number(self.tip_relief, "tip_relief", strict=False))
        for key in MESH_FACTORS:
            if getattr(self, key) is not None:
                object.__setattr__(self, key, check_given(getattr(self, key), key))
        for key in GEAR_DEVIATIONS:
            if getattr(self, key) is not None:
                object.__setattr__(self, key, check_given(getattr(self, key), key, 0.0))
        if self.accuracy_standard is None:
            object.__setattr__(self, "accuracy_standard", "1995" if self.standard == "2006" else "2013")
        accuracy = str(self.accuracy_standard).removeprefix("ISO 1328-1:")
        if accuracy not in ACCURACY_EDITIONS:
            raise RatingError(f"rating.accuracy_standard must be one of {', '.join(map(repr, ACCURACY_EDITIONS))} "
                              f"(ISO 1328-1:1995 or :2013), got {self.accuracy_standard!r}.")
        object.__setattr__(self, "accuracy_standard", accuracy)
        low, high = ACCURACY_EDITIONS[accuracy]
        grades = self.accuracy_grade if isinstance(self.accuracy_grade, Mapping) else {"": self.accuracy_grade}
        for name, g in grades.items():
            if isinstance(g, bool) or not isinstance(g, int) or not low <= g <= high:
                key = f"accuracy_grade.{name}" if name else "accuracy_grade"
                raise RatingError(f"rating.{key} must be a whole number {low} ... {high} (ISO 1328-1:{accuracy}), "
                                  f"got {g!r}; the default is 6.")
        if isinstance(self.accuracy_grade, Mapping):
            object.__setattr__(self, "accuracy_grade", MappingProxyType(dict(self.accuracy_grade)))
        if self.long_life not in ("standard", "optimum"):
            raise RatingError(f"rating.long_life must be 'standard' or 'optimum', got {self.long_life!r}.")
        if self.rim_thickness is not None:
            rims = dict(self.rim_thickness)
            for key, value in rims.items():
                rims[key] = _number(value, f"rim_thickness.{key}")
            object.__setattr__(self, "rim_thickness", MappingProxyType(rims))
        if self.scuffing is not None and not (hasattr(self.scuffing, "clauses") and hasattr(self.scuffing, "to_dict")):
            raise RatingError(f"rating.scuffing must be an epicyclic.rating.scuffing.ScuffingSpec, got "
                              f"{type(self.scuffing).__name__}.")
        if self.flank_fracture is not None and not hasattr(self.flank_fracture, "profile_of"):
            raise RatingError(f"rating.flank_fracture must be an epicyclic.rating.flank_fracture.FlankFractureSpec, "
                              f"got {type(self.flank_fracture).__name__}.")
        if self.tools is not None:
            for key, tool in dict(self.tools).items():
                if not isinstance(tool, (RackTool, PinionCutter)):
                    raise RatingError(f"rating.tool.{key} must be a RackTool or a PinionCutter, got "
                                      f"{type(tool).__name__}.")
            object.__setattr__(self, "tools", MappingProxyType(dict(self.tools)))
        if isinstance(self.material, str):
            object.__setattr__(self, "material", material(self.material))
        elif isinstance(self.material, Mapping):
            object.__setattr__(self, "material", MappingProxyType(
                {k: material(v) if isinstance(v, str) else v for k, v in self.material.items()}))
        for key, kind in (("micropitting", MicropittingSpec),):
            if getattr(self, key) is not None and not isinstance(getattr(self, key), kind):
                raise RatingError(f"rating.{key} must be a {kind.__name__}, got {type(getattr(self, key)).__name__}.")

    # ------------------------------------------------------------------ required values
    def material_of(self, element: str, gear: str) -> Material:
        """The material of ``gear`` of ``element`` (``"P1:ring"``, then ``"ring"``, then the one for all).

        Parameters
        ----------
        element : str
            The set or stage.
        gear : str
            The gear's name in it (``sun``, ``planet``, ``ring``, ``driving`` ...).

        Returns
        -------
        Material

        Raises
        ------
        RatingError
            No material is given for it: the key and the suggested material are named.
        """
        given = self.material
        if isinstance(given, Material):
            return given
        if isinstance(given, Mapping):
            return _per_gear(given, "material", element, gear, f"'{SUGGESTED['material']}'")
        raise _missing("material", "a material of the data file for every gear, see docs/rating.md")

    def rim_of(self, element: str, gear: str) -> float | None:
        """The rim thickness s_R of ``gear`` of ``element`` in mm, None for a solid gear.

        Parameters
        ----------
        element : str
            The set or stage.
        gear : str
            The gear's name in it.

        Returns
        -------
        float or None
        """
        rims = self.rim_thickness or {}
        return rims.get(f"{element}:{gear}", rims.get(gear))

    def check_gear_keys(self, gears) -> None:
        """Every key of a per-gear input names a rated gear (``"ring"``, ``"P1:ring"``) or is ``"all"``.

        A key that names no gear (``rim_thickness = { moon = 12 }``) would be dropped silently while the
        gear it meant is rated without it: an error naming the key and the gears.

        Parameters
        ----------
        gears : iterable of (element, gear)
            The rated gears.

        Raises
        ------
        RatingError
        """
        pairs = set(gears)
        known = {"all"} | {g for _, g in pairs} | {f"{e}:{g}" for e, g in pairs}
        for key, given in (("material", self.material), ("flank_roughness", self.flank_roughness),
                           ("root_roughness", self.root_roughness), ("rim_thickness", self.rim_thickness),
                           ("tool", self.tools)):
            if not isinstance(given, Mapping):
                continue
            unknown = sorted(k for k in given if k not in known)
            if unknown:
                names = ", ".join(sorted({g for _, g in pairs})) or "none"
                raise RatingError(f"rating.{key}.{unknown[0]} names no gear of the rated train (gears: {names}); "
                                  "write a gear's name, 'ELEMENT:GEAR' or 'all'.")

    def tool_of(self, element: str, gear: str, internal: bool) -> RackTool | PinionCutter | None:
        """The tool that cuts ``gear`` of ``element`` (``"P1:ring"``, then ``"ring"``, then ``"all"``), or None.

        An internal gear without a tool of its own is cut by ``cutter`` where one is given.

        Parameters
        ----------
        element : str
            The set or stage.
        gear : str
            The gear's name in it.
        internal : bool
            The gear is internal (a pinion-type cutter cuts it).

        Returns
        -------
        RackTool or PinionCutter or None
            None: no tool given (the rating takes ISO's closed form of the basic rack).

        Raises
        ------
        RatingError
            A rack-type tool for an internal gear or a pinion-type cutter for an external one.
        """
        tools = self.tools or {}
        for key in (f"{element}:{gear}", gear, "all"):
            if key in tools:
                tool = tools[key]
                if isinstance(tool, PinionCutter) != internal:
                    need = "a pinion-type cutter (give teeth = z0)" if internal else "a rack-type tool (no teeth)"
                    raise RatingError(f"rating.tool.{key}: the {'internal' if internal else 'external'} gear "
                                      f"{gear!r} of {element!r} is cut by {need}.")
                return tool
        return self.cutter if internal else None

    def roughness_of(self, key: str, element: str, gear: str) -> float:
        """R_z of ``gear`` of ``element``: ``key`` is ``flank_roughness`` or ``root_roughness``, µm.

        Parameters
        ----------
        key : str
            ``"flank_roughness"`` or ``"root_roughness"``.
        element : str
            The set or stage.
        gear : str
            The gear's name in it.

        Returns
        -------
        float

        Raises
        ------
        RatingError
            No value for that gear (the key and the value commonly taken are named).
        """
        given = getattr(self, key)
        if isinstance(given, Mapping):
            return _per_gear(given, key, element, gear, f"{SUGGESTED[key]} (R_z, µm)")
        return self.required(key)

    def required(self, key: str) -> float:
        """``flank_roughness``, ``root_roughness`` or ``viscosity_40``; an error naming the key if absent.

        Parameters
        ----------
        key : str
            One of the three keys.

        Returns
        -------
        float
        """
        value = getattr(self, key)
        if value is None:
            meaning = {"flank_roughness": "R_z of the tooth flanks in µm, for Z_R",
                       "root_roughness": "R_z of the root fillets in µm, for Y_RrelT",
                       "viscosity_40": "kinematic viscosity of the oil at 40 degC in mm^2/s, for Z_L; "
                                       "or lubricant.viscosity_40"}[key]
            raise _missing(key, meaning)
        return value

    def given_factor(self, key: str, element: str, mesh: str) -> FactorValue | None:
        """The given load factor ``key`` of ``mesh`` of ``element``, or None where it is to be computed.

        Parameters
        ----------
        key : str
            A key of :data:`~epicyclic.rating.given_factors.MESH_FACTORS` (``application_factor``,
            ``load_sharing``, ``K_v``, ``K_Hbeta``, ``K_Fbeta``, ``K_Halpha``, ``K_Falpha``).
        element, mesh : str
            The set or stage and the mesh's name.

        Returns
        -------
        FactorValue or None
        """
        return mesh_factor(getattr(self, key), element, mesh)

    def grade_of(self, element: str, gear: str) -> int:
        """The ISO 1328-1 accuracy grade of ``gear`` of ``element``.

        Parameters
        ----------
        element, gear : str
            The set or stage and the gear's name in it.

        Returns
        -------
        int

        Raises
        ------
        RatingError
            A table of grades without an entry for the gear.
        """
        grade = gear_value(self.accuracy_grade, element, gear)
        if grade is None:
            raise RatingError(f"rating.accuracy_grade has no entry for gear {gear!r} of {element!r} (keys "
                              f"{', '.join(map(repr, self.accuracy_grade))}); add {gear} = 6 or all = 6.")
        return grade

    def deviation_of(self, key: str, element: str, gear: str) -> float | None:
        """A measured deviation ``key`` (``f_pb``, ``f_falpha``, ``f_Hbeta``) of a gear in µm, or None.

        Parameters
        ----------
        key : str
            One of :data:`~epicyclic.rating.given_factors.GEAR_DEVIATIONS`.
        element, gear : str
            The set or stage and the gear's name in it.

        Returns
        -------
        float or None
            None where it follows from the accuracy grade.
        """
        value = gear_value(getattr(self, key), element, gear)
        return None if value is None else float(value)

    def to_dict(self) -> dict[str, Any]:
        """Plain data of the inputs (materials by name)."""
        m = self.material
        mats = (m.to_dict() if isinstance(m, Material) else {k: v.to_dict() for k, v in m.items()}) if m else None

        def given(value):
            if isinstance(value, Mapping):
                return {k: given(v) for k, v in value.items()}
            return float(value) if isinstance(value, FactorValue) else value

        return {"standard": f"ISO 6336:{self.standard}", "application_factor": given(self.application_factor),
                "life": self.life, "S_Hmin": self.S_Hmin, "S_Fmin": self.S_Fmin,
                "accuracy_grade": _plain(self.accuracy_grade),
                "accuracy_standard": f"ISO 1328-1:{self.accuracy_standard}",
                **{k: given(getattr(self, k)) for k in tuple(MESH_FACTORS)[1:] + GEAR_DEVIATIONS},
                "shaft_deflection": self.shaft_deflection,
                "flank_roughness": _plain(self.flank_roughness), "root_roughness": _plain(self.root_roughness),
                "viscosity_40": self.viscosity_40, "viscosity_100": self.viscosity_100,
                "tool_tip_radius": self.tool_tip_radius, "long_life": self.long_life,
                "pitting_permitted": self.pitting_permitted, "tip_relief": self.tip_relief, "material": mats,
                "rim_thickness": dict(self.rim_thickness) if self.rim_thickness else None,
                "micropitting": self.micropitting.to_dict() if self.micropitting else None,
                "scuffing": self.scuffing.to_dict() if self.scuffing is not None else None,
                "flank_fracture": self.flank_fracture.to_dict() if self.flank_fracture is not None else None,
                "tool": {k: v.to_dict() for k, v in self.tools.items()} if self.tools else None,
                "ignored": list(self.ignored)}
