#!/usr/bin/env python3
"""Writes assets/meshes/blob.obj: a lumpy closed blob for the fur track's OBJ
example. Quads and triangle fans at the poles, no normals and no texture
coordinates, so RayLab computes both when it loads the file (the case a
user's own model often is). Deterministic: run it again to check the file.

    python3 tools/meshes/make_blob.py assets/meshes/blob.obj
"""
import math
import sys

SLICES, STACKS = 32, 16


def radius(theta, phi):
    return 1.0 + 0.18 * math.sin(3 * phi) * math.sin(2 * theta) + 0.1 * math.cos(5 * theta)


def main(out):
    lines = ["# A lumpy blob for RayLab's fur track (tools/meshes/make_blob.py).",
             "# Faces are counter-clockwise seen from outside; no vn, no vt: computed on load."]
    # The south pole, the rings in between, the north pole.
    lines.append("v 0 %.6f 0" % -radius(0.0, 0.0))
    for i in range(1, STACKS):
        theta = math.pi * i / STACKS
        for j in range(SLICES):
            phi = 2 * math.pi * j / SLICES
            r = radius(theta, phi)
            x = -r * math.sin(theta) * math.sin(phi)
            y = -r * math.cos(theta)
            z = -r * math.sin(theta) * math.cos(phi)
            lines.append("v %.6f %.6f %.6f" % (x, y, z))
    lines.append("v 0 %.6f 0" % radius(math.pi, 0.0))
    north = 2 + (STACKS - 1) * SLICES  # 1-based

    def ring(i, j):  # 1-based index of ring i (1..STACKS-1), slice j
        return 2 + (i - 1) * SLICES + (j % SLICES)

    for j in range(SLICES):
        lines.append("f 1 %d %d" % (ring(1, j + 1), ring(1, j)))
    for i in range(1, STACKS - 1):
        for j in range(SLICES):
            lines.append("f %d %d %d %d" % (ring(i, j), ring(i, j + 1), ring(i + 1, j + 1),
                                            ring(i + 1, j)))
    for j in range(SLICES):
        lines.append("f %d %d %d" % (ring(STACKS - 1, j), ring(STACKS - 1, j + 1), north))
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "assets/meshes/blob.obj")
