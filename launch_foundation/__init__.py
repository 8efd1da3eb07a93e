"""The floor under the launch packages: what the model (``launch``, ``launch_ros``), its
front-ends (``launch_xml``, ``launch_yaml``) and the launcher on top all stand on.

- ``errors``: ``LaunchError`` (one line, exit 1) and ``CodeRefused``;
- ``declarations``: the plan's data (``NodeDecl``, ``Step`` at a ``When``, ``ContainerDecl``)
  and ``PlanSink``, the one interface through which executing an entity hands its result up;
- ``naming``: ROS names, namespaces, remaps, parameter flattening;
- ``parse``: markup (XML, YAML) to ``Element``s that remember their file:line, bounded;
- ``expressions``: ``$(eval)``'s expressions computed without running code;
- ``substitutions``: the rules of ``$(...)`` text the layers share (``to_bool``, the expansion
  caps, ``run_command`` for ``$(command)`` and ``Command``).

It imports nothing of the packages above it (``tests/test_import_rules.py`` checks that no
import runs up a floor), only ``ros_tutorials_common``'s plain modules and the standard library.
"""

from launch_foundation.errors import CodeRefused, LaunchError

__all__ = ["CodeRefused", "LaunchError"]
