"""rviz2's 3D view, its pure parts: .rviz files (rviz2/config.py), URDFs (rviz2/robot_model.py)
and messages made small for the page (rviz2/encode.py), on rosidl's real message classes."""

from __future__ import annotations

import math
import struct
from pathlib import Path

import numpy as np
import pytest
from nav_msgs.msg import OccupancyGrid
from sensor_msgs.msg import Image, LaserScan, PointCloud2, PointField
from visualization_msgs.msg import Marker

from ros_tutorials_common import urdf
from rviz2 import encode
from rviz2.config import ConfigError, default_config, load, parse
from rviz2.robot_model import REFUSED, UrdfError
from rviz2.robot_model import parse as parse_urdf

ROOT = Path(__file__).resolve().parent.parent
TURTLE_RVIZ = ROOT / "turtle_tf2_py" / "rviz" / "turtle_rviz.rviz"

GROUPED = """
Visualization Manager:
  Displays:
    - Class: rviz_default_plugins/Grid
      Name: Grid
      Cell Size: 0.5
    - Class: rviz_common/Group
      Name: sensors
      Displays:
        - Class: rviz_default_plugins/LaserScan
          Name: Scan
          Enabled: false
          Topic:
            Value: scan
            Reliability Policy: Best Effort
        - Class: rviz_default_plugins/Camera
          Name: Front camera
    - Class: rviz_default_plugins/RobotModel
      Description Topic:
        Value: /my_robot_description
    - Class: rviz_default_plugins/InteractiveMarkers
      Name: im
  Global Options:
    Fixed Frame: odom
"""


class TestRvizFiles:
    def test_turtle_rviz_is_world_and_tf(self) -> None:
        config = load(TURTLE_RVIZ)
        assert config.fixed_frame == "world"
        assert [(d.kind, d.enabled) for d in config.displays] == [("Grid", True), ("TF", True)]
        assert config.lacking == []
        assert config.view["focal"] == [5.5, 5.5, 0.0]

    def test_groups_topics_and_what_the_view_lacks(self) -> None:
        config = parse(GROUPED, "robot.rviz")
        assert config.fixed_frame == "odom"
        shown = [(d.kind, d.name, d.topic, d.enabled) for d in config.displays]
        assert shown == [
            ("Grid", "Grid", None, True),
            ("LaserScan", "Scan", "/scan", False),
            ("RobotModel", "RobotModel", "/my_robot_description", True),
        ]
        assert config.displays[0].options == {"Cell Size": 0.5}
        assert len(config.lacking) == 2
        assert config.lacking[0].startswith(
            "robot.rviz: display 'Front camera' (rviz_default_plugins/Camera) is not drawn by "
            "this 3D view; it draws Grid, Axes, TF, RobotModel"
        )
        assert "'im' (rviz_default_plugins/InteractiveMarkers)" in config.lacking[1]

    @pytest.mark.parametrize(
        ("text", "line"),
        [
            ("Displays: [", "bad.rviz:1: not a .rviz file: "),
            ("just: text", "bad.rviz: not a .rviz file: no 'Visualization Manager' section"),
            ("Visualization Manager:\n  Displays: 3", "bad.rviz: not a .rviz file: 'Displays'"),
            ("Visualization Manager:\n  Displays: [1]", "bad.rviz: not a .rviz file: a display"),
        ],
    )
    def test_a_malformed_file_is_one_line(self, text: str, line: str) -> None:
        with pytest.raises(ConfigError) as error:
            parse(text, "bad.rviz")
        assert str(error.value).startswith(line)
        assert "\n" not in str(error.value)

    def test_a_missing_file_is_one_line(self, tmp_path: Path) -> None:
        with pytest.raises(ConfigError, match=r"^cannot read .*nothing\.rviz: No such file"):
            load(tmp_path / "nothing.rviz")

    def test_a_ros1_rviz_file(self) -> None:
        """ROS 1's rviz writes rviz/TF, rviz/Group, a plain Topic and the robot description's
        parameter name: read as their ROS 2 namesakes."""
        config = parse(
            "Visualization Manager:\n"
            "  Displays:\n"
            "    - {Class: rviz/Grid, Name: Grid}\n"
            "    - Class: rviz/Group\n"
            "      Displays:\n"
            "        - {Class: rviz/RobotModel, Robot Description: robot_description}\n"
            "        - {Class: rviz/LaserScan, Name: Scan, Topic: /base_scan}\n"
            "    - {Class: rviz/Camera, Name: Cam}\n"
            "  Global Options: {Fixed Frame: odom_combined}\n",
            "seed.rviz",
        )
        assert config.fixed_frame == "odom_combined"
        assert [(d.kind, d.topic) for d in config.displays] == [
            ("Grid", None),
            ("RobotModel", "/robot_description"),
            ("LaserScan", "/base_scan"),
        ]
        assert config.lacking[0].startswith(
            "seed.rviz: display 'Cam' (rviz_default_plugins/Camera) is not drawn"
        )

    def test_no_file_shows_grid_tf_and_robot(self) -> None:
        config = default_config()
        assert [d.kind for d in config.displays] == ["Grid", "TF", "RobotModel"]
        assert config.displays[2].topic == "/robot_description"
        assert config.fixed_frame is None


