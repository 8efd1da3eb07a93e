"""rviz2's RobotModel display, its model: a URDF (the text on ``/robot_description``) as the
3D view draws it. No ROS here.

The URDF is read by the project's one reader (``ros_tutorials_common/urdf.py``, the reader
robot_state_publisher uses): bounded, no DTD, and checked as urdfdom checks it, so a
description robot_state_publisher refuses is refused here with the same one line
(``UrdfError``), as rviz2's display fails to load a model urdfdom refuses. This module turns
each link's visuals into what the page draws: the origin in the link's frame (xyz, rpy), the
geometry (box size, cylinder radius and length, sphere radius, or a mesh file with its
scale) and the colour of its material. Where the links are is tf's business
(robot_state_publisher broadcasts each link's frame); the view places each link at its frame.

Meshes are named by ``package://PKG/path`` (found through the ament index, and only inside
that package's share folder) or ``file:///path``; the view serves a mesh file only when the
current model names it (``meshes``, each served as ``/mesh/DISPLAY/INDEX/NAME``), and only
STL and COLLADA (.dae) files. A mesh the view cannot draw is skipped with one line in
``problems``; the rest of the robot is drawn.
"""

from __future__ import annotations

import os
import urllib.parse
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ros_tutorials_common import urdf
from ros_tutorials_common.urdf import UrdfError

__all__ = ["RobotModel", "UrdfError", "parse", "resolve_mesh"]

MESH_SUFFIXES = (".stl", ".dae")
MAX_VISUALS = 5000  # visuals the page is sent; the rest are left out, with one line
DEFAULT_COLOR = [0.8, 0.8, 0.8, 1.0]  # a visual without a material, as rviz2 draws it
REFUSED = "the robot description is not a valid URDF: "


@dataclass
class RobotModel:
    name: str
    links: list[dict[str, Any]]
    meshes: list[Path] = field(default_factory=list)
    problems: list[str] = field(default_factory=list)

    def as_dict(self) -> dict[str, Any]:
        return {"name": self.name, "links": self.links, "problems": self.problems}


def resolve_mesh(uri: str, package_share: Any) -> Path:
    """The file a mesh URI names (package:// through ``package_share(name)``, and inside
    that folder; file://, or a plain path); UrdfError if it is none."""
    parts = urllib.parse.urlsplit(uri)
    if parts.scheme == "package":
        try:
            share = Path(package_share(parts.netloc))
        except Exception:
            raise UrdfError(f"mesh {uri!r}: package {parts.netloc!r} not found") from None
        inside = os.path.normpath(urllib.parse.unquote(parts.path).lstrip("/"))
        if inside == ".." or inside.startswith(("../", "/")):
            raise UrdfError(f"mesh {uri!r}: the path leaves package {parts.netloc!r}")
        path = share / inside
    elif parts.scheme == "file":
        path = Path(urllib.parse.unquote(parts.path))
    elif not parts.scheme:
        path = Path(uri)
    else:
        raise UrdfError(f"mesh {uri!r}: only package:// and file:// meshes are read")
    if path.suffix.lower() not in MESH_SUFFIXES:
        raise UrdfError(f"mesh {uri!r}: the 3D view reads STL and COLLADA (.dae) meshes only")
    if not path.is_file():
        raise UrdfError(f"mesh {uri!r}: no such file {path}")
    return path.resolve()


def parse(text: str | bytes, package_share: Any) -> RobotModel:
    """The model in a URDF's text; UrdfError (one line: REFUSED and urdf.parse's reason)
    if it is not a valid URDF."""
    try:
        robot = urdf.parse(text)
    except UrdfError as error:
        raise UrdfError(f"{REFUSED}{error}") from None
    model = RobotModel(robot.name, [])
    count = 0
    for name in robot.links:
        shapes = []
        for visual in robot.visuals[name]:
            if count >= MAX_VISUALS:
                break
            try:
                shapes.append(_shape(visual, model, package_share))
            except UrdfError as error:
                model.problems.append(f"link {name!r}: {error}")
                continue
            count += 1
        model.links.append({"name": name, "visuals": shapes})
    total = sum(len(visuals) for visuals in robot.visuals.values())
    if total > MAX_VISUALS:
        model.problems.append(f"{total} visuals: the first {MAX_VISUALS} are drawn")
    return model


def _shape(visual: urdf.Visual, model: RobotModel, package_share: Any) -> dict[str, Any]:
    """A visual as the page draws it."""
    color = list(visual.color) if visual.color is not None else DEFAULT_COLOR
    shape: dict[str, Any] = {"xyz": list(visual.xyz), "rpy": list(visual.rpy), "color": color}
    geometry = visual.geometry
    if geometry.type == "box":
        shape.update(type="box", size=list(geometry.size))
    elif geometry.type == "cylinder":
        shape.update(type="cylinder", radius=geometry.radius, length=geometry.length)
    elif geometry.type == "sphere":
        shape.update(type="sphere", radius=geometry.radius)
    else:
        path = resolve_mesh(geometry.filename, package_share)
        if path not in model.meshes:
            model.meshes.append(path)
        shape.update(
            type="mesh",
            uri=geometry.filename,
            mesh=f"{model.meshes.index(path)}/{urllib.parse.quote(path.name)}",
            format=path.suffix.lower()[1:],
            scale=list(geometry.scale),
        )
    return shape
