"""Write urdf_tutorial's gripper meshes: meshes/l_finger.dae and meshes/l_finger_tip.dae.

The URDF pages' R2D2 names two meshes of ROS's urdf_tutorial package (borrowed there from the
PR2). This project does not copy them: these are simple shapes of its own, under the same names
and at the same scale (a finger about 9 cm long; its tip starts where the URDF's tip joint puts
it, 0.09137 m along), as COLLADA 1.4.1 with a colour of their own.

    .venv/bin/python tools/make_urdf_meshes.py    (the files are committed; run after a change)
"""

# ruff: noqa: E501 - the COLLADA text below is kept as one would read it
from __future__ import annotations

import sys
from pathlib import Path

MESHES = Path(__file__).resolve().parent.parent / "urdf_tutorial" / "meshes"

# A tapered block: (x, y_min, y_max, z_half) at its back and front ends.
FINGER = ((-0.01, -0.012, 0.012, 0.010), (0.095, -0.002, 0.014, 0.007))
FINGER_TIP = ((-0.004, -0.010, 0.008, 0.007), (0.045, -0.002, 0.004, 0.003))
# The faces of the block's eight corners (0-3 back, 4-7 front), each wound outwards.
QUADS = ((0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (2, 3, 7, 6), (1, 2, 6, 5), (0, 4, 7, 3))


def corners(shape: tuple) -> list[tuple[float, float, float]]:
    points = []
    for x, y_min, y_max, z in shape:
        points += [(x, y_min, -z), (x, y_max, -z), (x, y_max, z), (x, y_min, z)]
    return points


def normal(a: tuple, b: tuple, c: tuple) -> tuple[float, float, float]:
    u = [b[i] - a[i] for i in range(3)]
    v = [c[i] - a[i] for i in range(3)]
    n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
    length = sum(x * x for x in n) ** 0.5
    return (n[0] / length, n[1] / length, n[2] / length)


def collada(name: str, shape: tuple, rgba: tuple[float, ...]) -> str:
    points = corners(shape)
    normals = [normal(points[q[0]], points[q[1]], points[q[2]]) for q in QUADS]
    triangles = []
    for face, (a, b, c, d) in enumerate(QUADS):
        for corner in (a, b, c, a, c, d):
            triangles += [corner, face]
    flat = " ".join(f"{x:.6g}" for point in points for x in point)
    flat_normals = " ".join(f"{x:.6g}" for n in normals for x in n)
    color = " ".join(f"{x:g}" for x in rgba)
    return f"""<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset>
    <contributor><authoring_tool>ros-tutorials tools/make_urdf_meshes.py</authoring_tool></contributor>
    <unit name="meter" meter="1"/>
    <up_axis>Z_UP</up_axis>
  </asset>
  <library_effects>
    <effect id="{name}-effect">
      <profile_COMMON>
        <technique sid="common">
          <phong>
            <diffuse><color sid="diffuse">{color}</color></diffuse>
            <specular><color sid="specular">0.3 0.3 0.3 1</color></specular>
            <shininess><float sid="shininess">20</float></shininess>
          </phong>
        </technique>
      </profile_COMMON>
    </effect>
  </library_effects>
  <library_materials>
    <material id="{name}-material" name="{name}">
      <instance_effect url="#{name}-effect"/>
    </material>
  </library_materials>
  <library_geometries>
    <geometry id="{name}-mesh" name="{name}">
      <mesh>
        <source id="{name}-positions">
          <float_array id="{name}-positions-array" count="{len(points) * 3}">{flat}</float_array>
          <technique_common>
            <accessor source="#{name}-positions-array" count="{len(points)}" stride="3">
              <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
            </accessor>
          </technique_common>
        </source>
        <source id="{name}-normals">
          <float_array id="{name}-normals-array" count="{len(normals) * 3}">{flat_normals}</float_array>
          <technique_common>
            <accessor source="#{name}-normals-array" count="{len(normals)}" stride="3">
              <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
            </accessor>
          </technique_common>
        </source>
        <vertices id="{name}-vertices">
          <input semantic="POSITION" source="#{name}-positions"/>
        </vertices>
        <triangles material="{name}-material" count="{len(triangles) // 6}">
          <input semantic="VERTEX" source="#{name}-vertices" offset="0"/>
          <input semantic="NORMAL" source="#{name}-normals" offset="1"/>
          <p>{" ".join(str(i) for i in triangles)}</p>
        </triangles>
      </mesh>
    </geometry>
  </library_geometries>
  <library_visual_scenes>
    <visual_scene id="scene" name="scene">
      <node id="{name}" name="{name}">
        <instance_geometry url="#{name}-mesh">
          <bind_material>
            <technique_common>
              <instance_material symbol="{name}-material" target="#{name}-material"/>
            </technique_common>
          </bind_material>
        </instance_geometry>
      </node>
    </visual_scene>
  </library_visual_scenes>
  <scene>
    <instance_visual_scene url="#scene"/>
  </scene>
</COLLADA>
"""


def main() -> int:
    MESHES.mkdir(parents=True, exist_ok=True)
    (MESHES / "l_finger.dae").write_text(collada("l_finger", FINGER, (0.55, 0.55, 0.58, 1)))
    (MESHES / "l_finger_tip.dae").write_text(
        collada("l_finger_tip", FINGER_TIP, (0.25, 0.25, 0.28, 1))
    )
    print(f"wrote {MESHES}/l_finger.dae, l_finger_tip.dae")
    return 0


if __name__ == "__main__":
    sys.exit(main())
