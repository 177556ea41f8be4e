"""Jupyter previews of the descriptions: a set, a train or a transmission shows itself before it is solved.

The results render themselves (``_repr_html_``); the descriptions are drawn by
:mod:`epicyclic.plotting.preview`, a layer above the model, so the model cannot call it without an
import cycle. Instead :func:`register` hands IPython's HTML formatter one function per type
(``for_type_by_name``: nothing is imported until an object is shown): a :class:`~epicyclic.PlanetarySet`
shows its gears and key figures, a :class:`~epicyclic.GearTrain` its lever diagram and elements, a
:class:`~epicyclic.transmission.Transmission` its lever diagram and the schedule with ratios and steps.
``import epicyclic`` registers them in a running IPython (a notebook); call :func:`register` yourself
where IPython starts after epicyclic was imported.
"""

from __future__ import annotations

import sys
from typing import Any

__all__ = ["register", "PREVIEWS"]

#: (module, class name, function of epicyclic.plotting.preview) of every previewed type.
PREVIEWS = (("epicyclic.model.planetary", "PlanetarySet", "set_html"),
            ("epicyclic.model.train", "GearTrain", "train_html"),
            ("epicyclic.transmission.transmission", "Transmission", "transmission_html"))


def _preview(function: str) -> Any:
    def show(obj: Any) -> str:
        from .plotting import preview

        return getattr(preview, function)(obj)

    show.__name__ = function
    return show


def register(shell: Any = None) -> bool:
    """Register the HTML previews with IPython's display formatter.

    Parameters
    ----------
    shell : IPython InteractiveShell, optional
        Default: the running one (``IPython.get_ipython()``), if IPython is imported.

    Returns
    -------
    bool
        Whether a shell was found and the previews registered.
    """
    if shell is None:
        ipython = sys.modules.get("IPython")
        shell = ipython.get_ipython() if ipython is not None and hasattr(ipython, "get_ipython") else None
    if shell is None:
        return False
    formatter = shell.display_formatter.formatters["text/html"]
    for module, name, function in PREVIEWS:
        formatter.for_type_by_name(module, name, _preview(function))
    return True
