"""`ros2 service`'s sub-verbs, one module each: HELP (its line in `ros2 service -h`),
add_arguments(parser) and main(graph, args), as ros2service's verb/ has them."""
