"""`rostopic hz` (ROS 1's rule, ros_comm's ROSTopicHz.print_hz): each second the rate over the
messages so far, `no new messages` when none came since the last report, nothing before the
second message; and a latched `rostopic pub` message reaches each subscriber once (ROS 1's
latching), so hz counts it once however many subscribers join."""

from __future__ import annotations

import itertools

from helpers import BIN


def reports(lines: list[str]) -> list[str]:
    """hz's report lines: `average rate: ...` and `no new messages`."""
    return [line for line in lines if line.startswith(("average rate", "no new messages"))]


def latched(node_process, text: str):
    pub = node_process(str(BIN / "rostopic"), "pub", "/hz_latched", "std_msgs/String", text)
    pub.wait_for_text("publishing and latching")
    return pub


def test_two_latched_messages_are_one_rate_then_no_new_messages(ros_domain, node_process):
    hz = node_process(str(BIN / "rostopic"), "hz", "/hz_latched")
    first = latched(node_process, "one")
    hz.wait_for_text("subscribed to [/hz_latched]")
    # Another subscriber joins (rostopic echo, latched as hz): it gets the message once, from
    # the publisher's history, and hz no second copy.
    echo = node_process(str(BIN / "rostopic"), "echo", "/hz_latched")
    echo.wait_for_text("data: one")
    second = latched(node_process, "two")
    # The rate once (over the two messages), then each second no new message.
    lines = hz.wait_for_output(
        lambda lines: reports(lines)[-2:] == ["no new messages"] * 2, what="two 'no new messages'"
    )
    shown = reports(lines)
    rates = [line for line in shown if line.startswith("average rate")]
    assert len(rates) == 1, lines
    window = lines[lines.index(rates[0]) + 1]
    assert window.endswith("window: 2"), lines  # two messages, neither counted twice
    assert shown[shown.index(rates[0]) + 1 :] == ["no new messages"] * (len(shown) - 1), lines
    echo.wait_for_text("data: two")
    assert [line for line in echo.lines if line.startswith("data:")] == ["data: one", "data: two"]
    for proc in (hz, echo, first, second):
        assert proc.interrupt() == 0


def bandwidths(lines: list[str]) -> list[float]:
    """bw's figures, in B/s, in the order printed."""
    return [float(line.split(" B/s")[0]) for line in lines if " B/s from " in line]


def test_bw_falls_after_the_publisher_stops(ros_domain, node_process):
    """ROS 1's rostopic bw divides the window's bytes by the time from its first message until
    now: when the messages stop, the figure falls each second."""
    pub = node_process(
        str(BIN / "rostopic"), "pub", "-r", "10", "/bw_topic", "std_msgs/String", "x"
    )
    bw = node_process(str(BIN / "rostopic"), "bw", "/bw_topic")
    bw.wait_for_output(lambda lines: len(bandwidths(lines)) >= 2, what="two bandwidths")
    assert pub.interrupt() == 0
    stopped = len(bandwidths(bw.lines))
    # The first report after the stop may still count a message; the ones after it cannot.
    lines = bw.wait_for_output(
        lambda lines: len(bandwidths(lines)) >= stopped + 4, what="four bandwidths after the stop"
    )
    after = bandwidths(lines)[stopped + 1 :]
    assert all(later < earlier for earlier, later in itertools.pairwise(after)), lines
    assert bw.interrupt() == 0
