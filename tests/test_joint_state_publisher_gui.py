"""joint_state_publisher_gui: the movable page's sliders as a page in the browser.

The node runs as a real process with 06-flexible.urdf; its page is driven in headless Chromium
as a person would (the sliders' names, End on a slider, Center, Randomize, what the page
shows), and the test's node reads /joint_states. The guard: no token, a foreign Host or a
foreign Origin is refused; a message that does not fit is one line in the page and changes
nothing."""

from __future__ import annotations

import json
import math
import re
import urllib.error
import urllib.request
from pathlib import Path

import pytest
from browser import chromium, until
from helpers import script, spin_until
from rclpy.node import Node
from sensor_msgs.msg import JointState

FLEXIBLE = Path(__file__).resolve().parents[1] / "urdf_tutorial" / "urdf" / "06-flexible.urdf"
HEADLESS = {"DISPLAY": "", "WAYLAND_DISPLAY": ""}
LINK = re.compile(r"Open (http://127\.0\.0\.1:(\d+)/\?token=([\w-]+)) in a browser")
SLIDERS = [
    "right_front_wheel_joint",
    "right_back_wheel_joint",
    "left_front_wheel_joint",
    "left_back_wheel_joint",
    "gripper_extension",
    "left_gripper_joint",
    "right_gripper_joint",
    "head_swivel",
]


@pytest.fixture
def gui(node_process):
    """The running node and its link (address, port, token)."""
    process = node_process(
        script("ros2"),
        "run",
        "joint_state_publisher_gui",
        "joint_state_publisher_gui",
        str(FLEXIBLE),
        "--port",
        "0",
        env=HEADLESS,
    )
    lines = process.wait_for_output(lambda ls: any(LINK.search(line) for line in ls))
    found = next(LINK.search(line) for line in lines if LINK.search(line))
    yield process, found.group(1), int(found.group(2)), found.group(3)
    assert process.interrupt() in (0, 130)
    assert "Traceback" not in process.output


def status(url: str, headers: dict[str, str] | None = None) -> int:
    try:
        with urllib.request.urlopen(urllib.request.Request(url, headers=headers or {})) as r:
            return r.status
    except urllib.error.HTTPError as error:
        return error.code


def test_the_guard_refuses_what_is_not_this_runs_page(gui):
    _process, link, port, token = gui
    assert status(link) == 200
    assert status(f"http://127.0.0.1:{port}/") == 403  # no token
    assert status(f"http://127.0.0.1:{port}/ws") == 403
    assert status(link, {"Host": f"evil.example:{port}"}) == 403  # DNS rebinding
    assert status(link, {"Origin": "http://evil.example"}) == 403
    assert status(f"http://127.0.0.1:{port}/?token=x{token}") == 403


