"""The web viewer's tf panel (`ros2 run ros_tutorials_web viewer`, ros_tutorials_web/frames.py):
frames broadcast in this process by tf2_ros's broadcasters, read back through the viewer's own
WebSocket as a page gets them: the tree, each frame's pose (checked against hand
computations), bad input, the same guard as the other streams, and the page in headless
Chromium where it is installed.
"""

from __future__ import annotations

import asyncio
import importlib.util
import json
import math
import re
import threading
import time
from collections.abc import Callable, Iterator
from typing import Any

import aiohttp
import pytest
import rclpy
from browser import chromium, until
from geometry_msgs.msg import TransformStamped
from helpers import BIN, TIMEOUT
from rclpy.context import Context
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile
from test_web_viewer import CANVAS, HEADLESS, LINK, Tab, at, with_tab
from tf2_msgs.msg import TFMessage

from ros_tutorials_web.frames import MAX_FRAMES, parse_frames, tree_order

SQRT_HALF = math.sqrt(0.5)
TURTLE1 = (5.544445, 5.544445)  # where turtlesim puts turtle1
FOLLOW_TIMEOUT = 90.0  # the demo's turtle2 is steered once a second; slow on a loaded machine


def transform(parent: str, child: str, xyz: tuple, yaw: float = 0.0, q: tuple | None = None):
    """A TransformStamped: child's origin at xyz in parent, turned by yaw about z (or q)."""
    t = TransformStamped()
    t.header.frame_id, t.child_frame_id = parent, child
    t.transform.translation.x, t.transform.translation.y, t.transform.translation.z = xyz
    rotation = q if q is not None else (0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2))
    r = t.transform.rotation
    r.x, r.y, r.z, r.w = rotation
    return t


@pytest.fixture
def spinning(context: Context) -> Iterator[Callable[[str], Node]]:
    """Nodes of this test, spun in a thread of their own until the test ends."""
    executor = SingleThreadedExecutor(context=context)
    stop = threading.Event()

    def spin() -> None:
        while not stop.is_set():
            executor.spin_once(timeout_sec=0.05)

    thread = threading.Thread(target=spin, daemon=True)
    nodes: list[Node] = []

    def start(name: str) -> Node:
        node = rclpy.create_node(name, context=context)
        nodes.append(node)
        executor.add_node(node)
        if not thread.is_alive():
            thread.start()
        return node

    yield start
    stop.set()
    if thread.is_alive():
        thread.join()
    for node in nodes:
        executor.remove_node(node)
        node.destroy_node()
    executor.shutdown()


def broadcast_demo(start: Callable[[str], Node]) -> Node:
    """tf2_ros's broadcasters: world -> base (static, at (1, 2), turned 90 degrees) -> sensor
    (static, 0.5 m ahead and 0.2 m up), world -> turtle (20 Hz, at (3, 4), turned 30 degrees)
    -> carrot (20 Hz, 2 m to the turtle's left)."""
    from tf2_ros import StaticTransformBroadcaster, TransformBroadcaster

    node = start("tf_test_broadcaster")
    static = StaticTransformBroadcaster(node)
    static.sendTransform(
        [
            transform("world", "base", (1.0, 2.0, 0.0), math.pi / 2),
            transform("base", "sensor", (0.5, 0.0, 0.2)),
        ]
    )
    dynamic = TransformBroadcaster(node)

    def moving() -> None:
        stamp = node.get_clock().now().to_msg()
        pair = [
            transform("world", "turtle", (3.0, 4.0, 0.0), math.pi / 6),
            transform("turtle", "carrot", (0.0, 2.0, 0.0)),
        ]
        for t in pair:
            t.header.stamp = stamp
        dynamic.sendTransform(pair)

    node.create_timer(0.05, moving)
    return node


def tf_with(names: set[str], fixed: str | None = None) -> Callable[[Any], Any]:
    """A finder for Tab.until: a tf message holding poses of all the named frames."""

    def found(item: Any) -> Any:
        if not isinstance(item, dict) or item.get("type") != "tf":
            return None
        assert_finite(item)
        if fixed is not None and item["fixed"] != fixed:
            return None
        posed = {f["name"] for f in item["frames"] if f.get("pose")}
        return item if names <= posed else None

    return found


def assert_finite(data: Any) -> None:
    """No NaN or infinity in what the viewer sent (JSON has no word for them)."""
    if isinstance(data, float):
        assert math.isfinite(data), data
    elif isinstance(data, dict):
        for value in data.values():
            assert_finite(value)
    elif isinstance(data, list):
        for value in data:
            assert_finite(value)


