"""A robot read from URDF: links, joints, their origins, axes and limits, and each link's
visuals (origin, geometry, material colour).

The one URDF reader of the project: robot_state_publisher and joint_state_publisher read the
joints, rviz2's RobotModel display the visuals. A description is checked as urdfdom (ROS 2's
C++ URDF parser, which all three use upstream) checks it: a ``<robot>`` with a name, links
and joints with unique names, known joint types, a parent and a child link that exist, limits
on revolute and prismatic joints, one root link and no link with two parents; a visual with
one known geometry and its required sizes, a named material, robot-level materials with a
colour and unique names. A description that breaks one of those rules is refused with a
``UrdfError`` whose text is one line.

Bounded: at most MAX_URDF_BYTES of text and MAX_ELEMENTS elements, and no DTD (an entity
declaration is how a few hundred bytes of XML expand into gigabytes). Collision geometry and
inertia are read by no tool here and are not read. Where a mesh file is is the reader's
business (rviz2 finds ``package://`` files). No rclpy: a pure model.

Why not a URDF parser from PyPI: urdf-parser-py's last release is from 2021 and does not check
the tree; yourdfpy and urchin load trimesh (and meshes) to read a file. What the two nodes need
is the joints of a checked tree, which the standard library reads in about 200 lines.
"""

from __future__ import annotations

import math
import xml.etree.ElementTree as ElementTree
from collections.abc import Container
from dataclasses import dataclass, field

from ros_tutorials_common.quaternion import (
    Quaternion,
    Vector,
    multiply,
    quaternion_from_rpy,
    rotate,
)

MAX_URDF_BYTES = 8 * 1024 * 1024  # a robot description (real robots' are well under 1 MiB)
MAX_ELEMENTS = 200_000
JOINT_TYPES = ("revolute", "continuous", "prismatic", "fixed", "floating", "planar")
MOVING = ("revolute", "continuous", "prismatic")  # one position each, as KDL moves them
GEOMETRIES = ("box", "cylinder", "sphere", "mesh")
Color = tuple[float, float, float, float]  # red, green, blue, alpha: 0 to 1


class UrdfError(ValueError):
    """A robot description refused: the text is one line saying why."""


@dataclass(frozen=True)
class Pose:
    """A rigid transform: translation, then rotation as a unit quaternion (x, y, z, w)."""

    xyz: Vector = (0.0, 0.0, 0.0)
    rotation: Quaternion = (0.0, 0.0, 0.0, 1.0)

    def __mul__(self, other: Pose) -> Pose:
        """This pose followed by ``other`` expressed in this pose's frame."""
        moved = rotate(self.rotation, other.xyz)
        return Pose(
            (self.xyz[0] + moved[0], self.xyz[1] + moved[1], self.xyz[2] + moved[2]),
            multiply(self.rotation, other.rotation),
        )


@dataclass(frozen=True)
class Mimic:
    joint: str
    multiplier: float = 1.0
    offset: float = 0.0


@dataclass(frozen=True)
class Joint:
    name: str
    type: str
    parent: str
    child: str
    origin: Pose = Pose()
    axis: Vector = (1.0, 0.0, 0.0)
    lower: float = 0.0
    upper: float = 0.0
    has_limit: bool = False
    soft_lower: float | None = None  # <safety_controller soft_lower_limit>
    soft_upper: float | None = None
    mimic: Mimic | None = None

    def pose(self, position: float = 0.0) -> Pose:
        """The child link's frame in the parent's at this joint position (KDL's segment pose:
        the origin, then a turn about the axis or a slide along it)."""
        if self.type in ("revolute", "continuous"):
            half = position / 2.0
            s = math.sin(half)
            turn = (self.axis[0] * s, self.axis[1] * s, self.axis[2] * s, math.cos(half))
            return self.origin * Pose(rotation=turn)
        if self.type == "prismatic":
            return self.origin * Pose(xyz=tuple(a * position for a in self.axis))  # type: ignore[arg-type]
        return self.origin


