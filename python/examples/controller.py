"""A callback controller from Python: robot 0 of a scenario, driven each
10 ms tick by a function that reads its sensors and writes its joints (here:
stand, and nod the head with the gyroscope's pitch rate shown).

    PYTHONPATH=build/python python3 python/examples/controller.py
"""
import math
import pathlib

import simswift

ROOT = pathlib.Path(__file__).resolve().parents[2]
SCENARIO = "duration: 5\nseed: 1\nrobots:\n  - {team: 19, player: 1, x: 0.0, y: 0.0}\n"

HEAD_PITCH, L_HIP, L_KNEE, L_ANKLE, R_HIP, R_KNEE, R_ANKLE = 1, 10, 11, 12, 15, 16, 17


def main():
    sim = simswift.Simulation.from_yaml(SCENARIO, "controller.yaml", str(ROOT))
    t = [0.0]

    def controller(sensors, joints):
        joints.stiffnesses[:] = 1.0
        joints.angles[:] = 0.0
        joints.angles[[L_HIP, R_HIP, L_ANKLE, R_ANKLE]] = -0.4
        joints.angles[[L_KNEE, R_KNEE]] = 0.8
        joints.angles[HEAD_PITCH] = 0.3 * math.sin(2 * math.pi * 0.5 * t[0])
        t[0] += 0.01

    sim.robot(0).set_controller(controller)
    for second in range(5):
        sim.run(1.0)
        s = sim.robot(0).sensors
        print(f"t {sim.time:.1f} s  FSR sum {s.fsr.sum():.2f} kg  gyro y {s.gyroscope[1]:+.3f} rad/s  "
              f"fallen {sim.robot(0).fallen}")


if __name__ == "__main__":
    main()
