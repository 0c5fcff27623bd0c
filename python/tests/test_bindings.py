"""The Python bindings (python/simswift_module.cpp): a standing robot's FSRs
sum to its mass, a 2-trial experiment's table, and bad arguments raise
Python exceptions naming file, line and key (never a crash)."""
import math
import os
import pathlib

import numpy as np
import pytest

import simswift

SOURCE = pathlib.Path(os.environ["SIMSWIFT_SOURCE_DIR"])
BINARY = pathlib.Path(os.environ["SIMSWIFT_BINARY_DIR"])
NAO_MASS_KG = 5.305  # Aldebaran's NAO V5 (H25) datasheet

ONE_ROBOT = "duration: 4\nseed: 3\nrobots:\n  - {team: 87, player: 1, x: 0.0, y: 0.0}\n"


def test_standing_robot_fsrs_sum_to_its_mass():
    sim = simswift.Simulation.from_yaml(ONE_ROBOT, "stand.yaml", str(SOURCE))
    sim.run(1.0)
    assert sim.ticks == 100
    s = sim.robot(0).sensors
    assert s.fsr.shape == (8,) and s.fsr.dtype == np.float32
    sums, acc = [], []
    for _ in range(50):  # the means over 0.5 s: noise and the stance's sway average out
        sim.step()
        sums.append(sim.robot(0).sensors.fsr.sum())
        acc.append(sim.robot(0).sensors.accelerometer)
    assert np.mean(sums) == pytest.approx(NAO_MASS_KG, rel=0.05)
    assert s.joint_angles.shape == (25,)
    assert np.linalg.norm(np.mean(acc, axis=0)) == pytest.approx(9.81, rel=0.05)  # m/s^2: gravity
    assert not sim.robot(0).fallen


def test_a_python_controller_drives_the_joints():
    sim = simswift.Simulation.from_yaml(ONE_ROBOT, "ctl.yaml", str(SOURCE))
    calls = []

    def controller(sensors, joints):
        calls.append(sensors.fsr.sum())
        joints.angles[0] = 0.4  # HeadYaw, rad
        joints.stiffnesses[0] = 1.0

    sim.robot(0).set_controller(controller)
    sim.run(1.0)
    assert len(calls) == 100
    assert sim.robot(0).sensors.joint_angles[0] == pytest.approx(0.4, abs=0.05)


def test_two_trial_experiment_table(tmp_path):
    exp = (SOURCE / "scenarios" / "findball_quick.yaml").read_text()
    exp = exp.replace("trials_per_position: 3", "trials_per_position: 1").replace("time_limit: 180", "time_limit: 20")
    # one ball position, so two trials: one per setup
    lines = exp.splitlines()
    start = next(i for i, l in enumerate(lines) if l.startswith("balls:"))
    end = next(i for i, l in enumerate(lines) if l.startswith("setups:"))
    keep = [l for l in lines[start + 1:end] if "position: 1," in l]
    exp = "\n".join(lines[:start + 1] + keep + lines[end:]) + "\n"
    f = tmp_path / "two.yaml"
    f.write_text(exp.replace("name: findball_quick", "name: two") + f"base_dir: {SOURCE}\n")
    rows = simswift.run_experiment(str(f), jobs=2, out=str(tmp_path / "out"))
    assert [r["trial"] for r in rows] == ["0", "1"]
    assert [r["setup"] for r in rows] == ["2016", "2017"]
    assert all(r["position"] == "1" and r["failed"] == "" for r in rows)
    assert (tmp_path / "out" / "report.md").exists()


def test_bad_arguments_raise_python_exceptions():
    with pytest.raises(simswift.ConfigError) as e:
        simswift.Simulation.from_yaml("robots:\n  - {team: 300, player: 1}\n", "bad.yaml")
    assert (e.value.file, e.value.line, e.value.key) == ("bad.yaml", 2, "robots[0].team")
    with pytest.raises(simswift.ConfigError):
        simswift.Simulation("/no/such/file.yaml")
    sim = simswift.Simulation.from_yaml(ONE_ROBOT, "x.yaml", str(SOURCE))
    with pytest.raises(IndexError):
        sim.robot(5)
    with pytest.raises(ValueError):
        sim.robot(0).set_joints(np.zeros(3), np.zeros(25))
    with pytest.raises(TypeError):
        sim.run("ten")


