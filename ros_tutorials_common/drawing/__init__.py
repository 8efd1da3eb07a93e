"""A graph drawn as rqt_graph draws it, with no ROS: the model (boxes and ellipses, arrows,
namespace frames), where each goes (``layout``), and its files (``render``: DOT, SVG, PNG).
``rqt_graph`` (ros2cmd/graph_view) draws the running graph with it, ``view_frames`` tf2's frame
tree."""
