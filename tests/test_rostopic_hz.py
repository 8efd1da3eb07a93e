"""`rostopic hz` (ROS 1's rule, ros_comm's ROSTopicHz.print_hz): each second the rate over the
messages so far, `no new messages` when none came since the last report, nothing before the
second message; each message counted once, a latched one too."""

from __future__ import annotations

from helpers import BIN


def reports(lines: list[str]) -> list[str]:
    """hz's report lines: `average rate: ...` and `no new messages`."""
    return [line for line in lines if line.startswith(("average rate", "no new messages"))]


def test_two_latched_messages_are_one_rate_then_no_new_messages(ros_domain, node_process):
    hz = node_process(str(BIN / "rostopic"), "hz", "/hz_latched")
    first = node_process(str(BIN / "rostopic"), "pub", "/hz_latched", "std_msgs/String", "one")
    first.wait_for_text("publishing and latching")
    hz.wait_for_text("subscribed to [/hz_latched]")
    second = node_process(str(BIN / "rostopic"), "pub", "/hz_latched", "std_msgs/String", "two")
    second.wait_for_text("publishing and latching")
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
    for proc in (hz, first, second):
        assert proc.interrupt() == 0
