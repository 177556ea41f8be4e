"""Fixtures of the web tests: one app with its worker pool for the whole session, example texts."""

from __future__ import annotations

import pytest

from epicyclic.web import Limits, create_app
from epicyclic.web.examples import bundled_examples


@pytest.fixture(scope="session")
def client():
    """A Starlette test client of the app (two worker processes, default limits)."""
    from starlette.testclient import TestClient

    with TestClient(create_app(Limits(workers=2))) as test_client:
        yield test_client


@pytest.fixture(scope="session")
def examples():
    return bundled_examples()


def _form(text: str, *rows: tuple[str, str, str, str, str], **fields: str) -> dict:
    """The page's form for ``text``: operating-point rows (shaft, role, speed, moment, value) as
    parallel lists, as the browser sends them, and further fields."""
    data = {"toml": text, "source": "test.toml", "units": "file", "lang": "en", "gear": ""}
    for k, name in enumerate(("shaft", "role", "speed", "moment", "value")):
        if rows:
            data[name] = [row[k] for row in rows]
    data.update(fields)
    return data


@pytest.fixture(scope="session")
def page_form():
    """``page_form(text, *rows, **fields)``: the form the page posts."""
    return _form
