"""Scuffing load capacity: the integral and the flash temperature methods.

* :mod:`~.factors` — the factors both methods share (X_M, X_αβ, X_BE/X_G, K_Bγ, X_ε, X_Ca, X_Q,
  μ_mC, the FZG A/8.3/90 load stages);
* :mod:`~.spec` — :class:`ScuffingSpec`, the file's ``[rating.scuffing]``;
* :mod:`~.methods` — :func:`integral_temperature` (ISO/TS 6336-21:2017, ISO/TR 13989-2:2000) and
  :func:`flash_temperature` along the path of contact (ISO/TS 6336-20:2017, ISO/TR 13989-1:2000),
  vectorised over load cases;
* :mod:`~.rating` — :func:`rate_scuffing` / :func:`rate_train_scuffing` beside the ISO 6336 rating, and
  :func:`~.rating.scuffing_modes`, which :func:`~epicyclic.rating.rate_mesh` calls (through
  :mod:`epicyclic.rating.failure_modes`) when the spec has ``scuffing``: every mesh's rating then
  carries the modes ``scuffing_integral`` and ``scuffing_flash`` (``MeshRating.mode(...)``), which the
  reports of ``epicyclic rate`` show in every format;
* :mod:`~.results` — :class:`ScuffingRating` (both methods, rendered as two failure modes).

References
----------
ISO/TS 6336-20:2017, ISO/TS 6336-21:2017 (and their 2022 revisions); ISO/TR 13989-1, -2:2000;
ISO 14635-1:2000.
"""

from .methods import ScuffingInput, ScuffingLoad, flash_temperature, integral_temperature
from .rating import rate_scuffing, rate_train_scuffing, scuffing_input
from .results import ScuffingRating
from .spec import ScuffingSpec

__all__ = [
    "ScuffingInput",
    "ScuffingLoad",
    "ScuffingRating",
    "ScuffingSpec",
    "flash_temperature",
    "integral_temperature",
    "rate_scuffing",
    "rate_train_scuffing",
    "scuffing_input",
]
