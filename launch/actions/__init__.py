"""launch.actions: what a LaunchDescription holds, one module per action as ros2/launch has
them. Each action's ``execute`` adds to the plan: a process (ExecuteProcess, and launch_ros's
Node), a step (LogInfo, EmitEvent(Shutdown)), or a change to the scope the following actions
see (DeclareLaunchArgument, SetEnvironmentVariable, GroupAction, ...). A tag of the markup
front-ends is the action that exposes it (``@expose_action``)."""

from launch._missing import module_getattr
from launch.actions._common import (
    NameValueAction,
    command_words,
    enabled,
    flag,
    frontend_attr,
    number_check,
)
from launch.actions.append_environment_variable import AppendEnvironmentVariable
from launch.actions.declare_launch_argument import DeclareLaunchArgument
from launch.actions.emit_event import EmitEvent
from launch.actions.execute_process import ExecuteProcess
from launch.actions.group_action import GroupAction
from launch.actions.include_launch_description import IncludeLaunchDescription
from launch.actions.log_info import LogInfo
from launch.actions.opaque_function import OpaqueFunction
from launch.actions.pop_environment import PopEnvironment
from launch.actions.pop_launch_configurations import PopLaunchConfigurations
from launch.actions.push_environment import PushEnvironment
from launch.actions.push_launch_configurations import PushLaunchConfigurations
from launch.actions.register_event_handler import RegisterEventHandler
from launch.actions.reset_environment import ResetEnvironment
from launch.actions.reset_launch_configurations import ResetLaunchConfigurations
from launch.actions.set_environment_variable import SetEnvironmentVariable
from launch.actions.set_launch_configuration import SetLaunchConfiguration
from launch.actions.shutdown_action import Shutdown
from launch.actions.timer_action import TimerAction
from launch.actions.unset_environment_variable import UnsetEnvironmentVariable
from launch.actions.unset_launch_configuration import UnsetLaunchConfiguration

__all__ = [
    "AppendEnvironmentVariable", "DeclareLaunchArgument", "EmitEvent", "ExecuteProcess",
    "GroupAction", "IncludeLaunchDescription", "LogInfo", "OpaqueFunction", "PopEnvironment",
    "PopLaunchConfigurations", "PushEnvironment", "PushLaunchConfigurations",
    "RegisterEventHandler", "ResetEnvironment", "ResetLaunchConfigurations",
    "SetEnvironmentVariable", "SetLaunchConfiguration", "Shutdown", "TimerAction",
    "UnsetEnvironmentVariable", "UnsetLaunchConfiguration",
]  # fmt: skip
# What launch_ros's actions and the launcher's attribute checks share with these.
_SHARED = (NameValueAction, command_words, enabled, flag, frontend_attr, number_check)

__getattr__ = module_getattr("launch.actions", lambda: __all__)
