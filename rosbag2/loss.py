"""What a recording lost before the recorder received it, counted per topic.

Two witnesses, per topic:

- the middleware's message-lost QoS event (rclpy's ``SubscriptionEventCallbacks``), which Fast
  DDS raises for samples a writer sent that never reached the recorder's reader (a gap in a
  best-effort stream, or samples a reliable writer dropped from its history before they were
  acknowledged);
- gaps in the publication sequence numbers of the messages received, counted only while the
  topic has one publisher (each publisher numbers its own messages, and the numbers do not
  say which publisher sent a message).

The larger of the two is the topic's loss. The recorder reports it while it runs, at the end,
and stores it in metadata.yaml's ``custom_data`` (``LOST_PREFIX`` + topic), which `rosbag info`
shows. What the recorder itself chose not to write (paused, past --max-messages) is not loss.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass

LOST_PREFIX = "messages_lost_before_recording:"


@dataclass
class _TopicLoss:
    reported_by_middleware: int = 0  # the event's running total
    gaps: int = 0  # sequence-number gaps while the topic had one publisher
    pending_gaps: int = 0  # since the last look at the publishers
    last_sequence: int | None = None
    one_publisher: bool = False  # at the last look
    told: int = 0  # what the user has been told so far

    @property
    def lost(self) -> int:
        return max(self.reported_by_middleware, self.gaps)


class LossCount:
    """The per-topic loss of one recording."""

    def __init__(self) -> None:
        self.topics: dict[str, _TopicLoss] = {}

    def _topic(self, topic: str) -> _TopicLoss:
        return self.topics.setdefault(topic, _TopicLoss())

    def middleware_lost(self, topic: str, total_count: int) -> None:
        """The message-lost event: the middleware's running total for the topic's reader."""
        entry = self._topic(topic)
        entry.reported_by_middleware = max(entry.reported_by_middleware, total_count)

    def received(self, topic: str, sequence: int | None) -> None:
        """A message arrived with its publication sequence number (None or 0: unknown)."""
        self.received_many(topic, [sequence])

    def received_many(self, topic: str, sequences: list[int | None]) -> None:
        """Messages of one topic arrived, in this order, with these sequence numbers."""
        entry = self._topic(topic)
        last, gaps = entry.last_sequence, 0
        for sequence in sequences:
            if not sequence:
                continue
            if last is not None and sequence > last + 1:
                gaps += sequence - last - 1
            last = sequence  # lower than before: a new publisher started over
        entry.last_sequence = last
        entry.pending_gaps += gaps

    def look_at_publishers(self, count_publishers: Callable[[str], int]) -> None:
        """Every so often: gaps counted since the last look are loss only if the topic had
        one publisher at both looks (two publishers' numbers interleave)."""
        for topic, entry in self.topics.items():
            one = count_publishers(topic) == 1
            if one and entry.one_publisher:
                entry.gaps += entry.pending_gaps
            entry.pending_gaps = 0
            entry.one_publisher = one

    def news(self) -> list[tuple[str, int, int]]:
        """(topic, lost since the last news, lost in all) for each topic that lost more."""
        told = []
        for topic, entry in sorted(self.topics.items()):
            if entry.lost > entry.told:
                told.append((topic, entry.lost - entry.told, entry.lost))
                entry.told = entry.lost
        return told

    def totals(self) -> dict[str, int]:
        return {topic: entry.lost for topic, entry in sorted(self.topics.items()) if entry.lost}

    def custom_data(self) -> dict[str, str]:
        return {LOST_PREFIX + topic: str(lost) for topic, lost in self.totals().items()}


def lost_in(custom_data: object) -> dict[str, int]:
    """The per-topic loss a recording stored in metadata.yaml's custom_data."""
    lost = {}
    if not isinstance(custom_data, Mapping):  # metadata.yaml is input: any shape may come
        return lost
    for key, value in custom_data.items():
        if isinstance(key, str) and key.startswith(LOST_PREFIX):
            try:
                lost[key[len(LOST_PREFIX) :]] = int(str(value))
            except ValueError:
                continue
    return lost
