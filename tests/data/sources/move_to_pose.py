"""The reference numbers of tests/planners_orca.rs for the `move-to-pose` planner.

The controller and the example loop of PythonRobotics'
PathTracking/move_to_pose/move_to_pose.py (github.com/AtsushiSakai/PythonRobotics), without
the plotting, run from the start and goal of its tests/test_move_to_pose.py::test_stability and
of one case of test_reach_goal. Each case runs twice:

- `euler`: the file's own loop, `theta += w*dt` then `x += v*cos(theta)*dt`, which ends once
  the distance it computed before a step is at most 0.001;
- `exact`: the same law, the robot stopped once within 0.001 of its goal, moved by the exact
  integration of a held command over the step (an arc: `v*dt*sinc(w*dt/2)` along the mean
  heading `theta + w*dt/2`), as dvf's unicycle moves it.

Prints, per case and run, the number of steps and the pose after steps 1 to 5 and at the end.
Run with numpy: `python3 tests/data/sources/move_to_pose.py`.
"""

import numpy as np


def angle_mod(x):
    return float((np.asarray(x) + np.pi) % (2 * np.pi) - np.pi)


Kp_rho, Kp_alpha, Kp_beta = 9, 15, 3
dt = 0.01
MAX_SIM_TIME = 5
MAX_LINEAR_SPEED = 15
MAX_ANGULAR_SPEED = 7


def calc_control_command(x_diff, y_diff, theta, theta_goal):
    rho = np.hypot(x_diff, y_diff)
    v = Kp_rho * rho
    alpha = angle_mod(np.arctan2(y_diff, x_diff) - theta)
    beta = angle_mod(theta_goal - theta - alpha)
    if alpha > np.pi / 2 or alpha < -np.pi / 2:
        alpha = angle_mod(np.arctan2(-y_diff, -x_diff) - theta)
        beta = angle_mod(theta_goal - theta - alpha)
        w = Kp_alpha * alpha - Kp_beta * beta
        v = -v
    else:
        w = Kp_alpha * alpha - Kp_beta * beta
    return rho, v, w


def move_to_pose(x, y, theta, x_goal, y_goal, theta_goal, exact):
    poses = []
    rho = np.hypot(x_goal - x, y_goal - y)
    t = 0
    while rho > 0.001 and t < MAX_SIM_TIME:
        t += dt
        rho, v, w = calc_control_command(x_goal - x, y_goal - y, theta, theta_goal)
        if abs(v) > MAX_LINEAR_SPEED:
            v = np.sign(v) * MAX_LINEAR_SPEED
        if abs(w) > MAX_ANGULAR_SPEED:
            w = np.sign(w) * MAX_ANGULAR_SPEED
        if exact:
            if rho <= 0.001:
                break
            half = w * dt / 2
            chord = v * dt * np.sinc(half / np.pi)
            x += chord * np.cos(theta + half)
            y += chord * np.sin(theta + half)
            theta += w * dt
        else:
            theta = theta + w * dt
            x = x + v * np.cos(theta) * dt
            y = y + v * np.sin(theta) * dt
        poses.append((float(x), float(y), angle_mod(theta), float(v), float(w)))
    return poses


for case in [(5.0, 5.0, 0.0, 1.0, 4.0, 0.0), (5.0, 5.0, np.pi / 2, 10.0, 10.0, 0.0)]:
    for exact in (False, True):
        poses = move_to_pose(*case, exact)
        print(case, "exact" if exact else "euler", "steps", len(poses))
        for k in list(range(5)) + [len(poses) - 1]:
            x, y, th, v, w = poses[k]
            print(f"  {k + 1:3d} [{x!r}, {y!r}, {th!r}]  v={v!r} w={w!r}")