def test_run_stops_when_until_is_true():
    # Issue 34: `until` was dropped (a TypeError), so run() always ran the full time.
    sim = simswift.Simulation.from_yaml(ONE_ROBOT, "until.yaml", str(SOURCE))
    seen = []

    def until(s):
        seen.append(s.ticks)
        return s.ticks >= 30

    assert sim.run(2.0, until=until) == pytest.approx(0.30, abs=1e-9)  # s: 30 ticks of 10 ms
    assert sim.ticks == 30 and seen == list(range(1, 31))
    assert sim.run(0.5) == pytest.approx(0.5, abs=1e-9)  # without it: the full time
    assert sim.ticks == 80


def test_ball_carries_its_velocity():
    # Issue 34: `ball` gave (present, x, y, z) and dropped the velocity. A
    # ball placed 0.04 m into the left post of the positive-x goal (post
    # centre (4.5, 0.8) m, radius 0.05 m; ball radius 0.05 m) is pushed out:
    # over each tick its position changes by its velocity times 10 ms.
    sim = simswift.Simulation.from_yaml(ONE_ROBOT, "ball.yaml", str(SOURCE))
    before = sim.ball  # before the first step: as placed, at rest
    assert before.present and (before.x, before.y, before.vx, before.vy, before.vz) == (0.0, 0.0, 0.0, 0.0, 0.0)
    sim.place_ball(4.5, 0.74)
    sim.run(0.05)
    a = sim.ball
    sim.step()
    b = sim.ball
    assert math.hypot(b.vx, b.vy) > 0.1  # m/s: it moves
    # Finite differences over one tick against the reported velocity (the
    # mean of the two ends; 0.05 m/s allows the carpet's friction and a bounce).
    assert (b.x - a.x) / 0.01 == pytest.approx((a.vx + b.vx) / 2, abs=0.05)
    assert (b.y - a.y) / 0.01 == pytest.approx((a.vy + b.vy) / 2, abs=0.05)
    assert (b.z - a.z) / 0.01 == pytest.approx((a.vz + b.vz) / 2, abs=0.05)


def test_queries_before_the_first_step_answer_or_raise():
    # Issue 34: sim.robot(0).fallen before the first step killed the interpreter (SIGSEGV).
    sim = simswift.Simulation.from_yaml(ONE_ROBOT, "first.yaml", str(SOURCE))
    r = sim.robot(0)
    assert r.fallen is False and r.falls == 0
    assert (r.pose.x, r.pose.y) == (0.0, 0.0)
    with pytest.raises(RuntimeError, match="sensors\\(\\) before the first step"):
        r.sensors
    sim.step()
    assert r.sensors.fsr.shape == (8,)


def test_a_nao_v6_over_lola_at_12_ms():
    """A V6 robot (lola:) through the library: the reference program and a
    Python controller talk to its LoLA socket; the world ticks at 12 ms."""
    socket = f"/tmp/simswift-pytest-lola-{os.getpid()}"
    v6 = f"duration: 4\nseed: 3\nrobots:\n  - {{team: 87, player: 1, x: 0.0, y: 0.0, lola: {{socket: {socket}}}}}\n"
    sim = simswift.Simulation.from_yaml(v6, "v6.yaml", str(SOURCE))
    calls = []

    def controller(sensors, joints):
        calls.append(sensors.fsr.sum())
        joints.angles[0] = 0.4  # HeadYaw, rad
        joints.stiffnesses[:] = 1.0  # LoLA starts limp: a V6 program sends its stiffness

    sim.robot(0).set_controller(controller)
    assert sim.run(1.2) == pytest.approx(1.2)
    assert sim.ticks == 100  # 12 ms each
    assert len(calls) == 100
    assert sim.robot(0).sensors.joint_angles[0] == pytest.approx(0.4, abs=0.05)
    # Held where it stood, the robot sways for about a second (as a V5 does
    # with this controller); then the FSRs carry its mass (2.6 % low at seed 3).
    sim.run(1.2)
    v6_mass_kg = 5.36  # models/nao_v6.urdf (the V5's links, the V6 head: docs/lola.md)
    assert np.mean(calls[100:]) == pytest.approx(v6_mass_kg, rel=0.05)
    assert not sim.robot(0).fallen