def by_name(message: dict) -> dict[str, dict]:
    return {frame["name"]: frame for frame in message["frames"]}


def start_viewer(node_process: Callable[..., Any]) -> tuple[Any, str]:
    process = node_process(str(BIN / "ros2"), "run", "ros_tutorials_web", "viewer", "--port", "0")
    found = re.search(LINK, process.wait_for_text("in a browser")[-1])
    assert found
    return process, found.group(1)


@pytest.fixture(scope="class")
def viewer(class_own_domain, class_node_process) -> str:
    """The viewer (on a free port) in a domain of its own; its address, as it prints it."""
    return start_viewer(class_node_process)[1]


class TestFrames:
    def test_tree_and_poses_in_world(self, viewer: str, spinning) -> None:
        """No fixed frame asked: the viewer takes world; every pose as computed by hand."""
        broadcast_demo(spinning)
        wanted = {"world", "base", "sensor", "turtle", "carrot"}

        async def check(tab: Tab) -> dict:
            await tab.ws.send_str(json.dumps({"tf": {"fixed": ""}}))
            return await tab.until(tf_with(wanted), "the demo's frames in world")

        message = with_tab(viewer, check)
        assert message["fixed"] == "world" and message["asked"] == ""
        assert message["total"] >= 5 and not message["capped"]
        frames = by_name(message)
        assert message["frames"][0]["name"] == "world"  # the root first
        assert {name: frames[name]["parent"] for name in wanted} == {
            "world": None,
            "base": "world",
            "sensor": "base",
            "turtle": "world",
            "carrot": "turtle",
        }
        for name in ("base", "sensor"):  # as view_frames shows a static transform
            assert frames[name]["static"] is True and frames[name]["age"] is None
            assert frames[name]["rate"] == 10000.0
        for name in ("turtle", "carrot"):
            assert frames[name]["static"] is False
            assert frames[name]["broadcaster"] == "default_authority"
            assert frames[name]["rate"] > 0 and -1.0 < frames[name]["age"] < TIMEOUT
        approx = lambda *values: pytest.approx(list(values), abs=1e-6)  # noqa: E731
        world, base = frames["world"]["pose"], frames["base"]["pose"]
        sensor = frames["sensor"]["pose"]
        assert world["xyz"] == approx(0, 0, 0) and world["q"] == approx(0, 0, 0, 1)
        assert base["xyz"] == approx(1, 2, 0) and base["yaw"] == pytest.approx(math.pi / 2)
        assert base["q"] == approx(0, 0, SQRT_HALF, SQRT_HALF)
        # sensor: 0.5 m along base's x, which points along world's y; 0.2 m up.
        assert sensor["xyz"] == approx(1, 2.5, 0.2)
        assert sensor["q"] == approx(0, 0, SQRT_HALF, SQRT_HALF)
        assert sensor["x_axis"] == approx(0, 1) and sensor["y_axis"] == approx(-1, 0)
        turtle, carrot = frames["turtle"]["pose"], frames["carrot"]["pose"]
        assert turtle["xyz"] == approx(3, 4, 0) and turtle["yaw"] == pytest.approx(math.pi / 6)
        assert turtle["x_axis"] == approx(math.cos(math.pi / 6), 0.5)
        # carrot: 2 m along the turtle's y, which is world's (-sin 30, cos 30).
        assert carrot["xyz"] == approx(3 - 1, 4 + math.sqrt(3), 0)
        assert carrot["yaw"] == pytest.approx(math.pi / 6)

    def test_poses_in_another_fixed_frame(self, viewer: str, spinning) -> None:
        """Fixed frame turtle: the world is where the turtle sees it; an unknown fixed frame
        gives each frame tf2's reason, and the stream goes on."""
        broadcast_demo(spinning)

        async def check(tab: Tab) -> tuple[dict, dict]:
            await tab.ws.send_str(json.dumps({"tf": {"fixed": "turtle"}}))
            seen = await tab.until(tf_with({"world", "carrot"}, "turtle"), "frames in turtle")
            await tab.ws.send_str(json.dumps({"tf": {"fixed": "nowhere"}}))

            def unknown(item: Any) -> Any:
                is_tf = isinstance(item, dict) and item.get("type") == "tf"
                return item if is_tf and item["fixed"] == "nowhere" and item["frames"] else None

            return seen, await tab.until(unknown, "frames in an unknown fixed frame")

        seen, unknown = with_tab(viewer, check)
        frames = by_name(seen)
        c, s = math.cos(math.pi / 6), math.sin(math.pi / 6)
        # The world's origin seen from the turtle: R(-30 degrees) times (-3, -4).
        world = frames["world"]["pose"]
        assert world["xyz"] == pytest.approx([-3 * c - 4 * s, 3 * s - 4 * c, 0], abs=1e-6)
        assert world["yaw"] == pytest.approx(-math.pi / 6)
        assert frames["carrot"]["pose"]["xyz"] == pytest.approx([0, 2, 0], abs=1e-6)
        assert frames["carrot"]["pose"]["yaw"] == pytest.approx(0, abs=1e-6)
        for frame in unknown["frames"]:
            assert frame["pose"] is None and frame["error"], frame

    def test_a_tab_that_is_gone_costs_nothing(self, viewer: str, spinning) -> None:
        """The viewer listens to /tf only while a tab shows the frames."""
        node = spinning("tf_test_counter")

        def viewer_listens() -> bool:
            return any(
                info.node_name == "web_viewer"
                for info in node.get_subscriptions_info_by_topic("/tf")
            )

        def until(condition: Callable[[], bool], what: str) -> None:
            deadline = time.monotonic() + TIMEOUT
            while not condition():
                assert time.monotonic() < deadline, f"{what}: not within {TIMEOUT} s"
                time.sleep(0.05)

        async def check(tab: Tab) -> None:
            await tab.ws.send_str(json.dumps({"tf": {"fixed": ""}}))
            await asyncio.to_thread(until, viewer_listens, "the viewer subscribed to /tf")
            await tab.ws.send_str(json.dumps({"tf": None}))
            await asyncio.to_thread(until, lambda: not viewer_listens(), "/tf let go")
            await tab.ws.send_str(json.dumps({"tf": {"fixed": "world"}}))
            await asyncio.to_thread(until, viewer_listens, "/tf again")

        with_tab(viewer, check)
        until(lambda: not viewer_listens(), "/tf let go when the tab closed")

    def test_the_frames_are_refused_to_foreign_pages(self, viewer: str) -> None:
        """The tf stream comes through the one WebSocket: a foreign Origin, another Host or
        no token is refused before a frame is sent."""
        port = int(re.search(r":(\d+)/", viewer).group(1))
        page = viewer.split("?token=")[0]

        async def check() -> None:
            async with aiohttp.ClientSession() as client:
                refusals = [
                    client.ws_connect(at(viewer, "ws"), origin="https://evil.example"),
                    client.ws_connect(at(viewer, "ws"), headers={"Host": f"rebind.example:{port}"}),
                    client.ws_connect(page + "ws"),
                ]
                for refused in refusals:
                    with pytest.raises(aiohttp.WSServerHandshakeError) as error:
                        await refused
                    assert error.value.status == 403

        asyncio.run(check())