@dataclass(frozen=True)
class Geometry:
    """A visual's shape: a box's size, a cylinder's radius and length, a sphere's radius, or
    a mesh file's name (as the URDF gives it: ``package://``, ``file://``) and scale."""

    type: str  # one of GEOMETRIES
    size: Vector = (0.0, 0.0, 0.0)
    radius: float = 0.0
    length: float = 0.0
    filename: str = ""
    scale: Vector = (1.0, 1.0, 1.0)


@dataclass(frozen=True)
class Visual:
    """One ``<visual>`` of a link: its origin in the link's frame (xyz, rpy as written), its
    geometry, and its material's name and colour (the visual's own, or the robot's material
    of that name; none: '' and None)."""

    geometry: Geometry
    xyz: Vector = (0.0, 0.0, 0.0)
    rpy: Vector = (0.0, 0.0, 0.0)
    material: str = ""
    color: Color | None = None


@dataclass
class Robot:
    name: str
    links: list[str] = field(default_factory=list)
    joints: dict[str, Joint] = field(default_factory=dict)  # in the file's order
    root: str = ""
    visuals: dict[str, list[Visual]] = field(default_factory=dict)  # link -> its visuals
    materials: dict[str, Color] = field(default_factory=dict)  # the robot-level ones

    def moving_joints(self) -> list[Joint]:
        return [joint for joint in self.joints.values() if joint.type in MOVING]


def _numbers(text: str | None, count: int, what: str, default: tuple[float, ...]) -> tuple:
    if text is None:
        return default
    words = text.split()
    if len(words) != count:
        raise UrdfError(f"{what} must be {count} numbers, not {text[:60]!r}")
    try:
        values = tuple(float(word) for word in words)
    except ValueError:
        raise UrdfError(f"{what} must be {count} numbers, not {text[:60]!r}") from None
    if not all(math.isfinite(value) for value in values):
        raise UrdfError(f"{what} must be finite numbers, not {text[:60]!r}")
    return values


def _number(element: ElementTree.Element, attribute: str, what: str, default: float) -> float:
    return _numbers(element.get(attribute), 1, what, (default,))[0]


def _xyz_rpy(element: ElementTree.Element | None, what: str) -> tuple[Vector, Vector]:
    """An ``<origin>``'s xyz and rpy as written (zeros where absent)."""
    if element is None:
        return (0.0, 0.0, 0.0), (0.0, 0.0, 0.0)
    xyz = _numbers(element.get("xyz"), 3, f"{what}: origin xyz", (0.0, 0.0, 0.0))
    rpy = _numbers(element.get("rpy"), 3, f"{what}: origin rpy", (0.0, 0.0, 0.0))
    return xyz, rpy


def _origin(element: ElementTree.Element | None, what: str) -> Pose:
    xyz, rpy = _xyz_rpy(element, what)
    return Pose(xyz, quaternion_from_rpy(*rpy))


def _color(material: ElementTree.Element, what: str) -> Color | None:
    color = material.find("color")
    if color is None:
        return None
    rgba = _numbers(color.get("rgba"), 4, f"{what}: color rgba", (0.0, 0.0, 0.0, 1.0))
    if not all(0.0 <= value <= 1.0 for value in rgba):
        raise UrdfError(f"{what}: color rgba must be 4 numbers from 0 to 1, not {rgba}")
    return rgba  # type: ignore[return-value]


def _new_name(element: ElementTree.Element, kind: str, seen: Container[str]) -> str:
    """An element's name: given, and not an earlier one's of its kind (urdfdom's rule)."""
    name = element.get("name")
    if not name:
        raise UrdfError(f"a {kind} has no name")
    if name in seen:
        raise UrdfError(f"{kind} '{name}' is not unique.")
    return name


def _materials(root: ElementTree.Element) -> dict[str, Color]:
    """The robot-level materials: each named, unique and with a colour (a texture alone is
    drawn by no tool here: grey)."""
    materials: dict[str, Color] = {}
    for material in root.findall("material"):
        name = _new_name(material, "material", materials)
        color = _color(material, f"material [{name}]")
        if color is None and material.find("texture") is None:
            raise UrdfError(f"material [{name}] has neither a texture nor a color defined")
        materials[name] = color or (0.8, 0.8, 0.8, 1.0)
    return materials


