"""The walk test kit's bindings (simswift.WalkTest, WalkCommand, WalkFigures,
reference_gait, plot_trace): a Python gait sees each tick's command and its
joints reach the robot; a direction not commanded has no ratio; errors are
Python exceptions."""
import math

import numpy as np
import pytest

import simswift


def test_a_python_gait_gets_the_command_and_drives_the_robot():
    walk = simswift.reference_gait()
    seen = []

    def gait(command, sensors, joints):
        seen.append((command.forward, command.left, command.turn, command.walk))
        walk(command, sensors, joints)

    test = simswift.WalkTest(71, gait)
    f = test.walk(forward=150, settle=1.0, window=1.0)
    assert len(seen) == 200  # one call per 10 ms tick
    assert seen[-1] == (150, 0, 0, True)
    assert f.seconds == pytest.approx(1.0)
    assert f.forward > 50  # mm/s: it walked
    assert math.isnan(f.left_ratio) and math.isnan(f.turn_ratio)
    assert f.falls == 0 and test.falls == 0
    assert "forward 150 mm/s" in f.summary()


def test_a_limp_gait_falls_and_the_kit_counts_it():
    def limp(command, sensors, joints):
        joints.stiffnesses[:] = -1.0  # every joint off

    test = simswift.WalkTest(72, limp)
    f = test.walk(forward=100, settle=0.5, window=2.5)
    assert f.falls == 1
    assert test.pose.z < 0.2  # m: on the ground


def test_errors_are_python_exceptions(tmp_path):
    bad = tmp_path / "bad.csv"
    bad.write_text("a,b\n1,2\n")
    with pytest.raises(RuntimeError, match="no column 't'"):
        simswift.plot_trace(str(bad), str(tmp_path / "bad.png"))
    test = simswift.WalkTest(73, simswift.reference_gait())
    with pytest.raises(RuntimeError, match="cannot write the trace"):
        test.trace(str(tmp_path / "no-such-folder" / "t.csv"))
    with pytest.raises(TypeError):
        simswift.WalkTest(73, None)
