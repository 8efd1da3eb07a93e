"""rqt in the browser, used as a person uses it: headless Chromium opens the link `rqt`
printed, picks from the lists, types in the forms, clicks, and reads what the page shows,
against a real headless turtlesim; what the page did is checked with the command-line tools.
Screenshots go to the test's tmp_path (docs/images has the ones the docs show).
"""

from __future__ import annotations

import os
import pty
import re
import select
import signal
import subprocess
import time
from pathlib import Path
from typing import Any

import pytest
from browser import chromium, text_of, until
from geometry_msgs.msg import Twist
from helpers import BIN, TIMEOUT, ok
from rclpy.serialization import serialize_message
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support.ui import Select
from std_msgs.msg import String

import rosbag2_py

HEADLESS = {"DISPLAY": "", "WAYLAND_DISPLAY": ""}
LINK = r"Open (http://127\.0\.0\.1:\d+/rqt\?token=[\w-]{32})#service_caller in a browser"


@pytest.fixture(scope="class")
def rqt(class_own_domain, class_node_process) -> str:
    """A headless turtlesim and `rqt` (on a free port) in a domain of their own; the page's
    address without its #tool."""
    sim = class_node_process(str(BIN / "ros2"), "run", "turtlesim", "turtlesim_node", env=HEADLESS)
    sim.wait_for_text("Spawning turtle [turtle1]")
    tool = class_node_process(str(BIN / "rqt"), "--port", "0", env=HEADLESS)
    found = re.search(LINK, tool.wait_for_text("in a browser")[-1])
    assert found, tool.output
    return found.group(1)


def pose(turtle: str = "turtle1") -> dict[str, float]:
    text = ok("ros2", "topic", "echo", "--once", f"/{turtle}/pose")
    return {k: float(v) for k, v in re.findall(r"^(x|y|theta): (\S+)$", text, re.M)}


def field(browser: Any, scope: str, path: str) -> Any:
    """The input of a form's field, by its dotted path (linear.x) under ``scope`` (CSS)."""
    *sets, name = path.split(".")
    css = scope + "".join(f' fieldset[data-field="{s}"]' for s in sets) + f' [name="{name}"]'
    return browser.find_element(By.CSS_SELECTOR, css)


def type_into(element: Any, text: str) -> None:
    """Type over what the field holds, as a person does (select all, type)."""
    element.send_keys(Keys.CONTROL, "a")
    element.send_keys(text)


def choose(browser: Any, select_id: str, value: str) -> None:
    """Pick ``value`` from a list the page fills from the graph (it may come a moment later;
    the list's refresh button asks again)."""

    def there() -> bool:
        options = [
            o.get_attribute("value") for o in Select(browser.find_element(By.ID, select_id)).options
        ]
        if value not in options:
            refresh = browser.find_elements(By.ID, select_id.split("-")[0] + "-refresh")
            if refresh:
                refresh[0].click()
            return False
        return True

    until(there, f"{value} in the list {select_id}")
    Select(browser.find_element(By.ID, select_id)).select_by_value(value)


