"""demo_nodes_cpp's parameter_blackboard (ros2/demos, Jazzy), in Python: a node that holds
whatever parameters it is given or set, for other nodes to read and watch. The page that
uses it ("Monitoring for parameter changes (Python)") types:

    ros2 run demo_nodes_cpp parameter_blackboard
"""

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node


class ParameterBlackboard(Node):
    def __init__(self) -> None:
        super().__init__(
            "parameter_blackboard",
            allow_undeclared_parameters=True,
            automatically_declare_parameters_from_overrides=True,
        )
        names = self.list_parameters([], 0).names  # depth 0: every parameter
        self.get_logger().info(
            f"Parameter blackboard node named '{self.get_fully_qualified_name()}' ready, "
            f"and serving '{len(names)}' parameters already!"
        )


def main(args: list[str] | None = None) -> None:
    rclpy.init(args=args)
    node = ParameterBlackboard()
    try:
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl-C or SIGTERM: the normal way to stop
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == "__main__":
    main()