URDF = """<?xml version="1.0"?>
<robot name="walker">
  <material name="blue"><color rgba="0 0 0.8 1"/></material>
  <link name="base_link">
    <visual>
      <geometry><cylinder length="0.6" radius="0.2"/></geometry>
      <material name="blue"/>
    </visual>
  </link>
  <link name="head">
    <visual>
      <origin xyz="0 0 0.1" rpy="0 1.5708 0"/>
      <geometry><sphere radius="0.2"/></geometry>
      <material name="white"><color rgba="1 1 1 1"/></material>
    </visual>
    <visual><geometry><box size="0.1 0.2 0.3"/></geometry><material name="white"/></visual>
  </link>
  <link name="gripper">
    <visual><geometry><mesh filename="package://rviz_test_pkg/meshes/finger.stl"
      scale="0.1 0.1 0.1"/></geometry></visual>
    <visual><geometry><mesh filename="package://rviz_test_pkg/meshes/gone.stl"/></geometry>
    </visual>
  </link>
  <link name="empty"/>
  <joint name="neck" type="continuous"><parent link="base_link"/><child link="head"/></joint>
  <joint name="hand" type="fixed"><parent link="base_link"/><child link="gripper"/></joint>
  <joint name="tail" type="fixed"><parent link="base_link"/><child link="empty"/></joint>
</robot>
"""
# What robot_state_publisher refuses, rviz2's RobotModel refuses with the same reason.
CRAFTED = {
    "an entity that expands": '<?xml version="1.0"?><!DOCTYPE r [<!ENTITY a "aaaaaaaaaa">'
    '<!ENTITY b "&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;">]><robot name="&b;"><link name="l"/></robot>',
    "too many elements": "<robot name='r'><link name='l'>"
    + "<visual><geometry><box size='1 1 1'/></geometry></visual>" * 70_000
    + "</link></robot>",
    "too large": "<robot name='r'><link name='l'/>" + " " * (9 << 20) + "</robot>",
    "two roots": "<robot name='r'><link name='a'/><link name='b'/></robot>",
    "a visual without geometry": "<robot name='r'><link name='a'><visual/></link></robot>",
}


