"""launch_ros.events.lifecycle: ChangeState (ask lifecycle nodes to make a transition) and
StateTransition (a node made one), as launch_ros jazzy names them. A launch file builds them;
the launcher, which hosts no ROS node, runs no transition: EmitEvent(ChangeState) is refused
with one line where the launch file emits it (launch.actions.EmitEvent)."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from launch._missing import module_getattr
from launch.event import Event

__all__ = ["ChangeState", "StateTransition"]


class ChangeState(Event):
    """Ask the lifecycle nodes ``lifecycle_node_matcher`` accepts to make transition
    ``transition_id`` (lifecycle_msgs/msg/Transition's ids)."""

    def __init__(
        self, *, lifecycle_node_matcher: Callable[[Any], bool], transition_id: int
    ) -> None:
        super().__init__(lifecycle_node_matcher=lifecycle_node_matcher, transition_id=transition_id)


class StateTransition(Event):
    """A lifecycle node's transition, from ``start_state`` to ``goal_state``."""

    def __init__(self, *, action: Any, msg: Any) -> None:
        super().__init__(action=action, msg=msg)


__getattr__ = module_getattr("launch_ros.events.lifecycle", lambda: __all__)
