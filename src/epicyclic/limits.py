"""The limits on what epicyclic reads, builds and draws, in one place.

Every input channel — a train file, a unit string, an expression, a command
line option — is checked against these named constants *before* the work
starts, so that a careless or hostile input is answered at once with a clear
error (exit code 2 on the command line) instead of minutes of work, a
``MemoryError`` or a hang.  ``docs/limits.md`` lists every limit and what
happens past it; keep the two in step.

The values are generous for real gear trains (an eight-speed automatic has 4
sets and 5 shift elements; real gears have 10–300 teeth) and small enough that
the largest input allowed is handled in about a second.

Examples
--------
>>> from epicyclic import limits
>>> limits.MAX_FILE_BYTES
1048576
>>> limits.check_range(150, "--dpi", limits.DPI_RANGE)
150
>>> limits.check_range(0, "--dpi", limits.DPI_RANGE)
Traceback (most recent call last):
...
epicyclic.limits.LimitError: --dpi: 0 is outside the accepted range 20 … 600 (see docs/limits.md).
"""

from __future__ import annotations

import os

from .errors import EpicyclicError

__all__ = [
    "LimitError",
    "MAX_FILE_BYTES",
    "FILE_BYTES_VARIABLE",
    "max_file_bytes",
    "MAX_NESTING",
    "MAX_TOML_VALUES",
    "MAX_STRING_CHARS",
    "MAX_TITLE_CHARS",
    "MAX_NAME_CHARS",
    "MAX_ELEMENTS",
    "MAX_SHAFTS",
    "MAX_GEARS",
    "MAX_MESHES",
    "MIN_TEETH",
    "MAX_TEETH",
    "MAX_PLANETS",
    "RATIO_RANGE",
    "MAX_EXPRESSION_CHARS",
    "MAX_EXPRESSION_EXPONENT",
    "MAX_UNIT_CHARS",
    "MAX_UNIT_POWER",
    "MAX_DECIMAL_EXPONENT",
    "UNIT_FACTOR_RANGE",
    "DPI_RANGE",
    "FRAMES_RANGE",
    "FPS_RANGE",
    "SIZE_RANGE",
    "MODULE_RANGE",
    "MAX_TOOTH_HEIGHT_FACTOR",
    "MAX_SYNTHESIS_SETS",
    "MAX_SYNTHESIS_ELEMENTS",
    "MAX_SYNTHESIS_GEARS",
    "MAX_MAP_POINTS",
    "MAX_MAP_VALUES",
    "OIL_TEMPERATURE_RANGE",
    "MAX_PLATE_GAPS",
    "SEAL_DIAMETER_RANGE",
    "check_range",
    "check_count",
]

# ---------------------------------------------------------------- files
#: Largest input file read (bytes): 1 MiB, a hundred times the largest example.
MAX_FILE_BYTES = 1 << 20
#: Environment variable that raises (or lowers) :data:`MAX_FILE_BYTES` for one run.
FILE_BYTES_VARIABLE = "EPICYCLIC_MAX_FILE_BYTES"
#: Deepest nesting of arrays and tables in a TOML file (the format needs 5).
MAX_NESTING = 16
#: Most keys and values in a TOML file (keys, strings, arrays, tables, list items); the
#: largest example holds about 400.
MAX_TOML_VALUES = 20_000
#: Longest string value anywhere in a file (characters), e.g. a ``description``.
MAX_STRING_CHARS = 10_000
#: Longest ``title`` (characters).
MAX_TITLE_CHARS = 200
#: Longest name of a shaft, element or gear (characters).
MAX_NAME_CHARS = 64

# ---------------------------------------------------------------- trains
#: Most elements (sets, stages, clutches, brakes) in one train.
MAX_ELEMENTS = 200
#: Most shafts in one train (the housing included).
MAX_SHAFTS = 400
#: Most gears in a ``[transmission]`` schedule.
MAX_GEARS = 64
#: Most meshes in one fixed-axis stage.
MAX_MESHES = 32
#: Fewest teeth of a gear (below 3 no involute gear exists).
MIN_TEETH = 3
#: Most teeth of a gear (large slewing rings have a few hundred).
MAX_TEETH = 1000
#: Accepted |stationary_ratio| and |ratio| in files and ``modes --i0`` (real sets and stages lie
#: within 1/100 … 100; beyond this range a train is numerically singular).
RATIO_RANGE = (1e-6, 1e6)
#: Most planets of one set.
MAX_PLANETS = 24

# ---------------------------------------------------------------- numbers and units
#: Longest arithmetic expression such as ``"(24/50)*(42/30)"`` (characters).
MAX_EXPRESSION_CHARS = 200
#: Largest |exponent| in ``a ** b`` inside an expression.
MAX_EXPRESSION_EXPONENT = 16
#: Longest unit string such as ``"1500 U/min"`` (characters).
MAX_UNIT_CHARS = 200
#: Largest |power| of one unit name in a unit expression (``m**2``, ``s^-3``).
MAX_UNIT_POWER = 4
#: Largest |decimal exponent| of a number in a unit string (``1e308``); beyond it a double overflows.
MAX_DECIMAL_EXPONENT = 308
#: Core units per chosen unit, ``[units]`` only: a unit outside this range is degenerate.
UNIT_FACTOR_RANGE = (1e-12, 1e12)