def test_the_follow_demo_in_the_viewer(own_domain, node_process) -> None:
    """The official tf2 demo (turtle2 follows turtle1) as the page gets it: turtle1 where
    turtlesim put it, turtle2 seen moving until it is next to turtle1."""
    if importlib.util.find_spec("turtle_tf2_py") is None:
        pytest.skip("needs turtle_tf2_py, the official tf2 tutorials' demo package")
    _, link = start_viewer(node_process)
    seen: list[tuple[float, float]] = []  # turtle2's positions, as the page got them

    def near(item: Any) -> Any:
        found = tf_with({"turtle1", "turtle2"}, "world")(item)
        if not found:
            return None
        turtle1, turtle2 = (
            by_name(found)[name]["pose"]["xyz"][:2] for name in ("turtle1", "turtle2")
        )
        if not seen or seen[-1] != tuple(turtle2):
            seen.append(tuple(turtle2))
        return found if len(seen) > 1 and math.dist(turtle1, turtle2) < 1.0 else None

    async def check(tab: Tab) -> dict:
        await tab.ws.send_str(json.dumps({"tf": {"fixed": ""}}))
        launch = ("launch", "turtle_tf2_py", "turtle_tf2_demo.launch.py")
        await asyncio.to_thread(node_process, str(BIN / "ros2"), *launch, env=HEADLESS)
        return await tab.until(near, "turtle2 next to turtle1 in the view", FOLLOW_TIMEOUT)

    message = with_tab(link, check)
    assert message["fixed"] == "world"
    frames = by_name(message)
    assert frames["turtle1"]["parent"] == frames["turtle2"]["parent"] == "world"
    assert frames["turtle1"]["pose"]["xyz"] == pytest.approx([*TURTLE1, 0], abs=1e-3)
    assert frames["turtle1"]["rate"] > 0 and frames["turtle2"]["rate"] > 0