class TestRqtInTheBrowser:
    """One turtlesim and one `rqt` for the class."""

    def test_service_caller_spawns_turtle2_and_sets_its_pen(self, rqt: str, tmp_path) -> None:
        """The first turtlesim page's rqt steps: Service Caller, /spawn, then the new
        turtle's /set_pen; a value that is no number is one line, and nothing is called."""
        with chromium(1200, 800) as browser:
            browser.get(rqt + "#service_caller")
            choose(browser, "sc-service", "/spawn")
            until(lambda: browser.find_elements(By.CSS_SELECTOR, "#sc-form [name=x]"), "the form")
            type_into(field(browser, "#sc-form", "x"), "two")
            browser.find_element(By.ID, "sc-call").click()
            until(lambda: text_of(browser, "#sc-error"), "the error line")
            assert text_of(browser, "#sc-error") == "x is a number (float), got 'two'"
            assert text_of(browser, "#sc-response") == ""
            for name, value in (("x", "2"), ("y", "2"), ("theta", "0.2"), ("name", "turtle2")):
                type_into(field(browser, "#sc-form", name), value)
            browser.find_element(By.ID, "sc-call").click()
            until(lambda: text_of(browser, "#sc-response") == "name: turtle2", "the response")
            assert pose("turtle2") == pytest.approx({"x": 2.0, "y": 2.0, "theta": 0.2}, abs=1e-4)
            browser.save_screenshot(str(tmp_path / "rqt_service_caller.png"))

            choose(browser, "sc-service", "/turtle2/set_pen")
            until(lambda: browser.find_elements(By.CSS_SELECTOR, "#sc-form [name=off]"), "SetPen")
            for name, value in (("r", "255"), ("g", "255"), ("b", "255"), ("width", "10")):
                type_into(field(browser, "#sc-form", name), value)
            type_into(field(browser, "#sc-form", "r"), "256")
            browser.find_element(By.ID, "sc-call").click()
            until(lambda: "256" in text_of(browser, "#sc-error"), "uint8 out of range")
            type_into(field(browser, "#sc-form", "r"), "255")
            browser.find_element(By.ID, "sc-call").click()
            until(lambda: text_of(browser, "#sc-response") == "(an empty response)", "set_pen")
            assert text_of(browser, "#sc-error") == ""

    def test_publisher_drives_the_turtle_and_stops_with_the_tab(self, rqt: str, tmp_path) -> None:
        with chromium(1200, 800) as browser:
            browser.get(rqt + "#publisher")
            until(lambda: text_of(browser, "#status") == "live", "the page live")
            type_into(browser.find_element(By.ID, "pub-topic"), "/turtle1/cmd_vel\t")
            # A topic of the graph: its type filled in.
            kind = browser.find_element(By.ID, "pub-type")
            until(lambda: kind.get_attribute("value") == "geometry_msgs/msg/Twist", "the type")
            type_into(browser.find_element(By.ID, "pub-rate"), "10")
            browser.find_element(By.ID, "pub-add").click()
            until(lambda: browser.find_elements(By.CSS_SELECTOR, ".publisher form"), "the form")
            card = ".publisher"
            type_into(field(browser, card, "linear.x"), "fast")
            browser.find_element(By.CSS_SELECTOR, ".publisher .on").click()
            until(lambda: text_of(browser, ".publisher .error"), "the error line")
            assert "'fast'" in text_of(browser, ".publisher .error")
            assert not browser.find_element(By.CSS_SELECTOR, ".publisher .on").is_selected()
            start = pose()
            type_into(field(browser, card, "linear.x"), "1.0")
            type_into(field(browser, card, "angular.z"), "0.5")
            browser.find_element(By.CSS_SELECTOR, ".publisher .on").click()
            until(lambda: "sent" in text_of(browser, ".publisher .count"), "messages sent")
            until(lambda: pose()["theta"] != pytest.approx(start["theta"], abs=0.05), "turning")
            assert text_of(browser, ".publisher .error") == ""
            browser.save_screenshot(str(tmp_path / "rqt_publisher.png"))
        # The tab has gone: its publisher with it.
        until(lambda: "Publisher count: 0" in ok("ros2", "topic", "info", "/turtle1/cmd_vel"),
              "no publisher left on /turtle1/cmd_vel")  # fmt: skip

    def test_parameters_are_edited_live_within_their_range(self, rqt: str, tmp_path) -> None:
        with chromium(1200, 900) as browser:
            browser.get(rqt + "#reconfigure")
            choose(browser, "rc-node", "/turtlesim")
            row = '#rc-params tr[data-name="background_r"]'
            until(lambda: browser.find_elements(By.CSS_SELECTOR, row), "background_r's row")
            assert "integer" in text_of(browser, row)
            slider = browser.find_element(By.CSS_SELECTOR, row + " input[type=range]")
            assert (slider.get_attribute("min"), slider.get_attribute("max")) == ("0", "255")
            value = browser.find_element(By.CSS_SELECTOR, row + " input.value")
            type_into(value, "300\n")
            until(lambda: "out of range" in text_of(browser, row + " .row-error"), "refused")
            background_r = ("ros2", "param", "get", "/turtlesim", "background_r")
            assert ok(*background_r) == "Integer value is: 69\n"
            type_into(value, "150\n")
            until(
                lambda: ok(*background_r) == "Integer value is: 150\n",
                "background_r set to 150",
            )
            assert text_of(browser, row + " .row-error") == ""
            browser.save_screenshot(str(tmp_path / "rqt_reconfigure.png"))
        ok("ros2", "param", "set", "/turtlesim", "background_r", "69")

    def test_logger_level_is_changed_live(self, rqt: str, tmp_path) -> None:
        with chromium(1200, 600) as browser:
            browser.get(rqt + "#logger_level")
            choose(browser, "ll-node", "/turtlesim")
            until(lambda: "INFO" in text_of(browser, "#ll-info"), "the default level said")
            Select(browser.find_element(By.ID, "ll-level")).select_by_value("WARN")
            until(lambda: text_of(browser, "#ll-info") == "set to WARN", "set")
            assert ok("rqt_logger_level", "/turtlesim").startswith("/turtlesim: WARN")
            browser.save_screenshot(str(tmp_path / "rqt_logger_level.png"))
        ok("rqt_logger_level", "/turtlesim", "info")

    def test_plot_draws_two_fields_and_pauses(self, rqt: str, tmp_path) -> None:
        with chromium(1200, 800) as browser:
            browser.get(rqt + "#plot:/turtle1/pose/x,/turtle1/pose/theta")
            until(lambda: text_of(browser, "#status") == "live", "the page live")
            ok("ros2", "topic", "pub", "-t", "3", "-r", "3", "/turtle1/cmd_vel",
               "geometry_msgs/msg/Twist", "{linear: {x: 1.5}, angular: {z: 1.0}}")  # fmt: skip

            def points() -> list[int]:
                return browser.execute_script(
                    "return window.rqtState.series.map(s => s.points.length)"
                )

            until(lambda: min(points()) > 5, "points of both fields")
            xs = browser.execute_script("return window.rqtState.series[0].points.map(p => p[1])")
            assert len(set(xs)) > 1  # the turtle moved: x changed
            browser.find_element(By.ID, "plot-pause").click()
            paused = points()
            ok("ros2", "topic", "pub", "-t", "2", "-r", "2", "/turtle1/cmd_vel",
               "geometry_msgs/msg/Twist", "{linear: {x: -1.0}}")  # fmt: skip
            assert points() == paused
            Select(browser.find_element(By.ID, "plot-span")).select_by_value("10")
            browser.save_screenshot(str(tmp_path / "rqt_plot.png"))
            type_into(browser.find_element(By.ID, "plot-field"), "/turtle1/pose/nope\n")
            browser.find_element(By.ID, "plot-pause").click()
            until(lambda: "no such number" in text_of(browser, "#plot-series"), "said so")
        # The tab has gone: rqt's subscription to the pose with it.
        until(
            lambda: "Subscription count: 0" in ok("ros2", "topic", "info", "/turtle1/pose"),
            "no subscriber left on /turtle1/pose",
        )

    def test_bag_shows_its_topics_a_message_and_plays_a_range(self, rqt: str, tmp_path) -> None:
        bag = write_bag(tmp_path / "drive")
        with chromium(1200, 800) as browser:
            browser.get(rqt + "#bag:" + str(bag))
            until(lambda: "2 topic(s)" in text_of(browser, "#bag-info"), "the bag opened")
            assert "20 message(s)" in text_of(browser, "#bag-info")
            # A click on /chatter's row (the second, sorted), half way: the message then.
            canvas = browser.find_element(By.ID, "bag-timeline")
            width = canvas.size["width"]
            left = 220 * width / 900
            x = left + (width - left - 10 * width / 900) * 0.5 - width / 2
            y = (8 + 22 + 10) * width / 900 - canvas.size["height"] / 2
            from selenium.webdriver import ActionChains

            ActionChains(browser).move_to_element_with_offset(
                canvas, int(x), int(y)
            ).click().perform()
            until(lambda: "data: word" in text_of(browser, "#bag-message"), "the message shown")
            assert "/chatter" in text_of(browser, "#bag-cursor")
            # The bag drives a turtle of its own, spawned where nothing is in its way.
            spawn = "{x: 2.0, y: 5.5, theta: 0.0, name: 'bagturtle'}"
            ok("ros2", "service", "call", "/spawn", "turtlesim/srv/Spawn", spawn)
            start = pose("bagturtle")
            browser.find_element(By.ID, "bag-play").click()
            until(lambda: "played 20 message(s)" in text_of(browser, "#bag-play-info"), "played")
            until(lambda: pose("bagturtle")["x"] > start["x"] + 0.5, "the turtle driven by the bag")
            browser.save_screenshot(str(tmp_path / "rqt_bag.png"))
            type_into(browser.find_element(By.ID, "bag-path"), str(tmp_path / "nothing") + "\n")
            until(lambda: "does not exist" in text_of(browser, "#bag-error"), "one line")


