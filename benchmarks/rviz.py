"""rviz2's 3D view in headless Chromium: turtlesim's tf (turtle1 driven in circles, its frame
broadcast by turtle_tf2_py's broadcaster), a URDF robot on /robot_description with its links
on /tf_static, and a 10,000-point cloud published at 10 Hz.

Frame latency: from the cloud's header stamp (set just before it is published; same machine,
same clock) to the page's animation frame that has drawn it (rviz.js records ``Date.now()``
less the stamp after ``renderer.render``): DDS + rviz2's encoding + WebSocket + three.js.
Frames a second: the frames the page drew over the window (it draws at most 30 a second,
rviz's Frame Rate, and only when something changed). The baseline is the same stream read at
the same time by a bare WebSocket client in this process (no drawing); and rviz2's CPU with
the page (and that client) open against with neither.
Chromium draws WebGL in software (SwiftShader): there is no GPU here.
"""

from __future__ import annotations

import re
import shutil
import tempfile
import threading
import time
from pathlib import Path

import rclpy
from geometry_msgs.msg import TransformStamped
from rclpy.qos import DurabilityPolicy, QoSProfile
from sensor_msgs.msg import PointCloud2, PointField
from std_msgs.msg import String

from benchmarks.common import Row, fmt_ms, p50, p99, python, start, stop, wait_for_lines
from benchmarks.turtlesim import HEADLESS, Bench, _cpu_seconds
from benchmarks.websocket import FrameReader

POINTS = 10_000
CLOUD_HZ = 10.0
LINK = r"http://\S+\?token=[\w-]+"
CONFIG = """Visualization Manager:
  Displays:
    - {Class: rviz_default_plugins/Grid, Name: Grid}
    - {Class: rviz_default_plugins/TF, Name: TF}
    - Class: rviz_default_plugins/RobotModel
      Name: RobotModel
      Description Topic: {Value: /robot_description}
    - Class: rviz_default_plugins/PointCloud2
      Name: Cloud
      Topic: {Value: /cloud}
  Global Options: {Fixed Frame: world}
"""
LINKS = 12  # the robot: a chain of boxes and cylinders, each on /tf_static
URDF_LINK = """<link name="link{i}"><visual><geometry>{shape}</geometry>
  <material name="m{i}"><color rgba="0.2 0.4 {c} 1"/></material></visual></link>"""


def urdf() -> str:
    links, joints = [], []
    for i in range(LINKS):
        shape = '<box size="0.3 0.2 0.2"/>' if i % 2 else '<cylinder radius="0.1" length="0.3"/>'
        links.append(URDF_LINK.format(i=i, shape=shape, c=i / LINKS))
        if i:
            joints.append(
                f'<joint name="j{i}" type="fixed"><parent link="link{i - 1}"/>'
                f'<child link="link{i}"/><origin xyz="0.3 0 0.1"/></joint>'
            )
    return f'<robot name="bench">{"".join(links)}{"".join(joints)}</robot>'


def cloud(stamp: object) -> PointCloud2:
    fields = [PointField(name=n, offset=4 * i, datatype=7, count=1) for i, n in enumerate("xyz")]
    msg = PointCloud2(height=1, width=POINTS, fields=fields, point_step=12, row_step=12 * POINTS)
    msg.header.frame_id = "world"
    msg.header.stamp = stamp
    msg.data = CLOUD_DATA
    return msg


def _cloud_bytes() -> bytes:
    import numpy as np

    i = np.arange(POINTS, dtype=np.float32)
    xyz = np.stack([5.5 + 3 * np.cos(i / 300), 5.5 + 3 * np.sin(i / 300), i / POINTS], axis=1)
    return xyz.astype("<f4").tobytes()


CLOUD_DATA = _cloud_bytes()


def robot_publishers(bench: Bench) -> None:
    """The URDF (latched), its links on /tf_static, and the cloud at CLOUD_HZ."""
    from tf2_ros import StaticTransformBroadcaster

    node = bench.node
    latched = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)
    node.create_publisher(String, "/robot_description", latched).publish(String(data=urdf()))
    transforms = []
    for i in range(LINKS):
        t = TransformStamped()
        t.header.frame_id, t.child_frame_id = (
            ("world", "link0") if i == 0 else (f"link{i - 1}", f"link{i}")
        )
        t.transform.translation.x = 2.0 if i == 0 else 0.3
        t.transform.translation.z = 0.1
        t.transform.rotation.w = 1.0
        transforms.append(t)
    bench.static = StaticTransformBroadcaster(node)
    bench.static.sendTransform(transforms)
    publisher = node.create_publisher(PointCloud2, "/cloud", 10)
    node.create_timer(
        1 / CLOUD_HZ, lambda: publisher.publish(cloud(node.get_clock().now().to_msg()))
    )


class Socket(FrameReader):
    """A bare WebSocket client (no drawing): each cloud frame's latency at arrival."""

    def on_frame(self, header: dict, now: float) -> None:
        if header.get("kind") == "PointCloud2":
            self.latencies.append(now - header["stamp"])


