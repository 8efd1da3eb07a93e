"""rviz2's display configuration (a ``.rviz`` file, as ``rviz2 -d FILE`` reads it): the fixed
frame and the displays, in the 3D view's terms. No ROS here.

A ``.rviz`` file is YAML that rviz2 writes: ``Visualization Manager`` holds ``Global Options``
(``Fixed Frame``) and ``Displays``, a list of mappings each with a ``Class``
(``rviz_default_plugins/TF``), a ``Name``, ``Enabled`` and, for a display that subscribes, a
``Topic`` (or ``Description Topic`` for RobotModel) whose ``Value`` is the topic name.
``rviz_common/Group`` holds more displays under its own ``Displays``. ROS 1's rviz writes the
same layout with classes ``rviz/TF``, ``rviz/Group`` ...: read as their ROS 2 namesakes (its
RobotModel's ``Robot Description`` names a parameter; here the topic of that name).

What the 3D view draws is in ``KINDS``; a display of any other class is kept out and named in
one line each (``lacking``). A file that is not such YAML is one line (``ConfigError``).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import yaml

# rviz_default_plugins' class -> the 3D view's display kind, its message type, default topic.
KINDS: dict[str, tuple[str, str | None, str | None]] = {
    "rviz_default_plugins/Grid": ("Grid", None, None),
    "rviz_default_plugins/Axes": ("Axes", None, None),
    "rviz_default_plugins/TF": ("TF", None, None),
    "rviz_default_plugins/RobotModel": ("RobotModel", "std_msgs/msg/String", "/robot_description"),
    "rviz_default_plugins/Marker": (
        "Marker",
        "visualization_msgs/msg/Marker",
        "/visualization_marker",
    ),
    "rviz_default_plugins/MarkerArray": (
        "MarkerArray",
        "visualization_msgs/msg/MarkerArray",
        "/visualization_marker_array",
    ),
    "rviz_default_plugins/LaserScan": ("LaserScan", "sensor_msgs/msg/LaserScan", None),
    "rviz_default_plugins/PointCloud2": ("PointCloud2", "sensor_msgs/msg/PointCloud2", None),
    "rviz_default_plugins/Pose": ("Pose", "geometry_msgs/msg/PoseStamped", None),
    "rviz_default_plugins/PoseArray": ("PoseArray", "geometry_msgs/msg/PoseArray", None),
    "rviz_default_plugins/Path": ("Path", "nav_msgs/msg/Path", None),
    "rviz_default_plugins/Odometry": ("Odometry", "nav_msgs/msg/Odometry", None),
    "rviz_default_plugins/Map": ("Map", "nav_msgs/msg/OccupancyGrid", None),
    "rviz_default_plugins/Image": ("Image", "sensor_msgs/msg/Image", None),
}
# A display kind by the message type it shows (rviz's "By topic" list).
BY_TYPE = {type_name: kind for kind, type_name, _ in KINDS.values() if type_name}
GROUP = "rviz_common/Group"
ROS1_PREFIX = "rviz/"  # ROS 1's rviz: rviz/TF is rviz_default_plugins/TF
DEFAULT_FIXED_FRAME = "map"  # rviz2's own default
MAX_DISPLAYS = 200
MAX_FILE = 1 << 20  # bytes of a .rviz file read


class ConfigError(Exception):
    """A .rviz file that cannot be read; str() is one line."""


@dataclass
class Display:
    """One display of the view: its kind, name and (for a subscribing one) topic."""

    kind: str
    name: str
    topic: str | None = None
    type_name: str | None = None
    enabled: bool = True
    options: dict[str, Any] = field(default_factory=dict)

    def as_dict(self, number: int) -> dict[str, Any]:
        return {
            "id": number,
            "kind": self.kind,
            "name": self.name,
            "topic": self.topic,
            "type": self.type_name,
            "enabled": self.enabled,
            "options": self.options,
        }


@dataclass
class Config:
    fixed_frame: str | None  # None: the view chooses (no file, or the file names none)
    displays: list[Display]
    lacking: list[str] = field(default_factory=list)  # one line per display it cannot show
    view: dict[str, Any] = field(default_factory=dict)  # the orbit camera: distance, focal...


def display(kind: str, topic: str | None = None, name: str | None = None) -> Display:
    """A display of ``kind`` (its rviz class without the plugin prefix) on ``topic``."""
    for _, (known, type_name, default_topic) in KINDS.items():
        if known == kind:
            return Display(kind, name or kind, topic or default_topic, type_name)
    raise KeyError(kind)


def default_config() -> Config:
    """What ``rviz2`` with no file shows: a grid, the tf frames and the robot."""
    return Config(None, [display("Grid"), display("TF"), display("RobotModel")])


def load(path: str | Path) -> Config:
    """The configuration in a .rviz file; ConfigError (one line) if it is not one."""
    where = str(path)
    try:
        with open(path, "rb") as file:
            data = file.read(MAX_FILE + 1)
    except OSError as error:
        raise ConfigError(f"cannot read {where}: {error.strerror}") from None
    if len(data) > MAX_FILE:
        raise ConfigError(f"{where}: larger than {MAX_FILE} bytes: not a .rviz file")
    return parse(data.decode("utf-8", "replace"), where)


def parse(text: str, where: str = "<config>") -> Config:
    try:
        document = yaml.safe_load(text)
    except yaml.YAMLError as error:
        mark = getattr(error, "problem_mark", None)
        line = f":{mark.line + 1}" if mark is not None else ""
        problem = getattr(error, "problem", None) or "not YAML"
        raise ConfigError(f"{where}{line}: not a .rviz file: {problem}") from None
    manager = document.get("Visualization Manager") if isinstance(document, dict) else None
    if not isinstance(manager, dict):
        raise ConfigError(f"{where}: not a .rviz file: no 'Visualization Manager' section")
    options = manager.get("Global Options") or {}
    fixed = options.get("Fixed Frame") if isinstance(options, dict) else None
    fixed = str(fixed).strip() if fixed not in (None, "") else None
    config = Config(fixed, [], view=_view(manager.get("Views")))
    _displays(manager.get("Displays") or [], config, where)
    return config


def _view(views: Any) -> dict[str, Any]:
    """The orbit camera of ``Views: Current:`` (distance, focal point, pitch, yaw), the
    parts that are numbers."""
    current = views.get("Current") if isinstance(views, dict) else None
    if not isinstance(current, dict):
        return {}
    view: dict[str, Any] = {}
    for key, name in (("Distance", "distance"), ("Pitch", "pitch"), ("Yaw", "yaw")):
        if isinstance(current.get(key), (int, float)) and not isinstance(current[key], bool):
            view[name] = float(current[key])
    focal = current.get("Focal Point")
    if isinstance(focal, dict):
        values = [focal.get(axis, 0) for axis in "XYZ"]
        if all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in values):
            view["focal"] = [float(v) for v in values]
    return view


def _displays(items: Any, config: Config, where: str) -> None:
    if not isinstance(items, list):
        raise ConfigError(f"{where}: not a .rviz file: 'Displays' is not a list")
    for item in items:
        if not isinstance(item, dict):
            raise ConfigError(f"{where}: not a .rviz file: a display is not a mapping")
        class_name = str(item.get("Class", ""))
        if class_name.startswith(ROS1_PREFIX):
            rest = class_name[len(ROS1_PREFIX) :]
            class_name = GROUP if rest == "Group" else "rviz_default_plugins/" + rest
        name = str(item.get("Name") or class_name.rpartition("/")[2] or "display")
        enabled = item.get("Enabled", True) is not False
        if class_name == GROUP:
            _displays(item.get("Displays") or [], config, where)
            continue
        if class_name not in KINDS:
            config.lacking.append(
                f"{where}: display {name!r} ({class_name or 'no Class'}) is not drawn by this "
                "3D view; it draws " + ", ".join(kind for kind, _, _ in KINDS.values())
            )
            continue
        if len(config.displays) >= MAX_DISPLAYS:
            config.lacking.append(f"{where}: more than {MAX_DISPLAYS} displays: {name!r} left out")
            continue
        kind, type_name, default_topic = KINDS[class_name]
        topic_field = item.get("Description Topic" if kind == "RobotModel" else "Topic")
        if kind == "RobotModel" and topic_field is None and item.get("Robot Description"):
            topic_field = item["Robot Description"]  # ROS 1: a parameter's name
        topic = topic_field.get("Value") if isinstance(topic_field, dict) else topic_field
        topic = str(topic).strip() if topic else default_topic
        if type_name and topic and not topic.startswith("/"):
            topic = "/" + topic
        settings = {}
        for key in ("Size (m)", "Size (Pixels)", "Alpha", "Color", "Cell Size", "Plane Cell Count"):
            if isinstance(item.get(key), (int, float, str)):
                settings[key] = item[key]
        for key in ("Show Names", "Show Axes", "Show Arrows"):
            if isinstance(item.get(key), bool):
                settings[key] = item[key]
        for key in ("Marker Scale", "Length"):
            if isinstance(item.get(key), (int, float)) and not isinstance(item[key], bool):
                settings[key] = item[key]
        offset = item.get("Offset")
        if isinstance(offset, dict) and all(
            isinstance(offset.get(axis, 0), (int, float)) for axis in "XYZ"
        ):
            settings["Offset"] = {axis: offset.get(axis, 0) for axis in "XYZ"}
        config.displays.append(Display(kind, name, topic, type_name, enabled, settings))
