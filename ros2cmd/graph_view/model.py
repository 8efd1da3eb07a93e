"""What rqt_graph's picture holds: nodes and topics as vertices, publish and subscribe as
edges, each in its namespace, taken from the graph snapshot every tool reads (the model itself:
ros_tutorials_common/drawing/model.py)."""

from __future__ import annotations

from ros2cmd.errors import ToolError
from ros2cmd.graph import Graph, Snapshot, split_node_name
from ros_tutorials_common.drawing.model import MAX_VERTICES, ROOT, GraphModel

DEBUG_TOPICS = {"/rosout", "/parameter_events"}  # hidden unless --all, as rqt_graph does


def namespace_of(name: str) -> str:
    return split_node_name(name)[0]


def model_from_snapshot(snapshot: Snapshot, groups: bool = True, all_topics: bool = False):
    """Nodes and topics with their publish/subscribe edges (rqt_graph's "Nodes/Topics (all)")."""
    model = GraphModel()
    for node in snapshot.nodes:
        model.add("n:" + node, node, "node", namespace_of(node) if groups else ROOT)
    for topic, info in sorted(snapshot.topics.items()):
        if topic in DEBUG_TOPICS and not all_topics:
            continue
        if not info.publishers and not info.subscribers:
            continue
        model.add("t:" + topic, topic, "topic", namespace_of(topic) if groups else ROOT)
        for endpoint in {e.node for e in info.publishers}:
            model.add("n:" + endpoint, endpoint, "node", namespace_of(endpoint) if groups else ROOT)
            model.edges.append(("n:" + endpoint, "t:" + topic))
        for endpoint in {e.node for e in info.subscribers}:
            model.add("n:" + endpoint, endpoint, "node", namespace_of(endpoint) if groups else ROOT)
            model.edges.append(("t:" + topic, "n:" + endpoint))
    model.edges.sort()
    return model


def current_model(graph: Graph, groups: bool, all_topics: bool) -> GraphModel:
    model = model_from_snapshot(graph.snapshot(), groups, all_topics)
    if len(model.vertices) > MAX_VERTICES:
        raise ToolError(
            f"the graph has {len(model.vertices)} nodes and topics, too many to draw readably "
            f"(at most {MAX_VERTICES}); `ros2 node list` and `topic list` list them"
        )
    return model
