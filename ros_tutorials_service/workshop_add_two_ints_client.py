"""AddTwoInts client of seed 004 (the "ROS Overview" workshop's add_two_ints_client.py).

Sends x and y to ``add_two_ints`` once; prints "Requesting x+y" and "x + y = sum" as the seed
does. Where the seed waits for ever, this gives up after 30 seconds:
    rosrun my_package add_two_ints_client.py 1 2    (ros2 run: workshop_add_two_ints_client)
"""

import sys

import rclpy
from rclpy.node import Node
from rclpy.utilities import remove_ros_args
from ros_tutorials_interfaces.srv import AddTwoInts


def add_two_ints_client(node, x, y):
    client = node.create_client(AddTwoInts, "add_two_ints")
    if not client.wait_for_service(timeout_sec=30.0):  # rospy.wait_for_service('add_two_ints')
        raise RuntimeError("service add_two_ints not available after 30 s")
    future = client.call_async(AddTwoInts.Request(a=x, b=y))
    rclpy.spin_until_future_complete(node, future, timeout_sec=30.0)
    if not future.done():
        raise RuntimeError("no answer from add_two_ints after 30 s")
    return future.result().sum


def main(args=None):
    argv = remove_ros_args(sys.argv if args is None else args)
    if len(argv) != 3 or not all(w.lstrip("-").isdigit() and abs(int(w)) < 2**63 for w in argv[1:]):
        print(f"{argv[0]} [x y]")  # the seed's usage()
        return 1
    x, y = int(argv[1]), int(argv[2])
    rclpy.init(args=args)
    node = Node("add_two_ints_client")
    try:
        print(f"Requesting {x}+{y}", flush=True)
        print(f"{x} + {y} = {add_two_ints_client(node, x, y)}", flush=True)
        return 0
    except RuntimeError as e:  # the seed's `except rospy.ServiceException, e`
        print(f"Service call failed: {e}")
        return 1
    except KeyboardInterrupt:
        return 130  # Ctrl-C while waiting: the shell's status for it
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == "__main__":
    sys.exit(main())
