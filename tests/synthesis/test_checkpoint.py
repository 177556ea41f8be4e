"""Resumable searches: finished tasks are kept in an atomically written checkpoint and never run again;
results stream back as tasks finish."""

from __future__ import annotations

import os
import pickle
from dataclasses import replace

import pytest

from epicyclic.synthesis import SynthesisError, SynthesisSpec, synthesize_spec
from epicyclic.synthesis import search as search_module

SPEC = SynthesisSpec.create([2.46, 1.46, 1.0, -2.18], 2, {"brakes": 2, "clutches": 2}, {"tolerance": 0.01})


@pytest.fixture(scope="module")
def full():
    return synthesize_spec(SPEC, workers=1, announce=False)


def test_an_interrupted_search_resumes_without_recomputing(tmp_path, full, monkeypatch):
    path = tmp_path / "search.ckpt"
    first = synthesize_spec(replace(SPEC, time_limit=0.05), workers=1, announce=False, checkpoint=path)
    assert path.exists() and not first.stats["complete"]
    done_before = first.stats["tasks_done"]
    calls = []
    real = search_module.search_task
    monkeypatch.setattr(search_module, "search_task", lambda task: calls.append(task) or real(task))
    again = synthesize_spec(SPEC, workers=1, announce=False, checkpoint=path)
    assert again.stats["complete"] and again.stats["resumed_tasks"] == done_before
    assert len(calls) == again.stats["tasks"] - done_before  # only the missing tasks ran
    assert sorted(c.key for c in again.candidates) == sorted(c.key for c in full.candidates)
    calls.clear()
    third = synthesize_spec(SPEC, workers=1, announce=False, checkpoint=path)  # everything is there now
    assert calls == [] and third.stats["resumed_tasks"] == third.stats["tasks"]
    assert [c.key for c in third.candidates] == [c.key for c in again.candidates]


def test_the_checkpoint_is_replaced_atomically(tmp_path):
    path = tmp_path / "search.ckpt"
    synthesize_spec(SPEC, workers=1, announce=False, checkpoint=path)
    assert sorted(os.listdir(tmp_path)) == ["search.ckpt"]  # no temporary file left beside it


def test_a_checkpoint_of_another_search_is_refused(tmp_path):
    path = tmp_path / "search.ckpt"
    synthesize_spec(SPEC, workers=1, announce=False, checkpoint=path)
    other = SynthesisSpec.create([2.46, 1.46, 1.0, -2.18], 2, {"brakes": 2, "clutches": 2}, {"tolerance": 0.02})
    with pytest.raises(SynthesisError, match="belongs to another search"):
        synthesize_spec(other, workers=1, announce=False, checkpoint=path)
    # what only changes the ranking or the display is the same search
    same = replace(SPEC, top=3, weights=(("planet_speed", 2.0),))
    assert synthesize_spec(same, workers=1, announce=False, checkpoint=path).stats["resumed_tasks"] > 0


@pytest.mark.parametrize("payload", [b"not a pickle", pickle.dumps({"format": "something else"}),
                                     pickle.dumps(os.system)])
def test_a_file_that_is_no_checkpoint_is_refused_and_runs_nothing(tmp_path, payload):
    path = tmp_path / "search.ckpt"
    path.write_bytes(payload)
    with pytest.raises(SynthesisError, match="is not a synthesis checkpoint"):
        synthesize_spec(SPEC, workers=1, announce=False, checkpoint=path)


def test_results_stream_as_tasks_finish(full):
    batches = []
    result = synthesize_spec(SPEC, workers=1, announce=False, on_candidates=batches.append)
    assert len(batches) == result.stats["tasks"]
    assert {c.key for b in batches for c in b} == {c.key for c in full.candidates}


def test_the_task_log_keeps_every_finished_task_and_a_stopped_search_ranks_them(tmp_path, full):
    """Every task is logged as it finishes (log_task); a record cut short (a writer stopped while writing) is left
    out; the finished tasks, assembled, are the search's candidates with the reason it stopped."""
    from epicyclic.synthesis.checkpoint import log_task, logged_tasks
    from epicyclic.synthesis.estimate import count, estimate
    from epicyclic.synthesis.search import assemble, plan

    log = tmp_path / "tasks.log"
    result = synthesize_spec(SPEC, workers=1, announce=False, on_task=lambda k, r: log_task(log, k, r))
    done = logged_tasks(log)
    assert sorted(done) == list(range(result.stats["tasks"]))
    whole = log.read_bytes()
    log.write_bytes(whole[:-7])  # the last record cut short
    assert sorted(logged_tasks(log)) == list(range(result.stats["tasks"] - 1))
    assert logged_tasks(tmp_path / "none.log") == {}
    tasks = plan(SPEC)
    bound = count(SPEC, (m for t in tasks for m in t.mechanisms))
    again = assemble(SPEC, [done[k] for k in range(len(tasks))], estimate(SPEC), bound)
    assert [c.key for c in again.candidates] == [c.key for c in full.candidates]
    assert again.stats["complete"] and "stopped" not in again.stats
    half = assemble(SPEC, [done.get(k) if k < 2 else None for k in range(len(tasks))], estimate(SPEC), bound,
                    stopped="cancelled")
    assert half.stats["tasks_done"] == 2 and not half.stats["complete"]
    assert {c.key for c in half.candidates} == {c.key for k in (0, 1) for c in done[k].candidates}
    assert f"INCOMPLETE: cancelled after 2 of {len(tasks)} tasks" in half.table()


def test_the_task_log_is_read_with_the_restricted_unpickler(tmp_path):
    from epicyclic.synthesis.checkpoint import logged_tasks

    log = tmp_path / "tasks.log"
    log.write_bytes(pickle.dumps((0, os.system)))  # no callable from the file is ever built
    assert logged_tasks(log) == {}
