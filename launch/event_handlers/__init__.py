"""launch.event_handlers: actions that happen when a process starts, exits or prints a line,
or when the launch shuts down, one module per handler as ros2/launch has them."""

from launch._missing import module_getattr
from launch.event_handlers.on_action_event_base import first_event, run_handler_function
from launch.event_handlers.on_execution_complete import OnExecutionComplete
from launch.event_handlers.on_process_exit import OnProcessExit
from launch.event_handlers.on_process_io import OnProcessIO
from launch.event_handlers.on_process_start import OnProcessStart
from launch.event_handlers.on_shutdown import OnShutdown

__all__ = [
    "OnExecutionComplete", "OnProcessExit", "OnProcessIO", "OnProcessStart", "OnShutdown",
]  # fmt: skip
_SHARED = (first_event, run_handler_function)  # what lazy steps of the actions call

__getattr__ = module_getattr("launch.event_handlers", lambda: __all__)
