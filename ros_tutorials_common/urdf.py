"""A robot's kinematic tree read from URDF: links, joints, their origins, axes and limits.

What robot_state_publisher and joint_state_publisher read of a robot description, checked as
urdfdom checks it (ROS 2's C++ URDF parser): a ``<robot>`` with a name, links and joints with
unique names, known joint types, a parent and a child link that exist, limits on revolute and
prismatic joints, one root link and no link with two parents. A description that breaks one of
those rules is refused with a ``UrdfError`` whose text is one line.

Bounded: at most MAX_URDF_BYTES of text and MAX_ELEMENTS elements, and no DTD (an entity
declaration is how a few hundred bytes of XML expand into gigabytes). Geometry (visual,
collision) is the 3D view's business and is not read here. No rclpy: a pure model.

Why not a URDF parser from PyPI: urdf-parser-py's last release is from 2021 and does not check
the tree; yourdfpy and urchin load trimesh (and meshes) to read a file. What the two nodes need
is the joints of a checked tree, which the standard library reads in about 200 lines.
"""

from __future__ import annotations

import math
import xml.etree.ElementTree as ElementTree
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


@dataclass
class Robot:
    name: str
    links: list[str] = field(default_factory=list)
    joints: dict[str, Joint] = field(default_factory=dict)  # in the file's order
    root: str = ""

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


def _origin(element: ElementTree.Element | None, what: str) -> Pose:
    if element is None:
        return Pose()
    xyz = _numbers(element.get("xyz"), 3, f"{what}: origin xyz", (0.0, 0.0, 0.0))
    rpy = _numbers(element.get("rpy"), 3, f"{what}: origin rpy", (0.0, 0.0, 0.0))
    return Pose(xyz, quaternion_from_rpy(*rpy))


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
    robot = Robot(name)
    seen: set[str] = set()
    for link in root.findall("link"):
        link_name = link.get("name")
        if not link_name:
            raise UrdfError("a link has no name")
        if link_name in seen:
            raise UrdfError(f"link '{link_name}' is not unique.")
        seen.add(link_name)
        robot.links.append(link_name)
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
