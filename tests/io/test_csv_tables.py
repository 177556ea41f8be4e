"""CSV tables with units in the header (drive cycles, shift schedules): hostile input is exit-2 material.

Every error names the file, the line and the column (issue 20: empty CSV, NaN, missing columns,
unit errors).
"""

from __future__ import annotations

import pytest

from epicyclic.io.csv_table import Column, read_csv_text
from epicyclic.io.shift_schedule_csv import read_shift_schedule, read_shift_schedule_text
from epicyclic.io.source import InputFileError
from epicyclic.units import UnitError

COLUMNS = {"time": Column("time", "s"), "output_speed": Column("speed", "1/min"),
           "vehicle_speed": Column("velocity", "km/h"), "gear": Column("text")}


def read(text):
    return read_csv_text(text, "c.csv", COLUMNS, required=("time",))


def test_units_in_the_header_are_converted():
    t = read("# a comment\ntime [min],vehicle_speed [m/s],output_speed [rad/s],gear\n1,2,3,4\n")
    assert t.values["time"].tolist() == [60.0] and t.values["vehicle_speed"].tolist() == [2.0]
    assert t.values["output_speed"][0] == pytest.approx(3 * 30 / 3.141592653589793)
    assert t.text["gear"] == ("4",) and t.lines.tolist() == [3]


@pytest.mark.parametrize("text, error, says", [
    ("", InputFileError, "the file is empty"),
    ("# only a comment\n", InputFileError, "the file is empty"),
    ("time\n", InputFileError, "no rows"),
    ("time,speed\n0,1\n", InputFileError, "line 1: unknown column 'speed'"),
    ("vehicle_speed\n0\n", InputFileError, "missing column 'time'"),
    ("time,time\n0,1\n", InputFileError, "given twice"),
    ("time\n0\nnan\n", InputFileError, "line 3, column 'time': expected a finite number in s, got 'nan'"),
    ("time\n0\n1e999\n", InputFileError, "line 3, column 'time'"),
    ("time,vehicle_speed\n0,fast\n", InputFileError, "line 2, column 'vehicle_speed'"),
    ("time,vehicle_speed\n0\n", InputFileError, "line 2: 1 values, expected 2"),
    ("time [parsec]\n0\n", UnitError, "column 'time': unknown unit 'parsec'"),
    ("time,output_speed [N*m]\n0,1\n", UnitError, "column 'output_speed'.*not a speed"),
    ("time [ ]\n0\n", InputFileError, "unit of column 'time' is empty"),
    ("time,gear\n0,\n", InputFileError, "column 'gear': expected a name"),
    # issue 30: one field of about 1 MiB gave csv's "field larger than field limit (131072)", exit 1
    ("# c\ntime,gear\n0,a\n1,\"" + "x" * (1 << 20) + "\"\n", InputFileError,
     "line 4: a value is longer than 131072 characters"),
])
def test_hostile_tables(text, error, says):
    with pytest.raises(error, match=says):
        read(text)


def test_shift_schedule_from_csv(tmp_path):
    path = tmp_path / "s.csv"
    path.write_text("output_torque [kN*m],1-2 [1/min],2-3\n0,300,600\n0.4,600,1200\n")
    s = read_shift_schedule(path)
    assert s.gears == ("1", "2", "3") and s.torques.tolist() == [0.0, 400.0]


@pytest.mark.parametrize("text, says", [
    ("output_torque\n0\n", "one column per upshift"),
    ("output_torque,1-2,3-4\n0,1,2\n", "does not start from gear '2'"),
    ("output_torque,fast\n0,1\n", "neither 'output_torque' nor an upshift"),
    ("1-2\n300\n", "missing column 'output_torque'"),
])
def test_bad_shift_schedules(text, says):
    with pytest.raises(Exception, match=says):
        read_shift_schedule_text(text, "s.csv")


def test_the_bundled_schedule_reads():
    s = read_shift_schedule("examples/schedules/zf_8hp70_upshift.csv")
    assert s.gears == tuple("12345678") and s.torques[0] == 0.0
