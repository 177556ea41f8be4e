"""Input files and reports: TOML train descriptions, JSON, Markdown and HTML reports.

Units are handled at this edge (:mod:`epicyclic.units`); the core sees 1/min, N·m and W.
"""

from .expressions import ExpressionError, evaluate
from .overrides import OverrideError, apply_overrides
from .toml_format import InputFileError, TrainFile, Transmission, load_train_file, loads_train_file

__all__ = [
    "ExpressionError",
    "InputFileError",
    "OverrideError",
    "TrainFile",
    "Transmission",
    "apply_overrides",
    "evaluate",
    "load_train_file",
    "loads_train_file",
]
