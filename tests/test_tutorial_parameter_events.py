"""The official Jazzy page "Monitoring for parameter changes (Python)": the page's node
(tests/data/workspace/parameter_event_handler.py, as printed) in a package built with the real
colcon; `ros2 param set` on its own parameter, then (step 3.1) on demo_nodes_cpp's
parameter_blackboard (this project's Python port), each logged by the node's callback."""

from __future__ import annotations

import pytest
from test_workspace import (
    DATA,
    add_entry_points,
    colcon_build,
    create,
    new_workspace,
    ok,
    sourced,
    terminal,
)

# Step 3.1: the lines the page adds at the end of the constructor.
REMOTE_CALLBACK = """
        self.callback_handle = self.handler.add_parameter_callback(
            parameter_name="a_double_param",
            node_name="parameter_blackboard",
            callback=self.callback,
        )
"""


@pytest.mark.long  # a colcon build
def test_the_node_logs_changes_of_its_own_and_another_nodes_parameter(tmp_path):
    workspace = new_workspace(tmp_path)
    create(
        workspace,
        "--build-type ament_python --license Apache-2.0 python_parameter_event_handler "
        "--dependencies rclpy",
    )
    package = workspace / "src" / "python_parameter_event_handler"
    code = (DATA / "parameter_event_handler.py").read_text()
    end_of_constructor = code.index("\n    def callback")
    code = code[:end_of_constructor] + REMOTE_CALLBACK + code[end_of_constructor:]
    (package / "python_parameter_event_handler" / "parameter_event_handler.py").write_text(code)
    add_entry_points(
        package / "setup.py",
        "node_with_parameters = python_parameter_event_handler.parameter_event_handler:main",
    )
    colcon_build(workspace, "--packages-select python_parameter_event_handler")
    node = terminal(workspace, "ros2 run python_parameter_event_handler node_with_parameters")
    blackboard = terminal(workspace, "ros2 run demo_nodes_cpp parameter_blackboard")
    try:
        said = ok(sourced("ros2 param set node_with_parameters an_int_param 43"), workspace)
        assert said == "Set parameter successful\n"
        node.wait_for_text(
            "[node_with_parameters]: Received an update to parameter: an_int_param: 43"
        )
        blackboard.wait_for_text(
            "[parameter_blackboard]: Parameter blackboard node named '/parameter_blackboard' "
            "ready, and serving"
        )
        said = ok(sourced("ros2 param set parameter_blackboard a_double_param 3.45"), workspace)
        assert said == "Set parameter successful\n"
        node.wait_for_text(
            "[node_with_parameters]: Received an update to parameter: a_double_param: 3.45"
        )
    finally:
        node.kill()
        blackboard.kill()
