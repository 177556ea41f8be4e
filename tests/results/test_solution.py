"""Results render themselves: table, plain data (JSON), HTML, repr; element states."""

import json
import re

import pytest

from epicyclic import Brake, Clutch, EpicyclicError, GearTrain, OperatingPoint, PlanetarySet, UnknownShaftError, solve
from epicyclic.demo import brandenberger_1952


@pytest.fixture(scope="module")
def solution():
    train, op = brandenberger_1952()
    return solve(train, op)


def test_table_lists_shafts_elements_and_summary(solution):
    text = solution.table()
    for word in ("shaft", "speed [1/min]", "torque [N*m]", "planetary", "stage", "rolling"):
        assert word in text
    assert re.search(r"\nefficiency +0.849377\n", text)
    assert str(solution) == text


def test_to_dict_is_json_and_states_units(solution):
    data = json.loads(json.dumps(solution.to_dict()))
    assert data["units"] == {"speed": "1/min", "torque": "N*m", "power": "W"}
    assert data["shafts"]["II"]["role"] == "drive"
    assert data["elements"]["planetary"]["loss_direction"] == 1
    assert data["efficiency"] == pytest.approx(solution.efficiency)
    assert data["self_locking"] is None


def test_html_and_repr(solution):
    assert solution._repr_html_().count("<table>") == 2
    assert repr(solution).startswith("<Solution 'Brandenberger 1952, Bild 10': efficiency 0.8494")


def test_unknown_shaft_lookup(solution):
    with pytest.raises(UnknownShaftError, match="solution: unknown shaft 'IV'"):
        solution.speed("IV")


def test_element_states_rolling_locked_idle_open():
    # Set P1 is locked by a clutch (direct drive); set P2 has no torque path (idle); brake B open.
    train = GearTrain([
        PlanetarySet("P1", "in", "out", "c1", -2.0, 0.97), Clutch("C", "in", "c1"),
        PlanetarySet("P2", "in", "r2", "c2", -2.0, 0.97), Brake("B", "r2", engaged=False),
    ])
    op = OperatingPoint(speeds={"in": 1000, "c2": 200}, torques={"in": 10}, drives=["in"], loads=["out"])
    sol = solve(train, op)
    states = {name: e.status for name, e in sol.elements.items()}
    assert states == {"P1": "locked", "C": "engaged", "P2": "idle", "B": "open"}
    assert sol.elements["B"].slip_speed == pytest.approx(sol.speed("r2"))
    assert sol.efficiency == pytest.approx(1.0)


def test_self_locking_renders_without_negative_efficiency():
    train = GearTrain([PlanetarySet("P", "sun", "ring", "carrier", 1.02, 0.95), Brake("B", "ring")])
    sol = solve(train, OperatingPoint(speeds={"sun": 1000}, torques={"sun": 1}, drives=["sun"], loads=["carrier"]))
    text = sol.table()
    summary = text.split("\n\n")[-1].splitlines()
    assert "efficiency             — (self-locking)" in summary
    assert any(line.startswith("self-locking           the train self-locks") for line in summary)
    # every summary value starts in one column (the labels used to be ragged)
    assert len({len(line) - len(line.split("  ", 1)[1].lstrip()) for line in summary}) == 1
    assert "self-locking" in repr(sol)
    assert sol.to_dict()["self_locking"]["thresholds"]["P"] == pytest.approx(1 / 1.02, rel=1e-6)


def test_deferred_fields_are_made_on_first_access_and_equal_their_eager_values():
    """circulation, warnings and ideal are made when read: the same as solving lossless, or the
    circulation of the solution's own port powers; made once; a pickled copy carries them made."""
    import dataclasses
    import pickle

    from epicyclic.results.circulation import circulation

    train, op = brandenberger_1952()
    solution = solve(train, op)
    assert all(callable(solution.__dict__["_" + name]) for name in ("circulation", "warnings", "ideal"))
    replaced = solution.replace(efficiency=None)  # replace keeps them unmade
    assert replaced.efficiency is None and callable(replaced.__dict__["_ideal"])
    copied = pickle.loads(pickle.dumps(solution))  # made for pickling
    assert not any(callable(copied.__dict__["_" + name]) for name in ("circulation", "warnings", "ideal"))
    lossless = solve(train, op, lossless=True)
    for made in (solution, copied):
        assert made.ideal.shafts == lossless.shafts and made.ideal.elements == lossless.elements
        assert made.ideal.efficiency == 1.0 and made.ideal.ideal is None
        flows = [(e.name, e.ports[p], power) for e in made.elements.values() for p, power in e.port_powers.items()]
        assert made.circulation == circulation(flows, made.input_power, train.shafts)
        assert made.warnings == ()
    assert solution.ideal is solution.ideal  # made once
    assert replaced.ideal is solution.ideal  # one maker, shared by the copy
    with pytest.raises(dataclasses.FrozenInstanceError):
        solution.ideal = None


def test_deferred_warnings_name_the_circulating_power():
    """A plus set driven backwards circulates power; the warning is made from the deferred circulation."""
    train = GearTrain([PlanetarySet("P", "sun", "ring", "carrier", 0.8, 0.97), Brake("B", "ring")])
    op = OperatingPoint(speeds={"carrier": 1000}, torques={"carrier": 10}, drives=["carrier"], loads=["sun"])
    solution = solve(train, op)
    if solution.circulation.loops:
        assert any("power circulates" in w for w in solution.warnings)
    else:
        assert not any("power circulates" in w for w in solution.warnings)


def test_trains_points_and_solutions_pickle_without_their_process_bound_hash():
    """Read-only mappings pickle as read-only copies; a train's cached hash (string hashes differ between
    processes) is not pickled, so an unpickled train in another process hashes as that process's trains."""
    import pickle
    from types import MappingProxyType

    train, op = brandenberger_1952()
    hash(train)  # cached on the train
    assert "_hash" in train.__dict__
    copy = pickle.loads(pickle.dumps(train))
    assert "_hash" not in copy.__dict__ and copy == train and hash(copy) == hash(train)
    op_copy = pickle.loads(pickle.dumps(op))
    assert op_copy == op and isinstance(op_copy.speeds, MappingProxyType)
    solved = pickle.loads(pickle.dumps(solve(train, op)))
    assert isinstance(solved.shafts, MappingProxyType) and solved.to_dict() == solve(copy, op_copy).to_dict()


def test_table_in_the_sources_units():
    # regression: Solution.table() printed only 1/min, N*m, W; Brandenberger's numbers (3 PS at 1500 U/min,
    # M_An' = 143.24 cm kg, N1' = 2.55 PS; Brandenberger 1952, text to Bild 10) were out of reach in Python
    from epicyclic import solve
    from epicyclic.demo import brandenberger_1952
    from epicyclic.units import Units

    sol = solve(*brandenberger_1952())
    text = sol.table({"speed": "U/min", "torque": "kp*cm", "power": "PS"})
    assert "speed [U/min]" in text and "torque [kp*cm]" in text and "loss [PS]" in text
    row = next(line.split() for line in text.splitlines() if line.startswith("II "))
    assert row[1:4] == ["1500", "143.239", "3"]                       # U/min, kp*cm, PS
    assert "output power           2.54813 PS" in text
    assert sol.table(Units(power="PS")) == sol.table({"power": "PS"})
    assert sol.table() == sol.table(Units())                            # the core units by default
    with pytest.raises(EpicyclicError, match=r"units: unknown quantity 'speeds'"):
        sol.table({"speeds": "rpm"})
    with pytest.raises(EpicyclicError, match=r"units\.power: 'U/min' is not a power"):
        sol.table({"power": "U/min"})
