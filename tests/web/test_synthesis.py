"""The Synthesis tab, server side: the size before a search, the page's bound, progress, Cancel, hostile input,
and a candidate opened in the editor that is the file ``epicyclic synthesize --out-dir`` writes.

The search of the tests is the Simpson (Ford C4) three-speed of ``examples/synthesis/simpson_3speed.toml``
(ratios 2.46, 1.46, 1.00, reverse -2.18: "Ford C4 transmission", Wikipedia), about a second on one worker; the
long search that is cancelled has three sets and three clutches (381 tasks, minutes of fitting).
"""

from __future__ import annotations

import html
import re
import threading
import time
from pathlib import Path

import pytest
from typer.testing import CliRunner

from epicyclic.synthesis import SynthesisSpec
from epicyclic.synthesis.estimate import count, estimate
from epicyclic.synthesis.search import plan
from epicyclic.web.synthesis_tool import FIELDS, read_spec

EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "synthesis"
SIMPSON = EXAMPLES / "simpson_3speed.toml"
#: Three sets, two brakes and three clutches, two engaged: 381 tasks, some of them tens of seconds.
LONG = {"synth_forward": "2.40, 1.47, 1.0, 0.67", "synth_reverse": "-2.0", "synth_simple": "3", "synth_clutches": "3",
        "synth_engaged": "2"}


def _candidate_texts(page: str) -> list[str]:
    """The train files the "Open in editor" buttons of an answer carry, best first."""
    return [html.unescape(t) for t in re.findall(r'data-toml="([^"]*)"', page)]


def _start(client, fields: dict, search_id: str, client_id: str = "test-page") -> object:
    return client.post("/synthesis/start", data={"synth_mode": "form", "synth_id": search_id, **fields},
                       headers={"X-Epicyclic-Client": client_id})


def test_the_form_starts_as_the_simpson_spec():
    spec, text = read_spec({})
    assert spec == SynthesisSpec.from_file(SIMPSON)  # same targets, sets, elements, bounds (not the source)
    assert SynthesisSpec.from_text(text, "again") == spec  # the TOML shown is what is searched
    assert {f.name for f in FIELDS} >= {"synth_forward", "synth_reverse", "synth_tolerance", "synth_sun"}


def test_the_size_is_stated_before_the_search(client):
    answer = client.post("/synthesis/estimate", data={"synth_mode": "form"})
    assert answer.status_code == 200
    spec = SynthesisSpec.from_file(SIMPSON)
    tasks = plan(spec, 1)
    bound = count(spec, (m for t in tasks for m in t.mechanisms))
    text = html.unescape(answer.text)
    assert "Before it runs" in text and bound.describe() in text and estimate(spec).describe() in text
    assert f"{len(tasks)} task(s)" in text and "60 s" in text  # the page's time limit is said


def test_a_search_larger_than_the_page_is_refused_with_the_command_line(client):
    pasted = (EXAMPLES / "ten_speed_10r80.toml").read_text()  # about 7e9 architectures
    answer = client.post("/synthesis/estimate", data={"synth_mode": "toml", "synth_spec": pasted})
    text = html.unescape(answer.text)
    assert answer.status_code == 200 and "too large for the page" in text
    assert "2e+07 architectures" in text and "epicyclic synthesize spec.toml" in text
    started = client.app.state.searches.started
    answer = _start(client, {"synth_mode": "toml", "synth_spec": pasted}, "refused-0001")
    assert answer.status_code == 422 and "too large for the page" not in answer.text  # the message, not the box
    assert "more than the page runs" in html.unescape(answer.text)
    assert client.app.state.searches.started == started + 1 and not client.app.state.searches.running