class TestUrdf:
    def share(self, tmp_path: Path):
        (tmp_path / "meshes").mkdir()
        (tmp_path / "meshes" / "finger.stl").write_bytes(b"solid finger\nendsolid finger\n")

        def package_share(name: str) -> Path:
            if name != "rviz_test_pkg":
                raise LookupError(name)
            return tmp_path

        return package_share

    def test_links_visuals_colours_and_meshes(self, tmp_path: Path) -> None:
        model = parse_urdf(URDF, self.share(tmp_path))
        assert model.name == "walker"
        links = {link["name"]: link["visuals"] for link in model.links}
        assert list(links) == ["base_link", "head", "gripper", "empty"]
        base = links["base_link"][0]
        assert (base["type"], base["radius"], base["length"]) == ("cylinder", 0.2, 0.6)
        assert base["color"] == [0, 0, 0.8, 1]
        head, box = links["head"]
        assert (head["type"], head["xyz"], head["rpy"]) == ("sphere", [0, 0, 0.1], [0, 1.5708, 0])
        assert head["color"] == [1, 1, 1, 1]
        # a material coloured in one visual is known by its name to the visuals after it
        assert (box["type"], box["size"], box["color"]) == ("box", [0.1, 0.2, 0.3], [1, 1, 1, 1])
        (finger,) = links["gripper"]
        assert (finger["format"], finger["scale"]) == ("stl", [0.1] * 3)
        assert finger["mesh"] == "0/finger.stl"
        assert model.meshes == [(tmp_path / "meshes" / "finger.stl").resolve()]
        assert model.problems == [
            "link 'gripper': mesh 'package://rviz_test_pkg/meshes/gone.stl': no such file "
            f"{tmp_path / 'meshes' / 'gone.stl'}"
        ]

    @pytest.mark.parametrize(
        ("text", "line"),
        [
            ("<robot name='r'><link name='a'>", "not valid XML: "),
            ("<sdf/>", "Could not find the 'robot' element in the xml file"),
            ("<robot name='r'/>", "No link elements found in urdf file"),
            (
                "<robot name='r'><link name='a'><visual><origin xyz='1 2'/><geometry><box "
                "size='1 1 1'/></geometry></visual></link></robot>",
                "link [a]: visual: origin xyz must be 3 numbers, not '1 2'",
            ),
            (
                "<robot name='r'><link name='a'><visual><geometry><cone/></geometry></visual>"
                "</link></robot>",
                "link [a]: visual: unknown geometry type 'cone'",
            ),
            (
                "<robot name='r'><link name='a'><visual><geometry><box/></geometry></visual>"
                "</link></robot>",
                "link [a]: visual: box has no size attribute",
            ),
            (
                "<robot name='r'><link name='a'><visual><geometry><sphere radius='1'/>"
                "</geometry><material name='red'/></visual></link></robot>",
                "link 'a' material 'red' undefined.",
            ),
            (
                "<robot name='r'><material name='m'><color rgba='2 0 0 1'/></material>"
                "<link name='a'/></robot>",
                "material [m]: color rgba must be 4 numbers from 0 to 1, not (2.0, 0.0, 0.0, 1.0)",
            ),
        ],
    )
    def test_a_malformed_urdf_is_one_line(self, text: str, line: str) -> None:
        with pytest.raises(UrdfError) as error:
            parse_urdf(text, lambda name: Path("/"))
        assert str(error.value).startswith(REFUSED + line)
        assert "\n" not in str(error.value)

    @pytest.mark.parametrize("what", sorted(CRAFTED))
    def test_a_crafted_urdf_is_refused_as_robot_state_publisher_refuses_it(self, what: str) -> None:
        """The one reader decides for both: rviz2 gives robot_state_publisher's reason."""
        text = CRAFTED[what]
        with pytest.raises(urdf.UrdfError) as reader:
            urdf.parse(text)  # robot_state_publisher: "Unable to initialize ...: " + this
        with pytest.raises(UrdfError) as error:
            parse_urdf(text, lambda name: Path("/"))
        assert str(error.value) == REFUSED + str(reader.value)
        assert "\n" not in str(error.value) and len(str(error.value)) < 300

    def test_a_mesh_outside_its_package_is_refused(self, tmp_path: Path) -> None:
        package = tmp_path / "share" / "rviz_test_pkg"
        (package / "meshes").mkdir(parents=True)
        (tmp_path / "secret.stl").write_bytes(b"solid secret\nendsolid secret\n")
        text = (
            "<robot name='r'><link name='a'><visual><geometry>"
            "<mesh filename='package://rviz_test_pkg/meshes/../../../secret.stl'/>"
            "</geometry></visual></link></robot>"
        )
        model = parse_urdf(text, lambda name: package)
        assert model.meshes == []  # never served
        assert model.problems == [
            "link 'a': mesh 'package://rviz_test_pkg/meshes/../../../secret.stl': the path "
            "leaves package 'rviz_test_pkg'"
        ]


