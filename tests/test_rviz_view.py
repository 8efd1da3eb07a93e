"""rviz2's 3D view (`rviz2`, `ros2 run rviz2 rviz2 -d FILE.rviz`, `rviz`): the real command
against real nodes (tf broadcasters, a marker publisher, a URDF on /robot_description, a point
cloud) in this test's process, read through the view's own WebSocket as its page reads it, and
the page itself in headless Chromium (TestInBrowser, below); the guard (token, Host,
Origin) on every page, socket and mesh file; bad input in one line.
"""

from __future__ import annotations

import asyncio
import json
import math
import re
import signal
import struct
import threading
import time
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import aiohttp
import pytest
import rclpy
from geometry_msgs.msg import TransformStamped
from helpers import BIN, TIMEOUT, run
from rclpy.context import Context
from rclpy.executors import SingleThreadedExecutor
from rclpy.qos import DurabilityPolicy, QoSProfile
from sensor_msgs.msg import PointCloud2, PointField
from std_msgs.msg import String
from visualization_msgs.msg import Marker, MarkerArray

HEADLESS = {"DISPLAY": "", "WAYLAND_DISPLAY": ""}  # no window: the link only
LINK = r"Open (http://127\.0\.0\.1:\d+/\?token=[\w-]{32}) in a browser"
ROOT = Path(__file__).resolve().parent.parent
# An STL triangle (ASCII): the robot's mesh.
STL = """solid finger
facet normal 0 0 1
outer loop
vertex 0 0 0
vertex 1 0 0
vertex 0 1 0
endloop
endfacet
endsolid finger
"""
# A COLLADA tetrahedron (z up, metres): the robot's other mesh.
DAE = """<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="meter" meter="1"/><up_axis>Z_UP</up_axis></asset>
  <library_geometries>
    <geometry id="tip" name="tip"><mesh>
      <source id="tip-xyz">
        <float_array id="tip-xyz-array" count="12">0 0 0 0.2 0 0 0 0.2 0 0 0 0.2</float_array>
        <technique_common><accessor source="#tip-xyz-array" count="4" stride="3">
          <param name="X" type="float"/><param name="Y" type="float"/>
          <param name="Z" type="float"/></accessor></technique_common>
      </source>
      <vertices id="tip-vertices"><input semantic="POSITION" source="#tip-xyz"/></vertices>
      <triangles count="4"><input semantic="VERTEX" source="#tip-vertices" offset="0"/>
        <p>0 2 1 0 1 3 0 3 2 1 2 3</p></triangles>
    </mesh></geometry>
  </library_geometries>
  <library_visual_scenes><visual_scene id="scene">
    <node id="tip-node"><instance_geometry url="#tip"/></node>
  </visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#scene"/></scene>
</COLLADA>
"""
URDF = """<?xml version="1.0"?>
<robot name="test_bot">
  <material name="blue"><color rgba="0 0 0.8 1"/></material>
  <link name="base_link">
    <visual><geometry><cylinder length="0.6" radius="0.2"/></geometry>
      <material name="blue"/></visual>
  </link>
  <link name="head">
    <visual><geometry><sphere radius="0.2"/></geometry></visual>
  </link>
  <link name="gripper">
    <visual><geometry><mesh filename="file://{mesh}"/></geometry></visual>
    <visual><origin xyz="0.1 0 0"/><geometry><mesh filename="file://{dae}"/></geometry>
    </visual>
  </link>
  <joint name="neck" type="fixed"><parent link="base_link"/><child link="head"/>
    <origin xyz="0 0 0.5"/></joint>
  <joint name="hand" type="fixed"><parent link="base_link"/><child link="gripper"/>
    <origin xyz="0.3 0 0"/></joint>
</robot>
"""
CONFIG = """Visualization Manager:
  Displays:
    - Class: rviz_default_plugins/Grid
      Name: Grid
    - Class: rviz_default_plugins/TF
      Name: TF
    - Class: rviz_default_plugins/RobotModel
      Name: RobotModel
      Description Topic:
        Value: /robot_description
    - Class: rviz_default_plugins/Marker
      Name: Marker
      Topic:
        Value: /visualization_marker
    - Class: rviz_default_plugins/MarkerArray
      Name: MarkerArray
      Topic:
        Value: /visualization_marker_array
    - Class: rviz_default_plugins/PointCloud2
      Name: Cloud
      Topic:
        Value: /cloud
    - Class: rviz_default_plugins/Camera
      Name: Front camera
  Global Options:
    Fixed Frame: world
"""


def transform(parent: str, child: str, xyz: tuple, yaw: float = 0.0) -> TransformStamped:
    t = TransformStamped()
    t.header.frame_id, t.child_frame_id = parent, child
    t.transform.translation.x, t.transform.translation.y, t.transform.translation.z = xyz
    t.transform.rotation.z, t.transform.rotation.w = math.sin(yaw / 2), math.cos(yaw / 2)
    return t


def cube(ns: str, number: int, frame: str, x: float) -> Marker:
    m = Marker(ns=ns, id=number, type=Marker.CUBE, action=Marker.ADD)
    m.header.frame_id = frame
    m.pose.position.x, m.pose.orientation.w = x, 1.0
    m.scale.x = m.scale.y = m.scale.z = 0.4
    m.color.g, m.color.a = 1.0, 1.0
    return m