@pytest.mark.parametrize("fields, named", [
    ({"synth_forward": "2.46, abc"}, "[targets], key 'forward'"),
    ({"synth_forward": "nan"}, "[targets], key 'forward'"),
    ({"synth_forward": "1e999"}, "[targets], key 'forward'"),
    ({"synth_forward": ", ".join(["2"] * 40)}, "[targets], key 'forward'"),  # more gears than a spec holds
    ({"synth_tolerance": "inf"}, "[targets], key 'tolerance'"),
    ({"synth_simple": "1000000000"}, "[sets]"),
    ({"synth_brakes": "-1"}, "[elements], key 'brakes'"),
    ({"synth_brakes": "2.5"}, "[elements], key 'brakes'"),
    ({"synth_sun": "3..100000"}, "[bounds], key 'sun'"),
    ({"synth_planets": "10**9"}, "[bounds], key 'planets'"),
    ({"synth_stationary_ratio": "4"}, "[bounds], key 'stationary_ratio'"),
    ({"synth_hunting": "maybe"}, "[bounds], key 'hunting'"),
    ({"synth_input_members": "planet"}, "[search], key 'input_members'"),
    ({"synth_mode": "<script>"}, "synthesis: the spec comes from form or toml"),
    ({"synth_mode": "toml", "synth_spec": "[targets\nforward = 1"}, "pasted spec: not valid TOML"),
    ({"synth_mode": "toml", "synth_spec": ""}, "pasted spec: the text is empty"),
    ({"synth_mode": "toml", "synth_spec": "[targets]\nforward = [2.0, 1.0]\n[search]\nmax_architectures = 1e9\n"
                                          "[sets]\nsimple = 4\n[elements]\nbrakes = 3\nclutches = 4\n"},
     "[search], key 'max_architectures'"),  # 10^9 architectures asked for: over the spec's own bound
])
def test_hostile_input_gets_the_problem_box_naming_the_field(client, fields, named):
    for path in ("/synthesis/estimate", "/synthesis/start"):
        answer = client.post(path, data={"synth_mode": "form", "synth_id": "hostile-001", **fields})
        assert answer.status_code == 422, answer.text
        assert 'class="problem"' in answer.text and "Traceback" not in answer.text
        assert named in html.unescape(answer.text)
        assert "<script>" not in answer.text  # escaped


def test_bad_forms_and_foreign_pages_are_refused(client):
    started = client.app.state.searches.started
    assert _start(client, {}, "no").status_code == 400  # an id the page did not make
    assert client.post("/synthesis/estimate", data={"synth_spec": "x" * 70000, "synth_mode": "toml"}).status_code == 400
    foreign = client.post("/synthesis/start", data={"synth_id": "foreign-0001"},
                          headers={"Origin": "http://elsewhere.example", "Sec-Fetch-Site": "cross-site"})
    assert foreign.status_code == 403
    assert client.app.state.searches.started == started
    # progress and Cancel of a search that is not running (or another page's): nothing to do
    assert client.post("/synthesis/progress", data={"synth_id": "nothing-001"}).status_code == 286
    assert client.post("/synthesis/cancel", data={"synth_id": "nothing-001"}).status_code == 204


def test_the_candidate_opened_is_the_file_the_command_line_writes(client, tmp_path):
    from epicyclic.cli.main import app

    cli = CliRunner().invoke(app, ["synthesize", str(SIMPSON), "--out-dir", str(tmp_path), "--workers", "1", "-q"])
    assert cli.exit_code == 0, cli.output
    answer = client.post("/synthesis/start", data={"synth_mode": "toml", "synth_spec": SIMPSON.read_text(),
                                                   "synth_id": "simpson-toml-1"})
    assert answer.status_code == 200 and 'data-complete="yes"' in answer.text
    texts = _candidate_texts(answer.text)
    assert texts and len(texts) == len(list(tmp_path.glob("candidate_*.toml")))
    assert texts[0] == (tmp_path / "candidate_01.toml").read_text(encoding="utf-8")
    assert "Pareto" in answer.text and "Why this order" in answer.text
    opened = client.post("/synthesis/open", data={"toml": texts[0], "name": "candidate_01-0000.toml"})
    assert opened.status_code == 200
    assert "candidate 1" in opened.text and 'id="efficiency"' in opened.text and "candidate_01-0000.toml" in opened.text