def write_bag(path: Path) -> Path:
    """A bag of 1 s: /bagturtle/cmd_vel forward at 10 Hz, and /chatter's words."""
    writer = rosbag2_py.SequentialWriter()
    writer.open(
        rosbag2_py.StorageOptions(uri=str(path), storage_id="mcap"),
        rosbag2_py.ConverterOptions("", ""),
    )
    for name, kind in (
        ("/bagturtle/cmd_vel", "geometry_msgs/msg/Twist"),
        ("/chatter", "std_msgs/msg/String"),
    ):
        writer.create_topic(
            rosbag2_py.TopicMetadata(id=0, name=name, type=kind, serialization_format="cdr")
        )
    begin = time.time_ns()
    for i in range(10):
        twist = Twist()
        twist.linear.x = 2.0
        writer.write("/bagturtle/cmd_vel", serialize_message(twist), begin + i * 100_000_000)
        writer.write(
            "/chatter", serialize_message(String(data=f"word {i}")), begin + i * 100_000_000 + 1
        )
    writer.close()
    return path


class TestRqtCommands:
    """Each command opens the view at its tool; given what the terminal form takes, the
    terminal form runs (tests/test_console.py and test_graph_view.py check those)."""

    def test_each_command_prints_the_link_to_its_tool(self, own_domain, node_process) -> None:
        for command, fragment in (
            (["rqt_console"], "#console"),
            (["rqt_logger_level"], "#logger_level"),
            (["rqt_reconfigure"], "#reconfigure"),
            (["rqt_service_caller"], "#service_caller"),
            (["rqt_plot", "/turtle1/pose/x", "/turtle1/pose/y"], "#plot:/turtle1/pose/x,/turtle1/pose/y"),  # noqa: E501
            (["ros2", "run", "rqt_bag", "rqt_bag", "/tmp/no bag"], "#bag:/tmp/no%20bag"),
        ):  # fmt: skip
            tool = node_process(str(BIN / command[0]), *command[1:], "--port", "0", env=HEADLESS)
            line = tool.wait_for_text("in a browser")[-1]
            assert re.search(r"/rqt\?token=[\w-]{32}" + re.escape(fragment) + " in a browser", line)
            tool.kill()

    def test_graph_and_console_are_the_viewers_panels(self, rqt: str) -> None:
        with chromium(1200, 800) as browser:
            browser.get(rqt + "#console")
            until(lambda: browser.current_url.endswith("#log-section"), "the viewer's log")
            until(lambda: "Spawning turtle" in text_of(browser, "#log"), "turtlesim's log lines")
            browser.get(rqt + "#graph")
            until(lambda: "/turtlesim" in text_of(browser, "#graph"), "the viewer's graph")

    def test_ctrl_c_and_sigterm_end_it_at_once(self, own_domain, node_process) -> None:
        for stop in ("interrupt", "terminate"):
            tool = node_process(str(BIN / "rqt_publisher"), "--port", "0", env=HEADLESS)
            tool.wait_for_text("in a browser")
            if stop == "interrupt":
                assert tool.interrupt() == 0, tool.output
            else:
                tool.process.send_signal(signal.SIGTERM)
                assert tool.wait() == 0, tool.output
            assert "Traceback" not in tool.output

    def test_rqt_graph_in_a_terminal_without_display_opens_the_view(self, own_domain) -> None:
        """Typed in a terminal with no display: the browser view's graph (down a pipe it
        prints DOT, as test_graph_view.py checks)."""
        main, child = pty.openpty()
        tool = subprocess.Popen(
            [str(BIN / "rqt_graph"), "--port", "0"],
            stdin=child, stdout=child, stderr=child,
            env={**os.environ, **HEADLESS}, start_new_session=True,
        )  # fmt: skip
        os.close(child)
        seen = b""
        try:
            deadline = time.monotonic() + TIMEOUT
            while b"in a browser" not in seen:
                assert time.monotonic() < deadline, f"no link printed: {seen!r}"
                ready, _, _ = select.select([main], [], [], 0.5)
                if ready:
                    seen += os.read(main, 4096)
            assert re.search(rb"/rqt\?token=[\w-]{32}#graph in a browser", seen), seen
        finally:
            tool.send_signal(signal.SIGINT)
            assert tool.wait(TIMEOUT) == 0
            os.close(main)