def _geometry(element: ElementTree.Element | None, what: str) -> Geometry:
    shapes = [child for child in element] if element is not None else []
    if not shapes:
        raise UrdfError(f"{what}: no geometry")
    shape = shapes[0]
    kind = shape.tag
    if kind not in GEOMETRIES:
        raise UrdfError(f"{what}: unknown geometry type '{kind}'")

    def required(attribute: str, count: int) -> tuple[float, ...]:
        text = shape.get(attribute)
        if text is None:
            raise UrdfError(f"{what}: {kind} has no {attribute} attribute")
        return _numbers(text, count, f"{what}: {kind} {attribute}", ())

    if kind == "box":
        return Geometry(kind, size=required("size", 3))  # type: ignore[arg-type]
    if kind == "cylinder":
        return Geometry(kind, radius=required("radius", 1)[0], length=required("length", 1)[0])
    if kind == "sphere":
        return Geometry(kind, radius=required("radius", 1)[0])
    filename = shape.get("filename")
    if not filename:
        raise UrdfError(f"{what}: mesh has no filename")
    scale = _numbers(shape.get("scale"), 3, f"{what}: mesh scale", (1.0, 1.0, 1.0))
    return Geometry(kind, filename=filename, scale=scale)  # type: ignore[arg-type]


def _visual(element: ElementTree.Element, materials: dict[str, Color], link: str) -> Visual:
    """A link's ``<visual>``. Its material is named; a colour given there also defines the
    name for the visuals after it (as urdfdom adds it to the robot's materials)."""
    what = f"link [{link}]: visual"
    xyz, rpy = _xyz_rpy(element.find("origin"), what)
    geometry = _geometry(element.find("geometry"), what)
    material = element.find("material")
    if material is None:
        return Visual(geometry, xyz, rpy)
    name = material.get("name")
    if not name:
        raise UrdfError(f"{what}: its material has no name")
    color = _color(material, f"{what}: material [{name}]")
    if color is None:
        if name not in materials:
            raise UrdfError(f"link '{link}' material '{name}' undefined.")
        color = materials[name]
    materials.setdefault(name, color)
    return Visual(geometry, xyz, rpy, name, color)


def _joint(element: ElementTree.Element, links: set[str]) -> Joint:
    name = element.get("name")
    if not name:
        raise UrdfError("a joint has no name")
    kind = element.get("type", "")
    if kind not in JOINT_TYPES:
        raise UrdfError(f"Joint [{name}] has no known type [{kind}]")
    ends = {}
    for end in ("parent", "child"):
        tag = element.find(end)
        link = tag.get("link") if tag is not None else None
        if not link:
            raise UrdfError(f"no {end} link specified for joint [{name}]")
        if link not in links:
            raise UrdfError(f"{end} link [{link}] of joint [{name}] not found")
        ends[end] = link
    what = f"joint [{name}]"
    axis_tag = element.find("axis")
    axis = _numbers(
        axis_tag.get("xyz") if axis_tag is not None else None, 3, f"{what}: axis", (1, 0, 0)
    )
    norm = math.sqrt(sum(a * a for a in axis))
    if kind in MOVING and norm == 0.0:
        raise UrdfError(f"{what}: the axis is zero")
    axis = tuple(a / norm for a in axis) if norm else (1.0, 0.0, 0.0)
    limit = element.find("limit")
    if limit is None and kind in ("revolute", "prismatic"):
        raise UrdfError(f"Joint [{name}] is of type {kind.upper()} but it does not specify limits")
    lower = _number(limit, "lower", f"{what}: limit lower", 0.0) if limit is not None else 0.0
    upper = _number(limit, "upper", f"{what}: limit upper", 0.0) if limit is not None else 0.0
    safety = element.find("safety_controller")
    soft = {}
    for side in ("soft_lower_limit", "soft_upper_limit"):
        if safety is not None and safety.get(side) is not None:
            soft[side] = _number(safety, side, f"{what}: {side}", 0.0)
    mimic_tag = element.find("mimic")
    mimic = None
    if mimic_tag is not None:
        if not mimic_tag.get("joint"):
            raise UrdfError(f"{what}: mimic names no joint")
        mimic = Mimic(
            mimic_tag.get("joint", ""),
            _number(mimic_tag, "multiplier", f"{what}: mimic multiplier", 1.0),
            _number(mimic_tag, "offset", f"{what}: mimic offset", 0.0),
        )
    return Joint(
        name,
        kind,
        ends["parent"],
        ends["child"],
        _origin(element.find("origin"), what),
        axis,  # type: ignore[arg-type]
        lower,
        upper,
        limit is not None,
        soft.get("soft_lower_limit"),
        soft.get("soft_upper_limit"),
        mimic,
    )


