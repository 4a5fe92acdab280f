"""What the analysis scripts read from an `hdprior run` / `eval` output folder."""
import math


def read_tum(path):
    """A TUM trajectory: {timestamp (s, rounded to the microsecond): [tx, ty, tz, qx, qy, qz, qw]}."""
    poses = {}
    with open(path) as f:
        for line in f:
            if line.startswith('#') or not line.strip():
                continue
            v = [float(x) for x in line.split()]
            poses[round(v[0], 6)] = v[1:]
    return poses


def yaw(q):
    """Heading of a quaternion (x, y, z, w)."""
    x, y, z, w = q
    return math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z))