def cloud(count: int, frame: str) -> PointCloud2:
    fields = [PointField(name=n, offset=4 * i, datatype=7, count=1) for i, n in enumerate("xyz")]
    msg = PointCloud2(height=1, width=count, fields=fields, point_step=12, row_step=12 * count)
    msg.header.frame_id = frame
    msg.data = b"".join(
        struct.pack("<fff", math.cos(i / 50), math.sin(i / 50), i / count) for i in range(count)
    )
    return msg


class Publishers:
    """The nodes a learner's robot would run: tf (world -> base_link 2 m along x, turned 90
    degrees; base_link -> head and gripper, as robot_state_publisher sends them), the URDF on
    /robot_description (transient local), markers and a cloud, in this test's process."""

    def __init__(self, context: Context, mesh: Path) -> None:
        from tf2_ros import StaticTransformBroadcaster, TransformBroadcaster

        self.executor = SingleThreadedExecutor(context=context)
        self.node = rclpy.create_node("rviz_test_robot", context=context)
        self.executor.add_node(self.node)
        self.static = StaticTransformBroadcaster(self.node)
        self.static.sendTransform(
            [
                transform("world", "base_link", (2.0, 0.0, 0.0), math.pi / 2),
                transform("base_link", "head", (0.0, 0.0, 0.5)),
                transform("base_link", "gripper", (0.3, 0.0, 0.0)),
            ]
        )
        self.dynamic = TransformBroadcaster(self.node)
        latched = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)
        self.description = self.node.create_publisher(String, "/robot_description", latched)
        dae = mesh.with_name("tip.dae")
        self.description.publish(String(data=URDF.format(mesh=mesh, dae=dae)))
        self.marker = self.node.create_publisher(Marker, "/visualization_marker", 10)
        self.markers = self.node.create_publisher(MarkerArray, "/visualization_marker_array", 10)
        self.cloud = self.node.create_publisher(PointCloud2, "/cloud", 10)
        self.node.create_timer(0.1, self.tick)
        self.stop = threading.Event()
        self.thread = threading.Thread(target=self.spin, daemon=True)
        self.thread.start()

    def tick(self) -> None:
        stamp = self.node.get_clock().now().to_msg()
        t = transform("world", "turtle1", (5.0, 5.0, 0.0))
        t.header.stamp = stamp
        self.dynamic.sendTransform(t)
        self.marker.publish(cube("box", 1, "base_link", 1.0))
        self.markers.publish(
            MarkerArray(markers=[cube("row", i, "world", float(i)) for i in range(3)])
        )
        msg = cloud(1000, "head")
        msg.header.stamp = stamp
        self.cloud.publish(msg)

    def spin(self) -> None:
        while not self.stop.is_set():
            self.executor.spin_once(timeout_sec=0.05)

    def close(self) -> None:
        self.stop.set()
        self.thread.join()
        self.executor.remove_node(self.node)
        self.node.destroy_node()
        self.executor.shutdown()


class Tab:
    """A WebSocket to the view, as the page holds one: JSON text, or (header, data) frames."""

    def __init__(self, ws: aiohttp.ClientWebSocketResponse) -> None:
        self.ws = ws

    async def until(self, found: Callable[[Any], Any], what: str, timeout: float = TIMEOUT):
        deadline = time.monotonic() + timeout
        while True:
            remaining = deadline - time.monotonic()
            if remaining <= 0:
                pytest.fail(f"{what}: not seen from the 3D view within {timeout:.0f} s")
            try:
                message = await self.ws.receive(timeout=remaining)
            except asyncio.TimeoutError:
                continue
            if message.type == aiohttp.WSMsgType.BINARY:
                (length,) = struct.unpack("!I", message.data[:4])
                item: Any = (json.loads(message.data[4 : 4 + length]), message.data[4 + length :])
            elif message.type == aiohttp.WSMsgType.TEXT:
                item = json.loads(message.data)
            else:
                pytest.fail(f"{what}: the view closed the WebSocket ({message.type})")
            result = found(item)
            if result:
                return result


def at(link: str, path: str = "") -> str:
    page, _, query = link.partition("?")
    return f"{page}{path}?{query}"


def with_tab(link: str, test: Callable[[Tab], Any]) -> Any:
    async def session() -> Any:
        async with aiohttp.ClientSession() as client, client.ws_connect(at(link, "ws")) as ws:
            return await test(Tab(ws))

    return asyncio.run(session())


def started(process: Any) -> str:
    """The link the view printed."""
    line = process.wait_for_text("in a browser")[-1]
    found = re.search(LINK, line)
    assert found, line
    return found.group(1)


def display_named(name: str, config: dict) -> dict:
    return next(d for d in config["displays"] if d["name"] == name)


def kind_of(item: Any) -> dict | None:
    return item[0] if isinstance(item, tuple) else item if isinstance(item, dict) else None


@pytest.fixture(scope="class")
def robot(tmp_path_factory: pytest.TempPathFactory, ros_domain: int) -> Iterator[Path]:
    """The publishers, and the folder holding the test's .rviz file and mesh."""
    folder = tmp_path_factory.mktemp("robot")
    (folder / "finger.stl").write_text(STL)
    (folder / "tip.dae").write_text(DAE)
    (folder / "robot.rviz").write_text(CONFIG)
    context = Context()
    rclpy.init(context=context)
    publishers = Publishers(context, folder / "finger.stl")
    yield folder
    publishers.close()
    context.try_shutdown()


