"""demo_nodes_py's introspection (ros2/demos, Jazzy): the introspection demo's server and
client (introspection_service.py, introspection_client.py, beside this file) as two nodes in
one process.

    ros2 run demo_nodes_py introspection --ros-args -p client_configure_introspection:=metadata \
        -p service_configure_introspection:=metadata
    ros2 service echo /add_two_ints
"""

import rclpy
from rclpy.executors import ExternalShutdownException, SingleThreadedExecutor

# The two nodes, from the files beside this one (copy all three into a package of your own).
from .introspection_client import IntrospectionClientNode
from .introspection_service import IntrospectionServiceNode


def main(args: list[str] | None = None) -> None:
    rclpy.init(args=args)  # initialise ROS 2 (reads --ros-args)
    service, client = IntrospectionServiceNode(), IntrospectionClientNode()
    # Both nodes in one executor: the server answers the client's requests between its timers.
    executor = SingleThreadedExecutor()
    executor.add_node(service)
    executor.add_node(client)
    try:
        executor.spin()  # until Ctrl-C
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl-C or SIGTERM: the normal way to stop (exit status 0)
    finally:
        client.destroy_node()
        service.destroy_node()
        rclpy.try_shutdown()  # shut ROS 2 down


if __name__ == "__main__":
    main()