def test_a_bag_time_line_keeps_a_bounded_even_sample_of_its_messages() -> None:
    """rqt_bag's time line of a topic: every message counted, at most TIMELINE_POINTS stamps
    shown, evenly spread from the first message to near the last, and never more than twice
    that held while the bag is read."""
    import itertools

    from ros_tutorials_web.rqt import TIMELINE_POINTS, Timeline

    line, held = Timeline(), 0
    for stamp in range(1_000_003):
        line.add(stamp)
        held = max(held, len(line.kept))
    shown = line.stamps()
    assert line.count == 1_000_003
    assert held < 2 * TIMELINE_POINTS
    assert TIMELINE_POINTS // 2 <= len(shown) <= TIMELINE_POINTS
    assert shown[0] == 0 and shown[-1] > 1_000_003 - 2 * 1_000_003 // len(shown)
    gaps = {b - a for a, b in itertools.pairwise(shown)}
    assert len(gaps) == 1  # even
    few = Timeline()
    for stamp in (5, 7, 9):
        few.add(stamp)
    assert few.stamps() == [5, 7, 9]


@pytest.mark.parametrize(
    "text", ["2", "-2.5", "true", "[1, 2]", "[1.5, 2.5]", "[a, b]", "[]", "hi"]
)
def test_the_page_sends_what_ros2_param_set_sends(text: str) -> None:
    """A text typed into the page for a parameter of the type `ros2 param set` reads it as
    is sent as the same ParameterValue: one table of types (ros2cmd.param.api)."""
    from ros2cmd.param.api import described_type
    from ros2cmd.param.verb.set import typed_value
    from ros_tutorials_web.forms import parameter_value

    sent = typed_value("p", text)
    assert parameter_value(text, described_type(sent.type)) == sent