@pytest.fixture(scope="class")
def view(robot: Path, class_node_process) -> tuple[str, Any]:
    """`ros2 run rviz2 rviz2 -d robot.rviz`, its link and its process."""
    process = class_node_process(
        str(BIN / "ros2"), "run", "rviz2", "rviz2", "-d", str(robot / "robot.rviz"),
        "--port", "0", env=HEADLESS,
    )  # fmt: skip
    return started(process), process


class TestView:
    def test_the_file_lacks_one_display_said_in_one_line(self, view) -> None:
        _, process = view
        process.wait_for_text(
            "display 'Front camera' (rviz_default_plugins/Camera) is not drawn by this 3D view"
        )

    def test_frames_are_placed_in_the_fixed_frame(self, view) -> None:
        link, _ = view

        def placed(item: Any) -> Any:
            if not isinstance(item, dict) or item.get("type") != "tf":
                return None
            frames = {f["name"]: f for f in item["frames"] if "p" in f}
            return frames if {"base_link", "head", "gripper", "turtle1"} <= set(frames) else None

        async def check(tab: Tab) -> dict:
            return await tab.until(placed, "tf frames world, base_link, head, gripper, turtle1")

        frames = with_tab(link, check)
        assert frames["base_link"]["p"] == pytest.approx([2.0, 0.0, 0.0])
        # The gripper is 0.3 m along base_link's x, which points along world's y.
        assert frames["gripper"]["p"] == pytest.approx([2.0, 0.3, 0.0], abs=1e-6)
        assert frames["head"]["p"] == pytest.approx([2.0, 0.0, 0.5])
        assert frames["turtle1"]["parent"] == "world"

    def test_robot_model_markers_and_cloud_arrive(self, view, robot: Path) -> None:
        link, _ = view
        seen: dict[str, Any] = {}
        wanted = {"RobotModel", "Marker", "MarkerArray", "PointCloud2"}

        def everything(item: Any) -> Any:
            head = kind_of(item)
            if head and head.get("type") == "config":
                seen["config"] = head
            elif head and head.get("type") == "display" and head.get("kind") in wanted:
                seen[head["kind"]] = item
            return wanted <= set(seen) and "config" in seen

        async def check(tab: Tab) -> None:
            await tab.until(everything, "the robot, the markers and the cloud")

        with_tab(link, check)
        model = seen["RobotModel"]
        links = {entry["name"]: entry["visuals"] for entry in model["links"]}
        assert links["base_link"][0]["type"] == "cylinder"
        assert links["base_link"][0]["color"] == [0, 0, 0.8, 1]
        assert links["gripper"][0]["type"] == "mesh"
        assert [m["ns"] for m in seen["Marker"]["markers"]] == ["box"]
        assert sorted(m["id"] for m in seen["MarkerArray"]["markers"]) == [0, 1, 2]
        header, blob = seen["PointCloud2"]
        assert (header["frame"], header["count"]) == ("head", 1000)
        assert len(blob) == 1000 * 12
        assert display_named("TF", seen["config"])["status"] == "ok"
        # The mesh the model names is served, with the token; nothing else is.
        mesh = links["gripper"][0]["mesh"]
        number = display_named("RobotModel", seen["config"])["id"]

        async def fetch() -> None:
            async with aiohttp.ClientSession() as client:
                async with client.get(at(link, f"mesh/{number}/{mesh}")) as got:
                    assert got.status == 200
                    assert await got.text() == STL
                async with client.get(at(link, f"mesh/{number}/0/robot.rviz")) as got:
                    assert got.status == 404
                async with client.get(at(link, f"mesh/{number}/1/finger.stl")) as got:
                    assert got.status == 404
                plain = link.partition("?")[0]
                async with client.get(f"{plain}mesh/{number}/{mesh}") as got:
                    assert got.status == 403

        asyncio.run(fetch())

    def test_page_and_three_js_are_served(self, view) -> None:
        link, _ = view

        async def check() -> None:
            async with aiohttp.ClientSession() as client:
                async with client.get(link) as got:
                    assert got.status == 200
                    assert "three/addons/" in await got.text()
                async with client.get(at(link, "static/three/three.module.min.js")) as got:
                    assert got.status == 200
                    assert "REVISION" in await got.text()

        asyncio.run(check())

    def test_the_guard_refuses_what_is_not_its_page(self, view) -> None:
        link, process = view
        plain = link.partition("?")[0]

        async def check() -> None:
            async with aiohttp.ClientSession() as client:
                async with client.get(plain) as got:  # no token
                    assert got.status == 403
                    assert "no valid token" in await got.text()
                with pytest.raises(aiohttp.WSServerHandshakeError) as refused:
                    await client.ws_connect(plain + "ws")
                assert refused.value.status == 403
                with pytest.raises(aiohttp.WSServerHandshakeError) as refused:
                    await client.ws_connect(at(link, "ws"), origin="https://evil.example")
                assert refused.value.status == 403
                elsewhere = {"Host": "rebound.example:80"}
                async with client.get(link, headers=elsewhere) as got:
                    assert got.status == 403

        asyncio.run(check())
        process.wait_for_text("Refused GET /ws: Origin 'https://evil.example'")

    def test_a_slow_page_gets_no_backlog_of_clouds(self, view) -> None:
        """A page that asked for flow control is sent at most IN_FLIGHT clouds it has not
        drawn (acknowledged); the markers' text keeps coming; an ack lets the next through."""
        from rviz2.server import IN_FLIGHT

        link, _ = view
        counts = {"binary": 0, "text": 0}

        def count(until: Callable[[dict], bool]) -> Callable[[Any], bool]:
            def found(item: Any) -> bool:
                counts["binary" if isinstance(item, tuple) else "text"] += 1
                return until(counts)

            return found

        async def check(tab: Tab) -> None:
            await tab.ws.send_str(json.dumps({"flow": True}))
            # The markers are sent ten times a second: 40 of them take about two seconds,
            # in which twenty clouds are published.
            await tab.until(count(lambda c: c["text"] >= 40), "40 text payloads")
            held = counts["binary"]
            assert held <= IN_FLIGHT + 1  # +1: a cloud may go before the page's "flow"
            await tab.ws.send_str(json.dumps({"ack": held}))
            await tab.until(count(lambda c: c["binary"] > held), "a cloud after the ack")

        with_tab(link, check)

    def test_a_page_adds_a_display_by_topic(self, view) -> None:
        link, _ = view

        async def check(tab: Tab) -> None:
            def config(item: Any) -> Any:
                return item if isinstance(item, dict) and item.get("type") == "config" else None

            first = await tab.until(config, "the view's displays")
            assert "/cloud" in [d["topic"] for d in first["displays"]]
            await tab.ws.send_str(json.dumps({"add": "/cloud"}))  # shown already: nothing new
            await tab.ws.send_str(json.dumps({"enable": [first["displays"][-1]["id"], False]}))
            await tab.ws.send_str("not json at all")
            await tab.ws.send_str(json.dumps({"fixed": 7, "enable": "yes"}))

            def disabled(item: Any) -> Any:
                got = config(item)
                return got and not got["displays"][-1]["enabled"] and got

            after = await tab.until(disabled, "the last display disabled")
            assert len(after["displays"]) == len(first["displays"])
            assert after["displays"][-1]["status"] == "disabled"
            await tab.ws.send_str(json.dumps({"enable": [first["displays"][-1]["id"], True]}))

        with_tab(link, check)


