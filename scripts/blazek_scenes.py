#!/usr/bin/env python3
"""Writes Blazek 1991's ch. VI workload: scenes/blazek/thesis_spheres_N.json, N uniformly random
spheres of identical size (N = 1, 4, 16, 64, 256, 1024, 2048), octahedra subdivided 5 times
(8 * 4^5 = 8192 triangles each; the thesis's "5102 polygons per sphere" matches no subdivision
rule, see scenes/README.md). `zcube reproduce blazek` runs them."""
import json, os

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RECURSION = 5


def scene(n):
    return {"description": f"Blazek 1991 ch. VI workload: {n} uniformly random spheres of identical "
                           f"size, octahedral recursion {RECURSION} ({8 * 4 ** RECURSION} triangles "
                           "each). Written by scripts/blazek_scenes.py.",
            "image": {"width": 512, "height": 512}, "ambient": 0.2, "lights": [{"direction": [-1, -1, -1]}],
            "camera": {"eye": [0, 0, 12], "target": [0, 0, 0], "up": [0, 1, 0], "fov": 45},
            "objects": [{"type": "sphere", "recursion": RECURSION, "count": n, "seed": 1991, "color": "random",
                         "transform": {"scale": 0.35},
                         "placement": {"min": [-3.5, -3.5, -3.5], "max": [3.5, 3.5, 3.5]}}]}


if __name__ == "__main__":
    for n in (1, 4, 16, 64, 256, 1024, 2048):
        path = os.path.join(ROOT, "scenes", "blazek", f"thesis_spheres_{n}.json")
        with open(path, "w") as f:
            f.write(json.dumps(scene(n), indent=1) + "\n")
        print("wrote", os.path.relpath(path, ROOT))
