#!/usr/bin/env python3
"""Writes assets/scenes/lite.json and pro.json, the two scenes of the full demo.

The JSON files are what RayLab reads (and what is committed); this script is
only how they were made, so that pro stays "lite plus more" after an edit to
lite. Run from the repository root: python3 tools/scenes/make_demo_scenes.py

lite (as in the seed thesis): 10 spheres, a mirror of 2 triangles, 1 disc,
the sky box, 3 point lights. pro: lite plus 100 small spheres on a spiral
around it and a glass cube (12 triangles) with a spinning torus inside.
"""
import json
import math
from pathlib import Path

TEX = "../textures/"

def material(ambient, diffuse, specular, shininess, **extra):
    return {"ambient": ambient, "diffuse": diffuse, "specular": specular, "shininess": shininess, **extra}

MATERIALS = {
    "sun":    material([1, 1, 1], [0, 0, 0], [0, 0, 0], 1, texture=TEX + "sun.png"),
    "earth":  material([0.06] * 3, [1, 1, 1], [0.25] * 3, 40, texture=TEX + "earth.png", normal_map=TEX + "earth_normal.png"),
    "moon":   material([0.05] * 3, [0.95] * 3, [0.05] * 3, 10, texture=TEX + "moon.png", normal_map=TEX + "moon_normal.png"),
    "marble": material([0.08] * 3, [0.95] * 3, [0.5] * 3, 60, texture=TEX + "marble.png"),
    "glass":  material([0, 0, 0], [0.02] * 3, [0.8] * 3, 120, type="glass", ior=1.5),
    "mirror": material([0, 0, 0], [0.03] * 3, [0.85, 0.85, 0.88], 120, type="mirror"),
    "gold":   material([0.1, 0.08, 0.02], [0.35, 0.27, 0.06], [0.6, 0.5, 0.2], 60, type="metal",
                       n=[0.143, 0.375, 1.442], k=[3.983, 2.386, 1.603]),
    "red":    material([0.09, 0.02, 0.02], [0.8, 0.2, 0.17], [0.6] * 3, 30),
    "blue":   material([0.02, 0.04, 0.09], [0.2, 0.36, 0.8], [0.9] * 3, 80),
    "white":  material([0.09] * 3, [0.9, 0.9, 0.88], [0.5] * 3, 30),
    "green":  material([0.03, 0.07, 0.03], [0.25, 0.65, 0.28], [0.3] * 3, 30),
}

def sphere(center, radius, mat, motion=None):
    s = {"center": center, "radius": radius, "material": mat}
    if motion:
        s["motion"] = motion
    return s

LITE_SPHERES = [
    sphere([40.0, 20.0, -70.0], 7.0, "sun"),  # index 0: the glow's sphere
    sphere([-2.0, 1.3, -1.0], 1.3, "earth"),
    sphere([-0.9, 2.7, 0.9], 0.4, "moon", {"axis": [0, 1, 0], "amplitude": 0.4, "period": 6.0}),
    sphere([0.9, 0.8, 1.8], 0.8, "glass"),
    sphere([2.6, 0.9, -0.6], 0.9, "gold"),
    sphere([0.6, 0.6, -2.9], 0.6, "mirror"),
    sphere([-2.7, 0.45, 2.0], 0.45, "red"),
    sphere([2.3, 0.4, 2.6], 0.4, "blue", {"axis": [1, 0, 0], "amplitude": 0.6, "period": 5.0}),
    sphere([-0.9, 0.35, 2.9], 0.35, "white"),
    sphere([3.7, 0.5, 1.3], 0.5, "green"),
]

def base(comment):
    return {
        "comment": comment,
        "background": [0.02, 0.02, 0.05],
        "camera": {"position": [0.0, 3.0, 9.5], "yaw": 0.0, "pitch": -12.0, "fov_y": 45.0},
        "materials": dict(MATERIALS),
        "lights": [
            {"position": [20.0, 10.0, -35.0], "color": [0.95, 0.88, 0.75]},
            {"position": [-8.0, 6.0, 10.0], "color": [0.30, 0.32, 0.40]},
            {"position": [8.0, 4.0, 6.0], "color": [0.25, 0.22, 0.20]},
        ],
        "sky_box": [TEX + "sky_" + face + ".png" for face in ("px", "nx", "py", "ny", "pz", "nz")],
        "glow": {"sphere": 0, "color": [1.0, 0.75, 0.4], "size": 2.5},
        "discs": [{"center": [0.0, 0.0, 0.0], "normal": [0.0, 1.0, 0.0], "radius": 5.0, "material": "marble"}],
        "rectangles": [{"corner": [-3.5, 0.0, -4.8], "edge_u": [6.5, 0.0, 1.0], "edge_v": [0.0, 3.5, 0.0], "material": "mirror"}],
        "spheres": list(LITE_SPHERES),
    }

def lite():
    return base("Full demo, lite: 10 spheres (textured sun with glow, earth and moon with normal maps, glass, gold, mirror, "
                "plastic), a mirror of 2 triangles, a marble disc, the sky box, 3 point lights. "
                "Made by tools/scenes/make_demo_scenes.py.")

def pro():
    scene = base("Full demo, pro: lite plus 100 small spheres on a spiral around it and a glass cube of 12 triangles "
                 "with a spinning gold torus inside. Made by tools/scenes/make_demo_scenes.py.")
    scene["camera"] = {"position": [0.0, 6.5, 16.5], "yaw": 0.0, "pitch": -19.0, "fov_y": 45.0}  # the spiral needs room
    ring = ["red", "blue", "white", "green", "gold", "mirror", "glass"]
    for i in range(100):
        angle = i * 2.0 * math.pi / 25.0           # four turns
        radius = 6.0 + 0.03 * i                    # widening
        height = 0.3 + 0.045 * i                   # rising
        r = 0.22 + 0.12 * ((i * 7) % 5) / 4.0
        center = [round(radius * math.cos(angle), 3), round(height, 3), round(radius * math.sin(angle), 3)]
        motion = {"axis": [0, 1, 0], "amplitude": 0.25, "period": 3.0 + (i % 4)} if i % 10 == 0 else None
        scene["spheres"].append(sphere(center, round(r, 3), ring[i % len(ring)], motion))
    scene["boxes"] = [{"center": [0.2, 0.92, -0.4], "size": [1.8, 1.8, 1.8], "rotation_y": 30.0, "material": "glass"}]
    scene["tori"] = [{"center": [0.2, 0.92, -0.4], "axis": [0.35, 1.0, 0.25], "major_radius": 0.5, "minor_radius": 0.16,
                      "material": "gold", "spin": {"axis": [0.0, 1.0, 0.0], "period": 8.0}}]
    return scene

def write(name, scene):
    path = Path(__file__).resolve().parents[2] / "assets" / "scenes" / name
    path.write_text(json.dumps(scene, indent=1) + "\n")
    print("wrote", path)

if __name__ == "__main__":
    write("lite.json", lite())
    write("pro.json", pro())
