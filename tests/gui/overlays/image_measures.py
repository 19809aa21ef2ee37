"""Measures on screenshots that the overlay tests assert: where the object is, and how much
the stripes (or isophotes) change direction across the joint line of two patches.

Plain numpy on the PNG that FreeCAD saved (read with matplotlib), no GUI needed, so the
measures can be checked on the committed reference screenshots too.
"""

import math

import numpy as np


def read_rgb(path):
    import matplotlib.image

    image = matplotlib.image.imread(path)
    return np.asarray(image[..., :3], dtype=float)


def object_box(plain_rgb, margin=0):
    """(top, bottom, left, right) of the object in a screenshot of FreeCAD's own display: its
    grey faces stand out from the bluish background (blue well above red)."""
    r, b = plain_rgb[..., 0], plain_rgb[..., 2]
    grey = np.abs(b - r) < 0.04
    rows = np.where(grey.sum(axis=1) > 20)[0]
    cols = np.where(grey.sum(axis=0) > 20)[0]
    if rows.size == 0 or cols.size == 0:
        raise AssertionError("no object found in the screenshot")
    return rows[0] + margin, rows[-1] - margin, cols[0] + margin, cols[-1] - margin


def edge_direction(gray, rows, cols):
    """Dominant direction of the light/dark edges in the window (degrees in [0, 180)), from
    the structure tensor of the image gradient; None where the window has no edges."""
    window = gray[rows[0] : rows[1], cols[0] : cols[1]]
    gy, gx = np.gradient(window)
    jxx, jyy, jxy = (gx * gx).sum(), (gy * gy).sum(), (gx * gy).sum()
    if jxx + jyy < 1e-6:
        return None
    gradient_angle = 0.5 * math.degrees(math.atan2(2 * jxy, jxx - jyy))
    return (gradient_angle + 90.0) % 180.0


def _angle_difference(a, b):
    d = abs(a - b) % 180.0
    return min(d, 180.0 - d)


def joint_kink(rgb, box, joint_column, reach=40, band=6, gap=3):
    """How much the edges turn at the joint column, in degrees: on each side the edge
    direction is measured in narrow column bands at growing distance from the joint, fitted
    by a line and extrapolated to the joint; the kink is the difference of the two limits.

    At a G1 (not G2) joint the reflection lines and isophotes keep their position but change
    direction, so the limits differ; at a G2 joint they agree.
    Returns (kink, left_limit, right_limit)."""
    gray = rgb.mean(axis=2)
    top, bottom, _, _ = box
    limits = []
    for side in (-1, 1):
        distances, angles = [], []
        for start in range(gap, reach - band + 1, band):
            if side > 0:
                cols = (joint_column + start, joint_column + start + band)
            else:
                cols = (joint_column - start - band, joint_column - start)
            angle = edge_direction(gray, (top, bottom), cols)
            if angle is not None:
                distances.append(start + 0.5 * band)
                angles.append(angle)
        if len(angles) < 2:
            raise AssertionError("no edges near the joint on side {}".format(side))
        # unwrap around the first angle so that 179 and 1 degrees fit as neighbours
        reference = angles[0]
        unwrapped = [reference + ((a - reference + 90.0) % 180.0 - 90.0) for a in angles]
        slope, intercept = np.polyfit(distances, unwrapped, 1)
        limits.append(intercept % 180.0)
    return _angle_difference(*limits), limits[0], limits[1]


def color_jump(rgb, box, joint_column, gap=3, band=4, spacing=10):
    """(jump, ratio): the largest colour difference (0..sqrt(3)) between the bands just left
    and just right of the joint, over the object's rows, and that difference divided by the
    largest one between two bands as far apart on one side. A map that is continuous at the
    joint changes there no faster than beside it (ratio about 1 or less); a jump stands out
    (ratio well above 1)."""
    top, bottom, _, _ = box

    def band_at(start):
        return rgb[top:bottom, start : start + band].mean(axis=1)

    def difference(a, b):
        return float(np.linalg.norm(a - b, axis=1).max())

    left, right = band_at(joint_column - gap - band), band_at(joint_column + gap)
    across = difference(left, right)
    beside = max(
        difference(right, band_at(joint_column + gap + spacing)),
        difference(left, band_at(joint_column - gap - band - spacing)),
        0.02,  # a flat colour on both sides: the ratio stays finite
    )
    return across, across / beside
