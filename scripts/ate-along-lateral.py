#!/usr/bin/env python3
"""Splits the per-sweep position errors of an `hdprior eval` (or `run`) output into along and across
the true heading: per log and pooled, for the odometry and with the priors, and counts the keyframes
whose prior observes the along-track position.

usage: scripts/ate-along-lateral.py EVAL_OUT_DIR   (folders holding groundtruth.tum, odometry.tum,
                                                    optimized.tum and keyframes.json)
"""
import glob
import json
import math
import os
import sys

from run_files import read_tum, yaw


def along_lateral(truth, estimate):
    h = yaw(truth[3:7])
    dx, dy = estimate[0] - truth[0], estimate[1] - truth[1]
    return math.cos(h) * dx + math.sin(h) * dy, -math.sin(h) * dx + math.cos(h) * dy


def rms(values):
    return math.sqrt(sum(v * v for v in values) / len(values)) if values else float('nan')


def main():
    if len(sys.argv) != 2 or not os.path.isdir(sys.argv[1]):
        print('usage: scripts/ate-along-lateral.py EVAL_OUT_DIR', file=sys.stderr)
        return 2
    pooled = {'odometry': ([], []), 'priors': ([], [])}
    for d in sorted(glob.glob(os.path.join(sys.argv[1], '*', ''))):
        if not os.path.exists(os.path.join(d, 'optimized.tum')):
            continue
        gt = read_tum(os.path.join(d, 'groundtruth.tum'))
        split = {}
        for name, file in (('odometry', 'odometry.tum'), ('priors', 'optimized.tum')):
            est = read_tum(os.path.join(d, file))
            errors = [along_lateral(gt[t], est[t]) for t in sorted(est) if t in gt]
            split[name] = ([e[0] for e in errors], [e[1] for e in errors])
            pooled[name][0].extend(split[name][0])
            pooled[name][1].extend(split[name][1])
        with open(os.path.join(d, 'keyframes.json')) as f:
            keyframes = json.load(f)
        along_priors = sum(1 for k in keyframes
                           if k.get('prior_error') and k['prior_error'].get('sigma_along_m') is not None)
        print('%s odometry along %.3f lateral %.3f | priors along %.3f lateral %.3f m | along-observing priors %d of %d keyframes'
              % (os.path.basename(os.path.normpath(d)), rms(split['odometry'][0]), rms(split['odometry'][1]),
                 rms(split['priors'][0]), rms(split['priors'][1]), along_priors, len(keyframes)))
    print('pooled odometry along %.3f lateral %.3f | priors along %.3f lateral %.3f m'
          % (rms(pooled['odometry'][0]), rms(pooled['odometry'][1]), rms(pooled['priors'][0]), rms(pooled['priors'][1])))
    return 0


if __name__ == '__main__':
    sys.exit(main())
