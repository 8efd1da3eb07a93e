"""launch.frontend: what the markup front-ends (launch_xml, launch_yaml) share, as ros2/launch
has it: ``Entity`` (one parsed element), ``Parser`` (a file -> entities -> a LaunchDescription
of actions) and the registries a tag's parse method is exposed in (``expose_action``,
``expose_substitution``)."""

from launch._missing import module_getattr
from launch.frontend.entity import Entity
from launch.frontend.expose import expose_action, expose_substitution
from launch.frontend.parser import InvalidFrontendLaunchFileError, Parser

__all__ = [
    "Entity", "InvalidFrontendLaunchFileError", "Parser", "expose_action",
    "expose_substitution",
]  # fmt: skip

__getattr__ = module_getattr("launch.frontend", lambda: __all__)
