"""Stick–slip by events against closed forms.

* A clutch between two inertias J1, J2 with driving torque T1 on the first, load T2 on the second and a
  constant capacity T_c: the slip Δω falls at the constant rate (T_c − T_eff)/I_eq with
  I_eq = J1 J2/(J1 + J2) and T_eff = (T1 J2 + T2 J1)/(J1 + J2), so it locks after
  t = I_eq Δω0/(T_c − T_eff) having dissipated E = T_c Δω0²/(2 (T_c − T_eff)/I_eq)
  = ½ I_eq Δω0² · T_c/(T_c − T_eff): ½ I_eq Δω0² without torques (Budynas & Nisbett, *Shigley's
  Mechanical Engineering Design*, 9th ed. 2011, §16-10 "Energy considerations") plus the work of the
  driving torques while it slips.
* A brake stopping a free shaft: t = J ω0/T_b, E = ½ J ω0².
* A freewheel (blocking the first shaft from overtaking the second) on a shaft accelerated by a constant torque towards a shaft held at its speed takes over
  at exactly t = J (ω_b − ω_a0)/T and then carries T.
"""


import numpy as np
import pytest

from epicyclic import Brake, Clutch, GearTrain
from epicyclic.dynamics import (
    DynamicsError,
    Freewheel,
    FrictionCapacity,
    HeldSpeed,
    Inertias,
    Mode,
    OutputTorque,
    PressureProfile,
    TorqueTrace,
    TrainDynamics,
    WetElement,
    integrate,
)


def _balance(d, run):
    n = len(d.shafts)
    y0, y1 = run.states[0], run.states[-1]
    residual = y1[n] - y1[n + 1] - y1[n + 2] - np.sum(y1[n + 3:]) - (d.kinetic_energy(y1[:n]) - d.kinetic_energy(y0[:n]))
    return abs(residual) / max(abs(y1[n]), d.kinetic_energy(y0[:n]), 1.0)


def _clutch(j1, j2, t1, t2, tc):
    cap = FrictionCapacity(piston_area=0.01, faces=2, mean_radius=0.1, friction=0.15)
    return TrainDynamics(GearTrain([Clutch("C", "a", "b")]), "a", "b", Inertias({"a": j1, "b": j2}),
                         {"C": WetElement("C", cap)}, {"C": PressureProfile.constant(cap.pressure_for(tc))},
                         TorqueTrace(((0, t1),)), OutputTorque(((0, t2),)))


@pytest.mark.parametrize("j1, j2, t1, t2, tc", [(0.2, 0.5, 0.0, 0.0, 150.0), (0.2, 0.5, 50.0, 20.0, 150.0),
                                                (1.0, 0.1, -30.0, 10.0, 80.0)])
def test_clutch_between_two_inertias(j1, j2, t1, t2, tc):
    d = _clutch(j1, j2, t1, t2, tc)
    s0 = 200.0
    run = integrate(d, np.array([300.0, 300.0 - s0]), Mode(frozenset()), 1.0)
    i_eq, t_eff = j1 * j2 / (j1 + j2), (t1 * j2 + t2 * j1) / (j1 + j2)
    t_lock = i_eq * s0 / (tc - t_eff)
    energy = 0.5 * i_eq * s0 ** 2 * tc / (tc - t_eff)
    assert [m.locked for _, m in run.modes] == [frozenset(), frozenset({"C"})]
    assert run.modes[1][0] == pytest.approx(t_lock, rel=1e-9)
    assert run.states[-1, -1] == pytest.approx(energy, rel=1e-9)
    if t1 == t2 == 0.0:
        assert run.states[-1, -1] == pytest.approx(0.5 * i_eq * s0 ** 2, rel=1e-9)
    assert _balance(d, run) < 1e-9
    # locked: both turn together at the common acceleration (T1 − T2)/(J1 + J2)
    k = np.searchsorted(run.times, t_lock + 0.1)
    slope = (run.states[-1, 0] - run.states[k, 0]) / (run.times[-1] - run.times[k])
    assert slope == pytest.approx((t1 - t2) / (j1 + j2), rel=1e-7, abs=1e-9)


def test_clutch_too_weak_to_hold_slips_through_synchronism():
    d = _clutch(0.2, 0.5, 400.0, 0.0, 150.0)  # once locked, 400 N·m would need 400·0.5/0.7 = 286 N·m > 150
    run = integrate(d, np.array([300.0, 100.0]), Mode(frozenset()), 1.0)
    assert all("C" not in m.locked for _, m in run.modes[1:]) or len(run.modes) == 1
    assert _balance(d, run) < 1e-9


