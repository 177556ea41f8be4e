"""Tooth flank fracture (ISO/TS 6336-4:2019, simplified) and the hardened-layer check.

* :mod:`.subsurface` — the Hertzian line contact along the depth (Johnson 1985);
* :mod:`.hardness` — the hardness profile HV(y), measured or estimated from HV_s, HV_c and CHD;
* :mod:`.spec` — :class:`FlankFractureSpec`, the ``[rating.flank_fracture]`` inputs;
* :mod:`.rating` — :func:`rate_flank_fracture`: A_FF along the depth, S_FF, CHD_req.

References
----------
ISO/TS 6336-4:2019; ISO 2639:2002; K. L. Johnson, Contact Mechanics, CUP 1985, §4.6.
"""

from .hardness import LIMIT_HARDNESS, HardnessProfile
from .rating import material_exposure, rate_flank_fracture, required_case_depth
from .spec import DEFAULT_SHEAR_STRENGTH_FACTOR, FlankFractureSpec
from .subsurface import axis_stresses, half_width, principal_shear, principal_shear_peak

__all__ = ["DEFAULT_SHEAR_STRENGTH_FACTOR", "LIMIT_HARDNESS", "FlankFractureSpec", "HardnessProfile",
           "axis_stresses", "half_width", "material_exposure", "principal_shear", "principal_shear_peak",
           "rate_flank_fracture", "required_case_depth"]
