"""Tooth load capacity of every mesh: ISO 6336 Method B, editions 2006 and 2019.

Public API (stable):

* :mod:`~epicyclic.rating.life_factors` — Z_NT, Y_NT S–N curves by material treatment
  (:class:`SNCurve`, :func:`pitting_curve`, :func:`bending_curve`, :func:`pitting_life_factor`,
  :func:`bending_life_factor`) and the Palmgren–Miner sums :func:`pitting_damage`,
  :func:`bending_damage`, :func:`miner_damage`;
* result objects :class:`Factor`, :class:`GearRating`, :class:`MeshRating`, :class:`TrainRating`
  (:mod:`~epicyclic.rating.results`);
* inputs :class:`RatingSpec`, materials :func:`material` / :class:`Material` (ISO 6336-5 data file);
* :func:`rate_mesh` (one mesh, vectorised over load cases) with :class:`MeshInput`;
  :func:`rate_solution` / :func:`rate_batch` (every mesh of a solved train, one point or a
  :class:`~epicyclic.solver.batch.BatchSolution`), :func:`mesh_inputs`;
* :func:`smallest_module` (sizing);
* :mod:`~epicyclic.rating.standard` — the edition (``"2006"`` / ``"2019"``);
* :mod:`~epicyclic.rating.given_factors` — load factors given per mesh or computed
  (:class:`FactorValue`: value, source, clause);
* :mod:`~epicyclic.rating.hardness` — hardness scales (HB, HV, HRC) and their conversion;
* bearing life per ISO 281:2007 (:mod:`~epicyclic.rating.bearing_life`: :class:`BearingRating`) and
  duty cycles (:mod:`~epicyclic.rating.duty_cycle`: :class:`DutyCycle` of :class:`LoadCase` s;
  :func:`analyse_duty_cycle` → :class:`DutyCycleResult`, with :class:`BearingLife` and the tooth
  damage sums of :mod:`~epicyclic.rating.duty_damage`).

References
----------
ISO 6336-1, -2, -3 (2006 and 2019 editions); ISO 6336-5:2016; ISO 6336-6:2019 (damage sums);
ISO 281:2007 (bearing rating life).
"""

from .bearing_life import BearingLifeError, BearingRating
from .duty_analysis import analyse_duty_cycle
from .duty_cycle import DutyCycle, DutyCycleError, LoadCase
from .duty_result import BearingLife, DutyCycleResult
from .errors import RatingError, RatingWarning
from .given_factors import FactorValue
from .life_factors import (
    TREATMENTS,
    SNCurve,
    bending_curve,
    bending_damage,
    bending_life_factor,
    miner_damage,
    pitting_curve,
    pitting_damage,
    pitting_life_factor,
)
from .materials import Material, material, material_names
from .mesh_rating import MeshInput, rate_mesh
from .results import Factor, GearRating, MeshRating, TrainRating
from .sizing import SizingResult, smallest_module
from .spec import RatingSpec
from .standard import DEFAULT_EDITION, EDITIONS, edition
from .tooth_form import Cutter
from .train import mesh_inputs, rate_batch, rate_solution

__all__ = [
    "DEFAULT_EDITION",
    "EDITIONS",
    "TREATMENTS",
    "BearingLife",
    "BearingLifeError",
    "BearingRating",
    "Cutter",
    "DutyCycle",
    "DutyCycleError",
    "DutyCycleResult",
    "Factor",
    "FactorValue",
    "GearRating",
    "LoadCase",
    "Material",
    "MeshInput",
    "MeshRating",
    "RatingError",
    "RatingSpec",
    "RatingWarning",
    "SNCurve",
    "SizingResult",
    "TrainRating",
    "analyse_duty_cycle",
    "bending_curve",
    "bending_damage",
    "bending_life_factor",
    "edition",
    "material",
    "material_names",
    "mesh_inputs",
    "miner_damage",
    "pitting_curve",
    "pitting_damage",
    "pitting_life_factor",
    "rate_batch",
    "rate_mesh",
    "rate_solution",
    "smallest_module",
]
