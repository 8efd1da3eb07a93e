"""AddTwoInts server of seed 004 (the "ROS Overview" workshop's add_two_ints_server.py):
serves ``add_two_ints`` and prints "Ready to add two ints." and "Returning [a + b = sum]":
    rosrun my_package add_two_ints_server.py    (ros2 run: workshop_add_two_ints_server)
"""

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from ros_tutorials_interfaces.srv import AddTwoInts


class AddTwoIntsServer(Node):
    def __init__(self):
        super().__init__("add_two_ints_server")
        self.srv = self.create_service(AddTwoInts, "add_two_ints", self.handle_add_two_ints)
        print("Ready to add two ints.", flush=True)

    def handle_add_two_ints(self, req, response):
        if not -(2**63) <= req.a + req.b < 2**63:  # Python's ints do not overflow; int64 does
            print(f"Cannot return [{req.a} + {req.b}]: the sum does not fit in int64", flush=True)
            return response  # sum 0
        print(f"Returning [{req.a} + {req.b} = {req.a + req.b}]", flush=True)
        response.sum = req.a + req.b
        return response


def main(args=None):
    rclpy.init(args=args)
    node = AddTwoIntsServer()
    try:
        rclpy.spin(node)  # rospy.spin()
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == "__main__":
    main()