def test_the_sliders_move_the_joints(gui, executor, tmp_path):
    from selenium.webdriver.common.by import By
    from selenium.webdriver.common.keys import Keys

    _process, link, _port, _token = gui
    node = Node("sliders_watcher", context=executor.context)
    executor.add_node(node)
    states: list[JointState] = []
    node.create_subscription(JointState, "/joint_states", states.append, 10)

    def position(joint: str) -> float | None:
        if not states:
            return None
        return dict(zip(states[-1].name, states[-1].position, strict=True)).get(joint)

    with chromium(1100, 700) as browser:
        browser.get(link)
        until(lambda: len(browser.find_elements(By.CSS_SELECTOR, ".joint")) == 8, "8 sliders")
        names = [
            box.get_attribute("data-joint")
            for box in browser.find_elements(By.CSS_SELECTOR, ".joint")
        ]
        assert names == SLIDERS  # every movable joint, in the file's order
        head = browser.find_element(By.CSS_SELECTOR, '.joint[data-joint="head_swivel"]')
        assert head.find_element(By.CSS_SELECTOR, ".value").text == "0.000"
        # End on the head's slider: a continuous joint goes to pi.
        head.find_element(By.CSS_SELECTOR, "input").send_keys(Keys.END)
        spin_until(
            executor,
            lambda: (
                position("head_swivel") is not None
                and math.isclose(position("head_swivel"), math.pi, abs_tol=1e-3)
            ),
            what="head_swivel at pi on /joint_states",
        )
        assert head.find_element(By.CSS_SELECTOR, ".value").text == "3.142"
        browser.save_screenshot(str(tmp_path / "sliders.png"))
        # Center: every joint back to its zero.
        browser.find_element(By.ID, "center").click()
        spin_until(
            executor,
            lambda: position("head_swivel") == 0.0,
            what="head_swivel back at 0 after Center",
        )
        until(lambda: head.find_element(By.CSS_SELECTOR, ".value").text == "0.000", "0.000")
        # Randomize: the arm somewhere within its limits.
        browser.find_element(By.ID, "randomize").click()
        spin_until(
            executor,
            lambda: position("gripper_extension") not in (None, 0.0),
            what="gripper_extension moved by Randomize",
        )
        assert -0.38 <= position("gripper_extension") <= 0.0
        # A message that does not fit: one line in the page, nothing changes.
        before = position("gripper_extension")
        browser.execute_script(
            "socket.send(arguments[0])", json.dumps({"set": {"no_such_joint": 1.0}})
        )
        error = until(
            lambda: browser.find_element(By.ID, "error").text, "the error line in the page"
        )
        assert error == "no movable joint named 'no_such_joint'"
        browser.execute_script("socket.send(arguments[0])", '{"set": {"head_swivel": "up"}}')
        until(
            lambda: "must be a number" in browser.find_element(By.ID, "error").text,
            "the error for a value that is not a number",
        )
        spin_until(executor, lambda: len(states) > 3, what="more /joint_states")
        assert position("gripper_extension") == before


def test_a_window_opens_where_there_is_a_display(node_process, tmp_path):
    """With a display, the sliders open in the learner's browser ($BROWSER here: a script that
    notes what it was asked to open), as ROS 2's window opens; the link is printed either way."""
    opened = tmp_path / "opened"
    browser = tmp_path / "browser"
    browser.write_text(f'#!/bin/sh\necho "$1" >> {opened}\n')
    browser.chmod(0o755)
    process = node_process(
        script("ros2"),
        "run",
        "joint_state_publisher_gui",
        "joint_state_publisher_gui",
        str(FLEXIBLE),
        "--port",
        "0",
        env={"DISPLAY": ":99", "BROWSER": str(browser)},
    )
    lines = process.wait_for_output(lambda ls: any(LINK.search(line) for line in ls))
    link = next(LINK.search(line) for line in lines if LINK.search(line)).group(1)
    until(lambda: opened.exists() and opened.read_text(), "a browser asked to open the sliders")
    assert opened.read_text() == f"{link}\n"
    assert process.interrupt() in (0, 130)


def test_a_slow_tab_gets_the_newest_positions_not_a_backlog(context):
    """While a tab does not read, the positions offered to it wait as one message, the
    newest: a thousand changes leave two sends (the one under way, then the newest)."""
    import asyncio

    from joint_state_publisher.joint_state_publisher import JointStatePublisher
    from joint_state_publisher_gui.joint_state_publisher_gui import Sliders

    class StuckTab:
        """A WebSocket whose reader is slow: each send waits until released."""

        closed = False

        def __init__(self) -> None:
            self.sent: list[str] = []
            self.release = asyncio.Event()

        async def send_str(self, text: str) -> None:
            await self.release.wait()
            self.sent.append(text)

    async def offer() -> list[str]:
        jsp = JointStatePublisher(str(FLEXIBLE), context=context)
        try:
            sliders = Sliders(jsp, asyncio.get_running_loop())
            tab = StuckTab()
            sliders.tabs.add(tab)
            for step in range(1000):
                sliders.change({"set": {"head_swivel": step / 1000}})
                sliders.send_all(sliders.positions())
                await asyncio.sleep(0)
            tab.release.set()
            while tab in sliders.sending:
                await asyncio.sleep(0.01)
            return tab.sent
        finally:
            jsp.destroy_node()

    sent = asyncio.run(offer())
    assert len(sent) == 2
    assert json.loads(sent[-1])["positions"]["head_swivel"] == 0.999
