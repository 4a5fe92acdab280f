#!/usr/bin/env python3
"""Writes docs/config.md, the configuration reference: every key of the schema in
engine/pipeline/config.cpp (its JSON key and range), its default from assets/default_config.json
(the file `hdprior config --defaults` prints) and the one-line comment of its member in the option
struct that holds it.

usage: scripts/make-config-doc.py [OUT]   (default docs/config.md; run from anywhere)
"""
import json
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# The option struct behind each section of the schema (file, struct name).
STRUCTS = {
    'odometry.features': ('engine/odom/odometry_options.h', 'FeatureOptions'),
    'odometry.deskew': ('engine/odom/odometry_options.h', 'DeskewOptions'),
    'odometry.registration': ('engine/odom/odometry_options.h', 'RegistrationOptions'),
    'odometry.local_map': ('engine/odom/odometry_options.h', 'LocalMapOptions'),
    'odometry.drift': ('engine/odom/odometry_drift.h', 'OdometryDrift'),
    'keyframes': ('engine/odom/odometry_options.h', 'KeyframeOptions'),
    'road_points.ground': ('engine/lidar/ground_segmentation.h', 'GroundSegmentationOptions'),
    'road_points.road': ('engine/lidar/road_points.h', 'RoadPointOptions'),
    'match': ('engine/match/match_options.h', 'MatchOptions'),
    'prior': ('engine/graph/pose_prior.h', 'PosePriorOptions'),
    'graph': ('engine/graph/pose_graph.h', 'PoseGraphOptions'),
}
# Members of Config itself or of another struct than the section's.
MEMBER_STRUCTS = {
    'thinCell': ('engine/lidar/sweep_road_points.h', 'SweepRoadPointOptions'),
    'submapRoadPoints': ('engine/pipeline/config.h', 'Config'),
    'maxUnreadableSweepShare': ('engine/pipeline/config.h', 'Config'),
}


def read(path):
    with open(os.path.join(ROOT, path)) as f:
        return f.read()


def struct_body(path, name):
    text = read(path)
    m = re.search(r'struct ' + name + r'\s*\{', text)
    if not m:
        raise SystemExit(f'make-config-doc.py: struct {name} not found in {path}')
    depth, i = 1, m.end()
    while depth:
        depth += {'{': 1, '}': -1}.get(text[i], 0)
        i += 1
    return text[m.end():i - 1].split('\n')


def member_comment(path, struct, member):
    lines = struct_body(path, struct)
    for n, line in enumerate(lines):
        code = line.split('//')[0]
        if re.search(r'\b' + re.escape(member) + r'\s*(=|\{|;)', code):
            if '//' in line:
                return line.split('//', 1)[1].strip()
            # The comment block above it, or above the few uncommented declarations it is one of.
            k = n - 1
            while k >= 0 and n - k <= 4 and lines[k].strip() and '//' not in lines[k]:
                k -= 1
            above = []
            while k >= 0 and lines[k].strip().startswith('//') and not lines[k].strip().startswith('// ---'):
                above.insert(0, lines[k].strip()[2:].strip())
                k -= 1
            return ' '.join(above)
    return ''


# Keys whose member carries no comment of its own.
NOTES = {
    'odometry.features.max_range': 'metres; farther returns are not used as features',
    'odometry.deskew.mode': '`none`: the sweeps are stored motion-compensated (Argoverse 2); `constant_velocity` deskews raw sweeps with offset_ns',
    'odometry.local_map.voxel_size': 'metres, the local map\'s voxel hash',
    'odometry.local_map.max_points_per_voxel': 'points kept per voxel of the local map',
    'odometry.drift.pitch_deg_per_100m': 'pitch error per 100 m travelled, positive tips the nose down',
    'road_points.ground.max_range': 'metres; farther returns are not segmented',
    'road_points.ground.min_bin_points': 'points a bin needs for a plane fit',
    'match.backend': '`ndt2d`: the project\'s 2-D NDT; `pcl`: PCL\'s 3-D NDT on the same points at z = 0 (the baseline)',
    'match.outlier_ratio': 'the NDT score\'s outlier share (d1, d2 of the Gaussian-plus-uniform mixture)',
    'match.lookup': 'cells scored per point: the one containing it, the 2 x 2 nearest, or those four weighted bilinearly',
    'match.pcl_max_iterations': 'PCL NDT iterations',
    'match.curb_refinement': 'after the NDT, put the curb points seen on the drivable boundary',
    'match.stale_regions': 'leave out regions of road points where the map disagrees (a stale map)',
    'graph.odometry_scale_sigma_per_sqrt_m': 'how fast the scale state wanders, per square root of metres between keyframes (0: one scale for the log)',
    'graph.given_odometry_rotation_sigma_deg_per_m': 'a trajectory file\'s rotation drift model, degrees per metre (1 deg per 100 m)',
    'graph.odometry_rotation_sigma_deg_per_m': 'the built-in odometry\'s rotation drift model, degrees per metre',
    'graph.odometry_rotation_sigma_deg': 'constant rotation sigma of every odometry step, degrees',
    'match.degenerate_ratio': 'a direction is observable when its boundary constraint eigenvalue is at least this share of the largest ...',
    'match.min_boundary_points': '... and at least this many point-equivalents',
    'match.min_points': 'fewer road points: the match is rejected',
    'match.map_sigma_yaw_deg': 'the map\'s own yaw error, degrees, added to the match\'s',
    'match.max_sigma_lateral': 'metres; a lateral sigma beyond this is reported unobservable',
    'match.max_sigma_yaw_deg': 'degrees; a yaw sigma beyond this is reported unobservable',
    'prior.min_sigma_yaw_deg': 'degrees, added to the match\'s yaw sigma',
}