def test_progress_then_cancel_keeps_the_candidates_found(client):
    searches, jobs = client.app.state.searches, client.app.state.jobs
    answers: list = []
    worker = threading.Thread(target=lambda: answers.append(_start(client, LONG, "long-search-01")))
    worker.start()
    try:
        deadline, progress = time.monotonic() + 60, ""
        while time.monotonic() < deadline:
            reply = client.post("/synthesis/progress", data={"synth_id": "long-search-01"},
                                headers={"X-Epicyclic-Client": "test-page"})
            done = re.search(r'data-done="(\d+)"', reply.text)
            if reply.status_code == 200 and done and int(done.group(1)) >= 3:
                progress = html.unescape(reply.text)
                break
            time.sleep(0.2)
        assert "Searching:" in progress and "/381 tasks" in progress and "candidate(s) so far" in progress
        assert "about" in progress and "left" in progress  # the time left, from the tasks done
        assert "381 task(s) on 1 local worker thread, stopped after 60 s" in progress  # the search's announcement
        # one search per page, and one at a time on this two-worker server
        assert _start(client, {}, "second-search-1").status_code == 429
        assert _start(client, {}, "other-page-0001", client_id="other-page").status_code == 503
        # another page cannot cancel it
        client.post("/synthesis/cancel", data={"synth_id": "long-search-01"}, headers={"X-Epicyclic-Client": "x"})
        time.sleep(0.3)
        assert worker.is_alive()
        cancelled, pressed = jobs.cancelled, time.monotonic()
        assert client.post("/synthesis/cancel", data={"synth_id": "long-search-01"},
                           headers={"X-Epicyclic-Client": "test-page"}).status_code == 204
        worker.join(timeout=20)
        took = time.monotonic() - pressed
    finally:
        worker.join(timeout=120)
    assert not worker.is_alive() and took < 10  # the worker is stopped, not waited for (a task can take 40 s)
    answer = answers[0]
    text = html.unescape(answer.text)
    assert answer.status_code == 200 and "The search was cancelled" in text and 'data-complete="no"' in text
    found = int(re.search(r"(\d+) candidate\(s\) so far", progress).group(1))
    assert len(_candidate_texts(answer.text)) >= min(found, 20)  # what was found by then is kept (top 20 shown)
    assert "INCOMPLETE: cancelled after" in text
    assert jobs.cancelled == cancelled + 1 and not searches.running
    assert not any(searches.root.iterdir())  # the search's folder is gone


def test_the_page_stops_a_search_at_its_time_limit():
    from starlette.testclient import TestClient

    from epicyclic.web import Limits, create_app

    with TestClient(create_app(Limits(workers=1, synthesis_seconds=2.0))) as small:
        answer = _start(small, LONG, "limited-0001")
    text = html.unescape(answer.text)
    assert answer.status_code == 200 and 'data-complete="no"' in text
    assert "stopped at the page's limit of 2 s" in text


def test_a_search_stopped_before_any_task_finished_does_not_say_the_targets_are_unmet(tmp_path):
    """Cancel pressed before the first task is done: the answer says nothing finished, not "no transmission meets"."""
    from epicyclic.web.synthesis_tool import partial_view

    fields = {"synth_mode": "form", **LONG}
    reply = partial_view(fields, str(tmp_path), "cancelled")
    text = html.unescape(reply.body)
    assert reply.status == 200
    assert "The search was cancelled; 0 candidate(s) of the 0 finished task(s) are kept." in text
    assert "No task had finished when the search stopped" in text
    assert "No transmission meets the targets" not in text


def test_the_time_left_is_never_past_the_pages_limit(tmp_path):
    """Issue 30: a search the page stops at 60 s never says "about 7 min left": it says when the page stops it
    and how long the whole space would take (and the command for it)."""
    import time as clock

    from epicyclic.web.synthesis_routes import Search, progress_state

    search = Search("c", tmp_path, seconds=60.0)
    state = progress_state({"done": 1, "total": 50, "found": 0, "started": clock.time() - 10}, search)
    assert state["eta"] in ("50 s", "49 s", "51 s"), state["eta"]  # 10 s per task × 49 left = 490 s: cut at 60 s
    assert "stops the search at 60 s" in state["stops"] and "epicyclic synthesize" in state["stops"], state["stops"]
    short = progress_state({"done": 5, "total": 6, "found": 0, "started": clock.time() - 10}, search)
    assert short["stops"] == "" and short["eta"] == "2 s"


def test_the_candidate_table_names_the_units_of_its_columns():
    from epicyclic.synthesis.results import SynthesisResult

    assert {"T elem max /T_in", "T elem sum /T_in", "P circ max /P_in"} <= set(SynthesisResult.HEADER)