class TestBadInput:
    def test_a_malformed_rviz_file_is_one_line(self, tmp_path: Path) -> None:
        bad = tmp_path / "bad.rviz"
        bad.write_text("Visualization Manager: [\n")
        result = run("rviz2", "-d", str(bad), "--port", "0")
        assert result.returncode == 1
        assert result.stderr.startswith(f"error: {bad}:")
        assert len(result.stderr.strip().splitlines()) == 1

    def test_a_missing_rviz_file_is_one_line(self, tmp_path: Path) -> None:
        result = run("rviz", "-d", str(tmp_path / "none.rviz"), "--port", "0")
        assert result.returncode == 1
        missing = tmp_path / "none.rviz"
        assert result.stderr == f"error: cannot read {missing}: No such file or directory\n"

    def test_a_malformed_robot_description_is_one_line(self, node_process, context) -> None:
        node = rclpy.create_node("bad_description", context=context)
        latched = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)
        node.create_publisher(String, "/robot_description", latched).publish(
            String(data="<robot name='r'><link name='a'>")
        )
        try:
            process = node_process(
                str(BIN / "rviz2"), "--port", "0", "-f", "base_link", env=HEADLESS
            )
            lines = process.wait_for_text(
                "RobotModel: error: the robot description is not a valid URDF: not valid XML"
            )
            assert "Traceback" not in "\n".join(process.lines)
            assert len([line for line in lines if "not valid XML" in line]) == 1
        finally:
            node.destroy_node()


def browser_for(tmp_path: Path) -> Any:
    """Headless Chromium (tests/browser.py's, skipped with its reason where there is none)
    with WebGL drawn in software: there is no GPU here."""
    from browser import open_chromium

    return open_chromium(
        1400,
        900,
        "--use-angle=swiftshader",
        "--enable-unsafe-swiftshader",
        f"--user-data-dir={tmp_path / 'chromium'}",
    )


def page_until(browser: Any, script: str, what: str, timeout: float = TIMEOUT) -> Any:
    """Run SCRIPT in the page until it returns something truthy; return that."""
    from browser import until

    return until(lambda: browser.execute_script(script), what, timeout)


class TestInBrowser:
    """The page in headless Chromium, read as a person reads it: the objects the view draws
    and where, the frame names written beside the axes, the displays' status lines."""

    def test_robot_markers_cloud_and_frames(self, view, tmp_path: Path) -> None:
        link, _ = view
        browser = browser_for(tmp_path)
        try:
            browser.get(link)
            objects = page_until(
                browser,
                """const seen = window.rvizState ? window.rvizState.objects() : [];
                   const want = ["link base_link", "link gripper", "marker box/1 CUBE",
                                 "marker row/2 CUBE", "1000 points", "frame turtle1"];
                   const have = seen.filter((o) => o.visible).map((o) => o.what);
                   return want.every((w) => have.includes(w)) ? seen : null;""",
                "the robot, markers, cloud and frames",
            )
            where = {o["what"]: o["position"] for o in objects if o["visible"]}
            assert where["link base_link"] == pytest.approx([2, 0, 0], abs=1e-4)
            assert where["link head"] == pytest.approx([2, 0, 0.5], abs=1e-4)
            # The marker 1 m along base_link's x: world's y, as tf says.
            assert where["marker box/1 CUBE"] == pytest.approx([2, 1, 0], abs=1e-4)
            assert where["marker row/2 CUBE"] == pytest.approx([2, 0, 0], abs=1e-4)
            names = browser.execute_script(
                """return [...document.querySelectorAll('.label')]
                     .filter((e) => e.style.display !== 'none').map((e) => e.textContent)"""
            )
            assert {"world", "base_link", "head", "gripper", "turtle1"} <= set(names)
            statuses = page_until(
                browser,
                """const ds = window.rvizState.displays();
                   return ds.every((d) => d.status.startsWith("ok")) ? ds : null;""",
                "every display ok",
            )
            assert [d["kind"] for d in statuses] == [
                "Grid", "TF", "RobotModel", "Marker", "MarkerArray", "PointCloud2"
            ]  # fmt: skip
            meshes = page_until(
                browser,
                """const m = window.rvizState.meshes();
                   return Object.keys(m).length === 2
                     && Object.values(m).every((s) => s !== "loading") ? m : null;""",
                "the robot's STL and COLLADA meshes loaded",
            )
            assert set(meshes.values()) == {"loaded"}, meshes
            lacking = browser.find_element("id", "lacking").text
            assert "'Front camera' (rviz_default_plugins/Camera) is not drawn" in lacking
            assert browser.execute_script("return window.rvizState.renders") > 0
            browser.save_screenshot(str(tmp_path / "rviz_robot.png"))
        finally:
            browser.quit()