def _browser(folder: str):
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service

    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    driver = shutil.which("chromedriver")
    if not chromium or not driver:
        raise RuntimeError("needs Debian's chromium and chromium-driver")
    options = webdriver.ChromeOptions()
    options.binary_location = chromium
    for argument in (
        "--headless=new", "--no-sandbox", "--disable-gpu", "--use-angle=swiftshader",
        "--enable-unsafe-swiftshader", "--disable-background-networking",
        "--disable-component-update", "--disable-sync", "--no-first-run",
        "--window-size=1280,800", f"--user-data-dir={folder}/chromium",
    ):  # fmt: skip
        options.add_argument(argument)
    return webdriver.Chrome(options=options, service=Service(driver))


def view_figures(seconds: float = 10.0) -> list[Row]:
    folder = tempfile.mkdtemp(prefix="rviz_bench_")
    (Path(folder) / "bench.rviz").write_text(CONFIG)
    sim = start(python("-m", "ros_tutorials_turtlesim.turtlesim_node"), env=HEADLESS)
    broadcaster = start(
        python(
            "-m", "turtle_tf2_py.turtle_tf2_broadcaster", "--ros-args", "-p", "turtlename:=turtle1"
        )
    )
    rviz = start(
        python("-m", "rviz2.rviz2", "-d", f"{folder}/bench.rviz", "--port", "0"), env=HEADLESS
    )
    context = rclpy.Context()
    rclpy.init(context=context)
    bench = Bench(context)
    browser = None
    try:
        if not wait_for_lines(sim, lambda line: "Spawning turtle [turtle1]" in line, 60):
            raise RuntimeError("turtlesim did not start")
        link: list[str] = []
        if not wait_for_lines(rviz, lambda line: link.extend(re.findall(LINK, line)) or link, 60):
            raise RuntimeError("rviz2 did not start")
        for proc in (sim, rviz, broadcaster):
            threading.Thread(target=proc.stdout.read, daemon=True).start()
        bench.drive(["turtle1"])
        robot_publishers(bench)
        bench.spin_for(2.0)
        before, wall = _cpu_seconds(rviz.pid), time.monotonic()
        bench.spin_for(seconds)
        idle_cpu = (_cpu_seconds(rviz.pid) - before) / (time.monotonic() - wall)

        page, _, query = link[0].partition("?")
        socket = Socket(f"{page}ws?{query}")
        socket.start()
        bench.spin_until(lambda: len(socket.latencies) > 5 or socket.error is not None)
        browser = _browser(folder)
        browser.get(link[0])
        ready = """const s = window.rvizState;
            return !!s && s.objects().some((o) => o.what === "10000 points")
              && s.objects().some((o) => o.what === "link link11" && o.visible)
              && s.objects().some((o) => o.what === "frame turtle1" && o.visible);"""
        bench.spin_until(lambda: browser.execute_script(ready), timeout=90)
        bench.spin_for(2.0)
        browser.execute_script(
            "const s = window.rvizState;"
            "s.latencies.length = 0; s.arrivals.length = 0; s.drawMs.length = 0"
        )
        renders = browser.execute_script("return window.rvizState.renders")
        socket.latencies.clear()
        before, wall = _cpu_seconds(rviz.pid), time.monotonic()
        bench.spin_for(seconds)
        bare = list(socket.latencies)
        elapsed = time.monotonic() - wall
        open_cpu = (_cpu_seconds(rviz.pid) - before) / elapsed
        fps = (browser.execute_script("return window.rvizState.renders") - renders) / elapsed
        drawn = browser.execute_script("return window.rvizState.latencies.slice()")
        arrived = browser.execute_script("return window.rvizState.arrivals.slice()")
        draw_ms = browser.execute_script("return window.rvizState.drawMs.slice()")
        socket.stop.set()
        socket.join(5)
    finally:
        if browser is not None:
            browser.quit()
        bench.close()
        context.try_shutdown()
        for proc in (rviz, broadcaster, sim):
            stop(proc)
        shutil.rmtree(folder, ignore_errors=True)
    where = f"turtlesim tf + {LINKS}-link URDF + {POINTS}-point cloud at {CLOUD_HZ:g} Hz"
    return [
        Row(
            f"rviz2 3D view ({where}): cloud stamp -> frame drawn in Chromium, median / p99",
            f"{fmt_ms(p50(drawn))} / {fmt_ms(p99(drawn))}",
            f"{fmt_ms(p50(bare))} / {fmt_ms(p99(bare))} (a bare WebSocket client beside it)",
            target="p99 under 100 ms",
            met=p99(drawn) < 0.1,
        ),
        Row(
            f"rviz2 3D view ({where}): cloud stamp -> the page's WebSocket, median / p99",
            f"{fmt_ms(p50(arrived))} / {fmt_ms(p99(arrived))}",
        ),
        Row(
            f"rviz2 3D view ({where}): the page's time to update and draw one frame, p50 / p99",
            f"{fmt_ms(p50(draw_ms) / 1e3)} / {fmt_ms(p99(draw_ms) / 1e3)}",
        ),
        Row(
            f"rviz2 3D view ({where}): frames a second drawn (headless Chromium, SwiftShader)",
            f"{fps:.1f}",
            f"{len(drawn) / seconds:.1f} clouds a second drawn",
            target="at least 20",
            met=fps >= 20,
        ),
        Row(
            f"rviz2 CPU ({where}), page open",
            f"{open_cpu * 100:.1f} %",
            f"{idle_cpu * 100:.1f} % (no page)",
            open_cpu / idle_cpu if idle_cpu else None,
        ),
    ]
