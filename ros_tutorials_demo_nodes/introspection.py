"""demo_nodes_py's introspection (ros2/demos, Jazzy): the introspection demo's server and
client (introspection_service.py, introspection_client.py) as two nodes in one process.

    ros2 run demo_nodes_py introspection --ros-args -p client_configure_introspection:=metadata \
        -p service_configure_introspection:=metadata
    ros2 service echo /add_two_ints
"""

import rclpy
from rclpy.executors import ExternalShutdownException, SingleThreadedExecutor

from ros_tutorials_common.ros import ros_args
from ros_tutorials_demo_nodes.introspection_client import IntrospectionClientNode
from ros_tutorials_demo_nodes.introspection_service import IntrospectionServiceNode


def main(args=None) -> None:
    rclpy.init(args=ros_args(args))  # initialise ROS 2 (reads --ros-args; DDS defaults)
    # Both nodes in one executor: the server answers the client's requests between its timers.
    executor = SingleThreadedExecutor()
    executor.add_node(IntrospectionServiceNode())
    executor.add_node(IntrospectionClientNode())
    try:
        executor.spin()
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl-C or SIGTERM: the normal way to stop (exit status 0)
    finally:
        rclpy.try_shutdown()


if __name__ == "__main__":
    main()
