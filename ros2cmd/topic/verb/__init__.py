"""`ros2 topic`'s sub-verbs, one module each: HELP (its line in `ros2 topic -h`),
add_arguments(parser) and main(graph, args), as ros2topic's verb/ has them."""
