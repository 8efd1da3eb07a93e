"""Subscribing so that every publisher of a topic is heard, also those that come later.

A subscription and a publisher only match when their QoS are compatible: a reliable
subscription gets nothing from a best-effort publisher, and a transient-local subscription
(the only kind that receives what a latching publisher sent before it joined) gets nothing
from a volatile publisher. `ros2 topic echo` picks its QoS once, from the publishers present
at start; a publisher with other QoS that appears later is never heard ("offering
incompatible QoS ... DURABILITY"). ``AdaptiveSubscription`` picks the QoS the same way and
creates the subscription again whenever the set of publisher QoS changes.

A subscription made again as transient-local receives what the latching publishers still hold,
which the volatile one before it may have received already: each message is taken once (by
its publisher's stamp and sequence number), so a latched message is seen once, as ROS 1's
latching gave it once.

When no single QoS gets everything (transient-local and volatile publishers together), it
subscribes volatile, which matches them all, and says once on stderr that what the
transient-local publishers sent before it joined is not received. The other policies
(deadline, liveliness) are left at the defaults that match any publisher; should one still be
incompatible, rmw's event is reported in one line and the publishers are looked at again.
"""

from __future__ import annotations

import argparse
import sys
import time
from collections import deque
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:  # rclpy is loaded where a subscription is made, not to build the parser
    from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy

CHECK_PERIOD = 0.2  # s between looks at the topic's publishers
# Messages remembered to take each once across a new subscription: more than a publisher's
# history a transient-local subscription is sent on joining (`rostopic pub` keeps 10).
SEEN_MESSAGES = 1000
# rclpy.qos's short keys, the choices ros2topic offers, written out so that building the parser
# does not load rclpy (tests/test_cli_imports.py checks them against rclpy's).
PROFILE_HISTORY = {  # QoSPresetProfiles.short_keys() -> the preset's history short key
    "unknown": "unknown",
    "default": "keep_last",
    "system_default": "system_default",
    "sensor_data": "keep_last",
    "services_default": "keep_last",
    "parameters": "keep_last",
    "parameter_events": "keep_last",
    "action_status_default": "keep_last",
    "best_available": "keep_last",
}
POLICY_KEYS = {  # the policy's short_keys()
    "history": ("system_default", "keep_last", "keep_all", "unknown"),
    "reliability": ("system_default", "reliable", "best_effort", "unknown", "best_available"),
    "durability": ("system_default", "transient_local", "volatile", "unknown", "best_available"),
    "liveliness": ("system_default", "automatic", "manual_by_topic", "unknown", "best_available"),
}


def publisher_qos_kinds(graph: Any, topic: str) -> set[tuple[DurabilityPolicy, ReliabilityPolicy]]:
    """The (durability, reliability) pairs the topic's publishers offer now."""
    return {
        (p.qos_profile.durability, p.qos_profile.reliability)
        for p in graph.node.get_publishers_info_by_topic(topic)
    }


def qos_for(kinds: set[tuple[DurabilityPolicy, ReliabilityPolicy]]) -> QoSProfile:
    """A subscription QoS that matches every publisher offering one of these kinds."""
    from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy

    qos = QoSProfile(depth=10)
    if kinds and all(durability == DurabilityPolicy.TRANSIENT_LOCAL for durability, _ in kinds):
        qos.durability = DurabilityPolicy.TRANSIENT_LOCAL
    if any(reliability == ReliabilityPolicy.BEST_EFFORT for _, reliability in kinds):
        qos.reliability = ReliabilityPolicy.BEST_EFFORT
    return qos


def compatible_qos(graph: Any, topic: str) -> QoSProfile:
    """A subscription QoS that matches every current publisher, as `ros2 topic echo` picks it.

    A reliable subscription gets nothing from a best-effort publisher, and only a
    transient-local one receives what a latching publisher sent before we joined.
    """
    return qos_for(publisher_qos_kinds(graph, topic))


def _say(message: str) -> None:
    print(message, file=sys.stderr, flush=True)


