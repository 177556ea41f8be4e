"""The page to work in: ``epicyclic serve`` (Starlette, Jinja2 templates, htmx).

Open a bundled example or your own TOML file, edit it, change the operating
point and see the tables, the efficiency, self-locking, the pictures and the
worked solution update; transmissions, geometry forms and downloads.

Architecture (data flows one way): the browser sends the page's form
(:mod:`~epicyclic.web.state`); the server (:mod:`~epicyclic.web.app`) checks
its size and hands it to a worker process (:mod:`~epicyclic.web.jobs`), where
:mod:`~epicyclic.web.views` reads it with the library and renders HTML; load
errors are placed at their line (:mod:`~epicyclic.web.editor`).  Pictures
(:mod:`~epicyclic.web.figures`) and geometry forms (:mod:`~epicyclic.web.tools`)
are tables of entries: a new kind is one more entry.
"""

from .app import Limits, create_app

__all__ = ["Limits", "create_app"]
