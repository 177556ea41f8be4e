"""Which failure modes a mesh is rated for: a mesh that stands still (a set that turns as a block in a gear of a
transmission) has no lubricant film and no flash temperature, so micropitting and scuffing are not rated, and the
mesh's notes say so instead of the rating failing (ISO/TS 6336-22:2018, clause 7: the film needs the sum velocity;
ISO/TS 6336-20:2017, clause 5: the flash temperature needs the sliding velocity).  Pitting and root are rated as
before (their stresses do not need the speed)."""

import warnings
from types import SimpleNamespace

import numpy as np
import pytest

from epicyclic.geometry import BasicRack, GearGeometry, MeshGeometry
from epicyclic.rating import MeshInput, RatingSpec, RatingWarning, rate_mesh
from epicyclic.rating.failure_modes import idle_note
from epicyclic.rating.micropitting import MicropittingSpec

RACK = BasicRack(4.0)
PAIR = MeshGeometry(GearGeometry(19, RACK, 0.5), GearGeometry(104, RACK, 0.15)).with_tip_shortening()
SPEC = RatingSpec(material="18CrNiMo7-6", flank_roughness=3.0, root_roughness=10.0, viscosity_40=220.0,
                  viscosity_100=19.0, K_Hbeta=1.2,
                  micropitting=MicropittingSpec(oil_temperature=70.0, load_stage=9, roughness=0.5))


def _rated(torque, speed):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RatingWarning)
        return rate_mesh(MeshInput("pair", PAIR, 40.0, ("pinion", "wheel"), SPEC), torque, speed)


@pytest.mark.parametrize("speed, expected", [(1500.0, None), (np.array([0.0, 1500.0]), "stands still in 1 of 2"),
                                             (0.0, "the mesh does not turn"), (np.zeros(3), "the mesh does not turn")])
def test_the_note_says_whether_and_how_often_the_mesh_stands_still(speed, expected):
    note = idle_note(SimpleNamespace(spec=SimpleNamespace(micropitting=object(), scuffing=None)), speed)
    assert note is None if expected is None else (expected in note and note.startswith("micropitting not rated"))


def test_no_note_where_no_mode_is_asked_for():
    assert idle_note(SimpleNamespace(spec=SimpleNamespace(micropitting=None, scuffing=None)), 0.0) is None


def test_a_mesh_that_stands_still_is_rated_for_pitting_and_root_only_and_says_so():
    torques, speeds = np.array([300.0, 300.0]), np.array([0.0, 1500.0])
    batch = _rated(torques, speeds)
    assert batch.modes == () and any("stands still in 1 of 2" in n for n in batch.notes)
    assert np.all(np.isfinite(batch.gears[0].S_H)) and np.all(batch.gears[0].S_H > 0)
    turning = _rated(300.0, 1500.0)  # the case that turns, alone, is rated for micropitting
    assert turning.mode("micropitting").value > 0
    assert batch.gears[0].S_H[1] == pytest.approx(turning.gears[0].S_H, rel=1e-12)
