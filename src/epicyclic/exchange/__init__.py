"""REXS exchange: read and write gearboxes in the Reusable Engineering EXchange Standard.

REXS (FVA GmbH) is how KISSsoft, FVA-Workbench, MASTA and Bearinx exchange
gearbox models.  This package reads REXS 1.x in its three containers (XML
``.rexs``, JSON ``.rexsj``, zip ``.rexsz``) onto the train description of a
TOML file (:mod:`~epicyclic.exchange.mapping`), and writes a train
description as REXS 1.7 (:mod:`~epicyclic.exchange.writing`).  Every
command that reads a train file reads REXS (``epicyclic.io.load_train_file``
dispatches by content); ``epicyclic convert`` converts both ways.

References
----------
REXS specification and database: github.com/fva-net/rexs-api-java, github.com/BearinxSimulationSuite/REXSapi
(FVA GmbH, Apache-2.0); docs/how-to/rexs.md.
"""

from .mapping import RexsDocument
from .operating import RexsLoadCase
from .reading import is_rexs, load_rexs_document, loads_rexs_document

__all__ = ["RexsDocument", "RexsLoadCase", "is_rexs", "load_rexs_document", "loads_rexs_document"]
