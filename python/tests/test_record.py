"""Simulation.record (docs/recording.md) from Python: the MCAP file is
complete after finish_recording (magic at both ends), holds the poses at the
rate asked, and the same seed twice gives the same bytes."""
import os
import pathlib

import pytest

import simswift

SOURCE = pathlib.Path(os.environ["SIMSWIFT_SOURCE_DIR"])
ONE_ROBOT = "duration: 4\nseed: 3\nrobots:\n  - {team: 87, player: 1, x: 0.0, y: 0.0}\n"
MAGIC = b"\x89MCAP0\r\n"


def recorded(path):
    sim = simswift.Simulation.from_yaml(ONE_ROBOT, "rec.yaml", str(SOURCE))
    sim.record(str(path), rate_hz=10)
    sim.run(1.0)
    sim.finish_recording()
    return path.read_bytes()


def test_record_writes_a_complete_deterministic_file(tmp_path):
    a = recorded(tmp_path / "a.mcap")
    b = recorded(tmp_path / "b.mcap")
    assert a[:8] == MAGIC and a[-8:] == MAGIC
    assert a == b
    # 1 s at 10 Hz: samples at 0.01 s, then every 0.1 s to 1.0 s.
    assert a.count(b'"child_frame_id":"robot0/torso"') == 11


def test_record_refuses_what_it_cannot_do(tmp_path):
    sim = simswift.Simulation.from_yaml(ONE_ROBOT, "rec.yaml", str(SOURCE))
    with pytest.raises(RuntimeError, match="nonexistent-dir"):
        sim.record("/nonexistent-dir/x.mcap")
    with pytest.raises(ValueError, match="rate_hz"):
        sim.record(str(tmp_path / "x.mcap"), rate_hz=0)
    sim.record(str(tmp_path / "y.mcap"))
    with pytest.raises(RuntimeError, match="already recording"):  # std::logic_error
        sim.record(str(tmp_path / "z.mcap"))
