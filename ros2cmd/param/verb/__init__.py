"""`ros2 param`'s sub-verbs, one module each: HELP (its line in `ros2 param -h`),
add_arguments(parser) and main(graph, args), as ros2param's verb/ has them."""