# ---------------------------------------------------------------- pictures
#: ``plot --dpi`` (dots per inch of PNG output).
DPI_RANGE = (20, 600)
#: ``animate --frames`` (frames of one loop).
FRAMES_RANGE = (2, 240)
#: ``animate --fps`` (frames per second).
FPS_RANGE = (1, 60)
#: ``animate --size``: width of the SVG or GIF in pixels.
SIZE_RANGE = (120, 2000)

# ---------------------------------------------------------------- gear geometry
#: Normal module of a geometry table and of ``search --module``, mm (watch gears have about 0.05 mm,
#: the largest industrial gears about 50 mm); past 1e154 mm the squared radii overflow.
MODULE_RANGE = (1e-3, 100.0)
#: Addendum and dedendum of the basic rack, multiples of the module (ISO 53: 1 and 1.25).
MAX_TOOTH_HEIGHT_FACTOR = 5.0

# ---------------------------------------------------------------- efficiency maps
#: Most grid points (speed values × torque values) of one efficiency map (``map``, the page's form).
MAX_MAP_POINTS = 1_000_000
#: Most values along one axis of an efficiency map (``A..B:N``).
MAX_MAP_VALUES = 10_000

# ---------------------------------------------------------------- spin losses and the oil
#: Oil temperatures a viscosity or a spin loss is evaluated at, and the hottest sump the heat balance
#: searches, °C (ASTM D341's line is used from the cloud point to the onset of decomposition).
OIL_TEMPERATURE_RANGE = (-40.0, 200.0)
#: Most oil films (friction surfaces) of one clutch or brake (automatic transmissions: 4 … 20).
MAX_PLATE_GAPS = 100
#: Shaft diameters of a radial lip seal, mm.
SEAL_DIAMETER_RANGE = (5.0, 1000.0)

# ---------------------------------------------------------------- synthesis
#: Most planetary sets of a synthesis (five sets have ~10^7 tie patterns before any placement).
MAX_SYNTHESIS_SETS = 4
#: Most shift elements (brakes + clutches) of a synthesis.
MAX_SYNTHESIS_ELEMENTS = 8
#: Most target ratios (forward and reverse) of a synthesis.
MAX_SYNTHESIS_GEARS = 16


class LimitError(EpicyclicError, ValueError):
    """An input past one of the limits of this module.

    Attributes
    ----------
    field : str
        What was given (an option such as ``"--dpi"`` or a key).
    """

    def __init__(self, message: str, field: str = ""):
        self.field = field
        super().__init__(message)


def max_file_bytes() -> int:
    """The file size limit of this run: ``$EPICYCLIC_MAX_FILE_BYTES`` if set, else :data:`MAX_FILE_BYTES`.

    Raises
    ------
    LimitError
        The variable is set but is not a positive whole number.
    """
    text = os.environ.get(FILE_BYTES_VARIABLE)
    if text is None or not text.strip():
        return MAX_FILE_BYTES
    try:
        value = int(text)
    except ValueError:
        value = 0
    if value <= 0:
        raise LimitError(f"{FILE_BYTES_VARIABLE}={text[:40]!r}: expected a positive whole number of bytes, "
                         f"e.g. {MAX_FILE_BYTES}.", FILE_BYTES_VARIABLE)
    return value


def check_range(value: int | float, field: str, bounds: tuple[int | float, int | float]) -> int | float:
    """Return ``value`` if ``bounds[0] <= value <= bounds[1]``, else raise :class:`LimitError`.

    Parameters
    ----------
    value : int or float
        The number to check (NaN is outside every range).
    field : str
        Where it came from, the start of the message (e.g. ``"geometry.module"``).
    bounds : tuple of (int or float, int or float)
        The accepted range, both ends included (one of the ``*_RANGE`` constants here).

    Returns
    -------
    int or float
        ``value`` unchanged.

    Raises
    ------
    LimitError
        ``value`` outside ``bounds``; the message names ``field`` and the range.

    Examples
    --------
    >>> check_range(2.5, "geometry.module", MODULE_RANGE)
    2.5
    """
    low, high = bounds
    if not low <= value <= high:  # also False for NaN
        raise LimitError(f"{field}: {value!r} is outside the accepted range {low} … {high} (see docs/limits.md).",
                         field)
    return value


def check_count(count: int, field: str, maximum: int, what: str) -> int:
    """Return ``count`` if it is at most ``maximum``, else raise :class:`LimitError`.

    Parameters
    ----------
    count : int
        How many were given.
    field : str
        Where they came from, the start of the message (e.g. ``"planetary"``).
    maximum : int
        The most accepted (one of the ``MAX_*`` constants here).
    what : str
        What is counted, plural, for the message (e.g. ``"elements"``).

    Returns
    -------
    int
        ``count`` unchanged.

    Raises
    ------
    LimitError
        ``count > maximum``.
    """
    if count > maximum:
        raise LimitError(f"{field}: {count} {what} given; at most {maximum} are accepted (see docs/limits.md).",
                         field)
    return count
