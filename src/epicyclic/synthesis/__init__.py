"""Synthesis: from target gear ratios to transmissions (architecture, shift schedule, tooth counts).

:func:`synthesize` enumerates mechanisms (planetary sets joined by permanent
ties, :mod:`.mechanisms`), places input, output, brakes and clutches on them and
screens every placement by ratio bounds over boxes of stationary ratios
(:mod:`.screening`, vectorised over candidates with :mod:`.kinematics`), fits
the stationary ratios and the shift schedule of the survivors (:mod:`.fitting`),
chooses tooth counts that fit (:mod:`.teeth`, using :mod:`epicyclic.geometry`)
and ranks the transmissions by drive efficiency, shift-element torque, planet
speed, shafts and step smoothness with the project's solver (:mod:`.candidate`).
Independent tasks run on Dask (:mod:`.distributed`).  See ``docs/synthesis.md``.
"""

from .candidate import Candidate
from .mechanisms import Mechanism, enumerate_mechanisms
from .results import SynthesisResult
from .search import synthesize, synthesize_spec
from .spec import SynthesisError, SynthesisSpec

__all__ = ["Candidate", "Mechanism", "SynthesisError", "SynthesisResult", "SynthesisSpec", "enumerate_mechanisms",
           "synthesize", "synthesize_spec"]