def test_brake_stops_a_free_shaft():
    cap = FrictionCapacity(piston_area=0.01, faces=2, mean_radius=0.1, friction=0.12)
    j, w0, tb = 0.3, 250.0, 60.0
    d = TrainDynamics(GearTrain([Brake("B", "a"), Clutch("K", "a", "b")]), "a", "b", Inertias({"a": j, "b": 0.1}),
                      {"B": WetElement("B", cap)}, {"B": PressureProfile.constant(cap.pressure_for(tb))},
                      TorqueTrace(((0, 0.0),)), OutputTorque(((0, 0.0),)))
    run = integrate(d, np.array([w0, 0.0]), Mode(frozenset()), 2.0)
    assert run.modes[1][0] == pytest.approx(j * w0 / tb, rel=1e-9)
    assert run.modes[1][1].locked == frozenset({"B"})
    assert run.states[-1, -1] == pytest.approx(0.5 * j * w0 ** 2, rel=1e-9)
    assert run.states[-1, 0] == 0.0
    assert _balance(d, run) < 1e-9


def test_freewheel_takes_over_exactly_at_synchronism():
    j, torque, w_b, w_a0 = 0.25, 40.0, 100.0, 20.0
    d = TrainDynamics(GearTrain([Clutch("F", "a", "b")]), "a", "b", Inertias({"a": j, "b": 0.5}),
                      {"F": Freewheel("F", reverse=True)}, {}, TorqueTrace(((0, torque),)), HeldSpeed())
    run = integrate(d, np.array([w_a0, w_b]), Mode(frozenset()), 1.0)
    assert run.modes[1][1].locked == frozenset({"F"})
    assert run.modes[1][0] == pytest.approx(j * (w_b - w_a0) / torque, rel=1e-9)
    r = d.evaluate(1.0, run.states[-1, :2], run.modes[-1][1])
    assert r.element_torques["F"] == pytest.approx(torque, rel=1e-12)  # it takes the whole drive torque
    assert r.load_torque == pytest.approx(torque, rel=1e-12)
    assert _balance(d, run) < 1e-9


def test_freewheel_overruns_when_the_torque_reverses():
    d = TrainDynamics(GearTrain([Clutch("F", "a", "b")]), "a", "b", Inertias({"a": 0.25, "b": 0.5}),
                      {"F": Freewheel("F", reverse=True)}, {}, TorqueTrace(((0.0, 40.0), (0.2, 40.0), (0.3, -40.0))),
                      HeldSpeed())
    run = integrate(d, np.array([100.0, 100.0]), Mode(frozenset({"F"})), 1.0, breakpoints=d.breakpoints())
    release = [t for t, m in run.modes if "F" not in m.locked]
    assert release and release[0] == pytest.approx(0.25, rel=1e-9)  # the trace crosses zero at 0.25 s
    assert run.states[-1, 0] < 100.0


def test_bounds_are_stated_before_running():
    d = _clutch(0.2, 0.5, 0.0, 0.0, 150.0)
    with pytest.raises(DynamicsError, match="simulated time"):
        integrate(d, np.array([1.0, 0.0]), Mode(frozenset()), 1e9)
    with pytest.raises(DynamicsError, match="output step"):
        integrate(d, np.array([1.0, 0.0]), Mode(frozenset()), 1.0, step=0.0)


def test_a_shaft_without_inertia_is_named():
    with pytest.raises(DynamicsError, match="'b'"):
        TrainDynamics(GearTrain([Clutch("C", "a", "b")]), "a", "b", Inertias({"a": 1.0}), {}, {},
                      TorqueTrace(((0, 1.0),)), OutputTorque(((0, 0.0),)))


def test_a_run_that_exhausts_its_bounds_ends_and_says_so(monkeypatch):
    import sys

    d = _clutch(0.2, 0.5, 50.0, 20.0, 150.0)
    run = integrate(d, np.array([300.0, 100.0]), Mode(frozenset()), 1.0, max_events=0)
    assert run.ended.startswith("stopped after 0 stick/slip changes") and run.times[-1] < 1.0
    module = sys.modules["epicyclic.dynamics.integrate"]
    monkeypatch.setattr(module, "MAX_EVALUATIONS", 50)
    run = integrate(d, np.array([300.0, 100.0]), Mode(frozenset()), 1.0)
    assert run.ended.startswith("stopped after 50 evaluations")
