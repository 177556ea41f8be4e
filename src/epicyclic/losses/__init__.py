"""Losses from gear geometry: mesh friction, planet bearings, drag; the efficiency they give.

* :mod:`~epicyclic.losses.tooth_loss` — Ohlendorf's tooth loss factor H_V (external and
  internal meshes) and the mesh efficiency η = 1 − μ H_V;
* :mod:`~epicyclic.losses.friction` — μ given, or Schlenk's load- and speed-dependent
  correlation (ISO/TR 14179-2);
* :mod:`~epicyclic.losses.mesh` — the meshes of a set or stage, loaded and turned by the
  element's state;
* :mod:`~epicyclic.losses.bearing` — planet-bearing friction (SKF, M = 0.5 μ P d);
* :mod:`~epicyclic.losses.drag` — load-independent drag torques, functions of speed (measured);
* :mod:`~epicyclic.losses.oil` — viscosity at any temperature (ASTM D341), density, thermal data;
* :mod:`~epicyclic.losses.clutch_drag` — open wet multi-plate clutch and brake drag: the film (Yuan et al.
  2007) and, past the peak, the oil mist (Iqbal et al. 2013);
* :mod:`~epicyclic.losses.pump` — the oil pump's drive power;
* :mod:`~epicyclic.losses.churning` — churning of dipped gears (Changenet & Velex 2007);
* :mod:`~epicyclic.losses.windage` — windage of fast gears (free disc, Dawson);
* :mod:`~epicyclic.losses.seals` — radial lip seals (ISO/TR 14179-2, Simrit);
* :mod:`~epicyclic.losses.thermal` — the housing's heat balance and the sump temperature (ISO/TR 14179-1);
* :mod:`~epicyclic.losses.spin` — all spin losses of a transmission, evaluated over arrays;
* :mod:`~epicyclic.losses.element` — all of them for one element, evaluated over arrays;
* :mod:`~epicyclic.losses.solve` — the general solver fed with the models (load-dependent: fixed point);
* :mod:`~epicyclic.losses.efficiency_map` — η and losses over speed × torque.

Lengths in mm, speeds in 1/min, torques in N·m, powers in W, viscosity in mPa·s,
roughness in µm.  See ``docs/losses.md``.
"""

from .bearing import BEARING_FRICTION, PlanetBearing
from .churning import ChurningGear
from .clutch_drag import ClutchDrag
from .drag import DragTorque
from .efficiency_map import EfficiencyMap, efficiency_map
from .element import SOURCES, ElementLosses, LossState
from .errors import LossModelError
from .friction import ConstantFriction, Lubricant, SchlenkFriction, schlenk_friction
from .mesh import MeshLoss, set_meshes, stage_meshes
from .oil import Oil
from .pump import OilPump
from .seals import ShaftSeal
from .solve import solve_batch_with_losses, solve_with_losses
from .spin import SPIN_SOURCES, SpinLosses, SpinState
from .thermal import Housing, steady_temperature
from .tooth_loss import addendum_contact_ratios, mesh_efficiency, tooth_loss_factor, tooth_loss_factor_numerical
from .windage import WindageGear

__all__ = [
    "BEARING_FRICTION", "ConstantFriction", "DragTorque", "EfficiencyMap", "ElementLosses", "LossModelError",
    "LossState", "efficiency_map", "solve_batch_with_losses", "solve_with_losses",
    "Lubricant", "MeshLoss", "PlanetBearing", "SOURCES", "SchlenkFriction", "addendum_contact_ratios",
    "mesh_efficiency", "schlenk_friction", "set_meshes", "stage_meshes", "tooth_loss_factor",
    "tooth_loss_factor_numerical", "ChurningGear", "ClutchDrag", "Housing", "Oil", "OilPump", "SPIN_SOURCES",
    "ShaftSeal", "SpinLosses", "SpinState", "WindageGear", "steady_temperature",
]