class TestTurtleRviz:
    """The tf2 pages' step: `ros2 run rviz2 rviz2 -d $(ros2 pkg prefix --share
    turtle_tf2_py)/rviz/turtle_rviz.rviz` beside the turtle_tf2 demo shows the turtles'
    frames in the fixed frame world."""

    def test_the_turtles_frames_in_the_page(self, node_process, tmp_path: Path) -> None:
        share = run("ros2", "pkg", "prefix", "--share", "turtle_tf2_py").stdout.strip()
        node_process(
            str(BIN / "ros2"), "launch", "turtle_tf2_py", "turtle_tf2_demo.launch.py", env=HEADLESS
        )
        rviz = node_process(
            str(BIN / "ros2"), "run", "rviz2", "rviz2", "-d", f"{share}/rviz/turtle_rviz.rviz",
            "--port", "0", env=HEADLESS,
        )  # fmt: skip
        link = started(rviz)
        browser = browser_for(tmp_path)
        try:
            browser.get(link)
            frames = page_until(
                browser,
                """const s = window.rvizState;
                   const at = s ? s.objects().filter((o) => o.visible && o.kind === "TF") : [];
                   const names = at.map((o) => o.what);
                   return names.includes("frame turtle1") && names.includes("frame turtle2")
                     ? at : null;""",
                "turtle1 and turtle2's frames",
                timeout=90,
            )
            assert browser.execute_script("return window.rvizState.fixed") == "world"
            where = {o["what"]: o["position"] for o in frames}
            # turtlesim puts turtle1 in the middle of its 11 m square.
            assert where["frame turtle1"][:2] == pytest.approx([5.544445, 5.544445], abs=0.01)
            kinds = browser.execute_script("return window.rvizState.displays().map((d) => d.kind)")
            assert kinds == ["Grid", "TF"]
            # The learner drives turtle1: its frame moves in the view.
            run(
                "ros2", "topic", "pub", "--once", "/turtle1/cmd_vel", "geometry_msgs/msg/Twist",
                "{linear: {x: 2.5}, angular: {z: 1.2}}",
            )  # fmt: skip
            page_until(
                browser,
                """const at = Object.fromEntries(window.rvizState.objects()
                     .filter((o) => o.kind === "TF").map((o) => [o.what, o.position]));
                   const t1 = at["frame turtle1"];
                   return Math.hypot(t1[0] - 5.544445, t1[1] - 5.544445) > 1;""",
                "turtle1's frame moved in the view",
            )
            browser.save_screenshot(str(tmp_path / "rviz_turtles.png"))
        finally:
            browser.quit()


SEED_LAUNCH = """<launch>
  <arg name="show_rviz" default="true" />
  <node name="rviz" pkg="rviz" type="rviz" if="$(arg show_rviz)" />
</launch>
"""


def test_seed_launch_file_with_show_rviz_opens_the_view(node_process, tmp_path: Path) -> None:
    """Seed 002's launch file: ROS 1's rviz node (pkg rviz, type rviz) runs the 3D view."""
    launch_file = tmp_path / "lesson.launch"
    launch_file.write_text(SEED_LAUNCH)
    launch = node_process(str(BIN / "roslaunch"), str(launch_file), env=HEADLESS)
    line = launch.wait_for_text("in a browser")[-1]
    assert re.search(LINK, line), line


def test_a_window_opens_where_there_is_a_display(node_process, tmp_path: Path) -> None:
    """With a display, rviz2 opens its link in the learner's browser ($BROWSER here: a script
    that notes what it was asked to open); without one it only prints the link."""
    opened = tmp_path / "opened"
    browser = tmp_path / "browser"
    browser.write_text(f'#!/bin/sh\necho "$1" >> {opened}\n')
    browser.chmod(0o755)
    process = node_process(
        str(BIN / "rviz2"), "--port", "0", env={"DISPLAY": ":99", "BROWSER": str(browser)}
    )
    link = started(process)
    deadline = time.monotonic() + TIMEOUT
    while not (opened.exists() and opened.read_text()):
        assert time.monotonic() < deadline, "no browser was asked to open the view"
        time.sleep(0.1)
    assert opened.read_text() == f"{link}\n"


