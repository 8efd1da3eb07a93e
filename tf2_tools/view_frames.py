"""`ros2 run tf2_tools view_frames`: listen to /tf and /tf_static for 5 s, then write the frame
tree as frames_YYYY-MM-DD_HH.MM.SS.gv (graphviz's DOT, as tf2_tools writes it) and a picture.

ROS 2's view_frames has graphviz's `dot` program draw the PDF. No `dot` is assumed here: the
picture is an SVG (frames_....svg), laid out by rqt_graph's own layout
(ros_tutorials_common/drawing), each frame an ellipse, each transform a box between parent
and child saying who broadcasts it and how often. The log lines are view_frames' own.

    ros2 run tf2_tools view_frames [-t WAIT_TIME] [-o NAME]    NAME.gv and NAME.svg
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import rclpy
import yaml
from rclpy.executors import SingleThreadedExecutor
from tf2_msgs.srv import FrameGraph

from ros_tutorials_common import shutdown
from ros_tutorials_common.cli import EXIT_INTERRUPTED, positive_seconds
from ros_tutorials_common.drawing.model import MAX_VERTICES, GraphModel
from ros_tutorials_common.drawing.render import CannotWrite, write
from ros_tutorials_common.ros import init, node_stopped, user_args
from ros_tutorials_common.wait import Interrupted, spin_until


class Parser(argparse.ArgumentParser):
    def error(self, message: str) -> None:  # one line, as every tool here
        sys.stderr.write(f"view_frames: error: {message}\n")
        sys.exit(2)


def parse_args(argv: list[str]) -> argparse.Namespace:
    parser = Parser(
        prog="view_frames", description="Create a diagram of the TF frames being broadcast over ROS"
    )
    parser.add_argument(
        "--wait-time", "-t", type=positive_seconds, default=5.0,
        help="Listen to the /tf topic for this many seconds before rendering the frame tree",
    )  # fmt: skip
    parser.add_argument("-o", "--output", help="Output filename")
    return parser.parse_args(argv)


def frames_from_yaml(frame_yaml: str) -> dict[str, dict]:
    """The frames of tf2's all_frames_as_yaml(): child frame -> parent, broadcaster, rate..."""
    data = yaml.safe_load(frame_yaml)
    return data if isinstance(data, dict) else {}


def to_dot(frames: dict[str, dict], recorded_at: float) -> str:
    """The frame tree in DOT, as ROS 2's view_frames writes it (edge labels, the legend)."""
    if not frames:
        return 'digraph G { "No tf data received" }'
    lines = ["digraph G {"]
    root = ""
    for child, info in frames.items():
        label = "\\n".join(
            f"{title}: {info.get(key)}"
            for title, key in (
                ("Broadcaster", "broadcaster"),
                ("Average rate", "rate"),
                ("Buffer length", "buffer_length"),
                ("Most recent transform", "most_recent_transform"),
                ("Oldest transform", "oldest_transform"),
            )
        )
        lines.append(f'"{info["parent"]}" -> "{child}"[label=" {label}\\n"];')
        if info["parent"] not in frames:
            root = info["parent"]
    lines.append("edge [style=invis];")
    lines.append(' subgraph cluster_legend { style=bold; color=black; label ="view_frames Result";')
    lines.append(f'"Recorded at time: {recorded_at}"[ shape=plaintext ] ;')
    lines.append(f'}}->"{root}";')
    return "\n".join(lines) + "\n}"


def to_model(frames: dict[str, dict], recorded_at: float) -> GraphModel:
    """The picture: frames as ellipses, each transform a box from parent to child, all in one
    frame labelled with the time, as view_frames' legend."""
    legend = f"view_frames Result, recorded at time: {recorded_at:.3f}"
    model = GraphModel()
    if not frames:
        model.add("f:none", "No tf data received", "topic", legend)
    for child, info in frames.items():
        parent, edge = "f:" + info["parent"], "t:" + child
        model.add(parent, info["parent"], "topic", legend)
        model.add("f:" + child, child, "topic", legend)
        rate = info.get("rate", 0.0)
        model.add(edge, f"{info.get('broadcaster')}, {rate} Hz", "node", legend)
        model.edges += [(parent, edge), (edge, "f:" + child)]
    return model


def view_frames(node: rclpy.node.Node, args: argparse.Namespace) -> int:
    import tf2_ros  # here, so that the DOT and the picture need no tf2 (tests, the viewer)

    buffer = tf2_ros.Buffer(node=node)
    tf2_ros.TransformListener(buffer, node, spin_thread=False)
    executor = SingleThreadedExecutor()
    executor.add_node(node)
    node.get_logger().info(f"Listening to tf data for {args.wait_time} seconds...")
    # Any press so far ends it: one delivered would have, so this one was lost on its way.
    spin_until(executor, lambda: False, args.wait_time, interrupted=lambda: shutdown.presses > 0)
    node.get_logger().info("Generating graph...")
    result = FrameGraph.Response(frame_yaml=buffer.all_frames_as_yaml())
    node.get_logger().info("Result:" + str(result))
    name = args.output or "frames_" + time.strftime("%Y-%m-%d_%H.%M.%S")
    picture = Path(name + ".svg")
    node.get_logger().info(f"Exporting graph in {picture} file...")
    sec, nanosec = node.get_clock().now().seconds_nanoseconds()
    frames = frames_from_yaml(result.frame_yaml)
    try:
        Path(name + ".gv").write_text(to_dot(frames, sec + nanosec / 1e9))
    except OSError as error:
        raise CannotWrite(f"cannot write '{name}.gv': {error.strerror or error}") from None
    model = to_model(frames, sec + nanosec / 1e9)
    if len(model.vertices) > MAX_VERTICES:  # the layout's limit of a readable picture
        raise CannotWrite(
            f"{len(frames)} frames are too many to draw readably; {name}.gv has them all"
        )
    write(model, picture)
    return 0


@shutdown.program_main
def main(argv: list[str] | None = None) -> int:
    argv = sys.argv if argv is None else argv
    args = parse_args(user_args(argv))
    init(argv)
    node = None
    try:
        node = rclpy.create_node("view_frames")
        return view_frames(node, args)
    except CannotWrite as error:
        print(f"view_frames: {error}", file=sys.stderr)
        return 1
    except Interrupted:
        return EXIT_INTERRUPTED
    except Exception as error:  # SIGTERM (rclpy's handler shut ROS down): as Ctrl-C
        if node_stopped(error):
            return EXIT_INTERRUPTED
        raise
    finally:
        if node is not None:
            node.destroy_node()
        rclpy.try_shutdown()


if __name__ == "__main__":
    sys.exit(main())
