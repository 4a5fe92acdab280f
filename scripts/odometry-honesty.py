#!/usr/bin/env python3
"""Checks the odometry covariance the pose graph uses against the odometry's actual error: for
windows of K consecutive keyframes (K = 1, 5, 25), the planar error (x, y, yaw) of the odometry's
relative pose against the ground truth's, and its normalised squared error under the window's
covariance (each step's relative covariance plus the drift model metrics.json records, compounded
along the window). An honest model gives a median NEES near 2.37 (chi-square, 3 dof) and 0.3 %
beyond 14.16 (its 99.7 % quantile) at every K; a model that takes systematic drift for independent
noise passes at K = 1 and fails at K = 25.

usage: scripts/odometry-honesty.py OUT_DIR   (run folders: keyframes.json, groundtruth.tum, metrics.json)
"""
import glob
import json
import math
import os
import statistics
import sys

from run_files import read_tum, yaw

WINDOWS = (1, 5, 25)
CHI2_3_997 = 14.16


def wrap(a):
    return math.atan2(math.sin(a), math.cos(a))


def relative(a, b):
    """a^-1 b for planar poses (x, y, yaw)."""
    c, s = math.cos(a[2]), math.sin(a[2])
    dx, dy = b[0] - a[0], b[1] - a[1]
    return (c * dx + s * dy, -s * dx + c * dy, wrap(b[2] - a[2]))


def mat_mul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def transpose(a):
    return [[a[j][i] for j in range(3)] for i in range(3)]


def add(a, b):
    return [[a[i][j] + b[i][j] for j in range(3)] for i in range(3)]


def inverse(m):
    a, b, c = m[0]
    d, e, f = m[1]
    g, h, i = m[2]
    det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g)
    return [[(e * i - f * h) / det, (c * h - b * i) / det, (b * f - c * e) / det],
            [(f * g - d * i) / det, (a * i - c * g) / det, (c * d - a * f) / det],
            [(d * h - e * g) / det, (b * g - a * h) / det, (a * e - b * d) / det]]


def compound(pose, cov, step, step_cov):
    """(pose, cov) followed by (step, step_cov): first-order covariance of the composition."""
    c, s = math.cos(pose[2]), math.sin(pose[2])
    x, y = step[0], step[1]
    ja = [[1, 0, -s * x - c * y], [0, 1, c * x - s * y], [0, 0, 1]]
    jb = [[c, -s, 0], [s, c, 0], [0, 0, 1]]
    new_cov = add(mat_mul(mat_mul(ja, cov), transpose(ja)), mat_mul(mat_mul(jb, step_cov), transpose(jb)))
    return (pose[0] + c * x - s * y, pose[1] + s * x + c * y, wrap(pose[2] + step[2])), new_cov


def step_covariance(keyframe, model):
    """The planar (x, y, yaw) part of the graph's between-factor covariance for this keyframe's step."""
    t = keyframe['previous_T_this']['t']
    d = math.sqrt(sum(v * v for v in t))
    own = keyframe.get('relative_covariance_v_w')
    if own and not isinstance(own[0], list):
        own = [own[6 * r:6 * r + 6] for r in range(6)]  # row-major, 36 numbers
    idx = (0, 1, 5)
    cov = [[(own[i][j] if own else 0.0) for j in idx] for i in idx]
    trans = (model['translation_sigma_per_m'] * d) ** 2
    rot = (math.radians(model['rotation_sigma_deg_per_m']) * d) ** 2
    cov[0][0] += trans
    cov[1][1] += trans
    cov[2][2] += rot
    return cov


def nees_of_log(folder, window):
    with open(os.path.join(folder, 'keyframes.json')) as f:
        keyframes = json.load(f)
    with open(os.path.join(folder, 'metrics.json')) as f:
        model = json.load(f)['odometry_drift_model']
    truth = read_tum(os.path.join(folder, 'groundtruth.tum'))

    def planar(p):
        return (p[0], p[1], yaw(p[3:7]))

    odo, gt = [], []
    for k in keyframes:
        t = round(k['timestamp_ns'] / 1e9, 6)
        pose = k['city_T_ego']
        odo.append((pose['t'][0], pose['t'][1], yaw(pose['q_xyzw'])))
        gt.append(planar(truth[t]) if t in truth else None)
    out = []
    for i in range(0, len(keyframes) - window, window):
        j = i + window
        if gt[i] is None or gt[j] is None:
            continue
        pose, cov = (0.0, 0.0, 0.0), [[0.0] * 3 for _ in range(3)]
        for k in range(i + 1, j + 1):
            pose, cov = compound(pose, cov, relative(odo[k - 1], odo[k]), step_covariance(keyframes[k], model))
        truth_rel = relative(gt[i], gt[j])
        e = (pose[0] - truth_rel[0], pose[1] - truth_rel[1], wrap(pose[2] - truth_rel[2]))
        info = inverse(cov)
        out.append((sum(e[a] * info[a][b] * e[b] for a in range(3) for b in range(3)), math.hypot(e[0], e[1])))
    return out


def main():
    if len(sys.argv) != 2 or not os.path.isdir(sys.argv[1]):
        print('usage: scripts/odometry-honesty.py OUT_DIR', file=sys.stderr)
        return 2
    folders = [d for d in sorted(glob.glob(os.path.join(sys.argv[1], '*', '')))
               if os.path.exists(os.path.join(d, 'keyframes.json'))]
    for window in WINDOWS:
        pooled = []
        for d in folders:
            pooled.extend(nees_of_log(d, window))
        if not pooled:
            continue
        nees = [n for n, _ in pooled]
        print('%2d keyframes: %4d windows, median NEES %8.2f, beyond 3 sigma %5.1f %%, position error RMS %.4f m'
              % (window, len(nees), statistics.median(nees), 100.0 * sum(n > CHI2_3_997 for n in nees) / len(nees),
                 math.sqrt(sum(e * e for _, e in pooled) / len(pooled))))
    return 0


if __name__ == '__main__':
    sys.exit(main())