def cloud(count: int, rgb: bool = False) -> PointCloud2:
    fields = [PointField(name=n, offset=4 * i, datatype=7, count=1) for i, n in enumerate("xyz")]
    step = 16 if rgb else 12
    if rgb:
        fields.append(PointField(name="rgb", offset=12, datatype=7, count=1))
    msg = PointCloud2(height=1, width=count, fields=fields, point_step=step, row_step=step * count)
    data = bytearray()
    for i in range(count):
        data += struct.pack("<fff", i * 0.01, -i * 0.01, 1.0 if i % 2 else math.nan)
        if rgb:
            data += struct.pack("<I", 0x00FF8000)
    msg.data = bytes(data)
    msg.header.frame_id = "sensor"
    return msg


class TestEncode:
    def test_point_cloud_drops_nan_and_keeps_colours(self) -> None:
        header, blob = encode.point_cloud2(cloud(10, rgb=True))
        assert (header["frame"], header["count"], header["total"], header["colors"]) == (
            "sensor",
            5,
            10,
            True,
        )
        xyz = np.frombuffer(blob[: 5 * 12], dtype=np.float32).reshape(5, 3)
        assert xyz[0].tolist() == pytest.approx([0.01, -0.01, 1.0])
        assert list(blob[5 * 12 : 5 * 12 + 3]) == [255, 128, 0]

    def test_a_huge_cloud_is_decimated(self) -> None:
        header, blob = encode.point_cloud2(cloud(2 * encode.MAX_POINTS + 2))
        assert header["total"] == 2 * encode.MAX_POINTS + 2
        assert header["count"] <= encode.MAX_POINTS
        assert len(blob) == header["count"] * 12

    def test_a_short_cloud_is_one_line(self) -> None:
        msg = cloud(10)
        msg.data = msg.data[:50]
        with pytest.raises(ValueError, match="shorter than its width"):
            encode.point_cloud2(msg)

    def test_laser_scan_points(self) -> None:
        scan = LaserScan(angle_min=0.0, angle_increment=math.pi / 2, range_min=0.1, range_max=10.0)
        scan.ranges = [1.0, 2.0, math.inf, 0.05]
        header, blob = encode.laser_scan(scan)
        assert header["count"] == 2
        points = np.frombuffer(blob, dtype=np.float32).reshape(2, 3)
        assert np.allclose(points, [[1, 0, 0], [0, 2, 0]], atol=1e-6)

    def test_a_large_map_is_decimated(self) -> None:
        grid = OccupancyGrid()
        grid.info.width, grid.info.height, grid.info.resolution = 4000, 10, 0.05
        grid.data = [100, -1] * 20000
        header, blob = encode.occupancy_grid(grid)
        assert header["width"] <= encode.MAX_MAP and header["total"] == [4000, 10]
        assert header["resolution"] == pytest.approx(0.05 * 4)
        assert set(blob) == {100}  # every 4th cell: the even ones

    def test_image_rgb_and_bgr(self) -> None:
        img = Image(width=2, height=1, encoding="bgr8", step=6, data=bytes([1, 2, 3, 4, 5, 6]))
        header, blob = encode.image(img)
        assert (header["width"], header["height"]) == (2, 1)
        assert list(blob) == [3, 2, 1, 255, 6, 5, 4, 255]
        img.encoding = "yuv422"
        with pytest.raises(ValueError, match="encoding 'yuv422'"):
            encode.image(img)

    def test_marker(self) -> None:
        m = Marker(ns="shapes", id=3, type=Marker.CUBE)
        m.header.frame_id = "base_link"
        m.scale.x = m.scale.y = m.scale.z = 0.5
        m.color.r, m.color.a = 1.0, 1.0
        m.pose.orientation.w = 2.0  # not normalised: the view normalises it
        entry = encode.marker(m)
        assert (entry["ns"], entry["id"], entry["type"], entry["frame"]) == (
            "shapes",
            3,
            1,
            "base_link",
        )
        assert entry["pose"]["q"] == [0.0, 0.0, 0.0, 1.0]
        assert entry["color"] == [1.0, 0.0, 0.0, 1.0]
