"""Read-only mappings pickle, so every value object does.

The value objects of epicyclic (a :class:`~epicyclic.Solution`, an operating point, a
transmission and its analysis, a set's geometry, a fitting report, ...) are frozen dataclasses
whose mappings are read-only views, :class:`types.MappingProxyType`: a user cannot change a
solution through ``sol.shafts[...] = ...``.  The standard library cannot pickle such a view,
so without help none of these objects could be sent to another process (``multiprocessing``,
``concurrent.futures``, Dask) or deep-copied.  This module teaches :mod:`copyreg` to pickle a
view as the plain dict it shows and to rebuild a read-only view from it; it is imported with
the package, so the rule holds wherever an epicyclic object exists.  It changes nothing that
pickled before (a read-only view could not be pickled at all).

Examples
--------
>>> import pickle
>>> from types import MappingProxyType
>>> view = pickle.loads(pickle.dumps(MappingProxyType({"sun": 3000.0})))
>>> type(view).__name__, dict(view)
('mappingproxy', {'sun': 3000.0})
"""

from __future__ import annotations

import copyreg
from collections.abc import Mapping
from types import MappingProxyType

__all__ = ["read_only"]


def read_only(items: Mapping) -> Mapping:
    """A read-only view of a copy of ``items`` (what an unpickled view is rebuilt with)."""
    return MappingProxyType(dict(items))


def _reduce(view: MappingProxyType) -> tuple:
    return read_only, (dict(view),)


copyreg.pickle(MappingProxyType, _reduce)
