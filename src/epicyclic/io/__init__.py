"""Input files and reports: TOML train descriptions, JSON, Markdown and HTML reports.

Units are handled at this edge (:mod:`epicyclic.units`); the core sees 1/min, N·m and W.
"""

from .expressions import ExpressionError, evaluate
from .located import NonFiniteResultError, check_finite, locate_error
from .overrides import OverrideError, apply_overrides
from .source import InputFileError, read_source
from .toml_format import TrainFile, Transmission, load_train_file, loads_train_file

__all__ = [
    "ExpressionError",
    "InputFileError",
    "NonFiniteResultError",
    "OverrideError",
    "TrainFile",
    "check_finite",
    "locate_error",
    "read_source",
    "Transmission",
    "apply_overrides",
    "evaluate",
    "load_train_file",
    "loads_train_file",
]
