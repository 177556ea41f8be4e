"""Hypothesis: random trains, losses, inertias, capacities and pressure profiles never break the energy balance.

A simple set (random minus ratio i0 and η0 ≤ 1, losses by the direction of power flow, Brandenberger 1952,
eq. 7) whose ring a wet brake holds and a wet clutch locks to the sun: energy in = energy to the load +
mesh loss + friction energy + change of kinetic energy, to 1e-6 of the largest energy term; every
element's friction energy and the mesh loss are ≥ 0 (up to that tolerance).
"""

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from epicyclic import Brake, Clutch, GearTrain, PlanetarySet
from epicyclic.dynamics import (
    FrictionCapacity,
    Inertias,
    Mode,
    OutputTorque,
    PressureProfile,
    TorqueTrace,
    TrainDynamics,
    WetElement,
    integrate,
)

profile = st.lists(st.tuples(st.floats(0.0, 0.5), st.floats(0.0, 20e5)), min_size=1, max_size=4)


@settings(max_examples=12, deadline=None)
@given(i0=st.floats(-5.0, -1.2), eta=st.floats(0.85, 1.0), inertia=st.tuples(*[st.floats(0.005, 0.5)] * 3),
       brake=profile, clutch=profile, drive=st.floats(-200.0, 300.0), load=st.floats(-100.0, 400.0),
       speeds=st.tuples(st.floats(-300.0, 300.0), st.floats(-300.0, 300.0)))
def test_energy_balance_of_random_trains(i0, eta, inertia, brake, clutch, drive, load, speeds):
    train = GearTrain([PlanetarySet("P", "in", "ring", "out", i0, eta), Brake("B", "ring"), Clutch("C", "in", "ring")])
    cap = FrictionCapacity(piston_area=0.01, faces=6, mean_radius=0.08, friction=((0, 0.13), (200, 0.11)),
                           return_spring=800.0)
    d = TrainDynamics(train, "in", "out", Inertias(dict(zip(("in", "ring", "out"), inertia))),
                      {"B": WetElement("B", cap), "C": WetElement("C", cap)},
                      {"B": PressureProfile(tuple(sorted(brake)), "B"), "C": PressureProfile(tuple(sorted(clutch)), "C")},
                      TorqueTrace(((0.0, drive),)), OutputTorque(((0.0, load),)))
    w_in, w_out = speeds
    omega = np.zeros(3)
    index = d.index
    omega[index["in"]], omega[index["out"]] = w_in, w_out
    omega[index["ring"]] = (w_in - (1 - i0) * w_out) / i0  # Willis
    run = integrate(d, omega, Mode(frozenset()), 0.6, step=0.01, breakpoints=d.breakpoints())
    n = 3
    y0, y1 = run.states[0], run.states[-1]
    ke0, ke1 = d.kinetic_energy(y0[:n]), d.kinetic_energy(y1[:n])
    residual = y1[n] - y1[n + 1] - y1[n + 2] - np.sum(y1[n + 3:]) - (ke1 - ke0)
    scale = max(abs(y1[n]), abs(y1[n + 1]), ke0, ke1, 1e-3)
    assert abs(residual) <= 1e-6 * scale
    assert y1[n + 2] >= -1e-6 * scale  # mesh loss
    assert np.all(y1[n + 3:] >= -1e-6 * scale)  # friction energy
