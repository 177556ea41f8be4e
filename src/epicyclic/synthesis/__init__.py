"""Synthesis: from target gear ratios to transmissions (architecture, shift schedule, tooth counts).

:func:`synthesize` enumerates mechanisms (planetary sets joined by permanent
ties, :mod:`.mechanisms`), places input, output, brakes and clutches on them and
screens every placement by ratio bounds over boxes of stationary ratios
(:mod:`.screening`, vectorised over candidates with :mod:`.kinematics`), fits
the stationary ratios and the shift schedule of the survivors (:mod:`.fitting`),
chooses tooth counts that fit (:mod:`.teeth`, using :mod:`epicyclic.geometry`)
and ranks the transmissions by weighted criteria from the project's solver —
losses, circulating power, element torques and slip, planet speeds, ring sizes,
steps, single-swap shifts — with a Pareto front and explanations
(:mod:`.candidate`, :mod:`.ranking`).  Every search is sized and bounded before it
starts (:mod:`.estimate`); independent tasks run in this process or on Dask
(:mod:`.distributed`).  See ``docs/synthesis.md``.
"""

from .candidate import Candidate
from .mechanisms import Mechanism, enumerate_mechanisms
from .results import SynthesisResult
from .search import synthesize, synthesize_spec
from .spec import SynthesisError, SynthesisSpec

__all__ = ["Candidate", "Mechanism", "SynthesisError", "SynthesisResult", "SynthesisSpec", "enumerate_mechanisms",
           "synthesize", "synthesize_spec"]