def schema():
    """(section, key, member, range text) in the schema's order."""
    text = read('engine/pipeline/config.cpp')
    body = text[text.index('Sections sectionsOf'):text.index('std::string rangeText')]
    out = []
    for sec in re.finditer(r'\{"([a-z_.]+)",\s*\{(.*?)\}\}(?=,\s*(?://[^\n]*\n\s*)*\{"|,\s*\};)', body, re.S):
        section, fields = sec.group(1), sec.group(2)
        for f in re.finditer(r'\{"([a-z_0-9]+)",\s*(choice\(&([\w.]+),\s*\{([^}]*)\}\)|&([\w.]+))\s*(?:,\s*([^,}]+),\s*([^,}]+))?\}', fields):
            key = f.group(1)
            if f.group(3):
                member = f.group(3).split('.')[-1]
                rng = ' \\| '.join(s.strip().strip('"') for s in f.group(4).split(','))
            else:
                member = f.group(5).split('.')[-1]
                rng = f'[{f.group(6).strip()}, {f.group(7).strip()}]' if f.group(6) else ''
            out.append((section, key, member, rng.replace('kInf', 'inf')))
    return out


def experiment_link(m):
    # docs/*.md stay undated: an experiment is named by its title and found in the index.
    with open(os.path.join(ROOT, 'docs', 'experiments', m.group(1) + '.md')) as f:
        title = f.readline().lstrip('# ').strip()
    return f'experiment "{title}" in [experiments](experiments/README.md)'


def default_of(defaults, section, key):
    v = defaults
    for part in section.split('.') + [key]:
        v = v[part]
    return json.dumps(v)


def main():
    out_path = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, 'docs', 'config.md')
    defaults = json.loads(read('assets/default_config.json'))
    rows = schema()
    lines = [
        '# Configuration reference',
        '',
        '<!-- Generated by scripts/make-config-doc.py: do not edit by hand. -->',
        'Generated by `scripts/make-config-doc.py` from the schema in `engine/pipeline/config.cpp` (keys and',
        'ranges), `assets/default_config.json` (the defaults, embedded in the binary and printed by',
        '`hdprior config --defaults`) and the comments of the option structs. Regenerate it after changing',
        'any of them.',
        '',
        'A configuration is one JSON file given with `--config FILE` to `run`, `eval`, `match`, `snapshot`',
        'and `view`; it needs only the keys it changes, e.g. `{"match": {"min_inlier_ratio": 0.9}}`.',
        'Unknown keys, wrong types and values out of range are one line naming the file and the key, exit',
        'status 2; `hdprior config --check FILE` checks a file without running anything. Ranges are',
        'inclusive; angles are in degrees where the key says `_deg`, lengths in metres.',
        '',
        f'{len(rows)} keys.',
    ]
    section = None
    for sec, key, member, rng in rows:
        if sec != section:
            section = sec
            lines += ['', f'## `{sec}`', '', '| key | default | range | what |', '|---|---|---|---|']
        path, struct = MEMBER_STRUCTS.get(member) or STRUCTS.get(sec, (None, None))
        what = member_comment(path, struct, member) if path else ''
        what = NOTES.get(f'{sec}.{key}', what)
        what = re.sub(r'docs/experiments/(\d{4}-\d\d-\d\d-[a-z0-9-]+)\.md', experiment_link, what)
        what = what.replace('|', '\\|')
        lines.append(f'| `{sec}.{key}` | `{default_of(defaults, sec, key)}` | {rng} | {what} |')
    with open(out_path, 'w') as f:
        f.write('\n'.join(lines) + '\n')
    missing = [f'{s}.{k}' for s, k, m, r in rows if not (MEMBER_STRUCTS.get(m) or STRUCTS.get(s))]
    if missing:
        print('make-config-doc.py: no struct for ' + ', '.join(missing), file=sys.stderr)


if __name__ == '__main__':
    main()