class TestBadInput:
    """What a broken broadcaster sends: the view stays up, no NaN reaches the page, the
    viewer's terminal shows no traceback."""

    def test_loop_two_parents_nan_and_odd_stamps(self, own_domain, node_process, spinning) -> None:
        process, link = start_viewer(node_process)
        node = spinning("tf_test_bad")
        publisher = node.create_publisher(TFMessage, "/tf", 100)
        now = node.get_clock().now()
        bad = [
            transform("world", "ok", (1.0, 0.0, 0.0)),
            transform("loop_b", "loop_a", (1.0, 0.0, 0.0)),
            transform("loop_a", "loop_b", (1.0, 0.0, 0.0)),
            transform("world", "twice", (1.0, 0.0, 0.0)),
            transform("ok", "twice", (2.0, 0.0, 0.0)),  # a second parent: the newest wins
            transform("world", "nan", (1.0, 0.0, 0.0), q=(math.nan, 0.0, 0.0, 1.0)),
            transform("world", "not_unit", (1.0, 0.0, 0.0), q=(0.0, 0.0, 2.0, 2.0)),
            transform("world", "nan_xyz", (math.nan, 0.0, 0.0)),
            transform("world", "inf_xyz", (math.inf, 0.0, 0.0)),
            transform("", "no_parent", (1.0, 0.0, 0.0)),
            transform("world", "", (1.0, 0.0, 0.0)),
            transform("world", "world", (1.0, 0.0, 0.0)),
            transform("world", "future", (1.0, 0.0, 0.0)),
            transform("world", "past", (1.0, 0.0, 0.0)),
        ]
        for t in bad:
            t.header.stamp = now.to_msg()  # a message of its own: set below for two of them
        bad[-2].header.stamp.sec += 3600
        bad[-1].header.stamp.sec = 1

        async def check(tab: Tab) -> dict:
            await tab.ws.send_str(json.dumps({"tf": {"fixed": "world"}}))
            deadline = time.monotonic() + TIMEOUT

            def everything(item: Any) -> Any:
                if time.monotonic() < deadline:
                    publisher.publish(TFMessage(transforms=bad))  # until discovery joined us
                return tf_with({"ok", "twice", "future", "past"})(item)

            return await tab.until(everything, "the good frames among the bad")

        message = with_tab(link, check)
        frames = by_name(message)
        for name in ("loop_a", "loop_b"):  # the loop is shown, without a pose, with tf2's reason
            assert frames[name]["loop"] and frames[name]["pose"] is None
            assert frames[name]["error"] == "The tf tree is invalid because it contains a loop."
        assert frames["twice"]["parent"] in ("world", "ok")
        # tf2 keeps a stamp an hour ahead or from 1970: the page gets their ages to show.
        assert frames["future"]["age"] < -3000 and frames["past"]["age"] > 1e9
        # tf2 refuses NaN, a quaternion far from unit length and a frame without a name, each
        # with its line in the viewer's terminal; an infinity (which tf2 takes) is null.
        for name in ("nan", "nan_xyz", "not_unit", "no_parent", ""):
            assert name not in frames
        assert frames["inf_xyz"]["pose"]["xyz"][0] is None
        process.wait_for_text('TF_NAN_INPUT: Ignoring transform for child_frame_id "nan"')
        process.wait_for_text("TF_SELF_TRANSFORM")
        assert "Traceback" not in process.output
        # Still serving: the other streams and the API.
        with_tab(link, lambda tab: tab.until(lambda i: i.get("type") == "graph", "the graph"))

    def test_ten_thousand_frames_are_capped(self, own_domain, node_process, spinning) -> None:
        process, link = start_viewer(node_process)
        node = spinning("tf_test_many")
        latched = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)
        publisher = node.create_publisher(TFMessage, "/tf_static", latched)
        many = [transform("world", f"f{i:05d}", (i * 0.001, 0.0, 0.0)) for i in range(10000)]
        publisher.publish(TFMessage(transforms=many))

        async def check(tab: Tab) -> dict:
            await tab.ws.send_str(json.dumps({"tf": {"fixed": ""}}))

            def all_there(item: Any) -> Any:
                return item if tf_with({"f00000"})(item) and item["total"] >= 10001 else None

            return await tab.until(all_there, "10,000 frames counted", timeout=2 * TIMEOUT)

        message = with_tab(link, check)
        assert message["capped"] and len(message["frames"]) == MAX_FRAMES
        assert message["fixed"] == "world"
        assert by_name(message)["f00100"]["pose"]["xyz"] == pytest.approx([0.1, 0, 0])
        assert "Traceback" not in process.output

    def test_a_fast_broadcaster(self, own_domain, node_process, spinning) -> None:
        """A broadcaster as fast as this process can publish (10 kHz where the CPU allows):
        snapshots keep coming, each one at most MAX_FRAMES frames."""
        process, link = start_viewer(node_process)
        node = spinning("tf_test_fast")
        publisher = node.create_publisher(TFMessage, "/tf", 100)
        flooding = threading.Event()
        flooding.set()

        def flood() -> None:
            clock = node.get_clock()
            while flooding.is_set():
                t = transform("world", "fast", (1.0, 0.0, 0.0))
                t.header.stamp = clock.now().to_msg()
                publisher.publish(TFMessage(transforms=[t]))

        thread = threading.Thread(target=flood, daemon=True)
        thread.start()
        try:

            async def check(tab: Tab) -> list[dict]:
                await tab.ws.send_str(json.dumps({"tf": {"fixed": ""}}))
                seen = []
                for _ in range(5):  # five snapshots in a row, each newer than the one before
                    seen.append(await tab.until(tf_with({"fast"}), "the fast frame"))
                return seen

            seen = with_tab(link, check)
        finally:
            flooding.clear()
            thread.join()
        stamps = [message["stamp"] for message in seen]
        assert stamps == sorted(stamps) and len(set(stamps)) == 5
        assert all(by_name(m)["fast"]["rate"] > 0 for m in seen)
        assert "Traceback" not in process.output