def parse(text: str | bytes) -> Robot:
    """The robot a URDF text describes; UrdfError (one line) if it is not a valid one."""
    if len(text) > MAX_URDF_BYTES:
        raise UrdfError(f"the robot description is larger than {MAX_URDF_BYTES // 2**20} MiB")
    if not text.strip():
        raise UrdfError("the robot description is empty")
    marker = b"<!DOCTYPE" if isinstance(text, bytes) else "<!DOCTYPE"
    if marker in text:
        raise UrdfError("a DOCTYPE (DTD) is not allowed in a robot description")
    parser = ElementTree.XMLPullParser(events=("start",))
    elements = 0
    root = None
    try:
        parser.feed(text)
        parser.close()
        for _, element in parser.read_events():
            root = element if root is None else root
            elements += 1
            if elements > MAX_ELEMENTS:
                raise UrdfError(f"the robot description has more than {MAX_ELEMENTS} elements")
    except ElementTree.ParseError as error:
        raise UrdfError(f"not valid XML: {error}") from None
    if root is None:
        raise UrdfError("the robot description is empty")
    if root.tag != "robot":
        raise UrdfError("Could not find the 'robot' element in the xml file")
    name = root.get("name")
    if not name:
        raise UrdfError("No name given for the robot.")
    robot = Robot(name, materials=_materials(root))
    seen: set[str] = set()
    for link in root.findall("link"):
        link_name = _new_name(link, "link", seen)
        seen.add(link_name)
        robot.links.append(link_name)
        robot.visuals[link_name] = [
            _visual(visual, robot.materials, link_name) for visual in link.findall("visual")
        ]
    if not robot.links:
        raise UrdfError("No link elements found in urdf file")
    parents: dict[str, str] = {}
    for element in root.findall("joint"):
        joint = _joint(element, seen)
        if joint.name in robot.joints:
            raise UrdfError(f"joint '{joint.name}' is not unique.")
        if joint.child in parents:
            raise UrdfError(
                f"link [{joint.child}] has two parents: joints [{parents[joint.child]}] "
                f"and [{joint.name}]"
            )
        parents[joint.child] = joint.name
        robot.joints[joint.name] = joint
    for joint in robot.joints.values():
        if joint.mimic is not None and joint.mimic.joint not in robot.joints:
            raise UrdfError(
                f"joint [{joint.name}] mimics joint [{joint.mimic.joint}], which does not exist"
            )
    roots = [link for link in robot.links if link not in parents]
    if not roots:
        raise UrdfError("No root link found. The robot xml is not a valid tree.")
    if len(roots) > 1:
        raise UrdfError(f"Two root links found: [{roots[0]}] and [{roots[1]}]")
    robot.root = roots[0]
    _check_tree(robot)
    return robot


def _check_tree(robot: Robot) -> None:
    """Every link reached from the root (a loop of joints leaves its links unreached)."""
    children: dict[str, list[str]] = {}
    for joint in robot.joints.values():
        children.setdefault(joint.parent, []).append(joint.child)
    reached, todo = {robot.root}, [robot.root]
    while todo:
        for child in children.get(todo.pop(), []):
            if child not in reached:
                reached.add(child)
                todo.append(child)
    lost = [link for link in robot.links if link not in reached]
    if lost:
        raise UrdfError(f"link [{lost[0]}] is in a loop of joints: a URDF must be a tree")
