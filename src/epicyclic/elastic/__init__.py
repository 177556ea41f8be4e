"""The planetary set as an elastic, vibrating system: stiffnesses, natural modes, mesh phasing, load sharing.

* :mod:`~epicyclic.elastic.stiffness` — mesh stiffness c', c_γα of ISO 6336-1 (used by the rating too);
* :mod:`~epicyclic.elastic.lumped` — the lumped-parameter model of Lin & Parker (1999) (stepped planets too),
  :mod:`~epicyclic.elastic.double` of double-planet sets;
* :mod:`~epicyclic.elastic.modes` — natural frequencies, mode types, modal strain energy, speed;
* :mod:`~epicyclic.elastic.phasing` — mesh phasing: which mesh harmonics excite which modes (Parker & Lin 2004);
* :mod:`~epicyclic.elastic.campbell` — Campbell diagram: mesh and shaft orders, crossings over speed;
* :mod:`~epicyclic.elastic.sharing` — static load sharing among the planets, K_γ (one-sided contact,
  :mod:`~epicyclic.elastic.contact`), over torque, carrier angle and Monte-Carlo draws;
* :mod:`~epicyclic.elastic.face_load` — face load distribution of a mesh (slice model), K_Hβ, K_Fβ, crowning.

References
----------
J. Lin, R. G. Parker, J. Vib. Acoust. 121 (1999) 316–321; R. G. Parker, J. Lin, J. Mech. Des. 126 (2004)
365–370; A. Kahraman, Mech. Mach. Theory 29 (1994) 1151–1165; ISO 6336-1:2006, 9.3.
"""

from .campbell import CampbellDiagram, campbell_diagram
from .double import DoublePlanetModel
from .errors import ElasticError
from .face_load import FaceLoad, HelixModification, best_crowning, face_load
from .lumped import Body, PlanetaryLumpedModel, equally_spaced
from .modes import NaturalModes, frequencies_at_speeds, natural_modes
from .phasing import MeshPhasing, mesh_phasing
from .sharing import (
    PlanetErrors,
    Tolerances,
    load_sharing,
    monte_carlo_sharing,
    sharing_over_revolution,
    sharing_over_torque,
)
from .sharing_results import PlanetLoads, SharingStudy

__all__ = ["ElasticError", "Body", "DoublePlanetModel", "PlanetaryLumpedModel", "equally_spaced", "NaturalModes", "natural_modes",
           "frequencies_at_speeds", "MeshPhasing", "mesh_phasing",
           "CampbellDiagram", "campbell_diagram", "PlanetErrors", "Tolerances", "load_sharing",
           "monte_carlo_sharing", "sharing_over_revolution", "sharing_over_torque", "PlanetLoads", "SharingStudy",
           "FaceLoad", "HelixModification", "face_load", "best_crowning"]
