#!/usr/bin/env python3
"""A flight controller written in Python flies the default scenario through
cosim.Simulation.set_controller; its tracking error is printed beside the built-in controller's.

    PYTHONPATH=build/python python3 examples/pd_controller.py [--quick] [--scenario FILE.yaml]

The controller is the textbook cascade in SE(3) form (Lee, Leok and McClamroch 2010, "Geometric
tracking control of a quadrotor UAV on SE(3)", CDC, eqs. 11-16, without the feed-forward
angular terms): a PD law on position with the reference's acceleration as feed-forward gives the
thrust vector; its direction and the reference yaw give the desired attitude; a PD law on the
attitude error gives the torques; the airframe's allocation matrix turns collective thrust and
torques into the four rotor thrusts. It sees what the built-in controller sees (the estimate
under the scenario's sensors) and runs at the same rate. --quick flies the first 8 s only.
"""
import argparse
import time

import numpy as np

import cosim


def rotation(q):
    """Body-to-world rotation matrix of a unit quaternion (w, x, y, z)."""
    w, x, y, z = q
    return np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
    ])


def vee(m):
    """The vector of a skew-symmetric matrix."""
    return np.array([m[2, 1], m[0, 2], m[1, 0]])


class PDController:
    """Position PD + attitude PD for one quadrotor, gains per unit mass and inertia."""

    def __init__(self, airframe, kp=6.0, kd=4.5, k_att=120.0, k_rate=22.0):
        self.m = airframe["mass"]
        self.g = airframe["gravity"]
        self.J = np.asarray(airframe["inertia"])
        self.A_inv = np.linalg.inv(airframe["allocation"])
        self.lo, self.hi = airframe["min_thrust"], airframe["max_thrust"]
        self.kp, self.kd, self.k_att, self.k_rate = kp, kd, k_att, k_rate

    def __call__(self, state, reference):
        R = rotation(state["quaternion"])
        # Thrust vector: PD on position with acceleration feed-forward, and gravity (eq. 11-12).
        a = (self.kp * (reference["position"] - state["position"])
             + self.kd * (reference["velocity"] - state["velocity"])
             + reference["acceleration"] + np.array([0.0, 0.0, self.g]))
        force = self.m * a
        thrust = force @ R[:, 2]  # along the body's z axis as it is now
        # Desired attitude: body z along the thrust vector, body x towards the reference yaw.
        b3 = force / np.linalg.norm(force)
        heading = np.array([np.cos(reference["yaw"]), np.sin(reference["yaw"]), 0.0])
        b2 = np.cross(b3, heading)
        b2 /= np.linalg.norm(b2)
        Rd = np.column_stack([np.cross(b2, b3), b2, b3])
        # Attitude PD (eq. 13-16): error on SO(3), desired body rates zero.
        e_R = 0.5 * vee(Rd.T @ R - R.T @ Rd)
        torque = self.J * (-self.k_att * e_R - self.k_rate * state["angular_velocity"])
        rotors = self.A_inv @ np.concatenate([[thrust], torque])
        return np.clip(rotors, self.lo, self.hi)


def fly(scenario, until, python_controller):
    """Flies the scenario to its end (or `until` s); returns metrics, wall seconds."""
    with cosim.Simulation(scenario) as sim:
        if python_controller:
            for name in sim.vehicles:
                sim.set_controller(name, PDController(sim.airframe(name)))
        start = time.perf_counter()
        sim.step_until(until)
        wall = time.perf_counter() - start
        return sim.metrics(), wall


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scenario", default=cosim.DEFAULT_SCENARIO)
    parser.add_argument("--quick", action="store_true", help="fly the first 8 s only")
    args = parser.parse_args()
    until = 8.0 if args.quick else float("inf")

    builtin, builtin_wall = fly(args.scenario, until, python_controller=False)
    python, python_wall = fly(args.scenario, until, python_controller=True)
    print(f"{'controller':<22} {'rmse_m':>8} {'max_error_m':>12} {'reached_goal':>13} "
          f"{'sim s / wall s':>15}")
    for name, m, wall in ((builtin["controller"] + " (built-in)", builtin, builtin_wall),
                          ("python PD", python, python_wall)):
        print(f"{name:<22} {m['rmse_m']:>8.4f} {m['max_error_m']:>12.4f} "
              f"{str(m['reached_goal']):>13} {m['sim_time_s'] / wall:>15.1f}")
    ratio = python["rmse_m"] / builtin["rmse_m"]
    print(f"RMSE of the Python PD controller: {ratio:.2f} x the built-in controller's")


if __name__ == "__main__":
    main()
