"""rviz2's RobotModel display, its model: a URDF (the text on ``/robot_description``) as the
3D view draws it. No ROS here.

Each link's ``<visual>``s: the origin in the link's frame (xyz, rpy), the geometry (box size,
cylinder radius and length, sphere radius, or a mesh file with its scale) and the colour of
its material (given in the visual or by name at the robot's top level). Where the links are
is tf's business (robot_state_publisher broadcasts each link's frame); the view places each
link at its frame.

Meshes are named by ``package://PKG/path`` (found through the ament index) or
``file:///path``; the view serves a mesh file only when the current model names it
(``meshes``, each served as ``/mesh/DISPLAY/INDEX/NAME``), and only STL and COLLADA (.dae)
files. A text that is not a URDF is one line (``UrdfError``);
a visual the view cannot draw is skipped with one line in ``problems``.
"""

from __future__ import annotations

import urllib.parse
import xml.etree.ElementTree as ElementTree
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

MESH_SUFFIXES = (".stl", ".dae")
MAX_LINKS = 1000
MAX_VISUALS = 5000
MAX_TEXT = 10 << 20  # characters of a robot description read
DEFAULT_COLOR = [0.8, 0.8, 0.8, 1.0]


class UrdfError(Exception):
    """A robot description that is not a URDF; str() is one line."""


@dataclass
class RobotModel:
    name: str
    links: list[dict[str, Any]]
    meshes: list[Path] = field(default_factory=list)
    problems: list[str] = field(default_factory=list)

    def as_dict(self) -> dict[str, Any]:
        return {"name": self.name, "links": self.links, "problems": self.problems}


def numbers(text: str | None, count: int, default: list[float], what: str) -> list[float]:
    if text is None:
        return list(default)
    try:
        values = [float(word) for word in text.split()]
    except ValueError:
        raise UrdfError(f"{what}: {text!r} is not {count} numbers") from None
    if len(values) != count:
        raise UrdfError(f"{what}: {text!r} is not {count} numbers")
    return values


def resolve_mesh(uri: str, package_share: Any) -> Path:
    """The file a mesh URI names (package:// through ``package_share(name)``, file://, or a
    plain path); UrdfError if it is none."""
    parts = urllib.parse.urlsplit(uri)
    if parts.scheme == "package":
        try:
            share = Path(package_share(parts.netloc))
        except Exception:
            raise UrdfError(f"mesh {uri!r}: package {parts.netloc!r} not found") from None
        path = share / urllib.parse.unquote(parts.path).lstrip("/")
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


def parse(text: str, package_share: Any) -> RobotModel:
    """The model in a URDF's text; UrdfError (one line) if it is not a URDF."""
    if len(text) > MAX_TEXT:
        raise UrdfError(f"robot description larger than {MAX_TEXT} characters")
    try:
        root = ElementTree.fromstring(text)
    except ElementTree.ParseError as error:
        raise UrdfError(f"robot description is not XML: {error}") from None
    if root.tag != "robot":
        raise UrdfError(f"robot description is not a URDF: its root is <{root.tag}>, not <robot>")
    colors = {}
    for material in root.findall("material"):
        color = material.find("color")
        if material.get("name") and color is not None:
            colors[material.get("name")] = numbers(
                color.get("rgba"), 4, DEFAULT_COLOR, f"material {material.get('name')!r}"
            )
    model = RobotModel(root.get("name", ""), [])
    visuals = 0
    for link in root.findall("link")[:MAX_LINKS]:
        name = link.get("name")
        if not name:
            raise UrdfError("robot description is not a URDF: a <link> has no name")
        shapes = []
        for visual in link.findall("visual"):
            if visuals >= MAX_VISUALS:
                model.problems.append(f"more than {MAX_VISUALS} visuals: the rest left out")
                break
            try:
                shape = _visual(visual, colors, model, package_share, name)
            except UrdfError as error:
                model.problems.append(f"link {name!r}: {error}")
                continue
            if shape is not None:
                shapes.append(shape)
                visuals += 1
        model.links.append({"name": name, "visuals": shapes})
    if not model.links:
        raise UrdfError("robot description is not a URDF: it has no <link>")
    return model


def _visual(
    visual: ElementTree.Element,
    colors: dict[str, list[float]],
    model: RobotModel,
    package_share: Any,
    link: str,
) -> dict[str, Any] | None:
    where = f"visual of {link!r}"
    origin = visual.find("origin")
    xyz = numbers(origin.get("xyz") if origin is not None else None, 3, [0, 0, 0], where)
    rpy = numbers(origin.get("rpy") if origin is not None else None, 3, [0, 0, 0], where)
    shape: dict[str, Any] = {"xyz": xyz, "rpy": rpy, "color": DEFAULT_COLOR}
    material = visual.find("material")
    if material is not None:
        color = material.find("color")
        if color is not None:
            shape["color"] = numbers(color.get("rgba"), 4, DEFAULT_COLOR, where)
        elif material.get("name") in colors:
            shape["color"] = colors[material.get("name")]
    geometry = visual.find("geometry")
    item = geometry[0] if geometry is not None and len(geometry) else None
    if item is None:
        raise UrdfError("a <visual> without <geometry>")
    if item.tag == "box":
        shape.update(type="box", size=numbers(item.get("size"), 3, [1, 1, 1], where))
    elif item.tag == "cylinder":
        radius = numbers(item.get("radius"), 1, [1], where)[0]
        length = numbers(item.get("length"), 1, [1], where)[0]
        shape.update(type="cylinder", radius=radius, length=length)
    elif item.tag == "sphere":
        shape.update(type="sphere", radius=numbers(item.get("radius"), 1, [1], where)[0])
    elif item.tag == "mesh":
        uri = item.get("filename", "")
        path = resolve_mesh(uri, package_share)
        if path not in model.meshes:
            model.meshes.append(path)
        index = model.meshes.index(path)
        shape.update(
            type="mesh",
            uri=uri,
            mesh=f"{index}/{urllib.parse.quote(path.name)}",
            format=path.suffix.lower()[1:],
            scale=numbers(item.get("scale"), 3, [1, 1, 1], where),
        )
    else:
        raise UrdfError(f"<{item.tag}> is not a URDF geometry")
    return shape