ROOM = 10.0  # m: the map's square room, walls all round, a pillar in the middle
ROVER = """<robot name="rover">
  <link name="base_link"><visual><origin xyz="0 0 0.15"/><geometry><box size="0.6 0.4 0.2"/>
    </geometry><material name="orange"><color rgba="1 0.5 0.1 1"/></material></visual></link>
  <link name="left_wheel"><visual><origin rpy="1.5708 0 0"/><geometry>
    <cylinder radius="0.1" length="0.06"/></geometry><material name="black">
    <color rgba="0.1 0.1 0.1 1"/></material></visual></link>
  <link name="right_wheel"><visual><origin rpy="1.5708 0 0"/><geometry>
    <cylinder radius="0.1" length="0.06"/></geometry><material name="black"/></visual></link>
  <link name="laser"><visual><geometry><cylinder radius="0.06" length="0.08"/></geometry>
    <material name="black"/></visual></link>
  <joint name="left" type="continuous"><parent link="base_link"/><child link="left_wheel"/>
  </joint>
  <joint name="right" type="continuous"><parent link="base_link"/><child link="right_wheel"/>
  </joint>
  <joint name="laser" type="fixed"><parent link="base_link"/><child link="laser"/></joint>
</robot>
"""


class Sensors:
    """A robot in a room, as a navigation stack shows it: the map (transient local, 200 x 200
    cells of 5 cm, and a 2100 x 60 strip that must be thinned), a laser scan of the walls, a
    point cloud of 250,000 points (thinned too), the planned path, a goal pose, a pose array,
    odometry, and a camera image of 800 x 600 (thinned); tf map -> odom -> base_link ->
    laser."""

    def __init__(self, context: Context) -> None:
        import numpy as np
        from geometry_msgs.msg import Pose, PoseArray, PoseStamped
        from nav_msgs.msg import OccupancyGrid, Odometry, Path
        from sensor_msgs.msg import Image, LaserScan

        from tf2_ros import StaticTransformBroadcaster

        self.executor = SingleThreadedExecutor(context=context)
        node = self.node = rclpy.create_node("rviz_test_sensors", context=context)
        latched = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)
        self.executor.add_node(node)
        self.static = StaticTransformBroadcaster(node)
        self.static.sendTransform(
            [
                transform("map", "odom", (0.0, 0.0, 0.0)),
                transform("odom", "base_link", (3.0, 2.0, 0.0), math.pi / 4),
                transform("base_link", "laser", (0.2, 0.0, 0.3)),
                transform("base_link", "left_wheel", (0.0, 0.25, 0.1)),
                transform("base_link", "right_wheel", (0.0, -0.25, 0.1)),
            ]
        )
        node.create_publisher(String, "/robot_description", latched).publish(String(data=ROVER))
        cells = np.zeros((200, 200), dtype=np.int8)
        cells[:4, :] = cells[-4:, :] = cells[:, :4] = cells[:, -4:] = 100
        cells[90:110, 90:110] = 100
        cells[150:, 150:] = -1
        room = OccupancyGrid()
        room.header.frame_id = "map"
        room.info.width = room.info.height = 200
        room.info.resolution = ROOM / 200
        room.info.origin.orientation.w = 1.0
        room.data = cells.flatten().tolist()
        node.create_publisher(OccupancyGrid, "/map", latched).publish(room)
        strip = OccupancyGrid()
        strip.header.frame_id = "map"
        strip.info.width, strip.info.height, strip.info.resolution = 2100, 60, 0.01
        strip.info.origin.position.y = -1.0
        strip.info.origin.orientation.w = 1.0
        strip.data = [50] * (2100 * 60)
        node.create_publisher(OccupancyGrid, "/strip_map", latched).publish(strip)

        scan = LaserScan(angle_min=-math.pi, angle_max=math.pi, range_min=0.1, range_max=20.0)
        scan.header.frame_id = "laser"
        scan.angle_increment = 2 * math.pi / 720
        ranges = []
        for i in range(720):  # the walls of the room, seen from base_link at (3, 2), turned 45
            a = scan.angle_min + i * scan.angle_increment + math.pi / 4
            dx, dy = math.cos(a), math.sin(a)
            hits = [t for t in ((ROOM - 0.2 - 3.2) / dx if dx > 1e-9 else math.inf,
                                (0.2 - 3.2) / dx if dx < -1e-9 else math.inf,
                                (ROOM - 0.2 - 2.2) / dy if dy > 1e-9 else math.inf,
                                (0.2 - 2.2) / dy if dy < -1e-9 else math.inf) if t > 0]  # fmt: skip
            ranges.append(min(hits))
        scan.ranges = ranges
        self.scan = (node.create_publisher(LaserScan, "/scan", 10), scan)

        count = 250_000
        angle = np.linspace(0, 40 * math.pi, count, dtype=np.float32)
        xyz = np.stack([7 + np.cos(angle), 7 + np.sin(angle), angle / (40 * math.pi)], axis=1)
        fields = [
            PointField(name=name, offset=4 * i, datatype=PointField.FLOAT32, count=1)
            for i, name in enumerate("xyz")
        ]
        big = PointCloud2(height=1, width=count, fields=fields, point_step=12, row_step=12 * count)
        big.header.frame_id = "map"
        big.data = xyz.astype("<f4").tobytes()
        self.cloud = (node.create_publisher(PointCloud2, "/points", 10), big)

        path = Path()
        path.header.frame_id = "map"
        for i in range(30):
            p = PoseStamped()
            p.pose.position.x = 3.0 + i * 0.15
            p.pose.position.y = 2.0 + 3 * math.sin(i / 10)
            path.poses.append(p)
        self.path = (node.create_publisher(Path, "/plan", 10), path)
        goal = PoseStamped()
        goal.header.frame_id = "map"
        goal.pose.position.x, goal.pose.position.y = 7.5, 4.8
        goal.pose.orientation.w = 1.0
        self.goal = (node.create_publisher(PoseStamped, "/goal_pose", 10), goal)
        particles = PoseArray()
        particles.header.frame_id = "map"
        for i in range(20):
            p = Pose()
            p.position.x, p.position.y = 3.0 + 0.3 * math.cos(i), 2.0 + 0.3 * math.sin(i)
            p.orientation.z, p.orientation.w = math.sin(i / 4), math.cos(i / 4)
            particles.poses.append(p)
        self.particles = (node.create_publisher(PoseArray, "/particlecloud", 10), particles)
        odom = Odometry()
        odom.header.frame_id, odom.child_frame_id = "odom", "base_link"
        odom.pose.pose.position.x, odom.pose.pose.position.y = 3.0, 2.0
        odom.pose.pose.orientation.z = math.sin(math.pi / 8)
        odom.pose.pose.orientation.w = math.cos(math.pi / 8)
        self.odom = (node.create_publisher(Odometry, "/odom", 10), odom)
        pixels = np.zeros((600, 800, 3), dtype=np.uint8)
        pixels[:, :, 0] = np.linspace(0, 255, 800, dtype=np.uint8)[None, :]
        pixels[:, :, 2] = np.linspace(255, 0, 600, dtype=np.uint8)[:, None]
        image = Image(height=600, width=800, encoding="rgb8", step=2400)
        image.header.frame_id = "camera"
        image.data = pixels.tobytes()
        self.image = (node.create_publisher(Image, "/camera/image_raw", 10), image)
        node.create_timer(0.2, self.tick)
        self.stop = threading.Event()
        self.thread = threading.Thread(target=self.spin, daemon=True)
        self.thread.start()

    def tick(self) -> None:
        stamp = self.node.get_clock().now().to_msg()
        for publisher, msg in (
            self.scan, self.cloud, self.path, self.goal, self.particles, self.odom, self.image
        ):  # fmt: skip
            msg.header.stamp = stamp
            publisher.publish(msg)

    def spin(self) -> None:
        while not self.stop.is_set():
            self.executor.spin_once(timeout_sec=0.05)

    def close(self) -> None:
        self.stop.set()
        self.thread.join()
        self.executor.remove_node(self.node)
        self.node.destroy_node()
        self.executor.shutdown()


