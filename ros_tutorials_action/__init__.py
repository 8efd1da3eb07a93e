"""The action lesson: a Fibonacci action server and a one-shot action client."""
