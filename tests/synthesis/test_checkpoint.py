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