class TestPureParts:
    """The tree's order from tf2's YAML listing, loops and long chains included."""

    def test_order_roots_and_loops(self) -> None:
        listing = "".join(
            f"{child}: \n  parent: '{parent}'\n  broadcaster: 'default_authority'\n"
            f"  rate: 10000.000\n  most_recent_transform: 0.000\n  oldest_transform: 0.000\n"
            "  buffer_length: 0.000\n"
            for child, parent in [("b", "a"), ("c", "a"), ("x", "y"), ("y", "x"), ("d", "c")]
        )
        frames = parse_frames(listing)
        roots, order, looped = tree_order(frames)
        assert roots == {"a": 3}
        assert order == ["a", "b", "c", "d", "x", "y"] and looped == {"x", "y"}
        assert parse_frames("[]") == {}
        # tf2 writes names unquoted: one that is no YAML key still shows, and its neighbours.
        odd = parse_frames(listing.replace("x: \n", "x: # y: \n"))
        assert odd["x: # y"].parent == "y" and odd["y"].parent == "x"
        assert odd["b"] == frames["b"]

    def test_a_long_chain(self) -> None:
        listing = "".join(
            f"f{i}: \n  parent: 'f{i - 1}'\n  broadcaster: 'default_authority'\n  rate: 1.0\n"
            for i in range(1, 10001)
        )
        roots, order, looped = tree_order(parse_frames(listing))
        assert roots == {"f0": 10000} and len(order) == 10001 and not looped


class TestInBrowser:
    """The page in headless Chromium: the demo's axes on turtlesim's canvas."""

    def test_axes_on_turtlesim(self, own_domain, node_process, spinning, tmp_path) -> None:
        sim = node_process(str(BIN / "ros2"), "run", "turtlesim", "turtlesim_node", env=HEADLESS)
        sim.wait_for_text("Spawning turtle [turtle1]")
        _, link = start_viewer(node_process)
        broadcast_demo(spinning)
        # Red (x axis) pixels on the overlay of turtlesim's canvas, around turtle's origin.
        red_near = """
            const [topic, px, py] = arguments;
            const state = window.viewerState;
            const picture = state.pictures[topic];
            if (!picture || !state.tf || state.tf.fixed !== "world") return -1;
            const ctx = picture.overlay.getContext("2d");
            const box = ctx.getImageData(px - 40, py - 40, 80, 80).data;
            let n = 0;
            for (let i = 0; i < box.length; i += 4)
              if (box[i] > 180 && box[i + 1] < 80 && box[i + 2] < 80 && box[i + 3] > 0) n++;
            return n;
        """
        with chromium(1400, 1100) as browser:
            browser.get(link)
            # turtle at (3, 4) m: 45 px a metre, y up from the canvas's last row.
            at_pixel = (3 * 45, 499 - 4 * 45)
            until(
                lambda: browser.execute_script(red_near, CANVAS, *at_pixel) > 10,
                "turtle's x axis drawn on the canvas",
            )
            tree = browser.find_element("id", "tf-tree").text
            assert "turtle" in tree and "carrot" in tree and "static" in tree
            assert not browser.find_element("id", "tf-on-canvas").get_attribute("hidden")
            browser.save_screenshot(str(tmp_path / "web_viewer_tf.png"))
