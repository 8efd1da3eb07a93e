"""`ros2 pkg`'s sub-verbs, one module each: HELP (its line in `ros2 pkg -h`),
add_arguments(parser) and main(graph, args), as ros2pkg's verb/ has them."""
