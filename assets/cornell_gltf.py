#!/usr/bin/env python3
"""Writes assets/cornell.gltf, the built-in `cornell` scene, from the Cornell Box data.

Geometry: the Cornell Program of Computer Graphics' published measurements of the box (in mm),
converted to metres. Reflectances and the light are RGB approximations; docs/scenes.md says where
each number comes from. Run from anywhere: `python3 assets/cornell_gltf.py`. The output is
deterministic (same bytes on every run), so a diff of cornell.gltf shows any change to the data.
"""
import base64
import json
import math
import pathlib
import struct

MM = 0.001  # the published data are in millimetres; glTF and radmesh use metres

# The published quads, in mm, in their published vertex order (which faces each surface into the
# box; main() checks it). The ceiling is published as one quad with the light in its plane; here
# it is cut into four rectangles around the light's opening so that the two do not overlap.
LIGHT = [(343.0, 548.8, 227.0), (343.0, 548.8, 332.0), (213.0, 548.8, 332.0), (213.0, 548.8, 227.0)]
SURFACES = [
    ("floor", "white", [[(552.8, 0.0, 0.0), (0.0, 0.0, 0.0), (0.0, 0.0, 559.2), (549.6, 0.0, 559.2)]]),
    ("ceiling", "white", [
        # x from 0 to 556, z from 0 to 559.2, less the light's 213..343 x 227..332; facing down.
        [(556.0, 548.8, 0.0), (556.0, 548.8, 227.0), (0.0, 548.8, 227.0), (0.0, 548.8, 0.0)],
        [(556.0, 548.8, 332.0), (556.0, 548.8, 559.2), (0.0, 548.8, 559.2), (0.0, 548.8, 332.0)],
        [(213.0, 548.8, 227.0), (213.0, 548.8, 332.0), (0.0, 548.8, 332.0), (0.0, 548.8, 227.0)],
        [(556.0, 548.8, 227.0), (556.0, 548.8, 332.0), (343.0, 548.8, 332.0), (343.0, 548.8, 227.0)],
    ]),
    ("light", "light", [LIGHT]),
    ("back wall", "white", [[(549.6, 0.0, 559.2), (0.0, 0.0, 559.2), (0.0, 548.8, 559.2), (556.0, 548.8, 559.2)]]),
    ("right wall", "green", [[(0.0, 0.0, 559.2), (0.0, 0.0, 0.0), (0.0, 548.8, 0.0), (0.0, 548.8, 559.2)]]),
    # Published non-planar (3.2 mm off at one corner): it stays two triangles.
    ("left wall", "red", [[(552.8, 0.0, 0.0), (549.6, 0.0, 559.2), (556.0, 548.8, 559.2), (556.0, 548.8, 0.0)]]),
    ("short block", "white", [
        [(130.0, 165.0, 65.0), (82.0, 165.0, 225.0), (240.0, 165.0, 272.0), (290.0, 165.0, 114.0)],
        [(290.0, 0.0, 114.0), (290.0, 165.0, 114.0), (240.0, 165.0, 272.0), (240.0, 0.0, 272.0)],
        [(130.0, 0.0, 65.0), (130.0, 165.0, 65.0), (290.0, 165.0, 114.0), (290.0, 0.0, 114.0)],
        [(82.0, 0.0, 225.0), (82.0, 165.0, 225.0), (130.0, 165.0, 65.0), (130.0, 0.0, 65.0)],
        [(240.0, 0.0, 272.0), (240.0, 165.0, 272.0), (82.0, 165.0, 225.0), (82.0, 0.0, 225.0)],
    ]),
    ("tall block", "white", [
        [(423.0, 330.0, 247.0), (265.0, 330.0, 296.0), (314.0, 330.0, 456.0), (472.0, 330.0, 406.0)],
        [(423.0, 0.0, 247.0), (423.0, 330.0, 247.0), (472.0, 330.0, 406.0), (472.0, 0.0, 406.0)],
        [(472.0, 0.0, 406.0), (472.0, 330.0, 406.0), (314.0, 330.0, 456.0), (314.0, 0.0, 456.0)],
        [(314.0, 0.0, 456.0), (314.0, 330.0, 456.0), (265.0, 330.0, 296.0), (265.0, 0.0, 296.0)],
        [(265.0, 0.0, 296.0), (265.0, 330.0, 296.0), (423.0, 330.0, 247.0), (423.0, 0.0, 247.0)],
    ]),
]