@pytest.fixture
def sensors(ros_domain: int) -> Iterator[Sensors]:
    context = Context()
    rclpy.init(context=context)
    publishers = Sensors(context)
    yield publishers
    publishers.close()
    context.try_shutdown()


def test_every_display_by_topic(sensors: Sensors, node_process, tmp_path: Path) -> None:
    """`rviz2` with no file adds a display for each topic of a type it draws and picks the
    fixed frame map; the page draws each (big data thinned), every status ok."""
    link = started(node_process(str(BIN / "rviz2"), "--port", "0", env=HEADLESS))
    browser = browser_for(tmp_path)
    try:
        browser.get(link)
        drawn = page_until(
            browser,
            """const s = window.rvizState;
               if (!s) return null;
               const have = s.objects().filter((o) => o.visible).map((o) => o.what);
               const want = ["map 200x200 cells", "map 2100x60 cells", "720 points",
                 "link base_link", "link right_wheel",
                 "83334 points of 250000", "path of 30 poses", "image 800x600"];
               const poses = have.filter((w) => w.startsWith("pose ")).length;
               const odometry = have.some((w) => w.startsWith("odometry 3.00 2.00"));
               return want.every((w) => have.includes(w)) && poses === 21 && odometry
                 ? have : null;""",
            "every display drawn",
            timeout=90,
        )
        assert "grid 10x10 cells of 1 m" in drawn
        assert browser.execute_script("return window.rvizState.fixed") == "map"
        statuses = page_until(
            browser,
            """const ds = window.rvizState.displays();
               return ds.length >= 12 && ds.every((d) => d.status.startsWith("ok")) ? ds : null;""",
            "every display ok",
        )
        kinds = sorted(d["kind"] for d in statuses)
        assert kinds == sorted(
            ["Grid", "TF", "RobotModel", "LaserScan", "PointCloud2", "Path", "Pose",
             "PoseArray", "Odometry", "Map", "Map", "Image"]
        )  # fmt: skip
        # The laser's points are in the laser's frame, placed by tf in the map.
        scan = browser.execute_script(
            "return window.rvizState.objects().find((o) => o.what === '720 points').position"
        )
        assert scan[:2] == pytest.approx(
            [3.0 + 0.2 * math.cos(math.pi / 4), 2.0 + 0.2 * math.sin(math.pi / 4)], abs=1e-4
        )
        assert "link right_wheel" in drawn
        browser.execute_script(
            "window.rvizState.setView({distance: 11, pitch: 0.75, yaw: -2.2, focal: [5, 5, 0]})"
        )
        browser.save_screenshot(str(tmp_path / "rviz_sensors.png"))
        # The learner types another fixed frame: everything is drawn from base_link now,
        # the map's corner 3 m behind and 2 m to the side of the robot, turned by -45 degrees.
        from selenium.webdriver.common.keys import Keys

        field = browser.find_element("id", "fixed")
        field.click()  # selects the frame's name: what is typed replaces it
        field.send_keys("base_link", Keys.ENTER)
        corner = page_until(
            browser,
            """const s = window.rvizState;
               const map = s.objects().find((o) => o.what === "map 200x200 cells");
               return s.fixed === "base_link" && map && map.visible ? map.position : null;""",
            "the map placed in base_link",
        )
        c, s = math.cos(-math.pi / 4), math.sin(-math.pi / 4)
        assert corner[:2] == pytest.approx([c * -3 - s * -2, s * -3 + c * -2], abs=1e-3)
    finally:
        browser.quit()