class AdaptiveSubscription:
    """A subscription that follows the topic's publishers' QoS; call ``update()`` often."""

    def __init__(
        self,
        graph: Any,
        msg_type: type,
        topic: str,
        callback: Callable[[Any], None],
        raw: bool = False,
    ) -> None:
        self.graph = graph
        self.msg_type = msg_type
        self.topic = topic
        self.callback = callback
        self.raw = raw
        self.kinds: set | None = None
        self.qos: QoSProfile | None = None
        self.subscription = None
        self._next_check = 0.0
        self._warned_mixed = False
        self._incompatible: tuple[str, float] | None = None  # (policy, when reported)
        self._seen: set[tuple[int, int]] = set()
        self._seen_order: deque[tuple[int, int]] = deque()
        self.update(force=True)

    def update(self, force: bool = False) -> None:
        """Create the subscription again if the publishers' QoS ask for another one."""
        now = time.monotonic()
        if not force and now < self._next_check:
            return
        self._next_check = now + CHECK_PERIOD
        kinds = publisher_qos_kinds(self.graph, self.topic)
        if kinds == self.kinds:
            # rmw may report a new publisher before our graph shows it: give it a second.
            if self._incompatible is not None and now - self._incompatible[1] > 1.0:
                policy, self._incompatible = self._incompatible[0], None
                _say(f"warning: a publisher of {self.topic} offers an incompatible QoS ({policy})")
            return
        self.kinds = kinds
        self._incompatible = None
        durabilities = {durability for durability, _ in kinds}
        if len(durabilities) > 1 and not self._warned_mixed:
            self._warned_mixed = True
            _say(
                f"note: {self.topic} has transient-local (latched) and volatile publishers; "
                "no one QoS gets both the latched messages sent before now and the others: "
                "subscribing volatile, so every publisher is heard from now on"
            )
        qos = qos_for(kinds)
        if self.qos is not None and _same(qos, self.qos):
            return
        from rclpy.event_handler import SubscriptionEventCallbacks

        if self.subscription is not None:
            self.graph.node.destroy_subscription(self.subscription)
        self.qos = qos
        self.subscription = self.graph.node.create_subscription(
            self.msg_type,
            self.topic,
            self._receive,
            qos,
            raw=self.raw,
            event_callbacks=SubscriptionEventCallbacks(incompatible_qos=self._on_incompatible),
        )

    def _receive(self, msg: Any, info: dict) -> None:
        """The callback, once per message: a new subscription may be sent again what a
        latching publisher holds."""
        key = (info["source_timestamp"], info["publication_sequence_number"])
        if key in self._seen:
            return
        self._seen.add(key)
        self._seen_order.append(key)
        if len(self._seen_order) > SEEN_MESSAGES:
            self._seen.discard(self._seen_order.popleft())
        self.callback(msg)

    def _on_incompatible(self, event: Any) -> None:
        """rmw reports a publisher we do not match: usually one that just appeared."""
        policy = getattr(event.last_policy_kind, "name", str(event.last_policy_kind))
        self._incompatible = (policy.removeprefix("RMW_QOS_POLICY_"), time.monotonic())
        self._next_check = 0.0  # look at the publishers again at once


def _same(a: QoSProfile, b: QoSProfile) -> bool:
    return (a.durability, a.reliability) == (b.durability, b.reliability)


# The --qos-* options of `ros2 topic echo` and `pub`, as ros2topic has them.


def add_qos_arguments(parser: argparse.ArgumentParser, verb: str, default_profile: str) -> None:
    """--qos-profile (a preset: sensor_data, services_default, ...) and its overrides."""
    parser.add_argument(
        "--qos-profile",
        choices=list(PROFILE_HISTORY),
        default=default_profile,
        help=f"Quality of service preset profile to {verb} with (default: {default_profile})",
    )
    history = PROFILE_HISTORY[default_profile]
    parser.add_argument(
        "--qos-depth",
        metavar="N",
        type=int,
        help=f"Queue size setting to {verb} with (overrides depth value of --qos-profile option)",
    )
    parser.add_argument(
        "--qos-history",
        choices=list(POLICY_KEYS["history"]),
        help=f"History of samples setting to {verb} with (overrides history value of "
        f"--qos-profile option, default: {history})",
    )
    for name in ("reliability", "durability"):
        parser.add_argument(
            f"--qos-{name}",
            choices=list(POLICY_KEYS[name]),
            help=f"Quality of service {name} setting to {verb} with (overrides {name} value "
            "of --qos-profile option, default: Compatible profile with running endpoints )",
        )
    parser.add_argument(
        "--qos-liveliness",
        choices=list(POLICY_KEYS["liveliness"]),
        help=f"Quality of service liveliness setting to {verb} with (overrides liveliness "
        "value of --qos-profile option",
    )
    parser.add_argument(
        "--qos-liveliness-lease-duration-seconds",
        type=float,
        help=f"Quality of service liveliness lease duration setting to {verb} with "
        "(overrides liveliness lease duration value of --qos-profile option",
    )


def qos_overridden(args: argparse.Namespace) -> bool:
    """Whether any --qos-* option but the preset was given (echo then adapts nothing)."""
    return any(
        getattr(args, f"qos_{name}") is not None
        for name in (
            "depth",
            "history",
            "reliability",
            "durability",
            "liveliness",
            "liveliness_lease_duration_seconds",
        )
    )


def qos_from_args(args: argparse.Namespace) -> QoSProfile:
    """The preset --qos-profile names, with the --qos-* overrides given applied."""
    from rclpy.duration import Duration
    from rclpy.qos import (
        DurabilityPolicy,
        HistoryPolicy,
        LivelinessPolicy,
        QoSPresetProfiles,
        ReliabilityPolicy,
    )

    profile = QoSPresetProfiles.get_from_short_key(args.qos_profile)
    if args.qos_history:
        profile.history = HistoryPolicy.get_from_short_key(args.qos_history)
    if args.qos_durability:
        profile.durability = DurabilityPolicy.get_from_short_key(args.qos_durability)
    if args.qos_reliability:
        profile.reliability = ReliabilityPolicy.get_from_short_key(args.qos_reliability)
    if args.qos_liveliness:
        profile.liveliness = LivelinessPolicy.get_from_short_key(args.qos_liveliness)
    lease = args.qos_liveliness_lease_duration_seconds
    if lease is not None and lease >= 0:
        profile.liveliness_lease_duration = Duration(seconds=lease)
    if args.qos_depth is not None and args.qos_depth >= 0:
        profile.depth = args.qos_depth
    elif profile.durability == DurabilityPolicy.TRANSIENT_LOCAL and profile.depth == 0:
        profile.depth = 1
    return profile