# Light: the radiance (17, 12, 4) W/(m^2 sr) of common RGB renditions of the box, as the exitance
# of a Lambertian emitter, E = pi * L, written as emissiveFactor (17, 12, 4)/17 x strength 17 pi.
LIGHT_RADIANCE = (17.0, 12.0, 4.0)
MATERIALS = {
    "white": {"rho": (0.725, 0.71, 0.68)},
    "red": {"rho": (0.63, 0.065, 0.05)},
    "green": {"rho": (0.14, 0.45, 0.091)},
    "light": {"rho": (0.78, 0.78, 0.78), "radiance": LIGHT_RADIANCE},
}


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def centroid(points):
    return tuple(sum(c) / len(points) for c in zip(*points))


def check_facing(name, quad):
    """Shell surfaces face the box's centre; block faces face away from their block's centre."""
    normal = cross(sub(quad[1], quad[0]), sub(quad[2], quad[0]))
    if "block" in name:
        block = next(quads for n, _, quads in SURFACES if n == name)
        outward = sub(centroid(quad), centroid([p for q in block for p in q]))
    else:
        outward = sub((278.0, 274.4, 279.6), centroid(quad))
    if dot(normal, outward) <= 0.0:
        raise SystemExit(f"{name}: quad {quad} faces the wrong way")


def main():
    binary = bytearray()
    views, accessors, meshes, nodes = [], [], [], []

    def add_view(data, target):
        while len(binary) % 4:
            binary.append(0)
        views.append({"buffer": 0, "byteOffset": len(binary), "byteLength": len(data), "target": target})
        binary.extend(data)
        return len(views) - 1

    material_names = list(MATERIALS)
    for name, material, quads in SURFACES:
        points, indices = [], []
        for quad in quads:
            check_facing(name, quad)
            base = len(points)
            points.extend(tuple(c * MM for c in p) for p in quad)
            indices.extend([base, base + 1, base + 2, base, base + 2, base + 3])
        floats = [struct.unpack("<f", struct.pack("<f", c))[0] for p in points for c in p]
        position_view = add_view(struct.pack(f"<{len(floats)}f", *floats), 34962)
        accessors.append({"bufferView": position_view, "componentType": 5126, "count": len(points), "type": "VEC3",
                          "min": [min(floats[k::3]) for k in range(3)], "max": [max(floats[k::3]) for k in range(3)]})
        index_view = add_view(struct.pack(f"<{len(indices)}H", *indices), 34963)
        accessors.append({"bufferView": index_view, "componentType": 5123, "count": len(indices), "type": "SCALAR"})
        meshes.append({"name": name, "primitives": [{"attributes": {"POSITION": len(accessors) - 2},
                                                    "indices": len(accessors) - 1,
                                                    "material": material_names.index(material), "mode": 4}]})
        nodes.append({"name": name, "mesh": len(meshes) - 1})

    materials = []
    for name, m in MATERIALS.items():
        entry = {"name": name, "pbrMetallicRoughness": {"baseColorFactor": [*m["rho"], 1.0], "metallicFactor": 0.0}}
        if "radiance" in m:
            peak = max(m["radiance"])
            entry["emissiveFactor"] = [c / peak for c in m["radiance"]]
            entry["extensions"] = {"KHR_materials_emissive_strength": {"emissiveStrength": math.pi * peak}}
        materials.append(entry)

    gltf = {
        "asset": {"version": "2.0", "generator": "radmesh assets/cornell_gltf.py",
                  "copyright": "Geometry from the Cornell Box data, Cornell University Program of Computer Graphics"},
        "extensionsUsed": ["KHR_materials_emissive_strength"],
        "scene": 0,
        "scenes": [{"name": "Cornell box", "nodes": list(range(len(nodes)))}],
        "nodes": nodes,
        "meshes": meshes,
        "materials": materials,
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [{"byteLength": len(binary),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(binary).decode("ascii")}],
    }
    out = pathlib.Path(__file__).with_name("cornell.gltf")
    out.write_text(json.dumps(gltf, indent=1) + "\n")


if __name__ == "__main__":
    main()