@pytest.mark.parametrize("signum", [signal.SIGINT, signal.SIGTERM])
def test_ctrl_c_and_sigterm_end_the_view_with_a_page_open(node_process, signum) -> None:
    """Ctrl-C or SIGTERM while a page holds the WebSocket: rviz2 closes it and ends, status 0,
    no traceback."""
    process = node_process(str(BIN / "rviz2"), "--port", "0", env=HEADLESS)
    link = started(process)

    async def hold() -> None:
        async with aiohttp.ClientSession() as client, client.ws_connect(at(link, "ws")) as ws:
            await Tab(ws).until(lambda item: kind_of(item), "a first payload")
            process.process.send_signal(signum)
            ending = (aiohttp.WSMsgType.CLOSE, aiohttp.WSMsgType.CLOSED)
            while (await ws.receive(timeout=TIMEOUT)).type not in ending:
                pass  # what was on its way before the signal

    asyncio.run(hold())
    assert process.wait() == 0
    assert "Traceback" not in "\n".join(process.lines)


def test_a_cloud_the_view_cannot_draw_is_one_status_line(node_process, context) -> None:
    """A PointCloud2 without x, y and z (its type allows it): the display's status says so in
    one line, once in rviz2's log; the view goes on."""
    node = rclpy.create_node("rviz_bad_cloud", context=context)
    bad = PointCloud2(height=1, width=2, point_step=4, row_step=8, data=bytes(8))
    bad.fields = [PointField(name="intensity", offset=0, datatype=PointField.FLOAT32, count=1)]
    bad.header.frame_id = "map"
    publisher = node.create_publisher(PointCloud2, "/bad_cloud", 10)
    timer = node.create_timer(0.2, lambda: publisher.publish(bad))
    executor = SingleThreadedExecutor(context=context)
    executor.add_node(node)
    try:
        process = node_process(str(BIN / "rviz2"), "--port", "0", env=HEADLESS)
        link = started(process)

        def status(item: Any) -> Any:
            if not (isinstance(item, dict) and item.get("type") == "config"):
                return None
            shown = [d for d in item["displays"] if d["topic"] == "/bad_cloud"]
            return shown and shown[0]["status"].startswith("error") and shown[0]["status"]

        async def check(tab: Tab) -> str:
            return await tab.until(status, "the bad cloud's status")

        stop = threading.Event()

        def spin() -> None:
            while not stop.is_set():
                executor.spin_once(timeout_sec=0.05)

        spinner = threading.Thread(target=spin)
        spinner.start()
        try:
            line = with_tab(link, check)
        finally:
            stop.set()
            spinner.join()
        assert line == "error: a PointCloud2 without x, y and z fields"
        warnings = [entry for entry in process.lines if "without x, y and z" in entry]
        assert len(warnings) == 1, warnings
        assert "Traceback" not in "\n".join(process.lines)
    finally:
        node.destroy_timer(timer)
        executor.remove_node(node)
        executor.shutdown()
        node.destroy_node()


def test_rviz2_is_a_package_with_its_executable() -> None:
    """As a ROS 2 installation has it: `ros2 pkg executables rviz2`, and its share folder."""
    assert run("ros2", "pkg", "executables", "rviz2").stdout == "rviz2 rviz2\n"
    share = run("ros2", "pkg", "prefix", "--share", "rviz2").stdout.strip()
    assert (Path(share) / "package.xml").is_file()


def test_with_no_page_open_nothing_is_encoded(context) -> None:
    """The scene's timer encodes the tf frames and the displays only while a page is open
    (the robot model excepted: a bad URDF is said at once); once one opens, the newest is
    sent."""
    from rviz2.config import default_config
    from rviz2.scene import Scene
    from tf2_ros import StaticTransformBroadcaster

    sent: list[str] = []
    scene = Scene(
        default_config(), lambda stream, _payload: sent.append(stream), Path, context=context
    )
    node = rclpy.create_node("rviz_test_tf", context=context)
    broadcaster = StaticTransformBroadcaster(node)
    broadcaster.sendTransform(transform("world", "base_link", (1.0, 0.0, 0.0)))
    executor = SingleThreadedExecutor(context=context)
    for each in (scene, node):
        executor.add_node(each)
    try:
        deadline = time.monotonic() + 3.0  # three seconds: ninety ticks of the scene's timer
        while time.monotonic() < deadline:
            executor.spin_once(timeout_sec=0.05)
        assert "tf" not in sent and sent.count("config") <= 1
        scene.set_viewers(1)
        deadline = time.monotonic() + TIMEOUT
        while "tf" not in sent:
            assert time.monotonic() < deadline, "no tf payload once a page was open"
            executor.spin_once(timeout_sec=0.05)
    finally:
        executor.shutdown()
        scene.destroy_node()
        node.destroy_node()
